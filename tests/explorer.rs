//! The explorer page (`stickslip explorer`, `reports/explorer.html`) in headless Chromium,
//! driven by playwright-core (tests/explorer/run.mjs): it loads from file:// with no request
//! leaving file:/data:/blob:, renders every model (the belt's block moved on its belt), follows sliders (mouse and keyboard), map
//! clicks (mouse and keyboard), options and presets, shows the one-line error of an invalid
//! value, has no console error and no serious accessibility violation; every parameter set it
//! visited gives the same bytes as `stickslip eval … --json`; honours `prefers-reduced-motion`
//! and fits a phone's width. Prints the measured size, first
//! render and redraw times next to their budgets; it does not assert them (a test must not fail
//! from a loaded machine: budgets belong in benchmarks). `SCREENSHOTS=1` saves
//! docs/screenshots/explorer-*.png.
//!
//! Needs chromium and Node with axe-core and playwright-core in `STICKSLIP_NODE_MODULES`
//! (default `target/axe/node_modules`, where `.ci/run` installs them); without them the browser
//! test is skipped locally but fails on CI (CI=true).

mod common;
use common::find;

use std::path::{Path, PathBuf};
use std::process::Command;

use stickslip::classroom;
use stickslip::report::explorer::Placement;
use stickslip::report::{builtin_scenes, explorer, Format};

/// Budgets of the issue: page size, first render, one redraw.
const MAX_BYTES: usize = 1_500_000;
const FIRST_RENDER_MS: f64 = 1000.0;
const REDRAW_MS: f64 = 16.0;

/// Chromium, node and the folder of axe-core and playwright-core; `None` (skip) when one is
/// missing, which CI (CI=true) does not allow.
fn tools() -> Option<(PathBuf, PathBuf, PathBuf)> {
    let modules = std::env::var("STICKSLIP_NODE_MODULES").map_or_else(
        |_| Path::new(env!("CARGO_MANIFEST_DIR")).join("target/axe/node_modules"),
        PathBuf::from,
    );
    let found = (
        find(&["chromium", "chromium-browser", "google-chrome"]),
        find(&["node"]),
        modules.join("playwright-core").exists() && modules.join("axe-core").exists(),
    );
    if let (Some(browser), Some(node), true) = found {
        return Some((browser, node, modules));
    }
    assert!(
        std::env::var("CI").is_err(),
        "CI must install chromium, node, axe-core and playwright-core"
    );
    eprintln!(
        "skipped: chromium, node, or axe-core and playwright-core in {}",
        modules.display()
    );
    None
}

fn median(xs: &[f64]) -> f64 {
    let mut v = xs.to_vec();
    v.sort_by(f64::total_cmp);
    v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
}

/// `stickslip eval` for the page's request (model, SI parameters, options), as printed.
fn cli_eval(request: &serde_json::Value) -> String {
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_stickslip"));
    cmd.arg("eval").arg(request["model"].as_str().unwrap());
    for (key, value) in request["params"].as_object().unwrap() {
        // `{}` of an f64 reads back as the same f64.
        let value = value.as_f64().unwrap();
        cmd.arg(format!("--{}={value}", key.replace('_', "-")));
    }
    for (key, value) in request["choices"].as_object().unwrap() {
        cmd.arg(format!("--{key}={}", value.as_str().unwrap()));
    }
    let out = cmd.arg("--json").output().unwrap();
    assert!(out.status.success(), "{request}: {out:?}");
    String::from_utf8(out.stdout).unwrap()
}

#[test]
fn the_page_is_one_small_file_without_network_references() {
    let page = explorer::render(&builtin_scenes().unwrap(), Placement::Alone).unwrap();
    let text = String::from_utf8(page.bytes.clone()).unwrap();
    eprintln!(
        "explorer.html: {} bytes (budget {MAX_BYTES})",
        page.bytes.len()
    );
    assert!(page.bytes.len() <= MAX_BYTES, "{} bytes", page.bytes.len());
    assert_eq!(common::network_references(&text), Vec::<&str>::new());
    // One file: no other script, style, image or frame is loaded.
    for tag in ["<script src", "<link", "<img", "<iframe"] {
        assert!(!text.contains(tag), "{tag}");
    }
    assert_eq!(
        page.bytes,
        explorer::render(&builtin_scenes().unwrap(), Placement::Alone)
            .unwrap()
            .bytes
    );
}

#[test]
fn the_default_report_writes_and_links_the_explorer_with_its_html() {
    let scenes = builtin_scenes().unwrap();
    let (files, links) = classroom::material(&scenes, &[Format::Html]).unwrap();
    let page = explorer::render(&scenes, Placement::InReport).unwrap();
    assert!(files.contains(&page));
    assert!(links.iter().any(|l| l.html == explorer::FILE));
    let (files, links) = classroom::material(&scenes, &[Format::Md]).unwrap();
    assert!(files.iter().all(|f| f.path != Path::new(explorer::FILE)));
    assert!(links.iter().all(|l| l.html != explorer::FILE));
}

