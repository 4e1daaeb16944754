//! Force laws as data: a period tiled by pieces on which the driving force D and the
//! friction-bearing normal force N_f are affine in one basis function b(t).

use crate::fmath;
use serde::Serialize;

use crate::error::{Error, Result};

/// The basis function b(t) of a piece; t is the time within the period (s). Serialized as
/// `{"kind": "linear", "t_ref": …}` or `{"kind": "cos", "omega": …, "shift": …}`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Basis {
    /// b(t) = t − t_ref (s): the triangle-wave (linearized) laws.
    Linear { t_ref: f64 },
    /// b(t) = cos ωt − shift (ω in rad/s): the harmonic laws. A force that vanishes where
    /// cos ωt = C is written as c1·(cos ωt − C) with shift C, so that what is added to it (the
    /// sleeve's weight) is a coefficient of its own, not the rounding of a sum with k z0.
    Cos { omega: f64, shift: f64 },
}

impl Basis {
    /// b(t) at time t within the period.
    #[inline]
    pub fn eval(&self, t: f64) -> f64 {
        match *self {
            Basis::Linear { t_ref } => t - t_ref,
            Basis::Cos { omega, shift } => fmath::cos(omega * t) - shift,
        }
    }

    /// The shift of a cos basis (b = cos ωt − shift), 0 on a linear one.
    #[inline]
    pub fn shift(&self) -> f64 {
        match *self {
            Basis::Linear { .. } => 0.0,
            Basis::Cos { shift, .. } => shift,
        }
    }
}

/// An affine function of the basis, c0 + c1·b(t) (units of the quantity it stands for).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Affine {
    pub c0: f64,
    pub c1: f64,
}

impl Affine {
    pub const fn new(c0: f64, c1: f64) -> Self {
        Self { c0, c1 }
    }

    /// Value at basis value b.
    #[inline]
    pub fn at(&self, b: f64) -> f64 {
        self.c0 + self.c1 * b
    }

    /// a·self + c·other.
    #[inline]
    pub fn combine(a: f64, x: Affine, c: f64, y: Affine) -> Affine {
        Affine::new(a * x.c0 + c * y.c0, a * x.c1 + c * y.c1)
    }
}

/// One piece of a force law, on [start, end) within the period (s).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Piece {
    pub start: f64,
    pub end: f64,
    pub basis: Basis,
    /// Driving force D along the motion axis (N).
    pub drive: Affine,
    /// Friction-bearing normal force N_f ≥ 0 (N).
    pub normal: Affine,
}

impl Piece {
    /// D(t) (N).
    pub fn drive_at(&self, t: f64) -> f64 {
        self.drive.at(self.basis.eval(t))
    }

    /// N_f(t) (N).
    pub fn normal_at(&self, t: f64) -> f64 {
        self.normal.at(self.basis.eval(t))
    }

    /// An interval [b_min, b_max] that holds b(t) for t in [start − before, end], b computed in
    /// floating point included: the exact range widened by |db/dt|·`before` and a few ulps.
    pub fn basis_range(&self, before: f64) -> (f64, f64) {
        let cos_ends = match self.basis {
            Basis::Linear { .. } => (0.0, 0.0),
            Basis::Cos { omega, .. } => {
                (fmath::cos(omega * self.start), fmath::cos(omega * self.end))
            }
        };
        self.basis_range_from(before, cos_ends)
    }

