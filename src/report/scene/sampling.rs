//! Sampling exact runs for figures: uniform grids in time with the event times inserted, so
//! that kinks at slip and stick are drawn sharp.

pub use crate::engine::run::sample;
use crate::report::figures::spec::{Curve, Stroke};

/// Points per curve on a uniform grid (the renderer keeps at most ~2000).
pub const SAMPLES: usize = 1200;

/// A curve of column `col` (1 = x, 2 = v, 3 = a) of `samples`, scaled by `scale` (e.g. 1000 for
/// mm), against time.
pub fn curve(
    label: &str,
    samples: &[[f64; 4]],
    col: usize,
    scale: f64,
    color: usize,
    stroke: Stroke,
) -> Curve {
    Curve {
        label: label.to_string(),
        points: samples.iter().map(|s| (s[0], s[col] * scale)).collect(),
        color,
        stroke,
    }
}

/// A curve of a function of time on [t0, t1] with `n` points.
pub fn function_curve(
    label: &str,
    t0: f64,
    t1: f64,
    n: usize,
    f: impl Fn(f64) -> f64,
    color: usize,
    stroke: Stroke,
) -> Curve {
    Curve {
        label: label.to_string(),
        points: (0..n)
            .map(|i| {
                let t = t0 + (t1 - t0) * i as f64 / (n.max(2) - 1) as f64;
                (t, f(t))
            })
            .collect(),
        color,
        stroke,
    }
}
