//! The failure studies of `stickslip bench`, run after the timed sweep and untimed, so in
//! parallel: creep of every method and of the tanh methods over ε, regime classification and
//! missed events near the regime boundaries, and the fitted orders of the fixed-step methods;
//! near-tangent sticks ([`super::near_tangent`]), events on a step boundary
//! ([`super::step_boundary`]) and crowding events ([`super::crowding`]).

use rayon::prelude::*;
use serde::Serialize;

use super::analysis::{fit_order, Metric, OrderFit};
use super::crowding::{self, CrowdPoint};
use super::failures::{self, CreepPoint, MissedPoint, RegimePoint, ReversalPoint, EPSILONS};
use super::near_tangent::{self, TangentPoint};
use super::problems::{self, BenchProblem, Reference, SweepProblem};
use super::step_boundary::{self, BoundaryPoint};
use super::sweep::{is_compiled_peer, method_kind, Grid, MethodKind, SweepPoint};
use crate::error::Result;
use crate::solver::{Method, Setting};

/// The failure studies.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Studies {
    pub reversals: Vec<ReversalPoint>,
    /// Every method at its creep setting (tolerance 1e-8 or T/10^4).
    pub creep: Vec<CreepPoint>,
    /// Both tanh methods over ε.
    pub creep_epsilon: Vec<CreepPoint>,
    pub missed: Vec<MissedPoint>,
    pub regime: Vec<RegimePoint>,
    pub orders: Vec<OrderFit>,
    /// Slips and sticks at φ = φ_c (1 ± δ), δ = 1e-3 … 1e-13.
    pub near_tangent: Vec<TangentPoint>,
    /// Fixed-step methods with an exact event on a step boundary.
    pub step_boundary: Vec<BoundaryPoint>,
    /// Slips and sticks of an ever weaker pull, the slip shrinking to nothing (Zeno-like).
    pub crowding: Vec<CrowdPoint>,
}

/// The fitted orders of the fixed-step methods on every problem of the sweep and metric it
/// compares (no v̄ on the belt), for the methods that take the problem.
fn orders(
    methods: &[&dyn Method],
    swept: &[(&SweepProblem, &Reference)],
    sweep: &[SweepPoint],
) -> Vec<OrderFit> {
    let mut out = Vec::new();
    for (bp, r) in swept {
        let refused = |m: &str| {
            sweep
                .iter()
                .any(|p| p.problem == bp.id() && p.method == m && p.refused())
        };
        for m in methods
            .iter()
            .filter(|m| method_kind(m.name()) == MethodKind::FixedStep && !refused(m.name()))
        {
            for metric in Metric::ALL {
                let scale = match metric {
                    Metric::EventTime => Some(bp.t_end()),
                    Metric::XEnd => Some(r.x_end_m),
                    Metric::VBar => r.vbar_m_s,
                };
                if let Some(scale) = scale {
                    out.push(fit_order(sweep, bp.id(), m.name(), metric, scale));
                }
            }
        }
    }
    out
}

/// Runs the untimed failure studies (in parallel): the fitted orders on every problem of the
/// sweep `swept`, the rest on the paper's problems (they are defined by its regimes).
pub fn run(
    methods: &[&dyn Method],
    swept: &[(&SweepProblem, &Reference)],
    grid: &Grid,
    sweep: &[SweepPoint],
    quick: bool,
) -> Result<Studies> {
    let find = |id: &str| {
        swept
            .iter()
            .find_map(|(sp, r)| sp.paper().filter(|bp| bp.id == id).map(|bp| (bp, *r)))
    };
    // Creep: one problem per model.
    let creep_cases: Vec<(&BenchProblem, &Reference, (f64, f64))> =
        ["pulled_mass_b_linear", "woodpecker_fig15_harmonic"]
            .iter()
            .filter_map(|id| {
                let (bp, r) = find(id)?;
                Some((bp, r, failures::first_stick_phase(r)?))
            })
            .collect();
    let jobs: Vec<(&dyn Method, usize)> = methods
        .iter()
        .flat_map(|m| (0..creep_cases.len()).map(move |i| (*m, i)))
        .collect();
    let creep: Vec<CreepPoint> = jobs
        .par_iter()
        .map(|(m, i)| {
            let (bp, _, phase) = creep_cases[*i];
            failures::creep(
                *m,
                bp,
                phase,
                failures::creep_setting(*m, bp.period()),
                None,
            )
        })
        .collect();
    let eps: &[f64] = if quick { &[1e-2, 1e-4] } else { &EPSILONS };
    let cases: Vec<(&BenchProblem, (f64, f64))> =
        creep_cases.iter().map(|(bp, _, ph)| (*bp, *ph)).collect();
    let creep_epsilon = failures::creep_epsilon_sweep(&cases, eps);

    // Boundary cases: regime classification, and events missed by step-end checks.
    let boundary = problems::boundary_problems()?;
    let boundary_refs = boundary
        .par_iter()
        .map(problems::reference)
        .collect::<Result<Vec<_>>>()?;
    let regime_jobs: Vec<(&dyn Method, usize, &'static str, Setting)> = methods
        .iter()
        .flat_map(|m| {
            boundary.iter().enumerate().flat_map(move |(i, bp)| {
                failures::regime_settings(method_kind(m.name()), bp.period())
                    .into_iter()
                    .map(move |(level, s)| (*m, i, level, s))
            })
        })
        .collect();
    let regime: Vec<RegimePoint> = regime_jobs
        .par_iter()
        .map(|(m, i, level, s)| {
            failures::classify(*m, &boundary[*i], &boundary_refs[*i], level, *s)
        })
        .collect();

    let mut missed_cases: Vec<(&BenchProblem, &Reference)> =
        find("pulled_mass_b_linear").into_iter().collect();
    for id in [
        "woodpecker_halt_below_harmonic",
        "pulled_mass_phi_c_below_linear",
    ] {
        if let Some(i) = boundary.iter().position(|bp| bp.id == id) {
            missed_cases.push((&boundary[i], &boundary_refs[i]));
        }
    }
    let missed_methods: Vec<&dyn Method> = methods
        .iter()
        .copied()
        .filter(|m| is_compiled_peer(m.name()))
        .collect();
    let missed_jobs: Vec<(&dyn Method, usize, f64)> = missed_methods
        .iter()
        .flat_map(|m| {
            (0..missed_cases.len())
                .flat_map(move |i| grid.tolerances.iter().map(move |&t| (*m, i, t)))
        })
        .collect();
    let missed: Vec<MissedPoint> = missed_jobs
        .par_iter()
        .map(|(m, i, tol)| {
            let (bp, r) = missed_cases[*i];
            failures::missed_events(*m, bp, r, *tol)
        })
        .collect();

    Ok(Studies {
        reversals: failures::reversal_points(sweep),
        creep,
        creep_epsilon,
        missed,
        regime,
        orders: orders(methods, swept, sweep),
        near_tangent: near_tangent::run(methods)?,
        step_boundary: step_boundary::run(methods)?,
        crowding: crowding::run(methods)?,
    })
}
