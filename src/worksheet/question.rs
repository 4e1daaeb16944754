//! The questions a worksheet can ask, per model: what is asked, the derivation step that
//! answers it, the check of the exact integration that confirms it, the unit expected and the
//! regimes in which its closed form can describe the motion. Also the regimes a teacher can ask
//! for and the inequalities that decide them.

use super::exercise::Exercise;
use crate::models::{with_model, Model};

/// How a question is answered.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Compute a closed form: the derivation step `step`, confirmed by the check `check` of
    /// the exact integration of the linearized law.
    ClosedForm {
        step: &'static str,
        check: &'static str,
    },
    /// Compute the least μd for a stick before T/2 (derivation step `step`), confirmed by
    /// searching that μd on the exact integration.
    Threshold { step: &'static str },
    /// Decide the regime from the inequalities.
    Regime,
    /// Read the first speed maximum off the student's v(t) figure (the step and check of the
    /// closed form that gives it).
    ReadFigure {
        step: &'static str,
        check: &'static str,
    },
}

/// One question of the catalogue.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Question {
    /// Key used by `--questions` and in answer-key.json.
    pub key: &'static str,
    pub kind: Kind,
    /// What the student is asked (plain text).
    pub prompt: &'static str,
    /// LaTeX symbol of the answer ("" for the regime).
    pub symbol: &'static str,
    /// SI unit expected ("" when dimensionless or a name).
    pub unit: &'static str,
    /// Regimes (closed-form ids) in which the answer can exist.
    pub regimes: &'static [&'static str],
}

pub(crate) const PULLED_REGIMES: &[&str] = &["slip_stick", "slip_stick_late", "continuous_slip"];
const SAME_PERIOD: &[&str] = &["slip_stick"];
pub(crate) const WOODPECKER_REGIMES: &[&str] = &[
    "double_slip_stick",
    "double_slip_no_halt",
    "single_slip_stick",
    "continuous_or_multiperiod",
];
const STANDARD: &[&str] = &["double_slip_stick"];
/// Where the first slip's speed peaks in the lobe after the zero of F_e, as (46)–(48) assume:
/// not with a single speed maximum (u_B h_B ≤ 1, no deceleration there). μd,MIN^(I) (51) is
/// left out there too: its threshold is then mostly 1/η, not (51), and the sets on which the
/// integration confirms it are too rare to draw together with t_SL^(I).
const PEAK_IN_LOBE_B: &[&str] = &[
    "double_slip_stick",
    "double_slip_no_halt",
    "continuous_or_multiperiod",
];

/// The pulled-mass questions (physics.md §1.3, §1.5), in sheet order.
pub const PULLED_MASS: &[Question] = &[
    Question {
        key: "t_slip",
        kind: Kind::ClosedForm {
            step: "t_slip",
            check: "t_slip",
        },
        prompt: "At what time does the block first start to slip? (eqs. 13, 25)",
        symbol: r"t_{SL}",
        unit: "s",
        regimes: PULLED_REGIMES,
    },
    Question {
        key: "t_stick",
        kind: Kind::ClosedForm {
            step: "t_stick",
            check: "t_stick",
        },
        prompt: "At what time does it stick again? (eqs. 18, 25)",
        symbol: r"t_{ST}",
        unit: "s",
        regimes: SAME_PERIOD,
    },
    Question {
        key: "v_max",
        kind: Kind::ClosedForm {
            step: "v_max",
            check: "v_max",
        },
        prompt: "What is the largest speed of the first slip? (eq. 26)",
        symbol: r"v_M",
        unit: "m/s",
        regimes: PULLED_REGIMES,
    },
    Question {
        key: "v_avg",
        kind: Kind::ClosedForm {
            step: "v_avg",
            check: "v_avg",
        },
        prompt: "What is the mean speed of the block over a period? (eqs. 27, 28)",
        symbol: r"\bar v",
        unit: "m/s",
        regimes: SAME_PERIOD,
    },
    Question {
        key: "power",
        kind: Kind::ClosedForm {
            step: "power",
            check: "power",
        },
        prompt: "What power does friction dissipate on average? (eq. 29)",
        symbol: "P",
        unit: "W",
        regimes: SAME_PERIOD,
    },
    Question {
        key: "regime",
        kind: Kind::Regime,
        prompt: "Which regime is the block in? Decide from the inequalities below.",
        symbol: "",
        unit: "",
        regimes: PULLED_REGIMES,
    },
    Question {
        key: "read_v_max",
        kind: Kind::ReadFigure {
            step: "v_max",
            check: "v_max",
        },
        prompt: "Read the first speed maximum off Figure 1.",
        symbol: r"v_M",
        unit: "m/s",
        regimes: PULLED_REGIMES,
    },
];