#[test]
fn the_page_explores_every_model_in_chromium_with_the_clis_numbers() {
    let Some((browser, node, modules)) = tools() else {
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_stickslip"))
        .args(["explorer", "--out"])
        .arg(dir.path())
        .output()
        .unwrap();
    assert!(out.status.success(), "{out:?}");
    let page = dir.path().join("explorer.html");
    let shots = std::env::var("SCREENSHOTS")
        .is_ok_and(|v| v == "1")
        .then(|| {
            let d = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/screenshots");
            std::fs::create_dir_all(&d).unwrap();
            d
        });
    let mut cmd = Command::new(node);
    cmd.arg(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/explorer/run.mjs"))
        .arg(&browser)
        .arg(&modules)
        .arg(&page);
    if let Some(d) = &shots {
        cmd.arg(d);
    }
    let run = cmd.output().unwrap();
    assert!(run.status.success(), "{run:?}");
    let r: serde_json::Value = serde_json::from_slice(&run.stdout).unwrap();

    // Nothing leaves the file, nothing is logged as an error, nothing serious for axe.
    for url in r["requests"].as_array().unwrap() {
        let url = url.as_str().unwrap();
        assert!(
            ["file:", "data:", "blob:"]
                .iter()
                .any(|s| url.starts_with(s)),
            "request to {url}"
        );
    }
    assert_eq!(r["errors"], serde_json::json!([]), "console errors");
    assert_eq!(r["axe"], serde_json::json!([]), "axe violations");

    // Sliders, keyboard, map, options and presets change what is shown.
    let checks = &r["checks"];
    for key in [
        "keyboardChanged",
        "dragChanged",
        "mapChanged",
        "mapKeyboard",
        "mapCursorAtSet",
        "woodChanged",
    ] {
        assert_eq!(checks[key], true, "{key}: {checks}");
    }
    let message = checks["invalidMessage"].as_str().unwrap();
    assert!(
        message.starts_with("invalid parameter mu_d = 5"),
        "{message}"
    );
    assert!(checks["firstRegime"].as_str().unwrap().contains("because"));
    assert!(checks["woodRegime"]
        .as_str()
        .unwrap()
        .contains("two slips and two sticks"));
    assert!(checks["woodTable"].as_u64().unwrap() >= 10, "{checks}");
    assert_ne!(checks["animationTime"], "t = 0 s", "the animation ran");
    // Under prefers-reduced-motion the time moves in whole steps of T/8 (how many were taken
    // before the pause depends on the machine's load), and a phone never scrolls sideways.
    let steps = checks["reducedMotionStep"].as_f64().unwrap();
    assert!(
        (steps - steps.round()).abs() < 0.01 && steps.round() >= 1.0,
        "{steps}"
    );
    assert_eq!(checks["phoneOverflow"], 0, "{checks}");
    assert_eq!(checks["phonePlotWithSlider"], true, "{checks}");

    // A slider move moves the elements it finds, it makes none: no new SVG element, table
    // row or cell, legend item (tests every element before 30 moves of F against after).
    assert_eq!(checks["newNodes"], serde_json::json!([]), "{checks}");
    assert_eq!(checks["rowsKept"], true, "{checks}");

    // The apparatus animated is the sketch's (issue 28): the same sizes, the same layout.
    let pm = stickslip::models::pulled_mass::sketch::APPARATUS;
    let drawn = &checks["pulledApparatus"];
    let size = |key: &str| -> Vec<f64> {
        drawn[key]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect()
    };
    assert_eq!(size("block"), [pm.block_width, pm.block_height], "{drawn}");
    assert_eq!(size("hanging"), [pm.mass_width, pm.mass_height], "{drawn}");
    assert_eq!(drawn["springPoints"], 2 * pm.coils + 4, "{drawn}");
    assert_eq!(drawn["springHalf"].as_f64(), Some(pm.coil_half), "{drawn}");
    let layout = stickslip::models::woodpecker::sketch::woodpecker_layout(
        &stickslip::models::woodpecker::WoodpeckerParams::default(),
    );
    let wood = &checks["woodApparatus"];
    let near = |page: &serde_json::Value, rust: f64, tol: f64| {
        (page.as_f64().unwrap() - rust).abs() <= tol * rust.abs().max(1.0)
    };
    for (key, rust) in [
        ("scale", layout.scale),
        ("l_px", layout.l_px),
        ("h_px", layout.h_px),
        ("theta", layout.theta),
        ("b", layout.b),
    ] {
        assert!(
            near(&wood["layout"][key], rust, 1e-12),
            "{key}: {wood} against {layout:?}"
        );
    }
    // Measured on the drawing (coordinates rounded to 0.1 px): the contacts h apart, the
    // spring l from the pole's axis.
    for (key, rust) in [("contacts", layout.h_px), ("arm", layout.l_px)] {
        assert!(
            (wood[key].as_f64().unwrap() - rust).abs() <= 0.15,
            "{key}: {wood} against {layout:?}"
        );
    }

    // The belt: its own laws, regime and drawing; the block carried by the belt moves with
    // its marks at v_b (first stick, t < x_s/v_b), then follows the exact motion.
    let regime = checks["beltRegime"].as_str().unwrap();
    assert!(
        regime.contains("Closed forms (exact for this system): a stick and one harmonic slip")
            && regime.contains("Exact integration, spring force −k x (exact): a stick and one"),
        "{regime}"
    );
    assert!(!regime.contains("linearized"), "{regime}");
    assert_eq!(
        checks["beltLaws"],
        serde_json::json!(["spring force −k x (exact)"])
    );
    assert!(checks["beltTable"].as_u64().unwrap() >= 15, "{checks}");
    let map = checks["beltMap"].as_str().unwrap();
    assert!(map.contains("stuck ≥ 50 % of the cycle"), "{map}");
    let g = stickslip::models::belt::sketch::APPARATUS;
    let p = stickslip::models::belt::BeltParams::default();
    let c = stickslip::models::belt::formula::evaluate(&p);
    let (_, run) = stickslip::models::belt::results::evaluate_with_run(&p, 8).unwrap();
    let frames = checks["beltApparatus"].as_array().unwrap();
    let f64s = |v: &serde_json::Value| v.as_f64().unwrap();
    for frame in frames {
        let (t, x, scale) = (
            f64s(&frame["time"]),
            f64s(&frame["x"]),
            f64s(&frame["scale"]),
        );
        assert_eq!(frame["parts"][0], 1, "{frame}");
        assert_eq!(frame["parts"][1], 1, "{frame}");
        assert_eq!(frame["parts"][2], 1, "{frame}");
        assert!(frame["parts"][3].as_u64().unwrap() >= 5, "{frame}");
        let size: Vec<f64> = frame["blockSize"]
            .as_array()
            .unwrap()
            .iter()
            .map(f64s)
            .collect();
        assert_eq!(size, [g.block_width, g.block_height], "{frame}");
        // The block drawn at x to scale from the sketch's position; x that of the engine.
        assert!(
            (f64s(&frame["blockX"]) - (g.block_x + scale * x)).abs() <= 0.06,
            "{frame}"
        );
        let (exact, v, _) = run.state_at(t).unwrap();
        assert!((x - exact).abs() <= 1e-4, "{frame}: x = {exact} m");
        // The belt's marks at its travel v_b t, to the block's scale.
        let shift = (scale * p.v_b * t).rem_euclid(40.0);
        assert!((f64s(&frame["shift"]) - shift).abs() <= 1e-6, "{frame}");
        let stuck = frame["desc"].as_str().unwrap().contains("is stuck");
        assert_eq!(stuck, t < c.first_slip_time, "{frame}: v = {v}");
    }
    // Carried by the belt: the block moves as far as the belt's marks.
    let (a, b) = (&frames[0], &frames[1]);
    assert!(f64s(&b["time"]) < c.first_slip_time);
    let moved = f64s(&b["blockX"]) - f64s(&a["blockX"]);
    let carried = f64s(&a["scale"]) * p.v_b * (f64s(&b["time"]) - f64s(&a["time"]));
    assert!(
        moved > 10.0 && (moved - carried).abs() <= 0.15,
        "{moved} {carried}"
    );

    // Every set the page visited: the same bytes as the command line.
    let visited = r["visited"].as_array().unwrap();
    assert!(visited.len() >= 8, "{}", visited.len());
    for v in visited {
        let page = v["evaluation"].as_str().unwrap();
        assert_eq!(
            format!("{page}\n"),
            cli_eval(&v["request"]),
            "{}: {}",
            v["what"],
            v["request"]
        );
    }

    // Budgets, printed against the measured times, not asserted.
    let t = &r["timings"];
    let list = |k: &str| -> Vec<f64> {
        t[k].as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect()
    };
    let first = t["firstRender"].as_f64().unwrap();
    let (layout, frames, redraws) = (list("layout"), list("frames"), list("redraws"));
    eprintln!(
        "explorer: first render {first:.0} ms; slider move, both laws over 4 periods: \
         script {:.1} ms median ({:.1} max), to layout {:.1} ms median ({:.1} max), to the \
         next frame {:.1} ms median; {} sets compared with the CLI, byte for byte",
        median(&redraws),
        redraws.iter().copied().fold(0.0, f64::max),
        median(&layout),
        layout.iter().copied().fold(0.0, f64::max),
        median(&frames),
        visited.len()
    );
    eprintln!(
        "explorer budgets (not asserted): first render {first:.0} ms of {FIRST_RENDER_MS} ms, \
         redraw to layout {:.1} ms of {REDRAW_MS} ms (medians)",
        median(&layout)
    );
}
