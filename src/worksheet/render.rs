//! Rendering the worksheets: template contexts of already formatted strings and MathML, the
//! tera pages (worksheets and answer key, HTML and Markdown), the v(t) figures as files for
//! Markdown, and answer-key.json ([`super::json`]). Pure: everything in memory; the caller
//! writes the files.

use serde::Serialize;

use super::answer::{Answer, Comparison, Value};
use super::exercise::Exercise;
use super::figure;
use super::json::key_json;
use super::question::{self, Kind, Question};
use super::{Student, Worksheets};
use crate::derivation::{self, Step};
use crate::error::Result;
use crate::format::{figures, people, people_rel};
use crate::lang::phrases::Translator;
use crate::lang::{Catalogue, Lang};
use crate::models::{with_capability, with_model, Model, Physics};
use crate::report::context::regime_words;
use crate::report::figures::style::with_text;
use crate::report::math::mathml;
use crate::report::render::{page, templates, CSS};
use crate::report::{Format, OutFile};

const TEMPLATES: &[(&str, &str)] = &[
    (
        "worksheets.html",
        include_str!("../../templates/worksheets.html.tera"),
    ),
    (
        "answer-key.html",
        include_str!("../../templates/answer-key.html.tera"),
    ),
    (
        "worksheets.md",
        include_str!("../../templates/worksheets.md.tera"),
    ),
    (
        "answer-key.md",
        include_str!("../../templates/answer-key.md.tera"),
    ),
];
/// The worksheet's additions to the report's stylesheet (answer boxes, one student per page).
const WORKSHEET_CSS: &str = include_str!("../../templates/worksheet.css");
/// Significant figures of the answers, and of the integration beside them in the key.
const ANSWER_DIGITS: usize = 4;
const NUMERIC_DIGITS: usize = 10;

/// The definitions of the model's [`Exercise::DEFINED`] symbols, `symbol = formula` in LaTeX,
/// from the worked steps of `case` (the formulas are the same for every student).
pub(crate) fn definitions_tex(case: &Model) -> Vec<String> {
    fn of<M: Exercise>(_: &M) -> &'static [&'static str] {
        M::DEFINED
    }
    let steps = super::answer::steps(case);
    // A model without worksheets defines no symbols on a sheet (`generate` refuses it first).
    with_capability!(case, exercise, p => of(p), else &[])
        .iter()
        .filter_map(|symbol| steps.iter().find(|s| s.symbol == *symbol))
        .map(|s| format!("{} = {}", s.symbol, s.formula()))
        .collect()
}

fn definitions(case: &Model, words: &Words) -> Vec<Math> {
    definitions_tex(case)
        .iter()
        .map(|tex| words.math(tex))
        .collect()
}

/// (LaTeX symbol, value as typed, unit) of a case's given parameters, in the order of the
/// sheet (an unset optional parameter is not shown).
pub(crate) fn parameters(case: &Model) -> Vec<(&'static str, f64, &'static str)> {
    fn of<M: Physics>(p: &M) -> Vec<(&'static str, f64, &'static str)> {
        M::PARAMS
            .iter()
            .filter_map(|s| Some((s.tex, (s.get)(p)?, s.unit)))
            .collect()
    }
    with_model!(case, p => of(p))
}

/// A formula for both formats: MathML for HTML, LaTeX for Markdown.
#[derive(Clone, Debug, Serialize)]
pub(crate) struct Math {
    mathml: String,
    pub(crate) tex: String,
}

fn math(tex: &str) -> Math {
    Math {
        mathml: mathml(tex),
        tex: tex.to_string(),
    }
}

#[derive(Clone, Debug, Serialize)]
struct ParamCtx {
    symbol: Math,
    value: String,
    unit: String,
}

#[derive(Clone, Debug, Serialize)]
struct QuestionCtx {
    number: usize,
    prompt: String,
    /// The answer line: `symbol =` (empty for the regime).
    symbol: Option<Math>,
    unit: &'static str,
    /// The rules of the regimes (regime question only).
    rules: Vec<RuleCtx>,
}

#[derive(Clone, Debug, Serialize)]
struct RuleCtx {
    regime: String,
    condition: Math,
}

