//! Closed-form motion on one piece while slipping, written relative to the start of the arc.
//!
//! With D and N_f affine in b(t), the acceleration while slipping in direction s is affine in b,
//! a = A0 + A1 b(t), A = (D − s μd N_f)/M. The arc stores the acceleration a_c at its start
//! (formed there without cancellation, see run.rs) and the slope A1, and moves by
//!
//! ```text
//! linear basis:   a = a_c + A1 w,   v = v_c + a_c w + A1 w²/2,   x = x_c + v_c w + a_c w²/2 + A1 w³/6
//! cos basis:      a = a_c + A1 Q(δ),  v = v_c + a_c w + (A1/ω) P(δ),  x = x_c + v_c w + a_c w²/2 + (A1/ω²) R(δ)
//!                 Q = cos(θc + δ) − cos θc = −cos θc (1 − cos δ) − sin θc sin δ
//!                 P = ∫Q = −sin θc (1 − cos δ) − cos θc (δ − sin δ)
//!                 R = ∫P = −sin θc (δ − sin δ) − cos θc (δ²/2 − 1 + cos δ)
//! ```
//! with w = t − t_c the time since the start (t_c in two parts, see [`Arc::w`]), δ = ωw and
//! θc = ωt_c (guide §4). Every term is a product of factors that keep their relative
//! accuracy on a short arc (δ − sin δ and δ²/2 − 1 + cos δ by their series below |δ| = 1.5),
//! so a slip of duration φT with accelerations O(φ g) loses nothing to the O(μd g) terms that
//! make up A0 and A1 b: the old form A0 w + (A1/ω)(sin ωt − sin ωt_c) lost eps·μd/φ.

use std::cell::Cell;

use super::accel::{sign_of, SignChanges};
use super::dd::{self, Dd};
use super::law::{Affine, Basis};
use crate::fmath;

/// The state at the start of an arc: time t_c (s, within the period, as hi + lo), position
/// (m), velocity (m/s) and acceleration (m/s²).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Start {
    pub t: Dd,
    pub x: f64,
    pub v: f64,
    pub a: f64,
}

/// The motion at one time of an arc ([`Arc::at`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Point {
    /// Position (m), velocity (m/s), acceleration (m/s²) and its rate da/dt (m/s³).
    pub x: f64,
    pub v: f64,
    pub a: f64,
    pub jerk: f64,
    /// x − x_c (m), the displacement since the start as computed before x_c is added: x is
    /// exactly x_c + dx, so that a replayed period moves by the same sum ([`super::replay`]).
    pub dx: f64,
    /// b(t) − b(t_c) of the arc's basis (t − t_c, or cos ωt − cos ωt_c), relative to the start.
    pub db: f64,
    /// (sin ωt, cos ωt) on a cos basis (from the arc's phase at its start and the kernels, to
    /// about an ulp), none on a linear one.
    pub phase: Option<(f64, f64)>,
}

/// The motion from a start (t_c, x_c, v_c, a_c) under a slope A1 of a in b(t); t is time in the
/// period.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Arc {
    /// Polynomial motion: a = a_c + jerk·(t − t_c).
    Poly(PolyArc),
    /// Trigonometric motion: a = a_c + a1 (cos ωt − cos ωt_c).
    Trig(TrigArc),
}

/// Polynomial motion: a = a_c + jerk·(t − t_c).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PolyArc {
    t_c: f64,
    t_lo: f64,
    x_c: f64,
    v_c: f64,
    a_c: f64,
    jerk: f64,
}

/// Trigonometric motion: a = a_c + a1 (cos ωt − cos ωt_c).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TrigArc {
    t_c: f64,
    t_lo: f64,
    x_c: f64,
    v_c: f64,
    a_c: f64,
    a1: f64,
    omega: f64,
    /// A1/ω (m/s) and A1/ω² (m), the scales of P and R.
    v1: f64,
    x1: f64,
    /// sin ωt_c and cos ωt_c, with both parts of t_c.
    sin_c: f64,
    cos_c: f64,
}

/// What the event search asks of an arc, answered by each kind of arc on its own: code generic
/// over it (run.rs's slide) is compiled once per kind, without the other kind's branches.
pub trait ArcMotion: Copy {
    /// On a cos basis: the arc's points carry their phase (sin ωt, cos ωt).
    const TRIG: bool;

    /// The arc of this kind on `basis` (of this kind) from `start` whose acceleration has slope
    /// `a1` (m/s² per unit of b), with (sin θc, cos θc) = [`phase`]`(ω, t_c)` on a cos basis
    /// when known (a piece's start and a located onset have the same phase in every period).
    fn from_start(basis: Basis, a1: f64, start: Start, phase: Option<(f64, f64)>) -> Self;

    /// The arc as either kind.
    fn arc(self) -> Arc;

    /// Start time t_c of the arc (s, within the period; the high part).
    fn t_start(&self) -> f64;

    /// Where s·a changes sign, given those located for the piece in direction s (`located`):
    /// on a cos basis those; on a linear basis where a_c + A1·w = 0, w = −a_c/A1, one division
    /// from the arc's own start (cheaper per arc than locating the zero once per run in two
    /// parts, which costs a short run more than it saves).
    fn sign_changes(&self, s: f64, located: &SignChanges) -> SignChanges;

    /// Velocity at the start (m/s).
    fn v_start(&self) -> f64;

    /// w = t − t_c, the time since the start (s): t − t_c.hi is exact near the start
    /// (Sterbenz), and t_c.lo is then subtracted.
    fn w(&self, t: f64) -> f64;

