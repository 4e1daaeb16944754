//! Closed-form motion on one piece while slipping.
//!
//! With D and N_f affine in b(t), the acceleration while slipping in direction s is
//! a(t) = A0 + A1 b(t), A = (D − s μd N_f)/M, and
//!
//! ```text
//! linear basis:   v = v_c + a_c w + A1 w²/2,           x = x_c + v_c w + a_c w²/2 + A1 w³/6
//! cos basis:      v = v_c + A0 w + (A1/ω)(sin ωt − sin ωt_c)
//!                 x = x_c + v_c w + A0 w²/2 + (A1/ω)[(cos ωt_c − cos ωt)/ω − w sin ωt_c]
//! ```
//! with w = t − t_c (physics.md §0). Differences of sines and cosines are written as products
//! so that short intervals keep their relative accuracy.

use super::law::{Affine, Basis};

/// The motion from a state (t_c, x_c, v_c) under a(t) = A0 + A1 b(t); t is time in the period.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Arc {
    /// Polynomial motion: a = a_c + jerk·(t − t_c).
    Poly {
        t_c: f64,
        x_c: f64,
        v_c: f64,
        a_c: f64,
        jerk: f64,
        t_ref: f64,
    },
    /// Trigonometric motion: a = a0 + a1 cos ωt.
    Trig {
        t_c: f64,
        x_c: f64,
        v_c: f64,
        a0: f64,
        a1: f64,
        omega: f64,
        sin_c: f64,
        cos_c: f64,
    },
}

impl Arc {
    /// The arc starting at (t_c, x_c, v_c) with acceleration `accel` (m/s², affine in b).
    pub fn new(basis: Basis, accel: Affine, t_c: f64, x_c: f64, v_c: f64) -> Arc {
        match basis {
            Basis::Linear { t_ref } => Arc::Poly {
                t_c,
                x_c,
                v_c,
                a_c: accel.at(t_c - t_ref),
                jerk: accel.c1,
                t_ref,
            },
            Basis::Cos { omega } => {
                let (sin_c, cos_c) = (omega * t_c).sin_cos();
                Arc::Trig {
                    t_c,
                    x_c,
                    v_c,
                    a0: accel.c0,
                    a1: accel.c1,
                    omega,
                    sin_c,
                    cos_c,
                }
            }
        }
    }

    /// Start time t_c of the arc (s, within the period).
    pub fn t_start(&self) -> f64 {
        match *self {
            Arc::Poly { t_c, .. } | Arc::Trig { t_c, .. } => t_c,
        }
    }

    /// Acceleration a(t) (m/s²).
    #[inline]
    pub fn a(&self, t: f64) -> f64 {
        match *self {
            Arc::Poly { t_c, a_c, jerk, .. } => a_c + jerk * (t - t_c),
            Arc::Trig { a0, a1, omega, .. } => a0 + a1 * (omega * t).cos(),
        }
    }

    /// Velocity v(t) (m/s).
    #[inline]
    pub fn v(&self, t: f64) -> f64 {
        match *self {
            Arc::Poly {
                t_c,
                v_c,
                a_c,
                jerk,
                ..
            } => {
                let w = t - t_c;
                v_c + w * (a_c + 0.5 * jerk * w)
            }
            Arc::Trig {
                t_c,
                v_c,
                a0,
                a1,
                omega,
                ..
            } => {
                let w = t - t_c;
                // sin ωt − sin ωt_c = 2 cos(ω(t + t_c)/2) sin(ωw/2)
                let dsin = 2.0 * (0.5 * omega * (t + t_c)).cos() * (0.5 * omega * w).sin();
                v_c + a0 * w + a1 / omega * dsin
            }
        }
    }

    /// Position x(t) (m).
    #[inline]
    pub fn x(&self, t: f64) -> f64 {
        match *self {
            Arc::Poly {
                t_c,
                x_c,
                v_c,
                a_c,
                jerk,
                ..
            } => {
                let w = t - t_c;
                x_c + w * (v_c + w * (0.5 * a_c + jerk * w / 6.0))
            }
            Arc::Trig {
                t_c,
                x_c,
                v_c,
                a0,
                a1,
                omega,
                sin_c,
                ..
            } => {
                let w = t - t_c;
                // cos ωt_c − cos ωt = 2 sin(ω(t + t_c)/2) sin(ωw/2)
                let dcos = 2.0 * (0.5 * omega * (t + t_c)).sin() * (0.5 * omega * w).sin();
                x_c + v_c * w + 0.5 * a0 * w * w + a1 / omega * (dcos / omega - w * sin_c)
            }
        }
    }

