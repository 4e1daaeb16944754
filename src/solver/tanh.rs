//! Regularized friction: the Coulomb law replaced by a smooth one, integrated by an adaptive
//! explicit method ([`TanhAdaptive`], Dormand–Prince 5(4) from [`super::dopri5`]) and by an
//! implicit one ([`TanhImplicit`], TR-BDF2), to show what regularization costs: creep where the
//! true body sticks, and stiffness as ε → 0. Owns also the creep measurement
//! ([`creep_per_stick`]).
//!
//! ```text
//! x' = v,   M v' = D(t) − μd N_f(t) tanh(v/ε)          (no stick state; μs is not used)
//! belt:     M w' = D(x) − μd N_f tanh(w/ε),  w = v − v_s   (x = u + v_s t, u' = w)
//! ∂v'/∂v = −μd N_f sech²(v/ε) / (M ε)                   (stiff near v = 0 when ε is small)
//! ∂v'/∂x = (∂D/∂x)/M                                     (−k/M on the belt, 0 on forces of t)
//! ```
//!
//! Where the exact body is stuck with |D| < μd N_f, the regularized one creeps at the speed
//! v ≈ ε atanh(D/(μd N_f)), a distance O(ε) per stick phase; where μd N_f < |D| ≤ μs N_f the
//! exact body is still stuck but the regularized law (which knows only μd) slides, so the
//! creep per stick phase tends to a non-zero limit as ε → 0 and the regularized slip starts
//! early (set B: at N_f = F/μd instead of F/μs).
//!
//! Events (a regularized law has no stick): with the creep threshold v_c = [`CREEP_FACTOR`]·ε,
//! "slip" when |v| rises above v_c, "stick" when it falls back below, "reversal" when v jumps
//! from above v_c to below −v_c (or back) without being seen inside the band. In creep
//! |v| ≈ ε atanh(|D|/(μd N_f)) exceeds 10 ε only when |D|/(μd N_f) > tanh 10 = 1 − 4e-9, i.e.
//! where the regularized body really starts sliding. TR-BDF2 locates the crossings on the cubic Hermite
//! interpolant of each step (v and v' at both ends); the adaptive method, which only returns
//! end states, checks the band on a grid of [`GRID_PER_PERIOD`] points per period (aligned
//! with the pieces of the force law) and bisects a crossing by re-integrating, to a resolution
//! of tol·T; two crossings inside one grid cell (T/64) are missed.
//!
//! On the belt ([`SurfaceProblem`], both methods) the band test reads w: the adaptive
//! method's on a grid of [`GRID_PER_PERIOD`] points per natural period 2π √(M/|∂D/∂x|),
//! TR-BDF2's on each step, its steps capped at 1/[`GRID_PER_PERIOD`] of that period and its
//! Newton iteration on the stage equation with ∂D/∂x in the Jacobian (the stepper `Trbdf2`;
//! with forces of time only ∂D/∂x = 0 and the numbers are the time-only ones, bit for bit).
//! Knowing only μd, the body creeps until D reaches μd N_f (at x_d, not x_s), then oscillates
//! harmonically about x_d with w touching 0 only at the top of each swing: a short "stick" (a
//! visit of the creep band) per period 2π/ω, not the closed forms' stick of t_stick. The
//! visits shrink with ε and with time (ε = 1e-4: 0.032 s first, 0.027 s after 37 swings);
//! with ε = 1e-5 (tol 1e-8) tanh_dopri5's grid misses them from t ≈ 17.8 s on, after 28
//! swings, where TR-BDF2 (steps of at most T/64, 73 events) still sees them. TR-BDF2
//! converges to tanh_dopri5's events as the tolerance tightens (ε = 1e-4: 7.8e-3, 4.7e-4,
//! 2.2e-5 s at 1e-6, 1e-8, 1e-10) and at order 2 with a fixed step.
//!
//! Adaptive TR-BDF2 steps are capped at T/[`GRID_PER_PERIOD`]: an L-stable method in creep
//! samples the forcing only at its stage times, and with no cap one step of 0.17 s (ε = 1e-5,
//! tol 1e-6, harmonic law) jumped over a whole slip phase with an error estimate of 0.25,
//! because the body was creeping at both ends and at the stage point.

use serde::Serialize;

use super::dopri5::try_solve_smooth;
use super::moreau::{step_count, step_grid};
use super::surface::{absolute, SurfaceProblem, System};
use super::{Method, MethodEvent, Problem, Setting, Solution, Stats};
use crate::error::{Error, Result};

/// The creep threshold is this multiple of ε.
pub const CREEP_FACTOR: f64 = 10.0;
/// Checking points per period of the adaptive method's band test.
pub const GRID_PER_PERIOD: f64 = 64.0;
/// Largest number of steps a run may take.
pub const MAX_STEPS: u64 = 10_000_000;

/// TR-BDF2 constants (Hosea & Shampine 1996): γ = 2 − √2, both stages solve
/// z − d h f(z) = ψ with d = γ/2, and the local error is ≈ 2 k h · f[0, γ, 1] (second
/// divided difference of f over the stage nodes, scaled by h).
const GAMMA: f64 = 2.0 - std::f64::consts::SQRT_2;
const D_STAGE: f64 = GAMMA / 2.0;
const K_ERR: f64 = (-3.0 * GAMMA * GAMMA + 4.0 * GAMMA - 2.0) / (12.0 * (2.0 - GAMMA));
/// Step-size controller (order 2 error estimate ⇒ exponent 1/3).
const SAFETY: f64 = 0.9;
const FAC_MIN: f64 = 0.2;
const FAC_MAX: f64 = 5.0;
/// Newton: at most this many safeguarded iterations (bisection fallback guarantees progress).
const NEWTON_MAX_ITER: u32 = 200;
/// Newton stopping rule of the fixed-step mode, relative to |v| + ε.
const NEWTON_STEP_REL: f64 = 1e-12;

/// Regularized friction integrated by adaptive Dormand–Prince 5(4), `Setting::Tolerance`.
pub struct TanhAdaptive {
    /// Regularization width ε (m/s).
    pub epsilon: f64,
}

/// Regularized friction integrated by TR-BDF2 with Newton: adaptive with
/// `Setting::Tolerance`, fixed step with `Setting::Step`.
pub struct TanhImplicit {
    /// Regularization width ε (m/s).
    pub epsilon: f64,
}

