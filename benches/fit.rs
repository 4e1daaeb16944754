//! Timing of `stickslip fit` on 500 tracked points (synthetic: the model with σ = 0.2 mm
//! noise, 240 fps, the truth of `scenarios/tracked-toy-example.csv`), from the Figs. 26–27
//! scenario values: the default fit (μd, z0, d0), a fit with k free too (started from the
//! data's own period), and one model evaluation (the exact integration behind one residual
//! vector).
//!
//! ```text
//! cargo bench --bench fit
//! ```
//!
//! Target: a 500-point fit < 2 s.

use std::hint::black_box;
use std::path::Path;

use criterion::{criterion_group, criterion_main, Criterion};

use stickslip::fit::data::{parse, ReadOptions, Tracked, Unit};
use stickslip::models::woodpecker::fit::synthetic::Synthetic;
use stickslip::models::woodpecker::fit::{fit, track, FitParam};
use stickslip::models::woodpecker::WoodpeckerParams;

/// The Figs. 26–27 scenario values (the starting point).
fn fig26() -> WoodpeckerParams {
    WoodpeckerParams {
        mu_d: 0.332,
        k: 20.3,
        d0: 0.0095,
        ..WoodpeckerParams::default()
    }
}

fn tracked() -> Tracked {
    let truth = WoodpeckerParams {
        mu_d: 0.34,
        z0: 0.0069,
        d0: 0.0093,
        ..fig26()
    };
    let synthetic = Synthetic {
        truth,
        points: 500,
        frame_rate: 240.0,
        noise: 2e-4,
        seed: 2017,
    };
    let text = synthetic.generate().expect("track").csv(Unit::Mm, "bench");
    parse(&text, Path::new("bench.csv"), &ReadOptions::default()).expect("parses")
}

fn fits(c: &mut Criterion) {
    let data = tracked();
    let start = fig26();
    let mut group = c.benchmark_group("fit 500 points");
    group.sample_size(10);
    group.bench_function("mu_d, z0, d0 (default)", |b| {
        b.iter(|| fit(black_box(&data), black_box(&start), &FitParam::DEFAULT))
    });
    let with_k = [FitParam::MuD, FitParam::Z0, FitParam::D0, FitParam::K];
    group.bench_function("mu_d, z0, d0, k", |b| {
        b.iter(|| fit(black_box(&data), black_box(&start), &with_k))
    });
    let dt: Vec<f64> = data.t.iter().map(|t| t - data.t[0]).collect();
    group.bench_function("one model evaluation", |b| {
        b.iter(|| track(black_box(&start), black_box(0.05), black_box(&dt)))
    });
    group.finish();
}

criterion_group!(benches, fits);
criterion_main!(benches);
