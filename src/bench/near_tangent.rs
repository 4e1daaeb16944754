//! Near-tangent sticks: the pulled mass (set B friction, linear law) at φ = φ_c (1 ± δ), where
//! the speed touches zero tangentially at τ = 1 + τ'_M (guide §7.5), probed ever closer to
//! φ_c. Each method's slips and sticks are compared with the closed form's regime, not with
//! the exact engine, so the exact engine is measured too.
//!
//! ```text
//! φ = φ_c (1 − δ)   late stick: a slip every period, each stick early in the next period
//!                   → over P periods, P slips and P − 1 sticks
//! φ = φ_c (1 + δ)   continuous slip: the speed dips to ∝ δ near τ = 1.25, then grows
//!                   → 1 slip, 0 sticks
//! δ = 1e-3, 1e-5, …, 1e-13;  φ_c = 4 μs μd / (2 μs + √(2D)) in closed form
//! ```

use serde::Serialize;

use super::failure_table::FailureRow;
use super::failures::probe_all;
use super::problems::{self, transitions, BenchProblem};
use super::tables::{by_method_and_setting, row, table, Table};
use crate::error::Result;
use crate::models::pulled_mass::formula::phi_continuous;
use crate::models::pulled_mass::PulledMassParams;
use crate::models::LawKind;
use crate::solver::{Method, Problem, Setting};

/// Relative distances δ of φ from φ_c.
pub const OFFSETS: [f64; 6] = [1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-13];
/// Periods of each run: the first near-touch comes at τ ≈ 1.25, so that the count over P
/// periods says which side of φ_c the method found.
pub const TANGENT_PERIODS: u32 = 4;

/// One probe: a side of φ_c and an offset.
#[derive(Clone, Debug, PartialEq)]
pub struct TangentCase {
    /// −1 below φ_c (late stick), +1 above (continuous slip).
    pub side: i8,
    pub offset: f64,
    pub phi: f64,
    pub bp: BenchProblem,
}

impl TangentCase {
    /// (slips, sticks) over the run from the closed-form regime.
    pub fn expected(&self) -> (usize, usize) {
        expected_on(self.side)
    }

    fn problem(&self) -> Problem {
        Problem {
            t_end: f64::from(TANGENT_PERIODS) * self.bp.period(),
            ..self.bp.problem.clone()
        }
    }
}

/// (slips, sticks) over [`TANGENT_PERIODS`] periods on a side of φ_c (−1 below: a slip and a
/// late stick every period, the last stick after the run; +1 above: one slip, never a stick).
fn expected_on(side: i8) -> (usize, usize) {
    let p = TANGENT_PERIODS as usize;
    if side < 0 {
        (p, p - 1)
    } else {
        (1, 0)
    }
}

/// The study's introduction for the page: the probes, and the counts the closed form gives.
pub fn intro() -> String {
    use super::long_runs::plural;
    let count = |(slips, sticks): (usize, usize)| {
        format!("{} and {}", plural(slips, "slip"), plural(sticks, "stick"))
    };
    format!(
        "The pulled mass (set B friction, linear law) at φ = φ_c (1 − δ), where it sticks early \
         in each next period (late stick), and at φ = φ_c (1 + δ), where it never sticks again: \
         at φ_c its speed touches zero tangentially. Over {TANGENT_PERIODS} periods the closed \
         form says {} below φ_c, {} above; each method's own events are counted against that \
         (the exact engine too). \"right\" means both sides counted as the closed form says.",
        count(expected_on(-1)),
        count(expected_on(1))
    )
}

/// Both sides of φ_c at every offset.
pub fn cases() -> Result<Vec<TangentCase>> {
    let b = problems::set_b();
    let phi_c = phi_continuous(b.mu_s, b.mu_d);
    let mut out = Vec::new();
    for &offset in &OFFSETS {
        for side in [-1i8, 1] {
            let phi = phi_c * (1.0 + f64::from(side) * offset);
            let p = PulledMassParams {
                force: phi * b.weight(),
                ..b
            };
            let tag = if side < 0 { "below" } else { "above" };
            let bp = problems::pulled(
                &format!("phi_c_{tag}_{offset:.0e}"),
                &format!("Pulled mass, φ = φ_c (1 {} {offset:.0e})", side_char(side)),
                p,
                LawKind::Linear,
            )?;
            out.push(TangentCase {
                side,
                offset,
                phi,
                bp,
            });
        }
    }
    Ok(out)
}

fn side_char(side: i8) -> char {
    if side < 0 {
        '−'
    } else {
        '+'
    }
}

/// What one method found at one setting on one probe.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct TangentPoint {
    /// "below" or "above" φ_c.
    pub side: String,
    pub offset: f64,
    pub phi: f64,
    pub method: String,
    pub setting: String,
    pub slips: Option<usize>,
    pub sticks: Option<usize>,
    pub expected_slips: usize,
    pub expected_sticks: usize,
    /// Counts differ from the closed form's (an error counts as wrong).
    pub wrong: bool,
    pub error: Option<String>,
}

/// Runs every method at its three boundary-study settings on every probe (in parallel).
pub fn run(methods: &[&dyn Method]) -> Result<Vec<TangentPoint>> {
    let cases = cases()?;
    Ok(probe_all(methods, cases[0].bp.period(), &cases, probe))
}

