//! The explorer's engine side: what the page (`stickslip explorer`, compiled to wasm32 in
//! [`crate::wasm`]) asks of the library, as plain functions that run and are tested natively.
//!
//! ```text
//! request (JSON: model, parameters, options)  →  Model (the registry's setters, validate())
//!     → evaluation: the same §7 JSON as `stickslip eval MODEL … --json` (same code, same bytes)
//!       + extras: the regime sentences and which closed forms describe the motion
//!     → curves: both laws sampled over a few periods (t, x, v, apparatus coordinate)
//!     → map: the regime of each cell of a coarse grid around the current parameters
//! ```
//!
//! A model answers the page through [`Explore`], implemented in its folder
//! (`src/models/<name>/explore.rs`).

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use crate::engine::{integrate, ForceLaw, IntegrationRegime, RunOptions};
use crate::error::{Error, Result};
use crate::models::param::invalid;
use crate::models::{with_model, LawKind, Model, Physics};
use crate::params::{validate_periods, DEFAULT_PERIODS};
use crate::results::quantity::Quantity;
use crate::results::Applicability;

/// Periods the page shows by default.
pub const SHOWN_PERIODS: u32 = 4;
/// Uniform samples per law and curve, before the event times are inserted: two pixels apart on
/// the page's widest plot, and cheap enough to redraw at every slider step.
pub const SAMPLES: usize = 480;
/// Largest number of samples or map cells per side a request may ask for.
const MAX_SAMPLES: usize = 20_000;
const MAX_CELLS: u32 = 400;
/// Numbers per curve sample: t (s), x (m), v (m/s), the apparatus coordinate (m).
pub const SAMPLE_WIDTH: usize = 4;

/// The closed forms' regime of an evaluation, for people.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RegimeText {
    /// The §7 id (`closed_form.regime`).
    pub id: &'static str,
    /// In plain words.
    pub words: &'static str,
    /// The inequality that decides it, with numbers.
    pub why: String,
}

/// One axis of a regime map: the parameter it sets and its range (SI).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct MapAxis {
    pub key: &'static str,
    pub range: (f64, f64),
}

/// What the explorer asks of a model beyond [`Physics`].
pub trait Explore: Physics {
    /// The model in a few words ("pulled mass").
    const NAME: &'static str;
    /// The symbol of the body's position in the figures ("x", "y_S").
    const POSITION: &'static str;
    /// The closed-form quantities of the model's registry, in its order.
    fn quantities() -> Vec<&'static Quantity>;
    /// The closed forms' regime in words with the inequality that decides it.
    fn regime(e: &Self::Evaluation) -> RegimeText;
    /// Which closed forms describe the motion (the others are greyed).
    fn applicability(e: &Self::Evaluation) -> &[Applicability];
    /// The apparatus' second coordinate at time t (m) under `law` (whose force law is
    /// `force_law`): what the animation moves besides the body.
    fn apparatus(&self, law: LawKind, force_law: &ForceLaw, t: f64) -> f64;
    /// The two parameters of the regime map (x, y) and their ranges around `self`.
    fn map_axes(&self) -> [MapAxis; 2];
    /// The map's categories under `law`, in the order of [`Explore::map_cell`]'s values:
    /// legend label and palette index of the fill.
    fn map_categories(law: LawKind) -> &'static [(&'static str, usize)];
    /// The category of the map cell where the x parameter is `x` and the y parameter `y`.
    fn map_cell(&self, law: LawKind, x: f64, y: f64) -> u8;
}

/// A parameter set as the page sends it: the model's defaults overridden by `params` (keys of
/// the model's registry, SI) and `choices`.
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Setup {
    pub model: String,
    #[serde(default)]
    pub params: BTreeMap<String, f64>,
    #[serde(default)]
    pub choices: BTreeMap<String, String>,
}

impl Setup {
    /// The model with these parameters (not yet validated: evaluating validates).
    pub fn model(&self) -> Result<Model> {
        let mut model = Model::from_id(&self.model).ok_or_else(|| Error::InvalidChoice {
            flag: "model",
            value: self.model.clone(),
            valid: Model::ids().join(", "),
        })?;
        for (key, &value) in &self.params {
            if !model.set(key, value) {
                return Err(Error::InvalidChoice {
                    flag: "parameter",
                    value: key.clone(),
                    valid: model.param_keys().join(", "),
                });
            }
        }
        for (key, value) in &self.choices {
            if !model.set_choice(key, value) {
                return Err(Error::InvalidChoice {
                    flag: "option",
                    value: format!("{key} = {value}"),
                    valid: "the options of the model and their values".to_string(),
                });
            }
        }
        Ok(model)
    }
}

/// The page's request for one parameter set.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Request {
    #[serde(flatten)]
    pub setup: Setup,
    /// Periods of the evaluation (that of `stickslip eval`: [`DEFAULT_PERIODS`]).
    #[serde(default = "default_periods")]
    pub periods: u32,
    /// Periods of the curves.
    #[serde(default = "default_shown")]
    pub shown: u32,
    /// Uniform samples per curve.
    #[serde(default = "default_samples")]
    pub samples: usize,
}

fn default_periods() -> u32 {
    DEFAULT_PERIODS
}

fn default_shown() -> u32 {
    SHOWN_PERIODS
}

fn default_samples() -> usize {
    SAMPLES
}

