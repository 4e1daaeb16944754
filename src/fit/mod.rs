//! `stickslip fit`: the harmonic woodpecker (physics.md §2) fitted to the tracked positions of
//! a real toy, as the paper does by hand for Figs. 26–27 ("the friction coefficients and the
//! initial spring conditions (z0 and d0) have to be varied to a small (a few percent) extent").
//!
//! ```text
//! data     (t_i, y_i), i = 1..n                                        data.rs
//! model    y(t_i) = y_off + s [y_S(τ_i) − y_S(τ_1)],   τ_i = K T + t_shift + (t_i − t_1)
//! free     a subset of μd, z0, d0, μs, k; nuisance t_shift ∈ [0, T) and y_off
//! LM       Levenberg–Marquardt (levenberg-marquardt crate) from the best phases of a scan
//! errors   cov = s² (JᵀJ)⁻¹,  s² = RSS/(n − p),  J in the physical parameters at the optimum
//! ```
//!
//! * y_S is the sleeve's position (the paper's Fig. 26 plots the sleeve), integrated exactly
//!   by the engine from rest at t = 0. Friction does not depend on y, so once the sleeve has
//!   stuck the motion repeats every period: the tracked window starts after
//!   [`TRANSIENT_PERIODS`] periods, and measuring y_S from τ_1 makes the model exactly periodic
//!   in t_shift (taken mod T).
//! * The origin of the tracked y and the phase of the clock are unknown, hence y_off and
//!   t_shift; s = +1 when the tracked y grows as the toy falls (the paper's axis), −1 when the
//!   tracking app's y points up (read from the data: the toy only falls).
//! * Validity by construction: LM works on ln d0, ln k, z0 (mm), logit(μd/μs) and the logit of
//!   μs within (0 or a fixed μd, [`MU_MAX`]), so every trial set has 0 < μd < μs ≤ 100 and
//!   positive lengths; the standard errors are then taken in the physical parameters.
//! * Non-smoothness: slip and stick times move with the parameters, but y is C¹ in them away
//!   from a change of regime: at a stick v = 0, so moving the stick time leaves y unchanged to
//!   first order, and at a slip onset only the acceleration jumps. Central differences with a
//!   relative step of 1e-6 are therefore accurate (the engine resolves events to ~1e-15); the
//!   derivatives in t_shift (the sleeve speed) and y_off (1) are exact.
//! * The phase makes the problem non-convex, and so does k (it sets the period): LM starts from
//!   the [`STARTS`] best local minima of a scan of phases (at the given k and, when k is free,
//!   at the k of the data's own period), runs a few steps from each, and carries the best on.

pub mod data;
mod render;
pub mod synthetic;

use std::cell::Cell;

use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt, TerminationReason};
use nalgebra::{storage::Owned, DMatrix, DVector, Dyn};
use serde::Serialize;

use crate::engine::{analyse, integrate, Run, RunOptions};
use crate::error::{Error, Result};
use crate::model::{woodpecker, LawKind};
use crate::params::{invalid, WoodpeckerParams, DEFAULT_PERIODS, MAX_PERIODS, MU_MAX};
pub use data::Tracked;
pub use render::{json, render, text};

/// Periods integrated before the first tracked time: past the transient from rest (the first
/// stick happens within the first period in every sticking regime).
pub const TRANSIENT_PERIODS: u32 = 3;
/// Phases t_shift = jT/PHASE_SCAN tried before the fit.
pub const PHASE_SCAN: usize = 24;
/// Fits started, from the best local minima of the phase scan.
pub const STARTS: usize = 3;
/// The data's period is looked for within this fraction of the model's.
const PERIOD_SEARCH: f64 = 0.25;
/// Frequencies per 1/span (the periodogram's resolution) in that search.
const PERIOD_OVERSAMPLING: f64 = 8.0;
/// LM gives up after PATIENCE·(p + 1) residual evaluations; each start first runs for
/// RACE_PATIENCE·(p + 1), and only the best goes on.
const PATIENCE: usize = 30;
const RACE_PATIENCE: usize = 5;
/// Step of the central differences: in the internal coordinates, and relative in the physical.
const FD_STEP: f64 = 1e-6;
/// Samples of the model curve drawn in the figure.
const CURVE_SAMPLES: usize = 4000;

