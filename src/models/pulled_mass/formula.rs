//! Closed forms of the linearized pulled mass (guide §7 and guide §9), valid for 0 < φ < 2μs,
//! μd ≤ μs. φ = F/W; τ is a time fraction t/T here; g in m/s², T in s.
//!
//! ```text
//! D = μs² + 2μsμd − μd²,   Θ = (μs + √D)/(2μsμd)
//! ```

use serde::Serialize;

use super::quantity::Key;
use crate::engine::IntegrationRegime;
use crate::results::quantity::{serialize_closed_form, Value};

/// D ≡ μs² + 2μsμd − μd² (dimensionless), guide §7.
pub fn big_d(mu_s: f64, mu_d: f64) -> f64 {
    mu_s * mu_s + 2.0 * mu_s * mu_d - mu_d * mu_d
}

/// Θ ≡ (μs + √D)/(2μsμd), guide §7 \[P\] (18).
pub fn theta(mu_s: f64, mu_d: f64) -> f64 {
    (mu_s + big_d(mu_s, mu_d).sqrt()) / (2.0 * mu_s * mu_d)
}

/// Slip time as a fraction of T, where F = μs N:
/// ```text
/// τ_SL = ½ (1 − φ/(2μs))                                   [P] (13), (25)
/// ```
pub fn tau_slip(phi: f64, mu_s: f64) -> f64 {
    0.5 * (1.0 - phi / (2.0 * mu_s))
}

/// Acceleration just after the slip onset (m/s²):
/// ```text
/// a_SL = (g φ/2)(1 − μd/μs)                                [D]
/// ```
pub fn a_slip(g: f64, phi: f64, mu_s: f64, mu_d: f64) -> f64 {
    0.5 * g * phi * (1.0 - mu_d / mu_s)
}

/// Time of maximum speed (a = 0 on the rising-N half), fraction of T:
/// ```text
/// τ_M = ½ (1 + φ/(2μd))                                    [P] (17)
/// ```
pub fn tau_max_speed(phi: f64, mu_d: f64) -> f64 {
    0.5 * (1.0 + phi / (2.0 * mu_d))
}

/// The other zero of a, on the falling-N half: τ'_M = ½ (1 − φ/(2μd)) = 1 − τ_M   \[D\]
pub fn tau_accel_zero_falling(phi: f64, mu_d: f64) -> f64 {
    1.0 - tau_max_speed(phi, mu_d)
}

/// Maximum speed (m/s):
/// ```text
/// v_M = g T φ² D / (16 μs² μd)                             [P] (26)
/// ```
pub fn v_max(g: f64, period: f64, phi: f64, mu_s: f64, mu_d: f64) -> f64 {
    g * period * phi * phi * big_d(mu_s, mu_d) / (16.0 * mu_s * mu_s * mu_d)
}

/// Speed during the first slip (m/s), τ_SL ≤ τ ≤ τ_ST (fraction of T):
/// ```text
/// τ ≤ ½:  v = gT [μs² (2μd(2τ−1) + φ)² − φ² (μs−μd)²] / (16 μs² μd)     [P] (24)
/// τ ≥ ½:  v = v_M − gT μd (τ − τ_M)²                                    [P] (24)
/// ```
pub fn speed(g: f64, period: f64, phi: f64, mu_s: f64, mu_d: f64, tau: f64) -> f64 {
    if tau <= 0.5 {
        let r = 2.0 * mu_d * (2.0 * tau - 1.0) + phi;
        g * period * (mu_s * mu_s * r * r - phi * phi * (mu_s - mu_d).powi(2))
            / (16.0 * mu_s * mu_s * mu_d)
    } else {
        let dt = tau - tau_max_speed(phi, mu_d);
        v_max(g, period, phi, mu_s, mu_d) - g * period * mu_d * dt * dt
    }
}

/// Stick time, fraction of T:
/// ```text
/// τ_ST = ½ (1 + φ Θ)                                       [P] (18), (25)
/// ```
pub fn tau_stick(phi: f64, mu_s: f64, mu_d: f64) -> f64 {
    0.5 * (1.0 + phi * theta(mu_s, mu_d))
}