#[derive(Clone, Debug, Serialize)]
struct SheetCtx {
    number: u32,
    params: Vec<ParamCtx>,
    /// Inline SVG for HTML, file path for Markdown; empty without a figure.
    figure_svg: String,
    figure_file: String,
    /// The apparatus with the student's parameters, at rest at t = 0 (nothing of the answers):
    /// inline SVG and the file for Markdown.
    sketch_svg: String,
    sketch_file: String,
}

#[derive(Clone, Debug, Serialize)]
struct AnswerCtx {
    number: usize,
    prompt: String,
    /// The steps the answer uses, each worked out (`symbol = formula = numbers = result`),
    /// for partial credit.
    working: Vec<Math>,
    /// `symbol = formula = numbers = result` (closed forms), or the values compared (regime).
    worked: Option<Math>,
    /// The answer to 4 significant figures with its unit, or the regime.
    result: String,
    /// The exact integration's value (10 significant figures) or regime.
    numeric: String,
    rel_error: String,
    /// Reading tolerance (figure question), empty otherwise.
    tolerance: String,
}

#[derive(Clone, Debug, Serialize)]
struct KeyCtx {
    number: u32,
    params: Vec<ParamCtx>,
    /// v(t) from rest: inline SVG for HTML, file path for Markdown; empty without.
    figure_svg: String,
    figure_file: String,
    answers: Vec<AnswerCtx>,
}

fn with_unit(value: String, unit: &str) -> String {
    if unit.is_empty() {
        value
    } else {
        format!("{value} {unit}")
    }
}

/// The words of one language for one model's sheets.
pub(crate) struct Words {
    pub(crate) lang: Lang,
    /// The model, whose id names its section of the catalogue (`pulled-mass`, `woodpecker`).
    model: Model,
    pub(crate) catalogue: &'static Catalogue,
}

impl Words {
    pub(crate) fn new(lang: Lang, model: Model) -> Result<Self> {
        Ok(Self {
            lang,
            model,
            catalogue: lang.catalogue()?,
        })
    }

    /// A text of the model's section.
    pub(crate) fn model_text(&self, key: &str) -> Result<String> {
        self.catalogue
            .text(&format!("{}.{key}", self.model.id()), &[])
    }

    pub(crate) fn prompt(&self, q: &Question) -> Result<String> {
        self.model_text(&format!("questions.{}", q.key()))
    }

    /// The words of a regime id (the id itself if the catalogue has none).
    pub(crate) fn regime(&self, id: &str) -> String {
        self.catalogue
            .optional(&format!("regimes.{id}"))
            .map_or_else(|| regime_words(id).to_string(), str::to_string)
    }

    /// A rule's LaTeX with its connectives (`\text{ and }`, `\text{ or }`) in this language.
    pub(crate) fn rule(&self, condition: &str) -> Result<Math> {
        let mut tex = condition.to_string();
        for word in ["and", "or"] {
            let here = self.catalogue.text(&format!("sheet.{word}"), &[])?;
            tex = tex.replace(
                &format!(r"\text{{ {word} }}"),
                &format!(r"\text{{ {here} }}"),
            );
        }
        Ok(self.math(&tex))
    }

    fn math(&self, tex: &str) -> Math {
        Math {
            mathml: self.lang.mathml(tex),
            tex: self.lang.tex(tex),
        }
    }

    /// A worked step as formulas that a printed line wraps between (a whole step is often
    /// wider than an A4 column); the TeX stays one line.
    fn worked(&self, step: &Step) -> Math {
        let pieces = step.worked_pieces();
        Math {
            mathml: pieces
                .iter()
                .map(|p| self.lang.mathml(p))
                .collect::<Vec<_>>()
                .join(" "),
            tex: self.lang.tex(&pieces.join(" ")),
        }
    }

    pub(crate) fn number(&self, text: &str) -> String {
        self.lang.number(text)
    }
}

fn params_ctx(case: &Model, words: &Words) -> Vec<ParamCtx> {
    parameters(case)
        .into_iter()
        .map(|(symbol, value, unit)| ParamCtx {
            symbol: math(symbol),
            value: words.number(&value.to_string()),
            unit: unit.to_string(),
        })
        .collect()
}

