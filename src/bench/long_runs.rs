//! Error growth over long runs: problems on which error can accumulate, run for 10, 100, 1000
//! (and, in the full run, 10⁴) periods by the exact engine and by dopri5 and rk4 at a few
//! settings each. Untimed: the purpose is accuracy, so the runs go in parallel.
//!
//! ```text
//! continuous slip   pulled mass, set B friction, F = 0.30 N (φ = 0.51 > φ_c = 0.351), harmonic
//!                   law: one delayed slip, then it never sticks again; v grows ≈ g(φ − μd)/2·t
//! reversals         woodpecker, μs 0.1, μd 0.08, z0 = −3 mm (the spring carries the sleeve's
//!                   weight on average), harmonic law: slides down and up, two reversals per
//!                   period, never sticks
//! set B, Fig. 15    the harmonic laws of the sweep: one (two) slip-stick cycles per period
//! errors            max |t − t_exact| over all events (slip, stick, reversal) matched in order,
//!                   only when kinds and count agree; |x(t_end) − x_exact(t_end)|
//! ```
//! A run whose events differ in number or kind from the exact ones is a failure: it is reported
//! with what it missed or added, and its event-time error is not reported.

use rayon::prelude::*;
use serde::Serialize;

use super::failures::MATCH_WINDOW;
use super::problems::{self, BenchProblem};
use super::sweep::{finite, match_events};
use crate::error::Result;
use crate::models::pulled_mass::PulledMassParams;
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::LawKind;
use crate::solver::exact::Exact;
use crate::solver::{Method, MethodEvent, Problem, Setting};

/// Run lengths (periods) of `--quick` and of the full run.
pub const CHECKPOINTS_QUICK: [u32; 3] = [10, 100, 1_000];
pub const CHECKPOINTS_FULL: [u32; 4] = [10, 100, 1_000, 10_000];
/// Tolerances of dopri5.
pub const TOLERANCES: [f64; 3] = [1e-6, 1e-8, 1e-10];
/// Steps per period of rk4 (T/500 keeps 10⁴ periods under rk4's cap of 10⁷ steps).
pub const STEPS_PER_PERIOD: [u32; 2] = [100, 500];
/// Drive of the continuous-slip case (N): φ = F/W = 0.51 with W = 0.5886 N.
pub const CONTINUOUS_SLIP_FORCE: f64 = 0.30;
/// The reversal case: woodpecker friction and spring offset (m).
pub const REVERSAL_MU_S: f64 = 0.1;
pub const REVERSAL_MU_D: f64 = 0.08;
pub const REVERSAL_Z0: f64 = -3e-3;
/// The setting handed to the exact engine (which ignores it).
const REFERENCE: Setting = Setting::Tolerance(problems::REFERENCE_TOLERANCE);

/// A problem of the study, with what it is in words.
#[derive(Clone, Debug, PartialEq)]
pub struct LongCase {
    pub bp: BenchProblem,
    /// What the exact motion does, in words (a verb phrase: "the body …").
    pub motion: &'static str,
}

/// The four problems of the study.
pub fn cases() -> Result<Vec<LongCase>> {
    let slip = PulledMassParams {
        force: CONTINUOUS_SLIP_FORCE,
        ..problems::set_b()
    };
    let reversals = WoodpeckerParams {
        mu_s: REVERSAL_MU_S,
        mu_d: REVERSAL_MU_D,
        z0: REVERSAL_Z0,
        ..WoodpeckerParams::default()
    };
    Ok(vec![
        LongCase {
            bp: problems::pulled(
                "continuous_slip",
                "Pulled mass, set B friction, F = 0.30 N (φ = 0.51 > φ_c = 0.351)",
                slip,
                LawKind::Harmonic,
            )?,
            motion: "slips once, after a short stick, and never sticks again; its speed grows \
                     every period",
        },
        LongCase {
            bp: problems::wood(
                "reversals",
                "Woodpecker, Fig. 15 set with μs 0.1, μd 0.08, z0 = −3 mm",
                reversals,
                LawKind::Harmonic,
            )?,
            motion: "slips at once, then slides down and up, turning without stopping twice \
                     per period, and never sticks",
        },
        LongCase {
            bp: problems::pulled(
                "pulled_mass_b",
                "Pulled mass, set B",
                problems::set_b(),
                LawKind::Harmonic,
            )?,
            motion: "slips and sticks once per period",
        },
        LongCase {
            bp: problems::wood(
                "woodpecker_fig15",
                "Woodpecker, Fig. 15",
                WoodpeckerParams::default(),
                LawKind::Harmonic,
            )?,
            motion: "slips and sticks twice per period",
        },
    ])
}

