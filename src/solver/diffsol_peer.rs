//! The compiled peer of `stickslip bench` from a Rust ODE library: diffsol's explicit adaptive
//! Runge–Kutta (Tsitouras 5(4), [`DiffsolTsit45`], `Setting::Tolerance(tol)`), driven by the
//! stick/slip state machine of the tool's own DOPRI5 ([`super::dopri5::drive`]), so that the
//! two differ only in the integrator and its event location. On a moving surface (the belt,
//! [`Method::solve_surface`]) the machine is dopri5's generic one ([`drive_system`]), in the
//! surface's frame u = x − v_s t, w = v − v_s: sticking is w = 0, the stick ends where the
//! static margin |D(x)| − μs N_f of the carried body turns positive, the state y = (u, w).
//!
//! ```text
//! slipping, direction s:  y = (x, v),  y' = (v, (D − s μd N_f)/M)    diffsol root_fn  g = s·v
//! stuck:                  y = (x, 0) constant                         the dopri5 stuck walk
//! belt:                   y = (u, w),  y' = (w, (D(u + v_s t) − s μd N_f)/M),  g = s·w
//! ```
//!
//! * Slip phase: one diffsol problem and one solver per solve (rtol = tol, atol = (tol, tol)),
//!   restarted at each slip onset (its initial step by diffsol's own Hairer heuristic); its stop
//!   time (`set_stop_time`) is the next breakpoint of the force law or t_end, so steps end where
//!   the right-hand side has kinks, as in dopri5.
//! * Stick event: diffsol's root finding (a sign change of g between step ends, located by the
//!   Illinois-modified secant of SUNDIALS on its interpolant). Like most event-locating codes,
//!   and unlike the tool's dopri5, it checks step ends only: a dip of s·v below 0 and back
//!   inside one step is not seen (the `dopri5_endpoints` failure). A slip starts from rest, so
//!   g is exactly 0 where its first step starts and diffsol's sign test cannot see a stop inside
//!   that step: the driver locates it ([`unreported_stop`]).
//! * Stuck phase, transitions (stick, reversal, slip goes on): shared with dopri5.
//! * Work: every evaluation of the right-hand side closure (the two of each restart
//!   included), diffsol's accepted steps and error-test failures, and the stuck walk's counts.
//! * Errors of diffsol (a step size below its minimum, too many error-test failures) become
//!   [`Error::Library`], never a panic.

use std::cell::Cell;

use diffsol::{
    DiffsolError, ExplicitRk, NalgebraContext, NalgebraMat, NalgebraVec, NonLinearOp, OdeBuilder,
    OdeEquations, OdeSolverMethod, OdeSolverStopReason, Tableau, Vector,
};

use super::dopri5::{drive, drive_system, Forces, Labels, Options, SlipEnd, MAX_STEPS};
use super::surface::{SurfaceProblem, System};
use super::{Method, Problem, Setting, Solution, Stats};
use crate::error::{Error, Result};

/// The method's name in the benchmark.
pub const NAME: &str = super::DIFFSOL_PEER;

/// The matrix type of the diffsol problem: nalgebra, serial (the state has two components).
type M = NalgebraMat<f64>;

/// diffsol's Tsit45 (the Tsitouras 2011 5(4) pair, FSAL, with dense output) with its root
/// finding for the stick event. Setting: `Setting::Tolerance(tol)`.
pub struct DiffsolTsit45;

impl Method for DiffsolTsit45 {
    fn name(&self) -> &'static str {
        NAME
    }

    fn solve(&self, problem: &Problem, setting: Setting) -> Result<Solution> {
        solve(problem, setting.tolerance(self.name())?)
    }

    /// The belt: dopri5's generic state machine ([`drive_system`]) in the surface's frame
    /// u = x − v_s t, w = v − v_s, each slip phase integrated by Tsit45 with the root s·w.
    fn solve_surface(&self, problem: &SurfaceProblem, setting: Setting) -> Result<Solution> {
        let tol = setting.tolerance(self.name())?;
        let v_s = problem.surface_speed();
        tsit45(
            problem,
            tol,
            |t, u, s| problem.slip_acceleration(t, u + v_s * t, s),
            |phase| drive_system(problem, &Options::default(), &LABELS, phase),
        )
    }
}

