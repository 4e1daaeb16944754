//! Event location: first up-crossing of a switching function that is affine in the basis, and
//! the zero of a monotone function on a bracket.
//!
//! Root finding is written here rather than taken from a crate because every call has an exact
//! derivative and a bracket on which the function is monotone: Newton's method safeguarded by
//! bisection converges in a few steps to the last bit (about 1e-16 relative).

use super::arc::cos_level_crossings_dd;
use super::dd::Dd;
use super::law::{Affine, Basis};
use crate::fmath;

/// Where a switching function starts to be positive (see [`first_up_crossing`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Crossing {
    /// Time (s, within the period), in two parts: a located root carries the digits below the
    /// ulp of its double, which a short slip after it needs.
    pub t: Dd,
    /// The basis value b(t) at a located root, where g = 0 exactly; `None` where g is positive
    /// already at the start of the search (or crossed zero within the resolution before it).
    pub root_b: Option<Dd>,
    /// (sin ωt, cos ωt) at a located root on a cos basis, from its basis value cos ωt = b: the
    /// phase of the arc that starts there, without sin and cos.
    pub phase: Option<(f64, f64)>,
}

impl Crossing {
    /// At time t, with (sin ωt, cos ωt) on a cos basis when known.
    fn at_once(t: f64, phase: Option<(f64, f64)>) -> Crossing {
        Crossing {
            t: Dd::from(t),
            root_b: None,
            phase,
        }
    }
}

/// Earliest time t in [from, to) at which g(t) = c0 + c1 b(t) is positive just after t, i.e.
/// g(t) > 0, or g(t) = 0 while increasing. `g` is the rounded switching function, on which the
/// search decides; `exact` gives its coefficients in two parts (g = s·D − μs·N_f formed
/// exactly), from which a root that is found is located to better than its ulp. `snap` (s) is
/// the resolution below which a crossing at `to` belongs to the next piece and a crossing at
/// `from` happens at `from`.
pub fn first_up_crossing(
    basis: Basis,
    g: Affine,
    exact: impl Fn() -> (Dd, Dd),
    from: f64,
    to: f64,
    snap: f64,
) -> Option<Crossing> {
    UpCrossings::new(basis, g, exact, to, snap).first(from, snap, None)
}

/// [`first_up_crossing`] with what does not depend on `from` worked out once: the roots of g on
/// a piece of the force law are the same in every period, and a run searches each piece for a
/// slip onset once or twice per period. The two-part root, and on a cos basis its arccosine,
/// are formed here, so that a search from a time is a few comparisons.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum UpCrossings {
    /// b = t − t_ref.
    Linear {
        t_ref: f64,
        g: Affine,
        /// Where g is increasing: its rounded root, and the located crossing there when the root
        /// lies before the end of the piece (less `snap`).
        rising: Option<(f64, Option<Crossing>)>,
    },
    /// b = cos ωt where g = c0 + c1 b is never positive.
    Never,
    /// b = cos ωt − shift.
    Cos {
        omega: f64,
        shift: f64,
        g: Affine,
        /// The crossings of g = 0 at which g rises in the period 2π/ω, in time order, located
        /// with their phase; those before `limit` are the piece's ([`UpCrossings::crossings`]).
        all: [Option<Crossing>; 2],
        /// The end of the piece less `snap` (s).
        limit: f64,
    },
}

