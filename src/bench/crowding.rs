//! Crowding events, the nearest these models come to Zeno behaviour. With μs ≥ μd a body that
//! comes to rest either sticks or accelerates away, and a slip starts only at an up-crossing of
//! the static margin |D| − μs N_f, of which a period has finitely many: events cannot
//! accumulate at a finite time. What can happen is that a slip and the stick ending it close in
//! on each other: the pulled mass (set B friction) pulled ever more weakly, φ = F/W → 0, slips
//! only around the instant N = 0 (τ = ½), for a time
//!
//! ```text
//! linear law:    t_ST − t_SL = (T φ/2)(μs + μd + √D)/(2 μs μd)  ∝ φ     (paper (21))
//! harmonic law:  F > μs W (1 + cos ωt) only for |ωt − π| < √(2φ/μs)   ∝ √φ
//! ```
//!
//! and moves ∝ φ³ (linear law, (30)). Each method's slips and sticks over
//! [`CROWD_PERIODS`] periods are compared with the closed forms (13), (18) on the linear law
//! (so the exact engine is measured too) and with the exact engine on the harmonic law; a
//! method resolves the slip when it finds the same events in the same order with every time
//! within [`RESOLVED`] of the slip's duration. The right-hand-side evaluations show whether an
//! adaptive method's work grows as the events crowd (a Zeno-like failure would show as work
//! growing without bound).

use serde::Serialize;

use super::failure_table::FailureRow;
use super::failures::{probe_all, setting_label};
use super::problems::{self, transitions, BenchProblem};
use super::sweep::{method_kind, MethodKind};
use super::tables::{by_method_and_setting, row, table, Table};
use crate::error::Result;
use crate::format::sig;
use crate::models::pulled_mass::formula::{tau_slip, tau_stick};
use crate::models::pulled_mass::PulledMassParams;
use crate::models::LawKind;
use crate::solver::exact::Exact;
use crate::solver::{Method, MethodEvent, Problem, Setting};

/// Pulling ratios φ = F/W, ever weaker.
pub const RATIOS: [f64; 5] = [1e-1, 1e-3, 1e-5, 1e-7, 1e-9];
/// Periods of each run: a slip and a stick in each.
pub const CROWD_PERIODS: u32 = 4;
/// A method resolves a slip when every event time is within this fraction of its duration.
pub const RESOLVED: f64 = 0.1;

/// One probe: a force law and a pulling ratio, with the events it must give.
#[derive(Clone, Debug, PartialEq)]
pub struct CrowdCase {
    pub law: LawKind,
    pub phi: f64,
    pub bp: BenchProblem,
    /// The expected slips and sticks over the run (closed form or exact engine).
    pub expected: Vec<MethodEvent>,
}

impl CrowdCase {
    fn problem(&self) -> Problem {
        Problem {
            t_end: f64::from(CROWD_PERIODS) * self.bp.period(),
            ..self.bp.problem.clone()
        }
    }

    /// Duration of the first slip (s).
    pub fn slip_duration(&self) -> f64 {
        self.expected[1].t - self.expected[0].t
    }
}

/// Slips and sticks of the linear law over the run, from the closed forms (13) and (18).
fn closed_form_events(p: &PulledMassParams, period: f64) -> Vec<MethodEvent> {
    let phi = p.force / p.weight();
    let (slip, stick) = (tau_slip(phi, p.mu_s), tau_stick(phi, p.mu_s, p.mu_d));
    (0..CROWD_PERIODS)
        .flat_map(|k| {
            let k = f64::from(k);
            [
                MethodEvent {
                    t: (k + slip) * period,
                    kind: "slip",
                },
                MethodEvent {
                    t: (k + stick) * period,
                    kind: "stick",
                },
            ]
        })
        .collect()
}

fn law_words(law: LawKind) -> &'static str {
    match law {
        LawKind::Linear => "linear law",
        LawKind::Harmonic => "harmonic law",
    }
}

/// Both laws at every ratio.
pub fn cases() -> Result<Vec<CrowdCase>> {
    let b = problems::set_b();
    let mut out = Vec::new();
    for law in [LawKind::Linear, LawKind::Harmonic] {
        for &phi in &RATIOS {
            let p = PulledMassParams {
                force: phi * b.weight(),
                ..b
            };
            let bp = problems::pulled(
                &format!("weak_pull_{phi:.0e}"),
                &format!("Pulled mass, φ = {phi:.0e}"),
                p,
                law,
            )?;
            let run = Problem {
                t_end: f64::from(CROWD_PERIODS) * bp.period(),
                ..bp.problem.clone()
            };
            let expected = match law {
                LawKind::Linear => closed_form_events(&p, bp.period()),
                LawKind::Harmonic => transitions(
                    &Exact
                        .solve(&run, Setting::Tolerance(problems::REFERENCE_TOLERANCE))?
                        .events,
                ),
            };
            out.push(CrowdCase {
                law,
                phi,
                bp,
                expected,
            });
        }
    }
    Ok(out)
}