/// Slip duration (s):
/// ```text
/// t_ST − t_SL = (T F/(2W)) (μs + μd + √D)/(2 μs μd)        [P] (21)
/// ```
pub fn slip_duration(period: f64, phi: f64, mu_s: f64, mu_d: f64) -> f64 {
    0.5 * period * phi * (mu_s + mu_d + big_d(mu_s, mu_d).sqrt()) / (2.0 * mu_s * mu_d)
}

/// Largest φ for a stick in the same period, t_ST ≤ T:
/// ```text
/// φ ≤ 1/Θ = 2μsμd/(μs + √D)                                [P] (20)
/// ```
pub fn phi_stick_max(mu_s: f64, mu_d: f64) -> f64 {
    1.0 / theta(mu_s, mu_d)
}

/// Minimum friction coefficient for (20) when μs = μd = μ:
/// ```text
/// μ_MIN = (1 + √2) φ / 2                                   [P] (22)
/// ```
pub fn mu_min_equal(phi: f64) -> f64 {
    0.5 * (1.0 + std::f64::consts::SQRT_2) * phi
}

/// Largest φ for any stick (late stick included):
/// ```text
/// φ_c = 4 μs μd / (2 μs + √(2D))                           [D] guide §7.5
/// ```
pub fn phi_continuous(mu_s: f64, mu_d: f64) -> f64 {
    4.0 * mu_s * mu_d / (2.0 * mu_s + (2.0 * big_d(mu_s, mu_d)).sqrt())
}

/// Γ(μs, μd) of the mean speed (coefficient 1 in front of D^{3/2}; see claim 2):
/// ```text
/// Γ = [D^{3/2} + μs³ + 3μs²μd − μd³] / (96 μs³ μd²)        [P*] (28)
/// ```
pub fn gamma(mu_s: f64, mu_d: f64) -> f64 {
    let d = big_d(mu_s, mu_d);
    (d * d.sqrt() + mu_s.powi(3) + 3.0 * mu_s * mu_s * mu_d - mu_d.powi(3))
        / (96.0 * mu_s.powi(3) * mu_d * mu_d)
}

/// Mean speed over a period (m/s): v̄ = g T φ³ Γ             \[P\] (27)
pub fn v_avg(g: f64, period: f64, phi: f64, mu_s: f64, mu_d: f64) -> f64 {
    g * period * phi.powi(3) * gamma(mu_s, mu_d)
}

/// Advance per period (m): x_T = v̄ T = g T² φ³ Γ             \[P\] (30)
pub fn advance_per_period(g: f64, period: f64, phi: f64, mu_s: f64, mu_d: f64) -> f64 {
    v_avg(g, period, phi, mu_s, mu_d) * period
}

/// Dissipated power (W): P = F v̄ = (g T/W³) Γ F⁴             \[P\] (29)
pub fn power(force: f64, v_avg: f64) -> f64 {
    force * v_avg
}

/// Late-stick time (fraction of T, in the next period), defined for 1/Θ < φ ≤ φ_c (`None`
/// elsewhere, serialized as null):
/// ```text
/// τ_ST,late = 1 + τ'_M − √(2 τ'_M² − v_M/(gT μd))          [D] guide §7.5
/// ```
pub fn tau_stick_late(phi: f64, mu_s: f64, mu_d: f64) -> Option<f64> {
    // Only where it describes the motion: beyond φ_c the root of the same expression (it comes
    // back for φ > 2μd, where τ'_M < 0) is no stick of a mass that never sticks again.
    if regime(phi, mu_s, mu_d) != Regime::SlipStickLate {
        return None;
    }
    let tp = tau_accel_zero_falling(phi, mu_d);
    let arg = 2.0 * tp * tp - v_max_reduced(phi, mu_s, mu_d) / mu_d;
    (arg >= 0.0).then(|| 1.0 + tp - arg.sqrt())
}

/// v_M/(gT), the maximum speed in units of gT.
pub(crate) fn v_max_reduced(phi: f64, mu_s: f64, mu_d: f64) -> f64 {
    phi * phi * big_d(mu_s, mu_d) / (16.0 * mu_s * mu_s * mu_d)
}

