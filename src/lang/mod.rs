//! The languages of worksheets, answer keys and handouts (`--lang`): one message catalogue per
//! language, `templates/lang/<code>.toml` with each model's words merged in (its folder's
//! `lang/<code>.toml`, [`crate::present::Present::words`]; every key of the English one in
//! each), the locale's decimal
//! sign for the numbers on the page, and ([`phrases`]) the tool's generated English text in the
//! other languages.

pub mod phrases;

use std::collections::BTreeMap;
use std::sync::OnceLock;

use crate::error::{Error, Result};

/// A language of the sheets.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum Lang {
    /// English.
    #[default]
    En,
    /// Italian: words from `it.toml`, decimal commas.
    It,
}

impl Lang {
    pub const ALL: [Lang; 2] = [Lang::En, Lang::It];

    /// The ISO 639-1 code (`lang` attribute, catalogue file name).
    pub fn code(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::It => "it",
        }
    }

    fn source(self) -> &'static str {
        match self {
            Lang::En => include_str!("../../templates/lang/en.toml"),
            Lang::It => include_str!("../../templates/lang/it.toml"),
        }
    }

    /// The catalogue of this language, parsed once.
    pub fn catalogue(self) -> Result<&'static Catalogue> {
        static PARSED: [OnceLock<std::result::Result<Catalogue, String>>; 2] =
            [OnceLock::new(), OnceLock::new()];
        let slot = &PARSED[self as usize];
        slot.get_or_init(|| {
            let mut table: toml::Table =
                toml::from_str(self.source()).map_err(|e| e.to_string())?;
            for words in model_words(self) {
                let words: toml::Table = toml::from_str(words).map_err(|e| e.to_string())?;
                merge(&mut table, words);
            }
            Ok(Catalogue { table })
        })
        .as_ref()
        .map_err(|reason| self.error(reason.clone()))
    }

    fn error(self, reason: String) -> Error {
        Error::Template {
            name: format!("templates/lang/{}.toml", self.code()),
            reason,
        }
    }

    /// A number as formatted (`0.06461`, `5.3 × 10⁻⁴`) with this language's decimal sign.
    pub fn number(self, text: &str) -> String {
        match self {
            Lang::En => text.to_string(),
            Lang::It => decimal_commas(text, ","),
        }
    }

    /// LaTeX with this language's decimal sign in its numbers (`0{,}2375`: braces keep TeX
    /// from spacing the comma as punctuation).
    pub fn tex(self, tex: &str) -> String {
        match self {
            Lang::En => tex.to_string(),
            Lang::It => decimal_commas(tex, "{,}"),
        }
    }
}

impl Lang {
    /// MathML of `tex` with this language's decimal sign: `0{,}25` comes out of the converter
    /// as two numbers around a comma operator, joined here into one number again.
    pub fn mathml(self, tex: &str) -> String {
        crate::report::math::mathml(&self.tex(tex)).replace("</mn><mo rspace=\"0\">,</mo><mn>", ",")
    }

    /// An SVG's numbers with this language's decimal sign, in text content only (never in
    /// attributes or style sheets); its words are left as they are.
    pub fn svg_numbers(self, svg: &str) -> String {
        phrases::map_text_nodes(svg, |text| self.number(text))
    }
}

/// The words of every model with a presentation in `lang` ([`crate::present::Present::words`]),
/// in the order of the registry.
fn model_words(lang: Lang) -> Vec<&'static str> {
    fn of<M: crate::present::Present>(_: &M, code: &str) -> Option<&'static str> {
        M::words(code)
    }
    crate::models::Model::offering(crate::models::Capability::Present)
        .iter()
        .filter_map(
            |m| crate::models::with_capability!(m, present, p => of(p, lang.code()), else None),
        )
        .collect()
}

