//! The work-precision sweep (the DiffEqDevTools protocol): for each method and problem, each
//! accuracy setting is run once untimed (its result gives the errors), then timed sequentially
//! as the minimum of N runs; the work is the method's own count of rhs evaluations.
//!
//! ```text
//! adaptive     tolerance 1e-3, 1e-4, …, 1e-12
//! fixed-step   steps per period n = 10^(1 + k/2), k = 0…8  (10 … 10^5), h = T/n
//! errors       max |t_i − t_i,exact| over events matched in order (slip/stick only),
//!              |x(t_end) − x_exact|,  |v̄ − v̄_exact| with v̄ = (x(t_end) − x(t_end − T))/T
//!              (not on the belt, which returns to the same place each cycle)
//! refusal      a method that does not take a problem (the belt, for a method of forces of
//!              time only) gives one point of status "refused" with its reason
//! time         warm-up, then min of N runs (one run when a run exceeds 1 s)
//! ```
//! `std::time::Instant` is used here only: this is the tool's benchmark command, and timings
//! never enter the tests.

use std::hint::black_box;
use std::time::{Duration, Instant};

use serde::{Deserialize, Serialize};

use super::problems::{is_refusal, transitions, Reference, SweepProblem};
use crate::solver::{Method, MethodEvent, Setting, Solution};

/// The status of a point whose method does not take its problem.
pub const REFUSED: &str = "refused";

/// A run longer than this is timed once (the protocol's "fewer if one run exceeds 1 s").
pub const LONG_RUN: Duration = Duration::from_secs(1);

/// How a method is driven: by a tolerance, a step, or not at all (the exact reference).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum MethodKind {
    Reference,
    Adaptive,
    FixedStep,
}

impl MethodKind {
    /// Words for tables.
    pub fn label(self) -> &'static str {
        match self {
            MethodKind::Reference => "reference",
            MethodKind::Adaptive => "adaptive",
            MethodKind::FixedStep => "fixed step",
        }
    }
}

/// The kind of a method of the registry, by name: the fixed-step methods of the issue, the
/// exact reference, and adaptive for everything else (dopri5, its endpoint-only variant, the
/// diffsol peer and the tanh methods).
pub fn method_kind(name: &str) -> MethodKind {
    match name {
        "exact" => MethodKind::Reference,
        "rk4" | "moreau" | "euler_sign" => MethodKind::FixedStep,
        _ => MethodKind::Adaptive,
    }
}

/// True for the compiled peers of the exact engine (issue 14): the adaptive integrators of the
/// Coulomb model itself (no regularization) on the shared stick/slip event loop, i.e. the
/// tool's dopri5, its endpoint-only variant and the diffsol peer.
pub fn is_compiled_peer(name: &str) -> bool {
    name == "dopri5"
        || name == super::failure_table::ENDPOINTS
        || name == crate::solver::DIFFSOL_PEER
}

/// The accuracy settings of a sweep.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Grid {
    /// Tolerances of the adaptive methods.
    pub tolerances: Vec<f64>,
    /// Steps per period of the fixed-step methods.
    pub steps_per_period: Vec<u32>,
}

impl Grid {
    /// The default sweep: tolerances 1e-3 … 1e-12 by decades, 10 … 10^5 steps per period by
    /// half decades.
    pub fn full() -> Self {
        Self {
            tolerances: (3..=12).map(|k| 10f64.powi(-k)).collect(),
            steps_per_period: (0..=8)
                .map(|k| 10f64.powf(1.0 + 0.5 * f64::from(k)).round() as u32)
                .collect(),
        }
    }

    /// The reduced sweep of `--quick`: three settings per method.
    pub fn quick() -> Self {
        Self {
            tolerances: vec![1e-3, 1e-6, 1e-9],
            steps_per_period: vec![100, 1_000, 10_000],
        }
    }

    /// The settings of a method of the given kind on a problem of period `period` (s).
    pub fn settings(&self, kind: MethodKind, period: f64) -> Vec<Setting> {
        match kind {
            MethodKind::Reference => vec![Setting::Tolerance(super::problems::REFERENCE_TOLERANCE)],
            MethodKind::Adaptive => self
                .tolerances
                .iter()
                .map(|&t| Setting::Tolerance(t))
                .collect(),
            MethodKind::FixedStep => self
                .steps_per_period
                .iter()
                .map(|&n| Setting::Step(period / f64::from(n)))
                .collect(),
        }
    }
}