impl UpCrossings {
    /// The crossings of g on a piece of `basis` that ends at `to` (see [`first_up_crossing`]).
    pub fn new(
        basis: Basis,
        g: Affine,
        exact: impl Fn() -> (Dd, Dd),
        to: f64,
        snap: f64,
    ) -> UpCrossings {
        // The basis value where g = 0, in two parts.
        let root_b = || {
            let (c0, c1) = exact();
            -c0 / c1
        };
        match basis {
            Basis::Linear { t_ref } => UpCrossings::Linear {
                t_ref,
                g,
                rising: (g.c1 > 0.0).then(|| {
                    let root = t_ref - g.c0 / g.c1;
                    let located = (root < to - snap).then(|| {
                        let b = root_b();
                        Crossing {
                            t: Dd::from(t_ref) + b,
                            root_b: Some(b),
                            phase: None,
                        }
                    });
                    (root, located)
                }),
            },
            // g ≤ c0 + |c1| < 0 everywhere: never positive (the usual case for the direction
            // opposite to the drive), decided without trigonometry.
            Basis::Cos { shift, .. } if g.c0 - g.c1 * shift + g.c1.abs() < 0.0 => {
                UpCrossings::Never
            }
            Basis::Cos { omega, shift } => {
                // The crossings θ/ω and (2π − θ)/ω of cos ωt = b, in two parts; g = c0 + c1 cos ωt
                // rises where c1·d(cos ωt)/dt > 0. Their lower limit depends on the start of the
                // search and is applied there (−∞ keeps every crossing a number).
                // The root in the basis, and the level of cos ωt there (b + shift).
                let root = root_b();
                let b = root + Dd::from(shift);
                // sin ωt > 0 at the first crossing θ/ω, < 0 at the second (2π − θ)/ω;
                // |sin| = √((1 − b)(1 + b)) with both factors formed from both parts of b.
                let sin = ((1.0 - b.hi - b.lo) * (1.0 + b.hi + b.lo)).sqrt();
                let rising = |c: Option<(Dd, i8)>, sin: f64| {
                    c.filter(|&(_, dir)| g.c1 * f64::from(dir) > 0.0)
                        .map(|(t, _)| Crossing {
                            t,
                            root_b: Some(root),
                            phase: Some((sin, b.value())),
                        })
                };
                let [first, second] =
                    cos_level_crossings_dd(b, omega, f64::NEG_INFINITY, f64::INFINITY);
                let all = [rising(first, sin), rising(second, -sin)];
                UpCrossings::Cos {
                    omega,
                    shift,
                    g,
                    all,
                    limit: to - snap,
                }
            }
        }
    }

    /// On a cos basis, the same crossings for a piece of the same basis and switching function
    /// that ends at `to` (they are located over all time, not the piece's span); `None` on a
    /// linear basis, whose located crossing depends on the end.
    #[inline]
    pub fn ending_at(self, to: f64, snap: f64) -> Option<UpCrossings> {
        match self {
            UpCrossings::Linear { .. } => None,
            UpCrossings::Never => Some(UpCrossings::Never),
            UpCrossings::Cos {
                omega,
                shift,
                g,
                all,
                ..
            } => Some(UpCrossings::Cos {
                omega,
                shift,
                g,
                all,
                limit: to - snap,
            }),
        }
    }

    /// On a cos basis, the crossings of g = 0 before the end of the piece (less `snap`) at
    /// which g rises, in time order; none on a linear basis.
    #[inline(always)]
    pub fn crossings(&self) -> [Option<Crossing>; 2] {
        match *self {
            UpCrossings::Cos {
                all: [first, second],
                limit,
                ..
            } => {
                let before_limit = |c: &Crossing| c.t.value() < limit;
                [first.filter(before_limit), second.filter(before_limit)]
            }
            _ => [None, None],
        }
    }

    /// A located root of g on the piece, if any (all of them have the same basis value).
    pub fn root(&self) -> Option<Crossing> {
        match *self {
            UpCrossings::Linear {
                rising: Some((_, located)),
                ..
            } => located,
            UpCrossings::Cos { .. } => self.crossings().into_iter().flatten().next(),
            _ => None,
        }
    }

