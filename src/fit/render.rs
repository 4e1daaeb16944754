//! The outputs of a finished fit: `fit.json` (the [`Fit`] in SI units), `fit.csv` (data, model
//! and residual at the tracked times, in the file's unit), `fit.svg` (the overlay of Figs. 26–27
//! with a residual panel) and the terminal table. Pure: strings in, [`OutFile`]s out.

use std::fmt::Write as _;
use std::path::Path;

use super::{Axis, Estimate, Fit};
use crate::error::{excerpt, excerpt_path, Error, Result};
use crate::export::num;
use crate::output::format::sig;
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
    serde_json::to_string_pretty(fit)
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
    let u = fit.data.unit.symbol();
    let s = &fit.series;
    let curve = |label: &str, points: Vec<(f64, f64)>, color: usize, stroke: Stroke| Curve {
        label: label.to_string(),
        points,
        color,
        stroke,
    };
    let zip = |y: &[f64]| s.t.iter().copied().zip(y.iter().copied()).collect();
    let spec = LineChart {
        x_label: "t (s)".to_string(),
        x_range: None,
        panels: vec![
            Panel {
                y_label: format!("y ({u})"),
                curves: vec![
                    curve("tracked", zip(&s.y), DATA_COLOR, Stroke::Solid),
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
                curves: vec![curve("", zip(&s.residual), DATA_COLOR, Stroke::Solid)],
                h_lines: vec![(0.0, String::new())],
            },
        ],
        markers: Vec::new(),
    };
    line_chart(&spec).map_err(|e| Error::Figure {
        id: "fit".to_string(),
        reason: e.to_string(),
    })
}

/// A model period that drifts more than this many periods from the data's over the tracked
/// span is warned about.
const MAX_DRIFT: f64 = 0.25;
/// Correlations beyond this (in absolute value) between physical parameters are warned about.
const STRONG_CORRELATION: f64 = 0.99;

/// Pairs of physical parameters whose estimates are strongly correlated.
fn strong_correlations(fit: &Fit) -> Vec<(&'static str, &'static str, f64)> {
    let Some(c) = &fit.correlation else {
        return Vec::new();
    };
    let physics: Vec<&Estimate> = fit.estimates.iter().filter(|e| !e.nuisance).collect();
    let mut out = Vec::new();
    for (i, a) in physics.iter().enumerate() {
        for (j, b) in physics.iter().enumerate().skip(i + 1) {
            if c[i][j].abs() > STRONG_CORRELATION {
                out.push((a.name, b.name, c[i][j]));
            }
        }
    }
    out
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
    let _ = writeln!(
        o,
        "data:     {} points, t = {} to {} s; time column {}, position column {} in {}; y axis {}",
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
        "fit:      {}{}, {} iterations, {} evaluations; starts tried: {}",
        if fit.converged { "" } else { "NOT CONVERGED: " },
        fit.termination,
        fit.iterations,
        fit.evaluations,
        fit.starts
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
    let strong = strong_correlations(fit);
    if !strong.is_empty() {
        let pairs: Vec<String> = strong
            .iter()
            .map(|(a, b, r)| format!("{a} and {b} at r = {r:.4}"))
            .collect();
        let _ = writeln!(
            o,
            "warning: correlated beyond {STRONG_CORRELATION}: {}; the data hardly separate \
             them: fix some of them (fewer --free)",
            pairs.join(", ")
        );
    }
    let p = &fit.params;
    let _ = writeln!(
        o,
        "\nfitted model: mu_s = {}, mu_d = {}, k = {} N/m, z0 = {} mm, d0 = {} mm; T = {} s, \
         first tracked time at phase {} T; regime {}, v̄ = {} mm/s",
        sig(Some(p.mu_s), 6),
        sig(Some(p.mu_d), 6),
        sig(Some(p.k), 6),
        sig(Some(p.z0 * 1e3), 6),
        sig(Some(p.d0 * 1e3), 6),
        sig(Some(fit.period), 6),
        sig(Some(fit.phase), 3),
        fit.regime,
        sig(fit.v_avg.map(|v| v * 1e3), 4)
    );
    let _ = writeln!(
        o,
        "wrote {0}/fit.json, {0}/fit.csv, {0}/fit.svg",
        excerpt_path(&out.display().to_string())
    );
    o
}
