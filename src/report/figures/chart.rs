//! Stacked line charts: panels over one shared x axis, each with its own automatic y range,
//! reference lines, curves in palette colour and dash pattern, and a framed legend; vertical
//! markers run through every panel and are labelled above the top one.
//!
//! Also owns the curve geometry the map reuses: non-finite points break a curve, curves are
//! clipped to the plotted box and thinned to [`MAX_POINTS`] points.

use plotters::element::{Rectangle, Text};
use plotters::prelude::{ChartBuilder, IntoDrawingArea, SVGBackend};
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{ShapeStyle, WHITE};

use super::spec::{LineChart, Panel};
pub use super::style::FigureError;
use super::style::{
    curve_color, draw_curve, draw_err, draw_legend, draw_legend_in, draw_stroked, finish_svg, font,
    legend_columns, legend_size, legend_size_in, text_width, tick_label, Geometry, LegendEntry,
    AXIS_COLOR, CURVE_WIDTH, FRAME_WIDTH, GRID_COLOR, LABEL_FONT_PX, LEGEND_FONT_PX, MARKER_COLOR,
    MARKER_DASH, MARKER_FONT_PX, MARKER_WIDTH, REFERENCE_COLOR, REFERENCE_WIDTH, RIGHT_MARGIN,
    TICK_FONT_PX, X_LABEL_AREA, Y_LABEL_AREA,
};

/// At most this many points of one curve are drawn (first, last and local extrema kept).
pub const MAX_POINTS: usize = 2000;
/// Blank space above and below each plotting area (px).
const PANEL_GAP: u32 = 8;
/// Space above the top panel when there are no marker labels (px).
const TOP_MARGIN: u32 = 6;
/// Height of one row of marker labels (px).
const MARKER_ROW: u32 = 20;
/// Marker labels whose centres are closer than this (px) go on different rows.
const MARKER_MIN_SEPARATION: f64 = 60.0;
/// Fraction of the data span added above and below the data of a panel.
const Y_MARGIN: f64 = 0.06;
/// Distance of the legend box from the plot frame (px).
const LEGEND_INSET: i32 = 10;
/// Space around a legend below its panel (px, half above and half below).
const LEGEND_BELOW_GAP: u32 = 12;

type Point = (f64, f64);
type Px = (i32, i32);

/// A box in data coordinates; infinite sides do not clip.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Bounds {
    pub lo: Point,
    pub hi: Point,
}

/// Renders `spec` as an SVG document on the report's canvas ([`Geometry::REPORT`]).
pub fn line_chart(spec: &LineChart) -> Result<String, FigureError> {
    line_chart_in(spec, Geometry::REPORT)
}

