//! Classic fixed-step RK4 ([`Rk4`], `Setting::Step(h)`) with the stick/slip state machine of
//! the exact engine: switching functions checked at step ends, events located by bisection.
//!
//! ```text
//! slipping, direction s:  y = (x, v),  y' = (v, (D − s μd N_f)/M)    stick switch  s·v
//! stuck:                  y = (x, 0) constant                         slip switch   |D| − μs N_f
//! ```
//!
//! The steps lie on the grid t_k = k h, cut short at the breakpoints of the force law (where
//! the right-hand side has kinks) and at t_end. When the switching function has changed sign at
//! a step end, the event time is located by bisection on the step length σ, re-integrating one
//! RK4 step of length σ from the step start for each trial (stuck: G is evaluated directly),
//! until the bracket is 2 ulps of the event time (at most 64 halvings): a looser bracket, e.g.
//! 1e-14 relative, displaces the slip that follows by ≈ a·δt·(its duration) and left a floor of
//! ~3e-16 m on set B, the truncation error of h = T/1600. The state is moved to the
//! event by one RK4 step of the located length, the transition is applied (stick: v := 0;
//! reversal: new direction), and the integration goes on in the new mode with the rest of the
//! step. Events are located to round-off, so the global error stays O(h⁴) across them; a sign
//! change that starts and ends inside one step is not seen (a brief stick or slip is missed).

use super::dopri5::State;
use super::surface::{absolute, SurfaceProblem, System};
use super::{Method, MethodEvent, Setting, Solution, Stats};
use crate::error::{Error, Result};

/// Largest number of grid steps a run may take.
pub const MAX_STEPS: u64 = 10_000_000;
/// Bisection stops when the bracket is below this fraction of the event time.
const BRACKET_REL: f64 = 2.0 * f64::EPSILON;
/// Most halvings of one bisection.
const MAX_HALVINGS: u32 = 64;
/// More events than this at one instant means the state machine cannot advance.
const MAX_EVENTS_AT_ONE_TIME: u32 = 16;

/// Fixed-step classic RK4 with located events. Setting: `Setting::Step(h)`, h in s.
pub struct Rk4;

impl Method for Rk4 {
    fn name(&self) -> &'static str {
        "rk4"
    }

    fn solve(&self, problem: &super::Problem, setting: Setting) -> Result<Solution> {
        solve_step(problem, setting.fixed_step(self.name())?)
    }

    fn solve_surface(&self, problem: &SurfaceProblem, setting: Setting) -> Result<Solution> {
        solve_step(problem, setting.fixed_step(self.name())?)
    }
}

/// What one step ends with (STYLE habit 9): the driver applies the transition.
enum Advance {
    /// The step reached its end; the mode goes on.
    Step,
    /// The switching function of the mode crossed zero at `t`, with position `x` there.
    Event { t: f64, x: f64 },
}

/// The increment of one RK4 step of length h from (t, y) for the slip direction s, counting
/// 4 evaluations; y = (u, w) = (x − v_s t, v − v_s).
fn rk4(problem: &impl System, s: f64, t: f64, y: State, h: f64, stats: &mut Stats) -> State {
    stats.rhs_evals += 4;
    let v_s = problem.surface_speed();
    let f = |t: f64, y: State| [y[1], problem.slip_acceleration(t, y[0] + v_s * t, s)];
    let k1 = f(t, y);
    let k2 = f(
        t + 0.5 * h,
        [y[0] + 0.5 * h * k1[0], y[1] + 0.5 * h * k1[1]],
    );
    let k3 = f(
        t + 0.5 * h,
        [y[0] + 0.5 * h * k2[0], y[1] + 0.5 * h * k2[1]],
    );
    let k4 = f(t + h, [y[0] + h * k3[0], y[1] + h * k3[1]]);
    std::array::from_fn(|i| h / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]))
}

/// The state with its compensation term (Kahan summation of the increments): without it the
/// round-off of ~10⁴ small increments reaches the truncation error at h ≈ T/3200 on set B
/// (measured: 5.7e-17 m instead of 3.5e-18 m at T/6400).
#[derive(Clone, Copy, Debug, Default)]
struct Sum {
    y: State,
    c: State,
}

impl Sum {
    fn add(&self, dy: State) -> Sum {
        let term: State = std::array::from_fn(|i| dy[i] - self.c[i]);
        let y: State = std::array::from_fn(|i| self.y[i] + term[i]);
        let c = std::array::from_fn(|i| (y[i] - self.y[i]) - term[i]);
        Sum { y, c }
    }
}

/// G(t) = |D| − μs N_f (N) for the body stuck at u, one evaluation: the body leaves the
/// surface when it becomes positive.
fn margin(problem: &impl System, t: f64, u: f64, stats: &mut Stats) -> f64 {
    stats.rhs_evals += 1;
    let (d, n) = forces(problem, t, u);
    d.abs() - problem.body().mu_s * n
}

/// The forces at t for the body at u = x − v_s t.
fn forces(problem: &impl System, t: f64, u: f64) -> (f64, f64) {
    problem.forces(t, u + problem.surface_speed() * t)
}

