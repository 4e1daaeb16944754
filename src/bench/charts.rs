//! The benchmark's figures as [`LineChart`] specifications (drawn by the report's renderer,
//! which has linear axes: every logarithmic quantity is plotted as its log10, and the axis
//! label says so). One curve per method, in a colour and a dash pattern of its own.
//!
//! ```text
//! work-precision   log10 error against log10 time, per model × law (exact: a marker)
//! work             log10 error against log10 rhs evaluations, per model × law
//! order            log10 error against log10 h for the fixed-step methods, fitted order in
//!                  the legend
//! failures         euler_sign reversals per period against h; tanh creep and cost against ε;
//!                  events missed against tolerance
//! ```

use super::analysis::{Metric, OrderFit};
use super::failures::{CreepPoint, MissedPoint, ReversalPoint};
use super::peer::{PeerPoint, SCIPY_METHODS};
use super::sweep::{method_kind, MethodKind, SweepPoint};
use crate::report::figures::spec::{Curve, LineChart, Marker, Panel, Stroke};

/// Errors below this are drawn at it (an exact zero has no logarithm).
pub const ERROR_FLOOR: f64 = 1e-16;
/// Palette indices for the methods, in registry order (yellow, index 6, is too pale for lines).
const COLORS: [usize; 7] = [0, 1, 2, 3, 4, 5, 7];
const STROKES: [Stroke; 4] = [
    Stroke::Solid,
    Stroke::Dashed,
    Stroke::Dotted,
    Stroke::DashDot,
];
/// SciPy's curves: black, in the strokes of [`SCIPY_STROKES`].
const SCIPY_COLOR: usize = 7;
const SCIPY_STROKES: [Stroke; 3] = [Stroke::Solid, Stroke::Dashed, Stroke::DashDot];

/// Colour and stroke of the i-th method: every pair differs for up to 28 methods.
pub fn style(i: usize) -> (usize, Stroke) {
    (
        COLORS[i % COLORS.len()],
        STROKES[(i + i / COLORS.len()) % STROKES.len()],
    )
}

/// A fitted slope with two decimals ("—" when there is none).
pub fn slope_text(k: Option<f64>) -> String {
    k.map_or("—".to_string(), |k| format!("{k:.2}"))
}

fn log_err(e: f64) -> f64 {
    e.max(ERROR_FLOOR).log10()
}

/// A curve through `points` in the order given: the order of the settings, so that a
/// work-precision curve runs from the loosest to the tightest setting even where its time is
/// not monotone.
fn curve(label: String, points: Vec<(f64, f64)>, style: (usize, Stroke)) -> Curve {
    Curve {
        label,
        points,
        color: style.0,
        stroke: style.1,
    }
}

/// An x range covering `xs` with 4 % padding (`None` without finite values).
fn x_range(xs: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    let (lo, hi) = xs
        .filter(|x| x.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(x), b.max(x))
        });
    if lo > hi {
        return None;
    }
    let pad = ((hi - lo) * 0.04).max(0.1);
    Some((lo - pad, hi + pad))
}

