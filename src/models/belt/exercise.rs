//! The belt on a worksheet (`Exercise`): its questions (the closed forms (B5)–(B16) a student
//! works out from ω, x_s, x_d and Δ, which the sheet defines), its regimes, and how a student's
//! parameter set is drawn (tidy lab values) or probed for `check` (the whole valid domain).

use super::formula::Regime as BeltRegime;
use super::params::MU_RANGE;
use super::quantity::{any, Key, Key as B};
use super::{results, BeltParams};
use crate::draws::Draws;
use crate::engine::Run;
use crate::error::Result;
use crate::params::G_STANDARD;
use crate::results::quantity::AnyKey;
use crate::results::Check;
use crate::worksheet::exercise::Exercise;
use crate::worksheet::question::{Kind, Question, Regime};
use crate::worksheet::sample::round3;

/// The regimes a belt worksheet can ask for, the default first: a touching oscillation is
/// drawn with μd = μs exactly.
pub(crate) const REGIMES: &[Regime] = &[
    Regime::new(BeltRegime::StickSlip.id()),
    Regime::new(BeltRegime::TouchingOscillation.id()),
];
/// Where the block sticks for a time 2Δ/v_b > 0 (in a touching oscillation it is 0, and an
/// answer of 0 is not a number to work out).
const STICKING: &[Regime] = &[Regime::new(BeltRegime::StickSlip.id())];

const fn closed(key: Key, regimes: &'static [Regime]) -> Question {
    Question {
        kind: Kind::ClosedForm(any(key)),
        regimes,
    }
}

/// The belt's questions (docs/belt.md (B5)–(B16)), in sheet order.
pub const QUESTIONS: &[Question] = &[
    closed(B::FirstSlipTime, REGIMES),
    closed(B::Amplitude, REGIMES),
    closed(B::TSlip, REGIMES),
    closed(B::TStick, STICKING),
    closed(B::Period, REGIMES),
    closed(B::XMax, REGIMES),
    closed(B::SlipSpeedMax, REGIMES),
    closed(B::EnergyPerCycle, REGIMES),
    Question {
        kind: Kind::Regime(any(B::Regime)),
        regimes: REGIMES,
    },
];

/// The rules that decide the regime, as (regime, condition in LaTeX).
const REGIME_RULES: &[(Regime, &str)] = &[
    (Regime::new(BeltRegime::StickSlip.id()), r"\mu_d < \mu_s"),
    (
        Regime::new(BeltRegime::TouchingOscillation.id()),
        r"\mu_d = \mu_s",
    ),
];

/// The regime boundary `check` packs draws against, in the order of
/// [`Exercise::onto_boundary`].
const BOUNDARIES: [&str; 1] = ["μd = μs"];

impl Exercise for BeltParams {
    const DEFINED: &'static [&'static str] = &[r"\omega", "x_s", "x_d", r"\Delta"];

    fn catalogue() -> &'static [Question] {
        QUESTIONS
    }

    fn regimes() -> &'static [Regime] {
        REGIMES
    }

    fn regime_rules() -> &'static [(Regime, &'static str)] {
        REGIME_RULES
    }

    fn sketch_givens(&self) -> String {
        super::sketch::belt_givens(self)
    }

    fn draw(regime: Regime, rng: &mut Draws) -> Self {
        draw_set(regime, rng)
    }

    fn regime_comparisons(
        &self,
        _value: &dyn Fn(AnyKey) -> Option<f64>,
    ) -> Vec<(&'static str, Option<f64>)> {
        vec![(r"\mu_d", Some(self.mu_d)), (r"\mu_s", Some(self.mu_s))]
    }

    fn probe(rng: &mut Draws) -> Self {
        probe_set(rng)
    }

    fn boundaries() -> &'static [&'static str] {
        &BOUNDARIES
    }

    /// μd moved to μs (1 + offset): only below μs is the set valid.
    fn onto_boundary(&self, _i: usize, offset: f64) -> Option<Self> {
        let mu_d = self.mu_s * (1.0 + offset);
        (MU_RANGE.0..=self.mu_s)
            .contains(&mu_d)
            .then_some(Self { mu_d, ..*self })
    }

    /// The belt's checks; it has no linearized law (its closed forms describe the exact
    /// system), so no run and no figure of one.
    fn checks_and_linear_run(
        &self,
        periods: u32,
        _record_segments: bool,
    ) -> Result<(Vec<Check>, Option<Run>)> {
        Ok((results::evaluate(self, periods)?.checks, None))
    }
}