/// Advance per period of the late-stick orbit (m):
/// ```text
/// x_T,late = gT² [F1(½) − F1(τ_SL) + F2(1) − F2(½) + F3(τ_ST,late) − F3(1)]
/// F1(t) = μd (t−τ'_M)³/3 − c t,   c = φ²(μs−μd)²/(16μs²μd)
/// F2(t) = (v_M/gT) t − μd (t−τ_M)³/3
/// F3(t) = (v_M/gT − 2μdτ'_M²) t + μd (t−1−τ'_M)³/3          [D] guide §7.5
/// ```
pub fn advance_per_period_late(g: f64, period: f64, phi: f64, mu_s: f64, mu_d: f64) -> Option<f64> {
    let t_late = tau_stick_late(phi, mu_s, mu_d)?;
    let tp = tau_accel_zero_falling(phi, mu_d);
    let tm = tau_max_speed(phi, mu_d);
    let vm = v_max_reduced(phi, mu_s, mu_d);
    let c = phi * phi * (mu_s - mu_d).powi(2) / (16.0 * mu_s * mu_s * mu_d);
    let f1 = |t: f64| mu_d * (t - tp).powi(3) / 3.0 - c * t;
    let f2 = |t: f64| vm * t - mu_d * (t - tm).powi(3) / 3.0;
    let f3 = |t: f64| (vm - 2.0 * mu_d * tp * tp) * t + mu_d * (t - 1.0 - tp).powi(3) / 3.0;
    let tau_sl = tau_slip(phi, mu_s);
    let sum = f1(0.5) - f1(tau_sl) + f2(1.0) - f2(0.5) + f3(t_late) - f3(1.0);
    Some(g * period * period * sum)
}

/// Regime of the linearized pulled mass (guide §9), serialized as its [`id`].
///
/// [`id`]: Regime::id
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Regime {
    /// φ > 2μs: slips at t = 0 and never sticks.
    ImmediateContinuousSlip,
    /// φ ≤ 1/Θ: sticks within the same period (the paper's stick-slip).
    SlipStick,
    /// 1/Θ < φ ≤ φ_c: sticks early in the next period.
    SlipStickLate,
    /// φ_c < φ ≤ 2μs: never sticks again.
    ContinuousSlip,
}

impl Regime {
    /// Every regime, in the order of φ.
    pub const ALL: [Self; 4] = [
        Self::SlipStick,
        Self::SlipStickLate,
        Self::ContinuousSlip,
        Self::ImmediateContinuousSlip,
    ];

    /// The identifier used in JSON and reports.
    pub const fn id(self) -> &'static str {
        match self {
            Self::ImmediateContinuousSlip => "immediate_continuous_slip",
            Self::SlipStick => "slip_stick",
            Self::SlipStickLate => "slip_stick_late",
            Self::ContinuousSlip => "continuous_slip",
        }
    }

    /// The regime in plain words: those of the motion the integration shows
    /// ([`Self::integrated`]), with when the stick comes or the slip starts.
    pub fn words(self) -> &'static str {
        match self {
            Self::SlipStick => "one slip and one stick per period, the stick within the period",
            Self::SlipStickLate => {
                "one slip and one stick per period, the stick early in the next period"
            }
            Self::ContinuousSlip => "continuous slip, never sticking",
            Self::ImmediateContinuousSlip => "continuous slip, never sticking, from t = 0",
        }
    }

    /// The regime the exact integration of the linearized law shows.
    pub fn integrated(self) -> IntegrationRegime {
        match self {
            Self::SlipStick | Self::SlipStickLate => IntegrationRegime::SingleSlipStick,
            Self::ContinuousSlip | Self::ImmediateContinuousSlip => {
                IntegrationRegime::ContinuousSlip
            }
        }
    }
}

impl Serialize for Regime {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.id())
    }
}

/// The regime from φ, μs, μd (guide §9).
pub fn regime(phi: f64, mu_s: f64, mu_d: f64) -> Regime {
    if phi > 2.0 * mu_s {
        Regime::ImmediateContinuousSlip
    } else if phi <= phi_stick_max(mu_s, mu_d) {
        Regime::SlipStick
    } else if phi <= phi_continuous(mu_s, mu_d) {
        Regime::SlipStickLate
    } else {
        Regime::ContinuousSlip
    }
}

