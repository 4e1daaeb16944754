//! Error types of the library: invalid parameters, engine failures, scenario files, tracked
//! data and fits.
//!
//! Every message is one line: the text that comes from the user (paths, scenario keys, CSV
//! cells, header names) goes through [`excerpt`], which escapes control characters and cuts it
//! to a bounded length, and numbers are written short ([`short`]).

use thiserror::Error;

/// Longest excerpt of a path, a reason, a value or a name in a message (characters).
const PATH_CHARS: usize = 70;
const REASON_CHARS: usize = 150;
const VALUE_CHARS: usize = 40;

/// Everything the library can refuse or fail at. Each variant carries the data needed for a
/// one-line message naming the parameter, its value and the valid range.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum Error {
    /// A parameter outside its valid range.
    #[error(
        "invalid parameter {name} = {}: must satisfy {}",
        excerpt(value, VALUE_CHARS),
        excerpt(rule, REASON_CHARS)
    )]
    InvalidParam {
        name: &'static str,
        value: String,
        rule: String,
    },
    /// A force law that does not tile its period with finite pieces.
    #[error("invalid force law: {}", excerpt(.0, REASON_CHARS))]
    InvalidLaw(String),
    /// Something a model does not have: a capability a command needs (a report, a worksheet, an
    /// explorer map), or a time-periodic force law for a model whose force depends on the
    /// position. `what` says what is missing and, where there is one, what to use instead.
    #[error("the {model} model has no {}", excerpt(what, REASON_CHARS))]
    Unsupported { model: &'static str, what: String },
    /// The engine could not advance (should not happen for valid laws).
    #[error("integration stalled at t = {} s: {reason}", short(*t))]
    Stalled { t: f64, reason: &'static str },
    /// An ODE library driven by a method of `stickslip bench` refused or failed (its own
    /// message, e.g. a step size below its minimum).
    #[error(
        "{library} failed at t = {} s: {}",
        short(*t),
        excerpt(reason, REASON_CHARS)
    )]
    Library {
        library: &'static str,
        t: f64,
        reason: String,
    },
    /// A figure that could not be drawn.
    #[error(
        "figure {}: {}",
        excerpt(id, PATH_CHARS),
        excerpt(reason, REASON_CHARS)
    )]
    Figure { id: String, reason: String },
    /// A report template that failed to render (a bug in a template).
    #[error(
        "template {}: {}",
        excerpt(name, PATH_CHARS),
        excerpt(reason, REASON_CHARS)
    )]
    Template { name: String, reason: String },
    /// A formula of `stickslip check` that cannot be read or evaluated.
    #[error("formula {formula}: {}", excerpt(reason, REASON_CHARS))]
    Formula { formula: String, reason: String },
    /// An output file or folder that cannot be written.
    #[error(
        "cannot write {}: {}",
        excerpt_path(path),
        excerpt(reason, REASON_CHARS)
    )]
    Output { path: String, reason: String },
    /// A choice outside the valid values of a command-line option.
    #[error(
        "invalid value '{}' for {flag}: {}",
        excerpt(value, VALUE_CHARS),
        excerpt(valid, REASON_CHARS)
    )]
    InvalidChoice {
        flag: &'static str,
        value: String,
        valid: String,
    },
    /// No drawn parameter set was in the requested regime with every question answerable.
    #[error(
        "no parameter set in regime {} answers every question after {attempts} draws: \
         ask fewer questions (--questions) or another --regime",
        excerpt(regime, VALUE_CHARS)
    )]
    Unreachable { regime: String, attempts: u32 },
    /// A scenario file that cannot be read or parsed.
    #[error("scenario {}: {}", excerpt_path(path), excerpt(reason, REASON_CHARS))]
    Scenario { path: String, reason: String },
    /// A scene id that is neither a built-in scene nor a scenario file.
    #[error(
        "unknown scene `{}`: `stickslip handout --list` shows the built-in scene ids; a \
         scenario file (.toml) is accepted too",
        excerpt(id, PATH_CHARS)
    )]
    UnknownScene { id: String },
    /// `--pdf` without a headless Chromium to print with.
    #[error(
        "--pdf needs headless Chromium: install Chromium, Google Chrome or Microsoft Edge, or \
         set STICKSLIP_CHROMIUM to the browser's program{}",
        excerpt(detail, REASON_CHARS)
    )]
    NoChromium {
        /// Empty, or why the browser named by STICKSLIP_CHROMIUM cannot be used.
        detail: String,
    },
    /// Chromium ran but did not print the PDF.
    #[error(
        "printing {} to PDF with {} failed: {}",
        excerpt_path(path),
        excerpt_path(browser),
        excerpt(reason, REASON_CHARS - 60)
    )]
    Pdf {
        path: String,
        browser: String,
        reason: String,
    },
    /// A tracked-positions file (`stickslip fit`) that cannot be read or is malformed; `line`
    /// is the line of the file (1-based) and `column` the header name of the cell, when the
    /// problem has a place.
    #[error(
        "tracked data {}: {}{}",
        excerpt_path(path),
        place(*.line, .column.as_deref()),
        excerpt(reason, REASON_CHARS)
    )]
    TrackedData {
        path: String,
        line: Option<u64>,
        column: Option<String>,
        reason: String,
    },
    /// Parameters each inside its range whose combination drives a result out of the range of
    /// double precision (overflow to ∞, underflow to 0 of a non-zero quantity, or NaN).
    #[error(
        "the parameters make {} = {} out of the range of double precision: bring {} closer \
         to a real apparatus",
        excerpt(quantity, VALUE_CHARS),
        excerpt(value, VALUE_CHARS),
        excerpt(params, REASON_CHARS)
    )]
    OutOfRange {
        quantity: String,
        value: String,
        params: String,
    },
    /// A fit that ended without converging (results are still reported, flagged).
    #[error("the fit did not converge: {}", excerpt(reason, REASON_CHARS))]
    NotConverged { reason: String },
    /// A negative verdict on the user's own input, reached and reported in full: a formula
    /// that disagrees with the exact integration (`check`), tracked data the model does not
    /// describe (`fit`). Its results are written; the exit code lets a script or CI job tell it
    /// from success and from bad input.
    #[error("{}", excerpt(reason, REASON_CHARS))]
    Verdict { reason: String },
}

