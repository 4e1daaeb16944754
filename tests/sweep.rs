//! `stickslip sweep` as a user runs it: the woodpecker's double slip-stick giving way to the
//! double slip without intermediate halt near z0 = 7.0746 mm (the paper's "critically related
//! with small changes of the parameters"), the files written, invalid grid points kept as rows,
//! and every bad request refused (exit 2, one line naming the parameter, nothing written).

mod common;

use std::fs;

use assert_cmd::Command;

/// The harmonic woodpecker's regime boundary in z0 (m) for the Fig. 15 set, from a
/// 100000-point sweep: between 7.074646e-3 and 7.074650e-3.
const Z0_CRITICAL: f64 = 7.0746e-3;

fn stickslip() -> Command {
    Command::cargo_bin("stickslip").unwrap()
}

#[test]
fn the_harmonic_double_slip_stick_ends_near_the_critical_z0() {
    let tmp = tempfile::tempdir().unwrap();
    let out = tmp.path().join("sweep");
    let assert = stickslip()
        .args([
            "sweep",
            "woodpecker",
            "--param",
            "z0",
            "--from",
            "6.9e-3",
            "--to",
            "7.3e-3",
            "--steps",
            "50",
            "--out",
        ])
        .arg(&out)
        .assert()
        .success();
    let stdout = String::from_utf8(assert.get_output().stdout.clone()).unwrap();
    assert_eq!(stdout.lines().count(), 1, "{stdout}");
    assert!(
        stdout.contains("50 points") && stdout.contains(
                "two slips and two sticks per period -> one slip per period that slows down without stopping in between"
            ),
        "{stdout}"
    );
    assert!(
        out.join("sweep.svg").exists()
            && fs::read_to_string(out.join("sweep.svg"))
                .unwrap()
                .starts_with("<svg")
    );

    let (header, rows) = common::read_csv(&out.join("sweep.csv"));
    assert_eq!(
        header,
        [
            "z0_m",
            "v_avg_harmonic_m_s",
            "slips_harmonic",
            "sticks_harmonic",
            "regime_harmonic",
            "v_avg_linear_m_s",
            "slips_linear",
            "sticks_linear",
            "regime_linear",
            "regime_closed_form"
        ]
    );
    assert_eq!(rows.len(), 50);
    let z0: Vec<f64> = rows.iter().map(|r| r[0].parse().unwrap()).collect();
    assert_eq!((z0[0], z0[49]), (6.9e-3, 7.3e-3));
    let regime: Vec<&str> = rows.iter().map(|r| r[4].as_str()).collect();
    // One change only, from the double slip-stick to the double slip without halt.
    let changes: Vec<usize> = (1..50).filter(|&i| regime[i] != regime[i - 1]).collect();
    assert_eq!(changes.len(), 1, "{regime:?}");
    let i = changes[0];
    assert_eq!(
        (regime[i - 1], regime[i]),
        ("double_slip_stick", "double_slip_no_halt")
    );
    assert!(
        z0[i - 1] < Z0_CRITICAL && Z0_CRITICAL < z0[i],
        "change between {} and {}",
        z0[i - 1],
        z0[i]
    );
    // The slip count follows the regime: two slips and sticks before, one slip after.
    assert_eq!((rows[0][2].as_str(), rows[0][3].as_str()), ("2", "2"));
    assert_eq!(rows[49][2], "1");
    for row in &rows {
        let v: f64 = row[1].parse().unwrap();
        assert!(v > 0.0 && v < 0.1, "{row:?}");
    }
}

#[test]
fn invalid_grid_points_are_rows_not_errors() {
    let tmp = tempfile::tempdir().unwrap();
    // μs = 0.4: the points with μd > 0.4 are invalid.
    stickslip()
        .args([
            "sweep",
            "pulled-mass",
            "--param",
            "mu_d",
            "--from",
            "0.1",
            "--to",
            "0.6",
            "--steps",
            "11",
            "--out",
        ])
        .arg(tmp.path())
        .assert()
        .success();
    let (header, rows) = common::read_csv(&tmp.path().join("sweep.csv"));
    assert_eq!(header[0], "mu_d");
    assert_eq!(rows.len(), 11);
    for row in &rows {
        let mu_d: f64 = row[0].parse().unwrap();
        if mu_d > 0.4 {
            assert_eq!(row[1..4], ["", "", ""], "{row:?}");
            assert_eq!(row[4], "invalid");
            assert_eq!(row[9], "invalid");
        } else {
            assert_ne!(row[4], "invalid", "{row:?}");
            assert!(row[2].parse::<u32>().is_ok(), "{row:?}");
        }
    }
}

/// Runs a sweep that must be refused (`common::refused`) with `name` in its one line.
fn refused(args: &[&str], name: &str) {
    let mut cmd = stickslip();
    cmd.args(args);
    let stderr = common::refused(cmd);
    assert!(stderr.contains(name), "{args:?}: {stderr}");
}

#[test]
fn bad_requests_are_refused_with_one_line_naming_the_parameter() {
    let sweep = |param: &str, from: &str, to: &str, steps: &str| {
        [
            "sweep",
            "woodpecker",
            "--param",
            param,
            "--from",
            from,
            "--to",
            to,
            "--steps",
            steps,
        ]
        .map(String::from)
    };
    let cases = [
        (sweep("mass", "1", "2", "10"), "param"),
        (sweep("omega", "1", "2", "10"), "param"),
        (sweep("z0", "1", "2", "1"), "--steps"),
        (sweep("z0", "1", "2", "100001"), "--steps"),
        (sweep("z0", "nan", "2", "10"), "from"),
        (sweep("z0", "1", "inf", "10"), "to"),
        (sweep("z0", "1e-3", "1e-3", "10"), "to"),
        // Every point invalid: the parameter is named.
        (sweep("k", "-2", "-1", "10"), "k = -2"),
    ];
    for (args, name) in &cases {
        let args: Vec<&str> = args.iter().map(String::as_str).collect();
        refused(&args, name);
    }
    refused(
        &[
            "sweep",
            "pulled-mass",
            "--param",
            "mu_s",
            "--from",
            "0.3",
            "--to",
            "0.5",
            "--steps",
            "5",
            "--json",
        ],
        "--json",
    );
}
