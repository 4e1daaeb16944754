//! Time-stepping methods for the dry-friction system, compared against the exact engine
//! ([`crate::engine`]) in `stickslip bench`: the methods people use for stick-slip, each in one
//! file behind the [`Method`] trait, each counting its work in [`Stats`].
//!
//! ```text
//! exact       event-driven closed-form arcs (the reference)
//! dopri5      Dormand–Prince 5(4), step control, dense output, events on the interpolant
//! rk4         fixed-step RK4, switching functions checked each step, events by bisection
//! moreau      Moreau–Jean θ-method, set-valued Coulomb law solved exactly per step
//! tanh        regularized friction μd tanh(v/ε), adaptive (dopri5) or implicit (TR-BDF2)
//! euler_sign  explicit Euler with sign(v) friction (the spreadsheet method)
//! ```
//!
//! With the `peers` feature, `diffsol_peer` adds diffsol's Tsit45 on dopri5's event loop: the
//! benchmark's peer from a Rust ODE library (not in [`methods`], which lists the core methods).
//! Its name, [`DIFFSOL_PEER`], is known without it, so a build without the peer can say so.
//!
//! Every method integrates the same [`Problem`]: one body under D(t) and N_f(t) from a
//! [`ForceLaw`], starting stuck at rest at x = 0, t = 0, up to `t_end`. Every method, the
//! diffsol peer included, also integrates a [`surface::SurfaceProblem`] (the belt: a force
//! affine in x, sticking at the surface's speed), stepping it as a [`surface::System`]
//! (dopri5 and the diffsol peer through a generic state machine beside their fast path of
//! forces of time only; the tanh methods with the relative velocity in the tanh, TR-BDF2's
//! Newton with ∂D/∂x in its Jacobian); [`Method::solve_surface`]'s default refuses it, for a
//! method of forces of time only.

use serde::Serialize;

use crate::engine::{Body, ForceLaw};
use crate::error::Result;

#[cfg(feature = "peers")]
pub mod diffsol_peer;
pub mod dopri5;
pub mod euler_sign;
pub mod exact;
pub mod moreau;
pub mod rk4;
pub mod surface;
pub mod tanh;

/// The name of the compiled peer from a Rust ODE library (diffsol's Tsit45), built in with the
/// cargo feature `peers`.
pub const DIFFSOL_PEER: &str = "diffsol_tsit45";

/// Default regularization width ε of the tanh methods (m/s).
pub const TANH_EPSILON: f64 = 1e-4;

/// Every method of the comparison, the exact reference first.
pub fn methods() -> Vec<Box<dyn Method>> {
    vec![
        Box::new(exact::Exact),
        Box::new(dopri5::Dopri5),
        Box::new(rk4::Rk4),
        Box::new(moreau::Moreau),
        Box::new(tanh::TanhAdaptive {
            epsilon: TANH_EPSILON,
        }),
        Box::new(tanh::TanhImplicit {
            epsilon: TANH_EPSILON,
        }),
        Box::new(euler_sign::EulerSign),
    ]
}

/// Work counters every method fills (the work-precision chart reads only these and the result).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Stats {
    /// Evaluations of the right-hand side a(t, v) (for `exact`: closed-form piece evaluations).
    pub rhs_evals: u64,
    /// Steps attempted, accepted and rejected (fixed-step methods: accepted = steps).
    pub steps: u64,
    pub accepted: u64,
    pub rejected: u64,
    /// Slip/stick events located (or, for methods without a stick state, velocity sign changes).
    pub events: u64,
}

/// A slip or stick event found by a method (absolute time, s).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct MethodEvent {
    pub t: f64,
    /// "slip", "stick" or "reversal" (a velocity sign change without a stick).
    pub kind: &'static str,
}

/// What a method returns: its events, the final state and its work.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Solution {
    pub events: Vec<MethodEvent>,
    /// Position (m) and velocity (m/s) at `t_end`.
    pub x_end: f64,
    pub v_end: f64,
    pub stats: Stats,
}

