//! Seeded fuzz driver of whole command lines (issue 27): runs the binary on generated calls
//! (eval, claims, sweep, check, report, explorer, handout, worksheet; both models; parameter
//! values at and beyond their ranges) and counts panics, hangs, exit 1, partial outputs (an
//! output folder or a staging folder left by a failed call) and non-finite values (`inf`,
//! `NaN` in stdout or in a written CSV, JSON or Markdown file). It fails if any count is not 0.
//!
//! Ignored in CI (minutes); a run of N calls:
//! `FUZZ_CLI_CALLS=100000 FUZZ_CLI_SEED=27 cargo test --release --test fuzz_cli -- --ignored --nocapture`

use std::fs;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use assert_cmd::cargo::cargo_bin;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};

/// A call still running after this is a hang.
const HANG: Duration = Duration::from_secs(60);

const PULLED: &[&str] = &["--mu-s", "--mu-d", "--mass", "--k", "--force", "--g"];
const WOOD: &[&str] = &[
    "--mu-s",
    "--mu-d",
    "--k",
    "--m-sleeve",
    "--m-bird",
    "--l",
    "--h",
    "--z0",
    "--d0",
    "--g",
    "--lever",
    "--omega",
];
const SPECIAL: &[&str] = &[
    "0", "-0", "1", "-1", "0.4", "0.35", "0.1", "1e-300", "1e308", "1.79e308", "-1e308", "nan",
    "inf", "-inf", "5e-324", "abc", "", "1e-8", "2.2e-16", "0.47088", "143.4", "1e13", "1e20",
];

fn value(rng: &mut StdRng) -> String {
    match rng.gen_range(0..4) {
        0 => SPECIAL[rng.gen_range(0..SPECIAL.len())].to_string(),
        1 => format!("{}", rng.gen_range(0.0..2.0)),
        2 => format!("{:e}", 10f64.powf(rng.gen_range(-12.0..12.0))),
        _ => format!("{}", rng.gen_range(0.01..1.0)),
    }
}

/// One generated command line; `out` is the folder it may write to.
fn call(rng: &mut StdRng, out: &Path) -> Vec<String> {
    let model = if rng.gen_bool(0.5) {
        "pulled-mass"
    } else {
        "woodpecker"
    };
    let flags = if model == "pulled-mass" { PULLED } else { WOOD };
    let out = out.display().to_string();
    let mut args: Vec<String> = match rng.gen_range(0..10) {
        0..=2 => vec!["eval".into(), model.into()],
        3 => vec![
            "claims".into(),
            "--samples".into(),
            rng.gen_range(1..20).to_string(),
            model.into(),
        ],
        4 | 5 => {
            let param = flags[rng.gen_range(0..flags.len())]
                .trim_start_matches("--")
                .replace('-', "_");
            vec![
                "sweep".into(),
                model.into(),
                "--param".into(),
                param,
                "--from".into(),
                value(rng),
                "--to".into(),
                value(rng),
                "--steps".into(),
                rng.gen_range(2..12).to_string(),
                "--out".into(),
                out.clone(),
            ]
        }
        6 => vec![
            "check".into(),
            model.into(),
            ["g", "2*g", "mu_s", "1/0", "sqrt(-1)", "g^400"][rng.gen_range(0..6)].into(),
            "--quantity".into(),
            ["v_avg", "t_slip", "phi", "nope"][rng.gen_range(0..4)].into(),
            "--samples".into(),
            rng.gen_range(1..6).to_string(),
            "--out".into(),
            out.clone(),
        ],
        7 => vec![
            "report".into(),
            "--out".into(),
            out.clone(),
            "--format".into(),
            "md".into(),
        ]
        .into_iter()
        .chain(rng.gen_bool(0.9).then(|| {
            let s = [
                "set-b-slip-stick",
                "set-c-late-stick",
                "fig05-immediate-slip",
                "fig15-double-slip-stick",
            ];
            format!(
                "{}/scenarios/{}.toml",
                env!("CARGO_MANIFEST_DIR"),
                s[rng.gen_range(0..s.len())]
            )
        }))
        .collect(),
        8 => vec![
            "handout".into(),
            [
                "fig05-immediate-slip",
                "fig06-continuous-slip",
                "pulled-forces",
                "nope",
            ][rng.gen_range(0..4)]
            .into(),
            "--out".into(),
            out.clone(),
            "--format".into(),
            "md".into(),
        ],
        _ => vec![
            "worksheet".into(),
            "--model".into(),
            model.into(),
            "--students".into(),
            rng.gen_range(1..3).to_string(),
            "--seed".into(),
            rng.gen_range(0..1000).to_string(),
            "--out".into(),
            out.clone(),
            "--format".into(),
            "md".into(),
        ],
    };
    if matches!(args[0].as_str(), "eval" | "sweep" | "check" | "claims") {
        let i = args.iter().position(|a| a == model).unwrap() + 1;
        for _ in 0..rng.gen_range(0..4) {
            let f = flags[rng.gen_range(0..flags.len())];
            args.insert(i, value(rng));
            args.insert(i, f.to_string());
        }
        if args[0] != "check" && rng.gen_bool(0.2) {
            args.push("--periods".into());
            args.push(["1", "8", "100", "0", "-1", "1000000"][rng.gen_range(0..6)].into());
        }
        if args[0] == "eval" && rng.gen_bool(0.3) {
            args.push("--json".into());
        }
        if args[0] == "eval" && rng.gen_bool(0.2) {
            args.push("--csv".into());
            args.push(out);
        }
    }
    args
}

