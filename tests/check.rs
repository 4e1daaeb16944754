//! `stickslip check` as a user runs it: the README's examples (the paper's Γ with coefficient 1
//! and 2, a student's t_ST with a sign error, a woodpecker formula in LaTeX), the JSON, the
//! exit codes (0 agrees, 3 disagrees, 2 bad input), and bad input refused in one line.

use assert_cmd::Command;
use serde_json::Value;

fn stickslip() -> Command {
    Command::cargo_bin("stickslip").unwrap()
}

/// The JSON of a check that ends with `code` (0 agrees, 3 disagrees).
fn check_json(args: &[&str], code: i32) -> Value {
    let out = stickslip()
        .arg("check")
        .args(args)
        .args(["--samples", "300", "--json"])
        .assert()
        .code(code);
    serde_json::from_slice(&out.get_output().stdout).unwrap()
}

#[test]
fn the_papers_gamma_agrees_in_its_regime_and_twice_it_does_not() {
    let right = check_json(
        &[
            "pulled-mass",
            r"g T \varphi^3 \Gamma",
            "--quantity",
            "v_avg",
            "--regime",
            "slip_stick",
        ],
        0,
    );
    assert_eq!(right["agrees"], true, "{right}");
    assert_eq!(right["verdict"], "agrees");
    assert!(right["compared"].as_u64().unwrap() > 200);
    assert!(right["max_rel_error"].as_f64().unwrap() < 1e-6);
    assert_eq!(right["read_as"]["plain"], "g*T*varphi^3*Gamma");
    let wrong = check_json(
        &[
            "pulled-mass",
            "2*g*T*phi^3*Gamma",
            "--quantity",
            "v_avg",
            "--regime",
            "slip_stick",
        ],
        3,
    );
    assert_eq!(wrong["agrees"], false);
    assert_eq!(wrong["verdict"], "disagrees");
    assert_eq!(wrong["disagree"], wrong["compared"]);
    let worst = wrong["worst"].as_array().unwrap();
    assert_eq!(worst.len(), 5);
    let w = &worst[0];
    let ratio = w["formula"].as_f64().unwrap() / w["numeric"].as_f64().unwrap();
    assert!((ratio - 2.0).abs() < 1e-5, "{w}");
    assert!(w["params"]["mu_s"].is_number());
    // Every set drawn is counted.
    let counted = wrong["compared"].as_u64().unwrap()
        + wrong["undefined"].as_u64().unwrap()
        + wrong["not_measured"].as_u64().unwrap();
    assert_eq!(counted, 300);
}

/// Over every regime, (27) disagrees where the mass sticks early in the next period: the
/// integration measures v̄ there too (the tool's claim 1), and the verdict says so.
#[test]
fn the_papers_gamma_over_every_regime_fails_in_the_late_stick_band() {
    let r = check_json(
        &[
            "pulled-mass",
            r"g T \varphi^3 \Gamma",
            "--quantity",
            "v_avg",
        ],
        3,
    );
    for row in r["by_regime"].as_array().unwrap() {
        let late = row["regime"] == "slip_stick_late";
        assert_eq!(row["disagree"].as_u64().unwrap() > 0, late, "{row}");
    }
}

#[test]
fn a_students_sign_error_is_shown_with_counterexamples_in_words() {
    let out = stickslip()
        .args([
            "check",
            "pulled-mass",
            r"\frac{T}{2}\left(1 - \varphi\Theta\right)",
        ])
        .args(["--quantity", "t_stick", "--samples", "200"])
        .assert()
        .code(3);
    let text = String::from_utf8(out.get_output().stdout.clone()).unwrap();
    for want in [
        "DISAGREES",
        "worst sets",
        "counterexamples nearest each regime boundary",
        "one slip and one stick per period",
    ] {
        assert!(text.contains(want), "{want}: {text}");
    }
    assert!(
        text.starts_with("read as: t_stick = T/2*(1 - varphi*Theta)"),
        "{text}"
    );
    let stderr = String::from_utf8(out.get_output().stderr.clone()).unwrap();
    assert!(
        stderr.starts_with("verdict: the formula for t_stick disagrees"),
        "{stderr}"
    );
}

#[test]
fn a_woodpecker_formula_in_latex_agrees() {
    let r = check_json(
        &[
            "woodpecker",
            r"t_0^{(I)} - \Delta^{(I)}",
            "--quantity",
            "t_slip_1",
        ],
        0,
    );
    assert_eq!(r["agrees"], true, "{r}");
    assert_eq!(r["given"]["agrees"], true);
}

#[test]
fn bad_input_is_refused_in_one_line() {
    for (args, want) in [
        (
            vec!["pulled-mass", "g*T*xi", "--quantity", "v_avg"],
            "unknown symbol xi",
        ),
        (
            vec!["pulled-mass", "g*(T", "--quantity", "v_avg"],
            "not closed",
        ),
        (
            vec!["pulled-mass", "g*T"],
            "--quantity NAME, or a left side",
        ),
        (
            vec!["pulled-mass", "g*T", "--quantity", "v_avg", "--regime", "x"],
            "--regime",
        ),
        (
            vec!["pulled-mass", "g*T", "--quantity", "speed"],
            "--quantity",
        ),
        (
            vec![
                "pulled-mass",
                "g*T",
                "--quantity",
                "v_avg",
                "--samples",
                "0",
            ],
            "samples",
        ),
        (
            vec!["pulled-mass", r"\frac{g}{T", "--quantity", "v_avg"],
            "not closed",
        ),
    ] {
        let out = stickslip().arg("check").args(&args).assert().code(2);
        let stderr = String::from_utf8(out.get_output().stderr.clone()).unwrap();
        assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
        assert!(stderr.contains(want), "{args:?}: {stderr}");
        assert!(out.get_output().stdout.is_empty());
    }
}

/// Several formulas from a file, each with its page: the README's examples in one command.
#[test]
fn a_formulas_file_checks_each_and_writes_a_page_each() {
    let tmp = tempfile::tempdir().unwrap();
    let out = stickslip()
        .args([
            "check",
            "pulled-mass",
            "--formulas",
            "scenarios/checks/paper-formulas.toml",
        ])
        .args(["--samples", "150", "--json", "--out"])
        .arg(tmp.path())
        .assert()
        .code(3);
    let all: Value = serde_json::from_slice(&out.get_output().stdout).unwrap();
    let verdicts: Vec<bool> = all
        .as_array()
        .unwrap()
        .iter()
        .map(|r| r["agrees"].as_bool().unwrap())
        .collect();
    assert_eq!(verdicts, [true, false, false, false]);
    // (20) as "sticks at all" fails exactly in the late-stick band.
    for row in all[3]["by_regime"].as_array().unwrap() {
        let late = row["regime"] == "slip_stick_late";
        assert_eq!(row["disagree"] == row["compared"], late, "{row}");
    }
    for n in 1..=4 {
        let html = std::fs::read_to_string(tmp.path().join(format!("check-{n}.html"))).unwrap();
        assert!(html.contains("<math") && !html.contains("merror") && html.contains("Verdict"));
        assert!(tmp.path().join(format!("check-{n}.md")).exists());
    }
    let md = std::fs::read_to_string(tmp.path().join("check-2.md")).unwrap();
    assert!(md.contains("DISAGREES") && md.contains("| μs |"), "{md}");
}
