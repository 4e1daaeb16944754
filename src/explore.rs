//! The explorer's engine side: what the page (`stickslip explorer`, compiled to wasm32 in
//! [`crate::wasm`]) asks of the library, as plain functions that run and are tested natively.
//!
//! ```text
//! request (JSON: model, parameters, options)  →  Model (the registry's setters, validate())
//!     → evaluation: the same guide §14 JSON as `stickslip eval MODEL … --json` (same code, same bytes)
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
use crate::models::{with_capability, with_model, LawKind, Model, Physics};
use crate::params::{validate_periods, DEFAULT_PERIODS};
use crate::results::quantity::Quantity;
use crate::results::{Applicability, Versioned};

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

/// One sample of a curve: t (s), x (m), v (m/s), the apparatus coordinate (m).
pub type Sample = [f64; SAMPLE_WIDTH];

/// [`Explore::curve`] of a model with a time-periodic force law: `law` integrated over
/// `shown` forcing periods, sampled, with the apparatus coordinate `apparatus(force law, t)`.
pub fn periodic_curve<M: Physics>(
    p: &M,
    law: LawKind,
    shown: u32,
    samples: usize,
    apparatus: impl Fn(&ForceLaw, f64) -> f64,
) -> Result<Option<Vec<Sample>>> {
    let Ok(force_law) = p.force_law(law) else {
        return Ok(None);
    };
    let opts = RunOptions {
        periods: shown,
        record_segments: true,
        dissipation: false,
    };
    let run = integrate(&p.body(), &force_law, &opts)?;
    let end = f64::from(shown) * run.period;
    Ok(Some(
        crate::engine::run::sample(&run, 0.0, end, samples)
            .into_iter()
            .map(|[t, x, v, _]| [t, x, v, apparatus(&force_law, t)])
            .collect(),
    ))
}

/// The closed forms' regime of an evaluation, for people.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct RegimeText {
    /// The JSON id (guide §14) (`closed_form.regime`).
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

/// A force law the page shows for a model: the slot of the curves it fills, its label, and
/// the member of the evaluation (guide §14) that summarises its exact integration.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ExploredLaw {
    /// The slot: "linear" or "harmonic" (the [`LawKind`] of the curve).
    pub id: &'static str,
    /// For people ("harmonic law").
    pub label: &'static str,
    /// The evaluation's member with the integration's summary ("harmonic", "integration").
    pub summary: &'static str,
}

/// The two force laws of a model whose closed forms are those of its linearized law, with its
/// harmonic law beside them (the pulled mass and the woodpecker): [`Explore::LAWS`].
pub const LINEARIZED_AND_HARMONIC: &[ExploredLaw] = &[
    ExploredLaw {
        id: "linear",
        label: "linearized law",
        summary: "linear",
    },
    ExploredLaw {
        id: "harmonic",
        label: "harmonic law",
        summary: "harmonic",
    },
];

/// What the page's animation draws for a model: the kind of drawing, the geometry of the
/// model's sketch it draws with (px), and the drawing itself: the model's script
/// (`src/models/<name>/explorer.js`), which the page inserts once per kind.
#[cfg(feature = "cli")]
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Apparatus {
    pub kind: &'static str,
    pub geometry: serde_json::Value,
    /// The body of a script function returning the drawing (see the models' explorer.js).
    #[serde(skip)]
    pub drawing: &'static str,
}

#[cfg(feature = "cli")]
impl Apparatus {
    /// The drawing `kind` with the sketch's `geometry` (a struct of numbers) and its script.
    pub fn new(kind: &'static str, geometry: &impl Serialize, drawing: &'static str) -> Self {
        Self {
            kind,
            geometry: serde_json::to_value(geometry).unwrap_or_default(),
            drawing,
        }
    }
}

