//! The SciPy peer: `bench/scipy_peer.py` runs `solve_ivp` (RK45, DOP853, Radau) with an
//! event-restart loop on the same problems and tolerances; this module probes for Python with
//! SciPy, feeds the script the problems and the exact events on stdin, reads its JSON, and
//! compares times at equal error on the work-precision curves.
//!
//! ```text
//! ratio = our time / SciPy time, both read off their curves at the same error level
//!         (log-log interpolation on the Pareto front, see analysis::cost_at)
//! ```
//! Absent Python or SciPy is a plain statement in the report, never an error.
//!
//! The script integrates only the slip phases: the end of a stick is located on the static
//! margin |D| − μs N_f, which the force law gives in closed form (solved on linear pieces,
//! sampled and refined by brentq on harmonic ones); its evaluations are reported apart from the
//! rhs evaluations ([`PeerPoint::margin_evals`]).
//!
//! The script holds no model: each problem's force law and body are sent as data, the engine's
//! own [`ForceLaw`](crate::engine::ForceLaw) and [`Body`](crate::engine::Body) serialized:
//!
//! ```text
//! "body":      {"mass", "mu_s", "mu_d"}
//! "force_law": {"period", "pieces": [{"start", "end",
//!                "basis": {"kind": "linear", "t_ref"} | {"kind": "cos", "omega"},
//!                "drive": {"c0", "c1"}, "normal": {"c0", "c1"}}]}
//! ```
//!
//! The belt sends its surface law instead (the engine's
//! [`SurfaceLaw`](crate::engine::SurfaceLaw)), with its final time and cycle period:
//!
//! ```text
//! "surface_law": {"drive": D0, "stiffness": c = ∂D/∂x, "normal": N_f, "surface_speed": v_s}
//! "t_end", "period"
//! ```
//! and the script integrates its slips in the surface frame (w = v − v_s), the end of a stick
//! solved for on the margin |D0 + c x| − μs N_f, affine in t while x = x0 + v_s (t − t0).

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use serde::{Deserialize, Serialize};
use serde_json::json;

use super::analysis::{cost_at, time_curve, Metric};
use super::machine::Machine;
use super::problems::{Reference, SweepProblem, PERIODS};
use super::sweep::{SweepPoint, LONG_RUN};

/// The script's name in the repository (it is compiled into the binary: [`SCRIPT_TEXT`]).
pub const SCRIPT: &str = "bench/scipy_peer.py";
/// The script itself, shipped inside the binary.
const SCRIPT_TEXT: &str = include_str!("../../bench/scipy_peer.py");
/// SciPy's methods, in the order of the tables.
pub const SCIPY_METHODS: [&str; 3] = ["RK45", "DOP853", "Radau"];
/// Error levels of the ratio table.
pub const RATIO_LEVELS: [f64; 3] = [1e-6, 1e-8, 1e-10];

/// Which peer to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum PeerChoice {
    /// SciPy's solve_ivp through bench/scipy_peer.py.
    Scipy,
}

/// One SciPy run as the script reports it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct PeerPoint {
    pub problem: String,
    pub method: String,
    pub tol: f64,
    pub status: String,
    pub error: Option<String>,
    pub time_s: Option<f64>,
    pub runs: u32,
    pub nfev: Option<u64>,
    /// solve_ivp steps, all of them in slip phases: `steps_stuck` counts those taken while stuck.
    pub steps: Option<u64>,
    pub steps_stuck: Option<u64>,
    /// Evaluations of the static margin |D| − μs N_f (stick ends, stick or reversal decisions).
    pub margin_evals: Option<u64>,
    pub n_events: Option<usize>,
    pub n_events_exact: usize,
    pub err_event_s: Option<f64>,
    pub x_end_m: Option<f64>,
    pub err_x_m: Option<f64>,
    /// Exact events with no found event of the same kind within T/100, and the first of them.
    pub n_missed: Option<usize>,
    pub first_missed_t: Option<f64>,
    pub first_missed_kind: Option<String>,
}

impl PeerPoint {
    /// The run returned a solution.
    pub fn ok(&self) -> bool {
        self.status == "ok"
    }

    /// The run found a different number of slips and sticks than the exact solution.
    pub fn count_mismatch(&self) -> bool {
        self.n_events.is_some_and(|n| n != self.n_events_exact)
    }

