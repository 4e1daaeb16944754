//! Moreau–Jean time-stepping: the θ-method of the multibody codes (Siconos), with the
//! set-valued Coulomb law solved exactly at each step. Owns [`Moreau`] and [`solve_theta`].
//!
//! ```text
//! M (v_{k+1} − v_k) = h D_θ + P_{k+1},     P_{k+1} ∈ −h μ N_θ Sign(v_{k+1})
//! x_{k+1} = x_k + h (θ v_{k+1} + (1 − θ) v_k),   D_θ = θ D(t_{k+1}) + (1 − θ) D(t_k) (same for N)
//! ```
//!
//! The inclusion is scalar, so its solution is explicit: with the free velocity
//! v_free = v_k + h D_θ / M,
//!
//! ```text
//! |M v_free| ≤ h μ N_θ   →  v_{k+1} = 0                                  (stick)
//! otherwise              →  v_{k+1} = v_free − sgn(v_free) h μd N_θ / M    (slip)
//! ```
//!
//! Convention for μ in the stick test: μ = μs when the body was at rest (v_k = 0: the static
//! capacity must be overcome to start), μ = μd when it was moving (a moving body is stopped by
//! the dynamic friction it feels, as in the exact engine, which sticks when v reaches 0 and then
//! holds with μs). The impulse of a slipping step always uses μd.
//!
//! On a moving surface ([`System`]) the scheme runs in the surface's frame, u = x − v_s t and
//! w = v − v_s (v_s constant, so M (w_{k+1} − w_k) = M (v_{k+1} − v_k)), and sticking is
//! w = 0. A force depending on the position, D(t, x) with constant ∂D/∂x = c, is taken at
//! x_{k+1} as Siconos does for linear systems: D(t_{k+1}, x_{k+1}) = D(t_{k+1}, x*) +
//! c (x_{k+1} − x*) with the predictor x* = x_k + h v_k, which puts M − h²θ² c in place of M
//! in the two lines above (the iteration matrix W). With forces of time only (c = 0, v_s = 0)
//! the numbers are those of the scheme above, bit for bit.
//!
//! Events are read off the step ends: "slip" when v leaves exactly 0, "stick" when it returns to
//! exactly 0, "reversal" when it changes sign within one step without stopping. Their time is
//! the step end t_{k+1}, so event times are first-order accurate, and so is the position after
//! an event: the method is of order 1 across events whatever θ is (order 2 for θ = ½ only on
//! smooth stretches).

use super::surface::{absolute, SurfaceProblem, System};
use super::{Method, MethodEvent, Problem, Setting, Solution, Stats};
use crate::error::{Error, Result};

/// θ of [`Moreau`]: ½ (trapezoidal, the Siconos default for this kind of problem).
pub const THETA: f64 = 0.5;

/// Largest number of steps a run may take.
pub const MAX_STEPS: u64 = 10_000_000;

/// Moreau–Jean time-stepping with θ = [`THETA`], fixed step `Setting::Step(h)`. Other θ in
/// (0, 1] (e.g. θ = 1, fully implicit) through [`solve_theta`].
pub struct Moreau;

impl Method for Moreau {
    fn name(&self) -> &'static str {
        "moreau"
    }

    fn solve(&self, problem: &Problem, setting: Setting) -> Result<Solution> {
        let h = setting.fixed_step(self.name())?;
        solve_theta(problem, h, THETA)
    }

    fn solve_surface(&self, problem: &SurfaceProblem, setting: Setting) -> Result<Solution> {
        let h = setting.fixed_step(self.name())?;
        solve_theta(problem, h, THETA)
    }
}

/// The uniform step grid of the fixed-step methods of this family (Moreau, Euler-sign, the
/// implicit tanh method with a step): the steps (t0, t1) (s) of `n` steps of `h`
/// ([`step_count`]), the last one shortened to end exactly on `t_end`.
pub(super) fn step_grid(n: u64, h: f64, t_end: f64) -> impl Iterator<Item = (f64, f64)> {
    (0..n).map(move |k| {
        let t1 = if k + 1 == n {
            t_end
        } else {
            (k + 1) as f64 * h
        };
        (k as f64 * h, t1)
    })
}

/// The number of steps of [`step_grid`]: `t_end / h` rounded up; more than [`MAX_STEPS`] is
/// refused.
pub(super) fn step_count(h: f64, t_end: f64) -> Result<u64> {
    if !(h.is_finite() && h > 0.0) {
        return Err(Error::InvalidParam {
            name: "h",
            value: h.to_string(),
            rule: "finite and > 0 (s)".into(),
        });
    }
    if !(t_end.is_finite() && t_end >= 0.0) {
        return Err(Error::InvalidParam {
            name: "t_end",
            value: t_end.to_string(),
            rule: "finite and ≥ 0 (s)".into(),
        });
    }
    // A t_end that is a multiple of h up to rounding must not produce a sliver of a last step.
    let n = (t_end / h * (1.0 - 1e-12)).ceil();
    if n > MAX_STEPS as f64 {
        return Err(Error::Stalled {
            t: 0.0,
            reason: "step size too small: more than 10^7 fixed steps requested",
        });
    }
    Ok(n as u64)
}

