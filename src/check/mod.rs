//! `stickslip check`: a formula of the user's (a textbook variant, a student's derivation, the
//! paper's formula with a suspected misprint) put against the exact integration of the
//! linearized law, at the given parameters and on a seeded sample that covers every regime of
//! the model, with draws packed against every regime boundary from both sides.
//!
//! ```text
//! formula (plain, LaTeX, Unicode) → formula.rs → expression tree over the case's symbols
//! case → symbols (parameters, derived symbols of the worked steps) → formula value
//!      → checks of the exact integration → the measured quantity (on its own scale)
//!      → agrees / disagrees per set → verdict: agrees only if every compared set agrees
//! ```
//!
//! A set is compared only where the exact integration measures the quantity and the tool's own
//! closed form agrees with it there (so the integration is known to be right on that set); the
//! others are counted with the reason.

pub mod formula;
mod render;

pub use formula::{Formula, Symbol};
pub use render::{render, text};

use rayon::prelude::*;
use serde::Serialize;

use crate::draws::Draws;
use crate::error::{Error, Result};
use crate::models::{with_capability, with_model, Capability, Model, Physics};
use crate::params::DEFAULT_PERIODS;
use crate::present::Present;
use crate::results::{CheckValue, Checked};
use crate::worksheet::exercise::{Exercise, Measured};

/// Default sample size.
pub const DEFAULT_SAMPLES: usize = 1000;
/// Largest sample.
pub const MAX_SAMPLES: usize = 100_000;
/// Sets of the pilot that finds the measurable quantities' names.
const PILOT: usize = 24;
/// Worst cases listed.
const WORST: usize = 5;
/// Share of the sample packed against the regime boundaries (when the model has some).
const BOUNDARY_SHARE: f64 = 0.6;
/// Relative offsets from a boundary: 10^-u for u uniform in this range, on both sides (down to
/// the band in which rounding decides the regime, [`crate::results::BOUNDARY_BAND`]).
const OFFSET_DECADES: (f64, f64) = (1.0, 10.5);

/// What to check.
#[derive(Clone, Debug)]
pub struct Request {
    /// The model with the given parameters.
    pub case: Model,
    /// The formula as typed.
    pub formula: String,
    /// The JSON key (guide §14) of the measured quantity (`v_avg`, `t_stick` …); `None` when the formula's
    /// left side names it.
    pub quantity: Option<String>,
    /// Only sets of this closed-form regime (the regime a formula is stated for); `None`: all.
    pub regime: Option<String>,
    pub samples: usize,
    pub seed: u64,
}

/// A boundary a set was drawn against: its words and the set's relative offset from it.
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Near {
    pub boundary: &'static str,
    pub offset: f64,
}

/// The formula and the integration on one parameter set.
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Sample {
    /// The parameters (guide §14 `params` keys, SI).
    pub params: Model,
    /// The regime of the closed forms.
    pub regime: &'static str,
    /// The formula's value; `None` where it is undefined (a zero denominator, a negative root).
    pub formula: Option<f64>,
    /// The exact integration's value; `None` where the run does not measure the quantity.
    pub numeric: Option<f64>,
    /// |formula − numeric| / max(|formula|, |numeric|, the quantity's scale).
    pub rel_error: Option<f64>,
    /// The tolerance of the tool's own check of this quantity on this set.
    pub tolerance: f64,
    pub agrees: Option<bool>,
    /// The boundary this set was packed against, if any.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub near: Option<Near>,
    /// Why the set was not compared.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub skipped: Option<String>,
}

/// Agreement in one regime.
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct RegimeRow {
    pub regime: &'static str,
    pub sets: usize,
    pub compared: usize,
    pub disagree: usize,
    pub max_rel_error: Option<f64>,
}

/// Why sets were not compared, with their count.
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Skipped {
    pub reason: String,
    pub sets: usize,
}

/// How the formula was read.
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct ReadAs {
    pub plain: String,
    pub latex: String,
}

/// The verdict.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// Every compared set agrees within its tolerance.
    Agrees,
    /// At least one compared set (or the given one) disagrees.
    Disagrees,
    /// No set could be compared.
    NotCompared,
}