/// `text` made safe for a one-line message: control characters, line and paragraph separators
/// and the bidirectional overrides escaped (`\n`, `\t`, `\u{1b}`), and cut to at most `max`
/// characters, the last one "…" when something was cut.
pub fn excerpt(text: &str, max: usize) -> String {
    let mut out = String::new();
    let mut count = 0;
    // Where the text is cut if it turns out too long: the ellipsis must fit too.
    let mut cut = None;
    let mut buf = [0u8; 4];
    for c in text.chars() {
        let escaped = escape(c);
        let piece = escaped
            .as_deref()
            .unwrap_or_else(|| c.encode_utf8(&mut buf));
        let len = piece.chars().count();
        if cut.is_none() && count + len >= max {
            cut = Some(out.len());
        }
        if count + len > max {
            out.truncate(cut.unwrap_or(0));
            out.push('…');
            return out;
        }
        out.push_str(piece);
        count += len;
    }
    out
}

/// A path for a message: escaped like [`excerpt`], and when too long cut in the middle, so
/// that the start and the file name stay.
pub fn excerpt_path(path: &str) -> String {
    let escaped = excerpt(path, usize::MAX);
    let chars: Vec<char> = escaped.chars().collect();
    if chars.len() <= PATH_CHARS {
        return escaped;
    }
    let head = PATH_CHARS / 3;
    let tail = PATH_CHARS - head - 1;
    let mut out: String = chars[..head].iter().collect();
    out.push('…');
    out.extend(&chars[chars.len() - tail..]);
    out
}

/// The escape of a character that must not reach a terminal or break a line; `None` for the
/// others.
fn escape(c: char) -> Option<String> {
    match c {
        '\n' => Some("\\n".to_string()),
        '\r' => Some("\\r".to_string()),
        '\t' => Some("\\t".to_string()),
        c if c.is_control()
            || matches!(c, '\u{2028}' | '\u{2029}' | '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}') =>
        {
            Some(format!("\\u{{{:x}}}", u32::from(c)))
        }
        _ => None,
    }
}

/// A number as written in messages: plain for ordinary magnitudes, else scientific with at most
/// 17 significant figures (never the 300 digits of `{}` of 1e300).
pub fn short(x: f64) -> String {
    let a = x.abs();
    if a != 0.0 && a.is_finite() && !(1e-4..1e6).contains(&a) {
        format!("{x:e}")
    } else {
        x.to_string()
    }
}