    /// The earliest up-crossing in [from, to), see [`first_up_crossing`]. On a cos basis
    /// `phase` is (sin ωt, cos ωt) at t = `from` where the caller knows it (the start of a piece,
    /// a stick), else it is evaluated; a crossing at once carries it to the arc that starts
    /// there.
    #[inline(always)]
    pub fn first(&self, from: f64, snap: f64, phase: Option<(f64, f64)>) -> Option<Crossing> {
        match *self {
            UpCrossings::Linear { t_ref, g, rising } => match rising {
                Some((root, located)) => {
                    if root <= from + snap {
                        Some(Crossing::at_once(from, None))
                    } else {
                        located
                    }
                }
                None if g.at(from - t_ref) > 0.0 => Some(Crossing::at_once(from, None)),
                None => None,
            },
            UpCrossings::Never => None,
            UpCrossings::Cos {
                omega,
                shift,
                g,
                all,
                limit,
            } => {
                // At g = 0, look at the slope, and at the curvature where the slope vanishes too
                // (a tangency from above, e.g. F = 2μsW at t = 0 for the pulled mass).
                // sin ωt only where g = 0.
                let cos = phase.map_or_else(|| fmath::cos(omega * from), |(_, cos)| cos);
                let g_from = g.at(cos - shift);
                let rising = || {
                    let sin = phase.map_or_else(|| fmath::sin(omega * from), |(sin, _)| sin);
                    let slope = -g.c1 * omega * sin;
                    let curvature = -g.c1 * omega * omega * cos;
                    slope > 0.0 || (slope == 0.0 && curvature > 0.0)
                };
                if g_from > 0.0 || (g_from == 0.0 && rising()) {
                    return Some(Crossing::at_once(from, phase));
                }
                // An up-crossing within snap before `from` happens at `from`.
                let lo = from - snap;
                // The crossings are in time order: the first after `lo` is the piece's if any is.
                let c = all
                    .into_iter()
                    .flatten()
                    .find(|c| c.t.value() >= lo)
                    .filter(|c| c.t.value() < limit)?;
                if c.t.value() < from {
                    return Some(Crossing::at_once(from, phase));
                }
                Some(c)
            }
        }
    }
}

/// Zero of f on [lo, hi] where f(lo) > 0 ≥ f(hi) and f is monotone; `f` returns (f, f', f'')
/// and the bracket ends come with their values of f, the end `hi` with f' and f'' too. The
/// search starts from the zero of the Taylor parabola at `hi` (exact when f is a quadratic, as
/// the speed on a polynomial arc), or the secant where that parabola has no zero in the bracket.
/// With `refine` (f is no quadratic: a trigonometric arc's speed) that zero is first improved by
/// one Newton step on the cubic through the parabola and f(lo) ([`cubic_start`]), taken where it
/// stays inside the bracket: on the woodpecker's and the pulled mass' harmonic laws the search
/// then converges one evaluation sooner (the parabola alone starts about 10 % of the way from
/// `hi` off). Halley steps (cubic convergence) are accepted while they stay inside the
/// shrinking bracket, bisection otherwise.
///
/// Convergence is a Halley step below a few ulps of t whose Newton step f/f′ is as small: near
/// a tangency (f′ ≈ 0, e.g. a speed maximum at the end of the bracket) the Halley step
/// 2ff′/(2f′² − ff″) vanishes with f′ while f does not, and such a point is no root. The test
/// comes before the bracket test, so a sub-ulp step that lands on a bracket end ends the search
/// instead of restarting it by bisection.
///
/// With `refine`, too, the step after a converging one is predicted instead of evaluated where
/// it can be (a polynomial arc's speed is a quadratic, which the parabola start solves at once,
/// and its search keeps its bits without the cubic's and the prediction's divisions): with
/// cubic convergence, steps h₀, h₁ of consecutive Halley iterates (or the parabola's step from
/// `hi` and the first Halley step; not the cubic's step, whose error is no cube of a step) give
/// the next one as about |h₁|·|h₁/h₀|³. Where that is below [`PREDICTED_STEP_MAX`]·eps·|t|,
/// and h₁ is a contraction by at least [`CONTRACTION_MAX`] whose Newton step agrees with the
/// Halley step (within a factor 2: no tangency), the search ends at t − h₁ (within the
/// bracket) without the one more evaluation of f that would only confirm it.
#[inline]
pub fn monotone_zero(
    mut f: impl FnMut(f64) -> (f64, f64, f64),
    (lo, f_lo): (f64, f64),
    (hi, (f_hi, d1_hi, d2_hi)): (f64, (f64, f64, f64)),
    refine: bool,
) -> f64 {
    let (mut lo, mut hi) = (lo, hi);
    if f_hi == 0.0 {
        return hi;
    }
    // f_hi + f'·h + f''·h²/2 = 0 at the root h ≤ 0 nearest to hi (its form without
    // cancellation), else the secant.
    let root = (d1_hi * d1_hi - 2.0 * d2_hi * f_hi).sqrt();
    let parabola = hi - 2.0 * f_hi / (d1_hi - root);
    // The last step of a cubically converging kind that led to t (none after a secant or
    // bisection step, or the cubic's).
    let cubic = refine.then(|| cubic_start(parabola, (lo, f_lo), (hi, (f_hi, d1_hi, d2_hi))));
    let (mut t, mut last_step) = if let Some(t) = cubic.filter(|&t| t > lo && t < hi) {
        (t, None)
    } else if parabola > lo && parabola < hi {
        (parabola, Some(hi - parabola))
    } else {
        (lo + (hi - lo) * f_lo / (f_lo - f_hi), None)
    };
    for _ in 0..200 {
        if !(t > lo && t < hi) {
            (t, last_step) = (0.5 * (lo + hi), None);
        }
        let (ft, d1, d2) = f(t);
        if ft > 0.0 {
            lo = t;
        } else if ft < 0.0 {
            hi = t;
        } else {
            return t;
        }
        let denominator = 2.0 * d1 * d1 - ft * d2;
        let step = if denominator != 0.0 {
            2.0 * ft * d1 / denominator
        } else {
            f64::NAN
        };
        let next = t - step;
        // Cubic convergence: a step below a few ulps is the last one, unless f′ ≈ 0. Tested
        // before the width of the bracket, whose fallback costs two more evaluations of f.
        let tol = 4.0 * f64::EPSILON * t.abs();
        if step.abs() <= tol && ft.abs() <= tol * d1.abs() {
            return next.clamp(lo, hi);
        }
        if refine && last_step.is_some_and(|last| next_step_is_sub_ulp(last, step, ft / d1, t)) {
            return next.clamp(lo, hi);
        }
        if hi - lo <= 2.0 * f64::EPSILON * hi.abs().max(lo.abs()) {
            break;
        }
        (t, last_step) = if next > lo && next < hi {
            (next, Some(step))
        } else {
            (0.5 * (lo + hi), None)
        };
    }
    // Out of iterations (not seen in practice): the bracket end with the smaller residual.
    if f(lo).0.abs() < f(hi).0.abs() {
        lo
    } else {
        hi
    }
}

