//! The context of the benchmark pages: machine, protocol, tables and drawn figures, all as
//! formatted strings for the templates.

use serde::Serialize;

use super::charts;
use super::cost_tables;
use super::crowding::{crowd_tables, CrowdTable};
use super::failures::reversal_slope;
use super::long_run_report::{self, LongRunCtx};
use super::near_tangent::tangent_table;
use super::peer_tables::{peer_section, PeerSection};
use super::step_boundary::boundary_table;
use super::sweep::SweepPoint;
use super::tables::{self, Table};
use super::BenchResults;
use crate::error::{Error, Result};
use crate::report::figures::chart::line_chart;
use crate::report::figures::spec::LineChart;

#[derive(Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
struct Kv {
    name: String,
    value: String,
}

/// A drawn figure: its SVG, caption and file name under the output folder.
#[derive(Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct FigureCtx {
    pub id: String,
    pub caption: String,
    pub svg: String,
    pub file: String,
}

/// Everything the templates show.
#[derive(Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Ctx {
    title: String,
    css: &'static str,
    version: String,
    elapsed: String,
    quick: bool,
    /// One line per method this build leaves out (the diffsol peer without `peers`).
    not_built_in: Vec<String>,
    protocol: Vec<String>,
    machine: Vec<Kv>,
    problems: Table,
    reference_note: String,
    reference_check: Table,
    /// The belt's reference against its closed forms.
    closed_form_note: String,
    closed_form_check: Table,
    /// The methods that do not take a problem, with their reasons.
    refusals: Table,
    costs: Vec<Table>,
    headline: Vec<String>,
    pub wp_figures: Vec<FigureCtx>,
    pub order_figures: Vec<FigureCtx>,
    orders: Table,
    failure_summary: Table,
    failures: Table,
    pub failure_figures: Vec<FigureCtx>,
    regime: Table,
    regime_intro: String,
    creep: Table,
    creep_intro: String,
    near_tangent: Table,
    near_tangent_intro: String,
    step_boundary: Table,
    crowding: Vec<CrowdTable>,
    crowding_intro: String,
    pub long_runs: Vec<LongRunCtx>,
    long_run_protocol: String,
    peer: PeerSection,
}

pub(super) fn figure(id: &str, caption: String, spec: &LineChart) -> Result<FigureCtx> {
    let svg = line_chart(spec).map_err(|e| Error::Figure {
        id: id.to_string(),
        reason: e.to_string(),
    })?;
    // The caption is the figure's text alternative (axe: svg-img-alt).
    let svg = crate::report::figures::style::with_text(&svg, &caption, &caption);
    Ok(FigureCtx {
        id: id.to_string(),
        caption,
        svg,
        file: format!("figures/{id}.svg"),
    })
}

