//! The cost tables: time and work of every method at equal error, and the headline sentences
//! (the exact engine against the fastest compiled peer: dopri5, dopri5_endpoints or diffsol on
//! the same event loop; SciPy is not in them: its section is [`super::peer_tables`]).

use super::analysis::{CostRow, Metric};
use super::sweep::is_compiled_peer;
use super::tables::{e2, row, Table};
use super::BenchResults;
use crate::format::sig;

/// The error level of the headline cost tables.
pub const HEADLINE_LEVEL: f64 = 1e-8;
/// The target against the compiled peers (issue 14): the exact engine at least this many
/// times faster than the fastest compiled peer ([`is_compiled_peer`]) at event-time error
/// [`TARGET_LEVEL`] (s).
const TARGET_RATIO: f64 = 10.0;
const TARGET_LEVEL: f64 = 1e-10;

/// The cost tables at [`HEADLINE_LEVEL`] (event-time error, x_end error: rows are methods,
/// columns problems) and the headline sentences.
pub fn cost_table(r: &BenchResults) -> (Vec<Table>, Vec<String>) {
    let at_level = |problem: &str, method: &str, metric: Metric, level: f64| -> Option<&CostRow> {
        r.costs.iter().find(|c| {
            c.problem == problem && c.method == method && c.metric == metric && c.level == level
        })
    };
    let at = |problem: &str, method: &str, metric: Metric| {
        at_level(problem, method, metric, HEADLINE_LEVEL)
    };
    let refuses = |problem: &str, method: &str| {
        r.sweep
            .iter()
            .any(|p| p.problem == problem && p.method == method && p.refused())
    };
    let mut header = vec!["method".to_string()];
    header.extend(r.problems.iter().map(|p| p.title.clone()));
    let mut tables = Vec::new();
    for metric in [Metric::EventTime, Metric::XEnd] {
        let rows = r
            .methods
            .iter()
            .map(|m| {
                let mut cells = vec![m.name.clone()];
                let mut reached = false;
                for p in &r.problems {
                    let exact = at(&p.id, "exact", metric).and_then(|c| c.time_s);
                    let c = at(&p.id, &m.name, metric);
                    cells.push(match c.and_then(|c| c.time_s.map(|t| (t, c))) {
                        Some((t, c)) => {
                            reached = true;
                            format!(
                                "{}{} s · {} rhs · {}× exact",
                                if c.overshoot { "≤ " } else { "" },
                                e2(Some(t)),
                                c.rhs_evals.map_or("—".into(), |w| format!("{w:.0}")),
                                exact.map_or("—".into(), |e| sig(Some(t / e), 3))
                            )
                        }
                        None if refuses(&p.id, &m.name) => "refuses it (see the refusals)".into(),
                        None => "not reached".into(),
                    });
                }
                row(cells, if reached { "" } else { "na" })
            })
            .collect();
        tables.push(Table {
            header: header.clone(),
            rows,
        });
    }
    let mut headline = Vec::new();
    for p in &r.problems {
        let exact = at(&p.id, "exact", Metric::EventTime).and_then(|c| c.time_s);
        // The compiled peers that miss events in the study near the regime boundaries.
        let misses = |name: &str| -> usize {
            r.failures
                .studies
                .missed
                .iter()
                .filter(|m| m.method == name)
                .filter_map(|m| m.missed)
                .sum()
        };
        // The fastest compiled peer (dopri5, its endpoint-only variant, diffsol) at an error
        // level, among all or (`misses_none`) among those that miss no event: the exact
        // engine's competitors on the same equations and event loop.
        let fastest_peer = |level: f64, misses_none: bool| {
            r.methods
                .iter()
                .filter(|m| is_compiled_peer(&m.name) && (!misses_none || misses(&m.name) == 0))
                .filter_map(|m| {
                    let cost = at_level(&p.id, &m.name, Metric::EventTime, level)?;
                    Some((cost.time_s?, &m.name))
                })
                .min_by(|a, b| a.0.total_cmp(&b.0))
        };
        // Why the fastest peer may not be the one to trust, and the cost of the fastest that
        // misses no event; said in full once per problem (`explained`: said already).
        let caveat = |name: &str, level: f64, explained: bool| -> String {
            let safe = fastest_peer(level, true);
            let exact_here =
                at_level(&p.id, "exact", Metric::EventTime, level).and_then(|c| c.time_s);
            let safe_ratio = safe
                .zip(exact_here)
                .map(|((t, safe), e)| (safe.as_str(), t / e));
            missed_events_caveat(name, misses(name), safe_ratio, explained)
        };
        let headline_peer = fastest_peer(HEADLINE_LEVEL, false);
        let mut sentence = match (exact, headline_peer) {
            (Some(e), Some((t, name))) => format!(
                "{}: exact {} s; the fastest compiled peer at event-time error \
                 {HEADLINE_LEVEL:.0e} s is {name}, {} s ({}× the exact time).{}",
                p.title,
                e2(Some(e)),
                e2(Some(t)),
                sig(Some(t / e), 3),
                caveat(name, HEADLINE_LEVEL, false)
            ),
            (Some(e), None) => format!(
                "{}: exact {} s; no compiled peer reached event-time error {HEADLINE_LEVEL:.0e} s.",
                p.title,
                e2(Some(e))
            ),
            _ => format!("{}: the exact engine failed.", p.title),
        };
        // The target against the compiled peers: the exact engine ≥ 10× the fastest that
        // misses no event at 1e-10 (a peer that misses events solves an easier problem), where
        // the arcs are not polynomials that an RK method of order ≥ 3 integrates exactly (the
        // harmonic laws and the belt, whose slips are harmonic arcs).
        let exact_at_target =
            at_level(&p.id, "exact", Metric::EventTime, TARGET_LEVEL).and_then(|c| c.time_s);
        if p.law != "linear" {
            sentence.push_str(&match (exact_at_target, fastest_peer(TARGET_LEVEL, true)) {
                (Some(e), Some((t, name))) => {
                    format!(
                    " At {TARGET_LEVEL:.0e} s: {name} (the fastest compiled peer that misses no \
                     event), {}× the exact time (target ≥ {TARGET_RATIO}×: {}).",
                    sig(Some(t / e), 3),
                    if t / e >= TARGET_RATIO { "met" } else { "not met" },
                )
                }
                _ => {
                    format!(" No compiled peer that misses no event reached {TARGET_LEVEL:.0e} s.")
                }
            });
        } else {
            sentence.push_str(
                " (On the linear law every RK method of order ≥ 3 integrates the arcs exactly: no \
                 target against the compiled peers here.)",
            );
        }
        headline.push(sentence);
    }
    (tables, headline)
}

