//! Figures of the pulled mass (guide §5.1): motion under both laws, the competing forces,
//! the (μd, μs) domain of Fig. 9, the long run of Fig. 11 and the comparison of Fig. 12.

use rayon::prelude::*;

use crate::engine::analyse;
use crate::error::Result;
use crate::models::pulled_mass::formula::{self as cf, ClosedForm, Regime};
use crate::models::pulled_mass::map::{self, harmonic_category, linear_category, MAP_PERIODS};
use crate::models::pulled_mass::results::{evaluate_with_runs, Runs};
use crate::models::pulled_mass::PulledMassParams;
use crate::models::{pulled_mass, LawKind};
use crate::report::figures::spec::{CategoryMap, Curve, LineChart, Marker, Panel, Stroke};
use crate::report::scene::sampling::{curve, function_curve, sample, SAMPLES};
use crate::report::scene::{Drawing, Figure};

crate::present::vocab::figure_kinds! {
    /// What a scene of the pulled mass draws. Each kind may produce one or more figures.
    pub enum PulledFigure {
        /// x, v, a against t for both laws, with t_SL, t_M, t_ST (Figs. 5, 6, 10).
        Motion { periods: f64 } = "pulled-motion",
        /// F against μs N(t) and μd N(t), with t_SL, t_M, t_ST.
        Forces = "pulled-forces",
        /// The (μd, μs) domain for the scene's φ, both laws on a grid (Fig. 9).
        Domain = "pulled-domain",
        /// Position over 10 periods and the line of slope v̄ (Fig. 11).
        LongRun = "pulled-long-run",
        /// Speed and acceleration, harmonic against linear (Fig. 12).
        Compare = "pulled-compare",
    }
}

/// Palette indices and strokes of the two laws, the same in every figure.
const HARMONIC: (usize, Stroke) = (0, Stroke::Solid);
const LINEAR: (usize, Stroke) = (1, Stroke::Dashed);
/// Cells per side of the domain maps.
const GRID: usize = 200;

/// The figures of one kind for the pulled mass `p`.
pub fn figures(scene_id: &str, p: &PulledMassParams, kind: PulledFigure) -> Result<Vec<Figure>> {
    let figure = |name: &str, caption: String, drawing| Figure {
        id: format!("{scene_id}-{name}"),
        caption,
        drawing,
    };
    Ok(match kind {
        PulledFigure::Motion { periods } => {
            let (chart, caption) = motion(p, periods)?;
            vec![figure("motion", caption, Drawing::Chart(chart))]
        }
        PulledFigure::Forces => {
            let (chart, caption) = forces(p)?;
            vec![figure("forces", caption, Drawing::Chart(chart))]
        }
        PulledFigure::Domain => {
            let [(lin, lin_caption), (har, har_caption)] = domain(p)?;
            vec![
                figure("domain-linear", lin_caption, Drawing::Map(lin)),
                figure("domain-harmonic", har_caption, Drawing::Map(har)),
            ]
        }
        PulledFigure::LongRun => {
            let (chart, caption) = long_run(p)?;
            vec![figure("long-run", caption, Drawing::Chart(chart))]
        }
        PulledFigure::Compare => {
            let (chart, caption) = compare(p)?;
            vec![figure("compare", caption, Drawing::Chart(chart))]
        }
    })
}

/// Runs of both laws with segments, for at least `periods` periods (and 8 for the steady state).
fn runs(p: &PulledMassParams, periods: f64) -> Result<(ClosedForm, Runs)> {
    let n = (periods.ceil() as u32 + 2).max(8);
    let (e, runs) = evaluate_with_runs(p, n, true)?;
    Ok((e.closed_form, runs))
}

/// The characteristic times of the closed forms that describe the motion, inside [t0, t1].
fn markers(c: &ClosedForm, period: f64, t0: f64, t1: f64) -> Vec<Marker> {
    if c.immediate_slip {
        return Vec::new();
    }
    let mut times = vec![("t_SL", c.t_slip)];
    if c.tau_max_speed < 1.0 {
        times.push(("t_M", c.t_max_speed));
    }
    match c.regime {
        Regime::SlipStick => times.push(("t_ST", c.t_stick)),
        Regime::SlipStickLate => {
            if let Some(tau) = c.tau_stick_late {
                times.push(("t_ST,late", tau * period));
            }
        }
        _ => {}
    }
    let stuck_periodically = matches!(c.regime, Regime::SlipStick | Regime::SlipStickLate);
    let repeats = if stuck_periodically {
        (t1 / period).ceil() as i32
    } else {
        1
    };
    (0..repeats)
        .flat_map(|n| {
            times.iter().map(move |&(label, t)| Marker {
                x: t + f64::from(n) * period,
                label: label.to_string(),
            })
        })
        .filter(|m| m.x >= t0 && m.x <= t1)
        .collect()
}