impl Method for TanhAdaptive {
    fn name(&self) -> &'static str {
        "tanh_dopri5"
    }

    fn solve(&self, problem: &Problem, setting: Setting) -> Result<Solution> {
        self.states_at(problem, setting, &[]).map(|(s, _)| s)
    }

    /// The belt: tanh of the relative velocity w = v − v_s, band checks on a grid of
    /// [`GRID_PER_PERIOD`] points per natural period 2π √(M/|∂D/∂x|).
    fn solve_surface(&self, problem: &SurfaceProblem, setting: Setting) -> Result<Solution> {
        let law = Law::new(problem, self.epsilon)?;
        let tol = self.tolerance(setting)?;
        let period = natural_period(problem, self.name())?;
        let stops = grid_points(problem.t_end, period / GRID_PER_PERIOD)?;
        adaptive_run(&law, tol, &stops, period * tol.max(1e-13), &[]).map(|(s, _)| s)
    }
}

impl Method for TanhImplicit {
    fn name(&self) -> &'static str {
        "tanh_trbdf2"
    }

    fn solve(&self, problem: &Problem, setting: Setting) -> Result<Solution> {
        self.states_at(problem, setting, &[]).map(|(s, _)| s)
    }

    /// The belt: tanh of the relative velocity w = v − v_s, Newton on the stage equation with
    /// ∂D/∂x in its Jacobian; adaptive steps capped at 1/[`GRID_PER_PERIOD`] of the natural
    /// period 2π √(M/|∂D/∂x|).
    fn solve_surface(&self, problem: &SurfaceProblem, setting: Setting) -> Result<Solution> {
        let law = Law::new(problem, self.epsilon)?;
        let newton = self.newton_tolerances(setting)?;
        let period = natural_period(problem, self.name())?;
        let stops = match setting {
            Setting::Tolerance(_) => grid_points(problem.t_end, f64::INFINITY)?,
            Setting::Step(_) => Vec::new(),
        };
        implicit_run(law, setting, newton, &stops, period, &[]).map(|(s, _)| s)
    }
}

/// The natural period 2π √(M/|∂D/∂x|) (s) of a force depending on the position, which sets the
/// grid of the regularized methods on a moving surface; refused without one (∂D/∂x = 0).
fn natural_period(problem: &SurfaceProblem, method: &str) -> Result<f64> {
    let stiffness = problem.force_gradient().abs();
    if !(stiffness.is_finite() && stiffness > 0.0) {
        return Err(Error::InvalidParam {
            name: "stiffness",
            value: stiffness.to_string(),
            rule: format!("{method} on a moving surface: |∂D/∂x| finite and > 0 (N/m)"),
        });
    }
    Ok(2.0 * std::f64::consts::PI * (problem.body.mass / stiffness).sqrt())
}

/// The regularized right-hand side of one problem, in the relative velocity w = v − v_s.
struct Law<'a, S: System = Problem> {
    problem: &'a S,
    epsilon: f64,
    /// Creep threshold v_c (m/s).
    v_creep: f64,
}

impl<'a, S: System> Law<'a, S> {
    fn new(problem: &'a S, epsilon: f64) -> Result<Self> {
        if !(epsilon.is_finite() && epsilon > 0.0) {
            return Err(Error::InvalidParam {
                name: "epsilon",
                value: epsilon.to_string(),
                rule: "finite and > 0 (m/s)".into(),
            });
        }
        Ok(Self {
            problem,
            epsilon,
            v_creep: CREEP_FACTOR * epsilon,
        })
    }

    /// w' = v' = (D(t, x) − μd N_f tanh(w/ε))/M at x = u + v_s t.
    fn accel(&self, t: f64, u: f64, w: f64) -> f64 {
        let x = u + self.problem.surface_speed() * t;
        let (d, n) = System::forces(self.problem, t, x);
        let body = self.problem.body();
        (d - body.mu_d * n * (w / self.epsilon).tanh()) / body.mass
    }

    fn band(&self, w: f64) -> i8 {
        band_of(w, self.v_creep)
    }

    /// ∂w'/∂w = −μd N_f sech²(w/ε)/(M ε) (N_f does not depend on x).
    fn accel_dv(&self, t: f64, w: f64) -> f64 {
        let (_, n) = System::forces(self.problem, t, 0.0);
        let body = self.problem.body();
        let th = (w / self.epsilon).tanh();
        -body.mu_d * n * (1.0 - th * th) / (body.mass * self.epsilon)
    }
}

/// −1, 0, +1: below −v_c, inside the creep band [−v_c, v_c], above v_c.
fn band_of(v: f64, v_creep: f64) -> i8 {
    if v > v_creep {
        1
    } else if v < -v_creep {
        -1
    } else {
        0
    }
}

/// The event of a move from band `from` to band `to` (they differ).
fn event_kind(from: i8, to: i8) -> &'static str {
    match (from, to) {
        (0, _) => "slip",
        (_, 0) => "stick",
        _ => "reversal",
    }
}

/// The level v crosses when moving from band `from` to band `to`.
fn crossing_level(from: i8, to: i8, v_creep: f64) -> f64 {
    match (from, to) {
        (0, s) | (s, 0) => f64::from(s) * v_creep,
        _ => 0.0,
    }
}

fn check_tolerance(tol: f64) -> Result<f64> {
    if tol.is_finite() && tol > 0.0 {
        Ok(tol)
    } else {
        Err(Error::InvalidParam {
            name: "tol",
            value: tol.to_string(),
            rule: "finite and > 0".into(),
        })
    }
}

/// Sorted sample times must lie in [0, t_end].
fn check_samples(samples: &[f64], t_end: f64) -> Result<()> {
    let sorted = samples.windows(2).all(|w| w[0] <= w[1]);
    let inside = samples.iter().all(|&t| (0.0..=t_end).contains(&t));
    if sorted && inside {
        Ok(())
    } else {
        Err(Error::InvalidParam {
            name: "sample times",
            value: format!("{} times", samples.len()),
            rule: format!("sorted, within [0, t_end = {t_end}] s"),
        })
    }
}

/// Stop points of the adaptive integrations in (0, t_end]: the ends of the force law's pieces
/// (where the forces have kinks), every sample time, and `t_end`, each cell of a length at most
/// `max_cell` split evenly, sorted, without duplicates.
fn stop_points(problem: &Problem, samples: &[f64], max_cell: f64) -> Result<Vec<f64>> {
    let period = problem.law.period;
    let t_end = problem.t_end;
    let periods = (t_end / period).ceil();
    if periods > MAX_STEPS as f64 {
        return Err(Error::Stalled {
            t: 0.0,
            reason: "tanh: more than 10^7 periods requested",
        });
    }
    let mut points: Vec<f64> = (0..periods as u64)
        .flat_map(|p| {
            let start = p as f64 * period;
            problem
                .law
                .pieces
                .iter()
                .map(move |piece| start + piece.end)
        })
        .filter(|&t| t < t_end)
        .chain(samples.iter().copied().filter(|&t| t > 0.0))
        .chain(std::iter::once(t_end))
        .collect();
    points.sort_by(f64::total_cmp);
    points.dedup();
    subdivide(&points, max_cell)
}

