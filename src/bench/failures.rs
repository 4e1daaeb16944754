//! Where methods fail, measured: each study runs methods on chosen problems (untimed, so the
//! studies may run in parallel) and records numbers, never verdicts; [`super::failure_table`](mod@super::failure_table) turns
//! them into the failures table.
//!
//! ```text
//! reversals   velocity reversals per period against h (from the sweep); exact: 0, since the
//!             drive is positive throughout on every problem, so the true motion never reverses
//! creep       distance moved inside the first exact stick phase [t_stick, t_slip], trimmed by
//!             10 % of its length at each end: |x(b) − x(a)|, each end a run of its own; exact: 0
//! missed      exact events with no event of the same kind within 2 % of T, against tolerance
//! regime      slips and sticks in the last period near a regime boundary, against exact
//! ```

use rayon::prelude::*;
use serde::Serialize;

use super::analysis::slope;
use super::problems::{transitions, BenchProblem, Reference, PERIODS};
use super::sweep::{method_kind, MethodKind, SweepPoint};
use crate::solver::tanh::{TanhAdaptive, TanhImplicit};
use crate::solver::{Method, MethodEvent, Problem, Setting};

/// Regularization widths ε of the creep study (m/s).
pub const EPSILONS: [f64; 5] = [1e-2, 1e-3, 1e-4, 1e-5, 1e-6];
/// Tolerance of the creep runs: tight, so that what moves is the regularization.
pub const CREEP_TOL: f64 = 1e-8;
/// Steps per period of the fixed-step methods in the creep comparison.
pub const CREEP_STEPS: u32 = 10_000;
/// An event of the method within this fraction of T of an exact one of the same kind is found.
pub const MATCH_WINDOW: f64 = 0.02;
/// Creep is measured on the middle of the stick phase, this fraction of its length in from each
/// end: a method with a stick state does not move there at all, whatever its event accuracy.
pub const CREEP_MARGIN: f64 = 0.1;

/// Velocity reversals per period of a fixed-step method at one step.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct ReversalPoint {
    pub problem: String,
    pub method: String,
    pub h_s: f64,
    pub steps_per_period: f64,
    pub reversals_per_period: f64,
}

/// Reversals per period of every fixed-step point of the sweep.
pub fn reversal_points(sweep: &[SweepPoint]) -> Vec<ReversalPoint> {
    sweep
        .iter()
        .filter(|p| method_kind(&p.method) == MethodKind::FixedStep)
        .filter_map(|p| {
            Some(ReversalPoint {
                problem: p.problem.clone(),
                method: p.method.clone(),
                h_s: p.h_s?,
                steps_per_period: p.steps_per_period?,
                reversals_per_period: p.reversals? as f64 / f64::from(PERIODS),
            })
        })
        .collect()
}

/// Slope of log10 (reversals per period) against log10 h (≈ −1 for chatter ∝ 1/h).
pub fn reversal_slope(points: &[ReversalPoint], problem: &str, method: &str) -> Option<f64> {
    let logs: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| p.problem == problem && p.method == method && p.reversals_per_period > 0.0)
        .map(|p| (p.h_s.log10(), p.reversals_per_period.log10()))
        .collect();
    if logs.len() >= 2 {
        slope(&logs)
    } else {
        None
    }
}

/// Creep during one exact stick phase, with the work of reaching its end.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct CreepPoint {
    pub problem: String,
    pub method: String,
    /// ε of a tanh method in the ε sweep (m/s); `None` for a method at its own setting.
    pub epsilon_m_s: Option<f64>,
    /// The exact stick phase (s); creep is measured on its middle 80 %.
    pub t_stick_s: f64,
    pub t_slip_s: f64,
    pub creep_m: Option<f64>,
    /// The method's own velocity at both ends of the window is exactly 0: it holds the body at
    /// rest, and a non-zero `creep_m` is only the difference between the two runs' slides
    /// (an adaptive step sequence depends on t_end), not motion during the stick.
    pub at_rest: Option<bool>,
    /// rhs evaluations of the run to the end of the measured window, and per period.
    pub rhs_evals: Option<u64>,
    pub rhs_per_period: Option<f64>,
    pub error: Option<String>,
}

/// The first exact stick phase that ends in a slip: (t_stick, t_slip).
pub fn first_stick_phase(reference: &Reference) -> Option<(f64, f64)> {
    reference
        .events
        .windows(2)
        .find_map(|w| (w[0].kind == "stick" && w[1].kind == "slip").then_some((w[0].t, w[1].t)))
}

