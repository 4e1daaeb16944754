//! The one place that writes output files, all or nothing, also across a crash: every file is
//! first written (and synced) into a fresh staging folder inside the target folder, a journal
//! naming the files is committed with one rename, then the files are renamed into place. A run
//! that is killed leaves its staging folder behind; the next run that writes into the folder
//! finds it (under the folder's lock, so it is not another writer's) and finishes it (journal
//! committed: the new output) or removes it (no journal: the old output).
//!
//! ```text
//! lock      flock on <out> (report/lock.rs): a second writer is refused, exit 2
//! recover   every <out>/.stickslip-*/: journal → install the rest; rollback → undo; else remove
//! check     paths relative and distinct; no output is a folder, no folder of one is a file,
//!           nothing below <out> on the way to a target is a symbolic link
//! skip      a target that already holds exactly the new bytes is left alone (a regenerated
//!           report rewrites only what changed: no staging, sync, rename or old copy for it)
//! stage     <out>/.stickslip-XXXXXX/new/<path>   written, then synced at once (one syncfs on
//!           Linux, else each file)                                        (a full disk fails here)
//! commit    journal.tmp (paths, which existed, folders to make) synced, renamed to journal
//! install   per file: the old file kept as a hard link in old/<i>, rename(new/<path>, target)
//! undo      on error: a rollback marker, then the old files renamed back, the new ones removed
//! ```
//!
//! Between a crash and the next run the folder can hold old and new files; the next writer
//! completes or undoes the interrupted install before anything else. A link planted below
//! `--out` while a run installs (after its check) is a race this does not close.

