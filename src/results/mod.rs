//! Results: the integration summaries, the checks of closed forms against the integration, and
//! the evaluation of a whole model (physics.md §7), as plain serde data.

pub mod checks;
pub mod quantity;
pub mod summary;

pub use checks::{rel_diff, Check, CheckValue, Checked, TOLERANCE};
pub use summary::{Power, Summary};

/// Whether a paper formula describes the computed motion, and why not.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Applicability {
    /// The quantity (serialized as its §7 key).
    pub quantity: quantity::AnyKey,
    pub applies: bool,
    /// Why not (empty when it applies).
    pub reason: String,
}

impl Applicability {
    /// An entry that applies when `reason` is `None`.
    pub fn new(quantity: impl Into<quantity::AnyKey>, reason: Option<String>) -> Self {
        Self {
            quantity: quantity.into(),
            applies: reason.is_none(),
            reason: reason.unwrap_or_default(),
        }
    }
}
