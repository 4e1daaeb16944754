//! Levenberg–Marquardt on the tracked data (the `levenberg-marquardt` crate: MINPACK's
//! algorithm on nalgebra), its starting points, and the standard errors.
//!
//! ```text
//! x        (internal coordinates of the free parameters, t_shift, y_off)       param.rs
//! r_i      y_off + s [y_S(τ_i) − y_S(τ_1)] − y_i   (m)                             model.rs
//! J        central differences in the parameters, exact in t_shift (s Δv_i) and y_off (1)
//! centres  the given parameters, then a fixed spread around them (SPREAD, ±15 %)  spread()
//! starts   at each centre, the best local minima of a scan of phases (also at the data's k
//!          when k is free): 3 at the given parameters, 1 at each other centre
//! race     a few LM steps from each start (in parallel over the centres)
//! finish   the given start's leader and the 3 best other leaders go on to convergence
//! best     the lowest residual, continued if it has not converged; the earliest converged
//!          centre among equals, so a fit the given start already solves is unchanged
//! errors   cov = s² (JᵀJ)⁻¹, s² = RSS/(n − p), J in the physical parameters at the optimum
//! ```
//!
//! Why several centres: the residual is multimodal in (μd, z0, d0). Stick and slip times move
//! with the parameters, and a start ~10 % off in μd can sit in the basin of a minimum where a
//! stick of the model faces a slip of the data (RMS 7σ, residuals autocorrelated at 0.96) —
//! SciPy's `least_squares` from the same start ends there too. A local method cannot tell;
//! starting from several points and keeping the best can, and `verdict.rs` says when even the
//! best does not describe the data.
//!
//! Non-smoothness: slip and stick times move with the parameters, but y is C¹ in them away
//! from a change of regime: at a stick v = 0, so moving the stick time leaves y unchanged to
//! first order, and at a slip onset only the acceleration jumps. Central differences with a
//! relative step of 1e-6 are therefore accurate (the engine resolves events to ~1e-15).

use std::cell::Cell;

use rayon::prelude::*;

use levenberg_marquardt::{LeastSquaresProblem, LevenbergMarquardt, TerminationReason};
use nalgebra::{storage::Owned, DMatrix, DVector, Dyn};

use super::model::track;
use super::param::{from_internal, to_internal, with_values, FitParam};
use crate::error::{Error, Result};
use crate::models::woodpecker::WoodpeckerParams;

/// Phases t_shift = jT/PHASE_SCAN tried before the fit.
pub const PHASE_SCAN: usize = 24;
/// Starts raced, from the best local minima of the phase scan.
pub const STARTS: usize = 3;
/// LM gives up after PATIENCE·(p + 1) residual evaluations; each start first runs for
/// RACE_PATIENCE·(p + 1), and only the best goes on.
const PATIENCE: usize = 30;
const RACE_PATIENCE: usize = 5;
/// Most row evaluations of the model (tracks × data rows) that LM spends over all its starts:
/// about 600 tracks of 10^5 rows, a few seconds, and never binding for a few thousand rows.
pub const WORK_BUDGET: usize = 60_000_000;
/// Tracks each centre's LM runs may spend at least: the centres of the spread are used only
/// as far as the budget gives each this much (all of them below ~5000 rows, only the given
/// start at 10^5 rows).
const RUN_TRACKS: usize = 600;
/// Phase-scan starts raced at each centre of the spread (the given start races [`STARTS`]).
const SPREAD_STARTS: usize = 1;
/// Runs that go on to convergence after the race: the given start's and the best others'.
const FINALISTS: usize = 4;
/// Relative spread of the centres around the given values (z0: of max(|z0|, d0), its scale).
pub const SPREAD: f64 = 0.15;
/// Two runs whose residual sums of squares agree to this relative tolerance ended in the same
/// minimum.
const SAME_MINIMUM: f64 = 1e-6;
/// Step of the central differences: in the internal coordinates, and relative in the physical.
const FD_STEP: f64 = 1e-6;

