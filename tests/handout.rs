//! `stickslip handout`: every built-in scene renders a self-contained two-page handout whose
//! substituted numbers are the engine's closed forms; scenario files are accepted; bad input is
//! refused with one line and nothing written; the Markdown is pinned by a snapshot.

mod common;

use std::path::Path;

use assert_cmd::Command;
use stickslip::explore::evaluate_model;
use stickslip::handout::{self, Handout};
use stickslip::lang::phrases::Translator;
use stickslip::report::{builtin_scenes, Format, Scene};
use stickslip::worksheet::Lang;

use common::rendered;

/// The guide §14 object of the scene's evaluation and its checks, straight from the engine.
fn engine(scene: &Scene) -> (serde_json::Value, Vec<serde_json::Value>) {
    let json = evaluate_model(&scene.setup, scene.periods).unwrap();
    let checks = json["checks"].as_array().unwrap().clone();
    (json, checks)
}

/// The value of a JSON key (guide §14): `closed_form` first, then `params`.
fn section7(json: &serde_json::Value, key: &str) -> f64 {
    json["closed_form"]
        .get(key)
        .or_else(|| json["params"].get(key))
        .and_then(serde_json::Value::as_f64)
        .unwrap_or_else(|| panic!("{key}: no guide §14 number"))
}

/// The result of a worked line as a number.
fn result_of(tex: &str) -> f64 {
    let number = common::result_tex(tex);
    match number.split_once(r" \times 10^{") {
        Some((mantissa, exponent)) => {
            let exponent: i32 = exponent.trim_end_matches('}').parse().unwrap();
            mantissa.parse::<f64>().unwrap() * 10f64.powi(exponent)
        }
        None => number
            .parse()
            .unwrap_or_else(|_| panic!("not a number: {tex}")),
    }
}

/// `a` and `b` agree to 4 significant figures.
fn english() -> Translator {
    Translator::new(Lang::En).unwrap()
}

fn same_to_4_figures(a: f64, b: f64) -> bool {
    (a - b).abs() <= 5e-4 * b.abs()
}

#[test]
fn every_builtin_scene_renders_a_complete_self_contained_handout() {
    for scene in builtin_scenes().unwrap() {
        let id = &scene.id;
        let files = handout::render(&scene, &[Format::Html, Format::Md], None, &english()).unwrap();
        let html = rendered(&files, &format!("{id}.html"));
        let md = rendered(&files, &format!("{id}.md"));
        assert!(html.contains("<style>") && html.contains("@page"), "{id}");
        for bad in ["<script", "<link", "<img"] {
            assert!(!html.contains(bad), "{id}: {bad}");
        }
        for (name, page) in [("html", html), ("md", md)] {
            let found = common::network_references(page);
            assert!(found.is_empty(), "{id}.{name}: references {found:?}");
        }
        assert!(html.contains("<math"), "{id}: MathML");
        assert_eq!(html.matches("<section class=\"page\"").count(), 2, "{id}");
        assert!(html.contains("break-after: page"), "{id}: page break");
        let handout: Handout = handout::build(&scene, &english()).unwrap();
        // The figures of page 2, the sketch of the apparatus among them.
        let svgs = html.matches("<svg").count();
        assert!((2..=4).contains(&svgs), "{id}: {svgs} figures");
        assert_eq!(svgs, handout.scene.figures.len(), "{id}");
        assert!(handout
            .scene
            .figures
            .iter()
            .any(|f| f.id == handout.scene.sketch.id));
        assert!(html.contains("<title>") && handout.scene.sketch.svg.contains("<desc>"));
        for f in std::iter::once(&handout.scene.sketch).chain(&handout.scene.figures) {
            assert!(md.contains(&format!("]({})", f.file)), "{id}: {}", f.file);
            assert!(files.iter().any(|g| g.path == Path::new(&f.file)), "{id}");
        }
        // The chain: every substituted result is the engine's value to 4 significant figures,
        // and shows in both formats.
        let (json, checks) = engine(&scene);
        assert!(
            handout.steps.len() >= 5,
            "{id}: {} steps",
            handout.steps.len()
        );
        for step in &handout.steps {
            assert!(
                md.contains(&format!("${}$", step.tex)),
                "{id}: {}",
                step.key
            );
            for piece in &step.pieces {
                assert!(html.contains(piece.as_str()), "{id}: {}", step.key);
            }
            if step.reason.is_empty() {
                let (shown, engine) = (result_of(&step.tex), section7(&json, &step.key));
                assert!(
                    same_to_4_figures(shown, engine),
                    "{id}: {} = {shown}, engine {engine}",
                    step.key
                );
            } else {
                assert!(md.contains(&step.reason), "{id}: {}", step.key);
            }
        }
        // Every check of the engine is a row of the verification table, in both formats.
        assert_eq!(handout.scene.verification.len(), checks.len(), "{id}");
        for c in &checks {
            if let Some(x) = c["numeric"].as_f64() {
                let shown = stickslip::format::people(Some(x), 8);
                assert!(
                    html.contains(&shown),
                    "{id}: check {} = {shown}",
                    c["quantity"]
                );
                assert!(
                    md.contains(&shown),
                    "{id}: check {} = {shown}",
                    c["quantity"]
                );
            }
        }
        // The claims of the scene, and only those.
        for claim in 1..=8u8 {
            let heading = format!("Claim {claim}: ");
            let expected = scene.claims.contains(&claim);
            assert_eq!(html.contains(&heading), expected, "{id}: claim {claim}");
            assert_eq!(md.contains(&heading), expected, "{id}: claim {claim}");
        }
    }
}

