//! Dormand–Prince 5(4) ([`Dopri5`], `Setting::Tolerance(tol)`) with the stick/slip state
//! machine of the exact engine, events located on the dense output; also the plain smooth
//! integrator [`solve_smooth`] (used by the regularized-friction method).
//!
//! ```text
//! slipping, direction s:  y = (x, v),  y' = (v, (D − s μd N_f)/M)    stick switch  s·v
//! stuck:                  y = (x, 0) constant                         slip switch   G = |D| − μs N_f
//! ```
//!
//! * Steps: the standard tableau with FSAL (Hairer–Nørsett–Wanner I, Table 5.2); error norm
//!   RMS of e_i / (tol + tol·max(|y_i|, |y1_i|)) (atol = rtol = tol); new step
//!   h·clamp(0.9 err^(−1/5), 0.2, 5), no growth right after a rejection; first step by
//!   Hairer's heuristic. Steps end at the breakpoints of the force law (its piece boundaries,
//!   where the right-hand side has kinks) and at t_end.
//! * Forces of the position ([`System`], the belt's [`SurfaceProblem`]): a generic path,
//!   [`solve_system`], in the surface's frame u = x − v_s t, w = v − v_s, without the piece
//!   cache below; its stuck steps are 1/16 of the free period 2π/ω, ω = √(−(∂D/∂x)/M). Its
//!   state machine, [`drive_system`], also drives the diffsol peer on the belt.
//! * Dense output: the standard 4th-order continuous extension of DOPRI5 (Hairer's `contd5`,
//!   Shampine's coefficients), which matches y and y' at both step ends; formed only on a step
//!   whose stick check needs it ([`Accepted::dense`]).
//! * Stick events: a step on which s·v of the interpolant is provably positive after its start
//!   (lower bounds from v's coefficients, [`positive`]) has none; otherwise s·v is sampled at
//!   8 points of the step and at every minimum of s·v bracketed between them (where the
//!   interpolated s·a goes from − to +), so that a dip below zero and back inside one step is
//!   not missed (SciPy issue 9228); the first crossing is located by Illinois regula falsi on
//!   the interpolant to a few ulps of t. [`Dopri5EndpointsOnly`] checks the step ends only, to
//!   show that failure.
//! * Transitions (guide §4): at a stick time v := 0; STUCK if |D| ≤ μs N_f, otherwise a
//!   reversal to direction sgn D. The integration restarts from the event in the new mode
//!   (new first step, new FSAL stage).
//! * Stuck: nothing to integrate. G is sampled at 4 points per T/16 (and its sampled local
//!   maxima refined by golden-section search, so a brief excursion above 0 is seen); the onset
//!   is located on the exact force law by the same root finder, direction sgn D. Each G
//!   evaluation counts as one right-hand-side evaluation, each T/16 stretch as one step.
//! * Cost (benches/dopri5_instructions.rs): the force law is evaluated once per stage but the
//!   last (FSAL: at the sixth's time, [`Slip`]), on the piece remembered from the previous
//!   evaluation ([`Forces`], which also crosses a period boundary without `rem_euclid`), with
//!   no check at all on a step known to stay on one piece, the steps that land on a breakpoint
//!   or start from one included (the piece's formula continued to the breakpoint, where the
//!   law is continuous); the next breakpoint is kept while ahead; the interpolant is formed
//!   only where a stick is possible; the stage states, the new state, the error estimate and
//!   r5 of the interpolant are formed as a textbook forms them, y + h·Σ a_ij k_j (one product
//!   by h per sum, not one per coefficient). About 1.13–1.19× the instructions per step of a
//!   textbook DOPRI5 on the same slip equation (3.8× before).

use super::surface::{absolute, SurfaceProblem, System};
use super::{Method, MethodEvent, Problem, Setting, Solution, Stats};
use crate::engine::Basis;
use crate::error::{Error, Result};
use crate::fmath;

/// State (x, v) of the 2-D systems integrated here.
pub type State = [f64; 2];

/// Most steps one integration may take before it is declared stalled.
pub(crate) const MAX_STEPS: u64 = 10_000_000;

/// The method's constants, shared with the textbook and lean DOPRI5s of
/// benches/dopri5_instructions.rs, which integrate with exactly these.
pub mod tableau {
    /// Step-size controller: safety factor and limits of the factor h_new/h.
    pub const SAFETY: f64 = 0.9;
    pub const FAC_MIN: f64 = 0.2;
    pub const FAC_MAX: f64 = 5.0;

    // The Dormand–Prince 5(4) tableau (Hairer, Nørsett & Wanner I, Table 5.2; FSAL: the last stage
    // is f at the new point).
    pub const C2: f64 = 1.0 / 5.0;
    pub const C3: f64 = 3.0 / 10.0;
    pub const C4: f64 = 4.0 / 5.0;
    pub const C5: f64 = 8.0 / 9.0;
    pub const A21: f64 = 1.0 / 5.0;
    pub const A31: f64 = 3.0 / 40.0;
    pub const A32: f64 = 9.0 / 40.0;
    pub const A41: f64 = 44.0 / 45.0;
    pub const A42: f64 = -56.0 / 15.0;
    pub const A43: f64 = 32.0 / 9.0;
    pub const A51: f64 = 19372.0 / 6561.0;
    pub const A52: f64 = -25360.0 / 2187.0;
    pub const A53: f64 = 64448.0 / 6561.0;
    pub const A54: f64 = -212.0 / 729.0;
    pub const A61: f64 = 9017.0 / 3168.0;
    pub const A62: f64 = -355.0 / 33.0;
    pub const A63: f64 = 46732.0 / 5247.0;
    pub const A64: f64 = 49.0 / 176.0;
    pub const A65: f64 = -5103.0 / 18656.0;
    pub const A71: f64 = 35.0 / 384.0;
    pub const A73: f64 = 500.0 / 1113.0;
    pub const A74: f64 = 125.0 / 192.0;
    pub const A75: f64 = -2187.0 / 6784.0;
    pub const A76: f64 = 11.0 / 84.0;
    // Error coefficients b − b̂ (5th minus 4th order weights).
    pub const E1: f64 = 71.0 / 57600.0;
    pub const E3: f64 = -71.0 / 16695.0;
    pub const E4: f64 = 71.0 / 1920.0;
    pub const E5: f64 = -17253.0 / 339200.0;
    pub const E6: f64 = 22.0 / 525.0;
    pub const E7: f64 = -1.0 / 40.0;
    // Dense output of order 4 (Hairer's `contd5`, Shampine 1986).
    pub const D1: f64 = -12715105075.0 / 11282082432.0;
    pub const D3: f64 = 87487479700.0 / 32700410799.0;
    pub const D4: f64 = -10690763975.0 / 1880347072.0;
    pub const D5: f64 = 701980252875.0 / 199316789632.0;
    pub const D6: f64 = -1453857185.0 / 822651844.0;
    pub const D7: f64 = 69997945.0 / 29380423.0;
}
use tableau::*;

/// Σ_j w_j k_j, component by component, summed from the first term: a combination of the
/// stages with tableau weights. The two components are written out (with `array::from_fn`
/// the step kept a call per component and sum).
#[inline(always)]
fn combination<const N: usize>(w: [f64; N], k: [State; N]) -> State {
    let component = |i: usize| (1..N).fold(w[0] * k[0][i], |s, j| s + w[j] * k[j][i]);
    [component(0), component(1)]
}

/// y + h·Σ_j a_j k_j: the state at a stage (or at the step's end) from the earlier stages k_j
/// with the tableau's weights a_j.
#[inline(always)]
fn stage<const N: usize>(y: State, h: f64, a: [f64; N], k: [State; N]) -> State {
    let sum = combination(a, k);
    [y[0] + h * sum[0], y[1] + h * sum[1]]
}

/// RMS norm of `e` weighted by atol + rtol·max(|a|, |b|) with atol = rtol = tol.
fn weighted_norm(e: State, a: State, b: State, tol: f64) -> f64 {
    // Summed from the first square, not from 0 (a square is never −0: the same bits).
    let term = |i: usize| (e[i] / (tol + tol * a[i].abs().max(b[i].abs()))).powi(2);
    (0.5 * (term(0) + term(1))).sqrt()
}

/// A right-hand side y' = f(t, y) of the integrator: any closure, or [`Slip`].
pub(crate) trait Field {
    /// f(t, y).
    fn at(&self, t: f64, y: State) -> State;

    /// f(t, y) given k = f(t, z) at the same t: the last stage of a step (FSAL) is taken at
    /// the time of the sixth, so a field whose time-dependent part does not depend on y
    /// passes it on instead of evaluating it again.
    #[inline]
    fn at_same_time(&self, t: f64, y: State, k: State) -> State {
        let _ = k;
        self.at(t, y)
    }
}

impl<F: Fn(f64, State) -> State> Field for F {
    #[inline]
    fn at(&self, t: f64, y: State) -> State {
        self(t, y)
    }
}

