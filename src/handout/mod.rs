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

use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::claims::{self, Sample};
use crate::error::{Error, Result};
use crate::report::context::SceneCtx;
use crate::report::render::{claim_params, page, scene_context, templates, CSS};
use crate::report::{builtin_scenes, math, Format, OutFile, Scene};

mod figures;
pub mod pdf;
mod physics;

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

/// A line of the equation of motion, in symbols, with a sentence of physics.
#[derive(Clone, Debug, Serialize)]
pub struct MotionLine {
    pub mathml: String,
    pub tex: String,
    pub note: String,
}

/// One step of the chain: formula = numbers substituted = result, and why.
#[derive(Clone, Debug, Serialize)]
pub struct StepCtx {
    pub symbol: String,
    /// "(13)", "§1.4" …
    pub equation: String,
    /// "formula = substituted" as MathML (HTML) and LaTeX (Markdown).
    pub mathml: String,
    pub tex: String,
    /// The value with its unit, or why there is none.
    pub result: String,
    /// A sentence of physics.
    pub note: String,
    /// CSS class: "value" or "reason".
    pub class: String,
}

/// Everything the handout shows besides the report's scene context.
#[derive(Clone, Debug, Serialize)]
pub struct Handout {
    /// The report's context of the scene: parameters, regimes, the figures of the handout (in
    /// number order), the checked rows of the verification table, claims.
    pub scene: SceneCtx,
    /// The same figures as laid out on page 2: two columns.
    pub figure_columns: [Vec<figures::Numbered>; 2],
    /// The regime of the closed forms (linearized law) and the inequality that decides it.
    pub regime: String,
    pub regime_why: String,
    pub motion: Vec<MotionLine>,
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

/// The text up to the first full stop that ends a sentence (not "Fig. 6").
fn first_sentence(text: &str) -> &str {
    text.match_indices(". ")
        .map(|(i, _)| &text[..=i])
        .find(|head| !(head.ends_with("Fig.") || head.ends_with("Figs.")))
        .unwrap_or(text)
}

/// The handout of `scene`: context, figures and claims.
pub fn build(scene: &Scene) -> Result<Handout> {
    let (pulled, wood) = claim_params(scene);
    let claims = claims::evaluate(&pulled, &wood, &Sample::default())?;
    let with_figures = Scene {
        figures: figures::kinds(scene),
        ..scene.clone()
    };
    let mut ctx = scene_context(&with_figures, &claims)?;
    for f in &mut ctx.figures {
        f.caption = first_sentence(&f.caption).to_string();
    }
    let figure_columns = figures::columns(std::mem::take(&mut ctx.figures));
    let mut placed: Vec<&figures::Numbered> = figure_columns.iter().flatten().collect();
    placed.sort_by_key(|n| n.number);
    ctx.figures = placed.into_iter().map(|n| n.figure.clone()).collect();
    // The finding of each claim states its numbers; the list of them stays in the report.
    for c in &mut ctx.claims {
        c.numbers.clear();
    }
    let checked = ctx.verification.len();
    ctx.verification
        .retain(|r| r.class == "pass" || r.class == "fail");
    let unchecked = checked - ctx.verification.len();
    let (regime, regime_why) = ctx
        .regimes
        .first()
        .map(|r| (r.regime.clone(), r.why.clone()))
        .unwrap_or_default();
    let motion = physics::equation_of_motion(&scene.setup)
        .iter()
        .map(|(tex, note)| MotionLine {
            mathml: math::mathml(tex),
            tex: tex.to_string(),
            note: note.to_string(),
        })
        .collect();
    Ok(Handout {
        scene: ctx,
        figure_columns,
        regime,
        regime_why,
        motion,
        steps: Vec::new(),
        omitted: Vec::new(),
        unchecked,
    })
}

/// Renders the handout of `scene` in `formats` (HTML, Markdown with its SVG figures) and, with
/// a `browser`, prints the HTML to `<id>.pdf`. Nothing is written here.
pub fn render(scene: &Scene, formats: &[Format], browser: Option<&Path>) -> Result<Vec<OutFile>> {
    let handout = build(scene)?;
    let mut ctx = tera::Context::new();
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
            let pdf = pdf::print(browser, &name, &html)?;
            files.push(out(format!("{id}.pdf"), pdf));
        }
        if html_requested {
            files.push(out(format!("{id}.html"), html.into_bytes()));
        }
    }
    if formats.contains(&Format::Md) {
        files.push(out(
            format!("{id}.md"),
            page(&tera, "handout.md", &ctx)?.into_bytes(),
        ));
        for f in &handout.scene.figures {
            files.push(out(f.file.clone(), f.svg.clone().into_bytes()));
        }
    }
    Ok(files)
}

fn out(path: String, bytes: Vec<u8>) -> OutFile {
    OutFile {
        path: PathBuf::from(path),
        bytes,
    }
}
