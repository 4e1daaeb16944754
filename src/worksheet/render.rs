//! Rendering the worksheets: template contexts of already formatted strings and MathML, the
//! tera pages (worksheets and answer key, HTML and Markdown), the v(t) figures as files for
//! Markdown, and answer-key.json ([`super::json`]). Pure: everything in memory; the caller
//! writes the files.

use serde::Serialize;

use super::answer::{Answer, Comparison, Value};
use super::exercise::Exercise;
use super::json::key_json;
use super::question::{self, Kind, Question};
use super::{Student, Worksheets};
use crate::derivation::{self, Step};
use crate::error::Result;
use crate::models::{with_model, Model, Physics};
use crate::output::format::{rel, sig};
use crate::report::context::regime_words;
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

/// What the student is told about the model (the parameters follow in a table).
pub(crate) fn intro(model: Model) -> &'static str {
    fn of<M: Exercise>(_: &M) -> &'static str {
        M::INTRO
    }
    with_model!(&model, p => of(p))
}

/// The definitions of the model's [`Exercise::DEFINED`] symbols, `symbol = formula`, from the
/// worked steps of `case` (the formulas are the same for every student).
fn definitions(case: &Model) -> Vec<Math> {
    fn of<M: Exercise>(_: &M) -> &'static [&'static str] {
        M::DEFINED
    }
    let steps = super::answer::steps(case);
    with_model!(case, p => of(p))
        .iter()
        .filter_map(|symbol| steps.iter().find(|s| s.symbol == *symbol))
        .map(|s| math(&format!("{} = {}", s.symbol, s.formula)))
        .collect()
}

pub(crate) fn title(model: Model) -> &'static str {
    fn of<M: Exercise>(_: &M) -> &'static str {
        M::TITLE
    }
    with_model!(&model, p => of(p))
}

