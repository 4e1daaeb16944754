//! The words of the handout: the equation of motion of each model in symbols (physics.md §1,
//! §2–3), and for each step of the chain of formulas (by its key) what it means: a label for
//! a definition, a sentence of physics for a step of the motion. Keys not named here stay out of
//! the handout's chain (thresholds such as μd,MIN; the report shows them).

use crate::derivation::StepKey;
use crate::models::pulled_mass::{derivation::param as pm_param, quantity::Key as P};
use crate::models::woodpecker::{derivation::param as wp_param, quantity::Key as W};
use crate::models::{with_model, Model};
use crate::present::Present;

/// (LaTeX, sentence) lines of the pulled mass: physics.md §1.1–1.2.
pub(crate) const PULLED_MASS: &[(&str, &str)] = &[
    (
        r"(m + m')\,\ddot x = 2m\,\ddot x = F - \mu_d\,N(t) \quad (\dot x > 0)",
        "while slipping: both masses move (14), friction opposes F (5)",
    ),
    (
        r"N(t) = W\,(1 + \cos\omega t), \quad W = mg, \quad \omega = \sqrt{k/m'}",
        "the hanging mass oscillates: N from 2W (t = 0) to 0 (t = T/2) (8)",
    ),
    (
        r"N(\tau) = 2W\,|1 - 2\tau|, \quad \tau = t/T\;\text{mod}\;1",
        "linearized law, same extremes; the closed forms are exact for it",
    ),
    (
        r"\ddot x = g\left[\frac{\varphi}{2} - \mu_d\,|1 - 2\tau|\right], \quad \varphi = F/W",
        "divided by 2m: the acceleration while slipping (15)",
    ),
    (
        r"F \le \mu_s\,N(t) \;\Rightarrow\;\dot x = 0",
        "stuck while the pull is within the static capacity; stuck again when v returns to 0",
    ),
];

/// (LaTeX, sentence) lines of the woodpecker: physics.md §2–3.1.
pub(crate) const WOODPECKER: &[(&str, &str)] = &[
    (
        r"m_S\,\ddot y = W_S + F_e(t) - 2\lambda\mu_d\,|F_e(t)| \quad (\dot y > 0)",
        "sleeve, y down: weight and spring force drive, friction at two contacts brakes",
    ),
    (
        r"F_e(t) = k\,(z_0 + d_0\cos\omega t), \quad \omega = \sqrt{k/m_W}",
        "the bird oscillates on the spring: a prescribed force on the sleeve",
    ),
    (
        r"F_e(t) = k\,(\delta_0 + \zeta(t)), \quad \zeta(t) = \zeta_0\,(1 - t/\tau)\;\;(0 \le t \le 2\tau), \quad \tau = T/4",
        "linearized law (37), the closed forms are exact for it",
    ),
    (
        r"|W_S + F_e| \le 2\lambda\mu_s\,|F_e| \;\Rightarrow\;\dot y = 0",
        "stuck while the drive is within the static capacity; stuck again when v returns to 0",
    ),
];

