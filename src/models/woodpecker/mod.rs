//! The falling woodpecker of the paper's Sec. 3 (physics.md §2–3): a sleeve that slides and
//! sticks down a pole while the bird oscillates on its spring. Everything about this model
//! lives in this folder:
//!
//! ```text
//! body.rs        the sleeve as a body and the force laws (harmonic, linearized) for the engine
//! formula.rs     the closed forms of §3, one pure function per quantity
//! lobe.rs        the lobe engine: the periodic orbit of the linearized law in every regime
//! quantity.rs    the registry of the quantities: key, symbol, unit, equation, scope
//! results.rs     the evaluation: closed forms, both laws integrated, checks, applicability
//! claims.rs      the paper's claims about this model (claims 4, 6); halt.rs claim 5, lever.rs claim 8
//! derivation.rs  the worked substitutions (formula, numbers, value) of the closed forms
//! scene.rs       the report's figures of this model
//! ```

pub mod body;
pub(crate) mod claims;
pub mod derivation;
pub mod formula;
pub(crate) mod halt;
pub(crate) mod lever;
pub mod lobe;
pub mod quantity;
pub mod results;
pub mod scene;

pub use body::{body, force_law, linear_amplitudes, spring_coordinate};