/// The start of [`monotone_zero`] improved by the value at `lo`: the cubic through the Taylor
/// parabola at `hi` and f(lo), one Newton step on it from the parabola's zero.
#[inline(always)]
fn cubic_start(
    parabola: f64,
    (lo, f_lo): (f64, f64),
    (hi, (f_hi, d1_hi, d2_hi)): (f64, (f64, f64, f64)),
) -> f64 {
    let width = lo - hi;
    let taylor = |h: f64| f_hi + h * (d1_hi + 0.5 * d2_hi * h);
    let c3 = (f_lo - taylor(width)) / (width * width * width);
    let h = parabola - hi;
    let value = taylor(h) + c3 * h * h * h;
    let slope = d1_hi + h * (d2_hi + 3.0 * c3 * h);
    parabola - value / slope
}

/// The largest predicted next step of [`monotone_zero`] that ends its search, in units of
/// eps·|t| (a few hundredths of an ulp of t, far below the accuracy of the predicted size).
const PREDICTED_STEP_MAX: f64 = 1.0 / 64.0;

/// The largest ratio |h₁/h₀| of consecutive steps from which [`monotone_zero`] predicts the
/// next step: well inside the cubic convergence.
const CONTRACTION_MAX: f64 = 1e-2;

/// Whether the Halley step `step` at t, after a step `last` of a cubically converging kind, is
/// the last one needed (see [`monotone_zero`]): it contracts by at least [`CONTRACTION_MAX`],
/// the Newton step `newton` = f/f′ agrees with it within a factor 2, and the next step,
/// predicted as |step|·|step/last|³, is below [`PREDICTED_STEP_MAX`]·eps·|t|.
#[inline(always)]
fn next_step_is_sub_ulp(last: f64, step: f64, newton: f64, t: f64) -> bool {
    let ratio = (step / last).abs();
    ratio <= CONTRACTION_MAX
        && newton.abs() <= 2.0 * step.abs()
        && step.abs() * ratio * ratio * ratio <= PREDICTED_STEP_MAX * f64::EPSILON * t.abs()
}