#[test]
fn the_handout_is_deterministic() {
    let scene = handout::find_scene("fig15-double-slip-stick").unwrap();
    let render = || handout::render(&scene, &[Format::Html, Format::Md], None, &english()).unwrap();
    assert_eq!(render(), render());
}

#[test]
fn markdown_handout_matches_its_snapshot() {
    let scene = handout::find_scene("fig10-linear-slip-stick").unwrap();
    let files = handout::render(&scene, &[Format::Md], None, &english()).unwrap();
    insta::assert_snapshot!(
        "handout_fig10_md",
        rendered(&files, "fig10-linear-slip-stick.md")
    );
    let files = handout::render(
        &scene,
        &[Format::Md],
        None,
        &Translator::new(Lang::It).unwrap(),
    )
    .unwrap();
    insta::assert_snapshot!(
        "handout_fig10_md_it",
        rendered(&files, "fig10-linear-slip-stick.md")
    );
}

fn stickslip() -> Command {
    Command::cargo_bin("stickslip").unwrap()
}

/// In Italian, a scenario file's own words stay as written, and the command says so on stderr.
#[test]
fn a_scenario_file_in_italian_names_the_phrases_left_in_english() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("my-set.toml");
    std::fs::write(
        &file,
        "model = \"pulled-mass\"\ntitle = \"My own set\"\n[params]\nmu_d = 0.3\n",
    )
    .unwrap();
    let out = stickslip()
        .args(["handout", "--lang", "it", "--format", "md", "--out"])
        .arg(dir.path().join("out"))
        .arg(&file)
        .output()
        .unwrap();
    assert!(out.status.success(), "{out:?}");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("have no it translation and stay in English"),
        "{stderr}"
    );
    let md = std::fs::read_to_string(dir.path().join("out/my-set.md")).unwrap();
    assert!(md.contains("# My own set") && md.contains("## Equazione del moto"));
    // The shipped scenario files are entirely in Italian: nothing to note.
    let out = stickslip()
        .args([
            "handout",
            "scenarios/fig06-continuous-slip.toml",
            "--lang",
            "it",
            "--out",
        ])
        .arg(dir.path().join("fig06"))
        .output()
        .unwrap();
    assert!(out.status.success() && out.stderr.is_empty(), "{out:?}");
}

#[test]
fn a_scenario_file_becomes_a_handout() {
    let dir = tempfile::tempdir().unwrap();
    stickslip()
        .args(["handout", "scenarios/set-c-late-stick.toml", "--out"])
        .arg(dir.path())
        .assert()
        .success();
    let html = std::fs::read_to_string(dir.path().join("set-c-late-stick.html")).unwrap();
    assert!(html.contains("the stick early in the next period"));
    assert!(
        !html.contains("slip_stick_late"),
        "regimes in words, not ids"
    );
    let md = std::fs::read_to_string(dir.path().join("set-c-late-stick.md")).unwrap();
    assert!(md.contains("](figures/set-c-late-stick-motion.svg)"));
    assert!(dir
        .path()
        .join("figures/set-c-late-stick-motion.svg")
        .exists());
    assert!(!dir.path().join("set-c-late-stick.pdf").exists());
}

