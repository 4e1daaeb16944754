//! Results: the integration summaries, the checks of closed forms against the integration, and
//! the evaluation of a whole model (physics.md §7), as plain serde data.

pub mod checks;
pub mod pulled_mass;
pub mod quantity;
pub mod summary;
pub mod woodpecker;

pub use checks::{Check, CheckValue, TOLERANCE};
pub use summary::{Power, Summary};
