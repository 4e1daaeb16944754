//! Rendering of a finished sweep: `sweep.csv` (units in the header), `sweep.svg` (v̄ and slips
//! per period of each of the model's laws against the parameter) and the one-line summary. Pure: strings in,
//! [`OutFile`]s out; the caller writes them.

use std::fmt::Write as _;
use std::path::Path;

use super::{LawPoint, Point, Sweep};
use crate::error::{Error, Result};
use crate::export::num;
use crate::report::context::regime_words;
use crate::report::figures::chart::line_chart;
use crate::report::figures::spec::{Curve, LineChart, Panel, Stroke};
use crate::report::OutFile;

/// Regime written for a point whose parameter set is invalid.
pub const INVALID: &str = "invalid";
/// Regime written for a law that does not exist at a point.
pub const UNDEFINED: &str = "undefined";
/// Regime changes listed by name in the summary line; more are counted.
const LISTED_CHANGES: usize = 3;

/// sweep.csv and sweep.svg.
pub fn render(s: &Sweep) -> Result<Vec<OutFile>> {
    Ok(vec![
        OutFile {
            path: "sweep.csv".into(),
            bytes: csv(s).into_bytes(),
        },
        OutFile {
            path: "sweep.svg".into(),
            bytes: svg(s)?.into_bytes(),
        },
    ])
}

/// The parameter column's header: the name with its unit suffix (`z0_m`, `mu_d`).
fn param_column(s: &Sweep) -> String {
    if s.param.unit.is_empty() {
        s.param.name.to_string()
    } else {
        format!("{}_{}", s.param.name, s.param.unit)
    }
}

fn csv(s: &Sweep) -> String {
    let mut text = param_column(s);
    for law in s.laws {
        let _ = write!(
            text,
            ",v_avg_{0}_m_s,slips_{0},sticks_{0},regime_{0}",
            law.id
        );
    }
    text.push_str(",regime_closed_form");
    for c in &s.columns {
        let _ = write!(text, ",{}", c.column);
    }
    text.push('\n');
    for p in &s.points {
        text.push_str(&num(p.value));
        for i in 0..s.laws.len() {
            let cells = match law(p, i) {
                Some(l) => format!(
                    "{},{},{},{}",
                    l.v_avg.map(num).unwrap_or_default(),
                    l.slips,
                    l.sticks,
                    l.regime
                ),
                None => format!(",,,{}", missing_regime(p)),
            };
            let _ = write!(text, ",{cells}");
        }
        let _ = write!(text, ",{}", p.closed_form.unwrap_or(INVALID));
        for i in 0..s.columns.len() {
            let cell = p.own.get(i).copied().flatten().map(num);
            let _ = write!(text, ",{}", cell.unwrap_or_default());
        }
        text.push('\n');
    }
    text
}

/// The point's run of law `i` of the sweep (`None`: invalid point, or no such law there).
fn law(p: &Point, i: usize) -> Option<&LawPoint> {
    p.laws.get(i).and_then(Option::as_ref)
}

fn missing_regime(p: &Point) -> &'static str {
    if p.invalid.is_some() {
        INVALID
    } else {
        UNDEFINED
    }
}