/// A woodpecker parameter the fit can adjust.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize, clap::ValueEnum)]
pub enum FitParam {
    #[value(name = "mu_d")]
    MuD,
    #[value(name = "z0")]
    Z0,
    #[value(name = "d0")]
    D0,
    #[value(name = "mu_s")]
    MuS,
    #[value(name = "k")]
    K,
}

impl FitParam {
    /// Fitted unless asked otherwise.
    pub const DEFAULT: [FitParam; 3] = [FitParam::MuD, FitParam::Z0, FitParam::D0];

    pub fn name(self) -> &'static str {
        match self {
            Self::MuD => "mu_d",
            Self::Z0 => "z0",
            Self::D0 => "d0",
            Self::MuS => "mu_s",
            Self::K => "k",
        }
    }

    /// SI unit ("" for the friction coefficients).
    pub fn unit(self) -> &'static str {
        match self {
            Self::MuD | Self::MuS => "",
            Self::Z0 | Self::D0 => "m",
            Self::K => "N/m",
        }
    }

    fn get(self, p: &WoodpeckerParams) -> f64 {
        match self {
            Self::MuD => p.mu_d,
            Self::Z0 => p.z0,
            Self::D0 => p.d0,
            Self::MuS => p.mu_s,
            Self::K => p.k,
        }
    }

    fn set(self, p: &mut WoodpeckerParams, value: f64) {
        match self {
            Self::MuD => p.mu_d = value,
            Self::Z0 => p.z0 = value,
            Self::D0 => p.d0 = value,
            Self::MuS => p.mu_s = value,
            Self::K => p.k = value,
        }
    }

    /// The coordinate LM moves: unbounded, and valid wherever it goes. μd is a fraction of μs
    /// and μs lies between its lower bound ([`Self::mu_s_floor`]) and [`MU_MAX`] (logits).
    fn internal(self, p: &WoodpeckerParams, free: &[FitParam]) -> f64 {
        match self {
            Self::MuD => logit(p.mu_d / p.mu_s),
            Self::MuS => {
                let lo = Self::mu_s_floor(p, free);
                logit((p.mu_s - lo) / (MU_MAX - lo))
            }
            Self::Z0 => p.z0 * 1e3,
            Self::D0 | Self::K => self.get(p).ln(),
        }
    }

    /// Sets the parameter from its internal coordinate (μd after μs, see [`Self::internal`]).
    fn set_internal(self, p: &mut WoodpeckerParams, x: f64, free: &[FitParam]) {
        let value = match self {
            Self::MuD => p.mu_s * logistic(x),
            Self::MuS => {
                let lo = Self::mu_s_floor(p, free);
                lo + (MU_MAX - lo) * logistic(x)
            }
            Self::Z0 => x * 1e-3,
            Self::D0 | Self::K => x.exp(),
        };
        self.set(p, value);
    }

    /// μs must stay above a fixed μd; a free μd follows μs.
    fn mu_s_floor(p: &WoodpeckerParams, free: &[FitParam]) -> f64 {
        if free.contains(&Self::MuD) {
            0.0
        } else {
            p.mu_d
        }
    }

    /// Typical size, for the relative difference step (z0 may be 0: d0 sets its scale).
    fn scale(self, p: &WoodpeckerParams) -> f64 {
        match self {
            Self::Z0 => p.z0.abs().max(p.d0),
            _ => self.get(p).abs(),
        }
    }
}

fn logit(r: f64) -> f64 {
    let r = r.clamp(1e-9, 1.0 - 1e-9);
    (r / (1.0 - r)).ln()
}

fn logistic(x: f64) -> f64 {
    1.0 / (1.0 + (-x).exp())
}

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
    fn sign(self) -> f64 {
        match self {
            Axis::Down => 1.0,
            Axis::Up => -1.0,
        }
    }
}

/// The sleeve along the tracked window: y_S(τ_i) − y_S(τ_1) (m) and v(τ_i) − v(τ_1) (m/s) at
/// τ_i = K T + (t_shift mod T) + dt_i, with dt_i = t_i − t_1 ≥ 0.
#[derive(Clone, Debug, PartialEq)]
pub struct Track {
    pub y: Vec<f64>,
    pub v: Vec<f64>,
}

