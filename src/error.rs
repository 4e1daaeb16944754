//! Error types of the library: invalid parameters, engine failures, scenario files, tracked
//! data and fits.

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
    /// A tracked-positions file (`stickslip fit`) that cannot be read or is malformed; `line`
    /// is the line of the file (1-based) and `column` the header name of the cell, when the
    /// problem has a place.
    #[error("tracked data {path}: {}{reason}", place(*.line, .column.as_deref()))]
    TrackedData {
        path: String,
        line: Option<u64>,
        column: Option<String>,
        reason: String,
    },
    /// A fit that ended without converging (results are still reported, flagged).
    #[error("the fit did not converge: {reason}")]
    NotConverged { reason: String },
}

/// "line 17, column y: ", "line 17: " or nothing.
fn place(line: Option<u64>, column: Option<&str>) -> String {
    match (line, column) {
        (Some(l), Some(c)) => format!("line {l}, column {c}: "),
        (Some(l), None) => format!("line {l}: "),
        (None, Some(c)) => format!("column {c}: "),
        (None, None) => String::new(),
    }
}

/// Result alias of the library.
pub type Result<T> = std::result::Result<T, Error>;
