//! The belt as a bench problem: the textbook stick-slip oscillator (docs/belt.md), a standard
//! test for event-driven solvers, with the default set over [`PERIODS`] cycles, in the
//! work-precision sweep of `stickslip bench` beside the paper's four problems. The force is
//! the spring's −k x and the block sticks at the belt's speed v_b, so it is a
//! [`SurfaceProblem`], handed to each method by [`Method::solve_surface`]: every method
//! integrates it (each method's test on it is beside its code): the exact engine, rk4, dopri5
//! (and dopri5_endpoints: their generic path), moreau, tanh_dopri5, tanh_trbdf2, euler_sign
//! and, with the `peers` feature, diffsol_tsit45 (on dopri5's generic state machine). A method
//! that took forces of time only would refuse it, and the sweep would list the refusal with
//! its reason.
//!
//! ```text
//! reference   the exact engine's solve_surface, checked against the closed forms' events
//!             (first slip at x_s/v_b (B5), then slips of t_slip (B9), sticks of t_stick (B10))
//!             and x(t_end) = x_e + v_b (t_end − t_stick,last) (the end lies mid-stick)
//! errors      event times and x(t_end); no v̄: the block returns to the same place each cycle
//! ```
//!
//! The tanh methods (μd only, no stick state) do not reproduce the events: they slip at
//! x_d/v_b and settle to a harmonic oscillation of period 2π/ω about x_d that only grazes the
//! belt's speed (their tests in `solver::tanh`). The SciPy peer receives the belt's law as data
//! (D0, c = ∂D/∂x, N_f, v_s) and integrates its slips in the belt's frame ([`super::peer`]).
//! The failure studies and long runs are defined on the paper's problems only.

use serde::Serialize;

use super::problems::{transitions, Reference, PERIODS};
use super::sweep::match_events;
use crate::error::Result;
use crate::models::belt::body::{body, surface_law};
use crate::models::belt::formula::{self, ClosedForm};
use crate::models::belt::BeltParams;
use crate::solver::exact::Exact;
use crate::solver::surface::SurfaceProblem;
use crate::solver::{Method, MethodEvent, Setting};

/// The problem's id in the bench's tables.
pub const ID: &str = "belt_default";
/// Its title in tables and charts.
pub const TITLE: &str = "Belt oscillator, default set";
/// Its "law" in the bench's JSON: the spring's force −k x, with no forcing law.
pub const LAW: &str = "spring";
/// Why the mean speed of the last cycle is not compared on the belt.
pub const VBAR_NOT_APPLICABLE: &str =
    "not applicable: the block returns to the same place each cycle (mean speed 0)";

/// The belt's bench problem: its parameters, closed forms and surface problem.
#[derive(Clone, Debug, PartialEq)]
pub struct BeltBench {
    pub params: BeltParams,
    pub closed: ClosedForm,
    pub problem: SurfaceProblem,
}

/// The belt's bench problem of [`problem`].
pub fn bench() -> Result<BeltBench> {
    let (params, problem) = problem()?;
    Ok(BeltBench {
        params,
        closed: formula::evaluate(&params),
        problem,
    })
}

/// The belt's default set (m 0.5 kg, k 50 N/m, v_b 50 mm/s, μs 0.6, μd 0.4) over
/// [`PERIODS`] cycles after the first slip, the end in the middle of a stick.
pub fn problem() -> Result<(BeltParams, SurfaceProblem)> {
    let p = BeltParams::default();
    p.validate()?;
    let c = formula::evaluate(&p);
    let t_end = c.first_slip_time + f64::from(PERIODS) * c.period - 0.5 * c.t_stick;
    let problem = SurfaceProblem {
        body: body(&p),
        law: surface_law(&p)?,
        t_end,
    };
    Ok((p, problem))
}