/// The problem: the data, the fixed parameters and which ones are free.
pub struct Setup<'a> {
    pub base: WoodpeckerParams,
    pub free: &'a [FitParam],
    /// t_i − t_1 (s) and positions (m).
    pub dt: Vec<f64>,
    pub y: Vec<f64>,
    /// [`super::Axis::sign`] of the data.
    pub sign: f64,
}

/// The outcome of [`solve`].
pub struct Solution {
    pub params: WoodpeckerParams,
    /// t_shift ∈ [0, T) (s) and y_off (m).
    pub shift: f64,
    pub y_off: f64,
    /// model − data (m) at the tracked times.
    pub residuals: DVector<f64>,
    /// s² = RSS/(n − p) (m²) and the covariance of (free parameters, t_shift, y_off).
    pub s2: f64,
    pub covariance: Option<DMatrix<f64>>,
    pub termination: TerminationReason,
    /// LM stopped because [`WORK_BUDGET`] was spent.
    pub exhausted: bool,
    /// Of the winning start: Jacobians (LM iterations) and residual evaluations.
    pub iterations: usize,
    pub evaluations: usize,
    /// Starts raced over all the centres; centres tried, and how many of them ended in the
    /// winner's minimum.
    pub starts: usize,
    pub centres: usize,
    pub at_best: usize,
    /// The nuisance values the winner started from.
    pub start_shift: f64,
    pub start_y_off: f64,
}

/// Fits `setup`'s free parameters and the nuisance; `data_period` (s) starts k when it is free.
pub fn solve(setup: &Setup, data_period: f64) -> Result<Solution> {
    let tracks = WORK_BUDGET / setup.y.len().max(1);
    let centres = spread(&setup.base, setup.free);
    let used = (tracks / RUN_TRACKS).clamp(1, centres.len());
    // One share more than the centres: for continuing the winner if it has not converged.
    let share = tracks / (used + 1);
    let mut runs: Vec<Option<Run>> = centres[..used]
        .par_iter()
        .enumerate()
        .map(|(i, centre)| {
            let n_starts = if i == 0 { STARTS } else { SPREAD_STARTS };
            race_at(setup, centre, data_period, n_starts, share)
        })
        .collect::<Result<_>>()?;
    // The given start's run goes on, as it always did (its fit is unchanged when it wins), and
    // so do the best of the others after the race (the earlier centre among equals).
    let raced = |i: usize| runs[i].as_ref().map_or(f64::INFINITY, |r| r.best.rss);
    let mut finalists: Vec<usize> = (1..runs.len()).collect();
    finalists.sort_by(|&a, &b| raced(a).total_cmp(&raced(b)));
    finalists.truncate(FINALISTS - 1);
    finalists.push(0);
    runs.par_iter_mut()
        .enumerate()
        .filter(|(i, _)| finalists.contains(i))
        .for_each(|(_, run)| {
            if let Some(run) = run {
                finish(setup, run);
            }
        });
    let mut runs: Vec<Run> = runs.into_iter().flatten().collect();
    let rss = runs
        .iter()
        .map(|r| r.best.rss)
        .min_by(f64::total_cmp)
        .ok_or_else(|| Error::NotConverged {
            reason: "the phase scan found no starting point".to_string(),
        })?;
    // Across centres the lowest residual wins, converged or not: a run that ran out of
    // patience near the data beats one that converged far from them. Among the runs at that
    // minimum the earliest converged one is kept, so a fit the given start solves keeps the
    // given start's numbers to the last bit.
    let same = |r: &Run| (r.best.rss - rss).abs() <= SAME_MINIMUM * rss || r.best.rss == rss;
    let at_best = runs.iter().filter(|r| same(r)).count();
    let (centres, starts) = (runs.len(), runs.iter().map(|r| r.starts).sum());
    let chosen = runs
        .iter()
        .position(|r| same(r) && r.best.termination.was_successful())
        .or_else(|| runs.iter().position(same))
        .unwrap_or(0);
    let Run {
        best,
        start,
        exhausted,
        ..
    } = runs.swap_remove(chosen);
    let (best, exhausted) = if best.termination.was_successful() {
        (best, exhausted)
    } else {
        let budget = Budget(Cell::new(share));
        let more = minimize(setup, best.x.clone(), PATIENCE, &budget);
        let exhausted = budget.0.get() == 0 && !more.termination.was_successful();
        let more = Attempt {
            iterations: best.iterations + more.iterations,
            evaluations: best.evaluations + more.evaluations,
            ..more
        };
        (more, exhausted)
    };

    let k = setup.free.len();
    let params = setup.params(&best.x.as_slice()[..k]);
    let (shift, y_off) = (best.x[k].rem_euclid(params.period()), best.x[k + 1]);
    // LM only moves inside the transformed coordinates, yet they can saturate (d0 = e^x
    // underflowing to 0 when the fixed parameters cannot describe the data at all).
    let eval = setup
        .eval(&params, shift, y_off)
        .map_err(|e| Error::NotConverged {
            reason: format!(
                "the search left the model's range ({}); check the fixed parameters and the \
                 units of the file",
                crate::error::excerpt(&e.to_string(), 100)
            ),
        })?;
    let n = setup.y.len();
    let s2 = eval.r.norm_squared() / n.saturating_sub(k + 2).max(1) as f64;
    // The errors of the physical parameters, not of their internal coordinates.
    let values: Vec<f64> = setup.free.iter().map(|f| f.get(&params)).collect();
    let steps: Vec<f64> = setup
        .free
        .iter()
        .map(|f| FD_STEP * f.scale(&params))
        .collect();
    let physical = |v: &[f64]| with_values(&params, setup.free, v);
    let covariance = setup
        .jacobian(&values, &steps, physical, shift, &eval.dv)
        .and_then(|j| covariance(&j, s2));
    Ok(Solution {
        params,
        shift,
        y_off,
        residuals: eval.r,
        s2,
        covariance,
        exhausted,
        termination: best.termination,
        iterations: best.iterations,
        evaluations: best.evaluations,
        starts,
        centres,
        at_best,
        start_shift: start.shift,
        start_y_off: start.y_off,
    })
}