/// The exact motion of a case over the longest run.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct LongCaseInfo {
    pub id: String,
    pub title: String,
    pub motion: String,
    pub period_s: f64,
    pub periods: u32,
    pub slips: usize,
    pub sticks: usize,
    pub reversals: usize,
    pub x_end_m: f64,
    pub v_end_m_s: f64,
}

/// One method at one setting over one run length.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct LongPoint {
    pub case: String,
    pub method: String,
    /// "tol 1e-8" or "T/100".
    pub setting: String,
    pub periods: u32,
    pub n_events: Option<usize>,
    pub n_exact: usize,
    /// Max event-time error (s), only when kinds and count agree with the exact events.
    pub err_event_s: Option<f64>,
    pub err_x_m: Option<f64>,
    /// The exact position at the end of the run (m).
    pub x_exact_m: f64,
    /// What differs from the exact events, in words (`None`: same kinds in the same order).
    pub wrong_events: Option<String>,
    pub rhs_evals: Option<u64>,
    pub error: Option<String>,
}

impl LongPoint {
    /// The run failed: an error, or events that differ from the exact ones.
    pub fn failed(&self) -> bool {
        self.error.is_some() || self.wrong_events.is_some()
    }
}

/// The study: run lengths, the cases' exact motion and every point.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct LongRuns {
    pub checkpoints: Vec<u32>,
    pub cases: Vec<LongCaseInfo>,
    pub points: Vec<LongPoint>,
}

pub fn plural(n: usize, word: &str) -> String {
    if n == 1 {
        format!("1 {word}")
    } else {
        format!("{n} {word}s")
    }
}

/// How `got` differs from `exact`, in words; `None` when both have the same kinds in order.
/// The first difference is the first pair, in order, of different kinds or more than
/// `window` (s) apart.
pub fn difference_words(got: &[MethodEvent], exact: &[MethodEvent], window: f64) -> Option<String> {
    let same_kinds =
        got.len() == exact.len() && got.iter().zip(exact).all(|(a, b)| a.kind == b.kind);
    if same_kinds {
        return None;
    }
    let first = got
        .iter()
        .zip(exact)
        .position(|(a, b)| a.kind != b.kind || (a.t - b.t).abs() > window)
        .unwrap_or(got.len().min(exact.len()));
    let mut parts = Vec::new();
    for kind in ["slip", "stick", "reversal"] {
        let count = |e: &[MethodEvent]| e.iter().filter(|e| e.kind == kind).count();
        let (g, x) = (count(got), count(exact));
        if g < x {
            parts.push(format!("{} missed", plural(x - g, kind)));
        } else if g > x {
            parts.push(format!("{} too many", plural(g - x, kind)));
        }
    }
    if parts.is_empty() {
        parts.push("the same counts in another order".to_string());
    }
    let at = exact
        .get(first)
        .or(got.get(first))
        .map_or(String::new(), |e| {
            format!("; first difference at t = {:.4} s", e.t)
        });
    Some(format!(
        "{} events against {} exact: {}{at}",
        got.len(),
        exact.len(),
        parts.join(", ")
    ))
}

fn until(bp: &BenchProblem, periods: u32) -> Problem {
    Problem {
        t_end: f64::from(periods) * bp.period(),
        ..bp.problem.clone()
    }
}

/// The settings of the study's methods (dopri5 and rk4; the others are not run).
fn settings(method: &str, period: f64) -> Vec<(String, Setting)> {
    match method {
        "dopri5" => TOLERANCES
            .iter()
            .map(|&t| (format!("tol {t:.0e}"), Setting::Tolerance(t)))
            .collect(),
        "rk4" => STEPS_PER_PERIOD
            .iter()
            .map(|&n| (format!("T/{n}"), Setting::Step(period / f64::from(n))))
            .collect(),
        _ => Vec::new(),
    }
}

