//! Printing the handout to PDF with headless Chromium: find the browser, print a page from a
//! private temporary folder (its own profile, no network, no first-run work), and hand back the
//! bytes; the caller writes them with the report's atomic writer, so a failure leaves no PDF.

use std::ffi::OsString;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use crate::error::{Error, Result};

/// Environment variable naming the browser binary; it wins over the search of PATH.
pub const BROWSER_ENV: &str = "STICKSLIP_CHROMIUM";
/// Names looked up on PATH, in order.
const NAMES: &[&str] = &["chromium", "chromium-browser", "google-chrome"];
/// A handout prints in 1–3 s, the answer key of 500 students (13 MB of HTML) in about 65 s on
/// an idle machine: a print is given this much time, plus [`TIMEOUT_PER_PAGE`] per page, before
/// the browser is taken for stuck and killed.
const TIMEOUT_BASE: Duration = Duration::from_secs(60);
/// Time allowed per printed page (about 8× what a page of a 500-student key takes at load 1,
/// room for a second build running beside it).
const TIMEOUT_PER_PAGE: Duration = Duration::from_secs(1);

/// The time a print of `pages` pages may take before the browser is killed.
fn timeout(pages: u32) -> Duration {
    TIMEOUT_BASE + TIMEOUT_PER_PAGE * pages
}
/// How often the running browser is polled.
const POLL: Duration = Duration::from_millis(50);

/// The browser to print with: `$STICKSLIP_CHROMIUM`, else the first of chromium,
/// chromium-browser, google-chrome on PATH.
pub fn locate() -> Result<PathBuf> {
    locate_in(std::env::var_os(BROWSER_ENV), std::env::var_os("PATH"))
}

fn locate_in(named: Option<OsString>, path: Option<OsString>) -> Result<PathBuf> {
    if let Some(named) = named.filter(|n| !n.is_empty()) {
        let named = PathBuf::from(named);
        // A bare name is looked up on PATH like the defaults.
        let found = if named.components().count() == 1 {
            search(path.as_deref(), &named)
        } else {
            is_executable(&named).then(|| named.clone())
        };
        return found.ok_or_else(|| Error::NoChromium {
            detail: format!(
                " ({BROWSER_ENV} = {}: not an executable file)",
                named.display()
            ),
        });
    }
    NAMES
        .iter()
        .find_map(|n| search(path.as_deref(), Path::new(n)))
        .ok_or_else(|| Error::NoChromium {
            detail: String::new(),
        })
}

fn search(path: Option<&std::ffi::OsStr>, name: &Path) -> Option<PathBuf> {
    std::env::split_paths(path?)
        .map(|dir| dir.join(name))
        .find(|candidate| is_executable(candidate))
}

#[cfg(unix)]
fn is_executable(path: &Path) -> bool {
    use std::os::unix::fs::PermissionsExt;
    fs::metadata(path).is_ok_and(|m| m.is_file() && m.permissions().mode() & 0o111 != 0)
}

/// Without Unix permission bits any regular file counts; one that is not a program fails to
/// start when printing, which is reported as [`Error::Pdf`].
#[cfg(not(unix))]
fn is_executable(path: &Path) -> bool {
    fs::metadata(path).is_ok_and(|m| m.is_file())
}

/// Chromium's flags for printing offline without a desktop: headless, no sandbox (CI runs as
/// root), no GPU, no network of its own, no page header or footer.
pub const HEADLESS_FLAGS: &[&str] = &[
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-pdf-header-footer",
];

/// Prefix of the private temporary folder of one print (page, profile, PDF, log).
const WORK_PREFIX: &str = "stickslip-pdf-";
/// An unlocked work folder untouched for this long is a killed print's.
const STALE_AFTER: Duration = Duration::from_secs(120);

/// Removes the work folders of earlier prints that were killed: folders of this user named
/// `stickslip-pdf-*` in `tmp`, untouched for [`STALE_AFTER`], whose lock no running print
/// holds.
fn remove_stale_work_folders(tmp: &Path) {
    let Ok(entries) = fs::read_dir(tmp) else {
        return;
    };
    for e in entries.flatten() {
        if !e.file_name().to_string_lossy().starts_with(WORK_PREFIX) {
            continue;
        }
        let path = e.path();
        let Ok(meta) = fs::symlink_metadata(&path) else {
            continue;
        };
        // A folder made a moment ago may be a running print's that has not locked it yet.
        let settled = meta
            .modified()
            .ok()
            .and_then(|m| m.elapsed().ok())
            .is_some_and(|age| age > STALE_AFTER);
        if !meta.is_dir() || !owned_by_me(&meta) || !settled {
            continue;
        }
        let Ok(dir) = fs::File::open(&path) else {
            continue;
        };
        if !crate::report::lock::is_busy(&dir) {
            let _ = fs::remove_dir_all(&path);
        }
    }
}