/// The outcome of LM from one centre: the best attempt, the start it came from, whether the
/// centre's budget stopped it, and how many starts were raced.
struct Run {
    best: Attempt,
    start: Start,
    exhausted: bool,
    starts: usize,
    /// Model tracks left of its budget.
    left: usize,
}

/// The race at `centre`: a few LM steps from each of its `n_starts` best phase-scan starts,
/// with its own budget of `tracks` model tracks (independent of the other centres: the same
/// result in parallel as in sequence); `None` when the scan finds no start.
fn race_at(
    setup: &Setup,
    centre: &WoodpeckerParams,
    data_period: f64,
    n_starts: usize,
    tracks: usize,
) -> Result<Option<Run>> {
    let mut starts = starts(setup, centre, data_period)?;
    starts.truncate(n_starts);
    let budget = Budget(Cell::new(tracks));
    let mut leader: Option<(Attempt, &Start)> = None;
    for start in &starts {
        let mut x0 = to_internal(&start.p, setup.free);
        x0.extend([start.shift, start.y_off]);
        let attempt = minimize(setup, DVector::from_vec(x0), RACE_PATIENCE, &budget);
        if leader.as_ref().is_none_or(|(b, _)| attempt.beats(b)) {
            leader = Some((attempt, start));
        }
    }
    Ok(leader.map(|(best, start)| Run {
        best,
        start: *start,
        exhausted: false,
        starts: starts.len(),
        left: budget.0.get(),
    }))
}

/// A raced run goes on to convergence (at most [`PATIENCE`]), on what is left of its budget.
fn finish(setup: &Setup, run: &mut Run) {
    if run.best.termination.was_successful() {
        return;
    }
    let budget = Budget(Cell::new(run.left));
    let more = minimize(setup, run.best.x.clone(), PATIENCE, &budget);
    run.exhausted = budget.0.get() == 0 && !more.termination.was_successful();
    run.left = budget.0.get();
    run.best = Attempt {
        iterations: run.best.iterations + more.iterations,
        evaluations: run.best.evaluations + more.evaluations,
        ..more
    };
}

