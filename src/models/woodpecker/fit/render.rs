//! The outputs of a finished fit: `fit.json` (the [`Fit`] in SI units), `fit.csv` (data, model
//! and residual at the tracked times, in the file's unit), `fit.svg` (the overlay of Figs. 26–27
//! with a residual panel) and the terminal table. Pure: strings in, [`OutFile`]s out.

use std::fmt::Write as _;
use std::path::Path;

use super::{Axis, Estimate, Fit};
use crate::error::{excerpt, excerpt_path, Error, Result};
use crate::export::num;
use crate::format::sig;
use crate::report::context::regime_words;
use crate::report::figures::chart::line_chart;
use crate::report::figures::spec::{Curve, LineChart, Panel, Stroke};
use crate::report::OutFile;

/// Palette indices: tracked data in vermillion (the paper's red), the model in black.
const DATA_COLOR: usize = 1;
const MODEL_COLOR: usize = 7;

/// fit.json, fit.csv and fit.svg.
pub fn render(fit: &Fit) -> Result<Vec<OutFile>> {
    Ok(vec![
        OutFile {
            path: "fit.json".into(),
            bytes: json(fit)?.into_bytes(),
        },
        OutFile {
            path: "fit.csv".into(),
            bytes: csv(fit).into_bytes(),
        },
        OutFile {
            path: "fit.svg".into(),
            bytes: svg(fit)?.into_bytes(),
        },
    ])
}

/// The fit as pretty JSON (SI units), with a final newline.
pub fn json(fit: &Fit) -> Result<String> {
    serde_json::to_string_pretty(&crate::results::Versioned::new(fit))
        .map(|s| s + "\n")
        .map_err(|e| Error::Output {
            path: "fit.json".to_string(),
            reason: e.to_string(),
        })
}

fn csv(fit: &Fit) -> String {
    let u = fit.data.unit.symbol();
    let s = &fit.series;
    let mut text = format!("t_s,y_data_{u},y_model_{u},residual_{u}\n");
    for i in 0..s.t.len() {
        let _ = writeln!(
            text,
            "{},{},{},{}",
            num(s.t[i]),
            num(s.y[i]),
            num(s.model[i]),
            num(s.residual[i])
        );
    }
    text
}

fn svg(fit: &Fit) -> Result<String> {
    line_chart(&chart(fit)).map_err(|e| Error::Figure {
        id: "fit".to_string(),
        reason: e.to_string(),
    })
}

/// The overlay of Figs. 26–27: the tracked points and the fitted model, and the residuals.
pub fn chart(fit: &Fit) -> LineChart {
    let u = fit.data.unit.symbol();
    let s = &fit.series;
    let curve = |label: &str, points: Vec<(f64, f64)>, color: usize, stroke: Stroke| Curve {
        label: label.to_string(),
        points,
        color,
        stroke,
    };
    let zip = |y: &[f64]| s.t.iter().copied().zip(y.iter().copied()).collect();
    LineChart {
        x_label: "t (s)".to_string(),
        x_range: None,
        panels: vec![
            Panel {
                y_label: format!("y ({u})"),
                curves: vec![
                    curve("tracked", zip(&s.y), DATA_COLOR, Stroke::Points),
                    curve(
                        "model (harmonic law, fitted)",
                        s.curve.clone(),
                        MODEL_COLOR,
                        Stroke::Dashed,
                    ),
                ],
                h_lines: Vec::new(),
            },
            Panel {
                y_label: format!("model − data ({u})"),
                curves: vec![curve("", zip(&s.residual), DATA_COLOR, Stroke::Points)],
                h_lines: vec![(0.0, String::new())],
            },
        ],
        markers: Vec::new(),
    }
}

/// A model period that drifts more than this many periods from the data's over the tracked
/// span is warned about.
const MAX_DRIFT: f64 = 0.25;
/// Correlations from this (in absolute value) between physical parameters are warned about:
/// at |r| = 0.95 an error in one is compensated by the other to 95 %.
pub const STRONG_CORRELATION: f64 = 0.95;

