//! Figures of the falling woodpecker (guide §5.2 and guide §8): the sleeve's motion under both laws,
//! the spring coordinate against its linear counterparts, the forces that decide the slip, the
//! two phases of the linear law with their characteristic times, the μd sweep around μd,MIN,
//! the positions of sleeve and bird, and the regime maps in the (μd, z0) plane.
//!
//! Every figure is plain data ([`LineChart`], [`CategoryMap`]); the renderers draw it. Times are
//! in s, lengths in mm, speeds in mm/s, accelerations in m/s², forces in N. The harmonic law is
//! always solid in palette colour 0 and the linear law dashed in colour 1.

use rayon::prelude::*;

use std::path::Path;

use crate::engine::{integrate, EventKind, Run, RunOptions};
use crate::error::{Error, Result};
use crate::fit::data::{parse, ReadOptions, Unit};
use crate::format::people;
use crate::models::param::{invalid, num};
use crate::models::woodpecker::fit::synthetic::{Synthetic, EXAMPLE_FILE};
use crate::models::woodpecker::fit::{self, FitParam};
use crate::models::woodpecker::formula::{
    self as cf, counterpart, in_closed_form_domain, Counterpart, OrbitRegime, Phase,
    WoodpeckerClosedForm,
};
use crate::models::woodpecker::map;
use crate::models::woodpecker::map::{integrated_cell, linear_cell, MAP_PERIODS, REGIMES};
use crate::models::woodpecker::results::{evaluate_with_runs, linear_inputs};
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::{woodpecker, LawKind};
use crate::report::figures::spec::{CategoryMap, Curve, LineChart, Marker, Panel, Stroke};
use crate::report::scene::sampling::{curve, function_curve, sample, SAMPLES};
use crate::report::scene::{Drawing, Figure};

crate::present::vocab::figure_kinds! {
    /// What a scene of the woodpecker draws. Each kind may produce one or more figures.
    pub enum WoodFigure {
        /// y_S and v against t for both laws, with the characteristic times (Figs. 15, 16, 26).
        Motion { periods: f64 } = "wood-motion",
        /// The spring coordinate, harmonic against the three counterparts (Fig. 17).
        Spring = "wood-spring",
        /// W_S + F_e against 2λμs|F_e| and 2λμd|F_e|, with t_SL^(I) (Fig. 18).
        Forces = "wood-forces",
        /// a, v, y and the characteristic times of phase 1 or 2 (Fig. 19).
        Phase { phase: u8 } = "wood-phase",
        /// v for μd below, at and above μd,MIN of phase 1 or 2 (Fig. 20).
        MuSweep { phase: u8 } = "wood-mu-sweep",
        /// Sleeve and woodpecker positions and the speed (Fig. 23).
        Positions = "wood-positions",
        /// Regimes in the (μd, z0) plane with μd,MIN and μd,HALT of both phases.
        RegimeMap = "wood-regime-map",
        /// The example track (synthetic) with the harmonic law fitted to it from the scene's
        /// parameters (Figs. 26–27).
        Tracked = "wood-tracked",
    }
}

/// Palette index and stroke of each law, the same in every figure.
const HARMONIC: (usize, Stroke) = (0, Stroke::Solid);
const LINEAR: (usize, Stroke) = (1, Stroke::Dashed);
/// Further variants (counterparts, μd values, references): colour and stroke.
const VARIANTS: [(usize, Stroke); 2] = [(2, Stroke::Dotted), (3, Stroke::DashDot)];
/// m → mm, m/s → mm/s.
const MM: f64 = 1e3;
/// The period of a run shown as the settled motion (earlier periods may be a transient).
const STEADY_PERIOD: u32 = 2;
/// Cells per side of the regime maps.
const MAP_CELLS: usize = 200;
/// Points of each analytic boundary curve on the maps.
const BOUNDARY_POINTS: usize = 400;
/// Factors of μd,MIN in the μd sweep.
const SWEEP: [f64; 3] = [0.8, 1.0, 1.2];

/// The figures of one kind for the woodpecker `p` (other models' kinds give none).
pub fn figures(scene_id: &str, p: &WoodpeckerParams, kind: WoodFigure) -> Result<Vec<Figure>> {
    let figure = |name: &str, (chart, caption): (LineChart, String)| Figure {
        id: format!("{scene_id}-{name}"),
        caption,
        drawing: Drawing::Chart(chart),
    };
    Ok(match kind {
        WoodFigure::Motion { periods } => vec![figure("motion", motion(p, periods)?)],
        WoodFigure::Spring => vec![figure("spring", spring(p)?)],
        WoodFigure::Forces => {
            let mut out = vec![figure("forces", forces(p, None)?)];
            if let Some(window) = onset_window(p) {
                out.push(figure("forces-onsets", forces(p, Some(window))?));
            }
            out
        }
        WoodFigure::Phase { phase } => {
            let phase = phase_of(phase)?;
            vec![figure(
                &format!("phase-{}", phase_number(phase)),
                phase_chart(p, phase)?,
            )]
        }
        WoodFigure::MuSweep { phase } => {
            let phase = phase_of(phase)?;
            vec![figure(
                &format!("mu-sweep-{}", phase_number(phase)),
                mu_sweep(p, phase)?,
            )]
        }
        WoodFigure::Positions => vec![figure("positions", positions(p)?)],
        WoodFigure::RegimeMap => regime_maps(p)?
            .into_iter()
            .zip(["regimes-linear", "regimes-harmonic"])
            .map(|((map, caption), name)| Figure {
                id: format!("{scene_id}-{name}"),
                caption,
                drawing: Drawing::Map(map),
            })
            .collect(),
        WoodFigure::Tracked => vec![figure("tracked", tracked(p)?)],
    })
}

// ---------------------------------------------------------------------------------------------
// Figs. 26–27: a tracked toy and the fitted model

/// The example track ([`Synthetic::example`], made by the model itself: the paper's tracked data
/// are not in the paper) with the harmonic law fitted to it from `p`, as `stickslip fit` does.
fn tracked(p: &WoodpeckerParams) -> Result<(LineChart, String)> {
    let example = Synthetic::example();
    let csv = example.generate()?.csv(Unit::Mm, "");
    let data = parse(&csv, Path::new(EXAMPLE_FILE), &ReadOptions::default())?;
    let fit = fit::fit(&data, p, &FitParam::DEFAULT)?;
    let mut chart = fit::chart(&fit);
    if let Some(points) = chart
        .panels
        .first_mut()
        .and_then(|panel| panel.curves.first_mut())
    {
        points.label = "tracked (synthetic)".to_string();
    }
    let truth = &example.truth;
    let estimates: Vec<String> = fit
        .estimates
        .iter()
        .filter(|e| !e.nuisance)
        .map(|e| {
            let (scale, unit) = if e.unit == "m" {
                (MM, " mm")
            } else {
                (1.0, "")
            };
            let param = FitParam::DEFAULT.iter().find(|f| f.name() == e.name);
            format!(
                "{} = {} ± {}{unit} (made with {})",
                symbol(e.name),
                people(Some(e.value * scale), 4),
                people(e.std_error.map(|s| s * scale), 2),
                people(param.map(|f| f.get(truth) * scale), 3)
            )
        })
        .collect();
    let correlated: Vec<String> = fit::strong_correlations(&fit)
        .iter()
        .map(|c| format!("{} and {} at r = {:.2}", symbol(c.a), symbol(c.b), c.r))
        .collect();
    let correlated = if correlated.is_empty() {
        String::new()
    } else {
        format!(
            " The data hardly separate {}: an error in one is made up by the other, so the \
             fitted values may sit a standard error or two from the true ones; measuring one of \
             them with a ruler and fitting the rest does better.",
            correlated.join(" and ")
        )
    };
    let caption = format!(
        "Points: a tracked sleeve position, synthetic and not a measurement: {} Dashed: the \
         harmonic law fitted to the points from this scene's values (`stickslip fit \
         {EXAMPLE_FILE}`): {}; residuals of RMS {} mm below.{correlated}",
        example
            .provenance()
            .replace("mu_d", "μd")
            .replace("sigma", "σ"),
        estimates.join(", "),
        people(Some(fit.rms_residual * 1e3), 2)
    );
    Ok((chart, caption))
}

