//! The look of every figure: sizes, fonts, the colour-blind-safe palette, stroke patterns, and
//! the drawing helpers both renderers share (text styles, tick labels, dashed polylines, the
//! framed legend, the final touch on the SVG root). Change the look here, not in the renderers.
//!
//! Fonts are only named: plotters is built without `ttf`, so text extents are estimated, no
//! system font is read and the SVG bytes are the same on every machine.

use plotters::coord::Shift;
use plotters::element::{Circle, PathElement, Rectangle, Text};
use plotters::prelude::{DrawingArea, SVGBackend};
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{Color, IntoFont, RGBColor, ShapeStyle, TextStyle};

use super::spec::{Curve, Stroke};

/// The canvas of a figure (px of the SVG user space). Text keeps its size in px whatever the
/// canvas, so a narrower canvas prints its text larger at the same printed width.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Geometry {
    /// Width of the figure.
    pub width: u32,
    /// Height of one panel of a stacked chart, label areas included.
    pub panel_height: u32,
    /// Height of the plotting area of a category map.
    pub map_plot_height: u32,
    /// Tick labels asked for along the x axis.
    pub x_labels: usize,
}

impl Geometry {
    /// The report's figures: the page's width on screen, 17-19 cm printed.
    pub const REPORT: Geometry = Geometry {
        width: 900,
        panel_height: 260,
        map_plot_height: 520,
        x_labels: 10,
    };
    /// A column of a two-column A4 print (90.5 mm): 14 px text prints at 8.2 pt, as the
    /// report's figures do across the page.
    pub const COLUMN: Geometry = Geometry {
        width: 440,
        panel_height: 170,
        map_plot_height: 260,
        x_labels: 6,
    };

    /// Width of a plotting area on this canvas: the figure less the y labels and the right
    /// margin.
    pub fn plot_width(self) -> u32 {
        self.width - Y_LABEL_AREA - RIGHT_MARGIN
    }

    /// The same canvas with panels and maps `factor` times as tall (whole px), plotting areas
    /// at most square.
    pub fn taller(self, factor: f64) -> Geometry {
        let square = self.plot_width();
        let scale = |px: u32| ((f64::from(px) * factor).round() as u32).min(square);
        Geometry {
            panel_height: scale(self.panel_height),
            map_plot_height: scale(self.map_plot_height),
            ..self
        }
    }
}
/// Room left of a plotting area for tick labels and the rotated y label.
pub const Y_LABEL_AREA: u32 = 80;
/// Room below the bottom plotting area for tick labels and the x label.
pub const X_LABEL_AREA: u32 = 58;
/// Margin right of a chart's plotting area.
pub const RIGHT_MARGIN: u32 = 24;

/// Named only, never loaded: the viewer picks the first one it has.
pub const FONT_FAMILY: &str = "DejaVu Sans, Helvetica, Arial, sans-serif";
/// Tick labels (px). Print at 17 cm width keeps them above 2.5 mm.
pub const TICK_FONT_PX: f64 = 14.0;
/// Axis labels (px).
pub const LABEL_FONT_PX: f64 = 16.0;
/// Legend entries and reference-line labels (px).
pub const LEGEND_FONT_PX: f64 = 14.0;
/// Labels of vertical markers (px).
pub const MARKER_FONT_PX: f64 = 14.0;

/// Okabe & Ito, "Color Universal Design" (2008): distinguishable with every common colour
/// vision deficiency. Index 0 is the first curve colour.
pub const PALETTE: [RGBColor; 8] = [
    RGBColor(0x00, 0x72, 0xB2), // blue
    RGBColor(0xD5, 0x5E, 0x00), // vermillion
    RGBColor(0x00, 0x9E, 0x73), // bluish green
    RGBColor(0xCC, 0x79, 0xA7), // reddish purple
    RGBColor(0xE6, 0x9F, 0x00), // orange
    RGBColor(0x56, 0xB4, 0xE9), // sky blue
    RGBColor(0xF0, 0xE4, 0x42), // yellow
    RGBColor(0x00, 0x00, 0x00), // black
];

/// Category fills: the palette blended 60 % towards white, light enough for curves on top.
pub const FILLS: [RGBColor; 8] = [
    towards_white(PALETTE[0]),
    towards_white(PALETTE[1]),
    towards_white(PALETTE[2]),
    towards_white(PALETTE[3]),
    towards_white(PALETTE[4]),
    towards_white(PALETTE[5]),
    towards_white(PALETTE[6]),
    towards_white(PALETTE[7]),
];
/// Fill of a cell whose category has no legend entry.
pub const UNKNOWN_FILL: RGBColor = RGBColor(0xDD, 0xDD, 0xDD);

