//! Error types of the library: invalid parameters, engine failures, scenario files.

use thiserror::Error;

/// Everything the library can refuse or fail at. Each variant carries the data needed for a
/// one-line message naming the parameter, its value and the valid range.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum Error {
    /// A parameter outside its valid range.
    #[error("invalid parameter {name} = {value}: must satisfy {rule}")]
    InvalidParam {
        name: &'static str,
        value: String,
        rule: String,
    },
    /// A force law that does not tile its period with finite pieces.
    #[error("invalid force law: {0}")]
    InvalidLaw(String),
    /// The engine could not advance (should not happen for valid laws).
    #[error("integration stalled at t = {t} s: {reason}")]
    Stalled { t: f64, reason: &'static str },
    /// A figure that could not be drawn.
    #[error("figure {id}: {reason}")]
    Figure { id: String, reason: String },
    /// A report template that failed to render (a bug in a template).
    #[error("template {name}: {reason}")]
    Template { name: String, reason: String },
    /// An output file or folder that cannot be written.
    #[error("cannot write {path}: {reason}")]
    Output { path: String, reason: String },
    /// A choice outside the valid values of a command-line option.
    #[error("invalid value '{value}' for {flag}: {valid}")]
    InvalidChoice {
        flag: &'static str,
        value: String,
        valid: String,
    },
    /// No drawn parameter set was in the requested regime with every question answerable.
    #[error(
        "no parameter set in regime {regime} answers every question after {attempts} draws: \
         ask fewer questions (--questions) or another --regime"
    )]
    Unreachable { regime: String, attempts: u32 },
    /// A scenario file that cannot be read or parsed.
    #[error("scenario {path}: {reason}")]
    Scenario { path: String, reason: String },
}

/// Result alias of the library.
pub type Result<T> = std::result::Result<T, Error>;
