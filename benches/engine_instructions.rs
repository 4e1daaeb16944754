//! Instruction counts of the engine: a driver for `valgrind --tool=callgrind` that integrates 20
//! periods of one of the four problems of benches/engine.rs (pulled mass set B, woodpecker
//! Fig. 15 set; linear or harmonic law) a given number of times, without criterion's own work.
//! Instruction counts do not depend on the load of the machine, so they compare versions of the
//! engine where wall-clock timings on a shared machine cannot.
//!
//! ```text
//! cargo bench --bench engine_instructions --no-run
//! valgrind --tool=callgrind --toggle-collect='*engine_instructions*integrate_repeatedly*' \
//!     target/release/deps/engine_instructions-<hash> woodpecker-harmonic 1000
//! callgrind_annotate --inclusive=yes callgrind.out.<pid>
//! ```
//!
//! Arguments: the problem (`pulled-mass-linear`, `pulled-mass-harmonic`, `woodpecker-linear`,
//! `woodpecker-harmonic`; all four when omitted) and the number of runs (default 1000).
//! Instructions per run are the collected total divided by the runs; libm calls per period are
//! the calls to sin, cos, sincos, acos, asin divided by 20 × runs.
//!
//! The driver prints a fingerprint of the bits of every event time, position and velocity of the
//! last run, and with the argument `fingerprint` the same over 4 × 2000 seeded random sets of both
//! models and both laws (drawn as in tests/reference.rs, μd = μs and φ down to 1e-9 included):
//! a change to the engine that should keep every event bit for bit is checked by comparing the
//! fingerprints before and after it. The argument `list` prints every event of those runs (to
//! compare two versions event by event where they differ).

use std::hint::black_box;

#[path = "../tests/common/random_sets.rs"]
mod random_sets;

use rand::{rngs::StdRng, Rng, SeedableRng};
use stickslip::engine::{integrate, Body, ForceLaw, Run, RunOptions};
use stickslip::models::pulled_mass::PulledMassParams;
use stickslip::models::woodpecker::WoodpeckerParams;
use stickslip::models::{pulled_mass, woodpecker, LawKind};

/// Periods per run, as in benches/engine.rs.
const PERIODS: u32 = 20;

/// The problems of benches/engine.rs, by name.
fn problems() -> Vec<(&'static str, Body, ForceLaw)> {
    let set_b = PulledMassParams {
        mu_d: 0.35,
        force: 0.10,
        ..PulledMassParams::default()
    };
    let fig_15 = WoodpeckerParams::default();
    let law = |r: stickslip::error::Result<ForceLaw>| r.expect("a valid force law");
    vec![
        (
            "pulled-mass-linear",
            pulled_mass::body(&set_b),
            law(pulled_mass::force_law(&set_b, LawKind::Linear)),
        ),
        (
            "pulled-mass-harmonic",
            pulled_mass::body(&set_b),
            law(pulled_mass::force_law(&set_b, LawKind::Harmonic)),
        ),
        (
            "woodpecker-linear",
            woodpecker::body(&fig_15),
            law(woodpecker::force_law(&fig_15, LawKind::Linear)),
        ),
        (
            "woodpecker-harmonic",
            woodpecker::body(&fig_15),
            law(woodpecker::force_law(&fig_15, LawKind::Harmonic)),
        ),
    ]
}

/// `runs` integrations of 20 periods; the function callgrind collects in.
#[inline(never)]
fn integrate_repeatedly(body: &Body, law: &ForceLaw, runs: u32) -> Run {
    let opts = RunOptions {
        periods: PERIODS,
        record_segments: false,
        dissipation: false,
    };
    let mut last = None;
    for _ in 0..runs {
        last = Some(integrate(black_box(body), black_box(law), black_box(&opts)));
    }
    last.expect("at least one run")
        .expect("the problem integrates")
}

/// FNV-1a over the bits of the event times, positions and velocities and of the state at the
/// start of each period, continuing from `h`.
fn fingerprint(h: u64, run: &Run) -> u64 {
    let events = run.events.iter().flat_map(|e| [e.t, e.x, e.v]);
    let periods = run
        .x_at_period_start
        .iter()
        .chain(run.v_at_period_start.iter());
    events
        .chain(periods)
        .fold(h, |h, x| (h ^ x.to_bits()).wrapping_mul(0x0100_0000_01b3))
}

