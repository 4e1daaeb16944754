//! `stickslip bench`: speed against accuracy of every method of [`crate::solver`], measured
//! against the exact engine, and where each method fails.
//!
//! ```text
//! problems (pulled mass set B, woodpecker Fig. 15; both laws; 20 periods; the belt, 20 cycles)
//!   → exact references (the belt's checked against its closed forms)
//!   → timed sweep (sequential: nothing else runs while a method is timed)
//!   → SciPy peer (optional, sequential)
//!   → failure studies (untimed, in parallel) → orders, costs at equal error, failures table
//!   → long runs (untimed, in parallel): error growth over 10 … 10⁴ periods
//!   → results (serde) → report (charts, tera pages, JSON, CSV) → writer
//! ```
//!
//! The sweep reads only each method's [`crate::solver::Solution`]: events, final state and
//! statistics. A method that returns an error is a measured failure, never a crash; a method
//! that does not take a problem (the belt, for a method of forces of time only) is listed as
//! refusing it. The failure studies and long runs are defined on the paper's problems only.

use std::time::Instant;

use serde::Serialize;

use crate::error::Result;
#[cfg(feature = "peers")]
use crate::solver::diffsol_peer::DiffsolTsit45;
use crate::solver::dopri5::Dopri5EndpointsOnly;
use crate::solver::{methods, Method};

pub mod analysis;
pub mod belt;
pub mod charts;
pub mod context;
pub mod cost_tables;
pub mod crowding;
pub mod failure_table;
pub mod failures;
pub mod independent;
pub mod long_run_report;
pub mod long_runs;
pub mod machine;
pub mod near_tangent;
pub mod peer;
pub mod peer_tables;
pub mod problems;
pub mod render;
pub mod step_boundary;
pub mod studies;
pub mod sweep;
pub mod tables;

pub use peer::PeerChoice;
pub use render::render;

use crate::models::Model;
use analysis::{cost_rows, CostRow};
use belt::ClosedFormCheck;
use failure_table::{failure_table, FailureRow, ENDPOINTS};
use independent::ReferenceCheck;
use long_runs::LongRuns;
use machine::Machine;
use peer::PeerReport;
use problems::{BenchProblem, Reference, SweepProblem, PERIODS};
pub use studies::Studies;
use sweep::{measure, method_kind, Grid, MethodKind, SweepPoint};

/// Default number of timed runs per setting: enough for a median and its spread on a noisy
/// machine (the review asked for at least 20).
pub const DEFAULT_REPEATS: u32 = 20;

/// What to run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Config {
    /// Reduced sweep (three settings per method, one timed run).
    pub quick: bool,
    /// Timed runs per setting (ignored with `quick`).
    pub repeats: u32,
    pub peer: Option<PeerChoice>,
}

/// A method of the benchmark.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct MethodInfo {
    pub name: String,
    pub kind: MethodKind,
    /// Listed by `solver::methods()` (the endpoint-only dopri5 variant and the diffsol peer are
    /// constructed here).
    pub in_registry: bool,
}

/// A method of the benchmark that this build leaves out, and how to build it in.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct NotBuiltIn {
    pub name: &'static str,
    /// One line for people: what is missing and the build that has it.
    pub message: &'static str,
}

/// A problem of the sweep with its exact reference.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct ProblemInfo {
    pub id: String,
    pub model: &'static str,
    /// "linear" or "harmonic" (the paper's force laws), "spring" (the belt).
    pub law: &'static str,
    pub title: String,
    pub params: Model,
    pub period_s: f64,
    pub periods: u32,
    pub t_end_s: f64,
    pub exact: Reference,
    /// Why the error in the mean speed of the last period is not compared on this problem
    /// (the belt); `None` where it is.
    pub vbar_not_applicable: Option<&'static str>,
    /// The exact reference against the closed forms (the belt; the paper's problems are
    /// checked by a second program: [`BenchResults::reference_check`]).
    pub closed_form_check: Option<ClosedFormCheck>,
}

/// The failures: the table and the studies behind it.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Failures {
    pub table: Vec<FailureRow>,
    #[serde(flatten)]
    pub studies: Studies,
}

/// Everything `stickslip bench` measured (results.json).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct BenchResults {
    pub quick: bool,
    pub repeats: u32,
    pub periods: u32,
    pub machine: Machine,
    pub grid: Grid,
    pub methods: Vec<MethodInfo>,
    /// Methods of the benchmark left out of this build (cargo features), said on the page.
    pub not_built_in: Vec<NotBuiltIn>,
    pub problems: Vec<ProblemInfo>,
    /// The exact references against a 40-digit integration by a second program.
    pub reference_check: ReferenceCheck,
    pub sweep: Vec<SweepPoint>,
    pub costs: Vec<CostRow>,
    pub failures: Failures,
    /// Error growth over long runs (untimed).
    pub long_runs: LongRuns,
    pub peer: PeerReport,
    /// Wall time of the measurements (s), rendering excluded.
    pub elapsed_s: f64,
}

/// The methods of the benchmark: the registry, plus the endpoint-only dopri5 variant when the
/// registry does not list it, plus the compiled peer from a Rust ODE library (diffsol's Tsit45
/// on the same event loop, with the cargo feature `peers`; the registry is the core's, which
/// does not depend on diffsol).
pub fn bench_methods() -> Vec<(Box<dyn Method>, bool)> {
    let mut out: Vec<(Box<dyn Method>, bool)> = methods().into_iter().map(|m| (m, true)).collect();
    if !out.iter().any(|(m, _)| m.name() == ENDPOINTS) {
        out.push((Box::new(Dopri5EndpointsOnly), false));
    }
    #[cfg(feature = "peers")]
    out.push((Box::new(DiffsolTsit45), false));
    out
}

