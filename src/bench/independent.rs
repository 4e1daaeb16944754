//! An independent check of the bench's reference: the exact engine's events on every problem
//! against a 40-digit integration of the same force law and body by a second program
//! (`tests/reference/mp_engine.py`, mpmath, written apart from the engine: it brackets its roots
//! where the engine solves them, and its arithmetic leaves no cancellation to avoid).
//!
//! ```text
//! per problem:  events of both in order, same kinds   max |t_engine − t_mp|   |x_end − x_mp|
//! ```
//! Absent Python or mpmath is a plain statement on the page, never an error.

use std::io::Write;
use std::process::Stdio;

use serde::Serialize;
use serde_json::{json, Value};

use super::peer::ShippedScript;
use super::problems::{BenchProblem, Reference, PERIODS};
use crate::engine::{Body, ForceLaw};

/// The script's name in the repository (it is compiled into the binary: [`SCRIPT_TEXT`]).
pub const SCRIPT: &str = "tests/reference/mp_engine.py";
/// The script itself, shipped inside the binary.
const SCRIPT_TEXT: &str = include_str!("../../tests/reference/mp_engine.py");
/// Exit code of the script when mpmath is missing.
const NO_MPMATH: i32 = 3;

/// The check of one problem.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct CheckRow {
    pub problem: String,
    /// Slips and sticks of the exact engine and of the 40-digit integration.
    pub events: usize,
    pub events_mp: usize,
    /// Both lists have the same kinds in the same order.
    pub same_pattern: bool,
    /// max |t − t_mp| over the events (s); none when the patterns differ.
    pub max_event_err_s: Option<f64>,
    /// |x_end − x_mp(t_end)| (m).
    pub x_end_err_m: f64,
}

/// The check of every problem, or why it did not run.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct ReferenceCheck {
    /// "ok" or "skipped".
    pub status: String,
    /// Why it was skipped (empty when it ran).
    pub reason: String,
    pub rows: Vec<CheckRow>,
    /// Wall time of the 40-digit integration (s).
    pub elapsed_s: f64,
}

impl ReferenceCheck {
    fn skipped(reason: String) -> Self {
        ReferenceCheck {
            status: "skipped".into(),
            reason,
            rows: Vec::new(),
            elapsed_s: 0.0,
        }
    }

    /// Every problem has the same events as the 40-digit integration.
    pub fn all_agree(&self) -> bool {
        self.status == "ok" && self.rows.iter().all(|r| r.same_pattern)
    }
}

/// Runs the 40-digit integration on `pairs` and compares it with their exact references.
pub fn check(pairs: &[(&BenchProblem, &Reference)]) -> ReferenceCheck {
    let started = std::time::Instant::now();
    let problems: Vec<_> = pairs
        .iter()
        .map(|(bp, _)| (&bp.problem.law, &bp.problem.body))
        .collect();
    match integrate_40_digits(&problems, PERIODS) {
        Ok(out) => ReferenceCheck {
            status: "ok".into(),
            reason: String::new(),
            rows: pairs
                .iter()
                .zip(&out)
                .map(|((bp, r), mp)| compare(bp, r, mp))
                .collect(),
            elapsed_s: started.elapsed().as_secs_f64(),
        },
        Err(reason) => ReferenceCheck::skipped(reason.to_string()),
    }
}

/// Why the 40-digit integration gave no results.
#[derive(Debug, thiserror::Error)]
pub enum ScriptError {
    /// python3, mpmath or the script is missing: a plain statement, never a failure.
    #[error("{0}")]
    Unavailable(String),
    /// The script ran and failed, or did not write one result per problem.
    #[error("{0}")]
    Failed(String),
}

/// The 40-digit integration (`mp_engine.py`) of `periods` periods of every (law, body), one JSON
/// result per problem in order: `events` per period as [t, kind, …] with t a decimal string,
/// `x_at_period_start` as decimal strings.
pub fn integrate_40_digits(
    problems: &[(&ForceLaw, &Body)],
    periods: u32,
) -> Result<Vec<Value>, ScriptError> {
    let input = problems
        .iter()
        .map(|(law, body)| json!({"law": law, "body": body, "periods": periods}))
        .collect();
    run_script(input)
}