pub const TEXT_COLOR: RGBColor = RGBColor(0x00, 0x00, 0x00);
pub const AXIS_COLOR: RGBColor = RGBColor(0x00, 0x00, 0x00);
pub const GRID_COLOR: RGBColor = RGBColor(0xE3, 0xE3, 0xE3);
pub const REFERENCE_COLOR: RGBColor = RGBColor(0x80, 0x80, 0x80);
pub const MARKER_COLOR: RGBColor = RGBColor(0x60, 0x60, 0x60);
pub const LEGEND_BORDER_COLOR: RGBColor = RGBColor(0x80, 0x80, 0x80);

/// Stroke widths (px). plotters takes whole pixels, so the map's curves get 3 rather than 2.5.
pub const CURVE_WIDTH: u32 = 2;
pub const MAP_CURVE_WIDTH: u32 = 3;
pub const REFERENCE_WIDTH: u32 = 1;
pub const MARKER_WIDTH: u32 = 1;
pub const FRAME_WIDTH: u32 = 1;
/// Dash pattern of the vertical markers (on, off) in px.
pub const MARKER_DASH: [f64; 2] = [5.0, 4.0];

/// Legend geometry (px).
const LEGEND_PAD: i32 = 8;
const LEGEND_SAMPLE: i32 = 40;
const LEGEND_GAP: i32 = 8;
const LEGEND_ROW: i32 = 21;
const LEGEND_SWATCH: i32 = 15;
/// Extra space between the filled squares and the line samples of one legend.
const LEGEND_GROUP_GAP: i32 = 6;
/// Space between legend columns (px), and the most columns a legend takes.
const LEGEND_COLUMN_GAP: i32 = 16;
const MAX_LEGEND_COLUMNS: usize = 3;

const fn towards_white(c: RGBColor) -> RGBColor {
    const fn mix(v: u8) -> u8 {
        // 40 % colour, 60 % white, rounded.
        ((v as u32 * 40 + 255 * 60 + 50) / 100) as u8
    }
    RGBColor(mix(c.0), mix(c.1), mix(c.2))
}

/// Everything that can go wrong while drawing a figure.
#[derive(Debug, thiserror::Error)]
pub enum FigureError {
    /// plotters reported an error while drawing.
    #[error("figure: {0}")]
    Draw(String),
    /// A line chart was asked for without any panel.
    #[error("figure: a line chart needs at least one panel")]
    NoPanels,
    /// An axis range that is empty, reversed or not finite.
    #[error(
        "figure: {axis} range [{}, {}] must be finite with {axis}0 < {axis}1",
        crate::error::short(*lo),
        crate::error::short(*hi)
    )]
    BadRange {
        axis: &'static str,
        lo: f64,
        hi: f64,
    },
}

/// Maps any plotters error into [`FigureError::Draw`].
pub(super) fn draw_err<E: std::fmt::Display>(e: E) -> FigureError {
    FigureError::Draw(e.to_string())
}

/// Curve colour of palette index `i` (wraps around).
pub fn curve_color(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

/// Light fill of palette index `i` (wraps around).
pub fn fill_color(i: usize) -> RGBColor {
    FILLS[i % FILLS.len()]
}

/// Dash pattern (on, off, on, off, …) in px for a stroke of width `width`; empty = solid.
/// Patterns are tuned at width 2 and scale with the width so dots stay round-ish.
pub fn dash_pattern(stroke: Stroke, width: u32) -> Vec<f64> {
    let base: &[f64] = match stroke {
        Stroke::Solid | Stroke::Points => &[],
        Stroke::Dashed => &[10.0, 5.0],
        Stroke::Dotted => &[2.0, 4.0],
        Stroke::DashDot => &[11.0, 4.0, 2.0, 4.0],
    };
    let scale = f64::from(width.max(1)) / 2.0;
    base.iter().map(|v| v * scale).collect()
}

/// A text style whose SVG `font-size` is `px`.
///
/// The SVG backend writes `font-size = size / 1.24` (its em-to-px convention), hence the
/// factor; [`finish_svg`] rounds away the last-bit residue (`13.000000000000002`).
pub fn font(px: f64) -> TextStyle<'static> {
    (FONT_FAMILY, px * 1.24).into_font().color(&TEXT_COLOR)
}

