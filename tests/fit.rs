//! `stickslip fit` as a user runs it: tracks made by the model with seeded Gaussian noise
//! (σ = 0.2 mm, 500 frames at 240 fps, random phase and offset) are fitted back from a start a
//! few percent off, and every free parameter must come back within two standard errors, with
//! standard errors below 5 % of the value; files in m and mm, columns by name and number, the
//! outputs, determinism, and every malformed file refused (exit 2, one line naming the line,
//! nothing written).

mod common;

use std::fs;
use std::path::{Path, PathBuf};

use assert_cmd::Command;
use serde_json::Value;

use stickslip::fit::data::{parse, ReadOptions, Unit};
use stickslip::models::woodpecker::fit::synthetic::Synthetic;
use stickslip::models::woodpecker::fit::{self, FitParam};
use stickslip::models::woodpecker::WoodpeckerParams;
use stickslip::models::Model;
use stickslip::params::Scenario;

const EXAMPLE: &str = stickslip::models::woodpecker::fit::synthetic::EXAMPLE_FILE;
const FIG26: &str = "scenarios/fig26-tracked-toy.toml";

fn stickslip() -> Command {
    let mut cmd = Command::cargo_bin("stickslip").unwrap();
    cmd.current_dir(env!("CARGO_MANIFEST_DIR"));
    cmd
}

/// The tracked toy's parameters (Figs. 26–27).
fn fig26() -> WoodpeckerParams {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(FIG26);
    match Scenario::load(&path).unwrap().model_params(&path).unwrap() {
        Model::Woodpecker(p) => p,
        other => panic!("{FIG26} describes {}", other.id()),
    }
}

fn synthetic(truth: WoodpeckerParams, seed: u64) -> Synthetic {
    Synthetic {
        truth,
        points: 500,
        frame_rate: 240.0,
        noise: 2e-4,
        seed,
    }
}

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    fs::write(&path, text).unwrap();
    path
}

/// The value of parameter `name` in `p`.
fn value(p: &WoodpeckerParams, name: &str) -> f64 {
    match name {
        "mu_d" => p.mu_d,
        "mu_s" => p.mu_s,
        "k" => p.k,
        "z0" => p.z0,
        "d0" => p.d0,
        _ => panic!("{name}"),
    }
}

/// Runs `stickslip fit FILE --json --out OUT ARGS`, expecting success; returns the JSON.
fn fit_json(file: &Path, out: &Path, args: &[String]) -> Value {
    let output = stickslip()
        .arg("fit")
        .arg(file)
        .arg("--json")
        .arg("--out")
        .arg(out)
        .args(args)
        .output()
        .unwrap();
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let json: Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(json, read_json(&out.join("fit.json")), "stdout = fit.json");
    json
}

fn read_json(path: &Path) -> Value {
    serde_json::from_str(&fs::read_to_string(path).unwrap()).unwrap()
}

/// Estimates of a fit result as (name, value, std error).
fn estimates(json: &Value) -> Vec<(String, f64, f64)> {
    json["estimates"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| {
            (
                e["name"].as_str().unwrap().to_string(),
                e["value"].as_f64().unwrap(),
                e["std_error"].as_f64().unwrap(),
            )
        })
        .collect()
}

