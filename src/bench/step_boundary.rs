//! Events exactly on a step boundary: the fixed step h is chosen so that an exact event time
//! t_e is a grid point, t_e = k h to rounding, and each fixed-step method's reported time is
//! compared with t_e in steps; the same with the event in the middle of a step, for contrast.
//!
//! ```text
//! h_on  = t_e / k,          k = round(t_e / (T/1000))    (k h_on = t_e within a few ulps)
//! h_mid = t_e / (k + ½)                                   (t_e halfway between grid points)
//! lateness = (t_reported − t_e) / h                        (+1: reported one step late)
//! ```
//! Cases: the first slip and the first stick of set B (linear law), the first slip of the
//! woodpecker of Fig. 15 (harmonic law).

use rayon::prelude::*;
use serde::Serialize;

use super::failure_table::FailureRow;
use super::problems::{self, BenchProblem};
use super::sweep::{method_kind, MethodKind};
use super::tables::{row, table, Table};
use crate::error::Result;
use crate::format::sig;
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::LawKind;
use crate::solver::exact::Exact;
use crate::solver::{Method, MethodEvent, Problem, Setting};

/// About this many steps per period.
pub const STEPS_PER_PERIOD: f64 = 1000.0;
/// Lateness beyond this many steps fails: the reported time is nearer another grid point
/// than the exact one, which is itself a grid point.
pub const LATE_LIMIT: f64 = 0.5;

/// One case: an exact event of a problem, run over one period.
#[derive(Clone, Debug, PartialEq)]
pub struct BoundaryCase {
    pub bp: BenchProblem,
    /// "slip" or "stick": the first event of that kind.
    pub kind: &'static str,
    pub t_exact: f64,
}

impl BoundaryCase {
    fn problem(&self) -> Problem {
        Problem {
            t_end: self.bp.period(),
            ..self.bp.problem.clone()
        }
    }

    /// Grid index k and the two steps (s): the event on the grid, and halfway between.
    pub fn steps(&self) -> (u64, f64, f64) {
        let k = (self.t_exact / (self.bp.period() / STEPS_PER_PERIOD))
            .round()
            .max(1.0);
        (k as u64, self.t_exact / k, self.t_exact / (k + 0.5))
    }

    /// |k h_on − t_e| in units in the last place of t_e.
    pub fn grid_ulps(&self) -> f64 {
        let (k, h, _) = self.steps();
        let ulp = f64::from_bits(self.t_exact.to_bits() + 1) - self.t_exact;
        ((k as f64 * h) - self.t_exact).abs() / ulp
    }
}

fn first(events: &[MethodEvent], kind: &str) -> Option<f64> {
    events.iter().find(|e| e.kind == kind).map(|e| e.t)
}

/// The three cases, their event times from the exact engine.
pub fn cases() -> Result<Vec<BoundaryCase>> {
    let set_b = problems::pulled(
        "pulled_mass_b",
        "Pulled mass, set B",
        problems::set_b(),
        LawKind::Linear,
    )?;
    let fig15 = problems::wood(
        "woodpecker_fig15",
        "Woodpecker, Fig. 15",
        WoodpeckerParams::default(),
        LawKind::Harmonic,
    )?;
    let mut out = Vec::new();
    for (bp, kind) in [(&set_b, "slip"), (&set_b, "stick"), (&fig15, "slip")] {
        let one = Problem {
            t_end: bp.period(),
            ..bp.problem.clone()
        };
        let sol = Exact.solve(&one, Setting::Tolerance(problems::REFERENCE_TOLERANCE))?;
        if let Some(t_exact) = first(&sol.events, kind) {
            out.push(BoundaryCase {
                bp: bp.clone(),
                kind,
                t_exact,
            });
        }
    }
    Ok(out)
}

/// What one fixed-step method reported on one case.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct BoundaryPoint {
    pub problem: String,
    pub title: String,
    pub event: String,
    pub method: String,
    pub t_exact_s: f64,
    pub k: u64,
    pub h_on_s: f64,
    /// |k h_on − t_e| in ulps of t_e.
    pub grid_ulps: f64,
    /// (t_reported − t_e)/h with the event on the grid, and mid-step; `None` when the method
    /// reported no event of that kind.
    pub steps_late_on: Option<f64>,
    pub h_mid_s: f64,
    pub steps_late_mid: Option<f64>,
    pub error: Option<String>,
}

/// Runs the fixed-step methods of `methods` on every case (in parallel).
pub fn run(methods: &[&dyn Method]) -> Result<Vec<BoundaryPoint>> {
    let cases = cases()?;
    let jobs: Vec<(&dyn Method, &BoundaryCase)> = methods
        .iter()
        .filter(|m| method_kind(m.name()) == MethodKind::FixedStep)
        .flat_map(|m| cases.iter().map(move |c| (*m, c)))
        .collect();
    Ok(jobs.par_iter().map(|(m, c)| measure(*m, c)).collect())
}

