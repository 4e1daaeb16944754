//! The lobe engine of guide §8.6 \[D\]: one slip of the linearized woodpecker sleeve, from rest,
//! through the chain of triangular lobes of |F_e|, in closed form and in dimensionless units.
//!
//! ```text
//! θ = (t − t_zero)/(τε),  τε = τ W_S/(k ζ0)       time unit (s); t_zero = end of lobe A
//! speed unit g τε,  length unit g (τε)²,  a/g = 1 − u |F_e|/W_S  with |F_e|/W_S = |θ| per lobe
//!
//!   lobe A falling      lobe B rising   lobe B falling   lobe A rising   lobe A falling
//!   θ_SL = −1/U .. 0    0 .. h_B        h_B .. 2h_B      .. + h_A        .. + h_A
//!   (slip onset)        halt "B"        halt "B_late"    halt "A"        halt "A_late"
//! ```
//!
//! Phase I runs the engine with (U, u_A, u_B, h_A, h_B) = (u_s^(−), u_d^(−), u_d^(+), η', η),
//! t_zero = t0^(I); phase II with the swap (u_s^(+), u_d^(+), u_d^(−), η, η'), t_zero = t0^(II).
//! On every flank the acceleration is affine in θ, so v is a parabola and y a cubic: a halt is the
//! root of a quadratic, a speed maximum the zero of a where it turns from + to −.
//!
//! This module also owns the exact halt boundaries μd,HALT and the orbit selection that turns
//! the slips of the two phases into the period-T orbit in SI units ([`periodic_orbit`]).

use serde::{Deserialize, Serialize};

use crate::engine::IntegrationRegime;

/// The flank on which a slip of the lobe engine halts (guide §8.6 steps 2–5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub enum HaltKind {
    /// Rising flank of lobe B: the paper's stick, (49)/(60).
    #[serde(rename = "B")]
    B,
    /// Falling flank of lobe B: a late halt, still before the next ordinary slip time.
    #[serde(rename = "B_late")]
    BLate,
    /// Rising flank of the next lobe A: the slip merged across two half periods.
    #[serde(rename = "A")]
    A,
    /// Falling flank of the next lobe A.
    #[serde(rename = "A_late")]
    ALate,
}

impl HaltKind {
    /// Whether the slip runs through lobe B into the next lobe A (a merged slip, one per period).
    pub fn is_merged(self) -> bool {
        matches!(self, HaltKind::A | HaltKind::ALate)
    }
}

/// Where and how far a slip of the lobe engine stops (dimensionless θ and y).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Halt {
    pub kind: HaltKind,
    /// Halt time θ (units τε, from t_zero).
    pub theta: f64,
    /// Distance from the slip onset to the halt (units g (τε)²).
    pub distance: f64,
}

/// One slip of the lobe engine, dimensionless (see the module doc for the units).
#[derive(Clone, Debug, PartialEq)]
pub struct LobeSlip {
    /// Slip onset θ_SL = −1/U.
    pub theta_slip: f64,
    /// Speed maxima (θ, v) in time order, up to the halt (or through lobe A if there is none).
    pub maxima: Vec<(f64, f64)>,
    /// The halt; `None` when the slip goes on past lobe A (no closed form: continuous or
    /// multi-period motion).
    pub halt: Option<Halt>,
}

/// Motion at the start of a flank: time θ, speed v > 0, distance y since the slip onset.
#[derive(Clone, Copy, Debug)]
struct State {
    theta: f64,
    v: f64,
    y: f64,
}

/// How a flank ends: the sleeve halts on it, or leaves it still slipping.
enum FlankEnd {
    Halt { theta: f64, y: f64 },
    Through(State),
}

#[derive(Clone, Copy)]
enum Slope {
    Rising,
    Falling,
}