    /// [`Piece::basis_range`] from cos(ω·start) and cos(ω·end) (the doubles ω·start and ω·end,
    /// as [`fmath::cos`] gives them) on a cos basis, where they are known (a run prepares its
    /// pieces in order, and one's end is the next one's start); unused on a linear basis.
    #[inline]
    pub fn basis_range_from(&self, before: f64, (b_start, b_end): (f64, f64)) -> (f64, f64) {
        let (lo, hi, rate) = match self.basis {
            Basis::Linear { t_ref } => (self.start - t_ref, self.end - t_ref, 1.0),
            Basis::Cos { omega, shift } => {
                let (theta_start, theta_end) = (omega * self.start, omega * self.end);
                // cos θ = ±1 at θ = kπ inside: +1 for even k, −1 for odd k.
                let pi = std::f64::consts::PI;
                let (k_first, k_last) = ((theta_start / pi).ceil(), (theta_end / pi).floor());
                // k_first mod 2 (0 or 1, NaN for NaN and ±∞), as k_first.rem_euclid(2.0) but
                // without fmod: doubles from 2^53 on are even integers.
                let k_first_mod_2 = if k_first.abs() < 9_007_199_254_740_992.0 {
                    ((k_first as i64) & 1) as f64
                } else if k_first.is_finite() {
                    0.0
                } else {
                    f64::NAN
                };
                let has = |parity: f64| {
                    let k = if k_first_mod_2 == parity {
                        k_first
                    } else {
                        k_first + 1.0
                    };
                    k <= k_last
                };
                let lo = if has(1.0) { -1.0 } else { b_start.min(b_end) };
                let hi = if has(0.0) { 1.0 } else { b_start.max(b_end) };
                (lo - shift, hi - shift, omega.abs())
            }
        };
        let widen = rate * before + 4.0 * f64::EPSILON * lo.abs().max(hi.abs()).max(1.0);
        (lo - widen, hi + widen)
    }
}

/// A periodic force law: pieces tiling [0, period).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ForceLaw {
    /// Period T (s).
    pub period: f64,
    pub pieces: Vec<Piece>,
}

impl ForceLaw {
    /// Checks that the pieces are finite and tile [0, period) in order.
    pub fn new(period: f64, pieces: Vec<Piece>) -> Result<Self> {
        if !(period.is_finite() && period > 0.0) {
            return Err(Error::InvalidLaw(format!(
                "period {period} s must be finite and > 0"
            )));
        }
        let mut expected = 0.0;
        for p in &pieces {
            let finite = [
                p.start,
                p.end,
                p.drive.c0,
                p.drive.c1,
                p.normal.c0,
                p.normal.c1,
            ]
            .iter()
            .all(|c| c.is_finite());
            if !finite || p.start != expected || p.end <= p.start {
                return Err(Error::InvalidLaw(format!(
                    "piece [{}, {}) does not continue the tiling at {expected} s",
                    p.start, p.end
                )));
            }
            expected = p.end;
        }
        if pieces.is_empty() || expected != period {
            return Err(Error::InvalidLaw(format!(
                "pieces end at {expected} s, not at the period {period} s"
            )));
        }
        Ok(Self { period, pieces })
    }

    /// The piece containing time t (absolute, s); t is reduced modulo the period.
    pub fn piece_at(&self, t: f64) -> &Piece {
        let local = t.rem_euclid(self.period);
        let i = self.pieces.partition_point(|p| p.end <= local);
        &self.pieces[i.min(self.pieces.len() - 1)]
    }

    /// D(t) at absolute time t (N).
    pub fn drive(&self, t: f64) -> f64 {
        self.piece_at(t).drive_at(t.rem_euclid(self.period))
    }

    /// N_f(t) at absolute time t (N).
    pub fn normal(&self, t: f64) -> f64 {
        self.piece_at(t).normal_at(t.rem_euclid(self.period))
    }
}

/// The body: inertial mass and friction coefficients.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Body {
    /// Inertial mass M (kg).
    pub mass: f64,
    /// Static friction coefficient μs.
    pub mu_s: f64,
    /// Dynamic friction coefficient μd ≤ μs.
    pub mu_d: f64,
}

impl Body {
    /// Acceleration while slipping (m/s²), from Newton's law M dv/dt = D − s μd N_f:
    ///
    /// ```text
    /// a = (D − s·μd·N_f) / M
    /// ```
    ///
    /// `drive` is D (N), positive along the motion axis; `normal` is N_f ≥ 0 (N); `s` = ±1 is
    /// the direction of slip (the sign of v), so that kinetic friction −s·μd·N_f opposes the
    /// motion.
    #[inline]
    pub fn slip_acceleration(&self, drive: f64, normal: f64, s: f64) -> f64 {
        (drive - s * self.mu_d * normal) / self.mass
    }