fn questions_ctx(model: Model, questions: &[&Question], words: &Words) -> Result<Vec<QuestionCtx>> {
    questions
        .iter()
        .enumerate()
        .map(|(i, q)| {
            Ok(QuestionCtx {
                number: i + 1,
                prompt: words.prompt(q)?,
                symbol: (!q.symbol().is_empty()).then(|| math(q.symbol())),
                unit: q.unit(),
                rules: match q.kind {
                    Kind::Regime(_) => question::regime_rules(model)
                        .iter()
                        .map(|&(regime, condition)| {
                            Ok(RuleCtx {
                                regime: words.regime(regime.id()),
                                condition: words.rule(condition)?,
                            })
                        })
                        .collect::<Result<_>>()?,
                    _ => Vec::new(),
                },
            })
        })
        .collect()
}

fn figure_file(number: u32) -> String {
    format!("figures/student-{number:03}.svg")
}

fn key_figure_file(number: u32) -> String {
    format!("figures/student-{number:03}-speed.svg")
}

fn sketch_file(number: u32) -> String {
    format!("figures/student-{number:03}-apparatus.svg")
}

/// The apparatus of `case`, at rest at t = 0, labelled with the given values only, in the
/// words of `lang`.
fn sketch(case: &Model, lang: Lang) -> Result<String> {
    let svg = with_capability!(case, exercise, p => p.sketch_givens(),
        else return Err(case.missing(crate::models::Capability::Exercise)));
    Ok(Translator::new(lang)?.svg(&svg))
}

/// A sheet's context; `reads_figure`: a question reads the forces figure, drawn here.
fn sheet_ctx(s: &Student, words: &Words, reads_figure: bool) -> Result<SheetCtx> {
    let figure = if reads_figure {
        Some(figure::force_figure(&s.case, words.lang)?)
    } else {
        None
    };
    Ok(SheetCtx {
        sketch_svg: sketch(&s.case, words.lang)?,
        sketch_file: sketch_file(s.number),
        number: s.number,
        params: params_ctx(&s.case, words),
        figure_file: figure
            .as_ref()
            .map(|_| figure_file(s.number))
            .unwrap_or_default(),
        figure_svg: figure
            .map(|svg| {
                let t = |key: &str| words.catalogue.text(&format!("sheet.{key}"), &[]);
                Ok::<_, crate::error::Error>(with_text(&svg, &t("figure")?, &t("figure_caption")?))
            })
            .transpose()?
            .unwrap_or_default(),
    })
}

/// A value to `digits` figures (`× 10ⁿ`, never e-notation) with its unit, or a regime in words.
fn number(v: &Value, digits: usize, unit: &str, words: &Words) -> String {
    match v {
        Value::Number(x) => words.number(&with_unit(figures(Some(*x), digits), unit)),
        Value::Text(t) => words.regime(t),
    }
}

/// The values a regime inequality compares, in LaTeX.
fn comparisons_tex(c: &[Comparison]) -> String {
    c.iter()
        .map(|c| {
            format!(
                "{} = {}",
                c.symbol,
                crate::derivation::expr::number_tex(c.value)
            )
        })
        .collect::<Vec<_>>()
        .join(r",\quad ")
}

