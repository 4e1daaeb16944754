//! The SciPy section of the benchmark page: what the peer did (protocol sentence, failed runs and
//! what they missed), then the Python comparison — one row per problem and event-time error
//! level with SciPy's best method against the exact engine and the tool's dopri5 — and the
//! issue's Python targets last. The compiled comparison is the headline ([`super::cost_tables`]).
//!
//! ```text
//! SciPy / exact = best SciPy time / exact time, both read off their work-precision curves at the
//!                 same event-time error (see analysis::cost_at)
//! ```

use serde::Serialize;

use super::analysis::Metric;
use super::peer::{PeerPoint, RatioRow};
use super::tables::{e2, row, table, Table};
use super::BenchResults;
use crate::format::sig;

/// Event-time error levels of the comparison table (s).
pub const TABLE_LEVELS: [f64; 2] = [1e-8, 1e-10];

/// Everything the SciPy section shows, formatted.
#[derive(Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct PeerSection {
    pub status: String,
    pub message: String,
    /// How the script integrates, with its work counts; empty without runs.
    pub protocol: String,
    /// One sentence per failed run: what it found and what it missed.
    pub failures: Vec<String>,
    pub comparison: Table,
    pub targets: Table,
}

/// The SciPy section from the peer report.
pub fn peer_section(r: &BenchResults) -> PeerSection {
    let points = &r.peer.points;
    PeerSection {
        status: r.peer.status.clone(),
        message: r.peer.message.clone(),
        protocol: if points.is_empty() {
            String::new()
        } else {
            protocol(points)
        },
        failures: points
            .iter()
            .filter_map(|p| {
                let title = r.problems.iter().find(|q| q.id == p.problem);
                failure(p, title.map_or(p.problem.as_str(), |q| q.title.as_str()))
            })
            .collect(),
        comparison: comparison(r),
        targets: targets(r),
    }
}

fn total(points: &[PeerPoint], count: impl Fn(&PeerPoint) -> Option<u64>) -> u64 {
    points.iter().filter_map(count).sum()
}

/// How the peer integrates, with the work of all its runs (one pass each, not the timed
/// repeats).
fn protocol(points: &[PeerPoint]) -> String {
    let stuck = total(points, |p| p.steps_stuck);
    format!(
        "SciPy's solve_ivp (RK45, DOP853, Radau) at the sweep's tolerances, in an event-restart \
         loop (bench/scipy_peer.py) restarted at every event, period start and kink of the force \
         law. Only the slips are integrated: the end of each stick is located on the static \
         margin |D| − μs N_f, known in closed form from the force law — solved on the linear \
         pieces, sampled 16 times per piece and refined by brentq (xtol 10⁻¹⁵ t) on the harmonic \
         ones, instead of integrating y′ = 0 through the stick. The belt is sent as its law \
         D = D0 + c x, N_f and the belt's speed v_s: its slips are integrated in the belt's frame \
         (w = v − v_s), and while stuck x = x0 + v_s (t − t0), so the margin is affine in t and \
         the end of the stick is solved for. All runs: {} rhs evaluations in {} \
         steps ({}), and {} margin evaluations, counted apart.",
        total(points, |p| p.nfev),
        total(points, |p| p.steps),
        if stuck == 0 {
            "none while stuck".to_string()
        } else {
            format!("{stuck} while stuck")
        },
        total(points, |p| p.margin_evals),
    )
}

/// A failed run on the problem titled `problem`, in words, or none for a run that succeeded.
fn failure(p: &PeerPoint, problem: &str) -> Option<String> {
    let run = format!("{problem}, {}, tolerance {:.0e}", p.method, p.tol);
    if !p.ok() {
        return Some(format!(
            "{run}: {}",
            p.error.as_deref().unwrap_or("failed without a message")
        ));
    }
    if !p.count_mismatch() {
        return None;
    }
    let found = format!(
        "{run}: {} of {} events",
        p.n_events.unwrap_or(0),
        p.n_events_exact
    );
    Some(match (p.n_missed, p.first_missed_t, &p.first_missed_kind) {
        (Some(n), Some(t), Some(kind)) if n > 0 => format!(
            "{found}; {n} exact events missed (none of the same kind within T/100), the first a \
             {kind} at {} s",
            sig(Some(t), 6)
        ),
        _ => format!("{found}; every exact event has a found one of its kind within T/100"),
    })
}

