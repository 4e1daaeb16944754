//! The registry of the woodpecker's quantities (guide §8, guide §14): for each, the JSON key (guide §14),
//! symbol, unit, equation, tag, formula, a plain line of what it is, and where it describes the
//! motion ([`Scope`]). The JSON keys (guide §14) are written here and nowhere else; the orbit checks of the
//! lobe engine, numbered by slip at run time, are named by [`OrbitQuantity`].

use crate::models::woodpecker::lobe::Phase;
use crate::results::checks::{Checked, Numbered};
use crate::results::quantity::{AnyKey, Entry, Kind, Registry};

/// The section of the lobe engine (guide §8.6): the equation of its orbit quantities.
pub const ORBIT: &str = "guide §8.6";

/// A quantity of the woodpecker, in the order of the guide §14 `closed_form` object (suffix 1: phase I,
/// 2: phase II).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Key {
    Zeta0,
    Delta0,
    TauQuarter,
    USMinus,
    USPlus,
    UDMinus,
    UDPlus,
    Eta,
    EtaPrime,
    ImmediateSlip,
    T01,
    Delta1,
    TSlip1,
    ASlip1,
    TMaxSpeed1,
    VMax1,
    S1,
    TStick1,
    MuDMin1,
    MuDHalt1,
    Gamma1,
    Distance1,
    T02,
    Delta2,
    TSlip2,
    ASlip2,
    TMaxSpeed2,
    VMax2,
    S2,
    TStick2,
    MuDMin2,
    MuDHalt2,
    Gamma2,
    Distance2,
    Gamma,
    DistancePerPeriod,
    VAvg,
    PowerWeight,
    PaperRegimeValid,
    Regime,
    OrbitVAvg,
    OrbitDistancePerPeriod,
}

/// Every key, in registry order.
pub const ALL: [Key; 42] = [
    Key::Zeta0,
    Key::Delta0,
    Key::TauQuarter,
    Key::USMinus,
    Key::USPlus,
    Key::UDMinus,
    Key::UDPlus,
    Key::Eta,
    Key::EtaPrime,
    Key::ImmediateSlip,
    Key::T01,
    Key::Delta1,
    Key::TSlip1,
    Key::ASlip1,
    Key::TMaxSpeed1,
    Key::VMax1,
    Key::S1,
    Key::TStick1,
    Key::MuDMin1,
    Key::MuDHalt1,
    Key::Gamma1,
    Key::Distance1,
    Key::T02,
    Key::Delta2,
    Key::TSlip2,
    Key::ASlip2,
    Key::TMaxSpeed2,
    Key::VMax2,
    Key::S2,
    Key::TStick2,
    Key::MuDMin2,
    Key::MuDHalt2,
    Key::Gamma2,
    Key::Distance2,
    Key::Gamma,
    Key::DistancePerPeriod,
    Key::VAvg,
    Key::PowerWeight,
    Key::PaperRegimeValid,
    Key::Regime,
    Key::OrbitVAvg,
    Key::OrbitDistancePerPeriod,
];

/// Where a woodpecker quantity describes the motion.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scope {
    /// Set by the parameters alone (amplitudes, friction factors, thresholds, times of the
    /// force, flags): no feature of the motion to compare with.
    Parameters,
    /// The slip of this phase that starts from rest on the periodic orbit (guide §8.3, guide §8.4), as far
    /// as it runs as the paper assumes (speed maximum and stick in the next lobe).
    Slip(Phase),
    /// The paper's standard regime, both sticks within their half periods (guide §8.5).
    PaperRegime,
    /// The periodic orbit of the lobe engine, in every regime that has one (guide §8.6).
    Orbit,
}

impl Scope {
    /// The scope in plain words.
    pub fn words(self) -> &'static str {
        match self {
            Scope::Parameters => "set by the parameters alone",
            Scope::Slip(Phase::One) => "the phase-I slip from rest, when the orbit has one",
            Scope::Slip(Phase::Two) => "the phase-II slip from rest, when the orbit has one",
            Scope::PaperRegime => "the paper's regime: both sticks within their half periods",
            Scope::Orbit => "the periodic orbit, whatever its regime",
        }
    }
}

