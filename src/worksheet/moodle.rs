//! The worksheet as a Moodle question bank: Moodle XML (`worksheets.moodle.xml`) and GIFT
//! (`worksheets.gift.txt`).
//!
//! One question category per worksheet question, holding one variant per student (that
//! student's parameters and answer): a quiz that draws one random question from each category
//! gives every student a variant, and the teacher's answer key maps variant to student.
//!
//! ```text
//! closed form, threshold, figure  →  numerical question: the answer, a tolerance of one unit
//!                                    in its third significant figure (the figure: the reading
//!                                    tolerance), the SI unit, the worked step as feedback
//! regime                          →  multiple choice: the inequalities that decide the regime
//! ```
//!
//! Both carry HTML with formulas as MathJax LaTeX `\( … \)` (Moodle's MathJax filter renders
//! them). XML embeds the v(t) figure as a file of its question; GIFT, which has no files,
//! leaves the figure question out, and escapes its syntax characters `~ = # { } :` (no formula
//! here holds `\n`, which GIFT would read as a line break).

use base64::Engine;
use serde::Serialize;

use super::answer::{Answer, Value};
use super::question::{self, Kind};
use super::render::{parameters, Words};
use super::{Student, Worksheets};
use crate::error::Result;
use crate::lang::Lang;
use crate::models::Model;
use crate::report::render::{page, template_error};
use crate::report::OutFile;

const TEMPLATES: &[(&str, &str)] = &[
    (
        "moodle.xml",
        include_str!("../../templates/moodle.xml.tera"),
    ),
    ("gift.txt", include_str!("../../templates/gift.txt.tera")),
];

/// The file name of the forces figure embedded in its question.
pub(super) const FIGURE_FILE: &str = "forces.svg";
/// Significant figures a student is asked to give; the tolerance is one unit in the last.
pub const ANSWER_FIGURES: i32 = 3;

/// The tolerance of a numerical answer `x` given to [`ANSWER_FIGURES`] significant figures: one
/// unit in the last (rounding, and intermediate results rounded too).
pub fn tolerance(x: f64) -> f64 {
    if x == 0.0 || !x.is_finite() {
        return 0.0;
    }
    10f64.powi(x.abs().log10().floor() as i32 - (ANSWER_FIGURES - 1))
}

/// One question variant (a student's) in a category (a question of the sheet).
#[derive(Serialize)]
pub(super) struct Variant {
    pub(super) name: String,
    /// The student whose variant it is.
    pub(super) student: u32,
    /// Question text, HTML.
    pub(super) html: String,
    /// The worked step, HTML.
    pub(super) feedback: String,
    /// Numerical: the answer, its tolerance and SI unit.
    pub(super) answer: String,
    pub(super) tolerance: String,
    pub(super) unit: &'static str,
    /// Numerical: the answer and its tolerance as numbers (SI).
    #[serde(skip)]
    pub(super) number: Option<(f64, f64)>,
    /// Multiple choice: the options.
    pub(super) choices: Vec<Choice>,
    /// The v(t) figure (file name, base64), XML only.
    pub(super) file: Option<(String, String)>,
}

#[derive(Serialize)]
pub(super) struct Choice {
    pub(super) html: String,
    pub(super) right: bool,
}

#[derive(Serialize)]
pub(super) struct Category {
    pub(super) path: String,
    pub(super) numerical: bool,
    pub(super) variants: Vec<Variant>,
}

/// A number as Moodle reads it: plain or with an exponent, shortest round trip.
fn moodle_number(x: f64) -> String {
    crate::error::short(x)
}

/// An answer or tolerance as GIFT and Moodle XML read it: the shortest decimal that reads
/// back the same, never in e-notation (which GIFT editors and previewers reject: `gift-pegjs`
/// parses `5.397e-3` as an error).
pub(super) fn answer_number(x: f64) -> String {
    format!("{x}")
}