/// What one method found at one setting on one probe.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct CrowdPoint {
    pub law: LawKind,
    pub phi: f64,
    /// Duration of the expected first slip (s).
    pub slip_s: f64,
    pub method: String,
    pub setting: String,
    pub slips: Option<usize>,
    pub sticks: Option<usize>,
    pub expected_events: usize,
    /// Largest |t − t_expected| over the events (s), when the same events came in the same order.
    pub max_error_s: Option<f64>,
    /// `max_error_s` over the slip's duration.
    pub error_of_slip: Option<f64>,
    pub rhs_evals: Option<u64>,
    /// Not resolved: other events, an error, or times off by [`RESOLVED`] of the slip or more.
    pub wrong: bool,
    pub error: Option<String>,
}

/// Runs every method at its three boundary-study settings on every probe (in parallel).
pub fn run(methods: &[&dyn Method]) -> Result<Vec<CrowdPoint>> {
    let cases = cases()?;
    Ok(probe_all(methods, cases[0].bp.period(), &cases, probe))
}

/// Runs `method` at `setting` on probe `c`.
pub fn probe(method: &dyn Method, setting: Setting, c: &CrowdCase) -> CrowdPoint {
    let slip_s = c.slip_duration();
    let mut p = CrowdPoint {
        law: c.law,
        phi: c.phi,
        slip_s,
        method: method.name().to_string(),
        setting: setting_label(setting, c.bp.period()),
        slips: None,
        sticks: None,
        expected_events: c.expected.len(),
        max_error_s: None,
        error_of_slip: None,
        rhs_evals: None,
        wrong: true,
        error: None,
    };
    match method.solve(&c.problem(), setting) {
        Ok(sol) => {
            let events = transitions(&sol.events);
            let count = |k: &str| events.iter().filter(|e| e.kind == k).count();
            p.slips = Some(count("slip"));
            p.sticks = Some(count("stick"));
            p.rhs_evals = Some(sol.stats.rhs_evals);
            let same = events.len() == c.expected.len()
                && events
                    .iter()
                    .zip(&c.expected)
                    .all(|(a, b)| a.kind == b.kind);
            if same {
                let err = events
                    .iter()
                    .zip(&c.expected)
                    .map(|(a, b)| (a.t - b.t).abs())
                    .fold(0.0, f64::max);
                p.max_error_s = Some(err);
                p.error_of_slip = Some(err / slip_s);
                p.wrong = err >= RESOLVED * slip_s;
            }
        }
        Err(e) => p.error = Some(e.to_string()),
    }
    p
}

/// One cell: the error as a fraction of the slip, or what went wrong.
fn cell(p: &CrowdPoint) -> String {
    use super::long_runs::plural;
    match (&p.error, p.error_of_slip, p.slips, p.sticks) {
        (Some(e), ..) => format!("error: {e}"),
        (None, Some(_), ..) if p.method == "exact" && p.law == LawKind::Harmonic => {
            "reference".to_string()
        }
        (None, Some(f), ..) if !p.wrong => sig(Some(f), 2),
        (None, Some(f), ..) => format!("too coarse: {}", sig(Some(f), 2)),
        (None, None, Some(sl), Some(st)) => {
            format!("wrong: {}, {}", plural(sl, "slip"), plural(st, "stick"))
        }
        _ => "—".to_string(),
    }
}

/// Right-hand-side evaluations at the strongest and the weakest pull.
fn work(pts: &[&CrowdPoint]) -> String {
    let evals = |phi: f64| pts.iter().find(|p| p.phi == phi)?.rhs_evals;
    match (evals(RATIOS[0]), evals(RATIOS[RATIOS.len() - 1])) {
        (Some(a), Some(b)) => format!("{a} → {b}"),
        _ => "—".to_string(),
    }
}