/// Merges a model's words into a catalogue: its tables beside the shared ones, and the entries
/// of a table both have (`[phrases]`) into the catalogue's.
fn merge(table: &mut toml::Table, words: toml::Table) {
    for (key, value) in words {
        match (table.get_mut(&key), value) {
            (Some(toml::Value::Table(into)), toml::Value::Table(from)) => into.extend(from),
            (_, value) => {
                table.insert(key, value);
            }
        }
    }
}

/// `text` with every decimal point between two digits replaced by `comma`.
fn decimal_commas(text: &str, comma: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len() + 8);
    for (i, &c) in chars.iter().enumerate() {
        let between_digits = c == '.'
            && i > 0
            && chars[i - 1].is_ascii_digit()
            && chars.get(i + 1).is_some_and(char::is_ascii_digit);
        if between_digits {
            out.push_str(comma);
        } else {
            out.push(c);
        }
    }
    out
}

/// One language's words, by dotted path (`sheet.name`, `woodpecker.questions.t_slip_1`).
#[derive(Debug)]
pub struct Catalogue {
    table: toml::Table,
}

impl Catalogue {
    fn value(&self, path: &str) -> Option<&toml::Value> {
        let mut parts = path.split('.');
        let mut value = self.table.get(parts.next()?)?;
        for part in parts {
            value = value.get(part)?;
        }
        Some(value)
    }

    /// The text at `path`, with `{name}` placeholders filled from `args`.
    pub fn text(&self, path: &str, args: &[(&str, &str)]) -> Result<String> {
        let text = self
            .value(path)
            .and_then(toml::Value::as_str)
            .ok_or_else(|| missing(path))?;
        Ok(args.iter().fold(text.to_string(), |t, (name, value)| {
            t.replace(&format!("{{{name}}}"), value)
        }))
    }

    /// The phrase table (`[phrases]`: English with numbers masked → this language), empty
    /// when the catalogue has none (English).
    pub fn phrases(&self) -> &toml::Table {
        static EMPTY: OnceLock<toml::Table> = OnceLock::new();
        self.table
            .get("phrases")
            .and_then(toml::Value::as_table)
            .unwrap_or_else(|| EMPTY.get_or_init(toml::Table::new))
    }

    /// The text at `path` if the catalogue has one.
    pub fn optional(&self, path: &str) -> Option<&str> {
        self.value(path).and_then(toml::Value::as_str)
    }

    /// The list of texts at `path`.
    pub fn list(&self, path: &str) -> Result<Vec<String>> {
        self.value(path)
            .and_then(toml::Value::as_array)
            .and_then(|a| a.iter().map(|v| v.as_str().map(str::to_string)).collect())
            .ok_or_else(|| missing(path))
    }

    /// Every text of the section `name` by key (for the templates).
    pub fn section(&self, name: &str) -> Result<BTreeMap<String, String>> {
        self.table
            .get(name)
            .and_then(toml::Value::as_table)
            .map(|t| {
                t.iter()
                    .filter_map(|(k, v)| Some((k.clone(), v.as_str()?.to_string())))
                    .collect()
            })
            .ok_or_else(|| missing(name))
    }

    /// Every dotted path of a text or list in the catalogue.
    #[cfg(test)]
    fn paths(&self) -> Vec<String> {
        fn walk(prefix: &str, table: &toml::Table, out: &mut Vec<String>) {
            for (k, v) in table {
                let path = if prefix.is_empty() {
                    k.clone()
                } else {
                    format!("{prefix}.{k}")
                };
                match v.as_table() {
                    Some(t) => walk(&path, t, out),
                    None => out.push(path),
                }
            }
        }
        let mut out = Vec::new();
        walk("", &self.table, &mut out);
        out
    }
}

