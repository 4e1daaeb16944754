//! `stickslip handout`: one scene as a two-page lecture handout. Page 1: the set-up, the
//! equation of motion and the chain of formulas from it to the result, each with the numbers
//! substituted; page 2: figures, the verification table and the paper's claims for the scene.
//!
//! ```text
//! scene → report context (tables, figures, claims) + derivation steps + equation of motion
//!       → templates/handout.{html,md}.tera → files (+ PDF through headless Chromium, pdf.rs)
//! ```
//!
//! The numbers substituted into each formula come from [`crate::derivation`]; this module only
//! formats them and says which steps describe the scene's motion.

use std::path::Path;

use serde::Serialize;

use crate::error::{Error, Result};
use crate::lang::phrases::Translator;
use crate::lang::Lang;
use crate::models::{with_capability, Capability, Model};
use crate::present::Present;
use crate::report::context::{ClaimCtx, FigureCtx, SceneCtx};
use crate::report::render::{
    figure_contexts, first_sentence, page, scene_claims, scene_context, templates, CSS,
};
use crate::report::{builtin_scenes, Format, OutFile, Scene};
use physics::Note;

pub mod cdp;
mod layout;
pub mod pdf;
pub(crate) mod physics;

const TEMPLATES: &[(&str, &str)] = &[
    (
        "handout.html",
        include_str!("../../templates/handout.html.tera"),
    ),
    (
        "handout.md",
        include_str!("../../templates/handout.md.tera"),
    ),
];
const HANDOUT_CSS: &str = include_str!("../../templates/handout.css");

/// One step of the chain: symbol = formula = numbers substituted = result, and what it says.
#[derive(Clone, Debug, Serialize)]
pub struct StepCtx {
    /// The JSON key (guide §14) of the quantity ([`crate::derivation::StepKey::id`]).
    pub key: String,
    /// "(13)", "guide §7.5" …
    pub equation: String,
    /// The anchor in the guide of a section the equation cites, or empty.
    pub guide: String,
    /// That section's number (7.5), or empty.
    pub section: String,
    /// MathML of "symbol = formula", "= substituted" and "= result" (no result where the form
    /// does not apply), so that a long line wraps between them.
    pub pieces: Vec<String>,
    /// The whole line in LaTeX (Markdown).
    pub tex: String,
    /// Why the form does not describe this motion (shown instead of the result), or empty.
    pub reason: String,
    /// A label (definition) or a sentence of physics.
    pub note: String,
    /// CSS class: "label" or "numbers" (half a row), "sentence" (a whole row).
    pub class: String,
    /// A heading before the step, or empty.
    pub heading: String,
}

/// Everything the handout shows besides the report's scene context.
#[derive(Clone, Debug, Serialize)]
pub struct Handout {
    /// The report's context of the scene: parameters, regimes, the figures of the handout (in
    /// number order), the checked rows of the verification table, claims. The templates see
    /// it as `scene`, as the report's partials expect.
    #[serde(skip)]
    pub scene: SceneCtx,
    /// The same figures as laid out on page 2: two columns.
    pub figure_columns: [Vec<layout::Numbered>; 2],
    /// Claims of the scene that did not fit on page 2, named in one line.
    pub claims_brief: Vec<ClaimCtx>,
    /// The regime of the closed forms (linearized law) and the inequality that decides it.
    pub regime: String,
    pub regime_why: String,
    /// The chain of formulas that describe this motion.
    pub steps: Vec<StepCtx>,
    /// The formulas left out, one line per reason ("t_ST, v̄: why").
    pub omitted: Vec<String>,
    /// Closed forms of the verification table without a check (shown in the full report).
    pub unchecked: usize,
}

/// The built-in scene `arg`, or the scenario file at `arg` when it names a file or ends in
/// `.toml`.
pub fn find_scene(arg: &str) -> Result<Scene> {
    if let Some(scene) = builtin_scenes()?.into_iter().find(|s| s.id == arg) {
        return Ok(scene);
    }
    let path = Path::new(arg);
    if path.is_file() || path.extension().is_some_and(|e| e == "toml") {
        return Scene::from_file(path);
    }
    Err(Error::UnknownScene {
        id: arg.to_string(),
    })
}

/// The built-in scene ids, each with the first sentence of its caption (`--list`).
pub fn list() -> Result<String> {
    let scenes = builtin_scenes()?;
    let width = scenes.iter().map(|s| s.id.len()).max().unwrap_or(0);
    Ok(scenes
        .iter()
        .map(|s| format!("{:width$}  {}\n", s.id, first_sentence(&s.caption)))
        .collect())
}