/// Renders `spec` as an SVG document on the canvas `g`.
///
/// Errors: no panel, an invalid x range, or a plotters failure. Curves without finite points
/// and panels without curves are drawn empty, never a panic.
pub fn line_chart_in(spec: &LineChart, g: Geometry) -> Result<String, FigureError> {
    if spec.panels.is_empty() {
        return Err(FigureError::NoPanels);
    }
    let x = x_range(spec)?;
    let clip = Bounds {
        lo: (x.0, f64::NEG_INFINITY),
        hi: (x.1, f64::INFINITY),
    };
    let panels = spec
        .panels
        .iter()
        .map(|p| PreparedPanel::new(p, clip, g))
        .collect::<Result<Vec<_>, _>>()?;

    let (grid, markers): (Vec<_>, Vec<_>) = spec
        .markers
        .iter()
        .filter(|m| m.x.is_finite() && m.x >= x.0 && m.x <= x.1)
        .partition(|m| m.label.is_empty());
    // Rows are chosen before the layout exists, with the same affine map plotters will use.
    let plot_width = f64::from(g.plot_width());
    let approx_px = |v: f64| f64::from(Y_LABEL_AREA) + (v - x.0) / (x.1 - x.0) * plot_width;
    let rows = stagger(
        &markers
            .iter()
            .map(|m| (approx_px(m.x), text_width(&m.label, MARKER_FONT_PX)))
            .collect::<Vec<_>>(),
    );
    let n_rows = rows.iter().max().map_or(0, |r| r + 1) as u32;
    let strip = TOP_MARGIN + n_rows * MARKER_ROW;
    // Every plotting area is g.panel_height − 2·PANEL_GAP tall; the bottom one also gets the
    // x labels. A legend that goes below its panel gets a band under it (under the x labels
    // for the bottom panel).
    let x_labels_under = |i: usize| {
        if i + 1 == panels.len() {
            X_LABEL_AREA
        } else {
            0
        }
    };
    let mut tops = Vec::with_capacity(panels.len());
    let mut height = strip;
    for (i, panel) in panels.iter().enumerate() {
        tops.push(height);
        height += g.panel_height + x_labels_under(i) + panel.legend_band;
    }

    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (g.width, height)).into_drawing_area();
        root.fill(&WHITE).map_err(draw_err)?;
        let areas: Vec<_> = tops
            .iter()
            .enumerate()
            .map(|(i, &top)| {
                root.clone()
                    .shrink((0, top), (g.width, g.panel_height + x_labels_under(i)))
            })
            .collect();

        let mut frames = Vec::with_capacity(panels.len());
        let mut drawn: Vec<Vec<Vec<Px>>> = Vec::with_capacity(panels.len());
        for (i, (panel, area)) in panels.iter().zip(&areas).enumerate() {
            let last = i + 1 == panels.len();
            let (y0, y1) = panel.y;
            let mut chart = ChartBuilder::on(area)
                .margin_top(PANEL_GAP)
                .margin_bottom(PANEL_GAP)
                .margin_right(RIGHT_MARGIN)
                .x_label_area_size(if last { X_LABEL_AREA } else { 0 })
                .y_label_area_size(Y_LABEL_AREA)
                .build_cartesian_2d(x.0..x.1, y0..y1)
                .map_err(draw_err)?;
            let x_fmt = |v: &f64| tick_label(*v, x.1 - x.0);
            let y_fmt = |v: &f64| {
                // A count's axis labels whole numbers only.
                if panel.counts && (v - v.round()).abs() > 1e-9 * (y1 - y0) {
                    String::new()
                } else {
                    tick_label(*v, y1 - y0)
                }
            };
            let y_ticks = if panel.counts {
                // At most one tick per whole number, so that plotters steps by 1 or more.
                ((y1 - y0).floor() as usize + 1).clamp(2, 6)
            } else {
                6
            };
            let mut mesh = chart.configure_mesh();
            mesh.x_labels(g.x_labels)
                .y_labels(y_ticks)
                .max_light_lines(0)
                .x_label_formatter(&x_fmt)
                .y_label_formatter(&y_fmt)
                .label_style(font(TICK_FONT_PX))
                .axis_desc_style(font(LABEL_FONT_PX))
                .bold_line_style(ShapeStyle::from(&GRID_COLOR).stroke_width(1))
                .axis_style(ShapeStyle::from(&AXIS_COLOR).stroke_width(FRAME_WIDTH))
                .y_desc(panel.spec.y_label.clone());
            if last {
                mesh.x_desc(spec.x_label.clone());
            }
            mesh.draw().map_err(draw_err)?;

            let to_px = |p: &Point| chart.backend_coord(p);
            // plotters draws the left and bottom axis one pixel outside the data corners.
            let (tl, br) = (to_px(&(x.0, y1)), to_px(&(x.1, y0)));
            let frame = ((tl.0 - 1, tl.1), (br.0, br.1 + 1));
            let mut lines: Vec<Vec<Px>> = Vec::new();
            for (y, label) in &panel.spec.h_lines {
                if !y.is_finite() {
                    continue;
                }
                let left = to_px(&(x.0, *y));
                let line = [left, to_px(&(x.1, *y))];
                draw_stroked(&root, &line, REFERENCE_COLOR, REFERENCE_WIDTH, &[])?;
                if !label.is_empty() {
                    // Right end, just above the line: curves usually start at the left edge.
                    let style = font(LEGEND_FONT_PX)
                        .color(&REFERENCE_COLOR)
                        .pos(Pos::new(HPos::Right, VPos::Bottom));
                    let at = (line[1].0 - 6, line[1].1 - 2);
                    root.draw(&Text::new(label.clone(), at, style))
                        .map_err(draw_err)?;
                    let w = text_width(label, LEGEND_FONT_PX).ceil() as i32;
                    let h = LEGEND_FONT_PX as i32;
                    // The label's box counts as lines for the legend placement.
                    lines.push(vec![(at.0 - w, at.1 - h / 2), (at.0, at.1 - h / 2)]);
                }
                lines.push(line.to_vec());
            }
            for (curve, runs) in panel.spec.curves.iter().zip(&panel.runs) {
                for run in runs {
                    let px = to_pixels(run, to_px);
                    draw_curve(
                        &root,
                        &px,
                        curve_color(curve.color),
                        CURVE_WIDTH,
                        curve.stroke,
                    )?;
                    lines.push(px);
                }
            }
            frames.push(frame);
            drawn.push(lines);
        }

        // Markers: one dashed line from under its label through every panel.
        let bottom = frames.last().map_or(0, |f| f.1 .1);
        let (left, right) = frames.first().map_or((0, 0), |f| (f.0 .0, f.1 .0));
        let label_style = font(MARKER_FONT_PX).pos(Pos::new(HPos::Center, VPos::Bottom));
        // A marker without a label is a vertical grid line (graph paper to read times from).
        let top = frames.first().map_or(0, |f| f.0 .1);
        for marker in &grid {
            let px =
                left + ((marker.x - x.0) / (x.1 - x.0) * f64::from(right - left)).round() as i32;
            draw_stroked(&root, &[(px, top), (px, bottom)], GRID_COLOR, 1, &[])?;
        }
        for (marker, row) in markers.iter().zip(&rows) {
            let px =
                left + ((marker.x - x.0) / (x.1 - x.0) * f64::from(right - left)).round() as i32;
            let base = (strip - 4 - *row as u32 * MARKER_ROW) as i32;
            let line = [(px, base + 3), (px, bottom)];
            draw_stroked(&root, &line, MARKER_COLOR, MARKER_WIDTH, &MARKER_DASH)?;
            let half = (text_width(&marker.label, MARKER_FONT_PX) / 2.0).ceil() as i32;
            let tx = px.clamp(half + 2, g.width as i32 - half - 2);
            root.draw(&Text::new(
                marker.label.clone(),
                (tx, base),
                label_style.clone(),
            ))
            .map_err(draw_err)?;
        }

        for (i, ((panel, frame), lines)) in panels.iter().zip(&frames).zip(&drawn).enumerate() {
            let border = ShapeStyle::from(&AXIS_COLOR).stroke_width(FRAME_WIDTH);
            root.draw(&Rectangle::new([frame.0, frame.1], border))
                .map_err(draw_err)?;
            let entries = legend_entries(panel.spec);
            if panel.legend_band > 0 {
                let top = tops[i] + g.panel_height + x_labels_under(i) + LEGEND_BELOW_GAP / 2;
                draw_legend_in(
                    &root,
                    (frame.0 .0, top as i32),
                    &entries,
                    panel.legend_columns,
                )?;
            } else if let Some((at, _)) = legend_corner(&entries, *frame, lines) {
                draw_legend(&root, at, &entries)?;
            }
        }
        root.present().map_err(draw_err)?;
    }
    Ok(finish_svg(svg))
}

