//! The falling woodpecker of the paper's Sec. 3 (guide §5.2 and guide §8): a sleeve that slides and
//! sticks down a pole while the bird oscillates on its spring. Everything about this model
//! lives in this folder:
//!
//! ```text
//! body.rs        the sleeve as a body and the force laws (harmonic, linearized) for the engine
//! formula.rs     the closed forms of guide §8, one pure function per quantity
//! lobe.rs        the lobe engine: the periodic orbit of the linearized law in every regime
//! map.rs         the regime maps in the (μd, z0) plane, cell by cell (report and explorer)
//! explore.rs     what the explorer page asks of the model (regime sentence, apparatus)
//! explorer.js    the explorer page's drawing of the apparatus, animated
//! quantity.rs    the registry of the quantities: key, symbol, unit, equation, scope
//! results.rs     the evaluation: closed forms, both laws integrated, checks, applicability
//! claims.rs      the paper's claims about this model (claims 4, 6); halt.rs claim 5, lever.rs claim 8
//! derivation.rs  the worked substitutions (formula, numbers, value) of the closed forms
//! scene.rs       the report's figures of this model
//! fit/           the harmonic model fitted to a tracked toy (`stickslip fit`)
//! sketch.rs      the sketch of the apparatus with its forces (reports, handouts, worksheets)
//! ```

pub mod body;
pub(crate) mod claims;
#[cfg(feature = "cli")]
pub mod derivation;
#[cfg(feature = "cli")]
mod exercise;
pub mod explore;
#[cfg(feature = "cli")]
pub mod fit;
pub mod formula;
pub(crate) mod halt;
pub(crate) mod lever;
pub mod lobe;
pub mod map;
pub mod params;
#[cfg(feature = "cli")]
mod present;
pub mod quantity;
pub mod results;
#[cfg(feature = "cli")]
pub mod scene;
#[cfg(feature = "cli")]
mod scenes;
#[cfg(feature = "cli")]
pub mod sketch;
#[cfg(feature = "cli")]
mod tables;
#[cfg(feature = "cli")]
mod teaching;
pub mod threshold;

pub use body::{body, force_law, linear_amplitudes, spring_coordinate};
pub use params::{OmegaMode, WoodpeckerParams};

use crate::engine::{Body, ForceLaw};
use crate::error::Result;
use crate::models::param::{ChoiceSpec, ParamSpec};
use crate::models::{LawKind, Model, Physics};

impl Physics for WoodpeckerParams {
    const ID: &'static str = "woodpecker";
    const ABOUT: &'static str = "The falling woodpecker toy: the sleeve on the pole (paper Sec. 3)";
    const DEFAULTS_SOURCE: &'static str = params::DEFAULTS_SOURCE;
    const PARAMS: &'static [ParamSpec<Self>] = params::PARAMS;
    const CHOICES: &'static [ChoiceSpec<Self>] = params::CHOICES;
    type Evaluation = results::Evaluation;

    fn into_model(self) -> Model {
        Model::Woodpecker(self)
    }

    fn validate(&self) -> Result<()> {
        WoodpeckerParams::validate(self)
    }

    fn period(&self) -> f64 {
        WoodpeckerParams::period(self)
    }

    fn body(&self) -> Body {
        body::body(self)
    }

    fn force_law(&self, law: LawKind) -> Result<ForceLaw> {
        body::force_law(self, law)
    }

    fn evaluate(&self, periods: u32) -> Result<results::Evaluation> {
        results::evaluate(self, periods)
    }

    fn closed_form_regime(&self) -> &'static str {
        formula::evaluate(&results::linear_inputs(self)).regime.id()
    }

    fn regime_words(id: &str) -> Option<&'static str> {
        formula::OrbitRegime::ALL
            .iter()
            .find(|r| r.id() == id)
            .map(|r| r.words())
    }

    fn params_json(&self) -> serde_json::Value {
        serde_json::to_value(results::ParamsOut::of(self, 0)).unwrap_or_default()
    }
}
