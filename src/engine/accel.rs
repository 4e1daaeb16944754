//! Where the acceleration while slipping changes sign on a piece of the force law.
//!
//! In direction s the acceleration a = (D − s μd N_f)/M depends on time only, not on the state
//! of the body: s·a = h/M with h = s·D − μd·N_f affine in the basis b(t). On a cos basis its
//! zeros on a piece are therefore the same in every period and for every arc, and are located
//! once per run, in two parts as the slip onsets are ([`super::roots::UpCrossings`]): from the
//! coefficients of h formed exactly, so that a zero is known to better than its ulp (an arc's
//! own cos θc − a_c/A1 took the rounding of cos θc, up to 3e-13 of the time of a speed maximum
//! near θ = π). On a linear basis each arc finds its one zero by a division
//! ([`super::arc::ArcMotion::sign_changes`]). The sign of s·a on any stretch of the piece is
//! read off the zeros instead of evaluated (where the rounding of a near a zero could misjudge
//! it).

use super::arc::cos_level_crossings_dd;
use super::dd::Dd;
use super::law::Affine;

/// The zeros of h = c0 + c1 b(t) over the basis' range of time (t − t_ref on a linear basis, one
/// period 2π/ω of cos ωt), ascending, and the sign of h before the first: h changes sign at each
/// zero (a cos basis has two, a linear one at most one).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SignChanges {
    /// The zeros (s), ascending, +∞ for the missing ones.
    zeros: [f64; 2],
    /// The sign (±1) of h before the first zero (everywhere when there is none).
    before: i8,
}

/// The sign (±1) of x from its sign bit; 0 for NaN.
#[inline(always)]
pub fn sign_of(x: f64) -> i8 {
    if x.is_nan() {
        0
    } else if x.is_sign_negative() {
        -1
    } else {
        1
    }
}

impl SignChanges {
    /// Unknown: a placeholder for the pieces whose arcs give their own ([`SignChanges::once`]).
    pub const UNKNOWN: SignChanges = SignChanges {
        zeros: [f64::INFINITY; 2],
        before: 0,
    };

    /// At most one sign change, at `zero` (s) if any, where the sign goes from `before` (±1)
    /// to its opposite.
    #[inline(always)]
    pub fn once(zero: Option<f64>, before: i8) -> SignChanges {
        SignChanges {
            zeros: [zero.unwrap_or(f64::INFINITY), f64::INFINITY],
            before,
        }
    }

    /// The sign changes of h = c0 + c1 (cos ωt − shift) (ω in rad/s), with `h` the rounded
    /// coefficients and `exact` the same in two parts.
    pub fn cos(omega: f64, shift: f64, h: Affine, exact: impl Fn() -> (Dd, Dd)) -> SignChanges {
        // Where the level of cos ωt is beyond ±1 there is no zero, and h keeps the sign it has
        // at cos ωt = 0.
        let none = SignChanges::once(None, sign_of(h.c0 - h.c1 * shift));
        if h.c1 == 0.0 {
            return none;
        }
        let (c0, c1) = exact();
        // The basis value where h = 0, in two parts (cos ωt is ill-conditioned near ±1).
        let root_b = -c0 / c1 + Dd::from(shift);
        // dh/dt = c1·d(cos ωt)/dt: cos ωt falls through the first crossing θ/ω and rises
        // through the second (2π − θ)/ω.
        match cos_level_crossings_dd(root_b, omega, f64::NEG_INFINITY, f64::INFINITY) {
            [Some((first, _)), Some((second, _))] => SignChanges {
                zeros: [first.value(), second.value()],
                before: sign_of(h.c1),
            },
            _ => none,
        }
    }

    /// The sign changes of −h where these are h's and h has two zeros (`None` otherwise): the
    /// same zeros, the opposite signs. [`SignChanges::cos`] of the coefficients of h negated
    /// bit for bit gives the same bits (its arithmetic is symmetric under negation); with no
    /// zero the sign of h may be that of a zero (c0 − c1·shift = +0 for both h and −h), so
    /// that case is not shared.
    #[inline]
    pub fn negated(self) -> Option<SignChanges> {
        self.zeros[1].is_finite().then_some(SignChanges {
            before: -self.before,
            ..self
        })
    }

    /// The zeros, ascending, +∞ for the missing ones.
    #[inline(always)]
    pub fn zeros(&self) -> [f64; 2] {
        self.zeros
    }

    /// The sign of h just after time t: the sign before the first zero, changed at each zero at
    /// or before t.
    #[inline(always)]
    pub fn sign_after(&self, t: f64) -> i8 {
        let crossed = u8::from(self.zeros[0] <= t) + u8::from(self.zeros[1] <= t);
        if crossed % 2 == 0 {
            self.before
        } else {
            -self.before
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn exact(h: Affine) -> impl Fn() -> (Dd, Dd) {
        move || (Dd::from(h.c0), Dd::from(h.c1))
    }

    #[test]
    fn one_sign_change() {
        let changes = SignChanges::once(Some(0.75), -1);
        assert_eq!(changes.zeros(), [0.75, f64::INFINITY]);
        assert_eq!(changes.sign_after(0.7), -1);
        assert_eq!(changes.sign_after(0.75), 1);
        assert_eq!(SignChanges::once(None, -1).sign_after(3.0), -1);
    }

    #[test]
    fn cos_sign_changes_alternate() {
        let omega = 2.0;
        // h = 0.5 − cos 2t: negative until π/6, positive until 5π/6, negative after.
        let h = Affine::new(0.5, -1.0);
        let changes = SignChanges::cos(omega, 0.0, h, exact(h));
        let [z1, z2] = changes.zeros();
        let third = std::f64::consts::FRAC_PI_3;
        assert!((z1 - third / omega).abs() < 1e-15 && (z2 - 5.0 * third / omega).abs() < 1e-15);
        assert_eq!(
            [0.1, z1, 1.0, z2, 3.0].map(|t| changes.sign_after(t)),
            [-1, 1, 1, -1, -1]
        );
        // |b| > 1: no zero, the sign of c0.
        let h = Affine::new(-2.0, 1.0);
        let changes = SignChanges::cos(omega, 0.0, h, exact(h));
        assert_eq!(changes.zeros(), [f64::INFINITY; 2]);
        assert_eq!(changes.sign_after(1.0), -1);
    }
}
