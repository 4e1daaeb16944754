//! Explicit Euler with sign(v) friction: the spreadsheet method the paper mentions, kept as the
//! failure baseline. Owns [`EulerSign`].
//!
//! ```text
//! v_{k+1} = v_k + h (D(t_k) − μd N_f(t_k) sign(v_k)) / M,     sign(0) = 0
//! x_{k+1} = x_k + h v_k
//! ```
//!
//! There is no stick state and μs is never used: the law knows only the dynamic friction, and at
//! v = 0 exactly (only at t = 0 in practice) sign(0) = 0 lets the whole drive act, so the body
//! leaves rest at the first step whatever |D| / N_f is. Where the exact body is stuck, v
//! chatters around 0 with amplitude ~h |a|: each step that overshoots 0 is a spurious velocity
//! reversal, about one per step, so their number per period grows like 1/h while the exact
//! engine has none; a true stick is never found.
//!
//! On a moving surface ([`System`]) the same lines hold in the surface's frame, u = x − v_s t
//! and w = v − v_s, with sign(w) for sign(v) and D(t_k, x_k) read at x_k = u_k + v_s t_k; with
//! forces of time only (v_s = 0) these are the numbers above, bit for bit. On the belt the
//! body starts carried (w = 0, D = 0), leaves the belt at the second step whatever μs says,
//! and never sticks again: w chatters about 0 where the exact block is carried.
//!
//! Events: "slip" when v first leaves 0, then "reversal" at the end of every step where the
//! sign of v differs from its last non-zero sign; all of them are counted in `Stats::events`.

use super::moreau::{step_count, step_grid};
use super::surface::{absolute, SurfaceProblem, System};
use super::{Method, MethodEvent, Problem, Setting, Solution, Stats};
use crate::error::{Error, Result};

/// Explicit Euler with μd N_f sign(v) friction, fixed step `Setting::Step(h)`.
pub struct EulerSign;

impl Method for EulerSign {
    fn name(&self) -> &'static str {
        "euler_sign"
    }

    fn solve(&self, problem: &Problem, setting: Setting) -> Result<Solution> {
        solve_step(problem, setting.fixed_step(self.name())?)
    }

    fn solve_surface(&self, problem: &SurfaceProblem, setting: Setting) -> Result<Solution> {
        solve_step(problem, setting.fixed_step(self.name())?)
    }
}