/// A panel with its curves cut into drawable runs and its y range chosen.
struct PreparedPanel<'a> {
    spec: &'a Panel,
    /// runs[curve] = finite, clipped, thinned pieces of that curve.
    runs: Vec<Vec<Vec<Point>>>,
    y: (f64, f64),
    /// Every value drawn is a whole number (a count): ticks only at whole numbers.
    counts: bool,
    /// Height (px) of the band below the panel holding its legend, 0 when the legend sits in
    /// a corner of the plot, and the legend's columns there.
    legend_band: u32,
    legend_columns: usize,
}

impl<'a> PreparedPanel<'a> {
    fn new(spec: &'a Panel, clip: Bounds, g: Geometry) -> Result<Self, FigureError> {
        let runs: Vec<_> = spec
            .curves
            .iter()
            .map(|c| thin(clipped_runs(&c.points, clip), MAX_POINTS))
            .collect();
        let ys = runs
            .iter()
            .flatten()
            .flatten()
            .map(|p| p.1)
            .chain(spec.h_lines.iter().map(|h| h.0).filter(|y| y.is_finite()));
        let y = padded_range("y", ys, Y_MARGIN)?;
        let (y, legend_below) = with_legend_room(spec, &runs, (clip.lo.0, clip.hi.0), y, g);
        let (legend_band, legend_columns) = if legend_below {
            let entries = legend_entries(spec);
            let columns = legend_columns(&entries, g.plot_width() as i32);
            let height = legend_size_in(&entries, columns).1.max(0) as u32;
            (height + LEGEND_BELOW_GAP, columns)
        } else {
            (0, 1)
        };
        let mut values = runs.iter().flatten().flatten().map(|p| p.1).peekable();
        let counts = values.peek().is_some() && values.all(|v| v.fract() == 0.0);
        Ok(Self {
            spec,
            runs,
            y,
            counts,
            legend_band,
            legend_columns,
        })
    }
}

