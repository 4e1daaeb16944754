//! The questions a worksheet can ask, per model: the quantity asked for (whose derivation step
//! answers it, whose check of the exact integration confirms it, and whose symbol and unit the
//! registry gives), what is asked, and the regimes in which its closed form can describe the
//! motion. Also the regimes a teacher can ask for and the inequalities that decide them.

use super::exercise::Exercise;
use crate::models::pulled_mass::{formula::Regime as PulledRegime, quantity::Key as P};
use crate::models::woodpecker::{formula::OrbitRegime, quantity::Key as W};
use crate::models::{with_model, Model};
use crate::results::quantity::AnyKey;

/// A regime a worksheet can ask for: a closed-form regime of its model, by id.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Regime(&'static str);

impl Regime {
    /// The regime with this id (a model's closed-form regime id, in const context).
    pub const fn new(id: &'static str) -> Self {
        Self(id)
    }

    /// The id (`--regime`, answer-key.json).
    pub fn id(self) -> &'static str {
        self.0
    }
}

impl std::fmt::Display for Regime {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.id())
    }
}

/// How a question is answered; each names the quantity it asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Compute a closed form: its derivation step, confirmed by its check of the exact
    /// integration of the linearized law.
    ClosedForm(AnyKey),
    /// Compute the least μd for a stick before T/2 (its derivation step), confirmed by
    /// searching that μd on the exact integration.
    Threshold(AnyKey),
    /// Decide the regime from the inequalities, confirmed by the check of the regime.
    Regime(AnyKey),
    /// Read the first speed maximum off the student's v(t) figure (the step and check of the
    /// closed form that gives it).
    ReadFigure(AnyKey),
}

impl Kind {
    /// The quantity asked for.
    pub fn quantity(self) -> AnyKey {
        match self {
            Kind::ClosedForm(k) | Kind::Threshold(k) | Kind::Regime(k) | Kind::ReadFigure(k) => k,
        }
    }
}

/// One question of the catalogue.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Question {
    pub kind: Kind,
    /// What the student is asked (plain text).
    pub prompt: &'static str,
    /// Regimes in which the answer can exist.
    pub regimes: &'static [Regime],
}

impl Question {
    /// Key used by `--questions` and in answer-key.json: the §7 key of the quantity, `read_`
    /// before it for the figure.
    pub fn key(&self) -> String {
        match self.kind {
            Kind::ReadFigure(k) => format!("read_{}", k.id()),
            kind => kind.quantity().id().to_string(),
        }
    }

    /// LaTeX symbol of the answer ("" for the regime).
    pub fn symbol(&self) -> &'static str {
        match self.kind {
            Kind::Regime(_) => "",
            kind => kind.quantity().quantity().tex,
        }
    }

    /// SI unit expected ("" when dimensionless or a name).
    pub fn unit(&self) -> &'static str {
        self.kind.quantity().quantity().unit
    }
}

const fn p(k: P) -> AnyKey {
    crate::models::pulled_mass::quantity::any(k)
}

const fn w(k: W) -> AnyKey {
    crate::models::woodpecker::quantity::any(k)
}

pub(crate) const PULLED_REGIMES: &[Regime] = &[
    Regime::new(PulledRegime::SlipStick.id()),
    Regime::new(PulledRegime::SlipStickLate.id()),
    Regime::new(PulledRegime::ContinuousSlip.id()),
];
const SAME_PERIOD: &[Regime] = &[Regime::new(PulledRegime::SlipStick.id())];
pub(crate) const WOODPECKER_REGIMES: &[Regime] = &[
    Regime::new(OrbitRegime::DoubleSlipStick.id()),
    Regime::new(OrbitRegime::DoubleSlipNoHalt.id()),
    Regime::new(OrbitRegime::SingleSlipStick.id()),
    Regime::new(OrbitRegime::ContinuousOrMultiperiod.id()),
];
const STANDARD: &[Regime] = &[Regime::new(OrbitRegime::DoubleSlipStick.id())];
/// Where the first slip's speed peaks in the lobe after the zero of F_e, as (46)–(48) assume:
/// not with a single speed maximum (u_B h_B ≤ 1, no deceleration there). μd,MIN^(I) (51) is
/// left out there too: its threshold is then mostly 1/η, not (51), and the sets on which the
/// integration confirms it are too rare to draw together with t_SL^(I).
const PEAK_IN_LOBE_B: &[Regime] = &[
    Regime::new(OrbitRegime::DoubleSlipStick.id()),
    Regime::new(OrbitRegime::DoubleSlipNoHalt.id()),
    Regime::new(OrbitRegime::ContinuousOrMultiperiod.id()),
];

