//! `stickslip eval ... --csv DIR` as a user runs it: the four files of the pulled mass set B,
//! their headers with units, rows in time order, the stick state consistent with v = 0, the
//! events agreeing with the JSON's steady events, the woodpecker's y_W column, and a bad target
//! (exit 2, one line, nothing written).

mod common;

use std::fs;
use std::path::Path;

use assert_cmd::Command;
use serde_json::Value;

const SET_B: &str = "scenarios/set-b-slip-stick.toml";
const LAWS: [&str; 2] = ["harmonic", "linear"];

fn stickslip() -> Command {
    let mut cmd = Command::cargo_bin("stickslip").unwrap();
    cmd.current_dir(env!("CARGO_MANIFEST_DIR"));
    cmd
}

fn f(cell: &str) -> f64 {
    cell.parse()
        .unwrap_or_else(|e| panic!("cell {cell:?} is not a number: {e}"))
}

fn eval_set_b(dir: &Path, json: bool) -> Vec<u8> {
    let mut cmd = stickslip();
    cmd.args(["eval", "pulled-mass", "--scenario", SET_B, "--csv"])
        .arg(dir);
    if json {
        cmd.arg("--json");
    }
    cmd.assert().success().get_output().stdout.clone()
}

#[test]
fn eval_with_csv_writes_the_four_files_with_units_in_the_headers() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path().join("csv");
    let stdout = eval_set_b(&dir, false);
    assert!(!stdout.is_empty(), "the normal output is still printed");
    let mut names: Vec<_> = fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        [
            "events_harmonic.csv",
            "events_linear.csv",
            "timeseries_harmonic.csv",
            "timeseries_linear.csv"
        ]
    );
    for law in LAWS {
        let (header, rows) = common::read_csv(&dir.join(format!("timeseries_{law}.csv")));
        assert_eq!(header, ["t_s", "x_m", "v_m_s", "a_m_s2", "stuck"]);
        // 8 periods × 200 uniform points + the end + the event times.
        assert!(rows.len() > 1600, "{law}: {} rows", rows.len());
        let (header, rows) = common::read_csv(&dir.join(format!("events_{law}.csv")));
        assert_eq!(header, ["t_s", "kind", "phase", "x_m", "v_m_s"]);
        assert!(!rows.is_empty());
    }
}

#[test]
fn time_series_rows_are_in_time_order_and_stuck_means_v_zero() {
    let tmp = tempfile::tempdir().unwrap();
    eval_set_b(tmp.path(), false);
    for law in LAWS {
        let (_, rows) = common::read_csv(&tmp.path().join(format!("timeseries_{law}.csv")));
        let mut last_t = f64::NEG_INFINITY;
        let (mut stuck_rows, mut moving_rows) = (0, 0);
        for row in &rows {
            assert_eq!(row.len(), 5, "{law}: {row:?}");
            let (t, v, a) = (f(&row[0]), f(&row[2]), f(&row[3]));
            assert!(t > last_t, "{law}: t = {t} after {last_t}");
            last_t = t;
            match row[4].as_str() {
                "1" => {
                    assert_eq!((v, a), (0.0, 0.0), "{law}: stuck at t = {t} with v = {v}");
                    stuck_rows += 1;
                }
                "0" => moving_rows += 1,
                other => panic!("{law}: stuck = {other:?}"),
            }
            if v != 0.0 {
                assert_eq!(row[4], "0", "{law}: moving at t = {t} but marked stuck");
            }
        }
        // Set B is slip-stick: both states occur every period.
        assert!(stuck_rows > 100 && moving_rows > 100, "{law}");
    }
}

#[test]
fn event_phases_match_the_steady_events_of_the_json_output() {
    let tmp = tempfile::tempdir().unwrap();
    let json: Value = serde_json::from_slice(&eval_set_b(tmp.path(), true)).unwrap();
    for law in LAWS {
        let (_, rows) = common::read_csv(&tmp.path().join(format!("events_{law}.csv")));
        let times: Vec<f64> = rows.iter().map(|r| f(&r[0])).collect();
        assert!(
            times.windows(2).all(|w| w[0] <= w[1]),
            "{law}: events sorted"
        );
        let steady = json[law]["steady_events"].as_array().unwrap();
        assert_eq!(
            steady.len(),
            2,
            "{law}: set B slips and sticks once a period"
        );
        for event in steady {
            let t = event["t"].as_f64().unwrap();
            let row = rows
                .iter()
                .find(|r| (f(&r[0]) - t).abs() <= 1e-12 * t)
                .unwrap_or_else(|| panic!("{law}: no CSV event at t = {t}"));
            assert_eq!(row[1], event["kind"].as_str().unwrap(), "{law} at t = {t}");
            let phase = event["phase"].as_f64().unwrap();
            assert!(
                (f(&row[2]) - phase).abs() <= 1e-12,
                "{law}: phase {}",
                row[2]
            );
        }
        // Every slip and stick of the last period is in the JSON.
        let period = json["params"]["T"].as_f64().unwrap();
        let last_start = 7.0 * period;
        let last: Vec<_> = rows
            .iter()
            .filter(|r| f(&r[0]) >= last_start && (r[1] == "slip" || r[1] == "stick"))
            .collect();
        assert_eq!(last.len(), steady.len(), "{law}");
    }
}

