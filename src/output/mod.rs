//! Rendering of results for people: number formatting (in the core, for the claims' findings),
//! and with the `cli` feature the terminal tables of `eval` and the progress bar.

pub mod format;
#[cfg(feature = "cli")]
pub mod progress;
#[cfg(feature = "cli")]
pub mod text;