/// Runs one slip from rest through the lobes (guide §8.6, steps 1–5).
///
/// ```text
/// θ_SL = −1/U,   V0 = v(0) = (2U − u_A)/(2U²),   Y0 = y(0) = (3U − 2u_A)/(6U³)
/// rising flank  (|F_e|/W_S = ψ):        v = V + ψ − uψ²/2,          halt ψ = [1 + √(1 + 2uV)]/u ≤ h
/// falling flank (|F_e|/W_S = h − ψ):    v = V + (1 − uh)ψ + uψ²/2,   halt ψ = 2V/[(uh − 1) + √Δ],
///                                       Δ = (uh − 1)² − 2uV ≥ 0, uh > 1
/// ```
///
/// Arguments: `u_s` = U (static factor of lobe A, where the slip starts), `u_a`, `u_b` the dynamic
/// factors of lobes A and B, `h_a`, `h_b` the lobe heights in units of W_S. Returns `None` when the
/// slip cannot start from rest on the falling flank of lobe A: U ≤ 0, U h_A < 1 (the sleeve cannot
/// be held anywhere in lobe A, e.g. immediate slip (38) for phase I), u_A > U (μd > μs: the sleeve
/// would not accelerate), a lobe height ≤ 0, or a non-finite input.
pub fn lobe_engine(u_s: f64, u_a: f64, u_b: f64, h_a: f64, h_b: f64) -> Option<LobeSlip> {
    let finite = [u_s, u_a, u_b, h_a, h_b].iter().all(|x| x.is_finite());
    if !finite || u_s <= 0.0 || u_s * h_a < 1.0 || u_a > u_s || h_a <= 0.0 || h_b <= 0.0 {
        return None;
    }
    let flanks = [
        (Slope::Rising, u_b, h_b, HaltKind::B),
        (Slope::Falling, u_b, h_b, HaltKind::BLate),
        (Slope::Rising, u_a, h_a, HaltKind::A),
        (Slope::Falling, u_a, h_a, HaltKind::ALate),
    ];
    let mut state = State {
        theta: 0.0,
        v: speed_at_zero(u_s, u_a),
        y: distance_at_zero(u_s, u_a),
    };
    let mut maxima = Vec::new();
    for (slope, u, h, kind) in flanks {
        let end = match slope {
            Slope::Rising => rising_flank(state, u, h, &mut maxima),
            Slope::Falling => falling_flank(state, u, h),
        };
        match end {
            FlankEnd::Halt { theta, y } => {
                let halt = Halt {
                    kind,
                    theta,
                    distance: y,
                };
                return Some(LobeSlip {
                    theta_slip: -1.0 / u_s,
                    maxima,
                    halt: Some(halt),
                });
            }
            FlankEnd::Through(next) => state = next,
        }
    }
    Some(LobeSlip {
        theta_slip: -1.0 / u_s,
        maxima,
        halt: None,
    })
}

/// Speed at the end of lobe A (θ = 0), after slipping from θ_SL = −1/U with a = 1 + u_A θ:
/// V0 = (2U − u_A)/(2U²). Positive because u_A ≤ U.
fn speed_at_zero(u_s: f64, u_a: f64) -> f64 {
    (2.0 * u_s - u_a) / (2.0 * u_s * u_s)
}

/// Distance slipped by θ = 0: Y0 = (3U − 2u_A)/(6U³).
fn distance_at_zero(u_s: f64, u_a: f64) -> f64 {
    (3.0 * u_s - 2.0 * u_a) / (6.0 * u_s.powi(3))
}