/// Fits the synthetic track of `truth` with `free` from a start 3 % off (alternating sides)
/// and checks the recovery: every free parameter within 2 standard errors (the nuisance within
/// 3: one miss in 20 is expected at 2, and the coverage test below checks the errors' size),
/// standard errors of the physical parameters below 5 %.
fn recovers(truth: WoodpeckerParams, free: &[&str], seed: u64) {
    let tmp = tempfile::tempdir().unwrap();
    let track = synthetic(truth, seed).generate().unwrap();
    let file = write(tmp.path(), "track.csv", &track.csv(Unit::Mm, "synthetic"));
    // The fixed parameters are the truth's; the free ones start 3 % off.
    let mut args: Vec<String> = Vec::new();
    for (i, name) in ["mu_s", "mu_d", "k", "z0", "d0"].iter().enumerate() {
        let exact = value(&truth, name);
        let start = if free.contains(name) {
            exact * if i.is_multiple_of(2) { 1.03 } else { 0.97 }
        } else {
            exact
        };
        args.extend([format!("--{}", name.replace('_', "-")), start.to_string()]);
    }
    args.extend(["--free".to_string(), free.join(",")]);
    let json = fit_json(&file, &tmp.path().join("fit"), &args);
    assert_eq!(json["converged"], true, "{json}");
    let got = estimates(&json);
    let names: Vec<&str> = got.iter().map(|e| e.0.as_str()).collect();
    assert_eq!(names.len(), free.len() + 2, "{names:?}");
    for (name, fitted, se) in &got {
        let (exact, within) = match name.as_str() {
            "time_shift" => (track.time_shift, 3.0),
            "y_offset" => (track.y_offset, 3.0),
            name => {
                let exact = value(&truth, name);
                assert!(se / exact.abs() < 0.05, "{name}: std error {se} of {exact}");
                (exact, 2.0)
            }
        };
        assert!(
            (fitted - exact).abs() < within * se,
            "{name}: fitted {fitted} ± {se}, true {exact} (seed {seed})"
        );
    }
    // The residual is the noise.
    let rms = json["rms_residual"].as_f64().unwrap();
    assert!((rms / 2e-4 - 1.0).abs() < 0.1, "rms {rms}");
}

#[test]
fn mu_d_z0_d0_are_recovered_within_two_standard_errors() {
    let base = fig26();
    recovers(
        WoodpeckerParams {
            mu_d: 0.34,
            z0: 0.0068,
            d0: 0.0093,
            ..base
        },
        &["mu_d", "z0", "d0"],
        1,
    );
    // Above the 7.07 mm of Fig. 16: no intermediate halt.
    recovers(
        WoodpeckerParams {
            mu_d: 0.325,
            z0: 0.00715,
            d0: 0.0098,
            ..base
        },
        &["mu_d", "z0", "d0"],
        2,
    );
}

/// The standard errors are the spread of the estimates: over 100 noise seeds the estimates
/// fall within 2 standard errors of the truth about 95 % of the time, and (estimate − truth)/σ̂
/// has unit spread. (Measured over 300 seeds: coverage 94.3–95.7 %, spread 0.99–1.06.)
#[test]
fn standard_errors_match_the_scatter_over_noise_seeds() {
    let start = fig26();
    let truth = WoodpeckerParams {
        mu_d: 0.34,
        z0: 0.0068,
        d0: 0.0093,
        ..start
    };
    let seeds = 100;
    let mut z: Vec<Vec<f64>> = vec![Vec::new(); 5];
    for seed in 0..seeds {
        let track = synthetic(truth, 1000 + seed).generate().unwrap();
        let text = track.csv(Unit::Mm, "synthetic");
        let data = parse(&text, Path::new("track.csv"), &ReadOptions::default()).unwrap();
        let fit = fit::fit(&data, &start, &FitParam::DEFAULT).unwrap();
        assert!(fit.converged, "seed {seed}: {}", fit.termination);
        let exact = [
            truth.mu_d,
            truth.z0,
            truth.d0,
            track.time_shift,
            track.y_offset,
        ];
        for (i, e) in fit.estimates.iter().enumerate() {
            z[i].push((e.value - exact[i]) / e.std_error.unwrap());
        }
    }
    for (i, zi) in z.iter().enumerate() {
        let inside = zi.iter().filter(|z| z.abs() < 2.0).count();
        let spread = (zi.iter().map(|z| z * z).sum::<f64>() / zi.len() as f64).sqrt();
        assert!(
            (88..=100).contains(&inside),
            "estimate {i}: {inside} of {seeds}"
        );
        assert!(
            (0.8..1.25).contains(&spread),
            "estimate {i}: spread {spread}"
        );
    }
}

#[test]
fn mu_s_and_k_are_recovered_too_with_d0_fixed() {
    recovers(
        WoodpeckerParams {
            mu_s: 0.62,
            mu_d: 0.33,
            k: 21.0,
            z0: 0.0070,
            d0: 0.0096,
            ..fig26()
        },
        &["mu_d", "z0", "mu_s", "k"],
        3,
    );
}

