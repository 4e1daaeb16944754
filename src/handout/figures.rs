//! The figures of page 2: which ones (the scene's own, then the motion, the forces and one
//! more figure of its model) and how they share two columns so that the block stays short
//! enough for the verification table and the claims below it.

use serde::Serialize;

use crate::report::context::FigureCtx;
use crate::report::scene::{FigureKind, Setup};
use crate::report::Scene;

/// At most this many figures: the two columns, and one below the shorter.
pub const MAX_FIGURES: usize = 3;
/// Room a caption takes, in px of the 900-px-wide SVG user space (the columns print each
/// figure about 9 cm wide, so 100 px ≈ 1 cm).
const CAPTION: f64 = 100.0;
/// A third figure may make its column this much taller than the other one.
const SLACK: f64 = 200.0;

/// A figure of the handout with its number.
#[derive(Clone, Debug, Serialize)]
pub struct Numbered {
    pub number: usize,
    #[serde(flatten)]
    pub figure: FigureCtx,
}

/// The candidate figure kinds: the scene's own, then the motion and the forces of its model
/// (the figures the chain of formulas refers to) and a comparison of the two laws, each unless
/// the scene has that kind already.
pub fn kinds(scene: &Scene) -> Vec<FigureKind> {
    let standard = match scene.setup {
        Setup::PulledMass(_) => [
            FigureKind::PulledMotion { periods: 2.0 },
            FigureKind::PulledForces,
            FigureKind::PulledCompare,
        ],
        Setup::Woodpecker(_) => [
            FigureKind::WoodMotion { periods: 2.0 },
            FigureKind::WoodForces,
            FigureKind::WoodSpring,
        ],
    };
    let mut kinds = scene.figures.clone();
    for kind in standard {
        let same = std::mem::discriminant(&kind);
        if !kinds.iter().any(|k| std::mem::discriminant(k) == same) {
            kinds.push(kind);
        }
    }
    kinds
}

/// Places `candidates` in order: the first two side by side, then at most one more under the
/// shorter column if that column stays within [`SLACK`] of the other. Returns the two columns
/// (figures numbered in the order placed).
pub fn columns(candidates: Vec<FigureCtx>) -> [Vec<Numbered>; 2] {
    let mut columns: [Vec<Numbered>; 2] = [Vec::new(), Vec::new()];
    let mut heights = [0.0_f64; 2];
    let mut placed = 0;
    for figure in candidates {
        let height = svg_height(&figure.svg) + CAPTION;
        let column = if placed < 2 {
            placed
        } else {
            let shorter = usize::from(heights[1] < heights[0]);
            if heights[shorter] + height > heights[1 - shorter] + SLACK {
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
        if placed == MAX_FIGURES {
            break;
        }
    }
    columns
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
            caption: String::new(),
            svg: format!("<svg width=\"900\" height=\"{height}\" viewBox=\"0 0 900 {height}\">"),
            file: String::new(),
        }
    }

    fn ids(column: &[Numbered]) -> Vec<(usize, &str)> {
        column
            .iter()
            .map(|n| (n.number, n.figure.id.as_str()))
            .collect()
    }

    #[test]
    fn a_third_figure_goes_under_the_shorter_column_only_when_it_fits() {
        let [left, right] = columns(vec![
            figure("motion", 864),
            figure("forces", 344),
            figure("map", 900),
            figure("compare", 584),
            figure("spring", 344),
        ]);
        assert_eq!(ids(&left), [(1, "motion")]);
        assert_eq!(ids(&right), [(2, "forces"), (3, "compare")]);
        let [left, right] = columns(vec![figure("a", 624), figure("b", 344), figure("c", 624)]);
        assert_eq!((ids(&left), ids(&right)), (vec![(1, "a")], vec![(2, "b")]));
        let [left, right] = columns(vec![figure("a", 592), figure("b", 592), figure("c", 864)]);
        assert_eq!((left.len(), right.len()), (1, 1));
        assert_eq!(svg_height(&figure("x", 624).svg), 624.0);
    }
}