/// The answer's context; `shown` holds the symbols of the steps worked out in earlier answers
/// of the same key, which are not repeated.
fn answer_ctx(
    i: usize,
    a: &Answer,
    steps: &[Step],
    shown: &mut Vec<&'static str>,
    words: &Words,
) -> Result<AnswerCtx> {
    let q = a.question;
    let mut working = Vec::new();
    if let Some(step) = &a.step {
        for s in derivation::working(steps, step) {
            if !shown.contains(&s.symbol) {
                shown.push(s.symbol);
                working.push(words.worked(s));
            }
        }
        shown.push(step.symbol);
    }
    let worked = match (&a.step, q.kind) {
        (_, Kind::Regime(_)) => Some(words.math(&comparisons_tex(&a.comparisons))),
        (Some(step), _) => Some(words.worked(step)),
        (None, _) => None,
    };
    Ok(AnswerCtx {
        number: i + 1,
        prompt: words.prompt(q)?,
        working,
        worked,
        result: match (&a.value, q.kind) {
            (Value::Text(regime), Kind::Regime(_)) => {
                words.regime(question::regime_option(words.model, regime))
            }
            (value, _) => number(value, ANSWER_DIGITS, q.unit(), words),
        },
        numeric: match &a.numeric {
            Value::Number(x) => {
                words.number(&with_unit(people(Some(*x), NUMERIC_DIGITS), q.unit()))
            }
            other => number(other, NUMERIC_DIGITS, q.unit(), words),
        },
        rel_error: a
            .rel_error
            .map_or(String::new(), |e| words.number(&people_rel(Some(e)))),
        tolerance: a.tolerance.map_or(String::new(), |t| {
            words.number(&with_unit(figures(Some(t), 2), q.unit()))
        }),
    })
}

fn key_ctx(s: &Student, words: &Words) -> Result<KeyCtx> {
    let steps = super::answer::steps(&s.case);
    let mut shown = Vec::new();
    Ok(KeyCtx {
        number: s.number,
        params: params_ctx(&s.case, words),
        figure_svg: match &s.key_figure {
            Some(svg) => {
                let t = |key: &str| words.catalogue.text(&format!("sheet.{key}"), &[]);
                with_text(
                    &words.lang.svg_numbers(svg),
                    &t("speed")?,
                    &t("speed_caption")?,
                )
            }
            None => String::new(),
        },
        figure_file: s
            .key_figure
            .as_ref()
            .map(|_| key_figure_file(s.number))
            .unwrap_or_default(),
        answers: s
            .answers
            .iter()
            .enumerate()
            .map(|(i, a)| answer_ctx(i, a, &steps, &mut shown, words))
            .collect::<Result<_>>()?,
    })
}

/// Students per printed part. A class of up to this many gets worksheets.pdf and
/// answer-key.pdf; a larger one gets one pair per part (worksheets-001-100.pdf,
/// answer-key-001-100.pdf, …): the browser holds one part at a time (a 500-student key is
/// 13 MB of HTML and took 1.3-2.1 GB printed at once), and a part opens and prints quickly
/// where a 500-page PDF does not, and can be handed to one grader each.
pub const PDF_PART: usize = 100;

/// worksheets.pdf and answer-key.pdf (A4, one student per page), printed by one browser, in
/// parts of [`PDF_PART`] students.
pub fn pdf(w: &Worksheets, lang: Lang, browser: &std::path::Path) -> Result<Vec<OutFile>> {
    let mut printer = crate::handout::pdf::Printer::new(browser)?;
    let parts: Vec<&[super::Student]> = w.students.chunks(PDF_PART).collect();
    let mut files = Vec::new();
    for part in &parts {
        let sheets = Worksheets {
            model: w.model,
            seed: w.seed,
            regime: w.regime,
            questions: w.questions.clone(),
            students: part.to_vec(),
        };
        let html = render(&sheets, &[Format::Html], lang)?
            .into_iter()
            .filter(|f| f.path.extension().is_some_and(|e| e == "html"));
        for f in html {
            let name = f.path.display().to_string();
            let text = String::from_utf8_lossy(&f.bytes);
            let bytes = printer.print(&name, &text)?;
            let path = match (parts.len(), part.first(), part.last()) {
                (2.., Some(first), Some(last)) => {
                    let stem = f.path.file_stem().unwrap_or_default().to_string_lossy();
                    format!("{stem}-{:03}-{:03}.pdf", first.number, last.number).into()
                }
                _ => f.path.with_extension("pdf"),
            };
            files.push(OutFile::new(path, bytes));
        }
    }
    printer.close();
    Ok(files)
}

