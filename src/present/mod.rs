//! What the presentation layer asks of a model: its standard scene and figures, its report
//! tables, its worked derivation, its teaching notes, its terminal tables and CSV files.
//! Implemented by each model's params struct in `src/models/<name>/present.rs`; the report,
//! handout, worksheet, sweep and command line reach it through [`crate::models::with_model!`].
//! The types of its signatures live in [`vocab`], a leaf that names no model.

use crate::derivation::{Expr, Step, StepKey, Value};
use crate::error::Result;
use crate::models::Physics;
use crate::results::Summary;
use vocab::{Figure, FigureKind, Note, OutFile, Phase, Scene, SceneCtx};

pub mod spec;
pub mod vocab;

/// The figures, claims and caption of a user's scenario of this model.
pub struct StandardScene {
    pub figures: Vec<FigureKind>,
    pub claims: Vec<u8>,
    pub caption: &'static str,
}

/// The grid `stickslip sweep` runs without a model: one parameter over the paper's set,
/// across the regimes it shows.
pub struct DefaultSweep {
    /// A numeric parameter of the model (its flag's name).
    pub param: &'static str,
    /// First and last grid values (SI units, as the model flag).
    pub from: f64,
    pub to: f64,
    /// Grid points, both ends included.
    pub steps: u32,
}

/// The laws of an evaluation as a sweep or a table reads them.
pub struct Laws<'a> {
    pub harmonic: &'a Summary,
    /// `None` where the linearized law does not exist for the parameters.
    pub linear: Option<&'a Summary>,
    /// The regime id of the linearized law's closed forms.
    pub closed_form_regime: &'static str,
}

/// The presentation of a model.
pub trait Present: Physics {
    /// What the sketch of the apparatus shows, for its caption ("the block on the table …").
    const SKETCH_WHAT: &'static str;
    /// The sweep of `stickslip sweep` without a model.
    const SWEEP: DefaultSweep;
    /// The standard figures, claims and caption of a scenario of this model.
    fn standard_scene(&self) -> StandardScene;
    /// The figures of `kind` for the scene `scene_id`.
    fn figures(&self, scene_id: &str, kind: FigureKind) -> Result<Vec<Figure>>;
    /// The report's tables of a scene of this model.
    fn scene_tables(&self, scene: &Scene) -> Result<SceneCtx>;
    /// The worked substitutions of every closed form.
    fn derivation(&self) -> Vec<Step>;
    /// [`Present::derivation`] as values only (no expression tree), the same numbers bit for bit:
    /// what a caller that reads only the steps' values uses (`stickslip check` per set).
    fn derivation_values(&self) -> Vec<Step<Value>> {
        self.derivation()
            .into_iter()
            .map(|s| Step {
                expr: Value(Expr::eval(&s.expr)),
                key: s.key,
                symbol: s.symbol,
                equation: s.equation,
                value: s.value,
                unit: s.unit,
                reason: s.reason,
            })
            .collect()
    }
    /// How the handout explains the step of `key`, and the heading before it.
    fn handout_note(key: StepKey) -> Option<(Note, Option<&'static str>)>;
    /// The equation of motion, line by line: (formula, its physics).
    fn equation_of_motion() -> &'static [(&'static str, &'static str)];
    /// A sketch of the apparatus with these parameters and the forces of `phase` (SVG).
    fn sketch(&self, phase: Phase) -> String;
    /// The laws of an evaluation.
    fn laws(e: &Self::Evaluation) -> Laws<'_>;
    /// The evaluation as terminal tables.
    fn text(e: &Self::Evaluation) -> String;
    /// The evaluation, and the CSV files of its runs (time series and events of both laws).
    fn evaluate_with_csv(&self, periods: u32) -> Result<(Self::Evaluation, Vec<OutFile>)>;
}