fn missing(path: &str) -> Error {
    Error::Template {
        name: "templates/lang".to_string(),
        reason: format!("no text `{path}` in the catalogue"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_catalogue_parses_and_has_every_key_of_the_english_one() {
        // The phrase tables are keyed by the English: not a key of en.toml.
        let paths = |lang: Lang| -> Vec<String> {
            let mut paths = lang.catalogue().unwrap().paths();
            paths.retain(|p| !p.starts_with("phrases."));
            paths
        };
        let english = paths(Lang::En);
        assert!(english.len() > 40, "{}", english.len());
        for lang in Lang::ALL {
            let mut paths = paths(lang);
            paths.sort();
            let mut want = english.clone();
            want.sort();
            assert_eq!(paths, want, "{}", lang.code());
        }
    }

    /// Each model with a presentation has its words in every language: its title (worksheets,
    /// `check`, the index) and the handout's headings, so that a missing section fails here and
    /// not in `stickslip report`.
    #[test]
    fn every_presented_model_has_its_words_in_every_language() {
        use crate::models::{Capability, Model};
        let models = Model::offering(Capability::Present);
        assert!(models.len() >= 2);
        for lang in Lang::ALL {
            let c = lang.catalogue().unwrap();
            for m in &models {
                let keys = ["title"]
                    .into_iter()
                    .chain(crate::handout::MODEL_WORDS)
                    .map(|k| format!("{}.{k}", m.id()));
                for path in keys {
                    assert!(c.optional(&path).is_some(), "{}: {path}", lang.code());
                }
            }
        }
        assert_eq!(model_words(Lang::En).len(), models.len());
        assert_eq!(model_words(Lang::It).len(), models.len());
    }

    /// Every text of the worksheets' sketches (the built-in sets and sheets drawn in every
    /// regime) is in the `[phrases]` table of every other language.
    #[test]
    fn worksheet_sketches_are_translated_entirely() {
        use crate::models::{with_capability, Capability, Model};
        use crate::worksheet::exercise::Exercise;
        use crate::worksheet::question::regimes;
        use crate::worksheet::{generate, Request};
        let mut cases: Vec<Model> = Model::offering(Capability::Exercise);
        for model in Model::offering(Capability::Exercise) {
            for regime in regimes(model) {
                let request = Request {
                    model,
                    students: 3,
                    seed: 11,
                    regime: Some(regime.id().to_string()),
                    questions: None,
                };
                let sheets = generate(&request, &indicatif::ProgressBar::hidden()).unwrap();
                cases.extend(sheets.students.iter().map(|s| s.case));
            }
        }
        let words = phrases::Translator::new(Lang::It).unwrap();
        for case in &cases {
            let givens =
                with_capability!(case, exercise, p => p.sketch_givens(), else String::new());
            let italian = words.svg(&givens);
            assert!(!italian.contains("Friction coefficients"), "{italian}");
        }
        assert_eq!(words.missing(), Vec::<String>::new());
    }

    #[test]
    fn placeholders_are_filled_and_decimals_follow_the_language() {
        let it = Lang::It.catalogue().unwrap();
        assert_eq!(
            it.text("sheet.students_seed", &[("count", "3"), ("seed", "7")])
                .unwrap(),
            "3 studenti, seme 7."
        );
        assert!(it.text("sheet.nothing", &[]).is_err());
        assert_eq!(Lang::It.number("0.06461 s"), "0,06461 s");
        assert_eq!(Lang::It.number("5.3 × 10⁻⁴"), "5,3 × 10⁻⁴");
        assert_eq!(Lang::En.number("0.5"), "0.5");
        assert_eq!(
            Lang::It.tex(r"0.1692 \times 0.3820 = 0.06461\,\mathrm{s}"),
            r"0{,}1692 \times 0{,}3820 = 0{,}06461\,\mathrm{s}"
        );
        let svg = "<svg><style>a { opacity: 0.5 }</style><text x=\"1.5\">slot in the table, \
                   m = 66.1 g</text></svg>";
        assert_eq!(
            Lang::It.svg_numbers(svg),
            "<svg><style>a { opacity: 0.5 }</style><text x=\"1.5\">slot in the table, m = \
             66,1 g</text></svg>"
        );
        // Not a decimal point: an ellipsis, a sentence end.
        assert_eq!(Lang::It.number("a. 1... 2"), "a. 1... 2");
    }
}
