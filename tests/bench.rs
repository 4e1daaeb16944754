//! `stickslip bench --quick` as a user runs it: the command exits 0 and writes a report whose
//! JSON parses with the documented keys and whose CSV has its header; the failures table names
//! every method of the registry; the diffsol peer is swept and the headline names a compiled
//! peer (with the cargo feature `peers`; without it the pages and the failures table say it
//! is not built in); euler_sign's spurious reversals grow as the step shrinks; a
//! sweep point survives a JSON round trip. The quick run is made once and shared; no test reads
//! a timing.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use assert_cmd::Command;
use serde_json::{json, Value};

use stickslip::bench::render::CSV_HEADER;
use stickslip::bench::sweep::SweepPoint;
use stickslip::solver::methods;

/// Top-level keys of results.json.
const TOP_KEYS: [&str; 14] = [
    "quick",
    "repeats",
    "periods",
    "machine",
    "grid",
    "methods",
    "problems",
    "reference_check",
    "sweep",
    "costs",
    "failures",
    "long_runs",
    "peer",
    "elapsed_s",
];
/// Keys of `failures`: the table and the studies behind it.
const FAILURE_KEYS: [&str; 10] = [
    "table",
    "reversals",
    "creep",
    "creep_epsilon",
    "missed",
    "regime",
    "orders",
    "near_tangent",
    "step_boundary",
    "crowding",
];
/// Keys of `machine`.
const MACHINE_KEYS: [&str; 6] = ["crate_version", "profile", "nproc", "cpu", "os", "arch"];

struct QuickRun {
    /// Kept so that the folder lives as long as the tests.
    _dir: tempfile::TempDir,
    out: PathBuf,
    json: Value,
    stderr: String,
}

/// Runs `stickslip bench --quick` once for all tests.
fn quick() -> &'static QuickRun {
    static RUN: OnceLock<QuickRun> = OnceLock::new();
    RUN.get_or_init(|| {
        let dir = tempfile::tempdir().expect("temporary folder");
        let out = dir.path().join("bench");
        let done = Command::cargo_bin("stickslip")
            .expect("binary")
            .args(["bench", "--quick", "--out"])
            .arg(&out)
            .assert()
            .success();
        let stderr = String::from_utf8_lossy(&done.get_output().stderr).into_owned();
        let text = std::fs::read_to_string(out.join("results.json")).expect("results.json");
        let json = serde_json::from_str(&text).expect("results.json parses");
        QuickRun {
            _dir: dir,
            out,
            json,
            stderr,
        }
    })
}

fn array<'a>(v: &'a Value, key: &str) -> &'a Vec<Value> {
    v[key]
        .as_array()
        .unwrap_or_else(|| panic!("{key} is an array"))
}

#[test]
fn quick_bench_writes_json_with_every_key_csv_with_units_and_the_pages() {
    let run = quick();
    for key in TOP_KEYS {
        assert!(run.json.get(key).is_some(), "results.json lacks {key}");
    }
    for key in FAILURE_KEYS {
        assert!(
            run.json["failures"].get(key).is_some(),
            "failures lacks {key}"
        );
    }
    for key in MACHINE_KEYS {
        assert!(
            run.json["machine"].get(key).is_some(),
            "machine lacks {key}"
        );
    }
    assert_eq!(run.json["quick"], Value::Bool(true));
    assert_eq!(
        array(&run.json, "problems").len(),
        5,
        "the paper's four and the belt"
    );

    let csv = std::fs::read_to_string(run.out.join("results.csv")).expect("results.csv");
    let mut lines = csv.lines();
    let header = lines.next().expect("a header");
    assert_eq!(header, CSV_HEADER);
    assert!(header.contains("time_s") && header.contains("err_x_m"));
    assert_eq!(lines.count(), array(&run.json, "sweep").len());

    for page in ["index.html", "bench.md"] {
        let text = std::fs::read_to_string(run.out.join(page)).expect(page);
        assert!(text.contains("Where methods fail"), "{page}");
    }
    let svgs = std::fs::read_dir(run.out.join("figures"))
        .expect("figures/")
        .filter(|e| {
            e.as_ref()
                .is_ok_and(|e| e.path().extension() == Some("svg".as_ref()))
        })
        .count();
    assert_eq!(
        svgs,
        5 * 3 + 3 + 4,
        "work-precision, work and order per problem, 3 failures, 4 long runs"
    );
}

