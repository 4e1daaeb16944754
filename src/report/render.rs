//! Rendering the report: scenes → contexts (in parallel) → tera pages and SVG files, all in
//! memory; [`super::writer`] writes them.

use rayon::prelude::*;
use serde::Serialize;
use tera::Tera;

use super::context::{claim, scene_tables, FigureCtx, SceneCtx};
use super::figures::style::{with_text, Geometry};
use super::figures::{chart, map};
use super::scene::{Drawing, Figure, Part, Scene};
use super::writer::OutFile;
use crate::claims::{self, Claims, Sample};
use crate::error::{Error, Result};
use crate::models::{Capability, Model};

/// Output formats of the report.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// One self-contained HTML file per scene (inline SVG and CSS, MathML), plus an index.
    Html,
    /// GitHub-flavoured Markdown per scene, figures as SVG files beside it.
    Md,
}

impl Format {
    /// The file extension, also the suffix of the format's template names.
    pub fn ext(self) -> &'static str {
        match self {
            Format::Html => "html",
            Format::Md => "md",
        }
    }
}

const TEMPLATES: &[(&str, &str)] = &[
    // Partials shared with the handout (crate::handout).
    (
        "verification_table.html",
        include_str!("../../templates/verification_table.html.tera"),
    ),
    (
        "verification_table.md",
        include_str!("../../templates/verification_table.md.tera"),
    ),
    (
        "claims.html",
        include_str!("../../templates/claims.html.tera"),
    ),
    ("claims.md", include_str!("../../templates/claims.md.tera")),
    (
        "scene_body.html",
        include_str!("../../templates/scene_body.html.tera"),
    ),
    (
        "scene.html",
        include_str!("../../templates/scene.html.tera"),
    ),
    ("all.html", include_str!("../../templates/all.html.tera")),
    (
        "index.html",
        include_str!("../../templates/index.html.tera"),
    ),
    ("scene.md", include_str!("../../templates/scene.md.tera")),
    ("index.md", include_str!("../../templates/index.md.tera")),
];
/// The report's stylesheet (the handout adds its own print rules to it).
pub(crate) const CSS: &str = include_str!("../../templates/style.css");
const TITLE: &str = "stickslip: the paper's stick-slip models, verified";

/// Tera filter `cell`: text made safe for a Markdown table cell (pipes escaped, one line).
pub(crate) fn markdown_cell(
    value: &tera::Value,
    _: &std::collections::HashMap<String, tera::Value>,
) -> tera::Result<tera::Value> {
    Ok(tera::Value::String(
        filter_text(value).replace('|', "\\|").replace('\n', " "),
    ))
}

/// Tera filter `md`: text from the user (a scenario's title or description, a file name)
/// shown as literal text in Markdown: [`markdown_literal`].
pub(crate) fn markdown_text(
    value: &tera::Value,
    _: &std::collections::HashMap<String, tera::Value>,
) -> tera::Result<tera::Value> {
    Ok(tera::Value::String(markdown_literal(&filter_text(value))))
}

/// The text of a template value: a string as it is, anything else as JSON.
fn filter_text(value: &tera::Value) -> String {
    match value {
        tera::Value::String(s) => s.clone(),
        other => other.to_string(),
    }
}

/// `text` as literal Markdown on one line: HTML's `<`, `>` and `&` as entities (GitHub would
/// otherwise keep raw HTML such as `<img onerror=…>`), the characters that make inline markup
/// (emphasis, code, links, strike-through, table cells) backslash-escaped, as is a first
/// character that would start a heading or a list; line breaks become spaces and other
/// control characters are dropped.
pub fn markdown_literal(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for (i, c) in text.chars().enumerate() {
        match c {
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            '\\' | '`' | '*' | '_' | '[' | ']' | '|' | '~' => {
                out.push('\\');
                out.push(c);
            }
            '#' | '-' | '+' | '=' if i == 0 => {
                out.push('\\');
                out.push(c);
            }
            '\n' | '\r' | '\t' | '\u{2028}' | '\u{2029}' => out.push(' '),
            // Bidirectional overrides and isolates would reorder the page's text.
            '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}' => {}
            c if c.is_control() => {}
            c => out.push(c),
        }
    }
    out
}

