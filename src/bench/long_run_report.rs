//! The long-run study on the page ([`super::long_runs`]): per case a sentence on the exact
//! motion, a table of errors against run length and a chart of their growth; and one row per
//! method for the failures table (events lost or gained over long runs).

use serde::Serialize;

use super::charts::style;
use super::context::{figure, FigureCtx};
use super::failure_table::FailureRow;
use super::long_runs::{
    growth, plural, LongCaseInfo, LongPoint, LongRuns, STEPS_PER_PERIOD, TOLERANCES,
};
use super::tables::{e2, row, table, Table};
use crate::error::Result;
use crate::format::sig;
use crate::report::figures::spec::{Curve, LineChart, Panel};

/// Errors below this are drawn at it (an exact zero has no logarithm).
const FLOOR: f64 = 1e-16;

/// One case of the study as the templates show it.
#[derive(Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct LongRunCtx {
    pub title: String,
    pub text: String,
    pub table: Table,
    pub figure: FigureCtx,
}

/// The (method, setting) series of a case, in the study's order.
fn series<'a>(r: &'a LongRuns, case: &str) -> Vec<((&'a str, &'a str), Vec<&'a LongPoint>)> {
    let mut out: Vec<((&str, &str), Vec<&LongPoint>)> = Vec::new();
    for p in r.points.iter().filter(|p| p.case == case) {
        let key = (p.method.as_str(), p.setting.as_str());
        match out.iter_mut().find(|(k, _)| *k == key) {
            Some((_, v)) => v.push(p),
            None => out.push((key, vec![p])),
        }
    }
    out
}

fn cell(p: &LongPoint) -> String {
    match (&p.error, &p.wrong_events) {
        (Some(e), _) => format!("error: {e}"),
        (None, Some(w)) => format!("wrong events: {w}"),
        (None, None) => format!("events {} s; x {} m", e2(p.err_event_s), e2(p.err_x_m)),
    }
}

fn case_text(c: &LongCaseInfo) -> String {
    format!(
        "The body {}: over {} periods (T = {} s) the exact engine finds {}, {} and {}, and \
         ends at x = {} m with v = {} m/s.",
        c.motion,
        c.periods,
        sig(Some(c.period_s), 4),
        plural(c.slips, "slip"),
        plural(c.sticks, "stick"),
        plural(c.reversals, "reversal"),
        sig(Some(c.x_end_m), 4),
        sig(Some(c.v_end_m_s), 3)
    )
}

fn case_table(r: &LongRuns, case: &str) -> Table {
    let mut header = vec!["method".to_string(), "setting".to_string()];
    header.extend(r.checkpoints.iter().map(|n| format!("{n} periods")));
    header.push("x error grows as".to_string());
    header.push("x error / x_exact grows as".to_string());
    let rows = series(r, case)
        .into_iter()
        .map(|((m, s), pts)| {
            let mut cells = vec![m.to_string(), s.to_string()];
            for n in &r.checkpoints {
                cells.push(
                    pts.iter()
                        .find(|p| p.periods == *n)
                        .map_or("—".to_string(), |p| cell(p)),
                );
            }
            for relative in [false, true] {
                cells.push(match growth(&pts, relative) {
                    Some(k) => format!("N^{k:.2}"),
                    None => "—".to_string(),
                });
            }
            let failed = pts.iter().any(|p| p.failed());
            row(cells, if failed { "fail" } else { "" })
        })
        .collect();
    let header: Vec<&str> = header.iter().map(String::as_str).collect();
    table(&header, rows)
}

fn case_chart(r: &LongRuns, case: &str) -> LineChart {
    let all = series(r, case);
    let curves = |pick: fn(&LongPoint) -> Option<f64>| -> Vec<Curve> {
        all.iter()
            .enumerate()
            .map(|(i, ((m, s), pts))| {
                let (color, stroke) = style(i);
                let wrong = pts.iter().find(|p| p.failed()).map(|p| p.periods);
                Curve {
                    label: match wrong {
                        Some(n) => format!("{m} {s} (wrong events from {n} periods)"),
                        None => format!("{m} {s}"),
                    },
                    points: pts
                        .iter()
                        .filter(|p| !p.failed())
                        .filter_map(|p| {
                            Some((f64::from(p.periods).log10(), pick(p)?.max(FLOOR).log10()))
                        })
                        .collect(),
                    color,
                    stroke,
                }
            })
            .collect()
    };
    let xs: Vec<f64> = r
        .checkpoints
        .iter()
        .map(|n| f64::from(*n).log10())
        .collect();
    LineChart {
        x_label: "log10 periods run".to_string(),
        x_range: xs.first().zip(xs.last()).map(|(a, b)| (a - 0.1, b + 0.1)),
        panels: vec![
            Panel {
                y_label: "log10 max event error (s)".to_string(),
                curves: curves(|p| p.err_event_s),
                h_lines: Vec::new(),
            },
            Panel {
                y_label: "log10 |x error| (m)".to_string(),
                curves: curves(|p| p.err_x_m),
                h_lines: Vec::new(),
            },
        ],
        markers: Vec::new(),
    }
}

