//! Rendering of results for people: number formatting and the terminal tables of `eval`.

pub mod format;
pub mod progress;
pub mod text;