fn law_curves(runs: &Runs, t0: f64, t1: f64, col: usize, scale: f64) -> Vec<Curve> {
    let h = sample(&runs.harmonic, t0, t1, SAMPLES);
    let l = sample(&runs.linear, t0, t1, SAMPLES);
    vec![
        curve("harmonic law", &h, col, scale, HARMONIC.0, HARMONIC.1),
        curve("linearized law", &l, col, scale, LINEAR.0, LINEAR.1),
    ]
}

fn panel(y_label: &str, curves: Vec<Curve>) -> Panel {
    Panel {
        y_label: y_label.to_string(),
        curves,
        h_lines: Vec::new(),
    }
}

fn motion(p: &PulledMassParams, periods: f64) -> Result<(LineChart, String)> {
    let (c, runs) = runs(p, periods)?;
    let t1 = periods * p.period();
    let chart = LineChart {
        x_label: "t (s)".to_string(),
        x_range: Some((0.0, t1)),
        panels: vec![
            panel("x (mm)", law_curves(&runs, 0.0, t1, 1, 1e3)),
            panel("v (mm/s)", law_curves(&runs, 0.0, t1, 2, 1e3)),
            panel("a (m/s²)", law_curves(&runs, 0.0, t1, 3, 1.0)),
        ],
        markers: markers(&c, p.period(), 0.0, t1),
    };
    let caption = format!(
        "Position, speed and acceleration of the pulled mass over {periods} periods, harmonic law \
         (solid) and linearized law (dashed), from rest at t = 0. Marked: the closed-form times \
         of the linearized law ({}).",
        c.regime.words()
    );
    Ok((chart, caption))
}

fn forces(p: &PulledMassParams) -> Result<(LineChart, String)> {
    let (c, _) = runs(p, 1.5)?;
    let period = p.period();
    let t1 = 1.5 * period;
    let lin = pulled_mass::force_law(p, LawKind::Linear)?;
    let har = pulled_mass::force_law(p, LawKind::Harmonic)?;
    let n = SAMPLES;
    let curves = vec![
        function_curve("F", 0.0, t1, 2, |_| p.force, 7, Stroke::Solid),
        function_curve(
            "μs N (linearized)",
            0.0,
            t1,
            n,
            |t| p.mu_s * lin.normal(t),
            0,
            Stroke::Dashed,
        ),
        function_curve(
            "μd N (linearized)",
            0.0,
            t1,
            n,
            |t| p.mu_d * lin.normal(t),
            1,
            Stroke::DashDot,
        ),
        function_curve(
            "μs N (harmonic)",
            0.0,
            t1,
            n,
            |t| p.mu_s * har.normal(t),
            0,
            Stroke::Dotted,
        ),
    ];
    let chart = LineChart {
        x_label: "t (s)".to_string(),
        x_range: Some((0.0, t1)),
        panels: vec![panel("force (N)", curves)],
        markers: markers(&c, period, 0.0, t1),
    };
    let caption = format!(
        "The pull F = {} N against the static capacity μs N(t) and the dynamic friction μd N(t) \
         of the linearized law (the harmonic μs N dotted). The slip starts where F first exceeds \
         μs N (t_SL); while slipping the acceleration is (F − μd N)/2m, largest speed where F = \
         μd N (t_M).",
        p.force
    );
    Ok((chart, caption))
}

