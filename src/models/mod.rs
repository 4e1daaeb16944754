//! The paper's two models as forcings of the one dry-friction engine: each builds a [`Body`]
//! and a [`ForceLaw`] for the harmonic law (the real oscillation) or the linearized
//! (triangle-wave) law of the closed forms.
//!
//! [`Body`]: crate::engine::Body
//! [`ForceLaw`]: crate::engine::ForceLaw

use serde::Serialize;

pub mod pulled_mass;
pub mod woodpecker;

/// Which force law drives the model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum LawKind {
    /// The real, harmonic oscillation (cos ωt).
    Harmonic,
    /// The triangle wave with the same extremes or zeros, for which the paper gives closed forms.
    Linear,
}
