//! Helpers shared by the integration tests.
// Each test binary compiles this module and uses only some of it.
#![allow(dead_code)]

use std::path::{Path, PathBuf};

use assert_cmd::Command;
use stickslip::report::OutFile;

/// The first of the programs `names` on PATH (the browser tests' tools).
pub fn find(names: &[&str]) -> Option<PathBuf> {
    names.iter().find_map(|n| {
        let out = std::process::Command::new("which").arg(n).output().ok()?;
        out.status
            .success()
            .then(|| PathBuf::from(String::from_utf8_lossy(&out.stdout).trim()))
    })
}

/// The text of the rendered file `name` among `files`.
pub fn rendered<'a>(files: &'a [OutFile], name: &str) -> &'a str {
    let f = files
        .iter()
        .find(|f| f.path == Path::new(name))
        .unwrap_or_else(|| panic!("{name} rendered"));
    std::str::from_utf8(&f.bytes).unwrap()
}

/// Runs `cmd` with `--out` a fresh folder: it must be refused (exit 2, one line on stderr, no
/// panic, nothing on stdout) and write nothing. Returns stderr.
pub fn refused(mut cmd: Command) -> String {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("out");
    let output = cmd
        .arg("--out")
        .arg(&out)
        .assert()
        .code(2)
        .get_output()
        .clone();
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(output.stdout.is_empty(), "nothing printed: {stderr}");
    assert!(!out.exists(), "nothing written: {stderr}");
    stderr
}

/// Runs `cmd` with `--out` a folder below a plain file: it must exit 2 with one line
/// "error: cannot write …" and leave the file as it was. Returns stderr.
pub fn unwritable(mut cmd: Command) -> String {
    let tmp = tempfile::tempdir().unwrap();
    let blocker = tmp.path().join("a-file");
    std::fs::write(&blocker, b"x").unwrap();
    let output = cmd
        .arg("--out")
        .arg(blocker.join("sub"))
        .assert()
        .code(2)
        .get_output()
        .clone();
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    assert!(stderr.starts_with("error: cannot write"), "{stderr}");
    assert_eq!(std::fs::read(&blocker).unwrap(), b"x");
    stderr
}

/// The result of a worked line "… = 5.397 \times 10^{-4}\,\mathrm{W}" as LaTeX, without
/// its unit: "5.397 \times 10^{-4}".
pub fn result_tex(worked: &str) -> &str {
    let last = worked.rsplit("= ").next().unwrap_or_default();
    last.split(r"\,").next().unwrap_or_default().trim()
}

/// The network references in a page (`http:`, `//host`, `@import`, `url(`), XML namespace
/// names aside: those are identifiers, not resources. Empty for a self-contained page.
pub fn network_references(text: &str) -> Vec<&'static str> {
    let text = strip_namespaces(text);
    [
        "http:",
        "https:",
        "src=\"//",
        "href=\"//",
        "@import",
        "url(",
    ]
    .into_iter()
    .filter(|bad| text.contains(bad))
    .collect()
}

/// The text without `xmlns="…"` and `xmlns:prefix="…"` attributes.
fn strip_namespaces(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(i) = rest.find("xmlns") {
        out.push_str(&rest[..i]);
        let after = &rest[i..];
        let end = after
            .find('"')
            .and_then(|q| after[q + 1..].find('"').map(|e| q + 1 + e + 1))
            .unwrap_or(after.len());
        rest = &after[end..];
    }
    out.push_str(rest);
    out
}

/// Header and rows of a CSV file (no quoting in these files).
pub fn read_csv(path: &Path) -> (Vec<String>, Vec<Vec<String>>) {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut lines = text.lines();
    let header = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(String::from).collect())
        .collect();
    (header, rows)
}

/// Every kind of HTML page the tool writes, written by the binary into `dir`: the report
/// (scenes, index, lecture notes, explorer, handouts and worksheets with their answer keys in
/// English), the Italian worksheets and keys, a quick bench page and a `check` page. Returns the
/// pages' paths, sorted.
pub fn write_every_page(dir: &Path) -> Vec<PathBuf> {
    let runs: [&[&str]; 5] = [
        &["report", "--format", "html"],
        &[
            "worksheet",
            "--model",
            "pulled-mass",
            "--students",
            "2",
            "--lang",
            "it",
            "--format",
            "html",
        ],
        &[
            "worksheet",
            "--model",
            "woodpecker",
            "--students",
            "2",
            "--lang",
            "it",
            "--format",
            "html",
        ],
        &["bench", "--quick"],
        &[
            "check",
            "pulled-mass",
            "v_avg = g*T*phi^3*Gamma",
            "--samples",
            "20",
        ],
    ];
    for (i, args) in runs.iter().enumerate() {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_stickslip"))
            .args(*args)
            .arg("--out")
            .arg(dir.join(format!("run{i}")))
            .output()
            .unwrap();
        // `check` exits 3 when the formula disagrees somewhere: still a page.
        assert!(
            matches!(out.status.code(), Some(0 | 3)),
            "{args:?}: {out:?}"
        );
    }
    files(dir, &["html"])
}

/// Every text file below `dir` (recursively) whose name ends in one of `exts`.
pub fn files(dir: &Path, exts: &[&str]) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                stack.push(path);
            } else if exts
                .iter()
                .any(|e| path.extension().is_some_and(|x| x == *e))
            {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}
