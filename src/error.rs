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

impl Error {
    /// The exit code of the process that stops on this error. The rule: 2 when the input is at
    /// fault, that is when another command line, input file, output folder or installed
    /// browser would have succeeded (a parameter out of range, an invalid choice, a regime
    /// that no worksheet draw reaches, a scenario or tracked-data file that cannot be read or
    /// parsed, an unknown scene, an unwritable output, `--pdf` without Chromium); 1 when the
    /// program or the tool it runs failed on valid input (the engine stalled, a force law our
    /// own code built is invalid, a figure or template failed to render, a fit did not
    /// converge, Chromium failed to print). The match is exhaustive: a new variant has to be
    /// classified.
    pub fn exit_code(&self) -> u8 {
        match self {
            Self::InvalidParam { .. }
            | Self::InvalidChoice { .. }
            | Self::Unreachable { .. }
            | Self::Scenario { .. }
            | Self::UnknownScene { .. }
            | Self::TrackedData { .. }
            | Self::Output { .. }
            | Self::NoChromium { .. } => 2,
            Self::Stalled { .. }
            | Self::InvalidLaw(_)
            | Self::Figure { .. }
            | Self::Template { .. }
            | Self::NotConverged { .. }
            | Self::Pdf { .. } => 1,
        }
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    fn text(s: &str) -> String {
        s.to_string()
    }

    #[test]
    fn bad_input_exits_2() {
        let bad_input = [
            Error::InvalidParam {
                name: "mu_d",
                value: text("0.5"),
                rule: text("0 < mu_d <= mu_s"),
            },
            Error::InvalidChoice {
                flag: "--format",
                value: text("pdf"),
                valid: text("html, md"),
            },
            Error::Unreachable {
                regime: text("double"),
                attempts: 1000,
            },
            Error::Scenario {
                path: text("s.toml"),
                reason: text("missing title"),
            },
            Error::UnknownScene { id: text("nope") },
            Error::TrackedData {
                path: text("t.csv"),
                line: Some(3),
                column: None,
                reason: text("not a number"),
            },
            Error::Output {
                path: text("out"),
                reason: text("not a directory"),
            },
            Error::NoChromium {
                detail: String::new(),
            },
        ];
        for e in bad_input {
            assert_eq!(e.exit_code(), 2, "{e}");
        }
    }

    #[test]
    fn internal_failures_exit_1() {
        let internal = [
            Error::Stalled {
                t: 1.5,
                reason: "no progress",
            },
            Error::InvalidLaw(text("pieces end at 1 s, not at the period 2 s")),
            Error::Figure {
                id: text("motion"),
                reason: text("empty range"),
            },
            Error::Template {
                name: text("index.html"),
                reason: text("unknown variable"),
            },
            Error::NotConverged {
                reason: text("maximum evaluations"),
            },
            Error::Pdf {
                path: text("handout.pdf"),
                browser: text("chromium"),
                reason: text("exit status 1"),
            },
        ];
        for e in internal {
            assert_eq!(e.exit_code(), 1, "{e}");
        }
    }
}