impl Solution {
    /// A method's result; `stats.events` is set to the number of `events`.
    pub fn new(events: Vec<MethodEvent>, x_end: f64, v_end: f64, mut stats: Stats) -> Self {
        stats.events = events.len() as u64;
        Solution {
            events,
            x_end,
            v_end,
            stats,
        }
    }
}

/// The dry-friction initial-value problem shared by all methods.
#[derive(Clone, Debug, PartialEq)]
pub struct Problem {
    pub body: Body,
    pub law: ForceLaw,
    /// Final time (s).
    pub t_end: f64,
}

impl Problem {
    /// D(t) and N_f(t) (N) at absolute time t.
    pub fn forces(&self, t: f64) -> (f64, f64) {
        (self.law.drive(t), self.law.normal(t))
    }

    /// Acceleration while slipping in direction `s` (m/s²): (D − s μd N_f)/M.
    pub fn slip_acceleration(&self, t: f64, s: f64) -> f64 {
        let (d, n) = self.forces(t);
        self.body.slip_acceleration(d, n, s)
    }

    /// Static switching function for direction `s`: s·D − μs N_f (N); the body leaves rest in
    /// direction s when it becomes positive.
    pub fn static_margin(&self, t: f64, s: f64) -> f64 {
        let (d, n) = self.forces(t);
        s * d - self.body.mu_s * n
    }
}

/// The accuracy knob of a method: a tolerance (adaptive) or a step size (fixed-step).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum Setting {
    /// Relative = absolute tolerance of an adaptive method.
    Tolerance(f64),
    /// Step size h (s) of a fixed-step method.
    Step(f64),
}

impl Setting {
    /// The step size h (s) of a fixed-step method named `method`; any other setting, or an h
    /// that is not finite and positive, is refused naming the setting.
    pub fn fixed_step(self, method: &str) -> Result<f64> {
        match self {
            Setting::Step(h) if h.is_finite() && h > 0.0 => Ok(h),
            _ => Err(crate::error::Error::InvalidParam {
                name: "setting",
                value: format!("{self:?}"),
                rule: format!(
                    "{method} is a fixed-step method: give Setting::Step(h) with finite h > 0 (s)"
                ),
            }),
        }
    }
}

impl Setting {
    /// The tolerance (rtol = atol) of an adaptive method named `method`; any other setting,
    /// or a tolerance that is not finite and positive, is refused naming the setting.
    pub fn tolerance(self, method: &str) -> Result<f64> {
        match self {
            Setting::Tolerance(tol) if tol.is_finite() && tol > 0.0 => Ok(tol),
            _ => Err(crate::error::Error::InvalidParam {
                name: "setting",
                value: format!("{self:?}"),
                rule: format!(
                    "{method} is adaptive: give Setting::Tolerance(tol) with finite tol > 0"
                ),
            }),
        }
    }
}

/// A time-stepping method.
pub trait Method: Sync {
    /// Short identifier, e.g. "dopri5".
    fn name(&self) -> &'static str;
    /// Solves `problem` with the given accuracy setting.
    fn solve(&self, problem: &Problem, setting: Setting) -> Result<Solution>;
    /// Solves the autonomous `problem` of a moving surface; refused by a method that takes
    /// forces of time only.
    fn solve_surface(
        &self,
        _problem: &surface::SurfaceProblem,
        _setting: Setting,
    ) -> Result<Solution> {
        Err(surface::refused(self.name()))
    }
    /// The work the benchmark times: [`Method::solve`], unless the method does the same
    /// integration with less bookkeeping for its output (the exact engine).
    fn solve_timed(&self, problem: &Problem, setting: Setting) -> Result<()> {
        self.solve(problem, setting).map(drop)
    }
}

/// Helpers shared by the methods' tests: the problems they solve and how they compare.
#[cfg(test)]
pub(crate) mod test_support {
    use super::exact::Exact;
    use super::{Method, Problem, Setting, Solution};
    use crate::engine::{Affine, Basis, Body, ForceLaw, Piece};
    use crate::models::pulled_mass::PulledMassParams;
    use crate::models::woodpecker::WoodpeckerParams;
    use crate::models::{pulled_mass, woodpecker, LawKind};

