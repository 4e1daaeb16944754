//! The explorer page (`reports/explorer.html`, `stickslip explorer --out DIR`): one
//! self-contained HTML file in which sliders drive the engine itself, compiled to wasm32
//! (`src/explorer/engine.wasm`, built by `.ci/wasm`) and embedded in base64.
//!
//! ```text
//! registry (parameters, options, quantities), built-in scenes (presets), palette
//!        → page data (JSON)  ┐
//! engine.wasm (base64)       ├→ templates/explorer.html.tera → explorer.html
//! explorer.js, explorer.css  ┘
//! ```
//!
//! The page computes nothing itself: every number comes from the wasm exports of
//! [`crate::wasm`], which call the same functions as `stickslip eval … --json`. Names, units,
//! ranges and defaults come from the registry, serialised here; the script only lays them out.

use std::collections::BTreeMap;

use base64::Engine;
use serde::Serialize;

use super::figures::spec::Stroke;
use super::figures::style::{dash_pattern, CURVE_WIDTH, FILLS, PALETTE};
use super::render::{page, templates, Material, CSS};
use super::scene::Scene;
use super::writer::OutFile;
use crate::error::Result;
use crate::explore::{self, Apparatus, Explore, ExploredLaw, LawText};
use crate::models::param::{ParamSpec, Rule};
use crate::models::{with_capability, with_model, Capability, Model, Physics};
use crate::params::DEFAULT_PERIODS;

/// The engine, built by `.ci/wasm` (CI rebuilds it and fails if it differs).
const ENGINE: &[u8] = include_bytes!("../explorer/engine.wasm");
const TEMPLATE: &str = include_str!("../../templates/explorer.html.tera");
const SCRIPT: &str = include_str!("../../templates/explorer.js");
const STYLE: &str = include_str!("../../templates/explorer.css");
/// The file name of the page.
pub const FILE: &str = "explorer.html";
/// Cells per side of the regime map's first, coarse pass (shown within a moment of a slider's
/// pause); the page's workers then compute one cell per pixel of the map (400).
const MAP_CELLS: u32 = 40;
/// Friction coefficients on the sliders.
const MU_RANGE: (f64, f64) = (0.01, 1.5);
/// A positive parameter's slider spans its default divided and multiplied by this.
const DECADE: f64 = 10.0;
/// Slider positions between the ends.
const SLIDER_STEPS: f64 = 1000.0;

/// The index's link to the page.
pub fn material() -> Material {
    Material {
        html: FILE.to_string(),
        md: FILE.to_string(),
        title: "Explorer".to_string(),
        what: "move a slider and watch each model respond: the exact motion of its force \
               laws, the regime, every closed form against the integration, the regime map and \
               the apparatus animated (one file that works offline, from a USB stick)"
            .to_string(),
        key: None,
    }
}

/// Where the page is written: beside the report's index (which it then links), or alone.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Placement {
    InReport,
    Alone,
}

/// The page, with the built-in `scenes` as presets.
pub fn render(scenes: &[Scene], placement: Placement) -> Result<OutFile> {
    let mut models = Vec::new();
    for m in Model::offering(Capability::Explore) {
        with_capability!(&m, explore, p => models.push(model_data(p)), else ());
    }
    let data = PageData {
        models,
        presets: scenes
            .iter()
            .filter(|s| s.setup.has(Capability::Explore))
            .map(preset)
            .collect(),
        integration_regimes: explore::integration_regimes(),
        laws: [
            law("linear", "linearized law", 1, Stroke::Dashed),
            law("harmonic", "harmonic law", 0, Stroke::Solid),
        ],
        palette: PALETTE.iter().map(|c| hex(c.0, c.1, c.2)).collect(),
        fills: FILLS.iter().map(|c| hex(c.0, c.1, c.2)).collect(),
        periods: DEFAULT_PERIODS,
        shown: explore::SHOWN_PERIODS,
        samples: explore::SAMPLES,
        map_cells: MAP_CELLS,
        slider_steps: SLIDER_STEPS,
    };
    let json = serde_json::to_string(&data).map_err(|e| crate::error::Error::Template {
        name: FILE.to_string(),
        reason: e.to_string(),
    })?;
    let mut ctx = tera::Context::new();
    ctx.insert("version", env!("CARGO_PKG_VERSION"));
    ctx.insert("in_report", &(placement == Placement::InReport));
    ctx.insert("css", CSS);
    ctx.insert("style", STYLE);
    ctx.insert("script", &script_safe(&script(&data.models)));
    ctx.insert("data", &script_safe(&json));
    ctx.insert(
        "engine",
        &base64::engine::general_purpose::STANDARD.encode(ENGINE),
    );
    let tera = templates(&[("explorer.html", TEMPLATE)])?;
    Ok(OutFile::new(FILE, page(&tera, "explorer.html", &ctx)?))
}

