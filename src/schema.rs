//! JSON Schemas (draft 2020-12) of every JSON document the tool writes, generated from the
//! serde types with schemars: `eval --json` of each model, `claims MODEL --json`, `check --json`
//! (and check.json), `fit --json` (and fit.json), a worksheet's answer-key.json and the bench's
//! results.json. `stickslip report` writes them to `schema/` beside the pages (reports/schema/
//! in the repository); tests/schema.rs checks that the committed files are what this module
//! generates and that real outputs of the command line validate against them.
//!
//! Most types derive `JsonSchema` next to their `Serialize` (under the `cli` feature, so the
//! core builds without schemars); the types that serialize by hand are described in
//! [`crate::results::schema`], which the models use too. This module only lists the documents:
//! it is not imported by any model.

use std::borrow::Cow;

use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde_json::json;

use crate::error::{Error, Result};
use crate::fit::FitTracked;
use crate::models::{with_capability, with_model, Capability, Model, Physics};
use crate::results::Versioned;

/// One JSON document of the tool and its schema.
pub struct Document {
    /// File stem under `schema/` (`eval-pulled-mass` → `schema/eval-pulled-mass.schema.json`).
    pub name: String,
    /// The commands and files that write it.
    pub written_by: String,
    pub schema: Schema,
}

/// The folder of the schema files in a report's output.
pub const FOLDER: &str = "schema";

/// The schema of `T` as written (with `schema_version` first), titled and described.
fn document<T: JsonSchema>(name: impl Into<String>, written_by: impl Into<String>) -> Document {
    let (name, written_by) = (name.into(), written_by.into());
    // The serialize contract: outputs, so `rename(serialize = …)` names and every field written.
    let mut schema = schemars::generate::SchemaSettings::draft2020_12()
        .for_serialize()
        .into_generator()
        .into_root_schema_for::<T>();
    schema.insert("title".to_string(), json!(name));
    schema.insert(
        "description".to_string(),
        json!(format!("Written by {written_by}.")),
    );
    Document {
        name,
        written_by,
        schema,
    }
}

/// `check --json` prints one report for one formula and an array of them for a `--formulas` file.
struct CheckOutput;

impl JsonSchema for CheckOutput {
    fn schema_name() -> Cow<'static, str> {
        "CheckOutput".into()
    }

    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        let one = generator.subschema_for::<Versioned<crate::check::Report>>();
        json_schema!({
            "anyOf": [one, {"type": "array", "items": one}]
        })
    }
}

/// Every JSON document of the tool, in a fixed order.
pub fn documents() -> Vec<Document> {
    /// `eval --json` of a model: its evaluation's own type, through the registry.
    fn eval<M: Physics>(_: &M) -> Document {
        document::<Versioned<M::Evaluation>>(
            format!("eval-{}", M::ID),
            format!("`stickslip eval {} --json` (guide §14)", M::ID),
        )
    }
    /// `fit --json` of a model with [`Capability::Fit`]: its outcome's own type, through the
    /// registry; `fit` for the first such model (the one `stickslip fit` fits), `fit-ID` after.
    fn fit<M: FitTracked>(_: &M, first: bool) -> Document {
        if first {
            document::<Versioned<M::Outcome>>(
                "fit",
                "`stickslip fit … --json` and fit.json of `fit --out`",
            )
        } else {
            document::<Versioned<M::Outcome>>(
                format!("fit-{}", M::ID),
                format!("`stickslip fit` of the {} model and its fit.json", M::ID),
            )
        }
    }
    let mut all: Vec<Document> = Model::defaults()
        .iter()
        .map(|m| with_model!(m, p => eval(p)))
        .collect();
    let fits = Model::offering(Capability::Fit)
        .iter()
        .enumerate()
        .filter_map(|(i, m)| with_capability!(m, fit, p => Some(fit(p, i == 0)), else None))
        .collect::<Vec<_>>();
    all.extend([
        document::<Versioned<crate::claims::Claims>>(
            "claims",
            "`stickslip claims MODEL --json`",
        ),
        document::<CheckOutput>(
            "check",
            "`stickslip check … --json` (one object for one formula, an array for --formulas) and check.json of `check --out`",
        ),
    ]);
    all.extend(fits);
    all.extend([
        document::<crate::worksheet::json::KeySchema>(
            "answer-key",
            "answer-key.json of `stickslip worksheet`",
        ),
        document::<Versioned<crate::bench::BenchResults>>(
            "bench-results",
            "results.json of `stickslip bench`",
        ),
    ]);
    all
}

/// The schema files, `schema/NAME.schema.json`, pretty-printed with a final newline.
pub fn files() -> Result<Vec<crate::report::OutFile>> {
    documents()
        .into_iter()
        .map(|d| {
            let path = format!("{FOLDER}/{}.schema.json", d.name);
            let text = serde_json::to_string_pretty(&d.schema).map_err(|e| Error::Template {
                name: path.clone(),
                reason: e.to_string(),
            })?;
            Ok(crate::report::OutFile::new(
                path,
                (text + "\n").into_bytes(),
            ))
        })
        .collect()
}