/// Estimated advance width (px) of `text` in DejaVu Sans, the widest of the named fonts.
///
/// plotters' own estimate without `ttf` is 0.45 em per byte, too narrow for DejaVu Sans; the
/// legend frames and label staggering use this instead so the text stays inside its box.
pub fn text_width(text: &str, px: f64) -> f64 {
    let em: f64 = text
        .chars()
        .map(|c| match c {
            'i' | 'j' | 'l' | '.' | ',' | ':' | ';' | '\'' | '!' | '|' | 'I' => 0.30,
            ' ' | 'f' | 't' | 'r' | '(' | ')' | '[' | ']' | '-' | '/' => 0.40,
            'm' | 'w' | 'M' | 'W' => 0.95,
            'A'..='Z' => 0.74,
            _ => 0.64,
        })
        .sum();
    em * px
}

/// Tick label for value `v` on an axis spanning `span`: the fewest decimals that show the value
/// to 1e-6 of the span, a true minus sign, and no "-0".
pub fn tick_label(v: f64, span: f64) -> String {
    let tol = span.abs().max(f64::MIN_POSITIVE) * 1e-6;
    if v.abs() < tol {
        return "0".to_string();
    }
    let decimals = (0..=8)
        .find(|&d| {
            let p = 10f64.powi(d);
            ((v * p).round() / p - v).abs() < tol
        })
        .unwrap_or(8) as usize;
    let s = format!("{v:.decimals$}");
    match s.strip_prefix('-') {
        Some(rest) => format!("\u{2212}{rest}"),
        None => s,
    }
}

/// Splits a pixel polyline into the "on" pieces of a dash pattern that runs continuously
/// along the line. An empty pattern returns the line itself.
pub fn dash_runs(points: &[(i32, i32)], pattern: &[f64]) -> Vec<Vec<(i32, i32)>> {
    if points.len() < 2 {
        return Vec::new();
    }
    if pattern.is_empty()
        || pattern
            .iter()
            .any(|p| p.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater))
    {
        return vec![points.to_vec()];
    }
    let to_px = |(x, y): (f64, f64)| (x.round() as i32, y.round() as i32);
    let mut runs = Vec::new();
    let mut piece = 0usize;
    let mut left = pattern[0];
    let mut current = vec![points[0]];
    for w in points.windows(2) {
        let (a, b) = (
            (f64::from(w[0].0), f64::from(w[0].1)),
            (f64::from(w[1].0), f64::from(w[1].1)),
        );
        let len = (b.0 - a.0).hypot(b.1 - a.1);
        let mut done = 0.0;
        while len - done > left {
            done += left;
            let t = done / len;
            let p = to_px((a.0 + (b.0 - a.0) * t, a.1 + (b.1 - a.1) * t));
            if piece.is_multiple_of(2) {
                push_distinct(&mut current, p);
                if current.len() > 1 {
                    runs.push(std::mem::take(&mut current));
                }
                current.clear();
            } else {
                current = vec![p];
            }
            piece = (piece + 1) % pattern.len();
            left = pattern[piece];
        }
        left -= len - done;
        if piece.is_multiple_of(2) {
            push_distinct(&mut current, w[1]);
        }
    }
    if piece.is_multiple_of(2) && current.len() > 1 {
        runs.push(current);
    }
    runs
}

fn push_distinct(run: &mut Vec<(i32, i32)>, p: (i32, i32)) {
    if run.last() != Some(&p) {
        run.push(p);
    }
}

/// Draws a pixel polyline (backend coordinates) with colour, width and dash pattern.
pub fn draw_stroked(
    root: &DrawingArea<SVGBackend, Shift>,
    points: &[(i32, i32)],
    color: RGBColor,
    width: u32,
    pattern: &[f64],
) -> Result<(), FigureError> {
    let style = ShapeStyle::from(&color).stroke_width(width);
    for run in dash_runs(points, pattern) {
        root.draw(&PathElement::new(run, style)).map_err(draw_err)?;
    }
    Ok(())
}

/// Radius (px) of the circles of a [`Stroke::Points`] curve.
const POINT_RADIUS: i32 = 3;

/// Draws a curve in pixels: joined in its dash pattern, or as open circles for
/// [`Stroke::Points`].
pub fn draw_curve(
    root: &DrawingArea<SVGBackend, Shift>,
    points: &[(i32, i32)],
    color: RGBColor,
    width: u32,
    stroke: Stroke,
) -> Result<(), FigureError> {
    if stroke == Stroke::Points {
        let style = ShapeStyle::from(&color).stroke_width(1);
        for &p in points {
            root.draw(&Circle::new(p, POINT_RADIUS, style))
                .map_err(draw_err)?;
        }
        return Ok(());
    }
    draw_stroked(root, points, color, width, &dash_pattern(stroke, width))
}