    /// The motion at time t: position, velocity, acceleration, jerk and b(t) − b(t_c), from one
    /// evaluation of the trigonometric kernels.
    fn at(&self, t: f64) -> Point;

    /// [`ArcMotion::at`] at a time close to the last one evaluated with the same `seed`, as in a
    /// root search: where the half angle δ/2 moved by at most [`ADDITION_MAX`] since, the
    /// kernels follow from the seed's by the angle-addition formulas, without sin and cos (each
    /// addition adds about an ulp to them), unless δ/2 is one of the `known` half angles
    /// (worked out once for the times a run meets in every period, see run.rs): then from it,
    /// with the bits of sin and cos. The seed is the last half angle whose sin and cos were
    /// evaluated or known, not one reached by addition, so that the additions' rounding does not
    /// accumulate along a search. A linear arc has no angles (`None`).
    fn at_near(&self, t: f64, seed: &mut Option<HalfAngle>, known: Option<&KnownAngles>) -> Point;

    /// [`ArcMotion::at_near`] at an iterate of a root search or at the root it ends on: where
    /// δ/2 turned by at most [`SHORT_TURN_MAX`] from the half angle of an earlier iterate
    /// (`iterate`), the kernels follow from that one's by the angle-addition formulas with the
    /// Taylor sums to e⁴; else from the `seed` as by [`ArcMotion::at_near`] without known
    /// angles (the iterates are no piece's known times), and that half angle becomes `iterate`. An iterate's half angle is one addition from sin and cos evaluated or
    /// known, so the rounding of the additions still does not accumulate beyond two.
    fn at_iterate(
        &self,
        t: f64,
        seed: &mut Option<HalfAngle>,
        iterate: &mut Option<HalfAngle>,
    ) -> Point;

    /// ∫ N_f(t)·|v(t)| dt from the start of the arc to t1 (see
    /// [`Arc::integrate_normal_times_speed`]).
    fn integrate_normal_times_speed(&self, n_c: f64, n1: f64, t1: f64) -> f64;

    /// Velocity v(t) (m/s).
    #[inline(always)]
    fn v(&self, t: f64) -> f64 {
        self.at(t).v
    }

    /// At a stick located at time t (a double): the time since the start w of the root of v,
    /// refined in w where the arc can do so free of the rounding of t, with the motion there.
    /// A slip far shorter than the time of day it happens at (φ = 1e-9 at T/2) is resolved by
    /// t to a part in 1e5 only; x and ∫N_f|v| are flat at a stick, so that costs the square
    /// of it, and w refined costs nothing. `None`: the arc has no refinement (t is kept).
    #[inline(always)]
    fn stick_in_w(&self, _t: f64) -> Option<(f64, Point)> {
        None
    }

    /// The motion at a zero of the acceleration located at time t (a speed maximum), from the
    /// time since the start at which the arc's own coefficients put it, where the arc can (v
    /// is flat there: evaluated at the rounded t it costs the square of t's rounding over the
    /// length of the slip). `None`: the arc has no such form.
    #[inline(always)]
    fn at_accel_zero(&self, _t: f64) -> Option<Point> {
        None
    }

    /// ∫ N_f(t)·|v(t)| dt from the start of the arc to the time w after it (with w from
    /// [`ArcMotion::stick_in_w`]); `None` where the arc has no refinement.
    #[inline(always)]
    fn integrate_normal_times_speed_w(&self, _n_c: f64, _n1: f64, _w1: f64) -> Option<f64> {
        None
    }
}

impl ArcMotion for PolyArc {
    const TRIG: bool = false;

    #[inline(always)]
    fn from_start(_basis: Basis, a1: f64, start: Start, _phase: Option<(f64, f64)>) -> Self {
        PolyArc {
            t_c: start.t.hi,
            t_lo: start.t.lo,
            x_c: start.x,
            v_c: start.v,
            a_c: start.a,
            jerk: a1,
        }
    }

    #[inline(always)]
    fn arc(self) -> Arc {
        Arc::Poly(self)
    }

    #[inline(always)]
    fn t_start(&self) -> f64 {
        self.t_c
    }

    #[inline(always)]
    fn sign_changes(&self, s: f64, _located: &SignChanges) -> SignChanges {
        let PolyArc {
            t_c,
            t_lo,
            a_c,
            jerk,
            ..
        } = *self;
        if jerk == 0.0 {
            return SignChanges::once(None, sign_of(s * a_c));
        }
        SignChanges::once(Some(t_c + (t_lo + -a_c / jerk)), -sign_of(s * jerk))
    }

    #[inline(always)]
    fn v_start(&self) -> f64 {
        self.v_c
    }

    #[inline(always)]
    fn w(&self, t: f64) -> f64 {
        since(
            t,
            Dd {
                hi: self.t_c,
                lo: self.t_lo,
            },
        )
    }

    #[inline(always)]
    fn at(&self, t: f64) -> Point {
        self.at_w(self.w(t))
    }

    #[inline(always)]
    fn at_near(
        &self,
        t: f64,
        _seed: &mut Option<HalfAngle>,
        _known: Option<&KnownAngles>,
    ) -> Point {
        self.at(t)
    }

    #[inline(always)]
    fn at_iterate(
        &self,
        t: f64,
        _seed: &mut Option<HalfAngle>,
        _iterate: &mut Option<HalfAngle>,
    ) -> Point {
        self.at(t)
    }

    #[inline]
    fn integrate_normal_times_speed(&self, n_c: f64, n1: f64, t1: f64) -> f64 {
        self.normal_times_speed_to(n_c, n1, self.w(t1))
    }