/// The sorted `points` (s) with each gap from the previous one (from 0 for the first) cut
/// into equal cells at most `max_cell` (s) long; points at or before 0 are dropped.
fn subdivide(points: &[f64], max_cell: f64) -> Result<Vec<f64>> {
    let mut out = Vec::with_capacity(points.len());
    let mut prev = 0.0;
    for &t in points {
        if t <= prev {
            continue;
        }
        let cells = ((t - prev) / max_cell).ceil().max(1.0);
        if out.len() as f64 + cells > MAX_STEPS as f64 {
            return Err(Error::Stalled {
                t: prev,
                reason: "tanh: too many checking points",
            });
        }
        let cells = cells as u64;
        for i in 1..cells {
            out.push(prev + (t - prev) * i as f64 / cells as f64);
        }
        out.push(t);
        prev = t;
    }
    Ok(out)
}

impl TanhAdaptive {
    /// Solves `problem` and returns, with the solution, the state (x, v) at each of the sorted
    /// `samples` (absolute times in [0, t_end]); the integration lands on each sample time.
    pub fn states_at(
        &self,
        problem: &Problem,
        setting: Setting,
        samples: &[f64],
    ) -> Result<(Solution, Vec<[f64; 2]>)> {
        let law = Law::new(problem, self.epsilon)?;
        let tol = self.tolerance(setting)?;
        check_samples(samples, problem.t_end)?;
        let period = problem.law.period;
        let stops = stop_points(problem, samples, period / GRID_PER_PERIOD)?;
        adaptive_run(&law, tol, &stops, period * tol.max(1e-13), samples)
    }

    /// The tolerance of an adaptive `setting`, refused otherwise.
    fn tolerance(&self, setting: Setting) -> Result<f64> {
        let Setting::Tolerance(tol) = setting else {
            return Err(Error::InvalidParam {
                name: "setting",
                value: format!("{setting:?}"),
                rule: "tanh_dopri5 is adaptive: give Setting::Tolerance(tol) with tol > 0".into(),
            });
        };
        check_tolerance(tol)
    }
}

/// Evenly spaced points ending at `t_end` (s), cells at most `max_cell` (s) long ([`subdivide`]
/// of t_end alone: none for t_end = 0).
fn grid_points(t_end: f64, max_cell: f64) -> Result<Vec<f64>> {
    if !(t_end.is_finite() && t_end >= 0.0) {
        return Err(Error::InvalidParam {
            name: "t_end",
            value: t_end.to_string(),
            rule: "finite and >= 0 (s)".into(),
        });
    }
    subdivide(&[t_end], max_cell)
}

/// The adaptive integration of `law` from rest relative to the surface at t = 0 through the
/// sorted `stops` (s, the last is t_end), band changes of w located to `resolution` (s); the
/// states (x, v) at the `samples`, each of which is a stop.
fn adaptive_run<S: System>(
    law: &Law<'_, S>,
    tol: f64,
    stops: &[f64],
    resolution: f64,
    samples: &[f64],
) -> Result<(Solution, Vec<[f64; 2]>)> {
    let rhs = |t: f64, y: [f64; 2]| [y[1], law.accel(t, y[0], y[1])];
    let mut stats = Stats::default();
    let mut solve = |t0: f64, y0: [f64; 2], t1: f64| -> Result<[f64; 2]> {
        let (y, s) = try_solve_smooth(rhs, t0, y0, t1, tol)?;
        stats.rhs_evals += s.rhs_evals;
        stats.steps += s.steps;
        stats.accepted += s.accepted;
        stats.rejected += s.rejected;
        if stats.steps > MAX_STEPS {
            return Err(Error::Stalled {
                t: t1,
                reason: "tanh_dopri5: more than 10^7 steps",
            });
        }
        Ok(y)
    };
    let mut events = Vec::new();
    let mut states = Vec::with_capacity(samples.len());
    let mut next_sample = samples.iter().peekable();
    while next_sample.next_if(|&&t| t <= 0.0).is_some() {
        states.push([0.0, 0.0]);
    }
    let (mut t, mut y, mut band) = (0.0, [0.0, 0.0], 0);
    for &tb in stops {
        let yb = solve(t, y, tb)?;
        let band_b = law.band(yb[1]);
        // Walk from (t, y) to tb one band change at a time: bisect for the first change
        // after ta, record it, go on from just after it.
        let (mut ta, mut ya, mut band_a) = (t, y, band);
        let mut changes = 0;
        while band_a != band_b {
            changes += 1;
            if changes > 8 {
                return Err(Error::Stalled {
                    t: ta,
                    reason: "tanh_dopri5: too many band changes in one grid cell",
                });
            }
            let (mut lo, mut y_lo) = (ta, ya);
            let (mut hi, mut y_hi) = (tb, yb);
            while hi - lo > resolution {
                let mid = 0.5 * (lo + hi);
                if mid <= lo || mid >= hi {
                    break;
                }
                let y_mid = solve(lo, y_lo, mid)?;
                if law.band(y_mid[1]) == band_a {
                    (lo, y_lo) = (mid, y_mid);
                } else {
                    (hi, y_hi) = (mid, y_mid);
                }
            }
            let band_new = law.band(y_hi[1]);
            events.push(MethodEvent {
                t: 0.5 * (lo + hi),
                kind: event_kind(band_a, band_new),
            });
            (ta, ya, band_a) = (hi, y_hi, band_new);
        }
        (t, y, band) = (tb, yb, band_b);
        while next_sample.next_if(|&&s| s <= t).is_some() {
            let (x, v) = absolute(law.problem, t, y[0], y[1]);
            states.push([x, v]);
        }
    }
    let (x_end, v_end) = absolute(law.problem, t, y[0], y[1]);
    let solution = Solution::new(events, x_end, v_end, stats);
    Ok((solution, states))
}

/// One TR-BDF2 step's result.
struct Trbdf2Step {
    y1: [f64; 2],
    /// f(t + h, y1).
    f1: [f64; 2],
    /// Local error estimate (filtered by (I − d h J)⁻¹).
    err: [f64; 2],
}