/// Moreau–Jean with a given θ ∈ (0, 1] and step h (s), on either problem ([`System`]).
pub fn solve_theta(problem: &impl System, h: f64, theta: f64) -> Result<Solution> {
    if !(theta > 0.0 && theta <= 1.0) {
        return Err(Error::InvalidParam {
            name: "theta",
            value: theta.to_string(),
            rule: "0 < θ ≤ 1".into(),
        });
    }
    let t_end = problem.t_end();
    let n = step_count(h, t_end)?;
    let body = problem.body();
    let m = body.mass;
    let c = problem.force_gradient();
    let v_s = problem.surface_speed();
    let mut stats = Stats::default();
    let mut events = Vec::new();
    // u = x − v_s t and w = v − v_s: the body starts carried by the surface.
    let (mut u, mut w) = (0.0_f64, 0.0_f64);
    // Forces at the step start, carried over from the previous step end: one evaluation of the
    // force law per step.
    let (mut d0, mut n0) = problem.forces(0.0, 0.0);
    stats.rhs_evals += 1;
    for (t0, t1) in step_grid(n, h, t_end) {
        let hk = t1 - t0;
        // The predictor x* = x_k + h v_k, i.e. u* = u_k + h w_k.
        let (d1, n1) = problem.forces(t1, u + hk * w + v_s * t1);
        stats.rhs_evals += 1;
        let d_theta = theta * d1 + (1.0 - theta) * d0;
        let n_theta = theta * n1 + (1.0 - theta) * n0;
        // The iteration matrix: M for forces of time only.
        let w_mat = m - c * (hk * theta) * (hk * theta);
        let w_free = w + hk * d_theta / w_mat;
        let mu = if w == 0.0 { body.mu_s } else { body.mu_d };
        let w_new = if (w_mat * w_free).abs() <= hk * mu * n_theta {
            0.0
        } else {
            w_free - w_free.signum() * hk * body.mu_d * n_theta / w_mat
        };
        u += hk * (theta * w_new + (1.0 - theta) * w);
        let kind = match (w == 0.0, w_new == 0.0) {
            (true, false) => Some("slip"),
            (false, true) => Some("stick"),
            (false, false) if w.signum() != w_new.signum() => Some("reversal"),
            _ => None,
        };
        if let Some(kind) = kind {
            events.push(MethodEvent { t: t1, kind });
        }
        if !(u.is_finite() && w_new.is_finite()) {
            return Err(Error::Stalled {
                t: t1,
                reason: "moreau: the state became non-finite",
            });
        }
        // D at the step end from the one at the predictor: u_{k+1} − u* = h θ (w_{k+1} − w_k).
        d0 = if c == 0.0 {
            d1
        } else {
            d1 + c * hk * theta * (w_new - w)
        };
        n0 = n1;
        w = w_new;
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

    /// The error at one h depends on where the slip onsets fall inside their steps (an onset
    /// is rounded to the step grid, an O(h) shift of a slip that starts with a jump of the
    /// acceleration), and halving h keeps those phases nearly fixed: on a pure doubling
    /// sequence the error can sit on a plateau (set B, linear law: 5.7e-7 m from T/800 to
    /// T/6400) and the fitted slope means nothing. So the order is fitted to the RMS error over
    /// each octave [h, 2h), sampled at 32 step sizes: e/h stays within ±0.03 m/s everywhere.
    #[test]
    fn converges_to_the_exact_position_with_order_one_across_events() {
        const SAMPLES: usize = 32;
        for law in [LawKind::Linear, LawKind::Harmonic] {
            let problem = set_b(law, 4.0);
            let period = problem.law.period;
            let exact = Exact.solve(&problem, Setting::Step(1.0)).unwrap();
            let mut points = Vec::new();
            for n in [400.0, 800.0, 1600.0, 3200.0, 6400.0] {
                let (mut worst, mut sum_sq, mut at_h) = (0.0_f64, 0.0, 0.0);
                for i in 0..SAMPLES {
                    let h = period / n * 2f64.powf(i as f64 / SAMPLES as f64);
                    let s = Moreau.solve(&problem, Setting::Step(h)).unwrap();
                    let err = (s.x_end - exact.x_end).abs();
                    if i == 0 {
                        at_h = err;
                    }
                    worst = worst.max(err);
                    sum_sq += err * err;
                }
                let rms = (sum_sq / SAMPLES as f64).sqrt();
                println!(
                    "moreau {law:?}: h = T/{n}: error at h {at_h:.3e} m, over [h, 2h) RMS \
                     {rms:.3e} m, max {worst:.3e} m (x_exact = {:.6e} m)",
                    exact.x_end
                );
                points.push((period / n, rms));
            }
            let order = fitted_slope(&points);
            println!("moreau {law:?}: fitted order {order:.3}");
            assert!(order > 0.7 && order < 1.4, "{law:?}: order {order}");
        }
    }

    #[test]
    fn finds_one_slip_and_one_stick_per_period_near_the_exact_times() {
        let problem = set_b(LawKind::Linear, 6.0);
        let period = problem.law.period;
        let h = period / 1000.0;
        let exact = Exact.solve(&problem, Setting::Step(1.0)).unwrap();
        let s = Moreau.solve(&problem, Setting::Step(h)).unwrap();
        assert_eq!(s.stats.steps, 6000);
        assert_eq!(s.stats.rhs_evals, 6001);
        assert_eq!(s.stats.events, s.events.len() as u64);
        assert!(s.events.iter().all(|e| e.kind != "reversal"));
        // Settled motion: periods 1..6 (the first period starts from rest at t = 0).
        for k in 1..6 {
            let (a, b) = (k as f64 * period, (k + 1) as f64 * period);
            let count = |kind: &str, events: &[MethodEvent]| {
                events
                    .iter()
                    .filter(|e| e.kind == kind && e.t > a && e.t <= b)
                    .count()
            };
            assert_eq!(count("slip", &s.events), 1, "period {k}");
            assert_eq!(count("stick", &s.events), 1, "period {k}");
            assert_eq!(count("slip", &exact.events), 1);
            assert_eq!(count("stick", &exact.events), 1);
        }
        // Same sequence as the exact engine, each event within a few steps.
        assert_eq!(s.events.len(), exact.events.len());
        for (m, e) in s.events.iter().zip(&exact.events) {
            assert_eq!(m.kind, e.kind);
            assert!((m.t - e.t).abs() < 3.0 * h, "{m:?} vs {e:?}");
        }
    }

    #[test]
    fn fully_implicit_theta_also_converges_and_bad_input_is_refused() {
        let problem = set_b(LawKind::Linear, 3.0);
        let exact = Exact.solve(&problem, Setting::Step(1.0)).unwrap();
        let h = problem.law.period / 4000.0;
        let s = solve_theta(&problem, h, 1.0).unwrap();
        assert!((s.x_end - exact.x_end).abs() < 1e-2 * exact.x_end);
        assert!(solve_theta(&problem, h, 0.0).is_err());
        assert!(Moreau.solve(&problem, Setting::Step(0.0)).is_err());
        assert!(Moreau.solve(&problem, Setting::Step(f64::NAN)).is_err());
        assert!(Moreau.solve(&problem, Setting::Tolerance(1e-6)).is_err());
        assert!(matches!(
            Moreau.solve(&problem, Setting::Step(1e-12)),
            Err(Error::Stalled { .. })
        ));
    }

    #[test]
    fn on_the_belt_its_event_times_converge_to_the_closed_forms_at_order_one() {
        use crate::bench::belt::{closed_form_events, error, problem};
        let (p, problem) = problem().unwrap();
        let c = crate::models::belt::formula::evaluate(&p);
        let want = closed_form_events(&c, problem.t_end);
        let points: Vec<(f64, f64)> = [100.0, 200.0, 400.0, 800.0, 1600.0]
            .iter()
            .map(|n| {
                let h = c.period / n;
                let got = Moreau.solve_surface(&problem, Setting::Step(h)).unwrap();
                let err = error(&got, &want);
                println!(
                    "moreau belt: h = T/{n}: event error {err:.3e} s ({:.3} h), x_end {:.6e} m, v_end {:e}",
                    err / h,
                    got.x_end,
                    got.v_end
                );
                (h, err)
            })
            .collect();
        // Measured: 6.1e-3, 6.1e-3, 3.3e-3, 1.8e-3, 3.9e-4 s over 20 cycles (0.5 … 1.3 h: the
        // events are read at step ends, and the phase of the grid in each cycle moves them);
        // fitted order 0.97.
        assert!(points.iter().all(|&(h, e)| e < 1.5 * h), "{points:?}");
        let order = fitted_slope(&points);
        println!("moreau belt: fitted order {order:.3}");
        assert!(0.7 < order && order < 1.4, "order {order}: {points:?}");
    }
}
