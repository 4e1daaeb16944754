//! Double-double numbers hi + lo for the few quantities a double does not hold well enough: a
//! slip onset must be known to a small fraction of the slip that follows it, and a short slip
//! (φ ≪ 1) can be much shorter than the ulp of its start time allows to resolve relatively.
//!
//! Error-free transformations: two-sum (Knuth) and two-product (fused multiply-add).

use crate::fmath;

/// π − fl(π).
const PI_LO: f64 = 1.224_646_799_147_353_2e-16;

/// s + e = a + b exactly.
#[inline]
pub fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// p + e = a·b exactly.
#[inline]
pub fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// hi + lo with |lo| ≤ ulp(hi)/2 (about 32 significant digits).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dd {
    pub hi: f64,
    pub lo: f64,
}

impl Dd {
    /// The normalized sum hi + lo.
    #[inline]
    pub fn new(hi: f64, lo: f64) -> Dd {
        let (hi, lo) = two_sum(hi, lo);
        Dd { hi, lo }
    }

    /// A double.
    #[inline]
    pub const fn from(x: f64) -> Dd {
        Dd { hi: x, lo: 0.0 }
    }

    /// a·b exactly.
    #[inline]
    pub fn prod(a: f64, b: f64) -> Dd {
        let (hi, lo) = two_prod(a, b);
        Dd { hi, lo }
    }

    /// self / d.
    #[inline]
    pub fn div_f64(self, d: f64) -> Dd {
        self / Dd::from(d)
    }

    /// The nearest double.
    #[inline]
    pub fn value(self) -> f64 {
        self.hi + self.lo
    }

    /// π and 2π.
    pub const PI: Dd = Dd {
        hi: std::f64::consts::PI,
        lo: PI_LO,
    };
    pub const TAU: Dd = Dd {
        hi: std::f64::consts::TAU,
        lo: 2.0 * PI_LO,
    };
}

impl std::ops::Add for Dd {
    type Output = Dd;

    #[inline]
    fn add(self, o: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, o.hi);
        Dd::new(s, e + (self.lo + o.lo))
    }
}

impl std::ops::Neg for Dd {
    type Output = Dd;

    #[inline]
    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl std::ops::Div for Dd {
    type Output = Dd;

    /// self / o.
    #[inline]
    fn div(self, o: Dd) -> Dd {
        let q = self.hi / o.hi;
        // self − q·o, with q·o.hi exact.
        let (p, pe) = two_prod(q, o.hi);
        let r = ((self.hi - p) - pe) + self.lo - q * o.lo;
        Dd::new(q, r / o.hi)
    }
}

/// θ ∈ (0, π) with cos θ = r, for −1 < r < 1, accurate near r = ±1 where acos is
/// ill-conditioned: there θ = 2 asin √((1 − r)/2), or π − 2 asin √((1 + r)/2), with 1 ∓ r formed
/// exactly from both parts of r (|r| > ½).
pub fn acos(r: Dd) -> Option<Dd> {
    if !(r.hi > -1.0 && r.hi < 1.0) {
        return None;
    }
    if r.hi.abs() <= 0.5 {
        // Well-conditioned: acos r.hi, and the first-order term of r.lo.
        let root = ((1.0 - r.hi) * (1.0 + r.hi)).sqrt();
        return Some(Dd::from(fmath::acos(r.hi) - r.lo / root));
    }
    if r.hi > 0.0 {
        let u = (1.0 - r.hi) - r.lo;
        (u > 0.0).then(|| Dd::from(2.0 * fmath::asin((0.5 * u).sqrt())))
    } else {
        let u = (1.0 + r.hi) + r.lo;
        (u > 0.0).then(|| Dd::PI + Dd::from(-2.0 * fmath::asin((0.5 * u).sqrt())))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn error_free_transformations_are_exact() {
        let (s, e) = two_sum(1.0, 1e-20);
        assert_eq!((s, e), (1.0, 1e-20));
        let (p, e) = two_prod(1.0 + f64::EPSILON, 1.0 - f64::EPSILON);
        assert_eq!(p, 1.0);
        assert_eq!(e, -f64::EPSILON * f64::EPSILON);
    }

    #[test]
    fn division_carries_the_remainder() {
        let q = Dd::from(1.0).div_f64(3.0);
        // 3q − 1 ≈ 0 to about 1e-32.
        let back = Dd::prod(q.hi, 3.0) + Dd::prod(q.lo, 3.0) + Dd::from(-1.0);
        assert!(back.value().abs() < 1e-31, "{back:?}");
    }

    #[test]
    fn acos_is_accurate_next_to_minus_one_and_one() {
        // r = −1 + 5e-13 (exactly, in two parts): π − θ = 2 asin √2.5e-13 ≈ 1e-6, which acos of
        // the rounded r gets only to about 1e-10.
        let r = Dd::new(-1.0, 5e-13);
        let pi_minus = (Dd::PI + -acos(r).unwrap()).value();
        let expected = 2.0 * 2.5e-13_f64.sqrt().asin();
        assert!(((pi_minus - expected) / expected).abs() < 4.0 * f64::EPSILON);
        let near_one = acos(Dd::new(1.0, -5e-13)).unwrap().value();
        assert!(((near_one - expected) / expected).abs() < 4.0 * f64::EPSILON);
        assert!(acos(Dd::from(1.0)).is_none());
        assert!(acos(Dd::from(-1.0)).is_none());
        assert_eq!(
            acos(Dd::from(0.0)).unwrap().value(),
            std::f64::consts::FRAC_PI_2
        );
    }
}