/// The outcome of `stickslip check`, serialised as its JSON.
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Report {
    pub model: &'static str,
    pub quantity: String,
    /// The quantity's symbol and words, for the page.
    #[serde(skip)]
    pub named: Named,
    pub formula: String,
    /// The closed-form regime the sample was restricted to (`--regime`), if any.
    pub regime: Option<String>,
    /// The formula in plain syntax as read (= `read_as.plain`).
    pub expression: String,
    pub read_as: ReadAs,
    pub seed: u64,
    /// At the given parameters.
    pub given: Sample,
    /// Sets drawn; of them, compared, where the formula is undefined, where the exact
    /// integration does not measure the quantity or cannot be trusted to (`skipped` says why).
    pub samples: usize,
    pub compared: usize,
    pub undefined: usize,
    pub not_measured: usize,
    pub disagree: usize,
    pub max_rel_error: Option<f64>,
    pub median_rel_error: Option<f64>,
    pub verdict: Verdict,
    /// `true` when the verdict is [`Verdict::Agrees`].
    pub agrees: bool,
    /// The sets where the formula is worst, worst first.
    pub worst: Vec<Sample>,
    /// For each boundary, the disagreeing set nearest to it.
    pub nearest_counterexamples: Vec<Sample>,
    pub by_regime: Vec<RegimeRow>,
    pub skipped: Vec<Skipped>,
    /// Regimes sampled where no set measured the quantity.
    pub unmeasured_regimes: Vec<&'static str>,
    /// Sets of the sample drawn against a regime boundary.
    pub sample_near: usize,
}

impl Report {
    /// The verdict as an error when it is not agreement (exit code 3), for the command line.
    pub fn negative(&self) -> Option<Error> {
        let reason = match self.verdict {
            Verdict::Agrees => return None,
            Verdict::Disagrees => format!(
                "the formula for {} disagrees with the exact integration on {} of {} compared \
                 sets{}",
                self.quantity,
                self.disagree + usize::from(self.given.agrees == Some(false)),
                self.compared + usize::from(self.given.agrees.is_some()),
                if self.given.agrees == Some(false) {
                    " (the given set among them)"
                } else {
                    ""
                }
            ),
            Verdict::NotCompared => format!(
                "no set could be compared for {}: nothing is verified",
                self.quantity
            ),
        };
        Some(Error::Verdict { reason })
    }
}