    /// (v, a, da/dt) at t, for root finding: one `sin_cos` on a trigonometric arc (the
    /// difference sin ωt − sin ωt_c is taken directly here; its absolute error, ~1e-16 of the
    /// arc's speed scale, is what a root needs).
    #[inline]
    pub fn v_a_jerk(&self, t: f64) -> (f64, f64, f64) {
        match *self {
            Arc::Poly { jerk, .. } => (self.v(t), self.a(t), jerk),
            Arc::Trig {
                t_c,
                v_c,
                a0,
                a1,
                omega,
                sin_c,
                ..
            } => {
                let (sin, cos) = (omega * t).sin_cos();
                let v = v_c + a0 * (t - t_c) + a1 / omega * (sin - sin_c);
                (v, a0 + a1 * cos, -a1 * omega * sin)
            }
        }
    }

    /// Times in the open interval (lo, hi) where a(t) = 0, ascending (at most two; no
    /// allocation, this is on the hot path).
    pub fn accel_zeros(&self, lo: f64, hi: f64) -> [Option<f64>; 2] {
        let zeros = match *self {
            Arc::Poly { t_c, a_c, jerk, .. } => [(jerk != 0.0).then(|| t_c - a_c / jerk), None],
            Arc::Trig { a0, a1, omega, .. } => {
                cos_level_crossings(a0, a1, omega, lo, hi).map(|c| c.map(|(t, _)| t))
            }
        };
        zeros.map(|z| z.filter(|&t| t > lo && t < hi))
    }

    /// ∫ N_f(t)·|v(t)| dt over [t0, t1] on which v keeps its sign (N·m), with N_f = c0 + c1 b(t)
    /// in the arc's basis. Exact for both kinds of arc:
    ///
    /// ```text
    /// polynomial: two-point Gauss–Legendre (the integrand is a cubic)
    /// cos basis:  c0 Δx + c1 [sin ωt · v/ω + A0 cos ωt/ω² − A1 sin² ωt/(2ω²)]  (by parts)
    /// ```
    pub fn integrate_normal_times_speed(&self, normal: Affine, t0: f64, t1: f64) -> f64 {
        let signed = match *self {
            Arc::Poly { .. } => {
                let (half, mid) = (0.5 * (t1 - t0), 0.5 * (t1 + t0));
                let node = half * GL2_NODE;
                let f = |t: f64| normal.at(self.b(t)) * self.v(t);
                half * (f(mid - node) + f(mid + node))
            }
            Arc::Trig {
                t_c,
                x_c,
                v_c,
                a0,
                a1,
                omega,
                sin_c,
                cos_c,
            } => {
                // x and the by-parts antiderivative from one sin_cos per end (the start of the
                // arc has them stored).
                let ends = |t: f64| {
                    let (sin, cos) = if t == t_c {
                        (sin_c, cos_c)
                    } else {
                        (omega * t).sin_cos()
                    };
                    let w = t - t_c;
                    let v = v_c + a0 * w + a1 / omega * (sin - sin_c);
                    let x = x_c
                        + v_c * w
                        + 0.5 * a0 * w * w
                        + a1 / omega * ((cos_c - cos) / omega - w * sin_c);
                    let by_parts =
                        sin * v / omega + (a0 * cos - 0.5 * a1 * sin * sin) / (omega * omega);
                    (x, by_parts)
                };
                let ((x0, p0), (x1, p1)) = (ends(t0), ends(t1));
                normal.c0 * (x1 - x0) + normal.c1 * (p1 - p0)
            }
        };
        signed.abs()
    }

    /// The basis value b(t) of the arc's piece (t − t_ref, or cos ωt).
    fn b(&self, t: f64) -> f64 {
        match *self {
            Arc::Poly { t_ref, .. } => t - t_ref,
            Arc::Trig { omega, .. } => (omega * t).cos(),
        }
    }
}