/// k sets the period: over 100 tracked periods (500 frames at 30 fps) a start 10 % off in k is
/// 5 periods out of step, yet the fit finds k from the data's own period. With k fixed at the
/// wrong value the fit says why it fails.
#[test]
fn k_far_off_is_found_from_the_period_of_the_data() {
    let tmp = tempfile::tempdir().unwrap();
    let truth = WoodpeckerParams {
        mu_d: 0.34,
        ..fig26()
    };
    let slow = Synthetic {
        frame_rate: 30.0,
        ..synthetic(truth, 6)
    };
    let file = write(
        tmp.path(),
        "slow.csv",
        &slow.generate().unwrap().csv(Unit::Mm, "30 fps"),
    );
    for k in ["18.3", "22.3"] {
        let args = ["--scenario", FIG26, "--k", k, "--free", "mu_d,z0,d0,k"].map(String::from);
        let json = fit_json(&file, &tmp.path().join(k), &args);
        assert_eq!(json["converged"], true, "{json}");
        let (name, fitted, se) = estimates(&json)[3].clone();
        assert_eq!(name, "k");
        assert!((fitted - truth.k).abs() < 2.0 * se, "k = {fitted} ± {se}");
    }
    let output = stickslip()
        .arg("fit")
        .arg(&file)
        .args(["--scenario", FIG26, "--k", "21", "--out"])
        .arg(tmp.path().join("fixed"))
        .output()
        .unwrap();
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(
        stdout.contains("warning: the data repeat every 0.1650 s, the model every 0.1622 s"),
        "{stdout}"
    );
}

/// With μs, μd, z0 and d0 all free the position data hardly separate them: the fit says so.
#[test]
fn all_five_free_is_reported_as_poorly_determined() {
    let tmp = tempfile::tempdir().unwrap();
    let truth = WoodpeckerParams {
        mu_d: 0.34,
        ..fig26()
    };
    let track = synthetic(truth, 4).generate().unwrap();
    let file = write(tmp.path(), "track.csv", &track.csv(Unit::Mm, "synthetic"));
    let output = stickslip()
        .arg("fit")
        .arg(&file)
        .args(["--scenario", FIG26, "--free", "mu_d,z0,d0,mu_s,k", "--out"])
        .arg(tmp.path().join("fit"))
        .output()
        .unwrap();
    let stdout = String::from_utf8(output.stdout).unwrap();
    assert!(
        stdout.contains(" and z0 are correlated at r = ") && stdout.contains("correlations:"),
        "{stdout}"
    );
    let json = read_json(&tmp.path().join("fit/fit.json"));
    let z0 = &estimates(&json)[1];
    assert_eq!(z0.0, "z0");
    let converged = json["converged"].as_bool().unwrap();
    // Either LM gives up (exit 1, results flagged) or z0 comes with a large error.
    assert_eq!(output.status.code(), Some(if converged { 0 } else { 1 }));
    assert!(!converged || z0.2 > 0.05 * z0.1, "{json}");
}

