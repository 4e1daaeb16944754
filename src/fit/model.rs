//! What the fit compares with the data: the sleeve's position under the harmonic law, along
//! the tracked window, and the period the data themselves repeat with.
//!
//! ```text
//! track    y_S(τ_i) − y_S(τ_1),  τ_i = K T + (t_shift mod T) + (t_i − t_1),  K = TRANSIENT_PERIODS
//! period   the peak of the periodogram of the detrended positions near 1/T
//! ```
//! Friction does not depend on y, so once the sleeve has stuck its motion repeats every period
//! (the first stick comes within the first period in every sticking regime): past K periods the
//! track is steady, and measuring it from τ_1 makes it exactly periodic in t_shift.

use serde::Serialize;

use crate::engine::{integrate, Run, RunOptions};
use crate::error::{Error, Result};
use crate::models::param::{invalid, num};
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::{woodpecker, LawKind};
use crate::params::MAX_PERIODS;

/// Periods integrated before the first tracked time.
pub const TRANSIENT_PERIODS: u32 = 3;
/// The data's period is looked for within this fraction of the model's.
const PERIOD_SEARCH: f64 = 0.25;
/// Frequencies per 1/span (the periodogram's resolution) in that search.
const PERIOD_OVERSAMPLING: f64 = 8.0;

/// Which way the tracked y points.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Axis {
    /// y grows as the toy falls (the paper's y_S).
    Down,
    /// y grows upward (most tracking apps).
    Up,
}

impl Axis {
    /// +1 down, −1 up: the tracked y is y_off + sign·(y_S − y_S(τ_1)).
    pub fn sign(self) -> f64 {
        match self {
            Axis::Down => 1.0,
            Axis::Up => -1.0,
        }
    }
}

/// The sleeve along the tracked window: y_S(τ_i) − y_S(τ_1) (m) and v(τ_i) − v(τ_1) (m/s).
#[derive(Clone, Debug, PartialEq)]
pub struct Track {
    pub y: Vec<f64>,
    pub v: Vec<f64>,
}

/// The sleeve's track under the harmonic law of `p` (validated) at the times `dt` ≥ 0 after the
/// first tracked time, with the clock shifted by `shift` (s).
pub fn track(p: &WoodpeckerParams, shift: f64, dt: &[f64]) -> Result<Track> {
    p.validate()?;
    let period = p.period();
    let start = f64::from(TRANSIENT_PERIODS) * period + shift.rem_euclid(period);
    let span = dt.iter().fold(0.0_f64, |m, &t| m.max(t));
    let periods = ((start + span) / period).floor() + 1.0;
    if !periods.is_finite() || periods > f64::from(MAX_PERIODS) {
        return Err(invalid(
            "periods",
            num(periods),
            format!(
                "the tracked span ({} s) must cover at most {MAX_PERIODS} periods (T = {} s)",
                num(span),
                num(period)
            ),
        ));
    }
    let opts = RunOptions {
        periods: periods as u32,
        record_segments: true,
    };
    let law = woodpecker::force_law(p, LawKind::Harmonic)?;
    let run = integrate(&woodpecker::body(p), &law, &opts)?;
    let (y0, v0) = state(&run, start)?;
    let mut out = Track {
        y: Vec::with_capacity(dt.len()),
        v: Vec::with_capacity(dt.len()),
    };
    for &d in dt {
        let (y, v) = state(&run, start + d)?;
        out.y.push(y - y0);
        out.v.push(v - v0);
    }
    Ok(out)
}

fn state(run: &Run, t: f64) -> Result<(f64, f64)> {
    run.state_at(t)
        .map(|(y, v, _)| (y, v))
        .ok_or(Error::Stalled {
            t,
            reason: "tracked time outside the integrated run",
        })
}

/// The period of the tracked motion: the highest peak of the periodogram of the positions
/// (less their straight-line trend) within ±25 % of the model's period `around`, refined by a
/// parabola through the peak and its neighbours. The stick-slip pattern repeats every T, so the
/// peak is at 1/T (its harmonics 2/T, 1/(2T) lie outside the search).
pub fn data_period(t: &[f64], y: &[f64], around: f64) -> f64 {
    let n = t.len() as f64;
    let (tm, ym) = (t.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let sxx: f64 = t.iter().map(|t| (t - tm).powi(2)).sum();
    let sxy: f64 = t.iter().zip(y).map(|(t, y)| (t - tm) * (y - ym)).sum();
    let slope = sxy / sxx;
    let detrended: Vec<f64> = t
        .iter()
        .zip(y)
        .map(|(t, y)| y - ym - slope * (t - tm))
        .collect();
    let power = |f: f64| {
        let w = std::f64::consts::TAU * f;
        let (c, s) = t.iter().zip(&detrended).fold((0.0, 0.0), |(c, s), (t, r)| {
            let (sin, cos) = (w * (t - tm)).sin_cos();
            (c + r * cos, s + r * sin)
        });
        c * c + s * s
    };
    let f0 = 1.0 / around;
    let df = 1.0 / (PERIOD_OVERSAMPLING * (t[t.len() - 1] - t[0]));
    let half = (PERIOD_SEARCH * f0 / df).ceil() as i64;
    let freq = |j: i64| f0 + j as f64 * df;
    let (best, _) = (-half..=half)
        .map(|j| (j, power(freq(j))))
        .fold((0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a });
    let (p0, p1, p2) = (
        power(freq(best - 1)),
        power(freq(best)),
        power(freq(best + 1)),
    );
    let curvature = p0 - 2.0 * p1 + p2;
    let offset = if curvature < 0.0 {
        (0.5 * (p0 - p2) / curvature).clamp(-0.5, 0.5)
    } else {
        0.0
    };
    1.0 / (freq(best) + offset * df)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tracked_window_is_periodic_past_the_transient() {
        let p = crate::fit::tests::fig26();
        let period = p.period();
        let dt: Vec<f64> = (0..200).map(|i| f64::from(i) * period / 50.0).collect();
        let tr = track(&p, 0.3 * period, &dt).unwrap();
        // Every point advances by the same amount per period (50 samples per period).
        let advance = tr.y[50] - tr.y[0];
        assert!(advance > 1e-3, "{advance}");
        for i in 0..150 {
            assert!((tr.y[i + 50] - tr.y[i] - advance).abs() < 1e-12, "{i}");
            assert!((tr.v[i + 50] - tr.v[i]).abs() < 1e-12, "{i}");
        }
        // A whole period more of clock shift is the same track.
        let again = track(&p, 1.3 * period, &dt).unwrap();
        assert_eq!(tr.y, again.y);
    }

    #[test]
    fn the_period_of_the_data_is_the_periodogram_peak() {
        // A falling staircase-like signal: trend, fundamental and a strong second harmonic.
        let period = 0.17;
        let t: Vec<f64> = (0..400).map(|i| 0.3 + f64::from(i) / 60.0).collect();
        let y: Vec<f64> = t
            .iter()
            .map(|t| {
                let w = std::f64::consts::TAU * t / period;
                0.2 - 0.02 * t + 1e-3 * w.sin() + 8e-4 * (2.0 * w).cos()
            })
            .collect();
        for around in [0.15, 0.165, 0.19] {
            let found = data_period(&t, &y, around);
            assert!((found / period - 1.0).abs() < 2e-4, "{around}: {found}");
        }
    }
}
