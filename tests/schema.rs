//! The JSON Schemas of reports/schema/: the committed files are exactly what the serde types
//! generate now (src/schema.rs), and real outputs of the command line validate against them:
//! `eval --json` of every model at default and other regimes, `claims MODEL --json`, `check
//! --json` with one formula and with a formulas file, `fit --json`, a worksheet's
//! answer-key.json (fresh and committed), and a quick bench's results.json.

use std::fs;
use std::path::{Path, PathBuf};

use assert_cmd::Command;
use serde_json::Value;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn stickslip() -> Command {
    let mut cmd = Command::cargo_bin("stickslip").unwrap();
    cmd.current_dir(root());
    cmd
}

/// The committed schema `name` (reports/schema/NAME.schema.json).
fn committed(name: &str) -> Value {
    let path = root()
        .join("reports/schema")
        .join(format!("{name}.schema.json"));
    serde_json::from_slice(&fs::read(&path).unwrap()).unwrap()
}

/// Panics with every error when `doc` does not validate against the committed schema `name`.
fn validates(name: &str, doc: &Value, what: &str) {
    let schema = committed(name);
    let validator = jsonschema::validator_for(&schema)
        .unwrap_or_else(|e| panic!("{name}.schema.json is not a schema: {e}"));
    let errors: Vec<String> = validator
        .iter_errors(doc)
        .take(10)
        .map(|e| format!("{} at {}", e, e.instance_path()))
        .collect();
    assert!(
        errors.is_empty(),
        "{what} does not follow {name}.schema.json:\n{}",
        errors.join("\n")
    );
}

/// Runs the command with `args`, expecting exit `code` (0 or 3 when `None`: a verdict);
/// stdout as JSON.
fn json_of(args: &[&str], code: impl Into<Option<i32>>) -> Value {
    let out = stickslip().args(args).output().unwrap();
    let got = out.status.code();
    match code.into() {
        Some(code) => assert_eq!(
            got,
            Some(code),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        ),
        None => assert!(
            matches!(got, Some(0 | 3)),
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr)
        ),
    }
    serde_json::from_slice(&out.stdout).unwrap_or_else(|e| panic!("{args:?} printed no JSON: {e}"))
}