/// The events of a run, one line each: the set, the kind and t, x, v (or the error).
fn print_events(set: &str, run: &stickslip::error::Result<Run>) {
    match run {
        Ok(run) => {
            for e in &run.events {
                println!("{set}: {:?} {:e} {:e} {:e}", e.kind, e.t, e.x, e.v);
            }
        }
        Err(error) => println!("{set}: {error}"),
    }
}

/// The FNV-1a offset basis.
const FNV_START: u64 = 0xcbf2_9ce4_8422_2325;

/// Random sets per model and law of the `fingerprint` mode.
const RANDOM_SETS: usize = 2000;

/// A pulled-mass set as in tests/reference.rs: φ log-uniform from 1e-9 up to the immediate-slip
/// bound 2μs, μd = μs for every third set.
fn random_pulled_mass(rng: &mut StdRng, i: usize) -> PulledMassParams {
    let mu_s = rng.gen_range(0.1..1.0);
    let mu_d = if i.is_multiple_of(3) {
        mu_s
    } else {
        mu_s * rng.gen_range(0.3..1.0)
    };
    let phi = random_sets::log_uniform(rng, 1e-9, 2.0 * mu_s * 0.9999);
    let (mass, k, g) = (rng.gen_range(0.01..1.0), rng.gen_range(1.0..100.0), 9.81);
    PulledMassParams {
        mu_s,
        mu_d,
        mass,
        k,
        force: phi * mass * g,
        g,
    }
}

/// Fingerprints of 20-period runs of the random sets, per model and law (a set whose law is
/// undefined or whose run fails adds a marker instead); with `list`, every event of every run
/// instead, one line each (set, kind, t, x, v), to compare two versions of the engine event by
/// event.
fn random_fingerprints(list: bool) {
    let opts = RunOptions {
        periods: PERIODS,
        record_segments: false,
        dissipation: false,
    };
    for law_kind in [LawKind::Linear, LawKind::Harmonic] {
        let mut rng = StdRng::seed_from_u64(14);
        let (mut pulled, mut wood) = (FNV_START, FNV_START);
        for i in 0..RANDOM_SETS {
            let p = random_pulled_mass(&mut rng, i);
            let run = pulled_mass::force_law(&p, law_kind)
                .and_then(|law| integrate(&pulled_mass::body(&p), &law, &opts));
            if list {
                print_events(&format!("{law_kind:?} pulled mass {i}"), &run);
            }
            pulled = run.map_or(pulled ^ 1, |r| fingerprint(pulled, &r));
            let w = random_sets::woodpecker(&mut rng, i);
            let run = woodpecker::force_law(&w, law_kind)
                .and_then(|law| integrate(&woodpecker::body(&w), &law, &opts));
            if list {
                print_events(&format!("{law_kind:?} woodpecker {i}"), &run);
            }
            wood = run.map_or(wood ^ 1, |r| fingerprint(wood, &r));
        }
        if list {
            continue;
        }
        println!("{RANDOM_SETS} random sets, {law_kind:?} law: pulled mass {pulled:016x}, woodpecker {wood:016x}");
    }
}

fn main() {
    // `cargo bench` passes `--bench`; the positional arguments are the problem and the runs.
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with("--"))
        .collect();
    let only = args.first().map(String::as_str);
    if let Some(mode @ ("fingerprint" | "list")) = only {
        random_fingerprints(mode == "list");
        return;
    }
    let runs = args
        .get(1)
        .map_or(1000, |r| r.parse().expect("runs: a number"));
    for (name, body, law) in problems() {
        if only.is_some_and(|o| o != name) {
            continue;
        }
        let run = integrate_repeatedly(&body, &law, runs);
        println!(
            "{name}: {runs} runs, {} events kept, events fingerprint {:016x}",
            run.events.len(),
            fingerprint(FNV_START, &run)
        );
    }
}