/// Work-precision chart of one problem: a panel per metric, x = log10 time (or work).
pub fn work_precision<'a>(
    problem: &str,
    methods: &'a [String],
    sweep: &'a [SweepPoint],
    peer: &[PeerPoint],
    by_work: bool,
    vbar: bool,
) -> LineChart {
    let cost = |p: &SweepPoint| {
        if by_work {
            p.rhs_evals.map(|r| (r.max(1) as f64).log10())
        } else {
            p.time_s.map(f64::log10)
        }
    };
    let mine = |m: &'a str| {
        sweep
            .iter()
            .filter(move |p| p.problem == problem && p.method == m)
    };
    let metrics: &[Metric] = if by_work || !vbar {
        &[Metric::EventTime, Metric::XEnd]
    } else {
        &Metric::ALL
    };
    let mut xs = Vec::new();
    let mut panels = Vec::new();
    for (k, &metric) in metrics.iter().enumerate() {
        // One legend, in the bottom panel (the v̄ panel of the time chart has the most room):
        // colours and strokes are the same in every panel.
        let last = k + 1 == metrics.len();
        let label = |text: String| if last { text } else { String::new() };
        let mut curves = Vec::new();
        for (i, m) in methods.iter().enumerate() {
            if method_kind(m) == MethodKind::Reference {
                continue;
            }
            let pts: Vec<(f64, f64)> = mine(m)
                .filter_map(|p| Some((cost(p)?, log_err(metric.of(p)?))))
                .collect();
            xs.extend(pts.iter().map(|p| p.0));
            let name = if mine(m).any(SweepPoint::refused) {
                format!("{m} (refuses it)")
            } else {
                m.clone()
            };
            curves.push(curve(label(name), pts, style(i)));
        }
        if !by_work && metric != Metric::VBar {
            for (j, sm) in SCIPY_METHODS.iter().enumerate() {
                let pts: Vec<(f64, f64)> = peer
                    .iter()
                    .filter(|p| p.problem == problem && p.method == *sm)
                    .filter_map(|p| Some((p.time_s?.log10(), log_err(p.error_in(metric)?))))
                    .collect();
                if !pts.is_empty() {
                    xs.extend(pts.iter().map(|p| p.0));
                    curves.push(curve(
                        label(format!("SciPy {sm}")),
                        pts,
                        (SCIPY_COLOR, SCIPY_STROKES[j]),
                    ));
                }
            }
        }
        if last {
            // SciPy has no v̄: its legend entries ride on empty curves of this panel.
            for (j, sm) in SCIPY_METHODS.iter().enumerate() {
                let present = peer.iter().any(|p| p.problem == problem && p.method == *sm);
                if present && !by_work && metric == Metric::VBar {
                    curves.push(curve(
                        format!("SciPy {sm}"),
                        Vec::new(),
                        (SCIPY_COLOR, SCIPY_STROKES[j]),
                    ));
                }
            }
        }
        panels.push(Panel {
            y_label: metric.axis_label().to_string(),
            curves,
            h_lines: Vec::new(),
        });
    }
    let markers: Vec<Marker> = methods
        .iter()
        .filter(|m| method_kind(m) == MethodKind::Reference)
        .flat_map(|m| mine(m).filter_map(cost).take(1).map(move |x| (m, x)))
        .map(|(m, x)| Marker {
            x,
            label: format!("{m} (error 0)"),
        })
        .collect();
    xs.extend(markers.iter().map(|m| m.x));
    LineChart {
        x_label: if by_work {
            "log10 work (rhs evaluations)".to_string()
        } else {
            "log10 time (s), median of N runs".to_string()
        },
        x_range: x_range(xs.into_iter()),
        panels,
        markers,
    }
}

/// Error against step size for the fixed-step methods of one problem, with fitted orders.
pub fn order_chart(
    problem: &str,
    methods: &[String],
    sweep: &[SweepPoint],
    orders: &[OrderFit],
) -> LineChart {
    let mut xs = Vec::new();
    let mut panels = Vec::new();
    for metric in [Metric::XEnd, Metric::EventTime] {
        let mut curves = Vec::new();
        for (i, m) in methods.iter().enumerate() {
            if method_kind(m) != MethodKind::FixedStep {
                continue;
            }
            let pts: Vec<(f64, f64)> = sweep
                .iter()
                .filter(|p| p.problem == problem && &p.method == m)
                .filter_map(|p| Some((p.h_s?.log10(), log_err(metric.of(p)?))))
                .collect();
            xs.extend(pts.iter().map(|p| p.0));
            let order = orders
                .iter()
                .find(|o| o.problem == problem && &o.method == m && o.metric == metric)
                .and_then(|o| o.order);
            curves.push(curve(
                format!("{m} (order {})", slope_text(order)),
                pts,
                style(i),
            ));
        }
        panels.push(Panel {
            y_label: metric.axis_label().to_string(),
            curves,
            h_lines: Vec::new(),
        });
    }
    LineChart {
        x_label: "log10 step h (s)".to_string(),
        x_range: x_range(xs.into_iter()),
        panels,
        markers: Vec::new(),
    }
}