/// The table of one law: a row per method and setting, a column per ratio, and the work.
pub fn crowd_table(points: &[CrowdPoint], law: LawKind) -> Table {
    let mine: Vec<&CrowdPoint> = points.iter().filter(|p| p.law == law).collect();
    let mut header = vec!["method".to_string(), "setting".to_string()];
    header.extend(RATIOS.iter().map(|phi| {
        let slip = mine.iter().find(|p| p.phi == *phi).map(|p| p.slip_s);
        format!("φ = {phi:.0e} (slip {} s)", sig(slip, 2))
    }));
    header.push(format!(
        "evaluations, φ = {:.0e} → {:.0e}",
        RATIOS[0],
        RATIOS[RATIOS.len() - 1]
    ));
    let rows = by_method_and_setting(&mine, |p| &p.method, |p| &p.setting)
        .into_iter()
        .map(|(m, setting, pts)| {
            let mut cells = vec![m.to_string(), setting.to_string()];
            cells.extend(RATIOS.iter().map(|phi| {
                pts.iter()
                    .find(|p| p.phi == *phi)
                    .map_or("—".to_string(), |p| cell(p))
            }));
            cells.push(work(&pts));
            let fails = pts.iter().any(|p| p.wrong);
            row(cells, if fails { "fail" } else { "pass" })
        })
        .collect();
    let header: Vec<&str> = header.iter().map(String::as_str).collect();
    table(&header, rows)
}

/// A law's table with its heading.
#[derive(Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct CrowdTable {
    pub heading: String,
    pub table: Table,
}

/// The tables of both laws, with their headings.
pub fn crowd_tables(points: &[CrowdPoint]) -> Vec<CrowdTable> {
    [LawKind::Linear, LawKind::Harmonic]
        .into_iter()
        .map(|law| {
            let reference = match law {
                LawKind::Linear => "against the closed forms",
                LawKind::Harmonic => "against the exact engine",
            };
            CrowdTable {
                heading: format!("{}, {reference}", capitalized(law_words(law))),
                table: crowd_table(points, law),
            }
        })
        .collect()
}

fn capitalized(s: &str) -> String {
    let mut c = s.chars();
    c.next()
        .map(|f| f.to_uppercase().collect::<String>() + c.as_str())
        .unwrap_or_default()
}

/// The study's introduction for the page, from the constants it runs with.
pub fn intro() -> String {
    let ratios: Vec<String> = RATIOS.iter().map(|r| format!("{r:.0e}")).collect();
    format!(
        "These models have no Zeno point: with μs ≥ μd a body that comes to rest either sticks \
         or accelerates away, and a slip starts only where the static margin crosses zero, \
         finitely often per period, so events cannot pile up at one instant. The nearest thing \
         is a slip that shrinks to nothing: the pulled mass (set B friction) pulled ever more \
         weakly, φ = F/W = {}, slips only around the instant the normal force vanishes, for a \
         time ∝ φ on the linear law and ∝ √φ on the harmonic law, so the slip and the stick \
         ending it close in on each other. Over {CROWD_PERIODS} periods ({} slips and {} \
         sticks) each cell gives the largest event-time error as a fraction of the slip's \
         duration (\"too coarse\": {} of the slip or more; \"wrong\": other events than \
         expected), and the last column the evaluations of the right-hand side (closed-form \
         pieces for the exact engine) at the strongest and the weakest pull: work that grew \
         without bound as the events crowd would be the Zeno-like failure.",
        ratios.join(", "),
        CROWD_PERIODS,
        CROWD_PERIODS,
        RESOLVED
    )
}

