//! The words of the handout: for each step of the chain of formulas (by its key) what it
//! means: a label for a definition, a sentence of physics for a step of the motion (the
//! equation of motion of each model, guide §5.1, guide §5.2 and guide §8, is the report's
//! `context::equation_of_motion`). Keys not named here stay out of
//! the handout's chain (thresholds such as μd,MIN; the report shows them).

use crate::derivation::StepKey;
use crate::models::{with_capability, Model};
pub use crate::present::vocab::Note;
use crate::present::Present;

/// How the step of `key` is shown in the chain of `setup`'s model, and the heading before it;
/// `None`: not in the chain.
pub fn note(setup: &Model, key: StepKey) -> Option<(Note, Option<&'static str>)> {
    fn note_of<M: Present>(_: &M, key: StepKey) -> Option<(Note, Option<&'static str>)> {
        M::handout_note(key)
    }
    with_capability!(setup, present, p => note_of(p, key), else None)
}

#[cfg(test)]
mod tests {
    use crate::models::Model;
    use crate::report::context::equation_of_motion;
    use crate::report::math::mathml;

    #[test]
    fn every_line_renders_to_mathml() {
        let lines = Model::offering(crate::models::Capability::Present)
            .iter()
            .flat_map(equation_of_motion)
            .collect::<Vec<_>>();
        for (tex, _) in lines {
            let m = mathml(tex);
            assert!(m.starts_with("<math"), "{tex}: {m}");
            assert!(!m.contains("merror") && !m.contains("&amp;"), "{tex}: {m}");
        }
    }
}