/// Rising flank, a = 1 − uψ for 0 ≤ ψ ≤ h. The speed maximum at ψ = 1/u is recorded when a turns
/// from + to − inside the flank (uh > 1); it always precedes a halt on the same flank.
fn rising_flank(s: State, u: f64, h: f64, maxima: &mut Vec<(f64, f64)>) -> FlankEnd {
    let y_at = |psi: f64| s.y + s.v * psi + 0.5 * psi * psi - u * psi.powi(3) / 6.0;
    if u * h > 1.0 {
        maxima.push((s.theta + 1.0 / u, s.v + 0.5 / u));
    }
    if u > 0.0 {
        let psi = (1.0 + (1.0 + 2.0 * u * s.v).sqrt()) / u;
        if psi <= h {
            return FlankEnd::Halt {
                theta: s.theta + psi,
                y: y_at(psi),
            };
        }
    }
    FlankEnd::Through(State {
        theta: s.theta + h,
        v: s.v + h - 0.5 * u * h * h,
        y: y_at(h),
    })
}

/// Falling flank, a = 1 − u(h − ψ) for 0 ≤ ψ ≤ h: a rises, so the speed can only have a minimum,
/// at ψ = h − 1/u; the sleeve halts if that minimum is ≤ 0 (smaller root, cancellation-free form).
fn falling_flank(s: State, u: f64, h: f64) -> FlankEnd {
    let y_at = |psi: f64| s.y + s.v * psi + 0.5 * (1.0 - u * h) * psi * psi + u * psi.powi(3) / 6.0;
    let excess = u * h - 1.0;
    if excess > 0.0 {
        let disc = excess * excess - 2.0 * u * s.v;
        if disc >= 0.0 {
            let psi = 2.0 * s.v / (excess + disc.sqrt());
            return FlankEnd::Halt {
                theta: s.theta + psi,
                y: y_at(psi),
            };
        }
    }
    FlankEnd::Through(State {
        theta: s.theta + h,
        v: s.v + h - 0.5 * u * h * h,
        y: y_at(h),
    })
}

// ---------------------------------------------------------------------------------------------
// Exact halt boundaries (closed form)

/// Least u_B for which the slip halts in lobe B (rising or falling flank), dimensionless:
/// ```text
/// u_B ≥ max(x₊, 1/h_B),  x₊ = [B + √(B² − A U²)]/A,  A = 1 + 2h_B²U²,  B = U + σ + 2h_B U²
/// ```
/// with σ the ±1 of u_B = 2λμd + σ (phase I: +1, phase II: −1). Equivalent to
/// 2 v_ext(end of the rising flank) ≤ v_M. When B² < A U² the quadratic has no real root and every
/// u_B ≥ 1/h_B halts (x₋ < 1/h_B always, so the halt set is the one interval).      \[D\] guide §8.6
pub fn halt_threshold(u_s: f64, h_b: f64, sigma: f64) -> Option<f64> {
    let a = 1.0 + 2.0 * h_b * h_b * u_s * u_s;
    let b = u_s + sigma + 2.0 * h_b * u_s * u_s;
    let floor = 1.0 / h_b;
    let disc = b * b - a * u_s * u_s;
    // a ≥ 1, so only h_B = 0 or a non-finite input can make this undefined.
    let x = if disc >= 0.0 {
        ((b + disc.sqrt()) / a).max(floor)
    } else {
        floor
    };
    x.is_finite().then_some(x)
}

/// Exact least μd for a halt in lobe B (dimensionless):
/// ```text
/// μd,HALT = (max(x₊, 1/h_B) − σ)/(2λ)
///   phase I:  halt before the phase-II slip,      (max(x₊, 1/η) − 1)/(2λ)            [D] guide §8.6
///   phase II: halt before the next phase-I slip,  (max(x'₊, 1/η') + 1)/(2λ)          [D] guide §8.6
/// ```
pub fn mu_d_halt(lambda: f64, u_s: f64, h_b: f64, sigma: f64) -> Option<f64> {
    let mu = (halt_threshold(u_s, h_b, sigma)? - sigma) / (2.0 * lambda);
    mu.is_finite().then_some(mu)
}

// ---------------------------------------------------------------------------------------------
// The periodic orbit in SI units (guide §8.6, orbit selection)

/// Half period in which a slip starts: I (F_e decreasing) or II (F_e increasing).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub enum Phase {
    #[serde(rename = "I")]
    One,
    #[serde(rename = "II")]
    Two,
}