/// The stalls of the state machine, naming the method.
const LABELS: Labels = Labels {
    recurring: "diffsol_tsit45: events keep recurring at one instant",
    too_many_steps: "diffsol_tsit45: too many steps",
};

/// A diffsol error at time t as the crate's error.
fn library(t: f64) -> impl Fn(DiffsolError) -> Error {
    move |e| Error::Library {
        library: "diffsol",
        t,
        reason: e.to_string(),
    }
}

/// Integrates `problem` with diffsol's Tsit45 at rtol = atol = `tol` on the shared event loop.
fn solve(problem: &Problem, tol: f64) -> Result<Solution> {
    let body = problem.body;
    let forces = Forces::new(problem);
    tsit45(
        problem,
        tol,
        |t, _x, s| {
            let (d, n) = forces.at(t);
            body.slip_acceleration(d, n, s)
        },
        |phase| {
            drive(
                problem,
                &Options::default(),
                &LABELS,
                |_, t0, x, s, stats| phase(t0, x, s, stats),
            )
        },
    )
}

/// A slip phase of the state machine: from rest (relative to the surface) at (t0, x0) in
/// direction s, until s·v reaches 0 or t_end.
type Phase<'p> = dyn FnMut(f64, f64, f64, &mut Stats) -> Result<SlipEnd> + 'p;

/// Builds the diffsol problem of `problem`'s slip phases, y = (x, v) (in the surface's frame on
/// a [`System`] with a moving surface), y' = (v, `accel`(t, x, s)), with the root s·v, and one
/// Tsit45 solver; `run` drives the state machine, each slip phase on that solver.
fn tsit45(
    problem: &impl System,
    tol: f64,
    accel: impl Fn(f64, f64, f64) -> f64,
    run: impl FnOnce(&mut Phase<'_>) -> Result<Solution>,
) -> Result<Solution> {
    // The slip direction s is read by the closures, so one diffsol problem and one solver serve
    // every slip phase (`restart` sets the state at its onset).
    let dir = Cell::new(0.0_f64);
    let evals = Cell::new(0_u64);
    let rhs = |y: &[f64], _p: &[f64], t: f64, dy: &mut [f64]| {
        evals.set(evals.get() + 1);
        dy[0] = y[1];
        dy[1] = accel(t, y[0], dir.get());
    };
    // Each slip phase sets its own initial state (`restart`).
    let init = |_p: &[f64], _t: f64, y: &mut [f64]| y.fill(0.0);
    let stick = |y: &[f64], _p: &[f64], _t: f64, g: &mut [f64]| {
        g[0] = dir.get() * y[1];
    };
    let ode = OdeBuilder::<M>::new()
        .rtol(tol)
        .atol([tol, tol])
        .rhs(rhs)
        .init(init, 2)
        .root(stick, 1)
        .build()
        .map_err(library(0.0))?;
    let order = Tableau::<f64>::tsit45().order();
    let mut solver = ode.tsit45().map_err(library(0.0))?;
    run(&mut |t0, x, s, stats| {
        dir.set(s);
        evals.set(0);
        restart(&mut solver, &ode, order, t0, x);
        let end = slip(&mut solver, problem, t0, s, stats);
        stats.rhs_evals += evals.get();
        end
    })
}

/// Starts a slip phase on the one solver of the run: the state at rest at (t0, x), its
/// derivative, and diffsol's own initial step (Hairer's heuristic, as a new solver would
/// compute it); diffsol re-initializes its root finder and stop time at the next step. Two
/// evaluations of the right-hand side, as for a new solver, without building one (building
/// one per slip was ~24 µs of a 20-period solve).
fn restart<'a, Eqn>(
    solver: &mut ExplicitRk<'a, Eqn, M>,
    ode: &'a diffsol::OdeSolverProblem<Eqn>,
    order: usize,
    t0: f64,
    x: f64,
) where
    Eqn: OdeEquations<T = f64, V = NalgebraVec<f64>, C = NalgebraContext, M = M>,
{
    let mut state = solver.state_mut();
    state.y.set_index(0, x);
    state.y.set_index(1, 0.0);
    *state.t = t0;
    ode.eqn.rhs().call_inplace(state.y, t0, state.dy);
    state.set_step_size(ode.h0, &ode.atol, ode.rtol, &ode.eqn, order);
}