/// Where a symbol's value comes from: a parameter (by its key) or a worked step (by its LaTeX
/// symbol).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Source {
    Param(&'static str),
    Step(&'static str),
}

/// The symbols of `case`: the parameters (by symbol, `m`), then every derived symbol of its
/// worked steps (`varphi` and `phi`, `T`, `Gamma`, `tau_SL` …, NaN where its formula is
/// undefined), then the parameters by key (`mass`).
pub fn symbols(case: &Model) -> Vec<Symbol> {
    sourced_symbols(case).into_iter().map(|(s, _)| s).collect()
}

fn sourced_symbols(case: &Model) -> Vec<(Symbol, Source)> {
    fn params<M: Physics>(p: &M) -> Vec<(Symbol, &'static str)> {
        M::PARAMS
            .iter()
            .filter_map(|s| {
                let symbol = Symbol {
                    name: formula::identifier(s.tex),
                    tex: s.tex.to_string(),
                    value: (s.get)(p)?,
                };
                Some((symbol, s.key))
            })
            .collect()
    }
    let given = with_model!(case, p => params(p));
    let mut out: Vec<(Symbol, Source)> = given
        .iter()
        .map(|(s, key)| (s.clone(), Source::Param(key)))
        .collect();
    for step in crate::worksheet::answer::steps(case) {
        // A symbol, not an expression (the slip duration is written `t_{ST} - t_{SL}`, the
        // boundary `1/\Theta`); `\bar v` is one symbol.
        let plain = step.symbol.replace("\\bar ", "");
        if plain.contains(' ') || plain.contains('/') {
            continue;
        }
        let value = step.formula_value();
        let name = formula::identifier(step.symbol);
        let source = Source::Step(step.symbol);
        if name == "varphi" {
            let symbol = Symbol {
                name: "phi".to_string(),
                tex: step.symbol.to_string(),
                value,
            };
            out.push((symbol, source));
        }
        let symbol = Symbol {
            name,
            tex: step.symbol.to_string(),
            value,
        };
        out.push((symbol, source));
    }
    // The parameters' keys (`mass`, `force`) as well, last.
    out.extend(given.into_iter().map(|(s, key)| {
        (
            Symbol {
                name: key.to_string(),
                ..s
            },
            Source::Param(key),
        )
    }));
    let mut seen = std::collections::HashSet::new();
    out.retain(|(s, _)| {
        s.name.starts_with(|c: char| c.is_ascii_alphabetic()) && seen.insert(s.name.clone())
    });
    out
}

/// The values of a formula's symbols on `case`, in the order of its names, from their sources:
/// no symbol is named, rendered or looked up by string on the way, and the worked steps are
/// values without expression trees (the sample's path). A derived symbol's value is its
/// formula's ([`crate::derivation::Step::formula_value`]): NaN where undefined, so a formula
/// using it is undefined on that set, and counted so.
fn values(case: &Model, sources: &[Source]) -> Vec<f64> {
    fn param<M: Physics>(p: &M, key: &str) -> f64 {
        M::PARAMS
            .iter()
            .find(|s| s.key == key)
            .and_then(|s| (s.get)(p))
            .unwrap_or(f64::NAN)
    }
    let needs_steps = sources.iter().any(|s| matches!(s, Source::Step(_)));
    let steps = if needs_steps {
        with_capability!(case, present, p => p.derivation_values(), else Vec::new())
    } else {
        Vec::new()
    };
    sources
        .iter()
        .map(|source| match source {
            Source::Param(key) => with_model!(case, p => param(p, key)),
            Source::Step(tex) => steps
                .iter()
                .find(|s| std::ptr::eq(s.symbol, *tex) || s.symbol == *tex)
                .map_or(f64::NAN, crate::derivation::Step::formula_value),
        })
        .collect()
}

/// The sources of a formula's names among the symbols of `case`.
fn sources(case: &Model, formula: &Formula) -> Vec<Source> {
    let all = sourced_symbols(case);
    formula
        .names
        .iter()
        .map(|n| {
            all.iter()
                .find(|(s, _)| &s.name == n)
                .map_or(Source::Param(""), |(_, source)| *source)
        })
        .collect()
}

/// The symbols of `case` one per line with their values (`--symbols`).
pub fn symbols_text(case: &Model) -> String {
    let mut o = format!(
        "symbols of the {} for a formula (value at the given parameters, SI; pi is the \
         constant, exp(x) the exponential; Greek letters may be typed as such: φ, μs, τ_SL):\n",
        case.id()
    );
    for s in symbols(case) {
        let shown = if s.value.is_finite() {
            crate::format::people(Some(s.value), 6)
        } else {
            "undefined here".to_string()
        };
        o.push_str(&format!("  {:<14} {shown}\n", s.name));
    }
    o
}

/// The measured quantity that is a condition: whether the periodic motion has a stick (or
/// never slips), from the regime of the exact integration.
pub const STICKS: &str = "sticks";

/// What the exact integration says of the quantity on one set.
enum Measure {
    /// Its value, on the scale and at the tolerance of the tool's own check.
    Value(Measured),
    /// Not compared, and why.
    Skip(String),
}

/// The checks of `case` on the standard run (the linearized law only: the harmonic law is not
/// integrated).
fn checks_of(case: &Model) -> Result<Vec<crate::results::Check>> {
    Ok(
        with_capability!(case, exercise, p => p.checks_and_linear_run(DEFAULT_PERIODS, false)?.0,
        else return Err(case.missing(Capability::Exercise))),
    )
}

fn measured_elsewhere(
    case: &Model,
    quantity: &str,
    checks: &[crate::results::Check],
) -> Option<Measured> {
    // A model without worksheets has no quantity measured in another's place.
    with_capability!(case, exercise, p => p.measured_elsewhere(quantity, checks), else None)
}

/// The measured value of `quantity` on `case`: the numeric side of the tool's check of it (or,
/// where its closed form describes another regime, of the checks that measure the same thing
/// here), where that check passes, so the integration is known to be right on this set.
/// `checks` are those of `case` ([`checks_of`]).
fn measured(
    case: &Model,
    quantity: &str,
    checks: Result<Vec<crate::results::Check>>,
) -> Result<Measure> {
    let checks = checks?;
    let regime = || crate::report::context::regime_words(case.closed_form_regime());
    if quantity == STICKS {
        let check = checks.iter().find(|c| c.quantity.id() == "regime");
        return Ok(match check {
            Some(c) if c.pass.is_none() => Measure::Skip(format!(
                "the regime is not observable: {}",
                c.note.as_deref().unwrap_or("rounding decides it")
            )),
            Some(crate::results::Check {
                numeric: CheckValue::Text(label),
                ..
            }) => Measure::Value(Measured {
                value: f64::from(u8::from(!label.contains("continuous"))),
                scale: 0.0,
                tolerance: 0.0,
            }),
            _ => Measure::Skip("the exact integration has no regime here".to_string()),
        });
    }
    let Some(c) = checks.iter().find(|c| c.quantity.id() == quantity) else {
        return Ok(match measured_elsewhere(case, quantity, &checks) {
            Some(m) => Measure::Value(m),
            None => Measure::Skip(format!(
                "the exact integration does not measure it in {}",
                regime()
            )),
        });
    };
    Ok(match (c.pass, Measured::of(c)) {
        (_, Some(m)) => Measure::Value(m),
        (None, _) => Measure::Skip(format!(
            "not observable: {}",
            c.note.as_deref().unwrap_or("the run cannot show it")
        )),
        (Some(false), _) => Measure::Skip(
            "the tool's own closed form and its exact integration differ here: no verdict on \
             this set"
                .to_string(),
        ),
        (Some(true), None) => Measure::Skip(format!(
            "the exact integration does not show it in {}",
            regime()
        )),
    })
}

/// How a quantity is written: its LaTeX symbol and its words.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Named {
    pub id: String,
    pub tex: String,
    pub words: String,
}

