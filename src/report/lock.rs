//! One writer per output folder: an advisory lock (`flock`) on the folder itself, held by the
//! process from the moment it claims the folder until it exits (the kernel releases it when the
//! process ends, however it ends, so a crashed writer never blocks the next run).
//!
//! ```text
//! claim(out)   open(out, O_RDONLY | O_DIRECTORY), flock(LOCK_EX | LOCK_NB)
//!              taken  → kept for the life of the process (claiming again is a no-op)
//!              busy   → Error::Output "another stickslip is writing into this folder" (exit 2)
//! ```
//!
//! No lock file is left in the folder (`--out` may be a committed folder such as `reports/`).
//! File systems without `flock` (some network mounts) write without the lock.

use std::fs;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use crate::error::{Error, Result};

/// Folders this process holds, by canonical path, with the open folder that carries the lock.
static HELD: Mutex<Vec<(PathBuf, fs::File)>> = Mutex::new(Vec::new());

/// Claims `out` (an existing folder) for this process, or refuses when another process holds it.
pub fn claim(out: &Path) -> Result<()> {
    let fail = |reason: String| Error::Output {
        path: out.display().to_string(),
        reason,
    };
    let key = fs::canonicalize(out).map_err(|e| fail(e.to_string()))?;
    let mut held = HELD.lock().unwrap_or_else(|e| e.into_inner());
    if held.iter().any(|(p, _)| *p == key) {
        return Ok(());
    }
    let dir = fs::File::open(&key).map_err(|e| fail(e.to_string()))?;
    match try_lock(&dir) {
        Ok(true) => {}
        Ok(false) => {
            return Err(fail(
                "another stickslip is writing into this folder; wait for it to finish".to_string(),
            ))
        }
        // No advisory locks on this file system: nothing to hold.
        Err(_) => return Ok(()),
    }
    held.push((key, dir));
    Ok(())
}

/// Claims `out` when it exists already (a command claims its folder before its work, so a
/// second writer is refused at once, not after minutes of rendering).
pub fn claim_if_exists(out: &Path) -> Result<()> {
    match fs::metadata(out) {
        Ok(m) if m.is_dir() => claim(out),
        _ => Ok(()),
    }
}

/// `Ok(true)` when the lock was taken, `Ok(false)` when another process holds it.
#[cfg(unix)]
fn try_lock(file: &fs::File) -> std::io::Result<bool> {
    use std::os::fd::AsRawFd;
    // SAFETY: flock on a file descriptor owned by `file`, which outlives the call.
    let rc = unsafe { libc::flock(file.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) };
    if rc == 0 {
        return Ok(true);
    }
    let e = std::io::Error::last_os_error();
    match e.raw_os_error() {
        Some(libc::EWOULDBLOCK) => Ok(false),
        _ => Err(e),
    }
}

#[cfg(not(unix))]
fn try_lock(_file: &fs::File) -> std::io::Result<bool> {
    Err(std::io::Error::from(std::io::ErrorKind::Unsupported))
}

/// Whether another process holds the lock on `dir` (for the stale temporary folders of
/// `--pdf`): takes and keeps the lock when it is free.
pub fn is_busy(dir: &fs::File) -> bool {
    matches!(try_lock(dir), Ok(false))
}

/// Takes the lock on an open folder for as long as `dir` stays open (a `--pdf` work folder).
pub fn hold(dir: &fs::File) {
    let _ = try_lock(dir);
}