/// A word `inf`, `-inf`, `NaN` or `nan` in `text`.
fn non_finite(text: &str) -> bool {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .any(|w| matches!(w, "inf" | "NaN" | "nan" | "infinity" | "Infinity"))
}

fn written_non_finite(dir: &Path) -> bool {
    let Ok(entries) = fs::read_dir(dir) else {
        return false;
    };
    entries.flatten().any(|e| {
        let p = e.path();
        if p.is_dir() {
            return written_non_finite(&p);
        }
        let text_file = p
            .extension()
            .is_some_and(|x| x == "csv" || x == "json" || x == "md");
        text_file && non_finite(&fs::read_to_string(&p).unwrap_or_default())
    })
}

#[derive(Default, Debug)]
struct Counts {
    calls: u64,
    ok: u64,
    refused: u64,
    verdicts: u64,
    panics: u64,
    hangs: u64,
    exit_1: u64,
    partial: u64,
    non_finite: u64,
}

#[test]
#[ignore = "minutes: FUZZ_CLI_CALLS calls of the binary"]
fn fuzz_cli() {
    let calls: u64 = std::env::var("FUZZ_CLI_CALLS")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(2000);
    let seed: u64 = std::env::var("FUZZ_CLI_SEED")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(27);
    let mut rng = StdRng::seed_from_u64(seed);
    let bin = cargo_bin("stickslip");
    let root = tempfile::tempdir().unwrap();
    let mut c = Counts::default();
    let mut examples: Vec<String> = Vec::new();
    let started = Instant::now();
    for i in 0..calls {
        let out = root.path().join(format!("out-{i}"));
        let args = call(&mut rng, &out);
        let mut child = Command::new(&bin)
            .args(&args)
            .current_dir(root.path())
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // Drain the pipes on threads so a chatty call cannot block.
        let mut so = child.stdout.take().unwrap();
        let mut se = child.stderr.take().unwrap();
        let ho = std::thread::spawn(move || {
            let mut s = String::new();
            let _ = std::io::Read::read_to_string(&mut so, &mut s);
            s
        });
        let he = std::thread::spawn(move || {
            let mut s = String::new();
            let _ = std::io::Read::read_to_string(&mut se, &mut s);
            s
        });
        let t0 = Instant::now();
        let status = loop {
            if let Some(s) = child.try_wait().unwrap() {
                break Some(s);
            }
            if t0.elapsed() > HANG {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            std::thread::sleep(Duration::from_millis(2));
        };
        let (stdout, stderr) = (ho.join().unwrap(), he.join().unwrap());
        c.calls += 1;
        let mut bad = None;
        match status.and_then(|s| s.code()) {
            None if status.is_none() => {
                c.hangs += 1;
                bad = Some("hang");
            }
            None => {
                c.panics += 1;
                bad = Some("signal");
            }
            Some(0) => c.ok += 1,
            Some(2) => c.refused += 1,
            Some(3) => c.verdicts += 1,
            Some(1) => {
                c.exit_1 += 1;
                bad = Some("exit 1");
            }
            Some(_) => {
                c.panics += 1;
                bad = Some("panic");
            }
        }
        if stderr.contains("panicked") && bad.is_none() {
            c.panics += 1;
            bad = Some("panic");
        }
        let failed = !matches!(status.and_then(|s| s.code()), Some(0 | 3));
        let staging = fs::read_dir(&out).is_ok_and(|d| {
            d.flatten()
                .any(|e| e.file_name().to_string_lossy().starts_with(".stickslip-"))
        });
        if staging || (failed && out.exists()) {
            c.partial += 1;
            bad = bad.or(Some("partial output"));
        }
        if non_finite(&stdout) || written_non_finite(&out) {
            c.non_finite += 1;
            bad = bad.or(Some("non-finite value"));
        }
        if let Some(what) = bad {
            if examples.len() < 20 {
                examples.push(format!(
                    "{what}: {args:?}: {}",
                    stderr.lines().next().unwrap_or("")
                ));
            }
        }
        let _ = fs::remove_dir_all(&out);
    }
    eprintln!(
        "fuzz_cli seed {seed}: {c:?} in {:.0} s",
        started.elapsed().as_secs_f64()
    );
    for e in &examples {
        eprintln!("  {e}");
    }
    assert_eq!(
        (c.panics, c.hangs, c.exit_1, c.partial, c.non_finite),
        (0, 0, 0, 0, 0),
        "{c:?}"
    );
}
