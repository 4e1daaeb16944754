//! Page 2 of the handout: which figures (the scene's own, then the motion, the forces and a
//! third figure of its model), how they share two columns, how tall they are drawn, and how
//! many claims fit below the verification table, so that the page prints on one A4 sheet and
//! fills it.
//!
//! Figures are drawn on the column canvas ([`Geometry::COLUMN`]: legends and labels print at
//! 8.2 pt), then taller while the page keeps its figures and claims ([`fill`]). Heights are
//! estimated in mm from the figure sizes and the text lengths, with constants measured on
//! Chromium's print of `templates/handout.css` (A4, 5 mm margins, DejaVu fonts); the browser
//! test prints every built-in scene and checks that it takes exactly two pages and that page 2
//! is filled.

use serde::Serialize;

use crate::error::Result;

use crate::models::with_capability;
use crate::present::Present;
use crate::report::context::{ClaimCtx, FigureCtx};
use crate::report::figures::style::Geometry;
use crate::report::scene::FigureKind;
use crate::report::Scene;

/// At most this many figures: two side by side, and each further one below the shorter column.
const MAX_FIGURES: usize = 4;
/// Printed height of page 2's content: A4 less the margins, less room for font differences.
const PAGE_MM: f64 = 297.0 - 2.0 * 5.0 - 12.0;
/// A figure column is 90.5 mm wide; an SVG fills it whatever its canvas's width.
const COLUMN_MM: f64 = 90.5;
/// A caption line (8 pt over a column) and its characters; the figure's margins.
const CAPTION_LINE_MM: f64 = 3.4;
const CAPTION_LINE_CHARS: usize = 60;
const FIGURE_MARGIN_MM: f64 = 3.5;
/// The verification table: heading and summary, then each row (the header row too).
const TABLE_MM: f64 = 18.5;
const TABLE_ROW_MM: f64 = 4.4;
/// The claims: heading and footer, then per claim its lines (8 pt over the page) and margin.
const CLAIMS_MM: f64 = 10.5;
const CLAIM_LINE_MM: f64 = 3.45;
const CLAIM_LINE_CHARS: usize = 125;
const CLAIM_MARGIN_MM: f64 = 1.0;
/// The line naming the claims that do not fit.
const BRIEF_MM: f64 = 8.0;
/// The figures grow by this share of the column canvas's panel and map heights at a time, at
/// most this many times.
const STRETCH_STEP: f64 = 0.1;
const MAX_STRETCH_STEPS: u32 = 15;

/// A figure of the handout with its number.
#[derive(Clone, Debug, Serialize)]
pub struct Numbered {
    pub number: usize,
    #[serde(flatten)]
    pub figure: FigureCtx,
}

/// What page 2 shows besides the verification table.
#[derive(Clone, Debug)]
pub struct PageTwo {
    /// The figures in two columns.
    pub columns: [Vec<Numbered>; 2],
    /// The claims shown in full.
    pub claims: Vec<ClaimCtx>,
    /// The claims that did not fit (named in one line).
    pub brief: Vec<ClaimCtx>,
    /// Estimated room left at the foot of the page (mm; negative: the page overflows).
    pub room_mm: f64,
}

/// The candidate figure kinds: the scene's own, then the motion and the forces of its model
/// (the figures the chain of formulas refers to) and a third one (harmonic against linear for
/// the pulled mass, the spring coordinate's counterparts for the woodpecker), each unless the
/// scene has that kind already.
pub fn kinds(scene: &Scene) -> Vec<FigureKind> {
    // A model without a presentation has no standard figures (its scenes are refused on
    // loading).
    let standard =
        with_capability!(&scene.setup, present, p => p.standard_scene().figures, else Vec::new());
    let mut kinds = scene.figures.clone();
    for kind in standard {
        if !kinds.iter().any(|k| k.name == kind.name) {
            kinds.push(kind);
        }
    }
    kinds
}