fn params_html(case: &Model, words: &Words) -> String {
    let rows: String = parameters(case)
        .into_iter()
        .map(|(tex, value, unit)| {
            format!(
                "<tr><th scope=\"row\">\\({}\\)</th><td>{}</td><td>{}</td></tr>",
                tera::escape_html(tex),
                words.number(&moodle_number(value)),
                tera::escape_html(unit)
            )
        })
        .collect();
    format!("<table><tbody>{rows}</tbody></table>")
}

fn variant(w: &Worksheets, words: &Words, s: &Student, i: usize, a: &Answer) -> Result<Variant> {
    let c = words.catalogue;
    let intro = words.model_text("intro")?;
    let q = a.question;
    let n = ANSWER_FIGURES.to_string();
    let figures = match (q.kind, q.unit()) {
        (Kind::Regime(_), _) => String::new(),
        (_, "") => format!(" {}", c.text("moodle.figures", &[("n", &n)])?),
        (_, unit) => format!(
            " {}",
            c.text("moodle.figures_in", &[("n", &n), ("unit", unit)])?
        ),
    };
    let image = match q.kind {
        Kind::ReadFigure(_) => format!(
            "<p><img src=\"@@PLUGINFILE@@/{FIGURE_FILE}\" alt=\"{}\" width=\"640\"></p>",
            tera::escape_html(&c.text("moodle.figure_alt", &[])?)
        ),
        _ => String::new(),
    };
    // Every symbol the question and its rules use, defined in the question itself: a student
    // in Moodle sees no sheet.
    let defined: Vec<String> = super::render::definitions_tex(&s.case)
        .iter()
        .map(|tex| format!("\\({}\\)", tera::escape_html(&words.lang.tex(tex))))
        .collect();
    let html = format!(
        "<p>{}</p>{}<p>{}</p><p>{}{}</p>{image}",
        tera::escape_html(&intro),
        params_html(&s.case, words),
        defined.join("; "),
        tera::escape_html(&words.prompt(q)?),
        tera::escape_html(&figures),
    );
    let name = format!(
        "Q{} {} — {} {:03}",
        i + 1,
        q.key(),
        c.text("sheet.student", &[])?,
        s.number
    );
    let mut v = Variant {
        name,
        student: s.number,
        html,
        feedback: feedback(a, words)?,
        answer: String::new(),
        tolerance: String::new(),
        unit: q.unit(),
        number: None,
        choices: Vec::new(),
        file: None,
    };
    match (&a.value, q.kind) {
        (Value::Text(regime), Kind::Regime(_)) => {
            v.choices = question::regime_rules(w.model)
                .iter()
                .map(|&(r, condition)| {
                    Ok(Choice {
                        html: format!(
                            "{}: \\({}\\)",
                            tera::escape_html(&words.regime(r.id())),
                            tera::escape_html(&words.rule(condition)?.tex)
                        ),
                        right: r.id() == question::regime_option(w.model, regime),
                    })
                })
                .collect::<Result<_>>()?;
        }
        (Value::Number(x), kind) => {
            v.answer = answer_number(*x);
            let tol = match kind {
                Kind::ReadFigure(_) => a.tolerance.unwrap_or_else(|| tolerance(*x)),
                _ => tolerance(*x),
            };
            v.tolerance = answer_number(tol);
            v.number = Some((*x, tol));
            if let Kind::ReadFigure(_) = kind {
                let svg = super::figure::force_figure(&s.case, words.lang)?;
                let data = base64::engine::general_purpose::STANDARD.encode(svg);
                v.file = Some((FIGURE_FILE.to_string(), data));
            }
        }
        (Value::Text(t), _) => v.answer = t.clone(),
    }
    Ok(v)
}