/// (LaTeX symbol, value as typed, unit) of a case's given parameters, in the order of the
/// sheet (an unset optional parameter is not shown).
fn parameters(case: &Model) -> Vec<(&'static str, f64, &'static str)> {
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
struct Math {
    mathml: String,
    tex: String,
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
    prompt: &'static str,
    /// The answer line: `symbol =` (empty for the regime).
    symbol: Option<Math>,
    unit: &'static str,
    /// The rules of the regimes (regime question only).
    rules: Vec<RuleCtx>,
}

#[derive(Clone, Debug, Serialize)]
struct RuleCtx {
    regime: &'static str,
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
    prompt: &'static str,
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

fn params_ctx(case: &Model) -> Vec<ParamCtx> {
    parameters(case)
        .into_iter()
        .map(|(symbol, value, unit)| ParamCtx {
            symbol: math(symbol),
            value: value.to_string(),
            unit: unit.to_string(),
        })
        .collect()
}

fn questions_ctx(model: Model, questions: &[&Question]) -> Vec<QuestionCtx> {
    questions
        .iter()
        .enumerate()
        .map(|(i, q)| QuestionCtx {
            number: i + 1,
            prompt: q.prompt,
            symbol: (!q.symbol().is_empty()).then(|| math(q.symbol())),
            unit: q.unit(),
            rules: match q.kind {
                Kind::Regime(_) => question::regime_rules(model)
                    .iter()
                    .map(|&(regime, condition)| RuleCtx {
                        regime: regime_words(regime.id()),
                        condition: math(condition),
                    })
                    .collect(),
                _ => Vec::new(),
            },
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

/// The apparatus of `case`, at rest at t = 0, labelled with the given values only.
fn sketch(case: &Model) -> String {
    with_model!(case, p => p.sketch_givens())
}

fn sheet_ctx(s: &Student) -> SheetCtx {
    SheetCtx {
        sketch_svg: sketch(&s.case),
        sketch_file: sketch_file(s.number),
        number: s.number,
        params: params_ctx(&s.case),
        figure_svg: s.figure.clone().unwrap_or_default(),
        figure_file: s
            .figure
            .as_ref()
            .map(|_| figure_file(s.number))
            .unwrap_or_default(),
    }
}

fn number(v: &Value, digits: usize, unit: &str) -> String {
    match v {
        Value::Number(x) => with_unit(sig(Some(*x), digits), unit),
        Value::Text(t) => regime_words(t).to_string(),
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
fn answer_ctx(i: usize, a: &Answer, steps: &[Step], shown: &mut Vec<&'static str>) -> AnswerCtx {
    let q = a.question;
    let mut working = Vec::new();
    if let Some(step) = &a.step {
        for s in derivation::working(steps, step) {
            if !shown.contains(&s.symbol) {
                shown.push(s.symbol);
                working.push(math(&s.worked_tex()));
            }
        }
        shown.push(step.symbol);
    }
    let worked = match (&a.step, q.kind) {
        (_, Kind::Regime(_)) => Some(math(&comparisons_tex(&a.comparisons))),
        (Some(step), _) => Some(math(&step.worked_tex())),
        (None, _) => None,
    };
    AnswerCtx {
        number: i + 1,
        prompt: q.prompt,
        working,
        worked,
        result: number(&a.value, ANSWER_DIGITS, q.unit()),
        numeric: number(&a.numeric, NUMERIC_DIGITS, q.unit()),
        rel_error: a.rel_error.map_or(String::new(), |e| rel(Some(e))),
        tolerance: a
            .tolerance
            .map_or(String::new(), |t| with_unit(sig(Some(t), 2), q.unit())),
    }
}

fn key_ctx(s: &Student) -> KeyCtx {
    let steps = super::answer::steps(&s.case);
    let mut shown = Vec::new();
    KeyCtx {
        number: s.number,
        params: params_ctx(&s.case),
        figure_svg: s.key_figure.clone().unwrap_or_default(),
        figure_file: s
            .key_figure
            .as_ref()
            .map(|_| key_figure_file(s.number))
            .unwrap_or_default(),
        answers: s
            .answers
            .iter()
            .enumerate()
            .map(|(i, a)| answer_ctx(i, a, &steps, &mut shown))
            .collect(),
    }
}

/// worksheets.pdf and answer-key.pdf: the HTML pages printed with headless Chromium at
/// `browser` (A4, one student per page). Nothing is written here.
pub fn pdf(w: &Worksheets, browser: &std::path::Path) -> Result<Vec<OutFile>> {
    render(w, &[Format::Html])?
        .into_iter()
        .filter(|f| f.path.extension().is_some_and(|e| e == "html"))
        .map(|f| {
            let name = f.path.display().to_string();
            let html = String::from_utf8_lossy(&f.bytes);
            let bytes = crate::handout::pdf::print(browser, &name, &html)?;
            Ok(OutFile::new(f.path.with_extension("pdf"), bytes))
        })
        .collect()
}

/// The worksheet files in `formats` (HTML: worksheets.html, answer-key.html; Markdown:
/// worksheets.md, answer-key.md, figures/*.svg) and answer-key.json.
pub fn render(w: &Worksheets, formats: &[Format]) -> Result<Vec<OutFile>> {
    let tera = templates(TEMPLATES)?;
    let mut ctx = tera::Context::new();
    ctx.insert("title", title(w.model));
    ctx.insert("intro", intro(w.model));
    let first = w.students.first().map_or(w.model, |s| s.case);
    ctx.insert("definitions", &definitions(&first));
    ctx.insert("regime", w.regime.id());
    ctx.insert("seed", &w.seed);
    ctx.insert("count", &w.students.len());
    ctx.insert("css", &format!("{CSS}{WORKSHEET_CSS}"));
    ctx.insert("version", env!("CARGO_PKG_VERSION"));
    ctx.insert("questions", &questions_ctx(w.model, &w.questions));
    let sheets: Vec<SheetCtx> = w.students.iter().map(sheet_ctx).collect();
    ctx.insert("sheets", &sheets);
    let keys: Vec<KeyCtx> = w.students.iter().map(key_ctx).collect();
    ctx.insert("keys", &keys);
    let mut files = Vec::new();
    for format in formats {
        for name in ["worksheets", "answer-key"] {
            let name = format!("{name}.{}", format.ext());
            files.push(OutFile::new(&name, page(&tera, &name, &ctx)?));
        }
        if *format == Format::Md {
            for s in &w.students {
                files.push(OutFile::new(sketch_file(s.number), sketch(&s.case)));
                if let Some(svg) = &s.figure {
                    files.push(OutFile::new(figure_file(s.number), svg.as_str()));
                }
                if let Some(svg) = &s.key_figure {
                    files.push(OutFile::new(key_figure_file(s.number), svg.as_str()));
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

    #[test]
    fn every_rule_and_question_symbol_renders_to_mathml() {
        for model in Model::defaults() {
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
                // pulldown-latex escapes the entity of `\ ` twice: no such spaces.
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
        for model in Model::defaults() {
            let d = definitions(&model);
            assert_eq!(
                d.len(),
                with_model!(&model, p => defined(p)),
                "{}",
                model.id()
            );
            assert!(d.iter().all(|m| !m.mathml.contains("merror")));
        }
    }
}
