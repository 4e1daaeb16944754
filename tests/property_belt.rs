//! Property test: for random valid belt sets over the whole lab domain (docs/belt.md), every
//! closed form agrees with the exact integration of the same system at 1e-12 relative, also
//! where the cycle starts days late (the integration measures the cycle in its local time,
//! src/engine/autonomous.rs), and the closed forms hold the identities of the cycle.

use proptest::prelude::*;
use stickslip::models::belt::formula as cf;
use stickslip::models::belt::results::evaluate;
use stickslip::models::belt::BeltParams;

/// Log-uniform over [lo, hi].
fn log_between(lo: f64, hi: f64) -> impl Strategy<Value = f64> {
    (lo.ln()..=hi.ln()).prop_map(f64::exp)
}

/// A set over the lab ranges; μd a fraction of μs, equal coefficients (a touch) one time in
/// eight.
fn params() -> impl Strategy<Value = BeltParams> {
    (
        log_between(0.01, 10.0),
        log_between(1.0, 1e4),
        log_between(1e-4, 10.0),
        0.0..=2.0f64,
        0.0..1.0f64,
        0u8..8,
        1.0..=25.0f64,
    )
        .prop_map(|(mass, k, v_b, mu_s, ratio, equal, g)| BeltParams {
            mass,
            k,
            v_b,
            mu_s,
            mu_d: if equal == 0 { mu_s } else { mu_s * ratio },
            g,
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn closed_forms_agree_with_the_exact_integration_at_1e_12(p in params()) {
        let e = evaluate(&p, 4).unwrap();
        // Flat: a cycle that starts late (a slow belt and a soft spring: x_s / v_b of days
        // against a period of seconds) is measured from its own onset, not as a difference of
        // late absolute times or ledger totals.
        let bound = 1e-12;
        for check in &e.checks {
            prop_assert!(check.passed(), "{p:?}: {check:?}");
            if let Some(r) = check.rel_error {
                prop_assert!(r <= bound, "{p:?}: {check:?} (bound {bound:e})");
            }
        }
        prop_assert!(e.integration.period.is_some(), "{p:?}: no cycle");
    }

    #[test]
    fn the_cycle_holds_its_identities(p in params()) {
        let c = cf::evaluate(&p);
        // The slip lasts between half a turn and a full turn.
        let turn = std::f64::consts::TAU / c.omega;
        prop_assert!(c.t_slip >= 0.5 * turn * (1.0 - 1e-15) && c.t_slip <= turn * (1.0 + 1e-15));
        // The slip ends at 2 x_d − x_s; the extremes are x_d ± A; the shares add to one.
        prop_assert!((c.x_slip_end - (2.0 * c.x_d - c.x_s)).abs() <= 1e-14 * c.x_s.max(c.amplitude));
        prop_assert!((c.x_max - c.x_min - 2.0 * c.amplitude).abs() <= 1e-14 * c.x_max.abs().max(c.amplitude));
        prop_assert!((c.stick_share + c.slip_share - 1.0).abs() <= 1e-15);
        // The mean power is the dynamic friction dragged at the belt's speed (B17).
        let drag = p.mu_d * p.mass * p.g * p.v_b;
        prop_assert!((c.power - drag).abs() <= 1e-14 * drag, "{} vs {drag}", c.power);
        // The fastest backward speed is at least the belt's.
        prop_assert!(-c.v_min >= p.v_b * (1.0 - 1e-15));
    }
}
