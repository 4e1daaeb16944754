//! The registry of the pulled mass's quantities (guide §7 and guide §9, guide §14): for each, the JSON key (guide §14),
//! symbol, unit, equation, tag, formula, a plain line of what it is, and the regimes in which it
//! describes the motion. The JSON keys (guide §14) are written here and nowhere else.

use crate::models::pulled_mass::formula::Regime;
use crate::results::quantity::{AnyKey, Entry, Kind, Registry};

/// A quantity of the pulled mass, in the order of the guide §14 `closed_form` object.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Key {
    Phi,
    TauSlip,
    TSlip,
    ASlip,
    TauMaxSpeed,
    TMaxSpeed,
    VMax,
    TauStick,
    TStick,
    SlipDuration,
    Theta,
    PhiStickMax,
    PhiContinuous,
    MuMinEqual,
    Gamma,
    VAvg,
    AdvancePerPeriod,
    Power,
    TauStickLate,
    AdvancePerPeriodLate,
    VAvgLate,
    Regime,
    ImmediateSlip,
    SamePeriodValid,
    PowerLate,
}

/// Every key, in registry order.
pub const ALL: [Key; 25] = [
    Key::Phi,
    Key::TauSlip,
    Key::TSlip,
    Key::ASlip,
    Key::TauMaxSpeed,
    Key::TMaxSpeed,
    Key::VMax,
    Key::TauStick,
    Key::TStick,
    Key::SlipDuration,
    Key::Theta,
    Key::PhiStickMax,
    Key::PhiContinuous,
    Key::MuMinEqual,
    Key::Gamma,
    Key::VAvg,
    Key::AdvancePerPeriod,
    Key::Power,
    Key::TauStickLate,
    Key::AdvancePerPeriodLate,
    Key::VAvgLate,
    Key::Regime,
    Key::ImmediateSlip,
    Key::SamePeriodValid,
    Key::PowerLate,
];

/// Every regime: parameters of the set, and the labels.
const ALWAYS: &[Regime] = &[
    Regime::ImmediateContinuousSlip,
    Regime::SlipStick,
    Regime::SlipStickLate,
    Regime::ContinuousSlip,
];
/// Every regime with a slip onset after t = 0: the onset and the first speed maximum.
const SLIPS: &[Regime] = &[
    Regime::SlipStick,
    Regime::SlipStickLate,
    Regime::ContinuousSlip,
];
/// The stick within the same period (20): (18)–(30).
const SAME_PERIOD: &[Regime] = &[Regime::SlipStick];
/// The stick early in the next period (guide §7.5).
const LATE: &[Regime] = &[Regime::SlipStickLate];

use Kind::{Checked, Label, Number};

