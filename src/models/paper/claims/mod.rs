//! The paper's eight claims (guide §11), which span its two models: each is judged on the set
//! of the model the user gave, the other model keeping the paper's set, on variations of them
//! (another μd, z0, m_S or λ) and, for statements about "sensible values" in general, on a
//! seeded random sample of valid parameter sets. The vocabulary (claims, verdicts, the sample)
//! and the capability [`PaperClaims`] are shared, in [`crate::claims`].
//!
//! ```text
//! pulled mass + woodpecker params ─┬─ closed forms (formula)     ─┐
//!                                  ├─ exact integration (engine) ─┼─→ Claim { verdict,
//!            Sample { seed, size } ─┴─ random sets (closed forms)  ─┘    finding, numbers }
//! ```
//!
//! ```text
//! claims 1, 2  pulled_mass/claims.rs (and its random sample)
//! claims 3, 7  both.rs
//! claims 4, 6  woodpecker/claims.rs (and its random sample)
//! claim 5      woodpecker/halt.rs         claim 8  woodpecker/lever.rs
//! ```
//!
//! The capability is implemented here for both models, not in their folders: the claims about
//! both need both sets, so the imports run one way, from the paper to its two models.

mod both;

use crate::claims::{Claims, PaperClaims, Sample, Verdict};
use crate::error::Result;
use crate::models::pulled_mass::claims as pulled_mass;
use crate::models::pulled_mass::PulledMassParams;
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::woodpecker::{claims as woodpecker, halt, lever};
use crate::models::Physics;

pub use lever::halt_threshold_z0;

/// Whose parameter set the claims judge: a claim whose domain excludes the set of the model the
/// user gave does not apply; a model the user did not give keeps the paper's set, and a claim
/// about it is shown on a set of the paper inside its domain.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Given {
    /// Neither set was given: both are the paper's.
    Paper,
    /// The pulled-mass set was given.
    PulledMass,
    /// The woodpecker set was given.
    Woodpecker,
}

impl Given {
    fn gave(self, model_id: &str) -> bool {
        match self {
            Self::Paper => false,
            Self::PulledMass => model_id == <PulledMassParams as Physics>::ID,
            Self::Woodpecker => model_id == <WoodpeckerParams as Physics>::ID,
        }
    }
}

impl PaperClaims for PulledMassParams {
    /// The eight claims on this pulled-mass set and the paper's woodpecker set.
    fn claims(&self, given: bool, sample: &Sample) -> Result<Claims> {
        let given = if given {
            Given::PulledMass
        } else {
            Given::Paper
        };
        evaluate_given(self, &WoodpeckerParams::default(), given, sample)
    }
}

impl PaperClaims for WoodpeckerParams {
    /// The eight claims on the paper's pulled-mass set and this woodpecker set.
    fn claims(&self, given: bool, sample: &Sample) -> Result<Claims> {
        let given = if given {
            Given::Woodpecker
        } else {
            Given::Paper
        };
        evaluate_given(&PulledMassParams::default(), self, given, sample)
    }
}

/// The eight claims on sets that are the paper's or stand in for them: no claim is judged
/// outside its domain; a set outside it is replaced by the paper's set (the finding says so).
pub fn evaluate(
    pulled: &PulledMassParams,
    wood: &WoodpeckerParams,
    sample: &Sample,
) -> Result<Claims> {
    evaluate_given(pulled, wood, Given::Paper, sample)
}

/// Checks the parameters and the sample, then evaluates the eight claims; a claim whose domain
/// excludes the set of the model in `given` gets the verdict `does_not_apply` with its reason.
pub fn evaluate_given(
    pulled: &PulledMassParams,
    wood: &WoodpeckerParams,
    given: Given,
    sample: &Sample,
) -> Result<Claims> {
    pulled.validate()?;
    wood.validate()?;
    sample.check()?;
    let pulled_periodic = pulled_mass::periodic_set(pulled)?;
    let claims = vec![
        pulled_mass::claim_1(pulled, sample)?,
        pulled_mass::claim_2(pulled)?,
        both::claim_3(&pulled_periodic, wood)?,
        woodpecker::claim_4(wood, sample),
        halt::claim_5(wood)?,
        woodpecker::claim_6(wood)?,
        both::claim_7(&pulled_periodic, wood)?,
        lever::claim_8(wood)?,
    ];
    let claims = claims
        .into_iter()
        .map(|mut c| {
            if let Some((_, reason)) = c.outside.iter().find(|(m, _)| given.gave(m)) {
                c.verdict = Verdict::DoesNotApply;
                c.does_not_apply = Some(reason.clone());
            }
            c
        })
        .collect();
    Ok(Claims { claims })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::Model;

    /// Through the capability: without a model, the paper's sets, no claim judged outside its
    /// domain; with a model, its set is the one given, and a claim whose domain excludes it
    /// does not apply.
    #[test]
    fn the_capability_evaluates_the_given_set_or_the_papers() {
        let sample = Sample { seed: 3, size: 20 };
        let (paper, wood) = (PulledMassParams::default(), WoodpeckerParams::default());
        assert_eq!(
            crate::claims::paper(&sample).unwrap(),
            evaluate(&paper, &wood, &sample).unwrap()
        );
        // Not slip-stick: outside the domain of claim 2.
        let pulled = PulledMassParams {
            force: 0.35,
            ..paper
        };
        let given = crate::claims::of(&Model::PulledMass(pulled), &sample).unwrap();
        assert_eq!(
            given,
            evaluate_given(&pulled, &wood, Given::PulledMass, &sample).unwrap()
        );
        assert_eq!(given.claims[1].verdict, Verdict::DoesNotApply);
        let stand_in = pulled.claims(false, &sample).unwrap();
        assert_ne!(stand_in.claims[1].verdict, Verdict::DoesNotApply);
        assert_eq!(stand_in, evaluate(&pulled, &wood, &sample).unwrap());
    }
}