use std::fs;
use std::io::{self, Write};
use std::path::{Component, Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::lock;
use crate::error::{Error, Result};
pub use crate::present::vocab::OutFile;

/// Prefix of the staging folder (hidden; removed before `write_all` returns, or by the next
/// run after a crash).
pub const STAGING_PREFIX: &str = ".stickslip-";
/// The committed journal, the rollback marker, and the staged and kept files in a staging
/// folder.
const JOURNAL: &str = "journal";
const ROLLBACK: &str = "rollback";
const NEW: &str = "new";
const OLD: &str = "old";

/// What an install does, written before its first rename.
#[derive(Debug, Serialize, Deserialize)]
struct Journal {
    /// Paths relative to the output folder, and whether each existed before.
    files: Vec<(String, bool)>,
    /// Folders (relative) that did not exist and are made for the files, outermost first.
    made: Vec<String>,
}

fn output_error(path: &Path, e: impl std::fmt::Display) -> Error {
    Error::Output {
        path: path.display().to_string(),
        reason: e.to_string(),
    }
}

/// Writes `files` under `out`, all or nothing, creating folders as needed; returns the paths
/// written. On error nothing under `out` has changed (and `out` itself is removed again if this
/// call created it); after a crash the next call finishes or undoes this one.
pub fn write_all(out: &Path, files: &[OutFile]) -> Result<Vec<PathBuf>> {
    write_all_with(out, files, &write_staged)
}

/// Finishes or removes what interrupted runs left in `out` (taking the folder's lock first).
pub fn recover(out: &Path) -> Result<()> {
    lock::claim(out)?;
    recover_all(out)
}

/// [`write_all`] with the function that writes one staged file (the tests inject failures).
fn write_all_with(
    out: &Path,
    files: &[OutFile],
    write: &dyn Fn(&Path, &[u8]) -> io::Result<()>,
) -> Result<Vec<PathBuf>> {
    check_paths(files)?;
    let mut made = MadeDirs::default();
    let result = made
        .create(out)
        .and_then(|()| lock::claim(out))
        .and_then(|()| recover_all(out))
        .and_then(|()| check_targets(out, files))
        .and_then(|()| changed(out, files))
        .and_then(|changed| match changed.is_empty() {
            true => Ok(()),
            false => stage_and_install(out, &changed, write),
        })
        .map(|()| files.iter().map(|f| out.join(&f.path)).collect());
    if result.is_err() {
        made.remove();
    }
    result
}

/// Output paths: relative, made of plain UTF-8 names, distinct, and none a folder of another.
fn check_paths(files: &[OutFile]) -> Result<()> {
    let mut seen: Vec<&Path> = Vec::with_capacity(files.len());
    for f in files {
        let plain = f
            .path
            .components()
            .all(|c| matches!(c, Component::Normal(_)));
        if !plain || f.path.as_os_str().is_empty() || f.path.to_str().is_none() {
            return Err(output_error(
                &f.path,
                "an output path must be relative, without . or ..",
            ));
        }
        seen.push(&f.path);
    }
    seen.sort();
    for pair in seen.windows(2) {
        if pair[0] == pair[1] {
            return Err(output_error(pair[0], "two outputs have this path"));
        }
        if pair[1].starts_with(pair[0]) {
            return Err(output_error(
                pair[0],
                format!("is an output file and the folder of {}", pair[1].display()),
            ));
        }
    }
    Ok(())
}

/// What is at `path`, without following a link: `None` when nothing is.
fn entry(path: &Path) -> Result<Option<fs::Metadata>> {
    match fs::symlink_metadata(path) {
        Ok(m) => Ok(Some(m)),
        Err(e) if e.kind() == io::ErrorKind::NotFound => Ok(None),
        Err(e) => Err(output_error(path, e)),
    }
}

fn refuse_link(path: &Path) -> Error {
    output_error(
        path,
        "is a symbolic link; stickslip writes nothing through a link below the output folder",
    )
}

/// Every folder below `out` on the way to `rel` (outermost first), and the target itself, is a
/// real folder (resp. not a folder) or absent; never a symbolic link.
fn check_target(out: &Path, rel: &Path) -> Result<()> {
    let target = out.join(rel);
    let mut dirs: Vec<&Path> = rel.ancestors().skip(1).collect();
    dirs.pop(); // the empty path: `out` itself, which the user chose (a link there is fine)
    for d in dirs.into_iter().rev() {
        let folder = out.join(d);
        match entry(&folder)? {
            Some(m) if m.file_type().is_symlink() => return Err(refuse_link(&folder)),
            Some(m) if !m.is_dir() => {
                return Err(output_error(
                    &target,
                    format!("{} is a file, not a folder", folder.display()),
                ))
            }
            Some(_) => {}
            None => return Ok(()),
        }
    }
    match entry(&target)? {
        Some(m) if m.file_type().is_symlink() => Err(refuse_link(&target)),
        Some(m) if m.is_dir() => Err(output_error(&target, "is a folder, not a file")),
        _ => Ok(()),
    }
}

/// Before anything is written: [`check_target`] for every file.
fn check_targets(out: &Path, files: &[OutFile]) -> Result<()> {
    files.iter().try_for_each(|f| check_target(out, &f.path))
}

/// The files whose target does not already hold exactly their bytes (after
/// [`check_targets`]: a target is a regular file or absent).
fn changed<'a>(out: &Path, files: &'a [OutFile]) -> Result<Vec<&'a OutFile>> {
    let mut changed = Vec::with_capacity(files.len());
    for f in files {
        let target = out.join(&f.path);
        let same = match entry(&target)? {
            Some(m) if m.is_file() && m.len() == f.bytes.len() as u64 => {
                fs::read(&target).map_err(|e| output_error(&target, e))? == f.bytes
            }
            _ => false,
        };
        if !same {
            changed.push(f);
        }
    }
    Ok(changed)
}