/// The page's request for rows `rows.0 .. rows.1` of a `cells` × `cells` regime map of `law`.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MapRequest {
    #[serde(flatten)]
    pub setup: Setup,
    pub law: String,
    pub cells: u32,
    pub rows: (u32, u32),
}

/// The regime sentence of one integrated law.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LawText {
    pub id: &'static str,
    pub words: &'static str,
}

/// What the page shows besides the §7 evaluation.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Extras<'a> {
    pub closed_form: RegimeText,
    pub applicability: &'a [Applicability],
}

/// One parameter set explored: the §7 JSON, the extras (JSON) and the curves.
#[derive(Clone, Debug, PartialEq)]
pub struct Explored {
    /// Exactly what `stickslip eval MODEL … --json` prints, without the final newline.
    pub evaluation: String,
    /// [`Extras`] as JSON.
    pub extras: String,
    /// Both laws, linear then harmonic: [n_linear, n_harmonic] then n_linear samples of
    /// [`SAMPLE_WIDTH`] numbers, then n_harmonic (a law that does not exist has none).
    pub curves: Vec<f64>,
}

/// A request parsed from JSON bytes.
pub fn parse<'a, T: Deserialize<'a>>(bytes: &'a [u8]) -> Result<T> {
    serde_json::from_slice(bytes).map_err(|e| Error::InvalidChoice {
        flag: "request",
        value: String::from_utf8_lossy(bytes).into_owned(),
        valid: e.to_string(),
    })
}

/// Evaluates, describes and samples one parameter set.
pub fn explore(request: &Request) -> Result<Explored> {
    let model = request.setup.model()?;
    with_model!(&model, p => explore_model(p, request))
}

fn explore_model<M: Explore>(p: &M, request: &Request) -> Result<Explored> {
    validate_periods(request.shown)?;
    if !(2..=MAX_SAMPLES).contains(&request.samples) {
        return Err(invalid(
            "samples",
            request.samples,
            format!("2 <= samples <= {MAX_SAMPLES}"),
        ));
    }
    let evaluation = p.evaluate(request.periods)?;
    let json = |e: serde_json::Error| Error::InvalidLaw(e.to_string());
    let extras = Extras {
        closed_form: M::regime(&evaluation),
        applicability: M::applicability(&evaluation),
    };
    let mut curves = vec![0.0; 2];
    for (i, law) in [LawKind::Linear, LawKind::Harmonic].into_iter().enumerate() {
        let Ok(force_law) = p.force_law(law) else {
            continue;
        };
        let opts = RunOptions {
            periods: request.shown,
            record_segments: true,
        };
        let run = integrate(&p.body(), &force_law, &opts)?;
        let end = f64::from(request.shown) * run.period;
        let samples = crate::engine::run::sample(&run, 0.0, end, request.samples);
        curves[i] = samples.len() as f64;
        for [t, x, v, _] in samples {
            curves.extend([t, x, v, p.apparatus(law, &force_law, t)]);
        }
    }
    Ok(Explored {
        evaluation: serde_json::to_string_pretty(&evaluation).map_err(json)?,
        extras: serde_json::to_string(&extras).map_err(json)?,
        curves,
    })
}

/// The axes and the legend of a map (JSON), for the page.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MapInfo {
    pub x: MapAxis,
    pub y: MapAxis,
    pub categories: &'static [(&'static str, usize)],
}

/// Rows `rows.0 .. rows.1` (from the bottom) of the regime map, each `cells` categories from
/// left to right, evaluated at the cell centres; and the map's axes and legend.
pub fn map(request: &MapRequest) -> Result<(MapInfo, Vec<u8>)> {
    let model = request.setup.model()?;
    model.validate()?;
    let law = match request.law.as_str() {
        "linear" => LawKind::Linear,
        "harmonic" => LawKind::Harmonic,
        other => {
            return Err(Error::InvalidChoice {
                flag: "law",
                value: other.to_string(),
                valid: "linear, harmonic".to_string(),
            })
        }
    };
    let n = request.cells;
    let (r0, r1) = request.rows;
    if !(1..=MAX_CELLS).contains(&n) || r0 > r1 || r1 > n {
        return Err(invalid(
            "cells",
            format!("{n} (rows {r0}..{r1})"),
            format!("1 <= cells <= {MAX_CELLS}, rows within them"),
        ));
    }
    with_model!(&model, p => Ok(map_rows(p, law, n, (r0, r1))))
}

fn map_rows<M: Explore>(p: &M, law: LawKind, n: u32, (r0, r1): (u32, u32)) -> (MapInfo, Vec<u8>) {
    let [x, y] = p.map_axes();
    let centre =
        |(lo, hi): (f64, f64), i: u32| lo + (hi - lo) * (f64::from(i) + 0.5) / f64::from(n);
    let cells = (r0..r1)
        .flat_map(|row| {
            let yv = centre(y.range, row);
            (0..n).map(move |col| p.map_cell(law, centre(x.range, col), yv))
        })
        .collect();
    let info = MapInfo {
        x,
        y,
        categories: M::map_categories(law),
    };
    (info, cells)
}

/// Every integration regime with its words (the page's names for the laws' regimes).
pub fn integration_regimes() -> Vec<LawText> {
    IntegrationRegime::ALL
        .iter()
        .map(|r| LawText {
            id: r.id(),
            words: r.words(),
        })
        .collect()
}