/// One legend row: a line sample or a filled square, and its text.
#[derive(Clone, Debug, PartialEq)]
pub struct LegendEntry {
    pub label: String,
    pub key: LegendKey,
}

impl LegendEntry {
    /// Line-sample rows of the labelled `curves`, drawn `width` px wide.
    pub fn lines(curves: &[Curve], width: u32) -> impl Iterator<Item = LegendEntry> + '_ {
        curves
            .iter()
            .filter(|c| !c.label.is_empty())
            .map(move |c| LegendEntry {
                label: c.label.clone(),
                key: LegendKey::Line {
                    color: c.color,
                    stroke: c.stroke,
                    width,
                },
            })
    }
}

/// What a legend row shows left of its text.
#[derive(Clone, Debug, PartialEq)]
pub enum LegendKey {
    Line {
        color: usize,
        stroke: Stroke,
        width: u32,
    },
    Swatch {
        fill: usize,
    },
}

/// Vertical centre of each legend row, from the top of the box, and the box height.
fn legend_rows(entries: &[LegendEntry]) -> (Vec<i32>, i32) {
    let mut y = LEGEND_PAD - 2;
    let mut centres = Vec::with_capacity(entries.len());
    let mut previous: Option<&LegendKey> = None;
    for entry in entries {
        let switches = previous
            .is_some_and(|p| std::mem::discriminant(p) != std::mem::discriminant(&entry.key));
        if switches {
            y += LEGEND_GROUP_GAP;
        }
        centres.push(y + LEGEND_ROW / 2);
        y += LEGEND_ROW;
        previous = Some(&entry.key);
    }
    (centres, y + LEGEND_PAD - 2)
}

/// Width and height (px) of the framed legend box for `entries` in one column.
pub fn legend_size(entries: &[LegendEntry]) -> (i32, i32) {
    legend_size_in(entries, 1)
}

/// Width and height (px) of the framed legend box for `entries` in `columns` columns.
pub fn legend_size_in(entries: &[LegendEntry], columns: usize) -> (i32, i32) {
    let column = legend_column_width(entries);
    let height = legend_chunks(entries, columns)
        .map(|chunk| legend_rows(chunk).1)
        .max()
        .unwrap_or_else(|| legend_rows(&[]).1);
    let n = legend_chunks(entries, columns).count().max(1) as i32;
    (
        2 * LEGEND_PAD + n * column + (n - 1) * LEGEND_COLUMN_GAP,
        height,
    )
}

/// The most columns (at most [`MAX_LEGEND_COLUMNS`]) that keep the legend of `entries` within
/// `max_width` px; 1 if even one column is wider.
pub fn legend_columns(entries: &[LegendEntry], max_width: i32) -> usize {
    (1..=MAX_LEGEND_COLUMNS.min(entries.len()))
        .rev()
        .find(|&c| legend_size_in(entries, c).0 <= max_width)
        .unwrap_or(1)
}

/// Width of one legend column: sample, gap and the widest text.
fn legend_column_width(entries: &[LegendEntry]) -> i32 {
    let text = entries
        .iter()
        .map(|e| text_width(&e.label, LEGEND_FONT_PX).ceil() as i32)
        .max()
        .unwrap_or(0);
    LEGEND_SAMPLE + LEGEND_GAP + text
}

/// The entries of each column, filled column by column.
fn legend_chunks(entries: &[LegendEntry], columns: usize) -> std::slice::Chunks<'_, LegendEntry> {
    entries.chunks(entries.len().div_ceil(columns.max(1)).max(1))
}

/// Draws the framed legend in one column with its upper-left corner at `at` (backend
/// coordinates).
pub fn draw_legend(
    root: &DrawingArea<SVGBackend, Shift>,
    at: (i32, i32),
    entries: &[LegendEntry],
) -> Result<(), FigureError> {
    draw_legend_in(root, at, entries, 1)
}