/// The event times of the closed forms up to `t_end` (s): the reference of every method.
pub fn closed_form_events(c: &ClosedForm, t_end: f64) -> Vec<MethodEvent> {
    let mut out = Vec::new();
    let mut t = c.first_slip_time;
    let mut cycle = 0.0;
    while t <= t_end {
        out.push(MethodEvent { t, kind: "slip" });
        let stick = t + c.t_slip;
        if stick > t_end {
            break;
        }
        out.push(MethodEvent {
            t: stick,
            kind: "stick",
        });
        cycle += 1.0;
        // From the first slip, not summed: no drift of the rounding over the cycles.
        t = c.first_slip_time + cycle * c.period;
    }
    out
}

/// The exact engine's run of the belt: the reference of the sweep's errors (no v̄:
/// [`VBAR_NOT_APPLICABLE`]).
pub fn reference(b: &BeltBench) -> Result<Reference> {
    let full = Exact.solve_surface(
        &b.problem,
        Setting::Tolerance(super::problems::REFERENCE_TOLERANCE),
    )?;
    Ok(Reference {
        events: transitions(&full.events),
        x_end_m: full.x_end,
        v_end_m_s: full.v_end,
        vbar_m_s: None,
    })
}

/// The exact reference of the belt against its closed forms.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct ClosedFormCheck {
    /// Slip and stick events of the closed forms and of the exact engine up to t_end.
    pub events_closed_form: usize,
    pub events_exact: usize,
    /// Same kinds in the same order.
    pub same_pattern: bool,
    /// Largest |t_exact − t_closed form| over the events (s).
    pub max_event_err_s: Option<f64>,
    /// x(t_end) of the closed forms (m): x_e + v_b (t_end − t of the last stick), the run
    /// ending mid-stick; `None` if it ends in a slip.
    pub x_end_closed_form_m: Option<f64>,
    /// |x_exact(t_end) − x_closed form(t_end)| (m).
    pub x_end_err_m: Option<f64>,
}

impl ClosedFormCheck {
    /// The reference agrees with the closed forms: same events, times and end position
    /// within 1e-12 relative (the project's tolerance for the belt).
    pub fn agrees(&self, t_end: f64, x_scale: f64) -> bool {
        self.same_pattern
            && self.events_closed_form == self.events_exact
            && self.max_event_err_s.is_some_and(|e| e <= 1e-12 * t_end)
            && self.x_end_err_m.is_some_and(|e| e <= 1e-12 * x_scale)
    }
}

/// Checks the exact reference `r` of `b` against the closed forms.
pub fn closed_form_check(b: &BeltBench, r: &Reference) -> ClosedFormCheck {
    let want = closed_form_events(&b.closed, b.problem.t_end);
    let m = match_events(&r.events, &want);
    let x_end = want
        .last()
        .filter(|e| e.kind == "stick")
        .map(|e| b.closed.x_slip_end + b.params.v_b * (b.problem.t_end - e.t));
    ClosedFormCheck {
        events_closed_form: want.len(),
        events_exact: r.events.len(),
        same_pattern: m.n_method == m.n_exact && m.kind_mismatches == 0,
        max_event_err_s: m.max_err,
        x_end_closed_form_m: x_end,
        x_end_err_m: x_end.map(|x| (r.x_end_m - x).abs()),
    }
}

