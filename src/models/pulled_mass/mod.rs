//! The pulled mass of the paper's Sec. 2 (guide §5.1): a block pulled by a constant force
//! across a table while a hanging mass on a spring presses it down with N(t) = W(1 + cos ωt).
//! Everything about this model lives in this folder:
//!
//! ```text
//! body.rs        the body and the force laws (harmonic, linearized) for the engine
//! formula.rs     the closed forms of guide §7 and guide §9, one pure function per quantity
//! quantity.rs    the registry of the quantities: key, symbol, unit, equation, regimes
//! results.rs     the evaluation: closed forms, both laws integrated, checks, applicability
//! map.rs         the (μd, μs) domain maps, cell by cell (report and explorer)
//! explore.rs     what the explorer page asks of the model (regime sentence, apparatus)
//! explorer.js    the explorer page's drawing of the apparatus, animated
//! claims.rs      the paper's claims about this model (claims 1, 2)
//! derivation.rs  the worked substitutions (formula, numbers, value) of the closed forms
//! scene.rs       the report's figures of this model
//! ```

pub mod body;
pub(crate) mod claims;
#[cfg(feature = "cli")]
pub mod derivation;
#[cfg(feature = "cli")]
mod exercise;
pub mod explore;
pub mod formula;
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

pub use body::{body, force_law};
pub use params::PulledMassParams;

use crate::engine::{Body, ForceLaw};
use crate::error::Result;
use crate::models::param::ParamSpec;
use crate::models::{LawKind, Model, Physics};

impl Physics for PulledMassParams {
    const ID: &'static str = "pulled-mass";
    const ABOUT: &'static str =
        "The pulled mass pressed by an oscillating normal force (paper Sec. 2)";
    const DEFAULTS_SOURCE: &'static str = params::DEFAULTS_SOURCE;
    const PARAMS: &'static [ParamSpec<Self>] = params::PARAMS;
    type Evaluation = results::Evaluation;

    fn into_model(self) -> Model {
        Model::PulledMass(self)
    }

    fn validate(&self) -> Result<()> {
        PulledMassParams::validate(self)
    }

    fn period(&self) -> f64 {
        PulledMassParams::period(self)
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
        formula::regime(self.phi(), self.mu_s, self.mu_d).id()
    }

    fn regime_words(id: &str) -> Option<&'static str> {
        formula::Regime::ALL
            .iter()
            .find(|r| r.id() == id)
            .map(|r| r.words())
    }

    fn params_json(&self) -> serde_json::Value {
        serde_json::to_value(results::ParamsOut::of(self, 0)).unwrap_or_default()
    }
}