/// Draws the framed legend in `columns` columns with its upper-left corner at `at`.
pub fn draw_legend_in(
    root: &DrawingArea<SVGBackend, Shift>,
    at: (i32, i32),
    entries: &[LegendEntry],
    columns: usize,
) -> Result<(), FigureError> {
    if entries.is_empty() {
        return Ok(());
    }
    let (w, h) = legend_size_in(entries, columns);
    let (x, y) = at;
    let corners = [(x, y), (x + w, y + h)];
    root.draw(&Rectangle::new(corners, plotters::style::WHITE.filled()))
        .map_err(draw_err)?;
    root.draw(&Rectangle::new(
        corners,
        ShapeStyle::from(&LEGEND_BORDER_COLOR).stroke_width(FRAME_WIDTH),
    ))
    .map_err(draw_err)?;
    let text_style = font(LEGEND_FONT_PX).pos(Pos::new(HPos::Left, VPos::Center));
    let column = legend_column_width(entries) + LEGEND_COLUMN_GAP;
    for (k, chunk) in legend_chunks(entries, columns).enumerate() {
        let x0 = x + LEGEND_PAD + k as i32 * column;
        draw_legend_column(root, (x0, y), chunk, &text_style)?;
    }
    Ok(())
}

/// The rows of one legend column, samples starting at `x0`, the box's top at `y`.
fn draw_legend_column(
    root: &DrawingArea<SVGBackend, Shift>,
    (x0, y): (i32, i32),
    entries: &[LegendEntry],
    text_style: &TextStyle,
) -> Result<(), FigureError> {
    let (centres, _) = legend_rows(entries);
    for (entry, centre) in entries.iter().zip(centres) {
        let cy = y + centre;
        match entry.key {
            LegendKey::Line {
                color,
                stroke,
                width,
            } => {
                let sample = if stroke == Stroke::Points {
                    vec![(x0 + LEGEND_SAMPLE / 2, cy)]
                } else {
                    vec![(x0, cy), (x0 + LEGEND_SAMPLE, cy)]
                };
                draw_curve(root, &sample, curve_color(color), width, stroke)?;
            }
            LegendKey::Swatch { fill } => {
                let sx = x0 + (LEGEND_SAMPLE - LEGEND_SWATCH) / 2;
                let square = [
                    (sx, cy - LEGEND_SWATCH / 2),
                    (sx + LEGEND_SWATCH, cy + LEGEND_SWATCH / 2 + 1),
                ];
                root.draw(&Rectangle::new(square, fill_color(fill).filled()))
                    .map_err(draw_err)?;
                root.draw(&Rectangle::new(square, curve_color(fill)))
                    .map_err(draw_err)?;
            }
        }
        let tx = x0 + LEGEND_SAMPLE + LEGEND_GAP;
        root.draw(&Text::new(
            entry.label.clone(),
            (tx, cy),
            text_style.clone(),
        ))
        .map_err(draw_err)?;
    }
    Ok(())
}

/// Makes the SVG root responsive: keeps `width`/`height`, makes sure a `viewBox` is there and
/// lets CSS scale the figure down to its container (`max-width:100%; height:auto`).
pub fn finish_svg(svg: String) -> String {
    let Some(start) = svg.find("<svg") else {
        return svg;
    };
    let Some(end) = svg[start..].find('>').map(|e| start + e) else {
        return svg;
    };
    let head = &svg[start..end];
    let attr = |name: &str| -> Option<String> {
        let key = format!(" {name}=\"");
        let from = head.find(&key)? + key.len();
        let len = head[from..].find('"')?;
        Some(head[from..from + len].to_string())
    };
    let mut extra = String::new();
    if attr("viewBox").is_none() {
        if let (Some(w), Some(h)) = (attr("width"), attr("height")) {
            extra.push_str(&format!(" viewBox=\"0 0 {w} {h}\""));
        }
    }
    if attr("preserveAspectRatio").is_none() {
        extra.push_str(" preserveAspectRatio=\"xMidYMid meet\"");
    }
    if attr("style").is_none() {
        extra.push_str(" style=\"max-width:100%;height:auto\"");
    }
    if attr("role").is_none() {
        extra.push_str(" role=\"img\"");
    }
    let insert_at = if head.ends_with('/') { end - 1 } else { end };
    let mut out = String::with_capacity(svg.len() + extra.len());
    out.push_str(&svg[..insert_at]);
    out.push_str(&extra);
    push_rounded_font_sizes(&mut out, &svg[insert_at..]);
    out
}

