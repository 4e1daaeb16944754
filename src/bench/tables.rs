//! The report's tables as rows of formatted strings (templates hold no logic): problems,
//! fitted orders, the failures (summary and detail), regime classification and creep.

use serde::Serialize;

use super::BenchResults;
use crate::format::sig;

/// One table row: formatted cells and a CSS class ("pass", "fail", "na" or "").
#[derive(Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Row {
    pub cells: Vec<String>,
    pub class: String,
}

/// A table: header and rows.
#[derive(Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Table {
    pub header: Vec<String>,
    pub rows: Vec<Row>,
}

pub fn s3(x: Option<f64>) -> String {
    sig(x, 3)
}

pub fn e2(x: Option<f64>) -> String {
    match x {
        Some(0.0) => "0".to_string(),
        Some(v) => format!("{v:.1e}"),
        None => "—".to_string(),
    }
}

pub fn row(cells: Vec<String>, class: &str) -> Row {
    Row {
        cells,
        class: class.to_string(),
    }
}

pub fn table(header: &[&str], rows: Vec<Row>) -> Table {
    Table {
        header: header.iter().map(|h| h.to_string()).collect(),
        rows,
    }
}

/// The problems with their exact references.
pub fn problems(r: &BenchResults) -> Table {
    let exact_time = |id: &str| {
        r.sweep
            .iter()
            .find(|p| p.problem == id && p.method == "exact")
            .and_then(|p| p.time_s)
    };
    table(
        &[
            "problem",
            "T (s)",
            "periods",
            "exact events",
            "x_end (m)",
            "v̄ last period (m/s)",
            "exact time (s)",
        ],
        r.problems
            .iter()
            .map(|p| {
                row(
                    vec![
                        p.title.clone(),
                        sig(Some(p.period_s), 6),
                        p.periods.to_string(),
                        p.exact.events.len().to_string(),
                        sig(Some(p.exact.x_end_m), 7),
                        match (p.exact.vbar_m_s, p.vbar_not_applicable) {
                            (_, Some(why)) => why.to_string(),
                            (v, None) => sig(v, 7),
                        },
                        e2(exact_time(&p.id)),
                    ],
                    "",
                )
            })
            .collect(),
    )
}

/// The exact references against the 40-digit integration: a sentence and, when it ran, a table.
pub fn reference_check(r: &BenchResults) -> (String, Table) {
    let c = &r.reference_check;
    let header = [
        "problem",
        "events (exact · 40-digit)",
        "same slips and sticks in order",
        "max |Δt| (s)",
        "|Δx_end| (m)",
    ];
    if c.status != "ok" {
        return (
            format!("Independent check of the references not run: {}.", c.reason),
            table(&header, Vec::new()),
        );
    }
    let worst = c
        .rows
        .iter()
        .filter_map(|c| c.max_event_err_s)
        .fold(0.0, f64::max);
    let verdict = if c.all_agree() {
        format!(
            "same slips and sticks in the same order on every problem, event times within {} s",
            e2(Some(worst))
        )
    } else {
        "the events differ on at least one problem (marked below)".to_string()
    };
    let note = format!(
        "Independent check of the references: a second program ({}, mpmath at 40 significant \
         digits, roots bracketed rather than solved) integrated the same force laws and bodies \
         over the same {} periods in {:.1} s: {verdict}.",
        super::independent::SCRIPT,
        r.periods,
        c.elapsed_s
    );
    let rows = c
        .rows
        .iter()
        .map(|c| {
            agreement_row(
                &c.problem,
                (c.events, c.events_mp),
                c.same_pattern,
                (c.max_event_err_s, Some(c.x_end_err_m)),
                c.same_pattern,
            )
        })
        .collect();
    (note, table(&header, rows))
}

/// A row of a table comparing the exact references with another account of the same events:
/// the problem, both event counts, whether the slips and sticks come in the same order, the
/// largest event-time and end-position errors (s, m), and the row's verdict.
fn agreement_row(
    problem: &str,
    (events, events_other): (usize, usize),
    same_pattern: bool,
    (event_err_s, x_end_err_m): (Option<f64>, Option<f64>),
    pass: bool,
) -> Row {
    row(
        vec![
            problem.to_string(),
            format!("{events} · {events_other}"),
            if same_pattern { "yes" } else { "no" }.to_string(),
            e2(event_err_s),
            e2(x_end_err_m),
        ],
        if pass { "pass" } else { "fail" },
    )
}