impl Error {
    /// The exit code of the process that stops on this error. The rule: 2 when the input is at
    /// fault, that is when another command line, input file, output folder or installed
    /// browser would have succeeded (a parameter out of range, an invalid choice, a regime
    /// that no worksheet draw reaches, a scenario or tracked-data file that cannot be read or
    /// parsed, an unknown scene, an unwritable output, `--pdf` without Chromium); 1 when the
    /// program or the tool it runs failed on valid input (the engine stalled, a force law our
    /// own code built is invalid, a figure or template failed to render, a fit did not
    /// converge, Chromium failed to print); 3 for a negative verdict on the user's own input
    /// (`check`: the formula disagrees; `fit`: the model does not describe the data), whose
    /// results are complete. The match is exhaustive: a new variant has to be classified.
    pub fn exit_code(&self) -> u8 {
        match self {
            Self::InvalidParam { .. }
            | Self::InvalidChoice { .. }
            | Self::Unreachable { .. }
            | Self::Scenario { .. }
            | Self::UnknownScene { .. }
            | Self::TrackedData { .. }
            | Self::Output { .. }
            | Self::OutOfRange { .. }
            | Self::NoChromium { .. }
            | Self::Formula { .. }
            | Self::Unsupported { .. } => 2,
            Self::Stalled { .. }
            | Self::Library { .. }
            | Self::InvalidLaw(_)
            | Self::Figure { .. }
            | Self::Template { .. }
            | Self::NotConverged { .. }
            | Self::Pdf { .. } => 1,
            Self::Verdict { .. } => 3,
        }
    }
}

/// "line 17, column y: ", "line 17: " or nothing.
fn place(line: Option<u64>, column: Option<&str>) -> String {
    let column = column.map(|c| excerpt(c, VALUE_CHARS));
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
    fn excerpts_escape_control_bytes_and_stay_short() {
        assert_eq!(excerpt("plain", 10), "plain");
        assert_eq!(
            excerpt("a\nb\tc\u{1b}[31m\u{7}", 40),
            "a\\nb\\tc\\u{1b}[31m\\u{7}"
        );
        assert_eq!(excerpt("\u{202e}evil", 40), "\\u{202e}evil");
        assert_eq!(excerpt("abcdefghij", 10), "abcdefghij");
        assert_eq!(excerpt("abcdefghijk", 10), "abcdefghi…");
        assert_eq!(excerpt("abcdefgh\n", 9), "abcdefgh…");
        let long = "x".repeat(2_000_000);
        assert_eq!(excerpt(&long, 50).chars().count(), 50);
        let path = format!("/{}/file.csv", "d".repeat(500));
        let shown = excerpt_path(&path);
        assert!(shown.ends_with("/file.csv") && shown.chars().count() == PATH_CHARS);
        assert_eq!(short(1e300), "1e300");
        assert_eq!(short(0.25), "0.25");
        assert_eq!(short(-3.5e-9), "-3.5e-9");
    }

    #[test]
    fn every_message_is_one_bounded_line() {
        let nasty = format!("a\nb\u{1b}]0;title\u{7}{}", "z".repeat(5000));
        let errors = [
            Error::InvalidParam {
                name: "k",
                value: nasty.clone(),
                rule: nasty.clone(),
            },
            Error::Scenario {
                path: nasty.clone(),
                reason: nasty.clone(),
            },
            Error::TrackedData {
                path: nasty.clone(),
                line: Some(3),
                column: Some(nasty.clone()),
                reason: nasty.clone(),
            },
            Error::Output {
                path: nasty.clone(),
                reason: nasty.clone(),
            },
            Error::Stalled {
                t: 1e300,
                reason: "no progress",
            },
            Error::Library {
                library: "diffsol",
                t: 1e300,
                reason: nasty.clone(),
            },
            Error::Pdf {
                path: nasty.clone(),
                browser: nasty.clone(),
                reason: nasty.clone(),
            },
        ];
        for e in errors {
            let msg = e.to_string();
            // "error: " comes in front.
            assert!(msg.chars().count() <= 293, "{msg}");
            assert!(!msg.chars().any(char::is_control), "{msg:?}");
        }
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
