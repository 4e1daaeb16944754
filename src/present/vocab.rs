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

/// A table of the model's laws side by side, under its heading.
#[derive(Clone, Debug, Serialize)]
pub struct Comparison {
    /// "Linearization: harmonic law against the linearized law".
    pub heading: String,
    pub table: Table,
}

/// A law of a model: its id in CSV and JSON column names (`harmonic`), its name in tables
/// ("harmonic law") and the key of its integration's summary in `eval --json`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct LawName {
    pub id: &'static str,
    pub name: &'static str,
    /// The key of the law's summary in the evaluation's JSON (`harmonic`; the belt's
    /// `integration`): what a binding reads the summary from.
    #[serde(skip)]
    pub summary: &'static str,
}

/// The outcome of one law of an evaluation as a sweep reads it.
#[derive(Clone, Debug, PartialEq)]
pub struct LawPoint {
    /// Mean speed of the settled orbit (m/s); `None` when no periodic orbit was found, or for
    /// a body that does not advance (the belt's block oscillates about a fixed point).
    pub v_avg: Option<f64>,
    /// Slips and sticks per period (per cycle of an autonomous model).
    pub slips: u32,
    pub sticks: u32,
    /// The regime's id (the model's [`crate::models::Physics::regime_words`] names it).
    pub regime: &'static str,
}

/// How a sweep shows a quantity of the model's own: its CSV column and its plot panel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Column {
    /// The CSV column's name with its unit suffix (`period_s`, `stick_share`).
    pub column: &'static str,
    /// The plot panel's axis label with its unit ("T (s)").
    pub label: &'static str,
    /// Factor from SI to the axis unit (1e3 for mm).
    pub scale: f64,
}

/// A quantity of the model's own that `stickslip sweep` tabulates and plots at every point
/// ([`crate::present::Present::sweep_columns`]), read from the point's evaluation `E`.
pub struct SweepColumn<E> {
    pub head: Column,
    /// The value at a point (SI); `None` where it is undefined.
    pub value: fn(&E) -> Option<f64>,
}

impl LawPoint {
    /// The point of a run of a time-periodic law.
    pub fn of(s: &crate::results::Summary) -> Self {
        Self {
            v_avg: s.v_avg,
            slips: s.slips_per_period,
            sticks: s.sticks_per_period,
            regime: s.regime.id(),
        }
    }
}

/// How a model's pages and tables name what its closed forms are checked against.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct LawWords {
    /// The law the closed forms describe ("linearized law").
    pub closed_form_law: &'static str,
    /// What the closed forms are checked against ("exact integration of the linearized law").
    pub checked_against: &'static str,
    /// Where the numeric values of the verification come from ("exact event-driven
    /// integration of the same (triangle-wave) law").
    pub numeric_from: &'static str,
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
    /// What the model's laws are called on the page.
    pub words: LawWords,
    /// The table of the model's laws side by side, when it has more than one (the paper's
    /// harmonic law against its linearization).
    pub linearization: Option<Comparison>,
    pub claims: Vec<ClaimCtx>,
    /// Why the closed forms do not apply at all, if so.
    pub domain_note: String,
    /// Regimes for the index: closed form (linear) and harmonic integration.
    pub closed_regime: String,
    pub harmonic_regime: String,
}

/// What a scene draws, as the shared code carries it: the name of one of its model's figure
/// kinds and the kind's numeric argument, if it has one (periods to draw, a phase). Each
/// model defines its own kinds, an enum in its folder made with [`figure_kinds!`], and
/// converts it to and from this value ([`FigureKinds`]); the shared code compares kinds by
/// [`FigureKind::name`] and never lists them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FigureKind {
    pub name: &'static str,
    pub arg: Option<f64>,
}

/// A model's own figure kinds, converted to and from the shared [`FigureKind`].
pub trait FigureKinds: Copy + Sized {
    /// The kind as the shared code carries it.
    fn kind(self) -> FigureKind;
    /// The model's kind of `kind`; `None` for a name the model does not define.
    fn from_kind(kind: FigureKind) -> Option<Self>;
}