    /// One Newton step on v(w) = v_c + a_c w + jerk w²/2 from w(t): t carries the rounding of
    /// the time of day, v(w) and a(w) only that of their terms, so w comes out to a few ulps
    /// of itself.
    #[inline]
    fn stick_in_w(&self, t: f64) -> Option<(f64, Point)> {
        let w0 = self.w(t);
        let here = self.at_w(w0);
        let w = if here.a != 0.0 {
            w0 - here.v / here.a
        } else {
            w0
        };
        // The step is a correction of the rounding of t: far larger, it is no refinement.
        if !(w.is_finite() && (w - w0).abs() <= 8.0 * f64::EPSILON * t.abs() + 1e-6 * w0.abs()) {
            return None;
        }
        Some((w, self.at_w(w)))
    }

    /// w = −a_c/jerk, where a = a_c + jerk·w vanishes, from the arc's own coefficients.
    #[inline]
    fn at_accel_zero(&self, t: f64) -> Option<Point> {
        let PolyArc { a_c, jerk, .. } = *self;
        let w = -a_c / jerk;
        let near = (w - self.w(t)).abs() <= 8.0 * f64::EPSILON * t.abs() + 1e-6 * w.abs();
        (jerk != 0.0 && w.is_finite() && near).then(|| self.at_w(w))
    }

    #[inline]
    fn integrate_normal_times_speed_w(&self, n_c: f64, n1: f64, w1: f64) -> Option<f64> {
        Some(self.normal_times_speed_to(n_c, n1, w1))
    }
}

impl PolyArc {
    /// The motion a time w after the start.
    #[inline(always)]
    fn at_w(&self, w: f64) -> Point {
        let PolyArc {
            x_c,
            v_c,
            a_c,
            jerk,
            ..
        } = *self;
        let dx = w * (v_c + w * (0.5 * a_c + jerk * w / 6.0));
        Point {
            x: x_c + dx,
            dx,
            v: v_c + w * (a_c + 0.5 * jerk * w),
            a: a_c + jerk * w,
            jerk,
            db: w,
            phase: None,
        }
    }

    /// ∫ N_f|v| dt over [0, w1] after the start: the integrand is a cubic in w, which
    /// Gauss–Legendre with two nodes integrates exactly.
    #[inline]
    fn normal_times_speed_to(&self, n_c: f64, n1: f64, w1: f64) -> f64 {
        let PolyArc { v_c, a_c, jerk, .. } = *self;
        let half = 0.5 * w1;
        let node = half * GL2_NODE;
        let f = |w: f64| (n_c + n1 * w) * (v_c + w * (a_c + 0.5 * jerk * w));
        (half * (f(half - node) + f(half + node))).abs()
    }
}

impl TrigArc {
    /// The motion a time w after the start, with the kernels of δ = ωw.
    #[inline(always)]
    fn at_kernels(&self, w: f64, k: Kernels) -> Point {
        let TrigArc {
            x_c,
            v_c,
            a_c,
            a1,
            omega,
            v1,
            x1,
            sin_c,
            cos_c,
            ..
        } = *self;
        let p = -sin_c * k.one_minus_cos - cos_c * k.minus_sin;
        let q = -cos_c * k.one_minus_cos - sin_c * k.sin;
        let r = -sin_c * k.minus_sin - cos_c * k.minus_cos;
        // sin(θc + δ)
        let sin_t = sin_c * (1.0 - k.one_minus_cos) + cos_c * k.sin;
        let dx = w * (v_c + 0.5 * a_c * w) + x1 * r;
        Point {
            x: x_c + dx,
            dx,
            v: v_c + a_c * w + v1 * p,
            a: a_c + a1 * q,
            jerk: -a1 * omega * sin_t,
            db: q,
            phase: Some((sin_t, cos_c + q)),
        }
    }
}

impl ArcMotion for TrigArc {
    const TRIG: bool = true;

    #[inline(always)]
    fn from_start(basis: Basis, a1: f64, start: Start, phase: Option<(f64, f64)>) -> Self {
        let omega = match basis {
            Basis::Cos { omega, .. } => omega,
            Basis::Linear { .. } => unreachable!("a trigonometric arc on a linear basis"),
        };
        let (sin_c, cos_c) = phase.unwrap_or_else(|| super::arc::phase(omega, start.t));
        TrigArc {
            t_c: start.t.hi,
            t_lo: start.t.lo,
            x_c: start.x,
            v_c: start.v,
            a_c: start.a,
            a1,
            omega,
            v1: a1 / omega,
            x1: a1 / (omega * omega),
            sin_c,
            cos_c,
        }
    }

    #[inline(always)]
    fn arc(self) -> Arc {
        Arc::Trig(self)
    }

    #[inline(always)]
    fn t_start(&self) -> f64 {
        self.t_c
    }

    #[inline(always)]
    fn sign_changes(&self, _s: f64, located: &SignChanges) -> SignChanges {
        *located
    }

    #[inline(always)]
    fn v_start(&self) -> f64 {
        self.v_c
    }

    #[inline(always)]
    fn w(&self, t: f64) -> f64 {
        since(
            t,
            Dd {
                hi: self.t_c,
                lo: self.t_lo,
            },
        )
    }

    #[inline(always)]
    fn at(&self, t: f64) -> Point {
        let w = self.w(t);
        self.at_kernels(w, Kernels::new(self.omega * w))
    }

    #[inline(always)]
    fn at_near(&self, t: f64, seed: &mut Option<HalfAngle>, known: Option<&KnownAngles>) -> Point {
        let w = self.w(t);
        self.at_kernels(w, Kernels::near(self.omega * w, seed, known))
    }