/// The worked step (formula = numbers = result, or the values the regime inequalities
/// compare) and the exact integration that confirms it, in HTML.
fn feedback(a: &Answer, words: &Words) -> Result<String> {
    let unit = a.question.unit();
    let value = match &a.numeric {
        Value::Number(x) => {
            words.number(format!("{} {unit}", crate::format::sig(Some(*x), 10)).trim_end())
        }
        Value::Text(t) => words.regime(t),
    };
    let confirm = words
        .catalogue
        .text("moodle.integration_gives", &[("value", &value)])?;
    let worked = match &a.step {
        Some(step) => format!(
            "\\({}\\) ({} {})",
            tera::escape_html(&words.lang.tex(&step.worked_tex())),
            tera::escape_html(&words.catalogue.text("moodle.eq", &[])?),
            tera::escape_html(step.equation)
        ),
        None => {
            let compared = a
                .comparisons
                .iter()
                .map(|c| {
                    let value = crate::format::sig(Some(c.value), ANSWER_FIGURES as usize + 1);
                    format!("{} = {value}", c.symbol)
                })
                .collect::<Vec<_>>()
                .join(r",\quad ");
            format!("\\({}\\)", tera::escape_html(&words.lang.tex(&compared)))
        }
    };
    Ok(format!(
        "<p>{worked}</p><p>{}</p>",
        tera::escape_html(confirm.trim_end())
    ))
}

/// One category per question of the sheet, each with every student's variant (the QTI
/// package's question groups too).
pub(super) fn categories(w: &Worksheets, words: &Words) -> Result<Vec<Category>> {
    let title = words.model_text("title")?;
    w.questions
        .iter()
        .enumerate()
        .map(|(i, q)| {
            Ok(Category {
                path: format!(
                    "$course$/top/stickslip {title} (seed {})/Q{} {}",
                    w.seed,
                    i + 1,
                    q.key()
                ),
                numerical: !matches!(q.kind, Kind::Regime(_)),
                variants: w
                    .students
                    .iter()
                    .filter_map(|s| {
                        let a = s.answers.iter().find(|a| a.question == *q)?;
                        Some(variant(w, words, s, i, a))
                    })
                    .collect::<Result<_>>()?,
            })
        })
        .collect()
}

/// `worksheets.moodle.xml` and/or `worksheets.gift.txt` of the set, in the words of `lang`
/// (answers and tolerances keep `.`: Moodle reads them so).
pub fn render(w: &Worksheets, xml: bool, gift: bool, lang: Lang) -> Result<Vec<OutFile>> {
    let words = Words::new(lang, w.model)?;
    let mut tera = tera::Tera::default();
    // XML escaping: tera's HTML escape writes entities XML reads (`&#x27;`, `&#x2F;` …).
    tera.autoescape_on(vec![".xml"]);
    tera.register_filter("gift", gift_text);
    tera.add_raw_templates(TEMPLATES.iter().copied())
        .map_err(|e| template_error("moodle", &e))?;
    let mut ctx = tera::Context::new();
    ctx.insert("categories", &categories(w, &words)?);
    let mut out = Vec::new();
    if xml {
        out.push(OutFile::new(
            "worksheets.moodle.xml",
            page(&tera, "moodle.xml", &ctx)?,
        ));
    }
    if gift {
        out.push(OutFile::new(
            "worksheets.gift.txt",
            page(&tera, "gift.txt", &ctx)?,
        ));
    }
    Ok(out)
}

/// Tera filter `gift`: text safe in GIFT, its special characters escaped and on one line.
pub(crate) fn gift_text(
    value: &tera::Value,
    _: &std::collections::HashMap<String, tera::Value>,
) -> tera::Result<tera::Value> {
    let text = value
        .as_str()
        .map_or_else(|| value.to_string(), str::to_string);
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '~' | '=' | '#' | '{' | '}' | ':' => {
                out.push('\\');
                out.push(c);
            }
            '\n' | '\r' => out.push(' '),
            c => out.push(c),
        }
    }
    Ok(tera::Value::String(out))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn answers_and_tolerances_are_plain_decimals() {
        assert_eq!(answer_number(1e-5), "0.00001");
        assert_eq!(answer_number(5.397e-3), "0.005397");
        assert_eq!(answer_number(2500.0), "2500");
        assert_eq!(answer_number(-0.25), "-0.25");
    }

    #[test]
    fn tolerance_is_one_unit_in_the_third_figure() {
        assert_eq!(tolerance(0.1234), 0.001);
        assert_eq!(tolerance(5.397e-3), 1e-5);
        assert_eq!(tolerance(-2500.0), 10.0);
        assert_eq!(tolerance(0.0), 0.0);
    }
}