    /// The run's error in `metric` (x_end for the metrics SciPy does not report); none for a run
    /// with a wrong event count, a failure that stays off the fronts and the ratios.
    pub fn error_in(&self, metric: Metric) -> Option<f64> {
        if self.count_mismatch() {
            return None;
        }
        match metric {
            Metric::EventTime => self.err_event_s,
            _ => self.err_x_m,
        }
    }
}

#[derive(Deserialize)]
struct ScriptOutput {
    python: String,
    numpy: String,
    scipy: String,
    points: Vec<PeerPoint>,
}

/// Our time against SciPy's at one error level.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct RatioRow {
    pub problem: String,
    pub metric: Metric,
    pub level: f64,
    pub method: String,
    pub time_s: Option<f64>,
    /// SciPy times in the order of [`SCIPY_METHODS`] (s).
    pub scipy_time_s: Vec<Option<f64>>,
    /// our time / best SciPy time, and our time / RK45 time.
    pub ratio_best: Option<f64>,
    pub best_scipy: Option<String>,
    pub ratio_rk45: Option<f64>,
}

/// A target of the issue, measured.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct TargetRow {
    pub target: String,
    pub problem: String,
    pub measured: String,
    pub speedup: Option<f64>,
    pub met: Option<bool>,
}

/// Everything about the peer for the report.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct PeerReport {
    pub requested: bool,
    /// "not requested", "absent", "error" or "ok".
    pub status: String,
    /// A plain sentence saying what happened.
    pub message: String,
    pub points: Vec<PeerPoint>,
    pub ratios: Vec<RatioRow>,
    pub targets: Vec<TargetRow>,
}

impl PeerReport {
    fn without(requested: bool, status: &str, message: String) -> Self {
        Self {
            requested,
            status: status.to_string(),
            message,
            points: Vec::new(),
            ratios: Vec::new(),
            targets: Vec::new(),
        }
    }

    /// The report when `--peer` was not given.
    pub fn not_requested(machine: &Machine) -> Self {
        let found = match (&machine.python, &machine.scipy) {
            (Some(p), Some(s)) => format!("Python {p} with SciPy {s} is present"),
            (Some(p), None) => format!("Python {p} is present, SciPy does not import"),
            _ => "python3 was not found".to_string(),
        };
        Self::without(
            false,
            "not requested",
            format!("SciPy comparison not run (use --peer scipy); {found}."),
        )
    }
}

/// A Python script shipped with the binary (compiled in with `include_str!`), written to a
/// private temporary folder (mode 0700) for the time of one run, and run from there: nothing of
/// the working folder or of the machine that built the binary is run, and no module is
/// imported from the working folder (the folder of the script and of the process is the
/// private one).
pub(super) struct ShippedScript {
    dir: tempfile::TempDir,
    path: PathBuf,
}

impl ShippedScript {
    /// Writes `text` as `name` into a new private folder.
    pub(super) fn write(name: &str, text: &str) -> std::io::Result<Self> {
        let dir = tempfile::Builder::new()
            .prefix("stickslip-python-")
            .tempdir()?;
        let path = dir.path().join(name);
        std::fs::write(&path, text)?;
        Ok(ShippedScript { dir, path })
    }

    /// `python3 <script>`, started in the private folder.
    pub(super) fn command(&self) -> Command {
        let mut c = python3_in(self.dir.path());
        c.arg(&self.path);
        c
    }
}

/// `python3` started in `dir`: with `-c`, Python imports from the process's folder first, so
/// that folder must be a private one, not the user's working folder.
fn python3_in(dir: &Path) -> Command {
    let mut c = Command::new("python3");
    c.current_dir(dir);
    c
}

/// Records Python, NumPy and SciPy versions in `machine`; Ok(()) when SciPy imports, else the
/// reason it cannot run.
pub fn probe(machine: &mut Machine) -> Result<(), String> {
    let private = tempfile::Builder::new()
        .prefix("stickslip-python-")
        .tempdir()
        .map_err(|e| format!("no temporary folder ({e})"))?;
    let out = python3_in(private.path())
        .args(["-c", "import sys; print(sys.version.split()[0])"])
        .output()
        .map_err(|e| format!("python3 was not found ({e})"))?;
    if !out.status.success() {
        return Err("python3 does not run".to_string());
    }
    machine.python = Some(String::from_utf8_lossy(&out.stdout).trim().to_string());
    let out = python3_in(private.path())
        .args([
            "-c",
            "import numpy, scipy; print(numpy.__version__, scipy.__version__)",
        ])
        .output()
        .map_err(|e| e.to_string())?;
    let text = String::from_utf8_lossy(&out.stdout).to_string();
    let mut parts = text.split_whitespace();
    match (out.status.success(), parts.next(), parts.next()) {
        (true, Some(n), Some(s)) => {
            machine.numpy = Some(n.to_string());
            machine.scipy = Some(s.to_string());
            Ok(())
        }
        _ => {
            let err = String::from_utf8_lossy(&out.stderr);
            let last = err.lines().last().unwrap_or("import failed").to_string();
            Err(format!(
                "python3 {} is present but numpy/scipy do not import ({last})",
                machine.python.as_deref().unwrap_or("?")
            ))
        }
    }
}