#[cfg(unix)]
fn owned_by_me(meta: &fs::Metadata) -> bool {
    use std::os::unix::fs::MetadataExt;
    // SAFETY: getuid has no preconditions.
    meta.uid() == unsafe { libc::getuid() }
}

#[cfg(not(unix))]
fn owned_by_me(_meta: &fs::Metadata) -> bool {
    false
}

/// Prints `html` (a self-contained page of about `pages` A4 pages, saved as `name` in a temporary
/// folder) with `browser` and returns the PDF's bytes; the time allowed grows with `pages`.
pub fn print(browser: &Path, name: &str, html: &str, pages: u32) -> Result<Vec<u8>> {
    let limit = timeout(pages);
    let fail = |reason: String| Error::Pdf {
        path: name.to_string(),
        browser: browser.display().to_string(),
        reason,
    };
    remove_stale_work_folders(&std::env::temp_dir());
    let work = tempfile::Builder::new()
        .prefix(WORK_PREFIX)
        .tempdir()
        .map_err(|e| fail(format!("temporary folder: {e}")))?;
    // Locked while in use: a run killed mid-print leaves the folder (and Chromium's profile,
    // some MB) unlocked, and the next `--pdf` removes it.
    let work_lock =
        fs::File::open(work.path()).map_err(|e| fail(format!("temporary folder: {e}")))?;
    crate::report::lock::hold(&work_lock);
    let page = work.path().join(name);
    let pdf = work.path().join("out.pdf");
    let log = work.path().join("chromium.log");
    fs::write(&page, html).map_err(|e| fail(format!("{}: {e}", page.display())))?;
    let log_file = fs::File::create(&log).map_err(|e| fail(format!("{}: {e}", log.display())))?;
    let mut child = Command::new(browser)
        .args(HEADLESS_FLAGS)
        .arg(format!(
            "--user-data-dir={}",
            work.path().join("profile").display()
        ))
        .arg(format!("--print-to-pdf={}", pdf.display()))
        .arg(format!("file://{}", page.display()))
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        // A file, not a pipe: a chatty browser cannot block on a full pipe while we wait.
        .stderr(log_file)
        .spawn()
        .map_err(|e| fail(format!("cannot start: {e}")))?;
    let started = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break status,
            Ok(None) if started.elapsed() > limit => {
                let _ = child.kill();
                let _ = child.wait();
                return Err(fail(format!(
                    "no answer within {} s, stopped",
                    limit.as_secs()
                )));
            }
            Ok(None) => std::thread::sleep(POLL),
            Err(e) => return Err(fail(e.to_string())),
        }
    };
    let bytes = fs::read(&pdf).unwrap_or_default();
    if status.success() && bytes.starts_with(b"%PDF") {
        return Ok(bytes);
    }
    let last_line = fs::read_to_string(&log)
        .unwrap_or_default()
        .lines()
        .rev()
        .find(|l| !l.trim().is_empty())
        .map_or(String::new(), |l| format!("; last message: {}", l.trim()));
    Err(fail(format!("{status}, no PDF written{last_line}")))
}

// The fake browsers are shell scripts made executable with Unix permissions.
#[cfg(all(test, unix))]
mod tests {
    use super::*;

    fn executable(dir: &Path, name: &str) -> PathBuf {
        use std::os::unix::fs::PermissionsExt;
        let path = dir.join(name);
        fs::write(&path, "#!/bin/sh\nexit 3\n").unwrap();
        fs::set_permissions(&path, fs::Permissions::from_mode(0o755)).unwrap();
        path
    }

    #[test]
    fn the_environment_variable_wins_over_path_and_must_name_an_executable() {
        let dir = tempfile::tempdir().unwrap();
        let on_path = executable(dir.path(), "chromium");
        let other = executable(dir.path(), "my-browser");
        let path = Some(dir.path().as_os_str().to_owned());
        assert_eq!(locate_in(None, path.clone()).unwrap(), on_path);
        assert_eq!(
            locate_in(Some(other.clone().into()), path.clone()).unwrap(),
            other
        );
        assert_eq!(
            locate_in(Some("my-browser".into()), path.clone()).unwrap(),
            other
        );
        let err = locate_in(Some(dir.path().join("nope").into()), path).unwrap_err();
        assert!(err.to_string().contains("STICKSLIP_CHROMIUM"), "{err}");
        let err = locate_in(None, Some(OsString::new())).unwrap_err();
        assert!(err.to_string().starts_with("--pdf needs headless Chromium"));
    }

    #[test]
    fn a_browser_that_prints_nothing_is_an_error() {
        let dir = tempfile::tempdir().unwrap();
        let fake = executable(dir.path(), "fake-chromium");
        let err = print(&fake, "x.html", "<p>x</p>", 1).unwrap_err();
        assert!(matches!(err, Error::Pdf { .. }), "{err}");
        assert!(err.to_string().contains("no PDF written"), "{err}");
    }
}
