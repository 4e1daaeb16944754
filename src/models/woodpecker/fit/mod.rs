//! `stickslip fit`: the harmonic woodpecker (guide §5.2) fitted to the tracked positions of
//! a real toy (its [`FitTracked`], the capability `fit`), as the paper does by hand for Figs. 26–27 ("the friction coefficients and the
//! initial spring conditions (z0 and d0) have to be varied to a small (a few percent) extent").
//!
//! ```text
//! data     (t_i, y_i), i = 1..n                                        crate::fit::data
//! model    y(t_i) = y_off + s [y_S(τ_i) − y_S(τ_1)],  τ_i = K T + t_shift + t_i − t_1  model.rs
//! free     a subset of μd, z0, d0, μs, k (valid wherever LM goes)               param.rs
//! LM       Levenberg–Marquardt from the best phases of a scan at each of a spread of
//!          centres around the given values; the best kept; standard errors         solve.rs
//! verdict  is the residual the noise? if not, is the position unit slipped?  crate::fit::verdict
//! outputs  fit.json, fit.csv, fit.svg, the terminal table                       render.rs
//! ```
//!
//! y_S is the sleeve's position (the paper's Fig. 26 plots the sleeve), integrated exactly by
//! the engine. The origin of the tracked y and the phase of the tracking clock are unknown:
//! y_off and t_shift are fitted too, as nuisance values, not physics. s = +1 when the tracked y
//! grows as the toy falls (the paper's axis), −1 when the tracking app's y points up; it is
//! read from the data, since the toy only falls.

pub mod model;
pub mod param;
mod render;
mod solve;
pub mod synthetic;

use std::path::Path;

use nalgebra::DMatrix;
use serde::Serialize;

use crate::engine::{analyse, integrate, RunOptions};
use crate::error::{Error, Result};
use crate::fit::{verdict, FitTracked, Fitted, ScaleSlip, Tracked, Verdict};
use crate::format::sig;
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::{woodpecker, LawKind};
use crate::params::DEFAULT_PERIODS;
pub use model::{data_period, track, Axis, Track};
pub use param::FitParam;
pub use render::{chart, json, render, strong_correlations, text, Correlated};
use solve::{solve, termination_text, Setup};

/// Samples of the model curve drawn in the figure.
const CURVE_SAMPLES: usize = 4000;

/// One fitted value.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Estimate {
    pub name: &'static str,
    /// SI unit ("" when dimensionless).
    pub unit: &'static str,
    pub value: f64,
    /// Standard error; `None` when JᵀJ is singular.
    pub std_error: Option<f64>,
    /// Starting value (the given parameters; for the nuisance, the winning start's).
    pub start: f64,
    /// Offset or clock phase of the tracking, not physics.
    pub nuisance: bool,
}

/// Data, model and residual at the tracked times, and the model curve, for the outputs.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Series {
    /// Tracked times (s) and positions (file unit).
    pub t: Vec<f64>,
    pub y: Vec<f64>,
    /// Model and residual (model − data) at the tracked times (file unit).
    pub model: Vec<f64>,
    pub residual: Vec<f64>,
    /// The fitted model on a fine uniform grid: (t s, y file unit).
    pub curve: Vec<(f64, f64)>,
}

/// The outcome of `stickslip fit`, serialised as fit.json (SI units).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Fit {
    pub data: Tracked,
    /// Direction of the tracked y (from the data: the toy falls).
    pub axis: Axis,
    /// Tracked points and fitted values (nuisance included).
    pub n: usize,
    pub p: usize,
    /// Successful termination of LM and a regular JᵀJ.
    pub converged: bool,
    pub termination: String,
    /// Of the winning start: Jacobians computed (LM iterations) and residual evaluations;
    /// and how many starts were raced over all the centres.
    pub iterations: usize,
    pub evaluations: usize,
    pub starts: usize,
    /// Centres LM started from (the given values and a spread around them), and how many of
    /// them ended in the minimum kept: few means the residual has many minima here.
    pub centres: usize,
    pub centres_at_best: usize,
    /// Whether the fitted model describes the data (the residual is the noise), and why not.
    pub verdict: Verdict,
    /// Root-mean-square residual (m) and residual variance s² = RSS/(n − p) (m²).
    pub rms_residual: f64,
    pub residual_variance: f64,
    /// Lag-1 autocorrelation of the residuals: near 0 for white tracking noise, near 1 when
    /// the model misses a systematic part of the motion.
    pub residual_autocorrelation: f64,
    /// The free parameters, then time_shift (s) and y_offset (m).
    pub estimates: Vec<Estimate>,
    /// Covariance and correlation of `estimates` (same order); `None` when JᵀJ is singular.
    pub covariance: Option<Vec<Vec<f64>>>,
    pub correlation: Option<Vec<Vec<f64>>>,
    /// The full parameter set of the fitted model (fixed and fitted values).
    pub params: WoodpeckerParams,
    /// Period T (s) of the fitted model and the phase t_shift/T of the first tracked time.
    pub period: f64,
    pub phase: f64,
    /// The period the data repeat with (s), from their periodogram ([`data_period`]).
    pub data_period: f64,
    /// Regime and mean speed v̄ (m/s) of the fitted model's harmonic law.
    pub regime: &'static str,
    pub v_avg: Option<f64>,
    #[serde(skip)]
    pub series: Series,
}

