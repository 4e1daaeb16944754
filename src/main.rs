//! `stickslip`: thin entry point. Runs the command line ([`stickslip::console::run_args`], which
//! documents the exit codes) on the process's own streams.

use std::process::ExitCode;

use stickslip::console::{ignore_file_size_signal, run_args, Streams};

fn main() -> ExitCode {
    ignore_file_size_signal();
    let (mut out, mut err) = (std::io::stdout(), std::io::stderr());
    ExitCode::from(run_args(
        std::env::args_os(),
        Streams {
            out: &mut out,
            err: &mut err,
            process: true,
        },
    ))
}