/// The symbol people read for a fitted parameter's name (its key), from the registry.
fn symbol(name: &str) -> &str {
    crate::models::woodpecker::params::PARAMS
        .iter()
        .find(|s| s.key == name)
        .map_or(name, |s| s.symbol)
}

// ---------------------------------------------------------------------------------------------
// Shared pieces

fn phase_of(phase: u8) -> Result<Phase> {
    match phase {
        1 => Ok(Phase::One),
        2 => Ok(Phase::Two),
        _ => Err(invalid("phase", phase, "phase = 1 or 2")),
    }
}

fn phase_number(phase: Phase) -> u8 {
    match phase {
        Phase::One => 1,
        Phase::Two => 2,
    }
}

fn roman(phase: Phase) -> &'static str {
    match phase {
        Phase::One => "I",
        Phase::Two => "II",
    }
}

fn counterpart_name(c: Counterpart) -> &'static str {
    match c {
        Counterpart::Extremes => "extremes",
        Counterpart::Zeros => "zeros",
        Counterpart::Tangent => "tangent",
    }
}

/// Legend label of the linear law of `p`.
fn linear_label(p: &WoodpeckerParams) -> String {
    format!("linear law ({})", counterpart_name(p.counterpart))
}

/// The closed forms of the linear law of `p`.
fn closed_form(p: &WoodpeckerParams) -> WoodpeckerClosedForm {
    cf::evaluate(&linear_inputs(p))
}

/// The characteristic times of one phase from the closed forms (s, within the period).
struct PhaseTimes {
    t_slip: Option<f64>,
    t0: Option<f64>,
    t_max: Option<f64>,
    t_stick: Option<f64>,
    mu_d_min: Option<f64>,
}

fn phase_times(c: &WoodpeckerClosedForm, phase: Phase) -> PhaseTimes {
    match phase {
        Phase::One => PhaseTimes {
            t_slip: c.t_slip_1,
            t0: c.t0_1,
            t_max: c.t_max_speed_1,
            t_stick: c.t_stick_1,
            mu_d_min: c.mu_d_min_1,
        },
        Phase::Two => PhaseTimes {
            t_slip: c.t_slip_2,
            t0: c.t0_2,
            t_max: c.t_max_speed_2,
            t_stick: c.t_stick_2,
            mu_d_min: c.mu_d_min_2,
        },
    }
}

/// Markers at the given times that exist and lie in [lo, hi].
fn markers(
    times: impl IntoIterator<Item = (String, Option<f64>)>,
    (lo, hi): (f64, f64),
) -> Vec<Marker> {
    times
        .into_iter()
        .filter_map(|(label, t)| t.map(|x| Marker { x, label }))
        .filter(|m| m.x.is_finite() && m.x >= lo && m.x <= hi)
        .collect()
}

fn panel(y_label: &str, curves: Vec<Curve>) -> Panel {
    Panel {
        y_label: y_label.to_string(),
        curves,
        h_lines: Vec::new(),
    }
}

fn time_chart(x_range: (f64, f64), panels: Vec<Panel>, markers: Vec<Marker>) -> LineChart {
    LineChart {
        x_label: "t (s)".to_string(),
        x_range: Some(x_range),
        panels,
        markers,
    }
}

/// A function of time on [t0, t1] in the given style.
fn fn_curve(
    label: &str,
    (t0, t1): (f64, f64),
    (color, stroke): (usize, Stroke),
    f: impl Fn(f64) -> f64,
) -> Curve {
    function_curve(label, t0, t1, SAMPLES, f, color, stroke)
}

/// A run of the linear law of `p` with segments, covering period `n` (from 0) and the next one,
/// into which the last slip of period `n` may run.
fn linear_run(p: &WoodpeckerParams, n: u32) -> Result<Run> {
    let law = woodpecker::force_law(p, LawKind::Linear)?;
    let opts = RunOptions {
        periods: n + 2,
        record_segments: true,
        dissipation: false,
    };
    integrate(&woodpecker::body(p), &law, &opts)
}

/// Samples (t, y, v, a) of period `n` of `run` on [t0, t1] (times within the period): time
/// shifted back by n periods, position measured from its value at the start of the period.
fn period_samples(run: &Run, n: u32, (t0, t1): (f64, f64)) -> Vec<[f64; 4]> {
    let shift = f64::from(n) * run.period;
    let x0 = run.x_at_period_start.get(n as usize).unwrap_or(0.0);
    sample(run, shift + t0, shift + t1, SAMPLES)
        .into_iter()
        .map(|[t, x, v, a]| [t - shift, x - x0, v, a])
        .collect()
}

/// The first stick of `run` in period `n` after `after` and not later than `limit` (times
/// within the period).
fn stick_after(run: &Run, n: u32, after: f64, limit: f64) -> Option<f64> {
    let shift = f64::from(n) * run.period;
    run.events
        .iter()
        .filter(|e| matches!(e.kind, EventKind::Stick { .. }))
        .map(|e| e.t - shift)
        .find(|&t| t > after && t <= limit)
}

/// Start of the half period of a phase (s).
fn half_start(phase: Phase, period: f64) -> f64 {
    match phase {
        Phase::One => 0.0,
        Phase::Two => 0.5 * period,
    }
}

/// Which period the phase figures show, and how the caption names it.
fn period_words(n: u32) -> String {
    if n == 0 {
        "the first period, from rest at t = 0".to_string()
    } else {
        format!(
            "the settled motion (period {} of an exact integration, time within the period, \
             position from its value at the start of the period)",
            n + 1
        )
    }
}