/// The script's input: problems with their body, force law and exact events, tolerances,
/// SciPy's methods, repeats.
fn input(
    problems: &[(&SweepProblem, &Reference)],
    tolerances: &[f64],
    methods: &[&str],
    repeats: u32,
) -> String {
    let problems: Vec<serde_json::Value> = problems
        .iter()
        .map(|(sp, r)| {
            let mut problem = json!({
                "id": sp.id(),
                "model": sp.model(),
                "law": sp.law_id(),
                "periods": PERIODS,
                "exact": { "events": r.events, "x_end_m": r.x_end_m },
            });
            let law = match sp {
                SweepProblem::Paper(bp) => json!({
                    "body": bp.problem.body,
                    "force_law": bp.problem.law,
                }),
                SweepProblem::Belt(b) => {
                    let law = &b.problem.law;
                    json!({
                        "body": b.problem.body,
                        "surface_law": {
                            "drive": law.drive,
                            "stiffness": law.stiffness,
                            "normal": law.normal,
                            "surface_speed": law.surface_speed,
                        },
                        "t_end": b.problem.t_end,
                        "period": b.closed.period,
                    })
                }
            };
            if let (Some(problem), Some(law)) = (problem.as_object_mut(), law.as_object()) {
                problem.extend(law.clone());
            }
            problem
        })
        .collect();
    json!({
        "repeats": repeats,
        "long_run_s": LONG_RUN.as_secs_f64(),
        "tolerances": tolerances,
        "methods": methods,
        "problems": problems,
    })
    .to_string()
}

/// Runs the script (sequentially: nothing else runs while it times).
pub fn run(
    machine: &mut Machine,
    problems: &[(&SweepProblem, &Reference)],
    tolerances: &[f64],
    repeats: u32,
) -> PeerReport {
    if let Err(reason) = probe(machine) {
        return PeerReport::without(
            true,
            "absent",
            format!("SciPy comparison not available: {reason}."),
        );
    }
    let script = match ShippedScript::write("scipy_peer.py", SCRIPT_TEXT) {
        Ok(script) => script,
        Err(e) => {
            return PeerReport::without(
                true,
                "absent",
                format!("SciPy comparison not available: {SCRIPT} cannot be written ({e})."),
            )
        }
    };
    match execute(
        &script,
        &input(problems, tolerances, &SCIPY_METHODS, repeats),
    ) {
        Ok(out) => {
            machine.python = Some(out.python);
            machine.numpy = Some(out.numpy);
            machine.scipy = Some(out.scipy);
            let errors = out.points.iter().filter(|p| !p.ok()).count();
            // A run that finds a wrong number of slips and sticks failed too.
            let miscounted = out.points.iter().filter(|p| p.count_mismatch()).count();
            let mut report = PeerReport::without(
                true,
                "ok",
                format!(
                    "SciPy {} (Python {}): {} runs of solve_ivp, {} failed ({errors} returned \
                     an error, {miscounted} found a wrong number of events; these stay off the \
                     fronts and the ratios).",
                    machine.scipy.as_deref().unwrap_or("?"),
                    machine.python.as_deref().unwrap_or("?"),
                    out.points.len(),
                    errors + miscounted
                ),
            );
            report.points = out.points;
            report
        }
        Err(reason) => {
            PeerReport::without(true, "error", format!("SciPy comparison failed: {reason}."))
        }
    }
}