/// The handout of `scene` in the language of `words`: context, figures and claims. Phrases
/// without a translation stay in English and are listed by `words` ([`Translator::missing`]).
pub fn build(scene: &Scene, words: &Translator) -> Result<Handout> {
    scene.setup.require(Capability::Present)?;
    let claims = scene_claims(&scene.setup)?;
    let with_figures = Scene {
        figures: layout::kinds(scene),
        ..scene.clone()
    };
    let mut ctx = scene_context(&with_figures, &claims, Vec::new())?;
    // The finding of each claim states its numbers; the list of them stays in the report.
    for c in &mut ctx.claims {
        c.numbers.clear();
    }
    let checked = ctx.verification.len();
    ctx.verification
        .retain(|r| r.class == "pass" || r.class == "fail");
    let unchecked = checked - ctx.verification.len();
    // Translated before the layout, which measures the text.
    translate_scene(&mut ctx, words);
    let mut drawings = with_figures.build_figures()?;
    // Labels translated before drawing, so that legends are sized for them.
    for f in &mut drawings {
        f.caption = words.text(&f.caption);
        for label in f.drawing.labels_mut() {
            *label = words.text(label);
        }
    }
    // The apparatus sketch (its free-body diagram drawn for a column's width) is always
    // placed: second, beside the first figure.
    let sketch = ctx.sketch.clone();
    let draw = |g| -> Result<Vec<FigureCtx>> {
        let mut figures = figure_contexts(&drawings, g)?;
        for f in &mut figures {
            f.caption = first_sentence(&f.caption).to_string();
            f.svg = words.lang().svg_numbers(&f.svg);
        }
        figures.insert(1.min(figures.len()), sketch.clone());
        Ok(figures)
    };
    let page = layout::fill(
        draw,
        ctx.verification.len(),
        std::mem::take(&mut ctx.claims),
    )?;
    let mut placed: Vec<&layout::Numbered> = page.columns.iter().flatten().collect();
    placed.sort_by_key(|n| n.number);
    ctx.figures = placed.into_iter().map(|n| n.figure.clone()).collect();
    ctx.claims = page.claims;
    let (regime, regime_why) = ctx
        .regimes
        .first()
        .map(|r| (words.text(&r.regime), words.text(&r.why)))
        .unwrap_or_default();
    let (steps, omitted) = chain(&scene.setup, words);
    Ok(Handout {
        scene: ctx,
        figure_columns: page.columns,
        claims_brief: page.brief,
        regime,
        regime_why,
        steps,
        omitted,
        unchecked,
    })
}

/// The words of the scene's context in the language of `words` (nothing for English):
/// title, captions, parameter names, the equation of motion's notes, the sketch, the
/// verification table's words and numbers, and the claims.
fn translate_scene(ctx: &mut SceneCtx, words: &Translator) {
    if words.lang() == Lang::En {
        return;
    }
    for text in [
        &mut ctx.title,
        &mut ctx.caption,
        &mut ctx.model,
        &mut ctx.description,
    ] {
        *text = words.text(text);
    }
    ctx.domain_note = words.text(&ctx.domain_note);
    ctx.sketch.caption = words.text(&ctx.sketch.caption);
    ctx.sketch.svg = words.svg(&ctx.sketch.svg);
    for p in &mut ctx.params {
        p.name = words.text(&p.name);
        p.value = words.text(&p.value);
    }
    for line in &mut ctx.motion {
        line.note = words.text(&line.note);
    }
    for r in &mut ctx.verification {
        for text in [
            &mut r.symbol,
            &mut r.closed_form,
            &mut r.numeric,
            &mut r.rel_error,
            &mut r.verdict,
        ] {
            *text = words.text(text);
        }
    }
    for c in &mut ctx.claims {
        for text in [
            &mut c.title,
            &mut c.paper_says,
            &mut c.finding,
            &mut c.verdict,
        ] {
            *text = words.text(text);
        }
    }
}