/// The sleeve's track under the harmonic law of `p` (validated) for the times `dt` after the
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
            periods,
            format!(
                "the tracked span ({span} s) must cover at most {MAX_PERIODS} periods \
                 (T = {period} s)"
            ),
        ));
    }
    let opts = RunOptions {
        periods: periods as u32,
        record_segments: true,
    };
    let law = woodpecker::force_law(p, LawKind::Harmonic)?;
    let run = integrate(&woodpecker::body(p), &law, &opts)?;
    let (y0, v0, _) = state(&run, start)?;
    let mut out = Track {
        y: Vec::with_capacity(dt.len()),
        v: Vec::with_capacity(dt.len()),
    };
    for &d in dt {
        let (y, v, _) = state(&run, start + d)?;
        out.y.push(y - y0);
        out.v.push(v - v0);
    }
    Ok(out)
}

fn state(run: &Run, t: f64) -> Result<(f64, f64, f64)> {
    run.state_at(t).ok_or(Error::Stalled {
        t,
        reason: "tracked time outside the integrated run",
    })
}

/// One fitted value.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Estimate {
    pub name: &'static str,
    /// SI unit ("" when dimensionless).
    pub unit: &'static str,
    pub value: f64,
    /// Standard error; `None` when JᵀJ is singular.
    pub std_error: Option<f64>,
    /// Starting value (the given parameters; for the nuisance, the best phase of the scan).
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
pub struct Fit {
    pub data: Tracked,
    /// Direction of the tracked y (from the data: the toy falls).
    pub axis: Axis,
    /// Tracked points and fitted parameters (nuisance included).
    pub n: usize,
    pub p: usize,
    /// Successful termination of LM and a regular JᵀJ.
    pub converged: bool,
    pub termination: String,
    /// Jacobians computed (LM iterations), residual evaluations, starts tried.
    pub iterations: usize,
    pub evaluations: usize,
    pub starts: usize,
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

/// What LM works on: the data and the fixed parameters.
struct Setup<'a> {
    base: WoodpeckerParams,
    free: &'a [FitParam],
    /// t_i − t_1 (s), positions (m), direction.
    dt: Vec<f64>,
    y: Vec<f64>,
    sign: f64,
}

/// Residuals r_i = model − data (m) at a parameter set, and the speed differences of the
/// track (for the t_shift column of the Jacobian).
struct Eval {
    r: DVector<f64>,
    dv: Vec<f64>,
}

impl Setup<'_> {
    /// The parameters at internal coordinates `x` (free parameters first).
    fn params(&self, x: &[f64]) -> WoodpeckerParams {
        let mut p = self.base;
        let pairs = || self.free.iter().zip(x);
        // μd is a fraction of μs: set it last.
        for (param, &xi) in pairs().filter(|(f, _)| **f != FitParam::MuD) {
            param.set_internal(&mut p, xi, self.free);
        }
        for (param, &xi) in pairs().filter(|(f, _)| **f == FitParam::MuD) {
            param.set_internal(&mut p, xi, self.free);
        }
        p
    }

    fn eval(&self, p: &WoodpeckerParams, shift: f64, y_off: f64) -> Result<Eval> {
        let tr = track(p, shift, &self.dt)?;
        let r = DVector::from_iterator(
            self.y.len(),
            tr.y.iter()
                .zip(&self.y)
                .map(|(m, y)| y_off + self.sign * m - y),
        );
        Ok(Eval { r, dv: tr.v })
    }

    /// Jacobian of the residuals: central differences in the first `free.len()` coordinates of
    /// `at` (steps `steps`, mapped to parameters by `to_params`), exact in t_shift and y_off.
    fn jacobian(
        &self,
        at: &[f64],
        steps: &[f64],
        to_params: impl Fn(&[f64]) -> WoodpeckerParams,
        shift: f64,
        dv: &[f64],
    ) -> Option<DMatrix<f64>> {
        let m = self.y.len();
        let k = self.free.len();
        let mut jac = DMatrix::zeros(m, k + 2);
        let mut x = at.to_vec();
        for j in 0..k {
            let mut side = |h: f64| {
                x[j] = at[j] + h;
                // y_off drops out of the difference.
                self.eval(&to_params(&x), shift, 0.0).ok().map(|e| e.r)
            };
            let (plus, minus) = (side(steps[j])?, side(-steps[j])?);
            x[j] = at[j];
            jac.set_column(j, &((plus - minus) / (2.0 * steps[j])));
        }
        jac.set_column(
            k,
            &DVector::from_iterator(m, dv.iter().map(|v| self.sign * v)),
        );
        jac.column_mut(k + 1).fill(1.0);
        Some(jac)
    }
}

