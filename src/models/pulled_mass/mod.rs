//! The pulled mass of the paper's Sec. 2 (physics.md §1): a block pulled by a constant force
//! across a table while a hanging mass on a spring presses it down with N(t) = W(1 + cos ωt).
//! Everything about this model lives in this folder:
//!
//! ```text
//! body.rs        the body and the force laws (harmonic, linearized) for the engine
//! formula.rs     the closed forms of §1.3–1.5, one pure function per quantity
//! quantity.rs    the registry of the quantities: key, symbol, unit, equation, regimes
//! results.rs     the evaluation: closed forms, both laws integrated, checks, applicability
//! claims.rs      the paper's claims about this model (claims 1, 2)
//! derivation.rs  the worked substitutions (formula, numbers, value) of the closed forms
//! scene.rs       the report's figures of this model
//! ```

pub mod body;
pub(crate) mod claims;
pub mod derivation;
pub mod formula;
pub mod quantity;
pub mod results;
pub mod scene;

pub use body::{body, force_law};
