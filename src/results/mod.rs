//! Results: the integration summaries, the checks of closed forms against the integration, and
//! the evaluation of a whole model (guide §14), as plain serde data.

pub mod checks;
pub mod quantity;
#[cfg(feature = "cli")]
pub mod schema;
pub mod summary;
pub mod version;

pub use checks::{rel_diff, Check, CheckValue, Checked, TOLERANCE};
pub use summary::{Power, Summary};
pub use version::{Versioned, SCHEMA_KEY, SCHEMA_VERSION};

use crate::error::{Error, Result};

/// Refuses an evaluation whose `values` (name, value) hold one out of the range of double
/// precision: NaN, ±∞, or a subnormal (a quantity underflowing to 0). `params` names the
/// parameters of the model, for the message. The parameter ranges keep the paper's sets and
/// any real apparatus far inside; this is the net under their combinations.
pub fn ensure_in_range<'a>(
    values: impl IntoIterator<Item = (&'a str, f64)>,
    params: &str,
) -> Result<()> {
    match values
        .into_iter()
        .find(|(_, x)| !x.is_finite() || x.is_subnormal())
    {
        None => Ok(()),
        Some((name, x)) => Err(Error::OutOfRange {
            quantity: name.to_string(),
            value: crate::error::short(x),
            params: params.to_string(),
        }),
    }
}

/// Whether a paper formula describes the computed motion, and why not.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Applicability {
    /// The quantity (serialized as its JSON key (guide §14)).
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