pub fn context(r: &BenchResults) -> Result<Ctx> {
    let names: Vec<String> = r.methods.iter().map(|m| m.name.clone()).collect();
    let m = &r.machine;
    let machine = vec![
        (
            "stickslip",
            format!(
                "{} ({} build, Cargo's release profile), commit {}",
                m.crate_version, m.profile, m.commit
            ),
        ),
        ("compiler", m.rustc.clone()),
        ("CPU", format!("{} × {}", m.nproc, m.cpu)),
        ("load average (1, 5, 15 min)", m.load.clone()),
        ("OS", format!("{} {}", m.os, m.arch)),
        ("diffsol (compiled peer)", m.diffsol.clone()),
        (
            "Python",
            m.python.clone().unwrap_or_else(|| "not found".into()),
        ),
        ("NumPy", m.numpy.clone().unwrap_or_else(|| "—".into())),
        (
            "SciPy",
            m.scipy.clone().unwrap_or_else(|| "not importable".into()),
        ),
        (
            "timing",
            format!(
                "median of {} run(s) after a warm-up, sequential; spread (slowest − fastest) / \
                 median: {}; the exact engine timed as `integrate` without recording segments",
                r.repeats,
                spread(&r.sweep)
            ),
        ),
    ]
    .into_iter()
    .map(|(n, v)| Kv {
        name: n.to_string(),
        value: v,
    })
    .collect();

    let problems = tables::problems(r);
    let (reference_note, reference_check) = tables::reference_check(r);
    let (closed_form_note, closed_form_check) = tables::closed_form_check(r);

    let (costs, headline) = cost_tables::cost_table(r);

    let mut wp_figures = Vec::new();
    let mut order_figures = Vec::new();
    for p in &r.problems {
        let vbar = p.vbar_not_applicable.is_none();
        let wp = charts::work_precision(&p.id, &names, &r.sweep, &r.peer.points, false, vbar);
        wp_figures.push(figure(
            &format!("wp-{}", p.id),
            format!(
                "{}: error against time (log10 both; median of {} runs), one curve per method{}. The exact engine \
                 is the reference (its error is 0, drawn as a marker at its time). Errors below 1e-16 are drawn at 1e-16.{}",
                p.title,
                r.repeats,
                if r.peer.points.iter().any(|q| q.problem == p.id) { ", SciPy in black" } else { "" },
                p.vbar_not_applicable.map_or(String::new(), |why| format!(" No v̄ panel: {why}.")),
            ),
            &wp,
        )?);
        let work = charts::work_precision(&p.id, &names, &r.sweep, &[], true, vbar);
        wp_figures.push(figure(
            &format!("work-{}", p.id),
            format!(
                "{}: error against work (rhs evaluations, machine-independent), log10 both.",
                p.title
            ),
            &work,
        )?);
        let order = charts::order_chart(&p.id, &names, &r.sweep, &r.failures.studies.orders);
        order_figures.push(figure(
            &format!("order-{}", p.id),
            format!(
                "{}: error against step size for the fixed-step methods; the legend gives the least-squares \
                 slope of log10 error against log10 h over the finest steps above the round-off floor.",
                p.title
            ),
            &order,
        )?);
    }

    let orders = tables::orders(r);

    let (failure_summary, failures) = tables::failure_tables(r);
    let failure_figures = failure_figures(r)?;
    let regime = tables::regime(r);
    let creep = tables::creep(r);
    let near_tangent = tangent_table(&r.failures.studies.near_tangent);
    let step_boundary = boundary_table(&r.failures.studies.step_boundary);
    let long_runs = long_run_report::contexts(&r.long_runs)?;
    let long_run_protocol = long_run_report::protocol(&r.long_runs);

    Ok(Ctx {
        title: "stickslip bench: speed against accuracy, and where methods fail".into(),
        css: crate::report::render::CSS,
        version: r.machine.crate_version.clone(),
        elapsed: format!("{:.1} s", r.elapsed_s),
        quick: r.quick,
        not_built_in: r
            .not_built_in
            .iter()
            .map(|m| m.message.to_string())
            .collect(),
        protocol: protocol(r),
        machine,
        problems,
        reference_note,
        reference_check,
        closed_form_note,
        closed_form_check,
        refusals: tables::refusals(r),
        costs,
        headline,
        wp_figures,
        order_figures,
        orders,
        failure_summary,
        failures,
        failure_figures,
        regime,
        regime_intro: tables::regime_intro(),
        creep,
        creep_intro: tables::creep_intro(),
        near_tangent,
        near_tangent_intro: super::near_tangent::intro(),
        step_boundary,
        crowding: crowd_tables(&r.failures.studies.crowding),
        crowding_intro: super::crowding::intro(),
        long_runs,
        long_run_protocol,
        peer: peer_section(r),
    })
}

fn protocol(r: &BenchResults) -> Vec<String> {
    let g = &r.grid;
    vec![
        format!(
            "Problems: pulled mass set B (μs 0.4, μd 0.35, F 0.10 N) and woodpecker Fig. 15, both force laws, \
             {} periods each, starting stuck at rest; the exact event-driven engine on the same law is the reference. \
             The belt oscillator (the textbook block on a moving belt, default set: the spring's force −k x, \
             sticking at the belt's speed) over {} stick-slip cycles, starting carried by the belt at x = 0, its T \
             the cycle's period; its reference is the exact engine's run, checked against the closed forms. {}",
            r.periods,
            r.periods,
            if r.sweep.iter().any(|p| p.refused()) {
                "A method that does not take a problem is listed with its reason."
            } else {
                "Every method takes every problem (a force depending on the position included)."
            }
        ),
        format!(
            "Adaptive methods: tolerance (rtol = atol) {}; fixed-step methods: {} steps per period (h = T/n).",
            g.tolerances.iter().map(|t| format!("{t:.0e}")).collect::<Vec<_>>().join(", "),
            g.steps_per_period.iter().map(|n| n.to_string()).collect::<Vec<_>>().join(", ")
        ),
        "Errors: max |t − t_exact| over slip/stick events matched in order (if the counts differ, the common prefix; \
         the mismatch is recorded), |x(t_end) − x_exact| and |v̄ − v̄_exact| with v̄ the mean speed of the last period \
         (not on the belt: the block returns to the same place each cycle)."
            .into(),
        format!(
            "Time: median of {} timed run(s) after an untimed warm-up, one run if a run exceeds 1 s; every point is \
             timed alone on one thread; the spread of each point (fastest and slowest run) is in results.csv, its \
             median over the points {}. The exact engine is timed as `integrate` alone, as a user calls it; \
             recording the segments its event list is read from is not timed. Work: rhs evaluations counted by \
             the method itself (for the exact engine: segments).",
            r.repeats,
            spread(&r.sweep)
        ),
    ]
}

