//! The one place that writes output files, all or nothing: every file is first written (and
//! synced) into a fresh staging folder inside the target folder, then renamed into place; an
//! error at any point puts back what was there before, removes what was added (files and the
//! folders made for them) and leaves the target as it was.
//!
//! ```text
//! check     paths relative and distinct; no output is a folder, no folder of one is a file
//! stage     <out>/.stickslip-XXXXXX/<path>   written and synced    (a full disk fails here)
//! install   per file: the old file kept as a hard link (or copy) in the staging folder,
//!           then rename(staged, target)       (atomic: a reader sees the old or the new file)
//! undo      on error: the installed files are taken back and the old ones renamed back
//! ```

use std::fs;
use std::io::{self, Write};
use std::path::{Component, Path, PathBuf};

use crate::error::{Error, Result};

/// A rendered output file: a path relative to the output folder, and its bytes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OutFile {
    pub path: PathBuf,
    pub bytes: Vec<u8>,
}

impl OutFile {
    pub fn new(path: impl Into<PathBuf>, bytes: impl Into<Vec<u8>>) -> Self {
        OutFile {
            path: path.into(),
            bytes: bytes.into(),
        }
    }
}

/// Prefix of the staging folder (hidden; removed before `write_all` returns).
const STAGING_PREFIX: &str = ".stickslip-";

fn output_error(path: &Path, e: impl std::fmt::Display) -> Error {
    Error::Output {
        path: path.display().to_string(),
        reason: e.to_string(),
    }
}

/// Writes `files` under `out`, all or nothing, creating folders as needed; returns the paths
/// written. On error nothing under `out` has changed (and `out` itself is removed again if this
/// call created it).
pub fn write_all(out: &Path, files: &[OutFile]) -> Result<Vec<PathBuf>> {
    write_all_with(out, files, &write_synced)
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
        .and_then(|()| check_targets(out, files))
        .and_then(|()| stage_and_install(out, files, write, &mut made));
    if result.is_err() {
        made.remove();
    }
    result
}

/// Output paths: relative, made of plain names, distinct, and none a folder of another.
fn check_paths(files: &[OutFile]) -> Result<()> {
    let mut seen: Vec<&Path> = Vec::with_capacity(files.len());
    for f in files {
        let plain = f
            .path
            .components()
            .all(|c| matches!(c, Component::Normal(_)));
        if !plain || f.path.as_os_str().is_empty() {
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

/// Before anything is written: no target is a folder, and every folder a target needs is a
/// folder (or does not exist yet).
fn check_targets(out: &Path, files: &[OutFile]) -> Result<()> {
    for f in files {
        let target = out.join(&f.path);
        if target.is_dir() {
            return Err(output_error(&target, "is a folder, not a file"));
        }
        let mut dir = f.path.parent();
        while let Some(d) = dir.filter(|d| !d.as_os_str().is_empty()) {
            let folder = out.join(d);
            if folder.exists() && !folder.is_dir() {
                return Err(output_error(
                    &target,
                    format!("{} is a file, not a folder", folder.display()),
                ));
            }
            dir = d.parent();
        }
    }
    Ok(())
}

/// One installed file: where it went, and where its previous version is kept.
struct Installed {
    target: PathBuf,
    previous: Option<PathBuf>,
}

fn stage_and_install(
    out: &Path,
    files: &[OutFile],
    write: &dyn Fn(&Path, &[u8]) -> io::Result<()>,
    made: &mut MadeDirs,
) -> Result<Vec<PathBuf>> {
    let staging = tempfile::Builder::new()
        .prefix(STAGING_PREFIX)
        .tempdir_in(out)
        .map_err(|e| output_error(out, e))?;
    let root = staging.path();
    for f in files {
        let path = root.join(&f.path);
        if let Some(dir) = path.parent() {
            fs::create_dir_all(dir).map_err(|e| output_error(&out.join(&f.path), e))?;
        }
        write(&path, &f.bytes).map_err(|e| output_error(&out.join(&f.path), e))?;
    }
    let keep = root.join(".previous");
    fs::create_dir(&keep).map_err(|e| output_error(out, e))?;
    let mut installed: Vec<Installed> = Vec::with_capacity(files.len());
    for (i, f) in files.iter().enumerate() {
        let target = out.join(&f.path);
        match install(
            &root.join(&f.path),
            &target,
            &keep.join(i.to_string()),
            made,
        ) {
            Ok(previous) => installed.push(Installed { target, previous }),
            Err(e) => {
                undo(&installed);
                return Err(e);
            }
        }
    }
    // The staging folder (and the previous versions) goes when `staging` drops.
    Ok(installed.into_iter().map(|i| i.target).collect())
}

/// Moves `staged` to `target`, keeping the file it replaces at `keep`; returns that path.
fn install(
    staged: &Path,
    target: &Path,
    keep: &Path,
    made: &mut MadeDirs,
) -> Result<Option<PathBuf>> {
    if let Some(dir) = target.parent() {
        made.create(dir)?;
    }
    let previous = match fs::symlink_metadata(target) {
        Ok(_) => {
            // A hard link keeps the old file without moving it: the target never disappears.
            fs::hard_link(target, keep)
                .or_else(|_| fs::copy(target, keep).map(|_| ()))
                .map_err(|e| output_error(target, e))?;
            Some(keep.to_path_buf())
        }
        Err(e) if e.kind() == io::ErrorKind::NotFound => None,
        Err(e) => return Err(output_error(target, e)),
    };
    if let Err(e) = fs::rename(staged, target) {
        if let Some(p) = &previous {
            let _ = fs::remove_file(p);
        }
        return Err(output_error(target, e));
    }
    Ok(previous)
}

/// Takes back installed files, newest first: the previous version renamed back, or the new
/// file removed.
fn undo(installed: &[Installed]) {
    for i in installed.iter().rev() {
        match &i.previous {
            Some(p) => {
                let _ = fs::rename(p, &i.target);
            }
            None => {
                let _ = fs::remove_file(&i.target);
            }
        }
    }
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
}
