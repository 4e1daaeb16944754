//! The `stickslip eval pulled-mass` command as a user runs it: the guide §14 JSON object, the worked
//! sets B and C of guide §13 pinned through the CLI, the defaults, a snapshot of the text
//! output, and every kind of bad input (exit code 2, one line on stderr, nothing on stdout).

use std::path::Path;

use assert_cmd::Command;
use predicates::prelude::*;
use serde_json::Value;

/// Relative tolerance of the pinned numbers: the worked numbers carry 10 significant digits,
/// so their own rounding is at most 5e-10 relative.
const REL: f64 = 1e-9;

/// The guide §14 top-level keys.
const TOP_KEYS: [&str; 6] = [
    "model",
    "params",
    "closed_form",
    "linear",
    "harmonic",
    "checks",
];

/// Every pulled-mass `closed_form` key of guide §14.
const CLOSED_FORM_KEYS: [&str; 22] = [
    "phi",
    "tau_slip",
    "t_slip",
    "a_slip",
    "tau_max_speed",
    "t_max_speed",
    "v_max",
    "tau_stick",
    "t_stick",
    "slip_duration",
    "theta",
    "phi_stick_max",
    "phi_continuous",
    "mu_min_equal",
    "gamma",
    "v_avg",
    "advance_per_period",
    "power",
    "tau_stick_late",
    "advance_per_period_late",
    "v_avg_late",
    "regime",
];

/// The guide §14 integration summary keys of the pulled mass.
const SUMMARY_KEYS: [&str; 11] = [
    "regime",
    "immediate_slip",
    "first_slip_time",
    "period_multiplicity",
    "slips_per_period",
    "sticks_per_period",
    "v_avg",
    "advance_per_period",
    "power",
    "steady_events",
    "steady_speed_maxima",
];

/// `stickslip eval pulled-mass ARGS`, run from the crate root so scenario paths are relative.
fn eval(args: &[&str]) -> Command {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_stickslip"));
    cmd.current_dir(env!("CARGO_MANIFEST_DIR"))
        .args(["eval", "pulled-mass"])
        .args(args);
    cmd
}

/// Standard output of a successful run.
fn stdout_of(args: &[&str]) -> String {
    let out = eval(args)
        .assert()
        .success()
        .stderr("")
        .get_output()
        .clone();
    String::from_utf8(out.stdout).expect("stdout is UTF-8")
}

/// The JSON object of a successful `--json` run.
fn json_of(args: &[&str]) -> Value {
    let mut all = args.to_vec();
    all.push("--json");
    serde_json::from_str(&stdout_of(&all)).expect("stdout is one JSON object")
}

fn scenario(name: &str) -> String {
    format!("scenarios/{name}.toml")
}

/// `v[path]` as a number, with the path in the failure message.
fn num(v: &Value, path: &str) -> f64 {
    v.pointer(path)
        .and_then(Value::as_f64)
        .unwrap_or_else(|| panic!("{path} is not a number: {:?}", v.pointer(path)))
}

fn assert_rel(v: &Value, path: &str, want: f64) {
    let got = num(v, path);
    let rel = ((got - want) / want).abs();
    assert!(
        rel <= REL,
        "{path} = {got}, want {want} (rel. error {rel:e})"
    );
}

fn assert_str(v: &Value, path: &str, want: &str) {
    assert_eq!(
        v.pointer(path).and_then(Value::as_str),
        Some(want),
        "{path}"
    );
}

/// Asserts every entry of `checks` passed, naming the ones that did not.
fn assert_all_checks_pass(v: &Value) {
    let checks = v["checks"].as_array().expect("checks is an array");
    assert!(!checks.is_empty());
    let failed: Vec<&Value> = checks.iter().filter(|c| c["pass"] != true).collect();
    assert!(failed.is_empty(), "failed checks: {failed:#?}");
}