/// One point of the sweep: a method on a problem at one setting (SI units; `None` where a
/// quantity does not exist, e.g. every error of a method that returned an error).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct SweepPoint {
    pub problem: String,
    pub method: String,
    /// "tolerance", "step" or "none" (the exact engine ignores its setting).
    pub setting_kind: String,
    pub tolerance: Option<f64>,
    pub h_s: Option<f64>,
    pub steps_per_period: Option<f64>,
    /// "ok"; "error" with the method's message in `error`; or "refused" with its reason there
    /// (a problem the method does not take: one point, whatever the setting).
    pub status: String,
    pub error: Option<String>,
    /// Median wall time over `runs` timed runs (s); for the exact engine, of `integrate`
    /// alone ([`crate::solver::Method::solve_timed`]).
    pub time_s: Option<f64>,
    /// The fastest and the slowest of those runs (s): the spread of the timing.
    #[serde(default)]
    pub time_min_s: Option<f64>,
    #[serde(default)]
    pub time_max_s: Option<f64>,
    pub runs: u32,
    pub rhs_evals: Option<u64>,
    pub steps: Option<u64>,
    pub accepted: Option<u64>,
    pub rejected: Option<u64>,
    /// Slip and stick events found, exact count, and how many were compared in order.
    pub n_events: Option<usize>,
    pub n_events_exact: usize,
    pub n_matched: Option<usize>,
    /// Matched pairs whose kinds (slip/stick) differ.
    pub kind_mismatches: Option<usize>,
    /// Velocity reversals reported (none exist in the exact solutions of these problems).
    pub reversals: Option<usize>,
    pub err_event_s: Option<f64>,
    pub err_x_m: Option<f64>,
    pub err_vbar_m_s: Option<f64>,
    pub x_end_m: Option<f64>,
    pub v_end_m_s: Option<f64>,
}

impl SweepPoint {
    /// True when the method returned a solution.
    pub fn ok(&self) -> bool {
        self.status == "ok"
    }

    /// True when the method does not take the problem.
    pub fn refused(&self) -> bool {
        self.status == REFUSED
    }

    /// Events found differ in number from the exact ones.
    pub fn count_mismatch(&self) -> bool {
        self.n_events.is_some_and(|n| n != self.n_events_exact)
    }
}

/// Events compared in order: the i-th slip/stick of the method against the i-th exact one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EventMatch {
    pub n_method: usize,
    pub n_exact: usize,
    /// Length of the compared prefix, min(n_method, n_exact).
    pub matched: usize,
    /// Largest |t − t_exact| over the prefix (s); `None` for an empty prefix.
    pub max_err: Option<f64>,
    pub kind_mismatches: usize,
}

/// Compares two event lists in order (if the counts differ, the matched prefix is used and the
/// mismatch is visible in the counts).
pub fn match_events(got: &[MethodEvent], exact: &[MethodEvent]) -> EventMatch {
    let matched = got.len().min(exact.len());
    let pairs = got.iter().zip(exact);
    let max_err = pairs
        .clone()
        .map(|(a, b)| (a.t - b.t).abs())
        .fold(None, |m: Option<f64>, e| Some(m.map_or(e, |m| m.max(e))));
    EventMatch {
        n_method: got.len(),
        n_exact: exact.len(),
        matched,
        max_err,
        kind_mismatches: pairs.filter(|(a, b)| a.kind != b.kind).count(),
    }
}

/// Describes a setting as (kind, tolerance, h, steps per period).
fn describe(
    kind: MethodKind,
    setting: Setting,
    period: f64,
) -> (&'static str, Option<f64>, Option<f64>, Option<f64>) {
    match (kind, setting) {
        (MethodKind::Reference, _) => ("none", None, None, None),
        (_, Setting::Tolerance(t)) => ("tolerance", Some(t), None, None),
        (_, Setting::Step(h)) => ("step", None, Some(h), Some(period / h)),
    }
}

/// The timed runs of one setting: their median and extremes (s).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timing {
    pub median_s: f64,
    pub min_s: f64,
    pub max_s: f64,
    pub runs: u32,
}

/// `repeats` timed runs of [`Method::solve_timed`] after the untimed one that took `first`; a
/// run longer than [`LONG_RUN`] ends the series.
fn time_runs(
    method: &dyn Method,
    problem: &SweepProblem,
    setting: Setting,
    first: Duration,
    repeats: u32,
) -> Timing {
    let n = if first > LONG_RUN { 1 } else { repeats.max(1) };
    let mut times = Vec::with_capacity(n as usize);
    for _ in 0..n {
        let start = Instant::now();
        let out = black_box(problem).solve_timed(method, black_box(setting));
        let took = start.elapsed();
        black_box(out).ok();
        times.push(took.as_secs_f64());
        if took > LONG_RUN {
            break;
        }
    }
    summarize(times)
}