/// The window shown for a phase (times within the period): from 3/4 of the way between the
/// start of its half period and the slip, to 5 % past the later of the end of the half period
/// and the stick (never more than a period after the start of the half period).
fn phase_window(
    phase: Phase,
    period: f64,
    t_slip: Option<f64>,
    t_stick: Option<f64>,
) -> (f64, f64) {
    let origin = half_start(phase, period);
    let half_end = origin + 0.5 * period;
    let start = t_slip
        .filter(|&t| t > origin && t < half_end)
        .map_or(origin, |t| origin + 0.75 * (t - origin));
    let stop = t_stick
        .filter(|t| t.is_finite())
        .map_or(half_end, |t| t.max(half_end))
        .min(origin + period);
    (start, origin + 1.05 * (stop - origin))
}

// ---------------------------------------------------------------------------------------------
// Motion of the sleeve (Figs. 15, 16, 26)

/// The slip and stick times of the linear law that describe its periodic motion, per period.
fn motion_times(c: &WoodpeckerClosedForm) -> (Vec<(String, f64)>, bool, &'static str) {
    let named = |name: &str, phase: Phase| format!("{name}({})", roman(phase));
    if c.paper_regime_valid {
        let times = [
            (named("t_SL", Phase::One), c.t_slip_1),
            (named("t_ST", Phase::One), c.t_stick_1),
            (named("t_SL", Phase::Two), c.t_slip_2),
            (named("t_ST", Phase::Two), c.t_stick_2),
        ];
        let times = times
            .into_iter()
            .filter_map(|(l, t)| t.map(|t| (l, t)))
            .collect();
        return (
            times,
            true,
            "the slip and stick times of both phases from the closed forms (41), (49), (58), \
             (60), repeated every period",
        );
    }
    if let Some(orbit) = &c.orbit {
        let times = orbit
            .slips
            .iter()
            .flat_map(|s| {
                [
                    (named("t_SL", s.phase), s.t_slip),
                    (named("t_ST", s.phase), s.t_halt),
                ]
            })
            .collect();
        return (
            times,
            true,
            "the slip and stick times of the periodic orbit of the linear law (from the closed \
             forms), repeated every period; the paper's standard regime does not hold here",
        );
    }
    match c.t_slip_1.filter(|&t| t >= 0.0 && !c.immediate_slip) {
        Some(t) => (
            vec![(named("t_SL", Phase::One), t)],
            false,
            "the first slip time t_SL(I) of (41); the closed forms give no later stick",
        ),
        None => (Vec::new(), false, "none: no closed-form time applies"),
    }
}

fn motion(p: &WoodpeckerParams, periods: f64) -> Result<(LineChart, String)> {
    if !(periods.is_finite() && periods > 0.0) {
        return Err(invalid("periods", num(periods), "0 < periods < inf"));
    }
    let period = p.period();
    let n = periods.ceil().min(f64::from(u32::MAX)) as u32;
    let (eval, runs) = evaluate_with_runs(p, n.max(1), true)?;
    let range = (0.0, periods * period);
    let harmonic = sample(&runs.harmonic, range.0, range.1, SAMPLES);
    let linear = runs
        .linear
        .as_ref()
        .map(|r| sample(r, range.0, range.1, SAMPLES));
    let law_curves = |col: usize| {
        let mut out = vec![curve(
            "harmonic law",
            &harmonic,
            col,
            MM,
            HARMONIC.0,
            HARMONIC.1,
        )];
        if let Some(s) = &linear {
            out.push(curve(&linear_label(p), s, col, MM, LINEAR.0, LINEAR.1));
        }
        out
    };
    let c = &eval.closed_form;
    let (times, repeat, about_markers) = motion_times(c);
    let repeats = if repeat { n } else { 1 };
    let shifted = (0..repeats).flat_map(|k| {
        times
            .iter()
            .map(move |(l, t)| (l.clone(), Some(t + f64::from(k) * period)))
    });
    let chart = time_chart(
        range,
        vec![
            panel("y_S (mm)", law_curves(1)),
            panel("v (mm/s)", law_curves(2)),
        ],
        if linear.is_some() && eval.domain_note.is_none() {
            markers(shifted, range)
        } else {
            Vec::new()
        },
    );
    let linear_note = match (&eval.linear, &eval.domain_note) {
        (Some(s), None) => format!(
            "The linear law with the {} counterpart (dashed): {} by integration, {} by the \
             closed forms. Vertical lines (the linear law's events; the harmonic curve need not \
             stop there): {about_markers}.",
            counterpart_name(p.counterpart),
            s.regime.words(),
            c.regime.words()
        ),
        (Some(s), Some(note)) => format!(
            "The linear law with the {} counterpart (dashed): {} by integration; no closed \
             form applies: {note}.",
            counterpart_name(p.counterpart),
            s.regime.words()
        ),
        (None, note) => format!(
            "The linear law is not drawn: {}.",
            note.as_deref().unwrap_or("its counterpart is undefined")
        ),
    };
    let caption = format!(
        "Position y_S (downward) and speed v of the woodpecker's sleeve over {periods} periods, \
         from rest at t = 0, both laws integrated exactly. The harmonic law (solid): {}. \
         {linear_note}",
        eval.harmonic.regime.words()
    );
    Ok((chart, caption))
}

// ---------------------------------------------------------------------------------------------
// The spring coordinate and its counterparts (Fig. 17)

fn spring(p: &WoodpeckerParams) -> Result<(LineChart, String)> {
    let period = p.period();
    let range = (0.0, 1.25 * period);
    let tau = 0.25 * period;
    let mut curves = vec![fn_curve("harmonic z0 + d0 cos ωt", range, HARMONIC, |t| {
        MM * woodpecker::spring_coordinate(p, LawKind::Harmonic, t).unwrap_or(f64::NAN)
    })];
    let all = [
        (Counterpart::Zeros, "zeros: same amplitude and zeros of F_e"),
        (Counterpart::Extremes, "extremes: same maximum and minimum"),
        (
            Counterpart::Tangent,
            "tangent: same zeros and slopes of F_e",
        ),
    ];
    // The scene's counterpart in the linear law's style, the others as variants.
    let (own, others): (Vec<_>, Vec<_>) = all.into_iter().partition(|c| c.0 == p.counterpart);
    let styled = own
        .into_iter()
        .zip([LINEAR])
        .chain(others.into_iter().zip(VARIANTS));
    let mut described = Vec::new();
    for ((which, label), style) in styled {
        let Some((zeta0, delta0)) = counterpart(p.z0, p.d0, which) else {
            described.push(format!("{} is undefined", counterpart_name(which)));
            continue;
        };
        curves.push(fn_curve(label, range, style, |t| {
            MM * (delta0 + cf::spring_coordinate(t, tau, zeta0).unwrap_or(f64::NAN))
        }));
        described.push(format!(
            "{}: ζ0 = {:.3} mm, δ0 = {:.3} mm",
            counterpart_name(which),
            MM * zeta0,
            MM * delta0
        ));
    }
    let mut z_panel = panel("z (mm)", curves);
    z_panel.h_lines.push((0.0, "F_e = 0".to_string()));
    // Zeros of the harmonic z (shared by the zeros and tangent counterparts).
    let zeros = (p.z0.abs() < p.d0).then(|| (-p.z0 / p.d0).acos() / p.omega());
    let chart = time_chart(
        range,
        vec![z_panel],
        markers(
            [
                ("t0(I)".to_string(), zeros),
                ("t0(II)".to_string(), zeros.map(|t| period - t)),
            ],
            range,
        ),
    );
    let caption = format!(
        "Spring coordinate z(t) over 1.25 periods: the harmonic law z0 + d0 cos ωt (z0 = {:.3} \
         mm, d0 = {:.3} mm, solid) and the triangle waves δ0 + ζ(t) of (37) that replace it in \
         the linear law ({}). The spring force F_e = k z changes sign on the line z = 0; t0(I) and \
         t0(II) mark the zeros of the harmonic z, which the zeros and tangent counterparts share. \
         The scene uses the {} counterpart.",
        MM * p.z0,
        MM * p.d0,
        described.join("; "),
        counterpart_name(p.counterpart)
    );
    Ok((chart, caption))
}