/// Smallest σ in (0, width] with `after(σ)` true, given after(width), to BRACKET_REL of t + σ.
fn bisect(t: f64, width: f64, mut after: impl FnMut(f64) -> bool) -> f64 {
    let (mut lo, mut hi) = (0.0, width);
    for _ in 0..MAX_HALVINGS {
        if hi - lo <= BRACKET_REL * (t + hi).abs() {
            break;
        }
        let mid = 0.5 * (lo + hi);
        if after(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

/// One step of the current mode from t to `stop`: (x, v) move to the step end or to the event.
fn advance(
    problem: &impl System,
    dir: f64,
    t: f64,
    stop: f64,
    y: &mut Sum,
    stats: &mut Stats,
) -> Advance {
    stats.steps += 1;
    stats.accepted += 1;
    let width = stop - t;
    if dir == 0.0 {
        let u = y.y[0];
        if margin(problem, stop, u, stats) > 0.0 {
            let sigma = bisect(t, width, |sg| margin(problem, t + sg, u, stats) > 0.0);
            return Advance::Event {
                t: t + sigma,
                x: y.y[0],
            };
        }
        return Advance::Step;
    }
    let y1 = y.add(rk4(problem, dir, t, y.y, width, stats));
    if dir * y1.y[1] > 0.0 {
        *y = y1;
        return Advance::Step;
    }
    let start = *y;
    let sigma = bisect(t, width, |sg| {
        dir * start.add(rk4(problem, dir, t, start.y, sg, stats)).y[1] <= 0.0
    });
    *y = start.add(rk4(problem, dir, t, start.y, sigma, stats));
    y.y[1] = 0.0;
    y.c[1] = 0.0;
    Advance::Event {
        t: t + sigma,
        x: y.y[0],
    }
}

/// Integrates `problem` with RK4 of step h (s).
pub fn solve_step(problem: &impl System, h: f64) -> Result<Solution> {
    let t_end = problem.t_end();
    if t_end / h > MAX_STEPS as f64 {
        return Err(Error::Stalled {
            t: 0.0,
            reason: "rk4: step size too small: more than 10^7 steps requested",
        });
    }
    let mut stats = Stats::default();
    let mut events = Vec::new();
    let mut t = 0.0_f64;
    let mut y = Sum::default();
    // Direction of slip, 0 when stuck.
    let mut dir = 0.0_f64;
    let mut at_same_time = (f64::NAN, 0u32);
    if t_end > 0.0 && margin(problem, 0.0, 0.0, &mut stats) > 0.0 {
        dir = forces(problem, 0.0, 0.0).0.signum();
        events.push(MethodEvent { t, kind: "slip" });
    }
    while t < t_end {
        if stats.steps >= 2 * MAX_STEPS {
            return Err(Error::Stalled {
                t,
                reason: "rk4: too many steps",
            });
        }
        // Next grid point strictly after t (a point within round-off of t is t itself).
        let mut grid = ((t / h).floor() + 1.0) * h;
        while grid <= t + 1e-9 * h {
            grid += h;
        }
        let stop = grid.min(problem.breakpoint_after(t)).min(t_end);
        match advance(problem, dir, t, stop, &mut y, &mut stats) {
            Advance::Step => t = stop,
            Advance::Event { t: te, x } => {
                if at_same_time.0 == te {
                    at_same_time.1 += 1;
                    if at_same_time.1 > MAX_EVENTS_AT_ONE_TIME {
                        return Err(Error::Stalled {
                            t: te,
                            reason: "rk4: events keep recurring at one instant",
                        });
                    }
                } else {
                    at_same_time = (te, 0);
                }
                t = te;
                y.y = [x, 0.0];
                let (d, n) = forces(problem, te, x);
                let kind = if dir == 0.0 {
                    dir = d.signum();
                    "slip"
                } else if d.abs() <= problem.body().mu_s * n {
                    dir = 0.0;
                    "stick"
                } else if d.signum() != dir {
                    dir = d.signum();
                    "reversal"
                } else {
                    // v touched 0 while the drive keeps pushing the same way: the slip goes on
                    // (no event, as in the exact engine).
                    continue;
                };
                events.push(MethodEvent { t: te, kind });
            }
        }
    }
    let (x_end, v_end) = absolute(problem, t_end, y.y[0], y.y[1]);
    Ok(Solution::new(events, x_end, v_end, stats))
}

#[cfg(test)]
mod tests {
    use super::super::test_support::{
        back_and_forth, event_error, exact, last_period_kinds, set_b, woodpecker_fig15,
    };
    use super::*;
    use crate::models::LawKind;

    /// Least-squares slope of log y against log x.
    fn slope(points: &[(f64, f64)]) -> f64 {
        let n = points.len() as f64;
        let logs: Vec<(f64, f64)> = points.iter().map(|&(x, y)| (x.ln(), y.ln())).collect();
        let mx = logs.iter().map(|p| p.0).sum::<f64>() / n;
        let my = logs.iter().map(|p| p.1).sum::<f64>() / n;
        let sxy: f64 = logs.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
        let sxx: f64 = logs.iter().map(|p| (p.0 - mx).powi(2)).sum();
        sxy / sxx
    }

    #[test]
    fn final_position_converges_at_order_4_with_located_events() {
        // Harmonic law (smooth between events); h = T/200 … T/3200.
        let problem = set_b(LawKind::Harmonic, 4.0);
        let want = exact(&problem);
        let points: Vec<(f64, f64)> = [200.0, 400.0, 800.0, 1600.0, 3200.0]
            .iter()
            .map(|n| {
                let h = problem.law.period / n;
                let got = Rk4.solve(&problem, Setting::Step(h)).unwrap();
                assert!(event_error(&got, &want) < 1e-10);
                (h, (got.x_end - want.x_end).abs())
            })
            .collect();
        // Measured: errors 3.0e-12, 1.8e-13, 1.1e-14, 6.9e-16, 4.5e-17 m; order 4.01.
        let order = slope(&points);
        assert!(3.5 < order && order < 4.6, "order {order}: {points:?}");
    }

    #[test]
    fn set_b_events_match_exact() {
        let problem = set_b(LawKind::Harmonic, 4.0);
        let want = exact(&problem);
        let got = Rk4
            .solve(&problem, Setting::Step(problem.law.period / 200.0))
            .unwrap();
        let err = event_error(&got, &want);
        // Measured: 1.8e-11 s.
        assert!(err < 1e-10, "{err:e}");
        assert_eq!(got.stats.events, 8);
        assert_eq!(got.stats.steps, got.stats.accepted);
        assert_eq!(got.stats.rejected, 0);
        // 800 grid steps plus the 8 steps cut short at events (and the stuck ones cost 1).
        assert_eq!(got.stats.steps, 809);
        // On the linear law the slip arcs are cubics in t, which RK4 integrates exactly
        // between breakpoints: even a coarse step gives round-off.
        let problem = set_b(LawKind::Linear, 4.0);
        let got = Rk4
            .solve(&problem, Setting::Step(problem.law.period / 25.0))
            .unwrap();
        let want = exact(&problem);
        assert!(event_error(&got, &want) < 1e-14);
        assert!((got.x_end - want.x_end).abs() < 1e-16);
    }

    #[test]
    fn woodpecker_fig15_has_two_slips_and_two_sticks_in_the_last_period() {
        for law in [LawKind::Harmonic, LawKind::Linear] {
            let problem = woodpecker_fig15(law);
            let want = exact(&problem);
            let got = Rk4
                .solve(&problem, Setting::Step(problem.law.period / 100.0))
                .unwrap();
            let kinds = last_period_kinds(&got, &problem);
            assert_eq!(kinds, ["slip", "stick", "slip", "stick"], "{law:?}");
            // Measured: 1.7e-9 s (harmonic), round-off (linear).
            let err = event_error(&got, &want);
            assert!(err < 1e-8, "{law:?}: {err:e}");
            assert!((got.x_end - want.x_end).abs() < 1e-8, "{law:?}");
        }
    }

    #[test]
    fn reversals_are_located_like_the_exact_engine() {
        let problem = back_and_forth();
        let got = Rk4.solve(&problem, Setting::Step(1.0 / 200.0)).unwrap();
        let run = crate::engine::integrate(
            &problem.body,
            &problem.law,
            &crate::engine::RunOptions {
                periods: 3,
                record_segments: true,
                dissipation: false,
            },
        )
        .unwrap();
        let kinds: Vec<_> = got.events.iter().map(|e| e.kind).collect();
        assert_eq!(kinds[0], "slip");
        assert_eq!(got.events[0].t, 0.0);
        let reversals: Vec<f64> = run
            .events
            .iter()
            .filter(|e| matches!(e.kind, crate::engine::EventKind::Reversal { .. }))
            .map(|e| e.t)
            .collect();
        assert_eq!(kinds.len(), 1 + reversals.len());
        for (e, t) in got.events[1..].iter().zip(&reversals) {
            assert_eq!(e.kind, "reversal");
            assert!((e.t - t).abs() < 1e-9, "{e:?} vs {t}");
        }
        let (x, v, _) = run.state_at(3.0).unwrap();
        assert!((got.x_end - x).abs() < 1e-9 && (got.v_end - v).abs() < 1e-9);
    }

    #[test]
    fn a_tolerance_setting_or_a_bad_step_is_refused() {
        let problem = set_b(LawKind::Linear, 4.0);
        for setting in [
            Setting::Tolerance(1e-6),
            Setting::Step(0.0),
            Setting::Step(-1.0),
        ] {
            assert!(matches!(
                Rk4.solve(&problem, setting),
                Err(Error::InvalidParam { .. })
            ));
        }
        assert!(matches!(
            Rk4.solve(&problem, Setting::Step(1e-12)),
            Err(Error::Stalled { .. })
        ));
        assert_eq!(Rk4.name(), "rk4");
    }
}