/// Where the page's script takes the models' drawings.
const DRAWINGS_MARK: &str = "/* stickslip: the models' drawings */";

/// The page's script with each kind of apparatus drawing of `models` in place of
/// [`DRAWINGS_MARK`], once per kind, as `DRAWINGS[kind]`.
fn script(models: &[ModelData]) -> String {
    let mut drawings = BTreeMap::new();
    for m in models {
        drawings.insert(m.apparatus.kind, m.apparatus.drawing);
    }
    let mut inserted = String::new();
    for (kind, body) in drawings {
        inserted.push_str(&format!("  DRAWINGS[{kind:?}] = (() => {{\n"));
        for line in body.lines() {
            if !line.is_empty() {
                inserted.push_str("    ");
                inserted.push_str(line);
            }
            inserted.push('\n');
        }
        inserted.push_str("  })();\n");
    }
    SCRIPT.replacen(DRAWINGS_MARK, inserted.trim(), 1)
}

/// Text made safe inside a `<script>` element: no `</` (which could close it).
fn script_safe(text: &str) -> String {
    text.replace("</", "<\\/")
}

fn hex(r: u8, g: u8, b: u8) -> String {
    format!("#{r:02x}{g:02x}{b:02x}")
}

/// Everything the script needs besides the engine.
#[derive(Serialize)]
struct PageData {
    models: Vec<ModelData>,
    presets: Vec<Preset>,
    integration_regimes: Vec<LawText>,
    /// The curves' slots, linear then harmonic, as in the engine's curves: their styles (each
    /// model names the laws it fills, [`ModelData::laws`]).
    laws: [LawStyle; 2],
    palette: Vec<String>,
    fills: Vec<String>,
    /// Periods of the evaluation (that of `stickslip eval`) and of the curves.
    periods: u32,
    shown: u32,
    samples: usize,
    map_cells: u32,
    /// Slider positions between the ends of a range.
    slider_steps: f64,
}

/// How a law is drawn: the report's figures' colours and dashes.
#[derive(Serialize)]
struct LawStyle {
    id: &'static str,
    label: &'static str,
    color: String,
    dash: String,
    width: u32,
}

fn law(id: &'static str, label: &'static str, color: usize, stroke: Stroke) -> LawStyle {
    let c = PALETTE[color];
    LawStyle {
        id,
        label,
        color: hex(c.0, c.1, c.2),
        dash: dash_pattern(stroke, CURVE_WIDTH)
            .iter()
            .map(f64::to_string)
            .collect::<Vec<_>>()
            .join(","),
        width: CURVE_WIDTH,
    }
}

#[derive(Serialize)]
struct ModelData {
    id: &'static str,
    name: &'static str,
    about: &'static str,
    defaults_source: &'static str,
    position: &'static str,
    /// The laws the page shows for the model, and what its closed forms describe.
    laws: &'static [ExploredLaw],
    closed_forms: &'static str,
    /// The words of the regimes its integration summaries name beyond the engine's.
    regimes: Vec<LawText>,
    /// The apparatus as its sketch draws it: the animation draws the same.
    apparatus: Apparatus,
    params: Vec<ParamData>,
    choices: Vec<ChoiceData>,
    quantities: Vec<QuantityData>,
}

/// A numeric parameter as the page shows it, in the unit people think in (`unit`, `factor`
/// from SI).
#[derive(Serialize)]
struct ParamData {
    key: &'static str,
    symbol: &'static str,
    /// What it is, in words ("Static friction coefficient μs").
    words: String,
    unit: &'static str,
    factor: f64,
    /// The paper's value (display unit); `None` for an optional parameter left unset.
    default: Option<f64>,
    /// What an unset optional parameter stands for ("l/h").
    unset: &'static str,
    min: f64,
    max: f64,
    /// The slider moves on a logarithmic scale.
    log: bool,
}

#[derive(Serialize)]
struct ChoiceData {
    key: &'static str,
    help: &'static str,
    values: &'static [&'static str],
    default: &'static str,
}

