//! Category maps: a grid of cells filled by category (light palette fills), analytic boundary
//! curves on top, and a legend listing the categories and the curves: right of the plot, or
//! below it where a narrow canvas leaves no room beside it.
//!
//! A row's horizontal runs of one category become one rectangle, so a 200 × 200 map with a few
//! regions costs a few thousand elements rather than 40 000.

use plotters::element::Rectangle;
use plotters::prelude::{ChartBuilder, IntoDrawingArea, SVGBackend};
use plotters::style::{Color, ShapeStyle, WHITE};

use super::chart::{checked_range, clipped_runs, thin, to_pixels, Bounds, MAX_POINTS};
use super::spec::CategoryMap;
pub use super::style::FigureError;
use super::style::{
    curve_color, draw_curve, draw_err, draw_legend_in, fill_color, finish_svg, font,
    legend_columns, legend_size, legend_size_in, tick_label, Geometry, LegendEntry, LegendKey,
    AXIS_COLOR, FRAME_WIDTH, LABEL_FONT_PX, MAP_CURVE_WIDTH, RIGHT_MARGIN, TICK_FONT_PX,
    UNKNOWN_FILL, X_LABEL_AREA, Y_LABEL_AREA,
};

/// Space above the plotting area (px).
const MAP_TOP: u32 = 14;
/// Gap between the plot frame and the legend (px).
const LEGEND_GAP: u32 = 20;
/// A legend wider than this share of the figure goes below the plot.
const MAX_LEGEND_SHARE: f64 = 0.4;

/// Renders `spec` as an SVG document on the report's canvas ([`Geometry::REPORT`]).
pub fn category_map(spec: &CategoryMap) -> Result<String, FigureError> {
    category_map_in(spec, Geometry::REPORT)
}

