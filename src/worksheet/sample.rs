//! Seeded drawing of one student's parameter set: uniform draws from ranges around the paper's
//! sets (the pulled mass's force aimed at the requested regime), every value rounded to three
//! significant figures, the values a student types.

use rand::rngs::StdRng;
use rand::Rng;

use crate::models::pulled_mass::formula as pm;
use crate::models::woodpecker::formula as wp;
use crate::models::woodpecker::results::linear_inputs;
use crate::params::{ModelName, PulledMassParams, WoodpeckerParams, G_STANDARD};
use crate::worksheet::question::Regime;

/// One student's case: the model and its parameters (SI).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Case {
    PulledMass(PulledMassParams),
    Woodpecker(WoodpeckerParams),
}

impl Case {
    /// The regime of the linearized law from the closed forms (physics.md §1.5, §3.6).
    pub fn regime(&self) -> Regime {
        match self {
            Case::PulledMass(p) => Regime::PulledMass(pm::regime(p.phi(), p.mu_s, p.mu_d)),
            Case::Woodpecker(p) => Regime::Woodpecker(wp::evaluate(&linear_inputs(p)).regime),
        }
    }
}

/// `x` to three significant figures, as the nearest f64 of the shortest decimal (0.437, 45.2).
pub fn round3(x: f64) -> f64 {
    format!("{x:.2e}").parse().unwrap_or(x)
}

/// A candidate set for `model`, aimed at `regime` where the draw can be (rounded; the caller
/// checks the regime of the rounded set).
pub fn draw(model: ModelName, regime: Regime, rng: &mut StdRng) -> Case {
    match model {
        ModelName::PulledMass => Case::PulledMass(pulled_mass(regime, rng)),
        ModelName::Woodpecker => Case::Woodpecker(woodpecker(rng)),
    }
}

/// μs 0.25–0.8, μd/μs 0.5–1, m 20–200 g, k 10–100 N/m, and F = φW with φ inside the interval of
/// the regime (§1.5), away from its ends; the same period's slip-stick keeps φ ≥ 0.3/Θ so that
/// the motion is large enough to see.
fn pulled_mass(regime: Regime, rng: &mut StdRng) -> PulledMassParams {
    let mu_s = rng.gen_range(0.25..0.8);
    let mu_d = mu_s * rng.gen_range(0.5..=1.0);
    let mass = rng.gen_range(0.02..0.2);
    let k = rng.gen_range(10.0..100.0);
    let (stick, cont) = (
        pm::phi_stick_max(mu_s, mu_d),
        pm::phi_continuous(mu_s, mu_d),
    );
    let (lo, hi) = match regime {
        Regime::PulledMass(pm::Regime::SlipStickLate) => (stick, cont),
        Regime::PulledMass(pm::Regime::ContinuousSlip) => (cont, 2.0 * mu_s),
        _ => (0.3 * stick, stick),
    };
    let phi = lo + rng.gen_range(0.02..0.98) * (hi - lo);
    PulledMassParams {
        mu_s: round3(mu_s),
        mu_d: round3(mu_d),
        mass: round3(mass),
        k: round3(k),
        force: round3(phi * mass * G_STANDARD),
        g: G_STANDARD,
    }
}

/// Around the paper's Fig. 15 toy: μs 0.5–0.8, μd/μs 0.3–1, k 10–40 N/m, m_S 4–12 g,
/// m_W 8–25 g, l 12–20 mm, h 5–10 mm, d0 6–12 mm, z0/d0 0.3–0.95; λ = l/h, ω = √(k/m_W) and the
/// `zeros` counterpart (the defaults).
fn woodpecker(rng: &mut StdRng) -> WoodpeckerParams {
    let mu_s = rng.gen_range(0.5..0.8);
    let d0 = rng.gen_range(0.006..0.012);
    WoodpeckerParams {
        mu_s: round3(mu_s),
        mu_d: round3(mu_s * rng.gen_range(0.3..=1.0)),
        k: round3(rng.gen_range(10.0..40.0)),
        m_sleeve: round3(rng.gen_range(0.004..0.012)),
        m_bird: round3(rng.gen_range(0.008..0.025)),
        l: round3(rng.gen_range(0.012..0.020)),
        h: round3(rng.gen_range(0.005..0.010)),
        z0: round3(d0 * rng.gen_range(0.3..0.95)),
        d0: round3(d0),
        g: G_STANDARD,
        ..WoodpeckerParams::default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;

    #[test]
    fn rounding_keeps_three_significant_figures_as_typed() {
        assert_eq!(round3(0.436_72), 0.437);
        assert_eq!(round3(45.249), 45.2);
        assert_eq!(round3(0.007_049_9), 0.007_05);
        assert_eq!(round3(9.81), 9.81);
        assert_eq!(format!("{}", round3(0.123_456)), "0.123");
    }

    const SLIP_STICK: Regime = Regime::PulledMass(pm::Regime::SlipStick);

    #[test]
    fn draws_are_valid_and_reproducible() {
        for model in [ModelName::PulledMass, ModelName::Woodpecker] {
            let (mut a, mut b) = (StdRng::seed_from_u64(3), StdRng::seed_from_u64(3));
            for _ in 0..200 {
                let (x, y) = (
                    draw(model, SLIP_STICK, &mut a),
                    draw(model, SLIP_STICK, &mut b),
                );
                assert_eq!(x, y);
                match x {
                    Case::PulledMass(p) => p.validate().unwrap(),
                    Case::Woodpecker(p) => p.validate().unwrap(),
                }
            }
        }
    }
}
