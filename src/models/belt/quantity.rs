//! The registry of the belt's quantities (docs/belt.md): for each, the key of the
//! `closed_form` object, symbol, unit, equation, formula and a plain line of what it is. The
//! keys are written here and nowhere else.

use super::formula::Regime;
use crate::results::quantity::{AnyKey, Entry, Kind, Registry};

/// A quantity of the belt, in the order of the `closed_form` object.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Key {
    FirstSlipTime,
    TSlip,
    TStick,
    Period,
    Amplitude,
    XSlipEnd,
    XMax,
    XMin,
    VMin,
    SlipSpeedMax,
    EnergyPerCycle,
    PowerFriction,
    PowerBelt,
    StickShare,
    SlipShare,
    Regime,
}

/// Every key, in registry order.
pub const ALL: [Key; 16] = [
    Key::FirstSlipTime,
    Key::TSlip,
    Key::TStick,
    Key::Period,
    Key::Amplitude,
    Key::XSlipEnd,
    Key::XMax,
    Key::XMin,
    Key::VMin,
    Key::SlipSpeedMax,
    Key::EnergyPerCycle,
    Key::PowerFriction,
    Key::PowerBelt,
    Key::StickShare,
    Key::SlipShare,
    Key::Regime,
];

/// Both regimes: every closed form describes the motion in each (t_stick = 0 in a touching
/// oscillation).
const ALWAYS: &[Regime] = &[Regime::StickSlip, Regime::TouchingOscillation];

/// An entry of the table.
#[allow(clippy::too_many_arguments)]
const fn e(
    key: Key,
    kind: Kind,
    id: &'static str,
    symbol: &'static str,
    tex: &'static str,
    unit: &'static str,
    equation: &'static str,
    latex: &'static str,
    words: &'static str,
) -> Entry<Key, &'static [Regime]> {
    Entry::new(
        key, kind, ALWAYS, id, symbol, tex, unit, equation, "[D]", latex, words,
    )
}

/// The belt's quantities, in the order they are shown.
const ENTRIES: &[Entry<Key, &[Regime]>] = &[
    e(
        Key::FirstSlipTime,
        Kind::Number,
        "first_slip_time",
        "t_1",
        r"t_1",
        "s",
        "(B5)",
        r"t_1 = x_s / v_b",
        "when the block first slips, carried from x = 0",
    ),
    e(
        Key::TSlip,
        Kind::Number,
        "t_slip",
        "t_slip",
        r"t_{slip}",
        "s",
        "(B8)",
        r"t_{slip} = \frac{2}{\omega}\left(\pi - \arctan\frac{\omega\Delta}{v_b}\right)",
        "how long a slip lasts",
    ),
    e(
        Key::TStick,
        Kind::Number,
        "t_stick",
        "t_stick",
        r"t_{stick}",
        "s",
        "(B10)",
        r"t_{stick} = 2\Delta / v_b",
        "how long a stick lasts",
    ),
    e(
        Key::Period,
        Kind::Number,
        "period",
        "T",
        r"T",
        "s",
        "(B11)",
        r"T = t_{slip} + t_{stick}",
        "the period of the stick-slip cycle",
    ),
    e(
        Key::Amplitude,
        Kind::Number,
        "amplitude",
        "A",
        r"A",
        "m",
        "(B7)",
        r"A = \sqrt{\Delta^2 + (v_b/\omega)^2}",
        "the amplitude of the slip arc about x_d",
    ),
    e(
        Key::XSlipEnd,
        Kind::Number,
        "x_slip_end",
        "x_e",
        r"x_e",
        "m",
        "(B9)",
        r"x_e = x_d - \Delta",
        "where the block sticks again",
    ),
    e(
        Key::XMax,
        Kind::Number,
        "x_max",
        "x_max",
        r"x_{max}",
        "m",
        "(B13)",
        r"x_{max} = x_d + A",
        "the farthest position from the wall",
    ),
    e(
        Key::XMin,
        Kind::Number,
        "x_min",
        "x_min",
        r"x_{min}",
        "m",
        "(B13)",
        r"x_{min} = x_d - A",
        "the nearest position to the wall",
    ),
    e(
        Key::VMin,
        Kind::Number,
        "v_min",
        "v_min",
        r"v_{min}",
        "m/s",
        "(B14)",
        r"v_{min} = -\omega A",
        "the fastest backward velocity, against the belt",
    ),
    e(
        Key::SlipSpeedMax,
        Kind::Number,
        "slip_speed_max",
        "u_max",
        r"u_{max}",
        "m/s",
        "(B15)",
        r"u_{max} = v_b + \omega A",
        "the largest speed of the block relative to the belt",
    ),
    e(
        Key::EnergyPerCycle,
        Kind::Number,
        "energy_per_cycle",
        "E",
        r"E",
        "J",
        "(B16)",
        r"E = \mu_d m g\,(2\Delta + v_b t_{slip})",
        "the heat made by friction in a cycle (the belt's work)",
    ),
    e(
        Key::PowerFriction,
        Kind::Number,
        "power_friction",
        "P_f",
        r"P_f",
        "W",
        "(B17)",
        r"P_f = E / T",
        "the mean power of friction",
    ),
    e(
        Key::PowerBelt,
        Kind::Number,
        "power_belt",
        "P_b",
        r"P_b",
        "W",
        "(B17)",
        r"P_b = E / T",
        "the mean power of the belt",
    ),
    e(
        Key::StickShare,
        Kind::Number,
        "stick_share",
        "s_stick",
        r"s_{stick}",
        "",
        "(B12)",
        r"s_{stick} = t_{stick} / T",
        "the share of the period spent stuck",
    ),
    e(
        Key::SlipShare,
        Kind::Number,
        "slip_share",
        "s_slip",
        r"s_{slip}",
        "",
        "(B12)",
        r"s_{slip} = t_{slip} / T",
        "the share of the period spent slipping",
    ),
    e(
        Key::Regime,
        Kind::Label,
        "regime",
        "regime",
        r"\text{regime}",
        "",
        "docs/belt.md",
        r"\Delta > 0 \Rightarrow \text{stick-slip}",
        "stick-slip, or a touching oscillation when μd = μs",
    ),
];

impl Registry for Key {
    type Regimes = &'static [Regime];
    const ENTRIES: &'static [Entry<Key, &'static [Regime]>] = ENTRIES;

    fn index(self) -> usize {
        self as usize
    }
}

/// The model-independent key of `k`, in const context.
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