fn long_run(p: &PulledMassParams) -> Result<(LineChart, String)> {
    let (c, runs) = runs(p, 10.0)?;
    let period = p.period();
    let t1 = 10.0 * period;
    let mut curves = law_curves(&runs, 0.0, t1, 1, 1e3);
    // The line of slope v̄ through the slip onsets of the linear law: x = v̄ (t − t_SL).
    let steady = analyse(&runs.linear);
    let v_bar = match c.regime {
        Regime::SlipStick => Some(c.v_avg),
        Regime::SlipStickLate => c.v_avg_late,
        _ => steady.v_avg,
    };
    if let (Some(v), Some(t_sl)) = (v_bar, runs.linear.first_slip) {
        curves.push(function_curve(
            "slope v̄ (closed form)",
            t_sl,
            t1,
            2,
            |t| 1e3 * v * (t - t_sl),
            2,
            Stroke::Dotted,
        ));
    }
    let chart = LineChart {
        x_label: "t (s)".to_string(),
        x_range: Some((0.0, t1)),
        panels: vec![panel("x (mm)", curves)],
        markers: Vec::new(),
    };
    let caption = format!(
        "Position over ten periods, harmonic (solid) and linearized (dashed) law, and the line of \
         slope v̄ = {} mm/s of the closed forms through the slip onsets of the linearized law.",
        v_bar.map_or("—".to_string(), |v| format!("{:.4}", 1e3 * v))
    );
    Ok((chart, caption))
}

fn compare(p: &PulledMassParams) -> Result<(LineChart, String)> {
    let (_, runs) = runs(p, 8.0)?;
    let period = p.period();
    // The settled motion: the last two integrated periods.
    let t1 = f64::from(runs.linear.periods) * period;
    let t0 = t1 - 2.0 * period;
    let chart = LineChart {
        x_label: "t (s)".to_string(),
        x_range: Some((t0, t1)),
        panels: vec![
            panel("v (mm/s)", law_curves(&runs, t0, t1, 2, 1e3)),
            panel("a (m/s²)", law_curves(&runs, t0, t1, 3, 1.0)),
        ],
        markers: Vec::new(),
    };
    let caption = "Speed and acceleration in the settled motion (the last two of the integrated \
                   periods): harmonic law (solid) against the linearized law (dashed)."
        .to_string();
    Ok((chart, caption))
}

fn domain(p: &PulledMassParams) -> Result<[(CategoryMap, String); 2]> {
    let phi = p.phi();
    let top = map::top(phi);
    let step = top / GRID as f64;
    let centre = |i: usize| (i as f64 + 0.5) * step;
    let grid = |cell: &(dyn Fn(f64, f64) -> u8 + Sync)| -> Vec<Vec<u8>> {
        (0..GRID)
            .into_par_iter()
            .map(|row| {
                (0..GRID)
                    .map(|col| cell(centre(row), centre(col)))
                    .collect()
            })
            .collect()
    };
    let linear_cells = grid(&|mu_s, mu_d| linear_category(phi, mu_s, mu_d));
    let harmonic_cells = grid(&|mu_s, mu_d| harmonic_category(p, mu_s, mu_d));
    let mut curves = domain_curves(phi, top);
    curves.extend(Curve::point_marker(
        "this scene (μd, μs)",
        (p.mu_d, p.mu_s),
        (0.0, top),
        (0.0, top),
        0,
    ));
    let map = |cells, categories| CategoryMap {
        x_label: "μd".to_string(),
        y_label: "μs".to_string(),
        x_range: (0.0, top),
        y_range: (0.0, top),
        cells,
        categories,
        curves: curves.clone(),
    };
    let labels = |categories: &[(&str, usize)]| {
        categories
            .iter()
            .map(|&(label, fill)| (label.to_string(), fill))
            .collect()
    };
    let linear = map(linear_cells, labels(&map::LINEAR_CATEGORIES));
    let harmonic = map(harmonic_cells, labels(&map::HARMONIC_CATEGORIES));
    let about = format!(
        "Grid of {GRID}×{GRID} cells for φ = F/W = {phi:.4}. Curves: the boundary of (20) \
         (same-period stick), the boundary φ = φ_c of any stick (late stick), and the immediate-slip \
         line μs = φ/2. On the diagonal μs = μd, (22) gives μ_MIN = {:.4}; any stick needs only \
         μ > φ = {phi:.4}.",
        cf::mu_min_equal(phi)
    );
    Ok([
        (
            linear,
            format!("Regimes of the linearized law from the closed forms. {about}"),
        ),
        (
            harmonic,
            format!(
                "Regimes of the harmonic law by exact integration ({MAP_PERIODS} periods per \
                 cell). {about}"
            ),
        ),
    ])
}