#[test]
fn units_and_column_choices_give_the_same_fit() {
    let tmp = tempfile::tempdir().unwrap();
    let truth = WoodpeckerParams {
        mu_d: 0.335,
        ..fig26()
    };
    let track = synthetic(truth, 5).generate().unwrap();
    let scenario = ["--scenario".to_string(), FIG26.to_string()];
    let reference = fit_json(
        &write(tmp.path(), "mm.csv", &track.csv(Unit::Mm, "mm")),
        &tmp.path().join("mm"),
        &scenario,
    );
    let params = |j: &Value| {
        estimates(j)
            .into_iter()
            .map(|e| (e.0, e.1))
            .collect::<Vec<_>>()
    };
    // A Tracker-style file in metres: title line, t,x,y, units in no row at all.
    let mut tracker = String::from("mass A\nt,x,y\n");
    for (t, y) in track.t.iter().zip(&track.y) {
        tracker.push_str(&format!("{t:.6},0.0123,{y:.7}\n"));
    }
    let tracker = write(tmp.path(), "tracker.csv", &tracker);
    // A Kinovea-style file: ';' separators, decimal commas, y in mm in the header.
    let mut kinovea = String::from("# Kinovea export\nTime;Y (mm);X (mm)\n");
    for (t, y) in track.t.iter().zip(&track.y) {
        kinovea.push_str(&format!("{t:.6};{:.4};12,3\n", y * 1e3).replace('.', ","));
    }
    let kinovea = write(tmp.path(), "kinovea.csv", &kinovea);
    let runs: [(&Path, &[&str]); 5] = [
        (&tracker, &[]),
        (&tracker, &["--columns", "t,y"]),
        (&tracker, &["--columns", "1,3"]),
        (&kinovea, &["--columns", "time,Y"]),
        (&kinovea, &[]),
    ];
    for (i, (file, extra)) in runs.iter().enumerate() {
        let mut args = scenario.to_vec();
        args.extend(extra.iter().map(|s| s.to_string()));
        let json = fit_json(file, &tmp.path().join(format!("run{i}")), &args);
        for ((name, a), (_, b)) in params(&json).iter().zip(params(&reference)) {
            assert!(
                (a - b).abs() <= 1e-6 * b.abs(),
                "run {i} {name}: {a} against {b}"
            );
        }
    }
    // No unit declared: metres unless --units says otherwise.
    let mut bare = String::from("t,y\n");
    for (t, y) in track.t.iter().zip(&track.y) {
        bare.push_str(&format!("{t:.6},{:.4}\n", y * 1e3));
    }
    let bare = write(tmp.path(), "bare.csv", &bare);
    let args = [scenario.to_vec(), vec!["--units".into(), "mm".into()]].concat();
    let json = fit_json(&bare, &tmp.path().join("bare"), &args);
    assert_eq!(json["data"]["unit"], "mm");
    assert_eq!(params(&json), params(&reference));
}