/// Runs `method` on case `c` with both steps.
pub fn measure(method: &dyn Method, c: &BoundaryCase) -> BoundaryPoint {
    let (k, h_on, h_mid) = c.steps();
    let mut p = BoundaryPoint {
        problem: c.bp.id.clone(),
        title: c.bp.title.clone(),
        event: c.kind.to_string(),
        method: method.name().to_string(),
        t_exact_s: c.t_exact,
        k,
        h_on_s: h_on,
        grid_ulps: c.grid_ulps(),
        steps_late_on: None,
        h_mid_s: h_mid,
        steps_late_mid: None,
        error: None,
    };
    let problem = c.problem();
    let late = |h: f64| -> Result<Option<f64>> {
        let sol = method.solve(&problem, Setting::Step(h))?;
        Ok(first(&sol.events, c.kind).map(|t| (t - c.t_exact) / h))
    };
    match late(h_on).and_then(|on| Ok((on, late(h_mid)?))) {
        Ok((on, mid)) => {
            p.steps_late_on = on;
            p.steps_late_mid = mid;
        }
        Err(e) => p.error = Some(e.to_string()),
    }
    p
}

fn event_words(kind: &str) -> &'static str {
    if kind == "slip" {
        "first slip"
    } else {
        "first stick"
    }
}

/// A lateness in steps, in words.
fn lateness(x: Option<f64>, kind: &str) -> String {
    match x {
        None => format!("no {kind} reported"),
        Some(v) if v.abs() < 5e-4 => "on time (< 0.001 step)".to_string(),
        Some(v) if v > 0.0 => format!("{v:.2} steps late"),
        Some(v) => format!("{:.2} steps early", -v),
    }
}

/// One row per case and fixed-step method.
pub fn boundary_table(points: &[BoundaryPoint]) -> Table {
    let rows = points
        .iter()
        .map(|p| {
            let (on, mid) = match &p.error {
                Some(e) => (format!("error: {e}"), "—".to_string()),
                None => (
                    lateness(p.steps_late_on, &p.event),
                    lateness(p.steps_late_mid, &p.event),
                ),
            };
            let fails = p.error.is_some() || p.steps_late_on.is_none_or(|v| v.abs() > LATE_LIMIT);
            row(
                vec![
                    format!("{}, {}", p.title, event_words(&p.event)),
                    p.method.clone(),
                    format!("{}", sig(Some(p.t_exact_s), 10)),
                    format!(
                        "T/{:.0} (t_e = {} h, {} ulp off)",
                        STEPS_PER_PERIOD,
                        p.k,
                        sig(Some(p.grid_ulps), 2)
                    ),
                    on,
                    mid,
                ],
                if fails { "fail" } else { "pass" },
            )
        })
        .collect();
    table(
        &[
            "event",
            "method",
            "exact time (s)",
            "step h",
            "reported, event on a step boundary",
            "reported, event mid-step",
        ],
        rows,
    )
}

/// The failures-table row of fixed-step method `m`.
pub fn failure_row(m: &str, points: &[BoundaryPoint]) -> FailureRow {
    let mine: Vec<&BoundaryPoint> = points.iter().filter(|p| p.method == m).collect();
    let fails = mine
        .iter()
        .any(|p| p.error.is_some() || p.steps_late_on.is_none_or(|v| v.abs() > LATE_LIMIT));
    let parts: Vec<String> = mine
        .iter()
        .map(|p| match &p.error {
            Some(e) => format!("{} ({}): error: {e}", event_words(&p.event), p.title),
            None => format!(
                "{} ({}): {} (mid-step: {})",
                event_words(&p.event),
                p.title,
                lateness(p.steps_late_on, &p.event),
                lateness(p.steps_late_mid, &p.event)
            ),
        })
        .collect();
    FailureRow {
        method: m.to_string(),
        failure: "an event exactly on a step boundary reported away from it".to_string(),
        measured: if parts.is_empty() {
            "not measured".to_string()
        } else if m == "euler_sign" {
            // Its sign(v) law has no static threshold: the body moves from the first step.
            format!(
                "{}; the sign(v) law has no static friction, so the body moves from the first \
                 step and never sticks",
                parts.join("; ")
            )
        } else {
            parts.join("; ")
        },
        verdict: if fails { "fails" } else { "ok" }.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::moreau::Moreau;

    #[test]
    fn each_case_puts_its_exact_event_on_a_step_boundary_within_a_few_ulps() {
        let cases = cases().unwrap();
        assert_eq!(cases.len(), 3);
        for c in &cases {
            let (k, h_on, h_mid) = c.steps();
            assert!(
                c.grid_ulps() <= 4.0,
                "{} {}: {}",
                c.bp.id,
                c.kind,
                c.grid_ulps()
            );
            // Mid-step: half a step from the nearest grid points.
            let frac = (c.t_exact / h_mid).fract();
            assert!((frac - 0.5).abs() < 1e-9, "{frac}");
            assert!(k > 10 && h_on > 0.0);
        }
    }

    #[test]
    fn moreau_reports_a_slip_on_a_step_boundary_at_least_half_a_step_late() {
        // Measured: 1.00 step late on the boundary, 1.50 steps mid-step (the θ = ½ average of
        // the margin over a step must be positive before it moves).
        let c = &cases().unwrap()[0];
        let p = measure(&Moreau, c);
        let on = p.steps_late_on.unwrap();
        assert!(on > LATE_LIMIT, "{p:?}");
        assert_eq!(failure_row("moreau", &[p]).verdict, "fails");
    }
}
