//! `stickslip eval woodpecker` and `stickslip claims` as a user runs them: the guide §14 JSON object,
//! the worked numbers of guide §13 through the CLI, the harmonic regimes of the paper's
//! sets, closed forms outside their domain, and bad input.

use assert_cmd::Command;
use serde_json::Value;

/// Every woodpecker `closed_form` key of guide §14, in order.
const CLOSED_FORM_KEYS: [&str; 42] = [
    "zeta0",
    "delta0",
    "tau_quarter",
    "u_s_minus",
    "u_s_plus",
    "u_d_minus",
    "u_d_plus",
    "eta",
    "eta_prime",
    "immediate_slip",
    "t0_1",
    "delta_1",
    "t_slip_1",
    "a_slip_1",
    "t_max_speed_1",
    "v_max_1",
    "s_1",
    "t_stick_1",
    "mu_d_min_1",
    "mu_d_halt_1",
    "gamma_1",
    "distance_1",
    "t0_2",
    "delta_2",
    "t_slip_2",
    "a_slip_2",
    "t_max_speed_2",
    "v_max_2",
    "s_2",
    "t_stick_2",
    "mu_d_min_2",
    "mu_d_halt_2",
    "gamma_2",
    "distance_2",
    "gamma",
    "distance_per_period",
    "v_avg",
    "power_weight",
    "paper_regime_valid",
    "regime",
    "orbit_v_avg",
    "orbit_distance_per_period",
];

fn stickslip() -> Command {
    Command::cargo_bin("stickslip").unwrap()
}