/// The worksheet files in `formats` (HTML: worksheets.html, answer-key.html; Markdown:
/// worksheets.md, answer-key.md, figures/*.svg) and answer-key.json, in the words of `lang`.
pub fn render(w: &Worksheets, formats: &[Format], lang: Lang) -> Result<Vec<OutFile>> {
    let tera = templates(TEMPLATES)?;
    let words = Words::new(lang, w.model)?;
    let c = words.catalogue;
    let mut ctx = tera::Context::new();
    ctx.insert("t", &c.section("sheet")?);
    ctx.insert("title", &words.model_text("title")?);
    ctx.insert("intro", &words.model_text("intro")?);
    let first = w.students.first().map_or(w.model, |s| s.case);
    ctx.insert("definitions", &definitions(&first, &words));
    let (count, seed) = (w.students.len().to_string(), w.seed.to_string());
    ctx.insert(
        "students_line",
        &c.text("sheet.students_seed", &[("count", &count), ("seed", &seed)])?,
    );
    ctx.insert(
        "key_line",
        &c.text(
            "sheet.students_regime_seed",
            &[
                ("count", &count),
                ("regime", &words.regime(w.regime.id())),
                ("seed", &seed),
            ],
        )?,
    );
    ctx.insert("regime", &words.regime(w.regime.id()));
    ctx.insert("seed", &w.seed);
    ctx.insert("css", &format!("{CSS}{WORKSHEET_CSS}"));
    ctx.insert("version", env!("CARGO_PKG_VERSION"));
    ctx.insert("questions", &questions_ctx(w.model, &w.questions, &words)?);
    let reads_figure = w
        .questions
        .iter()
        .any(|q| matches!(q.kind, Kind::ReadFigure(_)));
    let sheets = w
        .students
        .iter()
        .map(|s| sheet_ctx(s, &words, reads_figure))
        .collect::<Result<Vec<_>>>()?;
    ctx.insert("sheets", &sheets);
    let keys = w
        .students
        .iter()
        .map(|s| key_ctx(s, &words))
        .collect::<Result<Vec<_>>>()?;
    ctx.insert("keys", &keys);
    let mut files = Vec::new();
    for format in formats {
        for name in ["worksheets", "answer-key"] {
            let name = format!("{name}.{}", format.ext());
            files.push(OutFile::new(&name, page(&tera, &name, &ctx)?));
        }
        if *format == Format::Md {
            for ((s, sheet), key) in w.students.iter().zip(&sheets).zip(&keys) {
                files.push(OutFile::new(
                    sketch_file(s.number),
                    sheet.sketch_svg.as_str(),
                ));
                if !sheet.figure_svg.is_empty() {
                    files.push(OutFile::new(
                        figure_file(s.number),
                        sheet.figure_svg.as_str(),
                    ));
                }
                if s.key_figure.is_some() {
                    files.push(OutFile::new(
                        key_figure_file(s.number),
                        key.figure_svg.as_str(),
                    ));
                }
            }
        }
    }
    files.push(OutFile::new("answer-key.json", key_json(w)?));
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::derivation::unit_tex;
    use crate::models::Capability;

    #[test]
    fn every_rule_and_question_symbol_renders_to_mathml() {
        for model in Model::offering(Capability::Exercise) {
            let texts = question::regime_rules(model)
                .iter()
                .map(|r| r.1)
                .chain(question::catalogue(model).iter().map(|q| q.symbol()))
                .filter(|t| !t.is_empty());
            for tex in texts {
                let m = mathml(tex);
                assert!(
                    m.starts_with("<math") && !m.contains("merror"),
                    "{tex}: {m}"
                );
                // No entity escaped twice (`&amp;nbsp;` for `\ `).
                assert!(!m.contains("&amp;"), "{tex}: {m}");
            }
        }
        assert_eq!(unit_tex("m/s²").as_deref(), Some(r"\mathrm{m/s^{2}}"));
    }

    #[test]
    fn every_symbol_a_sheet_defines_is_a_worked_step() {
        fn defined<M: Exercise>(_: &M) -> usize {
            M::DEFINED.len()
        }
        for model in Model::offering(Capability::Exercise) {
            let d = definitions(&model, &Words::new(Lang::En, model).unwrap());
            assert_eq!(
                d.len(),
                with_capability!(&model, exercise, p => defined(p), else 0),
                "{}",
                model.id()
            );
            assert!(d.iter().all(|m| !m.mathml.contains("merror")));
        }
    }
}
