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
    /// A scenario file that cannot be read or parsed.
    #[error("scenario {path}: {reason}")]
    Scenario { path: String, reason: String },
    /// A scene id that is neither a built-in scene nor a scenario file.
    #[error(
        "unknown scene `{id}`: `stickslip handout --list` shows the built-in scene ids; a \
         scenario file (.toml) is accepted too"
    )]
    UnknownScene { id: String },
    /// `--pdf` without a headless Chromium to print with.
    #[error(
        "--pdf needs headless Chromium: install the `chromium` package or set \
         STICKSLIP_CHROMIUM{detail}"
    )]
    NoChromium {
        /// Empty, or why the browser named by STICKSLIP_CHROMIUM cannot be used.
        detail: String,
    },
    /// Chromium ran but did not print the PDF.
    #[error("printing {path} to PDF with {browser} failed: {reason}")]
    Pdf {
        path: String,
        browser: String,
        reason: String,
    },
}

/// Result alias of the library.
pub type Result<T> = std::result::Result<T, Error>;