impl Phase {
    /// Index in [phase I, phase II] arrays.
    pub fn index(self) -> usize {
        match self {
            Phase::One => 0,
            Phase::Two => 1,
        }
    }

    /// The other half period.
    pub fn other(self) -> Phase {
        match self {
            Phase::One => Phase::Two,
            Phase::Two => Phase::One,
        }
    }
}

/// Regime of the periodic orbit of the linear model (guide §8.6, orbit selection), serialized as its
/// [`id`].
///
/// [`id`]: OrbitRegime::id
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OrbitRegime {
    /// (39): the sleeve never slips.
    NoSlip,
    /// Two slips and two sticks per period (the paper's regime when both halts are "B").
    DoubleSlipStick,
    /// One merged slip per period whose speed dips in lobe B (two maxima).
    DoubleSlipNoHalt,
    /// One merged slip per period with a single speed maximum.
    SingleSlipStick,
    /// The engine finds no halt: integrate numerically (continuous slip in all tests).
    ContinuousOrMultiperiod,
    /// δ0 ≥ ζ0 (or δ0 < 0), u_s^(−) ≤ 0, μd > μs, or degenerate k, W_S, ζ0, τ.
    OutsideClosedFormDomain,
}

impl OrbitRegime {
    /// Every regime.
    pub const ALL: [Self; 6] = [
        OrbitRegime::NoSlip,
        OrbitRegime::DoubleSlipStick,
        OrbitRegime::DoubleSlipNoHalt,
        OrbitRegime::SingleSlipStick,
        OrbitRegime::ContinuousOrMultiperiod,
        OrbitRegime::OutsideClosedFormDomain,
    ];

    /// The regime of the integration that shows this orbit, when it has one: the orbit of the
    /// lobe engine is then the periodic motion of that name.
    pub const fn integrated(self) -> Option<IntegrationRegime> {
        match self {
            OrbitRegime::NoSlip => Some(IntegrationRegime::NoSlip),
            OrbitRegime::DoubleSlipStick => Some(IntegrationRegime::DoubleSlipStick),
            OrbitRegime::DoubleSlipNoHalt => Some(IntegrationRegime::DoubleSlipNoHalt),
            OrbitRegime::SingleSlipStick => Some(IntegrationRegime::SingleSlipStick),
            OrbitRegime::ContinuousOrMultiperiod | OrbitRegime::OutsideClosedFormDomain => None,
        }
    }

    /// The identifier used in JSON and reports (guide §8.6): that of the integrated
    /// regime when the orbit is one.
    pub const fn id(self) -> &'static str {
        match (self, self.integrated()) {
            (_, Some(integrated)) => integrated.id(),
            (OrbitRegime::ContinuousOrMultiperiod, None) => "continuous_or_multiperiod",
            (_, None) => "outside_closed_form_domain",
        }
    }

    /// The regime in plain words.
    pub fn words(self) -> &'static str {
        match (self, self.integrated()) {
            (_, Some(integrated)) => integrated.words(),
            (OrbitRegime::ContinuousOrMultiperiod, None) => {
                "no halt: continuous slip, or a motion repeating only after several periods"
            }
            (_, None) => "outside the domain of the closed forms",
        }
    }
}

impl Serialize for OrbitRegime {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.id())
    }
}

/// One slip of the periodic orbit (SI). Times are measured from the start of the period in which
/// the slip starts (0 ≤ t_slip < T) and are not reduced mod T: a halt may come after T (every
/// phase-II slip that halts in A/A_late or B_late, and phase-I slips that halt in A_late).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct OrbitSlip {
    /// Half period in which the slip starts.
    pub phase: Phase,
    /// Flank on which it halts.
    pub halt: HaltKind,
    pub t_slip: f64,
    pub t_halt: f64,
    /// Speed maxima (t in s, v in m/s), in time order.
    pub speed_maxima: Vec<(f64, f64)>,
    /// Distance from the slip onset to the halt (m).
    pub distance: f64,
}

