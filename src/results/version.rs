//! The schema version of every JSON document the tool writes: one added top-level key,
//! `"schema_version"`, first in the object, beside the keys of guide §14 (which it never
//! renames or removes). Raised when a key is renamed, removed or changes meaning.

use serde::Serialize;

/// The key every JSON output carries at its top level.
pub const SCHEMA_KEY: &str = "schema_version";

/// The current version of the JSON outputs (a string, compared for equality).
pub const SCHEMA_VERSION: &str = "1";

/// `inner` serialised with `"schema_version"` first and its own keys after, in their order.
/// `inner` must serialise as an object (a struct or a map).
#[derive(Serialize)]
pub struct Versioned<'a, T: Serialize> {
    schema_version: &'static str,
    #[serde(flatten)]
    inner: &'a T,
}

impl<'a, T: Serialize> Versioned<'a, T> {
    /// `inner` with the current [`SCHEMA_VERSION`].
    pub fn new(inner: &'a T) -> Self {
        Versioned {
            schema_version: SCHEMA_VERSION,
            inner,
        }
    }
}

/// The schema of `inner`'s object with `"schema_version"` added as a required constant.
#[cfg(feature = "cli")]
impl<T: Serialize + schemars::JsonSchema> schemars::JsonSchema for Versioned<'_, T> {
    fn schema_name() -> std::borrow::Cow<'static, str> {
        T::schema_name()
    }

    fn json_schema(generator: &mut schemars::SchemaGenerator) -> schemars::Schema {
        let mut schema = T::json_schema(generator);
        if let Some(properties) = schema
            .ensure_object()
            .entry("properties")
            .or_insert_with(|| serde_json::Value::Object(Default::default()))
            .as_object_mut()
        {
            properties.insert(
                SCHEMA_KEY.to_string(),
                serde_json::json!({
                    "description": "Version of the JSON layout (raised when a key is renamed, removed or changes meaning).",
                    "const": SCHEMA_VERSION,
                }),
            );
        }
        if let Some(required) = schema
            .ensure_object()
            .entry("required")
            .or_insert_with(|| serde_json::Value::Array(Vec::new()))
            .as_array_mut()
        {
            required.insert(0, SCHEMA_KEY.into());
        }
        schema
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Serialize)]
    struct Two {
        b: f64,
        a: u32,
    }

    #[test]
    fn the_version_comes_first_and_the_keys_keep_their_order() {
        let text = serde_json::to_string(&Versioned::new(&Two { b: 0.1, a: 2 })).unwrap();
        assert_eq!(text, r#"{"schema_version":"1","b":0.1,"a":2}"#);
    }
}