// ---------------------------------------------------------------------------------------------
// The forces (Fig. 18)

/// The time window around the two slip onsets of the linear law, t_SL(I) − T/10 to
/// t_SL(II) + T/10, where the forces that decide them are a small fraction of the largest.
fn onset_window(p: &WoodpeckerParams) -> Option<(f64, f64)> {
    let c = closed_form(p);
    let (first, second) = (c.t_slip_1?, c.t_slip_2?);
    let margin = 0.1 * p.period();
    (woodpecker::linear_amplitudes(p).is_some() && 0.0 <= first && first < second)
        .then(|| ((first - margin).max(0.0), (second + margin).min(p.period())))
}

/// The competing forces over one period, or zoomed into `window` (s).
fn forces(p: &WoodpeckerParams, window: Option<(f64, f64)>) -> Result<(LineChart, String)> {
    let period = p.period();
    let range = window.unwrap_or((0.0, period));
    let (w_s, two_lambda) = (p.sleeve_weight(), 2.0 * p.lambda());
    let spring_force = |law: LawKind, t: f64| {
        woodpecker::spring_coordinate(p, law, t).map_or(f64::NAN, |z| p.k * z)
    };
    let mut curves = Vec::new();
    let has_linear = woodpecker::linear_amplitudes(p).is_some();
    if has_linear {
        let fe = |t: f64| spring_force(LawKind::Linear, t);
        curves.extend([
            fn_curve("W_S + F_e (linear)", range, (0, Stroke::Solid), |t| {
                w_s + fe(t)
            }),
            fn_curve("2λμs|F_e| (linear)", range, (1, Stroke::Dashed), |t| {
                two_lambda * p.mu_s * fe(t).abs()
            }),
            fn_curve("2λμd|F_e| (linear)", range, (2, Stroke::DashDot), |t| {
                two_lambda * p.mu_d * fe(t).abs()
            }),
        ]);
    }
    let fe = |t: f64| spring_force(LawKind::Harmonic, t);
    let reference = if has_linear {
        Stroke::Dotted
    } else {
        Stroke::Solid
    };
    curves.extend([
        fn_curve("W_S + F_e (harmonic)", range, (0, reference), |t| {
            w_s + fe(t)
        }),
        fn_curve("2λμs|F_e| (harmonic)", range, (1, reference), |t| {
            two_lambda * p.mu_s * fe(t).abs()
        }),
    ]);
    let c = closed_form(p);
    let marks = if has_linear {
        markers(
            [
                ("t_SL(I)".to_string(), c.t_slip_1),
                ("t_SL(II)".to_string(), c.t_slip_2),
            ],
            range,
        )
    } else {
        Vec::new()
    };
    let mut force_panel = panel("F (N)", curves);
    force_panel.h_lines.push((0.0, String::new()));
    let chart = time_chart(range, vec![force_panel], marks);
    let law_note = if has_linear {
        format!(
            "for the linear law with the {} counterpart (the harmonic law dotted for reference)",
            counterpart_name(p.counterpart)
        )
    } else {
        "for the harmonic law (the linear counterpart is undefined for these z0, d0)".to_string()
    };
    if window.is_some() {
        let caption = format!(
            "The same forces zoomed on the two slip onsets, from {} s to {} s {law_note}: near \
             the zeros of F_e the grip 2λμs|F_e| falls below the driving force W_S + F_e, a \
             small fraction of the largest forces of the period, and the sleeve slips at \
             t_SL(I) and t_SL(II).",
            people(Some(range.0), 3),
            people(Some(range.1), 3)
        );
        return Ok((chart, caption));
    }
    let caption = format!(
        "Forces on the sleeve over one period {law_note}: the driving force W_S + F_e (weight \
         W_S = {w_s:.4} N plus spring force), the static friction capacity 2λμs|F_e| and the \
         dynamic friction 2λμd|F_e| of the two contacts (lever ratio λ = {:.4}). The sleeve is \
         held while |W_S + F_e| ≤ 2λμs|F_e|; a slip starts where the driving force rises above the \
         capacity, at t_SL(I) of (41) and t_SL(II) of (58), and decelerates where 2λμd|F_e| \
         exceeds W_S + F_e.",
        p.lambda()
    );
    Ok((chart, caption))
}

// ---------------------------------------------------------------------------------------------
// One phase of the linear law (Fig. 19)

fn phase_chart(p: &WoodpeckerParams, phase: Phase) -> Result<(LineChart, String)> {
    let c = closed_form(p);
    let times = phase_times(&c, phase);
    let period = p.period();
    // The settled period when there is a periodic orbit; in continuous slip only the slip from
    // rest in the first period has closed forms.
    let n = if c.orbit.is_some() { STEADY_PERIOD } else { 0 };
    let run = linear_run(p, n)?;
    let origin = half_start(phase, period);
    let after = times.t_slip.unwrap_or(origin);
    let stick = stick_after(&run, n, after, origin + period).or(times.t_stick);
    let range = phase_window(phase, period, times.t_slip, stick);
    let s = period_samples(&run, n, range);
    let label = linear_label(p);
    let law_curve =
        |col: usize, scale: f64| vec![curve(&label, &s, col, scale, LINEAR.0, LINEAR.1)];
    let mut a_panel = panel("a (m/s²)", law_curve(3, 1.0));
    a_panel
        .h_lines
        .push((p.g, "a = g where F_e = 0".to_string()));
    let panels = vec![
        a_panel,
        panel("v (mm/s)", law_curve(2, MM)),
        panel("y_S (mm)", law_curve(1, MM)),
    ];
    let r = roman(phase);
    let marks = markers(
        [
            (format!("t_SL({r})"), times.t_slip),
            (format!("t0({r})"), times.t0),
            (format!("t_M({r})"), times.t_max),
            (format!("t_ST({r})"), times.t_stick),
        ],
        range,
    );
    let equations = match phase {
        Phase::One => "(40), (41), (46), (49)",
        Phase::Two => "(57), (58), (62), (60)",
    };
    let validity = if c.paper_regime_valid {
        "The parameters are in the paper's standard regime, so these formulas describe the \
         motion."
            .to_string()
    } else {
        format!(
            "The parameters are outside the paper's standard regime (the closed forms find {}): \
             where a marker and the curve disagree, the formula does not describe this motion.",
            c.regime.words()
        )
    };
    let caption = format!(
        "Phase {r} of the linear law ({} counterpart): acceleration, speed and position of the \
         sleeve in {}. Marked: the closed-form slip time t_SL, zero of the spring force t0 \
         (where a = g), time of the speed maximum t_M and stick time t_ST, {equations}. \
         {validity}",
        counterpart_name(p.counterpart),
        period_words(n)
    );
    Ok((time_chart(range, panels, marks), caption))
}