/// The exact references against the closed forms (the belt): a sentence and a table.
pub fn closed_form_check(r: &BenchResults) -> (String, Table) {
    let checked: Vec<_> = r
        .problems
        .iter()
        .filter_map(|p| {
            let c = p.closed_form_check.as_ref()?;
            Some((p, c, c.agrees(p.t_end_s, p.exact.x_end_m.abs())))
        })
        .collect();
    let rows: Vec<Row> = checked
        .iter()
        .map(|(p, c, agrees)| {
            agreement_row(
                &p.title,
                (c.events_exact, c.events_closed_form),
                c.same_pattern,
                (c.max_event_err_s, c.x_end_err_m),
                *agrees,
            )
        })
        .collect();
    let all = checked.iter().all(|(_, _, agrees)| *agrees);
    let note = match (checked.is_empty(), all) {
        (true, _) => String::new(),
        (false, true) => format!(
            "The belt's reference (the exact engine's run) against its closed forms (first slip \
             at x_s/v_b, slips of t_slip, sticks of t_stick over {} cycles; x(t_end) carried at \
             v_b from the last stick): the same slips and sticks, event times and end position \
             within 1e-12 relative. The 40-digit check above covers the paper's problems.",
            r.periods
        ),
        (false, false) => {
            "The belt's reference DISAGREES with its closed forms (marked below).".to_string()
        }
    };
    let header = [
        "problem",
        "events (exact · closed forms)",
        "same slips and sticks in order",
        "max |Δt| (s)",
        "|Δx_end| (m)",
    ];
    (note, table(&header, rows))
}

/// The methods that do not take a problem of the sweep, with their reasons.
pub fn refusals(r: &BenchResults) -> Table {
    table(
        &["problem", "method", "reason"],
        r.sweep
            .iter()
            .filter(|p| p.refused())
            .map(|p| {
                row(
                    vec![
                        super::problems::title(&p.problem),
                        p.method.clone(),
                        p.error.clone().unwrap_or_default(),
                    ],
                    "na",
                )
            })
            .collect(),
    )
}

/// The fitted orders of the fixed-step methods.
pub fn orders(r: &BenchResults) -> Table {
    table(
        &[
            "problem",
            "method",
            "metric",
            "fitted order",
            "h range (s)",
            "points",
        ],
        r.failures
            .studies
            .orders
            .iter()
            .map(|o| {
                row(
                    vec![
                        super::problems::title(&o.problem),
                        o.method.clone(),
                        o.metric.id().to_string(),
                        sig(o.order, 3),
                        format!("{} … {}", e2(o.h_min_s), e2(o.h_max_s)),
                        o.points.to_string(),
                    ],
                    "",
                )
            })
            .collect(),
    )
}

pub fn failure_tables(r: &BenchResults) -> (Table, Table) {
    let rows = &r.failures.table;
    let mut methods: Vec<&str> = Vec::new();
    for f in rows {
        if !methods.contains(&f.method.as_str()) {
            methods.push(&f.method);
        }
    }
    let mut summary: Vec<Row> = methods
        .iter()
        .map(|m| {
            let mine: Vec<_> = rows.iter().filter(|f| f.method == *m).collect();
            let failed: Vec<&str> = mine
                .iter()
                .filter(|f| f.verdict == "fails")
                .map(|f| f.failure.as_str())
                .collect();
            let unavailable = mine.iter().all(|f| f.verdict == "not available");
            let kind = r
                .methods
                .iter()
                .find(|x| x.name == *m)
                .map_or("—".to_string(), |x| {
                    format!(
                        "{}{}",
                        x.kind.label(),
                        if x.in_registry {
                            ""
                        } else {
                            " (not in solver::methods(); constructed)"
                        }
                    )
                });
            let (text, class) = if unavailable {
                ("not available".to_string(), "na")
            } else if failed.is_empty() {
                ("none measured".to_string(), "pass")
            } else {
                (failed.join("; "), "fail")
            };
            row(vec![m.to_string(), kind, text], class)
        })
        .collect();
    // A method this build leaves out keeps its row, saying so.
    summary.extend(r.not_built_in.iter().map(|m| {
        row(
            vec![
                m.name.to_string(),
                "compiled peer".to_string(),
                m.message.to_string(),
            ],
            "na",
        )
    }));
    let detail = rows
        .iter()
        .map(|f| {
            let class = match f.verdict.as_str() {
                "fails" => "fail",
                "ok" => "pass",
                _ => "na",
            };
            row(
                vec![
                    f.method.clone(),
                    f.failure.clone(),
                    f.measured.clone(),
                    f.verdict.clone(),
                ],
                class,
            )
        })
        .collect();
    (
        table(&["method", "kind", "failures"], summary),
        table(&["method", "failure", "measured", "verdict"], detail),
    )
}

