//! A fourth model of test builds only, to hold the README's "Adding a model" to its word: this
//! folder and one line of the registry (`src/models/mod.rs`, under `#[cfg(test)]`) are all it
//! needs. The physics is the belt without friction: a block of mass m on a spring k, released
//! at x = 0 with the speed v_b of the belt under it, oscillates harmonically for ever,
//!
//! ```text
//! x = (v_b/ω) sin ωt,   T = 2π/ω,   ω = √(k/m)
//! ```
//!
//! touching the belt's speed once a period; the engine's autonomous run finds the same period
//! from its events.

use serde::{Deserialize, Serialize};

use crate::engine::{integrate_surface, Body, ForceLaw, SurfaceLaw, SurfaceOptions};
use crate::error::{Error, Result};
use crate::models::param::{validate_all, ParamSpec, Rule};
use crate::models::{LawKind, Model, Physics};
use crate::results::checks::rel_diff;

/// The frictionless block on a spring and a belt.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
#[serde(default, deny_unknown_fields)]
pub struct DummyParams {
    /// Mass m (kg).
    pub mass: f64,
    /// Spring constant k (N/m).
    pub k: f64,
    /// Speed v_b of the belt (m/s).
    pub v_b: f64,
}

impl Default for DummyParams {
    /// m = 1 kg, k = 100 N/m, v_b = 0.1 m/s.
    fn default() -> Self {
        Self {
            mass: 1.0,
            k: 100.0,
            v_b: 0.1,
        }
    }
}

/// A parameter with its range.
const fn spec(
    key: &'static str,
    unit: &'static str,
    (lo, hi): (f64, f64),
    help: &'static str,
    get: fn(&DummyParams) -> Option<f64>,
    set: fn(&mut DummyParams, f64),
) -> ParamSpec<DummyParams> {
    ParamSpec {
        key,
        symbol: key,
        tex: key,
        what: "",
        unit,
        display: (unit, 1.0),
        rule: Rule::Range { lo, hi },
        help,
        unset: "",
        get,
        set,
    }
}

const PARAMS: &[ParamSpec<DummyParams>] = &[
    spec(
        "mass",
        "kg",
        (0.01, 10.0),
        "Mass m in kg",
        |p| Some(p.mass),
        |p, v| p.mass = v,
    ),
    spec(
        "k",
        "N/m",
        (1.0, 1e4),
        "Spring constant k in N/m",
        |p| Some(p.k),
        |p, v| p.k = v,
    ),
    spec(
        "v_b",
        "m/s",
        (1e-4, 10.0),
        "Belt speed v_b in m/s",
        |p| Some(p.v_b),
        |p, v| p.v_b = v,
    ),
];

/// The period, closed form and measured, and their agreement.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Evaluation {
    pub model: &'static str,
    pub params: DummyParams,
    /// T = 2π/ω (s).
    pub closed_form: f64,
    /// The period of the engine's cycle (s).
    pub numeric: Option<f64>,
    pub rel_error: Option<f64>,
}

impl Physics for DummyParams {
    const ID: &'static str = "dummy";
    const ABOUT: &'static str = "A frictionless block on a spring released on a belt (tests)";
    const DEFAULTS_SOURCE: &'static str = "round numbers";
    const PARAMS: &'static [ParamSpec<Self>] = PARAMS;
    type Evaluation = Evaluation;

    fn into_model(self) -> Model {
        Model::Dummy(self)
    }

    fn validate(&self) -> Result<()> {
        validate_all(PARAMS, self, 0.0)
    }

    fn period(&self) -> f64 {
        std::f64::consts::TAU * (self.mass / self.k).sqrt()
    }

    fn body(&self) -> Body {
        Body {
            mass: self.mass,
            mu_s: 0.0,
            mu_d: 0.0,
        }
    }

    fn force_law(&self, _law: LawKind) -> Result<ForceLaw> {
        Err(Error::Unsupported {
            model: Self::ID,
            what: "time-periodic force law".to_string(),
        })
    }

    fn evaluate(&self, periods: u32) -> Result<Evaluation> {
        self.validate()?;
        let law = SurfaceLaw::new(0.0, -self.k, self.mass * 9.81, self.v_b)?;
        let opts = SurfaceOptions {
            x0: 0.0,
            slips: periods,
            record_segments: false,
        };
        let run = integrate_surface(&self.body(), &law, &opts)?;
        let numeric = run.cycle.map(|c| c.period);
        Ok(Evaluation {
            model: Self::ID,
            params: *self,
            closed_form: self.period(),
            numeric,
            rel_error: numeric.map(|n| rel_diff(self.period(), n)),
        })
    }

    fn closed_form_regime(&self) -> &'static str {
        "harmonic"
    }
}

#[cfg(test)]
mod tests {
    use crate::explore::{evaluate, Setup};
    use crate::models::{Capability, Model};

    #[test]
    fn the_fourth_model_is_registered_evaluated_and_refused_where_it_offers_nothing() {
        assert!(Model::ids().contains(&"dummy"));
        let setup = Setup {
            model: "dummy".to_string(),
            params: [("k".to_string(), 400.0)].into(),
            ..Setup::default()
        };
        let json = evaluate(&setup, 3).unwrap();
        assert_eq!(json["closed_form"], std::f64::consts::TAU / 20.0);
        assert!(json["rel_error"].as_f64().unwrap() <= 1e-14, "{json}");
        let model = setup.model().unwrap();
        for capability in [
            Capability::Present,
            Capability::Explore,
            Capability::Exercise,
            Capability::Claims,
        ] {
            let refused = model.require(capability).unwrap_err().to_string();
            assert!(refused.starts_with("the dummy model has no"), "{refused}");
        }
        let refused = crate::claims::of(&model, &crate::claims::Sample::default());
        assert_eq!(
            refused.unwrap_err().to_string(),
            "the dummy model has no claims of the paper to check"
        );
    }
}
