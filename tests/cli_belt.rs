//! The belt through the front door: `stickslip eval belt --json` prints its evaluation with
//! every check passing, the model-agnostic evaluation by id and parameter map answers for every
//! registered model, the command that needs a capability the belt does not have (`claims`)
//! refuses it with one line naming the model and exit code 2 (never empty or borrowed output),
//! and its worksheet and `check` work.

use std::collections::BTreeMap;

use assert_cmd::Command;
use stickslip::explore::{evaluate, Setup};
use stickslip::models::Model;

fn stickslip() -> Command {
    let mut cmd = Command::cargo_bin("stickslip").expect("binary");
    cmd.current_dir(env!("CARGO_MANIFEST_DIR"));
    cmd
}

#[test]
fn eval_belt_json_passes_every_check() {
    let out = stickslip()
        .args(["eval", "belt", "--json", "--v-b", "0.2", "--mu-d", "0.3"])
        .assert()
        .success()
        .get_output()
        .clone();
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(json["model"], "belt");
    assert_eq!(json["params"]["v_b"], 0.2);
    assert_eq!(json["closed_form"]["regime"], "stick_slip");
    let checks = json["checks"].as_array().expect("checks");
    assert!(checks.len() >= 15);
    for c in checks {
        assert_eq!(c["pass"], true, "{c}");
    }
}

#[test]
fn every_model_evaluates_by_id_and_parameter_map() {
    for model in Model::defaults() {
        let setup = Setup {
            model: model.id().to_string(),
            params: BTreeMap::from([("mu_d".to_string(), 0.2)]),
            ..Setup::default()
        };
        let json = evaluate(&setup, 4).unwrap();
        assert_eq!(json["model"], model.id());
        assert_eq!(json["params"]["mu_d"], 0.2, "{}", model.id());
        assert!(!json["checks"].as_array().unwrap().is_empty());
    }
    let unknown = Setup {
        model: "belt".to_string(),
        params: BTreeMap::from([("force".to_string(), 1.0)]),
        ..Setup::default()
    };
    assert!(evaluate(&unknown, 4)
        .unwrap_err()
        .to_string()
        .contains("force"));
}

#[test]
fn commands_without_the_capability_refuse_the_belt_in_one_line() {
    let lines: [&[&str]; 1] = [&["claims", "belt"]];
    for args in lines {
        let assert = stickslip().args(args).assert().code(2);
        let output = assert.get_output();
        assert!(output.stdout.is_empty(), "{args:?}: no output");
        let err = String::from_utf8_lossy(&output.stderr);
        assert_eq!(err.trim_end().lines().count(), 1, "{args:?}: {err}");
        assert!(err.contains("the belt model has no"), "{args:?}: {err}");
    }
}

/// The belt's worksheet writes its sheets and key, and `check belt` agrees with its stick time
/// and refuses a wrong period (exit 3).
#[test]
fn the_belts_worksheet_and_check_work() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().to_str().unwrap();
    stickslip()
        .args(["worksheet", "--model", "belt", "--students", "2", "-o", out])
        .assert()
        .success();
    let key = std::fs::read_to_string(dir.path().join("answer-key.json")).unwrap();
    assert!(
        key.contains("t_stick") && key.contains("energy_per_cycle"),
        "{key}"
    );
    let agrees = [
        "t_stick = 2*(mu_s - mu_d)*mass*g/(k*v_b)",
        "--samples",
        "50",
    ];
    stickslip()
        .args(["check", "belt"])
        .args(agrees)
        .assert()
        .code(0);
    let wrong = ["period = 2*pi/omega", "--samples", "50"];
    stickslip()
        .args(["check", "belt"])
        .args(wrong)
        .assert()
        .code(3);
}

/// With its presentation, `eval belt` prints its tables, `--csv` writes its run and `sweep belt`
/// names its one law in the columns: no column of the paper's two laws, none "undefined".
#[test]
fn the_belts_tables_csv_and_sweep_name_its_own_law() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().to_str().unwrap();
    let text = stickslip().args(["eval", "belt"]).assert().success();
    let text = String::from_utf8_lossy(&text.get_output().stdout).to_string();
    assert!(text.contains("exact integration of the same autonomous system (16/16 pass"));
    for word in ["lineari", "harmonic law", "pulled", "woodpecker"] {
        assert!(!text.contains(word), "{word}: {text}");
    }
    let csv = dir.path().join("csv");
    stickslip()
        .args(["eval", "belt", "--csv", csv.to_str().unwrap()])
        .assert()
        .success();
    let events = std::fs::read_to_string(csv.join("events_exact.csv")).unwrap();
    assert!(events.starts_with("t_s,kind,cycle,x_m,v_m_s\n"), "{events}");
    stickslip()
        .args([
            "sweep", "belt", "--param", "v_b", "--from", "0.02", "--to", "0.2", "--steps", "4",
            "-o", out,
        ])
        .assert()
        .success();
    let sweep = std::fs::read_to_string(dir.path().join("sweep.csv")).unwrap();
    let mut lines = sweep.lines();
    assert_eq!(
        lines.next().unwrap(),
        "v_b_m_s,v_avg_exact_m_s,slips_exact,sticks_exact,regime_exact,regime_closed_form,\
         period_s,amplitude_m,stick_share"
    );
    assert!(
        !sweep.contains("undefined") && !sweep.contains("harmonic"),
        "{sweep}"
    );
    // Its own quantities are those `eval belt` measures on its integration at the same v_b,
    // to the last digit; the block does not advance, so v̄ is left empty.
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 4);
    for row in &rows {
        assert_eq!(
            &row[1..6],
            ["", "1", "1", "stick_slip", "stick_slip"],
            "{row:?}"
        );
        let eval = stickslip()
            .args(["eval", "belt", "--json", "--v-b", row[0]])
            .assert()
            .success();
        let json: serde_json::Value = serde_json::from_slice(&eval.get_output().stdout).unwrap();
        for (cell, key) in row[6..].iter().zip(["period", "amplitude", "stick_share"]) {
            let measured = json["integration"][key].as_f64().unwrap();
            assert_eq!(
                cell.parse::<f64>().unwrap(),
                measured,
                "{key} at v_b = {}",
                row[0]
            );
        }
    }
    let svg = std::fs::read_to_string(dir.path().join("sweep.svg")).unwrap();
    assert!(svg.contains("T (s)") && svg.contains("A (mm)") && !svg.contains("v̄"));
}