#[test]
fn fig06_json_has_exactly_the_section_7_keys_and_every_check_passes() {
    let v = json_of(&["--scenario", &scenario("fig06-continuous-slip")]);
    let mut got: Vec<&str> = v
        .as_object()
        .expect("top level is an object")
        .keys()
        .map(String::as_str)
        .collect();
    // The JSON keys (guide §14) and the added schema version.
    let mut want = TOP_KEYS.to_vec();
    want.push("schema_version");
    got.sort_unstable();
    want.sort_unstable();
    assert_eq!(got, want, "top-level keys");

    assert_str(&v, "/model", "pulled-mass");
    for key in [
        "mu_s", "mu_d", "mass", "k", "force", "g", "W", "T", "omega", "phi",
    ] {
        assert!(v["params"].get(key).is_some(), "params.{key} missing");
    }
    for key in CLOSED_FORM_KEYS {
        assert!(
            v["closed_form"].get(key).is_some(),
            "closed_form.{key} missing"
        );
    }
    for law in ["linear", "harmonic"] {
        for key in SUMMARY_KEYS {
            assert!(v[law].get(key).is_some(), "{law}.{key} missing");
        }
    }
    for check in v["checks"].as_array().expect("checks is an array") {
        for key in [
            "quantity",
            "equation",
            "closed_form",
            "numeric",
            "rel_error",
            "tolerance",
            "pass",
        ] {
            assert!(check.get(key).is_some(), "check key {key} missing: {check}");
        }
        assert_eq!(num(check, "/tolerance"), 1e-9);
    }
    assert_all_checks_pass(&v);
    assert_str(&v, "/closed_form/regime", "continuous_slip");
    assert_str(&v, "/linear/regime", "continuous_slip");
    assert_str(&v, "/harmonic/regime", "continuous_slip");
    // Continuous slip has no stick, so no mean speed: null, not NaN.
    assert!(v["linear"]["v_avg"].is_null());
    assert!(v["closed_form"]["tau_stick_late"].is_null());
    assert_rel(&v, "/linear/first_slip_time", 0.070_863_542_28);
    assert_rel(&v, "/harmonic/first_slip_time", 0.066_037_177_47);
}

/// The `list` (steady_events or steady_speed_maxima) of the summary of `law`.
fn steady(v: &Value, law: &str, list: &str) -> Vec<Value> {
    v[law][list].as_array().expect("an array").clone()
}

#[test]
fn worked_set_b_slip_stick_through_the_cli() {
    let v = json_of(&["--scenario", &scenario("set-b-slip-stick")]);
    assert_all_checks_pass(&v);
    let cf = [
        ("phi", 0.169_894_665_3),
        ("tau_slip", 0.393_815_834_2),
        ("t_slip", 0.090_352_965_35),
        ("tau_max_speed", 0.621_353_332_4),
        ("t_max_speed", 0.142_556_777_1),
        ("a_slip", 0.104_166_666_7),
        ("v_max", 0.023_020_430_9),
        ("tau_stick", 0.792_301_157_6),
        ("t_stick", 0.181_777_249_2),
        ("slip_duration", 0.091_424_283_87),
        ("theta", 3.440_969_227),
        ("phi_stick_max", 0.290_615_792_9),
        ("phi_continuous", 0.350_686_277_1),
        ("mu_min_equal", 0.205_081_002_6),
        ("gamma", 0.488_981_670_2),
        ("advance_per_period", 0.001_238_224_198),
        ("v_avg", 0.005_396_970_576),
        ("power", 5.396_970_576e-4),
    ];
    for (key, want) in cf {
        assert_rel(&v, &format!("/closed_form/{key}"), want);
    }
    assert_str(&v, "/closed_form/regime", "slip_stick");

    // Linear law, exactly integrated: the closed forms again.
    assert_str(&v, "/linear/regime", "single_slip_stick");
    assert_rel(&v, "/linear/first_slip_time", 0.090_352_965_35);
    assert_rel(&v, "/linear/v_avg", 0.005_396_970_576);
    assert_rel(&v, "/linear/advance_per_period", 0.001_238_224_198);
    assert_rel(&v, "/linear/power", 5.396_970_576e-4);

    // Harmonic law: the same regime, but more than twice as fast (claim 3).
    assert_str(&v, "/harmonic/regime", "single_slip_stick");
    assert_eq!(v["harmonic"]["period_multiplicity"], 1);
    assert_rel(&v, "/harmonic/first_slip_time", 0.079_738_267_07);
    assert_rel(&v, "/harmonic/v_avg", 0.011_783_111_03);
    assert_rel(&v, "/harmonic/advance_per_period", 0.002_703_393_136);
    assert_rel(&v, "/harmonic/power", 0.001_178_311_103);
    let events = steady(&v, "harmonic", "steady_events");
    assert_eq!(events.len(), 2);
    assert_str(&events[0], "/kind", "slip");
    assert_rel(&events[0], "/phase", 0.347_550_210_9);
    assert_str(&events[1], "/kind", "stick");
    assert_rel(&events[1], "/phase", 0.850_352_392_7);
    let maxima = steady(&v, "harmonic", "steady_speed_maxima");
    assert_eq!(maxima.len(), 1);
    assert_rel(&maxima[0], "/phase", 0.663_972_690_4);
    assert_rel(&maxima[0], "/v", 0.040_892_870_9);
}