#[derive(Serialize)]
struct QuantityData {
    id: &'static str,
    symbol: &'static str,
    unit: &'static str,
    equation: &'static str,
    tag: &'static str,
    words: &'static str,
}

/// A built-in scene as a preset: its model and every parameter (SI) and option.
#[derive(Serialize)]
struct Preset {
    id: String,
    title: String,
    model: &'static str,
    params: BTreeMap<&'static str, f64>,
    choices: BTreeMap<&'static str, &'static str>,
}

fn model_data<M: Explore>(p: &M) -> ModelData {
    ModelData {
        id: M::ID,
        name: M::NAME,
        about: M::ABOUT,
        defaults_source: M::DEFAULTS_SOURCE,
        position: M::POSITION,
        laws: M::LAWS,
        closed_forms: M::CLOSED_FORMS,
        regimes: M::SUMMARY_REGIMES
            .iter()
            .map(|&id| LawText {
                id,
                words: M::regime_words(id).unwrap_or(id),
            })
            .collect(),
        apparatus: M::apparatus(),
        params: M::PARAMS.iter().map(|s| param_data(s, p)).collect(),
        choices: M::CHOICES
            .iter()
            .map(|c| ChoiceData {
                key: c.key,
                help: c.help,
                values: c.values,
                default: (c.get)(p),
            })
            .collect(),
        quantities: M::quantities()
            .into_iter()
            .map(|q| QuantityData {
                id: q.id,
                symbol: q.symbol,
                unit: q.unit,
                equation: q.equation,
                tag: q.tag,
                words: q.words,
            })
            .collect(),
    }
}

fn param_data<P>(s: &ParamSpec<P>, p: &P) -> ParamData {
    let (unit, factor) = s.display;
    let default = (s.get)(p).map(|v| v * factor);
    let (min, max, log) = match (s.rule, default) {
        (Rule::StaticFriction | Rule::DynamicFriction, _) => (MU_RANGE.0, MU_RANGE.1, false),
        (Rule::Finite, Some(d)) => (-2.0 * d.abs(), 2.0 * d.abs(), false),
        (_, Some(d)) => (d / DECADE, d * DECADE, true),
        (_, None) => (1.0 / DECADE, DECADE, true),
    };
    // The help without its unit: "Pulling force F in N" → "Pulling force F".
    let words = s.help.split(" in ").next().unwrap_or(s.help).to_string();
    ParamData {
        key: s.key,
        symbol: s.symbol,
        words,
        unit,
        factor,
        default,
        unset: s.unset,
        min,
        max,
        log,
    }
}

fn preset(scene: &Scene) -> Preset {
    fn values<M: Physics>(
        p: &M,
    ) -> (
        BTreeMap<&'static str, f64>,
        BTreeMap<&'static str, &'static str>,
    ) {
        let params = M::PARAMS
            .iter()
            .filter_map(|s| Some((s.key, (s.get)(p)?)))
            .collect();
        let choices = M::CHOICES.iter().map(|c| (c.key, (c.get)(p))).collect();
        (params, choices)
    }
    let (params, choices) = with_model!(&scene.setup, p => values(p));
    Preset {
        id: scene.id.clone(),
        title: scene.title.clone(),
        model: scene.setup.id(),
        params,
        choices,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_kind_of_apparatus_drawing_is_inserted_once_in_place_of_the_mark() {
        assert_eq!(SCRIPT.matches(DRAWINGS_MARK).count(), 1);
        let page = render(&[], Placement::Alone).unwrap();
        let page = String::from_utf8(page.bytes).unwrap();
        assert!(!page.contains(DRAWINGS_MARK));
        let kinds: Vec<&str> = Model::offering(Capability::Explore)
            .iter()
            .map(|m| {
                let mut kind = "";
                with_capability!(m, explore, p => kind = apparatus_kind(p), else ());
                kind
            })
            .collect();
        assert!(kinds.len() >= 3, "{kinds:?}");
        for kind in kinds {
            let entry = format!("DRAWINGS[{kind:?}] = (() => {{");
            assert_eq!(page.matches(&entry).count(), 1, "{kind}");
            // The shared script names no apparatus: a new model's drawing stays in its folder.
            assert!(!SCRIPT.contains(kind), "templates/explorer.js names {kind}");
        }
    }

    fn apparatus_kind<M: Explore>(_: &M) -> &'static str {
        M::apparatus().kind
    }
}