/// The chain of formulas of `setup`'s model: the steps of [`crate::derivation`] the handout
/// explains ([`physics::note`]), in order. A step that does not describe this motion shows its
/// reason in place of the result the first time that reason comes up; later steps with the
/// same reason, and definitions that do not apply, are left out and named in one line per
/// reason ("t_ST, v̄: why").
fn chain(setup: &Model, words: &Translator) -> (Vec<StepCtx>, Vec<String>) {
    let lang = words.lang();
    // A model without a presentation has no chain (`build` refuses it first).
    let steps = with_capability!(setup, present, p => p.derivation(), else Vec::new());
    let mut shown = Vec::new();
    let mut in_place: Vec<&str> = Vec::new();
    let mut left_out: Vec<(&str, Vec<&str>)> = Vec::new();
    // The heading of a step left out goes to the next step shown.
    let mut heading = None;
    for step in &steps {
        let Some((note, step_heading)) = physics::note(setup, step.key) else {
            continue;
        };
        heading = step_heading.or(heading);
        let (class, text) = match note {
            Note::Label(text) => ("label", text),
            Note::Sentence(text) => ("sentence", text),
            Note::Numbers => ("numbers", ""),
        };
        if let Some(reason) = step.reason.as_deref() {
            if !matches!(note, Note::Sentence(_)) || in_place.contains(&reason) {
                let symbol = step.key.symbol();
                match left_out.iter_mut().find(|(r, _)| *r == reason) {
                    Some((_, symbols)) => symbols.push(symbol),
                    None => left_out.push((reason, vec![symbol])),
                }
                continue;
            }
            in_place.push(reason);
        }
        // "symbol = formula", "= substituted", "= result": a long line wraps between pieces.
        let pieces = match note {
            Note::Numbers => std::iter::once(format!("{} = {}", step.symbol, step.substituted()))
                .chain(step.result_tex().map(|r| format!("= {r}")))
                .collect(),
            _ => step.worked_pieces(),
        };
        let (section, guide) = crate::report::guide::cite(step.equation).unwrap_or_default();
        shown.push(StepCtx {
            key: step.key.id().to_string(),
            equation: step.equation.to_string(),
            guide: guide.to_string(),
            section: section.to_string(),
            pieces: pieces.iter().map(|p| lang.mathml(p)).collect(),
            tex: lang.tex(&pieces.join(" ")),
            reason: words.text(step.reason.as_deref().unwrap_or_default()),
            note: words.text(text),
            class: class.to_string(),
            heading: words.text(heading.take().unwrap_or_default()),
        });
    }
    let omitted = left_out
        .into_iter()
        .map(|(reason, symbols)| format!("{}: {}", symbols.join(", "), words.text(reason)))
        .collect();
    (shown, omitted)
}

/// The keys of the handout's words that each model with a presentation gives in its section of
/// every language's catalogue (`[<id>]`, in its folder's `lang/<code>.toml`).
pub const MODEL_WORDS: [&str; 2] = ["verification", "regime_of_closed_form"];

/// Renders the handout of `scene` in `formats` (HTML, Markdown with its SVG figures) in the
/// language of `words` and, with a `browser`, prints the HTML to `<id>.pdf`. Nothing is written
/// here; the phrases left in English are in `words`.
pub fn render(
    scene: &Scene,
    formats: &[Format],
    browser: Option<&Path>,
    words: &Translator,
) -> Result<Vec<OutFile>> {
    let lang = words.lang();
    let handout = build(scene, words)?;
    let mut ctx = tera::Context::new();
    let catalogue = lang.catalogue()?;
    let mut shared = catalogue.section("handout")?;
    // The headings that name the law the closed forms describe are the model's words.
    for key in MODEL_WORDS {
        let path = format!("{}.{key}", scene.setup.id());
        shared.insert(key.to_string(), catalogue.text(&path, &[])?);
    }
    ctx.insert("words", &shared);
    ctx.insert("scene", &handout.scene);
    ctx.insert("handout", &handout);
    ctx.insert("css", &format!("{CSS}{HANDOUT_CSS}"));
    ctx.insert("version", env!("CARGO_PKG_VERSION"));
    let tera = templates(TEMPLATES)?;
    let id = &handout.scene.id;
    let mut files = Vec::new();
    let html_requested = formats.contains(&Format::Html);
    if html_requested || browser.is_some() {
        let html = page(&tera, "handout.html", &ctx)?;
        if let Some(browser) = browser {
            let name = format!("{id}.html");
            let mut printer = pdf::Printer::new(browser)?;
            let pdf = printer.print(&name, &html)?;
            printer.close();
            files.push(OutFile::new(format!("{id}.pdf"), pdf));
        }
        if html_requested {
            files.push(OutFile::new(format!("{id}.html"), html));
        }
    }
    if formats.contains(&Format::Md) {
        files.push(OutFile::new(
            format!("{id}.md"),
            page(&tera, "handout.md", &ctx)?,
        ));
        // The figures of page 2, the apparatus sketch among them.
        files.extend(handout.scene.figures.iter().map(FigureCtx::out_file));
    }
    Ok(files)
}