/// The least-squares problem handed to LM: x = (internal free parameters, t_shift, y_off).
struct Problem<'a> {
    setup: &'a Setup<'a>,
    x: DVector<f64>,
    current: Option<Eval>,
    jacobians: Cell<usize>,
}

impl Problem<'_> {
    fn split(&self) -> (&[f64], f64, f64) {
        let k = self.setup.free.len();
        let x = self.x.as_slice();
        (&x[..k], x[k], x[k + 1])
    }
}

impl LeastSquaresProblem<f64, Dyn, Dyn> for Problem<'_> {
    type ResidualStorage = Owned<f64, Dyn>;
    type JacobianStorage = Owned<f64, Dyn, Dyn>;
    type ParameterStorage = Owned<f64, Dyn>;

    fn set_params(&mut self, x: &DVector<f64>) {
        self.x.copy_from(x);
        let (internal, shift, y_off) = self.split();
        let p = self.setup.params(internal);
        self.current = self.setup.eval(&p, shift, y_off).ok();
    }

    fn params(&self) -> DVector<f64> {
        self.x.clone()
    }

    fn residuals(&self) -> Option<DVector<f64>> {
        self.current.as_ref().map(|e| e.r.clone())
    }

    fn jacobian(&self) -> Option<DMatrix<f64>> {
        self.jacobians.set(self.jacobians.get() + 1);
        let (internal, shift, _) = self.split();
        let steps = vec![FD_STEP; internal.len()];
        let dv = &self.current.as_ref()?.dv;
        self.setup
            .jacobian(internal, &steps, |x| self.setup.params(x), shift, dv)
    }
}

/// Runs LM from `x0` for at most `patience`·(p + 1) residual evaluations.
fn minimize(setup: &Setup, x0: DVector<f64>, patience: usize) -> Attempt {
    let lm = LevenbergMarquardt::new()
        .with_ftol(1e-10)
        .with_xtol(1e-10)
        .with_gtol(1e-10)
        .with_stepbound(1.0)
        .with_patience(patience);
    let mut problem = Problem {
        setup,
        x: x0.clone(),
        current: None,
        jacobians: Cell::new(0),
    };
    problem.set_params(&x0);
    let (problem, report) = lm.minimize(problem);
    Attempt {
        rss: problem
            .current
            .as_ref()
            .map_or(f64::INFINITY, |e| e.r.norm_squared()),
        iterations: problem.jacobians.get(),
        evaluations: report.number_of_evaluations,
        termination: report.termination,
        x: problem.x,
    }
}

/// One LM run from one start.
struct Attempt {
    x: DVector<f64>,
    termination: TerminationReason,
    iterations: usize,
    evaluations: usize,
    rss: f64,
}

impl Attempt {
    /// A successful termination beats an unsuccessful one; then the lower residual wins.
    fn beats(&self, other: &Attempt) -> bool {
        match (
            self.termination.was_successful(),
            other.termination.was_successful(),
        ) {
            (true, false) => true,
            (false, true) => false,
            _ => self.rss < other.rss,
        }
    }
}