/// The setting of a method in the creep comparison.
pub fn creep_setting(method: &dyn Method, period: f64) -> Setting {
    match method_kind(method.name()) {
        MethodKind::FixedStep => Setting::Step(period / f64::from(CREEP_STEPS)),
        _ => Setting::Tolerance(CREEP_TOL),
    }
}

/// Measures the creep of `method` during the stick phase `phase` of `bp`.
pub fn creep(
    method: &dyn Method,
    bp: &BenchProblem,
    phase: (f64, f64),
    setting: Setting,
    epsilon: Option<f64>,
) -> CreepPoint {
    let until = |t_end: f64| Problem {
        t_end,
        ..bp.problem.clone()
    };
    let mut point = CreepPoint {
        problem: bp.id.clone(),
        method: method.name().to_string(),
        epsilon_m_s: epsilon,
        t_stick_s: phase.0,
        t_slip_s: phase.1,
        creep_m: None,
        at_rest: None,
        rhs_evals: None,
        rhs_per_period: None,
        error: None,
    };
    let margin = CREEP_MARGIN * (phase.1 - phase.0);
    let (from, to) = (phase.0 + margin, phase.1 - margin);
    let ends = method
        .solve(&until(from), setting)
        .and_then(|a| Ok((a, method.solve(&until(to), setting)?)));
    match ends {
        Ok((a, b)) => {
            point.creep_m = Some((b.x_end - a.x_end).abs()).filter(|c| c.is_finite());
            point.at_rest = Some(a.v_end == 0.0 && b.v_end == 0.0);
            point.rhs_evals = Some(b.stats.rhs_evals);
            point.rhs_per_period = Some(b.stats.rhs_evals as f64 * bp.period() / to);
        }
        Err(e) => point.error = Some(e.to_string()),
    }
    point
}

/// The ε sweep of both tanh methods on each problem.
pub fn creep_epsilon_sweep(
    cases: &[(&BenchProblem, (f64, f64))],
    epsilons: &[f64],
) -> Vec<CreepPoint> {
    let mut jobs: Vec<(Box<dyn Method>, usize, f64)> = Vec::new();
    for (i, _) in cases.iter().enumerate() {
        for &epsilon in epsilons {
            jobs.push((Box::new(TanhAdaptive { epsilon }), i, epsilon));
            jobs.push((Box::new(TanhImplicit { epsilon }), i, epsilon));
        }
    }
    jobs.par_iter()
        .map(|(m, i, eps)| {
            let (bp, phase) = cases[*i];
            let setting = creep_setting(m.as_ref(), bp.period());
            creep(m.as_ref(), bp, phase, setting, Some(*eps))
        })
        .collect()
}

/// Exact events found or missed by a method, against tolerance.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct MissedPoint {
    pub problem: String,
    pub method: String,
    pub tolerance: f64,
    pub n_exact: usize,
    pub n_events: Option<usize>,
    /// Exact events with no method event of the same kind within the window.
    pub missed: Option<usize>,
    /// Method events with no exact event of the same kind within the window.
    pub spurious: Option<usize>,
    pub error: Option<String>,
}

/// Greedy in-order matching within `window` (s): (missed exact events, spurious method events).
pub fn missed_and_spurious(
    got: &[MethodEvent],
    exact: &[MethodEvent],
    window: f64,
) -> (usize, usize) {
    let (mut i, mut j, mut matched) = (0, 0, 0);
    while i < exact.len() && j < got.len() {
        let (e, g) = (&exact[i], &got[j]);
        if (g.t - e.t).abs() <= window && g.kind == e.kind {
            matched += 1;
            i += 1;
            j += 1;
        } else if g.t < e.t {
            j += 1;
        } else {
            i += 1;
        }
    }
    (exact.len() - matched, got.len() - matched)
}

/// Runs `method` at `tolerance` on `bp` and counts missed and spurious events.
pub fn missed_events(
    method: &dyn Method,
    bp: &BenchProblem,
    reference: &Reference,
    tolerance: f64,
) -> MissedPoint {
    let mut point = MissedPoint {
        problem: bp.id.clone(),
        method: method.name().to_string(),
        tolerance,
        n_exact: reference.events.len(),
        n_events: None,
        missed: None,
        spurious: None,
        error: None,
    };
    match method.solve(&bp.problem, Setting::Tolerance(tolerance)) {
        Ok(sol) => {
            let got = transitions(&sol.events);
            let window = MATCH_WINDOW * bp.period();
            let (missed, spurious) = missed_and_spurious(&got, &reference.events, window);
            point.n_events = Some(got.len());
            point.missed = Some(missed);
            point.spurious = Some(spurious);
        }
        Err(e) => point.error = Some(e.to_string()),
    }
    point
}

