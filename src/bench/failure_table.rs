//! The failures table: for every method of the registry (and the endpoint-only dopri5 variant,
//! present or not) one row per failure mode, with the measured value and a verdict. The rows
//! are computed from the sweep and the studies of [`super::failures`]; nothing is dropped:
//! a method that returned errors is listed with them, an absent method says so.

use serde::Serialize;

use super::analysis::{Metric, OrderFit};
use super::failures::{CreepPoint, MissedPoint, RegimePoint, ReversalPoint};
use super::problems::{title, PERIODS};
use super::sweep::{is_compiled_peer, method_kind, MethodKind, SweepPoint};
use super::Studies;
use crate::format::sig;

/// Name of the dopri5 variant that checks the switching functions at step ends only.
pub const ENDPOINTS: &str = "dopri5_endpoints";
/// Creep below this (m) is round-off: a method with a stick state does not move at all.
pub const CREEP_FLOOR_M: f64 = 1e-12;
/// A fitted order this far below the nominal one is an order loss.
pub const ORDER_SLACK: f64 = 0.5;
/// Growth of the rhs evaluations from the largest to the smallest ε beyond which the
/// regularized problem counts as stiff for the method.
pub const STIFF_GROWTH: f64 = 10.0;

/// One row: a method, a failure mode, what was measured and the verdict.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct FailureRow {
    pub method: String,
    pub failure: String,
    pub measured: String,
    /// "fails", "ok" or "not available".
    pub verdict: String,
}

fn row(method: &str, failure: &str, measured: String, fails: bool) -> FailureRow {
    FailureRow {
        method: method.to_string(),
        failure: failure.to_string(),
        measured,
        verdict: if fails { "fails" } else { "ok" }.to_string(),
    }
}

/// The nominal order of a fixed-step method on smooth arcs.
pub fn nominal_order(method: &str) -> Option<f64> {
    match method {
        "rk4" => Some(4.0),
        "moreau" => Some(2.0),
        "euler_sign" => Some(1.0),
        _ => None,
    }
}

/// The table for `methods` (registry order; the endpoint variant appended if absent).
pub fn failure_table(
    methods: &[String],
    sweep: &[SweepPoint],
    studies: &Studies,
) -> Vec<FailureRow> {
    let mut rows = Vec::new();
    for m in methods {
        rows.extend(method_rows(m, sweep, studies));
    }
    if !methods.iter().any(|m| m == ENDPOINTS) {
        rows.push(FailureRow {
            method: ENDPOINTS.to_string(),
            failure: "events missed when only step ends are checked".to_string(),
            measured: format!("not available: no method named {ENDPOINTS} in solver::methods()"),
            verdict: "not available".to_string(),
        });
    }
    rows
}

fn method_rows(m: &str, sweep: &[SweepPoint], s: &Studies) -> Vec<FailureRow> {
    let pts: Vec<&SweepPoint> = sweep.iter().filter(|p| p.method == m).collect();
    let ok: Vec<&SweepPoint> = pts.iter().copied().filter(|p| p.ok()).collect();
    let mut rows = Vec::new();

    // A refusal (a problem the method does not take) is listed with the problems, not here.
    let errors: Vec<&&SweepPoint> = pts.iter().filter(|p| !p.ok() && !p.refused()).collect();
    let measured = match errors.first() {
        None => format!(
            "none in {} sweep runs",
            pts.iter().filter(|p| !p.refused()).count()
        ),
        Some(p) => format!(
            "{} of {} sweep runs returned an error, e.g. {}",
            errors.len(),
            pts.len(),
            p.error.as_deref().unwrap_or("?")
        ),
    };
    rows.push(row(m, "solver errors", measured, !errors.is_empty()));

    let bad: Vec<&&SweepPoint> = ok.iter().filter(|p| p.count_mismatch()).collect();
    let worst = bad
        .iter()
        .max_by_key(|p| p.n_events.unwrap_or(0).abs_diff(p.n_events_exact));
    let measured = match worst {
        None if ok.is_empty() => "no successful run".to_string(),
        None => format!("counts equal in all {} runs", ok.len()),
        Some(p) => format!(
            "{} of {} runs; worst {} vs {} exact ({}, {})",
            bad.len(),
            ok.len(),
            p.n_events.unwrap_or(0),
            p.n_events_exact,
            title(&p.problem),
            setting_of(p)
        ),
    };
    rows.push(row(
        m,
        "event count differs from exact",
        measured,
        !bad.is_empty() || ok.is_empty(),
    ));

    rows.push(reversal_row(m, &ok, &s.reversals));
    rows.push(creep_row(m, &s.creep));
    rows.push(regime_row(m, &s.regime));
    rows.push(super::near_tangent::failure_row(m, &s.near_tangent));
    rows.push(super::crowding::failure_row(m, &s.crowding));
    if is_compiled_peer(m) {
        rows.push(missed_row(m, &s.missed));
    }
    if method_kind(m) == MethodKind::FixedStep {
        rows.push(order_row(m, &s.orders, &pts));
        rows.push(super::step_boundary::failure_row(m, &s.step_boundary));
    }
    if m.starts_with("tanh") {
        rows.push(stiffness_row(m, &s.creep_epsilon));
    }
    rows
}