/// Largest event-time error (s) against `want`, after checking the kinds agree (the methods'
/// tests on the belt).
#[cfg(test)]
pub(crate) fn error(got: &crate::solver::Solution, want: &[MethodEvent]) -> f64 {
    let kinds = |e: &[MethodEvent]| e.iter().map(|e| e.kind).collect::<Vec<_>>();
    assert_eq!(kinds(&got.events), kinds(want));
    got.events
        .iter()
        .zip(want)
        .map(|(a, b)| (a.t - b.t).abs())
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::solver::rk4::Rk4;

    #[test]
    fn the_reference_agrees_with_the_closed_forms() {
        let b = bench().unwrap();
        let r = reference(&b).unwrap();
        let c = closed_form_check(&b, &r);
        assert_eq!((c.events_closed_form, c.events_exact), (40, 40));
        assert!(c.agrees(b.problem.t_end, b.closed.x_max.abs()), "{c:?}");
        assert_eq!(r.vbar_m_s, None);
        // A reference with one event moved by 1 µs is caught.
        let mut moved = r.clone();
        moved.events[7].t += 1e-6;
        let c = closed_form_check(&b, &moved);
        assert!(!c.agrees(b.problem.t_end, b.closed.x_max.abs()), "{c:?}");
        assert!((c.max_event_err_s.unwrap() - 1e-6).abs() < 1e-9);
    }

    #[test]
    fn the_exact_engine_gives_the_closed_forms_event_times() {
        let (p, problem) = problem().unwrap();
        let c = formula::evaluate(&p);
        let want = closed_form_events(&c, problem.t_end);
        assert_eq!(want.len(), 2 * PERIODS as usize);
        let got = Exact.solve_surface(&problem, Setting::Step(1.0)).unwrap();
        let err = error(&got, &want);
        assert!(err <= 1e-13 * problem.t_end, "{err:e}");
        // The end lies mid-stick: carried by the belt, at x_e + v_b t_stick/2.
        assert_eq!(got.v_end, p.v_b);
        let x = c.x_slip_end + 0.5 * p.v_b * c.t_stick;
        assert!((got.x_end - x).abs() <= 1e-13, "{} {x}", got.x_end);
    }

    #[test]
    fn rk4_converges_to_the_exact_event_times_as_its_step_shrinks() {
        let (p, problem) = problem().unwrap();
        let c = formula::evaluate(&p);
        let want = closed_form_events(&c, problem.t_end);
        let exact = Exact.solve_surface(&problem, Setting::Step(1.0)).unwrap();
        let points: Vec<(f64, f64)> = [25.0, 50.0, 100.0, 200.0]
            .iter()
            .map(|n| {
                let h = c.period / n;
                let got = Rk4.solve_surface(&problem, Setting::Step(h)).unwrap();
                assert_eq!(got.v_end, p.v_b);
                let err = error(&got, &want);
                // The position at the end carries the last stick's error, carried at v_b.
                assert!((got.x_end - exact.x_end).abs() <= 2.0 * p.v_b * err, "{n}");
                (h, err)
            })
            .collect();
        // Measured: 1.2e-3, 4.5e-5, 6.6e-6, 5.4e-7 s over 20 cycles; fitted order 3.6 (the
        // slips are harmonic arcs of ω h = 0.46 … 0.057 rad per step).
        assert!(
            points.windows(2).all(|w| w[1].1 < w[0].1 / 6.0),
            "{points:?}"
        );
        let order = crate::solver::test_support::fitted_slope(&points);
        assert!(3.0 < order && order < 4.8, "order {order}: {points:?}");
        assert!(points[3].1 < 1e-6, "{points:?}");
    }

    #[test]
    fn every_method_takes_it_and_one_of_forces_of_time_only_is_refused_by_name() {
        let (p, problem) = problem().unwrap();
        let h = Setting::Step(formula::evaluate(&p).period / 100.0);
        let tol = Setting::Tolerance(1e-6);
        for method in crate::solver::methods() {
            let setting = match method.name() {
                "exact" | "rk4" | "moreau" | "euler_sign" => h,
                _ => tol,
            };
            let got = method.solve_surface(&problem, setting);
            assert!(got.is_ok(), "{}: {got:?}", method.name());
        }
        // A method that does not override `solve_surface` takes forces of time only.
        struct TimeOnly;
        impl Method for TimeOnly {
            fn name(&self) -> &'static str {
                "time_only"
            }
            fn solve(
                &self,
                problem: &crate::solver::Problem,
                setting: Setting,
            ) -> Result<crate::solver::Solution> {
                Exact.solve(problem, setting)
            }
        }
        let e = TimeOnly
            .solve_surface(&problem, tol)
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("invalid parameter method"), "{e}");
        assert!(
            e.contains("time_only") && e.contains("forces of time only"),
            "{e}"
        );
    }
}