/// Runs `method` at `setting` on probe `c`.
pub fn probe(method: &dyn Method, setting: Setting, c: &TangentCase) -> TangentPoint {
    let (expected_slips, expected_sticks) = c.expected();
    let mut p = TangentPoint {
        side: if c.side < 0 { "below" } else { "above" }.to_string(),
        offset: c.offset,
        phi: c.phi,
        method: method.name().to_string(),
        setting: super::failures::setting_label(setting, c.bp.period()),
        slips: None,
        sticks: None,
        expected_slips,
        expected_sticks,
        wrong: true,
        error: None,
    };
    match method.solve(&c.problem(), setting) {
        Ok(sol) => {
            let events = transitions(&sol.events);
            let count = |k: &str| events.iter().filter(|e| e.kind == k).count();
            p.slips = Some(count("slip"));
            p.sticks = Some(count("stick"));
            p.wrong = (count("slip"), count("stick")) != (expected_slips, expected_sticks);
        }
        Err(e) => p.error = Some(e.to_string()),
    }
    p
}

/// What a wrong probe found, in words.
fn found(p: &TangentPoint) -> String {
    match (p.slips, p.sticks, &p.error) {
        (Some(sl), Some(st), _) => format!(
            "{sl} slip{}, {st} stick{}",
            if sl == 1 { "" } else { "s" },
            if st == 1 { "" } else { "s" }
        ),
        (_, _, Some(e)) => format!("error: {e}"),
        _ => "—".to_string(),
    }
}

/// One row per method and setting, one column per offset: "right", or what was found.
pub fn tangent_table(points: &[TangentPoint]) -> Table {
    let mut header = vec!["method".to_string(), "setting".to_string()];
    header.extend(OFFSETS.iter().map(|d| format!("δ = {d:.0e}")));
    let all: Vec<&TangentPoint> = points.iter().collect();
    let rows = by_method_and_setting(&all, |p| &p.method, |p| &p.setting)
        .into_iter()
        .map(|(m, setting, pts)| {
            let mut cells = vec![m.to_string(), setting.to_string()];
            let mut any_wrong = false;
            for &d in &OFFSETS {
                let wrong: Vec<String> = pts
                    .iter()
                    .filter(|p| p.offset == d && p.wrong)
                    .map(|p| format!("{}: {}", p.side, found(p)))
                    .collect();
                any_wrong |= !wrong.is_empty();
                cells.push(if wrong.is_empty() {
                    "right".to_string()
                } else {
                    format!("wrong ({})", wrong.join("; "))
                });
            }
            row(cells, if any_wrong { "fail" } else { "pass" })
        })
        .collect();
    let header: Vec<&str> = header.iter().map(String::as_str).collect();
    table(&header, rows)
}

/// The failures-table row of method `m`: per setting, down to which offset it is right.
pub fn failure_row(m: &str, points: &[TangentPoint]) -> FailureRow {
    let mine: Vec<&TangentPoint> = points.iter().filter(|p| p.method == m).collect();
    let settings = by_method_and_setting(&mine, |p| &p.method, |p| &p.setting);
    let mut fails = false;
    let parts: Vec<String> = settings
        .iter()
        .map(|(_, setting, pts)| {
            let wrong_at = |d: f64| pts.iter().any(|p| p.offset == d && p.wrong);
            match OFFSETS.iter().position(|&d| wrong_at(d)) {
                None => format!(
                    "{setting}: right down to δ = {:.0e}",
                    OFFSETS[OFFSETS.len() - 1]
                ),
                Some(0) => {
                    fails = true;
                    format!("{setting}: wrong already at δ = {:.0e}", OFFSETS[0])
                }
                Some(i) => {
                    fails = true;
                    format!(
                        "{setting}: right down to δ = {:.0e}, wrong at {:.0e}",
                        OFFSETS[i - 1],
                        OFFSETS[i]
                    )
                }
            }
        })
        .collect();
    let measured = if parts.is_empty() {
        "not measured".to_string()
    } else {
        format!(
            "slips and sticks over {TANGENT_PERIODS} periods at φ = φ_c (1 ± δ) against the \
             closed form: {}",
            parts.join("; ")
        )
    };
    FailureRow {
        method: m.to_string(),
        failure: "a near-tangent stick misread (speed touching zero)".to_string(),
        measured,
        verdict: if fails { "fails" } else { "ok" }.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::exact::Exact;

    #[test]
    fn the_exact_engine_classifies_every_near_tangent_probe_like_the_closed_form() {
        let cases = cases().unwrap();
        assert_eq!(cases.len(), 2 * OFFSETS.len());
        for c in &cases {
            let p = probe(&Exact, Setting::Tolerance(1e-15), c);
            assert!(
                !p.wrong,
                "δ = {:e} {}: found {:?}/{:?}, expected {:?}",
                c.offset,
                p.side,
                p.slips,
                p.sticks,
                c.expected()
            );
        }
    }

    #[test]
    fn a_wrong_probe_is_worded_and_fails_the_row() {
        let c = &cases().unwrap()[0];
        let mut p = probe(&Exact, Setting::Tolerance(1e-15), c);
        assert!(!p.wrong);
        assert_eq!(failure_row("exact", &[p.clone()]).verdict, "ok");
        p.sticks = Some(0);
        p.wrong = true;
        let row = failure_row("exact", &[p.clone()]);
        assert_eq!(row.verdict, "fails");
        assert!(
            row.measured.contains("wrong already at δ = 1e-3"),
            "{}",
            row.measured
        );
        let t = tangent_table(&[p]);
        assert_eq!(t.rows[0].cells[2], "wrong (below: 4 slips, 0 sticks)");
    }
}