fn setting_of(p: &SweepPoint) -> String {
    match (p.tolerance, p.steps_per_period) {
        (Some(t), _) => format!("tol {t:.0e}"),
        (_, Some(n)) => format!("T/{n:.0}"),
        _ => "—".to_string(),
    }
}

fn reversal_row(m: &str, ok: &[&SweepPoint], points: &[ReversalPoint]) -> FailureRow {
    let worst = ok
        .iter()
        .filter_map(|p| Some((p.reversals? as f64 / f64::from(PERIODS), *p)))
        .max_by(|a, b| a.0.total_cmp(&b.0));
    let Some((per_period, p)) = worst else {
        return row(
            m,
            "spurious velocity reversals",
            "no successful run".into(),
            true,
        );
    };
    let mut measured = if per_period > 0.0 {
        format!(
            "max {} per period ({}, {}); exact: 0",
            sig(Some(per_period), 3),
            title(&p.problem),
            setting_of(p)
        )
    } else {
        format!("none in {} runs; exact: 0", ok.len())
    };
    let slopes: Vec<String> = points
        .iter()
        .filter(|r| r.method == m)
        .map(|r| r.problem.as_str())
        .fold(Vec::<&str>::new(), |mut v, id| {
            if !v.contains(&id) {
                v.push(id);
            }
            v
        })
        .into_iter()
        .filter_map(|id| {
            let k = super::failures::reversal_slope(points, id, m)?;
            Some(format!(
                "{} ∝ h^{}",
                title(id),
                super::charts::slope_text(Some(k))
            ))
        })
        .collect();
    if per_period > 0.0 && !slopes.is_empty() {
        measured.push_str(&format!("; growth: {}", slopes.join(", ")));
    }
    row(m, "spurious velocity reversals", measured, per_period > 0.0)
}

fn creep_row(m: &str, creep: &[CreepPoint]) -> FailureRow {
    let mine: Vec<&CreepPoint> = creep.iter().filter(|c| c.method == m).collect();
    let parts: Vec<String> = mine
        .iter()
        .map(|c| match (&c.error, c.creep_m) {
            (Some(e), _) => format!("{}: error ({e})", title(&c.problem)),
            (None, v) if c.at_rest == Some(true) && v.is_some_and(|v| v > 0.0) => format!(
                "{}: at rest (v = 0) at both ends; the two runs' positions differ by {} m",
                title(&c.problem),
                sig(v, 3)
            ),
            (None, v) => format!("{}: {} m", title(&c.problem), sig(v, 3)),
        })
        .collect();
    let fails = mine.iter().any(|c| {
        c.error.is_some()
            || (c.at_rest != Some(true) && c.creep_m.is_none_or(|v| v > CREEP_FLOOR_M))
    });
    let measured = if parts.is_empty() {
        "not measured".to_string()
    } else {
        parts.join("; ")
    };
    let failure = if dynamic_only(m) {
        // Not a creep that shrinks with ε or h: where μd N < |D| ≤ μs N the exact body holds
        // and this law, which has no static friction, slides.
        "slides where μs would hold it (the law knows only μd)"
    } else {
        "creep during an exact stick phase"
    };
    row(m, failure, measured, fails)
}

/// Methods whose friction law has only the dynamic coefficient (no stick state, μs unused):
/// they converge to a different model, not to the stick-slip solution with an error.
fn dynamic_only(m: &str) -> bool {
    m == "euler_sign" || m.starts_with("tanh")
}

fn regime_row(m: &str, regime: &[RegimePoint]) -> FailureRow {
    let mine: Vec<&RegimePoint> = regime.iter().filter(|r| r.method == m).collect();
    let n_wrong = mine.iter().filter(|r| r.wrong).count();
    // One clause per boundary case: its wrong settings with what the method found.
    let mut cases: Vec<&str> = Vec::new();
    for r in mine.iter().filter(|r| r.wrong) {
        if !cases.contains(&r.case.as_str()) {
            cases.push(&r.case);
        }
    }
    let clauses: Vec<String> = cases
        .iter()
        .map(|case| {
            let wrong: Vec<&&RegimePoint> =
                mine.iter().filter(|r| r.wrong && r.case == *case).collect();
            let found: Vec<String> = wrong
                .iter()
                .map(|r| match (r.slips, r.sticks) {
                    (Some(sl), Some(st)) => format!("{} → {sl}/{st}", r.setting),
                    _ => format!("{} → error", r.setting),
                })
                .collect();
            let exact = wrong.first().map_or(String::new(), |r| {
                format!("{}/{}", r.exact_slips, r.exact_sticks)
            });
            format!("{} (exact {exact}): {}", title(case), found.join(", "))
        })
        .collect();
    let measured = if n_wrong == 0 {
        format!("all {} classifications right", mine.len())
    } else {
        format!(
            "{n_wrong} of {} wrong (slips/sticks in the last period); {}",
            mine.len(),
            clauses.join("; ")
        )
    };
    row(
        m,
        "regime misclassified near a boundary",
        measured,
        n_wrong > 0,
    )
}