    #[inline(always)]
    fn at_iterate(
        &self,
        t: f64,
        seed: &mut Option<HalfAngle>,
        iterate: &mut Option<HalfAngle>,
    ) -> Point {
        let w = self.w(t);
        let delta = self.omega * w;
        let kernels = match *iterate {
            Some(x) if (0.5 * delta - x.angle).abs() <= SHORT_TURN_MAX => {
                Kernels::turned(delta, x, short_turn(0.5 * delta - x.angle))
            }
            _ => {
                let kernels = Kernels::near(delta, seed, None);
                *iterate = Some(kernels.half);
                kernels
            }
        };
        self.at_kernels(w, kernels)
    }

    fn integrate_normal_times_speed(&self, n_c: f64, n1: f64, t1: f64) -> f64 {
        let TrigArc {
            v_c,
            a_c,
            a1,
            omega,
            sin_c,
            cos_c,
            ..
        } = *self;
        let w1 = self.w(t1);
        let delta = omega * w1;
        let k = Kernels::new(delta);
        let p = -sin_c * k.one_minus_cos - cos_c * k.minus_sin;
        let r = -sin_c * k.minus_sin - cos_c * k.minus_cos;
        let dx = w1 * (v_c + 0.5 * a_c * w1) + self.x1 * r;
        let moment = v_c * p + a_c / omega * (delta * p - r) + 0.5 * a1 / omega * p * p;
        (n_c * dx + n1 / omega * moment).abs()
    }
}

/// Calls `$method` on the kind of arc `$arc` holds.
macro_rules! either {
    ($arc:expr, $m:ident => $e:expr) => {
        match $arc {
            Arc::Poly($m) => $e,
            Arc::Trig($m) => $e,
        }
    };
}

impl Arc {
    /// The arc starting at (t_c, x_c, v_c) with acceleration `accel` (m/s², affine in b),
    /// evaluated at t_c as A0 + A1 b(t_c).
    pub fn new(basis: Basis, accel: Affine, t_c: f64, x_c: f64, v_c: f64) -> Arc {
        let start = Start {
            t: Dd::from(t_c),
            x: x_c,
            v: v_c,
            a: accel.at(basis.eval(t_c)),
        };
        Arc::from_start(basis, accel.c1, start)
    }

    /// The arc from `start` whose acceleration has slope `a1` (m/s² per unit of b).
    pub fn from_start(basis: Basis, a1: f64, start: Start) -> Arc {
        match basis {
            Basis::Linear { .. } => PolyArc::from_start(basis, a1, start, None).arc(),
            Basis::Cos { .. } => TrigArc::from_start(basis, a1, start, None).arc(),
        }
    }

    /// Start time t_c of the arc (s, within the period; the high part).
    pub fn t_start(&self) -> f64 {
        either!(self, arc => arc.t_start())
    }

    /// The same arc started at position `x` (m): the motion relative to the start does not
    /// depend on where it starts (a replayed period, [`super::replay`]).
    pub fn started_at(self, x: f64) -> Arc {
        match self {
            Arc::Poly(arc) => Arc::Poly(PolyArc { x_c: x, ..arc }),
            Arc::Trig(arc) => Arc::Trig(TrigArc { x_c: x, ..arc }),
        }
    }

    /// Velocity at the start (m/s).
    pub fn v_start(&self) -> f64 {
        either!(self, arc => arc.v_start())
    }

    /// w = t − t_c, the time since the start (s): t − t_c.hi is exact near the start
    /// (Sterbenz), and t_c.lo is then subtracted.
    #[inline]
    pub fn w(&self, t: f64) -> f64 {
        either!(self, arc => arc.w(t))
    }

    /// The motion at time t: position, velocity, acceleration, jerk and b(t) − b(t_c), from one
    /// evaluation of the trigonometric kernels. The accessors below take one field each: always
    /// inlined, the other fields cost nothing.
    #[inline(always)]
    pub fn at(&self, t: f64) -> Point {
        either!(self, arc => arc.at(t))
    }

    /// [`ArcMotion::at_near`] on either kind of arc.
    #[inline]
    pub fn at_near(
        &self,
        t: f64,
        seed: &mut Option<HalfAngle>,
        known: Option<&KnownAngles>,
    ) -> Point {
        either!(self, arc => arc.at_near(t, seed, known))
    }

    /// Acceleration a(t) (m/s²).
    #[inline]
    pub fn a(&self, t: f64) -> f64 {
        self.at(t).a
    }

    /// Velocity v(t) (m/s).
    #[inline]
    pub fn v(&self, t: f64) -> f64 {
        self.at(t).v
    }

    /// Position x(t) (m).
    #[inline]
    pub fn x(&self, t: f64) -> f64 {
        self.at(t).x
    }

    /// ∫ N_f(t)·|v(t)| dt from the start of the arc to t1, over which v keeps its sign (N·m),
    /// with N_f = n_c + n1 (b(t) − b(t_c)): n_c is N_f at the start, n1 its slope in the basis.
    /// Exact for both kinds of arc, and relative to the start, so that a short slip keeps its
    /// digits:
    ///
    /// ```text
    /// polynomial: two-point Gauss–Legendre in w (the integrand is a cubic)
    /// cos basis:  n_c Δx + (n1/ω) [v_c P + (a_c/ω)(δP − R) + (A1/2ω) P²]
    /// ```
    /// (N_f − n_c = n1 Q(δ) with Q = dP/dδ, P = dR/dδ, so ∫Q = P, ∫δQ = δP − R, ∫QP = P²/2.)
    pub fn integrate_normal_times_speed(&self, n_c: f64, n1: f64, t1: f64) -> f64 {
        either!(self, arc => arc.integrate_normal_times_speed(n_c, n1, t1))
    }
}