/// Every closed form of guide §7 and guide §9 for one parameter set. Serialized as the guide §14 `closed_form`
/// object through the registry ([`super::quantity`]), which names every field.
#[derive(Clone, Debug, PartialEq)]
pub struct ClosedForm {
    pub phi: f64,
    pub tau_slip: f64,
    pub t_slip: f64,
    pub a_slip: f64,
    pub tau_max_speed: f64,
    pub t_max_speed: f64,
    pub v_max: f64,
    pub tau_stick: f64,
    pub t_stick: f64,
    pub slip_duration: f64,
    pub theta: f64,
    pub phi_stick_max: f64,
    pub phi_continuous: f64,
    pub mu_min_equal: f64,
    pub gamma: f64,
    pub v_avg: f64,
    pub advance_per_period: f64,
    pub power: f64,
    pub tau_stick_late: Option<f64>,
    pub advance_per_period_late: Option<f64>,
    pub v_avg_late: Option<f64>,
    pub regime: Regime,
    /// φ > 2μs (the slip starts at t = 0).
    pub immediate_slip: bool,
    /// The same-period formulas (18)–(30) describe the motion (regime slip_stick).
    pub same_period_valid: bool,
    /// P_late = F v̄_late, the power of the late-stick orbit (checked; not a JSON key (guide §14)).
    pub power_late: Option<f64>,
}

impl ClosedForm {
    /// The value of the quantity `key`.
    pub fn value(&self, key: Key) -> Value {
        match key {
            Key::Phi => self.phi.into(),
            Key::TauSlip => self.tau_slip.into(),
            Key::TSlip => self.t_slip.into(),
            Key::ASlip => self.a_slip.into(),
            Key::TauMaxSpeed => self.tau_max_speed.into(),
            Key::TMaxSpeed => self.t_max_speed.into(),
            Key::VMax => self.v_max.into(),
            Key::TauStick => self.tau_stick.into(),
            Key::TStick => self.t_stick.into(),
            Key::SlipDuration => self.slip_duration.into(),
            Key::Theta => self.theta.into(),
            Key::PhiStickMax => self.phi_stick_max.into(),
            Key::PhiContinuous => self.phi_continuous.into(),
            Key::MuMinEqual => self.mu_min_equal.into(),
            Key::Gamma => self.gamma.into(),
            Key::VAvg => self.v_avg.into(),
            Key::AdvancePerPeriod => self.advance_per_period.into(),
            Key::Power => self.power.into(),
            Key::TauStickLate => self.tau_stick_late.into(),
            Key::AdvancePerPeriodLate => self.advance_per_period_late.into(),
            Key::VAvgLate => self.v_avg_late.into(),
            Key::Regime => Value::Label(self.regime.id()),
            Key::ImmediateSlip => self.immediate_slip.into(),
            Key::SamePeriodValid => self.same_period_valid.into(),
            Key::PowerLate => self.power_late.into(),
        }
    }

    /// The number of the quantity `key` (`None` for a label or where it is undefined).
    pub fn get(&self, key: Key) -> Option<f64> {
        self.value(key).number()
    }
}

impl Serialize for ClosedForm {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        serialize_closed_form(s, |key| self.value(key))
    }
}

/// Evaluates every closed form for φ = F/W, μs, μd, g (m/s²), T (s) and F (N).
pub fn evaluate(g: f64, period: f64, force: f64, phi: f64, mu_s: f64, mu_d: f64) -> ClosedForm {
    let v_avg = v_avg(g, period, phi, mu_s, mu_d);
    let tau_sl = tau_slip(phi, mu_s);
    let tau_m = tau_max_speed(phi, mu_d);
    let tau_st = tau_stick(phi, mu_s, mu_d);
    let advance_late = advance_per_period_late(g, period, phi, mu_s, mu_d);
    let regime = regime(phi, mu_s, mu_d);
    ClosedForm {
        phi,
        tau_slip: tau_sl,
        t_slip: tau_sl * period,
        a_slip: a_slip(g, phi, mu_s, mu_d),
        tau_max_speed: tau_m,
        t_max_speed: tau_m * period,
        v_max: v_max(g, period, phi, mu_s, mu_d),
        tau_stick: tau_st,
        t_stick: tau_st * period,
        slip_duration: slip_duration(period, phi, mu_s, mu_d),
        theta: theta(mu_s, mu_d),
        phi_stick_max: phi_stick_max(mu_s, mu_d),
        phi_continuous: phi_continuous(mu_s, mu_d),
        mu_min_equal: mu_min_equal(phi),
        gamma: gamma(mu_s, mu_d),
        v_avg,
        advance_per_period: advance_per_period(g, period, phi, mu_s, mu_d),
        power: power(force, v_avg),
        tau_stick_late: tau_stick_late(phi, mu_s, mu_d),
        advance_per_period_late: advance_late,
        v_avg_late: advance_late.map(|x| x / period),
        regime,
        immediate_slip: phi > 2.0 * mu_s,
        same_period_valid: regime == Regime::SlipStick,
        power_late: advance_late.map(|x| power(force, x / period)),
    }
}