#[test]
fn the_woodpecker_series_carries_the_bird_coordinate() {
    let tmp = tempfile::tempdir().unwrap();
    stickslip()
        .args(["eval", "woodpecker", "--csv"])
        .arg(tmp.path())
        .assert()
        .success();
    for law in LAWS {
        let (header, rows) = common::read_csv(&tmp.path().join(format!("timeseries_{law}.csv")));
        assert_eq!(
            header,
            ["t_s", "y_m", "v_m_s", "a_m_s2", "stuck", "y_woodpecker_m"]
        );
        // At t = 0 the sleeve is at 0 and the bird at z(0) (harmonic: z0 + d0 = 16 mm).
        assert_eq!(f(&rows[0][1]), 0.0);
        if law == "harmonic" {
            assert!((f(&rows[0][5]) - 0.016).abs() < 1e-15, "{:?}", rows[0]);
        }
        let (header, _) = common::read_csv(&tmp.path().join(format!("events_{law}.csv")));
        assert_eq!(header, ["t_s", "kind", "phase", "y_m", "v_m_s"]);
    }
}

#[test]
fn without_a_linear_law_only_the_harmonic_files_are_written() {
    let tmp = tempfile::tempdir().unwrap();
    stickslip()
        .args(["eval", "woodpecker", "--z0", "0.02", "--csv"])
        .arg(tmp.path())
        .assert()
        .success();
    assert!(tmp.path().join("timeseries_harmonic.csv").exists());
    assert!(tmp.path().join("events_harmonic.csv").exists());
    assert!(!tmp.path().join("timeseries_linear.csv").exists());
    assert!(!tmp.path().join("events_linear.csv").exists());
}

#[test]
fn csv_output_is_deterministic() {
    let (a, b) = (tempfile::tempdir().unwrap(), tempfile::tempdir().unwrap());
    eval_set_b(a.path(), false);
    eval_set_b(b.path(), false);
    for name in ["timeseries_harmonic.csv", "events_linear.csv"] {
        assert_eq!(
            fs::read(a.path().join(name)).unwrap(),
            fs::read(b.path().join(name)).unwrap(),
            "{name}"
        );
    }
}

#[test]
fn a_bad_csv_target_exits_2_with_one_line_and_writes_nothing() {
    let tmp = tempfile::tempdir().unwrap();
    let file = tmp.path().join("a-file");
    fs::write(&file, b"x").unwrap();
    for target in [file.clone(), file.join("sub")] {
        let out = stickslip()
            .args(["eval", "pulled-mass", "--scenario", SET_B, "--csv"])
            .arg(&target)
            .assert()
            .code(2)
            .get_output()
            .clone();
        let stderr = String::from_utf8(out.stderr).unwrap();
        assert_eq!(stderr.lines().count(), 1, "{stderr}");
        assert!(stderr.starts_with("error: cannot write"), "{stderr}");
        assert!(out.stdout.is_empty(), "nothing printed on failure");
    }
    assert_eq!(fs::read(&file).unwrap(), b"x");
    let entries: Vec<_> = fs::read_dir(tmp.path()).unwrap().collect();
    assert_eq!(entries.len(), 1, "nothing but the blocking file");
}

#[test]
fn csv_is_an_option_of_eval_only() {
    let out = stickslip()
        .args(["claims", "pulled-mass", "--csv", "nowhere"])
        .assert()
        .code(2)
        .get_output()
        .clone();
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.contains("--csv"), "{stderr}");
    assert!(!Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("nowhere")
        .exists());
}

/// `--csv-dialect semicolon`: `;` between fields and decimal commas, the same numbers as the
/// standard files, for spreadsheets in comma-decimal locales; refused without `--csv`.
#[test]
fn the_semicolon_dialect_writes_the_same_numbers_for_comma_decimal_spreadsheets() {
    let tmp = tempfile::tempdir().unwrap();
    let (standard, semicolon) = (tmp.path().join("std"), tmp.path().join("semi"));
    eval_set_b(&standard, false);
    stickslip()
        .args(["eval", "pulled-mass", "--scenario", SET_B, "--csv"])
        .arg(&semicolon)
        .args(["--csv-dialect", "semicolon"])
        .assert()
        .success();
    for name in ["timeseries_linear.csv", "events_harmonic.csv"] {
        let a = fs::read_to_string(standard.join(name)).unwrap();
        let b = fs::read_to_string(semicolon.join(name)).unwrap();
        assert_eq!(a.lines().count(), b.lines().count());
        assert!(b.starts_with("t_s;"), "{b}");
        for (la, lb) in a.lines().zip(b.lines()) {
            let (fa, fb): (Vec<&str>, Vec<&str>) =
                (la.split(',').collect(), lb.split(';').collect());
            assert_eq!(fa.len(), fb.len(), "{lb}");
            for (x, y) in fa.iter().zip(&fb) {
                assert!(!y.contains('.'), "{lb}");
                match x.parse::<f64>() {
                    Ok(v) => assert_eq!(y.replace(',', ".").parse::<f64>().unwrap(), v),
                    Err(_) => assert_eq!(x, y),
                }
            }
        }
        // Plain decimals where the magnitude allows: no exponent in a time column.
        assert!(
            b.lines()
                .skip(1)
                .all(|l| !l.split(';').next().unwrap().contains('e')),
            "{name}"
        );
    }
    stickslip()
        .args(["eval", "pulled-mass", "--csv-dialect", "semicolon"])
        .assert()
        .code(2)
        .stderr(predicates::str::contains("--csv-dialect"));
}