/// (sin θ, cos θ) at θ = ωt, t in two parts: the rounding of ω·t.hi and the low part of t, which
/// a first-order correction of sin and cos takes in.
pub fn phase(omega: f64, t: Dd) -> (f64, f64) {
    phase_from(omega, t, fmath::sin_cos(omega * t.hi))
}

/// [`phase`] from (sin, cos) of ω·t.hi (the double ω·t.hi, as [`fmath::sin_cos`] gives them),
/// where they are known.
#[inline]
pub fn phase_from(omega: f64, t: Dd, (sin, cos): (f64, f64)) -> (f64, f64) {
    let theta = omega * t.hi;
    let theta_lo = omega.mul_add(t.hi, -theta) + omega * t.lo;
    (sin + cos * theta_lo, cos - sin * theta_lo)
}

/// sin δ and 1 − cos δ from sin and cos of δ/2 (both keep their relative accuracy for small δ),
/// and the higher differences δ − sin δ and δ²/2 − (1 − cos δ).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Kernels {
    delta: f64,
    sin: f64,
    one_minus_cos: f64,
    /// δ − sin δ and δ²/2 − (1 − cos δ) (an evaluation inlined where it needs neither position
    /// nor speed does not sum their series).
    minus_sin: f64,
    minus_cos: f64,
    /// sin and cos of δ/2, from which the others are formed.
    half: HalfAngle,
}

/// sin and cos of half the angle δ = ωw an arc has turned through since its start: the seed of
/// [`Arc::at_near`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HalfAngle {
    angle: f64,
    sin: f64,
    cos: f64,
}

/// The half angles whose sin and cos a run works out once (see [`ArcMotion::at_near`]), with
/// their kernels (the series of δ − sin δ and δ²/2 − (1 − cos δ) summed once too): at most
/// [`KnownAngles::CAPACITY`], the later ones dropped. Which half angles are known is settled
/// when they are added; the kernels of one are worked out when an evaluation first meets it
/// (the same bits as at once: many are never met in a run that replays its periods).
#[derive(Clone, Debug, PartialEq)]
pub struct KnownAngles {
    angles: [f64; KnownAngles::CAPACITY],
    /// The kernels of each, once worked out.
    kernels: [Cell<Option<Kernels>>; KnownAngles::CAPACITY],
    len: usize,
}

impl KnownAngles {
    pub const CAPACITY: usize = 6;

    pub const fn new() -> KnownAngles {
        KnownAngles {
            angles: [f64::NAN; KnownAngles::CAPACITY],
            kernels: [const { Cell::new(None) }; KnownAngles::CAPACITY],
            len: 0,
        }
    }

    /// Adds (when there is room) the half angle δ/2, where δ = ω·(t − t_c) is the angle an arc
    /// of angular frequency ω (rad/s) that starts at t_c (s, in two parts) has turned through
    /// at t (s): the same δ and bits as the arc's own evaluation at t.
    pub fn push_between(&mut self, omega: f64, t_c: Dd, t: f64) {
        if self.len < KnownAngles::CAPACITY {
            self.angles[self.len] = 0.5 * (omega * since(t, t_c));
            self.len += 1;
        }
    }

    /// The kernels of the known half angle `angle`, if it is one: those of twice it (exactly),
    /// from sin and cos of it, worked out the first time.
    #[inline(always)]
    fn get(&self, angle: f64) -> Option<Kernels> {
        let i = self.angles[..self.len].iter().position(|&a| a == angle)?;
        let kernels = self.kernels[i].get().unwrap_or_else(|| {
            let (sin, cos) = fmath::sin_cos(angle);
            Kernels::from_half(2.0 * angle, HalfAngle { angle, sin, cos })
        });
        self.kernels[i].set(Some(kernels));
        Some(kernels)
    }
}

impl Default for KnownAngles {
    fn default() -> Self {
        KnownAngles::new()
    }
}

/// w = t − t_c (s): t − t_c.hi is exact near the start (Sterbenz), and t_c.lo is then
/// subtracted.
#[inline(always)]
fn since(t: f64, t_c: Dd) -> f64 {
    (t - t_c.hi) - t_c.lo
}

/// The largest change of δ/2 taken by the angle-addition formulas: there the Taylor sums of
/// [`SIN_TAYLOR`] and [`ONE_MINUS_COS_TAYLOR`] are exact to a relative 1e-19, and a root search
/// from the end of a piece reaches a stick up to 1.2 rad before it without sin and cos.
pub const ADDITION_MAX: f64 = 0.6;

/// sin e / e = Σ (−1)^k e^{2k}/(2k+1)!, to e^16.
const SIN_TAYLOR: [f64; 9] = [
    1.0,
    -1.0 / 6.0,
    1.0 / 120.0,
    -1.0 / 5040.0,
    1.0 / 362_880.0,
    -1.0 / 39_916_800.0,
    1.0 / 6_227_020_800.0,
    -1.0 / 1_307_674_368_000.0,
    1.0 / 355_687_428_096_000.0,
];

/// (1 − cos e) / e² = Σ (−1)^k e^{2k}/(2k+2)!, to e^14.
const ONE_MINUS_COS_TAYLOR: [f64; 8] = [
    0.5,
    -1.0 / 24.0,
    1.0 / 720.0,
    -1.0 / 40320.0,
    1.0 / 3_628_800.0,
    -1.0 / 479_001_600.0,
    1.0 / 87_178_291_200.0,
    -1.0 / 20_922_789_888_000.0,
];

