//! How the handout teaches this model: the equation of motion line by line, and how each
//! step of the chain of formulas is explained.

use super::derivation::param as pm_param;
use super::quantity::Key as P;
use crate::derivation::StepKey;
use crate::handout::physics::Note::{self, Label, Sentence};

/// (LaTeX, sentence) lines of the pulled mass: guide §5.1.
pub(crate) const EQUATION_OF_MOTION: &[(&str, &str)] = &[
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

/// The step of a pulled-mass quantity.
const fn p(k: P) -> StepKey {
    StepKey::Quantity(super::quantity::any(k))
}

pub(crate) const STEPS: &[(StepKey, Note)] = &[
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