/// Renders `spec` as an SVG document on the canvas `g`.
///
/// Errors: an empty or non-finite axis range, or a plotters failure. Ragged rows are drawn as
/// far as they go; a cell value without a category gets a neutral grey.
pub fn category_map_in(spec: &CategoryMap, g: Geometry) -> Result<String, FigureError> {
    let x = checked_range("x", spec.x_range)?;
    let y = checked_range("y", spec.y_range)?;
    let entries = legend_entries(spec);
    let beside = legend_size(&entries).0.max(0) as u32 + LEGEND_GAP + 8;
    let below = !entries.is_empty() && f64::from(beside) > f64::from(g.width) * MAX_LEGEND_SHARE;
    let columns = if below {
        legend_columns(&entries, g.plot_width() as i32)
    } else {
        1
    };
    let legend_h = legend_size_in(&entries, columns).1.max(0) as u32;
    let (legend_col, plot_h, legend_band) = if entries.is_empty() {
        (RIGHT_MARGIN, g.map_plot_height, 0)
    } else if below {
        (RIGHT_MARGIN, g.map_plot_height, legend_h + LEGEND_GAP / 2)
    } else {
        (beside, g.map_plot_height.max(legend_h), 0)
    };
    let height = MAP_TOP + plot_h + X_LABEL_AREA + legend_band;

    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (g.width, height)).into_drawing_area();
        let plot = root.clone().shrink((0, 0), (g.width, height - legend_band));
        root.fill(&WHITE).map_err(draw_err)?;
        let mut chart = ChartBuilder::on(&plot)
            .margin_top(MAP_TOP)
            .margin_right(legend_col)
            .x_label_area_size(X_LABEL_AREA)
            .y_label_area_size(Y_LABEL_AREA)
            .build_cartesian_2d(x.0..x.1, y.0..y.1)
            .map_err(draw_err)?;
        let x_fmt = |v: &f64| tick_label(*v, x.1 - x.0);
        let y_fmt = |v: &f64| tick_label(*v, y.1 - y.0);
        chart
            .configure_mesh()
            .disable_mesh()
            .x_labels(g.x_labels)
            .y_labels(8)
            .x_label_formatter(&x_fmt)
            .y_label_formatter(&y_fmt)
            .label_style(font(TICK_FONT_PX))
            .axis_desc_style(font(LABEL_FONT_PX))
            .axis_style(ShapeStyle::from(&AXIS_COLOR).stroke_width(FRAME_WIDTH))
            .x_desc(spec.x_label.clone())
            .y_desc(spec.y_label.clone())
            .draw()
            .map_err(draw_err)?;

        let ny = spec.cells.len();
        let nx = spec.cells.iter().map(Vec::len).max().unwrap_or(0);
        // Shared edges are computed by one formula, so neighbouring rectangles meet exactly.
        let x_edge = |i: usize| x.0 + (x.1 - x.0) * i as f64 / nx as f64;
        let y_edge = |j: usize| y.0 + (y.1 - y.0) * j as f64 / ny as f64;
        let area = chart.plotting_area();
        for (j, row) in spec.cells.iter().enumerate() {
            for (start, end, value) in runs(row) {
                let fill = spec
                    .categories
                    .get(usize::from(value))
                    .map_or(UNKNOWN_FILL, |c| fill_color(c.1));
                let corners = [(x_edge(start), y_edge(j + 1)), (x_edge(end), y_edge(j))];
                area.draw(&Rectangle::new(corners, fill.filled()))
                    .map_err(draw_err)?;
            }
        }

        let clip = Bounds {
            lo: (x.0, y.0),
            hi: (x.1, y.1),
        };
        let to_px = |p: &(f64, f64)| chart.backend_coord(p);
        for curve in &spec.curves {
            for run in thin(clipped_runs(&curve.points, clip), MAX_POINTS) {
                let px = to_pixels(&run, to_px);
                draw_curve(
                    &root,
                    &px,
                    curve_color(curve.color),
                    MAP_CURVE_WIDTH,
                    curve.stroke,
                )?;
            }
        }

        // plotters draws the left and bottom axis one pixel outside the data corners.
        let (tl, br) = (to_px(&(x.0, y.1)), to_px(&(x.1, y.0)));
        let frame = [(tl.0 - 1, tl.1), (br.0, br.1 + 1)];
        let border = ShapeStyle::from(&AXIS_COLOR).stroke_width(FRAME_WIDTH);
        root.draw(&Rectangle::new(frame, border))
            .map_err(draw_err)?;
        let at = if below {
            (frame[0].0, (height - legend_h) as i32)
        } else {
            (frame[1].0 + LEGEND_GAP as i32, frame[0].1)
        };
        draw_legend_in(&root, at, &entries, columns)?;
        root.present().map_err(draw_err)?;
    }
    // Crisp edges: anti-aliased neighbouring cells would show hairline seams between them.
    Ok(finish_svg(svg.replace(
        "<rect ",
        "<rect shape-rendering=\"crispEdges\" ",
    )))
}

/// Maximal runs of equal values in a row: (first column, one past the last, value).
fn runs(row: &[u8]) -> Vec<(usize, usize, u8)> {
    let mut out: Vec<(usize, usize, u8)> = Vec::new();
    for (i, &v) in row.iter().enumerate() {
        match out.last_mut() {
            Some(last) if last.2 == v => last.1 = i + 1,
            _ => out.push((i, i + 1, v)),
        }
    }
    out
}