// ---------------------------------------------------------------------------------------------
// μd around μd,MIN (Fig. 20)

/// One μd of the sweep: legend label, value, style and its run.
struct SweepCurve {
    label: String,
    mu_d: f64,
    style: (usize, Stroke),
    run: Run,
}

/// The μd values of the sweep around μd,MIN (capped at μs, repeats dropped), or the scene's μd
/// alone when μd,MIN is undefined or ≤ 0.
fn sweep_values(
    p: &WoodpeckerParams,
    mu_min: Option<f64>,
    r: &str,
) -> Vec<(String, f64, (usize, Stroke))> {
    let Some(m) = mu_min else {
        return vec![(format!("μd = {} (scene)", p.mu_d), p.mu_d, LINEAR)];
    };
    let styles = [VARIANTS[0], HARMONIC, VARIANTS[1]];
    let mut out: Vec<(String, f64, (usize, Stroke))> = Vec::new();
    for (i, (&f, style)) in SWEEP.iter().zip(styles).enumerate() {
        let mu_d = (f * m).min(p.mu_s);
        if mu_d <= 0.0 || out.iter().any(|w| w.1 == mu_d) {
            continue;
        }
        let label = if f * m > p.mu_s {
            "μd = μs (capped)".to_string()
        } else if i == 1 {
            format!("μd = μd,MIN({r})")
        } else {
            format!("μd = {f} μd,MIN({r})")
        };
        out.push((label, mu_d, style));
    }
    out
}

fn mu_sweep(p: &WoodpeckerParams, phase: Phase) -> Result<(LineChart, String)> {
    let c = closed_form(p);
    let times = phase_times(&c, phase);
    let r = roman(phase);
    let period = p.period();
    let mu_min = times.mu_d_min.filter(|&m| m > 0.0 && m.is_finite());
    // The slip from rest of the first period, which (51)/(65) describe; after an immediate slip
    // (independent of μd) the settled period instead.
    let n = if c.immediate_slip { STEADY_PERIOD } else { 0 };
    let variants: Vec<SweepCurve> = sweep_values(p, mu_min, r)
        .into_iter()
        .filter_map(|(label, mu_d, style)| {
            let q = WoodpeckerParams { mu_d, ..*p };
            q.validate().ok()?;
            let run = linear_run(&q, n).ok()?;
            Some(SweepCurve {
                label,
                mu_d,
                style,
                run,
            })
        })
        .collect();
    if variants.is_empty() {
        return Err(Error::InvalidLaw(format!(
            "no μd of the phase-{r} sweep gives a linear law to integrate"
        )));
    }
    let origin = half_start(phase, period);
    let after = times.t_slip.unwrap_or(origin);
    let latest_stick = variants
        .iter()
        .filter_map(|v| stick_after(&v.run, n, after, origin + period))
        .reduce(f64::max);
    let range = phase_window(phase, period, times.t_slip, latest_stick);
    let curves = variants
        .iter()
        .map(|v| {
            curve(
                &v.label,
                &period_samples(&v.run, n, range),
                2,
                MM,
                v.style.0,
                v.style.1,
            )
        })
        .collect();
    let (end_label, end) = match phase {
        Phase::One => ("T/2", 0.5 * period),
        Phase::Two => ("T", period),
    };
    let marks = markers(
        [
            (format!("t_SL({r})"), times.t_slip),
            (end_label.to_string(), Some(end)),
        ],
        range,
    );
    let values: Vec<String> = variants
        .iter()
        .map(|v| format!("{} = {:.4}", v.label, v.mu_d))
        .collect();
    let equation = match phase {
        Phase::One => "(51)",
        Phase::Two => "(65)",
    };
    let about = match (mu_min, times.mu_d_min) {
        (Some(m), _) if m > p.mu_s => format!(
            "{equation} gives μd,MIN({r}) = {m:.4}, above μs = {}: no admissible μd stops the \
             sleeve by {end_label}. Drawn: {}.",
            p.mu_s,
            values.join(", ")
        ),
        (Some(m), _) => format!(
            "μd,MIN({r}) = {m:.4} from {equation}; drawn: {}. By {equation} the sleeve stops \
             exactly at {end_label} for μd = μd,MIN({r}), before it for larger μd and after it \
             (or not at all) for smaller μd.",
            values.join(", ")
        ),
        (None, Some(m)) => format!(
            "{equation} gives μd,MIN({r}) = {m:.4} ≤ 0: every μd stops the sleeve before \
             {end_label}, so only the scene's μd = {} is drawn.",
            p.mu_d
        ),
        (None, None) => format!(
            "{equation} is undefined for these parameters, so only the scene's μd = {} is drawn.",
            p.mu_d
        ),
    };
    let caption = format!(
        "Speed of the sleeve in phase {r} of the linear law ({} counterpart), in {}. {about}",
        counterpart_name(p.counterpart),
        period_words(n)
    );
    let chart = time_chart(range, vec![panel("v (mm/s)", curves)], marks);
    Ok((chart, caption))
}

// ---------------------------------------------------------------------------------------------
// Sleeve and bird (Fig. 23)

fn positions(p: &WoodpeckerParams) -> Result<(LineChart, String)> {
    let period = p.period();
    let range = (0.0, 2.0 * period);
    let law = woodpecker::force_law(p, LawKind::Harmonic)?;
    let opts = RunOptions {
        periods: 2,
        record_segments: true,
        dissipation: false,
    };
    let run = integrate(&woodpecker::body(p), &law, &opts)?;
    let s = sample(&run, range.0, range.1, SAMPLES);
    let bird = Curve {
        label: "woodpecker y_W = y_S + z".to_string(),
        points: s
            .iter()
            .filter_map(|&[t, x, _, _]| {
                let z = woodpecker::spring_coordinate(p, LawKind::Harmonic, t)?;
                Some((t, MM * (x + z)))
            })
            .collect(),
        color: VARIANTS[1].0,
        stroke: VARIANTS[1].1,
    };
    let panels = vec![
        panel(
            "y (mm)",
            vec![curve("sleeve y_S", &s, 1, MM, HARMONIC.0, HARMONIC.1), bird],
        ),
        panel(
            "v_S (mm/s)",
            vec![curve("sleeve v_S", &s, 2, MM, HARMONIC.0, HARMONIC.1)],
        ),
    ];
    let events = run.events.iter().filter_map(|e| match e.kind {
        EventKind::Slip { .. } => Some(("slip".to_string(), Some(e.t))),
        EventKind::Stick { .. } => Some(("stick".to_string(), Some(e.t))),
        _ => None,
    });
    let chart = time_chart(range, panels, markers(events, range));
    let caption = "Harmonic law over two periods from rest: positions of the sleeve y_S (solid) \
                   and of the woodpecker y_W = y_S + z(t) (eq. (34), up to a constant), both \
                   positive downward, and the speed of the sleeve. The bird swings about the \
                   sleeve, which moves down only while slipping; vertical lines mark the slips \
                   and sticks of the exact integration."
        .to_string();
    Ok((chart, caption))
}

