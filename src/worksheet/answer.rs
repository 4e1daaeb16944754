//! The answers of one student's case: each question's worked step (from [`crate::derivation`]),
//! the value of the exact integration of the linearized law that confirms it (from the checks
//! of [`crate::results`]), for the figure question the forces figure and its reading tolerance,
//! and the key's v(t) figure.
//! `None` when some answer has no confirmed value: the sampler then draws another set.

use serde::Serialize;

use super::exercise::Exercise;
use super::figure::{time_spacing, v_figure};
use super::question::{Kind, Question};
use crate::derivation::{Step, StepKey};
use crate::engine::Run;
use crate::error::Result;
use crate::models::{with_capability, Model};
use crate::params::DEFAULT_PERIODS;
use crate::present::Present;
use crate::results::quantity::AnyKey;
use crate::results::{rel_diff, Check, CheckValue, Checked, TOLERANCE};

/// A time is readable off the forces figure when the reading tolerance (half a grid step) is at
/// most this fraction of it (not so for a slip onset just after t = 0).
const READABLE: f64 = 0.25;

/// A value of an answer: a number (SI) or a name (the regime).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
#[serde(untagged)]
pub enum Value {
    Number(f64),
    Text(String),
}

/// A value a regime inequality compares: its LaTeX symbol and value.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Comparison {
    pub symbol: &'static str,
    pub value: f64,
}

/// One answer of the key.
#[derive(Clone, Debug, PartialEq)]
pub struct Answer {
    pub question: &'static Question,
    /// The closed form's value (SI), or the regime id.
    pub value: Value,
    /// The worked step (closed-form and figure questions).
    pub step: Option<Step>,
    /// The exact integration's value: the measured quantity, the μd found by search, or the
    /// integrated regime.
    pub numeric: Value,
    /// |closed − numeric| / max(|closed|, |numeric|) (numbers only).
    pub rel_error: Option<f64>,
    /// Reading tolerance of the figure question (SI).
    pub tolerance: Option<f64>,
    /// The values the regime inequalities compare (regime question).
    pub comparisons: Vec<Comparison>,
}

/// The answers of a case, with the key's figure (the sheet's is drawn in the sheet's language
/// when it is rendered).
#[derive(Clone, Debug, PartialEq)]
pub struct Answers {
    pub answers: Vec<Answer>,
    /// SVG of v(t) of the linearized law from rest (in the answer key).
    pub key_figure: Option<String>,
}

/// What the answers read from the evaluation of the case.
struct Evaluated {
    checks: Vec<Check>,
    linear: Option<Run>,
}

fn evaluate(case: &Model, record_segments: bool) -> Result<Evaluated> {
    let (checks, linear) = with_capability!(case, exercise, p => p.checks_and_linear_run(DEFAULT_PERIODS, record_segments)?,
            else return Err(case.missing(crate::models::Capability::Exercise)));
    Ok(Evaluated { checks, linear })
}

/// The worked steps of a case.
pub fn steps(case: &Model) -> Vec<Step> {
    // A model without a presentation has no worked steps (the commands refuse it first).
    with_capability!(case, present, p => p.derivation(), else Vec::new())
}

/// The step of `key` with a value (its form applies), if any.
pub(crate) fn applying(steps: &[Step], key: impl Into<AnyKey>) -> Option<&Step> {
    let key = StepKey::Quantity(key.into());
    steps.iter().find(|s| s.key == key && s.value.is_some())
}

/// The passing check of `key` on the integration, if any.
fn passing(evaluated: &Evaluated, key: AnyKey) -> Option<&Check> {
    evaluated
        .checks
        .iter()
        .find(|c| c.quantity == Checked::Key(key) && c.passed())
}

/// Whether every closed form the questions need applies to the case (cheap: no integration).
pub fn closed_forms_apply(steps: &[Step], questions: &[&Question]) -> bool {
    questions.iter().all(|q| match q.kind {
        Kind::ClosedForm(key) | Kind::Threshold(key) | Kind::ReadFigure(key) => {
            applying(steps, key).is_some()
        }
        Kind::Regime(_) => true,
    })
}

/// The answers of `case` to `questions`, each confirmed by the exact integration within
/// [`TOLERANCE`]; `None` when one is not.
pub fn answer(
    case: &Model,
    steps: &[Step],
    questions: &[&'static Question],
) -> Result<Option<Answers>> {
    let evaluated = evaluate(case, true)?;
    let mut answers = Vec::with_capacity(questions.len());
    for &question in questions {
        let answer = match question.kind {
            Kind::ClosedForm(key) => measured(question, steps, &evaluated, key),
            Kind::Threshold(key) => {
                with_capability!(case, exercise, p => p.threshold(question, steps, key)?,
                    else return Err(case.missing(crate::models::Capability::Exercise)))
            }
            Kind::Regime(key) => regime(question, case, steps, &evaluated, key),
            Kind::ReadFigure(key) => {
                let tolerance = 0.5 * time_spacing(case)?;
                measured(question, steps, &evaluated, key)
                    .filter(|a| matches!(a.value, Value::Number(v) if tolerance <= READABLE * v))
                    .map(|a| Answer {
                        tolerance: Some(tolerance),
                        ..a
                    })
            }
        };
        match answer {
            Some(a) => answers.push(a),
            None => return Ok(None),
        }
    }
    let key_figure = match &evaluated.linear {
        Some(run) => Some(v_figure(run)?.0),
        None => None,
    };
    Ok(Some(Answers {
        answers,
        key_figure,
    }))
}

/// The closed form `key` confirmed by its passing check on the integration.
fn measured(
    question: &'static Question,
    steps: &[Step],
    evaluated: &Evaluated,
    key: AnyKey,
) -> Option<Answer> {
    let CheckValue::Number(numeric) = passing(evaluated, key)?.numeric else {
        return None;
    };
    confirmed(question, applying(steps, key)?, numeric)
}

/// The answer of a closed form `step` and the integration's `numeric` value of it, when they
/// agree within [`TOLERANCE`].
pub(crate) fn confirmed(question: &'static Question, step: &Step, numeric: f64) -> Option<Answer> {
    let value = step.value?;
    let rel = rel_diff(value, numeric);
    (rel <= TOLERANCE).then(|| Answer {
        question,
        value: Value::Number(value),
        step: Some(step.clone()),
        numeric: Value::Number(numeric),
        rel_error: Some(rel),
        tolerance: None,
        comparisons: Vec::new(),
    })
}

/// The regime of the closed forms (the id of guide §9 or guide §8.6), confirmed by the check of
/// the integrated regime (whose id may differ: `slip_stick` is integrated as
/// `single_slip_stick`), and the values its inequalities compare.
fn regime(
    question: &'static Question,
    case: &Model,
    steps: &[Step],
    evaluated: &Evaluated,
    key: AnyKey,
) -> Option<Answer> {
    let CheckValue::Text(numeric) = &passing(evaluated, key)?.numeric else {
        return None;
    };
    let value = |key: AnyKey| applying(steps, key).and_then(|s| s.value);
    let comparisons =
        with_capability!(case, exercise, p => p.regime_comparisons(&value), else Vec::new());
    Some(Answer {
        question,
        value: Value::Text(case.closed_form_regime().to_string()),
        step: None,
        numeric: Value::Text(numeric.clone()),
        rel_error: None,
        tolerance: None,
        comparisons: comparisons
            .into_iter()
            .map(|(symbol, v)| v.map(|value| Comparison { symbol, value }))
            .collect::<Option<_>>()?,
    })
}