fn stage_and_install(
    out: &Path,
    files: &[&OutFile],
    write: &dyn Fn(&Path, &[u8]) -> io::Result<()>,
) -> Result<()> {
    let staging = tempfile::Builder::new()
        .prefix(STAGING_PREFIX)
        .rand_bytes(6)
        .tempdir_in(out)
        .map_err(|e| output_error(out, e))?;
    let root = staging.path();
    let mut folders: Vec<&Path> = Vec::new();
    for f in files {
        let path = root.join(NEW).join(&f.path);
        // Each staging folder made once (the files of a folder are mostly consecutive).
        let folder = f.path.parent().unwrap_or(Path::new(""));
        if !folders.contains(&folder) {
            fs::create_dir_all(root.join(NEW).join(folder))
                .map_err(|e| output_error(&out.join(&f.path), e))?;
            folders.push(folder);
        }
        write(&path, &f.bytes).map_err(|e| output_error(&out.join(&f.path), e))?;
    }
    // Every staged file on disk before the journal names it.
    sync_staged(root).map_err(|e| output_error(out, e))?;
    fs::create_dir(root.join(OLD)).map_err(|e| output_error(out, e))?;
    let journal = plan(out, files)?;
    commit(root, &journal).map_err(|e| output_error(out, e))?;
    if let Err(e) = install(out, root, &journal, true) {
        // The marker first: a crash during the undo is undone by the next run, not finished.
        let _ = fs::write(root.join(ROLLBACK), b"").and_then(|()| sync_dir(root));
        rollback(out, root, &journal);
        return Err(e);
    }
    sync_parents(out, &journal);
    staging.close().map_err(|e| output_error(out, e))
}

/// The journal of installing `files` into `out` as it is now.
fn plan(out: &Path, files: &[&OutFile]) -> Result<Journal> {
    let mut made: Vec<String> = Vec::new();
    let mut entries = Vec::with_capacity(files.len());
    for f in files {
        let mut dirs: Vec<&Path> = f.path.ancestors().skip(1).collect();
        dirs.pop();
        for d in dirs.into_iter().rev() {
            let name = d.to_string_lossy().into_owned();
            if entry(&out.join(d))?.is_none() && !made.contains(&name) {
                made.push(name);
            }
        }
        let existed = entry(&out.join(&f.path))?.is_some();
        entries.push((f.path.to_string_lossy().into_owned(), existed));
    }
    Ok(Journal {
        files: entries,
        made,
    })
}

/// Writes the journal and commits it with one rename.
fn commit(root: &Path, journal: &Journal) -> io::Result<()> {
    let tmp = root.join("journal.tmp");
    write_synced(&tmp, &serde_json::to_vec(journal)?)?;
    fs::rename(&tmp, root.join(JOURNAL))?;
    sync_dir(root)
}

/// Fault injection for the crash tests (tests/faults.rs): with this variable set to n, the
/// process aborts (no unwinding, no cleanup, like `kill -9`) after the n-th rename of an
/// install; unset, nothing happens.
const CRASH_ENV: &str = "STICKSLIP_CRASH_AFTER_RENAMES";

fn crash_point(renamed: usize) {
    if let Some(n) = std::env::var_os(CRASH_ENV) {
        if n.to_str().and_then(|n| n.parse::<usize>().ok()) == Some(renamed) {
            std::process::abort();
        }
    }
}

/// Renames every staged file of `journal` still in `root` into place (idempotent: a file
/// already installed has left `new/`). `keep` keeps each replaced file in `old/` for an undo.
fn install(out: &Path, root: &Path, journal: &Journal, keep: bool) -> Result<()> {
    crash_point(0);
    // The folders of the targets made (or found) so far, each once.
    let mut folders: Vec<&Path> = Vec::new();
    for (i, (rel, _)) in journal.files.iter().enumerate() {
        let staged = root.join(NEW).join(rel);
        if entry(&staged)?.is_none() {
            continue;
        }
        let rel = Path::new(rel);
        let target = out.join(rel);
        check_target(out, rel)?;
        let folder = rel.parent().unwrap_or(Path::new(""));
        if !folders.contains(&folder) {
            let dir = out.join(folder);
            fs::create_dir_all(&dir).map_err(|e| output_error(&dir, e))?;
            // The folders just made are real: check again that no link took their place.
            check_target(out, rel)?;
            folders.push(folder);
        }
        if keep && entry(&target)?.is_some() {
            // A hard link keeps the old file without moving it: the target never disappears.
            let kept = root.join(OLD).join(i.to_string());
            fs::hard_link(&target, &kept)
                .or_else(|_| fs::copy(&target, &kept).map(|_| ()))
                .map_err(|e| output_error(&target, e))?;
        }
        fs::rename(&staged, &target).map_err(|e| output_error(&target, e))?;
        crash_point(i + 1);
    }
    Ok(())
}