/// Spurious reversals per period of euler_sign against h, one curve per problem.
pub fn reversals_chart(
    points: &[ReversalPoint],
    problems: &[String],
    slopes: &[(String, Option<f64>)],
) -> LineChart {
    let curves: Vec<Curve> = problems
        .iter()
        .enumerate()
        .map(|(i, id)| {
            let pts = points
                .iter()
                .filter(|p| {
                    &p.problem == id && p.method == "euler_sign" && p.reversals_per_period > 0.0
                })
                .map(|p| (p.h_s.log10(), p.reversals_per_period.log10()))
                .collect();
            let k = slopes.iter().find(|s| &s.0 == id).and_then(|s| s.1);
            curve(format!("{id} (∝ h^{})", slope_text(k)), pts, style(i))
        })
        .collect();
    let xs: Vec<f64> = curves
        .iter()
        .flat_map(|c| c.points.iter().map(|p| p.0))
        .collect();
    LineChart {
        x_label: "log10 step h (s)".to_string(),
        x_range: x_range(xs.into_iter()),
        panels: vec![Panel {
            y_label: "log10 reversals per period".to_string(),
            curves,
            h_lines: Vec::new(),
        }],
        markers: Vec::new(),
    }
}

/// Creep per stick phase and cost of the tanh methods against ε.
pub fn creep_chart(points: &[CreepPoint]) -> LineChart {
    let mut keys: Vec<(String, String)> = Vec::new();
    for p in points {
        let k = (p.method.clone(), p.problem.clone());
        if !keys.contains(&k) {
            keys.push(k);
        }
    }
    let series = |f: &dyn Fn(&CreepPoint) -> Option<f64>| -> Vec<Curve> {
        keys.iter()
            .enumerate()
            .map(|(i, (m, pr))| {
                let pts = points
                    .iter()
                    .filter(|p| &p.method == m && &p.problem == pr)
                    .filter_map(|p| Some((p.epsilon_m_s?.log10(), f(p)?)))
                    .collect();
                curve(format!("{m}, {pr}"), pts, style(i))
            })
            .collect()
    };
    let xs: Vec<f64> = points
        .iter()
        .filter_map(|p| p.epsilon_m_s)
        .map(f64::log10)
        .collect();
    LineChart {
        x_label: "log10 regularization width ε (m/s)".to_string(),
        x_range: x_range(xs.into_iter()),
        panels: vec![
            Panel {
                y_label: "log10 creep per stick phase (m)".to_string(),
                curves: series(&|p| p.creep_m.map(log_err)),
                h_lines: Vec::new(),
            },
            Panel {
                y_label: "log10 rhs evaluations per period".to_string(),
                curves: series(&|p| p.rhs_per_period.filter(|r| *r > 0.0).map(f64::log10)),
                h_lines: Vec::new(),
            },
        ],
        markers: Vec::new(),
    }
}

/// Exact events missed against tolerance: a panel per method, a curve per problem.
pub fn missed_chart(points: &[MissedPoint]) -> LineChart {
    let mut methods: Vec<&str> = Vec::new();
    let mut problems: Vec<&str> = Vec::new();
    for p in points {
        if !methods.contains(&p.method.as_str()) {
            methods.push(&p.method);
        }
        if !problems.contains(&p.problem.as_str()) {
            problems.push(&p.problem);
        }
    }
    let panels = methods
        .iter()
        .map(|m| Panel {
            y_label: format!("{m}: events missed"),
            curves: problems
                .iter()
                .enumerate()
                .map(|(i, pr)| {
                    let pts = points
                        .iter()
                        .filter(|p| p.method == *m && p.problem == *pr)
                        .filter_map(|p| Some((p.tolerance.log10(), p.missed? as f64)))
                        .collect();
                    curve(pr.to_string(), pts, style(i))
                })
                .collect(),
            h_lines: vec![(0.0, String::new())],
        })
        .collect();
    let xs: Vec<f64> = points.iter().map(|p| p.tolerance.log10()).collect();
    LineChart {
        x_label: "log10 tolerance".to_string(),
        x_range: x_range(xs.into_iter()),
        panels,
        markers: Vec::new(),
    }
}