/// Explicit Euler with sign(w) friction and step h (s), on either problem ([`System`]).
pub fn solve_step(problem: &impl System, h: f64) -> Result<Solution> {
    let t_end = problem.t_end();
    let n = step_count(h, t_end)?;
    let body = problem.body();
    let v_s = problem.surface_speed();
    let mut stats = Stats::default();
    let mut events = Vec::new();
    // u = x − v_s t and w = v − v_s: the body starts carried by the surface.
    let (mut u, mut w) = (0.0_f64, 0.0_f64);
    // Last non-zero sign of w (0 before the body first moves).
    let mut last_sign = 0.0_f64;
    for (t0, t1) in step_grid(n, h, t_end) {
        let hk = t1 - t0;
        let (d, n_f) = problem.forces(t0, u + v_s * t0);
        stats.rhs_evals += 1;
        let sign = if w == 0.0 { 0.0 } else { w.signum() };
        let w_new = w + hk * (d - body.mu_d * n_f * sign) / body.mass;
        u += hk * w;
        w = w_new;
        if !(u.is_finite() && w.is_finite()) {
            return Err(Error::Stalled {
                t: t1,
                reason: "euler_sign: the state became non-finite",
            });
        }
        if w != 0.0 {
            let s = w.signum();
            if last_sign == 0.0 {
                events.push(MethodEvent {
                    t: t1,
                    kind: "slip",
                });
            } else if s != last_sign {
                events.push(MethodEvent {
                    t: t1,
                    kind: "reversal",
                });
            }
            last_sign = s;
        }
    }
    stats.steps = n;
    stats.accepted = n;
    let (x, v) = absolute(problem, t_end, u, w);
    Ok(Solution::new(events, x, v, stats))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::LawKind;
    use crate::solver::exact::Exact;
    use crate::solver::test_support::{fitted_slope, set_b};

    #[test]
    fn spurious_reversals_per_period_grow_like_one_over_h_while_exact_has_none() {
        for law in [LawKind::Linear, LawKind::Harmonic] {
            let periods = 4.0;
            let problem = set_b(law, periods);
            let period = problem.law.period;
            let exact = Exact.solve(&problem, Setting::Step(1.0)).unwrap();
            assert_eq!(exact.events.len(), 8, "{law:?}: 4 slips and 4 sticks");
            assert!(exact.events.iter().all(|e| e.kind != "reversal"));
            assert_eq!(
                exact.stats.events, 8,
                "{law:?}: the exact engine has 0 reversals"
            );
            let mut points = Vec::new();
            for n in [400.0, 800.0, 1600.0, 3200.0, 6400.0] {
                let h = period / n;
                let s = EulerSign.solve(&problem, Setting::Step(h)).unwrap();
                let reversals = s.events.iter().filter(|e| e.kind == "reversal").count();
                assert_eq!(s.stats.events, s.events.len() as u64);
                assert_eq!(s.stats.rhs_evals, s.stats.steps);
                let per_period = reversals as f64 / periods;
                println!(
                    "euler_sign {law:?}: h = T/{n}: {per_period} spurious reversals per period \
                     ({:.3} per step), x_end = {:.6e} m (exact {:.6e} m)",
                    per_period / n,
                    s.x_end,
                    exact.x_end
                );
                assert!(per_period > 0.0);
                // (h, reversals): the slope against log h is minus the one against log 1/h.
                points.push((h, per_period));
            }
            let slope = -fitted_slope(&points);
            println!("euler_sign {law:?}: slope of log(reversals) vs log(1/h) = {slope:.3}");
            assert!(slope > 0.7 && slope < 1.3, "{law:?}: slope {slope}");
        }
    }

    #[test]
    fn leaves_rest_at_the_first_step_and_refuses_bad_steps() {
        let problem = set_b(LawKind::Linear, 1.0);
        let h = problem.law.period / 100.0;
        let s = EulerSign.solve(&problem, Setting::Step(h)).unwrap();
        assert_eq!(s.stats.steps, 100);
        assert_eq!(s.events[0], MethodEvent { t: h, kind: "slip" });
        assert!(EulerSign.solve(&problem, Setting::Step(-1.0)).is_err());
        assert!(EulerSign.solve(&problem, Setting::Tolerance(1e-6)).is_err());
        assert!(matches!(
            EulerSign.solve(&problem, Setting::Step(1e-12)),
            Err(Error::Stalled { .. })
        ));
    }

    #[test]
    fn on_the_belt_it_leaves_at_the_second_step_and_never_sticks() {
        use crate::bench::belt::problem;
        let (p, problem) = problem().unwrap();
        let c = crate::models::belt::formula::evaluate(&p);
        let cycles = (problem.t_end - c.first_slip_time) / c.period;
        let want_events = crate::bench::belt::closed_form_events(&c, problem.t_end).len();
        let mut points = Vec::new();
        // Coarser steps land on no clean power law (T/100: 128 reversals, T/200: 86).
        for n in [400.0, 800.0, 1600.0, 3200.0] {
            let h = c.period / n;
            let s = EulerSign.solve_surface(&problem, Setting::Step(h)).unwrap();
            let reversals = s.events.iter().filter(|e| e.kind == "reversal").count();
            println!(
                "euler_sign belt: h = T/{n}: first {:?}, {} events, {reversals} reversals, \
                 x_end {:.6e} m, v_end {:.6e} m/s (first exact slip {:.4} s)",
                s.events[0],
                s.events.len(),
                s.x_end,
                s.v_end,
                c.first_slip_time
            );
            assert_eq!(
                s.events[0],
                MethodEvent {
                    t: 2.0 * h,
                    kind: "slip"
                }
            );
            // The exact block leaves the belt at x_s/v_b = 1.18 s and sticks once per cycle.
            assert!(s.events.iter().all(|e| e.kind != "stick"));
            assert!(s.events.len() > 4 * want_events, "{n}");
            points.push((h, reversals as f64 / cycles));
        }
        // Measured: 160, 296, 570, 1116 reversals over the run (T/400 … T/3200), slope 0.94.
        let slope = -fitted_slope(&points);
        println!("euler_sign belt: slope of log(reversals) vs log(1/h) = {slope:.3}");
        assert!(slope > 0.7 && slope < 1.3, "slope {slope}: {points:?}");
    }
}