// ---------------------------------------------------------------------------------------------
// Regime maps in the (μd, z0) plane

/// The cells of one map (rows of z0 from the bottom, columns of μd) and its legend, holding
/// only the regimes that occur, in the order of [`REGIMES`].
fn map_cells(
    x: (f64, f64),
    y: (f64, f64),
    cell: &(dyn Fn(f64, f64) -> u8 + Sync),
) -> (Vec<Vec<u8>>, Vec<(String, usize)>) {
    let centre =
        |(lo, hi): (f64, f64), i: usize| lo + (hi - lo) * (i as f64 + 0.5) / MAP_CELLS as f64;
    let raw: Vec<Vec<u8>> = (0..MAP_CELLS)
        .into_par_iter()
        .map(|row| {
            let z0 = centre(y, row);
            (0..MAP_CELLS).map(|col| cell(centre(x, col), z0)).collect()
        })
        .collect();
    let mut present = [false; REGIMES.len()];
    raw.iter()
        .flatten()
        .for_each(|&i| present[usize::from(i)] = true);
    let mut remap = [0u8; REGIMES.len()];
    let mut categories: Vec<(String, usize)> = Vec::new();
    for (i, regime) in REGIMES.iter().enumerate() {
        if present[i] {
            // Two regimes with one fill share one legend row ("A or B"): a swatch names one
            // thing.
            match categories.iter().position(|c| c.1 == regime.2) {
                Some(k) => {
                    remap[i] = k as u8;
                    categories[k].0 = format!("{} or {}", categories[k].0, regime.1);
                }
                None => {
                    remap[i] = categories.len() as u8;
                    categories.push((regime.1.to_string(), regime.2));
                }
            }
        }
    }
    let cells = raw
        .into_iter()
        .map(|row| row.into_iter().map(|i| remap[usize::from(i)]).collect())
        .collect();
    (cells, categories)
}

/// The boundary μd(z0) of one closed form as curves of (μd, z0 in mm): broken where it is
/// undefined, outside the closed forms' domain or far outside the map; labelled once.
fn boundary_curves(
    p: &WoodpeckerParams,
    label: &str,
    (color, stroke): (usize, Stroke),
    x: (f64, f64),
    y: (f64, f64),
    of: impl Fn(&WoodpeckerClosedForm) -> Option<f64>,
) -> Vec<Curve> {
    let span = x.1 - x.0;
    let mut runs: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
    for i in 0..=BOUNDARY_POINTS {
        let z0_mm = y.0 + (y.1 - y.0) * i as f64 / BOUNDARY_POINTS as f64;
        let q = WoodpeckerParams {
            z0: z0_mm / MM,
            ..*p
        };
        let lin = linear_inputs(&q);
        let c = cf::evaluate(&lin);
        let mu = of(&c)
            .filter(|_| in_closed_form_domain(&lin))
            .filter(|&m| m.is_finite() && m > x.0 - span && m < x.1 + span);
        match (mu, runs.last_mut()) {
            (Some(m), Some(run)) => run.push((m, z0_mm)),
            (None, Some(run)) if !run.is_empty() => runs.push(Vec::new()),
            _ => {}
        }
    }
    runs.into_iter()
        .filter(|r| r.len() >= 2)
        .enumerate()
        .map(|(i, points)| Curve {
            label: if i == 0 {
                label.to_string()
            } else {
                String::new()
            },
            points,
            color,
            stroke,
        })
        .collect()
}

/// The analytic boundaries μd,MIN and μd,HALT of both phases, and the scene's own point.
fn map_curves(p: &WoodpeckerParams, x: (f64, f64), y: (f64, f64)) -> Vec<Curve> {
    type Of = fn(&WoodpeckerClosedForm) -> Option<f64>;
    let boundaries: [(&str, (usize, Stroke), Of); 4] = [
        ("μd,MIN(I) (51)", (0, Stroke::Solid), |c| c.mu_d_min_1),
        ("μd,HALT(I) (derived)", (0, Stroke::Dashed), |c| {
            c.mu_d_halt_1
        }),
        ("μd,MIN(II) (65)", (7, Stroke::DashDot), |c| c.mu_d_min_2),
        ("μd,HALT(II) (derived)", (7, Stroke::Dotted), |c| {
            c.mu_d_halt_2
        }),
    ];
    let mut curves: Vec<Curve> = boundaries
        .iter()
        .flat_map(|&(label, style, of)| boundary_curves(p, label, style, x, y, of))
        .collect();
    // The scene's (μd, z0) as a small closed diamond.
    curves.extend(Curve::point_marker(
        "this scene (μd, z0)",
        (p.mu_d, MM * p.z0),
        x,
        y,
        1,
    ));
    curves
}

/// Whether the closed forms do not apply at z0 (mm) for the other parameters of `p`.
fn linear_outside(p: &WoodpeckerParams, z0_mm: f64) -> bool {
    let q = WoodpeckerParams {
        z0: z0_mm / MM,
        ..*p
    };
    closed_form(&q).regime == OrbitRegime::OutsideClosedFormDomain
}

/// The z0 (mm) on the map where the closed forms' domain begins (it depends on z0 alone, for
/// μd ≤ μs), by bisection; `None` when the whole map lies on one side of it.
fn domain_edge(p: &WoodpeckerParams, (lo, hi): (f64, f64)) -> Option<f64> {
    let outside = |z0_mm| linear_outside(p, z0_mm);
    if !outside(lo) || outside(hi) {
        return None;
    }
    let (mut a, mut b) = (lo, hi);
    for _ in 0..60 {
        let mid = 0.5 * (a + b);
        if outside(mid) {
            a = mid;
        } else {
            b = mid;
        }
    }
    Some(b)
}

