//! Timing of the pulled-mass pipeline on worked set B of physics.md §5 (μs 0.4, μd 0.35,
//! m 0.06 kg, k 45 N/m, F 0.10 N: one slip and one stick per period, so every period has events
//! to locate): all closed forms, the exact integration of 20 periods of each force law, the
//! steady-state analysis of such a run, and the whole evaluation behind `stickslip eval`.
//!
//! ```text
//! cargo bench --bench engine -- --warm-up-time 1 --measurement-time 3
//! ```
//!
//! Targets: closed forms < 1 µs; 20 periods of either law < 20 µs.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};

use stickslip::engine::{analyse, integrate, RunOptions};
use stickslip::formula::pulled_mass as cf;
use stickslip::model::{pulled_mass, LawKind};
use stickslip::params::PulledMassParams;
use stickslip::results;

/// Periods integrated per run (the targets above are stated for 20).
const PERIODS: u32 = 20;

/// Worked set B.
fn set_b() -> PulledMassParams {
    PulledMassParams {
        mu_d: 0.35,
        force: 0.10,
        ..PulledMassParams::default()
    }
}

fn closed_forms(c: &mut Criterion) {
    let p = set_b();
    let (g, period, phi) = (p.g, p.period(), p.phi());
    c.bench_function("closed forms, all of physics.md 1.3-1.5", |b| {
        b.iter(|| {
            cf::evaluate(
                black_box(g),
                black_box(period),
                black_box(p.force),
                black_box(phi),
                black_box(p.mu_s),
                black_box(p.mu_d),
            )
        })
    });
}

fn integration(c: &mut Criterion) {
    let p = set_b();
    let body = pulled_mass::body(&p);
    let opts = RunOptions {
        periods: PERIODS,
        record_segments: false,
    };
    for (name, kind) in [("linear", LawKind::Linear), ("harmonic", LawKind::Harmonic)] {
        let law = pulled_mass::force_law(&p, kind).expect("set B gives a valid force law");
        c.bench_function(&format!("integrate {PERIODS} periods, {name} law"), |b| {
            b.iter(|| integrate(black_box(&body), black_box(&law), black_box(&opts)))
        });
    }
}

fn steady_analysis(c: &mut Criterion) {
    let p = set_b();
    let law = pulled_mass::force_law(&p, LawKind::Harmonic).expect("valid force law");
    let opts = RunOptions {
        periods: PERIODS,
        record_segments: false,
    };
    let run = integrate(&pulled_mass::body(&p), &law, &opts).expect("set B integrates");
    c.bench_function(&format!("steady analysis of {PERIODS} periods"), |b| {
        b.iter(|| analyse(black_box(&run)))
    });
}

fn whole_evaluation(c: &mut Criterion) {
    let p = set_b();
    c.bench_function(
        "evaluate: closed forms, 8 periods of both laws, checks",
        |b| b.iter(|| results::pulled_mass::evaluate(black_box(&p), black_box(8))),
    );
}

criterion_group!(
    benches,
    closed_forms,
    integration,
    steady_analysis,
    whole_evaluation
);
criterion_main!(benches);
