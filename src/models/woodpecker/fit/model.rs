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

use crate::engine::run::Motion;
use crate::engine::{integrate, Run, RunOptions};
use crate::error::{Error, Result};
use crate::format::sig;
use crate::models::param::{invalid, num};
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::{woodpecker, LawKind};

/// Periods integrated before the first tracked time.
pub const TRANSIENT_PERIODS: u32 = 3;
/// Most periods integrated for a sleeve that never halts (one that sticks needs
/// [`TRANSIENT_PERIODS`] + 2 whatever the span).
pub const MAX_SLIDING_PERIODS: u32 = 1_000;
/// The data's period is looked for within this fraction of the model's.
const PERIOD_SEARCH: f64 = 0.25;
/// Frequencies per 1/window (the periodogram's resolution) in that search.
const PERIOD_OVERSAMPLING: f64 = 8.0;
/// Model periods of data on which the whole search band is scanned.
const FIRST_PERIODS: f64 = 16.0;

/// Which way the tracked y points.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
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
///
/// A sleeve stuck at the same phase in two consecutive periods repeats its motion every period
/// from then on, advancing by the same Δy: the integration then covers two periods past the
/// [`TRANSIENT_PERIODS`] whatever the span, and later times are folded into the last whole
/// period (y(τ + mT) = y(τ) + mΔy). A sleeve that never halts is integrated over the whole span, at
/// most [`MAX_SLIDING_PERIODS`] periods.
pub fn track(p: &WoodpeckerParams, shift: f64, dt: &[f64]) -> Result<Track> {
    p.validate()?;
    let period = p.period();
    let start = f64::from(TRANSIENT_PERIODS) * period + shift.rem_euclid(period);
    let span = dt.iter().fold(0.0_f64, |m, &t| m.max(t));
    let law = woodpecker::force_law(p, LawKind::Harmonic)?;
    let body = woodpecker::body(p);
    let run = |periods: u32| {
        integrate(
            &body,
            &law,
            &RunOptions {
                periods,
                record_segments: true,
                dissipation: false,
            },
        )
    };
    let steady = run(TRANSIENT_PERIODS + 2)?;
    let sliding;
    // The steady run has TRANSIENT_PERIODS + 3 period starts: the advance of the last period.
    let k = TRANSIENT_PERIODS as usize;
    let xs = &steady.x_at_period_start;
    let advance = xs.get(k + 1).zip(xs.get(k)).map(|(end, start)| end - start);
    let (run, fold) = match steady_from(&steady).zip(advance) {
        Some((from, advance)) => (&steady, Some((from, advance))),
        None => {
            let periods = ((start + span) / period).floor() + 1.0;
            if !periods.is_finite() || periods > f64::from(MAX_SLIDING_PERIODS) {
                return Err(invalid(
                    "mu_d",
                    num(p.mu_d),
                    format!(
                        "a sleeve that halts over a tracked span of {} periods (T = {} s); \
                         one that never halts is followed over at most {MAX_SLIDING_PERIODS}",
                        sig(Some(span / period), 3),
                        sig(Some(period), 4)
                    ),
                ));
            }
            sliding = run(periods as u32)?;
            (&sliding, None)
        }
    };
    // (y, v) at t, folded into the last whole period when the motion repeats.
    let state_at = |t: f64| {
        let (t, dy) = match fold {
            Some((from, advance)) => {
                let m = ((t - from) / period).floor().max(0.0);
                (t - m * period, m * advance)
            }
            None => (t, 0.0),
        };
        state(run, t).map(|(y, v)| (y + dy, v))
    };
    let (y0, v0) = state_at(start)?;
    let mut out = Track {
        y: Vec::with_capacity(dt.len()),
        v: Vec::with_capacity(dt.len()),
    };
    for &d in dt {
        let (y, v) = state_at(start + d)?;
        out.y.push(y - y0);
        out.v.push(v - v0);
    }
    Ok(out)
}

/// The time from which the motion of `run` repeats every period, when the body is stuck at the
/// same phase in period [`TRANSIENT_PERIODS`] − 1 and the next one: the start of period
/// [`TRANSIENT_PERIODS`] (the motion after a stick depends on its phase alone).
fn steady_from(run: &Run) -> Option<f64> {
    let k = f64::from(TRANSIENT_PERIODS);
    let (from, to) = ((k - 1.0) * run.period, k * run.period);
    run.segments
        .iter()
        .filter(|s| matches!(s.motion, Motion::Rest { .. }) && s.t1 > from && s.t0 < to)
        .map(|s| 0.5 * (s.t0.max(from) + s.t1.min(to)))
        .find(|&t| run.stuck_at(t + run.period) == Some(true))
        .map(|_| to)
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
///
/// Coarse to fine, so that the work is O(rows), not O(rows × span / T): the whole band is
/// scanned on the first [`FIRST_PERIODS`] periods of the data, then the window doubles, each
/// time scanning ±2 resolution widths of the previous peak, until it holds every row.
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
    let span = t[t.len() - 1] - t[0];
    let f0 = 1.0 / around;
    let (mut lo, mut hi) = (f0 * (1.0 - PERIOD_SEARCH), f0 * (1.0 + PERIOD_SEARCH));
    let mut window = span.min(FIRST_PERIODS * around);
    loop {
        let rows = t.partition_point(|&ti| ti - t[0] <= window);
        let f = periodogram_peak(&t[..rows], &detrended[..rows], lo, hi, window);
        if window >= span {
            return 1.0 / f;
        }
        let width = 2.0 / window;
        (lo, hi) = ((f - width).max(lo), (f + width).min(hi));
        window = (2.0 * window).min(span);
    }
}