/// The median, extremes and count of the run times `times` (s, at least one).
fn summarize(mut times: Vec<f64>) -> Timing {
    times.sort_by(f64::total_cmp);
    let mid = times.len() / 2;
    let median_s = if times.len() % 2 == 1 {
        times[mid]
    } else {
        0.5 * (times[mid - 1] + times[mid])
    };
    Timing {
        median_s,
        min_s: times[0],
        max_s: times[times.len() - 1],
        runs: times.len() as u32,
    }
}

/// Runs one point of the sweep. A method's error is recorded in the point, never propagated;
/// a refusal is recorded as such ([`REFUSED`]).
pub fn measure(
    method: &dyn Method,
    bp: &SweepProblem,
    reference: &Reference,
    setting: Setting,
    repeats: u32,
) -> SweepPoint {
    let kind = method_kind(method.name());
    let (setting_kind, tolerance, h_s, steps_per_period) = describe(kind, setting, bp.period());
    let mut point = SweepPoint {
        problem: bp.id().to_string(),
        method: method.name().to_string(),
        setting_kind: setting_kind.to_string(),
        tolerance,
        h_s,
        steps_per_period,
        status: "error".to_string(),
        error: None,
        time_s: None,
        time_min_s: None,
        time_max_s: None,
        runs: 0,
        rhs_evals: None,
        steps: None,
        accepted: None,
        rejected: None,
        n_events: None,
        n_events_exact: reference.events.len(),
        n_matched: None,
        kind_mismatches: None,
        reversals: None,
        err_event_s: None,
        err_x_m: None,
        err_vbar_m_s: None,
        x_end_m: None,
        v_end_m_s: None,
    };
    let start = Instant::now();
    let first = bp.solve(method, setting);
    let took = start.elapsed();
    let sol = match first {
        Ok(sol) => sol,
        Err(e) => {
            if is_refusal(&e) {
                point.status = REFUSED.to_string();
            }
            point.error = Some(e.to_string());
            return point;
        }
    };
    let timing = time_runs(method, bp, setting, took, repeats);
    let shorter = bp
        .solve_one_period_shorter(method, setting)
        .and_then(|r| r.ok());
    fill(&mut point, &sol, shorter.as_ref(), reference, bp.period());
    point.time_s = Some(timing.median_s);
    point.time_min_s = Some(timing.min_s);
    point.time_max_s = Some(timing.max_s);
    point.runs = timing.runs;
    point
}

/// Fills the errors and the work of a successful point.
fn fill(
    point: &mut SweepPoint,
    sol: &Solution,
    shorter: Option<&Solution>,
    reference: &Reference,
    period: f64,
) {
    let m = match_events(&transitions(&sol.events), &reference.events);
    point.status = "ok".to_string();
    point.rhs_evals = Some(sol.stats.rhs_evals);
    point.steps = Some(sol.stats.steps);
    point.accepted = Some(sol.stats.accepted);
    point.rejected = Some(sol.stats.rejected);
    point.n_events = Some(m.n_method);
    point.n_matched = Some(m.matched);
    point.kind_mismatches = Some(m.kind_mismatches);
    point.reversals = Some(reversals(sol));
    point.err_event_s = m.max_err;
    point.err_x_m = finite((sol.x_end - reference.x_end_m).abs());
    point.err_vbar_m_s = shorter
        .zip(reference.vbar_m_s)
        .and_then(|(s, vbar)| finite(((sol.x_end - s.x_end) / period - vbar).abs()));
    point.x_end_m = finite(sol.x_end);
    point.v_end_m_s = finite(sol.v_end);
}

/// Velocity reversals a method reports (events of kind "reversal").
pub fn reversals(sol: &Solution) -> usize {
    sol.events.iter().filter(|e| e.kind == "reversal").count()
}

