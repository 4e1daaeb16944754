//! `stickslip`: thin entry point. Parses the command line, runs it, prints the error chain.
//!
//! Exit codes: 0 success; 2 bad input (usage, parameter out of range, unreadable or malformed
//! scenario or tracked data, unknown scene, unwritable output, `--pdf` without Chromium); 1 an
//! internal failure: the engine, a figure or template, a fit that did not converge (its results
//! are written, flagged), or Chromium failing to print; 3 a negative verdict on the user's own
//! input, reported in full (`check`: the formula disagrees with the exact integration; `fit`:
//! the model does not describe the data). [`Error::exit_code`] holds the rule.

use std::process::ExitCode;

use clap::Parser;

use stickslip::cli::Cli;
use stickslip::commands::run;
use stickslip::error::{excerpt, Error};

/// Longest error line (characters, "error: " included).
const MESSAGE_CHARS: usize = 300;

fn main() -> ExitCode {
    ignore_file_size_signal();
    let cli = match Cli::try_parse() {
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
            eprintln!(
                "{}",
                excerpt(
                    &format!("error: a subcommand is required: {usage} (see --help)"),
                    MESSAGE_CHARS
                )
            );
            return ExitCode::from(2);
        }
        Err(e) if e.use_stderr() => {
            eprintln!(
                "{}",
                excerpt(&one_line(&e.render().to_string()), MESSAGE_CHARS)
            );
            return ExitCode::from(2);
        }
        Err(e) => {
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
    };
    match run(cli) {
        Ok(()) => {
            for hint in stickslip::commands::take_hints() {
                eprintln!("{}", excerpt(&hint, MESSAGE_CHARS));
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            // The library's errors decide (Error::exit_code); the others are usage refused here.
            let code = e.downcast_ref::<Error>().map_or(2, Error::exit_code);
            // A negative verdict (3) is the result of a complete run, not a failure.
            let label = if code == 3 { "verdict" } else { "error" };
            // One line, control bytes escaped, bounded (the library's messages already are).
            eprintln!("{}", excerpt(&format!("{label}: {e:#}"), MESSAGE_CHARS));
            ExitCode::from(code)
        }
    }
}

/// A write beyond the file-size limit (`ulimit -f`) fails with EFBIG, reported as "cannot
/// write", instead of killing the process with SIGXFSZ mid-output.
fn ignore_file_size_signal() {
    #[cfg(unix)]
    // SAFETY: setting the disposition of one signal to SIG_IGN before any thread starts.
    unsafe {
        libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
    }
}

/// clap's message on one line: the problem, the flags it names and the possible values, without
/// the usage and help hints that follow a blank line.
fn one_line(clap_message: &str) -> String {
    let line = clap_message
        .lines()
        .take_while(|l| !l.trim().is_empty())
        .map(str::trim)
        .collect::<Vec<_>>()
        .join(" ");
    if line.is_empty() {
        "error: invalid usage".to_string()
    } else {
        line
    }
}
