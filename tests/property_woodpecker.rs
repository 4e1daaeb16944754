//! Property test: for random valid woodpecker sets covering every regime of guide §8.6, every check of
//! the closed forms (and of the lobe-engine orbit) against the exact linear integration passes
//! at 1e-9, and the closed-form regime is the integrated one.

use std::collections::BTreeMap;

use rand::{rngs::StdRng, Rng, SeedableRng};
use stickslip::models::woodpecker::formula::Counterpart;
use stickslip::models::woodpecker::results::evaluate;
use stickslip::models::woodpecker::{OmegaMode, WoodpeckerParams};

fn random_set(rng: &mut StdRng) -> WoodpeckerParams {
    let mu_s = rng.gen_range(0.2..1.0);
    let d0 = rng.gen_range(0.002..0.02);
    WoodpeckerParams {
        mu_s,
        mu_d: mu_s * rng.gen_range(0.05..=1.0),
        k: rng.gen_range(2.0..60.0),
        m_sleeve: rng.gen_range(0.001..0.03),
        m_bird: rng.gen_range(0.003..0.05),
        l: 0.016,
        h: 0.007,
        z0: d0 * rng.gen_range(-0.2..0.999),
        d0,
        g: 9.81,
        lever: Some(rng.gen_range(0.8..5.0)),
        omega: [OmegaMode::Bird, OmegaMode::Reduced, OmegaMode::Total][rng.gen_range(0..3)],
        counterpart: [
            Counterpart::Extremes,
            Counterpart::Zeros,
            Counterpart::Tangent,
        ][rng.gen_range(0..3)],
    }
}

#[test]
fn every_check_passes_on_random_sets_of_every_regime() {
    let mut rng = StdRng::seed_from_u64(20_171_121);
    let mut seen: BTreeMap<&str, usize> = BTreeMap::new();
    let mut checked = 0;
    for _ in 0..3000 {
        let p = random_set(&mut rng);
        let e = evaluate(&p, 8).expect("valid set");
        *seen.entry(e.closed_form.regime.id()).or_default() += 1;
        for c in &e.checks {
            assert!(c.passed(), "{} failed for {p:?}:\n{c:?}", c.quantity);
        }
        checked += e.checks.len();
        let json = serde_json::to_string(&e).unwrap();
        assert!(!json.contains("NaN"));
    }
    for regime in [
        "double_slip_stick",
        "double_slip_no_halt",
        "single_slip_stick",
        "continuous_or_multiperiod",
        "outside_closed_form_domain",
    ] {
        assert!(
            seen.get(regime).copied().unwrap_or(0) >= 20,
            "{regime}: {seen:?}"
        );
    }
    assert!(checked > 20_000, "{checked} checks");
}
