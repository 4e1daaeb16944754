//! The dry-friction engine: one body of mass M under a prescribed driving force D(t) and a
//! friction-bearing normal force N_f(t), with Coulomb friction (guide §4).
//!
//! ```text
//! STUCK (v = 0)     leaves when |D| > μs N_f (strict)        → SLIP, s = sgn D
//! SLIP (s = ±1)     M dv/dt = D − s μd N_f;  leaves when s·v reaches 0
//!                   then STUCK if |D| ≤ μs N_f, else SLIP in direction sgn D (a reversal)
//! ```
//!
//! The force law is data ([`ForceLaw`]): a period tiled by pieces on which D and N_f are affine
//! in one basis function (t − t_ref, or cos ωt). On each piece the motion is known in closed
//! form ([`arc::Arc`]), so the integration is exact: no step size anywhere, events are located by
//! bracketed root finding on monotone intervals ([`roots`]) to about 1e-15 relative.
//!
//! A force affine in the position on a moving surface (a block on a belt) is the autonomous
//! system of [`autonomous`]: harmonic slip arcs, sticking at the surface's speed, and a cycle
//! (with its period) found from the events.

pub mod accel;
pub mod arc;
pub mod autonomous;
pub mod dd;
pub mod law;
pub mod replay;
pub mod roots;
pub mod run;
pub mod series;
pub mod steady;

pub use autonomous::{
    integrate_surface, integrate_surface_with, HarmonicArc, SurfaceCycle, SurfaceLaw,
    SurfaceOptions, SurfaceRun,
};
pub use law::{Affine, Basis, Body, ForceLaw, Piece};
pub use replay::Replay;
pub use run::{integrate, integrate_with, Event, EventKind, Run, RunOptions, Segment};
pub use series::Series;
pub use steady::{analyse, IntegrationRegime, OrbitKind, Steady};