#[test]
fn list_names_every_builtin_scene() {
    let out = stickslip().args(["handout", "--list"]).output().unwrap();
    assert!(out.status.success());
    let listing = String::from_utf8(out.stdout).unwrap();
    let scenes = builtin_scenes().unwrap();
    assert_eq!(listing.lines().count(), scenes.len());
    for (line, scene) in listing.lines().zip(&scenes) {
        assert!(line.starts_with(&format!("{} ", scene.id)), "{line}");
    }
    assert!(listing.contains("(the paper's Fig. 6 set)"), "{listing}");
}

/// Runs `handout` with `args` (environment `env` added): refused (`common::refused`) with
/// `expect` in its one line.
fn refused(args: &[&str], env: &[(&str, &str)], expect: &str) {
    let mut cmd = stickslip();
    cmd.arg("handout").args(args).envs(env.iter().copied());
    let stderr = common::refused(cmd);
    assert!(stderr.contains(expect), "{stderr}");
}

#[test]
fn bad_handout_input_is_refused_without_writing() {
    refused(&["fig99-nope"], &[], "stickslip handout --list");
    refused(
        &["scenarios/does-not-exist.toml"],
        &[],
        "does-not-exist.toml",
    );
    refused(
        &["fig15-double-slip-stick", "--format", "pdf"],
        &[],
        "--format",
    );
    refused(
        &["fig15-double-slip-stick", "--pdf"],
        &[("STICKSLIP_CHROMIUM", "/nonexistent/chromium")],
        "--pdf needs headless Chromium: install Chromium, Google Chrome or Microsoft Edge, or set STICKSLIP_CHROMIUM",
    );
}

#[test]
fn a_failing_browser_is_an_internal_error_and_leaves_no_pdf() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let assert = stickslip()
        .args(["handout", "fig05-immediate-slip", "--pdf", "--out"])
        .arg(&out)
        .env("STICKSLIP_CHROMIUM", "/bin/false")
        .assert()
        .code(1);
    let stderr = String::from_utf8_lossy(&assert.get_output().stderr).into_owned();
    assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    assert!(stderr.contains("to PDF with /bin/false failed"), "{stderr}");
    assert!(!out.exists(), "nothing may be written");
}

#[test]
fn an_unwritable_output_folder_is_refused() {
    let mut cmd = stickslip();
    cmd.args(["handout", "fig05-immediate-slip"]);
    common::unwritable(cmd);
}

/// Every built-in handout in Italian: every phrase translated (the list of the missing ones
/// is printed, numbers masked, as `[phrases]` keys of templates/lang/it.toml), the page in
/// Italian with decimal commas.
#[test]
fn every_builtin_handout_is_entirely_in_italian() {
    let words = Translator::new(Lang::It).unwrap();
    let mut scenes = builtin_scenes().unwrap();
    // The scenario files shipped in scenarios/ too (their titles and descriptions, and the
    // tool's default caption for a file).
    for entry in std::fs::read_dir("scenarios").unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            scenes.push(Scene::from_file(&path).unwrap());
        }
    }
    for scene in scenes {
        handout::build(&scene, &words).unwrap();
    }
    let missing = words.missing();
    if !missing.is_empty() {
        let keys: Vec<String> = missing.iter().map(|m| format!("{m:?} = \"\"")).collect();
        panic!(
            "{} phrases without Italian:\n{}",
            missing.len(),
            keys.join("\n")
        );
    }
    let scene = builtin_scenes()
        .unwrap()
        .into_iter()
        .find(|s| s.id == "fig10-linear-slip-stick")
        .unwrap();
    let files = handout::render(
        &scene,
        &[Format::Html],
        None,
        &Translator::new(Lang::It).unwrap(),
    )
    .unwrap();
    let html = rendered(&files, "fig10-linear-slip-stick.html");
    assert!(html.contains("<html lang=\"it\">"));
    assert!(html.contains("Equazione del moto") && html.contains("legge armonica"));
    // The weight W = m g = 0.5886 N with a decimal comma, in the parameters and the chain.
    assert!(html.contains("0,5886"), "no decimal comma");
}