/// Runs `method` at `setting` and compares with the exact solution of the same run.
pub fn point(
    method: &dyn Method,
    label: &str,
    setting: Setting,
    case: &str,
    periods: u32,
    problem: &Problem,
    exact: &crate::solver::Solution,
) -> LongPoint {
    let mut p = LongPoint {
        case: case.to_string(),
        method: method.name().to_string(),
        setting: label.to_string(),
        periods,
        n_events: None,
        n_exact: exact.events.len(),
        err_event_s: None,
        err_x_m: None,
        x_exact_m: exact.x_end,
        wrong_events: None,
        rhs_evals: None,
        error: None,
    };
    match method.solve(problem, setting) {
        Ok(sol) => {
            p.n_events = Some(sol.events.len());
            let window = MATCH_WINDOW * problem.law.period;
            p.wrong_events = difference_words(&sol.events, &exact.events, window);
            if p.wrong_events.is_none() {
                p.err_event_s = match_events(&sol.events, &exact.events).max_err;
            }
            p.err_x_m = finite((sol.x_end - exact.x_end).abs());
            p.rhs_evals = Some(sol.stats.rhs_evals);
        }
        Err(e) => p.error = Some(e.to_string()),
    }
    p
}

/// Runs the study: the exact engine on every case and run length, then dopri5 and rk4 of
/// `methods` at their settings (in parallel).
pub fn run(methods: &[&dyn Method], quick: bool) -> Result<LongRuns> {
    let checkpoints: Vec<u32> = if quick {
        CHECKPOINTS_QUICK.to_vec()
    } else {
        CHECKPOINTS_FULL.to_vec()
    };
    let cases = cases()?;
    let runs: Vec<(usize, u32)> = (0..cases.len())
        .flat_map(|i| checkpoints.iter().map(move |&n| (i, n)))
        .collect();
    let exact = runs
        .par_iter()
        .map(|&(i, n)| Exact.solve(&until(&cases[i].bp, n), REFERENCE))
        .collect::<Result<Vec<_>>>()?;
    let mut jobs = Vec::new();
    for (j, &(i, _)) in runs.iter().enumerate() {
        for m in methods {
            for (label, s) in settings(m.name(), cases[i].bp.period()) {
                jobs.push((j, *m, label, s));
            }
        }
    }
    // Longest runs first, so that they do not end the parallel loop alone.
    jobs.sort_by_key(|(j, ..)| std::cmp::Reverse(runs[*j].1));
    let mut points: Vec<LongPoint> = jobs
        .par_iter()
        .map(|(j, m, label, s)| {
            let (i, n) = runs[*j];
            let bp = &cases[i].bp;
            point(*m, label, *s, &bp.id, n, &until(bp, n), &exact[*j])
        })
        .collect();
    // Case, method, setting (loosest first), then run length: the order the tables read.
    let key = |p: &LongPoint| {
        (
            cases.iter().position(|c| c.bp.id == p.case),
            methods.iter().position(|m| m.name() == p.method),
            settings_rank(&p.setting),
            p.periods,
        )
    };
    points.sort_by_key(key);
    let longest = checkpoints.len() - 1;
    let infos = cases
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let e = &exact[i * checkpoints.len() + longest];
            let count = |k: &str| e.events.iter().filter(|ev| ev.kind == k).count();
            LongCaseInfo {
                id: c.bp.id.clone(),
                title: c.bp.title.clone(),
                motion: c.motion.to_string(),
                period_s: c.bp.period(),
                periods: checkpoints[longest],
                slips: count("slip"),
                sticks: count("stick"),
                reversals: count("reversal"),
                x_end_m: e.x_end,
                v_end_m_s: e.v_end,
            }
        })
        .collect();
    Ok(LongRuns {
        checkpoints,
        cases: infos,
        points,
    })
}

/// Loosest setting first: tolerances by decreasing value, then steps by increasing count.
fn settings_rank(label: &str) -> (u8, i64) {
    if let Some(t) = label.strip_prefix("tol ") {
        let t: f64 = t.parse().unwrap_or(0.0);
        (0, (-t.log10() * 100.0).round() as i64)
    } else if let Some(n) = label.strip_prefix("T/") {
        (1, n.parse().unwrap_or(0))
    } else {
        (2, 0)
    }
}

