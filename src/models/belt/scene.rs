//! Figures of the belt (docs/belt.md), from its exact integration with the closed forms over it:
//! the motion x(t) and v(t) with the belt's speed and the stick and slip times, and the phase
//! portrait v(x), one harmonic arc about x_d (B6) closed by the stick at v = v_b (B10).

use super::formula::ClosedForm;
use super::results::evaluate_with_run;
use super::BeltParams;
use crate::engine::autonomous::SurfaceRun;
use crate::engine::EventKind;
use crate::error::{Error, Result};
use crate::present::spec::{Curve, LineChart, Marker, Panel, Stroke};
use crate::present::vocab::{Drawing, Figure};

/// Points per curve on the uniform grid, event times added.
const SAMPLES: usize = 1200;
/// Palette indices and strokes: the exact integration solid, the closed forms dashed, the
/// belt's speed dotted.
const EXACT: (usize, Stroke) = (0, Stroke::Solid);
const CLOSED: (usize, Stroke) = (1, Stroke::Dashed);
const BELT: (usize, Stroke) = (7, Stroke::Dotted);

/// The exact run over at least `cycles` cycles, with its closed forms.
fn run(p: &BeltParams, cycles: f64) -> Result<(ClosedForm, SurfaceRun)> {
    if !(cycles.is_finite() && cycles > 0.0 && cycles <= 50.0) {
        return Err(Error::InvalidParam {
            name: "cycles",
            value: cycles.to_string(),
            rule: "0 < cycles ≤ 50 (cycles a figure of the belt shows)".to_string(),
        });
    }
    let (e, run) = evaluate_with_run(p, cycles.ceil() as u32 + 1)?;
    Ok((e.closed_form, run))
}

/// (t, x, v) of `run` on [0, t1]: a uniform grid with the events inserted, so that the kinks at
/// slip and stick are drawn sharp.
fn samples(run: &SurfaceRun, t1: f64) -> Vec<(f64, f64, f64)> {
    let mut times: Vec<f64> = (0..SAMPLES)
        .map(|i| t1 * i as f64 / (SAMPLES - 1) as f64)
        .chain(run.events.iter().map(|e| e.t).filter(|&t| t <= t1))
        .collect();
    times.sort_by(f64::total_cmp);
    times.dedup();
    times
        .into_iter()
        .filter_map(|t| run.state_at(t).map(|(x, v, _)| (t, x, v)))
        .collect()
}

fn curve(label: &str, points: Vec<(f64, f64)>, (color, stroke): (usize, Stroke)) -> Curve {
    Curve {
        label: label.to_string(),
        points,
        color,
        stroke,
    }
}

/// The slip onsets (t_1 + nT, (B5), (B11)) and the sticks (t_1 + t_slip + nT, (B8)) of the
/// closed forms inside [0, t1].
fn markers(c: &ClosedForm, t1: f64) -> Vec<Marker> {
    let mut out = Vec::new();
    let mut n = 0.0;
    while c.first_slip_time + n * c.period <= t1 && n < 100.0 {
        let onset = c.first_slip_time + n * c.period;
        out.push(Marker {
            x: onset,
            label: if n == 0.0 { "t_1" } else { "" }.to_string(),
        });
        if onset + c.t_slip <= t1 && c.t_stick > 0.0 {
            out.push(Marker {
                x: onset + c.t_slip,
                label: if n == 0.0 { "t_1 + t_slip" } else { "" }.to_string(),
            });
        }
        n += 1.0;
    }
    out
}

/// Position and speed over `cycles` cycles of the closed forms (after the first stick), the
/// belt's speed and the turning points x_s, x_d on their panels.
pub fn motion(scene_id: &str, p: &BeltParams, cycles: f64) -> Result<Figure> {
    let (c, run) = run(p, cycles)?;
    let t1 = c.first_slip_time + cycles * c.period;
    let points = samples(&run, t1);
    let x = points.iter().map(|&(t, x, _)| (t, x * 1e3)).collect();
    let v = points.iter().map(|&(t, _, v)| (t, v * 1e3)).collect();
    let belt = vec![(0.0, p.v_b * 1e3), (t1, p.v_b * 1e3)];
    let chart = LineChart {
        x_label: "t (s)".to_string(),
        x_range: Some((0.0, t1)),
        panels: vec![
            Panel {
                y_label: "x (mm)".to_string(),
                curves: vec![curve("exact integration", x, EXACT)],
                h_lines: vec![
                    (c.x_s * 1e3, "x_s".to_string()),
                    (c.x_d * 1e3, "x_d".to_string()),
                ],
            },
            Panel {
                y_label: "v (mm/s)".to_string(),
                curves: vec![
                    curve("exact integration", v, EXACT),
                    curve("belt speed v_b", belt, BELT),
                ],
                h_lines: vec![(0.0, String::new())],
            },
        ],
        markers: markers(&c, t1),
    };
    let caption = format!(
        "Position and speed of the block on the belt over {} cycles (exact integration): carried \
         at the belt's speed v_b until the spring reaches μs m g at x_s, then one harmonic slip \
         about x_d, back to the belt's speed after t_slip = {} s; {}. Marked: the slip onsets and \
         sticks of the closed forms.",
        crate::report::sketch::num(cycles),
        crate::report::sketch::num(c.t_slip),
        c.regime.words()
    );
    Ok(Figure {
        id: format!("{scene_id}-motion"),
        caption,
        drawing: Drawing::Chart(chart),
    })
}

