//! Seeded random parameter sets shared by tests/reference.rs (the 40-digit reference),
//! tests/equal_friction.rs and benches/engine_instructions.rs (the engine's fingerprints), so
//! that the sets a bench fingerprints are the sets the reference checks. Included with
//! `#[path]`: it needs only the core library and `rand`.
#![allow(dead_code)]

use rand::{rngs::StdRng, Rng};
use stickslip::models::woodpecker::formula::Counterpart;
use stickslip::models::woodpecker::{OmegaMode, WoodpeckerParams};

/// A number log-uniform in [lo, hi).
pub fn log_uniform(rng: &mut StdRng, lo: f64, hi: f64) -> f64 {
    10f64.powf(rng.gen_range(lo.log10()..hi.log10()))
}

/// The `i`-th woodpecker set of the reference: μd = μs for every third, light sleeves (W_S
/// small against the spring force make short slips), any counterpart. May be invalid: callers
/// validate.
pub fn woodpecker(rng: &mut StdRng, i: usize) -> WoodpeckerParams {
    let mu_s = rng.gen_range(0.2..1.0);
    let d0 = rng.gen_range(0.002..0.02);
    WoodpeckerParams {
        mu_s,
        mu_d: if i.is_multiple_of(3) {
            mu_s
        } else {
            mu_s * rng.gen_range(0.3..=1.0)
        },
        k: rng.gen_range(2.0..60.0),
        m_sleeve: log_uniform(rng, 1e-8, 0.03),
        m_bird: rng.gen_range(0.003..0.05),
        l: 0.016,
        h: 0.007,
        z0: d0 * rng.gen_range(-0.2..0.999),
        d0,
        g: 9.81,
        lever: Some(rng.gen_range(0.8..5.0)),
        omega: OmegaMode::Bird,
        counterpart: [
            Counterpart::Extremes,
            Counterpart::Zeros,
            Counterpart::Tangent,
        ][rng.gen_range(0..3)],
    }
}
