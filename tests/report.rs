//! The report: Markdown snapshots, structure of the pages, determinism, and the `report`
//! command's handling of user scenarios and bad input.

mod common;

use std::path::Path;

use assert_cmd::Command;
use stickslip::report::{builtin_scenes, render, Format, OutFile};

use common::rendered;

fn default_report() -> Vec<OutFile> {
    render(&builtin_scenes().unwrap(), &[Format::Html, Format::Md]).unwrap()
}

#[test]
fn markdown_pages_match_their_snapshots() {
    let files = default_report();
    insta::assert_snapshot!("index_md", rendered(&files, "index.md"));
    insta::assert_snapshot!("fig10_md", rendered(&files, "fig10-linear-slip-stick.md"));
    insta::assert_snapshot!("fig15_md", rendered(&files, "fig15-double-slip-stick.md"));
}

#[test]
fn markdown_tables_have_as_many_cells_as_their_header() {
    for f in default_report()
        .iter()
        .filter(|f| f.path.extension().is_some_and(|e| e == "md"))
    {
        let text = std::str::from_utf8(&f.bytes).unwrap();
        let mut header_cells = None;
        for line in text.lines() {
            if !line.starts_with('|') {
                header_cells = None;
                continue;
            }
            // Cells are separated by unescaped pipes ("\|" is a pipe inside a cell).
            let unescaped = line.trim().replace("\\|", "");
            let cells = unescaped.trim_matches('|').split('|').count();
            match header_cells {
                None => header_cells = Some(cells),
                Some(n) => assert_eq!(cells, n, "{}: {line}", f.path.display()),
            }
        }
    }
}

#[test]
fn html_pages_are_self_contained_and_every_figure_is_inline() {
    let files = default_report();
    for f in files
        .iter()
        .filter(|f| f.path.extension().is_some_and(|e| e == "html"))
    {
        let text = std::str::from_utf8(&f.bytes).unwrap();
        assert!(text.contains("<style>"), "{}", f.path.display());
        for bad in ["<script", "<link", "<img"] {
            assert!(!text.contains(bad), "{}: {bad}", f.path.display());
        }
    }
    let page = rendered(&files, "fig09-domain.html");
    assert_eq!(page.matches("<svg").count(), 2, "two regime maps inline");
    assert!(page.contains("<math"), "MathML formulas");
    // Every Markdown figure link has its SVG file.
    for f in files
        .iter()
        .filter(|f| f.path.extension().is_some_and(|e| e == "md"))
    {
        let text = std::str::from_utf8(&f.bytes).unwrap();
        for link in text.split("](figures/").skip(1) {
            let name = format!("figures/{}", &link[..link.find(')').unwrap()]);
            assert!(files.iter().any(|g| g.path == Path::new(&name)), "{name}");
        }
    }
}

#[test]
fn the_report_is_deterministic() {
    assert_eq!(default_report(), default_report());
}

#[test]
fn every_default_scene_passes_all_its_checks() {
    let files = default_report();
    let index = rendered(&files, "index.md");
    let summary = index
        .split("Checks passed in all scenes: **")
        .nth(1)
        .and_then(|s| s.split("**").next())
        .unwrap();
    let (passed, total) = summary.split_once(" / ").unwrap();
    assert_eq!(passed, total, "{summary}");
    assert!(total.parse::<usize>().unwrap() > 200, "{summary}");
}

fn stickslip() -> Command {
    Command::cargo_bin("stickslip").unwrap()
}

#[test]
fn a_user_scenario_becomes_a_scene() {
    let dir = tempfile::tempdir().unwrap();
    stickslip()
        .args([
            "report",
            "scenarios/set-c-late-stick.toml",
            "--format",
            "md",
            "--out",
        ])
        .arg(dir.path())
        .assert()
        .success();
    let md = std::fs::read_to_string(dir.path().join("set-c-late-stick.md")).unwrap();
    assert!(md.contains("slip_stick_late"));
    assert!(dir
        .path()
        .join("figures/set-c-late-stick-motion.svg")
        .exists());
    assert!(
        !dir.path().join("index.html").exists(),
        "html not asked for"
    );
}

/// Runs `report` with `args` into a fresh folder: exit 2, one line on stderr, nothing written.
fn refused(args: &[&str], expect_in_error: &str) {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let assert = stickslip()
        .arg("report")
        .args(args)
        .arg("--out")
        .arg(&out)
        .assert()
        .code(2);
    let stderr = String::from_utf8_lossy(&assert.get_output().stderr).into_owned();
    assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    assert!(stderr.contains(expect_in_error), "{stderr}");
    assert!(!stderr.contains("panicked"));
    let written = std::fs::read_dir(&out).map(|d| d.count()).unwrap_or(0);
    assert_eq!(written, 0, "nothing may be written");
}

#[test]
fn bad_report_input_is_refused_without_writing() {
    refused(&["scenarios/does-not-exist.toml"], "does-not-exist.toml");
    let dir = tempfile::tempdir().unwrap();
    let malformed = dir.path().join("bad.toml");
    std::fs::write(&malformed, "model = \"pulled-mass\"\ntitle = \n").unwrap();
    refused(&[malformed.to_str().unwrap()], "bad.toml");
    let unknown = dir.path().join("unknown.toml");
    std::fs::write(
        &unknown,
        "model = \"pulled-mass\"\ntitle = \"x\"\n[params]\nmu = 1\n",
    )
    .unwrap();
    refused(&[unknown.to_str().unwrap()], "unknown field `mu`");
    let invalid = dir.path().join("invalid.toml");
    std::fs::write(
        &invalid,
        "model = \"pulled-mass\"\ntitle = \"x\"\n[params]\nmu_d = 0.9\n",
    )
    .unwrap();
    refused(&[invalid.to_str().unwrap()], "mu_d");
    refused(&["--format", "pdf"], "--format");
}

#[test]
fn an_unwritable_output_folder_is_refused() {
    let mut cmd = stickslip();
    cmd.args(["report", "scenarios/set-b-slip-stick.toml"]);
    common::unwritable(cmd);
}