/// One slip phase in direction `dir` from t0 (the solver restarted there) until s·v reaches 0
/// (diffsol's root, or [`unreported_stop`]) or t_end; the steps diffsol took go into `stats`.
fn slip<'a, Eqn>(
    solver: &mut ExplicitRk<'a, Eqn, M>,
    problem: &impl System,
    t0: f64,
    dir: f64,
    stats: &mut Stats,
) -> Result<SlipEnd>
where
    Eqn: OdeEquations<T = f64, V = NalgebraVec<f64>, C = NalgebraContext, M = M> + 'a,
{
    let t_end = problem.t_end();
    let mut stop = t0;
    let taken = |solver: &ExplicitRk<'a, Eqn, M>| {
        let statistics = solver.get_statistics();
        (
            statistics.number_of_steps as u64,
            statistics.number_of_error_test_failures as u64,
        )
    };
    // diffsol's counts run over the whole solve.
    let before = taken(solver);
    let result = loop {
        let (t, h) = (solver.state().t, solver.state().h);
        // The next stop: a breakpoint or t_end, beyond diffsol's own roundoff of "now" (it
        // refuses a stop time within it).
        let roundoff = 100.0 * f64::EPSILON * (t.abs() + h.abs());
        if stop <= t + roundoff {
            while stop <= t + roundoff && stop < t_end {
                stop = problem.breakpoint_after(stop).min(t_end);
            }
            if stop <= t + roundoff {
                let y = solver.state().y;
                break Ok(SlipEnd::End {
                    y: [y.get_index(0), y.get_index(1)],
                });
            }
            if let Err(e) = solver.set_stop_time(stop) {
                break Err(library(t)(e));
            }
        }
        let (accepted, rejected) = taken(solver);
        if stats.steps + accepted + rejected - before.0 - before.1 >= MAX_STEPS {
            break Err(Error::Stalled {
                t,
                reason: "diffsol_tsit45: too many steps",
            });
        }
        match solver.step() {
            Ok(OdeSolverStopReason::InternalTimestep | OdeSolverStopReason::TstopReached) => {
                if dir * solver.state().y.get_index(1) < 0.0 {
                    break unreported_stop(solver, dir, t, solver.state().t);
                }
            }
            Ok(OdeSolverStopReason::RootFound(te, _)) => {
                break solver
                    .interpolate(te)
                    .map(|y| SlipEnd::Stop {
                        t: te,
                        x: y.get_index(0),
                    })
                    .map_err(library(te));
            }
            Err(e) => break Err(library(t)(e)),
        }
    };
    let (accepted, rejected) = taken(solver);
    let (accepted, rejected) = (accepted - before.0, rejected - before.1);
    stats.accepted += accepted;
    stats.rejected += rejected;
    stats.steps += accepted + rejected;
    result
}

