//! The JSON Schemas of the types that serialize by hand, from the same data their `Serialize`
//! reads: the guide §14 `closed_form` objects from each model's registry (one property per key,
//! numbers with their unit and meaning), the regime ids from the enums' `ALL` lists. A leaf the
//! models call for their own `closed_form` (and that names no model); the list of documents is
//! [`crate::schema`].

use std::borrow::Cow;

use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde_json::{json, Value};

use crate::results::quantity::{Kind, Registry};

/// A string that is one of `ids` (deduplicated, in their order).
pub(crate) fn one_of<'a>(description: &str, ids: impl IntoIterator<Item = &'a str>) -> Schema {
    let mut list: Vec<&str> = Vec::new();
    for id in ids {
        if !list.contains(&id) {
            list.push(id);
        }
    }
    json_schema!({"type": "string", "description": description, "enum": list})
}

/// A number or null, described by `words` and `unit`.
fn number(words: &str, unit: &str) -> Value {
    let description = if unit.is_empty() {
        words.to_string()
    } else {
        format!("{words} ({unit})")
    };
    json!({"type": ["number", "null"], "description": description})
}

/// The guide §14 `closed_form` object of a registry: every key of the object required, numbers as
/// number-or-null, the `regime` key one of `regimes`, the other labels flags.
pub(crate) fn closed_form<K: Registry>(regimes: &[&str]) -> Schema {
    let mut properties = serde_json::Map::new();
    let mut required = Vec::new();
    for e in K::ENTRIES.iter().filter(|e| e.kind != Kind::Checked) {
        let q = &e.quantity;
        let value = match e.kind {
            Kind::Number => number(q.words, q.unit),
            _ if q.id == "regime" => {
                json!({"type": "string", "description": q.words, "enum": regimes})
            }
            _ => json!({"type": "boolean", "description": q.words}),
        };
        properties.insert(q.id.to_string(), value);
        required.push(q.id);
    }
    json_schema!({
        "type": "object",
        "properties": properties,
        "required": required,
        "additionalProperties": false,
    })
}

impl JsonSchema for crate::engine::IntegrationRegime {
    fn schema_name() -> Cow<'static, str> {
        "IntegrationRegime".into()
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        one_of(
            "Regime the exact integration shows (guide §14)",
            Self::ALL.iter().map(|r| r.json_id()),
        )
    }
}

impl JsonSchema for crate::results::quantity::AnyKey {
    fn schema_name() -> Cow<'static, str> {
        "QuantityKey".into()
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        json_schema!({"type": "string", "description": "A guide §14 closed-form key"})
    }
}

impl JsonSchema for crate::results::checks::Checked {
    fn schema_name() -> Cow<'static, str> {
        "CheckedQuantity".into()
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "type": "string",
            "description": "The quantity checked: a guide §14 closed-form key, or a quantity of the woodpecker's periodic orbit"
        })
    }
}

impl JsonSchema for crate::results::quantity::Value {
    fn schema_name() -> Cow<'static, str> {
        "QuantityValue".into()
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "description": "A number (SI; null where the expression is undefined), a flag or a regime id",
            "type": ["number", "null", "boolean", "string"]
        })
    }
}

impl JsonSchema for crate::results::summary::Power {
    fn schema_name() -> Cow<'static, str> {
        "Power".into()
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "type": "object",
            "properties": {
                "power": number("Pulled mass: driving power F v̄ on the settled orbit", "W"),
                "power_weight": number("Woodpecker: power of the weight W_S v̄ on the settled orbit", "W"),
                "power_friction": number("Friction dissipation measured on the run", "W"),
            },
            "required": ["power_friction"],
        })
    }
}