fn regime_maps(p: &WoodpeckerParams) -> Result<[(CategoryMap, String); 2]> {
    p.validate()?;
    let (x, (z_lo, z_hi)) = map::ranges(p);
    let y = (MM * z_lo, MM * z_hi);
    let curves = map_curves(p, x, y);
    let map = |(cells, categories)| CategoryMap {
        x_label: "μd".to_string(),
        y_label: "z0 (mm)".to_string(),
        x_range: x,
        y_range: y,
        cells,
        categories,
        curves: curves.clone(),
    };
    let mut linear = map(map_cells(x, y, &|mu_d, z0_mm| {
        linear_cell(p, mu_d, z0_mm / MM)
    }));
    let edge = domain_edge(p, y);
    if let Some(z0_mm) = edge {
        linear.curves.push(Curve {
            label: "edge of the closed forms' domain".to_string(),
            points: vec![(x.0, z0_mm), (x.1, z0_mm)],
            color: 3,
            stroke: Stroke::Dashed,
        });
    }
    let integrated = format!("the exact integration of the linear law over {MAP_PERIODS} periods");
    let edge_words = match edge {
        Some(z0_mm) => format!(
            " Below z0 = {} mm (the line \"edge of the closed forms' domain\") they do not \
             apply; there the cells come from {integrated}.",
            people(Some(z0_mm), 3)
        ),
        None if linear_outside(p, y.1) => {
            format!(" They do not apply anywhere on this map: every cell comes from {integrated}.")
        }
        None => String::new(),
    };
    let harmonic = map(map_cells(x, y, &|mu_d, z0_mm| {
        integrated_cell(p, LawKind::Harmonic, mu_d, z0_mm / MM, MAP_PERIODS)
    }));
    let about = format!(
        "Grid of {MAP_CELLS}×{MAP_CELLS} cells over μd from {:.2} to μs = {} and z0 from {:.2} \
         to {:.2} mm (d0 = {:.2} mm, the other parameters of the scene). Curves, from the \
         closed forms of the linear law ({} counterpart) as functions of z0: μd,MIN of phases I \
         and II, above which (51) and (65) put the stick within the half period, and the exact \
         halt thresholds μd,HALT (derived in the physics guide), above which a slip halts before the next slip onset. \
         The diamond marks the scene's own μd = {} and z0 = {:.3} mm. Regions: \"2 slips, 2 \
         sticks\" is the paper's double slip-stick; \"1 slip, 2 maxima\" has lost the \
         intermediate halt but the speed still dips between the two pushes; \"1 slip, 1 \
         maximum\" is a single slip-stick per period; in continuous slip the sleeve never sticks \
         again.",
        x.0,
        p.mu_s,
        y.0,
        y.1,
        MM * p.d0,
        counterpart_name(p.counterpart),
        p.mu_d,
        MM * p.z0
    );
    Ok([
        (
            linear,
            format!(
                "Regimes of the linear law's periodic orbit from the closed forms, which hold \
                 where 0 ≤ δ0 < ζ0 and 2λμs > 1.{edge_words} {about}"
            ),
        ),
        (
            harmonic,
            format!(
                "Regimes of the harmonic law by exact integration of {MAP_PERIODS} periods per \
                 cell, read off the last periods. {about} The curves belong to the linear law: \
                 where the harmonic regions depart from them, the linearization shifts the \
                 boundaries."
            ),
        ),
    ])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::woodpecker::map::{regime_index, Category, MAP_MU_D_MIN};
    use std::time::Instant;

    const WOOD_KINDS: [WoodFigure; 8] = [
        WoodFigure::Motion { periods: 2.0 },
        WoodFigure::Spring,
        WoodFigure::Forces,
        WoodFigure::Phase { phase: 1 },
        WoodFigure::Phase { phase: 2 },
        WoodFigure::MuSweep { phase: 1 },
        WoodFigure::MuSweep { phase: 2 },
        WoodFigure::Positions,
    ];

    fn chart_of(f: &Figure) -> &LineChart {
        match &f.drawing {
            Drawing::Chart(c) => c,
            Drawing::Map(_) => panic!("{} is not a chart", f.id),
        }
    }

    #[test]
    fn every_woodpecker_chart_builds_with_finite_curves_and_markers_in_range() {
        let p = WoodpeckerParams::default();
        for kind in WOOD_KINDS {
            let figs = figures("s", &p, kind).unwrap();
            // The forces also zoomed on the slip onsets.
            let expected = if kind == WoodFigure::Forces { 2 } else { 1 };
            assert_eq!(figs.len(), expected, "{kind:?}");
            for f in &figs {
                assert!(f.id.starts_with("s-") && !f.caption.is_empty(), "{kind:?}");
                let chart = chart_of(f);
                let (lo, hi) = chart.x_range.unwrap();
                assert!(lo < hi, "{kind:?}");
                for panel in &chart.panels {
                    assert!(!panel.curves.is_empty(), "{kind:?} {}", panel.y_label);
                    for c in &panel.curves {
                        assert!(c.points.len() > 10, "{kind:?} {}", c.label);
                        assert!(
                            c.points.iter().all(|(x, y)| x.is_finite() && y.is_finite()),
                            "{kind:?} {}",
                            c.label
                        );
                    }
                }
                assert!(!chart.markers.is_empty(), "{kind:?}");
                assert!(
                    chart.markers.iter().all(|m| m.x >= lo && m.x <= hi),
                    "{kind:?}"
                );
            }
        }
    }

    #[test]
    fn motion_marks_both_phases_of_the_standard_regime_in_each_period() {
        let p = WoodpeckerParams::default();
        let figs = figures("s", &p, WoodFigure::Motion { periods: 2.0 }).unwrap();
        let chart = chart_of(&figs[0]);
        let count = |l: &str| chart.markers.iter().filter(|m| m.label == l).count();
        for l in ["t_SL(I)", "t_ST(I)", "t_SL(II)", "t_ST(II)"] {
            assert_eq!(count(l), 2, "{l}");
        }
        // Both laws in both panels: harmonic solid 0, linear dashed 1.
        for panel in &chart.panels {
            let styles: Vec<_> = panel.curves.iter().map(|c| (c.color, c.stroke)).collect();
            assert_eq!(styles, vec![HARMONIC, LINEAR]);
        }
    }

    #[test]
    fn phase_one_speed_vanishes_at_the_closed_form_stick() {
        let p = WoodpeckerParams::default();
        let c = closed_form(&p);
        let run = linear_run(&p, STEADY_PERIOD).unwrap();
        let t_st = c.t_stick_1.unwrap();
        let t_m = c.t_max_speed_1.unwrap();
        let s = period_samples(&run, STEADY_PERIOD, (t_m, t_st + 1e-4));
        let v_max = s.iter().map(|r| r[2]).fold(0.0, f64::max);
        assert!((v_max - c.v_max_1.unwrap()).abs() < 1e-6 * v_max);
        assert!(s.iter().filter(|r| r[0] > t_st + 1e-9).all(|r| r[2] == 0.0));
    }

    #[test]
    fn mu_sweep_draws_three_values_around_mu_d_min() {
        let p = WoodpeckerParams::default();
        for phase in [1u8, 2] {
            let figs = figures("s", &p, WoodFigure::MuSweep { phase }).unwrap();
            let chart = chart_of(&figs[0]);
            let curves = &chart.panels[0].curves;
            assert_eq!(curves.len(), 3, "phase {phase}");
            let styles: Vec<_> = curves.iter().map(|c| (c.color, c.stroke)).collect();
            let mut unique = styles.clone();
            unique.dedup();
            assert_eq!(unique.len(), 3);
            let end = if phase == 1 { "T/2" } else { "T" };
            assert!(chart.markers.iter().any(|m| m.label == end));
        }
    }

    #[test]
    fn the_scenes_counterpart_is_drawn_in_the_linear_style() {
        let p = WoodpeckerParams {
            counterpart: Counterpart::Extremes,
            ..WoodpeckerParams::default()
        };
        let figs = figures("s", &p, WoodFigure::Spring).unwrap();
        let curves = &chart_of(&figs[0]).panels[0].curves;
        assert_eq!(curves.len(), 4);
        let style = |prefix: &str| {
            let c = curves.iter().find(|c| c.label.starts_with(prefix)).unwrap();
            (c.color, c.stroke)
        };
        assert_eq!(style("harmonic"), HARMONIC);
        assert_eq!(style("extremes"), LINEAR);
        assert_ne!(style("zeros"), style("tangent"));
    }

    #[test]
    fn mu_sweep_above_mu_s_draws_distinct_admissible_values_and_says_why() {
        // λ = 1, extremes: μd,MIN(I) = 0.807 > μs = 0.65 (guide §13).
        let p = WoodpeckerParams {
            lever: Some(1.0),
            counterpart: Counterpart::Extremes,
            ..WoodpeckerParams::default()
        };
        let figs = figures("s", &p, WoodFigure::MuSweep { phase: 1 }).unwrap();
        let curves = &chart_of(&figs[0]).panels[0].curves;
        assert_eq!(curves.len(), 2);
        assert!(figs[0].caption.contains("above μs"), "{}", figs[0].caption);
    }

    #[test]
    fn wrong_phase_is_an_error_and_other_models_kinds_are_refused() {
        use crate::present::vocab::{FigureKind, FigureKinds};
        use crate::present::Present;
        let p = WoodpeckerParams::default();
        assert!(figures("s", &p, WoodFigure::Phase { phase: 3 }).is_err());
        assert!(figures("s", &p, WoodFigure::Motion { periods: f64::NAN }).is_err());
        let other = FigureKind {
            name: "pulled-forces",
            arg: None,
        };
        assert!(p.figures_of("s", other).is_err());
        let own = WoodFigure::Phase { phase: 2 }.kind();
        assert_eq!(
            WoodFigure::from_kind(own),
            Some(WoodFigure::Phase { phase: 2 })
        );
        assert_eq!(p.figures_of("s", own).unwrap().len(), 1);
    }

    #[test]
    fn charts_without_a_linear_counterpart_draw_the_harmonic_law() {
        // |z0| > d0: the zeros counterpart is undefined.
        let p = WoodpeckerParams {
            z0: 0.010,
            ..WoodpeckerParams::default()
        };
        for kind in [WoodFigure::Motion { periods: 1.0 }, WoodFigure::Forces] {
            let figs = figures("s", &p, kind).unwrap();
            let chart = chart_of(&figs[0]);
            assert!(chart.panels.iter().all(|panel| !panel.curves.is_empty()));
        }
        assert!(figures("s", &p, WoodFigure::Phase { phase: 1 }).is_err());
    }

    #[test]
    fn regime_maps_are_fine_and_the_harmonic_map_has_the_scene_in_double_slip_stick() {
        let p = WoodpeckerParams::default();
        let start = Instant::now();
        let figs = figures("s", &p, WoodFigure::RegimeMap).unwrap();
        eprintln!(
            "woodpecker regime maps ({MAP_CELLS}×{MAP_CELLS}, {MAP_PERIODS} periods): {:.3} s",
            start.elapsed().as_secs_f64()
        );
        assert_eq!(figs.len(), 2);
        let maps: Vec<&CategoryMap> = figs
            .iter()
            .map(|f| match &f.drawing {
                Drawing::Map(m) => m,
                Drawing::Chart(_) => panic!("{} is a map", f.id),
            })
            .collect();
        let dss =
            REGIMES[usize::from(regime_index(Category::orbit(OrbitRegime::DoubleSlipStick)))].1;
        for map in &maps {
            assert!(map.cells.len() >= 200 && map.cells.iter().all(|r| r.len() >= 200));
            assert!(map
                .cells
                .iter()
                .flatten()
                .all(|&c| usize::from(c) < map.categories.len()));
            assert!(map
                .curves
                .iter()
                .flat_map(|c| &c.points)
                .all(|(x, y)| x.is_finite() && y.is_finite()));
            // The same regime has the same fill on both maps.
            let fill = map.categories.iter().find(|c| c.0 == dss).map(|c| c.1);
            assert_eq!(fill, Some(REGIMES[0].2));
            // Own cell.
            let (nx, ny) = (map.cells[0].len(), map.cells.len());
            let col =
                ((p.mu_d - map.x_range.0) / (map.x_range.1 - map.x_range.0) * nx as f64) as usize;
            let row = ((MM * p.z0 - map.y_range.0) / (map.y_range.1 - map.y_range.0) * ny as f64)
                as usize;
            let own = &map.categories[usize::from(map.cells[row][col])].0;
            assert_eq!(own, dss, "{}", figs[0].id);
        }
        // Every cell has a regime: where the closed forms fail, the linear law is integrated.
        for map in &maps {
            assert!(
                map.categories.iter().all(|c| c.0 != "integration failed"),
                "{:?}",
                map.categories
            );
        }
        // All four analytic boundaries are drawn, and the closed forms' domain edge (z0 = 0
        // here: δ0 < 0 below it) on the linear map.
        let labels: Vec<&str> = maps[0].curves.iter().map(|c| c.label.as_str()).collect();
        let edge = maps[0]
            .curves
            .iter()
            .find(|c| c.label == "edge of the closed forms' domain")
            .expect("domain edge");
        assert!(edge.points[0].1.abs() < 1e-9, "{:?}", edge.points);
        assert!(figs[0]
            .caption
            .contains("exact integration of the linear law"));
        for l in [
            "μd,MIN(I) (51)",
            "μd,HALT(I) (derived)",
            "μd,MIN(II) (65)",
            "μd,HALT(II) (derived)",
        ] {
            assert!(labels.contains(&l), "{l}");
        }
    }

    #[test]
    fn timing_of_the_two_maps_and_of_one_harmonic_cell() {
        let p = WoodpeckerParams::default();
        let (x, y) = ((MAP_MU_D_MIN, p.mu_s), (-4.5, 8.91));
        let start = Instant::now();
        let _ = map_cells(x, y, &|mu_d, z0_mm| linear_cell(&p, mu_d, z0_mm / MM));
        let linear = start.elapsed().as_secs_f64();
        let start = Instant::now();
        let _ = map_cells(x, y, &|mu_d, z0_mm| {
            integrated_cell(&p, LawKind::Harmonic, mu_d, z0_mm / MM, MAP_PERIODS)
        });
        let harmonic = start.elapsed().as_secs_f64();
        let n = 400;
        let start = Instant::now();
        let cells: Vec<u8> = (0..n)
            .map(|i| {
                integrated_cell(
                    &p,
                    LawKind::Harmonic,
                    0.2 + 0.0003 * f64::from(i),
                    p.z0,
                    MAP_PERIODS,
                )
            })
            .collect();
        eprintln!(
            "maps on {} threads: linear {linear:.3} s, harmonic {harmonic:.3} s; one harmonic \
             cell ({MAP_PERIODS} periods) {:.1} µs ({} cells)",
            rayon::current_num_threads(),
            start.elapsed().as_secs_f64() / f64::from(n) * 1e6,
            cells.len()
        );
    }
}
