//! The outputs of `stickslip check`: the terminal text, and with `--out` a page in the report's
//! style (`check.html`, `check.md`) and `check.json`. Pure: strings in, [`OutFile`]s out.

use std::fmt::Write as _;

use serde::Serialize;

use super::{Report, Sample, Verdict, STICKS};
use crate::error::{excerpt, Error, Result};
use crate::format::people;
use crate::models::{with_model, Model, Physics};
use crate::report::context::regime_words;
use crate::report::math::mathml;
use crate::report::render::{page, templates, CSS};
use crate::report::OutFile;

const TEMPLATES: &[(&str, &str)] = &[
    (
        "check.html",
        include_str!("../../templates/check.html.tera"),
    ),
    ("check.md", include_str!("../../templates/check.md.tera")),
];

fn rel(e: Option<f64>) -> String {
    e.map_or("—".to_string(), |e| people(Some(e), 2))
}

/// A value of the formula or the integration: `yes`/`no` for a condition.
fn value(r: &Report, v: Option<f64>, digits: usize) -> String {
    match (r.quantity == STICKS, v) {
        (true, Some(v)) => (if v > 0.5 { "yes" } else { "no" }).to_string(),
        (_, v) => people(v, digits),
    }
}

/// The verdict, and for an agreement its scope: the regimes where no set was compared are
/// named, as the agreement says nothing of them.
fn verdict(r: &Report) -> String {
    match r.verdict {
        Verdict::Agrees if !r.unmeasured_regimes.is_empty() => {
            let words: Vec<&str> = r
                .unmeasured_regimes
                .iter()
                .map(|id| regime_words(id))
                .collect();
            format!(
                "AGREES where compared (not compared in: {})",
                words.join("; ")
            )
        }
        Verdict::Agrees => "AGREES".to_string(),
        Verdict::Disagrees => "DISAGREES".to_string(),
        Verdict::NotCompared => "NOT COMPARED".to_string(),
    }
}

fn summary(r: &Report) -> String {
    let mut s = String::new();
    if let Some(regime) = &r.regime {
        let _ = write!(s, "Only sets in the regime: {}. ", regime_words(regime));
    }
    let _ = write!(
        s,
        "Of {} sets ({} packed against the regime boundaries), {} were compared; {} disagree.",
        r.samples, r.sample_near, r.compared, r.disagree
    );
    if r.compared > 0 {
        let _ = write!(
            s,
            " Relative error (on the quantity's own scale): largest {}, median {}; each set's \
             tolerance is the tool's own for this quantity there ({} at the given set).",
            rel(r.max_rel_error),
            rel(r.median_rel_error),
            people(Some(r.given.tolerance), 1)
        );
    }
    if !r.skipped.is_empty() {
        let reasons: Vec<String> = r
            .skipped
            .iter()
            .map(|k| format!("{} ({})", k.reason, k.sets))
            .collect();
        let _ = write!(s, " Not compared: {}.", reasons.join("; "));
    }
    s
}

fn given(r: &Report) -> String {
    let g = &r.given;
    let outcome = match (g.agrees, &g.skipped) {
        (Some(true), _) => "agrees",
        (Some(false), _) => "DISAGREES",
        (None, _) => "not compared",
    };
    let mut s = format!(
        "{}: formula {}, exact integration {}, relative error {}: {outcome}",
        regime_words(g.regime),
        value(r, g.formula, 10),
        value(r, g.numeric, 10),
        rel(g.rel_error)
    );
    if let Some(why) = &g.skipped {
        let _ = write!(s, " ({why})");
    }
    s.push('.');
    s
}

/// The report for the terminal.
pub fn text(r: &Report) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "read as: {} = {}   (LaTeX: {})",
        r.quantity,
        excerpt(&r.read_as.plain, 200),
        excerpt(&r.read_as.latex, 200)
    );
    let _ = writeln!(
        o,
        "stickslip check {}: {}",
        r.model,
        excerpt(&r.formula, 200)
    );
    let _ = writeln!(o, "given parameters, {}", given(r));
    let _ = writeln!(o, "sample (seed {}): {}", r.seed, summary(r));
    let _ = writeln!(o, "{}", verdict(r));
    let _ = writeln!(
        o,
        "\n{:>6} {:>9} {:>9} {:>10}  regime",
        "sets", "compared", "disagree", "max error"
    );
    for row in &r.by_regime {
        let _ = writeln!(
            o,
            "{:>6} {:>9} {:>9} {:>10}  {}",
            row.sets,
            row.compared,
            row.disagree,
            rel(row.max_rel_error),
            regime_words(row.regime)
        );
    }
    if !r.agrees && !r.worst.is_empty() {
        let _ = writeln!(
            o,
            "\nworst sets (formula, exact integration, relative error; parameters):"
        );
        for s in &r.worst {
            let _ = writeln!(o, "  {}", sample_line(r, s));
        }
    }
    if !r.nearest_counterexamples.is_empty() {
        let _ = writeln!(o, "\ncounterexamples nearest each regime boundary:");
        for s in &r.nearest_counterexamples {
            let _ = writeln!(o, "  {}", sample_line(r, s));
        }
    }
    o
}