/// Undoes an install (idempotent): the kept old files renamed back, the new files that
/// replaced nothing removed, the folders made for them removed when empty.
fn rollback(out: &Path, root: &Path, journal: &Journal) {
    for (i, (rel, existed)) in journal.files.iter().enumerate().rev() {
        let target = out.join(rel);
        if *existed {
            let kept = root.join(OLD).join(i.to_string());
            if kept.exists() {
                let _ = fs::rename(&kept, &target);
            }
        } else if !root.join(NEW).join(rel).exists() {
            // Installed (it has left new/): a file of this run, not the user's.
            if matches!(fs::symlink_metadata(&target), Ok(m) if m.is_file()) {
                let _ = fs::remove_file(&target);
            }
        }
    }
    for d in journal.made.iter().rev() {
        let _ = fs::remove_dir(out.join(d));
    }
}

/// Finishes or removes every staging folder in `out` (the caller holds the lock, so none is
/// another writer's).
fn recover_all(out: &Path) -> Result<()> {
    let entries = fs::read_dir(out).map_err(|e| output_error(out, e))?;
    for e in entries {
        let e = e.map_err(|e| output_error(out, e))?;
        let name = e.file_name();
        // `.stickslip-` and the six random letters of tempfile: no other folder is touched.
        let is_staging = name.to_str().is_some_and(|n| {
            n.strip_prefix(STAGING_PREFIX)
                .is_some_and(|r| r.len() == 6 && r.bytes().all(|b| b.is_ascii_alphanumeric()))
        }) && e.file_type().is_ok_and(|t| t.is_dir());
        if is_staging {
            recover_one(out, &e.path())?;
        }
    }
    Ok(())
}

/// One staging folder left by a crash: committed → installed, rolling back → undone, else
/// (still staging) removed.
fn recover_one(out: &Path, root: &Path) -> Result<()> {
    let journal = match fs::read(root.join(JOURNAL)) {
        Ok(bytes) => serde_json::from_slice::<Journal>(&bytes).ok(),
        Err(_) => None,
    };
    if let Some(journal) = journal.filter(|j| j.files.iter().all(|(p, _)| safe_rel(p))) {
        if root.join(ROLLBACK).exists() {
            rollback(out, root, &journal);
        } else {
            install(out, root, &journal, false)?;
            sync_parents(out, &journal);
        }
    }
    fs::remove_dir_all(root).map_err(|e| output_error(root, e))
}

/// A journal path is relative and plain (the journal is ours, but it is read from disk).
fn safe_rel(p: &str) -> bool {
    let p = Path::new(p);
    !p.as_os_str().is_empty() && p.components().all(|c| matches!(c, Component::Normal(_)))
}

/// Syncs the folders that received files (a crash of the machine keeps the renames).
fn sync_parents(out: &Path, journal: &Journal) {
    let mut dirs: Vec<PathBuf> = journal
        .files
        .iter()
        .filter_map(|(rel, _)| out.join(rel).parent().map(Path::to_path_buf))
        .collect();
    dirs.sort();
    dirs.dedup();
    for d in dirs {
        let _ = sync_dir(&d);
    }
}

fn sync_dir(dir: &Path) -> io::Result<()> {
    fs::File::open(dir)?.sync_all()
}

/// Folders this call created, to remove again (if empty) when it fails.
#[derive(Default)]
struct MadeDirs(Vec<PathBuf>);

impl MadeDirs {
    /// Creates `dir` and its missing ancestors, recording each one made.
    fn create(&mut self, dir: &Path) -> Result<()> {
        if dir.as_os_str().is_empty() || dir.is_dir() {
            return Ok(());
        }
        if let Some(parent) = dir.parent() {
            self.create(parent)?;
        }
        match fs::create_dir(dir) {
            Ok(()) => {
                self.0.push(dir.to_path_buf());
                Ok(())
            }
            Err(_) if dir.is_dir() => Ok(()),
            Err(e) => {
                let reason = match dir.exists() {
                    true => "is a file, not a folder".to_string(),
                    false => e.to_string(),
                };
                Err(output_error(dir, reason))
            }
        }
    }