/// The slip equations x' = v, v' = a(t), with the acceleration a(t) (m/s²) of a slip phase:
/// a depends on t only, so the FSAL stage reuses the sixth stage's (the same bits: one
/// evaluation of the force law less per step).
struct Slip<A>(A);

impl<A: Fn(f64) -> f64> Field for Slip<A> {
    #[inline]
    fn at(&self, t: f64, y: State) -> State {
        [y[1], (self.0)(t)]
    }

    #[inline]
    fn at_same_time(&self, _t: f64, y: State, k: State) -> State {
        [y[1], k[1]]
    }
}

/// One accepted step on [t0, t0 + h]: its ends and the stages its interpolant is formed from
/// (k2 has no weight in it), so that a step which needs no interpolant forms none.
#[derive(Clone, Copy, Debug)]
struct Accepted {
    t0: f64,
    t1: f64,
    h: f64,
    y0: State,
    y1: State,
    /// The stages k1, k3, k4, k5, k6, k7.
    k: [State; 6],
}

impl Accepted {
    /// The coefficients r1 … r5 of component i of the step's interpolant ([`Dense`]):
    /// r5 = h·Σ d_j k_j, the rest from the step's ends and its first and last stages.
    #[inline(always)]
    fn coefficients(&self, i: usize) -> [f64; 5] {
        let (h, k) = (self.h, self.k);
        let r5 = h * combination([D1, D3, D4, D5, D6, D7], k)[i];
        let ydiff = self.y1[i] - self.y0[i];
        let bspl = h * k[0][i] - ydiff;
        let r4 = ydiff - h * k[5][i] - bspl;
        [self.y0[i], ydiff, bspl, r4, r5]
    }

    /// The step's interpolant.
    fn dense(&self) -> Dense {
        let c = [self.coefficients(0), self.coefficients(1)];
        Dense {
            t0: self.t0,
            t1: self.t1,
            h: self.h,
            r: std::array::from_fn(|j| [c[0][j], c[1][j]]),
            y1: self.y1,
        }
    }
}

/// True when s·p is positive on the step after its start (θ ∈ (0, 1]) for the interpolant's
/// component p with coefficients `r` ([`Accepted::coefficients`]), by a margin that covers
/// the rounding of any evaluation of it (64 ε Σ|r_j|): positive on the whole step by the first
/// bound (the linear part is smallest at an end, θ(1−θ) ≤ 1/4, θ ≤ 1 bound the rest), or
/// s·r1 ≥ 0 (a step from a slip onset has s·r1 = 0) and q positive by the second
/// (θ(1−θ)² ≤ 4/27).
///
/// ```text
/// p = r1 + θ r2 + θ(1−θ) (r3 + θ r4 + θ(1−θ) r5) ≥ min(r1, r1 + r2) − (|r3| + |r4| + |r5|/4)/4
/// p = r1 + θ q,  q = r2 + (1−θ) r3 + θ(1−θ) r4 + θ(1−θ)² r5
///                  ≥ min(r2, r2 + r3) − |r4|/4 − 4|r5|/27
/// ```
fn positive(r: [f64; 5], s: f64) -> bool {
    // s = ±1 (a NaN fails every comparison below): only the signed terms take it.
    let [r1, r2, r3] = [s * r[0], s * r[1], s * r[2]];
    let (a4, a5) = (r[3].abs(), r[4].abs());
    let curve = r3.abs() + a4 + 0.25 * a5;
    let margin = 64.0 * f64::EPSILON * (r1.abs() + r2.abs() + curve);
    // Plain comparisons: a NaN fails them, as it should.
    if r1 - 0.25 * curve > margin && (r1 + r2) - 0.25 * curve > margin {
        return true;
    }
    let bend = 0.25 * a4 + 0.15 * a5;
    r1 >= 0.0 && r2 - bend > margin && (r2 + r3) - bend > margin
}

/// The continuous extension of one accepted step on [t0, t0 + h]: Hairer's 4th-order
/// interpolant, p(θ) = r1 + θ(r2 + (1−θ)(r3 + θ(r4 + (1−θ) r5))), θ = (t − t0)/h, which
/// matches y and f at both ends.
#[derive(Clone, Copy, Debug)]
struct Dense {
    t0: f64,
    t1: f64,
    h: f64,
    r: [State; 5],
    /// The step's end state, returned exactly at t1 (the next step starts from it).
    y1: State,
}

impl Dense {
    /// Interpolated state at time t.
    fn y(&self, t: f64) -> State {
        if t == self.t1 {
            return self.y1;
        }
        let th = (t - self.t0) / self.h;
        let th1 = 1.0 - th;
        let r = &self.r;
        std::array::from_fn(|i| {
            r[0][i] + th * (r[1][i] + th1 * (r[2][i] + th * (r[3][i] + th1 * r[4][i])))
        })
    }

    /// Time derivative of the interpolant at time t.
    fn dy(&self, t: f64) -> State {
        let th = (t - self.t0) / self.h;
        let th1 = 1.0 - th;
        let r = &self.r;
        std::array::from_fn(|i| {
            let u = r[2][i] + th * (r[3][i] + th1 * r[4][i]);
            let q = r[1][i] + th1 * u;
            let du = r[3][i] + (1.0 - 2.0 * th) * r[4][i];
            (q + th * (-u + th1 * du)) / self.h
        })
    }
}

/// Adaptive DOPRI5 on y' = f(t, y) from a given point, one accepted step at a time; f is
/// passed to each step, so that a step that stays on one piece of the force law can use a
/// right-hand side without per-evaluation checks (see [`Forces::on_piece`]).
struct Integrator {
    t: f64,
    y: State,
    /// f(t, y) (first stage of the next step, FSAL).
    k1: State,
    /// Proposed size of the next step.
    h: f64,
    tol: f64,
}

impl Integrator {
    /// Starts at (t0, y0) towards `t_dir_end`, choosing the first step by Hairer's heuristic
    /// (HNW I, II.4): h such that the explicit Euler error estimate is about tol.
    fn new(f: &impl Field, t0: f64, y0: State, t_end: f64, tol: f64, stats: &mut Stats) -> Self {
        let k1 = f.at(t0, y0);
        stats.rhs_evals += 1;
        let span = (t_end - t0).abs().max(f64::MIN_POSITIVE);
        let norm = |e: State| weighted_norm(e, y0, y0, tol);
        let (d0, d1) = (norm(y0), norm(k1));
        let h0 = if d0 < 1e-5 || d1 < 1e-5 {
            1e-6 * span
        } else {
            (0.01 * d0 / d1).min(span)
        };
        let y1 = [y0[0] + h0 * k1[0], y0[1] + h0 * k1[1]];
        let k2 = f.at(t0 + h0, y1);
        stats.rhs_evals += 1;
        let d2 = norm([k2[0] - k1[0], k2[1] - k1[1]]) / h0;
        let h1 = if d1.max(d2) <= 1e-15 {
            (h0 * 1e-3).max(1e-6 * span)
        } else {
            (0.01 / d1.max(d2)).powf(0.2)
        };
        let h = (100.0 * h0).min(h1).min(span);
        Self {
            t: t0,
            y: y0,
            k1,
            h,
            tol,
        }
    }

    /// One accepted step that ends at or before `t_stop` (> t); rejected attempts are retried
    /// with a smaller step. Returns the step (its dense output is formed on demand); (t, y, k1)
    /// move to its end.
    fn step(
        &mut self,
        f: &impl Field,
        t_stop: f64,
        h_max: f64,
        stats: &mut Stats,
    ) -> Result<Accepted> {
        let (t, y, k1) = (self.t, self.y, self.k1);
        let mut h = self.h.min(h_max);
        let mut rejected_last = false;
        loop {
            if stats.steps >= MAX_STEPS {
                return Err(Error::Stalled {
                    t,
                    reason: "dopri5: too many steps",
                });
            }
            // Land exactly on t_stop when it is within reach (or nearly: avoid a sliver step).
            let last = t + 1.01 * h >= t_stop;
            if last {
                h = t_stop - t;
            }
            let smallest = 8.0 * f64::EPSILON * t.abs().max(f64::MIN_POSITIVE);
            // Plain comparisons: a NaN fails them.
            if !(h > smallest && h < f64::INFINITY) {
                return Err(Error::Stalled {
                    t,
                    reason: "dopri5: step size underflow",
                });
            }
            stats.steps += 1;
            let k2 = f.at(t + C2 * h, stage(y, h, [A21], [k1]));
            let k3 = f.at(t + C3 * h, stage(y, h, [A31, A32], [k1, k2]));
            let k4 = f.at(t + C4 * h, stage(y, h, [A41, A42, A43], [k1, k2, k3]));
            let k5 = f.at(
                t + C5 * h,
                stage(y, h, [A51, A52, A53, A54], [k1, k2, k3, k4]),
            );
            let t1 = if last { t_stop } else { t + h };
            let k6 = f.at(
                t1,
                stage(y, h, [A61, A62, A63, A64, A65], [k1, k2, k3, k4, k5]),
            );
            let y1 = stage(y, h, [A71, A73, A74, A75, A76], [k1, k3, k4, k5, k6]);
            let k7 = f.at_same_time(t1, y1, k6);
            stats.rhs_evals += 6;
            // The error estimate y1 − ŷ1 = h·Σ (b_j − b̂_j) k_j.
            let sum = combination([E1, E3, E4, E5, E6, E7], [k1, k3, k4, k5, k6, k7]);
            let e = [h * sum[0], h * sum[1]];
            let err = weighted_norm(e, y, y1, self.tol);
            if !err.is_finite() {
                stats.rejected += 1;
                h *= FAC_MIN;
                rejected_last = true;
                continue;
            }
            let mut fac = (SAFETY * err.max(1e-300).powf(-0.2)).clamp(FAC_MIN, FAC_MAX);
            if err <= 1.0 {
                stats.accepted += 1;
                if rejected_last {
                    fac = fac.min(1.0);
                }
                let accepted = Accepted {
                    t0: t,
                    t1,
                    h,
                    y0: y,
                    y1,
                    k: [k1, k3, k4, k5, k6, k7],
                };
                self.t = t1;
                self.y = y1;
                self.k1 = k7;
                // A step cut short to land on t_stop says little about the next one.
                self.h = if last && h < self.h {
                    self.h.max(h * fac)
                } else {
                    h * fac
                };
                return Ok(accepted);
            }
            stats.rejected += 1;
            rejected_last = true;
            h *= fac.min(1.0);
        }
    }
}