/// The measurable quantities of `checks` (those of one set).
fn measurable(checks: &[crate::results::Check]) -> Vec<Named> {
    checks
        .iter()
        .filter(|c| matches!(c.numeric, CheckValue::Number(_)))
        .map(|c| match c.quantity {
            Checked::Key(k) => Named {
                id: k.id().to_string(),
                tex: k.quantity().tex.to_string(),
                words: k.quantity().words.to_string(),
            },
            other => Named {
                id: other.id().into_owned(),
                ..Named::default()
            },
        })
        .collect()
}

/// The sample of `case`, whose checks are `checks` ([`checks_of`]).
fn sample(
    formula: &Formula,
    sources: &[Source],
    (case, checks): (Model, Result<Vec<crate::results::Check>>),
    quantity: &str,
    near: Option<Near>,
) -> Result<Sample> {
    let value = formula.value_of(&values(&case, sources));
    let mut s = Sample {
        params: case,
        regime: case.closed_form_regime(),
        formula: value,
        numeric: None,
        rel_error: None,
        tolerance: crate::results::TOLERANCE,
        agrees: None,
        near,
        skipped: None,
    };
    // A set the model cannot evaluate (a combination out of double precision's range) is no
    // evidence either way.
    let measure = match measured(&case, quantity, checks) {
        Ok(m) => m,
        Err(e) if e.exit_code() == 2 => Measure::Skip(format!("not computable: {e}")),
        Err(e) => return Err(e),
    };
    match measure {
        Measure::Value(Measured {
            value: numeric,
            scale,
            tolerance,
        }) => {
            s.numeric = Some(numeric);
            s.tolerance = tolerance;
            match value {
                Some(f) => {
                    let e = crate::results::checks::rel_diff_on_scale(f, numeric, scale);
                    s.rel_error = Some(e);
                    s.agrees = Some(e <= tolerance);
                }
                None => {
                    s.skipped = Some(
                        "the formula is undefined here (a zero denominator, a negative root …)"
                            .to_string(),
                    )
                }
            }
        }
        Measure::Skip(reason) => s.skipped = Some(reason),
    }
    Ok(s)
}

/// One `[[check]]` table of a `--formulas` file.
#[derive(Clone, Debug, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Entry {
    pub formula: String,
    /// Unless the formula's left side names it.
    pub quantity: Option<String>,
    /// Only sets of this closed-form regime.
    pub regime: Option<String>,
}

/// The `[[check]]` tables of a `--formulas` file.
pub fn read_formulas(path: &std::path::Path) -> Result<Vec<Entry>> {
    #[derive(serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    struct File {
        check: Vec<Entry>,
    }
    let scenario_error = |reason: String| Error::Scenario {
        path: path.display().to_string(),
        reason,
    };
    let text = crate::params::read_input_text(path, "--formulas").map_err(scenario_error)?;
    let file: File = toml::from_str(&text).map_err(|e| scenario_error(e.message().to_string()))?;
    if file.check.is_empty() {
        return Err(scenario_error("no [[check]] table".to_string()));
    }
    Ok(file.check)
}

/// The closed-form regimes `--regime` accepts: the worksheet's, and the given set's.
fn regime_ids(model: Model) -> Vec<&'static str> {
    let mut ids: Vec<&'static str> = crate::worksheet::question::regimes(model)
        .iter()
        .map(|r| r.id())
        .collect();
    if !ids.contains(&model.closed_form_regime()) {
        ids.push(model.closed_form_regime());
    }
    ids
}

fn probe(model: Model, rng: &mut Draws) -> Result<Model> {
    fn of<M: Exercise>(_: &M, rng: &mut Draws) -> Model {
        M::probe(rng).into_model()
    }
    with_capability!(&model, exercise, p => Ok(of(p, rng)), else Err(model.missing(Capability::Exercise)))
}

fn boundaries(model: Model) -> &'static [&'static str] {
    fn of<M: Exercise>(_: &M) -> &'static [&'static str] {
        M::boundaries()
    }
    // A model without worksheets has no boundaries to pack draws against.
    with_capability!(&model, exercise, p => of(p), else &[])
}

fn onto_boundary(model: Model, i: usize, offset: f64) -> Option<Model> {
    fn of<M: Exercise>(p: &M, i: usize, offset: f64) -> Option<Model> {
        Some(p.onto_boundary(i, offset)?.into_model())
    }
    with_capability!(&model, exercise, p => of(p, i, offset), else None)
}