/// The report's templates and partials plus `extra` ones (name, source).
pub(crate) fn templates(extra: &[(&str, &str)]) -> Result<Tera> {
    let mut tera = Tera::default();
    tera.autoescape_on(vec![".html"]);
    tera.register_filter("cell", markdown_cell);
    tera.register_filter("md", markdown_text);
    tera.add_raw_templates(TEMPLATES.iter().chain(extra).copied())
        .map_err(|e| template_error("(all)", &e))?;
    Ok(tera)
}

/// Template `name` rendered with `ctx`.
pub(crate) fn page(tera: &Tera, name: &str, ctx: &tera::Context) -> Result<String> {
    tera.render(name, ctx).map_err(|e| template_error(name, &e))
}

/// A template error with tera's whole cause chain on one line.
pub(crate) fn template_error(name: &str, e: &tera::Error) -> Error {
    // tera keeps the cause in the source chain.
    let mut reason = e.to_string();
    let mut source = std::error::Error::source(e);
    while let Some(s) = source {
        reason = format!("{reason}: {s}");
        source = s.source();
    }
    Error::Template {
        name: name.to_string(),
        reason,
    }
}

/// SVG of a drawing on the canvas `g`.
fn draw(id: &str, drawing: &Drawing, g: Geometry) -> Result<String> {
    let svg = match drawing {
        Drawing::Chart(c) => chart::line_chart_in(c, g),
        Drawing::Map(m) => map::category_map_in(m, g),
    };
    svg.map_err(|e| Error::Figure {
        id: id.to_string(),
        reason: e.to_string(),
    })
}

/// The first sentence of `text` (to the first ". " that does not end "Fig.", "Figs." or the
/// Italian "Figg."), the whole text if it has one.
pub(crate) fn first_sentence(text: &str) -> &str {
    text.match_indices(". ")
        .map(|(i, _)| &text[..=i])
        .find(|head| !["Fig.", "Figs.", "Figg."].iter().any(|f| head.ends_with(f)))
        .unwrap_or(text)
}

/// The paper's claims on a scene's set (the set given), none for a model without them.
pub(crate) fn scene_claims(setup: &Model) -> Result<Claims> {
    if setup.has(Capability::Claims) {
        claims::of(setup, &Sample::default())
    } else {
        Ok(Claims::default())
    }
}

/// The full context of a scene: tables, `figures` and its claims.
pub(crate) fn scene_context(
    scene: &Scene,
    claims: &Claims,
    figures: Vec<FigureCtx>,
) -> Result<SceneCtx> {
    let mut ctx = scene_tables(scene)?;
    ctx.figures = figures;
    ctx.claims = claims
        .claims
        .iter()
        .filter(|c| scene.claims.contains(&c.id))
        .map(claim)
        .collect();
    Ok(ctx)
}

/// `figures` drawn on the canvas `g`, each with its caption as the SVG's title and description.
pub(crate) fn figure_contexts(figures: &[Figure], g: Geometry) -> Result<Vec<FigureCtx>> {
    figures
        .par_iter()
        .map(|f| {
            Ok(FigureCtx {
                id: f.id.clone(),
                caption: f.caption.clone(),
                svg: with_text(
                    &draw(&f.id, &f.drawing, g)?,
                    first_sentence(&f.caption),
                    &f.caption,
                ),
                file: format!("figures/{}.svg", f.id),
            })
        })
        .collect()
}

#[derive(Serialize)]
struct IndexRow<'a> {
    id: &'a str,
    title: &'a str,
    why: &'a str,
    model: &'a str,
    closed_regime: &'a str,
    harmonic_regime: &'a str,
    passed: usize,
    total: usize,
    all_pass: bool,
}

