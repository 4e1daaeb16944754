//! The belt's closed forms (docs/belt.md (B1)–(B17)), one pure function per quantity, SI units.
//! Every function takes what its equation names; [`evaluate`] puts them together.

use serde::Serialize;

use super::params::BeltParams;
use super::quantity::Key;
use crate::fmath;
use crate::results::quantity::{serialize_closed_form, Value};

/// Angular frequency of the slip ω = √(k/m) (rad/s), (B1).
pub fn omega(k: f64, mass: f64) -> f64 {
    (k / mass).sqrt()
}

/// Where the stick ends, x_s = μs m g / k (m), (B2).
pub fn x_stick_end(mu_s: f64, mass: f64, g: f64, k: f64) -> f64 {
    mu_s * mass * g / k
}

/// Centre of the slip arc, x_d = μd m g / k (m), (B3).
pub fn x_centre(mu_d: f64, mass: f64, g: f64, k: f64) -> f64 {
    mu_d * mass * g / k
}

/// Δ = x_s − x_d = (μs − μd) m g / k (m), (B4), formed without the cancellation of x_s − x_d.
pub fn delta(mu_s: f64, mu_d: f64, mass: f64, g: f64, k: f64) -> f64 {
    (mu_s - mu_d) * mass * g / k
}

/// First slip onset from x = 0, t_1 = x_s / v_b (s), (B5).
pub fn first_slip_time(x_s: f64, v_b: f64) -> f64 {
    x_s / v_b
}

/// Amplitude of the slip arc A = √(Δ² + (v_b/ω)²) (m), (B7).
pub fn amplitude(delta: f64, v_b: f64, omega: f64) -> f64 {
    delta.hypot(v_b / omega)
}

/// Slip duration t_slip = (2/ω)(π − arctan(ωΔ/v_b)) (s), (B8).
pub fn t_slip(omega: f64, delta: f64, v_b: f64) -> f64 {
    2.0 / omega * (std::f64::consts::PI - fmath::atan(omega * delta / v_b))
}

/// Where the block sticks again, x_e = x_d − Δ = 2x_d − x_s (m), (B9).
pub fn x_slip_end(x_d: f64, delta: f64) -> f64 {
    x_d - delta
}

/// Stick duration t_stick = 2Δ / v_b (s), (B10).
pub fn t_stick(delta: f64, v_b: f64) -> f64 {
    2.0 * delta / v_b
}

/// Period of the cycle T = t_slip + t_stick (s), (B11).
pub fn period(t_slip: f64, t_stick: f64) -> f64 {
    t_slip + t_stick
}

/// The share of the period spent in the phase of duration `t` (stick or slip), (B12).
pub fn share(t: f64, period: f64) -> f64 {
    t / period
}

/// Extreme positions x_d ± A (m), (B13): (x_min, x_max).
pub fn x_extremes(x_d: f64, amplitude: f64) -> (f64, f64) {
    (x_d - amplitude, x_d + amplitude)
}

/// The fastest backward velocity v_min = −ωA (m/s), (B14).
pub fn v_min(omega: f64, amplitude: f64) -> f64 {
    -omega * amplitude
}

/// The largest slip speed |v − v_b| = v_b + ωA (m/s), (B15).
pub fn slip_speed_max(v_b: f64, omega: f64, amplitude: f64) -> f64 {
    v_b + omega * amplitude
}

/// Heat per cycle = work of the belt per cycle, E = μd m g (2Δ + v_b t_slip) (J), (B16).
pub fn energy_per_cycle(mu_d: f64, mass: f64, g: f64, delta: f64, v_b: f64, t_slip: f64) -> f64 {
    mu_d * mass * g * (2.0 * delta + v_b * t_slip)
}

/// Mean power of the friction and of the belt, P = E / T (W), (B17); it equals μd m g v_b
/// (E = μd m g v_b T), which the property tests hold it to.
pub fn mean_power(energy: f64, period: f64) -> f64 {
    energy / period
}

/// The closed forms' regime (docs/belt.md, "Limits and edge cases").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum Regime {
    /// Δ > 0: a stick of 2Δ/v_b and one harmonic slip per cycle.
    StickSlip,
    /// Δ = 0 (μd = μs): a harmonic oscillation that touches the belt's speed once a period.
    TouchingOscillation,
}

impl Regime {
    /// The id, in the style of guide §14.
    pub const fn id(self) -> &'static str {
        match self {
            Regime::StickSlip => "stick_slip",
            Regime::TouchingOscillation => "touching_oscillation",
        }
    }

    /// The regime of a set with Δ (m).
    pub fn of(delta: f64) -> Self {
        if delta > 0.0 {
            Regime::StickSlip
        } else {
            Regime::TouchingOscillation
        }
    }

    /// In plain words.
    pub fn words(self) -> &'static str {
        match self {
            Regime::StickSlip => "a stick and one harmonic slip per cycle",
            Regime::TouchingOscillation => {
                "a harmonic oscillation that touches the belt's speed once a period"
            }
        }
    }
}