use Kind::{Label, Number};

/// The woodpecker's quantities; the numbers in the order they are shown.
const ENTRIES: &[Entry<Key, Scope>] = &[
    Entry::new(
        Key::Zeta0,
        Number,
        Scope::Parameters,
        "zeta0",
        "ζ0",
        r"\zeta_0",
        "m",
        "guide §5.2",
        "[D]",
        r"\zeta_0 \quad \text{(counterpart of } d_0)",
        "the amplitude of the linear law's spring coordinate",
    ),
    Entry::new(
        Key::Delta0,
        Number,
        Scope::Parameters,
        "delta0",
        "δ0",
        r"\delta_0",
        "m",
        "guide §5.2",
        "[D]",
        r"\delta_0 \quad \text{(counterpart of } z_0)",
        "the offset of the linear law's spring coordinate",
    ),
    Entry::new(
        Key::TauQuarter,
        Number,
        Scope::Parameters,
        "tau_quarter",
        "τ = T/4",
        r"\tau",
        "s",
        "guide §5.2",
        "[P]",
        r"\tau = T/4",
        "a quarter of the period",
    ),
    Entry::new(
        Key::USMinus,
        Number,
        Scope::Parameters,
        "u_s_minus",
        "u_s^(−)",
        r"u_s^{(-)}",
        "",
        "(44)",
        "[G]",
        r"u_s^{(-)} = 2\lambda\mu_s - 1",
        "the static friction factor while the spring force is positive",
    ),
    Entry::new(
        Key::USPlus,
        Number,
        Scope::Parameters,
        "u_s_plus",
        "u_s^(+)",
        r"u_s^{(+)}",
        "",
        "(44)",
        "[G]",
        r"u_s^{(+)} = 2\lambda\mu_s + 1",
        "the static friction factor while the spring force is negative",
    ),
    Entry::new(
        Key::UDMinus,
        Number,
        Scope::Parameters,
        "u_d_minus",
        "u_d^(−)",
        r"u_d^{(-)}",
        "",
        "(44)",
        "[G]",
        r"u_d^{(-)} = 2\lambda\mu_d - 1",
        "the dynamic friction factor while the spring force is positive",
    ),
    Entry::new(
        Key::UDPlus,
        Number,
        Scope::Parameters,
        "u_d_plus",
        "u_d^(+)",
        r"u_d^{(+)}",
        "",
        "(44)",
        "[G]",
        r"u_d^{(+)} = 2\lambda\mu_d + 1",
        "the dynamic friction factor while the spring force is negative",
    ),
    Entry::new(
        Key::Eta,
        Number,
        Scope::Parameters,
        "eta",
        "η",
        r"\eta",
        "",
        "guide §8.1",
        "[D]",
        r"\eta = k(\zeta_0 - \delta_0)/W_S",
        "the height of the negative lobe of the spring force, in sleeve weights",
    ),
    Entry::new(
        Key::EtaPrime,
        Number,
        Scope::Parameters,
        "eta_prime",
        "η'",
        r"\eta'",
        "",
        "guide §8.1",
        "[D]",
        r"\eta' = k(\zeta_0 + \delta_0)/W_S",
        "the height of the positive lobe of the spring force, in sleeve weights",
    ),
    Entry::new(
        Key::ImmediateSlip,
        Label,
        Scope::Parameters,
        "immediate_slip",
        "immediate slip",
        r"\text{immediate slip}",
        "",
        "(38)",
        "[P]",
        r"\text{immediate slip}",
        "whether the sleeve slips at once, at t = 0",
    ),
    Entry::new(
        Key::T01,
        Number,
        Scope::Parameters,
        "t0_1",
        "t0^(I)",
        r"t_0^{(I)}",
        "s",
        "(40)",
        "[P]",
        r"t_0^{(I)} = \tau\,(1 + \delta_0/\zeta_0)",
        "when the spring force falls through zero",
    ),
    Entry::new(
        Key::Delta1,
        Number,
        Scope::Parameters,
        "delta_1",
        "Δ^(I)",
        r"\Delta^{(I)}",
        "s",
        "(42)",
        "[G]",
        r"\Delta^{(I)} = \frac{\tau W_S}{k\zeta_0 u_s^{(-)}}",
        "how long before that zero the phase-I slip starts",
    ),
    Entry::new(
        Key::TSlip1,
        Number,
        Scope::Slip(Phase::One),
        "t_slip_1",
        "t_SL^(I)",
        r"t_{SL}^{(I)}",
        "s",
        "(41)",
        "[P]",
        r"t_{SL}^{(I)} = t_0^{(I)} - \Delta^{(I)}",
        "when the sleeve starts to slip in phase I",
    ),
    Entry::new(
        Key::ASlip1,
        Number,
        Scope::Slip(Phase::One),
        "a_slip_1",
        "a_SL^(I)",
        r"a_{SL}^{(I)}",
        "m/s²",
        "(45)",
        "[G]",
        r"a_{SL}^{(I)} = g\,\frac{u_s^{(-)} - u_d^{(-)}}{u_s^{(-)}}",
        "the acceleration just after the phase-I slip starts",
    ),
    Entry::new(
        Key::TMaxSpeed1,
        Number,
        Scope::Slip(Phase::One),
        "t_max_speed_1",
        "t_M^(I)",
        r"t_M^{(I)}",
        "s",
        "(46)",
        "[G]",
        r"t_M^{(I)} = t_0^{(I)} + \Delta^{(I)} u_s^{(-)}/u_d^{(+)}",
        "when the sleeve is fastest in the phase-I slip",
    ),
    Entry::new(
        Key::VMax1,
        Number,
        Scope::Slip(Phase::One),
        "v_max_1",
        "v_M^(I)",
        r"v_M^{(I)}",
        "m/s",
        "(48)",
        "[G]",
        r"v_M^{(I)} = \frac{g\Delta^{(I)}}{2}\,\frac{u_d^{(+)}(2u_s^{(-)} - u_d^{(-)}) + u_s^{(-)2}}{u_s^{(-)} u_d^{(+)}}",
        "the largest speed of the phase-I slip",
    ),
    Entry::new(
        Key::S1,
        Number,
        Scope::Slip(Phase::One),
        "s_1",
        "S^(I)",
        r"S^{(I)}",
        "",
        "(50)",
        "[G]",
        r"S^{(I)} = \frac{u_s^{(-)} + \sqrt{u_s^{(-)2} + 2u_s^{(-)}u_d^{(+)} - u_d^{(-)}u_d^{(+)}}}{u_d^{(+)}}",
        "a number set by the friction factors that fixes the phase-I stick time",
    ),
    Entry::new(
        Key::TStick1,
        Number,
        Scope::Slip(Phase::One),
        "t_stick_1",
        "t_ST^(I)",
        r"t_{ST}^{(I)}",
        "s",
        "(49)",
        "[G]",
        r"t_{ST}^{(I)} = t_0^{(I)} + \Delta^{(I)} S^{(I)}",
        "when the sleeve sticks again after the phase-I slip",
    ),
    Entry::new(
        Key::MuDMin1,
        Number,
        Scope::Parameters,
        "mu_d_min_1",
        "μd,MIN^(I)",
        r"\mu_{d,MIN}^{(I)}",
        "",
        "(51)",
        "[G]",
        r"\mu_{d,MIN}^{(I)} = \frac{1}{2\lambda}\,\frac{u_s^{(-)2}\eta(2-\eta) + 2u_s^{(-)} + 1}{u_s^{(-)2}\eta^2 + 1}",
        "the least μd for which the phase-I slip stops within its half period",
    ),
    Entry::new(
        Key::MuDHalt1,
        Number,
        Scope::Parameters,
        "mu_d_halt_1",
        "μd,HALT^(I)",
        r"\mu_{d,HALT}^{(I)}",
        "",
        ORBIT,
        "[D]",
        r"\mu_{d,HALT}^{(I)} = \frac{\max(x_+, 1/\eta) - 1}{2\lambda}",
        "the least μd for which the phase-I slip stops before the next slip",
    ),
    Entry::new(
        Key::Gamma1,
        Number,
        Scope::Slip(Phase::One),
        "gamma_1",
        "Γ^(I)",
        r"\Gamma^{(I)}",
        "",
        "(54)",
        "[P*]",
        r"\Gamma^{(I)} = \frac{3u_s^{(-)}(S+1)^2 - u_d^{(+)}S^3 - 3u_d^{(-)}S - 2u_d^{(-)}}{u_s^{(-)3}}",
        "a number set by the friction factors that fixes the phase-I distance",
    ),
    Entry::new(
        Key::Distance1,
        Number,
        Scope::Slip(Phase::One),
        "distance_1",
        "y^(I)",
        r"y^{(I)}",
        "m",
        "(55)",
        "[P]",
        r"y^{(I)} = \frac{g\tau^2 W_S^2\,\Gamma^{(I)}}{6\zeta_0^2 k^2}",
        "how far the sleeve slides in the phase-I slip",
    ),
    Entry::new(
        Key::T02,
        Number,
        Scope::Parameters,
        "t0_2",
        "t0^(II)",
        r"t_0^{(II)}",
        "s",
        "(57)",
        "[P]",
        r"t_0^{(II)} = \tau\,(3 - \delta_0/\zeta_0)",
        "when the spring force rises through zero",
    ),
    Entry::new(
        Key::Delta2,
        Number,
        Scope::Parameters,
        "delta_2",
        "Δ^(II)",
        r"\Delta^{(II)}",
        "s",
        "(59)",
        "[G]",
        r"\Delta^{(II)} = \frac{\tau W_S}{k\zeta_0 u_s^{(+)}}",
        "how long before that zero the phase-II slip starts",
    ),
    Entry::new(
        Key::TSlip2,
        Number,
        Scope::Slip(Phase::Two),
        "t_slip_2",
        "t_SL^(II)",
        r"t_{SL}^{(II)}",
        "s",
        "(58)",
        "[P]",
        r"t_{SL}^{(II)} = t_0^{(II)} - \Delta^{(II)}",
        "when the sleeve starts to slip in phase II",
    ),
    Entry::new(
        Key::ASlip2,
        Number,
        Scope::Slip(Phase::Two),
        "a_slip_2",
        "a_SL^(II)",
        r"a_{SL}^{(II)}",
        "m/s²",
        "(64)",
        "[G]",
        r"a_{SL}^{(II)} = g\,\frac{u_s^{(+)} - u_d^{(+)}}{u_s^{(+)}}",
        "the acceleration just after the phase-II slip starts",
    ),
    Entry::new(
        Key::TMaxSpeed2,
        Number,
        Scope::Slip(Phase::Two),
        "t_max_speed_2",
        "t_M^(II)",
        r"t_M^{(II)}",
        "s",
        "(62)",
        "[G]",
        r"t_M^{(II)} = t_0^{(II)} + \Delta^{(II)} u_s^{(+)}/u_d^{(-)}",
        "when the sleeve is fastest in the phase-II slip",
    ),
    Entry::new(
        Key::VMax2,
        Number,
        Scope::Slip(Phase::Two),
        "v_max_2",
        "v_M^(II)",
        r"v_M^{(II)}",
        "m/s",
        "(63)",
        "[G]",
        r"v_M^{(II)} = \frac{g\Delta^{(II)}}{2}\,\frac{u_d^{(-)}(2u_s^{(+)} - u_d^{(+)}) + u_s^{(+)2}}{u_s^{(+)} u_d^{(-)}}",
        "the largest speed of the phase-II slip",
    ),
    Entry::new(
        Key::S2,
        Number,
        Scope::Slip(Phase::Two),
        "s_2",
        "S^(II)",
        r"S^{(II)}",
        "",
        "(61)",
        "[G]",
        r"S^{(II)} = \frac{u_s^{(+)} + \sqrt{u_s^{(+)2} + 2u_s^{(+)}u_d^{(-)} - u_d^{(+)}u_d^{(-)}}}{u_d^{(-)}}",
        "a number set by the friction factors that fixes the phase-II stick time",
    ),
    Entry::new(
        Key::TStick2,
        Number,
        Scope::Slip(Phase::Two),
        "t_stick_2",
        "t_ST^(II)",
        r"t_{ST}^{(II)}",
        "s",
        "(60)",
        "[G]",
        r"t_{ST}^{(II)} = t_0^{(II)} + \Delta^{(II)} S^{(II)}",
        "when the sleeve sticks again after the phase-II slip",
    ),
    Entry::new(
        Key::MuDMin2,
        Number,
        Scope::Parameters,
        "mu_d_min_2",
        "μd,MIN^(II)",
        r"\mu_{d,MIN}^{(II)}",
        "",
        "(65)",
        "[G]",
        r"\mu_{d,MIN}^{(II)} = \frac{1}{2\lambda}\,\frac{u_s^{(+)2}\eta'(\eta'+2) + 2u_s^{(+)} - 1}{u_s^{(+)2}\eta'^2 + 1}",
        "the least μd for which the phase-II slip stops within its half period",
    ),
    Entry::new(
        Key::MuDHalt2,
        Number,
        Scope::Parameters,
        "mu_d_halt_2",
        "μd,HALT^(II)",
        r"\mu_{d,HALT}^{(II)}",
        "",
        ORBIT,
        "[D]",
        r"\mu_{d,HALT}^{(II)} = \frac{\max(x'_+, 1/\eta') + 1}{2\lambda}",
        "the least μd for which the phase-II slip stops before the next slip",
    ),
    Entry::new(
        Key::Gamma2,
        Number,
        Scope::Slip(Phase::Two),
        "gamma_2",
        "Γ^(II)",
        r"\Gamma^{(II)}",
        "",
        "(70)",
        "[P*]",
        r"\Gamma^{(II)} = \frac{3u_s^{(+)}(S+1)^2 - u_d^{(-)}S^3 - 3u_d^{(+)}S - 2u_d^{(+)}}{u_s^{(+)3}}",
        "a number set by the friction factors that fixes the phase-II distance",
    ),
    Entry::new(
        Key::Distance2,
        Number,
        Scope::Slip(Phase::Two),
        "distance_2",
        "y^(II)",
        r"y^{(II)}",
        "m",
        "(68)",
        "[P]",
        r"y^{(II)} = \frac{g\tau^2 W_S^2\,\Gamma^{(II)}}{6\zeta_0^2 k^2}",
        "how far the sleeve slides in the phase-II slip",
    ),
    Entry::new(
        Key::Gamma,
        Number,
        Scope::PaperRegime,
        "gamma",
        "Γ",
        r"\Gamma",
        "",
        "(69)",
        "[P]",
        r"\Gamma = \Gamma^{(I)} + \Gamma^{(II)}",
        "a number set by the friction factors that fixes the advance per period",
    ),
    Entry::new(
        Key::DistancePerPeriod,
        Number,
        Scope::PaperRegime,
        "distance_per_period",
        "y_S(T)",
        r"y_S(T)",
        "m",
        "(68),(69)",
        "[P]",
        r"y_S(T) = \frac{g\tau^2 W_S^2\,\Gamma}{6\zeta_0^2 k^2}",
        "how far the sleeve falls in one period",
    ),
    Entry::new(
        Key::VAvg,
        Number,
        Scope::PaperRegime,
        "v_avg",
        "v̄",
        r"\bar v",
        "m/s",
        "(71)",
        "[P]",
        r"\bar v = \frac{g\tau W_S^2\,\Gamma}{24\zeta_0^2 k^2}",
        "the mean speed of the sleeve",
    ),
    Entry::new(
        Key::PowerWeight,
        Number,
        Scope::PaperRegime,
        "power_weight",
        "P_W",
        r"P_W",
        "W",
        "guide §8.5",
        "[P]",
        r"P_W = W_S\,\bar v",
        "the mean power of the sleeve's weight (not the friction dissipation)",
    ),
    Entry::new(
        Key::PaperRegimeValid,
        Label,
        Scope::Parameters,
        "paper_regime_valid",
        "paper's regime",
        r"\text{paper's regime}",
        "",
        "guide §8.5",
        "[D]",
        r"t_{ST}^{(I)} \le T/2,\quad t_{ST}^{(II)} \le T",
        "whether both sticks fall within their half periods, so that (68)–(71) describe the motion",
    ),
    Entry::new(
        Key::Regime,
        Label,
        Scope::Parameters,
        "regime",
        "regime",
        r"\text{regime}",
        "",
        "guide §10",
        "[D]",
        r"\text{regime}",
        "which periodic motion the closed forms give: how many slips and sticks per period",
    ),
    Entry::new(
        Key::OrbitVAvg,
        Number,
        Scope::Orbit,
        "orbit_v_avg",
        "v̄ (orbit)",
        r"\bar v_{orbit}",
        "m/s",
        ORBIT,
        "[D]",
        r"\bar v = y_{orbit}/T",
        "the mean speed on the periodic orbit, in every regime that has one",
    ),
    Entry::new(
        Key::OrbitDistancePerPeriod,
        Number,
        Scope::Orbit,
        "orbit_distance_per_period",
        "y_T (orbit)",
        r"y_{orbit}",
        "m",
        ORBIT,
        "[D]",
        r"y_{orbit} \quad \text{(lobe engine)}",
        "how far the sleeve falls per period on the periodic orbit",
    ),
];