#[cfg(feature = "cli")]
impl schemars::JsonSchema for Regime {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "PulledMassRegime".into()
    }

    fn json_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
        crate::results::schema::one_of(
            "Regime of the pulled mass's closed forms (guide §9)",
            Self::ALL.iter().map(|r| r.id()),
        )
    }
}

#[cfg(feature = "cli")]
impl schemars::JsonSchema for ClosedForm {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "PulledMassClosedForm".into()
    }

    fn json_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
        let ids: Vec<&str> = Regime::ALL.iter().map(|r| r.id()).collect();
        crate::results::schema::closed_form::<super::quantity::Key>(&ids)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::results::quantity::tests::serialized_keys_are_the_registry;
    use crate::results::quantity::{Kind, Registry};

    const G: f64 = 9.81;
    const T: f64 = 0.229_429_488_381_819_04;
    const W: f64 = 0.06 * 9.81;

    fn close(got: f64, want: f64, what: &str) {
        // The worked numbers carry 10 significant digits.
        assert!(
            ((got - want) / want).abs() < 1e-9,
            "{what}: {got} vs {want}"
        );
    }

    #[test]
    fn worked_set_b_slip_stick() {
        let (mu_s, mu_d, f) = (0.4, 0.35, 0.10);
        let c = evaluate(G, T, f, f / W, mu_s, mu_d);
        close(c.phi, 0.169_894_665_3, "φ");
        close(c.tau_slip, 0.393_815_834_2, "tau_SL");
        close(c.t_slip, 0.090_352_965_35, "t_SL");
        close(c.tau_max_speed, 0.621_353_332_4, "tau_M");
        close(c.a_slip, 0.104_166_666_7, "a_SL");
        close(c.v_max, 0.023_020_430_9, "v_M");
        close(c.tau_stick, 0.792_301_157_6, "tau_ST");
        close(c.slip_duration, 0.091_424_283_87, "slip duration");
        close(c.theta, 3.440_969_227, "Theta");
        close(c.phi_stick_max, 0.290_615_792_9, "1/Theta");
        close(c.phi_continuous, 0.350_686_277_1, "phi_c");
        close(c.mu_min_equal, 0.205_081_002_6, "mu_min");
        close(c.gamma, 0.488_981_670_2, "Gamma");
        close(c.advance_per_period, 0.001_238_224_198, "x_T");
        close(c.v_avg, 0.005_396_970_576, "v̄");
        close(c.power, 5.396_970_576e-4, "P");
        assert_eq!(c.regime, Regime::SlipStick);
        assert_eq!(c.tau_stick_late, None);
    }

    #[test]
    fn worked_set_c_late_stick() {
        let (mu_s, mu_d, f) = (0.4, 0.35, 0.18);
        let c = evaluate(G, T, f, f / W, mu_s, mu_d);
        close(c.tau_max_speed, 0.718_435_998_3, "tau_M");
        close(c.v_max, 0.074_586_196_1, "v_M");
        close(c.tau_stick, 1.026_142_084, "tau_ST");
        close(c.advance_per_period, 0.007_221_323_524, "x_T");
        close(c.tau_stick_late.unwrap(), 1.028_831_853, "tau_ST,late");
        close(
            c.advance_per_period_late.unwrap(),
            0.007_223_807_769,
            "x_T,late",
        );
        close(c.v_avg_late.unwrap(), 0.031_485_960_33, "v_avg,late");
        assert_eq!(c.regime, Regime::SlipStickLate);
    }

    #[test]
    fn worked_set_a_fig6_continuous() {
        let (mu_s, mu_d, f) = (0.4, 0.25, 0.18);
        let c = evaluate(G, T, f, f / W, mu_s, mu_d);
        close(c.t_slip, 0.070_863_542_28, "t_SL");
        close(c.t_max_speed, 0.184_876_667_2, "t_M");
        close(c.a_slip, 0.5625, "a_SL");
        close(c.v_max, 0.097_842_994_26, "v_M");
        close(c.t_stick, 0.280_548_694_7, "t_ST");
        close(c.gamma, 0.861_047_116_4, "Gamma");
        close(c.v_avg, 0.055_424_515_16, "v̄");
        close(c.phi_continuous, 0.254_556_168_6, "phi_c");
        assert_eq!(c.regime, Regime::ContinuousSlip);
        assert_eq!(c.tau_stick_late, None);
    }

    #[test]
    fn regimes_are_serialized_as_their_ids_and_named_once() {
        for r in Regime::ALL {
            assert_eq!(serde_json::to_value(r).unwrap(), r.id());
            // People read one name for one motion: the closed form's words are the
            // integration's, with when the stick comes or the slip starts.
            assert!(r.words().starts_with(r.integrated().words()), "{}", r.id());
            assert_eq!(Regime::ALL.iter().filter(|q| q.id() == r.id()).count(), 1);
        }
        for r in IntegrationRegime::ALL {
            assert_eq!(serde_json::to_value(r).unwrap(), r.json_id());
            assert!(!r.words().is_empty());
            assert_eq!(
                IntegrationRegime::ALL
                    .iter()
                    .filter(|q| q.id() == r.id())
                    .count(),
                1
            );
        }
    }

    /// The guide §14 `closed_form` keys, in order.
    const SECTION_7_KEYS: &str = "phi, tau_slip, t_slip, a_slip, tau_max_speed, t_max_speed, v_max, tau_stick, t_stick, slip_duration, theta, phi_stick_max, phi_continuous, mu_min_equal, gamma, v_avg, advance_per_period, power, tau_stick_late, advance_per_period_late, v_avg_late, regime, immediate_slip, same_period_valid";

    #[test]
    fn json_has_exactly_the_section_7_keys_in_order() {
        let (mu_s, mu_d, f) = (0.4, 0.35, 0.10);
        let c = evaluate(G, T, f, f / W, mu_s, mu_d);
        let json = serde_json::to_value(&c).unwrap();
        serialized_keys_are_the_registry::<Key>(&json);
        let want: Vec<&str> = SECTION_7_KEYS.split(", ").collect();
        let registry: Vec<&str> = Key::ENTRIES
            .iter()
            .filter(|e| e.kind != Kind::Checked)
            .map(|e| e.quantity.id)
            .collect();
        assert_eq!(registry, want);
        let text = serde_json::to_string(&c).unwrap();
        let positions: Vec<usize> = want
            .iter()
            .map(|k| text.find(&format!("\"{k}\":")).unwrap())
            .collect();
        assert!(positions.windows(2).all(|w| w[0] < w[1]), "{text}");
        assert_eq!(json["regime"], "slip_stick");
        assert!(json["tau_stick_late"].is_null() && json.get("power_late").is_none());
    }

    #[test]
    fn equal_coefficients_special_cases() {
        let mu = 0.3;
        let g = gamma(mu, mu);
        let want = (1.0 + std::f64::consts::SQRT_2).powi(2) / (96.0 * mu * mu);
        assert!(((g - want) / want).abs() < 1e-14);
        assert!((phi_continuous(mu, mu) - mu).abs() < 1e-15);
        // (22): with μs = μd = μ_MIN, φ sits exactly on the boundary (20).
        let phi = 0.2;
        let m = mu_min_equal(phi);
        assert!((phi_stick_max(m, m) - phi).abs() < 1e-15);
    }

    #[test]
    fn speed_formula_vanishes_at_slip_and_stick_and_peaks_at_vm() {
        let (mu_s, mu_d, phi) = (0.4, 0.35, 0.17);
        let sp = |tau| speed(G, T, phi, mu_s, mu_d, tau);
        assert!(sp(tau_slip(phi, mu_s)).abs() < 1e-16);
        assert!(sp(tau_stick(phi, mu_s, mu_d)).abs() < 1e-16);
        let vm = v_max(G, T, phi, mu_s, mu_d);
        assert!((sp(tau_max_speed(phi, mu_d)) - vm).abs() < 1e-16);
        // Continuous at τ = ½.
        assert!((sp(0.5) - sp(0.5 + 1e-12)).abs() < 1e-12);
    }
}