/// The TR-BDF2 stepper on the reduced system: with y = (u, w) in the surface's frame
/// (u = x − v_s t, w = v − v_s; on forces of time only x and v) and f = (w, a(t, x, w)), the
/// stage equation z − c f(t, z) = ψ (c = d h) gives u = ψ_u + c w, and D is affine in x with
/// slope g = ∂D/∂x ([`System::force_gradient`], 0 for forces of time only), so Newton runs on
/// the scalar
///
/// ```text
/// G(w) = α w + b tanh(w/ε) − r,   α = 1 − c² g/M,   b = c μd N_f/M ≥ 0,
///                                  r = ψ_w + c D(t, ψ_u + v_s t)/M
/// ```
///
/// which is increasing when α > 0 (always for g ≤ 0, a restoring force), with its root in
/// [(r − b)/α, (r + b)/α]: Newton safeguarded by bisection on that bracket always converges.
struct Trbdf2<'a, S: System = Problem> {
    law: Law<'a, S>,
    /// Newton stops when |Δv| ≤ abs + rel·|v|.
    newton_abs: f64,
    newton_rel: f64,
    stats: Stats,
}

impl<S: System> Trbdf2<'_, S> {
    fn f(&mut self, t: f64, y: [f64; 2]) -> [f64; 2] {
        self.stats.rhs_evals += 1;
        [y[1], self.law.accel(t, y[0], y[1])]
    }

    /// Solves z − c f(t, z) = ψ for z (c = d h), starting Newton from w = `guess`.
    fn stage(&mut self, t: f64, c: f64, psi: [f64; 2], guess: f64) -> Result<[f64; 2]> {
        let problem = self.law.problem;
        let (d, n) = problem.forces(t, psi[0] + problem.surface_speed() * t);
        let body = problem.body();
        let alpha = 1.0 - c * c * problem.force_gradient() / body.mass;
        if alpha.is_nan() || alpha <= 0.0 {
            return Err(Error::Stalled {
                t,
                reason: "tanh_trbdf2: step too long for a force growing with the position",
            });
        }
        let eps = self.law.epsilon;
        let b = c * body.mu_d * n.max(0.0) / body.mass;
        let r = psi[1] + c * d / body.mass;
        let (mut lo, mut hi) = ((r - b) / alpha, (r + b) / alpha);
        let mut v = guess.clamp(lo, hi);
        let mut converged = false;
        for _ in 0..NEWTON_MAX_ITER {
            let th = (v / eps).tanh();
            let g = alpha * v + b * th - r;
            let dg = alpha + b * (1.0 - th * th) / eps;
            // One residual (an rhs evaluation) and one derivative (a Jacobian evaluation).
            self.stats.rhs_evals += 2;
            if g == 0.0 {
                converged = true;
                break;
            }
            if g > 0.0 {
                hi = v;
            } else {
                lo = v;
            }
            let newton = v - g / dg;
            let next = if newton > lo && newton < hi {
                newton
            } else {
                0.5 * (lo + hi)
            };
            let dv = (next - v).abs();
            v = next;
            if dv <= self.newton_abs + self.newton_rel * v.abs()
                || hi - lo <= f64::EPSILON * v.abs()
            {
                converged = true;
                break;
            }
        }
        if !(converged && v.is_finite()) {
            return Err(Error::Stalled {
                t,
                reason: "tanh_trbdf2: Newton did not converge",
            });
        }
        Ok([psi[0] + c * v, v])
    }

    /// One TR-BDF2 step of size h from (t, y) with f0 = f(t, y).
    fn step(&mut self, t: f64, y: [f64; 2], f0: [f64; 2], h: f64) -> Result<Trbdf2Step> {
        let c = D_STAGE * h;
        // Trapezoidal stage to t + γh.
        let psi1 = [y[0] + c * f0[0], y[1] + c * f0[1]];
        let y_g = self.stage(t + GAMMA * h, c, psi1, y[1])?;
        let f_g = self.f(t + GAMMA * h, y_g);
        // BDF2 stage through t, t + γh, t + h.
        let w = 1.0 / (GAMMA * (2.0 - GAMMA));
        let w0 = (1.0 - GAMMA) * (1.0 - GAMMA) * w;
        let psi2 = [w * y_g[0] - w0 * y[0], w * y_g[1] - w0 * y[1]];
        let guess = y_g[1] + (y_g[1] - y[1]) * (1.0 - GAMMA) / GAMMA;
        let y1 = self.stage(t + h, c, psi2, guess)?;
        let f1 = self.f(t + h, y1);
        let est: [f64; 2] = std::array::from_fn(|i| {
            2.0 * K_ERR
                * h
                * (f0[i] / GAMMA - f_g[i] / (GAMMA * (1.0 - GAMMA)) + f1[i] / (1.0 - GAMMA))
        });
        // Filter through (I − d h J)⁻¹, J = [[0, 1], [g/M, ∂a/∂w]], so that the estimate stays
        // bounded on the stiff components (Hosea & Shampine).
        let a_v = self.law.accel_dv(t + h, y1[1]);
        let a_x = self.law.problem.force_gradient() / self.law.problem.body().mass;
        self.stats.rhs_evals += 1;
        let e_v = (est[1] + c * a_x * est[0]) / (1.0 - c * a_v - c * c * a_x);
        let err = [est[0] + c * e_v, e_v];
        Ok(Trbdf2Step { y1, f1, err })
    }
}

/// Cubic Hermite interpolation on [t0, t0 + h] from values p and slopes d at both ends.
fn hermite(t0: f64, h: f64, p: [f64; 2], d: [f64; 2], t: f64) -> f64 {
    let s = (t - t0) / h;
    let s1 = 1.0 - s;
    p[0] * (1.0 + 2.0 * s) * s1 * s1
        + h * d[0] * s * s1 * s1
        + p[1] * s * s * (3.0 - 2.0 * s)
        + h * d[1] * s * s * (s - 1.0)
}

