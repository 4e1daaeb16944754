//! The autonomous problem of the bench: a body under a force affine in its position on a
//! surface moving at constant speed (the belt, [`crate::engine::autonomous`]), and the view of
//! both problems the generic methods step through ([`System`]).
//!
//! ```text
//! SurfaceProblem   D(x) = D0 + c x, constant N_f, surface speed v_s; start carried at x = 0, t = 0
//! System           forces(t, x) and the surface speed: a method integrates u = x − v_s t and
//!                  w = v − v_s, so that sticking is w = 0 on either problem
//! ```
//!
//! With v_s = 0 and a force of time only ([`Problem`]) u = x and w = v: the same numbers.

use super::dopri5::next_breakpoint;
use super::Problem;
use crate::engine::{Body, SurfaceLaw};
use crate::error::Error;

/// The dry-friction problem of a body on a moving surface, up to `t_end` (s).
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceProblem {
    pub body: Body,
    pub law: SurfaceLaw,
    /// Final time (s).
    pub t_end: f64,
}

/// What a generic method needs of a problem: the forces at (t, x), the surface's speed, and
/// where the forces have kinks in time.
pub trait System {
    fn body(&self) -> &Body;
    /// D and N_f (N) at absolute time t (s) and position x (m); N_f does not depend on x.
    fn forces(&self, t: f64, x: f64) -> (f64, f64);
    /// Speed of the surface the body sticks to (m/s).
    fn surface_speed(&self) -> f64;
    /// ∂D/∂x (N/m), constant on both problems (0 for forces of time only): the Jacobian the
    /// implicit methods solve with (Moreau–Jean's W = M − h²θ² ∂D/∂x).
    fn force_gradient(&self) -> f64;
    /// The first kink of the forces in time after t (s), infinity without one.
    fn breakpoint_after(&self, t: f64) -> f64;
    fn t_end(&self) -> f64;

    /// Acceleration while slipping in direction `s` relative to the surface (m/s²).
    fn slip_acceleration(&self, t: f64, x: f64, s: f64) -> f64 {
        let (d, n) = self.forces(t, x);
        self.body().slip_acceleration(d, n, s)
    }
}

impl System for Problem {
    fn body(&self) -> &Body {
        &self.body
    }
    /// The forces of time only: x is not read.
    fn forces(&self, t: f64, _x: f64) -> (f64, f64) {
        Problem::forces(self, t)
    }
    fn surface_speed(&self) -> f64 {
        0.0
    }
    fn force_gradient(&self) -> f64 {
        0.0
    }
    fn breakpoint_after(&self, t: f64) -> f64 {
        next_breakpoint(self, t)
    }
    fn t_end(&self) -> f64 {
        self.t_end
    }
}

impl System for SurfaceProblem {
    fn body(&self) -> &Body {
        &self.body
    }
    fn forces(&self, _t: f64, x: f64) -> (f64, f64) {
        (self.law.force(x), self.law.normal)
    }
    fn surface_speed(&self) -> f64 {
        self.law.surface_speed
    }
    fn force_gradient(&self) -> f64 {
        self.law.stiffness
    }
    fn breakpoint_after(&self, _t: f64) -> f64 {
        f64::INFINITY
    }
    fn t_end(&self) -> f64 {
        self.t_end
    }
}

/// Position (m) and velocity (m/s) at time t (s) of a body at u = x − v_s t, w = v − v_s; on
/// a still surface the same numbers.
pub fn absolute(problem: &impl System, t: f64, u: f64, w: f64) -> (f64, f64) {
    let v_s = problem.surface_speed();
    if v_s == 0.0 {
        (u, w)
    } else {
        (u + v_s * t, w + v_s)
    }
}

/// The refusal of a method that takes forces of time only ([`Problem`]).
pub fn refused(method: &str) -> Error {
    Error::InvalidParam {
        name: "method",
        value: method.to_string(),
        rule: "forces of time only: a force depending on the position needs exact, rk4, dopri5, \
               moreau, tanh_dopri5, tanh_trbdf2, euler_sign or diffsol_tsit45"
            .to_string(),
    }
}