/// The sample: probes of the whole domain, and sets packed against each boundary from both
/// sides; every set valid, and of closed-form regime `regime` when one is given. Deterministic
/// for a seed.
fn draw_sample(
    model: Model,
    samples: usize,
    seed: u64,
    regime: Option<&str>,
) -> Result<Vec<(Model, Option<Near>)>> {
    let mut rng = Draws::new(seed);
    let names = boundaries(model);
    let mut out = Vec::with_capacity(samples);
    // Attempt j is packed against a boundary when j mod 5 < 5·BOUNDARY_SHARE, in turn boundary
    // by boundary and side by side; attempts that miss `regime` or leave the domain are redrawn.
    let packed_of_five = (5.0 * BOUNDARY_SHARE).round() as usize;
    for j in 0..50 * samples + 100 {
        if out.len() == samples {
            break;
        }
        let base = probe(model, &mut rng)?;
        let drawn = if !names.is_empty() && j % 5 < packed_of_five {
            let turn = j / 5 * packed_of_five + j % 5;
            let i = (turn / 2) % names.len();
            let side = if turn.is_multiple_of(2) { 1.0 } else { -1.0 };
            let offset = side * 10f64.powf(-rng.between(OFFSET_DECADES.0, OFFSET_DECADES.1));
            onto_boundary(base, i, offset).map(|m| {
                (
                    m,
                    Some(Near {
                        boundary: names[i],
                        offset,
                    }),
                )
            })
        } else {
            Some((base, None))
        };
        let wanted =
            |m: &Model| m.validate().is_ok() && regime.is_none_or(|r| m.closed_form_regime() == r);
        if let Some((m, near)) = drawn.filter(|(m, _)| wanted(m)) {
            out.push((m, near));
        }
    }
    Ok(out)
}

/// Runs the check: the given parameters, then `samples` seeded sets over the model's whole
/// domain and its regime boundaries (in parallel).
pub fn run(req: &Request) -> Result<Report> {
    if !(1..=MAX_SAMPLES).contains(&req.samples) {
        return Err(crate::models::param::invalid(
            "samples",
            req.samples,
            format!("1 <= samples <= {MAX_SAMPLES}"),
        ));
    }
    req.case.validate()?;
    req.case.require(Capability::Exercise)?;
    req.case.require(Capability::Present)?;
    if let Some(r) = &req.regime {
        let valid = regime_ids(req.case);
        if !valid.contains(&r.as_str()) {
            return Err(Error::InvalidChoice {
                flag: "--regime",
                value: r.clone(),
                valid: valid.join(", "),
            });
        }
    }
    let known = symbols(&req.case);
    let formula = Formula::read(&req.formula, &known)?;
    let drawn = draw_sample(req.case, req.samples, req.seed, req.regime.as_deref())?;
    // The names of the measurable quantities, from the given set and a pilot drawn over every
    // regime (whatever `--regime` keeps).
    // The given set's checks, once: for the names and for its sample.
    let given_checks = checks_of(&req.case)?;
    let mut names = measurable(&given_checks);
    for (case, _) in draw_sample(req.case, PILOT, req.seed, None)? {
        if let Ok(here) = checks_of(&case) {
            names.extend(measurable(&here));
        }
    }
    names.push(Named {
        id: STICKS.to_string(),
        tex: r"\text{sticks}".to_string(),
        words: "whether the motion has a stick (a condition: 1 or 0)".to_string(),
    });
    let quantity = which_quantity(req, &formula, &names)?;
    let named = names
        .iter()
        .find(|n| n.id == quantity)
        .cloned()
        .unwrap_or_default();
    let sources = sources(&req.case, &formula);
    let mut given = sample(
        &formula,
        &sources,
        (req.case, Ok(given_checks)),
        &quantity,
        None,
    )?;
    if req.regime.as_deref().is_some_and(|r| r != given.regime) {
        given.agrees = None;
        given.rel_error = None;
        given.skipped = Some("the given set is outside --regime".to_string());
    }
    let samples = drawn
        .into_par_iter()
        .map(|(case, near)| {
            let checks = checks_of(&case);
            sample(&formula, &sources, (case, checks), &quantity, near)
        })
        .collect::<Result<Vec<_>>>()?;
    let read_as = ReadAs {
        plain: formula.plain(),
        latex: formula.latex(&known),
    };
    Ok(summarise(req, quantity, read_as, named, given, samples))
}