#[test]
fn failures_table_names_every_registered_method_and_the_endpoint_variant() {
    let run = quick();
    let table = array(&run.json["failures"], "table");
    let named = |m: &str| table.iter().any(|r| r["method"] == m);
    for m in methods() {
        assert!(
            named(m.name()),
            "{} missing from the failures table",
            m.name()
        );
    }
    assert!(named("dopri5_endpoints"));
    for r in table {
        let verdict = r["verdict"].as_str().expect("verdict");
        assert!(
            ["fails", "ok", "not available"].contains(&verdict),
            "{verdict}"
        );
    }
}

/// The compiled peer from a Rust ODE library (diffsol's Tsit45 on the tool's event loop) is
/// swept like the other adaptive methods, and the headline compares the exact engine with the
/// fastest compiled peer, named, never with SciPy.
#[cfg(feature = "peers")]
#[test]
fn the_diffsol_peer_is_swept_and_the_headline_names_a_compiled_peer() {
    let run = quick();
    let peer = "diffsol_tsit45";
    assert!(array(&run.json, "methods")
        .iter()
        .any(|m| m["name"] == peer && m["kind"] == "adaptive"));
    let points: Vec<&Value> = array(&run.json, "sweep")
        .iter()
        .filter(|p| p["method"] == peer)
        .collect();
    // The paper's 4 problems × 3 quick tolerances, and the belt: 3 runs, or one refusal.
    let (belt, paper): (Vec<&Value>, Vec<&Value>) =
        points.iter().partition(|p| p["problem"] == "belt_default");
    assert_eq!(paper.len(), 4 * 3, "4 problems × 3 quick tolerances");
    assert!(paper.iter().all(|p| p["status"] == "ok"), "{paper:?}");
    let refused = belt.len() == 1 && belt[0]["status"] == "refused";
    assert!(
        refused || (belt.len() == 3 && belt.iter().all(|p| p["status"] == "ok")),
        "{belt:?}"
    );
    // At tolerance 1e-9 every exact event is found (measured: ≤ 2e-9 s off).
    for p in points.iter().filter(|p| p["tolerance"] == 1e-9) {
        assert_eq!(p["n_events"], p["n_events_exact"], "{p}");
        let err = p["err_event_s"].as_f64().expect("event error");
        assert!(err < 1e-7, "{p}");
        assert!(p["rhs_evals"].as_u64().expect("rhs evals") > 0);
    }
    let csv = std::fs::read_to_string(run.out.join("results.csv")).expect("results.csv");
    assert!(csv.lines().any(|l| l.contains(peer)));
    let page = std::fs::read_to_string(run.out.join("bench.md")).expect("bench.md");
    let section = page
        .split("## Cost at equal error")
        .nth(1)
        .and_then(|s| s.split("\n## ").next())
        .expect("cost section");
    let headline: Vec<&str> = section.lines().filter(|l| l.starts_with("- ")).collect();
    assert_eq!(headline.len(), 5, "{section}");
    for h in headline {
        assert!(!h.contains("SciPy"), "{h}");
        if h.contains("the fastest compiled peer") {
            assert!(
                ["dopri5", "dopri5_endpoints", peer]
                    .iter()
                    .any(|m| h.contains(&format!(" is {m}, "))),
                "{h}"
            );
        }
        if h.contains("harmonic") {
            assert!(
                h.contains("target ≥ 10×") || h.contains("No compiled peer"),
                "{h}"
            );
        }
    }
    assert!(section.contains("diffsol_tsit45 (the Rust library diffsol"));
}