/// Every closed form of the belt (docs/belt.md), SI units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClosedForm {
    pub omega: f64,
    pub x_s: f64,
    pub x_d: f64,
    pub delta: f64,
    pub first_slip_time: f64,
    pub t_slip: f64,
    pub t_stick: f64,
    pub period: f64,
    pub amplitude: f64,
    pub x_slip_end: f64,
    pub x_max: f64,
    pub x_min: f64,
    pub v_min: f64,
    pub slip_speed_max: f64,
    pub energy_per_cycle: f64,
    pub power: f64,
    pub stick_share: f64,
    pub slip_share: f64,
    pub regime: Regime,
}

impl ClosedForm {
    /// The value of a quantity of the registry.
    pub fn value(&self, key: Key) -> Value {
        match key {
            Key::FirstSlipTime => self.first_slip_time.into(),
            Key::TSlip => self.t_slip.into(),
            Key::TStick => self.t_stick.into(),
            Key::Period => self.period.into(),
            Key::Amplitude => self.amplitude.into(),
            Key::XSlipEnd => self.x_slip_end.into(),
            Key::XMax => self.x_max.into(),
            Key::XMin => self.x_min.into(),
            Key::VMin => self.v_min.into(),
            Key::SlipSpeedMax => self.slip_speed_max.into(),
            Key::EnergyPerCycle => self.energy_per_cycle.into(),
            Key::PowerFriction | Key::PowerBelt => self.power.into(),
            Key::StickShare => self.stick_share.into(),
            Key::SlipShare => self.slip_share.into(),
            Key::Regime => Value::Label(self.regime.id()),
        }
    }
}

impl Serialize for ClosedForm {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        serialize_closed_form(s, |key| self.value(key))
    }
}

/// Evaluates every closed form of `p`.
pub fn evaluate(p: &BeltParams) -> ClosedForm {
    let BeltParams {
        mass,
        k,
        v_b,
        mu_s,
        mu_d,
        g,
    } = *p;
    let omega = omega(k, mass);
    let x_s = x_stick_end(mu_s, mass, g, k);
    let x_d = x_centre(mu_d, mass, g, k);
    let delta = delta(mu_s, mu_d, mass, g, k);
    let amplitude = amplitude(delta, v_b, omega);
    let t_slip = t_slip(omega, delta, v_b);
    let t_stick = t_stick(delta, v_b);
    let period = period(t_slip, t_stick);
    let (x_min, x_max) = x_extremes(x_d, amplitude);
    let energy = energy_per_cycle(mu_d, mass, g, delta, v_b, t_slip);
    ClosedForm {
        omega,
        x_s,
        x_d,
        delta,
        first_slip_time: first_slip_time(x_s, v_b),
        t_slip,
        t_stick,
        period,
        amplitude,
        x_slip_end: x_slip_end(x_d, delta),
        x_max,
        x_min,
        v_min: v_min(omega, amplitude),
        slip_speed_max: slip_speed_max(v_b, omega, amplitude),
        energy_per_cycle: energy,
        power: mean_power(energy, period),
        stick_share: share(t_stick, period),
        slip_share: share(t_slip, period),
        regime: Regime::of(delta),
    }
}

#[cfg(feature = "cli")]
impl schemars::JsonSchema for ClosedForm {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "BeltClosedForm".into()
    }

    fn json_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
        let ids = [Regime::StickSlip.id(), Regime::TouchingOscillation.id()];
        crate::results::schema::closed_form::<super::quantity::Key>(&ids)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_set_has_the_hand_worked_numbers() {
        // m 0.5 kg, k 50 N/m: ω = 10 rad/s; x_s = 0.05886 m, x_d = 0.03924 m, Δ = 0.01962 m;
        // ωΔ/v_b = 3.924: t_slip = 0.2 (π − arctan 3.924) = 0.36379… s, t_stick = 0.7848 s.
        let c = evaluate(&BeltParams::default());
        assert_eq!(c.omega, 10.0);
        assert!((c.delta - 0.01962).abs() < 1e-15);
        assert!((c.t_stick - 0.7848).abs() < 1e-14);
        let t_slip = 0.2 * (std::f64::consts::PI - 3.924f64.atan());
        assert!((c.t_slip - t_slip).abs() < 1e-15);
        assert!((c.stick_share + c.slip_share - 1.0).abs() < 1e-15);
        assert_eq!(c.regime, Regime::StickSlip);
        // Equal coefficients: a full turn, no stick.
        let equal = evaluate(&BeltParams {
            mu_d: 0.6,
            ..BeltParams::default()
        });
        assert_eq!(equal.t_stick, 0.0);
        assert!((equal.period - std::f64::consts::TAU / 10.0).abs() < 1e-15);
        assert_eq!(equal.regime, Regime::TouchingOscillation);
    }
}