/// Plain adaptive DOPRI5 (atol = rtol = `tol`) for a smooth 2-D ODE y' = f(t, y) from
/// (t0, y0) to t1 ≥ t0, without events. Returns y(t1) and the work done, or the error of a
/// stalled integration (step size underflow, more than 10^7 steps).
pub fn try_solve_smooth(
    f: impl Fn(f64, State) -> State,
    t0: f64,
    y0: State,
    t1: f64,
    tol: f64,
) -> Result<(State, Stats)> {
    let mut stats = Stats::default();
    smooth(f, t0, y0, t1, tol, &mut stats).map(|y| (y, stats))
}

/// [`try_solve_smooth`] that never fails: a stalled integration returns NaN for y(t1), with
/// the work done up to the stall.
pub fn solve_smooth(
    f: impl Fn(f64, State) -> State,
    t0: f64,
    y0: State,
    t1: f64,
    tol: f64,
) -> (State, Stats) {
    let mut stats = Stats::default();
    let y = smooth(f, t0, y0, t1, tol, &mut stats).unwrap_or([f64::NAN; 2]);
    (y, stats)
}

fn smooth(
    f: impl Fn(f64, State) -> State,
    t0: f64,
    y0: State,
    t1: f64,
    tol: f64,
    stats: &mut Stats,
) -> Result<State> {
    // An interval below the time resolution (e.g. two stop points one ulp apart) is no step.
    let resolution = |t: f64| 8.0 * f64::EPSILON * t1.abs().max(t.abs());
    if t1.partial_cmp(&(t0 + resolution(t0))) != Some(std::cmp::Ordering::Greater) {
        return Ok(y0);
    }
    let mut run = Integrator::new(&f, t0, y0, t1, tol, stats);
    while t1 - run.t > resolution(run.t) {
        run.step(&f, t1, f64::INFINITY, stats)?;
    }
    Ok(run.y)
}

/// D(t) and N_f(t) of a problem, bit for bit [`Problem::forces`], with the period and the
/// piece of the previous call remembered: the right-hand side is evaluated many times per
/// piece, so the lookup is done only when t leaves the piece, and the general one (a
/// `rem_euclid`, a search over the pieces, and all of it once for D and once for N_f) only
/// when t leaves the remembered period other than into the next one.
///
/// ```text
/// kT = hi + lo exactly (hi = fl(kT), lo = fma(k, T, −hi), for t ≥ 0)
/// fast path: τ = (t − hi) − lo, taken when τ ∈ [start, end) of the remembered piece
/// on leaving it: the same τ, or that of period k + 1, when in [0, T), and a search of the pieces
/// ```
///
/// A step known to stay on one piece evaluates it without these checks ([`Forces::on_piece`]).
///
/// Why bit for bit: t mod T (`fmod`, what `rem_euclid` is for t ≥ 0) is the exactly
/// representable t − nT with n = ⌊t/T⌋. τ is the one rounding of the real t − kT: either
/// lo = 0 (k = 0, 1, 2, …: kT exact), or k ≥ 3 and t − hi is exact (Sterbenz) unless t < hi/2
/// or t > 2 hi, where |t − hi| ≥ hi/2 > T puts τ outside [0, T). Rounding is monotone and 0,
/// T and the piece bounds are floats, so τ ∈ [0, T) implies the real t − kT ∈ [0, T), hence
/// k = n, the real value is representable and τ equals it; the piece containing τ is the one
/// [`crate::engine::ForceLaw::piece_at`] picks.
pub(crate) struct Forces<'a> {
    problem: &'a Problem,
    /// k, hi, lo of the remembered period (NaN: none yet) and the remembered piece.
    cache: std::cell::Cell<(f64, f64, f64, usize)>,
    /// One piece per period, a cosine of the period (ωT a multiple of 2π up to rounding, as
    /// T = 2π/ω): the piece's formula is T-periodic, so any period's offset gives its values
    /// up to rounding.
    periodic: bool,
}

impl<'a> Forces<'a> {
    pub(crate) fn new(problem: &'a Problem) -> Self {
        let law = &problem.law;
        let periodic = match law.pieces.as_slice() {
            [only] => match only.basis {
                Basis::Cos { omega, .. } => {
                    let turns = omega * law.period / std::f64::consts::TAU;
                    turns.round() >= 1.0
                        && (turns - turns.round()).abs() <= 8.0 * f64::EPSILON * turns
                }
                Basis::Linear { .. } => false,
            },
            _ => false,
        };
        Self {
            problem,
            cache: std::cell::Cell::new((f64::NAN, f64::NAN, 0.0, 0)),
            periodic,
        }
    }

    /// (D, N_f) at absolute time t (N).
    #[inline]
    pub(crate) fn at(&self, t: f64) -> (f64, f64) {
        let (_, hi, lo, i) = self.cache.get();
        let pieces = &self.problem.law.pieces;
        if let Some(piece) = pieces.get(i) {
            let local = (t - hi) - lo;
            if local >= piece.start && local < piece.end {
                let b = piece.basis.eval(local);
                return (piece.drive.at(b), piece.normal.at(b));
            }
        }
        self.lookup(t)
    }