fn execute(script: &ShippedScript, input: &str) -> Result<ScriptOutput, String> {
    let mut child = script
        .command()
        .arg("-")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("cannot start python3 {SCRIPT}: {e}"))?;
    if let Some(mut stdin) = child.stdin.take() {
        stdin
            .write_all(input.as_bytes())
            .map_err(|e| format!("cannot feed the script: {e}"))?;
    }
    let out = child
        .wait_with_output()
        .map_err(|e| format!("python3 did not finish: {e}"))?;
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        return Err(format!(
            "{SCRIPT} exited with {}: {}",
            out.status,
            err.lines().last().unwrap_or("")
        ));
    }
    serde_json::from_slice(&out.stdout).map_err(|e| format!("unreadable output: {e}"))
}

/// The (time, error) curve of a SciPy method on a problem.
fn scipy_curve(points: &[PeerPoint], problem: &str, method: &str, m: Metric) -> Vec<(f64, f64)> {
    points
        .iter()
        .filter(|p| p.problem == problem && p.method == method)
        .filter_map(|p| Some((p.time_s?, p.error_in(m)?)))
        .collect()
}

/// Fills the ratio table and the issue's targets from the sweep and the peer points.
pub fn compare(
    report: &mut PeerReport,
    sweep: &[SweepPoint],
    problems: &[String],
    methods: &[String],
) {
    let peered: Vec<&String> = problems
        .iter()
        .filter(|id| report.points.iter().any(|p| &p.problem == *id))
        .collect();
    for problem in &peered {
        for metric in [Metric::EventTime, Metric::XEnd] {
            for &level in &RATIO_LEVELS {
                let scipy: Vec<Option<f64>> = SCIPY_METHODS
                    .iter()
                    .map(|m| {
                        cost_at(&scipy_curve(&report.points, problem, m, metric), level)
                            .map(|c| c.cost)
                    })
                    .collect();
                let best = SCIPY_METHODS
                    .iter()
                    .zip(&scipy)
                    .filter_map(|(m, t)| Some((*m, (*t)?)))
                    .min_by(|a, b| a.1.total_cmp(&b.1));
                for method in methods {
                    let ours =
                        cost_at(&time_curve(sweep, problem, method, metric), level).map(|c| c.cost);
                    report.ratios.push(RatioRow {
                        problem: (*problem).clone(),
                        metric,
                        level,
                        method: method.clone(),
                        time_s: ours,
                        scipy_time_s: scipy.clone(),
                        ratio_best: ours.zip(best).map(|(o, b)| o / b.1),
                        best_scipy: best.map(|b| b.0.to_string()),
                        ratio_rk45: ours.zip(scipy[0]).map(|(o, r)| o / r),
                    });
                }
            }
        }
    }
    report.targets = targets(&report.ratios, &peered);
}