/// Tidy lab values: m 0.1–2 kg in steps of 0.1 kg, k 10–200 N/m in steps of 10 N/m, v_b
/// 0.01–0.2 m/s in steps of 0.01 m/s, μs 0.3–1 in steps of 0.05, μd 0.05 to 0.6 below μs
/// (stick-slip) or μd = μs (touching oscillation), g = 9.81 m/s².
fn draw_set(regime: Regime, rng: &mut Draws) -> BeltParams {
    let step = |rng: &mut Draws, lo: u32, hi: u32, unit: f64| {
        let n = lo + (rng.unit() * f64::from(hi - lo + 1)) as u32;
        round3(f64::from(n.min(hi)) * unit)
    };
    let mass = step(rng, 1, 20, 0.1);
    let k = step(rng, 1, 20, 10.0);
    let v_b = step(rng, 1, 20, 0.01);
    let mu_s = step(rng, 6, 20, 0.05);
    let mu_d = if regime == Regime::new(BeltRegime::TouchingOscillation.id()) {
        mu_s
    } else {
        let below = step(rng, 1, 12, 0.05);
        round3((mu_s - below).max(0.05))
    };
    BeltParams {
        mass,
        k,
        v_b,
        mu_s,
        mu_d,
        g: G_STANDARD,
    }
}

/// A set anywhere in the valid domain, for `check`: m, k, v_b and g log-uniform over their
/// whole ranges, μs mostly 0.05–1.5 and a quarter log-uniform down to 0.001; μd/μs uniform,
/// close to 1, exactly 1, or small.
fn probe_set(rng: &mut Draws) -> BeltParams {
    let mu_s = if rng.unit() < 0.75 {
        rng.between(0.05, 1.5)
    } else {
        rng.log_between(1e-3, MU_RANGE.1)
    };
    let ratio = match rng.unit() {
        u if u < 0.4 => rng.between(0.0, 1.0),
        u if u < 0.7 => 1.0 - 10f64.powf(-rng.between(1.0, 9.0)),
        u if u < 0.8 => 1.0,
        _ => 10f64.powf(-rng.between(0.0, 3.0)),
    };
    BeltParams {
        mass: rng.log_between(0.01, 10.0),
        k: rng.log_between(1.0, 1e4),
        v_b: rng.log_between(1e-4, 10.0),
        mu_s,
        mu_d: (mu_s * ratio).clamp(MU_RANGE.0, mu_s),
        g: rng.log_between(1.0, 25.0),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::derivation::StepKey;
    use crate::models::belt::formula;

    /// Every question's key answer (its worked step's value) is the closed form of formula.rs,
    /// bit for bit, on drawn sets of both regimes; every drawn set is valid and of its regime.
    #[test]
    fn every_answer_is_the_closed_form_of_its_quantity() {
        let mut rng = Draws::new(29);
        for &regime in REGIMES {
            for _ in 0..50 {
                let p = BeltParams::draw(regime, &mut rng);
                p.validate().unwrap();
                let c = formula::evaluate(&p);
                assert_eq!(c.regime.id(), regime.id(), "{p:?}");
                let steps = super::super::derivation::belt(&p);
                let mut asked = 0;
                for q in QUESTIONS.iter().filter(|q| q.regimes.contains(&regime)) {
                    let Kind::ClosedForm(quantity) = q.kind else {
                        continue;
                    };
                    let key = *super::super::quantity::ALL
                        .iter()
                        .find(|&&k| any(k) == quantity)
                        .unwrap();
                    let step = steps
                        .iter()
                        .find(|s| s.key == StepKey::Quantity(quantity))
                        .unwrap_or_else(|| panic!("no step for {key:?}"));
                    assert_eq!(step.value, c.value(key).number(), "{key:?} {p:?}");
                    asked += 1;
                }
                assert!(asked >= 7, "{regime}: {asked}");
            }
        }
    }

    #[test]
    fn probes_are_valid_and_reach_both_regimes() {
        let mut rng = Draws::new(7);
        let sets: Vec<BeltParams> = (0..400).map(|_| BeltParams::probe(&mut rng)).collect();
        assert!(sets.iter().all(|p| p.validate().is_ok()));
        let touching = sets.iter().filter(|p| p.mu_d == p.mu_s).count();
        assert!(touching > 0 && touching < sets.len());
        let p = BeltParams::default();
        assert_eq!(p.onto_boundary(0, 1e-3), None);
        assert!(p.onto_boundary(0, -1e-3).unwrap().mu_d < p.mu_s);
    }
}
