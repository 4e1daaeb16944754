//! How the handout teaches this model: the equation of motion line by line, and how each
//! step of the chain of formulas is explained.

use super::derivation::param as wp_param;
use super::quantity::Key as W;
use crate::derivation::StepKey;
use crate::handout::physics::Note::{self, Label, Numbers, Sentence};

/// (LaTeX, sentence) lines of the woodpecker: guide §5.2.
pub(crate) const EQUATION_OF_MOTION: &[(&str, &str)] = &[
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

/// The step of a woodpecker quantity.
const fn w(k: W) -> StepKey {
    StepKey::Quantity(super::quantity::any(k))
}

pub(crate) const STEPS: &[(StepKey, Note)] = &[
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
pub(crate) const HEADINGS: &[(StepKey, &str)] = &[
    (w(W::T01), "Phase I: F_e falls through zero (0 ≤ t ≤ T/2)"),
    (
        w(W::T02),
        "Phase II: F_e rises through zero (T/2 ≤ t ≤ T); the formulas of phase I with \
         u^(−) ↔ u^(+), η ↔ η', the numbers",
    ),
];
