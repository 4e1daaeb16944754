//! answer-key.json: the key for scripts, per student the parameters as a scenario's `[params]`
//! table (so that they load back into the parameter structs), the regime and every answer in SI
//! units beside the exact integration's value.

use serde::Serialize;

use super::answer::{Comparison, Value};
use super::Worksheets;
use crate::error::{Error, Result};
use crate::models::Model;

#[derive(Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub(crate) struct KeyJson<'a> {
    model: &'static str,
    seed: u64,
    regime: &'static str,
    questions: Vec<String>,
    students: Vec<StudentJson<'a>>,
}

#[derive(Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub(crate) struct StudentJson<'a> {
    student: u32,
    /// Regime of the closed forms (guide §9, guide §8.6).
    regime: &'static str,
    /// The scenario keys of the `[params]` table (SI). A map built from the model's parameter
    /// struct (the woodpecker's `omega_mode` renamed `omega`, as a scenario spells it).
    #[cfg_attr(feature = "cli", schemars(schema_with = "params_schema"))]
    params: serde_json::Value,
    answers: Vec<AnswerJson<'a>>,
}

#[derive(Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub(crate) struct AnswerJson<'a> {
    key: String,
    /// Closed-form value (SI) or regime id.
    value: &'a Value,
    unit: &'static str,
    /// The exact integration's value (SI) or integrated regime.
    numeric: &'a Value,
    rel_error: Option<f64>,
    /// Reading tolerance of the figure question (SI).
    tolerance: Option<f64>,
    equation: Option<&'static str>,
    formula: Option<String>,
    substituted: Option<String>,
    /// The values the regime inequalities compare.
    comparisons: &'a [Comparison],
}

/// The schema of answer-key.json (src/schema.rs).
pub(crate) type KeySchema = crate::results::Versioned<'static, KeyJson<'static>>;

/// A scenario's `[params]` table: numbers (SI) and the woodpecker's ω mode.
#[cfg(feature = "cli")]
fn params_schema(_: &mut schemars::SchemaGenerator) -> schemars::Schema {
    schemars::json_schema!({
        "type": "object",
        "description": "The scenario keys of the `[params]` table (SI)",
        "additionalProperties": {"type": ["number", "string", "null"]}
    })
}

/// The parameters as a scenario's `[params]` table (the woodpecker's ω mode under `omega`).
fn params_json(case: &Model) -> Result<serde_json::Value> {
    let mut value = serde_json::to_value(case).map_err(json_error)?;
    if let Some(map) = value.as_object_mut() {
        if let Some(mode) = map.remove("omega_mode") {
            map.insert("omega".to_string(), mode);
        }
    }
    Ok(value)
}

fn json_error(e: serde_json::Error) -> Error {
    Error::Template {
        name: "answer-key.json".to_string(),
        reason: e.to_string(),
    }
}

/// answer-key.json: per student the parameters (a scenario's `[params]` table), the regime,
/// and each answer with its value, unit, the integration's value and the worked step.
pub fn key_json(w: &Worksheets) -> Result<Vec<u8>> {
    let students = w
        .students
        .iter()
        .map(|s| {
            Ok(StudentJson {
                student: s.number,
                regime: s.case.closed_form_regime(),
                params: params_json(&s.case)?,
                answers: s
                    .answers
                    .iter()
                    .map(|a| AnswerJson {
                        key: a.question.key(),
                        value: &a.value,
                        unit: a.question.unit(),
                        numeric: &a.numeric,
                        rel_error: a.rel_error,
                        tolerance: a.tolerance,
                        equation: a.step.as_ref().map(|s| s.equation),
                        formula: a.step.as_ref().map(|s| s.formula()),
                        substituted: a.step.as_ref().map(|s| s.substituted()),
                        comparisons: &a.comparisons,
                    })
                    .collect(),
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let json = KeyJson {
        model: w.model.id(),
        seed: w.seed,
        regime: w.regime.id(),
        questions: w.questions.iter().map(|q| q.key()).collect(),
        students,
    };
    let mut bytes =
        serde_json::to_vec_pretty(&crate::results::Versioned::new(&json)).map_err(json_error)?;
    bytes.push(b'\n');
    Ok(bytes)
}