    /// The piece that holds the times [t_a, t_b] of a step, to a few ulps of t_b at either end:
    /// the remembered one, or else the one after it (the next of the period, or the first of
    /// the next period), which is then remembered. Every t in [t_a, t_b] then has its τ in
    /// [start − slack, end + slack] by monotone rounding, so the piece's (D, N_f) at
    /// (t − hi) − lo is [`Forces::at`] without the check, but for the few ulps at the ends:
    /// there the piece's formula continues across its boundary, which gives the neighbouring
    /// piece's values up to rounding (the force laws are continuous in t; at a period boundary
    /// the harmonic law is smooth, the linear law has a kink). So a step that lands on the
    /// piece's end, and the step that starts from it, need no lookup per evaluation.
    ///
    /// A [`Forces::periodic`] law's step that lands on the period's end is taken on the next
    /// period (τ ∈ [−h, 0], when h ≤ T/2), which is then remembered: the same formula up to
    /// rounding, and the cosine of an argument near 0 costs less than one near 2π.
    fn on_piece(&self, t_a: f64, t_b: f64) -> Option<OnPiece<'a>> {
        let slack = 4.0 * f64::EPSILON * t_b.abs();
        let cache = self.cache.get();
        let held = self.holding(cache, t_a, t_b, (slack, slack));
        let (_, hi, lo, _) = cache;
        if let Some(on) = held {
            if !self.periodic || (t_b - hi) - lo < on.piece.end {
                return held;
            }
        }
        let next = self.following(cache);
        let back = if self.periodic {
            0.5 * self.problem.law.period
        } else {
            slack
        };
        match self.holding(next, t_a, t_b, (back, slack)) {
            Some(on) => {
                self.cache.set(next);
                Some(on)
            }
            None => held,
        }
    }

    /// The piece of `cache` (k, hi, lo, i) when its τ of t_a and t_b lie in
    /// [start − before, end + after].
    #[inline]
    fn holding(
        &self,
        (_, hi, lo, i): (f64, f64, f64, usize),
        t_a: f64,
        t_b: f64,
        (before, after): (f64, f64),
    ) -> Option<OnPiece<'a>> {
        let piece = self.problem.law.pieces.get(i)?;
        let (a, b) = ((t_a - hi) - lo, (t_b - hi) - lo);
        (a >= piece.start - before && b <= piece.end + after).then_some(OnPiece { hi, lo, piece })
    }

    /// (k, hi, lo, i) of the piece after that of `cache`: the next of the period, or the first
    /// of period k + 1 (hi + lo = (k + 1)T exactly).
    fn following(&self, (k, hi, lo, i): (f64, f64, f64, usize)) -> (f64, f64, f64, usize) {
        if i + 1 < self.problem.law.pieces.len() {
            (k, hi, lo, i + 1)
        } else {
            let (period, k) = (self.problem.law.period, k + 1.0);
            let hi = k * period;
            (k, hi, k.mul_add(period, -hi), 0)
        }
    }

    /// t off the remembered piece: on the piece after it (as a step crosses its end), in the
    /// remembered period or the next one, otherwise by the general path, remembering the
    /// period (for t ≥ 0) and the piece.
    #[cold]
    fn lookup(&self, t: f64) -> (f64, f64) {
        if let Some(forces) = self.next_piece_at(t) {
            return forces;
        }
        let period = self.problem.law.period;
        let (k, hi, lo, _) = self.cache.get();
        let next = k + 1.0;
        let hi_next = next * period;
        for (k, hi, lo) in [(k, hi, lo), (next, hi_next, next.mul_add(period, -hi_next))] {
            let local = (t - hi) - lo;
            if local >= 0.0 && local < period {
                return self.forces_at(local, Some((k, hi, lo)));
            }
        }
        let local = t.rem_euclid(period);
        let k = ((t - local) / period).round();
        let hi = k * period;
        let kept = (t >= 0.0).then(|| (k, hi, k.mul_add(period, -hi)));
        self.forces_at(local, kept)
    }

    /// (D, N_f) at t on the piece that follows the remembered one (the next of the period, or
    /// the first of the next period: hi and lo of k + 1), remembered when it holds t: no search
    /// where a step crosses a breakpoint. Its τ in [start, end) gives the bits of
    /// [`Forces::at`] as the remembered piece's does.
    fn next_piece_at(&self, t: f64) -> Option<(f64, f64)> {
        let next = self.following(self.cache.get());
        let (_, hi, lo, i) = next;
        let piece = self.problem.law.pieces.get(i)?;
        let local = (t - hi) - lo;
        if !(local >= piece.start && local < piece.end) {
            return None;
        }
        self.cache.set(next);
        let b = piece.basis.eval(local);
        Some((piece.drive.at(b), piece.normal.at(b)))
    }

    /// (D, N_f) at `local` = t mod T on the piece containing it, remembering that piece and
    /// the period `kept` (k, hi, lo) if any.
    fn forces_at(&self, local: f64, kept: Option<(f64, f64, f64)>) -> (f64, f64) {
        let pieces = &self.problem.law.pieces;
        let i = pieces
            .partition_point(|p| p.end <= local)
            .min(pieces.len() - 1);
        if let Some((k, hi, lo)) = kept {
            self.cache.set((k, hi, lo, i));
        }
        let piece = &pieces[i];
        let b = piece.basis.eval(local);
        (piece.drive.at(b), piece.normal.at(b))
    }
}

/// One piece of the force law and its period offset hi + lo (see [`Forces`]), for times known
/// to lie on it.
#[derive(Clone, Copy)]
struct OnPiece<'a> {
    hi: f64,
    lo: f64,
    piece: &'a crate::engine::Piece,
}

/// Switching-function checks per accepted step: the interpolant is sampled at this many
/// equally spaced points (the last one is the step end), plus every zero of its derivative
/// found between samples.
const SAMPLES: u32 = 8;
/// Stuck stretches are walked in steps of the period over this (each sampled at
/// `STUCK_SAMPLES` points): the state is constant, only the static switching function is watched.
const STUCK_STEPS_PER_PERIOD: f64 = 16.0;
/// Samples of the static switching function per stuck step.
const STUCK_SAMPLES: u32 = 4;
/// More events than this at one instant means the state machine cannot advance.
const MAX_EVENTS_AT_ONE_TIME: u32 = 16;

/// Dormand–Prince 5(4) with events located on the dense output, checked at interior points of
/// every step (see [`Options::interior_checks`]). Setting: `Setting::Tolerance(tol)`.
pub struct Dopri5;

/// [`Dopri5`] with the switching function checked at step ends only, as most event-location
/// codes do: two sign changes of s·v inside one step go unseen (the "events missed" failure).
pub struct Dopri5EndpointsOnly;

impl Method for Dopri5 {
    fn name(&self) -> &'static str {
        "dopri5"
    }

    fn solve(&self, problem: &Problem, setting: Setting) -> Result<Solution> {
        solve_with(
            problem,
            setting.tolerance(self.name())?,
            &Options::default(),
        )
    }

    /// The generic path ([`solve_system`]): the fast path's piece cache is for forces of
    /// time only.
    fn solve_surface(&self, problem: &SurfaceProblem, setting: Setting) -> Result<Solution> {
        solve_system(
            problem,
            setting.tolerance(self.name())?,
            &Options::default(),
        )
    }
}

impl Method for Dopri5EndpointsOnly {
    fn name(&self) -> &'static str {
        "dopri5_endpoints"
    }

    fn solve(&self, problem: &Problem, setting: Setting) -> Result<Solution> {
        let opts = Options {
            interior_checks: false,
            ..Options::default()
        };
        solve_with(problem, setting.tolerance(self.name())?, &opts)
    }

    fn solve_surface(&self, problem: &SurfaceProblem, setting: Setting) -> Result<Solution> {
        let opts = Options {
            interior_checks: false,
            ..Options::default()
        };
        solve_system(problem, setting.tolerance(self.name())?, &opts)
    }
}

/// Options of the event-driven integration.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// Check s·v at `SAMPLES` interior points of each step and at the zeros of its derivative
    /// (true), or at the step end only (false).
    pub interior_checks: bool,
    /// Largest step (s), slipping or stuck.
    pub h_max: f64,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            interior_checks: true,
            h_max: f64::INFINITY,
        }
    }
}

/// What one step of a phase ends with (STYLE habit 9): the driver applies the transition.
enum Advance {
    /// An ordinary step; the phase goes on.
    Step,
    /// The switching function of the phase crossed zero at `t`, with position `x` there.
    Event { t: f64, x: f64 },
    /// The phase reached t_end with state `y`.
    End { y: State },
}

/// Integrates `problem` with tolerance `tol` (atol = rtol) under `opts`.
pub fn solve_with(problem: &Problem, tol: f64, opts: &Options) -> Result<Solution> {
    let labels = Labels {
        recurring: "dopri5: events keep recurring at one instant",
        too_many_steps: "dopri5: too many steps",
    };
    drive(problem, opts, &labels, |forces, t, x, s, stats| {
        let body = problem.body;
        let f = Slip(|t| {
            let (d, n) = forces.at(t);
            body.slip_acceleration(d, n, s)
        });
        let mut slide = Integrator::new(&f, t, [x, 0.0], problem.t_end, tol, stats);
        let mut stop = f64::NAN;
        loop {
            match slip_advance(&mut slide, forces, &mut stop, s, opts, stats)? {
                Advance::Step => {}
                Advance::Event { t, x } => return Ok(SlipEnd::Stop { t, x }),
                Advance::End { y } => return Ok(SlipEnd::End { y }),
            }
        }
    })
}

/// How one slip phase ends: s·v reached 0 at `t` with position `x`, or t_end with state `y`.
pub(crate) enum SlipEnd {
    Stop { t: f64, x: f64 },
    End { y: State },
}

/// The messages of the stalls of [`drive`], naming the method.
pub(crate) struct Labels {
    /// More than [`MAX_EVENTS_AT_ONE_TIME`] events at one instant.
    pub recurring: &'static str,
    /// More than [`MAX_STEPS`] steps (counted in `Stats::steps`, stuck steps included).
    pub too_many_steps: &'static str,
}