/// The period-T orbit of the linear model (guide §8.6), SI.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Orbit {
    /// Slips in order of their slip time within the period (empty for `no_slip`).
    pub slips: Vec<OrbitSlip>,
    /// T = 4τ (s).
    pub period: f64,
    /// Advance per period (m).
    pub distance_per_period: f64,
    /// v̄ = distance per period / T (m/s).
    pub v_avg: f64,
}

impl Orbit {
    /// The orbit made of `slips` (in order of slip time), advancing their summed distance per period.
    pub fn new(slips: Vec<OrbitSlip>, period: f64) -> Self {
        let distance_per_period: f64 = slips.iter().map(|s| s.distance).sum();
        // A sleeve at rest advances 0 per period, whatever T is.
        let v_avg = match slips.is_empty() {
            true => 0.0,
            false => distance_per_period / period,
        };
        Orbit {
            slips,
            period,
            distance_per_period,
            v_avg,
        }
    }
}

/// The lobes met by the slip of one phase, with the SI scales that place it in the period.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhaseLobes {
    pub phase: Phase,
    /// U of the lobe where the slip starts.
    pub u_s: f64,
    /// Dynamic factors of lobes A and B.
    pub u_a: f64,
    pub u_b: f64,
    /// Heights of lobes A and B in units of W_S.
    pub h_a: f64,
    pub h_b: f64,
    /// The zero of F_e that ends lobe A: t0 of the phase (s).
    pub t_zero: f64,
    /// τε = τ W_S/(k ζ0) (s).
    pub time_unit: f64,
    /// g (m/s²).
    pub g: f64,
}

impl PhaseLobes {
    /// The slip of this phase in SI units (times from the start of the period of the slip), if
    /// it can start from rest and halts.
    pub fn orbit_slip(&self) -> Option<OrbitSlip> {
        let slip = lobe_engine(self.u_s, self.u_a, self.u_b, self.h_a, self.h_b)?;
        let halt = slip.halt?;
        let time = |theta: f64| self.t_zero + theta * self.time_unit;
        let speed_unit = self.g * self.time_unit;
        Some(OrbitSlip {
            phase: self.phase,
            halt: halt.kind,
            t_slip: time(slip.theta_slip),
            t_halt: time(halt.theta),
            speed_maxima: (slip.maxima.iter())
                .map(|&(theta, v)| (time(theta), v * speed_unit))
                .collect(),
            distance: halt.distance * speed_unit * self.time_unit,
        })
    }
}

/// Orbit selection (guide §8.6) from the halting slips of the two phases, `[phase I, phase II]`
/// (`None`: that slip cannot start from rest or never halts), starting with the slip of `first`.
///
/// After a halt in lobe B the next slip is the ordinary slip of the other phase (at a halt a < 0,
/// so |F_e| > W_S/u_d ≥ W_S/u_s and the sleeve stays stuck until then); after a merged halt
/// (lobe A) it is the ordinary slip of the same phase one period later. Two B halts make
/// `double_slip_stick`; a merged slip is `double_slip_no_halt` with two speed maxima and
/// `single_slip_stick` with one; no halt on the way is `continuous_or_multiperiod`.
pub fn periodic_orbit(
    slips: &[Option<OrbitSlip>; 2],
    first: Phase,
    period: f64,
) -> (OrbitRegime, Option<Orbit>) {
    let Some(slips) = periodic_slips(slips, first) else {
        return (OrbitRegime::ContinuousOrMultiperiod, None);
    };
    let regime = match slips.as_slice() {
        [merged] if merged.speed_maxima.len() >= 2 => OrbitRegime::DoubleSlipNoHalt,
        [_] => OrbitRegime::SingleSlipStick,
        _ => OrbitRegime::DoubleSlipStick,
    };
    (regime, Some(Orbit::new(slips, period)))
}