/// Roots of α w² + β w + γ = 0 without cancellation: q = −½(β + sgn β √(β² − 4αγ)), roots
/// q/α and γ/q (guide §4). Returns none when the discriminant is negative.
pub fn quadratic_roots(alpha: f64, beta: f64, gamma: f64) -> Vec<f64> {
    if alpha == 0.0 {
        return if beta != 0.0 {
            vec![-gamma / beta]
        } else {
            vec![]
        };
    }
    let disc = beta * beta - 4.0 * alpha * gamma;
    if disc < 0.0 {
        return vec![];
    }
    let q = -0.5 * (beta + beta.signum() * disc.sqrt());
    if q == 0.0 {
        return vec![0.0];
    }
    vec![q / alpha, gamma / q]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// g rounded, and in two parts from one-part coefficients.
    fn g(c0: f64, c1: f64) -> (Affine, impl Fn() -> (Dd, Dd)) {
        (Affine::new(c0, c1), move || (Dd::from(c0), Dd::from(c1)))
    }

    fn crossing(
        basis: Basis,
        (g, exact): (Affine, impl Fn() -> (Dd, Dd)),
        from: f64,
        to: f64,
        snap: f64,
    ) -> Option<Crossing> {
        first_up_crossing(basis, g, exact, from, to, snap)
    }

    fn at(c: Option<Crossing>) -> Option<f64> {
        c.map(|c| c.t.value())
    }

    #[test]
    fn linear_up_crossing_is_exact_and_respects_the_piece() {
        let basis = Basis::Linear { t_ref: 0.0 };
        let c = crossing(basis, g(-1.0, 4.0), 0.0, 1.0, 1e-16).unwrap();
        assert_eq!(c.t, Dd::from(0.25));
        assert_eq!(c.root_b, Some(Dd::from(0.25)));
        assert_eq!(at(crossing(basis, g(-1.0, 4.0), 0.0, 0.25, 1e-16)), None);
        assert_eq!(
            at(crossing(basis, g(-1.0, 4.0), 0.25, 1.0, 1e-16)),
            Some(0.25)
        );
        // Decreasing and positive: slip at once; decreasing and negative: never.
        let once = crossing(basis, g(1.0, -1.0), 0.5, 1.0, 1e-16).unwrap();
        assert_eq!((once.t.value(), once.root_b), (0.5, None));
        assert_eq!(at(crossing(basis, g(-1.0, -1.0), 0.0, 1.0, 1e-16)), None);
    }

    #[test]
    fn a_root_carries_the_digits_below_its_ulp() {
        // g = (t − 0.3) − 0.1: the root 0.3 + 0.1 is not a double; hi + lo holds it exactly.
        let basis = Basis::Linear { t_ref: 0.3 };
        let c = crossing(basis, g(-0.1, 1.0), 0.3, 1.0, 1e-16).unwrap();
        assert_eq!(c.root_b, Some(Dd::from(0.1)));
        assert_eq!(c.t, Dd::new(0.3, 0.1));
        assert!(c.t.lo != 0.0);
    }

    #[test]
    fn cos_up_crossing_skips_down_crossings_and_tangency() {
        let basis = Basis::Cos {
            omega: 1.0,
            shift: 0.0,
        };
        let tau = std::f64::consts::TAU;
        // g = −cos t: up-crossing at π/2.
        let c = crossing(basis, g(0.0, -1.0), 0.0, tau, 1e-15).unwrap();
        assert!((c.t.value() - std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        assert_eq!(c.root_b, Some(Dd::from(0.0)));
        assert_eq!(c.phase, Some((1.0, 0.0)));
        // g = 0.5 − cos t rises through zero at t = π/3, where sin t > 0; g = cos t − 0.5 at
        // 5π/3, where sin t < 0: the phase of each root is sin and cos of its time.
        for (c0, c1, from) in [(0.5, -1.0, 0.0), (-0.5, 1.0, 3.0)] {
            let c = crossing(basis, g(c0, c1), from, tau, 1e-15).unwrap();
            let (sin, cos) = c.phase.unwrap();
            let (sin_t, cos_t) = c.t.value().sin_cos();
            assert!((sin - sin_t).abs() < 4.0 * f64::EPSILON, "{sin} vs {sin_t}");
            assert!((cos - cos_t).abs() < 4.0 * f64::EPSILON, "{cos} vs {cos_t}");
        }
        // g = cos t − 1 ≤ 0 touches zero at 0: never positive.
        assert_eq!(at(crossing(basis, g(-1.0, 1.0), 0.1, tau, 1e-15)), None);
        // g = cos t, starting at 0 where g > 0: at once.
        assert_eq!(at(crossing(basis, g(0.0, 1.0), 0.0, tau, 1e-15)), Some(0.0));
    }

    #[test]
    fn monotone_zero_reaches_machine_precision() {
        let f = |t: f64| (2.0 - t.exp(), -t.exp(), -t.exp());
        for refine in [false, true] {
            let t = monotone_zero(f, (0.0, f(0.0).0), (2.0, f(2.0)), refine);
            assert!((t - 2f64.ln()).abs() <= 2.0 * f64::EPSILON);
        }
    }

    /// f(t) = v_m − (t − 1)² on [1, 1 + 1e-3]: a speed maximum v_m at the left end of the
    /// bracket, the zero at 1 + √v_m. The secant start lands a few ulps from the maximum, where
    /// f′ ≈ 0 makes the Halley step sub-ulp although f is not small: that is no convergence.
    #[test]
    fn a_tangency_at_the_bracket_end_is_not_a_root() {
        let v_m = 3.3e-19;
        let f = |t: f64| (v_m - (t - 1.0).powi(2), -2.0 * (t - 1.0), -2.0);
        let (lo, hi) = (1.0, 1.0 + 1e-3);
        let root = 1.0 + v_m.sqrt();
        for refine in [false, true] {
            let t = monotone_zero(f, (lo, f(lo).0), (hi, f(hi)), refine);
            assert!((t - root).abs() <= 4.0 * f64::EPSILON, "{t} vs {root}");
        }
    }

    /// Evaluations of f until convergence, for smooth monotone functions whose root the Halley
    /// steps reach within a few ulps: a sub-ulp last step that lands on a bracket end must end
    /// the search, not bisect and converge again. With the start refined and the last step
    /// predicted, the search ends as close to the root, with at most as many evaluations.
    #[test]
    fn a_sub_ulp_step_on_a_bracket_end_ends_the_search() {
        use std::cell::Cell;
        let calls = Cell::new(0);
        // The cube root of 5.50296: Halley lands on it with a step of many ulps, and the next
        // step is sub-ulp (43 evaluations when that restarted the search by bisection).
        type WithDerivatives = fn(f64) -> (f64, f64, f64);
        let cases: [(WithDerivatives, f64, f64); 3] = [
            (|t| (2.0 - t.exp(), -t.exp(), -t.exp()), 0.0, 2.0),
            (|t| (t.cos() - t, -t.sin() - 1.0, -t.cos()), 0.0, 1.5),
            (
                |t| (1.0 + 616.0 * 0.00731 - t * t * t, -3.0 * t * t, -6.0 * t),
                0.5,
                3.0,
            ),
        ];
        for (g, lo, hi) in cases {
            let evaluations = [false, true].map(|refine| {
                calls.set(0);
                let f = |t: f64| {
                    calls.set(calls.get() + 1);
                    g(t)
                };
                let t = monotone_zero(f, (lo, g(lo).0), (hi, g(hi)), refine);
                assert!(g(t).0.abs() <= 4.0 * f64::EPSILON, "residual at {t}");
                calls.get()
            });
            assert!(evaluations[0] <= 6, "{} evaluations", evaluations[0]);
            assert!(
                evaluations[1] <= evaluations[0],
                "{evaluations:?} evaluations"
            );
        }
    }

    #[test]
    fn quadratic_roots_keep_the_small_root_accurate() {
        let r = quadratic_roots(1.0, -1e8, 1.0);
        assert!(r.iter().any(|&x| ((x - 1e-8) / 1e-8).abs() < 1e-15));
        assert!(quadratic_roots(1.0, 0.0, 1.0).is_empty());
    }
}