fn read_json(path: &Path) -> Value {
    serde_json::from_slice(&fs::read(path).unwrap())
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn the_committed_schemas_are_what_the_types_generate() {
    let files = stickslip::schema::files().unwrap();
    let dir = root().join("reports");
    for f in &files {
        let on_disk = fs::read(dir.join(&f.path))
            .unwrap_or_else(|e| panic!("{}: {e} (run `stickslip report`)", f.path.display()));
        assert!(
            on_disk == f.bytes,
            "{} differs from the generated schema: run `cargo run --release -- report`",
            f.path.display()
        );
    }
    let mut committed: Vec<String> = fs::read_dir(dir.join(stickslip::schema::FOLDER))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    committed.sort();
    let mut generated: Vec<String> = files
        .iter()
        .map(|f| f.path.file_name().unwrap().to_string_lossy().into_owned())
        .collect();
    generated.sort();
    assert_eq!(committed, generated, "a schema file no type generates");
}

#[test]
fn every_schema_is_a_draft_2020_12_schema_that_requires_the_version() {
    for d in stickslip::schema::documents() {
        let schema = committed(&d.name);
        assert_eq!(
            schema["$schema"], "https://json-schema.org/draft/2020-12/schema",
            "{}",
            d.name
        );
        jsonschema::meta::validate(&schema).unwrap_or_else(|e| panic!("{}: {e}", d.name));
        // A document without its version, or with another, is refused.
        let refused = serde_json::json!({"schema_version": "0"});
        assert!(
            !jsonschema::is_valid(&schema, &refused),
            "{} accepts a wrong version",
            d.name
        );
    }
}

#[test]
fn eval_json_of_every_model_follows_its_schema() {
    for (name, args) in [
        ("eval-pulled-mass", vec!["eval", "pulled-mass", "--json"]),
        // Continuous slip: stick times null, regime of the other branch.
        (
            "eval-pulled-mass",
            vec![
                "eval",
                "pulled-mass",
                "--json",
                "--scenario",
                "scenarios/fig06-continuous-slip.toml",
            ],
        ),
        ("eval-woodpecker", vec!["eval", "woodpecker", "--json"]),
        (
            "eval-woodpecker",
            vec![
                "eval",
                "woodpecker",
                "--json",
                "--scenario",
                "scenarios/fig16-no-intermediate-halt.toml",
            ],
        ),
        ("eval-belt", vec!["eval", "belt", "--json"]),
    ] {
        let doc = json_of(&args, 0);
        validates(name, &doc, &args.join(" "));
    }
}

#[test]
fn a_closed_form_key_missing_or_added_is_refused() {
    let doc = json_of(&["eval", "pulled-mass", "--json"], 0);
    let mut missing = doc.clone();
    missing["closed_form"]
        .as_object_mut()
        .unwrap()
        .remove("t_stick");
    let mut added = doc.clone();
    added["closed_form"]["t_stick_2"] = serde_json::json!(1.0);
    let schema = committed("eval-pulled-mass");
    assert!(!jsonschema::is_valid(&schema, &missing));
    assert!(!jsonschema::is_valid(&schema, &added));
}

#[test]
fn claims_check_and_fit_json_follow_their_schemas() {
    for model in ["pulled-mass", "woodpecker"] {
        let doc = json_of(&["claims", "--samples", "20", model, "--json"], 0);
        validates("claims", &doc, &format!("claims {model}"));
    }
    let one = json_of(
        &[
            "check",
            "pulled-mass",
            "g*T*phi^3*Gamma",
            "--quantity",
            "v_avg",
            "--samples",
            "40",
            "--json",
        ],
        None,
    );
    assert!(one.is_object());
    validates("check", &one, "check with one formula");
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("checks");
    let many = json_of(
        &[
            "check",
            "pulled-mass",
            "--formulas",
            "scenarios/checks/paper-formulas.toml",
            "--samples",
            "40",
            "--json",
            "--out",
            out.to_str().unwrap(),
        ],
        3,
    );
    assert!(many.is_array());
    validates("check", &many, "check --formulas");
    validates(
        "check",
        &read_json(&out.join("check-1.json")),
        "check-1.json",
    );

    let fit_out = tmp.path().join("fit");
    let fit = json_of(
        &[
            "fit",
            "scenarios/tracked-toy-example.csv",
            "--scenario",
            "scenarios/fig26-tracked-toy.toml",
            "--json",
            "--out",
            fit_out.to_str().unwrap(),
        ],
        0,
    );
    validates("fit", &fit, "fit --json");
    validates("fit", &read_json(&fit_out.join("fit.json")), "fit.json");
}

#[test]
fn answer_keys_follow_their_schema() {
    let tmp = tempfile::tempdir().unwrap();
    for (model, regime) in [("pulled-mass", "mixed"), ("woodpecker", "mixed")] {
        let out = tmp.path().join(model);
        stickslip()
            .args([
                "worksheet",
                "--model",
                model,
                "--students",
                "6",
                "--regime",
                regime,
            ])
            .args(["--format", "html", "--out"])
            .arg(&out)
            .assert()
            .success();
        let key = read_json(&out.join("answer-key.json"));
        validates("answer-key", &key, &format!("{model} answer-key.json"));
    }
    for model in ["pulled-mass", "woodpecker"] {
        let path = root()
            .join("reports/worksheets")
            .join(model)
            .join("answer-key.json");
        validates("answer-key", &read_json(&path), &path.display().to_string());
    }
}

/// A quick bench's results.json (reports/bench/results.json is written by a full run on a quiet
/// machine, not by `report`, and may predate the version key).
#[test]
fn bench_results_follow_their_schema() {
    let tmp = tempfile::tempdir().unwrap();
    stickslip()
        .args(["bench", "--quick", "--out"])
        .arg(tmp.path())
        .assert()
        .success();
    let doc = read_json(&tmp.path().join("results.json"));
    validates("bench-results", &doc, "bench --quick results.json");
}