/// Without the cargo feature `peers` the diffsol peer is not swept, and the run says so: in
/// results.json, on both pages, in the failures table and on stderr, never a silently missing row.
#[cfg(not(feature = "peers"))]
#[test]
fn without_the_peers_feature_the_diffsol_peer_is_said_to_be_not_built_in() {
    let run = quick();
    let peer = "diffsol_tsit45";
    assert!(!array(&run.json, "methods")
        .iter()
        .any(|m| m["name"] == peer));
    assert!(!array(&run.json, "sweep")
        .iter()
        .any(|p| p["method"] == peer));
    let missing = array(&run.json, "not_built_in");
    assert_eq!(missing.len(), 1, "{missing:?}");
    assert_eq!(missing[0]["name"], peer);
    let message = missing[0]["message"].as_str().expect("message");
    assert!(
        message.contains("not built in") && message.contains("--features peers"),
        "{message}"
    );
    for page in ["index.html", "bench.md"] {
        let text = std::fs::read_to_string(run.out.join(page)).expect(page);
        assert_eq!(
            text.matches(message).count(),
            2,
            "{page}: note and table row"
        );
    }
    let summary = array(&run.json["failures"], "table");
    assert!(
        !summary.iter().any(|r| r["method"] == peer),
        "no measured row"
    );
    assert!(run.stderr.contains(message), "{}", run.stderr);
}

/// With the cargo feature `peers` nothing is said to be missing.
#[cfg(feature = "peers")]
#[test]
fn with_the_peers_feature_nothing_is_said_to_be_not_built_in() {
    let run = quick();
    assert!(array(&run.json, "not_built_in").is_empty());
    assert!(!run.stderr.contains("not built in"), "{}", run.stderr);
}

#[test]
fn euler_sign_reversals_grow_as_the_step_shrinks_and_exact_has_none() {
    let run = quick();
    let points = array(&run.json["failures"], "reversals");
    for problem in array(&run.json, "problems") {
        let id = &problem["id"];
        let mut series: Vec<(f64, f64)> = points
            .iter()
            .filter(|p| &p["problem"] == id && p["method"] == "euler_sign")
            .map(|p| {
                (
                    p["h_s"].as_f64().expect("h"),
                    p["reversals_per_period"].as_f64().expect("count"),
                )
            })
            .collect();
        series.sort_by(|a, b| b.0.total_cmp(&a.0));
        assert!(series.len() >= 3, "{id}: {series:?}");
        assert!(
            series.windows(2).all(|w| w[1].1 > w[0].1),
            "{id}: reversals must grow as h shrinks: {series:?}"
        );
    }
    for p in array(&run.json, "sweep") {
        if p["method"] == "exact" {
            assert_eq!(p["reversals"], 0, "{p}");
            assert_eq!(p["err_x_m"], 0.0, "{p}");
        }
    }
}

#[test]
fn a_sweep_point_round_trips_through_json() {
    let run = quick();
    let original = array(&run.json, "sweep")
        .iter()
        .find(|p| p["method"] == "dopri5" && p["status"] == "ok")
        .expect("a dopri5 point");
    let point: SweepPoint = serde_json::from_value(original.clone()).expect("deserializes");
    assert_eq!(point.method, "dopri5");
    assert_eq!(&serde_json::to_value(&point).expect("serializes"), original);
}

/// The belt is in the sweep: its reference agrees with the closed forms, it has no v̄, and a
/// method that does not take it is listed as refusing it, with its reason, once.
#[test]
fn the_belt_is_swept_against_its_closed_forms_and_a_refusal_is_listed() {
    let run = quick();
    let belt = array(&run.json, "problems")
        .iter()
        .find(|p| p["id"] == "belt_default")
        .expect("the belt is a problem of the sweep");
    assert_eq!(
        (&belt["model"], &belt["law"]),
        (&json!("belt"), &json!("spring"))
    );
    let c = &belt["closed_form_check"];
    assert_eq!(
        (&c["events_exact"], &c["events_closed_form"]),
        (&json!(40), &json!(40))
    );
    assert_eq!(c["same_pattern"], true, "{c}");
    let t_end = belt["t_end_s"].as_f64().expect("t_end");
    assert!(
        c["max_event_err_s"].as_f64().expect("dt") <= 1e-12 * t_end,
        "{c}"
    );
    assert!(c["x_end_err_m"].as_f64().expect("dx") <= 1e-14, "{c}");
    assert_eq!(belt["exact"]["vbar_m_s"], Value::Null);
    let why = belt["vbar_not_applicable"].as_str().expect("a reason");
    let page = std::fs::read_to_string(run.out.join("bench.md")).expect("bench.md");
    assert!(page.contains(why), "the page says why there is no v̄");

    let points: Vec<&Value> = array(&run.json, "sweep")
        .iter()
        .filter(|p| p["problem"] == "belt_default")
        .collect();
    assert!(points.iter().all(|p| p["err_vbar_m_s"].is_null()));
    for m in array(&run.json, "methods") {
        let name = m["name"].as_str().expect("name");
        let mine: Vec<&&Value> = points.iter().filter(|p| p["method"] == name).collect();
        if mine.iter().any(|p| p["status"] == "refused") {
            assert_eq!(mine.len(), 1, "{name}: one refusal, whatever the setting");
            let reason = mine[0]["error"].as_str().expect("its reason");
            assert!(reason.contains(name), "{reason}");
            let line = format!("| Belt oscillator, default set | {name} | ");
            assert!(page.contains(&line), "{name}'s refusal is listed");
        } else {
            assert!(mine.iter().all(|p| p["status"] == "ok"), "{name}: {mine:?}");
            assert!(!mine.is_empty(), "{name}");
        }
    }
    // rk4 at T/10⁴: event times within 1e-9 s of the closed forms' (measured 1.7e-13).
    let rk4 = points
        .iter()
        .find(|p| p["method"] == "rk4" && p["steps_per_period"].as_f64() > Some(9e3))
        .expect("rk4 at T/10^4");
    assert_eq!(rk4["n_events"], 40);
    assert!(rk4["err_event_s"].as_f64().expect("error") < 1e-9, "{rk4}");
}