/// The quantity: `--quantity`, or the one the formula's left side names; both must agree.
fn which_quantity(req: &Request, formula: &Formula, names: &[Named]) -> Result<String> {
    let valid = || {
        let mut ids: Vec<&str> = names.iter().map(|n| n.id.as_str()).collect();
        ids.sort_unstable();
        ids.dedup();
        ids.join(", ")
    };
    let named_by = |lhs: &str| {
        names
            .iter()
            .find(|n| n.id == lhs || (!n.tex.is_empty() && formula::identifier(&n.tex) == lhs))
            .map(|n| n.id.clone())
    };
    let from_lhs = match &formula.lhs {
        Some(lhs) => Some(named_by(lhs).ok_or_else(|| Error::Formula {
            formula: crate::error::excerpt(&req.formula, 80),
            reason: format!(
                "the left side `{lhs}` names no measured quantity ({})",
                valid()
            ),
        })?),
        None => None,
    };
    match (&req.quantity, from_lhs) {
        (Some(q), _) if !names.iter().any(|n| &n.id == q) => Err(Error::InvalidChoice {
            flag: "--quantity",
            value: q.clone(),
            valid: valid(),
        }),
        (Some(q), Some(l)) if *q != l => Err(Error::Formula {
            formula: crate::error::excerpt(&req.formula, 80),
            reason: format!("the left side names {l}, but --quantity is {q}"),
        }),
        (Some(q), _) => Ok(q.clone()),
        (None, Some(l)) => Ok(l),
        (None, None) => Err(Error::Formula {
            formula: crate::error::excerpt(&req.formula, 80),
            reason: "say which quantity it gives: --quantity NAME, or a left side (`v_avg = …`)"
                .to_string(),
        }),
    }
}