/// A pair of physical parameters whose estimates are strongly correlated, and the one to fix:
/// the one in most such pairs (fixing it separates them all), else the one the data determine
/// worse (larger relative standard error).
#[derive(Clone, Debug, PartialEq)]
pub struct Correlated {
    pub a: &'static str,
    pub b: &'static str,
    pub r: f64,
    pub fix: &'static str,
}

/// Pairs of physical parameters whose estimates are strongly correlated.
pub fn strong_correlations(fit: &Fit) -> Vec<Correlated> {
    let Some(c) = &fit.correlation else {
        return Vec::new();
    };
    let physics: Vec<&Estimate> = fit.estimates.iter().filter(|e| !e.nuisance).collect();
    let n = physics.len();
    let pairs: Vec<(usize, usize)> = (0..n)
        .flat_map(|i| (i + 1..n).map(move |j| (i, j)))
        .filter(|&(i, j)| c[i][j].abs() >= STRONG_CORRELATION)
        .collect();
    let count = |k: usize| pairs.iter().filter(|&&(i, j)| i == k || j == k).count();
    let relative = |k: usize| {
        let e = physics[k];
        e.std_error.map_or(f64::INFINITY, |se| se / e.value.abs())
    };
    let rank = |k: usize| (count(k), relative(k));
    pairs
        .iter()
        .map(|&(i, j)| Correlated {
            a: physics[i].name,
            b: physics[j].name,
            r: c[i][j],
            fix: if rank(i) >= rank(j) {
                physics[i].name
            } else {
                physics[j].name
            },
        })
        .collect()
}

/// The correlation matrix of the estimates as a text table (two decimals).
fn correlation_table(fit: &Fit) -> String {
    let Some(c) = &fit.correlation else {
        return "correlations: not available (JᵀJ is singular)\n".to_string();
    };
    let names: Vec<&str> = fit.estimates.iter().map(|e| e.name).collect();
    let mut o = format!("correlations:\n{:<12}", "");
    for n in &names {
        let _ = write!(o, " {n:>11}");
    }
    o.push('\n');
    for (name, row) in names.iter().zip(c) {
        let _ = write!(o, "{name:<12}");
        for r in row {
            let _ = write!(o, " {:>11}", format!("{r:+.2}").replace('-', "−"));
        }
        o.push('\n');
    }
    o
}

/// Lengths are shown in mm in the table (the paper's unit), other values in SI.
fn shown(e: &Estimate) -> (String, f64) {
    match e.unit {
        "m" => (format!("{} (mm)", e.name), 1e3),
        "" => (e.name.to_string(), 1.0),
        unit => (format!("{} ({unit})", e.name), 1.0),
    }
}