/// The largest turn e of the half angle between the iterates of a root search that
/// [`ArcMotion::at_iterate`] takes by [`short_turn`]: there the first terms it leaves out,
/// e⁶/7! of sin e/e and e⁶/8! of (1 − cos e)/e², are below a relative 1e-19 of the sums.
pub const SHORT_TURN_MAX: f64 = 2.5e-3;

/// The first three terms of [`SIN_TAYLOR`], to e⁴.
const SIN_TAYLOR_SHORT: [f64; 3] = [SIN_TAYLOR[0], SIN_TAYLOR[1], SIN_TAYLOR[2]];

/// The first three terms of [`ONE_MINUS_COS_TAYLOR`], to e⁴.
const ONE_MINUS_COS_TAYLOR_SHORT: [f64; 3] = [
    ONE_MINUS_COS_TAYLOR[0],
    ONE_MINUS_COS_TAYLOR[1],
    ONE_MINUS_COS_TAYLOR[2],
];

/// (sin e, 1 − cos e) for a turn |e| ≤ [`SHORT_TURN_MAX`], by Taylor sums to e⁴.
#[inline(always)]
fn short_turn(e: f64) -> (f64, f64) {
    let z = e * e;
    (
        e * series(z, &SIN_TAYLOR_SHORT),
        z * series(z, &ONE_MINUS_COS_TAYLOR_SHORT),
    )
}

impl Kernels {
    #[inline]
    fn new(delta: f64) -> Kernels {
        let angle = 0.5 * delta;
        let (sin, cos) = fmath::sin_cos(angle);
        Kernels::from_half(delta, HalfAngle { angle, sin, cos })
    }

    /// The kernels at δ from the `known` half angle equal to δ/2 (the same bits as
    /// [`Kernels::new`]); else from those of a `seed` within [`ADDITION_MAX`] of δ/2, by
    /// sin(x + e) = sin x + (cos x sin e − sin x (1 − cos e)) and
    /// cos(x + e) = cos x − (sin x sin e + cos x (1 − cos e)); else by [`Kernels::new`]. A
    /// known or newly evaluated half angle becomes the seed.
    #[inline(always)]
    fn near(delta: f64, seed: &mut Option<HalfAngle>, known: Option<&KnownAngles>) -> Kernels {
        let angle = 0.5 * delta;
        if let Some(kernels) = known.and_then(|known| known.get(angle)) {
            *seed = Some(kernels.half);
            return kernels;
        }
        match *seed {
            Some(x) if (angle - x.angle).abs() <= ADDITION_MAX => {
                let e = angle - x.angle;
                let turn = (
                    e * series(e * e, &SIN_TAYLOR),
                    e * e * series(e * e, &ONE_MINUS_COS_TAYLOR),
                );
                Kernels::turned(delta, x, turn)
            }
            _ => {
                let kernels = Kernels::new(delta);
                *seed = Some(kernels.half);
                kernels
            }
        }
    }

    /// The kernels at δ from those of the half angle `x` turned by e = δ/2 − x (given as
    /// (sin e, 1 − cos e)), by the angle-addition formulas of [`Kernels::near`].
    #[inline(always)]
    fn turned(delta: f64, x: HalfAngle, (sin_e, one_minus_cos_e): (f64, f64)) -> Kernels {
        let half = HalfAngle {
            angle: 0.5 * delta,
            sin: x.sin + (x.cos * sin_e - x.sin * one_minus_cos_e),
            cos: x.cos - (x.sin * sin_e + x.cos * one_minus_cos_e),
        };
        Kernels::from_half(delta, half)
    }

    /// The kernels at δ from sin and cos of δ/2.
    #[inline(always)]
    fn from_half(delta: f64, half: HalfAngle) -> Kernels {
        let sin = 2.0 * half.sin * half.cos;
        let one_minus_cos = 2.0 * half.sin * half.sin;
        Kernels {
            delta,
            sin,
            one_minus_cos,
            minus_sin: minus_sin(delta, sin),
            minus_cos: minus_cos(delta, one_minus_cos),
            half,
        }
    }
}

/// δ − sin δ, given sin δ.
#[inline(always)]
fn minus_sin(d: f64, sin: f64) -> f64 {
    if d.abs() < SERIES_MAX {
        d * d * d * series(d * d, &MINUS_SIN)
    } else {
        d - sin
    }
}

/// δ²/2 − (1 − cos δ), given 1 − cos δ.
#[inline(always)]
fn minus_cos(d: f64, one_minus_cos: f64) -> f64 {
    if d.abs() < SERIES_MAX {
        let z = d * d;
        z * z * series(z, &MINUS_COS)
    } else {
        0.5 * d * d - one_minus_cos
    }
}

/// Below this |δ| the kernels are summed as series; above it the direct differences lose at
/// most a factor 6 to cancellation.
const SERIES_MAX: f64 = 1.5;

/// Σ c_k z^k by Estrin's scheme: c_2i + c_2i+1·z in pairs, the pairs combined with z², those
/// with z⁴, …: about log₂ N dependent steps instead of Horner's N, which a root search, whose
/// every step waits for the last evaluation, feels (the loops unroll for a constant N).
#[inline(always)]
fn series<const N: usize>(z: f64, c: &[f64; N]) -> f64 {
    let mut terms = *c;
    let (mut n, mut power) = (N, z);
    while n > 1 {
        let pairs = n.div_ceil(2);
        for i in 0..pairs {
            terms[i] = if 2 * i + 1 < n {
                terms[2 * i] + terms[2 * i + 1] * power
            } else {
                terms[2 * i]
            };
        }
        (n, power) = (pairs, power * power);
    }
    terms[0]
}