/// The stick/slip state machine shared by the event-locating adaptive methods (this file's
/// DOPRI5 and the diffsol peer of the benchmark): from rest at x = 0, t = 0, stuck phases are
/// walked by [`Stuck`] (the onset located on the exact force law, direction sgn D); each slip
/// phase in direction s is integrated by `slip(forces, t0, x0, s, stats)` from (x0, v = 0)
/// until s·v reaches 0 or t_end. At a stop: v := 0, STUCK if |D| ≤ μs N_f, a reversal to
/// sgn D if D pushes the other way, otherwise the slip goes on in the same direction (no event,
/// as in the exact engine).
pub(crate) fn drive(
    problem: &Problem,
    opts: &Options,
    labels: &Labels,
    mut slip: impl FnMut(&Forces, f64, f64, f64, &mut Stats) -> Result<SlipEnd>,
) -> Result<Solution> {
    let mut stats = Stats::default();
    // The capacity of a vector's first growth, allocated at once.
    let mut events = Vec::with_capacity(4);
    let (mut t, mut x) = (0.0_f64, 0.0_f64);
    let mut v_end = 0.0;
    // Direction of slip, 0 when stuck.
    let mut dir = 0.0_f64;
    let mut at_same_time = (t, 0u32);
    let mut record = |t: f64, kind: &'static str| events.push(MethodEvent { t, kind });
    let forces = Forces::new(problem);
    'phases: while t < problem.t_end {
        count_at_same_time(&mut at_same_time, t, labels)?;
        if dir == 0.0 {
            let mut stuck = Stuck::new(t, x, margin(&forces, t, &mut stats));
            let h = (problem.law.period / STUCK_STEPS_PER_PERIOD).min(opts.h_max);
            loop {
                let stop = (stuck.t + h)
                    .min(next_breakpoint(problem, stuck.t))
                    .min(problem.t_end);
                let g = |t, stats: &mut Stats| margin(&forces, t, stats);
                match stuck.advance(stop, problem.t_end, g, labels, &mut stats)? {
                    Advance::Step => {}
                    Advance::Event { t: onset, .. } => {
                        record(onset, "slip");
                        dir = forces.at(onset).0.signum();
                        t = onset;
                        continue 'phases;
                    }
                    Advance::End { y } => {
                        (x, v_end) = (y[0], y[1]);
                        break 'phases;
                    }
                }
            }
        }
        let s = dir;
        match slip(&forces, t, x, s, &mut stats)? {
            SlipEnd::Stop { t: te, x: xe } => {
                (t, x) = (te, xe);
                let (d, n) = forces.at(te);
                if d.abs() <= problem.body.mu_s * n {
                    record(te, "stick");
                    dir = 0.0;
                } else if d.signum() != s {
                    record(te, "reversal");
                    dir = d.signum();
                }
                // Otherwise v touched 0 where the drive keeps pushing the same way: the
                // slip goes on (no event, as in the exact engine).
            }
            SlipEnd::End { y } => {
                (x, v_end) = (y[0], y[1]);
                break 'phases;
            }
        }
    }
    Ok(Solution::new(events, x, v_end, stats))
}

/// Counts the phases that start at t, in `at` (time, count): more than
/// [`MAX_EVENTS_AT_ONE_TIME`] at one instant is a stall.
fn count_at_same_time(at: &mut (f64, u32), t: f64, labels: &Labels) -> Result<()> {
    if at.0 == t {
        at.1 += 1;
        if at.1 > MAX_EVENTS_AT_ONE_TIME {
            return Err(Error::Stalled {
                t,
                reason: labels.recurring,
            });
        }
    } else {
        *at = (t, 0);
    }
    Ok(())
}

/// The generic path: the state machine of [`drive`] on any [`System`] (the belt), in the
/// surface's frame u = x − v_s t, w = v − v_s (sticking is w = 0), without the fast path's
/// piece cache ([`drive_system`]). Slipping: y = (u, w), y' = (w, a(t, u + v_s t)) with the
/// force read at each stage (it depends on the position, so no FSAL reuse); stick located on
/// w's interpolant.
fn solve_system(problem: &impl System, tol: f64, opts: &Options) -> Result<Solution> {
    let labels = Labels {
        recurring: "dopri5: events keep recurring at one instant",
        too_many_steps: "dopri5: too many steps",
    };
    let (t_end, v_s) = (problem.t_end(), problem.surface_speed());
    drive_system(problem, opts, &labels, |t, u, s, stats| {
        let f = |t: f64, y: State| [y[1], problem.slip_acceleration(t, y[0] + v_s * t, s)];
        let mut run = Integrator::new(&f, t, [u, 0.0], t_end, tol, stats);
        loop {
            let stop = problem.breakpoint_after(run.t).min(t_end);
            let step = run.step(&f, stop, opts.h_max, stats)?;
            if !positive(step.coefficients(1), s) {
                let dense = step.dense();
                let samples = if opts.interior_checks { SAMPLES } else { 1 };
                if let Some(te) = first_stick(&dense, s, samples) {
                    return Ok(SlipEnd::Stop {
                        t: te,
                        x: dense.y(te)[0],
                    });
                }
            }
            if run.t >= t_end {
                return Ok(SlipEnd::End { y: run.y });
            }
        }
    })
}

/// The stick/slip state machine of [`drive`] on any [`System`], in the surface's frame
/// u = x − v_s t, w = v − v_s (sticking is w = 0), shared by the event-locating adaptive
/// methods' generic paths (this file's DOPRI5 and the diffsol peer): from rest relative to
/// the surface at u = 0, t = 0, stuck phases are walked by [`Stuck`] on
/// G(t) = |D(t, u + v_s t)| − μs N_f, in steps of 1/[`STUCK_STEPS_PER_PERIOD`] of the free
/// period 2π/ω, ω = √(−∂D/∂x / M), when the force pulls back (the whole span to the next
/// breakpoint otherwise: on the belt G is then |affine in t| − constant, convex, above 0
/// within a step only if at its end), the onset in direction sgn D. Each slip phase in
/// direction s is integrated by `slip(t0, u0, s, stats)` from (u0, w = 0) until s·w reaches 0
/// (`SlipEnd::Stop`, its x the u there) or t_end (`SlipEnd::End`, its y = (u, w)); the
/// transitions are [`drive`]'s.
pub(crate) fn drive_system(
    problem: &impl System,
    opts: &Options,
    labels: &Labels,
    mut slip: impl FnMut(f64, f64, f64, &mut Stats) -> Result<SlipEnd>,
) -> Result<Solution> {
    let (t_end, v_s, body) = (problem.t_end(), problem.surface_speed(), *problem.body());
    let forces = |t: f64, u: f64| problem.forces(t, u + v_s * t);
    let margin = |t: f64, u: f64, stats: &mut Stats| {
        stats.rhs_evals += 1;
        let (d, n) = forces(t, u);
        d.abs() - body.mu_s * n
    };
    let gradient = problem.force_gradient();
    let stuck_h = if gradient < 0.0 {
        std::f64::consts::TAU / (-gradient / body.mass).sqrt() / STUCK_STEPS_PER_PERIOD
    } else {
        f64::INFINITY
    }
    .min(opts.h_max);
    let mut stats = Stats::default();
    let mut events = Vec::with_capacity(4);
    let (mut t, mut u, mut w_end) = (0.0_f64, 0.0_f64, 0.0_f64);
    // Direction of slip relative to the surface, 0 when stuck.
    let mut dir = 0.0_f64;
    let mut at_same_time = (t, 0u32);
    'phases: while t < t_end {
        count_at_same_time(&mut at_same_time, t, labels)?;
        if dir == 0.0 {
            let mut stuck = Stuck::new(t, u, margin(t, u, &mut stats));
            loop {
                let stop = (stuck.t + stuck_h)
                    .min(problem.breakpoint_after(stuck.t))
                    .min(t_end);
                let g = |t, stats: &mut Stats| margin(t, u, stats);
                match stuck.advance(stop, t_end, g, labels, &mut stats)? {
                    Advance::Step => {}
                    Advance::Event { t: onset, .. } => {
                        events.push(MethodEvent {
                            t: onset,
                            kind: "slip",
                        });
                        dir = forces(onset, u).0.signum();
                        t = onset;
                        continue 'phases;
                    }
                    Advance::End { .. } => break 'phases,
                }
            }
        }
        let s = dir;
        let (te, ue) = match slip(t, u, s, &mut stats)? {
            SlipEnd::Stop { t, x } => (t, x),
            SlipEnd::End { y } => {
                (u, w_end) = (y[0], y[1]);
                break 'phases;
            }
        };
        (t, u) = (te, ue);
        let (d, n) = forces(te, ue);
        if d.abs() <= body.mu_s * n {
            events.push(MethodEvent {
                t: te,
                kind: "stick",
            });
            dir = 0.0;
        } else if d.signum() != s {
            events.push(MethodEvent {
                t: te,
                kind: "reversal",
            });
            dir = d.signum();
        }
    }
    let (x_end, v_end) = absolute(problem, t_end, u, w_end);
    Ok(Solution::new(events, x_end, v_end, stats))
}

