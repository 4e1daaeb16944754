//! The worksheet's figures. On the student's sheet, the forces of the linearized law over one
//! period on graph paper: the driving force against the static and dynamic friction limits, from
//! which the slip onset is read (the slip condition, not the answers). In the answer key, v(t)
//! from rest over two periods (fine horizontal grid of round spacing).

use crate::engine::Run;
use crate::error::{Error, Result};
use crate::lang::Lang;
use crate::models::{LawKind, Model};
use crate::report::figures::chart::line_chart_in;
use crate::report::figures::spec::{Curve, LineChart, Marker, Panel, Stroke};
use crate::report::figures::style::Geometry;
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
    let svg = line_chart_in(&chart, Geometry::COLUMN).map_err(|e| figure_error(e.to_string()))?;
    Ok((svg, spacing))
}

/// Samples of each force curve over the period (the pieces' ends are added).
const FORCE_SAMPLES: usize = 800;

/// The time step (s) of the forces figure's vertical grid: a round spacing of about a twentieth
/// of the period. The reading tolerance of a time is half of it.
pub fn time_spacing(case: &Model) -> Result<f64> {
    Ok(fine_spacing(case.force_law(LawKind::Linear)?.period))
}

/// The forces of `case`'s linearized law over one period, on graph paper: the driving force
/// and the friction limits μs·N and μd·N, and light vertical lines every [`time_spacing`], in
/// `lang`'s words and decimal sign.
pub fn force_figure(case: &Model, lang: Lang) -> Result<String> {
    let catalogue = lang.catalogue()?;
    let labels = catalogue.list(&format!("{}.force_labels", case.id()))?;
    let (Some(drive), Some(stat), Some(dynamic)) = (labels.first(), labels.get(1), labels.get(2))
    else {
        return Err(Error::Template {
            name: format!("templates/lang/{}.toml", lang.code()),
            reason: format!("{}.force_labels needs three labels", case.id()),
        });
    };
    let figure_error = |reason: String| Error::Figure {
        id: "worksheet forces".to_string(),
        reason,
    };
    let law = case.force_law(LawKind::Linear)?;
    let body = case.body();
    let period = law.period;
    let mut times: Vec<f64> = (0..=FORCE_SAMPLES)
        .map(|i| period * i as f64 / FORCE_SAMPLES as f64)
        .chain(law.pieces.iter().map(|p| p.end.min(period)))
        .collect();
    times.sort_by(f64::total_cmp);
    times.dedup();
    // Just before the period's end, so that the last piece (not the next period's first) is
    // evaluated there.
    let at = |t: f64| {
        if t >= period {
            period * (1.0 - 1e-12)
        } else {
            t
        }
    };
    let line = |label: &str, color, stroke, f: &dyn Fn(f64) -> f64| Curve {
        label: label.to_string(),
        points: times.iter().map(|&t| (t, f(at(t)))).collect(),
        color,
        stroke,
    };
    let spacing = time_spacing(case)?;
    let grid = (1..)
        .map(|k| f64::from(k) * spacing)
        .take_while(|&t| t < period)
        .map(|x| Marker {
            x,
            label: String::new(),
        })
        .collect();
    let chart = LineChart {
        x_label: "t (s)".to_string(),
        x_range: Some((0.0, period)),
        panels: vec![Panel {
            y_label: catalogue.text("sheet.force_axis", &[])?,
            curves: vec![
                line(drive, 7, Stroke::Solid, &|t| law.drive(t)),
                line(stat, 0, Stroke::Dashed, &|t| body.mu_s * law.normal(t)),
                line(dynamic, 1, Stroke::DashDot, &|t| body.mu_d * law.normal(t)),
            ],
            h_lines: Vec::new(),
        }],
        markers: grid,
    };
    let svg = line_chart_in(&chart, Geometry::COLUMN).map_err(|e| figure_error(e.to_string()))?;
    Ok(lang.svg_numbers(&svg))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_force_figure_has_the_three_forces_and_a_time_grid() {
        let case = Model::defaults()[0];
        let (svg, spacing) = (
            force_figure(&case, Lang::En).unwrap(),
            time_spacing(&case).unwrap(),
        );
        for label in ["pull F", "static limit", "dynamic limit", "force (N)"] {
            assert!(svg.contains(label), "{label}");
        }
        let period = case.force_law(LawKind::Linear).unwrap().period;
        assert!(
            spacing > period / 45.0 && spacing <= period / 10.0,
            "{spacing} {period}"
        );
        // The time grid: light vertical lines, no marker labels.
        assert!(svg.matches("stroke=\"#E3E3E3\"").count() >= 10);
        let italian = force_figure(&case, Lang::It).unwrap();
        assert!(italian.contains("trazione F") && italian.contains("forza (N)"));
    }

    #[test]
    fn fine_grid_spacing_is_round_and_about_a_twentieth() {
        for (range, spacing) in [(0.113, 0.01), (0.031, 0.002), (1.0, 0.05), (0.23, 0.02)] {
            let got = fine_spacing(range);
            assert!((got - spacing).abs() < 1e-12 * spacing, "{range}: {got}");
        }
    }
}
