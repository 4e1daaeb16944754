//! The paper's claims checked on computed evidence (guide §11): for each of the eight
//! statements, what the paper says, a verdict and the numbers behind it, computed on the given
//! parameter sets, on variations of them (another μd, z0, m_S or λ) and, for statements about
//! "sensible values" in general, on a seeded random sample of valid parameter sets.
//!
//! ```text
//! pulled mass + woodpecker params ─┬─ closed forms (formula)     ─┐
//!                                  ├─ exact integration (engine) ─┼─→ Claim { verdict,
//!            Sample { seed, size } ─┴─ random sets (closed forms)  ─┘    finding, numbers }
//! ```
//!
//! A verdict judges the paper's statement (`paper_says`) as written: `confirmed` (it holds on the
//! evidence), `refuted` (a computed counterexample contradicts it), `qualified` (it holds only in
//! part, or only after a correction the finding names), `does_not_apply` (the set the user gave
//! lies outside the claim's domain: the claim says nothing about it; `does_not_apply` gives the
//! reason in words and the finding shows the evidence on the paper's set). Nothing is quoted from
//! the specification: every verdict follows from numbers computed here.
//!
//! ```text
//! claims 1, 2  pulled_mass.rs     claims 3, 7  both.rs      claims 4, 6  woodpecker.rs
//! claim 5      halt.rs            claim 8      lever.rs     random sets  sample.rs
//! ```

mod both;
pub(crate) mod sample;

use crate::models::pulled_mass::claims as pulled_mass;
use crate::models::woodpecker::{claims as woodpecker, halt, lever};

use serde::{Deserialize, Serialize};

use crate::engine::{analyse, integrate, Body, EventKind, ForceLaw, Run, RunOptions, Steady};
use crate::error::Result;
use crate::models::param::invalid;
use crate::models::pulled_mass::PulledMassParams;
use crate::models::woodpecker::formula::Counterpart;
use crate::models::woodpecker::WoodpeckerParams;
use crate::models::{LawKind, Model, Physics};
use crate::params::DEFAULT_PERIODS;
pub(crate) use crate::results::rel_diff;

pub use lever::halt_threshold_z0;

/// Largest random sample a caller may ask for.
pub const MAX_SAMPLE: usize = 1_000_000;

/// The seeded random sample used for statements about many parameter sets.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Sample {
    /// Seed of the generator (`StdRng::seed_from_u64`): the same seed gives the same claims.
    pub seed: u64,
    /// Number of random parameter sets per sampled claim.
    pub size: usize,
}

impl Default for Sample {
    /// Seed 2017 (the paper's year), 2000 sets.
    fn default() -> Self {
        Self {
            seed: 2017,
            size: 2000,
        }
    }
}

/// How a claim fares against the computed evidence.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    Confirmed,
    Refuted,
    Qualified,
    /// The given set is outside the claim's domain (the reason is in [`Claim::does_not_apply`]).
    DoesNotApply,
}

impl Verdict {
    /// The verdict in words, lowercase ("does not apply" with spaces).
    pub fn words(self) -> &'static str {
        match self {
            Self::Confirmed => "confirmed",
            Self::Refuted => "refuted",
            Self::Qualified => "qualified",
            Self::DoesNotApply => "does not apply",
        }
    }
}

/// Whose parameter set the claims judge: a claim whose domain excludes the set of the model the
/// user gave does not apply; a model the user did not give keeps the paper's set, and a claim
/// about it is shown on a set of the paper inside its domain.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Given {
    /// Neither set was given: both are the paper's.
    Paper,
    /// The pulled-mass set was given.
    PulledMass,
    /// The woodpecker set was given.
    Woodpecker,
}

impl Given {
    /// The model whose parameters `model` carries (the paper's sets for a model the claims
    /// are not about).
    pub fn of(model: &Model) -> Self {
        match model {
            Model::PulledMass(_) => Self::PulledMass,
            Model::Woodpecker(_) => Self::Woodpecker,
            _ => Self::Paper,
        }
    }

    fn gave(self, model_id: &str) -> bool {
        match self {
            Self::Paper => false,
            Self::PulledMass => model_id == <PulledMassParams as Physics>::ID,
            Self::Woodpecker => model_id == <WoodpeckerParams as Physics>::ID,
        }
    }
}