    /// Removes the recorded folders, deepest first; a folder that is not empty stays.
    fn remove(&self) {
        for dir in self.0.iter().rev() {
            let _ = fs::remove_dir(dir);
        }
    }
}

/// Writes `bytes` to a new staged file at `path`: synced with the others by [`sync_staged`] on
/// Linux (one call for an output of hundreds of files), on its own elsewhere.
fn write_staged(path: &Path, bytes: &[u8]) -> io::Result<()> {
    if cfg!(target_os = "linux") {
        fs::write(path, bytes)
    } else {
        write_synced(path, bytes)
    }
}

/// Syncs the file system that holds the staging folder `root` (Linux: `syncfs`, which waits
/// for every file written to it); elsewhere [`write_staged`] has synced each file.
fn sync_staged(root: &Path) -> io::Result<()> {
    #[cfg(target_os = "linux")]
    {
        use std::os::fd::AsRawFd;
        let dir = fs::File::open(root)?;
        // SAFETY: syncfs takes an open descriptor, which `dir` holds for the call.
        if unsafe { libc::syncfs(dir.as_raw_fd()) } != 0 {
            return Err(io::Error::last_os_error());
        }
    }
    #[cfg(not(target_os = "linux"))]
    let _ = root;
    Ok(())
}

/// Writes `bytes` to a new file at `path` and syncs it to disk.
fn write_synced(path: &Path, bytes: &[u8]) -> io::Result<()> {
    let mut f = fs::File::create(path)?;
    f.write_all(bytes)?;
    f.sync_all()
}

#[cfg(test)]
mod tests {
    use std::cell::Cell;

    use super::*;

    fn files(names: &[&str]) -> Vec<OutFile> {
        names
            .iter()
            .map(|n| OutFile::new(*n, format!("new {n}")))
            .collect()
    }

    /// Every file under `dir` (relative path, contents), sorted.
    fn tree(dir: &Path) -> Vec<(String, String)> {
        fn walk(root: &Path, dir: &Path, out: &mut Vec<(String, String)>) {
            for e in fs::read_dir(dir).unwrap() {
                let p = e.unwrap().path();
                let rel = p.strip_prefix(root).unwrap().display().to_string();
                if p.is_dir() {
                    out.push((rel + "/", String::new()));
                    walk(root, &p, out);
                } else {
                    out.push((rel, fs::read_to_string(&p).unwrap_or_default()));
                }
            }
        }
        let mut out = Vec::new();
        if dir.exists() {
            walk(dir, dir, &mut out);
        }
        out.sort();
        out
    }

    #[test]
    fn writes_files_and_leaves_no_temporaries() {
        let dir = tempfile::tempdir().unwrap();
        let written = write_all(dir.path(), &files(&["a.html", "figures/b.svg"])).unwrap();
        assert_eq!(written.len(), 2);
        assert_eq!(
            tree(dir.path()),
            [
                ("a.html".to_string(), "new a.html".to_string()),
                ("figures/".to_string(), String::new()),
                ("figures/b.svg".to_string(), "new figures/b.svg".to_string()),
            ]
        );
    }

    #[test]
    fn an_unwritable_folder_is_an_error_not_a_panic() {
        let dir = tempfile::tempdir().unwrap();
        let blocker = dir.path().join("file");
        fs::write(&blocker, b"x").unwrap();
        let err = write_all(&blocker.join("sub"), &[]).unwrap_err();
        assert!(err.to_string().contains("cannot write"), "{err}");
        assert_eq!(fs::read(&blocker).unwrap(), b"x");
    }

    #[test]
    fn a_file_where_a_folder_is_needed_stops_everything_before_a_write() {
        let dir = tempfile::tempdir().unwrap();
        fs::write(dir.path().join("figures"), b"in the way").unwrap();
        fs::write(dir.path().join("a.html"), b"old").unwrap();
        let before = tree(dir.path());
        let err = write_all(
            dir.path(),
            &files(&["a.html", "b.html", "figures/c.svg", "z.md"]),
        )
        .unwrap_err();
        let msg = err.to_string();
        assert!(msg.contains("figures is a file, not a folder"), "{msg}");
        assert_eq!(tree(dir.path()), before);
    }