impl FitTracked for WoodpeckerParams {
    type Free = FitParam;
    const DEFAULT_FREE: &'static [FitParam] = &FitParam::DEFAULT;
    type Outcome = Fit;

    fn fit_tracked(&self, data: &Tracked, free: &[FitParam]) -> Result<Fit> {
        fit(data, self, free)
    }

    fn fitted(fit: &Fit, out: &Path) -> Result<Fitted> {
        Ok(Fitted {
            files: render(fit)?,
            json: json(fit)?,
            text: text(fit, out),
            converged: fit.converged,
            termination: fit.termination.clone(),
            misfit: (!fit.verdict.describes).then(|| fit.verdict.brief()),
        })
    }
}

/// Most model periods a tracked span may cover (a falling toy covers tens).
pub const MAX_SPAN_PERIODS: f64 = 100_000.0;

/// Fits the `free` parameters of `base` (validated; the start of the free ones) and the
/// nuisance to `data`.
///
/// Errors: invalid parameters, data that do not descend, or an engine failure. A fit that does
/// not converge is returned with `converged: false`, one that does not describe the data with
/// a negative [`Verdict`]. When the data fall a power of ten faster or slower than the model,
/// the verdict (or the error of a failed search) names the slip, and the unit with which the
/// model describes them (the fit is repeated in it to know).
pub fn fit(data: &Tracked, base: &WoodpeckerParams, free: &[FitParam]) -> Result<Fit> {
    let result = fit_as_read(data, base, free);
    let Some((mut slip, other)) = unit_slip(data, base, free) else {
        return result;
    };
    let other = other.filter(|o| o.converged && o.verdict.describes);
    slip.rms_in_units = other.as_ref().map(|o| o.rms_residual);
    match result {
        Ok(mut f) => {
            if f.verdict.describes {
                // The data as read may be described loosely (a 10× slip scales the noise
                // too); they stand unless the other unit's residual is clearly the noise.
                let Some(o) = other.filter(|o| o.verdict.less_systematic_than(&f.verdict, f.n))
                else {
                    return Ok(f);
                };
                f.verdict.describes = false;
                f.verdict.reasons.push(format!(
                    "as read the residuals are systematic (lag-1 autocorrelation {}), in {} \
                     they are noise ({})",
                    sig(Some(f.verdict.autocorrelation), 2),
                    o.data.unit.symbol(),
                    sig(Some(o.verdict.autocorrelation), 2)
                ));
            }
            f.verdict.scale = Some(slip);
            Ok(f)
        }
        // The search as read failed, and the unit that undoes the slip fits: a verdict on
        // the data as read (exit 3), naming the unit; nothing as read to write.
        Err(e @ (Error::NotConverged { .. } | Error::InvalidParam { .. })) => {
            match (slip.fits_in_units(), e) {
                (Some(reason), _) => Err(Error::Verdict { reason }),
                // First, as the one-line message is cut to its length.
                (None, Error::NotConverged { reason }) => Err(Error::NotConverged {
                    reason: format!("{}; {reason}", slip.brief()),
                }),
                (None, e) => Err(e),
            }
        }
        Err(e) => Err(e),
    }
}

/// A slip of the position unit when the data fall a power of ten faster or slower than the
/// model at `base` ([`verdict::scale_slip`]), and the fit in the unit that undoes it.
fn unit_slip(
    data: &Tracked,
    base: &WoodpeckerParams,
    free: &[FitParam],
) -> Option<(ScaleSlip, Option<Fit>)> {
    let model = steady_state(base).ok()?.1?;
    let ratio = verdict::descent_speed(&data.t, &data.y_metres()) / model;
    let (factor, units) = verdict::scale_slip(ratio, data.unit)?;
    let other = units.and_then(|unit| {
        let again = Tracked {
            unit,
            ..data.clone()
        };
        fit_as_read(&again, base, free).ok()
    });
    let slip = ScaleSlip {
        factor,
        ratio,
        units,
        rms_in_units: None,
    };
    Some((slip, other))
}