/// The centres LM starts from: `base` itself, then each free physical parameter alone at
/// ±[`SPREAD`], then the corners of the ±[`SPREAD`] box of the first three free ones (μd, z0,
/// d0 by default: 15 centres in all). A fixed design, so the fit is deterministic; centres
/// outside the valid parameters (μd above μs) are left out.
fn spread(base: &WoodpeckerParams, free: &[FitParam]) -> Vec<WoodpeckerParams> {
    let shifted = |moves: &[(FitParam, f64)]| {
        let mut p = *base;
        for &(f, sign) in moves {
            let value = f.get(base) + sign * SPREAD * f.scale(base);
            f.set(&mut p, value);
        }
        p
    };
    let mut centres = vec![*base];
    for &f in free {
        for sign in [-1.0, 1.0] {
            centres.push(shifted(&[(f, sign)]));
        }
    }
    let corner_axes = &free[..free.len().min(3)];
    if corner_axes.len() > 1 {
        for corner in 0..1usize << corner_axes.len() {
            let moves: Vec<(FitParam, f64)> = corner_axes
                .iter()
                .enumerate()
                .map(|(i, &f)| (f, if corner >> i & 1 == 1 { 1.0 } else { -1.0 }))
                .collect();
            centres.push(shifted(&moves));
        }
    }
    centres.retain(|p| p.validate().is_ok());
    centres
}

/// Residuals r_i = model − data (m) at a parameter set, and the speed differences of the
/// track (the t_shift column of the Jacobian).
struct Eval {
    r: DVector<f64>,
    dv: Vec<f64>,
}

impl Setup<'_> {
    /// The parameters at internal coordinates `x`.
    fn params(&self, x: &[f64]) -> WoodpeckerParams {
        from_internal(&self.base, self.free, x)
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

    /// Jacobian of the residuals: central differences in the coordinates `at` of the free
    /// parameters (steps `steps`, mapped to parameters by `to_params`), exact in t_shift and
    /// y_off. `None` if the model cannot be evaluated at a step.
    fn jacobian(
        &self,
        at: &[f64],
        steps: &[f64],
        to_params: impl Fn(&[f64]) -> WoodpeckerParams,
        shift: f64,
        dv: &[f64],
    ) -> Option<DMatrix<f64>> {
        let m = self.y.len();
        let k = at.len();
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
        let shift_column = DVector::from_iterator(m, dv.iter().map(|v| self.sign * v));
        jac.set_column(k, &shift_column);
        jac.column_mut(k + 1).fill(1.0);
        Some(jac)
    }
}

/// The least-squares problem handed to LM: x = (internal free parameters, t_shift, y_off).
struct Problem<'a> {
    setup: &'a Setup<'a>,
    x: DVector<f64>,
    /// The evaluation at x; `None` where the model cannot be evaluated (LM then stops).
    current: Option<Eval>,
    jacobians: Cell<usize>,
    budget: &'a Budget,
}

/// The model tracks LM may still compute; 0 once a request did not fit.
struct Budget(Cell<usize>);

impl Budget {
    /// Takes `tracks` from the budget; `false` (and the budget emptied) if they do not fit.
    fn spend(&self, tracks: usize) -> bool {
        let left = self.0.get();
        self.0.set(left.saturating_sub(tracks));
        left >= tracks && left > 0
    }
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
        self.current = if self.budget.spend(1) {
            self.setup.eval(&p, shift, y_off).ok()
        } else {
            None
        };
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
        if !self.budget.spend(2 * internal.len()) {
            return None;
        }
        self.setup
            .jacobian(internal, &steps, |x| self.setup.params(x), shift, dv)
    }
}

/// One LM run.
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