fn svg(s: &Sweep) -> Result<String> {
    let x = |p: &Point| p.value * s.param.axis_scale;
    // The first law solid in the first colour, the others dashed: the report's figures' styles.
    let curve = |i: usize, y: fn(&LawPoint) -> Option<f64>| Curve {
        label: s.laws[i].id.to_string(),
        // Invalid points and missing values are NaN: the renderer breaks the curve there.
        points: s
            .points
            .iter()
            .map(|p| (x(p), law(p, i).and_then(y).unwrap_or(f64::NAN)))
            .collect(),
        color: i,
        stroke: if i == 0 {
            Stroke::Solid
        } else {
            Stroke::Dashed
        },
    };
    let v_mm: fn(&LawPoint) -> Option<f64> = |l| l.v_avg.map(|v| v * 1e3);
    let slips: fn(&LawPoint) -> Option<f64> = |l| Some(f64::from(l.slips));
    let curves = |y| (0..s.laws.len()).map(|i| curve(i, y)).collect();
    let (a, b) = (
        s.spec.from * s.param.axis_scale,
        s.spec.to * s.param.axis_scale,
    );
    // The model's own quantities, one panel each, replace v̄ and slips per period.
    let own = s.columns.iter().enumerate().map(|(i, c)| Panel {
        y_label: c.label.to_string(),
        curves: vec![Curve {
            label: c.column.to_string(),
            points: s
                .points
                .iter()
                .map(|p| {
                    let y = p.own.get(i).copied().flatten();
                    (x(p), y.map_or(f64::NAN, |y| y * c.scale))
                })
                .collect(),
            color: 0,
            stroke: Stroke::Solid,
        }],
        h_lines: Vec::new(),
    });
    let panels = if s.columns.is_empty() {
        vec![
            Panel {
                y_label: "v̄ (mm/s)".to_string(),
                curves: curves(v_mm),
                h_lines: Vec::new(),
            },
            Panel {
                y_label: "slips per period".to_string(),
                curves: curves(slips),
                h_lines: Vec::new(),
            },
        ]
    } else {
        own.collect()
    };
    let spec = LineChart {
        x_label: s.param.axis_label.to_string(),
        x_range: Some((a.min(b), a.max(b))),
        panels,
        markers: Vec::new(),
    };
    line_chart(&spec).map_err(|e| Error::Figure {
        id: "sweep".to_string(),
        reason: e.to_string(),
    })
}

/// Distinct values in order of first appearance, with their counts.
fn tally<'a>(items: impl Iterator<Item = &'a str>) -> Vec<(&'a str, usize)> {
    let mut out: Vec<(&str, usize)> = Vec::new();
    for item in items {
        match out.iter_mut().find(|(name, _)| *name == item) {
            Some((_, n)) => *n += 1,
            None => out.push((item, 1)),
        }
    }
    out
}

/// One line: points, regimes seen per law, where the first law's regime changes, files
/// written.
pub fn summary_line(s: &Sweep, out: &Path) -> String {
    let unit = if s.param.unit_text.is_empty() {
        String::new()
    } else {
        format!(" {}", s.param.unit_text)
    };
    let seen = |regimes: Vec<(&str, usize)>| {
        regimes
            .iter()
            .map(|(r, n)| format!("{} ({n})", regime_words(r)))
            .collect::<Vec<_>>()
            .join(", ")
    };
    let regimes = |i: usize| -> Vec<&str> {
        s.points
            .iter()
            .map(|p| law(p, i).map_or_else(|| missing_regime(p), |l| l.regime))
            .collect()
    };
    let first: Vec<&str> = regimes(0);
    let changes: Vec<String> = first
        .windows(2)
        .zip(s.points.windows(2))
        .filter(|(r, _)| r[0] != r[1])
        .map(|(r, p)| {
            format!(
                "{} -> {} between {} = {} and {}{unit}",
                regime_words(r[0]),
                regime_words(r[1]),
                s.param.name,
                num(p[0].value),
                num(p[1].value)
            )
        })
        .collect();
    let change_text = match changes.len() {
        0 => "none".to_string(),
        n if n <= LISTED_CHANGES => changes.join("; "),
        n => format!(
            "{}; and {} more",
            changes[..LISTED_CHANGES].join("; "),
            n - LISTED_CHANGES
        ),
    };
    let seen_per_law: String = s
        .laws
        .iter()
        .enumerate()
        .map(|(i, l)| {
            format!(
                "{} regimes: {}; ",
                l.id,
                seen(tally(regimes(i).into_iter()))
            )
        })
        .collect();
    format!(
        "sweep {} {}: {} points from {} to {}{unit}; {seen_per_law}{} regime changes: {}; wrote {}\n",
        s.model,
        s.param.name,
        s.points.len(),
        num(s.spec.from),
        num(s.spec.to),
        s.laws.first().map_or("", |l| l.id),
        change_text,
        crate::error::excerpt_path(&out.display().to_string())
    )
}