/// Fits the free parameters of `base` (validated) and the nuisance to `data`.
///
/// Errors: invalid parameters, data that do not descend, or an engine failure at the
/// starting values. A fit that does not converge is returned with `converged: false`.
pub fn fit(data: &Tracked, base: &WoodpeckerParams, free: &[FitParam]) -> Result<Fit> {
    base.validate()?;
    let mut free = free.to_vec();
    free.sort();
    free.dedup();
    let y = data.y_metres();
    let (first, last) = (y[0], y[y.len() - 1]);
    let axis = match last.partial_cmp(&first) {
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
    let setup = Setup {
        base: *base,
        free: &free,
        dt: data.t.iter().map(|t| t - data.t[0]).collect(),
        y,
        sign: axis.sign(),
    };
    let n = setup.y.len();
    let k = free.len();

    let data_period = data_period(&data.t, &setup.y, base.period());
    let starts = starts(&setup, base, data_period)?;
    // A short race from every start, then the leader on to convergence.
    let mut leader: Option<Attempt> = None;
    for start in &starts {
        let mut x0: Vec<f64> = free.iter().map(|f| f.internal(&start.p, &free)).collect();
        x0.extend([start.shift, start.y_off]);
        let attempt = minimize(&setup, DVector::from_vec(x0), RACE_PATIENCE);
        if leader.as_ref().is_none_or(|b| attempt.beats(b)) {
            leader = Some(attempt);
        }
    }
    let leader = leader.ok_or_else(|| Error::NotConverged {
        reason: "the phase scan found no starting point".to_string(),
    })?;
    let best = if leader.termination.was_successful() {
        leader
    } else {
        let more = minimize(&setup, leader.x.clone(), PATIENCE);
        Attempt {
            iterations: leader.iterations + more.iterations,
            evaluations: leader.evaluations + more.evaluations,
            ..more
        }
    };
    let (internal, shift, y_off) = (&best.x.as_slice()[..k], best.x[k], best.x[k + 1]);
    let fitted = setup.params(internal);
    let period = fitted.period();
    let shift = shift.rem_euclid(period);
    let eval = setup.eval(&fitted, shift, y_off)?;
    let rss = eval.r.norm_squared();
    let p_count = k + 2;
    let dof = n.saturating_sub(p_count).max(1) as f64;
    let s2 = rss / dof;

    // Covariance in the physical parameters.
    let theta: Vec<f64> = free.iter().map(|f| f.get(&fitted)).collect();
    let steps: Vec<f64> = free.iter().map(|f| FD_STEP * f.scale(&fitted)).collect();
    let physical = |v: &[f64]| {
        let mut p = fitted;
        for (f, &value) in free.iter().zip(v) {
            f.set(&mut p, value);
        }
        p
    };
    let covariance = setup
        .jacobian(&theta, &steps, physical, shift, &eval.dv)
        .and_then(|j| covariance(&j, s2));
    let converged = best.termination.was_successful() && covariance.is_some();

    let std_error = |i: usize| covariance.as_ref().map(|c| c[(i, i)].sqrt());
    let mut estimates: Vec<Estimate> = free
        .iter()
        .enumerate()
        .map(|(i, f)| Estimate {
            name: f.name(),
            unit: f.unit(),
            value: theta[i],
            std_error: std_error(i),
            start: f.get(base),
            nuisance: false,
        })
        .collect();
    for (i, (name, unit, value, start)) in [
        ("time_shift", "s", shift, starts[0].shift),
        ("y_offset", "m", y_off, starts[0].y_off),
    ]
    .into_iter()
    .enumerate()
    {
        estimates.push(Estimate {
            name,
            unit,
            value,
            std_error: std_error(k + i),
            start,
            nuisance: true,
        });
    }

    let steady = steady_state(&fitted)?;
    let scale = data.unit.metres();
    let residual: Vec<f64> = eval.r.iter().map(|r| r / scale).collect();
    let series = Series {
        t: data.t.clone(),
        y: data.y.clone(),
        model: data.y.iter().zip(&residual).map(|(y, r)| y + r).collect(),
        residual,
        curve: curve(&setup, &fitted, shift, y_off, data)?,
    };
    Ok(Fit {
        data: data.clone(),
        axis,
        n,
        p: p_count,
        converged,
        termination: termination_text(&best.termination, covariance.is_some()),
        iterations: best.iterations,
        evaluations: best.evaluations,
        starts: starts.len(),
        rms_residual: (rss / n as f64).sqrt(),
        residual_variance: s2,
        residual_autocorrelation: eval.r.rows(0, n - 1).dot(&eval.r.rows(1, n - 1)) / rss,
        estimates,
        correlation: covariance.as_ref().map(correlation),
        covariance: covariance.as_ref().map(rows),
        params: fitted,
        period,
        phase: shift / period,
        data_period,
        regime: steady.0,
        v_avg: steady.1,
        series,
    })
}

/// A starting point of LM: parameters, t_shift, y_off, and the residual sum of squares there.
#[derive(Clone, Copy, Debug)]
struct Start {
    p: WoodpeckerParams,
    shift: f64,
    y_off: f64,
    rss: f64,
}

/// The starts of LM: the [`STARTS`] best local minima in phase of a scan of [`PHASE_SCAN`]
/// phases, y_off solved for at each. When k is free the scan runs at two values of k, the
/// given one and the one whose period is the data's ([`data_period`]): k sets the period, and
/// a period off by δT/T drifts by N δT/T periods over N tracked periods, far outside LM's reach
/// when N is large.
fn starts(setup: &Setup, base: &WoodpeckerParams, data_period: f64) -> Result<Vec<Start>> {
    let mut ks = vec![base.k];
    if setup.free.contains(&FitParam::K) {
        // ω ∝ √k in every ω mode.
        ks.push(base.k * (base.period() / data_period).powi(2));
    }
    let mut minima = Vec::new();
    for k in ks {
        let p = WoodpeckerParams { k, ..*base };
        let scan = (0..PHASE_SCAN)
            .map(|j| {
                let shift = p.period() * j as f64 / PHASE_SCAN as f64;
                let tr = track(&p, shift, &setup.dt)?;
                let n = setup.y.len() as f64;
                let offsets = || tr.y.iter().zip(&setup.y).map(|(m, y)| y - setup.sign * m);
                let y_off = offsets().sum::<f64>() / n;
                let rss = offsets().map(|o| (o - y_off).powi(2)).sum();
                Ok(Start {
                    p,
                    shift,
                    y_off,
                    rss,
                })
            })
            .collect::<Result<Vec<_>>>()?;
        // Local minima on the circle of phases.
        let len = scan.len();
        let rss = |j: usize| scan[j % len].rss;
        minima.extend(
            (0..len)
                .filter(|&j| rss(j) <= rss(j + len - 1) && rss(j) <= rss(j + 1))
                .map(|j| scan[j]),
        );
    }
    minima.sort_by(|a, b| a.rss.total_cmp(&b.rss));
    minima.truncate(STARTS);
    Ok(minima)
}

/// The period of the tracked motion: the highest peak of the periodogram of the positions
/// (less their straight-line trend) within ±[`PERIOD_SEARCH`] of the model's period `around`,
/// refined by a parabola through the peak and its neighbours. The sleeve's stick-slip pattern
/// repeats every T, so the peak is at 1/T (the harmonics 2/T, 1/(2T)… lie outside the search).
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

/// s² (JᵀJ)⁻¹, computed with the columns of J scaled to unit length (the parameters differ by
/// orders of magnitude); `None` when a column vanishes or JᵀJ is not positive definite.
fn covariance(j: &DMatrix<f64>, s2: f64) -> Option<DMatrix<f64>> {
    let norms: Vec<f64> = j.column_iter().map(|c| c.norm()).collect();
    if norms.iter().any(|&n| !(n > 0.0 && n.is_finite())) {
        return None;
    }
    let mut scaled = j.clone();
    for (mut col, n) in scaled.column_iter_mut().zip(&norms) {
        col /= *n;
    }
    let inverse = scaled.tr_mul(&scaled).cholesky()?.inverse();
    Some(DMatrix::from_fn(
        inverse.nrows(),
        inverse.ncols(),
        |a, b| s2 * inverse[(a, b)] / (norms[a] * norms[b]),
    ))
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

/// LM's termination in words, and whether the covariance exists.
fn termination_text(t: &TerminationReason, regular: bool) -> String {
    let text = match t {
        TerminationReason::Converged { ftol, xtol } => {
            let which: Vec<&str> = [(*ftol, "ftol"), (*xtol, "xtol")]
                .into_iter()
                .filter_map(|(on, name)| on.then_some(name))
                .collect();
            format!("converged ({})", which.join(", "))
        }
        TerminationReason::Orthogonal => "converged (gtol: gradient vanishes)".to_string(),
        TerminationReason::ResidualsZero => "converged (residuals zero)".to_string(),
        TerminationReason::LostPatience => "stopped: evaluation limit reached".to_string(),
        TerminationReason::NoImprovementPossible(what) => {
            format!("stopped: no further improvement possible ({what})")
        }
        TerminationReason::User(_) => {
            "stopped: the model could not be evaluated at a trial point".to_string()
        }
        TerminationReason::Numerical(what) => format!("stopped: NaN or infinity in {what}"),
        other => format!("stopped: {other:?}"),
    };
    if regular {
        text
    } else {
        format!("{text}; JᵀJ is singular: the data do not determine every free parameter")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fig26() -> WoodpeckerParams {
        WoodpeckerParams {
            mu_d: 0.332,
            k: 20.3,
            d0: 0.0095,
            ..WoodpeckerParams::default()
        }
    }

    #[test]
    fn the_tracked_window_is_periodic_past_the_transient() {
        let p = fig26();
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
    fn every_internal_point_is_a_valid_parameter_set() {
        let all = [
            FitParam::MuD,
            FitParam::Z0,
            FitParam::D0,
            FitParam::MuS,
            FitParam::K,
        ];
        for free in [&all[..], &[FitParam::MuS, FitParam::K][..]] {
            let setup = Setup {
                base: fig26(),
                free,
                dt: Vec::new(),
                y: Vec::new(),
                sign: 1.0,
            };
            let start: Vec<f64> = free.iter().map(|f| f.internal(&fig26(), free)).collect();
            let back = setup.params(&start);
            for f in free {
                let (a, b) = (f.get(&back), f.get(&fig26()));
                assert!((a - b).abs() < 1e-14 * b.abs(), "{f:?} round trip: {a} {b}");
            }
            for x in [-30.0, -1.0, 0.0, 2.0, 30.0] {
                let p = setup.params(&vec![x; free.len()]);
                p.validate()
                    .unwrap_or_else(|e| panic!("{free:?} at {x}: {e}"));
            }
        }
    }

    #[test]
    fn the_exact_shift_column_agrees_with_differences() {
        let p = fig26();
        let dt: Vec<f64> = (0..300).map(|i| f64::from(i) / 240.0).collect();
        let setup = Setup {
            base: p,
            free: &[FitParam::MuD],
            dt,
            y: vec![0.0; 300],
            sign: -1.0,
        };
        let shift = 0.05;
        let e = setup.eval(&p, shift, 0.0).unwrap();
        let x = [FitParam::MuD.internal(&p, setup.free)];
        let jac = setup
            .jacobian(&x, &[FD_STEP], |x| setup.params(x), shift, &e.dv)
            .unwrap();
        let h = 1e-7;
        let plus = setup.eval(&p, shift + h, 0.0).unwrap().r;
        let minus = setup.eval(&p, shift - h, 0.0).unwrap().r;
        let fd = (plus - minus) / (2.0 * h);
        let scale = fd.amax();
        assert!((jac.column(1) - fd).amax() < 1e-5 * scale);
        assert!(jac.column(2).iter().all(|&c| c == 1.0));
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

    #[test]
    fn covariance_of_a_straight_line_is_the_textbook_one() {
        // y = a + b t at t = 0..4: var(b) = s²/Σ(t − t̄)², var(a) = s² Σt²/(n Σ(t − t̄)²).
        let t = [0.0, 1.0, 2.0, 3.0, 4.0];
        let j = DMatrix::from_fn(5, 2, |i, c| if c == 0 { 1.0 } else { t[i] });
        let c = covariance(&j, 2.0).unwrap();
        let sxx = 10.0;
        assert!((c[(1, 1)] - 2.0 / sxx).abs() < 1e-14);
        assert!((c[(0, 0)] - 2.0 * 30.0 / (5.0 * sxx)).abs() < 1e-14);
        assert!((c[(0, 1)] + 2.0 * 2.0 / sxx).abs() < 1e-14);
        let singular = DMatrix::from_fn(5, 2, |i, _| t[i]);
        assert!(covariance(&singular, 1.0).is_none());
    }
}