/// What the explorer asks of a model beyond [`Physics`].
pub trait Explore: Physics {
    /// The model in a few words ("pulled mass").
    const NAME: &'static str;
    /// The symbol of the body's position in the figures ("x", "y_S").
    const POSITION: &'static str;
    /// The force laws the page shows, in the order of the curves' slots (linear, harmonic).
    const LAWS: &'static [ExploredLaw];
    /// What the closed forms describe, for the page's headings ("linearized law").
    const CLOSED_FORMS: &'static str;
    /// The regime ids the integration summaries name beyond the engine's
    /// [`IntegrationRegime`]s (their words are [`Physics::regime_words`]).
    const SUMMARY_REGIMES: &'static [&'static str];
    /// The closed-form quantities of the model's registry, in its order.
    fn quantities() -> Vec<&'static Quantity>;
    /// The closed forms' regime in words with the inequality that decides it.
    fn regime(e: &Self::Evaluation) -> RegimeText;
    /// Which closed forms describe the motion (the others are greyed).
    fn applicability(e: &Self::Evaluation) -> &[Applicability];
    /// The exact motion under `law` from the start over `shown` periods, sampled at
    /// `samples` uniform times and at its events: [t (s), x (m), v (m/s), the apparatus'
    /// second coordinate (m), what the animation moves besides the body] each; `None` when
    /// the model has no such law or it does not exist for these parameters.
    fn curve(&self, law: LawKind, shown: u32, samples: usize) -> Result<Option<Vec<Sample>>>;
    /// What the animation draws.
    #[cfg(feature = "cli")]
    fn apparatus() -> Apparatus;
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

/// The evaluation of any registered model, by its id and a parameter map (the model's
/// defaults overridden by `setup`, SI): the JSON of `stickslip eval MODEL … --json` as a value
/// (its objects' keys sorted, as `serde_json::Value` keeps them). What tests and bindings call
/// instead of listing the models.
pub fn evaluate(setup: &Setup, periods: u32) -> Result<serde_json::Value> {
    evaluate_model(&setup.model()?, periods)
}

/// [`evaluate`] of a model already built (validated here).
pub fn evaluate_model(model: &Model, periods: u32) -> Result<serde_json::Value> {
    fn of<M: Physics>(p: &M, periods: u32) -> Result<serde_json::Value> {
        serde_json::to_value(Versioned::new(&p.evaluate(periods)?))
            .map_err(|e| Error::InvalidLaw(e.to_string()))
    }
    with_model!(model, p => of(p, periods))
}

/// The text `stickslip eval MODEL … --json` prints for `model`, without the final newline
/// (keys in the order of the model's evaluation).
pub fn evaluate_json(model: &Model, periods: u32) -> Result<String> {
    fn of<M: Physics>(p: &M, periods: u32) -> Result<String> {
        serde_json::to_string_pretty(&Versioned::new(&p.evaluate(periods)?))
            .map_err(|e| Error::InvalidLaw(e.to_string()))
    }
    with_model!(model, p => of(p, periods))
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

/// What the page shows besides the evaluation (guide §14).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Extras<'a> {
    pub closed_form: RegimeText,
    pub applicability: &'a [Applicability],
    /// The period of the curves (s): the forcing's, or the cycle's of an autonomous model.
    pub period: f64,
    /// Periods (cycles) of the evaluation's integration.
    pub periods: u32,
}

/// One parameter set explored: the guide §14 JSON, the extras (JSON) and the curves.
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
    with_capability!(&model, explore, p => explore_model(p, request),
        else Err(model.missing(crate::models::Capability::Explore)))
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
        period: p.period(),
        periods: request.periods,
    };
    let mut curves = vec![0.0; 2];
    for (i, law) in [LawKind::Linear, LawKind::Harmonic].into_iter().enumerate() {
        let Some(samples) = p.curve(law, request.shown, request.samples)? else {
            continue;
        };
        curves[i] = samples.len() as f64;
        curves.extend(samples.into_iter().flatten());
    }
    Ok(Explored {
        evaluation: serde_json::to_string_pretty(&Versioned::new(&evaluation)).map_err(json)?,
        extras: serde_json::to_string(&extras).map_err(json)?,
        curves,
    })
}

/// What one call of the wasm exports leaves for the page ([`crate::wasm`]): the status (0 done,
/// 1 refused), the text out and the numbers out.
#[derive(Clone, Debug, PartialEq)]
pub struct Answer {
    pub status: u32,
    /// Done: `explore`: the evaluation (guide §14) JSON, a NUL byte, the extras JSON; `map`: the map's
    /// [`MapInfo`] as JSON. Refused: the one-line error message.
    pub text: Vec<u8>,
    /// Done: `explore`: [`Explored::curves`]; `map`: the cells' categories. Refused: empty.
    pub data: Vec<f64>,
}