/// `svg` with a text alternative: `<title>` (its accessible name) and `<desc>` (what it shows,
/// with its key numbers) as the first children of the root element, XML-escaped. An SVG that
/// has a `<title>` already is returned as it is.
pub fn with_text(svg: &str, title: &str, desc: &str) -> String {
    let Some(open) = svg.find("<svg") else {
        return svg.to_string();
    };
    let Some(end) = svg[open..].find('>').map(|e| open + e + 1) else {
        return svg.to_string();
    };
    if svg[end..].trim_start().starts_with("<title") {
        return svg.to_string();
    }
    let escape = |t: &str| {
        t.replace('&', "&amp;")
            .replace('<', "&lt;")
            .replace('>', "&gt;")
    };
    format!(
        "{}\n<title>{}</title>\n<desc>{}</desc>{}",
        &svg[..end],
        escape(title),
        escape(desc),
        &svg[end..]
    )
}

/// Copies `svg`, writing every `font-size="…"` value with at most two decimals.
fn push_rounded_font_sizes(out: &mut String, svg: &str) {
    const KEY: &str = "font-size=\"";
    let mut rest = svg;
    while let Some(i) = rest.find(KEY) {
        let from = i + KEY.len();
        out.push_str(&rest[..from]);
        rest = &rest[from..];
        let len = rest.find('"').unwrap_or(0);
        match rest[..len].parse::<f64>() {
            Ok(v) => {
                let r = (v * 100.0).round() / 100.0;
                out.push_str(&format!("{r}"));
            }
            Err(_) => out.push_str(&rest[..len]),
        }
        rest = &rest[len..];
    }
    out.push_str(rest);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn font_sizes_are_written_as_given() {
        let svg = "<svg width=\"1\" height=\"1\">\n<text font-size=\"13.000000000000002\">a</text>\n<text font-size=\"14\">b</text>\n</svg>";
        let out = finish_svg(svg.to_string());
        assert!(out.contains("font-size=\"13\">a"));
        assert!(out.contains("font-size=\"14\">b"));
        assert!((font(13.0).font.get_size() / 1.24 - 13.0).abs() < 1e-12);
    }

    #[test]
    fn tick_labels_are_short_and_use_a_true_minus() {
        assert_eq!(tick_label(0.30000000000000004, 1.0), "0.3");
        assert_eq!(tick_label(-2.5, 10.0), "\u{2212}2.5");
        assert_eq!(tick_label(1e-17, 1.0), "0");
        assert_eq!(tick_label(200.0, 1000.0), "200");
    }

    #[test]
    fn dash_runs_follow_the_pattern_along_the_line() {
        let runs = dash_runs(&[(0, 0), (100, 0)], &[10.0, 5.0]);
        // 100 px of a 15 px period: 7 dashes, the last one cut at the end.
        assert_eq!(runs.len(), 7);
        assert_eq!(runs[0], vec![(0, 0), (10, 0)]);
        assert_eq!(runs[1], vec![(15, 0), (25, 0)]);
        // The pattern continues across vertices.
        let bent = dash_runs(&[(0, 0), (6, 0), (6, 20)], &[10.0, 5.0]);
        assert_eq!(bent[0], vec![(0, 0), (6, 0), (6, 4)]);
        assert_eq!(bent[1], vec![(6, 9), (6, 19)]);
        assert_eq!(dash_runs(&[(0, 0), (3, 4)], &[]).len(), 1);
        assert!(dash_runs(&[(0, 0)], &[1.0, 1.0]).is_empty());
    }

    #[test]
    fn fills_are_lighter_than_the_palette() {
        for (c, f) in PALETTE.iter().zip(FILLS.iter()) {
            assert!(f.0 >= c.0 && f.1 >= c.1 && f.2 >= c.2);
        }
        assert_eq!(FILLS[7], RGBColor(153, 153, 153));
    }

    #[test]
    fn a_figure_gets_a_title_and_a_description_once() {
        let svg = "<svg width=\"10\" height=\"5\">\n<rect/>\n</svg>";
        let out = with_text(svg, "v(t) & x(t)", "speed <1 m/s>");
        assert!(out.starts_with(
            "<svg width=\"10\" height=\"5\">\n<title>v(t) &amp; x(t)</title>\n<desc>speed &lt;1 m/s&gt;</desc>\n<rect/>"
        ));
        assert_eq!(with_text(&out, "again", "again"), out);
    }

    #[test]
    fn finish_svg_adds_responsive_attributes_once() {
        let svg = "<svg width=\"10\" height=\"5\" xmlns=\"http://www.w3.org/2000/svg\">\n</svg>";
        let out = finish_svg(svg.to_string());
        assert!(out.contains("viewBox=\"0 0 10 5\""));
        assert!(out.contains("width=\"10\""));
        assert!(out.contains("max-width:100%"));
        assert_eq!(finish_svg(out.clone()), out);
    }
}
