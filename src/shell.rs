//! `stickslip completions <SHELL>` and `stickslip man`: the shell completion script and the
//! roff man page, both generated from the clap definition in [`crate::cli`], so they name every
//! subcommand and flag the binary has (the model subcommands made from the registry included).
//! Rendered to a `String`; the command prints it.

use clap::CommandFactory;
use clap_complete::Shell;

use crate::cli::Cli;

/// The binary's name, as the scripts and the page call it.
const BIN: &str = "stickslip";

/// The completion script of `shell` (bash, zsh, fish, powershell, elvish).
pub fn completions(shell: Shell) -> String {
    let mut cmd = Cli::command();
    let mut out = Vec::new();
    clap_complete::generate(shell, &mut cmd, BIN, &mut out);
    String::from_utf8_lossy(&out).into_owned()
}

/// The man page `stickslip(1)` in roff: name, synopsis, description, options, the
/// subcommands with their one-line descriptions, and the version. It opens with its `.TH`
/// line, as a man page does; the apostrophe string (`Aq`) that the roff writer defines first
/// follows it, still before any text uses it.
pub fn man_page() -> std::io::Result<String> {
    let mut out = Vec::new();
    clap_mangen::Man::new(Cli::command()).render(&mut out)?;
    let page = String::from_utf8_lossy(&out);
    let (title, rest): (Vec<&str>, Vec<&str>) = page.lines().partition(|l| l.starts_with(".TH "));
    Ok(title
        .into_iter()
        .chain(rest)
        .map(|l| format!("{l}\n"))
        .collect())
}