fn missed_row(m: &str, missed: &[MissedPoint]) -> FailureRow {
    let mine: Vec<&MissedPoint> = missed.iter().filter(|p| p.method == m).collect();
    let total: usize = mine.iter().filter_map(|p| p.missed).sum();
    let errors = mine.iter().filter(|p| p.error.is_some()).count();
    let worst = mine.iter().max_by_key(|p| p.missed.unwrap_or(0));
    let mut measured = format!("{total} exact events missed over {} runs", mine.len());
    if let Some(w) = worst.filter(|w| w.missed.unwrap_or(0) > 0) {
        measured.push_str(&format!(
            " (worst: {} of {} at tol {:.0e}, {})",
            w.missed.unwrap_or(0),
            w.n_exact,
            w.tolerance,
            title(&w.problem)
        ));
    }
    if errors > 0 {
        measured.push_str(&format!("; {errors} runs returned an error"));
    }
    row(
        m,
        "events missed when only step ends are checked",
        measured,
        total > 0 || errors > 0,
    )
}

/// The fitted orders of method `m`; runs with a wrong event count are left out of the fits
/// (they are failures), and a problem where every run has one fails this row too.
fn order_row(m: &str, orders: &[OrderFit], pts: &[&SweepPoint]) -> FailureRow {
    let mine: Vec<&OrderFit> = orders
        .iter()
        .filter(|o| o.method == m && o.metric == Metric::XEnd)
        .collect();
    let nominal = nominal_order(m);
    let mut all_miscounted = false;
    let parts: Vec<String> = mine
        .iter()
        .map(|o| {
            let runs: Vec<&&SweepPoint> = pts
                .iter()
                .filter(|p| p.problem == o.problem && p.ok())
                .collect();
            let miscounted = runs.iter().filter(|p| p.count_mismatch()).count();
            match o.order {
                Some(_) => format!(
                    "{} {}",
                    title(&o.problem),
                    super::charts::slope_text(o.order)
                ),
                None if !runs.is_empty() && miscounted == runs.len() => {
                    all_miscounted = true;
                    format!(
                        "{} — (no fit: all {} runs find a wrong number of events)",
                        title(&o.problem),
                        runs.len()
                    )
                }
                None => format!(
                    "{} — (fewer than 3 runs with the right event count and an error above \
                     round-off)",
                    title(&o.problem)
                ),
            }
        })
        .collect();
    let lowest = mine
        .iter()
        .filter_map(|o| o.order)
        .fold(f64::INFINITY, f64::min);
    let fails = all_miscounted
        || match nominal {
            Some(n) => lowest < n - ORDER_SLACK,
            None => false,
        };
    let measured = format!(
        "fitted order in x_end: {} (nominal on smooth arcs: {})",
        parts.join(", "),
        sig(nominal, 1)
    );
    if dynamic_only(m) {
        // The error of a μd-only law against the stick-slip solution tends to the difference
        // of the two models, not to zero: no order to lose.
        let measured = format!(
            "{measured}; the sign(v) law never uses μs, so its runs converge to a μd-only motion, \
             not to the stick-slip solution"
        );
        return row(
            m,
            "converges to a different model (μd only)",
            measured,
            true,
        );
    }
    row(m, "order loss across events", measured, fails)
}

fn stiffness_row(m: &str, sweep: &[CreepPoint]) -> FailureRow {
    let mine: Vec<&CreepPoint> = sweep.iter().filter(|c| c.method == m).collect();
    let mut parts = Vec::new();
    let mut fails = false;
    let mut problems: Vec<&str> = mine.iter().map(|c| c.problem.as_str()).collect();
    problems.dedup();
    for id in problems {
        let by_eps = |pick: fn(f64, f64) -> bool| {
            mine.iter()
                .filter(|c| c.problem == id)
                .filter_map(|c| Some((c.epsilon_m_s?, c)))
                .reduce(|a, b| if pick(a.0, b.0) { a } else { b })
        };
        let (Some((e_hi, hi)), Some((e_lo, lo))) = (by_eps(|a, b| a > b), by_eps(|a, b| a < b))
        else {
            continue;
        };
        match (hi.rhs_per_period, lo.rhs_per_period) {
            (Some(a), Some(b)) => {
                let growth = b / a;
                fails |= growth > STIFF_GROWTH;
                parts.push(format!(
                    "{}: {} → {} rhs/period from ε = {e_hi:.0e} to {e_lo:.0e} m/s (×{})",
                    title(id),
                    sig(Some(a), 3),
                    sig(Some(b), 3),
                    sig(Some(growth), 3)
                ));
            }
            _ => {
                fails = true;
                parts.push(format!("{id}: error at ε = {e_lo:.0e} m/s"));
            }
        }
    }
    let measured = if parts.is_empty() {
        "not measured".to_string()
    } else {
        parts.join("; ")
    };
    row(m, "cost grows as ε → 0 (stiffness)", measured, fails)
}
