//! The vocabulary of the paper's claims (guide §11), shared by every model that offers them: a
//! claim with what the paper says, a verdict and the numbers behind it, the seeded random
//! sample for statements about "sensible values", and the capability [`PaperClaims`] through
//! which the commands, the report and the handouts reach a model's claims. This module names no
//! model: the claims themselves are computed in the models' folders (the claims about both
//! paper models in `crate::models::paper::claims`).
//!
//! ```text
//! model params ─┬─ closed forms (formula)     ─┐
//!               ├─ exact integration (engine) ─┼─→ Claim { verdict, finding, numbers }
//!      Sample ──┴─ random sets (closed forms)  ─┘
//! Model ── of / paper (with_capability!, claims) ──→ PaperClaims::claims ──→ Claims
//! ```
//!
//! A verdict judges the paper's statement (`paper_says`) as written: `confirmed` (it holds on the
//! evidence), `refuted` (a computed counterexample contradicts it), `qualified` (it holds only in
//! part, or only after a correction the finding names), `does_not_apply` (the set the user gave
//! lies outside the claim's domain: the claim says nothing about it; `does_not_apply` gives the
//! reason in words and the finding shows the evidence on the paper's set). Nothing is quoted from
//! the specification: every verdict follows from numbers computed here.

use serde::{Deserialize, Serialize};

use crate::engine::{analyse, integrate, EventKind, Run, RunOptions, Steady};
use crate::error::{Error, Result};
use crate::models::param::invalid;
use crate::models::{with_capability, Capability, LawKind, Model, Physics};
use crate::params::DEFAULT_PERIODS;
pub(crate) use crate::results::rel_diff;

/// The paper's claims about a model: the capability `claims` of the registry, implemented for
/// the models the paper makes claims about.
pub trait PaperClaims: Physics {
    /// The claims on this set and the paper's sets of the other models they concern, checked
    /// on `sample`. `given`: the set is the user's, and a claim whose domain excludes it does
    /// not apply; otherwise the set stands in for the paper's, and a claim whose domain excludes
    /// it is shown on a set of the paper inside its domain. Errors: an invalid set or sample.
    fn claims(&self, given: bool, sample: &Sample) -> Result<Claims>;
}

/// The claims on `model`'s set, the one the user gave; a model without the capability `claims`
/// is refused with the one-line error of [`Model::missing`].
pub fn of(model: &Model, sample: &Sample) -> Result<Claims> {
    with_capability!(model, claims, p => p.claims(true, sample),
        else Err(model.missing(Capability::Claims)))
}

/// The claims on the paper's sets: those of the first registered model that offers them, at
/// its default set (which stands in for the paper's).
pub fn paper(sample: &Sample) -> Result<Claims> {
    let Some(model) = Model::offering(Capability::Claims).into_iter().next() else {
        return Err(Error::Unsupported {
            model: "registered",
            what: Capability::Claims.words().to_string(),
        });
    };
    with_capability!(&model, claims, p => p.claims(false, sample),
        else Err(model.missing(Capability::Claims)))
}

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

impl Sample {
    /// Checks the size: 1 to [`MAX_SAMPLE`] sets.
    pub fn check(&self) -> Result<()> {
        if (1..=MAX_SAMPLE).contains(&self.size) {
            Ok(())
        } else {
            Err(invalid(
                "sample size",
                self.size,
                format!("1 <= size <= {MAX_SAMPLE}"),
            ))
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

impl SampleResult {
    /// `counterexamples` among `size` valid sets of `sample`, the first described by `example`.
    pub(crate) fn counted(
        sample: &Sample,
        size: usize,
        counterexamples: usize,
        example: Option<String>,
    ) -> Self {
        Self {
            size,
            seed: sample.seed,
            counterexamples,
            share: if size == 0 {
                0.0
            } else {
                counterexamples as f64 / size as f64
            },
            example,
        }
    }
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
    /// id, the reason in words). The evaluation turns it into the verdict when the user gave
    /// that model's set ([`PaperClaims::claims`] with `given`).
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

/// The claims on a set, in the order of guide §11 (the paper's eight; none for a model the
/// paper makes no claim about).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Claims {
    pub claims: Vec<Claim>,
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

/// Integrates the model with parameters `p` under `law` for the default number of periods (the
/// linearized law may not exist for some sets).
pub(crate) fn steady_run<M: Physics>(p: &M, law: LawKind) -> Result<Integrated> {
    let opts = RunOptions {
        periods: DEFAULT_PERIODS,
        record_segments: false,
        dissipation: true,
    };
    let run = integrate(&p.body(), &p.force_law(law)?, &opts)?;
    let steady = analyse(&run);
    Ok(Integrated { run, steady })
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

/// A relative error in words: scientific below 0.1 %, else in percent.
pub(crate) fn rel_text(e: f64) -> String {
    if e == 0.0 {
        "0".to_string()
    } else if e < 1e-3 {
        crate::format::people_rel(Some(e))
    } else {
        format!("{:.1} %", 100.0 * e)
    }
}

/// An optional value formatted with `f`, or "none".
pub(crate) fn or_none(v: Option<f64>, f: impl Fn(f64) -> String) -> String {
    v.map_or_else(|| "none".to_string(), f)
}