/// One accepted slipping step up to the next breakpoint of the force law or t_end, with the
/// stick switching function s·v checked on the step's interpolant.
/// `stop` is the end of the previous step's search (NaN at the start of a slip): it is still
/// the next breakpoint while it lies beyond the slack of [`next_breakpoint`].
///
/// The right-hand side is v' = (D − s μd N_f)/M. No attempt of the step goes past its reach:
/// `stop` when the first attempt may land on it, otherwise t + h. When [t, reach] lies on one
/// piece of the force law, up to a few ulps at its ends ([`Forces::on_piece`]: the remembered
/// piece or the one after it; a landing step on the end of a period of the harmonic law is
/// taken on the next period), every stage of the step is evaluated on that piece: its
/// right-hand side then checks nothing per evaluation, which lets the compiler schedule the
/// six stages like a textbook DOPRI5's. The values are [`Forces::at`]'s but at a step's ends
/// that lie on a breakpoint, where the piece's formula is continued to it (the force laws
/// are continuous: a difference in rounding only).
fn slip_advance(
    run: &mut Integrator,
    forces: &Forces,
    stop: &mut f64,
    s: f64,
    opts: &Options,
    stats: &mut Stats,
) -> Result<Advance> {
    let problem = forces.problem;
    let ahead = run.t + 4.0 * f64::EPSILON * run.t.abs();
    if (*stop).partial_cmp(&ahead) != Some(std::cmp::Ordering::Greater) {
        *stop = next_breakpoint(problem, run.t).min(problem.t_end);
    }
    let body = problem.body;
    let h = run.h.min(opts.h_max);
    // A step that may land on `stop` reaches it, otherwise t + h at most.
    let reach = if run.t + 1.01 * h >= *stop {
        *stop
    } else {
        run.t + h
    };
    let on_piece = forces.on_piece(run.t, reach);
    let step = match on_piece {
        // The basis matched once per step, not at each evaluation (the same operations).
        Some(OnPiece { hi, lo, piece }) => match piece.basis {
            Basis::Cos { omega, shift } => {
                let f = Slip(move |t| {
                    let b = fmath::cos(omega * ((t - hi) - lo)) - shift;
                    body.slip_acceleration(piece.drive.at(b), piece.normal.at(b), s)
                });
                run.step(&f, *stop, opts.h_max, stats)?
            }
            Basis::Linear { t_ref } => {
                let f = Slip(move |t| {
                    let b = ((t - hi) - lo) - t_ref;
                    body.slip_acceleration(piece.drive.at(b), piece.normal.at(b), s)
                });
                run.step(&f, *stop, opts.h_max, stats)?
            }
        },
        None => {
            let f = Slip(|t| {
                let (d, n) = forces.at(t);
                body.slip_acceleration(d, n, s)
            });
            run.step(&f, *stop, opts.h_max, stats)?
        }
    };
    // Most steps are far from a stick: s·v > 0 on the whole step, so every sample of
    // `first_stick` would be positive and nothing would be found.
    if !positive(step.coefficients(1), s) {
        let dense = step.dense();
        let samples = if opts.interior_checks { SAMPLES } else { 1 };
        if let Some(te) = first_stick(&dense, s, samples) {
            return Ok(Advance::Event {
                t: te,
                x: dense.y(te)[0],
            });
        }
    }
    if run.t >= problem.t_end {
        return Ok(Advance::End { y: run.y });
    }
    Ok(Advance::Step)
}

/// Earliest time in (t0, t1] of the step at which s·v of the interpolant reaches 0, checked
/// at `samples` equally spaced points and, when `samples` > 1, at every minimum of s·v
/// bracketed between them (d(s·v)/dt from − to +): a dip of s·v below 0 and back inside one
/// step is seen (SciPy issue 9228 is this dip missed).
fn first_stick(dense: &Dense, s: f64, samples: u32) -> Option<f64> {
    let g = |t: f64| s * dense.y(t)[1];
    let dg = |t: f64| s * dense.dy(t)[1];
    let t0 = dense.t0;
    // Right after a slip onset s·v = 0 at t0; it is positive just after (s·a > 0 there), so
    // t0 counts as "before the event".
    let mut prev = (t0, g(t0).max(f64::MIN_POSITIVE), dg(t0));
    for j in 1..=samples {
        let tj = if j == samples {
            dense.t1
        } else {
            t0 + dense.h * f64::from(j) / f64::from(samples)
        };
        let gj = g(tj);
        let dj = if samples > 1 { dg(tj) } else { 0.0 };
        if prev.2 < 0.0 && dj > 0.0 {
            // A minimum of s·v between the samples: it may dip below 0 and come back.
            let tm = locate(
                |t| {
                    let d = -dg(t);
                    (d > 0.0, d)
                },
                (prev.0, -prev.2),
                (tj, -dj),
            );
            let gm = g(tm);
            if gm <= 0.0 {
                return Some(locate(|t| stick_side(g(t)), (prev.0, prev.1), (tm, gm)));
            }
            prev = (tm, gm, dg(tm));
        }
        if gj <= 0.0 {
            return Some(locate(|t| stick_side(g(t)), (prev.0, prev.1), (tj, gj)));
        }
        prev = (tj, gj, dj);
    }
    None
}

/// Before the stick while s·v > 0.
fn stick_side(g: f64) -> (bool, f64) {
    (g > 0.0, g)
}

/// A stuck stretch: the state is constant; the static switching function
/// G(t) = |D(t)| − μs N_f(t) is sampled until it becomes positive (ties stay stuck).
struct Stuck {
    t: f64,
    /// Position where the body rests (m).
    x: f64,
    /// The last two samples (t, G), to spot a local maximum of G between samples.
    last: [(f64, f64); 2],
}

impl Stuck {
    /// Stuck at x from t, where G is `g`.
    fn new(t: f64, x: f64, g: f64) -> Self {
        Self {
            t,
            x,
            last: [(t, g), (t, g)],
        }
    }

    /// One stuck step to `stop` (≤ `t_end`), G sampled by `margin(t, stats)` (one evaluation
    /// each).
    fn advance(
        &mut self,
        stop: f64,
        t_end: f64,
        mut margin: impl FnMut(f64, &mut Stats) -> f64,
        labels: &Labels,
        stats: &mut Stats,
    ) -> Result<Advance> {
        let (t0, g0) = self.last[1];
        if t0 == self.t && g0 > 0.0 {
            return Ok(Advance::Event { t: t0, x: self.x });
        }
        if stats.steps >= MAX_STEPS {
            return Err(Error::Stalled {
                t: self.t,
                reason: labels.too_many_steps,
            });
        }
        stats.steps += 1;
        stats.accepted += 1;
        for j in 1..=STUCK_SAMPLES {
            let tj = if j == STUCK_SAMPLES {
                stop
            } else {
                self.t + (stop - self.t) * f64::from(j) / f64::from(STUCK_SAMPLES)
            };
            let gj = margin(tj, stats);
            let [(ta, ga), (tb, gb)] = self.last;
            if gj > 0.0 {
                let te = locate(|t| stuck_side(margin(t, stats)), (tb, -gb), (tj, -gj));
                return Ok(Advance::Event { t: te, x: self.x });
            }
            if gb > ga && gb > gj {
                // A sampled maximum below 0: look for the true maximum between the neighbours.
                let (tm, gm) = maximize(|t| margin(t, stats), ta, (tb, gb), tj);
                if gm > 0.0 {
                    let side = |t| stuck_side(margin(t, stats));
                    let te = locate(side, (ta, -ga), (tm, -gm));
                    return Ok(Advance::Event { t: te, x: self.x });
                }
            }
            self.last = [(tb, gb), (tj, gj)];
        }
        self.t = stop;
        if stop >= t_end {
            return Ok(Advance::End { y: [self.x, 0.0] });
        }
        Ok(Advance::Step)
    }
}

/// Before the slip onset while G ≤ 0 (ties stay stuck); the value is −G.
fn stuck_side(g: f64) -> (bool, f64) {
    (g <= 0.0, -g)
}

/// G(t) = |D| − μs N_f (N), counted as one right-hand-side evaluation.
fn margin(forces: &Forces, t: f64, stats: &mut Stats) -> f64 {
    stats.rhs_evals += 1;
    let (d, n) = forces.at(t);
    d.abs() - forces.problem.body.mu_s * n
}

/// Golden-section search for the maximum of f on [a, c] given fb = f(b) ≥ f(a), f(c), to
/// 1e-12 relative in t.
fn maximize(mut f: impl FnMut(f64) -> f64, a: f64, (b, fb): (f64, f64), c: f64) -> (f64, f64) {
    const R: f64 = 0.381_966_011_250_105_1;
    let (mut a, mut c) = (a, c);
    let (mut b, mut fb) = (b, fb);
    for _ in 0..60 {
        if c - a <= 1e-12 * c.abs().max(a.abs()) {
            break;
        }
        // Probe the larger of the two parts.
        let probe = if c - b > b - a {
            b + R * (c - b)
        } else {
            b - R * (b - a)
        };
        let fp = f(probe);
        if fp > fb {
            if probe > b {
                a = b;
            } else {
                c = b;
            }
            (b, fb) = (probe, fp);
        } else if probe > b {
            c = probe;
        } else {
            a = probe;
        }
    }
    (b, fb)
}

/// The boundary in (a, b] between "before" and "after" an event, to a few ulps of t:
/// `side(t)` returns (before?, value) with value > 0 before and ≤ 0 after (the value at `a`
/// is taken as positive). Illinois regula falsi, with a bisection whenever two steps did not
/// halve the bracket. Returns the bracket end on the "after" side.
pub(super) fn locate(
    mut side: impl FnMut(f64) -> (bool, f64),
    (a, fa): (f64, f64),
    (b, fb): (f64, f64),
) -> f64 {
    let (mut a, mut fa, mut b, mut fb) = (a, fa.max(f64::MIN_POSITIVE), b, fb.min(0.0));
    let mut kept = 0i8;
    let mut width = b - a;
    for i in 0..400 {
        if b - a <= 2.0 * f64::EPSILON * a.abs().max(b.abs()) {
            break;
        }
        let mut t = if fb < fa {
            (a * fb - b * fa) / (fb - fa)
        } else {
            f64::NAN
        };
        if i % 3 == 2 {
            if b - a > 0.5 * width {
                t = f64::NAN;
            }
            width = b - a;
        }
        if !(t > a && t < b) {
            t = 0.5 * (a + b);
            if !(t > a && t < b) {
                break;
            }
        }
        let (before, ft) = side(t);
        if before {
            (a, fa) = (t, ft.max(f64::MIN_POSITIVE));
            if kept == 1 {
                fb *= 0.5;
            }
            kept = 1;
        } else {
            (b, fb) = (t, ft.min(0.0));
            if kept == -1 {
                fa *= 0.5;
            }
            kept = -1;
        }
    }
    b
}