/// Where the Hermite cubic of v crosses `level` on the step (v(t0) and v(t0 + h) lie on either
/// side of it), by bisection.
fn hermite_crossing(t0: f64, h: f64, v: [f64; 2], a: [f64; 2], level: f64) -> f64 {
    let side0 = v[0] - level;
    let (mut lo, mut hi) = (t0, t0 + h);
    for _ in 0..64 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if (hermite(t0, h, v, a, mid) - level) * side0 > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// RMS norm with atol = rtol = tol, as in the adaptive explicit method.
fn weighted_norm(e: [f64; 2], a: [f64; 2], b: [f64; 2], tol: f64) -> f64 {
    let sum: f64 = (0..2)
        .map(|i| (e[i] / (tol + tol * a[i].abs().max(b[i].abs()))).powi(2))
        .sum();
    (0.5 * sum).sqrt()
}

impl TanhImplicit {
    /// Solves `problem` and returns, with the solution, the state (x, v) at each of the sorted
    /// `samples` (absolute times in [0, t_end]): with a tolerance the steps land on the sample
    /// times; with a fixed step they are read off the cubic Hermite interpolant.
    pub fn states_at(
        &self,
        problem: &Problem,
        setting: Setting,
        samples: &[f64],
    ) -> Result<(Solution, Vec<[f64; 2]>)> {
        let law = Law::new(problem, self.epsilon)?;
        check_samples(samples, problem.t_end)?;
        let newton = self.newton_tolerances(setting)?;
        // With a tolerance: stops at the kinks of the force law and at the samples only.
        let stops = match setting {
            Setting::Tolerance(_) => stop_points(problem, samples, f64::INFINITY)?,
            Setting::Step(_) => Vec::new(),
        };
        implicit_run(law, setting, newton, &stops, problem.law.period, samples)
    }

    /// Newton's stopping rule (abs, rel) for `setting`; a bad tolerance is refused.
    fn newton_tolerances(&self, setting: Setting) -> Result<(f64, f64)> {
        Ok(match setting {
            // Well below the step's error tolerance (quadratic convergence makes it cheap).
            Setting::Tolerance(tol) => {
                let tol = check_tolerance(tol)?;
                (1e-3 * tol, 1e-3 * tol)
            }
            Setting::Step(_) => (NEWTON_STEP_REL * self.epsilon, NEWTON_STEP_REL),
        })
    }
}

/// The TR-BDF2 integration of `law` from rest relative to the surface at t = 0 to t_end:
/// fixed steps with `Setting::Step(h)`, otherwise adaptive through the sorted `stops` (s, the
/// last is t_end) from a first step of 1e-5 `period` with steps of at most
/// `period`/[`GRID_PER_PERIOD`] (s); Newton stops at `newton` (abs, rel). Band
/// changes of w are located on each step's Hermite cubic; the states (x, v) at the sorted
/// `samples`, each of which is a stop of an adaptive run.
fn implicit_run<S: System>(
    law: Law<'_, S>,
    setting: Setting,
    (newton_abs, newton_rel): (f64, f64),
    stops: &[f64],
    period: f64,
    samples: &[f64],
) -> Result<(Solution, Vec<[f64; 2]>)> {
    let problem = law.problem;
    let t_end = problem.t_end();
    let mut st = Trbdf2 {
        law,
        newton_abs,
        newton_rel,
        stats: Stats::default(),
    };
    let mut events = Vec::new();
    let mut states = Vec::with_capacity(samples.len());
    let mut next_sample = samples.iter().peekable();
    while next_sample.next_if(|&&t| t <= 0.0).is_some() {
        states.push([0.0, 0.0]);
    }
    let (mut t, mut y) = (0.0, [0.0, 0.0]);
    let mut f0 = st.f(0.0, y);
    let mut band = 0;
    let v_creep = st.law.v_creep;
    // After each accepted step [t, t + h]: events on the Hermite cubic of v.
    let mut on_step = |t0: f64, h: f64, y0: [f64; 2], f0: [f64; 2], y1: [f64; 2], f1: [f64; 2]| {
        let band1 = band_of(y1[1], v_creep);
        if band1 != band {
            let level = crossing_level(band, band1, v_creep);
            let te = hermite_crossing(t0, h, [y0[1], y1[1]], [f0[1], f1[1]], level);
            events.push(MethodEvent {
                t: te,
                kind: event_kind(band, band1),
            });
            band = band1;
        }
    };
    match setting {
        Setting::Step(h) => {
            let n = step_count(h, t_end)?;
            for (t0, t1) in step_grid(n, h, t_end) {
                let out = st.step(t0, y, f0, t1 - t0)?;
                on_step(t0, t1 - t0, y, f0, out.y1, out.f1);
                while let Some(&&ts) = next_sample.peek() {
                    if ts > t1 {
                        break;
                    }
                    next_sample.next();
                    let hk = t1 - t0;
                    let (x, v) = absolute(
                        problem,
                        ts,
                        hermite(t0, hk, [y[0], out.y1[0]], [f0[0], out.f1[0]], ts),
                        hermite(t0, hk, [y[1], out.y1[1]], [f0[1], out.f1[1]], ts),
                    );
                    states.push([x, v]);
                }
                (y, f0) = (out.y1, out.f1);
            }
            st.stats.steps = n;
            st.stats.accepted = n;
        }
        Setting::Tolerance(tol) => {
            let h_max = period / GRID_PER_PERIOD;
            let mut h = 1e-5 * period;
            for &target in stops {
                let mut rejected_last = false;
                while t < target {
                    if st.stats.steps >= MAX_STEPS {
                        return Err(Error::Stalled {
                            t,
                            reason: "tanh_trbdf2: more than 10^7 steps",
                        });
                    }
                    h = h.min(h_max);
                    let last = t + 1.01 * h >= target;
                    let hs = if last { target - t } else { h };
                    let resolution = 8.0 * f64::EPSILON * t.abs().max(f64::MIN_POSITIVE);
                    if last && hs <= resolution {
                        // The stop is within the time resolution: it is reached.
                        t = target;
                        break;
                    }
                    if hs <= resolution || !hs.is_finite() {
                        return Err(Error::Stalled {
                            t,
                            reason: "tanh_trbdf2: step size underflow",
                        });
                    }
                    st.stats.steps += 1;
                    let out = st.step(t, y, f0, hs)?;
                    let err = weighted_norm(out.err, y, out.y1, tol);
                    let fac = if err.is_finite() {
                        (SAFETY * err.max(1e-300).powf(-1.0 / 3.0)).clamp(FAC_MIN, FAC_MAX)
                    } else {
                        FAC_MIN
                    };
                    if err <= 1.0 {
                        st.stats.accepted += 1;
                        on_step(t, hs, y, f0, out.y1, out.f1);
                        let t1 = if last { target } else { t + hs };
                        (t, y, f0) = (t1, out.y1, out.f1);
                        let fac = if rejected_last { fac.min(1.0) } else { fac };
                        rejected_last = false;
                        // A step cut short to land on a stop says little about the next.
                        h = if last && hs < h {
                            h.max(hs * fac)
                        } else {
                            hs * fac
                        };
                    } else {
                        st.stats.rejected += 1;
                        rejected_last = true;
                        h = hs * fac.min(1.0);
                    }
                }
                while next_sample.next_if(|&&s| s <= t).is_some() {
                    let (x, v) = absolute(problem, t, y[0], y[1]);
                    states.push([x, v]);
                }
            }
        }
    }
    let (x_end, v_end) = absolute(problem, t_end, y[0], y[1]);
    let solution = Solution::new(events, x_end, v_end, st.stats);
    Ok((solution, states))
}

/// The regularized body's displacement during one stick phase of the exact engine.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Creep {
    /// The exact stick phase [t_stick, t_slip] (s); the first starts at 0, the last may be cut
    /// by t_end.
    pub t_stick: f64,
    pub t_slip: f64,
    /// x(t_slip) − x(t_stick) of the regularized solution (m); the exact value is 0.
    pub distance: f64,
}

