//! How a handout teaches the belt (docs/belt.md): the equation of motion line by line, and
//! how each step of the chain of formulas ([`super::derivation`]) is explained.

use super::derivation::param;
use super::quantity::Key as B;
use crate::derivation::StepKey;
use crate::present::vocab::Note::{self, Label, Sentence};

/// (LaTeX, sentence) lines of the belt: guide §16.1–16.3.
pub const EQUATION_OF_MOTION: &[(&str, &str)] = &[
    (
        r"m\,\ddot x = -k\,x + f, \quad N = W = mg",
        "the spring pulls the block toward the wall; f is the friction of the belt",
    ),
    (
        r"\dot x = v_b, \quad f = k\,x \le \mu_s\,mg",
        "stuck: carried by the belt while static friction holds the spring (B2)",
    ),
    (
        r"m\,\ddot x = -k\,(x - x_d), \quad x_d = \mu_d\,mg/k \quad (\dot x < v_b)",
        "slipping: the block is slower than the belt, friction μd m g pushes it on (B6)",
    ),
    (
        r"x(\tau) = x_d + \Delta\cos\omega\tau + \frac{v_b}{\omega}\sin\omega\tau",
        "one harmonic arc about x_d from x_s at the belt's speed, until v = v_b again",
    ),
];

/// The step of a belt quantity.
const fn b(k: B) -> StepKey {
    StepKey::Quantity(super::quantity::any(k))
}

/// How each step of [`super::derivation::belt`] is explained, in its order.
pub const STEPS: &[(StepKey, Note)] = &[
    (
        StepKey::Param(param::OMEGA),
        Label("angular frequency of the slip"),
    ),
    (
        StepKey::Param(param::X_S),
        Sentence("the spring overcomes static friction here: the stick ends"),
    ),
    (
        StepKey::Param(param::X_D),
        Label("centre of the slip arc: spring = dynamic friction"),
    ),
    (
        StepKey::Param(param::DELTA),
        Label("how far the slip starts from its centre"),
    ),
    (
        b(B::FirstSlipTime),
        Sentence("carried from x = 0 at the belt's speed to x_s"),
    ),
    (
        b(B::TSlip),
        Sentence("the arc returns to the belt's speed: tan(ωτ/2) = −ωΔ/v_b"),
    ),
    (
        b(B::TStick),
        Sentence("carried from x_e = x_d − Δ back to x_s, a distance 2Δ"),
    ),
    (b(B::Period), Label("one slip and one stick")),
    (b(B::Amplitude), Label("amplitude of the arc about x_d")),
    (b(B::XSlipEnd), Label("where the block sticks again")),
    (b(B::XMax), Label("farthest from the wall")),
    (b(B::XMin), Label("nearest to the wall")),
    (
        b(B::VMin),
        Sentence("fastest back toward the wall, at the arc's centre x_d"),
    ),
    (
        b(B::SlipSpeedMax),
        Label("largest speed relative to the belt"),
    ),
    (
        b(B::EnergyPerCycle),
        Sentence("friction μd m g over the slip's distance relative to the belt"),
    ),
    (b(B::PowerFriction), Label("heat per time")),
    (
        b(B::PowerBelt),
        Sentence("the belt's work per time: the block's energy returns each cycle"),
    ),
    (b(B::StickShare), Label("share of the cycle stuck")),
    (b(B::SlipShare), Label("share of the cycle slipping")),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_step_of_the_derivation_is_explained_in_its_order() {
        let steps = super::super::derivation::belt(&super::super::BeltParams::default());
        let keys: Vec<StepKey> = steps.iter().map(|s| s.key).collect();
        let explained: Vec<StepKey> = STEPS.iter().map(|(k, _)| *k).collect();
        assert_eq!(keys, explained);
    }
}
