//! Closed forms of the linearized falling woodpecker (physics.md §3): the counterpart (ζ0, δ0) of the
//! harmonic spring coordinate, the slip conditions (38)–(39), one pure function per quantity of
//! phases I and II (40)–(71), the exact halt boundaries and the periodic orbit from the lobe
//! engine ([`super::lobe`]). SI units: s, m, m/s, m/s², N, N/m, W.
//!
//! ```text
//! ζ(t) = ζ0 (1 − t/τ) on [0, 2τ], ζ0 (t/τ − 3) on [2τ, 4τ];   τ = T/4          (37)
//! F_e = k (δ0 + ζ);   m_S a = W_S + F_e − 2λμd |F_e|   while slipping down
//! u_s^(±) = 2λμs ± 1,  u_d^(±) = 2λμd ± 1                                       [G] (44)
//! η = k(ζ0 − δ0)/W_S (negative lobe),  η' = k(ζ0 + δ0)/W_S (positive lobe)
//! ```
//!
//! Phase II is phase I with u^(−) ↔ u^(+) and η ↔ η' ([`Groups::swapped`]): every per-phase
//! function below is written once, in terms of the factors seen by the slip,
//!
//! ```text
//! U   = static factor of the lobe where the slip starts     phase I: u_s^(−)   phase II: u_s^(+)
//! u_A = dynamic factor of that lobe (lobe A)                 phase I: u_d^(−)   phase II: u_d^(+)
//! u_B = dynamic factor of the next lobe (lobe B)             phase I: u_d^(+)   phase II: u_d^(−)
//! h_B = height of lobe B in units of W_S                     phase I: η         phase II: η'
//! σ   = the ±1 in u_B = 2λμd + σ                             phase I: +1        phase II: −1
//! ```
//!
//! Quantities of the speed maximum in lobe B (t_M, v_M, S, t_ST, Γ, y) exist only when u_B > 0;
//! otherwise a > 0 on the whole of lobe B and they are `None` (as for u_d^(−) < 0, λ = 1).

use serde::{Deserialize, Serialize};
use std::f64::consts::FRAC_2_PI;

use super::lobe::{self, HaltKind, LobeSlip};

// ---------------------------------------------------------------------------------------------
// Counterpart of the harmonic law (§3.1)

/// How the triangle wave (ζ0, δ0) is matched to the harmonic spring coordinate z0 + d0 cos ωt.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Counterpart {
    /// Same maximum and minimum spring coordinate: ζ0 = d0, δ0 = z0.
    Extremes,
    /// Same amplitude and same zero crossings of F_e (the default).
    Zeros,
    /// Same zero crossings of F_e and the same slope dF_e/dt there.
    Tangent,
}

/// (ζ0, δ0) in m of the linear counterpart of z(t) = z0 + d0 cos ωt (§3.1):
///
/// ```text
/// extremes:  ζ0 = d0,                  δ0 = z0
/// zeros:     ζ0 = d0,                  δ0 = d0 (2/π) arcsin(z0/d0)
/// tangent:   ζ0 = (π/2) √(d0² − z0²),  δ0 = ζ0 (2/π) arcsin(z0/d0)
/// ```
///
/// `None` for `zeros`/`tangent` when d0 = 0 or |z0/d0| > 1 (F_e never changes sign), and for any
/// non-finite result.
pub fn counterpart(z0: f64, d0: f64, c: Counterpart) -> Option<(f64, f64)> {
    let pair = match c {
        Counterpart::Extremes => (d0, z0),
        Counterpart::Zeros => (d0, d0 * FRAC_2_PI * arcsin_ratio(z0, d0)?),
        Counterpart::Tangent => {
            let zeta0 = sqrt(d0 * d0 - z0 * z0)? / FRAC_2_PI;
            (zeta0, zeta0 * FRAC_2_PI * arcsin_ratio(z0, d0)?)
        }
    };
    (pair.0.is_finite() && pair.1.is_finite()).then_some(pair)
}

fn arcsin_ratio(z0: f64, d0: f64) -> Option<f64> {
    let ratio = div(z0, d0)?;
    (ratio.abs() <= 1.0).then(|| ratio.asin())
}

// ---------------------------------------------------------------------------------------------
// Guarded arithmetic: an undefined expression is None, never NaN or ±∞.

fn div(num: f64, den: f64) -> Option<f64> {
    let q = num / den;
    (den != 0.0 && q.is_finite()).then_some(q)
}

fn sqrt(x: f64) -> Option<f64> {
    (x >= 0.0).then(|| x.sqrt())
}

fn finite(x: f64) -> Option<f64> {
    x.is_finite().then_some(x)
}

// ---------------------------------------------------------------------------------------------
// Inputs and dimensionless groups (§3.1)