/// The methods of the benchmark that this build leaves out: the diffsol peer without the
/// cargo feature `peers`.
pub fn not_built_in() -> Vec<NotBuiltIn> {
    let mut out = Vec::new();
    if !cfg!(feature = "peers") {
        out.push(NotBuiltIn {
            name: crate::solver::DIFFSOL_PEER,
            message: "The diffsol peer (diffsol_tsit45) is not built in: build with \
                      --features peers to measure it",
        });
    }
    out
}

/// Runs the benchmark. Progress goes to stderr.
pub fn run(config: &Config) -> Result<BenchResults> {
    let started = Instant::now();
    let grid = if config.quick {
        Grid::quick()
    } else {
        Grid::full()
    };
    let repeats = if config.quick {
        1
    } else {
        config.repeats.max(1)
    };
    let mut machine = Machine::detect();
    let registry = bench_methods();
    let not_built_in = not_built_in();
    for m in &not_built_in {
        eprintln!("bench: {}", m.message);
    }
    let all: Vec<&dyn Method> = registry.iter().map(|(m, _)| m.as_ref()).collect();
    let problems = problems::sweep()?;
    let references = problems
        .iter()
        .map(problems::sweep_reference)
        .collect::<Result<Vec<_>>>()?;

    let swept: Vec<(&SweepProblem, &Reference)> = problems.iter().zip(&references).collect();
    // The studies, the peer and the 40-digit check take the paper's problems.
    let pairs: Vec<(&BenchProblem, &Reference)> = swept
        .iter()
        .filter_map(|(sp, r)| Some((sp.paper()?, *r)))
        .collect();
    let reference_check = independent::check(&pairs);
    eprintln!(
        "bench: 40-digit check of the references {:.2} s {}",
        reference_check.elapsed_s, reference_check.reason
    );

    // The timed sweep: one thread, one point after another.
    let mut sweep = Vec::new();
    for (bp, reference) in problems.iter().zip(&references) {
        for m in &all {
            let t0 = Instant::now();
            for setting in grid.settings(method_kind(m.name()), bp.period()) {
                let point = measure(*m, bp, reference, setting, repeats);
                let refused = point.refused();
                sweep.push(point);
                if refused {
                    // A refusal does not depend on the setting: one point says it.
                    break;
                }
            }
            eprintln!(
                "bench: {:<16} {:<28} {:6.2} s",
                m.name(),
                bp.id(),
                t0.elapsed().as_secs_f64()
            );
        }
    }

    let mut peer = match config.peer {
        Some(PeerChoice::Scipy) => {
            let t0 = Instant::now();
            let peered: Vec<_> = if config.quick {
                swept[..1].to_vec()
            } else {
                swept.clone()
            };
            let report = peer::run(&mut machine, &peered, &grid.tolerances, repeats);
            eprintln!(
                "bench: SciPy peer {:.2} s: {}",
                t0.elapsed().as_secs_f64(),
                report.message
            );
            report
        }
        None => {
            // Versions are recorded even without the comparison; a failed probe is stated.
            let _ = peer::probe(&mut machine);
            PeerReport::not_requested(&machine)
        }
    };

    let t0 = Instant::now();
    let ids: Vec<String> = problems.iter().map(|p| p.id().to_string()).collect();
    let names: Vec<String> = all.iter().map(|m| m.name().to_string()).collect();
    let studies = studies::run(&all, &swept, &grid, &sweep, config.quick)?;
    eprintln!("bench: failure studies {:.2} s", t0.elapsed().as_secs_f64());
    let costs = cost_rows(&sweep, &ids, &names);
    peer::compare(&mut peer, &sweep, &ids, &names);
    let t0 = Instant::now();
    let long_runs = long_runs::run(&all, config.quick)?;
    eprintln!("bench: long runs {:.2} s", t0.elapsed().as_secs_f64());
    let mut table = failure_table(&names, &sweep, &studies);
    long_run_report::insert_rows(&mut table, long_run_report::failure_rows(&long_runs));
    let failures = Failures { table, studies };
    Ok(BenchResults {
        quick: config.quick,
        repeats,
        periods: PERIODS,
        machine,
        grid,
        methods: registry
            .iter()
            .map(|(m, in_registry)| MethodInfo {
                name: m.name().to_string(),
                kind: method_kind(m.name()),
                in_registry: *in_registry,
            })
            .collect(),
        not_built_in,
        problems: swept
            .iter()
            .map(|(bp, r)| ProblemInfo {
                id: bp.id().to_string(),
                model: bp.model(),
                law: bp.law_id(),
                title: bp.title(),
                params: bp.params(),
                period_s: bp.period(),
                periods: PERIODS,
                t_end_s: bp.t_end(),
                exact: (*r).clone(),
                vbar_not_applicable: bp.vbar_not_applicable(),
                closed_form_check: match bp {
                    SweepProblem::Belt(b) => Some(belt::closed_form_check(b, r)),
                    SweepProblem::Paper(_) => None,
                },
            })
            .collect(),
        reference_check,
        sweep,
        costs,
        failures,
        long_runs,
        peer,
        elapsed_s: started.elapsed().as_secs_f64(),
    })
}
