//! The one place that writes report files: every file is written to a temporary file in its
//! folder and renamed into place, so a reader never sees a half-written page.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};

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

fn output_error(path: &Path, e: impl std::fmt::Display) -> Error {
    Error::Output {
        path: path.display().to_string(),
        reason: e.to_string(),
    }
}

/// Writes `files` under `out`, creating folders as needed; returns the paths written.
pub fn write_all(out: &Path, files: &[OutFile]) -> Result<Vec<PathBuf>> {
    fs::create_dir_all(out).map_err(|e| output_error(out, e))?;
    let mut written = Vec::with_capacity(files.len());
    for f in files {
        let path = out.join(&f.path);
        write_atomic(&path, &f.bytes)?;
        written.push(path);
    }
    Ok(written)
}

/// Writes `bytes` to `path` through a temporary file in the same folder and a rename.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    let dir = path.parent().unwrap_or(Path::new("."));
    fs::create_dir_all(dir).map_err(|e| output_error(dir, e))?;
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let tmp = dir.join(format!(".{name}.{}.tmp", std::process::id()));
    let result = fs::File::create(&tmp)
        .and_then(|mut f| f.write_all(bytes).and_then(|()| f.sync_all()))
        .and_then(|()| fs::rename(&tmp, path));
    if let Err(e) = result {
        let _ = fs::remove_file(&tmp);
        return Err(output_error(path, e));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_files_and_leaves_no_temporaries() {
        let dir = tempfile::tempdir().unwrap();
        let files = vec![
            OutFile {
                path: "a.html".into(),
                bytes: b"<p>a</p>".to_vec(),
            },
            OutFile {
                path: "figures/b.svg".into(),
                bytes: b"<svg/>".to_vec(),
            },
        ];
        write_all(dir.path(), &files).unwrap();
        assert_eq!(fs::read(dir.path().join("a.html")).unwrap(), b"<p>a</p>");
        assert!(dir.path().join("figures/b.svg").exists());
        let names: Vec<_> = fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert!(names.iter().all(|n| !n.to_string_lossy().ends_with(".tmp")));
    }

    #[test]
    fn an_unwritable_folder_is_an_error_not_a_panic() {
        let dir = tempfile::tempdir().unwrap();
        let blocker = dir.path().join("file");
        fs::write(&blocker, b"x").unwrap();
        let err = write_all(&blocker.join("sub"), &[]).unwrap_err();
        assert!(err.to_string().contains("cannot write"), "{err}");
    }
}