    #[test]
    fn a_failed_write_such_as_a_full_disk_changes_nothing() {
        for fail_at in 0..4 {
            let dir = tempfile::tempdir().unwrap();
            let out = dir.path().join("new/out");
            fs::create_dir_all(dir.path().join("old")).unwrap();
            fs::write(dir.path().join("old/index.html"), b"old index").unwrap();
            let calls = Cell::new(0);
            let full = |path: &Path, bytes: &[u8]| {
                calls.set(calls.get() + 1);
                if calls.get() > fail_at {
                    return Err(io::Error::new(io::ErrorKind::StorageFull, "disk full"));
                }
                write_synced(path, bytes)
            };
            let names = files(&["index.html", "a.html", "figures/a.svg", "a.md"]);
            // A fresh target: nothing is left, not even the folders made for it.
            let err = write_all_with(&out, &names, &full).unwrap_err();
            assert!(err.to_string().contains("disk full"), "{err}");
            assert!(!dir.path().join("new").exists(), "{fail_at}");
            // An existing target keeps exactly its files.
            calls.set(0);
            let old = dir.path().join("old");
            let before = tree(&old);
            assert!(write_all_with(&old, &names, &full).is_err());
            assert_eq!(tree(&old), before, "{fail_at}");
        }
    }

    #[test]
    fn a_failed_install_puts_the_previous_files_back() {
        let dir = tempfile::tempdir().unwrap();
        fs::write(dir.path().join("a.html"), b"old a").unwrap();
        fs::write(dir.path().join("b.html"), b"old b").unwrap();
        let before = tree(dir.path());
        let names = files(&["a.html", "b.html", "c.html"]);
        // The target folder is checked first, so make the last rename fail with a folder that
        // appears between the staging and the install.
        let out = dir.path().to_path_buf();
        let sneaky = |path: &Path, bytes: &[u8]| {
            if path.ends_with("c.html") {
                fs::create_dir(out.join("c.html"))?;
                fs::write(out.join("c.html/x"), b"x")?;
            }
            write_synced(path, bytes)
        };
        assert!(write_all_with(dir.path(), &names, &sneaky).is_err());
        fs::remove_dir_all(dir.path().join("c.html")).unwrap();
        assert_eq!(tree(dir.path()), before);
    }

    #[test]
    fn overwriting_replaces_old_files_and_keeps_others() {
        let dir = tempfile::tempdir().unwrap();
        fs::write(dir.path().join("a.html"), b"old a").unwrap();
        fs::write(dir.path().join("keep.txt"), b"mine").unwrap();
        write_all(dir.path(), &files(&["a.html"])).unwrap();
        assert_eq!(
            tree(dir.path()),
            [
                ("a.html".to_string(), "new a.html".to_string()),
                ("keep.txt".to_string(), "mine".to_string()),
            ]
        );
    }

    /// A target that already holds the new bytes is left as it is (the same file, not a copy);
    /// one of the same length but other bytes, and one of another length, are replaced.
    #[test]
    fn only_changed_files_are_rewritten() {
        use std::os::unix::fs::MetadataExt;
        let dir = tempfile::tempdir().unwrap();
        let names = ["same.html", "sub/same.svg", "other.html", "longer.html"];
        write_all(dir.path(), &files(&names)).unwrap();
        fs::write(dir.path().join("other.html"), b"old other.html").unwrap();
        fs::write(dir.path().join("longer.html"), b"old").unwrap();
        let inode = |n: &str| fs::metadata(dir.path().join(n)).unwrap().ino();
        let before: Vec<u64> = names.iter().map(|n| inode(n)).collect();
        let written = write_all(dir.path(), &files(&names)).unwrap();
        assert_eq!(written.len(), names.len());
        let after: Vec<u64> = names.iter().map(|n| inode(n)).collect();
        assert_eq!(after[..2], before[..2]);
        assert_ne!(after[2], before[2]);
        assert_ne!(after[3], before[3]);
        assert_eq!(tree(dir.path()).len(), names.len() + 1);
        for n in names {
            assert_eq!(
                fs::read_to_string(dir.path().join(n)).unwrap(),
                format!("new {n}")
            );
        }
    }