/// SciPy's best method against the exact engine and dopri5 at each level of [`TABLE_LEVELS`].
fn comparison(r: &BenchResults) -> Table {
    let find = |problem: &str, method: &str, level: f64| -> Option<&RatioRow> {
        r.peer.ratios.iter().find(|x| {
            x.problem == problem
                && x.method == method
                && x.metric == Metric::EventTime
                && x.level == level
        })
    };
    let mut rows = Vec::new();
    for p in &r.problems {
        for level in TABLE_LEVELS {
            let (Some(exact), dopri5) = (find(&p.id, "exact", level), find(&p.id, "dopri5", level))
            else {
                continue;
            };
            let best = exact
                .scipy_time_s
                .iter()
                .flatten()
                .copied()
                .min_by(f64::total_cmp);
            let ratio = |ours: Option<f64>| best.zip(ours).map(|(b, o)| sig(Some(b / o), 3) + "×");
            let dopri5_time = dopri5.and_then(|d| d.time_s);
            rows.push(row(
                vec![
                    p.title.clone(),
                    format!("{level:.0e} s"),
                    exact
                        .best_scipy
                        .clone()
                        .unwrap_or_else(|| "not reached".into()),
                    e2(best),
                    e2(exact.time_s),
                    e2(dopri5_time),
                    ratio(exact.time_s).unwrap_or_else(|| "—".into()),
                    ratio(dopri5_time).unwrap_or_else(|| "—".into()),
                ],
                if best.is_some() { "" } else { "na" },
            ));
        }
    }
    table(
        &[
            "problem",
            "event-time error",
            "best SciPy method",
            "SciPy (s)",
            "exact (s)",
            "dopri5 (s)",
            "SciPy / exact",
            "SciPy / dopri5",
        ],
        rows,
    )
}

/// The issue's targets against SciPy, measured.
fn targets(r: &BenchResults) -> Table {
    table(
        &["target", "problem", "measured", "met"],
        r.peer
            .targets
            .iter()
            .map(|t| {
                let (met, class) = match t.met {
                    Some(true) => ("yes", "pass"),
                    Some(false) => ("no", "fail"),
                    None => ("—", "na"),
                };
                let problem = r.problems.iter().find(|p| p.id == t.problem);
                row(
                    vec![
                        t.target.clone(),
                        problem.map_or_else(|| t.problem.clone(), |p| p.title.clone()),
                        t.measured.clone(),
                        met.into(),
                    ],
                    class,
                )
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    fn point(n_events: usize, missed: Option<(usize, f64, &str)>) -> PeerPoint {
        serde_json::from_value(serde_json::json!({
            "problem": "woodpecker_fig15_harmonic", "method": "DOP853", "tol": 1e-3,
            "status": "ok", "error": null, "time_s": 1e-2, "runs": 1, "nfev": 100,
            "steps": 14, "steps_stuck": 0, "margin_evals": 30,
            "n_events": n_events, "n_events_exact": 80, "err_event_s": 1.7, "x_end_m": 0.1,
            "err_x_m": 1e-3, "n_missed": missed.map_or(0, |m| m.0),
            "first_missed_t": missed.map(|m| m.1), "first_missed_kind": missed.map(|m| m.2)
        }))
        .unwrap()
    }

    #[test]
    fn a_run_with_a_wrong_event_count_says_what_it_missed() {
        let missed = Some((40, 0.08887113616788032, "stick"));
        let text = failure(&point(40, missed), "Woodpecker, Fig. 15, harmonic law").unwrap();
        assert_eq!(
            text,
            "Woodpecker, Fig. 15, harmonic law, DOP853, tolerance 1e-3: 40 of 80 events; 40 exact events \
             missed (none of the same kind within T/100), the first a stick at 0.0888711 s"
        );
    }

    #[test]
    fn a_run_with_the_exact_event_count_is_not_a_failure() {
        assert_eq!(failure(&point(80, None), "Woodpecker"), None);
    }

    #[test]
    fn the_protocol_counts_the_margin_apart_and_no_step_while_stuck() {
        let text = protocol(&[point(80, None), point(80, None)]);
        assert!(
            text.contains(
                "200 rhs evaluations in 28 steps (none while stuck), and 60 margin evaluations"
            ),
            "{text}"
        );
    }
}