/// (δ − sin δ)/δ³ = Σ (−1)^k δ^{2k}/(2k+3)!, to a relative 1e-19 for |δ| < 1.5.
const MINUS_SIN: [f64; 11] = [
    1.0 / 6.0,
    -1.0 / 120.0,
    1.0 / 5040.0,
    -1.0 / 362_880.0,
    1.0 / 39_916_800.0,
    -1.0 / 6_227_020_800.0,
    1.0 / 1_307_674_368_000.0,
    -1.0 / 355_687_428_096_000.0,
    1.0 / 121_645_100_408_832_000.0,
    -1.0 / 51_090_942_171_709_440_000.0,
    1.0 / 25_852_016_738_884_976_640_000.0,
];

/// (δ²/2 − 1 + cos δ)/δ⁴ = Σ (−1)^k δ^{2k}/(2k+4)!, to a relative 1e-19 for |δ| < 1.5.
const MINUS_COS: [f64; 11] = [
    1.0 / 24.0,
    -1.0 / 720.0,
    1.0 / 40320.0,
    -1.0 / 3_628_800.0,
    1.0 / 479_001_600.0,
    -1.0 / 87_178_291_200.0,
    1.0 / 20_922_789_888_000.0,
    -1.0 / 6_402_373_705_728_000.0,
    1.0 / 2_432_902_008_176_640_000.0,
    -1.0 / 1_124_000_727_777_607_680_000.0,
    1.0 / 620_448_401_733_239_439_360_000.0,
];

/// Solutions t = θ/ω and (2π − θ)/ω in [lo, hi) of cos ωt = r, −1 < r < 1, as double-doubles,
/// each with the sign of d(cos ωt)/dt there (−1 for the first, +1 for the second).
pub fn cos_level_crossings_dd(r: Dd, omega: f64, lo: f64, hi: f64) -> [Option<(Dd, i8)>; 2] {
    let Some(theta) = dd::acos(r) else {
        return [None, None];
    };
    let first = theta.div_f64(omega);
    let second = (Dd::TAU + -theta).div_f64(omega);
    let within = |t: Dd, dir: i8| {
        let v = t.value();
        (v >= lo && v < hi).then_some((t, dir))
    };
    [within(first, -1), within(second, 1)]
}

/// Node of the two-point Gauss–Legendre rule on [−1, 1] (weights 1).
const GL2_NODE: f64 = 0.577_350_269_189_625_8;

#[cfg(test)]
mod tests {
    use super::*;

    /// Numerical derivative check: x' = v and v' = a for both kinds of arc.
    /// A known half angle's kernels, worked out when first met, are those of evaluating the
    /// angle at once (bit for bit), the second time as the first; other angles are not known.
    #[test]
    fn known_angles_are_worked_out_when_met_with_the_same_bits() {
        let mut known = KnownAngles::new();
        let omega = 37.796_447_300_922_72;
        let starts = [
            Dd::from(0.0),
            Dd::from(0.058_980_868_686_954_37),
            Dd::from(0.1),
        ];
        for (i, &t_c) in starts.iter().enumerate() {
            known.push_between(omega, t_c, 0.065_136_249_845_933_19 + 0.01 * i as f64);
        }
        for (i, &t_c) in starts.iter().enumerate() {
            let delta = omega * since(0.065_136_249_845_933_19 + 0.01 * i as f64, t_c);
            let direct = Kernels::new(delta);
            for _ in 0..2 {
                let got = known.get(0.5 * delta).expect("a known angle");
                assert_eq!(format!("{got:?}"), format!("{direct:?}"));
                assert_eq!(got.sin.to_bits(), direct.sin.to_bits());
                assert_eq!(got.half.cos.to_bits(), direct.half.cos.to_bits());
            }
        }
        assert!(known.get(0.123).is_none());
        assert!(KnownAngles::new().get(f64::NAN).is_none());
    }

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
                Basis::Cos {
                    omega: 9.0,
                    shift: 0.0,
                },
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
        // cos ωt = 0.5 at ωt = π/3 (cos falling) and 5π/3 (rising).
        let c = cos_level_crossings_dd(Dd::from(0.5), omega, 0.0, period).map(Option::unwrap);
        assert!((c[0].0.value() - std::f64::consts::FRAC_PI_3 / omega).abs() < 1e-15);
        assert!((c[1].0.value() - 5.0 * std::f64::consts::FRAC_PI_3 / omega).abs() < 1e-15);
        assert_eq!((c[0].1, c[1].1), (-1, 1));
        // Tangency is not a crossing.
        assert_eq!(
            cos_level_crossings_dd(Dd::from(1.0), omega, 0.0, period),
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
        let got = arc.integrate_normal_times_speed(3.0, -1.0, 1.0);
        assert!((got - exact).abs() < 1e-14);
    }