/// Runs LM from `x0` for at most `patience`·(p + 1) residual evaluations.
fn minimize(setup: &Setup, x0: DVector<f64>, patience: usize, budget: &Budget) -> Attempt {
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
        budget,
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

/// A starting point of LM: parameters, t_shift, y_off, and the residual sum of squares there.
#[derive(Clone, Copy, Debug)]
struct Start {
    p: WoodpeckerParams,
    shift: f64,
    y_off: f64,
    rss: f64,
}

/// The starts of LM at `base`: the [`STARTS`] best local minima in phase of a scan of [`PHASE_SCAN`]
/// phases, y_off solved for at each. When k is free the scan runs at two values of k, the
/// given one and the one whose period is the data's: k sets the period, and a period off by
/// δT/T drifts by N δT/T periods over N tracked periods, out of LM's reach when N is large.
fn starts(setup: &Setup, base: &WoodpeckerParams, data_period: f64) -> Result<Vec<Start>> {
    let base = *base;
    let mut ks = vec![base.k];
    if setup.free.contains(&FitParam::K) {
        // ω ∝ √k in every ω mode.
        ks.push(base.k * (base.period() / data_period).powi(2));
    }
    let n = setup.y.len() as f64;
    let mut minima = Vec::new();
    for k in ks {
        let p = WoodpeckerParams { k, ..base };
        let scan = (0..PHASE_SCAN)
            .map(|j| {
                let shift = p.period() * j as f64 / PHASE_SCAN as f64;
                let tr = track(&p, shift, &setup.dt)?;
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

/// LM's termination in words; `exhausted`: whether [`WORK_BUDGET`] stopped it; `regular`:
/// whether JᵀJ could be inverted.
pub fn termination_text(t: &TerminationReason, exhausted: bool, regular: bool) -> String {
    let text = match t {
        _ if exhausted => "stopped: work limit reached".to_string(),
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
    match text.strip_prefix("converged ") {
        _ if regular => text,
        // A minimum with a singular JᵀJ is no convergence: say where the search stopped.
        Some(test) => format!(
            "stopped on its test {test} where JᵀJ is singular: the data do not determine every \
             free parameter"
        ),
        None => format!("{text}; JᵀJ is singular: the data do not determine every free parameter"),
    }
}

#[cfg(test)]
mod tests {

    #[test]
    fn a_minimum_with_a_singular_jtj_is_not_called_converged() {
        let ftol = TerminationReason::Converged {
            ftol: true,
            xtol: false,
        };
        assert_eq!(termination_text(&ftol, false, true), "converged (ftol)");
        let singular = termination_text(&ftol, false, false);
        assert!(!singular.contains("converged"), "{singular}");
        assert!(singular.starts_with("stopped on its test (ftol) where JᵀJ is singular"));
    }
    use super::*;

    #[test]
    fn the_exact_shift_column_agrees_with_differences() {
        let p = crate::models::woodpecker::lever::fig26();
        let setup = Setup {
            base: p,
            free: &[FitParam::MuD],
            dt: (0..300).map(|i| f64::from(i) / 240.0).collect(),
            y: vec![0.0; 300],
            sign: -1.0,
        };
        let shift = 0.05;
        let e = setup.eval(&p, shift, 0.0).unwrap();
        let x = to_internal(&p, setup.free);
        let jac = setup
            .jacobian(&x, &[FD_STEP], |x| setup.params(x), shift, &e.dv)
            .unwrap();
        let h = 1e-7;
        let plus = setup.eval(&p, shift + h, 0.0).unwrap().r;
        let minus = setup.eval(&p, shift - h, 0.0).unwrap().r;
        let fd = (plus - minus) / (2.0 * h);
        assert!((jac.column(1) - &fd).amax() < 1e-5 * fd.amax());
        assert!(jac.column(2).iter().all(|&c| c == 1.0));
    }

    #[test]
    fn the_budget_refuses_what_does_not_fit_and_stays_spent() {
        let budget = Budget(Cell::new(10));
        assert!(budget.spend(4));
        assert!(budget.spend(6));
        assert!(!budget.spend(1));
        let budget = Budget(Cell::new(5));
        assert!(!budget.spend(6));
        assert!(!budget.spend(1));
        assert!(termination_text(&TerminationReason::User("x"), true, true).contains("work limit"));
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