#[test]
fn without_peer_the_report_says_scipy_was_not_run() {
    let run = quick();
    assert_eq!(run.json["peer"]["status"], "not requested");
    let message = run.json["peer"]["message"].as_str().expect("message");
    assert!(message.contains("not run"), "{message}");
    let page = std::fs::read_to_string(Path::new(&run.out).join("bench.md")).expect("bench.md");
    assert!(page.contains(message), "the page states it");
}

#[test]
fn the_references_agree_with_a_40_digit_integration_when_mpmath_is_there() {
    let run = quick();
    let check = &run.json["reference_check"];
    let page = std::fs::read_to_string(Path::new(&run.out).join("bench.md")).expect("bench.md");
    if check["status"] == "skipped" {
        let reason = check["reason"].as_str().expect("reason");
        eprintln!("skipped: {reason}");
        assert!(page.contains(reason), "the page says why");
        return;
    }
    assert_eq!(check["status"], "ok");
    let rows = array(check, "rows");
    assert_eq!(
        rows.len(),
        4,
        "every paper problem (the belt: by its closed forms)"
    );
    for r in rows {
        assert_eq!(r["same_pattern"], true, "{r}");
        assert_eq!(r["events"], r["events_mp"], "{r}");
        let dt = r["max_event_err_s"].as_f64().expect("event error");
        assert!(dt <= 1e-13, "{r}");
        assert!(r["x_end_err_m"].as_f64().expect("x error") <= 1e-13, "{r}");
    }
    assert!(page.contains("Independent check of the references: a second program"));
}

#[test]
fn zero_repeats_is_refused_as_bad_input() {
    Command::cargo_bin("stickslip")
        .expect("binary")
        .args(["bench", "--repeats", "0"])
        .assert()
        .code(2);
}

#[test]
fn near_the_regime_boundaries_exact_is_always_right_and_sign_euler_is_not() {
    let regime = array(&quick().json["failures"], "regime");
    let wrong = |method: &str| -> (usize, usize) {
        let runs: Vec<&Value> = regime.iter().filter(|r| r["method"] == method).collect();
        let wrong = runs.iter().filter(|r| r["wrong"] == true).count();
        (wrong, runs.len())
    };
    let (exact_wrong, exact_runs) = wrong("exact");
    assert!(
        exact_runs >= 4 && exact_wrong == 0,
        "exact: {exact_wrong}/{exact_runs}"
    );
    // The sign(v) Euler method cannot hold a stick: it misreads regimes near the boundaries.
    let (euler_wrong, euler_runs) = wrong("euler_sign");
    assert!(
        euler_runs > 0 && euler_wrong > 0,
        "euler_sign: {euler_wrong}/{euler_runs}"
    );
    // Located events (dopri5 with interior checks) read the regime right at every setting.
    let (dopri_wrong, dopri_runs) = wrong("dopri5");
    assert!(
        dopri_runs > 0 && dopri_wrong == 0,
        "dopri5: {dopri_wrong}/{dopri_runs}"
    );
}