/// The `model` of a claim about both models; a claim about one model names its id.
pub const BOTH_MODELS: &str = "both";

/// One number behind a verdict (SI units; `unit` is "" for a pure number).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct ClaimNumber {
    pub label: String,
    pub value: f64,
    pub unit: String,
}

/// The outcome of a claim on the random sample.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct SampleResult {
    /// Number of valid random sets examined.
    pub size: usize,
    pub seed: u64,
    /// Sets that contradict the paper's statement, and their share of `size`.
    pub counterexamples: usize,
    pub share: f64,
    /// The first counterexample, described in words.
    pub example: Option<String>,
}

/// One claim of guide §11 with its verdict.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Claim {
    /// 1..=8, the numbering of guide §11.
    pub id: u8,
    /// The id of the model the claim is about, or [`BOTH_MODELS`].
    pub model: &'static str,
    pub title: String,
    /// The paper's statement, short.
    pub paper_says: String,
    pub verdict: Verdict,
    /// Why the claim does not apply to the given set (verdict `does_not_apply`), else `None`.
    pub does_not_apply: Option<String>,
    /// One or two sentences with the numbers.
    pub finding: String,
    pub numbers: Vec<ClaimNumber>,
    pub sample: Option<SampleResult>,
    /// Set by a claim whose domain excludes the set it was given for one model: (that model's
    /// id, the reason in words). [`evaluate_given`] turns it into the verdict when the user
    /// gave that model's set.
    #[serde(skip)]
    pub(crate) outside: Vec<(&'static str, String)>,
}

impl Claim {
    /// Marks the set of model `model_id` as outside the claim's domain, for `reason`.
    pub(crate) fn outside(mut self, model_id: &'static str, reason: Option<String>) -> Self {
        self.outside.extend(reason.map(|r| (model_id, r)));
        self
    }
}

/// All eight claims, in the order of guide §11.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Claims {
    pub claims: Vec<Claim>,
}

/// The inputs of one evaluation of the claims: the two models' sets and which one was given
/// (the report computes the claims once per distinct value).
pub type Inputs = (PulledMassParams, WoodpeckerParams, Given);

/// The parameter pair the claims are computed on when one model's set is given: that set for
/// its model, the paper's default set for the other.
pub fn params_for(model: &Model) -> (PulledMassParams, WoodpeckerParams) {
    // The claims are about these two models; any other model leaves both at the paper's sets.
    let mut pair = (PulledMassParams::default(), WoodpeckerParams::default());
    if let Model::PulledMass(p) = *model {
        pair.0 = p;
    }
    if let Model::Woodpecker(p) = *model {
        pair.1 = p;
    }
    pair
}

/// The eight claims on `model`'s set (the other model keeps the paper's set): a claim whose
/// domain excludes the given set does not apply.
pub fn evaluate_for(model: &Model, sample: &Sample) -> Result<Claims> {
    let (pulled, wood) = params_for(model);
    evaluate_given(&pulled, &wood, Given::of(model), sample)
}

/// The eight claims on sets that are the paper's or stand in for them: no claim is judged
/// outside its domain; a set outside it is replaced by the paper's set (the finding says so).
pub fn evaluate(
    pulled: &PulledMassParams,
    wood: &WoodpeckerParams,
    sample: &Sample,
) -> Result<Claims> {
    evaluate_given(pulled, wood, Given::Paper, sample)
}

/// Checks the parameters and the sample, then evaluates the eight claims; a claim whose domain
/// excludes the set of the model in `given` gets the verdict `does_not_apply` with its reason.
pub fn evaluate_given(
    pulled: &PulledMassParams,
    wood: &WoodpeckerParams,
    given: Given,
    sample: &Sample,
) -> Result<Claims> {
    pulled.validate()?;
    wood.validate()?;
    if !(1..=MAX_SAMPLE).contains(&sample.size) {
        return Err(invalid(
            "sample size",
            sample.size,
            format!("1 <= size <= {MAX_SAMPLE}"),
        ));
    }
    let pulled_periodic = pulled_mass::periodic_set(pulled)?;
    let claims = vec![
        pulled_mass::claim_1(pulled, sample)?,
        pulled_mass::claim_2(pulled)?,
        both::claim_3(&pulled_periodic, wood)?,
        woodpecker::claim_4(wood, sample),
        halt::claim_5(wood)?,
        woodpecker::claim_6(wood)?,
        both::claim_7(&pulled_periodic, wood)?,
        lever::claim_8(wood)?,
    ];
    let claims = claims
        .into_iter()
        .map(|mut c| {
            if let Some((_, reason)) = c.outside.iter().find(|(m, _)| given.gave(m)) {
                c.verdict = Verdict::DoesNotApply;
                c.does_not_apply = Some(reason.clone());
            }
            c
        })
        .collect();
    Ok(Claims { claims })
}

