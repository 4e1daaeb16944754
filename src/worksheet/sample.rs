//! Seeded drawing of one student's parameter set: each model draws uniformly from ranges
//! around the paper's sets ([`Exercise::draw`]), every value rounded to three significant
//! figures, the values a student types.

use crate::draws::Draws;

use super::exercise::Exercise;
use super::question::Regime;
use crate::error::Result;
use crate::models::{with_capability, Model};

/// `x` to three significant figures, as the nearest f64 of the shortest decimal (0.437, 45.2).
pub fn round3(x: f64) -> f64 {
    format!("{x:.2e}").parse().unwrap_or(x)
}

/// A candidate set for `model`, aimed at `regime` where the draw can be (rounded; the caller
/// checks the regime of the rounded set).
pub fn draw(model: Model, regime: Regime, rng: &mut Draws) -> Result<Model> {
    fn draw_as<M: Exercise>(_: &M, regime: Regime, rng: &mut Draws) -> Model {
        M::draw(regime, rng).into_model()
    }
    with_capability!(&model, exercise, p => Ok(draw_as(p, regime, rng)),
        else Err(model.missing(crate::models::Capability::Exercise)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::Capability;
    use crate::worksheet::question;

    #[test]
    fn rounding_keeps_three_significant_figures_as_typed() {
        assert_eq!(round3(0.436_72), 0.437);
        assert_eq!(round3(45.249), 45.2);
        assert_eq!(round3(0.007_049_9), 0.007_05);
        assert_eq!(round3(9.81), 9.81);
        assert_eq!(format!("{}", round3(0.123_456)), "0.123");
    }

    #[test]
    fn draws_are_valid_and_reproducible() {
        for model in Model::offering(Capability::Exercise) {
            let regime = question::regimes(model)[0];
            let (mut a, mut b) = (Draws::new(3), Draws::new(3));
            for _ in 0..200 {
                let (x, y) = (
                    draw(model, regime, &mut a).unwrap(),
                    draw(model, regime, &mut b).unwrap(),
                );
                assert_eq!(x, y);
                assert_eq!(x.id(), model.id());
                x.validate().unwrap();
            }
        }
    }
}