fn summarise(
    req: &Request,
    quantity: String,
    read_as: ReadAs,
    named: Named,
    given: Sample,
    samples: Vec<Sample>,
) -> Report {
    let n = samples.len();
    let undefined = samples
        .iter()
        .filter(|s| s.formula.is_none() && s.numeric.is_some())
        .count();
    let not_measured = samples.iter().filter(|s| s.numeric.is_none()).count();
    let mut compared: Vec<&Sample> = samples.iter().filter(|s| s.agrees.is_some()).collect();
    compared.sort_by(|a, b| {
        b.rel_error
            .unwrap_or(0.0)
            .total_cmp(&a.rel_error.unwrap_or(0.0))
    });
    let errors: Vec<f64> = compared.iter().filter_map(|s| s.rel_error).collect();
    let disagree = compared.iter().filter(|s| s.agrees == Some(false)).count();
    let median = (!errors.is_empty()).then(|| {
        let mut e = errors.clone();
        e.sort_by(f64::total_cmp);
        e[e.len() / 2]
    });
    let mut by_regime: Vec<RegimeRow> = Vec::new();
    let mut skipped: Vec<Skipped> = Vec::new();
    for s in &samples {
        let row = match by_regime.iter_mut().find(|r| r.regime == s.regime) {
            Some(row) => row,
            None => {
                by_regime.push(RegimeRow {
                    regime: s.regime,
                    sets: 0,
                    compared: 0,
                    disagree: 0,
                    max_rel_error: None,
                });
                by_regime.last_mut().expect("just pushed")
            }
        };
        row.sets += 1;
        if let (Some(e), Some(agrees)) = (s.rel_error, s.agrees) {
            row.compared += 1;
            row.disagree += usize::from(!agrees);
            row.max_rel_error = Some(row.max_rel_error.map_or(e, |m: f64| m.max(e)));
        }
        if let Some(reason) = &s.skipped {
            match skipped.iter_mut().find(|k| &k.reason == reason) {
                Some(k) => k.sets += 1,
                None => skipped.push(Skipped {
                    reason: reason.clone(),
                    sets: 1,
                }),
            }
        }
    }
    skipped.sort_by(|a, b| b.sets.cmp(&a.sets).then(a.reason.cmp(&b.reason)));
    let mut nearest: Vec<Sample> = Vec::new();
    for boundary in boundaries(req.case) {
        let closest = samples
            .iter()
            .filter(|s| s.agrees == Some(false))
            .filter_map(|s| Some((s, s.near.as_ref().filter(|n| n.boundary == *boundary)?)))
            .min_by(|a, b| a.1.offset.abs().total_cmp(&b.1.offset.abs()));
        if let Some((s, _)) = closest {
            nearest.push(s.clone());
        }
    }
    let unmeasured_regimes = by_regime
        .iter()
        .filter(|r| r.compared == 0)
        .map(|r| r.regime)
        .collect();
    let worst = compared.iter().take(WORST).map(|s| (*s).clone()).collect();
    let verdict = if given.agrees == Some(false) || disagree > 0 {
        Verdict::Disagrees
    } else if errors.is_empty() && given.agrees.is_none() {
        Verdict::NotCompared
    } else {
        Verdict::Agrees
    };
    Report {
        model: req.case.id(),
        quantity,
        named,
        formula: req.formula.clone(),
        regime: req.regime.clone(),
        expression: read_as.plain.clone(),
        read_as,
        seed: req.seed,
        given,
        samples: n,
        compared: errors.len(),
        undefined,
        not_measured,
        disagree,
        max_rel_error: errors.first().copied(),
        median_rel_error: median,
        verdict,
        agrees: verdict == Verdict::Agrees,
        worst,
        nearest_counterexamples: nearest,
        by_regime,
        skipped,
        unmeasured_regimes,
        sample_near: samples.iter().filter(|s| s.near.is_some()).count(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::pulled_mass::PulledMassParams;

    fn check(formula: &str, quantity: &str, regime: Option<&str>) -> Report {
        run(&Request {
            case: Model::PulledMass(PulledMassParams::default()),
            formula: formula.to_string(),
            quantity: Some(quantity.to_string()),
            regime: regime.map(str::to_string),
            samples: 200,
            seed: 1,
        })
        .unwrap()
    }

    /// The paper's Γ with coefficient 1 agrees where (27) is stated; with 2 it does not; over
    /// every regime, (27) itself disagrees in the late-stick band, where v̄ is measured too.
    #[test]
    fn gamma_agrees_in_its_regime_and_fails_in_the_late_stick_band() {
        let right = check("g*T*phi^3*Gamma", "v_avg", Some("slip_stick"));
        assert!(right.agrees, "{}", text(&right));
        assert!(right.compared > 100);
        let wrong = check(r"2 g T \varphi^3 \Gamma", "v_avg", Some("slip_stick"));
        assert!(!wrong.agrees && wrong.disagree == wrong.compared);
        assert!((wrong.max_rel_error.unwrap() - 0.5).abs() < 1e-9);
        let everywhere = check("g*T*phi^3*Gamma", "v_avg", None);
        assert_eq!(everywhere.verdict, Verdict::Disagrees);
        for row in &everywhere.by_regime {
            let late = row.regime == "slip_stick_late";
            assert_eq!(row.disagree > 0, late, "{row:?}");
        }
        assert!(everywhere
            .nearest_counterexamples
            .iter()
            .all(|s| s.regime == "slip_stick_late"));
    }

    /// Eq. (20), φ ≤ 1/Θ, read as the condition to stick at all: it fails exactly in the
    /// late-stick band, where the mass sticks early in the next period.
    #[test]
    fn eq_20_as_a_stick_condition_fails_in_the_late_stick_band() {
        let r = check(r"\varphi \le 1/\Theta", STICKS, None);
        assert!(!r.agrees, "{}", text(&r));
        for row in r.by_regime.iter().filter(|r| r.compared > 0) {
            let late = row.regime == "slip_stick_late";
            assert_eq!(row.disagree == row.compared, late, "{row:?}");
            assert_eq!(row.disagree == 0, !late, "{row:?}");
        }
    }

    /// A student's t_ST with a sign error (1 − φΘ for 1 + φΘ) fails, with counterexamples and
    /// the disagreeing set nearest each boundary.
    #[test]
    fn a_sign_error_in_t_stick_is_caught_with_counterexamples() {
        let right = check(
            r"\frac{T}{2}\left(1 + \varphi\Theta\right)",
            "t_stick",
            Some("slip_stick"),
        );
        assert!(right.agrees, "{}", text(&right));
        let wrong = check(
            r"\frac{T}{2}\left(1 - \varphi\Theta\right)",
            "t_stick",
            None,
        );
        assert!(!wrong.agrees, "{}", text(&wrong));
        assert_eq!(wrong.worst.len(), WORST);
        let shown = text(&wrong);
        assert!(shown.contains("DISAGREES") && shown.contains("worst sets"));
        assert!(
            shown.starts_with("read as: t_stick = T/2*(1 - varphi*Theta)"),
            "{shown}"
        );
        assert!(!wrong.nearest_counterexamples.is_empty());
        // In continuous slip the mass never sticks: not measured, and said why.
        assert!(wrong
            .skipped
            .iter()
            .any(|k| k.reason.contains("does not measure it in continuous slip")));
    }

    #[test]
    fn bad_formulas_quantities_and_regimes_are_refused_with_what_is_known() {
        let err = |f: &str, q: Option<&str>, regime: Option<&str>| {
            run(&Request {
                case: Model::PulledMass(PulledMassParams::default()),
                formula: f.to_string(),
                quantity: q.map(str::to_string),
                regime: regime.map(str::to_string),
                samples: 10,
                seed: 1,
            })
            .unwrap_err()
            .to_string()
        };
        let e = err("g*T*xi", Some("v_avg"), None);
        assert!(
            e.contains("unknown symbol xi") && e.contains("--symbols"),
            "{e}"
        );
        let all = symbols_text(&Model::PulledMass(PulledMassParams::default()));
        for name in ["mu_s", "phi", "Theta", "Gamma", "tau_ST", "bar_v", "mass"] {
            assert!(all.contains(&format!("  {name} ")), "{name}: {all}");
        }
        assert!(err("g*T*(", Some("v_avg"), None).contains("operand"));
        let e = err("g*T", Some("speed"), None);
        assert!(e.contains("--quantity") && e.contains("v_avg"), "{e}");
        let e = err("g*T", None, None);
        assert!(e.contains("--quantity NAME, or a left side"), "{e}");
        let e = err("v_avg = g*T", Some("t_slip"), None);
        assert!(
            e.contains("left side names v_avg, but --quantity is t_slip"),
            "{e}"
        );
        let e = err("g*T", Some("v_avg"), Some("late"));
        assert!(
            e.contains("--regime") && e.contains("slip_stick_late"),
            "{e}"
        );
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(400))]

        /// Any text made of formula pieces is read or refused with an error, never a panic,
        /// and a formula that is read has a finite value or none.
        #[test]
        fn any_formula_text_is_read_or_refused_without_panicking(
            pieces in proptest::collection::vec(proptest::sample::select(vec![
                "phi", "T", "g", r"\varphi", r"\Theta", r"\frac", r"\sqrt", "[", "]", "{",
                "}", "(", ")", "^", "_", "+", "-", "*", "/", "2", "0.5", "1e308", r"\left(",
                r"\right)", r"\le", "<=", ">", "mu_s", r"\mu_s", "'", r"^{(I)}", " ", ",",
                r"\cdot", "PI", "sqrt", r"\", "x", "é", "0", "|", "φ", "³", "μs", "=", "−",
                r"\ln", "e-3", "√", r"\bar", "∛", "·",
            ]), 0..14)
        ) {
            let text: String = pieces.concat();
            let known = symbols(&Model::PulledMass(PulledMassParams::default()));
            if let Ok(f) = Formula::read(&text, &known) {
                if let Some(v) = f.value(&known) {
                    proptest::prop_assert!(v.is_finite());
                }
                // What is read back is read the same way.
                let again = Formula::read(&f.plain(), &known);
                proptest::prop_assert!(again.is_ok(), "{} → {}", text, f.plain());
                let (a, b) = (again.unwrap().value(&known), f.value(&known));
                proptest::prop_assert!(a == b || (a.is_none() && b.is_none()), "{} → {}", text, f.plain());
            }
        }
    }

    /// Every derived symbol is known whatever the regime of the given set: τ_ST on a set that
    /// slips continuously (the default pulled mass) still reads, and checks where it applies.
    #[test]
    fn derived_symbols_are_known_in_every_regime() {
        let r = check("T*tau_ST", "t_stick", Some("slip_stick"));
        assert!(r.agrees, "{}", text(&r));
        assert!(r.given.formula.is_some());
    }

    /// Undefined values are counted, not dropped: 1/(phi - phi) is nowhere defined, and a
    /// check that compared nothing verifies nothing.
    #[test]
    fn undefined_values_are_counted_and_nothing_compared_is_no_agreement() {
        let r = check("1/(phi - phi)", "v_avg", None);
        assert!(r.undefined > 0 && r.compared == 0);
        assert_eq!(r.verdict, Verdict::NotCompared);
        assert!(r.negative().is_some_and(|e| e.exit_code() == 3));
    }

    /// The sample covers every regime, with sets on both sides of every boundary, down to
    /// offsets of 1e-10.
    #[test]
    fn the_sample_packs_both_sides_of_every_boundary() {
        let drawn = draw_sample(
            Model::PulledMass(PulledMassParams::default()),
            1000,
            3,
            None,
        )
        .unwrap();
        assert_eq!(drawn.len(), 1000);
        for boundary in ["φ = 1/Θ", "φ = φ_c", "φ = 2μs"] {
            let near: Vec<f64> = drawn
                .iter()
                .filter_map(|(_, n)| n.as_ref().filter(|n| n.boundary == boundary))
                .map(|n| n.offset)
                .collect();
            assert!(near.iter().any(|o| *o > 0.0 && *o < 1e-9), "{boundary}");
            assert!(near.iter().any(|o| *o < 0.0 && *o > -1e-9), "{boundary}");
        }
        let mut regimes: Vec<&str> = drawn.iter().map(|(m, _)| m.closed_form_regime()).collect();
        regimes.sort_unstable();
        regimes.dedup();
        assert_eq!(regimes.len(), 4, "{regimes:?}");
    }
}
