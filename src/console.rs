//! The command line as a function: arguments in, exit code out, and what the command prints
//! written to two writers. `main` passes the process's streams; the Python module
//! (`src/python.rs`) passes buffers, so a notebook gets exactly the bytes a terminal would.
//!
//! Exit codes: 0 success; 2 bad input (usage, parameter out of range, unreadable or malformed
//! scenario or tracked data, unknown scene, unwritable output, `--pdf` without Chromium); 1 an
//! internal failure: the engine, a figure or template, a fit that did not converge (its results
//! are written, flagged), or Chromium failing to print; 3 a negative verdict on the user's own
//! input, reported in full (`check`: the formula disagrees with the exact integration; `fit`:
//! the model does not describe the data). [`Error::exit_code`] holds the rule.

use std::ffi::OsString;
use std::io::Write;

use clap::Parser;

use crate::cli::Cli;
use crate::commands::{run, take_hints};
use crate::error::{excerpt, Error};

/// Longest error line (characters, "error: " included).
const MESSAGE_CHARS: usize = 300;

/// Where a command line's output goes.
pub struct Streams<'a> {
    /// Standard output: what the command prints (tables, JSON, "wrote … files").
    pub out: &'a mut dyn Write,
    /// Standard error: the one-line error, hints and notes.
    pub err: &'a mut dyn Write,
    /// The streams are the process's own: clap prints `--help` and `--version` itself, styled
    /// when they are a terminal. Otherwise they go plain to `out`.
    pub process: bool,
}

/// Runs the command line `args` (the program name first, as `std::env::args_os` gives it) and
/// returns its exit code. Writing to `err` is best effort: a closed stderr is not an error.
pub fn run_args<I, T>(args: I, streams: Streams<'_>) -> u8
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let Streams { out, err, process } = streams;
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(e) if e.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            // `stickslip`, `stickslip eval`: clap prints the help, with no "error:" line.
            let usage = e.render().to_string();
            let usage = usage
                .lines()
                .find_map(|l| l.trim().strip_prefix("Usage:"))
                .unwrap_or(" stickslip <COMMAND>")
                .trim()
                .to_string();
            let message = format!("error: a subcommand is required: {usage} (see --help)");
            let _ = writeln!(err, "{}", excerpt(&message, MESSAGE_CHARS));
            return 2;
        }
        Err(e) if e.use_stderr() => {
            let message = excerpt(&one_line(&e.render().to_string()), MESSAGE_CHARS);
            let _ = writeln!(err, "{message}");
            return 2;
        }
        Err(e) => {
            // --help, --version.
            if process {
                let _ = e.print();
            } else {
                let _ = write!(out, "{}", e.render());
            }
            return 0;
        }
    };
    let outcome = run(cli, out, err);
    // Hints of a failed command are dropped with it (the next call starts clean).
    let hints = take_hints();
    match outcome {
        Ok(()) => {
            for hint in hints {
                let _ = writeln!(err, "{}", excerpt(&hint, MESSAGE_CHARS));
            }
            0
        }
        Err(e) => {
            // The library's errors decide (Error::exit_code); the others are usage refused here.
            let code = e.downcast_ref::<Error>().map_or(2, Error::exit_code);
            // A negative verdict (3) is the result of a complete run, not a failure.
            let label = if code == 3 { "verdict" } else { "error" };
            // One line, control bytes escaped, bounded (the library's messages already are).
            let message = excerpt(&format!("{label}: {e:#}"), MESSAGE_CHARS);
            let _ = writeln!(err, "{message}");
            code
        }
    }
}

/// clap's message on one line: the problem, the flags it names and the possible values, and
/// its "did you mean" tip in parentheses; without the usage and help hints.
fn one_line(clap_message: &str) -> String {
    let line = clap_message
        .lines()
        .take_while(|l| !l.trim().is_empty())
        .map(str::trim)
        .collect::<Vec<_>>()
        .join(" ");
    if line.is_empty() {
        return "error: invalid usage".to_string();
    }
    let tips: Vec<&str> = clap_message
        .lines()
        .map(str::trim)
        .filter(|l| l.starts_with("tip:"))
        .collect();
    if tips.is_empty() {
        line
    } else {
        format!("{line} ({})", tips.join("; "))
    }
}

/// A write beyond the file-size limit (`ulimit -f`) fails with EFBIG, reported as "cannot
/// write", instead of killing the process with SIGXFSZ mid-output.
pub fn ignore_file_size_signal() {
    #[cfg(unix)]
    // SAFETY: setting the disposition of one signal to SIG_IGN; no handler is involved.
    unsafe {
        libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn captured(args: &[&str]) -> (u8, String, String) {
        let (mut out, mut err) = (Vec::new(), Vec::new());
        let code = run_args(
            std::iter::once("stickslip").chain(args.iter().copied()),
            Streams {
                out: &mut out,
                err: &mut err,
                process: false,
            },
        );
        let text = |b: Vec<u8>| String::from_utf8(b).unwrap();
        (code, text(out), text(err))
    }

    #[test]
    fn clap_errors_keep_their_did_you_mean_tip_on_the_one_line() {
        let (code, out, err) = captured(&["evl"]);
        assert_eq!((code, out.as_str()), (2, ""));
        // clap names every near subcommand ('help' is one for "evl").
        assert!(
            err.starts_with("error: unrecognized subcommand 'evl' (tip: ")
                && err.contains("'eval'"),
            "{err}"
        );
        assert_eq!(err.lines().count(), 1, "{err}");
        let (code, _, err) = captured(&["eval", "woodpecker", "--mu_d", "0.3"]);
        assert_eq!(code, 2);
        assert!(
            err.starts_with("error: unexpected argument '--mu_d' found (tip: "),
            "{err}"
        );
        assert!(
            err.contains("'--mu-d'") && err.lines().count() == 1,
            "{err}"
        );
    }

    #[test]
    fn captured_output_is_what_the_terminal_gets() {
        let (code, out, err) = captured(&["eval", "pulled-mass", "--json"]);
        assert_eq!((code, err.as_str()), (0, ""));
        assert!(
            out.starts_with("{\n  \"schema_version\": \"1\",\n  \"model\": \"pulled-mass\""),
            "{out}"
        );
        let (code, out, _) = captured(&["--version"]);
        let version = format!("stickslip {}\n", env!("CARGO_PKG_VERSION"));
        assert_eq!((code, out), (0, version));
        let (code, out, err) = captured(&["eval", "pulled-mass", "--mu-d", "2"]);
        assert_eq!((code, out.as_str()), (2, ""));
        assert!(
            err.starts_with("error: invalid parameter mu_d = 2"),
            "{err}"
        );
    }
}