/// The pulled mass's quantities; the numbers in the order they are shown.
const ENTRIES: &[Entry<Key, &[Regime]>] = &[
    Entry::new(
        Key::Phi,
        Number,
        ALWAYS,
        "phi",
        "φ",
        r"\varphi",
        "",
        "—",
        "[P]",
        r"\varphi = F/W",
        "the pull in units of the weight",
    ),
    Entry::new(
        Key::TauSlip,
        Number,
        SLIPS,
        "tau_slip",
        "τ_SL",
        r"\tau_{SL}",
        "",
        "(13),(25)",
        "[P]",
        r"\tau_{SL} = \tfrac12\left(1 - \frac{\varphi}{2\mu_s}\right)",
        "when the block starts to slip, as a fraction of the period",
    ),
    Entry::new(
        Key::TSlip,
        Number,
        SLIPS,
        "t_slip",
        "t_SL",
        r"t_{SL}",
        "s",
        "(13),(25)",
        "[P]",
        r"t_{SL} = T\,\tau_{SL}",
        "when the block starts to slip",
    ),
    Entry::new(
        Key::ASlip,
        Number,
        SLIPS,
        "a_slip",
        "a_SL",
        r"a_{SL}",
        "m/s²",
        "guide §7.1",
        "[D]",
        r"a_{SL} = \frac{g\varphi}{2}\left(1 - \frac{\mu_d}{\mu_s}\right)",
        "the acceleration just after the slip starts",
    ),
    Entry::new(
        Key::TauMaxSpeed,
        Number,
        SLIPS,
        "tau_max_speed",
        "τ_M",
        r"\tau_M",
        "",
        "(17)",
        "[P]",
        r"\tau_M = \tfrac12\left(1 + \frac{\varphi}{2\mu_d}\right)",
        "when the block is fastest, as a fraction of the period",
    ),
    Entry::new(
        Key::TMaxSpeed,
        Number,
        SLIPS,
        "t_max_speed",
        "t_M",
        r"t_M",
        "s",
        "(17)",
        "[P]",
        r"t_M = T\,\tau_M",
        "when the block is fastest",
    ),
    Entry::new(
        Key::VMax,
        Number,
        SLIPS,
        "v_max",
        "v_M",
        r"v_M",
        "m/s",
        "(26)",
        "[P]",
        r"v_M = \frac{g T \varphi^2 D}{16 \mu_s^2 \mu_d}",
        "the largest speed of the slip",
    ),
    Entry::new(
        Key::TauStick,
        Number,
        SAME_PERIOD,
        "tau_stick",
        "τ_ST",
        r"\tau_{ST}",
        "",
        "(18),(25)",
        "[P]",
        r"\tau_{ST} = \tfrac12 (1 + \varphi\Theta)",
        "when the block sticks again, as a fraction of the period",
    ),
    Entry::new(
        Key::TStick,
        Number,
        SAME_PERIOD,
        "t_stick",
        "t_ST",
        r"t_{ST}",
        "s",
        "(18),(25)",
        "[P]",
        r"t_{ST} = T\,\tau_{ST}",
        "when the block sticks again",
    ),
    Entry::new(
        Key::SlipDuration,
        Number,
        SAME_PERIOD,
        "slip_duration",
        "t_ST − t_SL",
        r"t_{ST} - t_{SL}",
        "s",
        "(21)",
        "[P]",
        r"t_{ST} - t_{SL} = \frac{T\varphi}{2}\,\frac{\mu_s + \mu_d + \sqrt{D}}{2\mu_s\mu_d}",
        "how long the slip lasts",
    ),
    Entry::new(
        Key::Theta,
        Number,
        ALWAYS,
        "theta",
        "Θ",
        r"\Theta",
        "",
        "(18)",
        "[P]",
        r"\Theta = \frac{\mu_s + \sqrt{D}}{2\mu_s\mu_d},\quad D = \mu_s^2 + 2\mu_s\mu_d - \mu_d^2",
        "a number set by the two friction coefficients that fixes the stick time",
    ),
    Entry::new(
        Key::PhiStickMax,
        Number,
        ALWAYS,
        "phi_stick_max",
        "1/Θ",
        r"1/\Theta",
        "",
        "(20)",
        "[P]",
        r"\varphi \le 1/\Theta = \frac{2\mu_s\mu_d}{\mu_s + \sqrt{D}}",
        "the largest pull (in units of the weight) for a stick within the same period",
    ),
    Entry::new(
        Key::PhiContinuous,
        Number,
        ALWAYS,
        "phi_continuous",
        "φ_c",
        r"\varphi_c",
        "",
        "guide §7.5",
        "[D]",
        r"\varphi_c = \frac{4\mu_s\mu_d}{2\mu_s + \sqrt{2D}}",
        "the largest pull (in units of the weight) for any stick; above it the block never stops",
    ),
    Entry::new(
        Key::MuMinEqual,
        Number,
        ALWAYS,
        "mu_min_equal",
        "μ_MIN",
        r"\mu_{MIN}",
        "",
        "(22)",
        "[P]",
        r"\mu_{MIN} = \frac{(1+\sqrt2)\,\varphi}{2}",
        "the least friction coefficient, with μs = μd, for a stick within the same period",
    ),
    Entry::new(
        Key::Gamma,
        Number,
        ALWAYS,
        "gamma",
        "Γ",
        r"\Gamma",
        "",
        "(28)",
        "[P*]",
        r"\Gamma = \frac{D^{3/2} + \mu_s^3 + 3\mu_s^2\mu_d - \mu_d^3}{96\,\mu_s^3\mu_d^2}",
        "a number set by the two friction coefficients that fixes the mean speed",
    ),
    Entry::new(
        Key::VAvg,
        Number,
        SAME_PERIOD,
        "v_avg",
        "v̄",
        r"\bar v",
        "m/s",
        "(27)",
        "[P]",
        r"\bar v = g T \varphi^3 \Gamma",
        "the mean speed over a period",
    ),
    Entry::new(
        Key::AdvancePerPeriod,
        Number,
        SAME_PERIOD,
        "advance_per_period",
        "x_T",
        r"x_T",
        "m",
        "(30)",
        "[P]",
        r"x_T = g T^2 \varphi^3 \Gamma",
        "how far the block moves in one period",
    ),
    Entry::new(
        Key::Power,
        Number,
        SAME_PERIOD,
        "power",
        "P",
        "P",
        "W",
        "(29)",
        "[P]",
        r"P = F\bar v = \frac{gT}{W^3}\,\Gamma F^4",
        "the mean power of the pull, all of it dissipated by friction",
    ),
    Entry::new(
        Key::TauStickLate,
        Number,
        LATE,
        "tau_stick_late",
        "τ_ST,late",
        r"\tau_{ST,late}",
        "",
        "guide §7.5",
        "[D]",
        r"\tau_{ST,late} = 1 + \tau'_M - \sqrt{2\tau_M'^2 - \frac{v_M}{gT\mu_d}}",
        "when the block sticks early in the next period, as a fraction of the period",
    ),
    Entry::new(
        Key::AdvancePerPeriodLate,
        Number,
        LATE,
        "advance_per_period_late",
        "x_T,late",
        r"x_{T,late}",
        "m",
        "guide §7.5",
        "[D]",
        r"x_{T,late} = gT^2\,[F_1]_{\tau_{SL}}^{1/2} + [F_2]_{1/2}^{1} + [F_3]_{1}^{\tau_{ST,late}}",
        "how far the block moves in one period when it sticks late",
    ),
    Entry::new(
        Key::VAvgLate,
        Number,
        LATE,
        "v_avg_late",
        "v̄_late",
        r"\bar v_{late}",
        "m/s",
        "guide §7.5",
        "[D]",
        r"\bar v_{late} = x_{T,late}/T",
        "the mean speed when the block sticks late",
    ),
    Entry::new(
        Key::Regime,
        Label,
        ALWAYS,
        "regime",
        "regime",
        r"\text{regime}",
        "",
        "guide §9",
        "[D]",
        r"\text{regime}",
        "which motion the closed forms give: when, if ever, the block sticks",
    ),
    Entry::new(
        Key::ImmediateSlip,
        Label,
        ALWAYS,
        "immediate_slip",
        "immediate slip",
        r"\text{immediate slip}",
        "",
        "φ > 2μs",
        "[P]",
        r"\text{immediate slip}",
        "whether the block slips at once, at t = 0",
    ),
    Entry::new(
        Key::SamePeriodValid,
        Label,
        ALWAYS,
        "same_period_valid",
        "same-period forms apply",
        r"\text{same-period forms apply}",
        "",
        "(20)",
        "[D]",
        r"\varphi \le 1/\Theta",
        "whether the block sticks within the period, so that (18)–(30) describe it",
    ),
    Entry::new(
        Key::PowerLate,
        Checked,
        LATE,
        "power_late",
        "P_late",
        r"P_{late}",
        "W",
        "(29) with v̄_late",
        "[D]",
        r"P_{late} = F\,\bar v_{late}",
        "the mean power of the pull when the block sticks late",
    ),
];

impl Registry for Key {
    type Regimes = &'static [Regime];
    const ENTRIES: &'static [Entry<Key, &'static [Regime]>] = ENTRIES;

    fn index(self) -> usize {
        self as usize
    }

    fn time(self) -> Option<Key> {
        match self {
            Key::TauSlip => Some(Key::TSlip),
            Key::TauMaxSpeed => Some(Key::TMaxSpeed),
            Key::TauStick => Some(Key::TStick),
            _ => None,
        }
    }
}

impl Key {
    /// Whether the quantity describes the motion in `regime`.
    pub fn describes(self, regime: Regime) -> bool {
        self.entry().regimes.contains(&regime)
    }
}

/// The model-independent key of `k`, in const context (the entries are in the order of the
/// key's variants, see [`Registry::index`]).
pub const fn any(k: Key) -> AnyKey {
    AnyKey::new(&ENTRIES[k as usize].quantity)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::results::quantity::tests::registry_is_consistent;

    #[test]
    fn the_registry_is_consistent() {
        registry_is_consistent(&ALL);
    }
}
