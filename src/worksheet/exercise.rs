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

/// A quantity's value on the exact integration, with the floor of its error's denominator
/// (the period for an event time) and the tolerance of the checks it comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Measured {
    pub value: f64,
    pub scale: f64,
    pub tolerance: f64,
}

impl Measured {
    /// The numeric side of a passing check.
    pub fn of(check: &Check) -> Option<Self> {
        match (check.pass, &check.numeric) {
            (Some(true), crate::results::CheckValue::Number(value)) => Some(Self {
                value: *value,
                scale: check.scale,
                tolerance: check.tolerance,
            }),
            _ => None,
        }
    }
}

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
    /// A set anywhere in the model's valid domain, for `check`'s sample: the full ranges of
    /// every parameter and every regime, not a worksheet's tidy values. The default draws as a
    /// worksheet does.
    fn probe(rng: &mut Draws) -> Self
    where
        Self: Sized,
    {
        Self::draw(Self::regimes()[0], rng)
    }
    /// The regime boundaries `check` packs draws against, in words ("φ = 1/Θ"); none by default.
    fn boundaries() -> &'static [&'static str] {
        &[]
    }
    /// This set moved to boundary `i` of [`Exercise::boundaries`] times `1 + offset` (the
    /// deciding parameter set so that the compared value is the boundary's times `1 + offset`);
    /// `None` where the moved set would be invalid.
    fn onto_boundary(&self, _i: usize, _offset: f64) -> Option<Self>
    where
        Self: Sized,
    {
        None
    }
    /// Where a quantity's own check is absent on this set (its closed form describes another
    /// regime), its value on the exact integration from the checks that are there (the pulled
    /// mass's v̄ in the late-stick band is checked as `v_avg_late`): (value, floor of the
    /// error's denominator, tolerance), from passing checks only; `None` by default.
    fn measured_elsewhere(&self, _quantity: &str, _checks: &[Check]) -> Option<Measured> {
        None
    }
    /// The checks of the evaluation and the run of the linearized law (with its segments when
    /// `record_segments`), `None` where that law does not exist.
    fn checks_and_linear_run(
        &self,
        periods: u32,
        record_segments: bool,
    ) -> Result<(Vec<Check>, Option<Run>)>;
}