/// What was run, in one sentence.
pub fn protocol(r: &LongRuns) -> String {
    let list = |v: Vec<String>| v.join(", ");
    format!(
        "Each problem is run for {} periods from rest, each length a run of its own, by the exact \
         engine (the reference), dopri5 at tolerance {} and rk4 at h = {}. Errors: the largest \
         |t − t_exact| over all slips, sticks and reversals matched in order (given only when \
         the kinds and the count agree with the exact ones), and |x(t_end) − x_exact(t_end)|. \
         A run with a different number or order of events is marked wrong, with what it missed \
         or added. The growth columns are the slopes of log10 |x error|, and of log10 of it \
         divided by the distance travelled |x_exact|, against log10 N between the shortest and \
         the longest right run: where the body travels ever faster (continuous slip) an error \
         growing faster than N can still be a constant or slowly growing fraction of the \
         distance.",
        list(r.checkpoints.iter().map(u32::to_string).collect()),
        list(TOLERANCES.iter().map(|t| format!("{t:.0e}")).collect()),
        list(STEPS_PER_PERIOD.iter().map(|n| format!("T/{n}")).collect()),
    )
}

/// The page's blocks, one per case.
pub fn contexts(r: &LongRuns) -> Result<Vec<LongRunCtx>> {
    r.cases
        .iter()
        .map(|c| {
            Ok(LongRunCtx {
                title: c.title.clone(),
                text: case_text(c),
                table: case_table(r, &c.id),
                figure: figure(
                    &format!("long-{}", c.id),
                    format!(
                        "{}: max event-time error (top) and |x(t_end) − x_exact| (bottom) \
                         against the number of periods run, log10 both; a run whose events \
                         differ from the exact ones is left out (see the table). Errors below \
                         1e-16 are drawn at 1e-16.",
                        c.title
                    ),
                    &case_chart(r, &c.id),
                )?,
            })
        })
        .collect()
}

/// One row per method of the study: events lost or gained over long runs.
pub fn failure_rows(r: &LongRuns) -> Vec<FailureRow> {
    let mut methods: Vec<&str> = Vec::new();
    for p in &r.points {
        if !methods.contains(&p.method.as_str()) {
            methods.push(&p.method);
        }
    }
    methods
        .into_iter()
        .map(|m| {
            let mine: Vec<&LongPoint> = r.points.iter().filter(|p| p.method == m).collect();
            let bad: Vec<&&LongPoint> = mine.iter().filter(|p| p.failed()).collect();
            let longest = r.checkpoints.last().copied().unwrap_or(0);
            let measured = match bad.first() {
                None => format!(
                    "events right in all {} runs of up to {longest} periods",
                    mine.len()
                ),
                Some(p) => format!(
                    "{} of {} runs wrong; first: {} at {}, {} periods: {}",
                    bad.len(),
                    mine.len(),
                    p.case,
                    p.setting,
                    p.periods,
                    p.error
                        .clone()
                        .or(p.wrong_events.clone())
                        .unwrap_or_default()
                ),
            };
            FailureRow {
                method: m.to_string(),
                failure: "events lost or gained over long runs".to_string(),
                measured,
                verdict: if bad.is_empty() { "ok" } else { "fails" }.to_string(),
            }
        })
        .collect()
}

/// Puts each of `rows` after the last row of its method in `table` (at the end if none).
pub fn insert_rows(table: &mut Vec<FailureRow>, rows: Vec<FailureRow>) {
    for r in rows {
        let at = table
            .iter()
            .rposition(|x| x.method == r.method)
            .map_or(table.len(), |i| i + 1);
        table.insert(at, r);
    }
}