/// The analytic boundaries of Fig. 9 in the (μd, μs) plane.
fn domain_curves(phi: f64, top: f64) -> Vec<Curve> {
    let n = 400;
    // (20): φ < μd ≤ (1+√2)φ/2 and μs = μd φ/(φ − √(φ² + 4μdφ − 4μd²)).
    let upper = cf::mu_min_equal(phi);
    let same_period: Vec<(f64, f64)> = (1..=n)
        .map(|i| phi + (upper - phi) * i as f64 / n as f64)
        .filter_map(|mu_d| {
            let root = (phi * phi + 4.0 * mu_d * phi - 4.0 * mu_d * mu_d)
                .max(0.0)
                .sqrt();
            let mu_s = mu_d * phi / (phi - root);
            (mu_s.is_finite() && mu_s > 0.0 && mu_s <= top).then_some((mu_d, mu_s))
        })
        .collect();
    // φ = φ_c(μs, μd): for each μd, the μs where the late-stick band ends (bisection).
    let any_stick: Vec<(f64, f64)> = (0..=n)
        .map(|i| top * i as f64 / n as f64)
        .filter_map(|mu_d| {
            let f = |mu_s: f64| cf::phi_continuous(mu_s, mu_d) - phi;
            if mu_d <= 0.0 || f(mu_d) >= 0.0 || f(top) < 0.0 {
                return None;
            }
            let (mut lo, mut hi) = (mu_d, top);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if f(mid) < 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            Some((mu_d, 0.5 * (lo + hi)))
        })
        // The band closes on the diagonal at μs = μd = φ (φ_c = μ there).
        .chain(std::iter::once((phi, phi)))
        .collect();
    vec![
        Curve {
            label: "boundary of (20)".to_string(),
            points: same_period,
            color: 7,
            stroke: Stroke::Solid,
        },
        Curve {
            label: "φ = φ_c (any stick)".to_string(),
            points: any_stick,
            color: 7,
            stroke: Stroke::Dashed,
        },
        Curve {
            label: "μs = φ/2 (immediate slip below)".to_string(),
            points: vec![(0.0, 0.5 * phi), (top, 0.5 * phi)],
            color: 7,
            stroke: Stroke::Dotted,
        },
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_domain_maps_mark_the_scenes_own_point() {
        let p = PulledMassParams::default();
        for map in domain(&p).unwrap() {
            let marker = map
                .0
                .curves
                .iter()
                .find(|c| c.label == "this scene (μd, μs)")
                .expect("a marker");
            let centre = marker.points[..4]
                .iter()
                .fold((0.0, 0.0), |(x, y), p| (x + p.0, y + p.1));
            assert!((centre.0 / 4.0 - p.mu_d).abs() < 1e-12);
            assert!((centre.1 / 4.0 - p.mu_s).abs() < 1e-12);
        }
    }

    #[test]
    fn every_pulled_kind_builds_finite_curves() {
        let p = PulledMassParams {
            mu_d: 0.35,
            force: 0.10,
            ..PulledMassParams::default()
        };
        for kind in [
            PulledFigure::Motion { periods: 2.0 },
            PulledFigure::Forces,
            PulledFigure::LongRun,
            PulledFigure::Compare,
        ] {
            let figs = figures("t", &p, kind).unwrap();
            assert_eq!(figs.len(), 1, "{kind:?}");
            let Drawing::Chart(chart) = &figs[0].drawing else {
                panic!("{kind:?} is a chart")
            };
            for panel in &chart.panels {
                for c in &panel.curves {
                    assert!(!c.points.is_empty(), "{kind:?} {}", c.label);
                    assert!(c.points.iter().all(|(x, y)| x.is_finite() && y.is_finite()));
                }
            }
        }
    }

    #[test]
    fn domain_maps_agree_with_the_closed_forms_where_they_are_exact() {
        let p = PulledMassParams::default();
        let figs = figures("t", &p, PulledFigure::Domain).unwrap();
        assert_eq!(figs.len(), 2);
        let Drawing::Map(linear) = &figs[0].drawing else {
            panic!("map")
        };
        assert_eq!(linear.cells.len(), GRID);
        assert!(linear.cells.iter().all(|r| r.len() == GRID));
        // Every linear category appears for the Fig. 6 value of φ.
        for cat in 0..=4u8 {
            assert!(
                linear.cells.iter().flatten().any(|&c| c == cat),
                "category {cat}"
            );
        }
        // The (20) boundary meets the diagonal at μ_MIN of (22).
        let end = linear.curves[0].points.last().copied().unwrap();
        assert!((end.0 - end.1).abs() < 1e-9 && (end.0 - cf::mu_min_equal(p.phi())).abs() < 1e-9);
    }
}
