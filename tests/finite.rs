//! Accepted parameters never give NaN or ∞: over the whole accepted range (every dimensional
//! parameter from 1e-50 to 1e50, friction from 1e-6, φ from 1e-9 to 1e6) an evaluation is
//! either refused with a typed range error, or every number it holds is finite (issue 11,
//! item 4: `--force 1e200` printed `v_max: null`, `--mass 6e-302 --g 9.81e-200` gave φ = inf).
//! The evaluation is written as TOML, which, unlike JSON, keeps `nan` and `inf` visible.

use proptest::prelude::*;
use stickslip::error::Error;
use stickslip::models::pulled_mass::{results as pm, PulledMassParams};
use stickslip::models::woodpecker::formula::Counterpart;
use stickslip::models::woodpecker::{results as wp, OmegaMode, WoodpeckerParams};

/// A magnitude log-uniform over the accepted range.
fn magnitude() -> impl Strategy<Value = f64> {
    (-50.0..50.0f64).prop_map(|e| 10f64.powf(e))
}

fn friction() -> impl Strategy<Value = (f64, f64)> {
    (-6.0..2.0f64, 0.0..1.0f64).prop_map(|(e, r)| {
        let mu_s = 10f64.powf(e);
        (mu_s, (mu_s * r).clamp(1e-6, mu_s))
    })
}

fn assert_finite<T: serde::Serialize>(label: &str, e: &T) {
    let text = toml::to_string(e).expect("an evaluation serializes");
    for line in text.lines() {
        let bad = line
            .split(|c: char| c.is_whitespace() || c == ',' || c == '[' || c == ']')
            .any(|token| matches!(token, "nan" | "inf" | "-inf" | "+inf" | "-nan" | "+nan"));
        assert!(!bad, "{label}: {line}");
    }
}

fn accepted_or_range_error<T: serde::Serialize>(label: String, r: Result<T, Error>) {
    match r {
        Ok(e) => assert_finite(&label, &e),
        Err(Error::InvalidParam { .. } | Error::OutOfRange { .. }) => {}
        Err(other) => panic!("{label}: {other}"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn pulled_mass_results_are_finite_or_refused(
        (mu_s, mu_d) in friction(),
        (mass, k, g) in (magnitude(), magnitude(), magnitude()),
        phi_exp in -9.0..6.0f64,
    ) {
        let p = PulledMassParams { mu_s, mu_d, mass, k, force: 10f64.powf(phi_exp) * mass * g, g };
        accepted_or_range_error(format!("{p:?}"), pm::evaluate(&p, 8));
    }

    #[test]
    fn woodpecker_results_are_finite_or_refused(
        (mu_s, mu_d) in friction(),
        (k, m_sleeve, m_bird) in (magnitude(), magnitude(), magnitude()),
        (l, h, d0, g) in (magnitude(), magnitude(), magnitude(), magnitude()),
        (z0, z0_negative) in (magnitude(), any::<bool>()),
        lever in proptest::option::of(magnitude()),
        (omega, counterpart) in (0..3usize, 0..3usize),
    ) {
        let w = WoodpeckerParams {
            mu_s, mu_d, k, m_sleeve, m_bird, l, h, d0, g, lever,
            z0: if z0_negative { -z0 } else { z0 },
            omega: [OmegaMode::Bird, OmegaMode::Reduced, OmegaMode::Total][omega],
            counterpart: [Counterpart::Zeros, Counterpart::Extremes, Counterpart::Tangent][counterpart],
        };
        accepted_or_range_error(format!("{w:?}"), wp::evaluate(&w, 8));
    }
}
