//! A progress bar for long commands (`sweep`, `worksheet`): drawn on stderr when stderr is a
//! terminal, hidden when it is piped, so scripted output stays clean.

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// A bar of `len` steps labelled `what` (e.g. "sweep", "students").
pub fn progress_bar(len: u32, what: &str) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(u64::from(len)), ProgressDrawTarget::hidden());
    if std::io::stderr().is_terminal() {
        bar.set_draw_target(ProgressDrawTarget::stderr());
        if let Ok(style) =
            ProgressStyle::with_template(&format!("{what} {{bar:40}} {{pos}}/{{len}} {{eta}}"))
        {
            bar.set_style(style);
        }
    }
    bar
}