/// The introductions of the regime and creep studies, from the constants they run with.
pub fn regime_intro() -> String {
    use super::problems::{HALT_OFFSET_Z0, HALT_THRESHOLD_Z0, PERIODS, PHI_C_OFFSET};
    format!(
        "Slips and sticks in the last of {PERIODS} periods from each method's own events, against \
         the exact engine: the pulled mass (set B friction, linear law) at φ = φ_c (1 ± {PHI_C_OFFSET:e}), \
         where the speed touches zero tangentially, and the harmonic woodpecker at z0 = {} mm ± \
         {} mm, the Fig. 16 threshold of the intermediate halt.",
        sig(Some(HALT_THRESHOLD_Z0 * 1e3), 5),
        sig(Some(HALT_OFFSET_Z0 * 1e3), 1)
    )
}

/// See [`regime_intro`].
pub fn creep_intro() -> String {
    use super::failures::{CREEP_MARGIN, CREEP_STEPS, CREEP_TOL};
    format!(
        "Distance moved in the middle {} % of the first exact stick phase (each end a run of its \
         own): every method at tolerance {CREEP_TOL:e} or T/{CREEP_STEPS}, then both tanh methods over ε.",
        sig(Some(100.0 * (1.0 - 2.0 * CREEP_MARGIN)), 2)
    )
}

/// The regime classification near the boundaries.
pub fn regime(r: &BenchResults) -> Table {
    table(
        &[
            "case",
            "method",
            "setting",
            "slips/sticks in last period",
            "exact",
            "verdict",
        ],
        r.failures
            .studies
            .regime
            .iter()
            .map(|p| {
                let got = match (p.slips, p.sticks, &p.error) {
                    (Some(a), Some(b), _) => format!("{a}/{b}"),
                    (_, _, Some(e)) => format!("error: {e}"),
                    _ => "—".into(),
                };
                row(
                    vec![
                        super::problems::title(&p.case),
                        p.method.clone(),
                        p.setting.clone(),
                        got,
                        format!("{}/{}", p.exact_slips, p.exact_sticks),
                        if p.wrong { "wrong" } else { "right" }.into(),
                    ],
                    if p.wrong { "fail" } else { "pass" },
                )
            })
            .collect(),
    )
}

/// Creep of every method, then of the tanh methods over ε.
pub fn creep(r: &BenchResults) -> Table {
    table(
        &[
            "problem",
            "method",
            "ε (m/s)",
            "stick phase (s)",
            "creep (m)",
            "rhs evals/period",
        ],
        r.failures
            .studies
            .creep
            .iter()
            .chain(&r.failures.studies.creep_epsilon)
            .map(|c| {
                row(
                    vec![
                        super::problems::title(&c.problem),
                        c.method.clone(),
                        c.epsilon_m_s.map_or("—".into(), |e| format!("{e:.0e}")),
                        format!(
                            "{} … {}",
                            sig(Some(c.t_stick_s), 5),
                            sig(Some(c.t_slip_s), 5)
                        ),
                        c.error
                            .clone()
                            .map_or_else(|| e2(c.creep_m), |e| format!("error: {e}")),
                        s3(c.rhs_per_period),
                    ],
                    "",
                )
            })
            .collect(),
    )
}

/// `points` grouped by (method, setting), methods in order of first appearance and each
/// method's settings likewise: the rows of the studies' tables.
pub fn by_method_and_setting<'a, P>(
    points: &[&'a P],
    method: impl Fn(&'a P) -> &'a str,
    setting: impl Fn(&'a P) -> &'a str,
) -> Vec<(&'a str, &'a str, Vec<&'a P>)> {
    let mut out: Vec<(&str, &str, Vec<&P>)> = Vec::new();
    for &p in points {
        let (m, s) = (method(p), setting(p));
        match out.iter_mut().find(|(om, os, _)| *om == m && *os == s) {
            Some((_, _, v)) => v.push(p),
            None => {
                // After the method's last group, so that a method's settings stay together.
                let at = out
                    .iter()
                    .rposition(|(om, _, _)| *om == m)
                    .map_or(out.len(), |i| i + 1);
                out.insert(at, (m, s, vec![p]));
            }
        }
    }
    out
}