/// `Some(x)` for a finite x (serde_json would write NaN as null anyway; this makes it explicit).
pub fn finite(x: f64) -> Option<f64> {
    x.is_finite().then_some(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ev(t: f64, kind: &'static str) -> MethodEvent {
        MethodEvent { t, kind }
    }

    #[test]
    fn events_are_matched_in_order_on_the_common_prefix() {
        let exact = [ev(1.0, "slip"), ev(2.0, "stick"), ev(3.0, "slip")];
        let got = [ev(1.1, "slip"), ev(1.95, "slip")];
        let m = match_events(&got, &exact);
        assert_eq!((m.n_method, m.n_exact, m.matched), (2, 3, 2));
        assert!((m.max_err.unwrap() - 0.1).abs() < 1e-12);
        assert_eq!(m.kind_mismatches, 1);
        assert_eq!(match_events(&[], &exact).max_err, None);
    }

    /// A method whose timed runs take 1, 2, … ms in turn (the untimed first run aside).
    struct Slower(std::sync::atomic::AtomicU64);

    impl Method for Slower {
        fn name(&self) -> &'static str {
            "slower"
        }
        fn solve(&self, _: &crate::solver::Problem, _: Setting) -> crate::error::Result<Solution> {
            unreachable!("only the timed runs are called")
        }
        fn solve_timed(&self, _: &crate::solver::Problem, _: Setting) -> crate::error::Result<()> {
            let n = self.0.fetch_add(1, std::sync::atomic::Ordering::Relaxed) + 1;
            std::thread::sleep(Duration::from_millis(10 * n));
            Ok(())
        }
    }

    #[test]
    fn timing_is_the_median_of_the_timed_runs_with_their_extremes() {
        // The summary itself, on given times: odd and even counts, any order.
        let t = summarize(vec![0.05, 0.01, 0.03, 0.04, 0.02]);
        assert_eq!(
            (t.runs, t.min_s, t.median_s, t.max_s),
            (5, 0.01, 0.03, 0.05)
        );
        let t = summarize(vec![0.4, 0.1, 0.3, 0.2]);
        assert_eq!((t.runs, t.min_s, t.median_s, t.max_s), (4, 0.1, 0.25, 0.4));
        // The timed runs: five of them, each timed (a sleep lasts at least what it asks, and at
        // least three of the five ask for 30 ms or more). No upper bound: a loaded machine may
        // stretch any run, and a test must not fail from load.
        let problem = SweepProblem::Paper(
            super::super::problems::pulled(
                "set_b",
                "set B",
                super::super::problems::set_b(),
                crate::models::LawKind::Linear,
            )
            .unwrap(),
        );
        let method = Slower(0.into());
        let t = time_runs(&method, &problem, Setting::Step(1.0), Duration::ZERO, 5);
        assert_eq!(t.runs, 5);
        assert_eq!(method.0.load(std::sync::atomic::Ordering::Relaxed), 5);
        assert!(t.min_s >= 1e-2 && t.min_s <= t.median_s && t.median_s <= t.max_s);
        assert!(t.median_s >= 3e-2 && t.max_s >= 5e-2, "{t:?}");
    }

    /// A method of forces of time only: it keeps the default `solve_surface`, a refusal.
    struct TimeOnly;

    impl Method for TimeOnly {
        fn name(&self) -> &'static str {
            "time_only"
        }
        fn solve(
            &self,
            problem: &crate::solver::Problem,
            setting: Setting,
        ) -> crate::error::Result<Solution> {
            crate::solver::rk4::Rk4.solve(problem, setting)
        }
    }

    #[test]
    fn the_belt_is_refused_by_a_method_of_forces_of_time_only_and_has_no_vbar_error() {
        let belt = SweepProblem::Belt(super::super::belt::bench().unwrap());
        let r = super::super::problems::sweep_reference(&belt).unwrap();
        let h = Setting::Step(belt.period() / 1000.0);
        let p = measure(&TimeOnly, &belt, &r, h, 1);
        assert!(p.refused() && !p.ok(), "{p:?}");
        assert!(p.error.as_deref().unwrap().contains("time_only"), "{p:?}");
        assert_eq!((p.err_event_s, p.time_s, p.runs), (None, None, 0));
        let p = measure(&crate::solver::rk4::Rk4, &belt, &r, h, 1);
        assert!(p.ok() && !p.refused(), "{p:?}");
        assert_eq!(p.n_events, Some(p.n_events_exact));
        assert_eq!(p.n_events_exact, 40);
        assert!(
            p.err_event_s.unwrap() < 1e-6 && p.err_x_m.unwrap() < 1e-6,
            "{p:?}"
        );
        assert_eq!(p.err_vbar_m_s, None);
        // The same method on a paper problem is measured in every metric.
        let paper =
            SweepProblem::Paper(super::super::problems::sweep_problems().unwrap().remove(0));
        let r = super::super::problems::sweep_reference(&paper).unwrap();
        let p = measure(
            &TimeOnly,
            &paper,
            &r,
            Setting::Step(paper.period() / 1000.0),
            1,
        );
        assert!(p.ok() && p.err_vbar_m_s.is_some(), "{p:?}");
    }

    #[test]
    fn the_full_grid_has_ten_tolerances_and_nine_step_counts() {
        let g = Grid::full();
        assert_eq!(g.tolerances.len(), 10);
        assert_eq!(
            g.steps_per_period,
            [10, 32, 100, 316, 1000, 3162, 10000, 31623, 100000]
        );
        let s = g.settings(MethodKind::FixedStep, 2.0);
        assert_eq!(s[0], Setting::Step(0.2));
    }
}