/// Lays out page 2 with the figures `draw` draws on the column canvas, then on ever taller
/// canvases (steps of [`STRETCH_STEP`]) as long as the page keeps its figures and claims and
/// still fits: the figures take the room the text leaves.
pub fn fill(
    draw: impl Fn(Geometry) -> Result<Vec<FigureCtx>>,
    rows: usize,
    claims: Vec<ClaimCtx>,
) -> Result<PageTwo> {
    let mut best = page_two(draw(Geometry::COLUMN)?, rows, claims.clone());
    for step in 1..=MAX_STRETCH_STEPS {
        let g = Geometry::COLUMN.taller(1.0 + STRETCH_STEP * f64::from(step));
        let page = page_two(draw(g)?, rows, claims.clone());
        let figures = |p: &PageTwo| p.columns[0].len() + p.columns[1].len();
        if page.room_mm < 0.0
            || figures(&page) < figures(&best)
            || page.claims.len() < best.claims.len()
        {
            break;
        }
        best = page;
    }
    Ok(best)
}

/// Lays out page 2: the figures, each further one only where it leaves room for every claim
/// below a table of `rows` rows, then as many claims in full as the page holds.
pub fn page_two(candidates: Vec<FigureCtx>, rows: usize, mut claims: Vec<ClaimCtx>) -> PageTwo {
    let needs: Vec<f64> = claims.iter().map(claim_mm).collect();
    let table = TABLE_MM + TABLE_ROW_MM * (rows + 1) as f64 + CLAIMS_MM;
    let all_claims: f64 = needs.iter().sum();
    let (columns, heights) = place(candidates, |figures| {
        PAGE_MM - figures - table >= all_claims
    });
    let room = PAGE_MM - heights[0].max(heights[1]) - table;
    // The most leading claims that fit in full, and a line naming the others if any.
    let fits = |k: usize| {
        let brief = if k < needs.len() { BRIEF_MM } else { 0.0 };
        needs[..k].iter().sum::<f64>() + brief <= room
    };
    let shown = (0..=needs.len()).rev().find(|&k| fits(k)).unwrap_or(0);
    let brief_mm = if shown < needs.len() { BRIEF_MM } else { 0.0 };
    let room_mm = room - needs[..shown].iter().sum::<f64>() - brief_mm;
    let brief = claims.split_off(shown);
    PageTwo {
        columns,
        claims,
        brief,
        room_mm,
    }
}

/// Places `candidates` in order: the first two side by side, then up to [`MAX_FIGURES`] in
/// all, each under the shorter column when `fits(height of the taller column, mm)`; one that
/// does not fit is skipped for the next. Returns the columns (figures numbered in the order
/// placed) and their heights (mm).
fn place(candidates: Vec<FigureCtx>, fits: impl Fn(f64) -> bool) -> ([Vec<Numbered>; 2], [f64; 2]) {
    let mut columns: [Vec<Numbered>; 2] = [Vec::new(), Vec::new()];
    let mut heights = [0.0_f64; 2];
    let mut placed = 0;
    for figure in candidates {
        if placed == MAX_FIGURES {
            break;
        }
        let height = figure_mm(&figure);
        let column = if placed < 2 {
            placed
        } else {
            let shorter = usize::from(heights[1] < heights[0]);
            if !fits((heights[shorter] + height).max(heights[1 - shorter])) {
                continue;
            }
            shorter
        };
        placed += 1;
        heights[column] += height;
        columns[column].push(Numbered {
            number: placed,
            figure,
        });
    }
    (columns, heights)
}

/// Printed lines of `chars` characters at `per_line` a line.
fn lines(chars: usize, per_line: usize) -> f64 {
    chars.div_ceil(per_line).max(1) as f64
}

fn figure_mm(f: &FigureCtx) -> f64 {
    svg_size(&f.svg, " height=\"") * COLUMN_MM / svg_size(&f.svg, " width=\"").max(1.0)
        + CAPTION_LINE_MM * lines(f.caption.chars().count() + 12, CAPTION_LINE_CHARS)
        + FIGURE_MARGIN_MM
}

fn claim_mm(c: &ClaimCtx) -> f64 {
    let heading = c.title.chars().count() + c.verdict.chars().count() + 12;
    let paper = c.paper_says.chars().count() + 11;
    let text = lines(heading, CLAIM_LINE_CHARS)
        + lines(paper, CLAIM_LINE_CHARS)
        + lines(c.finding.chars().count(), CLAIM_LINE_CHARS);
    CLAIM_LINE_MM * text + CLAIM_MARGIN_MM
}