/// The frequency (Hz) of the highest periodogram peak of `r(t)` in `[lo, hi]`, scanned with
/// [`PERIOD_OVERSAMPLING`] frequencies per 1/`window` and refined by a parabola.
fn periodogram_peak(t: &[f64], r: &[f64], lo: f64, hi: f64, window: f64) -> f64 {
    let tm = 0.5 * (t[0] + t[t.len() - 1]);
    let power = |f: f64| {
        let w = std::f64::consts::TAU * f;
        let (c, s) = t.iter().zip(r).fold((0.0, 0.0), |(c, s), (t, r)| {
            let (sin, cos) = (w * (t - tm)).sin_cos();
            (c + r * cos, s + r * sin)
        });
        c * c + s * s
    };
    let df = 1.0 / (PERIOD_OVERSAMPLING * window);
    let bins = ((hi - lo) / df).ceil().max(1.0) as i64;
    let freq = |j: i64| lo + j as f64 * df;
    let (best, _) = (0..=bins)
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
    freq(best) + offset * df
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_tracked_window_is_periodic_past_the_transient() {
        let p = crate::models::woodpecker::lever::fig26();
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

    /// Past the first stick the track is folded into one period: the same numbers as an
    /// integration straight through all the periods.
    #[test]
    fn a_track_folded_into_one_period_is_the_integration_straight_through() {
        let p = crate::models::woodpecker::lever::fig26();
        let period = p.period();
        let shift = 0.3 * period;
        let dt: Vec<f64> = (0..3000).map(|i| f64::from(i) * 0.0371 * period).collect();
        let folded = track(&p, shift, &dt).unwrap();
        let start = f64::from(TRANSIENT_PERIODS) * period + shift;
        let run = integrate(
            &woodpecker::body(&p),
            &woodpecker::force_law(&p, LawKind::Harmonic).unwrap(),
            &RunOptions {
                periods: (start / period + 0.0371 * 3000.0) as u32 + 2,
                record_segments: true,
                dissipation: false,
            },
        )
        .unwrap();
        let (y0, v0) = state(&run, start).unwrap();
        let fall = folded.y[2999];
        assert!(fall > 0.05, "{fall}");
        for (i, &d) in dt.iter().enumerate() {
            let (y, v) = state(&run, start + d).unwrap();
            assert!((folded.y[i] - (y - y0)).abs() < 1e-12 * fall, "{i}");
            assert!((folded.v[i] - (v - v0)).abs() < 1e-9, "{i}");
        }
    }

    /// A sleeve that never halts is integrated over the span, within a bound named in the
    /// message.
    #[test]
    fn a_sleeve_that_never_halts_is_followed_over_a_bounded_span() {
        let p = WoodpeckerParams {
            mu_d: 0.02,
            ..crate::models::woodpecker::lever::fig26()
        };
        let period = p.period();
        let short: Vec<f64> = (0..100).map(|i| f64::from(i) * 0.1 * period).collect();
        assert!(track(&p, 0.0, &short).is_ok());
        let long = [0.0, 2.0 * f64::from(MAX_SLIDING_PERIODS) * period];
        let msg = track(&p, 0.0, &long).unwrap_err().to_string();
        assert!(msg.contains("mu_d") && msg.contains("never halts"), "{msg}");
    }

    /// Thousands of periods: the coarse-to-fine search finds the peak of the full scan.
    #[test]
    fn the_period_of_long_data_is_found_coarse_to_fine() {
        let period = 0.1653;
        let t: Vec<f64> = (0..60_000).map(|i| f64::from(i) / 100.0).collect();
        let y: Vec<f64> = t
            .iter()
            .map(|t| {
                let w = std::f64::consts::TAU * t / period;
                -0.02 * t + 1e-3 * w.sin() + 8e-4 * (2.0 * w).cos()
            })
            .collect();
        let found = data_period(&t, &y, 0.17);
        assert!((found / period - 1.0).abs() < 1e-7, "{found}");
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