/// The script on a list of cases as its docstring describes them (a serialized force law and
/// body, or a model, a law and its parameters, from which the script builds the forces
/// itself), one JSON result per case in order. Used here and by tests/reference.rs.
pub fn run_script(cases: Vec<Value>) -> Result<Vec<Value>, ScriptError> {
    use ScriptError::{Failed, Unavailable};
    let script = ShippedScript::write("mp_engine.py", SCRIPT_TEXT)
        .map_err(|e| Unavailable(format!("{SCRIPT} cannot be written ({e})")))?;
    let expected = cases.len();
    let input = Value::Array(cases);
    let mut child = script
        .command()
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| Unavailable(format!("python3 was not found ({e})")))?;
    // A script that exits at once (no mpmath) closes the pipe: its exit code tells.
    if let Some(mut stdin) = child.stdin.take() {
        let _ = stdin.write_all(input.to_string().as_bytes());
    }
    let out = child
        .wait_with_output()
        .map_err(|e| Failed(format!("python3 did not finish ({e})")))?;
    if out.status.code() == Some(NO_MPMATH) {
        return Err(Unavailable(
            "mpmath is not installed (python3 -m pip install mpmath)".into(),
        ));
    }
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        return Err(Failed(format!(
            "the 40-digit integration failed: {}",
            err.lines().last().unwrap_or("no message")
        )));
    }
    let list: Vec<Value> = serde_json::from_slice(&out.stdout)
        .map_err(|e| Failed(format!("the 40-digit integration wrote no JSON list ({e})")))?;
    if list.len() != expected {
        return Err(Failed(format!(
            "the 40-digit integration returned {} results for {expected} problems",
            list.len(),
        )));
    }
    Ok(list)
}

/// A decimal string of the script as f64 (NaN when absent or malformed).
fn num(v: &Value) -> f64 {
    v.as_str().and_then(|s| s.parse().ok()).unwrap_or(f64::NAN)
}

/// Slips and sticks of the script's output, every period in order, as (t, kind).
fn mp_events(mp: &Value) -> Vec<(f64, String)> {
    let periods = mp["events"].as_array().map(Vec::as_slice).unwrap_or(&[]);
    periods
        .iter()
        .flat_map(|p| p.as_array().map(Vec::as_slice).unwrap_or(&[]))
        .filter_map(|e| {
            let kind = e[1].as_str()?;
            (kind == "slip" || kind == "stick").then(|| (num(&e[0]), kind.to_string()))
        })
        .collect()
}

fn compare(bp: &BenchProblem, r: &Reference, mp: &Value) -> CheckRow {
    let theirs = mp_events(mp);
    let same_pattern =
        theirs.len() == r.events.len() && r.events.iter().zip(&theirs).all(|(a, b)| a.kind == b.1);
    let max_event_err_s = same_pattern.then(|| {
        r.events
            .iter()
            .zip(&theirs)
            .map(|(a, b)| (a.t - b.0).abs())
            .fold(0.0, f64::max)
    });
    let x_mp = mp["x_at_period_start"]
        .as_array()
        .and_then(|xs| xs.last())
        .map_or(f64::NAN, num);
    CheckRow {
        problem: bp.title.clone(),
        events: r.events.len(),
        events_mp: theirs.len(),
        same_pattern,
        max_event_err_s,
        x_end_err_m: (r.x_end_m - x_mp).abs(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::MethodEvent;

    fn reference(events: &[(f64, &'static str)], x_end_m: f64) -> Reference {
        Reference {
            events: events
                .iter()
                .map(|&(t, kind)| MethodEvent { t, kind })
                .collect(),
            x_end_m,
            v_end_m_s: 0.0,
            vbar_m_s: Some(0.0),
        }
    }

    fn mp(events: serde_json::Value, x_end: &str) -> Value {
        json!({"events": events, "x_at_period_start": ["0", x_end]})
    }

    #[test]
    fn events_are_compared_in_order_and_reversals_are_not_counted() {
        let bp = crate::bench::problems::sweep_problems().unwrap().remove(0);
        let r = reference(&[(0.1, "slip"), (0.2, "stick")], 1.0);
        let out = mp(
            json!([[
                ["0.1000000001", "slip", 1],
                ["0.15", "reversal", -1],
                ["0.2", "stick", 1]
            ]]),
            "1.5",
        );
        let row = compare(&bp, &r, &out);
        assert!(row.same_pattern);
        assert_eq!((row.events, row.events_mp), (2, 2));
        assert!((row.max_event_err_s.unwrap() - 1e-10).abs() < 1e-15);
        assert_eq!(row.x_end_err_m, 0.5);
    }

    #[test]
    fn a_different_pattern_has_no_event_error() {
        let bp = crate::bench::problems::sweep_problems().unwrap().remove(0);
        let r = reference(&[(0.1, "slip"), (0.2, "stick")], 1.0);
        let row = compare(&bp, &r, &mp(json!([[["0.1", "slip", 1]]]), "1"));
        assert!(!row.same_pattern);
        assert_eq!(row.max_event_err_s, None);
    }
}