/// How a step of the chain is shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Note {
    /// A definition or a shorthand with a few words: the step takes half a row.
    Label(&'static str),
    /// A step of the motion with a sentence of physics: the step takes a whole row.
    Sentence(&'static str),
    /// Only the numbers (symbol = substituted = result), half a row: the woodpecker's phase
    /// II, whose formulas are those of phase I with u^(−) ↔ u^(+), η ↔ η' (physics.md §3.4).
    Numbers,
}

use Note::{Label, Numbers, Sentence};

/// The step of a pulled-mass quantity.
const fn p(k: P) -> StepKey {
    StepKey::Quantity(crate::models::pulled_mass::quantity::any(k))
}

/// The step of a woodpecker quantity.
const fn w(k: W) -> StepKey {
    StepKey::Quantity(crate::models::woodpecker::quantity::any(k))
}

pub(crate) const PULLED_MASS_STEPS: &[(StepKey, Note)] = &[
    (StepKey::Param(pm_param::W), Label("weight of each mass")),
    (
        StepKey::Param(pm_param::OMEGA),
        Label("of the hanging mass"),
    ),
    (StepKey::Param(pm_param::T), Label("period of N(t)")),
    (p(P::Phi), Label("pull in units of W")),
    (
        p(P::TauSlip),
        Sentence("slip condition F = μs N, N falling: the slip starts"),
    ),
    (p(P::TSlip), Label("slip time")),
    (
        p(P::ASlip),
        Sentence("friction drops from μs N to μd N: a jumps from 0"),
    ),
    (
        p(P::TauMaxSpeed),
        Sentence("largest speed where a = 0: F = μd N, N rising"),
    ),
    (p(P::TMaxSpeed), Label("time of the largest speed")),
    (
        p(P::VMax),
        Sentence("area under a(t) from the slip to the maximum"),
    ),
    (p(P::Theta), Label("D = μs² + 2μsμd − μd²")),
    (
        p(P::TauStick),
        Sentence("the area under a(t) since the slip is zero again: stick"),
    ),
    (p(P::TStick), Label("stick time")),
    (p(P::SlipDuration), Label("duration of the slip")),
    (
        p(P::PhiStickMax),
        Label("largest φ that sticks in the same period"),
    ),
    (
        p(P::PhiContinuous),
        Label("above φ_c the mass never sticks again"),
    ),
    (p(P::MuMinEqual), Label("least μ for (20) when μs = μd")),
    (p(P::Gamma), Label("coefficient 1 before D^3/2 (claim 2)")),
    (
        p(P::VAvg),
        Sentence("mean speed: area under v(t) over a period, / T"),
    ),
    (p(P::AdvancePerPeriod), Label("advance per period")),
    (
        p(P::Power),
        Sentence("work of the pull per time = friction dissipation"),
    ),
    (
        p(P::TauStickLate),
        Sentence("beyond (20): stops early in the next period, before the next slip"),
    ),
];

pub(crate) const WOODPECKER_STEPS: &[(StepKey, Note)] = &[
    (StepKey::Param(wp_param::W_S), Label("sleeve weight")),
    (StepKey::Param(wp_param::T), Label("period of F_e(t)")),
    (
        StepKey::Param(wp_param::LAMBDA),
        Label("torque balance: N = λ|F_e|"),
    ),
    (w(W::TauQuarter), Label("quarter period")),
    (w(W::Zeta0), Label("linear counterpart of d0")),
    (w(W::Delta0), Label("linear counterpart of z0")),
    (w(W::USMinus), Label("F_e > 0")),
    (w(W::USPlus), Label("F_e < 0")),
    (w(W::UDMinus), Label("F_e > 0")),
    (w(W::UDPlus), Label("F_e < 0")),
    (w(W::T01), Label("F_e = 0, a = g")),
    (w(W::Delta1), Label("lead of the slip")),
    (
        w(W::TSlip1),
        Sentence("slip condition W_S + F_e = 2λμs|F_e|, F_e falling"),
    ),
    (
        w(W::TMaxSpeed1),
        Sentence("largest speed where a = 0, after F_e = 0"),
    ),
    (
        w(W::VMax1),
        Sentence("area under a(t) from the slip to the maximum"),
    ),
    (w(W::S1), Label("shorthand of (49)")),
    (
        w(W::TStick1),
        Sentence("the area under a(t) since the slip is zero again: stick"),
    ),
    (w(W::Gamma1), Label("shorthand of (55)")),
    (w(W::Distance1), Sentence("distance slid in phase I")),
    (w(W::T02), Numbers),
    (w(W::Delta2), Numbers),
    (w(W::TSlip2), Numbers),
    (w(W::TMaxSpeed2), Numbers),
    (w(W::VMax2), Numbers),
    (w(W::TStick2), Numbers),
    (w(W::Distance2), Numbers),
    (w(W::Gamma), Label("both phases")),
    (
        w(W::VAvg),
        Sentence("mean speed y_S(T)/T; independent of δ0 (claim 6)"),
    ),
    (
        w(W::PowerWeight),
        Sentence("power of the weight, ∝ W_S³; not the dissipation (claim 7)"),
    ),
];

/// Headings before the step of a key: the woodpecker's two phases.
const HEADINGS: &[(StepKey, &str)] = &[
    (w(W::T01), "Phase I: F_e falls through zero (0 ≤ t ≤ T/2)"),
    (
        w(W::T02),
        "Phase II: F_e rises through zero (T/2 ≤ t ≤ T); the formulas of phase I with \
         u^(−) ↔ u^(+), η ↔ η', the numbers",
    ),
];

/// How the step of `key` is shown in the chain of `setup`'s model, and the heading before it;
/// `None`: not in the chain.
pub fn note(setup: &Model, key: StepKey) -> Option<(Note, Option<&'static str>)> {
    fn note_of<M: Present>(_: &M, key: StepKey) -> Option<Note> {
        M::handout_note(key)
    }
    let heading = HEADINGS.iter().find(|(k, _)| *k == key).map(|(_, h)| *h);
    with_model!(setup, p => note_of(p, key)).map(|n| (n, heading))
}

/// The equation of motion of the scene's model, line by line.
pub fn equation_of_motion(setup: &Model) -> &'static [(&'static str, &'static str)] {
    fn lines<M: Present>(_: &M) -> &'static [(&'static str, &'static str)] {
        M::equation_of_motion()
    }
    with_model!(setup, p => lines(p))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::math::mathml;

    #[test]
    fn every_line_renders_to_mathml() {
        for (tex, _) in PULLED_MASS.iter().chain(WOODPECKER) {
            let m = mathml(tex);
            assert!(m.starts_with("<math"), "{tex}: {m}");
            assert!(!m.contains("merror") && !m.contains("&amp;"), "{tex}: {m}");
        }
    }
}
