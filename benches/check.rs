//! Timing of `stickslip check` on its default sample of 1000 parameter sets: the paper's v̄
//! (27) of the pulled mass and t_SL^(I) (40–42) of the woodpecker, each set evaluated by its
//! closed forms and the exact integration of the linearized law.
//!
//! ```text
//! cargo bench --bench check
//! ```
//!
//! Target: 1000 samples < 0.5 s on this 2-core machine.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};

use stickslip::check::{run, Request, DEFAULT_SAMPLES};
use stickslip::models::Model;

fn request(case: Model, formula: &str, quantity: &str) -> Request {
    Request {
        case,
        formula: formula.to_string(),
        quantity: Some(quantity.to_string()),
        regime: None,
        samples: DEFAULT_SAMPLES,
        seed: 1,
    }
}

fn bench(c: &mut Criterion) {
    let [pulled, wood] = [Model::defaults()[0], Model::defaults()[1]];
    let mut group = c.benchmark_group("check 1000 samples");
    group.sample_size(10);
    for (name, req) in [
        (
            "pulled mass v_avg",
            request(pulled, r"g T \varphi^3 \Gamma", "v_avg"),
        ),
        (
            "woodpecker t_slip_1",
            request(wood, r"t_0^{(I)} - \Delta^{(I)}", "t_slip_1"),
        ),
    ] {
        group.bench_function(name, |b| b.iter(|| black_box(run(&req).unwrap())));
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
