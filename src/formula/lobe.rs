//! The lobe engine of physics.md §3.6 [D]: one slip of the linearized woodpecker sleeve, from rest,
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

use serde::{Deserialize, Serialize};

/// The flank on which a slip of the lobe engine halts (§3.6 steps 2–5).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
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

/// Runs one slip from rest through the lobes (§3.6, steps 1–5).
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

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

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
}