/// One set on one line: the two values, the error, the boundary it was drawn against, the
/// parameters.
fn sample_line(r: &Report, s: &Sample) -> String {
    let params = serde_json::to_string(&s.params).unwrap_or_default();
    let near = s
        .near
        .as_ref()
        .map(|n| format!(" [{} × (1 {:+.1e})]", n.boundary, n.offset))
        .unwrap_or_default();
    format!(
        "{} vs {}, {}{near}: {}",
        value(r, s.formula, 8),
        value(r, s.numeric, 8),
        rel(s.rel_error),
        params
    )
}

#[derive(Serialize)]
struct RowCtx {
    words: &'static str,
    sets: usize,
    compared: usize,
    disagree: usize,
    max: String,
}

#[derive(Serialize)]
struct WorstCtx {
    formula: String,
    numeric: String,
    rel: String,
    regime: &'static str,
    near: String,
    params: Vec<String>,
}

#[derive(Serialize)]
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

/// (column head, value as typed) of a set's parameters.
fn params(case: &Model) -> Vec<(String, String)> {
    fn of<M: Physics>(p: &M) -> Vec<(String, String)> {
        M::PARAMS
            .iter()
            .filter_map(|s| {
                let v = (s.get)(p)?;
                let head = if s.unit.is_empty() {
                    s.symbol.to_string()
                } else {
                    format!("{} ({})", s.symbol, s.unit)
                };
                Some((head, people(Some(v), 4)))
            })
            .collect()
    }
    with_model!(case, p => of(p))
}

/// check.html, check.md and check.json.
pub fn render(r: &Report) -> Result<Vec<OutFile>> {
    let tera = templates(TEMPLATES)?;
    let mut ctx = tera::Context::new();
    let model = r.given.params;
    ctx.insert("r", r);
    let title = crate::worksheet::Lang::En
        .catalogue()?
        .text(&format!("{}.title", r.model), &[])?;
    ctx.insert("model", &title);
    ctx.insert("model_id", r.model);
    let named = &r.named;
    let tex = if named.tex.is_empty() {
        format!(r"\text{{{}}}", r.quantity.replace('_', r"\_"))
    } else {
        named.tex.clone()
    };
    ctx.insert("quantity_tex", &math(&tex));
    let words = if named.words.is_empty() {
        r.quantity.clone()
    } else {
        named.words.clone()
    };
    ctx.insert("quantity_words", &words);
    ctx.insert("formula", &math(&r.read_as.latex));
    ctx.insert("verdict", &verdict(r));
    ctx.insert("summary", &summary(r));
    ctx.insert("given", &given(r));
    let rows: Vec<RowCtx> = r
        .by_regime
        .iter()
        .map(|row| RowCtx {
            words: regime_words(row.regime),
            sets: row.sets,
            compared: row.compared,
            disagree: row.disagree,
            max: rel(row.max_rel_error),
        })
        .collect();
    ctx.insert("regimes", &rows);
    let worst: Vec<WorstCtx> = if r.agrees {
        Vec::new()
    } else {
        r.nearest_counterexamples
            .iter()
            .chain(&r.worst)
            .map(|s| worst_ctx(r, s))
            .collect()
    };
    ctx.insert(
        "param_heads",
        &params(&model).into_iter().map(|p| p.0).collect::<Vec<_>>(),
    );
    ctx.insert("worst", &worst);
    ctx.insert("css", CSS);
    ctx.insert("version", env!("CARGO_PKG_VERSION"));
    let json = serde_json::to_string_pretty(&crate::results::Versioned::new(r)).map_err(|e| {
        Error::Output {
            path: "check.json".to_string(),
            reason: e.to_string(),
        }
    })? + "\n";
    Ok(vec![
        OutFile::new("check.html", page(&tera, "check.html", &ctx)?),
        OutFile::new("check.md", page(&tera, "check.md", &ctx)?),
        OutFile::new("check.json", json),
    ])
}

fn worst_ctx(r: &Report, s: &Sample) -> WorstCtx {
    WorstCtx {
        formula: value(r, s.formula, 6),
        numeric: value(r, s.numeric, 6),
        rel: rel(s.rel_error),
        regime: regime_words(s.regime),
        near: s
            .near
            .as_ref()
            .map(|n| format!("{} × (1 {:+.1e})", n.boundary, n.offset))
            .unwrap_or_default(),
        params: params(&s.params).into_iter().map(|p| p.1).collect(),
    }
}