impl<'a> IndexRow<'a> {
    fn of(c: &'a SceneCtx) -> Self {
        IndexRow {
            id: &c.id,
            title: &c.title,
            why: &c.why,
            model: &c.model,
            closed_regime: &c.closed_regime,
            harmonic_regime: &c.harmonic_regime,
            passed: c.checks_passed,
            total: c.checks_total,
            all_pass: c.all_pass,
        }
    }
}

/// A part of the reading path in the index: its heading, story and scenes.
#[derive(Serialize)]
struct IndexPart<'a> {
    heading: String,
    story: &'static str,
    scenes: Vec<IndexRow<'a>>,
}

/// A page's neighbour in the reading path.
#[derive(Serialize)]
struct Link<'a> {
    id: &'a str,
    title: &'a str,
}

impl<'a> Link<'a> {
    fn of(c: &'a SceneCtx) -> Self {
        Link {
            id: &c.id,
            title: &c.title,
        }
    }
}

/// A scene of the lecture notes, and the earlier scene with the same parameters whose tables
/// it shares.
#[derive(Serialize)]
struct NotesItem<'a> {
    scene: &'a SceneCtx,
    /// Verification rows left out (no numeric counterpart, or outside the regime).
    left_out: usize,
    shared: Option<Link<'a>>,
}

/// Teaching material written beside the report, linked from the index.
#[derive(Clone, Debug, Serialize)]
pub struct Material {
    /// Relative links from the HTML and the Markdown index.
    pub html: String,
    pub md: String,
    pub title: String,
    pub what: String,
    /// The answer key beside the material (HTML and Markdown links), if it has one.
    pub key: Option<(String, String)>,
}

/// The checks of `scenes` counted once per distinct parameter set (scenes that share a set
/// share its checks): (passed, total, distinct sets).
fn distinct_checks(scenes: &[Scene], contexts: &[SceneCtx]) -> (usize, usize, usize) {
    let mut seen: Vec<(&crate::models::Model, u32)> = Vec::new();
    let (mut passed, mut total) = (0, 0);
    for (s, c) in scenes.iter().zip(contexts) {
        let key = (&s.setup, s.periods);
        if !seen.contains(&key) {
            seen.push(key);
            passed += c.checks_passed;
            total += c.checks_total;
        }
    }
    (passed, total, seen.len())
}

/// Renders `scenes` in the given formats: pages, index and figure files.
pub fn render(scenes: &[Scene], formats: &[Format]) -> Result<Vec<OutFile>> {
    render_with(scenes, formats, &[])
}