    /// Largest event-time error (s), after checking that the event kinds agree.
    pub fn event_error(got: &Solution, want: &Solution) -> f64 {
        let kinds = |s: &Solution| s.events.iter().map(|e| e.kind).collect::<Vec<_>>();
        assert_eq!(kinds(got), kinds(want));
        got.events
            .iter()
            .zip(&want.events)
            .map(|(a, b)| (a.t - b.t).abs())
            .fold(0.0, f64::max)
    }

    /// The exact event-driven engine's solution (it needs no setting).
    pub fn exact(problem: &Problem) -> Solution {
        Exact.solve(problem, Setting::Step(1.0)).unwrap()
    }

    /// The pulled mass with μs 0.4, μd 0.35 and force F (N), other parameters default, over
    /// `periods` periods.
    pub fn pulled(force: f64, law: LawKind, periods: f64) -> Problem {
        let p = PulledMassParams {
            mu_s: 0.4,
            mu_d: 0.35,
            force,
            ..PulledMassParams::default()
        };
        let law = pulled_mass::force_law(&p, law).expect("valid law");
        Problem {
            body: pulled_mass::body(&p),
            t_end: periods * law.period,
            law,
        }
    }

    /// Set B (guide §13): F = 0.10 N: one slip and one stick per period.
    pub fn set_b(law: LawKind, periods: f64) -> Problem {
        pulled(0.10, law, periods)
    }

    /// The woodpecker of the paper's Fig. 15 (the default set) over 6 periods: two slips and
    /// two sticks per period once steady.
    pub fn woodpecker_fig15(law: LawKind) -> Problem {
        let p = WoodpeckerParams::default();
        let law = woodpecker::force_law(&p, law).expect("valid law");
        Problem {
            body: woodpecker::body(&p),
            t_end: 6.0 * law.period,
            law,
        }
    }

    /// D = cos 2πt (N) with a constant N_f = 0.5 N over 3 s: an immediate slip at t = 0, then
    /// the body slides back and forth, turning without stopping (a reversal) where
    /// |D| > μs N_f at v = 0.
    pub fn back_and_forth() -> Problem {
        let law = ForceLaw::new(
            1.0,
            vec![Piece {
                start: 0.0,
                end: 1.0,
                basis: Basis::Cos {
                    omega: std::f64::consts::TAU,
                    shift: 0.0,
                },
                drive: Affine::new(0.0, 1.0),
                normal: Affine::new(0.5, 0.0),
            }],
        )
        .unwrap();
        Problem {
            body: Body {
                mass: 1.0,
                mu_s: 0.4,
                mu_d: 0.35,
            },
            law,
            t_end: 3.0,
        }
    }

    /// The kinds of the events in the last period of `problem` (a whole number of periods).
    pub fn last_period_kinds(s: &Solution, problem: &Problem) -> Vec<&'static str> {
        let period = problem.law.period;
        let start = ((problem.t_end / period).round() - 1.0) * period;
        s.events
            .iter()
            .filter(|e| e.t >= start)
            .map(|e| e.kind)
            .collect()
    }

    /// Least-squares slope of log(err) against log(h).
    pub fn fitted_slope(points: &[(f64, f64)]) -> f64 {
        let n = points.len() as f64;
        let (lx, ly): (Vec<f64>, Vec<f64>) = points.iter().map(|&(h, e)| (h.ln(), e.ln())).unzip();
        let mx = lx.iter().sum::<f64>() / n;
        let my = ly.iter().sum::<f64>() / n;
        let sxy: f64 = lx.iter().zip(&ly).map(|(a, b)| (a - mx) * (b - my)).sum();
        let sxx: f64 = lx.iter().map(|a| (a - mx) * (a - mx)).sum();
        sxy / sxx
    }
}
