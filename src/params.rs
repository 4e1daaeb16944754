//! Input parameters: serde structs with the paper's values as defaults, validation that names
//! the rule, and scenario files (TOML).

use std::path::Path;

use serde::Deserialize;

use crate::error::{Error, Result};
use crate::models::param::invalid;
use crate::models::Model;

/// Standard gravity used throughout the paper (m/s²).
pub const G_STANDARD: f64 = 9.81;
/// Largest number of periods a run may ask for.
pub const MAX_PERIODS: u32 = 1_000_000;
/// Periods integrated unless asked otherwise (guide §4: 8–12).
pub const DEFAULT_PERIODS: u32 = 8;

/// Checks the number of periods to integrate: 1 ≤ periods ≤ 10⁶.
pub fn validate_periods(periods: u32) -> Result<()> {
    if (1..=MAX_PERIODS).contains(&periods) {
        Ok(())
    } else {
        Err(invalid(
            "periods",
            periods,
            format!("1 <= periods <= {MAX_PERIODS}"),
        ))
    }
}

/// `text` on one line: runs of white space (line breaks included) become one space, other
/// control characters are dropped.
pub fn one_line(text: &str) -> String {
    without_controls(text)
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ")
}

/// `text` without control characters other than line breaks and tabs, and without the
/// bidirectional overrides and isolates (U+202A–U+202E, U+2066–U+2069), which reorder what a
/// page or a terminal shows (a title that reads differently from its bytes).
fn without_controls(text: &str) -> String {
    text.chars()
        .filter(|c| !c.is_control() || matches!(c, '\n' | '\t'))
        .filter(|c| !matches!(c, '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}'))
        .collect()
}

/// A scenario file: a model, a title, optionally the number of periods, and the parameters
/// (missing ones take the model's defaults).
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scenario {
    /// The model, with its default parameters (the file's are in `params`).
    #[serde(deserialize_with = "model_by_id")]
    pub model: Model,
    pub title: String,
    #[serde(default)]
    pub description: String,
    pub periods: Option<u32>,
    #[serde(default)]
    pub params: toml::Table,
}

/// Largest input file read (a scenario, a `--formulas` file, tracked data): 16 MiB, some
/// thousand times the largest real one; `/dev/zero` or a FIFO that never ends is refused after
/// reading this much.
pub const MAX_INPUT_BYTES: u64 = 16 << 20;

/// The path that stands for standard input (`stickslip fit -`, `--scenario -`, `--formulas -`).
pub const STDIN: &str = "-";

/// The bytes of an input file (standard input for [`STDIN`]), at most [`MAX_INPUT_BYTES`]; the
/// error is a reason for a message naming the file and `flag`.
pub fn read_input(path: &Path, flag: &str) -> std::result::Result<Vec<u8>, String> {
    use std::io::Read;
    let source: Box<dyn Read> = if path == Path::new(STDIN) {
        Box::new(std::io::stdin().lock())
    } else {
        let file = std::fs::File::open(path).map_err(|e| e.to_string())?;
        if file.metadata().is_ok_and(|m| m.is_dir()) {
            return Err("is a folder, not a file".to_string());
        }
        Box::new(file)
    };
    let mut bytes = Vec::new();
    source
        .take(MAX_INPUT_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| e.to_string())?;
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(format!(
            "larger than {} MiB, the limit of a {flag} file",
            MAX_INPUT_BYTES >> 20
        ));
    }
    Ok(bytes)
}

/// [`read_input`] as UTF-8 text.
pub fn read_input_text(path: &Path, flag: &str) -> std::result::Result<String, String> {
    String::from_utf8(read_input(path, flag)?)
        .map_err(|_| "stream did not contain valid UTF-8".to_string())
}

impl Scenario {
    /// Reads and parses a scenario file (at most [`MAX_INPUT_BYTES`]).
    pub fn load(path: &Path) -> Result<Self> {
        let text = read_input_text(path, "--scenario").map_err(|reason| Error::Scenario {
            path: path.display().to_string(),
            reason,
        })?;
        Self::parse(&text, path)
    }

    /// Parses scenario text; `path` only names the file in errors.
    /// The title becomes one line and both texts lose their control characters (a NUL or an
    /// escape sequence must not reach a page or a terminal).
    pub fn parse(text: &str, path: &Path) -> Result<Self> {
        let mut scenario: Self = toml::from_str(text).map_err(|e| toml_error(&e, text, path))?;
        scenario.title = one_line(&scenario.title);
        scenario.description = without_controls(&scenario.description);
        // The `params` object of `eval --json` pasted as [params]: its `periods`.
        if let Some(value) = scenario.params.remove("periods") {
            let periods = value
                .as_integer()
                .and_then(|n| u32::try_from(n).ok())
                .ok_or_else(|| scenario_error(path, "[params]: periods must be a whole number"))?;
            if scenario.periods.is_some_and(|p| p != periods) {
                return Err(scenario_error(
                    path,
                    "periods is given twice with different values (top level and [params])",
                ));
            }
            scenario.periods = Some(periods);
        }
        Ok(scenario)
    }