/// Parameters of the linearized woodpecker (§3.1). The friction coefficients enter only as λμ.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct LinearWoodpecker {
    /// Static friction coefficient μs.
    pub mu_s: f64,
    /// Dynamic friction coefficient μd.
    pub mu_d: f64,
    /// Lever ratio λ = l/h (each contact carries N = λ|F_e|); λ = 1 is the printed paper.
    pub lambda: f64,
    /// Spring constant k (N/m).
    pub k: f64,
    /// Sleeve weight W_S = m_S g (N).
    pub w_s: f64,
    /// Gravity g (m/s²).
    pub g: f64,
    /// Triangle amplitude ζ0 (m).
    pub zeta0: f64,
    /// Triangle offset δ0 (m).
    pub delta0: f64,
    /// Quarter period τ = T/4 (s).
    pub tau_quarter: f64,
}

impl LinearWoodpecker {
    /// Period T = 4τ (s).
    pub fn period(&self) -> f64 {
        4.0 * self.tau_quarter
    }
}

/// u^(−) = 2λμ − 1 (dimensionless)                                                   [G] (44)
pub fn u_minus(lambda: f64, mu: f64) -> f64 {
    2.0 * lambda * mu - 1.0
}

/// u^(+) = 2λμ + 1 (dimensionless)                                                   [G] (44)
pub fn u_plus(lambda: f64, mu: f64) -> f64 {
    2.0 * lambda * mu + 1.0
}

/// Height of the negative F_e lobe in units of W_S (dimensionless):
/// ```text
/// η = k (ζ0 − δ0)/W_S = (1 − r)/ε                                                   [P] §3.1
/// ```
pub fn eta(k: f64, zeta0: f64, delta0: f64, w_s: f64) -> Option<f64> {
    div(k * (zeta0 - delta0), w_s)
}

/// Height of the positive F_e lobe in units of W_S (dimensionless):
/// ```text
/// η' = k (ζ0 + δ0)/W_S = (1 + r)/ε                                                  [P] §3.1
/// ```
pub fn eta_prime(k: f64, zeta0: f64, delta0: f64, w_s: f64) -> Option<f64> {
    div(k * (zeta0 + delta0), w_s)
}

/// Time for |F_e| to change by W_S, the lobe engine's time unit (s):
/// ```text
/// τε = τ W_S/(k ζ0)                                                                  [D] §3.6
/// ```
pub fn time_unit(tau: f64, w_s: f64, k: f64, zeta0: f64) -> Option<f64> {
    div(tau * w_s, k * zeta0)
}

/// The friction factors and lobe heights of §3.1, oriented for phase I. [`Groups::swapped`]
/// gives the orientation of phase II (u^(−) ↔ u^(+), η ↔ η').
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Groups {
    pub u_s_minus: f64,
    pub u_s_plus: f64,
    pub u_d_minus: f64,
    pub u_d_plus: f64,
    /// Height of lobe B (phase I: η).
    pub eta: Option<f64>,
    /// Height of lobe A (phase I: η').
    pub eta_prime: Option<f64>,
    /// The ±1 in the slot `u_d_plus` = 2λμd + σ: +1 for phase I, −1 once swapped.
    pub sigma: f64,
}

impl Groups {
    /// Groups of phase I from the parameters.
    pub fn new(p: &LinearWoodpecker) -> Self {
        Groups {
            u_s_minus: u_minus(p.lambda, p.mu_s),
            u_s_plus: u_plus(p.lambda, p.mu_s),
            u_d_minus: u_minus(p.lambda, p.mu_d),
            u_d_plus: u_plus(p.lambda, p.mu_d),
            eta: eta(p.k, p.zeta0, p.delta0, p.w_s),
            eta_prime: eta_prime(p.k, p.zeta0, p.delta0, p.w_s),
            sigma: 1.0,
        }
    }