/// Raises the top of the y range when the legend would hide data in every corner, so that
/// the data leave a band free for it along the top of the panel; when that band would take
/// most of the panel, keeps the range and says the legend goes below the panel (`true`).
///
/// The pixel box is the one the layout will give (same constants); off by at most a pixel.
fn with_legend_room(
    spec: &Panel,
    runs: &[Vec<Vec<Point>>],
    x: (f64, f64),
    y: (f64, f64),
    g: Geometry,
) -> ((f64, f64), bool) {
    let entries = legend_entries(spec);
    if entries.is_empty() {
        return (y, false);
    }
    let w = f64::from(g.plot_width());
    let h = f64::from(g.panel_height - 2 * PANEL_GAP);
    let to_px = |p: &Point| {
        (
            ((p.0 - x.0) / (x.1 - x.0) * w).round() as i32,
            ((y.1 - p.1) / (y.1 - y.0) * h).round() as i32,
        )
    };
    let mut lines: Vec<Vec<Px>> = runs.iter().flatten().map(|r| to_pixels(r, to_px)).collect();
    lines.extend(
        spec.h_lines
            .iter()
            .filter(|l| l.0.is_finite())
            .map(|l| vec![to_px(&(x.0, l.0)), to_px(&(x.1, l.0))]),
    );
    let frame = ((0, 0), (w as i32, h as i32));
    let hidden = legend_corner(&entries, frame, &lines).map_or(0, |(_, hidden)| hidden);
    // Legend height, its inset from the frame, and the 3 px the corner test adds around it.
    let band = f64::from(legend_size(&entries).1 + LEGEND_INSET + 4);
    if hidden == 0 {
        return (y, false);
    }
    if band >= 0.6 * h {
        return (y, true);
    }
    // Keep the data (and the lower margin) in the lower h − band pixels.
    let top = y.0 + (y.1 - y.0) * h / (h - band);
    ((y.0, top), false)
}

/// The x range: given, or spanned by the finite points of all curves.
fn x_range(spec: &LineChart) -> Result<(f64, f64), FigureError> {
    if let Some((lo, hi)) = spec.x_range {
        return checked_range("x", (lo, hi));
    }
    let xs = spec
        .panels
        .iter()
        .flat_map(|p| &p.curves)
        .flat_map(|c| &c.points)
        .filter(|p| p.0.is_finite() && p.1.is_finite())
        .map(|p| p.0);
    padded_range("x", xs, 0.0)
}

/// Checks that a given range is finite and increasing.
pub(super) fn checked_range(axis: &'static str, r: (f64, f64)) -> Result<(f64, f64), FigureError> {
    let (lo, hi) = r;
    if lo.is_finite() && hi.is_finite() && lo < hi && (hi - lo).is_finite() {
        Ok((lo, hi))
    } else {
        Err(FigureError::BadRange { axis, lo, hi })
    }
}