/// The woodpecker questions (physics.md §3.3–3.6), in sheet order.
pub const WOODPECKER: &[Question] = &[
    Question {
        key: "t_slip_1",
        kind: Kind::ClosedForm {
            step: "t_slip_1",
            check: "t_slip_1",
        },
        prompt: "At what time does the sleeve first start to slip (phase I)? (eqs. 40–42)",
        symbol: r"t_{SL}^{(I)}",
        unit: "s",
        regimes: WOODPECKER_REGIMES,
    },
    Question {
        key: "t_stick_1",
        kind: Kind::ClosedForm {
            step: "t_stick_1",
            check: "t_stick_1",
        },
        prompt: "At what time does it stick again in phase I? (eqs. 49, 50)",
        symbol: r"t_{ST}^{(I)}",
        unit: "s",
        regimes: STANDARD,
    },
    Question {
        key: "v_max_1",
        kind: Kind::ClosedForm {
            step: "v_max_1",
            check: "v_max_1",
        },
        prompt: "What is the largest speed of the phase-I slip? (eq. 48)",
        symbol: r"v_M^{(I)}",
        unit: "m/s",
        regimes: PEAK_IN_LOBE_B,
    },
    Question {
        key: "mu_d_min_1",
        kind: Kind::Threshold { step: "mu_d_min_1" },
        prompt: "What is the least dynamic coefficient for which the sleeve sticks before \
                 t = T/2? (eq. 51)",
        symbol: r"\mu_{d,MIN}^{(I)}",
        unit: "",
        regimes: PEAK_IN_LOBE_B,
    },
    Question {
        key: "v_avg",
        kind: Kind::ClosedForm {
            step: "v_avg",
            check: "v_avg",
        },
        prompt: "What is the mean speed of the sleeve? (eqs. 54, 69–71)",
        symbol: r"\bar v",
        unit: "m/s",
        regimes: STANDARD,
    },
    Question {
        key: "regime",
        kind: Kind::Regime,
        prompt: "Which regime is the sleeve in? Decide from the inequalities below.",
        symbol: "",
        unit: "",
        regimes: WOODPECKER_REGIMES,
    },
    Question {
        key: "read_v_max_1",
        kind: Kind::ReadFigure {
            step: "v_max_1",
            check: "v_max_1",
        },
        prompt: "Read the first speed maximum off Figure 1.",
        symbol: r"v_M^{(I)}",
        unit: "m/s",
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

/// Regimes a worksheet can ask for (closed-form ids), the default first. The others
/// (immediate slip, no slip, outside the closed-form domain) leave no closed form to compute.
pub fn regimes(model: Model) -> &'static [&'static str] {
    fn of<M: Exercise>(_: &M) -> &'static [&'static str] {
        M::regimes()
    }
    with_model!(&model, p => of(p))
}

/// The rules that decide the regime, as (regime id, condition in LaTeX), shown with the regime
/// question (physics.md §1.5, §3.2, §3.6).
pub fn regime_rules(model: Model) -> &'static [(&'static str, &'static str)] {
    fn of<M: Exercise>(_: &M) -> &'static [(&'static str, &'static str)] {
        M::regime_rules()
    }
    with_model!(&model, p => of(p))
}