#[test]
fn worked_set_c_late_stick_through_the_cli() {
    let v = json_of(&["--scenario", &scenario("set-c-late-stick")]);
    assert_all_checks_pass(&v);
    let cf = [
        ("phi", 0.305_810_397_6),
        ("tau_slip", 0.308_868_501_5),
        ("tau_max_speed", 0.718_435_998_3),
        ("a_slip", 0.1875),
        ("v_max", 0.074_586_196_1),
        ("tau_stick", 1.026_142_084),
        ("phi_stick_max", 0.290_615_792_9),
        ("phi_continuous", 0.350_686_277_1),
        ("gamma", 0.488_981_670_2),
        ("advance_per_period", 0.007_221_323_524),
        ("tau_stick_late", 1.028_831_853),
        ("advance_per_period_late", 0.007_223_807_769),
        ("v_avg_late", 0.031_485_960_33),
    ];
    for (key, want) in cf {
        assert_rel(&v, &format!("/closed_form/{key}"), want);
    }
    assert_str(&v, "/closed_form/regime", "slip_stick_late");

    // The stick falls early in the next period: in the steady period it comes before the slip.
    assert_str(&v, "/linear/regime", "single_slip_stick");
    assert_rel(&v, "/linear/v_avg", 0.031_485_960_33);
    assert_rel(&v, "/linear/advance_per_period", 0.007_223_807_769);
    assert_rel(&v, "/linear/power", 0.005_667_472_859);
    let events = steady(&v, "linear", "steady_events");
    assert_eq!(events.len(), 2);
    assert_str(&events[0], "/kind", "stick");
    assert_rel(&events[0], "/phase", 0.028_831_852_62);
    assert_str(&events[1], "/kind", "slip");
    assert_rel(&events[1], "/phase", 0.308_868_501_5);

    assert_str(&v, "/harmonic/regime", "single_slip_stick");
    assert_rel(&v, "/harmonic/first_slip_time", 0.066_037_177_47);
    assert_rel(&v, "/harmonic/v_avg", 0.043_844_393_81);
    assert_rel(&v, "/harmonic/advance_per_period", 0.010_059_196_84);
    assert_rel(&v, "/harmonic/power", 0.007_891_990_885);
    let events = steady(&v, "harmonic", "steady_events");
    assert_eq!(events.len(), 2);
    assert_str(&events[0], "/kind", "stick");
    assert_rel(&events[0], "/phase", 0.058_676_127_02);
    assert_str(&events[1], "/kind", "slip");
    assert_rel(&events[1], "/phase", 0.287_832_126_3);
    let maxima = steady(&v, "harmonic", "steady_speed_maxima");
    assert_eq!(maxima.len(), 1);
    assert_rel(&maxima[0], "/phase", 0.729_851_960_1);
    assert_rel(&maxima[0], "/v", 0.101_128_206_1);
}

#[test]
fn set_b_and_c_flags_give_the_same_output_as_their_scenarios() {
    for (name, force) in [("set-b-slip-stick", "0.10"), ("set-c-late-stick", "0.18")] {
        let flags = stdout_of(&["--mu-d", "0.35", "--force", force]);
        assert_eq!(flags, stdout_of(&["--scenario", &scenario(name)]), "{name}");
    }
}

#[test]
fn defaults_equal_the_fig06_scenario_byte_for_byte() {
    let fig06 = scenario("fig06-continuous-slip");
    assert_eq!(stdout_of(&[]), stdout_of(&["--scenario", &fig06]));
    assert_eq!(
        stdout_of(&["--json"]),
        stdout_of(&["--scenario", &fig06, "--json"])
    );
}

