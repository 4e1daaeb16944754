//! The machine and the versions a benchmark ran on: timings mean nothing without them. The
//! compiler and the commit are asked of `rustc` and `git` on PATH at run time (the ones that
//! built the binary when run from the checkout with cargo); the load average is read before
//! the measurements; Python and SciPy versions come from the peer probe; the compiled peer
//! library's version from the Cargo.lock the binary was built with.

use serde::Serialize;

/// Where the benchmark ran.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Machine {
    /// stickslip's version (Cargo.toml).
    pub crate_version: String,
    /// "release" or "debug" (debug timings are not comparable).
    pub profile: String,
    /// `rustc --version`, or "unknown".
    pub rustc: String,
    /// `git describe --always --dirty` of the working directory, or "unknown".
    pub commit: String,
    /// The 1, 5 and 15 minute load averages before the measurements (/proc/loadavg).
    pub load: String,
    /// Logical CPUs available to the process.
    pub nproc: usize,
    /// `model name` of /proc/cpuinfo, or "unknown".
    pub cpu: String,
    pub os: String,
    pub arch: String,
    /// The version of diffsol (the compiled peer's library) this binary was built with, from
    /// Cargo.lock, or "not built in" without the cargo feature `peers`.
    pub diffsol: String,
    /// Python, NumPy and SciPy versions if a probe found them.
    pub python: Option<String>,
    pub numpy: Option<String>,
    pub scipy: Option<String>,
}

impl Machine {
    /// Describes this machine (no Python versions yet).
    pub fn detect() -> Self {
        Self {
            crate_version: env!("CARGO_PKG_VERSION").to_string(),
            profile: if cfg!(debug_assertions) {
                "debug"
            } else {
                "release"
            }
            .to_string(),
            rustc: command(&["rustc", "--version"]).unwrap_or_else(|| "unknown".to_string()),
            commit: command(&["git", "describe", "--always", "--dirty"])
                .unwrap_or_else(|| "unknown".to_string()),
            load: std::fs::read_to_string("/proc/loadavg")
                .ok()
                .map(|l| l.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
                .unwrap_or_else(|| "unknown".to_string()),
            nproc: std::thread::available_parallelism().map_or(1, |n| n.get()),
            cpu: cpu_model().unwrap_or_else(|| "unknown".to_string()),
            os: std::env::consts::OS.to_string(),
            arch: std::env::consts::ARCH.to_string(),
            diffsol: if cfg!(feature = "peers") {
                locked_version("diffsol").unwrap_or_else(|| "unknown".to_string())
            } else {
                "not built in (cargo feature peers)".to_string()
            },
            python: None,
            numpy: None,
            scipy: None,
        }
    }
}

/// The first line a command prints, if it runs and succeeds.
fn command(args: &[&str]) -> Option<String> {
    let out = std::process::Command::new(args[0])
        .args(&args[1..])
        .output()
        .ok()?;
    let text = String::from_utf8_lossy(&out.stdout);
    let line = text.lines().next()?.trim();
    (out.status.success() && !line.is_empty()).then(|| line.to_string())
}

/// The version of the package `name` in the Cargo.lock this binary was built from.
fn locked_version(name: &str) -> Option<String> {
    let lock: toml::Table = toml::from_str(include_str!(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/Cargo.lock"
    )))
    .ok()?;
    lock.get("package")?
        .as_array()?
        .iter()
        .find(|p| p.get("name").and_then(toml::Value::as_str) == Some(name))?
        .get("version")?
        .as_str()
        .map(str::to_string)
}

/// The first `model name` line of /proc/cpuinfo.
fn cpu_model() -> Option<String> {
    let text = std::fs::read_to_string("/proc/cpuinfo").ok()?;
    text.lines()
        .find(|l| l.starts_with("model name"))
        .and_then(|l| l.split_once(':'))
        .map(|(_, v)| v.trim().to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_locked_diffsol_version_is_read_from_cargo_lock() {
        let v = locked_version("diffsol").expect("diffsol in Cargo.lock");
        assert!(v.split('.').count() == 3 && v.starts_with("0."), "{v}");
        assert_eq!(locked_version("no-such-package"), None);
    }
}