fn json(args: &[&str]) -> Value {
    let out = stickslip().args(args).arg("--json").output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

fn close(v: &Value, want: f64, what: &str) {
    let got = v.as_f64().unwrap_or_else(|| panic!("{what} is {v}"));
    assert!(
        ((got - want) / want).abs() < 1e-9,
        "{what}: {got} vs {want}"
    );
}

#[test]
fn fig15_json_has_the_keys_of_section_7_and_the_worked_numbers() {
    let v = json(&["eval", "woodpecker"]);
    let sorted = |v: &Value| {
        let mut k: Vec<String> = v.as_object().unwrap().keys().cloned().collect();
        k.sort();
        k
    };
    let mut top = [
        "schema_version",
        "model",
        "params",
        "closed_form",
        "linear",
        "harmonic",
        "checks",
    ]
    .map(String::from);
    top.sort();
    assert_eq!(sorted(&v), top);
    let mut cf_keys = CLOSED_FORM_KEYS.map(String::from);
    cf_keys.sort();
    assert_eq!(sorted(&v["closed_form"]), cf_keys);
    let c = &v["closed_form"];
    close(&c["t_slip_1"], 0.058_242_816_14, "t_SL(I)");
    close(&c["t_stick_1"], 0.080_533_079_51, "t_ST(I)");
    close(&c["v_max_2"], 0.167_175_540_6, "v_M(II)");
    close(&c["mu_d_halt_2"], 0.298_683_430_3, "mu_d,HALT(II)");
    close(&c["v_avg"], 0.049_658_438_62, "v_avg (71)");
    assert_eq!(c["regime"], "double_slip_stick");
    assert_eq!(c["paper_regime_valid"], true);
    // The harmonic law of the paper's set: double slip-stick, v̄ = 35.39 mm/s, P_fric.
    let h = &v["harmonic"];
    assert_eq!(h["regime"], "double_slip_stick");
    close(&h["v_avg"], 0.035_392_212_93, "harmonic v_avg");
    close(&h["power_friction"], 5.231_084_172e-3, "harmonic P_fric");
    assert!(h.get("power_weight").is_some());
    for check in v["checks"].as_array().unwrap() {
        assert_eq!(check["pass"], true, "{check}");
    }
    assert_eq!(v["params"]["lambda"].as_f64().unwrap(), 0.016 / 0.007);
    assert_eq!(v["params"]["omega_mode"], "bird");
    // No key twice in the raw text (serde_json would silently keep the last one).
    let raw = stickslip()
        .args(["eval", "woodpecker", "--json"])
        .output()
        .unwrap()
        .stdout;
    let raw = String::from_utf8(raw).unwrap();
    assert_eq!(
        raw.matches("\"omega\":").count(),
        1,
        "params.omega appears once"
    );
}

#[test]
fn the_extremes_counterpart_loses_the_intermediate_halt() {
    let v = json(&["eval", "woodpecker", "--counterpart", "extremes"]);
    assert_eq!(v["closed_form"]["regime"], "double_slip_no_halt");
    assert_eq!(v["linear"]["regime"], "double_slip_no_halt");
    close(
        &v["closed_form"]["orbit_v_avg"],
        0.077_132_659_04,
        "orbit v_avg",
    );
    close(&v["linear"]["v_avg"], 0.077_132_659_04, "linear v_avg");
    // (71) is still evaluated (δ0-independent) but the paper's regime is not valid.
    close(&v["closed_form"]["v_avg"], 0.049_658_438_62, "(71)");
    assert_eq!(v["closed_form"]["paper_regime_valid"], false);
}

#[test]
fn fig16_harmonic_law_has_no_intermediate_halt() {
    let v = json(&[
        "eval",
        "woodpecker",
        "--scenario",
        "scenarios/fig16-no-intermediate-halt.toml",
    ]);
    assert_eq!(v["harmonic"]["regime"], "double_slip_no_halt");
    let v = json(&[
        "eval",
        "woodpecker",
        "--scenario",
        "scenarios/fig26-tracked-toy.toml",
    ]);
    assert_eq!(v["harmonic"]["regime"], "double_slip_stick");
    close(
        &v["harmonic"]["v_avg"],
        0.023_723_364_4,
        "Fig. 26 harmonic v_avg",
    );
}

#[test]
fn printed_formulas_lambda_one_never_stick() {
    let v = json(&[
        "eval",
        "woodpecker",
        "--scenario",
        "scenarios/lambda1-printed-formulas.toml",
    ]);
    assert_eq!(v["closed_form"]["regime"], "continuous_or_multiperiod");
    assert_eq!(v["harmonic"]["regime"], "continuous_slip");
    assert_eq!(v["linear"]["regime"], "continuous_slip");
    assert!(v["closed_form"]["t_max_speed_2"].is_null());
}

#[test]
fn outside_the_closed_form_domain_the_tool_integrates_and_says_why() {
    // |z0| > d0: the zeros counterpart does not exist; F_e never changes sign.
    let out = stickslip()
        .args(["eval", "woodpecker", "--z0", "0.012"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("closed forms do not apply"), "{text}");
    assert!(!text.contains("NaN"));
    let v = json(&["eval", "woodpecker", "--z0", "0.012"]);
    assert_eq!(v["closed_form"]["regime"], "outside_closed_form_domain");
    assert!(v["linear"].is_null());
    assert_eq!(v["harmonic"]["regime"], "no_slip");
    // δ0 > ζ0 with the extremes counterpart: F_e > 0 always and (39) holds: no slip, in the
    // closed form and in the linear integration.
    let v = json(&[
        "eval",
        "woodpecker",
        "--z0",
        "0.012",
        "--counterpart",
        "extremes",
    ]);
    assert_eq!(v["closed_form"]["regime"], "no_slip");
    assert_eq!(v["linear"]["regime"], "no_slip");
    // u_s^(−) = 2λμs − 1 < 0: outside the closed-form domain, both laws still integrated.
    let out = stickslip()
        .args(["eval", "woodpecker", "--lever", "0.5"])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("closed forms do not apply") && text.contains("u_s^(-)"),
        "{text}"
    );
    let v = json(&["eval", "woodpecker", "--lever", "0.5"]);
    assert_eq!(v["closed_form"]["regime"], "outside_closed_form_domain");
    assert!(v["linear"].is_object() && v["harmonic"].is_object());
}

#[test]
fn bad_woodpecker_input_is_one_line_and_exit_2() {
    let cases: [(&[&str], &str); 8] = [
        (&["--d0", "0"], "d0"),
        (&["--d0", "-0.001"], "d0"),
        (&["--l", "0"], "l"),
        (&["--h", "-1"], "h"),
        (&["--lever", "0"], "lever"),
        (&["--mu-d", "0.7"], "mu_d"),
        (&["--z0", "inf"], "z0"),
        (&["--counterpart", "middle"], "--counterpart"),
    ];
    for (args, name) in cases {
        let out = stickslip()
            .args(["eval", "woodpecker"])
            .args(args)
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(stderr.trim_end().lines().count(), 1, "{args:?}: {stderr}");
        assert!(stderr.contains(name), "{args:?}: {stderr}");
        assert!(out.stdout.is_empty());
    }
}

#[test]
fn claims_are_computed_with_verdicts_and_numbers() {
    let v = json(&["claims", "woodpecker"]);
    let claims = v["claims"].as_array().unwrap();
    assert_eq!(claims.len(), 8);
    let claim = |id: u64| claims.iter().find(|c| c["id"] == id).unwrap();
    assert_eq!(claim(4)["verdict"], "refuted");
    let share = claim(4)["sample"]["share"].as_f64().unwrap();
    assert!((0.4..0.75).contains(&share), "{share}");
    assert_eq!(claim(2)["verdict"], "confirmed");
    // Same seed, same output; another seed, another sample.
    assert_eq!(v, json(&["claims", "woodpecker"]));
    let other = json(&["claims", "--seed", "7", "woodpecker"]);
    assert_ne!(other["claims"][3]["sample"], v["claims"][3]["sample"]);
    let text = stickslip()
        .args(["claims", "pulled-mass"])
        .output()
        .unwrap();
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(
        text.contains("claim 1:") && text.contains("claim 8:"),
        "{text}"
    );
}

/// A teacher thinking in millimetres (`--z0 7`) gets the run as typed and a one-line hint with
/// the value in metres; a value in range gets none.
#[test]
fn a_length_typed_in_millimetres_gets_a_hint() {
    let out = stickslip()
        .args(["eval", "woodpecker", "--z0", "7"])
        .output()
        .unwrap();
    assert!(out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    assert!(
        stderr.starts_with("hint: z0 = 7 m is large") && stderr.contains("--z0 0.007"),
        "{stderr}"
    );
    let out = stickslip()
        .args(["eval", "woodpecker", "--z0", "0.007"])
        .output()
        .unwrap();
    assert!(out.stderr.is_empty());
}