/// The slips of the periodic orbit reached from phase `first`, in order of slip time.
fn periodic_slips(slips: &[Option<OrbitSlip>; 2], first: Phase) -> Option<Vec<OrbitSlip>> {
    let a = slips[first.index()].clone()?;
    if a.halt.is_merged() {
        return Some(vec![a]);
    }
    let b = slips[first.other().index()].clone()?;
    if b.halt.is_merged() {
        return Some(vec![b]);
    }
    let mut both = vec![a, b];
    both.sort_by(|x, y| x.t_slip.total_cmp(&y.t_slip));
    Some(both)
}

#[cfg(feature = "cli")]
impl schemars::JsonSchema for OrbitRegime {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        "OrbitRegime".into()
    }

    fn json_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
        crate::results::schema::one_of(
            "Regime of the woodpecker's periodic orbit (guide §10)",
            Self::ALL.iter().map(|r| r.id()),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    #[test]
    fn orbit_regimes_are_serialized_as_their_ids_and_named_once() {
        for r in OrbitRegime::ALL {
            assert_eq!(serde_json::to_value(r).unwrap(), r.id());
            assert!(!r.words().is_empty());
            assert_eq!(
                OrbitRegime::ALL.iter().filter(|q| q.id() == r.id()).count(),
                1
            );
            // An orbit the integration names has the integration's id and words.
            if let Some(i) = r.integrated() {
                assert_eq!((r.id(), r.words()), (i.id(), i.words()));
            }
        }
    }

    /// Speed on a rising flank from the engine's own formulas (for checks).
    fn rising_speed(v: f64, u: f64, psi: f64) -> f64 {
        v + psi - 0.5 * u * psi * psi
    }

    #[test]
    fn slip_onset_speed_and_distance_integrate_the_lobe_a_acceleration() {
        // a = 1 + u_A θ from θ_SL = −1/U: v(0) = ∫ a, y(0) = ∫∫ a, by the midpoint rule on a fine grid.
        let (u_s, u_a) = (1.9, 0.45);
        let n = 200_000;
        let (t0, dt) = (-1.0 / u_s, 1.0 / u_s / n as f64);
        let (mut v, mut y) = (0.0, 0.0);
        for i in 0..n {
            let a = 1.0 + u_a * (t0 + (i as f64 + 0.5) * dt);
            y += v * dt + 0.5 * a * dt * dt;
            v += a * dt;
        }
        assert_relative_eq!(v, speed_at_zero(u_s, u_a), max_relative = 1e-9);
        assert_relative_eq!(y, distance_at_zero(u_s, u_a), max_relative = 1e-8);
    }

    #[test]
    fn halt_on_the_rising_flank_has_zero_speed_and_follows_the_maximum() {
        let slip = lobe_engine(1.971428571, 0.4628571429, 2.462857143, 4.79, 1.32).unwrap();
        let halt = slip.halt.unwrap();
        assert_eq!(halt.kind, HaltKind::B);
        let v0 = speed_at_zero(1.971428571, 0.4628571429);
        assert!(rising_speed(v0, 2.462857143, halt.theta).abs() < 1e-14);
        assert_eq!(slip.maxima.len(), 1);
        assert!(slip.maxima[0].0 < halt.theta);
    }

    #[test]
    fn low_lobe_b_gives_a_single_maximum_in_lobe_a() {
        // u_B h_B ≤ 1: no deceleration in lobe B, the slip merges and halts in lobe A.
        let slip = lobe_engine(2.0, 0.5, 2.5, 5.0, 0.3).unwrap();
        assert_eq!(slip.maxima.len(), 1);
        assert!(slip.maxima[0].0 > 2.0 * 0.3);
        assert!(slip.halt.unwrap().kind.is_merged());
    }

    #[test]
    fn slip_that_cannot_start_from_rest_is_refused() {
        assert!(lobe_engine(0.5, 0.2, 2.0, 1.5, 1.0).is_none()); // U h_A < 1
        assert!(lobe_engine(1.0, 1.2, 3.0, 5.0, 1.0).is_none()); // u_A > U
        assert!(lobe_engine(-1.0, -2.0, 1.0, 5.0, 1.0).is_none());
        assert!(lobe_engine(2.0, 0.5, f64::NAN, 5.0, 1.0).is_none());
    }

    #[test]
    fn no_deceleration_anywhere_means_no_halt() {
        // u_A < 0 and u_B h_B < 1: a > 0 on every flank.
        let slip = lobe_engine(0.3, -0.36, 1.64, 5.4, 0.5).unwrap();
        assert!(slip.halt.is_none());
        assert!(slip.maxima.is_empty());
    }

    #[test]
    fn halt_threshold_without_a_real_root_is_the_lobe_floor() {
        // σ = −1, U = 1.5, h_B = 0.05: B² < A U², every u_B ≥ 1/h_B halts.
        assert_relative_eq!(
            halt_threshold(1.5, 0.05, -1.0).unwrap(),
            20.0,
            max_relative = 1e-15
        );
        assert_eq!(halt_threshold(1.5, 0.0, 1.0), None);
    }

    #[test]
    fn halt_threshold_separates_the_engine_halts_in_lobe_b() {
        // Phase-I factors of the Fig 15 `zeros` set, varying μd through u_A = u_B − 2.
        let (u_s, h_a, h_b) = (1.971428571, 4.792985346, 1.323222605);
        let thr = halt_threshold(u_s, h_b, 1.0).unwrap();
        let kind = |u_b: f64| lobe_engine(u_s, u_b - 2.0, u_b, h_a, h_b).and_then(|s| s.halt);
        assert!(!kind(thr * (1.0 + 1e-9)).unwrap().kind.is_merged());
        assert!(kind(thr * (1.0 - 1e-9)).is_none_or(|h| h.kind.is_merged()));
    }

    fn slip(phase: Phase, halt: HaltKind, t_slip: f64, distance: f64) -> OrbitSlip {
        OrbitSlip {
            phase,
            halt,
            t_slip,
            t_halt: t_slip + 0.01,
            speed_maxima: vec![(t_slip + 0.005, 0.1)],
            distance,
        }
    }

    #[test]
    fn orbit_selection_follows_the_halts_of_both_phases() {
        let one_b = slip(Phase::One, HaltKind::B, 0.05, 0.001);
        let two_b = slip(Phase::Two, HaltKind::BLate, 0.09, 0.002);
        let two_a = slip(Phase::Two, HaltKind::A, 0.09, 0.004);
        // I halts in B, II halts in B: two slips, in time order whatever the start.
        let (regime, orbit) =
            periodic_orbit(&[Some(one_b.clone()), Some(two_b.clone())], Phase::Two, 0.2);
        assert_eq!(regime, OrbitRegime::DoubleSlipStick);
        let orbit = orbit.unwrap();
        assert_eq!(orbit.slips, vec![one_b.clone(), two_b]);
        assert_relative_eq!(orbit.v_avg, 0.003 / 0.2, max_relative = 1e-15);
        // I halts in B, II merges into the next period: the steady orbit is the II slip alone.
        let (regime, orbit) =
            periodic_orbit(&[Some(one_b.clone()), Some(two_a.clone())], Phase::One, 0.2);
        assert_eq!(regime, OrbitRegime::SingleSlipStick);
        assert_eq!(orbit.unwrap().slips, vec![two_a]);
        // I never halts: no closed-form orbit.
        let (regime, orbit) = periodic_orbit(&[None, Some(one_b)], Phase::One, 0.2);
        assert_eq!(
            (regime, orbit),
            (OrbitRegime::ContinuousOrMultiperiod, None)
        );
    }
}