/// The failures-table row of method `m`: per law and setting, down to which ratio it resolves
/// the slip, and how its work changed over the ratios.
pub fn failure_row(m: &str, points: &[CrowdPoint]) -> FailureRow {
    let mine: Vec<&CrowdPoint> = points.iter().filter(|p| p.method == m).collect();
    let mut fails = false;
    let mut parts = Vec::new();
    for law in [LawKind::Linear, LawKind::Harmonic] {
        let of_law: Vec<&CrowdPoint> = mine.iter().copied().filter(|p| p.law == law).collect();
        for (_, setting, pts) in by_method_and_setting(&of_law, |p| &p.method, |p| &p.setting) {
            // A ratio without a point counts as not resolved.
            let wrong_at = |phi: f64| pts.iter().find(|p| p.phi == phi).is_none_or(|p| p.wrong);
            let reach = match RATIOS.iter().position(|&phi| wrong_at(phi)) {
                None => format!("resolved down to φ = {:.0e}", RATIOS[RATIOS.len() - 1]),
                Some(0) => format!("not resolved already at φ = {:.0e}", RATIOS[0]),
                Some(i) => format!(
                    "resolved down to φ = {:.0e}, not at {:.0e}",
                    RATIOS[i - 1],
                    RATIOS[i]
                ),
            };
            fails |= RATIOS.iter().any(|&phi| wrong_at(phi));
            let work = if method_kind(m) == MethodKind::Adaptive {
                format!(" (evaluations {})", work(&pts))
            } else {
                String::new()
            };
            parts.push(format!("{}, {setting}: {reach}{work}", law_words(law)));
        }
    }
    FailureRow {
        method: m.to_string(),
        failure: "a vanishing slip lost or misplaced (events crowding, Zeno-like)".to_string(),
        measured: if parts.is_empty() {
            "not measured".to_string()
        } else {
            format!(
                "slips and sticks over {CROWD_PERIODS} periods of a weak pull, φ = {:.0e} … \
                 {:.0e}: {}",
                RATIOS[0],
                RATIOS[RATIOS.len() - 1],
                parts.join("; ")
            )
        },
        verdict: if fails { "fails" } else { "ok" }.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::pulled_mass::formula::slip_duration;
    use crate::solver::dopri5::Dopri5;

    #[test]
    fn the_slips_shrink_like_phi_on_the_linear_law_and_like_its_root_on_the_harmonic_law() {
        let cases = cases().unwrap();
        assert_eq!(cases.len(), 2 * RATIOS.len());
        let b = problems::set_b();
        for c in &cases {
            assert_eq!(c.expected.len(), 2 * CROWD_PERIODS as usize, "{c:?}");
            if c.law == LawKind::Linear {
                let d = slip_duration(c.bp.period(), c.phi, b.mu_s, b.mu_d);
                assert!((c.slip_duration() / d - 1.0).abs() < 1e-5, "{c:?}");
            }
        }
        // Harmonic: F > μs W (1 + cos ωt) for |ωt − π| < √(2φ/μs), and the slip lasts longer
        // than that window but by a bounded factor; 1e-7 → 1e-9 shortens it 10×.
        let harmonic: Vec<&CrowdCase> = cases
            .iter()
            .filter(|c| c.law == LawKind::Harmonic)
            .collect();
        let (a, z) = (harmonic[3], harmonic[4]);
        let ratio = a.slip_duration() / z.slip_duration();
        assert!((ratio - 10.0).abs() < 0.01, "{ratio}");
        let window =
            2.0 * (2.0 * a.phi / b.mu_s).sqrt() / (2.0 * std::f64::consts::PI) * a.bp.period();
        assert!(a.slip_duration() > window && a.slip_duration() < 3.0 * window);
    }

    #[test]
    fn the_exact_engine_resolves_every_weak_pull_against_the_closed_forms() {
        for c in cases().unwrap() {
            let p = probe(&Exact, Setting::Tolerance(1e-15), &c);
            assert!(!p.wrong, "{p:?}");
            if c.law == LawKind::Linear {
                // Round-off of the event times near T/2 only: ≲ 1e-15 T.
                assert!(p.max_error_s.unwrap() < 1e-14 * c.bp.period(), "{p:?}");
            }
        }
    }

    #[test]
    fn moreau_misses_a_slip_far_shorter_than_its_step_and_the_row_says_where() {
        let cases = cases().unwrap();
        let short = cases
            .iter()
            .find(|c| c.law == LawKind::Linear && c.phi == 1e-5)
            .unwrap();
        let h = short.bp.period() / 1e3;
        assert!(short.slip_duration() < 0.1 * h);
        // Measured: its θ-average of the margin over a step never exceeds zero, so it never
        // moves; dopri5 finds the slip to 2e-11 of its length.
        let p = probe(&crate::solver::moreau::Moreau, Setting::Step(h), short);
        assert!(p.wrong, "{p:?}");
        assert_eq!((p.slips, p.sticks), (Some(0), Some(0)));
        let good = probe(&Dopri5, Setting::Tolerance(1e-9), short);
        assert!(
            !good.wrong && good.error_of_slip.unwrap() < 1e-6,
            "{good:?}"
        );
        let row = failure_row("moreau", std::slice::from_ref(&p));
        assert_eq!(row.verdict, "fails");
        assert!(
            row.measured.contains("linear law, T/1000: not resolved"),
            "{}",
            row.measured
        );
        let t = crowd_table(&[p, good], LawKind::Linear);
        assert_eq!(t.rows.len(), 2);
        assert_eq!(t.rows[0].cells[4], "wrong: 0 slips, 0 sticks");
        assert_eq!(t.rows[0].class, "fail");
        assert_eq!(t.rows[1].class, "pass");
    }
}