    #[test]
    fn trigonometric_friction_integral_matches_fine_quadrature() {
        let arc = Arc::new(
            Basis::Cos {
                omega: 3.0,
                shift: 0.0,
            },
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
        let got = arc.integrate_normal_times_speed(normal.at((3.0 * t0).cos()), normal.c1, t1);
        assert!(
            ((got - simpson) / simpson).abs() < 1e-12,
            "{got} vs {simpson}"
        );
    }

    /// The root search steps by angle addition from its last evaluation: a few steps of
    /// decreasing size, as Halley's method takes them, agree with sin and cos of each time to a
    /// few ulps of the motion, and a step beyond ADDITION_MAX evaluates sin and cos afresh.
    #[test]
    fn angle_addition_steps_agree_with_direct_evaluation() {
        let arc = Arc::new(
            Basis::Cos {
                omega: 37.8,
                shift: 0.0,
            },
            Affine::new(0.2, -1.1),
            0.07,
            0.01,
            0.4,
        );
        let mut seed = None;
        let times = [0.0944, 0.0893, 0.08887, 0.088_871_2, 0.088_871_136, 0.03];
        for t in times {
            let (near, direct) = (
                arc.at_near(t, &mut seed, Some(&KnownAngles::new())),
                arc.at(t),
            );
            let scale = |d: f64| 8.0 * f64::EPSILON * d.abs().max(1.0);
            assert!((near.v - direct.v).abs() <= scale(direct.v), "v at {t}");
            assert!((near.a - direct.a).abs() <= scale(direct.a), "a at {t}");
            assert!((near.x - direct.x).abs() <= scale(direct.x), "x at {t}");
            assert!(
                (near.jerk - direct.jerk).abs() <= scale(direct.jerk),
                "jerk at {t}"
            );
        }
        // The last step (δ/2 moves by about 1.1) is evaluated afresh.
        assert_eq!(
            arc.at_near(0.03, &mut seed, Some(&KnownAngles::new())),
            arc.at(0.03)
        );
        // As a root search's iterates: the 4th and 5th turn by less than SHORT_TURN_MAX from the
        // 3rd (by 2e-5 and 1e-5), by the short Taylor sums, and agree as well.
        let Arc::Trig(trig) = arc else {
            unreachable!("an arc on a cos basis")
        };
        let (mut seed, mut iterate) = (None, None);
        for t in times {
            let (near, direct) = (trig.at_iterate(t, &mut seed, &mut iterate), arc.at(t));
            let scale = |d: f64| 8.0 * f64::EPSILON * d.abs().max(1.0);
            assert!((near.v - direct.v).abs() <= scale(direct.v), "v at {t}");
            assert!((near.x - direct.x).abs() <= scale(direct.x), "x at {t}");
        }
    }

    #[test]
    fn kernel_series_join_the_direct_differences() {
        // Where they join, the direct differences lose a factor 6 at most.
        for d in [-1.4999, 1.4999] {
            let k = Kernels::new(d);
            let direct_sin = d - d.sin();
            let direct_cos = 0.5 * d * d - (1.0 - d.cos());
            assert!(((k.minus_sin - direct_sin) / direct_sin).abs() < 8.0 * f64::EPSILON);
            assert!(((k.minus_cos - direct_cos) / direct_cos).abs() < 16.0 * f64::EPSILON);
        }
        let d = 1e-5;
        let k = Kernels::new(d);
        assert!((k.minus_sin / (d * d * d / 6.0 * (1.0 - d * d / 20.0)) - 1.0).abs() < 1e-15);
        assert!((k.minus_cos / (d.powi(4) / 24.0 * (1.0 - d * d / 30.0)) - 1.0).abs() < 1e-15);
    }

    /// A short slip near θ = π, where N_f ∝ 1 + cos ωt nearly vanishes (the pulled mass at
    /// φ ≪ 1): a = a1 (cos ωt − cos θc) from rest with a_c = 0 (μd = μs). The speed is
    /// (a1/ω) P(δ), P = −sin θc δ²/2 − cos θc δ³/6 + sin θc δ⁴/24 + cos θc δ⁵/120 − …, and the
    /// friction integral follows from it by 5-point Gauss–Legendre (exact to O(δ¹⁰) here). The
    /// form A0 w + (A1/ω)(sin ωt − sin ωt_c) lost about eps/δ² of v, and the integration by
    /// parts everything.
    #[test]
    fn a_short_trigonometric_arc_keeps_its_digits() {
        let (omega, a1) = (1.0, -2.0);
        let theta_c = std::f64::consts::PI - 2e-4;
        let start = Start {
            t: Dd::from(theta_c),
            x: 0.0,
            v: 0.0,
            a: 0.0,
        };
        let arc = Arc::from_start(Basis::Cos { omega, shift: 0.0 }, a1, start);
        let (sin_c, cos_c) = theta_c.sin_cos();
        let p = |d: f64| {
            -sin_c * d * d / 2.0 - cos_c * d.powi(3) / 6.0
                + sin_c * d.powi(4) / 24.0
                + cos_c * d.powi(5) / 120.0
                - sin_c * d.powi(6) / 720.0
        };
        let v = |w: f64| a1 / omega * p(omega * w);
        // Offsets that t = θc + w represents exactly.
        let exact = |w: f64| (theta_c + w) - theta_c;
        let w1 = exact(3e-4);
        for w in [1e-6, 1e-5, 1e-4, w1].map(exact) {
            let got = arc.v(theta_c + w);
            assert!((got / v(w) - 1.0).abs() < 1e-11, "w {w}: {got} vs {}", v(w));
        }
        // N_f = n_c + n1 (cos ωt − cos θc), n_c = 1 + cos θc (a normal force that nearly vanishes).
        let (n_c, n1) = (1.0 + cos_c, 1.0);
        let normal = |w: f64| {
            let d = omega * w;
            n_c - n1 * 2.0 * (theta_c + 0.5 * d).sin() * (0.5 * d).sin()
        };
        let half = 0.5 * w1;
        let gl5 = half
            * [
                (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
                (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
                (0.0, 0.568_888_888_888_888_9),
                (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
                (0.906_179_845_938_664, 0.236_926_885_056_189_1),
            ]
            .iter()
            .map(|&(node, weight)| {
                let w = half * (1.0 + node);
                weight * normal(w) * v(w)
            })
            .sum::<f64>();
        let got = arc.integrate_normal_times_speed(n_c, n1, theta_c + w1);
        assert!((got / gl5.abs() - 1.0).abs() < 1e-10, "{got} vs {gl5}");
    }
}
