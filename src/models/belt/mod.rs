//! The textbook stick-slip oscillator (docs/belt.md): a block of mass m on a belt moving at
//! v_b, held by a spring k to a wall, with static and dynamic friction μs ≥ μd. The paper's
//! stick condition with a different forcing: the force depends on the position (the spring)
//! and the surface moves, so the engine runs it as an autonomous system
//! ([`crate::engine::autonomous`]) whose period is an output. Everything about the model
//! lives in this folder:
//!
//! ```text
//! params.rs    the parameters with their lab ranges
//! body.rs      the block and its surface law (D = −k x, N_f = m g, surface speed v_b)
//! formula.rs   the closed forms (B1)–(B17), one pure function per quantity
//! quantity.rs  the registry of the quantities: key, symbol, unit, equation
//! results.rs   the evaluation: closed forms, the exact integration's last cycle, checks
//! scene.rs     the figures: x(t) and v(t) with the belt's speed, the phase portrait
//! sketch.rs    the sketch of the apparatus with the balanced forces of the stated phase, and its
//!              geometry for the explorer's animation
//! derivation.rs the worked substitutions of every closed form (handout, answer keys)
//! teaching.rs  how a handout explains the equation of motion and each derivation step
//! exercise.rs  the worksheet (`Exercise`): questions, regimes, drawn and probed sets
//! present.rs   the presentation (report part, tables, handout, text, CSV)
//! scenes.rs    the built-in scenes of the report (scenarios/belt-*.toml)
//! lang/        its words in each language of the handouts
//! explore.rs   what the explorer page asks (`Explore`): regime sentence, curves, map
//! explorer.js  the explorer page's drawing of the apparatus, animated (inserted by
//!              src/report/explorer.rs)
//! map.rs       the (μd, v_b) regime map from the closed forms
//! ```
//!
//! The belt offers the `present`, `explore` and `exercise` capabilities (report, handout, sweep,
//! eval's tables, the explorer page, worksheet, check); `claims` refuses it.

pub mod body;
#[cfg(feature = "cli")]
pub mod derivation;
#[cfg(feature = "cli")]
mod exercise;
pub mod explore;
pub mod formula;
pub mod map;
pub mod params;
#[cfg(feature = "cli")]
pub mod present;
pub mod quantity;
pub mod results;
#[cfg(feature = "cli")]
pub mod scene;
#[cfg(feature = "cli")]
mod scenes;
#[cfg(feature = "cli")]
pub mod sketch;
#[cfg(feature = "cli")]
pub mod teaching;

pub use params::BeltParams;

use crate::engine::{Body, ForceLaw};
use crate::error::{Error, Result};
use crate::models::param::ParamSpec;
use crate::models::{LawKind, Model, Physics};

/// The model's id.
pub const ID: &str = "belt";

impl Physics for BeltParams {
    const ID: &'static str = ID;
    const ABOUT: &'static str =
        "The textbook stick-slip oscillator: a spring-held block on a moving belt";
    const DEFAULTS_SOURCE: &'static str = params::DEFAULTS_SOURCE;
    const PARAMS: &'static [ParamSpec<Self>] = params::PARAMS;
    type Evaluation = results::Evaluation;

    fn into_model(self) -> Model {
        Model::Belt(self)
    }

    fn validate(&self) -> Result<()> {
        BeltParams::validate(self)
    }

    /// The period of the stick-slip cycle (B11) (s): an output of the motion, not of a
    /// forcing.
    fn period(&self) -> f64 {
        formula::evaluate(self).period
    }

    fn body(&self) -> Body {
        body::body(self)
    }

    /// None: the belt's force depends on the position, not on time.
    fn force_law(&self, _law: LawKind) -> Result<ForceLaw> {
        Err(Error::Unsupported {
            model: ID,
            what: "time-periodic force law: its force depends on the position and its belt \
                   moves (`stickslip eval belt` integrates it exactly)"
                .to_string(),
        })
    }

    fn evaluate(&self, cycles: u32) -> Result<results::Evaluation> {
        results::evaluate(self, cycles)
    }

    fn closed_form_regime(&self) -> &'static str {
        formula::evaluate(self).regime.id()
    }

    fn regime_words(id: &str) -> Option<&'static str> {
        [
            formula::Regime::StickSlip,
            formula::Regime::TouchingOscillation,
        ]
        .into_iter()
        .find(|r| r.id() == id)
        .map(formula::Regime::words)
    }
}

/// Sets the figure and sketch tests draw: the defaults, μd = μs (a touching oscillation) and a
/// stiff, light, fast set.
#[cfg(test)]
pub(crate) fn test_sets() -> Vec<BeltParams> {
    vec![
        BeltParams::default(),
        BeltParams {
            mu_d: 0.6,
            ..Default::default()
        },
        BeltParams {
            mass: 0.05,
            k: 2000.0,
            v_b: 2.0,
            mu_s: 1.2,
            mu_d: 0.3,
            ..Default::default()
        },
    ]
}