/// The first breakpoint of the force law (piece boundary, absolute time) after t: the
/// right-hand side is only piecewise smooth, so steps end there (known time events).
pub(super) fn next_breakpoint(problem: &Problem, t: f64) -> f64 {
    let period = problem.law.period;
    let base = (t / period).floor();
    let slack = 4.0 * f64::EPSILON * t.abs();
    for k in 0..3 {
        let start = (base + f64::from(k)) * period;
        for piece in &problem.law.pieces {
            let b = start + piece.end;
            if b > t + slack {
                return b;
            }
        }
    }
    f64::INFINITY
}

#[cfg(test)]
mod tests {
    use super::super::test_support::{
        back_and_forth, event_error, exact, last_period_kinds, pulled, set_b, woodpecker_fig15,
    };
    use super::*;
    use crate::engine::{Affine, Basis, Body, ForceLaw, Piece};
    use crate::models::LawKind;

    #[test]
    fn smooth_oscillator_meets_the_tolerance() {
        let (y, stats) = solve_smooth(|_, y| [y[1], -y[0]], 0.0, [1.0, 0.0], 10.0, 1e-10);
        assert!((y[0] - 10f64.cos()).abs() < 1e-9, "{y:?}");
        assert!((y[1] + 10f64.sin()).abs() < 1e-9, "{y:?}");
        assert_eq!(stats.steps, stats.accepted + stats.rejected);
        assert_eq!(stats.rhs_evals, 2 + 6 * stats.steps);
        // Deterministic on a given platform: 235 accepted steps, none rejected.
        assert_eq!((stats.accepted, stats.rejected), (235, 0));
        let (nan, _) = solve_smooth(|_, y| [y[1] * y[1], 0.0], 0.0, [0.0, 1e300], 1.0, 1e-6);
        assert!(
            nan[0].is_nan(),
            "a blow-up is reported, not hidden: {nan:?}"
        );
        assert!(try_solve_smooth(|_, y| [y[1] * y[1], 0.0], 0.0, [0.0, 1e300], 1.0, 1e-6).is_err());
    }

    #[test]
    fn the_positivity_test_of_the_interpolant_is_a_lower_bound() {
        // Positive on [0, 1] (min ≈ 0.26), and the bound 0.3 − (0.1 + 0.05 + 0.1)/4 > 0.
        let r = [0.3, 0.2, -0.1, 0.05, 0.4];
        assert!(positive(r, 1.0));
        assert!(!positive(r, -1.0));
        // Zero at θ = ½ (0.3 + 0.1 − 0.4): not positive.
        assert!(!positive([0.3, 0.2, -1.6, 0.0, 0.0], 1.0));
        // Positive (min ≈ 0.043 at θ = 3/7), but the bound 0.3 − 1.4/4 does not show it:
        // the samples decide.
        assert!(!positive([0.3, 0.2, -1.4, 0.0, 0.0], 1.0));
        // A NaN is not positive.
        assert!(!positive([f64::NAN, 0.2, 0.0, 0.0, 0.0], 1.0));
        // From rest (a slip onset): 0 at θ = 0, positive after by the second bound
        // (0.2 − 0.1/4 − 0.15·0.3 > 0, 0.2 − 0.1 − … > 0); not so going the other way.
        let onset = [0.0, 0.2, -0.1, 0.1, 0.3];
        assert!(positive(onset, 1.0));
        assert!(!positive(onset, -1.0));
        // q = 0.2 − 0.3 (1 − θ) < 0 near θ = 0: p dips below 0 first.
        assert!(!positive([0.0, 0.2, -0.3, 0.0, 0.0], 1.0));
        // Sampled: the bounds hold wherever they say positive.
        for (r1, r3) in [0.0, 0.2]
            .into_iter()
            .flat_map(|r1| [-0.5, -0.1, 0.0, 0.3].map(|r3| (r1, r3)))
        {
            let r = [r1, 0.2 - r1 / 2.0, r3, 0.2, -0.3];
            let d = Dense {
                t0: 0.0,
                t1: 1.0,
                h: 1.0,
                r: r.map(|r| [0.0, r]),
                y1: [0.0, r[0] + r[1]],
            };
            if positive(r, 1.0) {
                for j in 1..=100 {
                    assert!(d.y(f64::from(j) / 100.0)[1] > 0.0, "{r:?}");
                }
            }
        }
    }

    #[test]
    fn set_b_event_times_match_exact_within_1e8_s_at_tol_1e10() {
        for law in [LawKind::Harmonic, LawKind::Linear] {
            let problem = set_b(law, 4.0);
            let want = exact(&problem);
            let got = Dopri5.solve(&problem, Setting::Tolerance(1e-10)).unwrap();
            assert_eq!(
                got.events.len(),
                8,
                "{law:?}: one slip and one stick per period"
            );
            let err = event_error(&got, &want);
            assert!(err < 1e-8, "{law:?}: event error {err:e} s");
            assert!((got.x_end - want.x_end).abs() < 1e-9, "{law:?}");
            assert_eq!(got.stats.events, 8);
            assert_eq!(got.stats.steps, got.stats.accepted + got.stats.rejected);
        }
    }

    #[test]
    fn set_b_event_error_decreases_with_the_tolerance() {
        // Harmonic law: on the linear law the slip arcs are cubics, which DOPRI5 integrates
        // exactly between breakpoints (errors at round-off for every tolerance).
        let problem = set_b(LawKind::Harmonic, 4.0);
        let want = exact(&problem);
        let errors: Vec<f64> = [1e-4, 1e-6, 1e-8, 1e-10, 1e-12]
            .iter()
            .map(|&tol| {
                event_error(
                    &Dopri5.solve(&problem, Setting::Tolerance(tol)).unwrap(),
                    &want,
                )
            })
            .collect();
        // Measured: 5.8e-5, 1.0e-6, 2.7e-8, 3.6e-10, 1.9e-12 s.
        for pair in errors.windows(2) {
            assert!(pair[1] < 0.5 * pair[0], "{errors:?}");
        }
        assert!(errors[4] < 1e-11, "{errors:?}");
    }

    /// A single step (h = 1, one step forced by a huge tolerance) over v(t) = (t − 0.52)(t −
    /// 0.58): s·v dips below 0 on (0.52, 0.58) and comes back, between the samples at 0.5 and
    /// 0.625, where v > 0. The 4th-order interpolant is exact for this quadratic.
    #[test]
    fn a_dip_of_the_speed_between_samples_is_found_by_the_minimum_check() {
        let mut stats = Stats::default();
        let f = |t: f64, y: State| [y[1], 2.0 * t - 1.1];
        let mut run = Integrator::new(&f, 0.0, [0.0, 0.52 * 0.58], 1.0, 1e6, &mut stats);
        run.h = 1.0;
        let dense = run
            .step(&f, 1.0, f64::INFINITY, &mut stats)
            .unwrap()
            .dense();
        assert_eq!(dense.t1, 1.0);
        for t in [0.0, 0.5, 0.625, 1.0] {
            assert!(dense.y(t)[1] > 0.0, "positive at the samples t = {t}");
        }
        let t_stick = first_stick(&dense, 1.0, SAMPLES).expect("the dip is found");
        assert!((t_stick - 0.52).abs() < 1e-14, "{t_stick}");
        assert_eq!(first_stick(&dense, 1.0, 1), None, "step ends only: missed");
    }

    /// F = 0.185 N (harmonic): the late-stick band (guide §7.5): the slip ends just
    /// after the period boundary with a brief stick (≈ 0.05 s) before the next slip. Continued
    /// past the stick, the slip-mode v goes below 0 and back inside one step at loose
    /// tolerances, so the stick and the next slip are both missed when only step ends are
    /// checked.
    ///
    /// Verified to fail without the interior checks: with `samples` forced to 1 in
    /// `slip_advance`, `Dopri5` returns the same 4 events as `Dopri5EndpointsOnly` and the
    /// kind comparison fails.
    #[test]
    fn interior_checks_find_a_brief_stick_that_step_ends_miss() {
        let problem = pulled(0.185, LawKind::Harmonic, 4.0);
        let want = exact(&problem);
        assert_eq!(want.events.len(), 7);
        for tol in [1e-2, 1e-3] {
            let got = Dopri5.solve(&problem, Setting::Tolerance(tol)).unwrap();
            let err = event_error(&got, &want);
            // Measured: 6.3e-3 s at 1e-2, 5.0e-4 s at 1e-3 (a stick with small deceleration).
            assert!(err < 0.05 * problem.law.period, "tol {tol:e}: {err:e} s");
            let blind = Dopri5EndpointsOnly
                .solve(&problem, Setting::Tolerance(tol))
                .unwrap();
            let kinds: Vec<_> = blind.events.iter().map(|e| e.kind).collect();
            assert_eq!(kinds, ["slip", "stick", "slip", "stick"], "tol {tol:e}");
            // Its first "stick" comes a period late, after the missed stick and slip.
            assert!(blind.events[1].t > want.events[3].t - 0.2 * problem.law.period);
            assert!((blind.x_end - want.x_end).abs() > 0.3 * want.x_end);
            assert!((got.x_end - want.x_end).abs() < 0.02 * want.x_end);
        }
    }