    /// The model with the file's parameters (defaults for keys not given). The `params` object
    /// of `eval --json` is read as well: `omega_mode` is the TOML key `omega`, and the derived
    /// quantities (W or W_S, T, the value of ω, φ, λ, ζ0, δ0) must be those of the inputs.
    pub fn model_params(&self, path: &Path) -> Result<Model> {
        let mut table = self.params.clone();
        let mut derived = toml::Table::new();
        if let Some(mode) = table.remove("omega_mode") {
            if let Some(value) = table.remove("omega") {
                if !value.is_float() && !value.is_integer() {
                    return Err(scenario_error(
                        path,
                        "[params]: omega and omega_mode both name the definition of ω; give one",
                    ));
                }
                derived.insert("omega".to_string(), value);
            }
            table.insert("omega".to_string(), mode);
        }
        let derived_keys = self.model.derived_keys();
        // A number under a derived key (`omega = "bird"` is the input).
        for key in &derived_keys {
            let numeric = table
                .get(key.as_str())
                .is_some_and(|v| v.is_float() || v.is_integer());
            if let Some(value) = numeric.then(|| table.remove(key.as_str())).flatten() {
                derived.insert(key.clone(), value);
            }
        }
        let model = self.model.with_scenario_params(&table, path)?;
        let computed = model.derived_params();
        for (key, given) in &derived {
            let given = given
                .as_float()
                .or_else(|| given.as_integer().map(|n| n as f64));
            let expected = computed.get(key).and_then(serde_json::Value::as_f64);
            let agrees = match (given, expected) {
                (Some(a), Some(b)) => (a - b).abs() <= 1e-12 * a.abs().max(b.abs()),
                _ => false,
            };
            if !agrees {
                return Err(scenario_error(
                    path,
                    &format!(
                        "[params]: {key} is derived from the other parameters ({}); remove it or \
                         change the parameters it is derived from",
                        expected.map_or("undefined here".to_string(), |b| format!("here {b}"))
                    ),
                ));
            }
        }
        Ok(model)
    }

    /// A `[params]` table as the parameters `P` (defaults for keys not given).
    pub fn read_params<P: for<'de> Deserialize<'de>>(
        table: &toml::Table,
        path: &Path,
    ) -> Result<P> {
        P::deserialize(toml::Value::Table(table.clone())).map_err(|e| Error::Scenario {
            path: path.display().to_string(),
            reason: format!("[params]: {}", e.message().trim()),
        })
    }
}

/// The `model` key: a registered model id, read as that model with its defaults.
fn model_by_id<'de, D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Model, D::Error> {
    let id = String::deserialize(d)?;
    Model::from_id(&id).ok_or_else(|| {
        let ids: Vec<String> = Model::ids().iter().map(|m| format!("`{m}`")).collect();
        serde::de::Error::custom(format!(
            "unknown variant `{id}`, expected {}",
            match ids.as_slice() {
                [a, b] => format!("{a} or {b}"),
                _ => format!("one of {}", ids.join(", ")),
            }
        ))
    })
}

fn scenario_error(path: &Path, reason: &str) -> Error {
    Error::Scenario {
        path: path.display().to_string(),
        reason: reason.to_string(),
    }
}

/// One line from a TOML error: the line number and the message, without the source snippet.
fn toml_error(e: &toml::de::Error, text: &str, path: &Path) -> Error {
    let line = e
        .span()
        .map(|s| text[..s.start.min(text.len())].matches('\n').count() + 1);
    let reason = match line {
        Some(l) => format!("line {l}: {}", e.message().trim()),
        None => e.message().trim().to_string(),
    };
    Error::Scenario {
        path: path.display().to_string(),
        reason: reason.replace('\n', " "),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn periods_outside_the_range_are_refused() {
        assert!(validate_periods(0).is_err());
        assert!(validate_periods(MAX_PERIODS + 1).is_err());
        assert!(validate_periods(MAX_PERIODS).is_ok());
    }

    #[test]
    fn unknown_scenario_keys_are_refused_with_the_line() {
        let text = "model = \"pulled-mass\"\ntitle = \"x\"\ncolour = 3\n";
        let err = Scenario::parse(text, Path::new("s.toml")).unwrap_err();
        let msg = err.to_string();
        assert!(msg.contains("line 3") && msg.contains("colour"), "{msg}");
        assert!(!msg.contains('\n'));
        let text = "model = \"pulled-mass\"\ntitle = \"x\"\n[params]\nmu = 3\n";
        let sc = Scenario::parse(text, Path::new("s.toml")).unwrap();
        let err = sc.model_params(Path::new("s.toml")).unwrap_err();
        assert!(err.to_string().contains("unknown field `mu`"), "{err}");
    }
}