/// The range of `values` widened by `margin` of its span on each side; a single value gets a
/// range around it, no value gets [0, 1].
fn padded_range(
    axis: &'static str,
    values: impl Iterator<Item = f64>,
    margin: f64,
) -> Result<(f64, f64), FigureError> {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    });
    if lo.partial_cmp(&hi).is_none_or(|o| o.is_gt()) {
        return Ok((0.0, 1.0));
    }
    let span = hi - lo;
    let scale = lo.abs().max(hi.abs());
    let range = if span > scale * 1e-9 {
        (lo - margin * span, hi + margin * span)
    } else {
        let pad = if scale > 0.0 { scale * 0.1 } else { 1.0 };
        (lo - pad, hi + pad)
    };
    checked_range(axis, range)
}

/// The finite pieces of a polyline inside `clip`: non-finite points break the line, segments
/// crossing the box are cut at its edges, pieces of fewer than two points are dropped.
pub(super) fn clipped_runs(points: &[Point], clip: Bounds) -> Vec<Vec<Point>> {
    let mut runs = Vec::new();
    let mut current: Vec<Point> = Vec::new();
    let mut flush = |current: &mut Vec<Point>| {
        if current.len() > 1 {
            runs.push(std::mem::take(current));
        }
        current.clear();
    };
    let finite = |p: &Point| p.0.is_finite() && p.1.is_finite();
    let mut prev: Option<Point> = None;
    for p in points {
        if !finite(p) {
            flush(&mut current);
            prev = None;
            continue;
        }
        let Some(a) = prev.replace(*p) else {
            continue;
        };
        match clip_segment(a, *p, clip) {
            None => flush(&mut current),
            Some((from, to, entered, left)) => {
                if entered {
                    flush(&mut current);
                }
                if current.is_empty() {
                    current.push(from);
                }
                current.push(to);
                if left {
                    flush(&mut current);
                }
            }
        }
    }
    flush(&mut current);
    runs
}

/// Liang–Barsky: the part of segment a→b inside `clip`, and whether a and b were cut off.
fn clip_segment(a: Point, b: Point, clip: Bounds) -> Option<(Point, Point, bool, bool)> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, a.0 - clip.lo.0),
        (dx, clip.hi.0 - a.0),
        (-dy, a.1 - clip.lo.1),
        (dy, clip.hi.1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
            if t0 > t1 {
                return None;
            }
        }
    }
    let at = |t: f64| {
        if t <= 0.0 {
            a
        } else if t >= 1.0 {
            b
        } else {
            (a.0 + dx * t, a.1 + dy * t)
        }
    };
    Some((at(t0), at(t1), t0 > 0.0, t1 < 1.0))
}

/// Thins runs to about `max` points in all: each run keeps its ends and, per bucket of
/// consecutive points, the lowest and the highest one (so peaks and sticks survive).
/// The bound is exact unless the curve is broken into more than `max / 2` runs.
pub(super) fn thin(runs: Vec<Vec<Point>>, max: usize) -> Vec<Vec<Point>> {
    let total: usize = runs.iter().map(Vec::len).sum();
    if total <= max {
        return runs;
    }
    let interior_budget = max.saturating_sub(2 * runs.len());
    runs.into_iter()
        .map(|run| {
            let n = run.len();
            let budget = interior_budget * n / total;
            let buckets = budget / 2;
            if n <= 2 + budget {
                return run;
            }
            let inner = &run[1..n - 1];
            let mut out = Vec::with_capacity(2 * buckets + 2);
            out.push(run[0]);
            for b in 0..buckets {
                let chunk = &inner[b * inner.len() / buckets..(b + 1) * inner.len() / buckets];
                if chunk.is_empty() {
                    continue;
                }
                let (mut lo, mut hi) = (0, 0);
                for (i, p) in chunk.iter().enumerate() {
                    if p.1 < chunk[lo].1 {
                        lo = i;
                    }
                    if p.1 > chunk[hi].1 {
                        hi = i;
                    }
                }
                out.push(chunk[lo.min(hi)]);
                if lo != hi {
                    out.push(chunk[lo.max(hi)]);
                }
            }
            out.push(run[n - 1]);
            out
        })
        .collect()
}