/// The stick phases of the exact engine read off its events: stuck from t = 0 to the first
/// slip, then from each stick to the next slip (or to `t_end`).
pub fn stick_intervals(exact_events: &[MethodEvent], t_end: f64) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    let mut since = Some(0.0);
    for e in exact_events {
        match (e.kind, since) {
            ("slip", Some(t0)) => {
                if e.t > t0 {
                    out.push((t0, e.t));
                }
                since = None;
            }
            ("stick", None) => since = Some(e.t),
            _ => {}
        }
    }
    if let Some(t0) = since {
        if t_end > t0 {
            out.push((t0, t_end));
        }
    }
    out
}

/// Creep of the regularized law (width ε, integrated by [`TanhImplicit`] with `setting`) over
/// each stick phase of the exact engine, given the exact engine's events; also returns the
/// work of the integration.
pub fn creep_per_stick(
    problem: &Problem,
    epsilon: f64,
    exact_events: &[MethodEvent],
    setting: Setting,
) -> Result<(Vec<Creep>, Stats)> {
    let intervals = stick_intervals(exact_events, problem.t_end);
    let samples: Vec<f64> = intervals.iter().flat_map(|&(a, b)| [a, b]).collect();
    let (solution, states) = TanhImplicit { epsilon }.states_at(problem, setting, &samples)?;
    let creep = intervals
        .iter()
        .zip(states.chunks_exact(2))
        .map(|(&(t_stick, t_slip), pair)| Creep {
            t_stick,
            t_slip,
            distance: pair[1][0] - pair[0][0],
        })
        .collect();
    Ok((creep, solution.stats))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bench::problems::PERIODS;
    use crate::models::LawKind;
    use crate::solver::exact::Exact;
    use crate::solver::test_support::{fitted_slope, set_b};
    use crate::solver::TANH_EPSILON;

    const EPSILONS: [f64; 4] = [1e-3, 1e-4, 1e-5, 1e-6];

    #[test]
    fn trbdf2_with_a_fixed_step_converges_at_order_two_on_the_smooth_regularized_problem() {
        for eps in [1e-2, 1e-3] {
            let problem = set_b(LawKind::Harmonic, 1.0);
            let period = problem.law.period;
            let reference = TanhAdaptive { epsilon: eps }
                .solve(&problem, Setting::Tolerance(1e-12))
                .unwrap();
            let mut points = Vec::new();
            for n in [200.0, 400.0, 800.0, 1600.0, 3200.0] {
                let h = period / n;
                let s = TanhImplicit { epsilon: eps }
                    .solve(&problem, Setting::Step(h))
                    .unwrap();
                assert_eq!(s.stats.steps, n as u64);
                let err = (s.x_end - reference.x_end).abs();
                println!(
                    "tanh_trbdf2 ε = {eps:e}: h = T/{n}: |x − x_dopri5(1e-12)| = {err:.3e} m, \
                     {} rhs+Jacobian evals",
                    s.stats.rhs_evals
                );
                points.push((h, err));
            }
            let order = fitted_slope(&points);
            println!("tanh_trbdf2 ε = {eps:e}: fitted order {order:.3}");
            assert!(order > 1.7 && order < 2.3, "ε = {eps}: order {order}");
        }
    }

    #[test]
    fn implicit_and_adaptive_methods_agree_on_the_same_regularized_problem() {
        let eps = 1e-4;
        let problem = set_b(LawKind::Linear, 3.0);
        let exact = Exact.solve(&problem, Setting::Step(1.0)).unwrap();
        let samples: Vec<f64> = stick_intervals(&exact.events, problem.t_end)
            .iter()
            .flat_map(|&(a, b)| [a, b])
            .collect();
        let setting = Setting::Tolerance(1e-10);
        let (a, ya) = TanhAdaptive { epsilon: eps }
            .states_at(&problem, setting, &samples)
            .unwrap();
        let (i, yi) = TanhImplicit { epsilon: eps }
            .states_at(&problem, setting, &samples)
            .unwrap();
        println!(
            "tol 1e-10: x_end dopri5 {:.9e} m, trbdf2 {:.9e} m; evals {} vs {}",
            a.x_end, i.x_end, a.stats.rhs_evals, i.stats.rhs_evals
        );
        // TR-BDF2 controls the error per step at order 2: its global error at tol 1e-10 is
        // 2.7e-8 m (reference: fixed step T/80000), dopri5's 4e-14 m.
        assert!((a.x_end - i.x_end).abs() < 1e-7);
        assert_eq!(a.events.len(), 6);
        assert_eq!(a.events.len(), i.events.len());
        for (ea, ei) in a.events.iter().zip(&i.events) {
            assert_eq!(ea.kind, ei.kind);
            assert!((ea.t - ei.t).abs() < 1e-6, "{ea:?} vs {ei:?}");
        }
        for (p, q) in ya.iter().zip(&yi) {
            assert!((p[0] - q[0]).abs() < 1e-7 && (p[1] - q[1]).abs() < 1e-7);
        }
        assert_eq!(a.stats.events, 6);
        assert_eq!(a.stats.steps, a.stats.accepted + a.stats.rejected);
        assert_eq!(i.stats.steps, i.stats.accepted + i.stats.rejected);
    }

    #[test]
    fn creep_during_the_exact_stick_phases_is_positive_and_shrinks_with_epsilon() {
        for law in [LawKind::Linear, LawKind::Harmonic] {
            let problem = set_b(law, 3.0);
            let exact = Exact.solve(&problem, Setting::Step(1.0)).unwrap();
            let mut previous = f64::INFINITY;
            for eps in EPSILONS {
                let (creep, stats) =
                    creep_per_stick(&problem, eps, &exact.events, Setting::Tolerance(1e-8))
                        .unwrap();
                assert_eq!(creep.len(), 4, "{law:?}: [0, slip], two settled, last cut");
                assert!(creep.iter().all(|c| c.distance > 0.0), "{creep:?}");
                // A settled stick phase: from the first period's stick to the second's slip.
                let settled = creep[1].distance;
                println!(
                    "tanh {law:?} ε = {eps:e}: creep per settled stick phase {settled:.3e} m \
                     ({:.3} ε·T), all phases {:?} m, {} rhs evals",
                    settled / (eps * problem.law.period),
                    creep
                        .iter()
                        .map(|c| format!("{:.3e}", c.distance))
                        .collect::<Vec<_>>(),
                    stats.rhs_evals
                );
                assert!(settled < previous, "{law:?}: creep must shrink with ε");
                previous = settled;
            }
        }
    }

    #[test]
    fn implicit_cost_grows_much_more_slowly_than_explicit_as_epsilon_shrinks() {
        let problem = set_b(LawKind::Linear, 3.0);
        let setting = Setting::Tolerance(1e-8);
        let (mut explicit, mut implicit) = (Vec::new(), Vec::new());
        for eps in EPSILONS {
            let a = TanhAdaptive { epsilon: eps }
                .solve(&problem, setting)
                .unwrap();
            let i = TanhImplicit { epsilon: eps }
                .solve(&problem, setting)
                .unwrap();
            let body = &problem.body;
            let stiffness = body.mu_d * problem.law.normal(0.0) / (body.mass * eps);
            println!(
                "tanh ε = {eps:e} (|∂a/∂v| ≤ {stiffness:.2e} 1/s): rhs evals dopri5 {} \
                 ({} steps), trbdf2 {} ({} steps), x_end {:.6e} / {:.6e} m",
                a.stats.rhs_evals,
                a.stats.steps,
                i.stats.rhs_evals,
                i.stats.steps,
                a.x_end,
                i.x_end
            );
            explicit.push(a.stats.rhs_evals as f64);
            implicit.push(i.stats.rhs_evals as f64);
        }
        let growth_explicit = explicit[3] / explicit[0];
        let growth_implicit = implicit[3] / implicit[0];
        println!(
            "cost growth from ε = 1e-3 to 1e-6: dopri5 ×{growth_explicit:.1}, trbdf2 \
             ×{growth_implicit:.2}"
        );
        assert!(growth_explicit > 50.0);
        assert!(growth_implicit < 3.0);
    }

    #[test]
    fn events_are_one_slip_and_one_stick_per_period_with_an_early_slip() {
        let problem = set_b(LawKind::Linear, 3.0);
        let period = problem.law.period;
        let exact = Exact.solve(&problem, Setting::Step(1.0)).unwrap();
        let setting = Setting::Tolerance(1e-8);
        let eps = 1e-5;
        for s in [
            TanhAdaptive { epsilon: eps }
                .solve(&problem, setting)
                .unwrap(),
            TanhImplicit { epsilon: eps }
                .solve(&problem, setting)
                .unwrap(),
        ] {
            assert_eq!(s.events.len(), exact.events.len());
            for (m, e) in s.events.iter().zip(&exact.events) {
                assert_eq!(m.kind, e.kind);
                let dt = m.t - e.t;
                println!(
                    "tanh ε = {eps:e}: {} at {:.6} s, exact {:.6} s",
                    m.kind, m.t, e.t
                );
                if m.kind == "slip" {
                    // The regularized law slips where μd N_f = F, before μs N_f = F.
                    assert!(dt < 0.0 && dt > -0.05 * period, "{m:?} vs {e:?}");
                } else {
                    assert!(dt.abs() < 2e-3 * period, "{m:?} vs {e:?}");
                }
            }
        }
    }

    /// Asserts what a regularized method does on the belt (`s`, at ε = [`TANH_EPSILON`]): it
    /// creeps until D reaches μd N_f, slips just after x_d/v_b, and settles to the harmonic
    /// oscillation of period 2π/ω about x_d whose top only grazes the belt's speed.
    fn assert_free_oscillation_on_the_belt(method: &str, s: &Solution) {
        let (p, problem) = crate::bench::belt::problem().unwrap();
        let c = crate::models::belt::formula::evaluate(&p);
        let natural = 2.0 * std::f64::consts::PI / c.omega;
        let slips: Vec<f64> = s
            .events
            .iter()
            .filter(|e| e.kind == "slip")
            .map(|e| e.t)
            .collect();
        // Slips and band visits alternate from the first slip; none reverses.
        assert!(
            s.events.iter().step_by(2).all(|e| e.kind == "slip"),
            "{method}: {:?}",
            s.events
        );
        assert!(s
            .events
            .iter()
            .skip(1)
            .step_by(2)
            .all(|e| e.kind == "stick"));
        // Measured (ε = 1e-4): first slip 0.802 s, x_d/v_b = 0.785 s, x_s/v_b = 1.177 s.
        let kinetic = c.x_d / p.v_b;
        println!(
            "{method} on the belt: first slip {:.4} s (x_d/v_b {kinetic:.4}, x_s/v_b {:.4})",
            slips[0], c.first_slip_time
        );
        assert!(slips[0] > kinetic && slips[0] < 1.05 * kinetic, "{method}");
        // Settled: slip to slip 0.62830 s = 2π/ω (0.62832 s), not the closed period 1.149 s.
        let settled = slips[slips.len() - 1] - slips[slips.len() - 2];
        println!(
            "  {} slips; settled cycle {settled:.5} s, 2π/ω {natural:.5} s, closed period {:.5} s",
            slips.len(),
            c.period
        );
        assert!((settled - natural).abs() < 1e-3 * natural, "{method}");
        // One slip per natural period from the first: 37 in the 20 closed-form periods.
        let cycles = ((problem.t_end - slips[0]) / natural).ceil() as usize;
        assert_eq!(slips.len(), cycles, "{method}");
        assert!(cycles > PERIODS as usize);
        // Its "stick" is a graze of the creep band: 0.032 s first, 0.027 s settled, 3.5 % of t_stick.
        let visits: Vec<f64> = s
            .events
            .windows(2)
            .filter(|w| w[0].kind == "stick")
            .map(|w| w[1].t - w[0].t)
            .collect();
        println!(
            "  band visits {:.4} … {:.4} s, t_stick {:.4} s",
            visits[0],
            visits[visits.len() - 1],
            c.t_stick
        );
        assert!(
            visits.windows(2).all(|w| w[1] < w[0]),
            "{method}: {visits:?}"
        );
        assert!(visits[visits.len() - 1] < 0.05 * c.t_stick, "{method}");
        // The end state lies on the circle of radius v_b/ω about (x_d, 0), within 3 %; at the
        // end it moves backwards (v_end −0.045 m/s), where the exact body rides at v_b.
        let radius = ((s.x_end - c.x_d).powi(2) + (s.v_end / c.omega).powi(2)).sqrt();
        println!(
            "  end: x {:.5} m, v {:.5} m/s, radius {radius:.3e} m, v_b/ω {:.3e} m",
            s.x_end,
            s.v_end,
            p.v_b / c.omega
        );
        assert!(
            (radius - p.v_b / c.omega).abs() < 0.03 * p.v_b / c.omega,
            "{method}"
        );
        assert!(s.v_end < 0.0, "{method}");
    }

    #[test]
    fn on_the_belt_it_slips_at_the_kinetic_threshold_and_settles_to_the_free_oscillation() {
        let (_, problem) = crate::bench::belt::problem().unwrap();
        let s = TanhAdaptive {
            epsilon: TANH_EPSILON,
        }
        .solve_surface(&problem, Setting::Tolerance(1e-8))
        .unwrap();
        assert_free_oscillation_on_the_belt("tanh_dopri5", &s);
    }

    #[test]
    fn trbdf2_on_the_belt_settles_to_the_free_oscillation_and_converges_to_the_same_law() {
        let (p, problem) = crate::bench::belt::problem().unwrap();
        let method = TanhImplicit {
            epsilon: TANH_EPSILON,
        };
        let s = method
            .solve_surface(&problem, Setting::Tolerance(1e-8))
            .unwrap();
        assert_free_oscillation_on_the_belt("tanh_trbdf2", &s);
        // The same regularized law as tanh_dopri5's: the events converge to those of dopri5 at
        // tolerance 1e-12 (73 events, the last slip at 23.419 s).
        let reference = TanhAdaptive {
            epsilon: TANH_EPSILON,
        }
        .solve_surface(&problem, Setting::Tolerance(1e-12))
        .unwrap();
        let errors: Vec<(f64, f64)> = [1e-6, 1e-8, 1e-10]
            .iter()
            .map(|&tol| {
                let s = method
                    .solve_surface(&problem, Setting::Tolerance(tol))
                    .unwrap();
                let err = crate::bench::belt::error(&s, &reference.events);
                let dx = (s.x_end - reference.x_end).abs();
                println!(
                    "tanh_trbdf2 on the belt, tol {tol:e}: event error {err:.2e} s, \
                     |x_end − x_ref| {dx:.2e} m, {} rhs+Jacobian evals",
                    s.stats.rhs_evals
                );
                (err, dx)
            })
            .collect();
        // Measured: 7.8e-3, 4.7e-4, 2.2e-5 s; x_end 3.5e-4, 2.1e-5, 1.0e-6 m.
        assert!(
            errors
                .windows(2)
                .all(|w| w[1].0 < 0.2 * w[0].0 && w[1].1 < 0.2 * w[0].1),
            "{errors:?}"
        );
        assert!(errors[2].0 < 1e-4 && errors[2].1 < 1e-5, "{errors:?}");
        // With a fixed step: order 2 in the event times (measured 9.1e-4 … 1.4e-5 s from
        // h = T/200 to T/1600 of the natural period T = 2π/ω).
        let c = crate::models::belt::formula::evaluate(&p);
        let natural = 2.0 * std::f64::consts::PI / c.omega;
        let points: Vec<(f64, f64)> = [200.0, 400.0, 800.0, 1600.0]
            .iter()
            .map(|n| {
                let h = natural / n;
                let s = method.solve_surface(&problem, Setting::Step(h)).unwrap();
                (h, crate::bench::belt::error(&s, &reference.events))
            })
            .collect();
        let order = fitted_slope(&points);
        println!("tanh_trbdf2 on the belt, fixed step: {points:?}, order {order:.3}");
        assert!(order > 1.8 && order < 2.2, "order {order}: {points:?}");
    }

    #[test]
    fn bad_input_on_the_belt_is_refused() {
        let (_, problem) = crate::bench::belt::problem().unwrap();
        let tol = Setting::Tolerance(1e-6);
        let adaptive = TanhAdaptive { epsilon: 1e-4 };
        let implicit = TanhImplicit { epsilon: 1e-4 };
        assert!(adaptive
            .solve_surface(&problem, Setting::Step(0.01))
            .is_err());
        assert!(implicit
            .solve_surface(&problem, Setting::Tolerance(0.0))
            .is_err());
        assert!(implicit
            .solve_surface(&problem, Setting::Step(f64::NAN))
            .is_err());
        assert!(TanhAdaptive { epsilon: -1.0 }
            .solve_surface(&problem, tol)
            .is_err());
        assert!(TanhImplicit { epsilon: 0.0 }
            .solve_surface(&problem, tol)
            .is_err());
        let mut flat = problem.clone();
        flat.law.stiffness = 0.0;
        for method in [&adaptive as &dyn Method, &implicit] {
            let e = method.solve_surface(&flat, tol).unwrap_err().to_string();
            assert!(e.contains("stiffness") && e.contains(method.name()), "{e}");
        }
        // A force growing with the position: a step so long that the stage equation is no
        // longer monotone (c² ∂D/∂x/M ≥ 1) is refused, not guessed.
        let mut pushing = problem.clone();
        pushing.law.stiffness = 50.0;
        assert!(matches!(
            implicit.solve_surface(&pushing, Setting::Step(1.0)),
            Err(Error::Stalled { .. })
        ));
    }

    #[test]
    fn stick_intervals_start_stuck_and_close_at_the_end() {
        let ev = |t, kind| MethodEvent { t, kind };
        let events = [
            ev(1.0, "slip"),
            ev(2.0, "stick"),
            ev(3.0, "slip"),
            ev(4.0, "stick"),
        ];
        assert_eq!(
            stick_intervals(&events, 5.0),
            vec![(0.0, 1.0), (2.0, 3.0), (4.0, 5.0)]
        );
        assert_eq!(stick_intervals(&[], 5.0), vec![(0.0, 5.0)]);
    }

    #[test]
    fn bad_input_is_refused() {
        let problem = set_b(LawKind::Linear, 1.0);
        let h = Setting::Step(problem.law.period / 100.0);
        let tol = Setting::Tolerance(1e-6);
        assert!(TanhAdaptive { epsilon: 0.0 }.solve(&problem, tol).is_err());
        assert!(TanhImplicit { epsilon: f64::NAN }
            .solve(&problem, h)
            .is_err());
        assert!(TanhAdaptive { epsilon: 1e-4 }.solve(&problem, h).is_err());
        assert!(TanhImplicit { epsilon: 1e-4 }
            .solve(&problem, Setting::Tolerance(-1.0))
            .is_err());
        assert!(TanhImplicit { epsilon: 1e-4 }
            .states_at(&problem, tol, &[0.1, 0.05])
            .is_err());
        assert!(matches!(
            TanhImplicit { epsilon: 1e-4 }.solve(&problem, Setting::Step(1e-12)),
            Err(Error::Stalled { .. })
        ));
    }
}
