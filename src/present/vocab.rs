//! The vocabulary of the presentation traits ([`super::Present`]): the types a model's
//! presentation hands to the report, the handout and the worksheets (a scene and its part, the
//! kinds of figure and the figures, the context of a scene page, the phase of a sketch, the
//! note of a step of the handout, an output file). A leaf: it names no model and imports none
//! of the modules that use it, so that the shared presentation modules and the models import
//! it, never each other, for these types.

use std::path::PathBuf;

use serde::Serialize;

use super::spec::{CategoryMap, LineChart};
use crate::models::Model;

/// A row of the parameter table.
#[derive(Clone, Debug, Serialize)]
pub struct ParamRow {
    pub name: String,
    pub value: String,
    pub unit: String,
}

/// The regime of one law and the reason.
#[derive(Clone, Debug, Serialize)]
pub struct RegimeRow {
    pub law: String,
    pub regime: String,
    pub why: String,
}

/// A row of the verification table.
#[derive(Clone, Debug, Serialize)]
pub struct VerificationRow {
    pub symbol: String,
    /// MathML for HTML and LaTeX for Markdown.
    pub formula_mathml: String,
    pub formula_tex: String,
    pub equation: String,
    /// The anchor in guide.html (guide.md) of the section that derives a formula the paper does
    /// not number (equation "guide §7.5"); empty for the paper's numbered equations.
    pub guide: String,
    /// That section's number, 7.5 (the link reads "guide §7.5" in the page's language); empty
    /// for the paper's numbered equations.
    pub section: String,
    pub tag: String,
    pub closed_form: String,
    pub numeric: String,
    /// SI unit of the closed form and the numeric value (empty: a number).
    pub unit: String,
    pub rel_error: String,
    pub tolerance: String,
    /// "pass", "FAIL", "n/a" (outside its regime) or "—" (no numeric counterpart).
    pub verdict: String,
    /// CSS class: pass, fail, na, none.
    pub class: String,
    /// Why the formula does not describe this motion (greyed rows).
    pub note: String,
}

/// A table with a header row.
#[derive(Clone, Debug, Serialize)]
pub struct Table {
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

/// A figure: the SVG for HTML (inline) and the file name for Markdown.
#[derive(Clone, Debug, Serialize)]
pub struct FigureCtx {
    pub id: String,
    pub caption: String,
    pub svg: String,
    pub file: String,
}

impl FigureCtx {
    /// The figure as the SVG file beside a Markdown page (`file`).
    pub fn out_file(&self) -> OutFile {
        OutFile::new(&self.file, self.svg.as_bytes())
    }
}

/// A line of the equation of motion, in symbols, with a sentence of physics.
#[derive(Clone, Debug, Serialize)]
pub struct MotionLine {
    pub mathml: String,
    pub tex: String,
    pub note: String,
}

/// A claim of the paper with its computed verdict.
#[derive(Clone, Debug, Serialize)]
pub struct ClaimCtx {
    pub id: u8,
    pub title: String,
    pub paper_says: String,
    pub verdict: String,
    /// The verdict's id (`confirmed`, `refuted`, …) for the page's style, whatever the
    /// language of `verdict`.
    pub verdict_class: String,
    /// Why the claim does not apply to the given set ("" when it does).
    pub does_not_apply: String,
    pub finding: String,
    pub numbers: Vec<String>,
}

/// Everything a scene page shows.
#[derive(Clone, Debug, Serialize)]
pub struct SceneCtx {
    pub id: String,
    pub title: String,
    pub model: String,
    /// The part of the reading path ([`Part::heading`]) and why the scene matters.
    pub part: String,
    pub why: String,
    /// The apparatus with the scene's parameters, at the slip onset.
    pub sketch: FigureCtx,
    /// The equation of motion and the force laws.
    pub motion: Vec<MotionLine>,
    pub caption: String,
    pub description: String,
    pub params: Vec<ParamRow>,
    pub regimes: Vec<RegimeRow>,
    pub verification: Vec<VerificationRow>,
    pub checks_passed: usize,
    pub checks_total: usize,
    pub all_pass: bool,
    pub figures: Vec<FigureCtx>,
    pub linearization: Table,
    pub claims: Vec<ClaimCtx>,
    /// Why the closed forms do not apply at all, if so.
    pub domain_note: String,
    /// Regimes for the index: closed form (linear) and harmonic integration.
    pub closed_regime: String,
    pub harmonic_regime: String,
}

/// What a scene draws. Each kind may produce one or more figures.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FigureKind {
    /// Pulled mass: x, v, a against t for both laws, with t_SL, t_M, t_ST (Figs. 5, 6, 10).
    PulledMotion { periods: f64 },
    /// Pulled mass: F against μs N(t) and μd N(t), with t_SL, t_M, t_ST.
    PulledForces,
    /// Pulled mass: the (μd, μs) domain for the scene's φ, both laws on a grid (Fig. 9).
    PulledDomain,
    /// Pulled mass: position over 10 periods and the line of slope v̄ (Fig. 11).
    PulledLongRun,
    /// Pulled mass: speed and acceleration, harmonic against linear (Fig. 12).
    PulledCompare,
    /// Woodpecker: y_S and v against t for both laws, with the characteristic times (Figs. 15,
    /// 16, 26).
    WoodMotion { periods: f64 },
    /// Woodpecker: the spring coordinate, harmonic against the three counterparts (Fig. 17).
    WoodSpring,
    /// Woodpecker: W_S + F_e against 2λμs|F_e| and 2λμd|F_e|, with t_SL^(I) (Fig. 18).
    WoodForces,
    /// Woodpecker: a, v, y and the characteristic times of phase 1 or 2 (Fig. 19).
    WoodPhase { phase: u8 },
    /// Woodpecker: v for μd below, at and above μd,MIN of phase 1 or 2 (Fig. 20).
    WoodMuSweep { phase: u8 },
    /// Woodpecker: sleeve and woodpecker positions and the speed (Fig. 23).
    WoodPositions,
    /// Woodpecker: regimes in the (μd, z0) plane with μd,MIN and μd,HALT of both phases.
    WoodRegimeMap,
    /// Woodpecker: the example track (synthetic) with the harmonic law fitted to it from the
    /// scene's parameters (Figs. 26–27).
    WoodTracked,
}