/// Solutions in [lo, hi) of c0 + c1 cos ωt = 0 with t in [0, 2π/ω], each with the sign of the
/// derivative there (+1 up-crossing, −1 down-crossing), ascending. A tangency (|c0| = |c1|) is
/// not a crossing and is not returned.
pub fn cos_level_crossings(
    c0: f64,
    c1: f64,
    omega: f64,
    lo: f64,
    hi: f64,
) -> [Option<(f64, i8)>; 2] {
    if c1 == 0.0 {
        return [None, None];
    }
    let r = -c0 / c1;
    if !(r > -1.0 && r < 1.0) {
        return [None, None];
    }
    let theta = r.acos();
    let period = std::f64::consts::TAU / omega;
    // d/dt (c1 cos ωt) = −c1 ω sin ωt: sin > 0 on (0, π), < 0 on (π, 2π).
    let first = theta / omega;
    let second = period - first;
    let up_first: i8 = if c1 < 0.0 { 1 } else { -1 };
    [(first, up_first), (second, -up_first)].map(|(t, dir)| (t >= lo && t < hi).then_some((t, dir)))
}

/// Node of the two-point Gauss–Legendre rule on [−1, 1] (weights 1).
const GL2_NODE: f64 = 0.577_350_269_189_625_8;

#[cfg(test)]
mod tests {
    use super::*;

    /// Numerical derivative check: x' = v and v' = a for both kinds of arc.
    #[test]
    fn arcs_are_consistent_derivatives() {
        let arcs = [
            Arc::new(
                Basis::Linear { t_ref: 0.1 },
                Affine::new(1.5, -7.0),
                0.3,
                0.2,
                0.4,
            ),
            Arc::new(
                Basis::Cos { omega: 9.0 },
                Affine::new(0.5, -2.0),
                0.3,
                0.2,
                0.4,
            ),
        ];
        for arc in arcs {
            for &t in &[0.31, 0.5, 0.7] {
                let h = 1e-6;
                let dx = (arc.x(t + h) - arc.x(t - h)) / (2.0 * h);
                let dv = (arc.v(t + h) - arc.v(t - h)) / (2.0 * h);
                assert!((dx - arc.v(t)).abs() < 1e-8, "{arc:?} x' at {t}");
                assert!((dv - arc.a(t)).abs() < 1e-7, "{arc:?} v' at {t}");
            }
            assert_eq!(arc.v(0.3), 0.4);
            assert_eq!(arc.x(0.3), 0.2);
        }
    }

    #[test]
    fn cos_crossings_have_the_right_direction() {
        let omega = 2.0;
        let period = std::f64::consts::TAU / omega;
        // g = 0.5 − cos ωt: up-crossing at ωt = π/3, down-crossing at 5π/3.
        let c = cos_level_crossings(0.5, -1.0, omega, 0.0, period).map(Option::unwrap);
        assert!((c[0].0 - std::f64::consts::FRAC_PI_3 / omega).abs() < 1e-15);
        assert_eq!((c[0].1, c[1].1), (1, -1));
        // Tangency is not a crossing.
        assert_eq!(
            cos_level_crossings(1.0, 1.0, omega, 0.0, period),
            [None, None]
        );
    }

    #[test]
    fn gauss_legendre_is_exact_for_cubics() {
        let arc = Arc::new(
            Basis::Linear { t_ref: 0.0 },
            Affine::new(1.0, 2.0),
            0.0,
            0.0,
            1.0,
        );
        // v = 1 + t + t², N = 3 − t: ∫0^1 (3 − t)(1 + t + t²) dt = 3·(1+1/2+1/3) − (1/2+1/3+1/4)
        let exact = 3.0 * (11.0 / 6.0) - 13.0 / 12.0;
        let got = arc.integrate_normal_times_speed(Affine::new(3.0, -1.0), 0.0, 1.0);
        assert!((got - exact).abs() < 1e-14);
    }

    #[test]
    fn trigonometric_friction_integral_matches_fine_quadrature() {
        let arc = Arc::new(
            Basis::Cos { omega: 3.0 },
            Affine::new(0.2, -1.1),
            0.1,
            0.0,
            0.7,
        );
        let normal = Affine::new(2.0, 0.5);
        let (t0, t1) = (0.1, 0.6);
        let n = 20_000;
        let h = (t1 - t0) / f64::from(n);
        // Composite Simpson, error ~ h⁴.
        let f = |t: f64| normal.at((3.0 * t).cos()) * arc.v(t);
        let mut sum = f(t0) + f(t1);
        for i in 1..n {
            sum += f(t0 + f64::from(i) * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
        }
        let simpson = sum * h / 3.0;
        let got = arc.integrate_normal_times_speed(normal, t0, t1);
        assert!(
            ((got - simpson) / simpson).abs() < 1e-12,
            "{got} vs {simpson}"
        );
    }
}