/// The stop of a slip that ended inside a step without a root from diffsol: s·v < 0 at the
/// step's end t1. diffsol reports a root where g(t_a)·g(t_b) < 0 between step ends, and a slip
/// starts from rest, so g = s·v is exactly 0 at the first step's start: a slip shorter than
/// its first step (a weak pull) would otherwise slide on with friction pushing it backwards.
/// SUNDIALS, whose root finding diffsol follows, looks a little past a zero at the start for
/// this reason; here the zero is located on diffsol's interpolant by bisection between a
/// point where s·v > 0 (halving the step from t1 towards t0: the slip starts with s·a > 0)
/// and t1, to the ulp.
fn unreported_stop<'a, Eqn>(
    solver: &ExplicitRk<'a, Eqn, M>,
    dir: f64,
    t0: f64,
    t1: f64,
) -> Result<SlipEnd>
where
    Eqn: OdeEquations<T = f64, V = NalgebraVec<f64>, C = NalgebraContext, M = M> + 'a,
{
    let g = |t: f64| -> Result<f64> {
        let y = solver.interpolate(t).map_err(library(t))?;
        Ok(dir * y.get_index(1))
    };
    let (mut lo, mut hi) = (t0 + 0.5 * (t1 - t0), t1);
    while g(lo)? <= 0.0 {
        hi = lo;
        lo = t0 + 0.5 * (lo - t0);
        if lo <= t0 {
            // No positive speed inside the step: the slip stopped at its start.
            lo = t0;
            break;
        }
    }
    loop {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if g(mid)? > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let y = solver.interpolate(hi).map_err(library(hi))?;
    Ok(SlipEnd::Stop {
        t: hi,
        x: y.get_index(0),
    })
}

#[cfg(test)]
mod tests {
    use super::super::dopri5::Dopri5;
    use super::super::test_support::{back_and_forth, event_error, exact, pulled};
    use super::*;
    use crate::bench::problems::sweep_problems;
    use crate::models::pulled_mass::PulledMassParams;
    use crate::models::LawKind;

    /// The four problems of the benchmark (20 periods): at tolerance 1e-8 every slip and
    /// stick of the exact engine is found, in order, each located by diffsol's root finding.
    #[test]
    fn bench_problems_have_the_exact_events_at_tol_1e8() {
        for bp in sweep_problems().unwrap() {
            let want = exact(&bp.problem);
            let got = DiffsolTsit45
                .solve(&bp.problem, Setting::Tolerance(1e-8))
                .unwrap();
            assert_eq!(got.events.len(), want.events.len(), "{}", bp.id);
            // Measured: 1.1e-8 s (set B), 6.1e-9 s (woodpecker) on the harmonic laws; 5e-14 s
            // on the linear laws (cubic arcs, integrated exactly: the root finder's own
            // resolution).
            let err = event_error(&got, &want);
            assert!(err < 1e-7, "{}: event error {err:e} s", bp.id);
            assert!((got.x_end - want.x_end).abs() < 1e-7, "{}", bp.id);
            assert_eq!(got.stats.steps, got.stats.accepted + got.stats.rejected);
            assert_eq!(got.stats.events, want.events.len() as u64);
            // At least one restart (two evaluations) and one step (six) per slip.
            assert!(
                got.stats.rhs_evals > 8 * got.stats.events / 2,
                "{:?}",
                got.stats
            );
        }
    }

    #[test]
    fn set_b_event_error_decreases_with_the_tolerance() {
        // Harmonic law (on the linear law the arcs are cubics, integrated exactly).
        let problem = pulled(0.10, LawKind::Harmonic, 20.0);
        let want = exact(&problem);
        let errors: Vec<f64> = [1e-4, 1e-6, 1e-8, 1e-10, 1e-12]
            .iter()
            .map(|&tol| {
                let got = DiffsolTsit45
                    .solve(&problem, Setting::Tolerance(tol))
                    .unwrap();
                event_error(&got, &want)
            })
            .collect();
        // Measured (20 periods): 1.8e-5, 1.1e-6, 1.1e-8, 1.6e-10, 1.5e-12 s.
        for pair in errors.windows(2) {
            assert!(pair[1] < 0.5 * pair[0], "{errors:?}");
        }
        assert!(errors[4] < 1e-11, "{errors:?}");
    }

    #[test]
    fn reversals_and_an_immediate_slip_match_the_exact_engine() {
        let problem = back_and_forth();
        let want = exact(&problem);
        let got = DiffsolTsit45
            .solve(&problem, Setting::Tolerance(1e-10))
            .unwrap();
        // Measured: ≤ 2.6e-10 s.
        assert!(event_error(&got, &want) < 1e-8, "{:?}", got.events);
        assert!((got.x_end - want.x_end).abs() < 1e-9);
        // F > 2 μs W: slips at t = 0 and never sticks (guide §9).
        let problem = pulled(0.5, LawKind::Harmonic, 3.0);
        let want = exact(&problem);
        let got = DiffsolTsit45
            .solve(&problem, Setting::Tolerance(1e-10))
            .unwrap();
        assert_eq!(got.events, want.events);
        assert!((got.x_end - want.x_end).abs() < 1e-9 * want.x_end);
    }

    /// diffsol looks for a sign change of s·v between step ends only: at a loose tolerance on
    /// the woodpecker (harmonic law) a brief stick falls inside one step and is missed, where
    /// the tool's dopri5, which also checks inside its steps, finds every event.
    #[test]
    fn step_end_root_finding_misses_events_at_a_loose_tolerance() {
        let bp = sweep_problems()
            .unwrap()
            .into_iter()
            .find(|bp| bp.id == "woodpecker_fig15_harmonic")
            .unwrap();
        let want = exact(&bp.problem);
        let setting = Setting::Tolerance(1e-4);
        let got = DiffsolTsit45.solve(&bp.problem, setting).unwrap();
        // Measured: 48 of 80.
        assert!(got.events.len() < want.events.len(), "{}", got.events.len());
        let ours = Dopri5.solve(&bp.problem, setting).unwrap();
        assert_eq!(ours.events.len(), want.events.len());
    }

    /// A weak pull (φ = 1e-7, harmonic law) slips for 8e-5 s around N = 0, less than
    /// diffsol's first step: its root test, a sign change of s·v between step ends, cannot see
    /// a stop when s·v starts from exactly 0; the driver finds it (without that: 1 slip and
    /// no stick over 4 periods, the body sliding backwards).
    #[test]
    fn a_slip_shorter_than_the_first_step_still_ends_in_a_stick() {
        let weight = PulledMassParams::default().weight();
        let problem = pulled(1e-7 * weight, LawKind::Harmonic, 4.0);
        let want = exact(&problem);
        assert_eq!(want.events.len(), 8);
        for tol in [1e-3, 1e-6, 1e-9] {
            let got = DiffsolTsit45
                .solve(&problem, Setting::Tolerance(tol))
                .unwrap();
            assert_eq!(got.events.len(), want.events.len(), "tol {tol:e}");
            let slip = want.events[1].t - want.events[0].t;
            assert!(event_error(&got, &want) < 1e-3 * slip, "tol {tol:e}");
            assert!(got.x_end >= 0.0 && (got.x_end - want.x_end).abs() < 1e-3 * want.x_end);
        }
    }

    /// The belt through the generic state machine: the onsets are located on the static
    /// margin G = |D(x)| − μs N_f of the stuck body (exactly, as dopri5's), the sticks by
    /// diffsol's root of s·w; the events converge to the closed forms with the tolerance.
    #[test]
    fn on_the_belt_its_event_times_converge_to_the_closed_forms() {
        use crate::bench::belt::{closed_form_events, error, problem};
        let (p, problem) = problem().unwrap();
        let c = crate::models::belt::formula::evaluate(&p);
        let want = closed_form_events(&c, problem.t_end);
        let errors: Vec<f64> = [1e-6, 1e-7, 1e-8, 1e-9, 1e-10]
            .iter()
            .map(|&tol| {
                let got = DiffsolTsit45
                    .solve_surface(&problem, Setting::Tolerance(tol))
                    .unwrap();
                let err = error(&got, &want);
                println!(
                    "diffsol_tsit45 belt: tol {tol:e}: event error {err:.3e} s, x_end {:.9e} m, \
                     v_end {:e}, {:?}",
                    got.x_end, got.v_end, got.stats
                );
                // Ends mid-stick: carried by the belt, 0.5 t_stick after the last stick.
                assert_eq!(got.v_end, p.v_b, "{tol:e}");
                let x = c.x_slip_end + 0.5 * p.v_b * c.t_stick;
                assert!(
                    (got.x_end - x).abs() <= 2.0 * p.v_b * err + 1e-12,
                    "{tol:e}"
                );
                assert_eq!(got.stats.steps, got.stats.accepted + got.stats.rejected);
                err
            })
            .collect();
        // Measured over 20 cycles: 8.2e-6, 1.6e-6, 2.9e-7, 3.0e-8, 3.2e-9 s (608 … 1465
        // accepted steps; dopri5's generic path: 6.7e-5, 8.5e-6, 8.9e-7, 9.9e-8, 1.1e-8 s).
        assert!(errors.windows(2).all(|w| w[1] < w[0] / 3.0), "{errors:?}");
        assert!(errors[0] / errors[4] > 1e3, "{errors:?}");
        assert!(errors[4] < 1e-8, "{errors:?}");
    }

    #[test]
    fn a_step_setting_or_a_bad_tolerance_is_refused() {
        let problem = pulled(0.10, LawKind::Linear, 2.0);
        for setting in [
            Setting::Step(1e-3),
            Setting::Tolerance(0.0),
            Setting::Tolerance(f64::INFINITY),
        ] {
            assert!(matches!(
                DiffsolTsit45.solve(&problem, setting),
                Err(Error::InvalidParam { .. })
            ));
        }
        assert_eq!(DiffsolTsit45.name(), "diffsol_tsit45");
    }
}