#[test]
fn outputs_are_the_table_the_csv_and_the_overlay_figure() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("fit");
    let assert = stickslip()
        .args(["fit", EXAMPLE, "--scenario", FIG26, "--out"])
        .arg(&out)
        .assert()
        .success();
    let stdout = String::from_utf8(assert.get_output().stdout.clone()).unwrap();
    for want in [
        "500 points",
        "converged",
        "mu_d",
        "z0 (mm)",
        "d0 (mm)",
        "time_shift (s)",
        "(nuisance)",
        "RMS",
        "fit.svg",
        "correlations:",
        // The example's z0 and d0 correlate at 0.98, μd and d0 at −0.96: one parameter to fix
        // separates both pairs.
        "warning: z0 and d0 are correlated at r = 0.98",
        "warning: mu_d and d0 are correlated at r = −0.96",
        "Fix d0 at a measured value",
    ] {
        assert!(stdout.contains(want), "{want}: {stdout}");
    }
    let csv = fs::read_to_string(out.join("fit.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("t_s,y_data_mm,y_model_mm,residual_mm"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|c| c.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 500);
    for r in &rows {
        assert!((r[2] - r[1] - r[3]).abs() < 1e-9, "{r:?}");
        assert!(r[3].abs() < 1.0, "{r:?}");
    }
    let svg = fs::read_to_string(out.join("fit.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("tracked") && svg.contains("model − data"));
    // The tracked data are points (and the residuals too), the model a line.
    assert!(
        svg.matches("<circle").count() >= 1000,
        "data drawn as points"
    );
    assert!(!stdout.contains("Fix z0"), "{stdout}");
    let json = read_json(&out.join("fit.json"));
    assert_eq!(
        (json["n"].as_u64(), json["p"].as_u64()),
        (Some(500), Some(5))
    );
    assert_eq!(json["axis"], "up");
    let corr = json["correlation"].as_array().unwrap();
    assert_eq!(corr.len(), 5);
    assert!((corr[0][0].as_f64().unwrap() - 1.0).abs() < 1e-12);
}

#[test]
fn the_same_input_gives_the_same_bytes() {
    let tmp = tempfile::tempdir().unwrap();
    let run = |name: &str| {
        let out = tmp.path().join(name);
        let stdout = stickslip()
            .args(["fit", EXAMPLE, "--scenario", FIG26, "--json", "--out"])
            .arg(&out)
            .assert()
            .success()
            .get_output()
            .stdout
            .clone();
        let files: Vec<Vec<u8>> = ["fit.json", "fit.csv", "fit.svg"]
            .iter()
            .map(|f| fs::read(out.join(f)).unwrap())
            .collect();
        (stdout, files)
    };
    assert_eq!(run("a"), run("b"));
}

/// The example file is what the generator writes (regenerate with
/// `STICKSLIP_WRITE_EXAMPLE=1 cargo test --release --test fit example`).
#[test]
fn the_example_file_is_the_generators_output() {
    let example = Synthetic::example();
    let comment = format!(
        "{}\nRegenerate: STICKSLIP_WRITE_EXAMPLE=1 cargo test --release --test fit example\n\
         Try: stickslip fit scenarios/tracked-toy-example.csv --scenario \
         scenarios/fig26-tracked-toy.toml",
        example.provenance()
    );
    let text = example.generate().unwrap().csv(Unit::Mm, &comment);
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(EXAMPLE);
    if std::env::var_os("STICKSLIP_WRITE_EXAMPLE").is_some() {
        fs::write(&path, &text).unwrap();
    }
    assert_eq!(fs::read_to_string(&path).unwrap(), text);
}

/// Runs a fit that must be refused (`common::refused`) with `want` in its one line.
fn refused(file_text: &str, extra: &[&str], want: &str) {
    let tmp = tempfile::tempdir().unwrap();
    let file = write(tmp.path(), "bad.csv", file_text);
    let mut cmd = stickslip();
    cmd.arg("fit").arg(&file).args(extra);
    let stderr = common::refused(cmd);
    assert!(stderr.contains(want), "wanted {want}: {stderr}");
}

#[test]
fn bad_files_are_refused_with_the_line_and_the_problem() {
    let rows = |n: usize| -> String {
        (0..n)
            .map(|i| format!("{},{}\n", i as f64 / 240.0, 100.0 - i as f64 * 0.1))
            .collect()
    };
    refused(&rows(20), &[], "line 1: no header");
    refused(
        &format!("t,y\n{}", rows(7)),
        &[],
        "line 8: only 7 data rows (lines 2-8); a fit needs at least 10",
    );
    refused(
        &format!("t,y\n{}0.1,abc\n{}", rows(15), rows(0)),
        &[],
        "line 17, column y: 'abc' is not a number",
    );
    refused(
        &format!("t,y\n{}0.01,3\n", rows(15)),
        &[],
        "line 17: time not strictly increasing",
    );
    // Rows with a blank cell are skipped, and counted when too few are left.
    refused(
        &format!("t,y\n{}1,\n,3\n", rows(8)),
        &[],
        "line 11: only 8 data rows (lines 2-11) (2 skipped for a blank cell in a used column)",
    );
    refused(
        &format!("t,y\n{}", rows(15)),
        &["--columns", "t,height"],
        "line 1: no column named 'height' in the header (t, y)",
    );
    refused(
        &format!("t,y\n{}", rows(15)),
        &["--columns", "1,4"],
        "line 1: column 4 does not exist",
    );
    refused(
        &format!("t,y\n{}", rows(15)),
        &["--columns", "0,1"],
        "--columns",
    );
    refused(
        &format!("t,y\n{}", rows(15)),
        &["--free", "mu_d,lambda"],
        "--free",
    );
    refused(
        &format!("t,y\n{}", rows(15)),
        &["--periods", "3"],
        "--periods",
    );
    refused(
        &format!("t,y\n{}", rows(15)),
        &["--mu-d", "0.9"],
        "mu_d = 0.9",
    );
    let flat: String = (0..15).map(|i| format!("{i},5\n")).collect();
    refused(&format!("t,y\n{flat}"), &[], "no descent to fit");
}

#[test]
fn a_missing_file_is_named() {
    stickslip()
        .args(["fit", "no/such/file.csv"])
        .assert()
        .code(2)
        .stderr(predicates::str::contains("tracked data no/such/file.csv"));
}

#[test]
fn fixed_parameters_that_cannot_describe_the_data_are_an_unconverged_fit_not_bad_input() {
    // k = 1000 N/m makes the model's period ~7× shorter than the track's: from the given start
    // the search runs out of the model's range (d0 → 0), from the spread around it it stops
    // where the model does not move at all (JᵀJ singular). That is a failed fit (exit 1), not
    // a bad parameter; what is written is flagged.
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("fit");
    let output = stickslip()
        .args(["fit", EXAMPLE, "--k", "1000", "--out"])
        .arg(&out)
        .assert()
        .code(1)
        .get_output()
        .clone();
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    assert!(stderr.contains("the fit did not converge"), "{stderr}");
    if out.exists() {
        let json = read_json(&out.join("fit.json"));
        assert_eq!(json["converged"], false, "{json}");
        assert_eq!(json["verdict"]["describes"], false, "{json}");
    }
}

/// Issue 25's wrong basin: data made with μd 0.30, z0 7.5 mm, d0 9.8 mm (the rest as the
/// Figs. 26–27 scenario), fitted from the scenario's values (μd 0.332, z0 7.0 mm, d0 9.5 mm).
fn wrong_basin_truth() -> WoodpeckerParams {
    WoodpeckerParams {
        mu_d: 0.30,
        z0: 0.0075,
        d0: 0.0098,
        ..fig26()
    }
}

/// A Tracker export of `track` in cm with no units row (title, `t,x,y`), the cells of `x` and
/// `y` blank in the frames listed in `unmarked` (Tracker leaves a frame without a mark blank).
fn tracker_cm(
    track: &stickslip::models::woodpecker::fit::synthetic::SyntheticTrack,
    unmarked: &[usize],
) -> String {
    let mut text = String::from("mass A\nt,x,y\n");
    for (i, (t, y)) in track.t.iter().zip(&track.y).enumerate() {
        if unmarked.contains(&i) {
            text.push_str(&format!("{t:.6},,\n"));
        } else {
            text.push_str(&format!("{t:.6},1.23,{:.5}\n", y * 100.0));
        }
    }
    text
}

/// Writes issue 25's example files into `$STICKSLIP_FIT_CASES` (for the before/after runs):
/// `wrong-basin-N.csv` (N = 1..8, noise seeds), `tracker-cm.csv` (with blank cells),
/// `tracker-cm-whole.csv`, and files whose declared unit is 10, 100 or 1000 times off.
#[test]
#[ignore = "writes files; run with STICKSLIP_FIT_CASES=dir"]
fn write_issue_25_cases() {
    let dir = PathBuf::from(std::env::var_os("STICKSLIP_FIT_CASES").expect("a folder"));
    fs::create_dir_all(&dir).unwrap();
    for seed in 1..=8 {
        let track = synthetic(wrong_basin_truth(), seed).generate().unwrap();
        write(
            &dir,
            &format!("wrong-basin-{seed}.csv"),
            &track.csv(Unit::Mm, "issue 25"),
        );
    }
    let track = Synthetic::example().generate().unwrap();
    write(
        &dir,
        "tracker-cm.csv",
        &tracker_cm(&track, &[8, 9, 200, 201, 202]),
    );
    write(&dir, "tracker-cm-whole.csv", &tracker_cm(&track, &[]));
    for (name, unit, declared) in [
        ("mm-as-m", Unit::Mm, "m"),
        ("cm-as-mm", Unit::Cm, "mm"),
        ("mm-as-cm", Unit::Mm, "cm"),
    ] {
        let text = track
            .csv(unit, name)
            .replace(&format!("s,{}", unit.symbol()), &format!("s,{declared}"));
        write(&dir, &format!("{name}.csv"), &text);
    }
}

/// The grid of truths of [`a_grid_of_known_parameters_is_recovered_or_declared_not_described`]:
/// μd, z0 (mm), d0 (mm) around the Figs. 26–27 values (μd 0.332, z0 7.0, d0 9.5), the rest as
/// the scenario. μd 0.26 is continuous slip, z0 8.0 beyond the 7.07 mm of Fig. 16, μd 0.44 a
/// third above the start: outside the ±15 % spread of the starts.
const GRID_MU_D: [f64; 5] = [0.26, 0.29, 0.32, 0.36, 0.44];
const GRID_Z0_MM: [f64; 3] = [6.4, 7.2, 8.0];
const GRID_D0_MM: [f64; 2] = [9.0, 10.0];
/// A wrong minimum lies many standard errors from the truth (issue 25's: μd 0.322 for 0.30,
/// 12 standard errors of the true minimum's); a recovered value lies within 2 standard errors
/// 95 % of the time. Every value must be within 3, and [`MIN_WITHIN_TWO`] of them within 2.
const MAX_Z: f64 = 3.0;
const MIN_WITHIN_TWO: f64 = 0.9;

/// (estimate − truth)/standard error of the three physical estimates.
fn z_scores(f: &fit::Fit, exact: [f64; 3]) -> Vec<f64> {
    f.estimates[..3]
        .iter()
        .zip(exact)
        .map(|(e, x)| (e.value - x) / e.std_error.expect("standard error"))
        .collect()
}

/// Synthetic tracks from a grid of known parameters (5 μd × 3 z0 × 2 d0, 500 frames at 240
/// fps, σ = 0.2 mm, one noise seed each), every one fitted from the Figs. 26–27 scenario's
/// values: each fit either recovers the truth (every value within [`MAX_Z`] standard errors,
/// and 90 % of them within 2) with a verdict that the model describes the data, or has a
/// negative verdict (exit 3) or fails to converge (exit 1). Never a wrong minimum reported as
/// a description.
///
/// Not the joint 2σ region of the three: z0, d0 and μd correlate at 0.93–0.99, and along the
/// thin direction of their ellipsoid the linearized covariance is too narrow (issue 25's seed 1
/// recovers every value within 1.7 standard errors, yet its squared Mahalanobis distance is 34,
/// where 8 is 2σ). The marginal errors are honest
/// (`standard_errors_match_the_scatter_over_noise_seeds`).
#[test]
fn a_grid_of_known_parameters_is_recovered_or_declared_not_described() {
    let start = fig26();
    let mut seed = 2500;
    let (mut recovered, mut declared, mut within_two) = (0, 0, 0);
    for mu_d in GRID_MU_D {
        for z0 in GRID_Z0_MM {
            for d0 in GRID_D0_MM {
                seed += 1;
                let truth = WoodpeckerParams {
                    mu_d,
                    z0: z0 * 1e-3,
                    d0: d0 * 1e-3,
                    ..start
                };
                let track = synthetic(truth, seed).generate().unwrap();
                let text = track.csv(Unit::Mm, "grid");
                let data = parse(&text, Path::new("grid.csv"), &ReadOptions::default()).unwrap();
                let f = fit::fit(&data, &start, &FitParam::DEFAULT).unwrap();
                let case = format!(
                    "mu_d {mu_d}, z0 {z0} mm, d0 {d0} mm (seed {seed}): {}; {}",
                    f.termination,
                    f.verdict.sentence()
                );
                if !(f.converged && f.verdict.describes) {
                    declared += 1;
                    eprintln!("declared: {case}");
                    continue;
                }
                let z = z_scores(&f, [truth.mu_d, truth.z0, truth.d0]);
                eprintln!("recovered? z = {z:.2?}: {case}");
                assert!(
                    z.iter().all(|z| z.abs() <= MAX_Z),
                    "a wrong minimum described as a fit: z = {z:?}, {case}"
                );
                within_two += z.iter().filter(|z| z.abs() <= 2.0).count();
                recovered += 1;
            }
        }
    }
    eprintln!("{recovered} recovered, {declared} declared not described or not converged");
    let share = within_two as f64 / (3 * recovered) as f64;
    assert!(
        share >= MIN_WITHIN_TWO,
        "{share} of the values within 2 standard errors"
    );
    // The grid lies mostly within reach of the starts: most truths must be recovered.
    assert!(recovered >= 24, "{recovered} of 30 recovered");
}

/// Issue 25: data made with μd 0.30, z0 7.5 mm, d0 9.8 mm and fitted from the Figs. 26–27
/// scenario ended, from the given start alone, in a wrong minimum on 7 of 8 noise seeds (RMS
/// 14–17× σ, autocorrelation 0.99) reported as converged. From the spread of starts all 8
/// recover the truth; a fit that did not would have to say so (exit 3).
#[test]
fn the_wrong_basin_of_issue_25_is_left_for_the_true_minimum() {
    let start = fig26();
    let truth = wrong_basin_truth();
    for seed in 1..=8 {
        let track = synthetic(truth, seed).generate().unwrap();
        let text = track.csv(Unit::Mm, "issue 25");
        let data = parse(&text, Path::new("track.csv"), &ReadOptions::default()).unwrap();
        let f = fit::fit(&data, &start, &FitParam::DEFAULT).unwrap();
        assert!(f.converged && f.verdict.describes, "seed {seed}: {f:?}");
        let z = z_scores(&f, [truth.mu_d, truth.z0, truth.d0]);
        assert!(z.iter().all(|z| z.abs() <= MAX_Z), "seed {seed}: z = {z:?}");
        assert!((f.rms_residual / 2e-4 - 1.0).abs() < 0.1, "seed {seed}");
    }
}

/// A Tracker export in cm with no units row is read in metres: the data fall 100× faster than
/// the model. The fit says the model does not describe them as read and names `--units cm`,
/// with which it does (exit 3, files written and flagged); with `--units cm` the fit is the
/// mm file's. Frames without a mark (blank cells) are skipped and counted.
#[test]
fn tracker_positions_in_cm_read_as_metres_are_a_unit_slip_named_with_its_units() {
    let tmp = tempfile::tempdir().unwrap();
    let track = Synthetic::example().generate().unwrap();
    let file = write(
        tmp.path(),
        "tracker.csv",
        &tracker_cm(&track, &[8, 9, 200, 201, 202]),
    );
    let out = tmp.path().join("as-read");
    let output = stickslip()
        .arg("fit")
        .arg(&file)
        .args(["--scenario", FIG26, "--out"])
        .arg(&out)
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(3));
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert_eq!(stderr.trim_end().lines().count(), 1, "{stderr}");
    assert!(
        stderr.contains("does not describe these data as read (positions 100× too large); with --units cm it does"),
        "{stderr}"
    );
    let stdout = String::from_utf8(output.stdout).unwrap();
    for want in [
        "495 points (5 rows skipped for a blank cell in the time or position column, the first on line 11)",
        "verdict:  THE MODEL DOES NOT DESCRIBE THESE DATA",
    ] {
        assert!(stdout.contains(want), "{want}: {stdout}");
    }
    // No advice on which parameter to fix for a fit that describes nothing.
    assert!(!stdout.contains("Fix "), "{stdout}");
    let json = read_json(&out.join("fit.json"));
    assert_eq!(json["verdict"]["describes"], false);
    assert_eq!(json["verdict"]["scale"]["units"], "cm");
    assert_eq!(json["data"]["skipped_rows"], 5);
    let args = ["--scenario", FIG26, "--units", "cm"].map(String::from);
    let json = fit_json(&file, &tmp.path().join("cm"), &args);
    assert_eq!(json["verdict"]["describes"], true, "{json}");
    assert_eq!(json["verdict"]["scale"], Value::Null);
    let rms = json["rms_residual"].as_f64().unwrap();
    assert!((rms / 2e-4 - 1.0).abs() < 0.1, "rms {rms}");
}

/// Positions 10× and 1000× off the model (the declared unit wrong, or none) are named with the
/// `--units` that fits, both ways. A 10× slip scales the noise too, and the data as read are
/// then loosely described (RMS 1.4σ̂, autocorrelation 0.3–0.45): the unit that makes the
/// residual noise is preferred.
#[test]
fn positions_ten_or_a_thousand_times_off_name_the_units_that_fit() {
    let tmp = tempfile::tempdir().unwrap();
    let track = Synthetic::example().generate().unwrap();
    for (written, declared, want) in [
        (
            Unit::Mm,
            "m",
            "positions 1000× too large); with --units mm it does",
        ),
        (
            Unit::Cm,
            "mm",
            "positions 10× too small); with --units cm it does",
        ),
        (
            Unit::Mm,
            "cm",
            "positions 10× too large); with --units mm it does",
        ),
    ] {
        let text = track
            .csv(written, "slip")
            .replace(&format!("s,{}", written.symbol()), &format!("s,{declared}"));
        let file = write(tmp.path(), &format!("{declared}.csv"), &text);
        let output = stickslip()
            .arg("fit")
            .arg(&file)
            .args(["--scenario", FIG26, "--out"])
            .arg(tmp.path().join(declared))
            .output()
            .unwrap();
        let stderr = String::from_utf8(output.stderr).unwrap();
        assert_eq!(output.status.code(), Some(3), "{declared}: {stderr}");
        assert!(stderr.contains(want), "{declared}: {stderr}");
    }
}