/// Slips and sticks of a method in the last period near a regime boundary.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct RegimePoint {
    pub case: String,
    pub method: String,
    /// "loose", "moderate" or "tight" (see [`regime_settings`]), "—" for the exact engine.
    pub level: String,
    pub setting: String,
    pub slips: Option<usize>,
    pub sticks: Option<usize>,
    pub exact_slips: usize,
    pub exact_sticks: usize,
    /// The per-period classification differs from the exact one (an error counts as wrong).
    pub wrong: bool,
    pub error: Option<String>,
}

/// Three settings per method kind for the boundary study: (level, setting).
pub fn regime_settings(kind: MethodKind, period: f64) -> Vec<(&'static str, Setting)> {
    match kind {
        MethodKind::Reference => vec![("—", Setting::Tolerance(1e-15))],
        MethodKind::Adaptive => vec![
            ("loose", Setting::Tolerance(1e-3)),
            ("moderate", Setting::Tolerance(1e-6)),
            ("tight", Setting::Tolerance(1e-9)),
        ],
        MethodKind::FixedStep => [("loose", 100.0), ("moderate", 1e3), ("tight", 1e4)]
            .into_iter()
            .map(|(l, n)| (l, Setting::Step(period / n)))
            .collect(),
    }
}

/// Every method at each of its [`regime_settings`] on every case, in parallel: the probes of
/// the near-tangent and crowding studies (`period` sets the fixed steps).
pub fn probe_all<'a, C: Sync, P: Send>(
    methods: &[&'a dyn Method],
    period: f64,
    cases: &'a [C],
    probe: impl Fn(&dyn Method, Setting, &C) -> P + Sync,
) -> Vec<P> {
    let jobs: Vec<(&dyn Method, Setting, &C)> = methods
        .iter()
        .flat_map(|m| {
            regime_settings(method_kind(m.name()), period)
                .into_iter()
                .flat_map(move |(_, s)| cases.iter().map(move |c| (*m, s, c)))
        })
        .collect();
    jobs.par_iter().map(|(m, s, c)| probe(*m, *s, c)).collect()
}

/// (slips, sticks) among `events` in the last period of `bp`.
pub fn last_period_counts(events: &[MethodEvent], bp: &BenchProblem) -> (usize, usize) {
    let t0 = bp.problem.t_end - bp.period();
    let last = events.iter().filter(|e| e.t >= t0);
    let count = |k: &str| last.clone().filter(|e| e.kind == k).count();
    (count("slip"), count("stick"))
}

/// Human form of a setting.
pub fn setting_label(s: Setting, period: f64) -> String {
    match s {
        Setting::Tolerance(t) => format!("tol {t:.0e}"),
        Setting::Step(h) => format!("T/{:.0}", period / h),
    }
}

/// Classifies the last period of `bp` by `method` at `setting` and compares with exact.
pub fn classify(
    method: &dyn Method,
    bp: &BenchProblem,
    reference: &Reference,
    level: &str,
    setting: Setting,
) -> RegimePoint {
    let (exact_slips, exact_sticks) = last_period_counts(&reference.events, bp);
    let mut point = RegimePoint {
        case: bp.id.clone(),
        method: method.name().to_string(),
        level: level.to_string(),
        setting: setting_label(setting, bp.period()),
        slips: None,
        sticks: None,
        exact_slips,
        exact_sticks,
        wrong: true,
        error: None,
    };
    match method.solve(&bp.problem, setting) {
        Ok(sol) => {
            let (slips, sticks) = last_period_counts(&transitions(&sol.events), bp);
            point.slips = Some(slips);
            point.sticks = Some(sticks);
            point.wrong = (slips, sticks) != (exact_slips, exact_sticks);
        }
        Err(e) => point.error = Some(e.to_string()),
    }
    point
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ev(t: f64, kind: &'static str) -> MethodEvent {
        MethodEvent { t, kind }
    }

    #[test]
    fn a_missed_stick_and_slip_pair_is_counted_as_missed_not_shifted() {
        let exact = [
            ev(1.0, "slip"),
            ev(2.0, "stick"),
            ev(2.1, "slip"),
            ev(3.0, "stick"),
        ];
        let got = [ev(1.001, "slip"), ev(3.002, "stick")];
        assert_eq!(missed_and_spurious(&got, &exact, 0.01), (2, 0));
        let spurious = [ev(1.0, "slip"), ev(1.5, "stick"), ev(2.0, "stick")];
        assert_eq!(missed_and_spurious(&spurious, &exact[..2], 0.01), (0, 1));
    }
}