    /// The paper's rule "phase II = phase I with u^(−) ↔ u^(+), η ↔ η'" (§3.4).
    pub fn swapped(&self) -> Self {
        Groups {
            u_s_minus: self.u_s_plus,
            u_s_plus: self.u_s_minus,
            u_d_minus: self.u_d_plus,
            u_d_plus: self.u_d_minus,
            eta: self.eta_prime,
            eta_prime: self.eta,
            sigma: -self.sigma,
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Slip conditions (§3.2)

/// Immediate slip at t = 0 (the top of the positive lobe), dimensionless test:
/// ```text
/// λμs < ½ (1 + W_S/(k(ζ0 + δ0)))   ⇔   u_s^(−) η' < 1                               [G] (38)
/// ```
/// Evaluated as u_s^(−) k(ζ0 + δ0) < W_S, which is defined for every input.
pub fn immediate_slip(u_s_minus: f64, k: f64, zeta0: f64, delta0: f64, w_s: f64) -> bool {
    u_s_minus * k * (zeta0 + delta0) < w_s
}

/// The sleeve never slips (F_e > 0 always, held at the lowest F_e), dimensionless test:
/// ```text
/// λμs ≥ ½ (1 + W_S/(k(δ0 − ζ0))),   δ0 > ζ0                                        [G] (39)
/// ```
pub fn never_slips(u_s_minus: f64, k: f64, zeta0: f64, delta0: f64, w_s: f64) -> bool {
    delta0 > zeta0 && u_s_minus * k * (delta0 - zeta0) >= w_s
}

/// The sleeve can be held somewhere in the negative lobe:  u_s^(+) η ≥ 1            [D] §3.2
pub fn held_in_negative_lobe(u_s_plus: f64, eta: f64) -> bool {
    u_s_plus * eta >= 1.0
}

// ---------------------------------------------------------------------------------------------
// One phase (§3.3; §3.4 by the swap)

/// Zero of F_e in phase I (s):   t0^(I) = τ (1 + δ0/ζ0)                             [P] (40)
pub fn t_zero_1(tau: f64, zeta0: f64, delta0: f64) -> Option<f64> {
    Some(tau * (1.0 + div(delta0, zeta0)?))
}

/// Zero of F_e in phase II (s):  t0^(II) = τ (3 − δ0/ζ0) = 4τ − t0^(I)              [P] (57)
pub fn t_zero_2(tau: f64, zeta0: f64, delta0: f64) -> Option<f64> {
    Some(4.0 * tau - t_zero_1(tau, zeta0, delta0)?)
}

/// Time from the slip onset to the zero of F_e (s):
/// ```text
/// Δ = τ W_S/(k ζ0 U)          Δ^(I): U = u_s^(−) [G] (42);   Δ^(II): U = u_s^(+) [G] (59)
/// ```
pub fn delta(tau: f64, w_s: f64, k: f64, zeta0: f64, u_s: f64) -> Option<f64> {
    div(tau * w_s, k * zeta0 * u_s)
}

/// Slip time (s), where |F_e| = W_S/U:
/// ```text
/// t_SL = t0 − Δ               phase I [P] (41);   phase II [P] (58)
/// ```
pub fn t_slip(t0: f64, delta: f64) -> f64 {
    t0 - delta
}

/// Acceleration just after the slip onset (m/s²):
/// ```text
/// a_SL = g (U − u_A)/U        phase I: 2λg(μs − μd)/(2λμs − 1) [G] (45);
///                             phase II: 2λg(μs − μd)/(2λμs + 1) [G] (64)
/// ```
pub fn a_slip(g: f64, u_s: f64, u_a: f64) -> Option<f64> {
    Some(g * div(u_s - u_a, u_s)?)
}

/// Time of the speed maximum, where a = 0 in lobe B (s); `None` when u_B ≤ 0 (no maximum):
/// ```text
/// t_M = t0 + Δ U/u_B          phase I [G] (46);   phase II [G] (62)
/// ```
pub fn t_max_speed(t0: f64, delta: f64, u_s: f64, u_b: f64) -> Option<f64> {
    positive(u_b)?;
    Some(t0 + delta * div(u_s, u_b)?)
}

/// Maximum speed (m/s); `None` when u_B ≤ 0:
/// ```text
/// v_M = ½ g Δ [u_B (2U − u_A) + U²] / (U u_B)      phase I [G] (48);   phase II [G] (63)
/// ```
pub fn v_max(g: f64, delta: f64, u_s: f64, u_a: f64, u_b: f64) -> Option<f64> {
    positive(u_b)?;
    Some(0.5 * g * delta * div(u_b * (2.0 * u_s - u_a) + u_s * u_s, u_s * u_b)?)
}

/// Stick time in units of Δ after t0 (dimensionless); `None` when u_B ≤ 0 or the root is complex:
/// ```text
/// S = [U + √(U² + 2U u_B − u_A u_B)] / u_B         S^(I) [G] (50);   S^(II) [G] (61)
/// ```
pub fn s_factor(u_s: f64, u_a: f64, u_b: f64) -> Option<f64> {
    positive(u_b)?;
    let root = sqrt(u_s * u_s + 2.0 * u_s * u_b - u_a * u_b)?;
    div(u_s + root, u_b)
}

/// Stick time (s), valid as the paper's stick when t_ST ≤ 2τ (phase I) or ≤ 4τ (phase II):
/// ```text
/// t_ST = t0 + Δ S             phase I [G] (49);   phase II [G] (60)
/// ```
pub fn t_stick(t0: f64, delta: f64, s: f64) -> f64 {
    t0 + delta * s
}

/// Critical dynamic coefficient for a stick before the end of the half period (dimensionless):
/// ```text
/// μd,MIN = (1/(2λ)) [U² h_B (2 − σ h_B) + 2U + σ] / [U² h_B² + 1]
///   phase I  (U, h_B, σ) = (u_s^(−), η, +1):  [u_s^(−)² η (2 − η) + 2u_s^(−) + 1]/…   [G] (51)
///   phase II (U, h_B, σ) = (u_s^(+), η', −1): [u_s^(+)² η' (η' + 2) + 2u_s^(+) − 1]/… [G] (65)
/// t_ST ≤ end of half period ⇔ u_B ≥ max(2λ μd,MIN + σ, 1/h_B)
/// ```
pub fn mu_d_min(lambda: f64, u_s: f64, h_b: f64, sigma: f64) -> Option<f64> {
    let num = u_s * u_s * h_b * (2.0 - sigma * h_b) + 2.0 * u_s + sigma;
    div(num, 2.0 * lambda * (u_s * u_s * h_b * h_b + 1.0))
}

/// Least u_B for which the slip halts in lobe B (rising or falling flank), dimensionless:
/// ```text
/// u_B ≥ max(x₊, 1/h_B),  x₊ = [B + √(B² − A U²)]/A,  A = 1 + 2h_B²U²,  B = U + σ + 2h_B U²
/// ```
/// (Equivalent to 2 v_ext(end of the rising flank) ≤ v_M.) When B² < A U² the quadratic has no
/// real root, so every u_B ≥ 1/h_B halts.                                               [D] §3.6
pub fn halt_threshold(u_s: f64, h_b: f64, sigma: f64) -> Option<f64> {
    let a = 1.0 + 2.0 * h_b * h_b * u_s * u_s;
    let b = u_s + sigma + 2.0 * h_b * u_s * u_s;
    let floor = div(1.0, h_b)?;
    match sqrt(b * b - a * u_s * u_s) {
        Some(root) => Some(div(b + root, a)?.max(floor)),
        None => Some(floor),
    }
}

/// Exact least μd for a halt in lobe B (dimensionless):
/// ```text
/// μd,HALT = (max(x₊, 1/h_B) − σ)/(2λ)
///   phase I:  halt before the phase-II slip,  (max(x₊, 1/η) − 1)/(2λ)                [D] §3.6
///   phase II: halt before the next phase-I slip, (max(x'₊, 1/η') + 1)/(2λ)           [D] §3.6
/// ```
pub fn mu_d_halt(lambda: f64, u_s: f64, h_b: f64, sigma: f64) -> Option<f64> {
    div(halt_threshold(u_s, h_b, sigma)? - sigma, 2.0 * lambda)
}

/// Γ of one phase (dimensionless):
/// ```text
/// Γ = [3U (S + 1)² − u_B S³ − 3u_A S − 2u_A] / U³       Γ^(I) [P*] (54);   Γ^(II) [P*] (70)
/// ```
pub fn gamma_phase(u_s: f64, u_a: f64, u_b: f64, s: f64) -> Option<f64> {
    let num = 3.0 * u_s * (s + 1.0).powi(2) - u_b * s.powi(3) - 3.0 * u_a * s - 2.0 * u_a;
    div(num, u_s.powi(3))
}

/// Distance slipped for a given Γ (m): one phase with Γ^(I) or Γ^(II), a period with Γ:
/// ```text
/// y = g τ² W_S² Γ / (6 ζ0² k²)        y^(I) [P] (55);  y^(II) [P] (68);  y_S(T) [P] (68),(69)
/// ```
pub fn distance(g: f64, tau: f64, w_s: f64, k: f64, zeta0: f64, gamma: f64) -> Option<f64> {
    div(
        g * tau * tau * w_s * w_s * gamma,
        6.0 * zeta0 * zeta0 * k * k,
    )
}

/// Mean speed of one slip (m/s), over its duration t_ST − t_SL = Δ (S + 1):
/// ```text
/// v̄^(I) = y^(I)/(Δ^(I)(S^(I) + 1)) = g τ W_S u_s^(−) Γ^(I)/(6 k ζ0 (S^(I)+1))      [P] (53)
/// ```
/// (normalization of the printed form uncertain, physics.md; phase II by the swap [D]).
pub fn v_avg_slip(distance: f64, delta: f64, s: f64) -> Option<f64> {
    div(distance, delta * (s + 1.0))
}

/// Mean speed of the sleeve over a period in the standard regime (m/s):
/// ```text
/// v̄ = y_S(T)/(4τ) = g τ W_S² Γ / (24 ζ0² k²),   Γ = Γ^(I) + Γ^(II)                  [P] (71)
/// ```
pub fn v_avg(g: f64, tau: f64, w_s: f64, k: f64, zeta0: f64, gamma: f64) -> Option<f64> {
    div(g * tau * w_s * w_s * gamma, 24.0 * zeta0 * zeta0 * k * k)
}

/// Power of the sleeve weight (W):   P_W = W_S v̄ = g τ W_S³ Γ/(24 ζ0² k²)     [P] text after (71)
pub fn power_weight(w_s: f64, v_avg: f64) -> f64 {
    w_s * v_avg
}

/// Triangle spring coordinate (m), period 4τ:
/// ```text
/// ζ(t) = ζ0 (1 − t/τ) on [0, 2τ],   ζ0 (t/τ − 3) on [2τ, 4τ]                        [P] (37)
/// ```
pub fn spring_coordinate(t: f64, tau: f64, zeta0: f64) -> Option<f64> {
    let phase = div(t, tau)?.rem_euclid(4.0);
    Some(
        zeta0
            * if phase <= 2.0 {
                1.0 - phase
            } else {
                phase - 3.0
            },
    )
}

/// Woodpecker position (m, downward):   y_W(t) = y_S(t) + ζ(t)                        [P] (56)
pub fn woodpecker_position(y_s: f64, t: f64, tau: f64, zeta0: f64) -> Option<f64> {
    Some(y_s + spring_coordinate(t, tau, zeta0)?)
}

fn positive(x: f64) -> Option<()> {
    (x > 0.0).then_some(())
}

/// Acceleration, speed and position of one slip from rest, t_SL ≤ t ≤ t_ST (SI), with
/// (U, u_A, u_B) the factors of the phase (module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SlipKinematics {
    pub g: f64,
    /// Zero of F_e, t0 (s).
    pub t0: f64,
    /// Δ = t0 − t_SL (s).
    pub delta: f64,
    pub u_s: f64,
    pub u_a: f64,
    pub u_b: f64,
}

impl SlipKinematics {
    /// `None` unless Δ and U are finite and non-zero (every formula divides by both).
    pub fn new(g: f64, t0: f64, delta: f64, u_s: f64, u_a: f64, u_b: f64) -> Option<Self> {
        let ok = [g, t0, delta, u_s, u_a, u_b].iter().all(|x| x.is_finite());
        (ok && delta != 0.0 && u_s != 0.0).then_some(SlipKinematics {
            g,
            t0,
            delta,
            u_s,
            u_a,
            u_b,
        })
    }

    /// Acceleration (m/s²):
    /// ```text
    /// a = g [1 + (u_A/U)(t − t0)/Δ]  (t ≤ t0),   g [1 − (u_B/U)(t − t0)/Δ]  (t ≥ t0)
    ///                                      phase I [G] (43); phase II by the swap
    /// ```
    pub fn acceleration(&self, t: f64) -> f64 {
        let x = (t - self.t0) / self.delta;
        let u = if x <= 0.0 { -self.u_a } else { self.u_b };
        self.g * (1.0 - u / self.u_s * x)
    }

    /// Speed (m/s):
    /// ```text
    /// t ≤ t0:  v = g (t − t_SL) [1 + (u_A/(2U)) ((t − t0)/Δ − 1)]
    /// t ≥ t0:  v = g Δ (2U − u_A)/(2U) + g (t − t0) − g u_B (t − t0)²/(2UΔ)
    ///                                      phase I [G] (47);  phase II [G] (67)
    /// ```
    pub fn speed(&self, t: f64) -> f64 {
        let (g, d, us) = (self.g, self.delta, self.u_s);
        let s = t - self.t0;
        if s <= 0.0 {
            g * (s + d) * (1.0 + self.u_a / (2.0 * us) * (s / d - 1.0))
        } else {
            g * d * (2.0 * us - self.u_a) / (2.0 * us) + g * s
                - g * self.u_b * s * s / (2.0 * us * d)
        }
    }

    /// Distance since the slip onset (m):
    /// ```text
    /// t ≤ t0:  y = a2 (t − t_SL)² + a3 (t − t_SL)³,      a2 = a_SL/2,  a3 = g u_A/(6UΔ)
    /// t ≥ t0:  y = b0 + b1 s + b2 s² + b3 s³,  s = t − t0,
    ///          b0 = gΔ²(3U − 2u_A)/(6U), b1 = gΔ(2U − u_A)/(2U), b2 = g/2, b3 = −g u_B/(6UΔ)
    ///                                      [D] coefficients of (52)
    /// ```
    pub fn position(&self, t: f64) -> f64 {
        let (g, d, us, ua) = (self.g, self.delta, self.u_s, self.u_a);
        let s = t - self.t0;
        if s <= 0.0 {
            let w = s + d;
            let a2 = 0.5 * g * (us - ua) / us;
            let a3 = g * ua / (6.0 * us * d);
            a2 * w * w + a3 * w.powi(3)
        } else {
            let b0 = g * d * d * (3.0 * us - 2.0 * ua) / (6.0 * us);
            let b1 = g * d * (2.0 * us - ua) / (2.0 * us);
            let b3 = -g * self.u_b / (6.0 * us * d);
            b0 + b1 * s + 0.5 * g * s * s + b3 * s.powi(3)
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Evaluation of every closed form (§7 keys)

/// Half period in which a slip starts: I (F_e decreasing) or II (F_e increasing).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Phase {
    #[serde(rename = "I")]
    One,
    #[serde(rename = "II")]
    Two,
}

impl Phase {
    /// The other half period.
    pub fn other(self) -> Phase {
        match self {
            Phase::One => Phase::Two,
            Phase::Two => Phase::One,
        }
    }
}

/// All closed forms of one phase (SI; dimensionless for s, mu_*, gamma). `None` where the
/// expression is undefined.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct PhaseClosedForm {
    pub t0: Option<f64>,
    pub delta: Option<f64>,
    pub t_slip: Option<f64>,
    pub a_slip: Option<f64>,
    pub t_max_speed: Option<f64>,
    pub v_max: Option<f64>,
    pub s: Option<f64>,
    pub t_stick: Option<f64>,
    pub mu_d_min: Option<f64>,
    pub mu_d_halt: Option<f64>,
    pub gamma: Option<f64>,
    pub distance: Option<f64>,
    pub v_avg_slip: Option<f64>,
}

/// Evaluates one phase from its oriented groups (phase II: `groups.swapped()`) and its t0.
pub fn phase_closed_form(p: &LinearWoodpecker, gr: &Groups, t0: Option<f64>) -> PhaseClosedForm {
    let (us, ua, ub) = (gr.u_s_minus, gr.u_d_minus, gr.u_d_plus);
    let delta = delta(p.tau_quarter, p.w_s, p.k, p.zeta0, us);
    let s = s_factor(us, ua, ub);
    let gamma = s.and_then(|s| gamma_phase(us, ua, ub, s));
    let dist = gamma.and_then(|gm| distance(p.g, p.tau_quarter, p.w_s, p.k, p.zeta0, gm));
    let both = |a: Option<f64>, b: Option<f64>| a.zip(b);
    PhaseClosedForm {
        t0,
        delta,
        t_slip: both(t0, delta).and_then(|(t0, d)| finite(t_slip(t0, d))),
        a_slip: a_slip(p.g, us, ua),
        t_max_speed: both(t0, delta).and_then(|(t0, d)| t_max_speed(t0, d, us, ub)),
        v_max: delta.and_then(|d| v_max(p.g, d, us, ua, ub)),
        s,
        t_stick: both(t0, delta)
            .zip(s)
            .and_then(|((t0, d), s)| finite(t_stick(t0, d, s))),
        mu_d_min: gr.eta.and_then(|h| mu_d_min(p.lambda, us, h, gr.sigma)),
        mu_d_halt: gr.eta.and_then(|h| mu_d_halt(p.lambda, us, h, gr.sigma)),
        gamma,
        distance: dist,
        v_avg_slip: both(dist, delta)
            .zip(s)
            .and_then(|((y, d), s)| v_avg_slip(y, d, s)),
    }
}

/// Regime of the periodic orbit of the linear model (§3.6, orbit selection).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
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

/// One slip of the periodic orbit (SI). Times are measured from the start of the period in which
/// the slip starts (0 ≤ t_slip < T) and are not reduced mod T: a halt may come after T (every
/// phase-II slip that halts in A/A_late or B_late, and phase-I slips that halt in A_late).
#[derive(Clone, Debug, PartialEq, Serialize)]
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

/// The period-T orbit of the linear model (§3.6), SI.
#[derive(Clone, Debug, PartialEq, Serialize)]
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

/// The closed forms of the linearized woodpecker, keyed as `closed_form` of physics.md §7.
/// Suffix `_1` = phase I, `_2` = phase II. `None` (JSON null) where the expression is undefined;
/// formulas are evaluated even outside the regime in which they describe the motion.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct WoodpeckerClosedForm {
    pub zeta0: Option<f64>,
    pub delta0: Option<f64>,
    pub tau_quarter: Option<f64>,
    pub u_s_minus: Option<f64>,
    pub u_s_plus: Option<f64>,
    pub u_d_minus: Option<f64>,
    pub u_d_plus: Option<f64>,
    pub eta: Option<f64>,
    pub eta_prime: Option<f64>,
    pub immediate_slip: bool,
    pub t0_1: Option<f64>,
    pub delta_1: Option<f64>,
    pub t_slip_1: Option<f64>,
    pub a_slip_1: Option<f64>,
    pub t_max_speed_1: Option<f64>,
    pub v_max_1: Option<f64>,
    pub s_1: Option<f64>,
    pub t_stick_1: Option<f64>,
    pub mu_d_min_1: Option<f64>,
    pub mu_d_halt_1: Option<f64>,
    pub gamma_1: Option<f64>,
    pub distance_1: Option<f64>,
    pub t0_2: Option<f64>,
    pub delta_2: Option<f64>,
    pub t_slip_2: Option<f64>,
    pub a_slip_2: Option<f64>,
    pub t_max_speed_2: Option<f64>,
    pub v_max_2: Option<f64>,
    pub s_2: Option<f64>,
    pub t_stick_2: Option<f64>,
    pub mu_d_min_2: Option<f64>,
    pub mu_d_halt_2: Option<f64>,
    pub gamma_2: Option<f64>,
    pub distance_2: Option<f64>,
    pub gamma: Option<f64>,
    pub distance_per_period: Option<f64>,
    /// (71), evaluated wherever its expression is defined.
    pub v_avg: Option<f64>,
    pub power_weight: Option<f64>,
    pub paper_regime_valid: bool,
    pub regime: OrbitRegime,
    pub orbit_v_avg: Option<f64>,
    pub orbit_distance_per_period: Option<f64>,
    /// Mean speed of slip I (53) and its phase-II analogue (m/s); not a §7 key.
    #[serde(skip)]
    pub v_avg_slip_1: Option<f64>,
    #[serde(skip)]
    pub v_avg_slip_2: Option<f64>,
    /// Where the lobe engine of each phase halts (`None`: no halt, or the slip cannot start from
    /// rest in that phase); not a §7 key.
    #[serde(skip)]
    pub halt_1: Option<HaltKind>,
    #[serde(skip)]
    pub halt_2: Option<HaltKind>,
    /// The periodic orbit (SI) for checks against the integrator; not a §7 key.
    #[serde(skip)]
    pub orbit: Option<Orbit>,
}

/// Evaluates every closed form of §3.2–3.6 for `p`.
pub fn evaluate(p: &LinearWoodpecker) -> WoodpeckerClosedForm {
    let gr = Groups::new(p);
    let t0_1 = t_zero_1(p.tau_quarter, p.zeta0, p.delta0);
    let t0_2 = t_zero_2(p.tau_quarter, p.zeta0, p.delta0);
    let ph1 = phase_closed_form(p, &gr, t0_1);
    let ph2 = phase_closed_form(p, &gr.swapped(), t0_2);
    let gamma = ph1.gamma.zip(ph2.gamma).map(|(a, b)| a + b);
    let (g, tau, w_s, k, zeta0) = (p.g, p.tau_quarter, p.w_s, p.k, p.zeta0);
    let v_avg = gamma.and_then(|gm| v_avg(g, tau, w_s, k, zeta0, gm));
    let immediate = immediate_slip(gr.u_s_minus, k, zeta0, p.delta0, w_s);
    let engines = PhaseEngines::run(p, &gr, t0_1, t0_2);
    let (regime, orbit) = steady_orbit(p, &gr, immediate, &engines);
    WoodpeckerClosedForm {
        zeta0: finite(p.zeta0),
        delta0: finite(p.delta0),
        tau_quarter: finite(p.tau_quarter),
        u_s_minus: finite(gr.u_s_minus),
        u_s_plus: finite(gr.u_s_plus),
        u_d_minus: finite(gr.u_d_minus),
        u_d_plus: finite(gr.u_d_plus),
        eta: gr.eta,
        eta_prime: gr.eta_prime,
        immediate_slip: immediate,
        t0_1: ph1.t0,
        delta_1: ph1.delta,
        t_slip_1: ph1.t_slip,
        a_slip_1: ph1.a_slip,
        t_max_speed_1: ph1.t_max_speed,
        v_max_1: ph1.v_max,
        s_1: ph1.s,
        t_stick_1: ph1.t_stick,
        mu_d_min_1: ph1.mu_d_min,
        mu_d_halt_1: ph1.mu_d_halt,
        gamma_1: ph1.gamma,
        distance_1: ph1.distance,
        t0_2: ph2.t0,
        delta_2: ph2.delta,
        t_slip_2: ph2.t_slip,
        a_slip_2: ph2.a_slip,
        t_max_speed_2: ph2.t_max_speed,
        v_max_2: ph2.v_max,
        s_2: ph2.s,
        t_stick_2: ph2.t_stick,
        mu_d_min_2: ph2.mu_d_min,
        mu_d_halt_2: ph2.mu_d_halt,
        gamma_2: ph2.gamma,
        distance_2: ph2.distance,
        gamma,
        distance_per_period: gamma.and_then(|gm| distance(g, tau, w_s, k, zeta0, gm)),
        v_avg,
        power_weight: v_avg.map(|v| power_weight(w_s, v)),
        paper_regime_valid: paper_regime_valid(p, &gr, immediate, &ph1, &ph2),
        regime,
        orbit_v_avg: orbit.as_ref().and_then(|o| finite(o.v_avg)),
        orbit_distance_per_period: orbit.as_ref().and_then(|o| finite(o.distance_per_period)),
        v_avg_slip_1: ph1.v_avg_slip,
        v_avg_slip_2: ph2.v_avg_slip,
        halt_1: engines.halt_kind(Phase::One),
        halt_2: engines.halt_kind(Phase::Two),
        orbit,
    }
}

/// Closed-form domain (§3.1): 0 ≤ δ0 < ζ0, u_s^(−) > 0, μd ≤ μs; plus k, W_S, ζ0, τ > 0 so that
/// the lobes and the time unit exist.
pub fn in_closed_form_domain(p: &LinearWoodpecker) -> bool {
    let positive = [p.k, p.w_s, p.zeta0, p.tau_quarter, p.lambda, p.g]
        .iter()
        .all(|&x| x.is_finite() && x > 0.0);
    positive
        && (0.0..p.zeta0).contains(&p.delta0)
        && u_minus(p.lambda, p.mu_s) > 0.0
        && p.mu_d <= p.mu_s
}

/// The paper's standard regime (§3.5): 0 ≤ δ0 < ζ0, u_s^(−) > 0, μd ≤ μs, not immediate,
/// t_SL^(I) ≥ 0, t_ST^(I) ≤ 2τ, u_d^(−) > 0, t_ST^(II) ≤ 4τ.
fn paper_regime_valid(
    p: &LinearWoodpecker,
    gr: &Groups,
    immediate: bool,
    ph1: &PhaseClosedForm,
    ph2: &PhaseClosedForm,
) -> bool {
    let tau = p.tau_quarter;
    in_closed_form_domain(p)
        && !immediate
        && ph1.t_slip.is_some_and(|t| t >= 0.0)
        && ph1.t_stick.is_some_and(|t| t <= 2.0 * tau)
        && gr.u_d_minus > 0.0
        && ph2.t_stick.is_some_and(|t| t <= 4.0 * tau)
}

// ---------------------------------------------------------------------------------------------
// Periodic orbit (§3.6)

/// The lobe engine of each phase, with what is needed to put its slip in SI units.
struct PhaseEngines {
    one: Option<SiSlip>,
    two: Option<SiSlip>,
}

/// A lobe-engine slip with its time origin t_zero and time unit τε (s).
struct SiSlip {
    phase: Phase,
    slip: LobeSlip,
    t_zero: f64,
    unit: f64,
    g: f64,
}

impl PhaseEngines {
    fn run(p: &LinearWoodpecker, gr: &Groups, t0_1: Option<f64>, t0_2: Option<f64>) -> Self {
        let unit = time_unit(p.tau_quarter, p.w_s, p.k, p.zeta0);
        let engine = |phase: Phase, gr: &Groups, t_zero: Option<f64>| {
            let slip = lobe::lobe_engine(
                gr.u_s_minus,
                gr.u_d_minus,
                gr.u_d_plus,
                gr.eta_prime?,
                gr.eta?,
            )?;
            Some(SiSlip {
                phase,
                slip,
                t_zero: t_zero?,
                unit: unit?,
                g: p.g,
            })
        };
        PhaseEngines {
            one: engine(Phase::One, gr, t0_1),
            two: engine(Phase::Two, &gr.swapped(), t0_2),
        }
    }

    fn get(&self, phase: Phase) -> Option<&SiSlip> {
        match phase {
            Phase::One => self.one.as_ref(),
            Phase::Two => self.two.as_ref(),
        }
    }

    fn halt_kind(&self, phase: Phase) -> Option<HaltKind> {
        Some(self.get(phase)?.slip.halt?.kind)
    }
}

impl SiSlip {
    fn time(&self, theta: f64) -> f64 {
        self.t_zero + theta * self.unit
    }

    /// The slip in SI units, if it halts.
    fn orbit_slip(&self) -> Option<OrbitSlip> {
        let halt = self.slip.halt?;
        let speed_unit = self.g * self.unit;
        Some(OrbitSlip {
            phase: self.phase,
            halt: halt.kind,
            t_slip: self.time(self.slip.theta_slip),
            t_halt: self.time(halt.theta),
            speed_maxima: (self.slip.maxima.iter())
                .map(|&(theta, v)| (self.time(theta), v * speed_unit))
                .collect(),
            distance: halt.distance * speed_unit * self.unit,
        })
    }
}

/// Orbit selection from the initial state (stuck at t = 0), §3.6. After a halt in lobe B the
/// next slip is the ordinary slip of the other phase; after a merged halt (lobe A) it is the
/// ordinary slip of the same phase one period later. Immediate slip (38) makes the first period
/// a transient that ends stuck in the negative lobe if anything does, so the steady orbit then
/// starts from the phase-II slip.
fn steady_orbit(
    p: &LinearWoodpecker,
    gr: &Groups,
    immediate: bool,
    engines: &PhaseEngines,
) -> (OrbitRegime, Option<Orbit>) {
    if never_slips(gr.u_s_minus, p.k, p.zeta0, p.delta0, p.w_s) {
        return (OrbitRegime::NoSlip, Some(orbit_of(p, Vec::new())));
    }
    if !in_closed_form_domain(p) {
        return (OrbitRegime::OutsideClosedFormDomain, None);
    }
    let first = if immediate { Phase::Two } else { Phase::One };
    let Some(slips) = periodic_slips(engines, first) else {
        return (OrbitRegime::ContinuousOrMultiperiod, None);
    };
    let regime = match slips.as_slice() {
        [merged] if merged.speed_maxima.len() >= 2 => OrbitRegime::DoubleSlipNoHalt,
        [_] => OrbitRegime::SingleSlipStick,
        _ => OrbitRegime::DoubleSlipStick,
    };
    (regime, Some(orbit_of(p, slips)))
}

/// The slips of the periodic orbit reached from the slip of phase `first`, in order of slip time;
/// `None` when a slip on the way never halts.
fn periodic_slips(engines: &PhaseEngines, first: Phase) -> Option<Vec<OrbitSlip>> {
    let a = engines.get(first)?.orbit_slip()?;
    if a.halt.is_merged() {
        return Some(vec![a]);
    }
    let b = engines.get(first.other())?.orbit_slip()?;
    if b.halt.is_merged() {
        return Some(vec![b]);
    }
    let mut both = vec![a, b];
    both.sort_by(|x, y| x.t_slip.total_cmp(&y.t_slip));
    Some(both)
}

fn orbit_of(p: &LinearWoodpecker, slips: Vec<OrbitSlip>) -> Orbit {
    let distance_per_period: f64 = slips.iter().map(|s| s.distance).sum();
    // A sleeve at rest advances 0 per period, whatever T is.
    let v_avg = match slips.is_empty() {
        true => 0.0,
        false => distance_per_period / p.period(),
    };
    Orbit {
        slips,
        period: p.period(),
        distance_per_period,
        v_avg,
    }
}
