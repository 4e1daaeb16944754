//! The answers of one student's case: each question's worked step (from [`crate::derivation`]),
//! the value of the exact integration of the linearized law that confirms it (from the checks
//! of [`crate::results`]), and for the figure question the v(t) plot and its reading tolerance.
//! `None` when some answer has no confirmed value: the sampler then draws another set.

use serde::Serialize;

use super::figure::v_figure;
use super::question::{Kind, Question};
use super::sample::Case;
use super::threshold::mu_d_sticking_at_half_period;
use crate::derivation::{self, Step};
use crate::engine::Run;
use crate::error::Result;
use crate::models::{pulled_mass::results as pulled_mass, woodpecker::results as woodpecker};
use crate::params::{WoodpeckerParams, DEFAULT_PERIODS};
use crate::results::{rel_diff, Check, CheckValue, TOLERANCE};

/// A figure is readable when its reading tolerance is at most this fraction of the value read
/// (not so when the speed grows far beyond the first maximum, as in continuous slip).
const READABLE: f64 = 0.05;

/// A value of an answer: a number (SI) or a name (the regime).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Value {
    Number(f64),
    Text(String),
}

/// A value a regime inequality compares: its LaTeX symbol and value.
#[derive(Clone, Debug, PartialEq, Serialize)]
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

/// The answers of a case, with the v(t) figure when a question reads it.
#[derive(Clone, Debug, PartialEq)]
pub struct Answers {
    pub answers: Vec<Answer>,
    /// SVG of v(t) of the linearized law, without the answer marked.
    pub figure: Option<String>,
}

/// What the answers read from the evaluation of the case.
struct Evaluated {
    checks: Vec<Check>,
    linear: Option<Run>,
}

fn evaluate(case: &Case, record_segments: bool) -> Result<Evaluated> {
    Ok(match case {
        Case::PulledMass(p) => {
            let (e, runs) = pulled_mass::evaluate_with_runs(p, DEFAULT_PERIODS, record_segments)?;
            Evaluated {
                checks: e.checks,
                linear: Some(runs.linear),
            }
        }
        Case::Woodpecker(p) => {
            let (e, runs) = woodpecker::evaluate_with_runs(p, DEFAULT_PERIODS, record_segments)?;
            Evaluated {
                checks: e.checks,
                linear: runs.linear,
            }
        }
    })
}

/// The worked steps of a case.
pub fn steps(case: &Case) -> Vec<Step> {
    match case {
        Case::PulledMass(p) => derivation::pulled_mass(p),
        Case::Woodpecker(p) => derivation::woodpecker(p),
    }
}

/// The step of `key` with a value (its form applies), if any.
fn applying<'a>(steps: &'a [Step], key: &str) -> Option<&'a Step> {
    steps
        .iter()
        .find(|s| s.key.id() == key && s.value.is_some())
}

/// Whether every closed form the questions need applies to the case (cheap: no integration).
pub fn closed_forms_apply(steps: &[Step], questions: &[&Question]) -> bool {
    questions.iter().all(|q| match q.kind {
        Kind::ClosedForm { step, .. }
        | Kind::Threshold { step }
        | Kind::ReadFigure { step, .. } => applying(steps, step).is_some(),
        Kind::Regime => true,
    })
}

/// The answers of `case` to `questions`, each confirmed by the exact integration within
/// [`TOLERANCE`]; `None` when one is not.
pub fn answer(
    case: &Case,
    steps: &[Step],
    questions: &[&'static Question],
) -> Result<Option<Answers>> {
    let reads_figure = questions
        .iter()
        .any(|q| matches!(q.kind, Kind::ReadFigure { .. }));
    let evaluated = evaluate(case, reads_figure)?;
    let mut answers = Vec::with_capacity(questions.len());
    let mut figure = None;
    for &question in questions {
        let answer = match question.kind {
            Kind::ClosedForm { step, check } => measured(question, steps, &evaluated, step, check),
            Kind::Threshold { step } => match case {
                Case::Woodpecker(p) => threshold(question, steps, p, step)?,
                Case::PulledMass(_) => None,
            },
            Kind::Regime => regime(question, case, steps, &evaluated),
            Kind::ReadFigure { step, check } => {
                let Some(run) = &evaluated.linear else {
                    return Ok(None);
                };
                let (svg, spacing) = v_figure(run)?;
                figure = Some(svg);
                measured(question, steps, &evaluated, step, check)
                    .filter(
                        |a| matches!(a.value, Value::Number(v) if 0.5 * spacing <= READABLE * v),
                    )
                    .map(|a| Answer {
                        tolerance: Some(0.5 * spacing),
                        ..a
                    })
            }
        };
        match answer {
            Some(a) => answers.push(a),
            None => return Ok(None),
        }
    }
    Ok(Some(Answers { answers, figure }))
}

/// A closed form confirmed by the passing check `check` of the integration.
fn measured(
    question: &'static Question,
    steps: &[Step],
    evaluated: &Evaluated,
    step: &str,
    check: &str,
) -> Option<Answer> {
    let check = evaluated
        .checks
        .iter()
        .find(|c| c.quantity.id() == check && c.pass)?;
    let CheckValue::Number(numeric) = check.numeric else {
        return None;
    };
    confirmed(question, applying(steps, step)?, numeric)
}

/// The answer of a closed form `step` and the integration's `numeric` value of it, when they
/// agree within [`TOLERANCE`].
fn confirmed(question: &'static Question, step: &Step, numeric: f64) -> Option<Answer> {
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

/// The regime of the closed forms (the id of physics.md §1.5 or §3.6), confirmed by the check of
/// the integrated regime (whose id may differ: `slip_stick` is integrated as
/// `single_slip_stick`), and the values its inequalities compare.
fn regime(
    question: &'static Question,
    case: &Case,
    steps: &[Step],
    evaluated: &Evaluated,
) -> Option<Answer> {
    let check = evaluated
        .checks
        .iter()
        .find(|c| c.quantity.id() == "regime" && c.pass)?;
    let CheckValue::Text(numeric) = &check.numeric else {
        return None;
    };
    let value = |key: &str| applying(steps, key).and_then(|s| s.value);
    let comparisons: Vec<(&'static str, Option<f64>)> = match case {
        Case::PulledMass(p) => vec![
            (r"\varphi", value("phi")),
            (r"1/\Theta", value("phi_stick_max")),
            (r"\varphi_c", value("phi_continuous")),
            (r"2\mu_s", Some(2.0 * p.mu_s)),
        ],
        Case::Woodpecker(p) => vec![
            (
                r"u_s^{(-)}\eta'",
                value("u_s_minus")
                    .zip(value("eta_prime"))
                    .map(|(u, h)| u * h),
            ),
            (r"\mu_d", Some(p.mu_d)),
            (r"\mu_{d,HALT}^{(I)}", value("mu_d_halt_1")),
            (r"\mu_{d,HALT}^{(II)}", value("mu_d_halt_2")),
        ],
    };
    Some(Answer {
        question,
        value: Value::Text(case.regime().to_string()),
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

/// μd,MIN^(I) (51), confirmed by the μd at which the integrated phase-I slip from rest sticks
/// exactly at T/2.
fn threshold(
    question: &'static Question,
    steps: &[Step],
    p: &WoodpeckerParams,
    step: &str,
) -> Result<Option<Answer>> {
    let Some((step, value)) = applying(steps, step).and_then(|s| Some((s, s.value?))) else {
        return Ok(None);
    };
    Ok(mu_d_sticking_at_half_period(p, value)?.and_then(|n| confirmed(question, step, n)))
}