    /// [`Body::slip_acceleration`] on a piece where D and N_f are affine in b(t): the same
    /// a = (D − s·μd·N_f)/M (m/s²), linear in (D, N_f), formed on the coefficients as
    /// (1/M)·D_i + (−s·μd/M)·N_i. Evaluated at b(t) it agrees with the pointwise form to
    /// rounding, not bit for bit. The engine takes only its slope c1 from here: an arc starts
    /// from the pointwise acceleration (or, at a slip onset, from the cancellation-free form of
    /// run.rs), because A0 + A1·b is a difference of O(μd g) terms.
    #[inline]
    pub fn slip_acceleration_affine(&self, drive: Affine, normal: Affine, s: f64) -> Affine {
        Affine::combine(1.0 / self.mass, drive, -s * self.mu_d / self.mass, normal)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slip_acceleration_opposes_the_direction_of_slip() {
        // M 2 kg, μd 0.25, D 3 N, N_f 4 N: friction is 1 N against the motion.
        let body = Body {
            mass: 2.0,
            mu_s: 0.4,
            mu_d: 0.25,
        };
        assert_eq!(body.slip_acceleration(3.0, 4.0, 1.0), 1.0);
        assert_eq!(body.slip_acceleration(3.0, 4.0, -1.0), 2.0);
        assert_eq!(body.slip_acceleration(-3.0, 4.0, -1.0), -1.0);
        // On coefficients: D = 3 + 0.5 b, N_f = 4 − 2 b.
        let a = body.slip_acceleration_affine(Affine::new(3.0, 0.5), Affine::new(4.0, -2.0), 1.0);
        assert_eq!(a, Affine::new(1.0, 0.5));
    }

    #[test]
    fn basis_range_holds_the_basis_over_the_piece() {
        let omega = 3.0;
        let pieces = [(0.2, 0.9), (0.9, 1.4), (0.0, 2.5), (1.2, 1.3)];
        for (start, end) in pieces {
            for basis in [
                Basis::Cos { omega, shift: 0.0 },
                Basis::Cos { omega, shift: -0.3 },
                Basis::Linear { t_ref: 0.7 },
            ] {
                let piece = Piece {
                    start,
                    end,
                    basis,
                    drive: Affine::new(0.0, 1.0),
                    normal: Affine::new(1.0, 0.0),
                };
                let (lo, hi) = piece.basis_range(0.0);
                let samples = (0..=1000).map(|i| start + (end - start) * f64::from(i) / 1000.0);
                let (min, max) = samples
                    .map(|t| basis.eval(t))
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
                        (a.min(x), b.max(x))
                    });
                assert!(lo <= min && max <= hi, "{basis:?} on [{start}, {end}]");
                // Tight: within the sampling resolution of the extremes.
                assert!(
                    min - lo < 1e-5 && hi - max < 1e-5,
                    "{basis:?} on [{start}, {end}]"
                );
            }
        }
    }

    #[test]
    fn affine_slip_acceleration_agrees_with_the_pointwise_form() {
        let body = Body {
            mass: 0.12,
            mu_s: 0.4,
            mu_d: 0.35,
        };
        let (drive, normal) = (Affine::new(0.1, 0.03), Affine::new(1.1772, -0.7));
        for s in [1.0, -1.0] {
            let a = body.slip_acceleration_affine(drive, normal, s);
            for b in [-1.0, -0.3, 0.0, 0.7, 1.0] {
                let pointwise = body.slip_acceleration(drive.at(b), normal.at(b), s);
                let scale = (drive.at(b).abs() + body.mu_d * normal.at(b).abs()) / body.mass;
                assert!(
                    (a.at(b) - pointwise).abs() <= 8.0 * f64::EPSILON * scale,
                    "s {s}, b {b}: {} vs {pointwise}",
                    a.at(b)
                );
            }
        }
    }
}