/// The `height` (or `width`) attribute of an SVG root, `attribute` being ` height="` (0 when
/// missing).
fn svg_size(svg: &str, attribute: &str) -> f64 {
    let root = &svg[..svg.find('>').unwrap_or(0)];
    root.split_once(attribute)
        .and_then(|(_, rest)| rest.split('"').next())
        .and_then(|h| h.parse().ok())
        .unwrap_or(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn figure(id: &str, height: u32) -> FigureCtx {
        FigureCtx {
            id: id.to_string(),
            caption: "A caption of one line.".to_string(),
            svg: format!("<svg width=\"440\" height=\"{height}\" viewBox=\"0 0 440 {height}\">"),
            file: String::new(),
        }
    }

    fn claim(id: u8, finding_chars: usize) -> ClaimCtx {
        ClaimCtx {
            id,
            title: "A claim".to_string(),
            paper_says: "The paper says so.".to_string(),
            verdict: "refuted".to_string(),
            verdict_class: "refuted".to_string(),
            does_not_apply: String::new(),
            finding: "x".repeat(finding_chars),
            numbers: Vec::new(),
        }
    }

    fn ids(page: &PageTwo) -> [Vec<(usize, &str)>; 2] {
        page.columns.each_ref().map(|column| {
            column
                .iter()
                .map(|n| (n.number, n.figure.id.as_str()))
                .collect()
        })
    }

    #[test]
    fn further_figures_go_under_the_shorter_column_when_the_claims_still_fit() {
        let candidates = vec![
            figure("motion", 500),
            figure("forces", 250),
            figure("map", 600),
            figure("compare", 300),
        ];
        let page = page_two(candidates, 11, vec![claim(1, 300)]);
        // The map would leave no room for the claim under the forces: skipped for the next.
        assert_eq!(ids(&page)[0], [(1, "motion")]);
        assert_eq!(ids(&page)[1], [(2, "forces"), (3, "compare")]);
        assert!(page.brief.is_empty() && page.room_mm >= 0.0);
        let page = page_two(
            vec![figure("a", 900), figure("b", 900), figure("c", 300)],
            18,
            Vec::new(),
        );
        assert_eq!((page.columns[0].len(), page.columns[1].len()), (1, 1));
        assert_eq!(svg_size(&figure("x", 624).svg, " height=\""), 624.0);
    }

    #[test]
    fn claims_that_do_not_fit_are_named_in_one_line_each_and_a_third_figure_yields_first() {
        let candidates = vec![figure("a", 624), figure("b", 344), figure("c", 200)];
        let both = vec![claim(3, 700), claim(8, 500)];
        let page = page_two(candidates.clone(), 8, both);
        assert_eq!(
            page.columns[1].len(),
            2,
            "room for both claims and three figures"
        );
        assert!(page.brief.is_empty());
        let many: Vec<ClaimCtx> = (3..=8).map(|id| claim(id, 600)).collect();
        let page = page_two(candidates, 8, many);
        assert_eq!(
            page.columns[1].len(),
            1,
            "the third figure gives way to the claims"
        );
        assert!(!page.claims.is_empty() && !page.brief.is_empty());
        assert_eq!(page.claims.len() + page.brief.len(), 6);
        assert_eq!(usize::from(page.brief[0].id), page.claims.len() + 3);
    }

    /// Two figures whose height follows the canvas's panel height, as charts do.
    fn draw(g: Geometry) -> Result<Vec<FigureCtx>> {
        Ok(vec![
            figure("two panels", 2 * g.panel_height + 60),
            figure("one panel", g.panel_height + 60),
        ])
    }

    #[test]
    fn the_figures_grow_into_the_room_the_page_leaves_and_no_further() {
        let column = page_two(draw(Geometry::COLUMN).unwrap(), 8, Vec::new());
        let filled = fill(draw, 8, Vec::new()).unwrap();
        assert!(filled.room_mm >= 0.0 && filled.room_mm < column.room_mm);
        let height = |p: &PageTwo| svg_size(&p.columns[0][0].figure.svg, " height=\"");
        assert!(height(&filled) > height(&column));
        // A page with no room left keeps the column canvas.
        let full = fill(draw, 40, Vec::new()).unwrap();
        let first = &full.columns[0][0].figure.svg;
        assert!(first.contains(&format!(
            "height=\"{}\"",
            2 * Geometry::COLUMN.panel_height + 60
        )));
    }
}