    #[test]
    fn paths_that_leave_the_folder_or_collide_are_refused() {
        let dir = tempfile::tempdir().unwrap();
        for bad in [
            files(&["../x.html"]),
            files(&["/etc/x"]),
            files(&["a.html", "a.html"]),
            files(&["a", "a/b.svg"]),
        ] {
            let err = write_all(dir.path(), &bad).unwrap_err();
            assert!(err.to_string().starts_with("cannot write"), "{err}");
        }
        assert!(tree(dir.path()).is_empty());
    }

    /// A staging folder as a crash leaves it: `new/` with the files not yet installed, the
    /// journal when committed, the rollback marker when undoing.
    fn crashed(out: &Path, journal: Option<&Journal>, staged: &[&str], rollback: bool) -> PathBuf {
        let root = out.join(format!("{STAGING_PREFIX}crash0"));
        fs::create_dir_all(root.join(NEW)).unwrap();
        fs::create_dir_all(root.join(OLD)).unwrap();
        for name in staged {
            fs::write(root.join(NEW).join(name), format!("new {name}")).unwrap();
        }
        if let Some(j) = journal {
            fs::write(root.join(JOURNAL), serde_json::to_vec(j).unwrap()).unwrap();
        }
        if rollback {
            fs::write(root.join(ROLLBACK), b"").unwrap();
        }
        root
    }

    fn journal(names: &[(&str, bool)]) -> Journal {
        Journal {
            files: names.iter().map(|(n, e)| (n.to_string(), *e)).collect(),
            made: Vec::new(),
        }
    }

    #[test]
    fn a_committed_install_cut_short_is_finished_by_the_next_run() {
        let dir = tempfile::tempdir().unwrap();
        // a.html was installed before the crash, b.html and c.html were not.
        fs::write(dir.path().join("a.html"), b"new a.html").unwrap();
        fs::write(dir.path().join("b.html"), b"old b").unwrap();
        fs::write(dir.path().join("mine.txt"), b"mine").unwrap();
        let j = journal(&[("a.html", true), ("b.html", true), ("c.html", false)]);
        crashed(dir.path(), Some(&j), &["b.html", "c.html"], false);
        write_all(dir.path(), &files(&["d.html"])).unwrap();
        assert_eq!(
            tree(dir.path()),
            [
                ("a.html".to_string(), "new a.html".to_string()),
                ("b.html".to_string(), "new b.html".to_string()),
                ("c.html".to_string(), "new c.html".to_string()),
                ("d.html".to_string(), "new d.html".to_string()),
                ("mine.txt".to_string(), "mine".to_string()),
            ]
        );
    }

    #[test]
    fn an_uncommitted_staging_folder_is_removed_and_an_undo_is_finished() {
        let dir = tempfile::tempdir().unwrap();
        fs::write(dir.path().join("a.html"), b"old a").unwrap();
        crashed(dir.path(), None, &["a.html"], false);
        recover(dir.path()).unwrap();
        assert_eq!(
            tree(dir.path()),
            [("a.html".to_string(), "old a".to_string())]
        );
        // An undo cut short: a.html was restored already, b.html (new) is still installed.
        fs::write(dir.path().join("b.html"), b"new b.html").unwrap();
        let j = journal(&[("a.html", true), ("b.html", false)]);
        crashed(dir.path(), Some(&j), &[], true);
        recover(dir.path()).unwrap();
        assert_eq!(
            tree(dir.path()),
            [("a.html".to_string(), "old a".to_string())]
        );
    }

    #[cfg(unix)]
    #[test]
    fn nothing_is_written_through_a_link_below_the_folder() {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("out");
        let outside = dir.path().join("outside");
        fs::create_dir_all(&out).unwrap();
        fs::create_dir_all(&outside).unwrap();
        std::os::unix::fs::symlink("../outside", out.join("figures")).unwrap();
        let err = write_all(&out, &files(&["a.html", "figures/b.svg"])).unwrap_err();
        assert!(err.to_string().contains("symbolic link"), "{err}");
        assert!(tree(&outside).is_empty());
        assert!(!out.join("a.html").exists());
    }
}