/// A drawing ready for a renderer.
#[derive(Clone, Debug, PartialEq)]
pub enum Drawing {
    Chart(LineChart),
    Map(CategoryMap),
}

impl Drawing {
    /// Every text the drawing shows: axis labels, legend entries, reference-line and marker
    /// labels (to write them in another language before the legend is sized).
    pub fn labels_mut(&mut self) -> Vec<&mut String> {
        match self {
            Drawing::Chart(c) => {
                let mut labels = vec![&mut c.x_label];
                for panel in &mut c.panels {
                    labels.push(&mut panel.y_label);
                    labels.extend(panel.curves.iter_mut().map(|c| &mut c.label));
                    labels.extend(panel.h_lines.iter_mut().map(|h| &mut h.1));
                }
                labels.extend(c.markers.iter_mut().map(|m| &mut m.label));
                labels
            }
            Drawing::Map(m) => {
                let mut labels = vec![&mut m.x_label, &mut m.y_label];
                labels.extend(m.categories.iter_mut().map(|c| &mut c.0));
                labels.extend(m.curves.iter_mut().map(|c| &mut c.label));
                labels
            }
        }
    }
}

/// One figure of a scene: a file-name id, a caption and the drawing.
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    pub id: String,
    pub caption: String,
    pub drawing: Drawing,
}

/// The part of the reading path a scene belongs to: the paper's two models, then the user's
/// own scenario files.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Part {
    PulledMass,
    Woodpecker,
    Scenarios,
}

impl Part {
    /// Every part, in reading order.
    pub const ALL: [Part; 3] = [Part::PulledMass, Part::Woodpecker, Part::Scenarios];

    /// The heading of the part in the index.
    pub fn heading(self) -> &'static str {
        match self {
            Part::PulledMass => "Part 1. The pulled mass",
            Part::Woodpecker => "Part 2. The falling woodpecker",
            Part::Scenarios => "Your scenarios",
        }
    }

    /// The part's story in two sentences: what the apparatus is and what to follow.
    pub fn story(self) -> &'static str {
        match self {
            Part::PulledMass => {
                "A block on a table is pulled by a constant force F while a spring presses it \
                 down with a mass hanging under the table: the normal force N oscillates, so \
                 friction alternately holds the block and lets it slide. Read the pages in order: \
                 the pull against the friction limits, then each kind of motion, then the price \
                 of the linearized law that makes every result a closed formula."
            }
            Part::Woodpecker => {
                "The toy woodpecker slides down its pole in jerks: the bird swings on a spring, \
                 tilting the sleeve so that it grips the pole and lets go twice per swing. The \
                 same stick-slip rule as in Part 1, with the grip set by the lever l/h; the pages \
                 follow one period phase by phase, then the regimes and the real toy."
            }
            Part::Scenarios => "Scenes from the scenario files given to `stickslip report`.",
        }
    }
}

/// A scene of the report.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// File stem of the scene's pages.
    pub id: String,
    pub title: String,
    /// Where the scene sits in the reading path.
    pub part: Part,
    /// Why the scene matters, in a sentence: the index's line and the page's opening.
    pub why: String,
    /// What the scene shows and what to look for.
    pub caption: String,
    /// The scenario's description of the parameters.
    pub description: String,
    /// The model and its parameters.
    pub setup: Model,
    /// Periods integrated for the results tables.
    pub periods: u32,
    pub figures: Vec<FigureKind>,
    /// Claims of the paper (guide §11) that concern the scene.
    pub claims: Vec<u8>,
}

/// What the body is doing in the sketch: it decides which friction law labels the friction
/// arrows and whether a velocity arrow is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Phase {
    /// At rest, held by static friction: the friction force is whatever balances the drive, up
    /// to μs N.
    Stuck,
    /// Sliding: the friction force is μd N, against the velocity.
    Slipping,
}

impl Phase {
    /// A few words for titles and descriptions.
    pub fn words(self) -> &'static str {
        match self {
            Phase::Stuck => "at rest (sticking)",
            Phase::Slipping => "slipping",
        }
    }
}

/// How a step of the chain is shown.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Note {
    /// A definition or a shorthand with a few words: the step takes half a row.
    Label(&'static str),
    /// A step of the motion with a sentence of physics: the step takes a whole row.
    Sentence(&'static str),
    /// Only the numbers (symbol = substituted = result), half a row: the woodpecker's phase
    /// II, whose formulas are those of phase I with u^(−) ↔ u^(+), η ↔ η' (guide §8.4).
    Numbers,
}

/// A rendered output file: a path relative to the output folder, and its bytes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OutFile {
    pub path: PathBuf,
    pub bytes: Vec<u8>,
}

impl OutFile {
    pub fn new(path: impl Into<PathBuf>, bytes: impl Into<Vec<u8>>) -> Self {
        OutFile {
            path: path.into(),
            bytes: bytes.into(),
        }
    }
}