#[test]
fn long_runs_cover_continuous_slip_and_reversals_and_report_growing_errors() {
    let long = &quick().json["long_runs"];
    let cases = array(long, "cases");
    let case = |id: &str| {
        cases
            .iter()
            .find(|c| c["id"] == id)
            .unwrap_or_else(|| panic!("{id} missing"))
    };
    let slip = case("continuous_slip_harmonic");
    assert_eq!(
        (slip["slips"].as_u64(), slip["sticks"].as_u64()),
        (Some(1), Some(0))
    );
    let rev = case("reversals_harmonic");
    assert_eq!(rev["sticks"], 0);
    assert!(rev["reversals"].as_u64().expect("count") >= 1, "{rev}");
    let checkpoints = array(long, "checkpoints");
    assert!(checkpoints.iter().any(|n| n.as_u64() >= Some(1000)));
    let points = array(long, "points");
    // Every run reports its errors, or says what went wrong.
    for p in points {
        let reported = p["err_x_m"].is_number() && p["err_event_s"].is_number();
        let flagged = p["wrong_events"].is_string() || p["error"].is_string();
        assert!(reported != flagged, "{p}");
    }
    // Set B over 10 and 1000 periods: the position error grows for every series.
    let err = |method: &str, setting: &str, n: u64| {
        points
            .iter()
            .find(|p| {
                p["case"] == "pulled_mass_b_harmonic"
                    && p["method"] == method
                    && p["setting"] == setting
                    && p["periods"] == n
            })
            .and_then(|p| p["err_x_m"].as_f64())
            .unwrap_or_else(|| panic!("{method} {setting} {n}"))
    };
    for (m, s) in [("dopri5", "tol 1e-8"), ("rk4", "T/100")] {
        assert!(err(m, s, 1000) > 10.0 * err(m, s, 10), "{m} {s}");
    }
    let page = std::fs::read_to_string(quick().out.join("bench.md")).expect("bench.md");
    assert!(page.contains("## Error growth over long runs"));
}

#[test]
fn near_tangent_and_step_boundary_studies_measure_what_they_claim() {
    let failures = &quick().json["failures"];
    let tangent = array(failures, "near_tangent");
    let exact: Vec<&Value> = tangent.iter().filter(|p| p["method"] == "exact").collect();
    assert_eq!(exact.len(), 12, "6 offsets × 2 sides");
    assert!(exact.iter().all(|p| p["wrong"] == false), "{exact:?}");
    assert!(
        tangent
            .iter()
            .any(|p| p["method"] == "euler_sign" && p["wrong"] == true),
        "a method without a stick state misreads them"
    );
    let boundary = array(failures, "step_boundary");
    assert!(!boundary.is_empty());
    for p in boundary {
        let ulps = p["grid_ulps"].as_f64().expect("ulps");
        assert!(ulps <= 4.0, "{p}");
    }
    let moreau_slip = boundary
        .iter()
        .find(|p| p["method"] == "moreau" && p["event"] == "slip")
        .expect("moreau on a slip");
    let late = moreau_slip["steps_late_on"].as_f64().expect("reported");
    assert!(late > 0.5, "{moreau_slip}");
}

#[test]
fn crowding_study_resolves_shrinking_slips_with_the_exact_engine_and_dopri5() {
    let crowding = array(&quick().json["failures"], "crowding");
    let of = |m: &str| -> Vec<&Value> { crowding.iter().filter(|p| p["method"] == m).collect() };
    assert_eq!(of("exact").len(), 10, "5 ratios × 2 laws");
    assert!(of("exact").iter().all(|p| p["wrong"] == false));
    let dopri5_tight: Vec<&Value> = of("dopri5")
        .into_iter()
        .filter(|p| p["setting"] == "tol 1e-9")
        .collect();
    assert_eq!(dopri5_tight.len(), 10);
    assert!(
        dopri5_tight.iter().all(|p| p["wrong"] == false),
        "{dopri5_tight:?}"
    );
    assert!(
        of("moreau").iter().any(|p| p["wrong"] == true),
        "a slip far shorter than moreau's step is lost"
    );
    let page = std::fs::read_to_string(quick().out.join("bench.md")).expect("bench.md");
    assert!(page.contains("### Crowding events: a slip that shrinks to nothing"));
    assert!(page.contains("#### Harmonic law, against the exact engine"));
}