    #[test]
    fn woodpecker_fig15_has_two_slips_and_two_sticks_in_the_last_period() {
        for law in [LawKind::Harmonic, LawKind::Linear] {
            let problem = woodpecker_fig15(law);
            let want = exact(&problem);
            let got = Dopri5.solve(&problem, Setting::Tolerance(1e-6)).unwrap();
            let kinds = last_period_kinds(&got, &problem);
            assert_eq!(kinds, ["slip", "stick", "slip", "stick"], "{law:?}");
            // Measured: ≤ 1.0e-6 s (harmonic), round-off (linear).
            let err = event_error(&got, &want);
            assert!(err < 1e-5, "{law:?}: {err:e}");
            assert!((got.x_end - want.x_end).abs() < 1e-5, "{law:?}");
        }
    }

    #[test]
    fn reversals_match_the_exact_engine() {
        let problem = back_and_forth();
        let want = exact(&problem);
        let got = Dopri5.solve(&problem, Setting::Tolerance(1e-10)).unwrap();
        let kinds: Vec<_> = got.events.iter().map(|e| e.kind).collect();
        assert_eq!(
            kinds,
            ["slip", "reversal", "reversal", "reversal", "reversal", "reversal", "reversal"]
        );
        assert_eq!(got.events[0].t, 0.0);
        // The exact method lists the same events.
        let want_kinds: Vec<_> = want.events.iter().map(|e| e.kind).collect();
        assert_eq!(kinds, want_kinds);
        assert_eq!(want.stats.events, 7);
        // Reversal times against the exact engine's own event list.
        let run = crate::engine::integrate(
            &problem.body,
            &problem.law,
            &crate::engine::RunOptions {
                periods: 3,
                record_segments: false,
                dissipation: false,
            },
        )
        .unwrap();
        let exact_reversals: Vec<f64> = run
            .events
            .iter()
            .filter(|e| matches!(e.kind, crate::engine::EventKind::Reversal { .. }))
            .map(|e| e.t)
            .collect();
        assert_eq!(exact_reversals.len(), 6);
        for (e, t) in got.events[1..].iter().zip(&exact_reversals) {
            // Measured: ≤ 3e-10 s.
            assert!((e.t - t).abs() < 1e-8, "{e:?} vs {t}");
        }
        assert!((got.x_end - want.x_end).abs() < 1e-9);
        assert!((got.v_end - want.v_end).abs() < 1e-9);
    }

    /// D = ½(1 − cos 2πt) (N), μs N_f = 0.9999 N: the static friction gives way only within
    /// ±0.0032 s of t = 0.5 s, a window narrower than the stuck sampling (T/64), between two
    /// samples (the law's breakpoint at 0.29 s puts the samples at 0.493 and 0.509 s). The
    /// sampled maximum is refined, so the brief slip is found.
    ///
    /// Verified to fail without the refinement (the `maximize` branch of `Stuck::advance`
    /// disabled): no event at all.
    #[test]
    fn a_slip_window_between_stuck_samples_is_found() {
        let omega = std::f64::consts::TAU;
        let piece = |start, end| Piece {
            start,
            end,
            basis: Basis::Cos { omega, shift: 0.0 },
            drive: Affine::new(0.5, -0.5),
            normal: Affine::new(0.9999 / 0.4, 0.0),
        };
        let law = ForceLaw::new(1.0, vec![piece(0.0, 0.29), piece(0.29, 1.0)]).unwrap();
        let problem = Problem {
            body: Body {
                mass: 1.0,
                mu_s: 0.4,
                mu_d: 0.35,
            },
            law,
            t_end: 1.0,
        };
        let want = exact(&problem);
        assert_eq!(want.events.len(), 2);
        let got = Dopri5.solve(&problem, Setting::Tolerance(1e-10)).unwrap();
        // Measured: 5e-16 s (slip), 4.8e-10 s (stick).
        assert!(event_error(&got, &want) < 1e-8, "{:?}", got.events);
        assert!((got.x_end - want.x_end).abs() < 1e-10);
    }

    /// Only a one-piece cosine law whose ωT is a multiple of 2π up to rounding is taken as
    /// periodic (a landing step is then evaluated on the next period).
    #[test]
    fn a_one_piece_cosine_law_is_periodic_only_when_its_period_is_the_cosines() {
        let periodic = |omega: f64, period: f64| {
            let piece = Piece {
                start: 0.0,
                end: period,
                basis: Basis::Cos { omega, shift: 0.0 },
                drive: Affine::new(0.5, -0.5),
                normal: Affine::new(1.0, 1.0),
            };
            let problem = Problem {
                body: Body {
                    mass: 1.0,
                    mu_s: 0.4,
                    mu_d: 0.35,
                },
                law: ForceLaw::new(period, vec![piece]).unwrap(),
                t_end: period,
            };
            Forces::new(&problem).periodic
        };
        let omega = 27.386_127_875_258_3;
        assert!(periodic(omega, std::f64::consts::TAU / omega));
        assert!(periodic(omega, 2.0 * std::f64::consts::TAU / omega));
        assert!(!periodic(
            omega * (1.0 + 1e-13),
            std::f64::consts::TAU / omega
        ));
        assert!(!periodic(0.5 * omega, std::f64::consts::TAU / omega));
    }

    #[test]
    fn immediate_slip_starts_at_zero_and_never_sticks() {
        // F > 2 μs W: slips at t = 0 and keeps slipping (guide §9).
        let problem = pulled(0.5, LawKind::Harmonic, 3.0);
        let want = exact(&problem);
        let got = Dopri5.solve(&problem, Setting::Tolerance(1e-10)).unwrap();
        assert_eq!(
            got.events,
            [MethodEvent {
                t: 0.0,
                kind: "slip"
            }]
        );
        // The exact method lists the same immediate slip.
        assert_eq!(got.events, want.events);
        assert!((got.x_end - want.x_end).abs() < 1e-9 * want.x_end);
        assert!((got.v_end - want.v_end).abs() < 1e-9 * want.v_end);
    }

    #[test]
    fn on_the_belt_its_event_times_converge_to_the_closed_forms() {
        use crate::bench::belt::{closed_form_events, error, problem};
        let (p, problem) = problem().unwrap();
        let c = crate::models::belt::formula::evaluate(&p);
        let want = closed_form_events(&c, problem.t_end);
        let errors: Vec<f64> = [1e-4, 1e-6, 1e-8, 1e-10]
            .iter()
            .map(|&tol| {
                let got = Dopri5.solve_surface(&problem, Setting::Tolerance(tol)).unwrap();
                let err = error(&got, &want);
                println!(
                    "dopri5 belt: tol {tol:e}: event error {err:.3e} s, x_end {:.9e} m, v_end {:e}, {} steps",
                    got.x_end, got.v_end, got.stats.steps
                );
                // Ends mid-stick: carried by the belt.
                assert_eq!(got.v_end, p.v_b, "{tol:e}");
                err
            })
            .collect();
        // Measured over 20 cycles: 1.5e-4, 6.7e-5, 8.9e-7, 1.1e-8 s (542 … 1609 steps); the
        // onsets are located on G exactly, the sticks on w's interpolant, so the error goes
        // about as the tolerance once the steps resolve the arcs (× 6200 over 4 decades).
        assert!(errors.windows(2).all(|w| w[1] < w[0] / 2.0), "{errors:?}");
        assert!(errors[1] / errors[3] > 1e3, "{errors:?}");
        assert!(errors[3] < 3e-8, "{errors:?}");
        // The slip's w has no interior minimum on a harmonic arc of the belt: the step ends
        // alone find the same sticks.
        let ends = Dopri5EndpointsOnly
            .solve_surface(&problem, Setting::Tolerance(1e-10))
            .unwrap();
        assert!(error(&ends, &want) < 3e-8);
    }

    #[test]
    fn a_step_setting_or_a_bad_tolerance_is_refused() {
        let problem = set_b(LawKind::Linear, 4.0);
        for setting in [
            Setting::Step(1e-3),
            Setting::Tolerance(0.0),
            Setting::Tolerance(f64::NAN),
        ] {
            assert!(matches!(
                Dopri5.solve(&problem, setting),
                Err(Error::InvalidParam { .. })
            ));
        }
        assert_eq!(Dopri5.name(), "dopri5");
        assert_eq!(Dopri5EndpointsOnly.name(), "dopri5_endpoints");
    }
}