/// `figure_kinds! { pub enum Name { Variant = "name", Other { field: f64 } = "other" } }`: a
/// model's figure kinds (each with at most one numeric field) and their [`FigureKinds`]
/// conversion, so that a name is written once.
macro_rules! figure_kinds {
    ($(#[$meta:meta])* $vis:vis enum $name:ident {
        $($(#[$vmeta:meta])* $variant:ident $({ $field:ident : $ty:ty })? = $id:literal),+ $(,)?
    }) => {
        $(#[$meta])*
        #[derive(Clone, Copy, Debug, PartialEq)]
        $vis enum $name {
            $($(#[$vmeta])* $variant $({ $field: $ty })?),+
        }

        impl $crate::present::vocab::FigureKinds for $name {
            fn kind(self) -> $crate::present::vocab::FigureKind {
                match self {
                    $($name::$variant $({ $field })? => $crate::present::vocab::FigureKind {
                        name: $id,
                        arg: $crate::present::vocab::figure_kinds!(@arg $($field)?),
                    }),+
                }
            }

            fn from_kind(kind: $crate::present::vocab::FigureKind) -> Option<Self> {
                $(if kind.name == $id {
                    return Some($name::$variant $({ $field: kind.arg? as $ty })?);
                })+
                None
            }
        }
    };
    (@arg $field:ident) => { Some(f64::from($field)) };
    (@arg) => { None };
}
pub(crate) use figure_kinds;

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

/// A model's part of the reading path: its title and its story in two sentences (what the
/// apparatus is and what to follow). Declared by the model ([`super::Present::PART`]); the
/// report numbers the parts in the order of the registry.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PartStory {
    pub title: &'static str,
    pub story: &'static str,
}

/// The part of the reading path a scene belongs to: a model's, numbered in the order of the
/// registry, or the user's own scenario files ([`Part::SCENARIOS`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Part {
    /// The part's number in the index (`None`: the user's scenarios, unnumbered).
    pub number: Option<usize>,
    pub story: PartStory,
}

impl Part {
    /// The scenes of the scenario files given to `stickslip report`.
    pub const SCENARIOS: Part = Part {
        number: None,
        story: PartStory {
            title: "Your scenarios",
            story: "Scenes from the scenario files given to `stickslip report`.",
        },
    };

    /// The heading of the part in the index ("Part 1. The pulled mass").
    pub fn heading(self) -> String {
        match self.number {
            Some(n) => format!("Part {n}. {}", self.story.title),
            None => self.story.title.to_string(),
        }
    }

    /// The part's story in two sentences.
    pub fn story(self) -> &'static str {
        self.story.story
    }
}

/// A built-in scene of a model: a scenario file compiled into the binary, what to draw and
/// its place in the model's part ([`super::Present::builtin_scenes`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Builtin {
    /// File stem of the scene's pages (unique across the report).
    pub id: &'static str,
    /// The figure(s) of the paper it reproduces, and what they show (unique).
    pub title: &'static str,
    /// Why the scene matters, in a sentence.
    pub why: &'static str,
    /// The scenario file's name in `scenarios/` and its text (`include_str!`).
    pub file: &'static str,
    pub text: &'static str,
    pub caption: &'static str,
    pub figures: Vec<FigureKind>,
    pub claims: &'static [u8],
}

impl Builtin {
    /// A built-in scene `id` with its `(title, why)`, its scenario `(file name, text)`, the
    /// caption, the model's figure kinds and the claims of the paper it concerns.
    pub fn new<F: FigureKinds>(
        id: &'static str,
        (title, why): (&'static str, &'static str),
        (file, text): (&'static str, &'static str),
        caption: &'static str,
        figures: &[F],
        claims: &'static [u8],
    ) -> Self {
        Builtin {
            id,
            title,
            why,
            file,
            text,
            caption,
            figures: figures.iter().map(|f| f.kind()).collect(),
            claims,
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