/// Categories first (filled squares), then the labelled curves (line samples).
fn legend_entries(spec: &CategoryMap) -> Vec<LegendEntry> {
    let categories = spec.categories.iter().map(|(label, fill)| LegendEntry {
        label: label.clone(),
        key: LegendKey::Swatch { fill: *fill },
    });
    let curves = LegendEntry::lines(&spec.curves, MAP_CURVE_WIDTH);
    categories.chain(curves).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::figures::spec::{Curve, Stroke};
    use std::time::Instant;

    /// A stick/slip-like phase diagram: regions bounded by two analytic curves.
    pub(crate) fn sample_map(n: usize) -> CategoryMap {
        let (x0, x1, y0, y1) = (0.0, 2.0, 0.0, 1.0);
        let upper = |x: f64| 0.3 + 0.25 * x + 0.1 * (3.0 * x).sin();
        let lower = |x: f64| 0.15 + 0.1 * x * x;
        let cells = (0..n)
            .map(|j| {
                let y = y0 + (y1 - y0) * (j as f64 + 0.5) / n as f64;
                (0..n)
                    .map(|i| {
                        let x = x0 + (x1 - x0) * (i as f64 + 0.5) / n as f64;
                        if y > upper(x) {
                            0
                        } else if y > lower(x) {
                            1
                        } else if x < 1.2 {
                            2
                        } else {
                            3
                        }
                    })
                    .collect()
            })
            .collect();
        let line = |label: &str, color, stroke, f: &dyn Fn(f64) -> f64| Curve {
            label: label.to_string(),
            points: (0..=300)
                .map(|i| {
                    let x = 2.2 * f64::from(i) / 300.0 - 0.1;
                    (x, f(x))
                })
                .collect(),
            color,
            stroke,
        };
        CategoryMap {
            x_label: "F/W".to_string(),
            y_label: "ω T".to_string(),
            x_range: (x0, x1),
            y_range: (y0, y1),
            cells,
            categories: vec![
                ("always sticks".to_string(), 0),
                ("stick-slip".to_string(), 1),
                ("pure slip".to_string(), 2),
                ("reversal".to_string(), 4),
            ],
            curves: vec![
                line("upper bound (eq. 12)", 7, Stroke::Solid, &upper),
                line("lower bound (eq. 14)", 3, Stroke::Dashed, &lower),
            ],
        }
    }

    #[test]
    fn large_map_is_small_fast_and_lists_every_category() {
        let spec = sample_map(200);
        let start = Instant::now();
        let svg = category_map(&spec).expect("renders");
        let elapsed = start.elapsed();
        assert!(svg.len() < 1_500_000, "{} bytes", svg.len());
        for (label, _) in &spec.categories {
            assert!(svg.contains(label.as_str()), "missing {label}");
        }
        for c in &spec.curves {
            assert!(svg.contains(c.label.as_str()), "missing {}", c.label);
        }
        assert!(svg.contains("F/W") && svg.contains("ω T"));
        assert!(svg.contains("viewBox=\"0 0 900 "));
        assert!(!svg.contains("<rect x") && svg.contains("<rect shape-rendering=\"crispEdges\""));
        assert_eq!(svg, category_map(&spec).expect("renders again"));
        eprintln!("200x200 map: {} bytes in {:?}", svg.len(), elapsed);
    }

    #[test]
    fn rows_are_merged_into_runs() {
        assert_eq!(runs(&[1, 1, 2, 2, 2, 1]), [(0, 2, 1), (2, 5, 2), (5, 6, 1)]);
        assert!(runs(&[]).is_empty());
    }

    #[test]
    fn odd_input_is_drawn_or_refused_cleanly() {
        let mut spec = sample_map(20);
        spec.cells[3].truncate(5);
        spec.cells[4][0] = 200;
        spec.curves[0].points[7] = (f64::NAN, 0.2);
        spec.curves[1].points.clear();
        assert!(category_map(&spec).is_ok());
        spec.cells.clear();
        spec.categories.clear();
        spec.curves.clear();
        assert!(category_map(&spec).is_ok());
        spec.y_range = (1.0, f64::NAN);
        assert!(matches!(
            category_map(&spec),
            Err(FigureError::BadRange { axis: "y", .. })
        ));
    }

    #[test]
    fn example_svgs_are_written_to_tmp() {
        let svg = category_map(&sample_map(200)).expect("renders");
        std::fs::write("/tmp/map.svg", svg).expect("writes /tmp/map.svg");
    }
}