/// The caveat after a headline peer that misses `missed` events in the study near the regime
/// boundaries: what it does and where that is shown (unless `explained` earlier in the same
/// sentence), and the cost (× the exact time) of the fastest peer that misses none.
fn missed_events_caveat(
    name: &str,
    missed: usize,
    safe: Option<(&str, f64)>,
    explained: bool,
) -> String {
    let safe = safe.map(|(safe, ratio)| {
        format!(
            "the fastest peer that misses none, {safe}, costs {}×",
            sig(Some(ratio), 3)
        )
    });
    match (explained, safe) {
        (_, _) if missed == 0 => String::new(),
        (true, Some(safe)) => format!(" ({}.)", upper_first(&safe)),
        (true, None) => String::new(),
        (false, safe) => format!(
            " ({name} checks for a stick only at step ends and misses {missed} events near the \
             regime boundaries, see \"Where methods fail\"{}.)",
            safe.map_or(String::new(), |s| format!("; {s}"))
        ),
    }
}

/// `text` with its first letter upper case.
fn upper_first(text: &str) -> String {
    let mut chars = text.chars();
    chars
        .next()
        .map_or(String::new(), |c| c.to_uppercase().chain(chars).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_peer_that_misses_events_is_explained_once_and_the_safe_peer_costed_each_time() {
        let first = missed_events_caveat("dopri5_endpoints", 496, Some(("dopri5", 6.4512)), false);
        assert_eq!(
            first,
            " (dopri5_endpoints checks for a stick only at step ends and misses 496 events near \
             the regime boundaries, see \"Where methods fail\"; the fastest peer that misses \
             none, dopri5, costs 6.45×.)"
        );
        let again = missed_events_caveat("dopri5_endpoints", 496, Some(("dopri5", 8.43)), true);
        assert_eq!(
            again,
            " (The fastest peer that misses none, dopri5, costs 8.43×.)"
        );
        assert_eq!(
            missed_events_caveat("dopri5_endpoints", 496, None, true),
            ""
        );
        assert!(missed_events_caveat("dopri5_endpoints", 496, None, false)
            .ends_with("see \"Where methods fail\".)"));
        assert_eq!(
            missed_events_caveat("dopri5", 0, Some(("dopri5", 8.0)), false),
            ""
        );
    }
}