/// [`render`], with the index linking `material` (handouts, worksheets, the study) written
/// beside the report.
pub fn render_with(
    scenes: &[Scene],
    formats: &[Format],
    material: &[Material],
) -> Result<Vec<OutFile>> {
    let tera = templates(&[])?;
    // Claims are computed once per distinct set.
    let mut setups: Vec<Model> = Vec::new();
    for s in scenes {
        if !setups.contains(&s.setup) {
            setups.push(s.setup);
        }
    }
    let all_claims: Vec<Claims> = setups.par_iter().map(scene_claims).collect::<Result<_>>()?;
    let figures: Vec<Vec<Figure>> = scenes
        .par_iter()
        .map(Scene::build_figures)
        .collect::<Result<_>>()?;
    let contexts: Vec<SceneCtx> = scenes
        .par_iter()
        .zip(&figures)
        .map(|(s, f)| {
            let i = setups.iter().position(|m| *m == s.setup).unwrap_or(0);
            scene_context(s, &all_claims[i], figure_contexts(f, Geometry::REPORT)?)
        })
        .collect::<Result<_>>()?;
    let version = env!("CARGO_PKG_VERSION");
    // The physics guide the pages link, beside them.
    let mut files = super::guide::files(formats, true)?;
    let page = |name: &str, ctx: &tera::Context| page(&tera, name, ctx).map(String::into_bytes);
    let parts: Vec<IndexPart> = super::scene::parts()
        .into_iter()
        .map(|(_, part)| part)
        .chain([Part::SCENARIOS])
        .map(|part| IndexPart {
            heading: part.heading(),
            story: part.story(),
            scenes: scenes
                .iter()
                .zip(&contexts)
                .filter(|(s, _)| s.part == part)
                .map(|(_, c)| IndexRow::of(c))
                .collect(),
        })
        .filter(|p| !p.scenes.is_empty())
        .collect();
    let (passed, total, sets) = distinct_checks(scenes, &contexts);
    let mut index = tera::Context::new();
    index.insert("title", TITLE);
    index.insert("version", version);
    index.insert("css", CSS);
    index.insert("parts", &parts);
    index.insert("material", material);
    index.insert("passed", &passed);
    index.insert("total", &total);
    index.insert("sets", &sets);
    index.insert("all_pass", &(passed == total));
    for format in formats {
        let ext = format.ext();
        files.push(OutFile::new(
            format!("index.{ext}"),
            page(&format!("index.{ext}"), &index)?,
        ));
        for (i, ctx) in contexts.iter().enumerate() {
            let mut c = tera::Context::new();
            c.insert("scene", ctx);
            c.insert("css", CSS);
            c.insert("version", version);
            c.insert("prev", &i.checked_sub(1).map(|j| Link::of(&contexts[j])));
            c.insert("next", &contexts.get(i + 1).map(Link::of));
            c.insert("shared", &None::<Link>);
            // The explorer beside the report has a preset for every built-in scene.
            let explorer = material.iter().any(|m| m.html == super::explorer::FILE);
            c.insert("explorer", &explorer.then_some(super::explorer::FILE));
            files.push(OutFile::new(
                format!("{}.{ext}", ctx.id),
                page(&format!("scene.{ext}"), &c)?,
            ));
        }
        match format {
            Format::Html => {
                // Each claim once, where it first concerns a scene.
                let mut shown: Vec<u8> = Vec::new();
                // Only the rows that compare a closed form with the integration; the others
                // (no counterpart, outside the regime) stay on the scene page.
                // The notes' figures on the column canvas, two to a row (or one beside its
                // caption): their words print at 8 pt or more (issue 28).
                let columns: Vec<Vec<FigureCtx>> = figures
                    .par_iter()
                    .map(|f| figure_contexts(f, Geometry::COLUMN))
                    .collect::<Result<_>>()?;
                let notes: Vec<(SceneCtx, usize)> = contexts
                    .iter()
                    .zip(columns)
                    .map(|(c, figures)| {
                        let mut c = c.clone();
                        c.figures = figures;
                        c.claims.retain(|claim| !shown.contains(&claim.id));
                        shown.extend(c.claims.iter().map(|claim| claim.id));
                        let rows = c.verification.len();
                        c.verification
                            .retain(|r| r.class == "pass" || r.class == "fail");
                        let left_out = rows - c.verification.len();
                        (c, left_out)
                    })
                    .collect();
                let items: Vec<NotesItem> = scenes
                    .iter()
                    .zip(&notes)
                    .enumerate()
                    .map(|(i, (s, (c, left_out)))| NotesItem {
                        scene: c,
                        left_out: *left_out,
                        shared: scenes[..i]
                            .iter()
                            .position(|e| e.setup == s.setup && e.periods == s.periods)
                            .map(|j| Link::of(&contexts[j])),
                    })
                    .collect();
                let mut all = tera::Context::new();
                all.insert("scenes", &items);
                all.insert("css", CSS);
                files.push(OutFile::new("all-scenes.html", page("all.html", &all)?));
            }
            Format::Md => {
                files.extend(
                    contexts
                        .iter()
                        .flat_map(|c| std::iter::once(&c.sketch).chain(&c.figures))
                        .map(FigureCtx::out_file),
                );
            }
        }
    }
    Ok(files)
}
