//! The belt's body and forces for the engine: the block (m, μs, μd) and its surface law, the
//! spring's force −k x and the weight m g on a belt moving at v_b (docs/belt.md (B6)).

use super::params::BeltParams;
use crate::engine::{Body, SurfaceLaw};
use crate::error::Result;

/// The block: inertial mass m and the friction coefficients.
pub fn body(p: &BeltParams) -> Body {
    Body {
        mass: p.mass,
        mu_s: p.mu_s,
        mu_d: p.mu_d,
    }
}

/// The forces: D(x) = −k x, N_f = m g, on a surface moving at v_b.
pub fn surface_law(p: &BeltParams) -> Result<SurfaceLaw> {
    SurfaceLaw::new(0.0, -p.k, p.weight(), p.v_b)
}
