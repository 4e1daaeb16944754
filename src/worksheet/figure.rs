//! The student's v(t) figure: the linearized law from rest over two periods on graph paper (a
//! fine horizontal grid of round spacing), without the answer marked.

use crate::engine::Run;
use crate::error::{Error, Result};
use crate::report::figures::chart::line_chart;
use crate::report::figures::spec::{LineChart, Panel, Stroke};
use crate::report::scene::sampling::{curve, sample};

/// Points of the figure over its two periods (event times are added).
const FIGURE_SAMPLES: usize = 2000;
/// Periods shown.
const FIGURE_PERIODS: f64 = 2.0;
/// Fine grid lines: about this many over the plotted speed range.
const FINE_LINES: f64 = 20.0;

/// A round spacing (1, 2 or 5 × 10ⁿ) that cuts `range` into about [`FINE_LINES`] parts.
fn fine_spacing(range: f64) -> f64 {
    let raw = range / FINE_LINES;
    let decade = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .find(|m| m * decade >= raw)
        .unwrap_or(10.0);
    step * decade
}

/// v(t) of the linearized law over two periods from rest, on graph paper: a fine horizontal
/// grid whose spacing (m/s) is returned; the reading tolerance is half of it.
pub fn v_figure(run: &Run) -> Result<(String, f64)> {
    let t1 = FIGURE_PERIODS * run.period;
    let samples = sample(run, 0.0, t1, FIGURE_SAMPLES);
    let top = samples.iter().fold(0.0_f64, |top, s| top.max(s[2]));
    let figure_error = |reason: String| Error::Figure {
        id: "worksheet v(t)".to_string(),
        reason,
    };
    if !(top.is_finite() && top > 0.0) {
        return Err(figure_error(format!(
            "no motion to plot (largest speed {top} m/s)"
        )));
    }
    let spacing = fine_spacing(top);
    let lines = (1..)
        .map(|k| f64::from(k) * spacing)
        .take_while(|&y| y <= top)
        .map(|y| (y, String::new()))
        .collect();
    let chart = LineChart {
        x_label: "t (s)".to_string(),
        x_range: Some((0.0, t1)),
        panels: vec![Panel {
            y_label: "v (m/s)".to_string(),
            // No legend: the only curve is the student's.
            curves: vec![curve("", &samples, 2, 1.0, 0, Stroke::Solid)],
            h_lines: lines,
        }],
        markers: Vec::new(),
    };
    let svg = line_chart(&chart).map_err(|e| figure_error(e.to_string()))?;
    Ok((svg, spacing))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fine_grid_spacing_is_round_and_about_a_twentieth() {
        for (range, spacing) in [(0.113, 0.01), (0.031, 0.002), (1.0, 0.05), (0.23, 0.02)] {
            let got = fine_spacing(range);
            assert!((got - spacing).abs() < 1e-12 * spacing, "{range}: {got}");
        }
    }
}