/// Maps a run to backend pixels, dropping consecutive duplicates.
pub(super) fn to_pixels(run: &[Point], to_px: impl Fn(&Point) -> Px) -> Vec<Px> {
    let mut out: Vec<Px> = Vec::with_capacity(run.len());
    for p in run {
        let q = to_px(p);
        if out.last() != Some(&q) {
            out.push(q);
        }
    }
    out
}

/// Legend rows of the labelled curves of a panel.
fn legend_entries(panel: &Panel) -> Vec<LegendEntry> {
    LegendEntry::lines(&panel.curves, CURVE_WIDTH).collect()
}

/// Upper-left corner of the legend: the inner corner of the frame that hides the fewest line
/// segments (ties: upper right, upper left, lower right, lower left), and how many it hides.
/// `None` if there is no legend.
fn legend_corner(
    entries: &[LegendEntry],
    frame: (Px, Px),
    lines: &[Vec<Px>],
) -> Option<(Px, usize)> {
    if entries.is_empty() {
        return None;
    }
    let (w, h) = legend_size(entries);
    let ((l, t), (r, b)) = frame;
    let (left, right) = (l + LEGEND_INSET, r - LEGEND_INSET - w);
    let (top, bottom) = (t + LEGEND_INSET, b - LEGEND_INSET - h);
    let candidates = [(right, top), (left, top), (right, bottom), (left, bottom)];
    let hidden = |&(x, y): &Px| {
        let bounds = Bounds {
            lo: (f64::from(x - 3), f64::from(y - 3)),
            hi: (f64::from(x + w + 3), f64::from(y + h + 3)),
        };
        lines
            .iter()
            .flat_map(|line| line.windows(2))
            .filter(|s| {
                let f = |p: Px| (f64::from(p.0), f64::from(p.1));
                clip_segment(f(s[0]), f(s[1]), bounds).is_some()
            })
            .count()
    };
    candidates
        .iter()
        .enumerate()
        .map(|(i, c)| (hidden(c), i, *c))
        .min()
        .map(|(n, _, c)| (c, n))
}