/// [`fit`] with the positions in the unit `data` says.
fn fit_as_read(data: &Tracked, base: &WoodpeckerParams, free: &[FitParam]) -> Result<Fit> {
    base.validate()?;
    let mut free = free.to_vec();
    free.sort();
    free.dedup();
    let y = data.y_metres();
    let axis = match y[y.len() - 1].partial_cmp(&y[0]) {
        Some(std::cmp::Ordering::Greater) => Axis::Down,
        Some(std::cmp::Ordering::Less) => Axis::Up,
        _ => {
            return Err(Error::TrackedData {
                path: data.file.clone(),
                line: None,
                column: Some(data.position_column.clone()),
                reason: "the first and the last position are equal: no descent to fit".to_string(),
            })
        }
    };
    let span_periods = (data.t[data.t.len() - 1] - data.t[0]) / base.period();
    if span_periods.is_nan() || span_periods > MAX_SPAN_PERIODS {
        return Err(Error::TrackedData {
            path: data.file.clone(),
            line: None,
            column: Some(data.time_column.clone()),
            reason: format!(
                "the tracked span covers {} periods of the model (T = {} s); a fit takes at \
                 most {}: check the time unit of the file, and k and m_W",
                sig(Some(span_periods), 3),
                sig(Some(base.period()), 4),
                sig(Some(MAX_SPAN_PERIODS), 6)
            ),
        });
    }
    let setup = Setup {
        base: *base,
        free: &free,
        dt: data.t.iter().map(|t| t - data.t[0]).collect(),
        y,
        sign: axis.sign(),
    };
    let data_period = data_period(&data.t, &setup.y, base.period());
    let s = solve(&setup, data_period)?;

    let k = free.len();
    let std_error = |i: usize| s.covariance.as_ref().map(|c| c[(i, i)].sqrt());
    let mut estimates: Vec<Estimate> = free
        .iter()
        .enumerate()
        .map(|(i, f)| Estimate {
            name: f.name(),
            unit: f.unit(),
            value: f.get(&s.params),
            std_error: std_error(i),
            start: f.get(base),
            nuisance: false,
        })
        .collect();
    let nuisance = [
        ("time_shift", "s", s.shift, s.start_shift),
        ("y_offset", "m", s.y_off, s.start_y_off),
    ];
    for (i, (name, unit, value, start)) in nuisance.into_iter().enumerate() {
        estimates.push(Estimate {
            name,
            unit,
            value,
            std_error: std_error(k + i),
            start,
            nuisance: true,
        });
    }

    let n = setup.y.len();
    let r = &s.residuals;
    let rss = r.norm_squared();
    let scale = data.unit.metres();
    let residual: Vec<f64> = r.iter().map(|r| r / scale).collect();
    let (regime, v_avg) = steady_state(&s.params)?;
    let period = s.params.period();
    Ok(Fit {
        data: data.clone(),
        axis,
        n,
        p: k + 2,
        converged: s.termination.was_successful() && !s.exhausted && s.covariance.is_some(),
        termination: termination_text(&s.termination, s.exhausted, s.covariance.is_some()),
        iterations: s.iterations,
        evaluations: s.evaluations,
        starts: s.starts,
        centres: s.centres,
        centres_at_best: s.at_best,
        verdict: Verdict::judge(&data.t, &setup.y, r.as_slice()),
        rms_residual: (rss / n as f64).sqrt(),
        residual_variance: s.s2,
        residual_autocorrelation: r.rows(0, n - 1).dot(&r.rows(1, n - 1)) / rss,
        estimates,
        correlation: s.covariance.as_ref().map(correlation),
        covariance: s.covariance.as_ref().map(rows),
        params: s.params,
        period,
        phase: s.shift / period,
        data_period,
        regime,
        v_avg,
        series: Series {
            t: data.t.clone(),
            y: data.y.clone(),
            model: data.y.iter().zip(&residual).map(|(y, r)| y + r).collect(),
            residual,
            curve: curve(&setup, &s.params, s.shift, s.y_off, data)?,
        },
    })
}

fn rows(m: &DMatrix<f64>) -> Vec<Vec<f64>> {
    m.row_iter().map(|r| r.iter().copied().collect()).collect()
}

fn correlation(c: &DMatrix<f64>) -> Vec<Vec<f64>> {
    let d: Vec<f64> = (0..c.nrows()).map(|i| c[(i, i)].sqrt()).collect();
    rows(&DMatrix::from_fn(c.nrows(), c.ncols(), |a, b| {
        c[(a, b)] / (d[a] * d[b])
    }))
}

/// Regime id and v̄ of the harmonic law of `p`, from rest over the default periods.
fn steady_state(p: &WoodpeckerParams) -> Result<(&'static str, Option<f64>)> {
    let opts = RunOptions {
        periods: DEFAULT_PERIODS,
        record_segments: false,
        dissipation: false,
    };
    let law = woodpecker::force_law(p, LawKind::Harmonic)?;
    let steady = analyse(&integrate(&woodpecker::body(p), &law, &opts)?);
    Ok((steady.regime().id(), steady.v_avg))
}

/// The fitted model on [`CURVE_SAMPLES`] uniform times over the tracked span (file unit).
fn curve(
    setup: &Setup,
    p: &WoodpeckerParams,
    shift: f64,
    y_off: f64,
    data: &Tracked,
) -> Result<Vec<(f64, f64)>> {
    let span = setup.dt[setup.dt.len() - 1];
    let dt: Vec<f64> = (0..CURVE_SAMPLES)
        .map(|i| span * i as f64 / (CURVE_SAMPLES - 1) as f64)
        .collect();
    let tr = track(p, shift, &dt)?;
    let scale = data.unit.metres();
    Ok(dt
        .iter()
        .zip(&tr.y)
        .map(|(d, m)| (data.t[0] + d, (y_off + setup.sign * m) / scale))
        .collect())
}