/// The terminal summary: data, termination, the table of estimates, the fitted model.
pub fn text(fit: &Fit, out: &Path) -> String {
    let d = &fit.data;
    let s = &fit.series;
    let mut o = String::new();
    // The file name and the header names are the user's: escaped, bounded.
    let _ = writeln!(o, "stickslip fit {}", excerpt_path(&d.file));
    let skipped = match (d.skipped_rows, d.first_skipped_line) {
        (0, _) => String::new(),
        (n, Some(line)) => format!(
            " ({n} rows skipped for a blank cell in the time or position column, the first on \
             line {line})"
        ),
        (n, None) => format!(" ({n} rows skipped for a blank cell)"),
    };
    let _ = writeln!(
        o,
        "data:     {} points{skipped}, t = {} to {} s; time column {}, position column {} in {}; \
         y axis {}",
        fit.n,
        sig(s.t.first().copied(), 4),
        sig(s.t.last().copied(), 4),
        excerpt(&d.time_column, 40),
        excerpt(&d.position_column, 40),
        d.unit.symbol(),
        match fit.axis {
            Axis::Down => "down (grows as the toy falls)",
            Axis::Up => "up (the toy falls to smaller y)",
        }
    );
    let _ = writeln!(
        o,
        "fit:      {}{}, {} iterations, {} evaluations; from {} centres (the given values \
         and ±{} % around them, {} starts in phase), {} of them ending in this minimum",
        if fit.converged { "" } else { "NOT CONVERGED: " },
        fit.termination,
        fit.iterations,
        fit.evaluations,
        fit.centres,
        super::solve::SPREAD * 100.0,
        fit.starts,
        fit.centres_at_best
    );
    let _ = writeln!(
        o,
        "residual: RMS {} mm, s = {} mm, n = {}, p = {}; lag-1 autocorrelation {} \
         (0 for white noise, near 1 for a systematic misfit)",
        sig(Some(fit.rms_residual * 1e3), 3),
        sig(Some(fit.residual_variance.sqrt() * 1e3), 3),
        fit.n,
        fit.p,
        sig(Some(fit.residual_autocorrelation), 2)
    );
    let v = &fit.verdict;
    if v.describes {
        let _ = writeln!(
            o,
            "verdict:  the model describes these data: the residual is {} the noise the data \
             show on their own ({} mm), and not systematic",
            v.rms_over_noise
                .map_or("within".to_string(), |q| format!("{}×", sig(Some(q), 2))),
            sig(v.noise.map(|s| s * 1e3), 2)
        );
    } else {
        let _ = writeln!(
            o,
            "verdict:  {}. The values below are the best minimum found, not a measurement of \
             the toy, and their standard errors mean nothing.",
            v.sentence().replacen(
                "the model does not describe these data",
                "THE MODEL DOES NOT DESCRIBE THESE DATA",
                1
            )
        );
    }
    let _ = writeln!(
        o,
        "\n{:<16} {:>12} {:>10} {:>8} {:>12}",
        "parameter", "value", "std error", "rel.", "start"
    );
    for e in &fit.estimates {
        let (label, scale) = shown(e);
        let rel = match e.std_error {
            Some(se) if e.value != 0.0 && !e.nuisance => {
                format!("{:.2} %", 100.0 * se / e.value.abs())
            }
            _ => String::new(),
        };
        let _ = writeln!(
            o,
            "{:<16} {:>12} {:>10} {:>8} {:>12}{}",
            label,
            sig(Some(e.value * scale), 6),
            sig(e.std_error.map(|x| x * scale), 2),
            rel,
            sig(Some(e.start * scale), 6),
            if e.nuisance { "  (nuisance)" } else { "" }
        );
    }
    // Over N tracked periods a period off by δT/T puts the model N δT/T periods out of step.
    let tracked_periods = (s.t[s.t.len() - 1] - s.t[0]) / fit.period;
    let drift = (fit.period / fit.data_period - 1.0).abs() * tracked_periods;
    if drift > MAX_DRIFT {
        let _ = writeln!(
            o,
            "warning: the data repeat every {} s, the model every {} s: {} periods out of step \
             over the {} tracked; give the toy's k (or m_bird), or fit k (--free ...,k)",
            sig(Some(fit.data_period), 4),
            sig(Some(fit.period), 4),
            sig(Some(drift), 2),
            sig(Some(tracked_periods), 3)
        );
    }
    let _ = write!(o, "\n{}", correlation_table(fit));
    // Which parameter to fix is advice for a fit that describes the data.
    let advice = if v.describes {
        strong_correlations(fit)
    } else {
        Vec::new()
    };
    for c in advice {
        let _ = writeln!(
            o,
            "warning: {} and {} are correlated at r = {} (|r| ≥ {STRONG_CORRELATION}): the \
             data hardly separate them, and an error in one is made up by the other. Fix {} \
             at a measured value (leave it out of --free) and fit again.",
            c.a,
            c.b,
            format!("{:.3}", c.r).replace('-', "−"),
            c.fix
        );
    }
    let p = &fit.params;
    let _ = writeln!(
        o,
        "\nfitted model: mu_s = {}, mu_d = {}, k = {} N/m, z0 = {} mm, d0 = {} mm; T = {} s, \
         first tracked time at phase {} T; {}, v̄ = {} mm/s",
        sig(Some(p.mu_s), 6),
        sig(Some(p.mu_d), 6),
        sig(Some(p.k), 6),
        sig(Some(p.z0 * 1e3), 6),
        sig(Some(p.d0 * 1e3), 6),
        sig(Some(fit.period), 6),
        sig(Some(fit.phase), 3),
        regime_words(fit.regime),
        sig(fit.v_avg.map(|v| v * 1e3), 4)
    );
    let _ = writeln!(
        o,
        "wrote {0}/fit.json, {0}/fit.csv, {0}/fit.svg",
        excerpt_path(&out.display().to_string())
    );
    o
}
