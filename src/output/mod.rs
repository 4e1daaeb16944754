//! Rendering of results for people (`cli` feature): the terminal tables of `eval` and the
//! progress bar. Number formatting is [`crate::format`], a leaf of the core.

#[cfg(feature = "cli")]
pub mod progress;
#[cfg(feature = "cli")]
pub mod text;
