//! What a figure shows, as plain data: the physics side fills these, the renderers in
//! [`crate::report::figures::chart`] and [`crate::report::figures::map`] draw them. No physics
//! here.

/// How a curve is stroked, so that curves stay distinguishable in black-and-white print.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stroke {
    Solid,
    Dashed,
    Dotted,
    DashDot,
    /// Each point as a small open circle, not joined: measured data.
    Points,
    /// The points as one filled outline (a marker such as the scene's diamond on a map); its
    /// legend row shows the same shape.
    Marker,
}

/// One curve: (x, y) points in plot units, a legend label, a palette index and a stroke.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    pub label: String,
    pub points: Vec<(f64, f64)>,
    /// Index into the palette (0 = first colour).
    pub color: usize,
    pub stroke: Stroke,
}

impl Curve {
    /// A small closed diamond at `at` (sized from the axis ranges) that marks a scene's own
    /// point on a map; `None` when the point lies outside the ranges.
    pub fn point_marker(
        label: &str,
        at: (f64, f64),
        x: (f64, f64),
        y: (f64, f64),
        color: usize,
    ) -> Option<Curve> {
        let inside = |v: f64, (lo, hi): (f64, f64)| (lo..=hi).contains(&v);
        if !(inside(at.0, x) && inside(at.1, y)) {
            return None;
        }
        let (cx, cy) = at;
        let (dx, dy) = (0.012 * (x.1 - x.0), 0.012 * (y.1 - y.0));
        Some(Curve {
            label: label.to_string(),
            points: vec![
                (cx - dx, cy),
                (cx, cy + dy),
                (cx + dx, cy),
                (cx, cy - dy),
                (cx - dx, cy),
            ],
            color,
            stroke: Stroke::Marker,
        })
    }
}

/// A vertical marker (a characteristic time) with a short label such as "t_SL".
#[derive(Clone, Debug, PartialEq)]
pub struct Marker {
    pub x: f64,
    pub label: String,
}

/// One panel of a stacked chart: its curves share the x axis of the chart.
#[derive(Clone, Debug, PartialEq)]
pub struct Panel {
    /// y-axis label with unit, e.g. "v (mm/s)".
    pub y_label: String,
    pub curves: Vec<Curve>,
    /// Horizontal reference lines (y value, label); drawn thin and grey.
    pub h_lines: Vec<(f64, String)>,
}

/// A chart of one or more panels stacked vertically over a common x axis.
#[derive(Clone, Debug, PartialEq)]
pub struct LineChart {
    /// x-axis label with unit, e.g. "t (s)".
    pub x_label: String,
    /// x range; `None` = from the data.
    pub x_range: Option<(f64, f64)>,
    pub panels: Vec<Panel>,
    /// Vertical markers drawn through every panel, labelled in the top one; a marker without a
    /// label is a light vertical grid line.
    pub markers: Vec<Marker>,
}

/// A category map: a grid of cells coloured by category, with analytic curves on top.
#[derive(Clone, Debug, PartialEq)]
pub struct CategoryMap {
    pub x_label: String,
    pub y_label: String,
    /// Cell-centre ranges: column i is at x0 + (i + ½)(x1 − x0)/nx, likewise for rows.
    pub x_range: (f64, f64),
    pub y_range: (f64, f64),
    /// `cells[row][col]`, row 0 at the bottom (smallest y); values index `categories`.
    pub cells: Vec<Vec<u8>>,
    /// Legend entries of the categories: (label, palette index of the fill).
    pub categories: Vec<(String, usize)>,
    /// Boundaries drawn over the cells.
    pub curves: Vec<Curve>,
}