// ---------------------------------------------------------------------------------------------
// Helpers shared by the claim modules

/// Builds the `numbers` of a claim, leaving out values that do not exist or are not finite.
#[derive(Default)]
pub(crate) struct Numbers(Vec<ClaimNumber>);

impl Numbers {
    pub(crate) fn push(
        &mut self,
        label: &str,
        value: impl Into<Option<f64>>,
        unit: &str,
    ) -> &mut Self {
        if let Some(value) = value.into().filter(|v| v.is_finite()) {
            self.0.push(ClaimNumber {
                label: label.to_string(),
                value,
                unit: unit.to_string(),
            });
        }
        self
    }

    pub(crate) fn take(&mut self) -> Vec<ClaimNumber> {
        std::mem::take(&mut self.0)
    }
}

/// An exact integration over the default number of periods, with its steady state.
pub(crate) struct Integrated {
    pub(crate) run: Run,
    pub(crate) steady: Steady,
}

impl Integrated {
    /// The first stick after the first slip onset: (slip time, stick time), absolute (s).
    pub(crate) fn first_slip_and_stick(&self) -> Option<(f64, Option<f64>)> {
        let mut events = self.run.events.iter().filter(|e| e.is_transition());
        let slip = events.find(|e| matches!(e.kind, EventKind::Slip { .. }))?;
        let stick = events
            .next()
            .filter(|e| matches!(e.kind, EventKind::Stick { .. }))
            .map(|e| e.t);
        Some((slip.t, stick))
    }
}

/// Integrates `body` under `law` for the default number of periods.
fn steady_run(body: &Body, law: &ForceLaw) -> Result<Integrated> {
    let opts = RunOptions {
        periods: DEFAULT_PERIODS,
        record_segments: false,
        dissipation: true,
    };
    let run = integrate(body, law, &opts)?;
    let steady = analyse(&run);
    Ok(Integrated { run, steady })
}

/// Integrates the pulled mass under `law`.
pub(crate) fn run_pulled(p: &PulledMassParams, law: LawKind) -> Result<Integrated> {
    let body = crate::models::pulled_mass::body(p);
    steady_run(&body, &crate::models::pulled_mass::force_law(p, law)?)
}

/// Integrates the woodpecker sleeve under `law` (the linear law needs a defined counterpart).
pub(crate) fn run_wood(p: &WoodpeckerParams, law: LawKind) -> Result<Integrated> {
    let body = crate::models::woodpecker::body(p);
    steady_run(&body, &crate::models::woodpecker::force_law(p, law)?)
}

/// (max − min) / max|x| of the values (0 for fewer than two).
pub(crate) fn spread(values: &[f64]) -> f64 {
    let max = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let min = values.iter().copied().fold(f64::INFINITY, f64::min);
    let scale = values.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    if values.len() < 2 || scale == 0.0 {
        0.0
    } else {
        (max - min) / scale
    }
}

/// A speed in mm/s for the findings.
pub(crate) fn mm_s(v: f64) -> String {
    format!("{:.2} mm/s", 1e3 * v)
}

/// The lowercase name of a counterpart, as on the command line.
pub(crate) fn counterpart_name(c: Counterpart) -> &'static str {
    match c {
        Counterpart::Extremes => "extremes",
        Counterpart::Zeros => "zeros",
        Counterpart::Tangent => "tangent",
    }
}

/// A relative error in words: scientific below 0.1 %, else in percent.
pub(crate) fn rel_text(e: f64) -> String {
    if e == 0.0 {
        "0".to_string()
    } else if e < 1e-3 {
        crate::output::format::people_rel(Some(e))
    } else {
        format!("{:.1} %", 100.0 * e)
    }
}

/// An optional value formatted with `f`, or "none".
pub(crate) fn or_none(v: Option<f64>, f: impl Fn(f64) -> String) -> String {
    v.map_or_else(|| "none".to_string(), f)
}
