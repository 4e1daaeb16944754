//! What a worksheet asks of a model: its questions and regimes, the words that introduce it,
//! how a student's parameter set is drawn, and the model-specific parts of the answers.
//! Implemented by each model's params struct (`src/models/<name>/exercise.rs`).

use crate::draws::Draws;

use super::answer::Answer;
use super::question::{Question, Regime};
use crate::derivation::Step;
use crate::engine::Run;
use crate::error::Result;
use crate::present::Present;
use crate::results::quantity::AnyKey;
use crate::results::Check;

/// The worksheet side of a model.
pub trait Exercise: Present {
    /// The computed symbols the sheet defines by their formulas (the symbols of worked steps),
    /// so that every symbol of the introduction and the regime rules is defined on the sheet.
    const DEFINED: &'static [&'static str];
    /// Every question the model's sheets can ask.
    fn catalogue() -> &'static [Question];
    /// Regimes a worksheet can ask for (closed-form regimes), the default first.
    fn regimes() -> &'static [Regime];
    /// The rules that decide the regime, as (regime, condition in LaTeX).
    fn regime_rules() -> &'static [(Regime, &'static str)];
    /// The apparatus at rest at t = 0 labelled with the given values only (SVG): the derived
    /// ones are the student's to work out.
    fn sketch_givens(&self) -> String;
    /// The option of the sheet's motion question that names the closed-form regime `regime`
    /// (the regime itself, unless the sheet's rules group regimes).
    fn regime_option(regime: &'static str) -> &'static str {
        regime
    }
    /// A candidate parameter set aimed at `regime`, every value rounded as typed.
    fn draw(regime: Regime, rng: &mut Draws) -> Self;
    /// The values the regime's inequalities compare, as (LaTeX symbol, value); `value` gives
    /// the value of a worked step.
    fn regime_comparisons(
        &self,
        value: &dyn Fn(AnyKey) -> Option<f64>,
    ) -> Vec<(&'static str, Option<f64>)>;
    /// The answer to a threshold question (a parameter value found by bisection on the
    /// engine); `None` where the model has none.
    fn threshold(
        &self,
        _question: &'static Question,
        _steps: &[Step],
        _step: AnyKey,
    ) -> Result<Option<Answer>> {
        Ok(None)
    }
    /// The checks of the evaluation and the run of the linearized law (with its segments when
    /// `record_segments`), `None` where that law does not exist.
    fn checks_and_linear_run(
        &self,
        periods: u32,
        record_segments: bool,
    ) -> Result<(Vec<Check>, Option<Run>)>;
}