/// The phase portrait of the settled cycle: the exact integration's v(x) from its second slip
/// onset on, over the closed forms' cycle, the arc (x − x_d)² + (v/ω)² = A² from x_s to x_e
/// (B6), (B7), (B9) and the stick v = v_b from x_e back to x_s.
pub fn phase_portrait(scene_id: &str, p: &BeltParams) -> Result<Figure> {
    let (c, run) = run(p, 2.0)?;
    let onsets: Vec<f64> = run
        .events
        .iter()
        .filter(|e| matches!(e.kind, EventKind::Slip { .. }))
        .map(|e| e.t)
        .collect();
    let (t0, t1) = match onsets.as_slice() {
        [_, second, third, ..] => (*second, *third),
        _ => {
            return Err(Error::Stalled {
                t: onsets.last().copied().unwrap_or(0.0),
                reason: "the belt's run has no complete settled cycle to draw",
            })
        }
    };
    let exact: Vec<(f64, f64)> = samples(&run, t1)
        .into_iter()
        .filter(|&(t, _, _)| t >= t0)
        .map(|(_, x, v)| (x * 1e3, v * 1e3))
        .collect();
    let angle = c.t_slip * c.omega;
    let arc: Vec<(f64, f64)> = (0..SAMPLES)
        .map(|i| {
            let th = angle * i as f64 / (SAMPLES - 1) as f64;
            let (s, co) = th.sin_cos();
            let x = c.x_d + c.delta * co + p.v_b / c.omega * s;
            let v = p.v_b * co - c.omega * c.delta * s;
            (x * 1e3, v * 1e3)
        })
        .collect();
    let stick = vec![
        (c.x_slip_end * 1e3, p.v_b * 1e3),
        (c.x_s * 1e3, p.v_b * 1e3),
    ];
    let chart = LineChart {
        x_label: "x (mm)".to_string(),
        x_range: None,
        panels: vec![Panel {
            y_label: "v (mm/s)".to_string(),
            curves: vec![
                curve("exact integration", exact, EXACT),
                curve("slip arc (B6)", arc, CLOSED),
                curve("stick at v_b (B10)", stick, (CLOSED.0, Stroke::DashDot)),
            ],
            h_lines: vec![(0.0, String::new())],
        }],
        markers: vec![
            Marker {
                x: c.x_d * 1e3,
                label: "x_d".to_string(),
            },
            Marker {
                x: c.x_s * 1e3,
                label: "x_s".to_string(),
            },
        ],
    };
    let caption = format!(
        "Phase portrait of the settled cycle: the slip is one arc of an ellipse about x_d of \
         amplitude A = {} mm, from x_s (where the spring overcomes μs m g) to x_e = 2x_d − x_s, \
         where the block regains the belt's speed; the stick carries it back along v = v_b. \
         Exact integration (solid) over the closed forms (dashed).",
        crate::report::sketch::num(c.amplitude * 1e3)
    );
    Ok(Figure {
        id: format!("{scene_id}-phase"),
        caption,
        drawing: Drawing::Chart(chart),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::belt::test_sets as sets;

    fn chart(f: &Figure) -> &LineChart {
        match &f.drawing {
            Drawing::Chart(c) => c,
            Drawing::Map(_) => panic!("a chart"),
        }
    }

    #[test]
    fn the_speed_never_exceeds_the_belts_and_the_position_stays_between_the_extremes() {
        for p in sets() {
            let fig = motion("belt", &p, 3.0).unwrap();
            let c = super::super::formula::evaluate(&p);
            let chart = chart(&fig);
            let x = &chart.panels[0].curves[0].points;
            let v = &chart.panels[1].curves[0].points;
            let tol = 1e-9;
            for &(_, v) in v {
                assert!(v <= p.v_b * 1e3 * (1.0 + tol), "{v} > v_b: {p:?}");
                assert!(v >= c.v_min * 1e3 * (1.0 + tol), "{v} < v_min: {p:?}");
            }
            for &(t, x) in x {
                let settled = t >= c.first_slip_time;
                assert!(x <= c.x_max * 1e3 * (1.0 + tol), "{x}: {p:?}");
                if settled {
                    assert!(x >= c.x_min * 1e3 - 1e-9, "{x}: {p:?}");
                }
            }
            // Three cycles after the first slip: three onsets marked.
            let onsets = chart
                .markers
                .iter()
                .filter(|m| m.label == "t_1" || m.label.is_empty())
                .count();
            assert!(onsets >= 3, "{:?}", chart.markers);
            assert!(fig.caption.contains(c.regime.words()));
            crate::report::figures::chart::line_chart(chart).unwrap();
        }
    }

    #[test]
    fn the_exact_phase_portrait_lies_on_the_closed_forms_cycle() {
        for p in sets() {
            let fig = phase_portrait("belt", &p).unwrap();
            let c = super::super::formula::evaluate(&p);
            let exact = &chart(&fig).panels[0].curves[0].points;
            assert!(exact.len() > 100);
            for &(x, v) in exact {
                let (x, v) = (x * 1e-3, v * 1e-3);
                let on_stick = (v - p.v_b).abs() <= 1e-9 * p.v_b;
                let r = ((x - c.x_d).powi(2) + (v / c.omega).powi(2)).sqrt();
                let on_arc = (r - c.amplitude).abs() <= 1e-9 * c.amplitude;
                assert!(on_stick || on_arc, "({x}, {v}) off the cycle: {p:?}");
            }
            crate::report::figures::chart::line_chart(chart(&fig)).unwrap();
        }
    }

    #[test]
    fn a_cycle_count_outside_its_range_is_refused() {
        let p = BeltParams::default();
        for bad in [0.0, -1.0, f64::NAN, 51.0] {
            let e = motion("belt", &p, bad).unwrap_err().to_string();
            assert!(e.contains("cycles"), "{e}");
        }
    }
}