/// Slope of log10 |x error| against log10 periods between the shortest and the longest run
/// without failure (the growth exponent p of error ∝ N^p); with `relative`, of the error
/// divided by the distance travelled, |x error| / |x_exact|.
pub fn growth(points: &[&LongPoint], relative: bool) -> Option<f64> {
    let ok: Vec<(f64, f64)> = points
        .iter()
        .filter(|p| !p.failed())
        .filter_map(|p| {
            let err = p.err_x_m.filter(|e| *e > 0.0)?;
            let scale = if relative { p.x_exact_m.abs() } else { 1.0 };
            Some((f64::from(p.periods).log10(), err / scale))
        })
        .filter(|(_, e)| e.is_finite() && *e > 0.0)
        .map(|(n, e)| (n, e.log10()))
        .collect();
    let (first, last) = (ok.first()?, ok.last()?);
    (last.0 > first.0).then(|| (last.1 - first.1) / (last.0 - first.0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::dopri5::Dopri5;

    fn ev(t: f64, kind: &'static str) -> MethodEvent {
        MethodEvent { t, kind }
    }

    #[test]
    fn a_run_that_misses_a_stick_and_a_slip_is_flagged_in_words() {
        let exact = [
            ev(1.0, "slip"),
            ev(2.0, "stick"),
            ev(3.0, "slip"),
            ev(4.0, "stick"),
        ];
        assert_eq!(difference_words(&exact, &exact, 0.1), None);
        let got = [ev(1.0, "slip"), ev(4.0, "stick")];
        let words = difference_words(&got, &exact, 0.1).unwrap();
        assert_eq!(
            words,
            "2 events against 4 exact: 1 slip missed, 1 stick missed; first difference at \
             t = 2.0000 s"
        );
        let extra = [ev(1.0, "slip"), ev(1.5, "reversal"), ev(2.0, "stick")];
        let words = difference_words(&extra, &exact[..2], 0.1).unwrap();
        assert!(words.contains("1 reversal too many"), "{words}");
    }

    #[test]
    fn the_continuous_slip_case_never_sticks_and_the_reversal_case_reverses() {
        let cases = cases().unwrap();
        let exact = |i: usize| Exact.solve(&until(&cases[i].bp, 100), Setting::Step(1.0));
        let slip = exact(0).unwrap();
        let kinds: Vec<&str> = slip.events.iter().map(|e| e.kind).collect();
        // One delayed slip (not at t = 0) and nothing after it.
        assert_eq!(kinds, ["slip"]);
        assert!(slip.events[0].t > 0.0);
        let rev = exact(1).unwrap();
        let count = |k: &str| rev.events.iter().filter(|e| e.kind == k).count();
        assert_eq!(count("stick"), 0);
        // Measured: 200 reversals in 100 periods, two per period.
        assert!(count("reversal") >= 100, "{}", count("reversal"));
    }

    #[test]
    fn position_error_grows_over_long_runs_of_set_b_and_is_reported() {
        let cases = cases().unwrap();
        let bp = &cases[2].bp;
        let method: &dyn Method = &Dopri5;
        let points: Vec<LongPoint> = [10, 1000]
            .iter()
            .map(|&n| {
                let problem = until(bp, n);
                let exact = Exact.solve(&problem, Setting::Step(1.0)).unwrap();
                point(
                    method,
                    "tol 1e-6",
                    Setting::Tolerance(1e-6),
                    &bp.id,
                    n,
                    &problem,
                    &exact,
                )
            })
            .collect();
        for p in &points {
            assert!(!p.failed(), "{p:?}");
            assert!(p.err_event_s.is_some() && p.err_x_m.is_some(), "{p:?}");
        }
        let (short, long) = (points[0].err_x_m.unwrap(), points[1].err_x_m.unwrap());
        assert!(long > 10.0 * short, "{short:e} → {long:e}");
        let refs: Vec<&LongPoint> = points.iter().collect();
        assert!(growth(&refs, false).is_some_and(|p| p > 0.5));
        // The body advances about equally every period: the relative error grows one power
        // of N less.
        let relative = growth(&refs, true).expect("relative growth");
        let absolute = growth(&refs, false).expect("growth");
        assert!(
            (absolute - relative - 1.0).abs() < 0.1,
            "{absolute} {relative}"
        );
    }
}