impl Answer {
    fn of(outcome: Result<(Vec<u8>, Vec<f64>)>) -> Self {
        match outcome {
            Ok((text, data)) => Answer {
                status: 0,
                text,
                data,
            },
            Err(e) => Answer {
                status: 1,
                text: e.to_string().into_bytes(),
                data: Vec::new(),
            },
        }
    }
}

/// The answer to the page's `explore` call with the request `bytes` (JSON of [`Request`]).
pub fn answer_explore(bytes: &[u8]) -> Answer {
    Answer::of(parse::<Request>(bytes).and_then(|r| explore(&r)).map(|e| {
        let mut text = e.evaluation.into_bytes();
        text.push(0);
        text.extend(e.extras.into_bytes());
        (text, e.curves)
    }))
}

/// The answer to the page's `map` call with the request `bytes` (JSON of [`MapRequest`]).
pub fn answer_map(bytes: &[u8]) -> Answer {
    Answer::of(
        parse::<MapRequest>(bytes)
            .and_then(|r| map(&r))
            .and_then(|(info, cells)| {
                let text =
                    serde_json::to_vec(&info).map_err(|e| Error::InvalidLaw(e.to_string()))?;
                Ok((text, cells.into_iter().map(f64::from).collect()))
            }),
    )
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
    with_capability!(&model, explore, p => Ok(map_rows(p, law, n, (r0, r1))),
        else Err(model.missing(crate::models::Capability::Explore)))
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_answers_of_the_wasm_calls_are_laid_out_as_documented() {
        let done = answer_explore(br#"{"model": "pulled-mass"}"#);
        assert_eq!(done.status, 0);
        let text = String::from_utf8(done.text).unwrap();
        let (evaluation, extras) = text.split_once('\0').unwrap();
        let p = crate::models::pulled_mass::PulledMassParams::default();
        let want =
            serde_json::to_string_pretty(&Versioned::new(&p.evaluate(DEFAULT_PERIODS).unwrap()))
                .unwrap();
        assert_eq!(evaluation, want);
        assert!(serde_json::from_str::<serde_json::Value>(extras).is_ok());
        assert_eq!(
            done.data[0] as usize + done.data[1] as usize,
            (done.data.len() - 2) / 4
        );

        let refused = answer_explore(br#"{"model": "pulled-mass", "params": {"k": -1}}"#);
        assert_eq!(refused.status, 1);
        assert!(refused.data.is_empty());
        assert!(String::from_utf8(refused.text)
            .unwrap()
            .starts_with("invalid parameter k = -1"));

        let map =
            answer_map(br#"{"model": "woodpecker", "law": "linear", "cells": 3, "rows": [0, 3]}"#);
        assert_eq!((map.status, map.data.len()), (0, 9));
        let info: serde_json::Value = serde_json::from_slice(&map.text).unwrap();
        assert_eq!(info["y"]["key"], "z0");
        assert_eq!(answer_map(b"").status, 1);
    }

    fn request(json: &str) -> Request {
        parse(json.as_bytes()).unwrap()
    }

    #[test]
    fn the_evaluation_is_the_eval_commands_json_for_the_same_set() {
        let r = request(
            r#"{"model": "woodpecker", "params": {"mu_d": 0.3}, "choices": {"counterpart": "extremes"}}"#,
        );
        let got = explore(&r).unwrap();
        let mut p = crate::models::woodpecker::WoodpeckerParams {
            mu_d: 0.3,
            ..Default::default()
        };
        p.counterpart = crate::models::woodpecker::formula::Counterpart::Extremes;
        let want =
            serde_json::to_string_pretty(&Versioned::new(&p.evaluate(DEFAULT_PERIODS).unwrap()))
                .unwrap();
        assert_eq!(got.evaluation, want);
        let extras: serde_json::Value = serde_json::from_str(&got.extras).unwrap();
        // Phase I's halt threshold is 0.513 here: the slips merge.
        assert_eq!(extras["closed_form"]["id"], "double_slip_no_halt");
        let why = extras["closed_form"]["why"].as_str().unwrap();
        assert!(
            why.starts_with("μd = 0.3 < μd,HALT(I) = 0.51260062;"),
            "{why}"
        );
        assert!(extras["applicability"].as_array().unwrap().len() > 10);
    }

    #[test]
    fn curves_hold_both_laws_over_the_shown_periods_in_time_order() {
        let got = explore(&request(
            r#"{"model": "pulled-mass", "shown": 2, "samples": 50}"#,
        ))
        .unwrap();
        let c = &got.curves;
        let (lin, har) = (c[0] as usize, c[1] as usize);
        assert!(lin >= 50 && har >= 50, "{lin} {har}");
        assert_eq!(c.len(), 2 + SAMPLE_WIDTH * (lin + har));
        let period = crate::models::pulled_mass::PulledMassParams::default().period();
        for law in [&c[2..2 + SAMPLE_WIDTH * lin], &c[2 + SAMPLE_WIDTH * lin..]] {
            let t: Vec<f64> = law.chunks(SAMPLE_WIDTH).map(|s| s[0]).collect();
            assert_eq!(t[0], 0.0);
            assert!((t[t.len() - 1] - 2.0 * period).abs() < 1e-12);
            assert!(t.windows(2).all(|w| w[0] <= w[1]));
            assert!(law.iter().all(|x| x.is_finite()));
        }
    }

    #[test]
    fn the_belts_answer_is_eval_belt_json_with_its_motion_in_one_slot() {
        let done = answer_explore(br#"{"model": "belt", "params": {"mu_d": 0.3}}"#);
        assert_eq!(done.status, 0, "{}", String::from_utf8_lossy(&done.text));
        let text = String::from_utf8(done.text).unwrap();
        let (evaluation, extras) = text.split_once('\0').unwrap();
        let mut model = Model::from_id("belt").unwrap();
        assert!(model.set("mu_d", 0.3));
        // What `stickslip eval belt --mu-d 0.3 --json` prints, without its final newline.
        assert_eq!(evaluation, evaluate_json(&model, DEFAULT_PERIODS).unwrap());
        let extras: serde_json::Value = serde_json::from_str(extras).unwrap();
        let p = crate::models::belt::BeltParams {
            mu_d: 0.3,
            ..Default::default()
        };
        let c = crate::models::belt::formula::evaluate(&p);
        assert_eq!(extras["period"], c.period);
        assert_eq!(extras["closed_form"]["id"], "stick_slip");
        // No linear law; the spring's law in the harmonic slot over the shown cycles.
        let d = &done.data;
        let n = d[1] as usize;
        assert_eq!((d[0], d.len()), (0.0, 2 + SAMPLE_WIDTH * n));
        let samples: Vec<&[f64]> = d[2..].chunks(SAMPLE_WIDTH).collect();
        let last = samples[n - 1];
        assert!((last[0] - f64::from(SHOWN_PERIODS) * c.period).abs() < 1e-12);
        for s in &samples {
            let (t, x, v, belt) = (s[0], s[1], s[2], s[3]);
            assert_eq!(belt, p.v_b * t);
            // Carried from x = 0 until x_s, then between the cycle's extremes.
            if t <= c.first_slip_time {
                assert!((x - p.v_b * t).abs() <= 1e-15 && v == p.v_b, "{s:?}");
            }
            assert!(
                x <= c.x_max * (1.0 + 1e-12) && x >= c.x_min - 1e-12 * c.x_max,
                "{s:?}"
            );
            assert!(v <= p.v_b * (1.0 + 1e-12) && v >= c.v_min - 1e-12, "{s:?}");
        }
    }

    #[test]
    fn a_missing_linear_law_has_no_curve_but_the_harmonic_one_does() {
        // z0 ≤ −d0: the spring never changes sign, the zeros counterpart is undefined.
        let r = request(r#"{"model": "woodpecker", "params": {"z0": -0.012}}"#);
        let got = explore(&r).unwrap();
        assert_eq!(got.curves[0], 0.0);
        assert!(got.curves[1] > 0.0);
        assert!(got.evaluation.contains("\"linear\": null"));
    }

    #[test]
    fn map_rows_cover_the_requested_rows_with_listed_categories() {
        for (model, law) in [
            ("pulled-mass", "linear"),
            ("pulled-mass", "harmonic"),
            ("woodpecker", "linear"),
            ("woodpecker", "harmonic"),
            ("belt", "linear"),
            ("belt", "harmonic"),
        ] {
            let json =
                format!(r#"{{"model": "{model}", "law": "{law}", "cells": 6, "rows": [2, 5]}}"#);
            let (info, cells) = map(&parse(json.as_bytes()).unwrap()).unwrap();
            assert_eq!(cells.len(), 3 * 6, "{model} {law}");
            assert!(cells
                .iter()
                .all(|&c| usize::from(c) < info.categories.len()));
            assert!(info.x.range.0 < info.x.range.1 && info.y.range.0 < info.y.range.1);
            assert_eq!(info.x.key, "mu_d");
            if model == "belt" {
                assert_eq!(info.y.key, "v_b");
            }
        }
    }

    #[test]
    fn the_maps_cell_at_the_default_set_is_its_regime() {
        // The woodpecker's defaults are in double slip-stick under both laws.
        let p = crate::models::woodpecker::WoodpeckerParams::default();
        for law in [LawKind::Linear, LawKind::Harmonic] {
            let cell = p.map_cell(law, p.mu_d, p.z0);
            let label = crate::models::woodpecker::WoodpeckerParams::map_categories(law)
                [usize::from(cell)]
            .0;
            assert_eq!(label, "2 slips, 2 sticks", "{law:?}");
        }
    }

    #[test]
    fn bad_requests_are_refused_with_one_line_messages() {
        let refused = |json: &str| match parse::<Request>(json.as_bytes()).and_then(|r| explore(&r))
        {
            Err(e) => e.to_string(),
            Ok(_) => panic!("{json} accepted"),
        };
        assert!(refused("not json").starts_with("invalid value 'not json' for request"));
        assert!(refused(r#"{"model": "seesaw"}"#).contains("pulled-mass, woodpecker, belt"));
        assert!(refused(r#"{"model": "woodpecker", "params": {"F": 1}}"#).contains("for parameter"));
        assert!(
            refused(r#"{"model": "woodpecker", "choices": {"omega": "x"}}"#).contains("for option")
        );
        assert!(
            refused(r#"{"model": "pulled-mass", "params": {"mu_d": 2}}"#)
                .starts_with("invalid parameter mu_d = 2")
        );
        assert!(refused(r#"{"model": "pulled-mass", "samples": 1}"#).contains("samples"));
        assert!(refused(r#"{"model": "pulled-mass", "shown": 0}"#).contains("periods"));
        let map_refused = |json: &str| {
            parse::<MapRequest>(json.as_bytes())
                .and_then(|r| map(&r))
                .unwrap_err()
                .to_string()
        };
        assert!(
            map_refused(r#"{"model": "pulled-mass", "law": "x", "cells": 4, "rows": [0, 4]}"#)
                .contains("for law")
        );
        assert!(map_refused(
            r#"{"model": "pulled-mass", "law": "linear", "cells": 4, "rows": [3, 5]}"#
        )
        .contains("cells"));
        assert!(map_refused(
            r#"{"model": "pulled-mass", "law": "linear", "cells": 0, "rows": [0, 0]}"#
        )
        .contains("cells"));
    }

    #[test]
    fn extreme_parameters_are_refused_or_explored_never_a_panic() {
        for value in [f64::MIN_POSITIVE, 1e-300, 1e-40, 1e40, 1e300, f64::MAX] {
            for model in Model::defaults() {
                for key in model.param_keys() {
                    let mut setup = Setup {
                        model: model.id().to_string(),
                        ..Setup::default()
                    };
                    setup.params.insert(key.to_string(), value);
                    let r = Request {
                        setup: setup.clone(),
                        periods: 2,
                        shown: 1,
                        samples: 8,
                    };
                    let _ = explore(&r);
                    let m = MapRequest {
                        setup,
                        law: "harmonic".to_string(),
                        cells: 2,
                        rows: (0, 2),
                    };
                    let _ = map(&m);
                }
            }
        }
    }
}