/// The issue's targets: exact ≥ 1000× faster than SciPy's best at 1e-10 on the pulled mass,
/// dopri5 ≥ 50× faster than RK45 at equal error (the worst level counts).
fn targets(ratios: &[RatioRow], problems: &[&String]) -> Vec<TargetRow> {
    let mut out = Vec::new();
    for problem in problems.iter().filter(|p| p.starts_with("pulled_mass")) {
        let find = |method: &str, level: f64| {
            ratios.iter().find(|r| {
                &r.problem == *problem
                    && r.method == method
                    && r.metric == Metric::EventTime
                    && r.level == level
            })
        };
        let exact = find("exact", 1e-10).and_then(|r| r.ratio_best);
        out.push(TargetRow {
            target: "exact ≥ 1000× faster than SciPy's best at 1e-10 (event-time error)".into(),
            problem: (*problem).clone(),
            measured: exact.map_or("SciPy did not reach 1e-10".into(), |r| {
                format!(
                    "{:.0}× ({})",
                    1.0 / r,
                    find("exact", 1e-10)
                        .and_then(|r| r.best_scipy.clone())
                        .unwrap_or_default()
                )
            }),
            speedup: exact.map(|r| 1.0 / r),
            met: exact.map(|r| 1.0 / r >= 1000.0),
        });
        let speedups: Vec<(f64, f64)> = RATIO_LEVELS
            .iter()
            .filter_map(|&l| Some((l, 1.0 / find("dopri5", l)?.ratio_rk45?)))
            .collect();
        let worst = speedups.iter().copied().min_by(|a, b| a.1.total_cmp(&b.1));
        out.push(TargetRow {
            target: "dopri5 ≥ 50× faster than SciPy RK45 at equal error (event-time, worst level)"
                .into(),
            problem: (*problem).clone(),
            measured: match worst {
                Some((l, s)) => format!(
                    "{:.0}× at {l:.0e} (levels: {})",
                    s,
                    speedups
                        .iter()
                        .map(|(l, s)| format!("{l:.0e}: {s:.0}×"))
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
                None => "no common error level".into(),
            },
            speedup: worst.map(|w| w.1),
            met: worst.map(|w| w.1 >= 50.0),
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bench::problems::{
        boundary_problems, reference, sweep_problems, sweep_reference, BenchProblem,
    };
    use crate::engine::Affine;
    use serde_json::Value;

    /// The sweep and boundary problems (both models, both laws) and the script's input for them.
    fn problems_and_input() -> (Vec<BenchProblem>, String) {
        let mut problems = sweep_problems().unwrap();
        problems.extend(boundary_problems().unwrap());
        let references: Vec<Reference> = problems.iter().map(|bp| reference(bp).unwrap()).collect();
        let swept: Vec<SweepProblem> = problems.iter().cloned().map(SweepProblem::Paper).collect();
        let pairs: Vec<(&SweepProblem, &Reference)> = swept.iter().zip(&references).collect();
        let text = input(&pairs, &[1e-6], &SCIPY_METHODS, 1);
        (problems, text)
    }

    /// The script, or None (said on stderr) without python3 and SciPy.
    fn script_if_scipy() -> Option<ShippedScript> {
        if let Err(reason) = probe(&mut Machine::detect()) {
            eprintln!("skipped: {reason}");
            return None;
        }
        Some(ShippedScript::write("scipy_peer.py", SCRIPT_TEXT).expect("a temporary folder"))
    }

    /// Times over several periods: every piece start and middle, and irregular ones.
    fn times(bp: &BenchProblem) -> Vec<f64> {
        let law = &bp.problem.law;
        let mut out: Vec<f64> = (0..24).map(|k| f64::from(k) * 0.37 * law.period).collect();
        for n in [0.0, 1.0, 7.0] {
            for p in &law.pieces {
                out.extend([
                    n * law.period + p.start,
                    n * law.period + 0.5 * (p.start + p.end),
                ]);
            }
        }
        out
    }

    fn number(v: &Value, key: &str) -> f64 {
        v[key]
            .as_f64()
            .unwrap_or_else(|| panic!("{key} is a number in {v}"))
    }

    /// D and N_f at absolute time t from a serialized force law, read the way the script reads
    /// it: t mod period, the piece whose end is past it, c0 + c1·b (b = cos ωt − shift on a cos
    /// basis).
    fn evaluate(law: &Value, t: f64) -> (f64, f64) {
        let local = t.rem_euclid(number(law, "period"));
        let pieces = law["pieces"].as_array().expect("pieces");
        let i = pieces.partition_point(|p| number(p, "end") <= local);
        let p = &pieces[i.min(pieces.len() - 1)];
        let basis = &p["basis"];
        let b = match basis["kind"].as_str() {
            Some("linear") => local - number(basis, "t_ref"),
            Some("cos") => (number(basis, "omega") * local).cos() - number(basis, "shift"),
            other => panic!("basis kind {other:?}"),
        };
        let at = |a: &Value| number(a, "c0") + number(a, "c1") * b;
        (at(&p["drive"]), at(&p["normal"]))
    }

    /// |a − b| ≤ 1e-12·scale. serde_json's default float parsing (no `float_roundtrip`
    /// feature) may be an ulp off, which t − t_ref and ωt amplify; Python's is exact, and the
    /// script's forces are checked bit for bit below. A wrong piece or basis is off by far more.
    fn close(a: f64, b: f64, scale: f64) -> bool {
        (a - b).abs() <= 1e-12 * scale.abs()
    }

    #[test]
    fn a_scipy_run_with_a_wrong_event_count_is_a_failure() {
        let mut p: PeerPoint = serde_json::from_value(serde_json::json!({
            "problem": "p", "method": "RK45", "tol": 1e-8, "status": "ok", "error": null,
            "time_s": 1e-3, "runs": 1, "nfev": 100, "n_events": 40, "n_events_exact": 80,
            "err_event_s": 1e-9, "x_end_m": 0.1, "err_x_m": 1e-9
        }))
        .unwrap();
        assert!(p.ok() && p.count_mismatch());
        assert_eq!(p.error_in(Metric::EventTime), None);
        assert!(scipy_curve(&[p.clone()], "p", "RK45", Metric::EventTime).is_empty());
        p.n_events = Some(80);
        assert_eq!(p.error_in(Metric::EventTime), Some(1e-9));
        assert_eq!(p.error_in(Metric::XEnd), Some(1e-9));
    }

    #[test]
    fn the_serialized_law_and_body_give_the_engines_forces() {
        let (problems, text) = problems_and_input();
        let input: Value = serde_json::from_str(&text).unwrap();
        let sent = input["problems"].as_array().unwrap();
        assert_eq!(sent.len(), problems.len());
        for (bp, json) in problems.iter().zip(sent) {
            let (body, b) = (&json["body"], bp.problem.body);
            for (key, value) in [("mass", b.mass), ("mu_s", b.mu_s), ("mu_d", b.mu_d)] {
                assert!(close(number(body, key), value, value), "{} {key}", bp.id);
            }
            let (law, period) = (&json["force_law"], bp.period());
            assert!(close(number(law, "period"), period, period), "{}", bp.id);
            let pieces = law["pieces"].as_array().unwrap();
            assert_eq!(pieces.len(), bp.problem.law.pieces.len(), "{}", bp.id);
            for t in times(bp) {
                let (d, n) = bp.problem.forces(t);
                let piece = bp.problem.law.piece_at(t);
                let (sent_d, sent_n) = evaluate(law, t);
                let scale = |a: Affine| a.c0.abs() + a.c1.abs();
                assert!(
                    close(sent_d, d, scale(piece.drive)) && close(sent_n, n, scale(piece.normal)),
                    "{} at t = {t}: engine ({d}, {n}), sent ({sent_d}, {sent_n})",
                    bp.id
                );
            }
        }
    }

    #[test]
    fn the_belt_is_sent_as_its_surface_law_with_its_final_time() {
        let b = crate::bench::belt::bench().unwrap();
        let r = crate::bench::belt::reference(&b).unwrap();
        let sp = SweepProblem::Belt(b.clone());
        let text = input(&[(&sp, &r)], &[1e-6], &["RK45"], 1);
        let sent: Value = serde_json::from_str(&text).unwrap();
        let p = &sent["problems"][0];
        assert_eq!(
            (&p["id"], &p["model"], &p["law"]),
            (&json!("belt_default"), &json!("belt"), &json!("spring"))
        );
        assert!(p.get("force_law").is_none(), "{p}");
        let law = &p["surface_law"];
        let l = b.problem.law;
        for (key, want) in [
            ("drive", l.drive),
            ("stiffness", l.stiffness),
            ("normal", l.normal),
            ("surface_speed", l.surface_speed),
        ] {
            assert!(
                close(number(law, key), want, want.abs().max(1.0)),
                "{key}: {law}"
            );
        }
        // c = −k, N_f = m g, v_s = v_b (docs/belt.md (B6)).
        assert_eq!(l.stiffness, -b.params.k);
        assert_eq!(l.surface_speed, b.params.v_b);
        assert!(close(number(p, "t_end"), b.problem.t_end, b.problem.t_end));
        assert!(close(number(p, "period"), b.closed.period, b.closed.period));
        assert_eq!(p["exact"]["events"].as_array().unwrap().len(), 40);
        let body = &p["body"];
        assert!(close(number(body, "mass"), b.params.mass, 1.0));
    }

    /// RK45 at tolerance 1e-8 on the five sweep problems (the belt too) finds every exact slip
    /// and stick, to within 1e-7 s on the paper's (measured: 1.6e-8 s at most) and 1e-5 s on
    /// the belt, and takes no solve_ivp step while stuck: the
    /// stick ends come from the static margin, whose evaluations are counted (skipped without
    /// python3 and SciPy).
    #[test]
    fn the_script_finds_every_event_at_1e_8_and_takes_no_step_while_stuck() {
        let Some(script) = script_if_scipy() else {
            return;
        };
        let problems = crate::bench::problems::sweep().unwrap();
        assert_eq!(problems.len(), 5, "the paper's four and the belt");
        let references: Vec<Reference> = problems
            .iter()
            .map(|sp| sweep_reference(sp).unwrap())
            .collect();
        let pairs: Vec<(&SweepProblem, &Reference)> = problems.iter().zip(&references).collect();
        let out = execute(&script, &input(&pairs, &[1e-8], &["RK45"], 1)).expect("the script runs");
        assert_eq!(out.points.len(), 5);
        for (p, bp) in out.points.iter().zip(&problems) {
            assert_eq!(p.problem, bp.id());
            assert!(p.ok(), "{}: {:?}", p.problem, p.error);
            assert_eq!(p.n_events, Some(p.n_events_exact), "{}", p.problem);
            assert_eq!(p.n_missed, Some(0), "{}", p.problem);
            // On the belt a stick ends where the carried position reaches x_s, so a slip's
            // time inherits the position error of the stick before it over v_b (×20 here) and
            // the error grows over the cycles (measured 9.6e-7 s over 20 cycles; the tool's
            // dopri5 does the same: 6.7e-5 s at 1e-6 against SciPy RK45's 6.6e-5 s).
            let bound = if p.problem == crate::bench::belt::ID {
                1e-5
            } else {
                1e-7
            };
            assert!(
                p.err_event_s.unwrap() < bound,
                "{}: {:?}",
                p.problem,
                p.err_event_s
            );
            assert_eq!(p.steps_stuck, Some(0), "{}", p.problem);
            assert!(p.steps.unwrap() > 0 && p.nfev.unwrap() > 0, "{}", p.problem);
            // At least the onset of every slip is read off the margin.
            let slips = p.n_events_exact as u64 / 2;
            assert!(
                p.margin_evals.unwrap() >= slips,
                "{}: {:?}",
                p.problem,
                p.margin_evals
            );
        }
    }

    /// The script itself evaluates the law it is sent (skipped without python3 and SciPy).
    #[test]
    fn the_script_evaluates_the_serialized_law_like_the_engine() {
        let Some(script) = script_if_scipy() else {
            return;
        };
        // The input text goes through verbatim: parsed here, it could lose an ulp (below).
        let (problems, text) = problems_and_input();
        let times_json = json!(problems.iter().map(times).collect::<Vec<_>>());
        let request = format!(r#"{{"input": {text}, "times": {times_json}}}"#);
        // The forces come back as the bits of the doubles: serde_json's default float parsing
        // may be an ulp off, integers are exact.
        const PROGRAM: &str = "\
import importlib.util, json, struct, sys
spec = importlib.util.spec_from_file_location('scipy_peer', sys.argv[1])
peer = importlib.util.module_from_spec(spec)
spec.loader.exec_module(peer)
bits = lambda x: struct.unpack('<Q', struct.pack('<d', x))[0]
out = []
request = json.load(sys.stdin)
for p, times in zip(request['input']['problems'], request['times']):
    law = peer.build_law(p)
    out.append({'body': [bits(law.mass), bits(law.mu_s), bits(law.mu_d)],
                'forces': [[bits(law.drive(t)), bits(law.normal(t))] for t in times]})
json.dump(out, sys.stdout)
";
        let mut child = Command::new("python3")
            .args(["-c", PROGRAM])
            .arg(&script.path)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .spawn()
            .expect("python3 starts");
        child
            .stdin
            .take()
            .unwrap()
            .write_all(request.as_bytes())
            .unwrap();
        let out = child.wait_with_output().unwrap();
        assert!(out.status.success(), "the evaluation script failed");
        let got: Vec<Value> = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(got.len(), problems.len());
        let bits = |x: f64| json!(x.to_bits());
        for (bp, got) in problems.iter().zip(&got) {
            let b = bp.problem.body;
            let body = json!([bits(b.mass), bits(b.mu_s), bits(b.mu_d)]);
            assert_eq!(got["body"], body, "{}", bp.id);
            let forces = got["forces"].as_array().unwrap();
            assert_eq!(forces.len(), times(bp).len());
            // Same operations on the same doubles, but cos from the C library there and from
            // the libm crate here (src/fmath.rs), which may differ in the last bit: equal to
            // the rounding of the forces' scale (a force near its zero keeps that absolute
            // error, not its relative one).
            let want: Vec<(f64, f64)> = times(bp)
                .into_iter()
                .map(|t| bp.problem.forces(t))
                .collect();
            let scale = want
                .iter()
                .map(|(d, n)| d.abs().max(n.abs()))
                .fold(0.0, f64::max);
            let from_bits = |v: &Value| f64::from_bits(v.as_u64().unwrap());
            for ((t, (d, n)), f) in times(bp).into_iter().zip(want).zip(forces) {
                let (gd, gn) = (from_bits(&f[0]), from_bits(&f[1]));
                let close = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * scale;
                assert!(
                    close(gd, d) && close(gn, n),
                    "{} at t = {t}: {f} against {d}, {n}",
                    bp.id
                );
            }
        }
    }
}
