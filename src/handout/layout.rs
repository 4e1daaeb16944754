//! Page 2 of the handout: which figures (the scene's own, then the motion, the forces and a
//! third figure of its model), how they share two columns, and how many claims fit below the
//! verification table, so that the page prints on one A4 sheet.
//!
//! Heights are estimated in mm from the figure sizes and the text lengths, with constants
//! measured on Chromium's print of `templates/handout.css` (A4, 9 mm margins, DejaVu fonts);
//! the browser test prints every built-in scene and checks that it takes exactly two pages.

use serde::Serialize;

use crate::models::with_model;
use crate::present::Present;
use crate::report::context::{ClaimCtx, FigureCtx};
use crate::report::scene::FigureKind;
use crate::report::Scene;

/// At most this many figures: the two columns, and one below the shorter.
const MAX_FIGURES: usize = 3;
/// Printed height of page 2's content: A4 less the margins, less room for font differences.
const PAGE_MM: f64 = 297.0 - 2.0 * 9.0 - 12.0;
/// A figure column is 90.5 mm wide and the SVGs 900 px.
const MM_PER_PX: f64 = 90.5 / 900.0;
/// A caption line (6.5 pt over a column) and its characters; the figure's margins.
const CAPTION_LINE_MM: f64 = 2.8;
const CAPTION_LINE_CHARS: usize = 75;
const FIGURE_MARGIN_MM: f64 = 3.5;
/// A third figure may make its column this much taller than the other one.
const SLACK_MM: f64 = 40.0;
/// The verification table: heading and summary, then each row (the header row too).
const TABLE_MM: f64 = 17.1;
const TABLE_ROW_MM: f64 = 3.93;
/// The claims: heading and footer, then per claim its lines (7.5 pt over the page) and margin.
const CLAIMS_MM: f64 = 10.0;
const CLAIM_LINE_MM: f64 = 3.25;
const CLAIM_LINE_CHARS: usize = 135;
const CLAIM_MARGIN_MM: f64 = 1.0;
/// The line naming the claims that do not fit.
const BRIEF_MM: f64 = 8.0;

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
    /// The claims that did not fit, one line each: "Claim 7: title — verdict".
    pub brief: Vec<String>,
}

/// The candidate figure kinds: the scene's own, then the motion and the forces of its model
/// (the figures the chain of formulas refers to) and a third one (harmonic against linear for
/// the pulled mass, the spring coordinate's counterparts for the woodpecker), each unless the
/// scene has that kind already.
pub fn kinds(scene: &Scene) -> Vec<FigureKind> {
    let standard = with_model!(&scene.setup, p => p.standard_scene().figures);
    let mut kinds = scene.figures.clone();
    for kind in standard {
        let same = std::mem::discriminant(&kind);
        if !kinds.iter().any(|k| std::mem::discriminant(k) == same) {
            kinds.push(kind);
        }
    }
    kinds
}

/// Lays out page 2: the figures (a third one only where it fits and leaves room for every
/// claim), then as many claims in full as the page holds below a table of `rows` rows.
pub fn page_two(candidates: Vec<FigureCtx>, rows: usize, mut claims: Vec<ClaimCtx>) -> PageTwo {
    let needs: Vec<f64> = claims.iter().map(claim_mm).collect();
    let room = |[left, right]: [f64; 2]| {
        PAGE_MM - left.max(right) - TABLE_MM - TABLE_ROW_MM * (rows + 1) as f64 - CLAIMS_MM
    };
    let (mut columns, mut heights) = place(candidates.clone(), MAX_FIGURES);
    if columns[0].len() + columns[1].len() > 2 && room(heights) < needs.iter().sum() {
        (columns, heights) = place(candidates, 2);
    }
    // The most leading claims that fit in full, and a line naming the others if any.
    let fits = |k: usize| {
        let brief = if k < needs.len() { BRIEF_MM } else { 0.0 };
        needs[..k].iter().sum::<f64>() + brief <= room(heights)
    };
    let shown = (0..=needs.len()).rev().find(|&k| fits(k)).unwrap_or(0);
    let brief = claims
        .split_off(shown)
        .iter()
        .map(|c| format!("Claim {}: {} — {}", c.id, c.title, c.verdict))
        .collect();
    PageTwo {
        columns,
        claims,
        brief,
    }
}

/// Places `candidates` in order: the first two side by side, then at most `limit − 2` more,
/// each under the shorter column if that column stays within [`SLACK_MM`] of the other.
/// Returns the columns (figures numbered in the order placed) and their heights (mm).
fn place(candidates: Vec<FigureCtx>, limit: usize) -> ([Vec<Numbered>; 2], [f64; 2]) {
    let mut columns: [Vec<Numbered>; 2] = [Vec::new(), Vec::new()];
    let mut heights = [0.0_f64; 2];
    let mut placed = 0;
    for figure in candidates {
        if placed == limit {
            break;
        }
        let height = figure_mm(&figure);
        let column = if placed < 2 {
            placed
        } else {
            let shorter = usize::from(heights[1] < heights[0]);
            if heights[shorter] + height > heights[1 - shorter] + SLACK_MM {
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
    svg_height(&f.svg) * MM_PER_PX
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

/// The `height` attribute of an SVG root (0 when missing).
fn svg_height(svg: &str) -> f64 {
    let root = &svg[..svg.find('>').unwrap_or(0)];
    root.split_once(" height=\"")
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
            svg: format!("<svg width=\"900\" height=\"{height}\" viewBox=\"0 0 900 {height}\">"),
            file: String::new(),
        }
    }

    fn claim(id: u8, finding_chars: usize) -> ClaimCtx {
        ClaimCtx {
            id,
            title: "A claim".to_string(),
            paper_says: "The paper says so.".to_string(),
            verdict: "refuted".to_string(),
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
    fn a_third_figure_goes_under_the_shorter_column_only_when_it_fits() {
        let candidates = vec![
            figure("motion", 864),
            figure("forces", 344),
            figure("map", 900),
            figure("compare", 584),
        ];
        let page = page_two(candidates, 11, vec![claim(1, 300)]);
        assert_eq!(ids(&page)[0], [(1, "motion")]);
        assert_eq!(ids(&page)[1], [(2, "forces"), (3, "compare")]);
        let page = page_two(
            vec![figure("a", 592), figure("b", 592), figure("c", 864)],
            18,
            Vec::new(),
        );
        assert_eq!((page.columns[0].len(), page.columns[1].len()), (1, 1));
        assert_eq!(svg_height(&figure("x", 624).svg), 624.0);
    }

    #[test]
    fn claims_that_do_not_fit_are_named_in_one_line_each_and_a_third_figure_yields_first() {
        let candidates = vec![figure("a", 624), figure("b", 344), figure("c", 344)];
        let all = vec![claim(3, 700), claim(8, 500)];
        let page = page_two(candidates.clone(), 18, all.clone());
        assert_eq!(
            page.columns[1].len(),
            2,
            "room for both claims and three figures"
        );
        assert!(page.brief.is_empty());
        let many: Vec<ClaimCtx> = (3..=8).map(|id| claim(id, 600)).collect();
        let page = page_two(candidates, 18, many);
        assert_eq!(
            page.columns[1].len(),
            1,
            "the third figure gives way to the claims"
        );
        assert!(!page.claims.is_empty() && !page.brief.is_empty());
        assert_eq!(page.claims.len() + page.brief.len(), 6);
        assert!(page.brief[0].starts_with(&format!(
            "Claim {}: A claim — refuted",
            page.claims.len() + 3
        )));
    }
}
