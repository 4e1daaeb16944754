//! What the paper's two models (the pulled mass and the woodpecker) share in their
//! presentation: the two force laws, the harmonic one and its linearization, and how the
//! pages name what the closed forms are checked against. A model of the paper's kind uses
//! these; another model (the belt) names its own laws. And the paper's claims, which span both
//! models ([`claims`]).

pub mod claims;

#[cfg(feature = "cli")]
use crate::present::vocab::{LawName, LawWords};

/// The harmonic law and its linearization, in the order of the evaluations' runs.
#[cfg(feature = "cli")]
pub const LAWS: &[LawName] = &[
    LawName {
        id: "harmonic",
        name: "harmonic law",
        summary: "harmonic",
    },
    LawName {
        id: "linear",
        name: "linearized law",
        summary: "linear",
    },
];

/// The closed forms are those of the linearized law, checked against its exact integration.
#[cfg(feature = "cli")]
pub const LAW_WORDS: LawWords = LawWords {
    closed_form_law: "linearized law",
    checked_against: "exact integration of the linearized law",
    numeric_from: "exact event-driven integration of the same (triangle-wave) law",
};

/// The heading of the table of both laws side by side.
#[cfg(feature = "cli")]
pub const LINEARIZATION: &str = "Linearization: harmonic law against the linearized law";