#[test]
fn text_output_of_set_b_matches_the_snapshot() {
    let text = stdout_of(&["--scenario", &scenario("set-b-slip-stick")]);
    insta::assert_snapshot!("eval_pulled_mass_set_b_text", text);
}

/// A temporary scenario file with `body`.
fn temp_scenario(dir: &Path, file: &str, body: &str) -> String {
    let path = dir.join(file);
    std::fs::write(&path, body).expect("temp scenario written");
    path.display().to_string()
}

#[test]
fn bad_input_exits_2_with_one_line_naming_the_parameter_or_file() {
    let dir = tempfile::tempdir().expect("temp dir");
    let unknown = temp_scenario(
        dir.path(),
        "unknown-key.toml",
        "model = \"pulled-mass\"\ntitle = \"x\"\n[params]\nmu_s = 0.4\nfriction = 0.3\n",
    );
    let malformed = temp_scenario(
        dir.path(),
        "malformed.toml",
        "model = \"pulled-mass\"\ntitle = \"unterminated\n",
    );
    let missing = dir.path().join("missing.toml").display().to_string();
    // Each case and what its one line must name: the parameter, or the file (and the key).
    let cases: Vec<(Vec<&str>, Vec<&str>)> = vec![
        (vec!["--mass", "0"], vec!["mass"]),
        (vec!["--k", "-1"], vec!["k = -1"]),
        (vec!["--force", "nan"], vec!["force"]),
        (vec!["--g", "inf"], vec!["g = inf"]),
        (vec!["--mu-d", "0.5"], vec!["mu_d"]),
        (vec!["--mu-s", "0"], vec!["mu_s"]),
        (vec!["--periods", "0"], vec!["periods"]),
        (vec!["--periods", "1000001"], vec!["periods"]),
        (
            vec!["--scenario", &unknown],
            vec!["unknown-key.toml", "friction"],
        ),
        (vec!["--scenario", &malformed], vec!["malformed.toml"]),
        (vec!["--scenario", &missing], vec!["missing.toml"]),
        (vec!["--mass", "heavy"], vec!["--mass"]),
    ];
    for (args, names) in cases {
        let mut assert = eval(&args).assert();
        assert = assert
            .code(2)
            .stdout("")
            .stderr(predicate::str::contains("panicked").not());
        for name in names {
            assert = assert.stderr(predicate::str::contains(name));
        }
        let out = assert.get_output().clone();
        let stderr = String::from_utf8(out.stderr).expect("stderr is UTF-8");
        assert_eq!(
            stderr.lines().count(),
            1,
            "{args:?}: want one line, got {stderr:?}"
        );
        assert!(stderr.ends_with('\n'), "{args:?}: {stderr:?}");
    }
}

#[test]
fn a_chosen_number_of_periods_is_used() {
    let v = json_of(&[
        "--scenario",
        &scenario("set-b-slip-stick"),
        "--periods",
        "50",
    ]);
    assert_eq!(v["params"]["periods"], 50);
    assert_all_checks_pass(&v);
    assert_rel(&v, "/harmonic/v_avg", 0.011_783_111_03);
    let last = steady(&v, "linear", "steady_events");
    // The steady events are those of the last of the 50 periods.
    let period = num(&v, "/params/T");
    assert!(num(&last[0], "/t") > 49.0 * period);
}

#[test]
fn fig05_slips_at_once_in_both_laws() {
    let v = json_of(&["--scenario", &scenario("fig05-immediate-slip")]);
    assert_all_checks_pass(&v);
    assert_str(&v, "/closed_form/regime", "immediate_continuous_slip");
    assert_eq!(v["closed_form"]["immediate_slip"], true);
    for law in ["linear", "harmonic"] {
        assert_eq!(v[law]["immediate_slip"], true, "{law}");
        assert_eq!(num(&v, &format!("/{law}/first_slip_time")), 0.0, "{law}");
        assert_str(&v, &format!("/{law}/regime"), "continuous_slip");
    }
    // F = 0.50 N against 2 μs W = 0.47088 N.
    assert!(num(&v, "/params/force") > 2.0 * 0.4 * num(&v, "/params/W"));
}
