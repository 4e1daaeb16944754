//! Property test: for random valid pulled-mass sets spanning all four regimes of guide §9, every
//! check of the closed forms against the exact linear integration passes at 1e-9.

use proptest::prelude::*;
use stickslip::models::pulled_mass::formula::{self as cf, Regime};
use stickslip::models::pulled_mass::results::evaluate;
use stickslip::models::pulled_mass::PulledMassParams;

/// φ inside the interval of regime `which`, away from its ends by a relative 1e-6.
fn phi_in_regime(which: u8, frac: f64, mu_s: f64, mu_d: f64) -> f64 {
    let (stick, cont) = (
        cf::phi_stick_max(mu_s, mu_d),
        cf::phi_continuous(mu_s, mu_d),
    );
    let (lo, hi) = match which {
        0 => (0.0, stick),
        1 => (stick, cont),
        2 => (cont, 2.0 * mu_s),
        _ => (2.0 * mu_s, 4.0 * mu_s),
    };
    let margin = 1e-6 * hi;
    lo + margin + frac * (hi - lo - 2.0 * margin)
}

fn params() -> impl Strategy<Value = (PulledMassParams, Regime)> {
    (
        0u8..4,
        0.0..1.0f64,
        0.05..1.2f64,
        0.02..=1.0f64,
        0.005..2.0f64,
        0.5..2000.0f64,
        1.0..25.0f64,
    )
        .prop_map(|(which, frac, mu_s, ratio, mass, k, g)| {
            let mu_d = mu_s * ratio;
            let phi = phi_in_regime(which, frac, mu_s, mu_d);
            let p = PulledMassParams {
                mu_s,
                mu_d,
                mass,
                k,
                force: phi * mass * g,
                g,
            };
            let expected = match which {
                0 => Regime::SlipStick,
                1 => Regime::SlipStickLate,
                2 => Regime::ContinuousSlip,
                _ => Regime::ImmediateContinuousSlip,
            };
            (p, expected)
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1200))]

    #[test]
    fn every_check_passes_in_every_regime((p, expected) in params()) {
        let e = evaluate(&p, 8).unwrap();
        prop_assert_eq!(e.closed_form.regime, expected);
        for c in &e.checks {
            prop_assert!(c.passed(), "{:?} failed for {:?}: {:?}", c.quantity, p, c);
        }
        // Each regime checks what it should.
        let has = |q: &str| e.checks.iter().any(|c| c.quantity.id() == q);
        match expected {
            Regime::SlipStick => prop_assert!(has("t_stick") && has("v_avg") && has("power")),
            Regime::SlipStickLate => prop_assert!(has("tau_stick_late") && has("v_avg_late")),
            Regime::ContinuousSlip => prop_assert!(has("t_slip") && !has("t_stick")),
            Regime::ImmediateContinuousSlip => prop_assert!(e.linear.immediate_slip),
        }
        // Keys of guide §14: nothing NaN anywhere in the JSON (serde_json would write null).
        let json = serde_json::to_string(&e).unwrap();
        prop_assert!(!json.contains("NaN"));
    }
}