/// The pulled-mass questions (physics.md §1.3, §1.5), in sheet order.
pub const PULLED_MASS: &[Question] = &[
    Question {
        kind: Kind::ClosedForm(p(P::TSlip)),
        prompt: "At what time does the block first start to slip? (eqs. 13, 25)",
        regimes: PULLED_REGIMES,
    },
    Question {
        kind: Kind::ClosedForm(p(P::TStick)),
        prompt: "At what time does it stick again? (eqs. 18, 25)",
        regimes: SAME_PERIOD,
    },
    Question {
        kind: Kind::ClosedForm(p(P::VMax)),
        prompt: "What is the largest speed of the first slip? (eq. 26)",
        regimes: PULLED_REGIMES,
    },
    Question {
        kind: Kind::ClosedForm(p(P::VAvg)),
        prompt: "What is the mean speed of the block over a period? (eqs. 27, 28)",
        regimes: SAME_PERIOD,
    },
    Question {
        kind: Kind::ClosedForm(p(P::Power)),
        prompt: "What power does friction dissipate on average? (eq. 29)",
        regimes: SAME_PERIOD,
    },
    Question {
        kind: Kind::Regime(p(P::Regime)),
        prompt: "Which regime is the block in? Decide from the inequalities below.",
        regimes: PULLED_REGIMES,
    },
    Question {
        kind: Kind::ReadFigure(p(P::VMax)),
        prompt: "Read the first speed maximum off Figure 1.",
        regimes: PULLED_REGIMES,
    },
];

/// The woodpecker questions (physics.md §3.3–3.6), in sheet order.
pub const WOODPECKER: &[Question] = &[
    Question {
        kind: Kind::ClosedForm(w(W::TSlip1)),
        prompt: "At what time does the sleeve first start to slip (phase I)? (eqs. 40–42)",
        regimes: WOODPECKER_REGIMES,
    },
    Question {
        kind: Kind::ClosedForm(w(W::TStick1)),
        prompt: "At what time does it stick again in phase I? (eqs. 49, 50)",
        regimes: STANDARD,
    },
    Question {
        kind: Kind::ClosedForm(w(W::VMax1)),
        prompt: "What is the largest speed of the phase-I slip? (eq. 48)",
        regimes: PEAK_IN_LOBE_B,
    },
    Question {
        kind: Kind::Threshold(w(W::MuDMin1)),
        prompt: "What is the least dynamic coefficient for which the sleeve sticks before \
                 t = T/2? (eq. 51)",
        regimes: PEAK_IN_LOBE_B,
    },
    Question {
        kind: Kind::ClosedForm(w(W::VAvg)),
        prompt: "What is the mean speed of the sleeve? (eqs. 54, 69–71)",
        regimes: STANDARD,
    },
    Question {
        kind: Kind::Regime(w(W::Regime)),
        prompt: "Which regime is the sleeve in? Decide from the inequalities below.",
        regimes: WOODPECKER_REGIMES,
    },
    Question {
        kind: Kind::ReadFigure(w(W::VMax1)),
        prompt: "Read the first speed maximum off Figure 1.",
        regimes: PEAK_IN_LOBE_B,
    },
];

/// The question catalogue of a model.
pub fn catalogue(model: Model) -> &'static [Question] {
    fn of<M: Exercise>(_: &M) -> &'static [Question] {
        M::catalogue()
    }
    with_model!(&model, p => of(p))
}

/// Regimes a worksheet can ask for (closed-form regimes), the default first. The others
/// (immediate slip, no slip, outside the closed-form domain) leave no closed form to compute.
pub fn regimes(model: Model) -> &'static [Regime] {
    fn of<M: Exercise>(_: &M) -> &'static [Regime] {
        M::regimes()
    }
    with_model!(&model, p => of(p))
}

/// The rules that decide the regime, as (regime, condition in LaTeX), shown with the regime
/// question (physics.md §1.5, §3.2, §3.6).
pub fn regime_rules(model: Model) -> &'static [(Regime, &'static str)] {
    fn of<M: Exercise>(_: &M) -> &'static [(Regime, &'static str)] {
        M::regime_rules()
    }
    with_model!(&model, p => of(p))
}