/// Row (0 = nearest the plot) of each label, given centre and width: a label moves up while it
/// would come closer than [`MARKER_MIN_SEPARATION`] (or overlap) a label already in that row.
fn stagger(labels: &[(f64, f64)]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..labels.len()).collect();
    order.sort_by(|&a, &b| labels[a].0.total_cmp(&labels[b].0));
    let mut rows = vec![0; labels.len()];
    // Per row: centre and half width of the rightmost label placed so far.
    let mut last: Vec<(f64, f64)> = Vec::new();
    for i in order {
        let (c, w) = labels[i];
        let free = |&(pc, ph): &(f64, f64)| c - pc >= MARKER_MIN_SEPARATION.max(ph + w / 2.0 + 8.0);
        let row = last.iter().position(free).unwrap_or(last.len());
        if row == last.len() {
            last.push((c, w / 2.0));
        } else {
            last[row] = (c, w / 2.0);
        }
        rows[i] = row;
    }
    rows
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::figures::spec::{Curve, Marker, Stroke};

    fn curve(label: &str, color: usize, stroke: Stroke, f: impl Fn(f64) -> f64) -> Curve {
        Curve {
            label: label.to_string(),
            points: (0..=400)
                .map(|i| {
                    let t = f64::from(i) * 0.01;
                    (t, f(t))
                })
                .collect(),
            color,
            stroke,
        }
    }

    pub(crate) fn sample_chart() -> LineChart {
        LineChart {
            x_label: "t (s)".to_string(),
            x_range: None,
            panels: vec![
                Panel {
                    y_label: "x (mm)".to_string(),
                    curves: vec![
                        curve("position exact", 0, Stroke::Solid, |t| (3.0 * t).sin() + t),
                        curve("position linearized", 1, Stroke::Dashed, |t| {
                            (3.0 * t).sin() * 0.9 + t
                        }),
                    ],
                    h_lines: vec![(0.0, "rest".to_string())],
                },
                Panel {
                    y_label: "v (mm/s)".to_string(),
                    curves: vec![
                        curve("velocity exact", 2, Stroke::Dotted, |t| {
                            3.0 * (3.0 * t).cos() + 1.0
                        }),
                        curve("friction limit", 3, Stroke::DashDot, |t| {
                            2.0 + 0.5 * (6.0 * t).cos()
                        }),
                    ],
                    h_lines: vec![],
                },
            ],
            markers: vec![
                Marker {
                    x: 1.0,
                    label: "t_SL".to_string(),
                },
                Marker {
                    x: 1.1,
                    label: "t_LS".to_string(),
                },
                Marker {
                    x: 3.0,
                    label: "T".to_string(),
                },
            ],
        }
    }

    #[test]
    fn two_panel_chart_has_labels_dashes_and_is_deterministic() {
        let spec = sample_chart();
        let svg = line_chart(&spec).expect("renders");
        assert!(svg.starts_with("<svg"));
        for label in [
            "position exact",
            "position linearized",
            "velocity exact",
            "friction limit",
            "t (s)",
            "x (mm)",
            "v (mm/s)",
            "t_SL",
            "t_LS",
        ] {
            assert!(svg.contains(label), "missing {label}");
        }
        // The x label appears once: under the bottom panel only.
        assert_eq!(svg.matches(">\nt (s)\n<").count(), 1);
        // Dashed curves are drawn as many separate dash pieces in their colour.
        let pieces = |hex: &str| svg.matches(&format!("stroke=\"{hex}\"")).count();
        assert!(pieces("#0072B2") < 5, "solid curve is one polyline");
        assert!(pieces("#D55E00") > 20, "dashed");
        assert!(pieces("#009E73") > 50, "dotted");
        assert!(pieces("#CC79A7") > 20, "dash-dot");
        assert!(svg.contains("viewBox=\"0 0 900 "));
        assert!(svg.contains("font-size=\"14\""));
        assert_eq!(svg, line_chart(&spec).expect("renders again"));
    }

    #[test]
    fn a_legend_that_would_hide_data_in_every_corner_of_a_short_panel_goes_below_it() {
        // Five curves filling the panel: every corner is covered.
        let crowded = |panels: usize| LineChart {
            x_label: "t (s)".to_string(),
            x_range: None,
            panels: vec![
                Panel {
                    y_label: "F (N)".to_string(),
                    curves: (0..5)
                        .map(|i| {
                            let phase = f64::from(i as u32);
                            curve(&format!("force number {i}"), i, Stroke::Solid, move |t| {
                                (7.0 * t + phase).sin()
                            })
                        })
                        .collect(),
                    h_lines: vec![],
                };
                panels
            ],
            markers: vec![],
        };
        let height = |svg: &str| svg_height(svg);
        let g = Geometry::COLUMN;
        let one = line_chart_in(&crowded(1), g).unwrap();
        let band = height(&one) - f64::from(TOP_MARGIN + g.panel_height + X_LABEL_AREA);
        let entries = legend_entries(&crowded(1).panels[0]);
        let legend = legend_size_in(&entries, legend_columns(&entries, g.plot_width() as i32)).1;
        assert_eq!(band, f64::from(legend.max(0) as u32 + LEGEND_BELOW_GAP));
        // A band under each panel; on the report's taller canvas the legend stays inside.
        let two = line_chart_in(&crowded(2), g).unwrap();
        assert_eq!(
            height(&two),
            height(&one) + f64::from(g.panel_height) + band
        );
        let report = line_chart(&crowded(1)).unwrap();
        let inside = TOP_MARGIN + Geometry::REPORT.panel_height + X_LABEL_AREA;
        assert_eq!(height(&report), f64::from(inside));
    }

    /// The `height` attribute of an SVG root.
    fn svg_height(svg: &str) -> f64 {
        let rest = svg.split_once(" height=\"").expect("a height").1;
        rest.split('"').next().unwrap().parse().unwrap()
    }

    #[test]
    fn a_panel_of_counts_labels_whole_numbers_only() {
        let mut spec = sample_chart();
        spec.panels[1].curves = vec![curve("slips per period", 0, Stroke::Solid, |t| {
            if t < 1.5 {
                1.0
            } else {
                2.0
            }
        })];
        spec.panels[0].curves = vec![curve("small", 0, Stroke::Solid, |t| 0.3 * t.sin())];
        let svg = line_chart(&spec).expect("renders");
        // y tick labels are the right-aligned texts; each panel's follow its axis title.
        let y_ticks = |part: &str| -> Vec<String> {
            part.split("<text")
                .filter(|t| t.contains("text-anchor=\"end\"") && !t.contains("rest"))
                .filter_map(|t| t.split('>').nth(1))
                .map(|t| t.split('<').next().unwrap_or("").trim().to_string())
                .collect()
        };
        let (first, second) = svg.split_once("v (mm/s)").expect("second panel");
        let counts = y_ticks(second);
        assert_eq!(counts, ["1", "2"]);
        // The first panel is not a count: it keeps its fractional ticks.
        assert!(y_ticks(first).iter().any(|l| l.contains('.')), "{first}");
    }

    #[test]
    fn non_finite_points_break_the_curve_without_panicking() {
        let mut spec = sample_chart();
        let pts = &mut spec.panels[0].curves[0].points;
        pts[10] = (f64::NAN, 1.0);
        pts[20] = (0.2, f64::INFINITY);
        pts[30] = (f64::NEG_INFINITY, f64::NAN);
        spec.panels[1].curves[0].points = vec![(f64::NAN, f64::NAN); 5];
        assert!(line_chart(&spec).is_ok());
    }

    #[test]
    fn empty_charts_are_drawn_or_refused_cleanly() {
        let mut spec = sample_chart();
        for p in &mut spec.panels {
            p.curves.clear();
        }
        assert!(line_chart(&spec).is_ok());
        spec.panels.clear();
        assert!(matches!(line_chart(&spec), Err(FigureError::NoPanels)));
        let bad = LineChart {
            x_range: Some((1.0, 1.0)),
            ..sample_chart()
        };
        assert!(matches!(
            line_chart(&bad),
            Err(FigureError::BadRange { .. })
        ));
    }

    #[test]
    fn long_curves_are_thinned_to_the_point_budget_keeping_ends_and_peaks() {
        let n = 100_000;
        let run: Vec<Point> = (0..n)
            .map(|i| {
                let t = i as f64 / n as f64;
                (t, if i == 54_321 { 10.0 } else { (50.0 * t).sin() })
            })
            .collect();
        let thinned = thin(vec![run.clone()], MAX_POINTS);
        assert!(thinned[0].len() <= MAX_POINTS);
        assert_eq!(thinned[0].first(), run.first());
        assert_eq!(thinned[0].last(), run.last());
        assert!(thinned[0].contains(&run[54_321]));
    }

    #[test]
    fn clipping_cuts_segments_at_the_box_and_splits_runs() {
        let clip = Bounds {
            lo: (0.0, f64::NEG_INFINITY),
            hi: (1.0, f64::INFINITY),
        };
        let runs = clipped_runs(&[(-1.0, 0.0), (0.5, 1.5), (2.0, 0.0), (0.5, 0.0)], clip);
        assert_eq!(runs.len(), 2);
        let xs = |r: &Vec<Point>| r.iter().map(|p| p.0).collect::<Vec<_>>();
        assert_eq!(xs(&runs[0]), [0.0, 0.5, 1.0]);
        assert!((runs[0][0].1 - 1.0).abs() < 1e-12 && (runs[0][2].1 - 1.0).abs() < 1e-12);
        assert_eq!(runs[1], vec![(1.0, 0.0), (0.5, 0.0)]);
    }

    #[test]
    fn close_marker_labels_are_staggered() {
        assert_eq!(
            stagger(&[(100.0, 30.0), (130.0, 30.0), (300.0, 30.0)]),
            [0, 1, 0]
        );
        assert_eq!(
            stagger(&[(100.0, 30.0), (110.0, 30.0), (120.0, 30.0)]),
            [0, 1, 2]
        );
    }

    #[test]
    fn example_svgs_are_written_to_tmp() {
        let svg = line_chart(&sample_chart()).expect("renders");
        std::fs::write("/tmp/chart.svg", svg).expect("writes /tmp/chart.svg");
    }
}