impl Registry for Key {
    type Regimes = Scope;
    const ENTRIES: &'static [Entry<Key, Scope>] = ENTRIES;

    fn index(self) -> usize {
        self as usize
    }
}

/// A quantity of the lobe-engine orbit checked against the integration (guide §8.6) that no closed
/// form of the paper gives, numbered by the slip of the orbit (from 1) and its speed maximum
/// (from 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OrbitQuantity {
    /// The halt time of a slip.
    TStick { slip: usize },
    /// The time of a speed maximum.
    TMaxSpeed { slip: usize, maximum: usize },
    /// The speed at a speed maximum.
    VMax { slip: usize, maximum: usize },
    /// The distance of a slip.
    Distance { slip: usize },
}

impl OrbitQuantity {
    /// The quantity as a check names it: `orbit_v_max_1_2` (guide §8.6).
    pub fn numbered(self) -> Numbered {
        let (stem, indices) = match self {
            OrbitQuantity::TStick { slip } => ("orbit_t_stick", (slip, None)),
            OrbitQuantity::TMaxSpeed { slip, maximum } => {
                ("orbit_t_max_speed", (slip, Some(maximum)))
            }
            OrbitQuantity::VMax { slip, maximum } => ("orbit_v_max", (slip, Some(maximum))),
            OrbitQuantity::Distance { slip } => ("orbit_distance", (slip, None)),
        };
        Numbered {
            stem,
            indices,
            equation: ORBIT,
        }
    }

    /// The name in the `checks` array.
    pub fn id(self) -> String {
        self.numbered().id()
    }
}

impl From<OrbitQuantity> for Checked {
    fn from(o: OrbitQuantity) -> Self {
        Checked::Numbered(o.numbered())
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

    /// The names of the orbit's checks are part of the JSON (guide §14): slip first, then the
    /// speed maximum.
    #[test]
    fn orbit_quantities_are_named_by_slip_then_maximum() {
        let v = OrbitQuantity::VMax {
            slip: 2,
            maximum: 1,
        };
        assert_eq!(v.id(), "orbit_v_max_2_1");
        assert_eq!(Checked::from(v).equation(), ORBIT);
        assert_eq!(OrbitQuantity::Distance { slip: 3 }.id(), "orbit_distance_3");
        assert_eq!(OrbitQuantity::TStick { slip: 1 }.id(), "orbit_t_stick_1");
        let t = OrbitQuantity::TMaxSpeed {
            slip: 1,
            maximum: 2,
        };
        assert_eq!(t.id(), "orbit_t_max_speed_1_2");
    }
}