fn failure_figures(r: &BenchResults) -> Result<Vec<FigureCtx>> {
    let s = &r.failures.studies;
    let ids: Vec<String> = r.problems.iter().map(|p| p.id.clone()).collect();
    let slopes: Vec<(String, Option<f64>)> = ids
        .iter()
        .map(|id| (id.clone(), reversal_slope(&s.reversals, id, "euler_sign")))
        .collect();
    Ok(vec![
        figure(
            "fail-reversals",
            "euler_sign: spurious velocity reversals per period against the step h, per problem (log10 both; the \
             slope is in the legend, −1 means ∝ 1/h). The exact solutions of these problems have none."
                .into(),
            &charts::reversals_chart(&s.reversals, &ids, &slopes),
        )?,
        figure(
            "fail-creep",
            "Regularized friction μd tanh(v/ε): distance moved in the middle 80 % of the first exact stick phase \
             (top) and rhs evaluations per period (bottom) against ε, tolerance 1e-8. Methods with a stick \
             state move 0 there."
                .into(),
            &charts::creep_chart(&s.creep_epsilon),
        )?,
        figure(
            "fail-missed",
            "Exact slip/stick events with no event of the same kind within 2 % of T, against tolerance: dopri5 \
             (switching functions checked inside each step on the dense output), dopri5_endpoints (step ends \
             only) and diffsol_tsit45 (diffsol's root finding, step ends only), on set B, the woodpecker just below the Fig. 16 threshold (a brief halt) and the pulled mass \
             just below φ_c (a nearly tangential stick)."
                .into(),
            &charts::missed_chart(&s.missed),
        )?,
    ])
}

/// The median over the timed points of (slowest − fastest) / median, as a percentage ("—"
/// when no point has more than one run).
fn spread(sweep: &[SweepPoint]) -> String {
    let mut spreads: Vec<f64> = sweep
        .iter()
        .filter(|p| p.runs > 1)
        .filter_map(|p| Some((p.time_max_s? - p.time_min_s?) / p.time_s?))
        .filter(|s| s.is_finite())
        .collect();
    if spreads.is_empty() {
        return "—".to_string();
    }
    spreads.sort_by(f64::total_cmp);
    format!("{:.0} %", 100.0 * spreads[spreads.len() / 2])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_spread_is_the_median_over_points_of_range_over_median() {
        let point = |min: f64, median: f64, max: f64, runs: u32| {
            let mut p: SweepPoint = serde_json::from_value(serde_json::json!({
                "problem": "p", "method": "m", "setting_kind": "step", "tolerance": null,
                "h_s": 0.1, "steps_per_period": 10.0, "status": "ok", "error": null,
                "time_s": median, "runs": runs, "rhs_evals": 1, "steps": 1, "accepted": null,
                "rejected": null, "n_events": 1, "n_events_exact": 1, "n_matched": 1,
                "kind_mismatches": 0, "reversals": 0, "err_event_s": 0.0, "err_x_m": 0.0,
                "err_vbar_m_s": 0.0, "x_end_m": 0.0, "v_end_m_s": 0.0
            }))
            .unwrap();
            p.time_min_s = Some(min);
            p.time_max_s = Some(max);
            p
        };
        let sweep = [
            point(1.0, 1.1, 1.2, 20),
            point(1.0, 1.0, 1.5, 20),
            point(2.0, 2.0, 2.2, 20),
            point(1.0, 1.0, 9.0, 1),
        ];
        // (0.2/1.1, 0.5, 0.1): median 0.18; the single run is left out.
        assert_eq!(spread(&sweep), "18 %");
        assert_eq!(spread(&sweep[3..]), "—");
    }
}
