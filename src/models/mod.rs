//! The models, and the one place that lists them.
//!
//! A model is the unit of extension: its folder (`src/models/<name>/`) holds its parameters
//! with their descriptors, its body and force laws for the engine, its closed forms, its
//! evaluation and checks, its claims, its worked derivations and its figures, and its params
//! struct implements [`Physics`] (and, with the `cli` feature, [`crate::present::Present`]).
//! The rest of the program holds a [`Model`], the enum of every model's parameters, and reaches
//! the model through [`with_model!`], which expands to a `match` with one arm per model.
//!
//! Why an enum plus a trait rather than `Box<dyn Trait>`: the evaluation, the figures and the
//! tables of each model are different types (the woodpecker has phases, counterparts and a
//! linear law that may not exist), so the code that uses them is generic over `M: Physics`
//! and monomorphised; the enum is the value people pass around (scenario files, command line,
//! sweeps, worksheets, benchmarks) and is listed once, in the [`registry!`] call below.
//!
//! Registering a model: a `pub mod` line here and one entry in the `registry!` call, with
//! the model's optional [`Capability`]s in brackets (test builds register a fourth model,
//! `dummy`, that way).

use serde::de::DeserializeOwned;
use serde::Serialize;

use crate::engine::{Body, ForceLaw};
use crate::error::Result;
use param::{ChoiceSpec, ParamSpec};

pub mod belt;
#[cfg(test)]
pub mod dummy;
pub mod paper;
pub mod param;
pub mod pulled_mass;
pub mod woodpecker;

/// Which force law drives the model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
#[serde(rename_all = "lowercase")]
pub enum LawKind {
    /// The real, harmonic oscillation (cos ωt).
    Harmonic,
    /// The triangle wave with the same extremes or zeros, for which the paper gives closed forms.
    Linear,
}

/// What the JSON Schema of an evaluation needs (`schemars::JsonSchema` with the `cli` feature,
/// which writes the schemas; nothing without it): every model's `eval --json` gets its schema
/// from the registry, with no list of models in `crate::schema`.
#[cfg(feature = "cli")]
pub trait EvaluationSchema: schemars::JsonSchema {}
#[cfg(feature = "cli")]
impl<T: schemars::JsonSchema> EvaluationSchema for T {}
/// What the JSON Schema of an evaluation needs: nothing without the `cli` feature.
#[cfg(not(feature = "cli"))]
pub trait EvaluationSchema {}
#[cfg(not(feature = "cli"))]
impl<T> EvaluationSchema for T {}

/// What the engine and the command line need of a model; implemented by its params struct.
pub trait Physics:
    Copy + Default + PartialEq + std::fmt::Debug + Serialize + DeserializeOwned + Send + Sync + 'static
{
    /// The id on the command line and in scenario files ("pulled-mass").
    const ID: &'static str;
    /// One line on what the model is (the `--help` of its subcommand).
    const ABOUT: &'static str;
    /// Where the default parameters come from.
    const DEFAULTS_SOURCE: &'static str;
    /// Every numeric parameter, described once.
    const PARAMS: &'static [ParamSpec<Self>];
    /// The parameters that take one of a few named values.
    const CHOICES: &'static [ChoiceSpec<Self>] = &[];
    /// The evaluation of guide §14: closed forms, both laws integrated, checks.
    type Evaluation: Serialize + EvaluationSchema;

    /// These parameters as a [`Model`].
    fn into_model(self) -> Model;
    /// Checks every parameter against its valid range.
    fn validate(&self) -> Result<()>;
    /// Period T of the forcing (s).
    fn period(&self) -> f64;
    /// The body the engine moves.
    fn body(&self) -> Body;
    /// The force law of `law` (the linearized law may not exist for some parameters).
    fn force_law(&self, law: LawKind) -> Result<ForceLaw>;
    /// Validates, evaluates the closed forms and integrates both laws for `periods` periods.
    fn evaluate(&self, periods: u32) -> Result<Self::Evaluation>;
    /// The id of the regime of the linearized law's closed forms.
    fn closed_form_regime(&self) -> &'static str;
    /// The `params` object of `eval --json` (guide §14): the inputs with their derived
    /// quantities; by default the inputs alone.
    fn params_json(&self) -> serde_json::Value {
        serde_json::to_value(self).unwrap_or_default()
    }
    /// The words of this model's regime `id` (its closed forms' regimes), `None` for an id it
    /// does not define.
    fn regime_words(_id: &str) -> Option<&'static str> {
        None
    }
}

/// What a model may offer beyond [`Physics`], each an optional capability: the commands that
/// need one refuse a model without it ([`Model::require`]), never serve it empty or borrowed
/// output. A capability is a trait the model's params struct implements in its folder.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Capability {
    /// `crate::present::Present`: report scenes and figures, tables, derivation, text, CSV.
    Present,
    /// [`crate::explore::Explore`]: the explorer page (regime sentence, apparatus, regime map).
    Explore,
    /// `crate::worksheet::Exercise`: worksheets, and `check`'s draws over the model's domain.
    Exercise,
    /// [`crate::claims::PaperClaims`]: the paper's claims about the model (`stickslip claims`).
    Claims,
    /// `crate::fit::FitTracked`: the model fitted to tracked data (`stickslip fit`).
    Fit,
}

impl Capability {
    /// The capability's name in the registry ("present").
    pub fn id(self) -> &'static str {
        match self {
            Capability::Present => "present",
            Capability::Explore => "explore",
            Capability::Exercise => "exercise",
            Capability::Claims => "claims",
            Capability::Fit => "fit",
        }
    }

    /// What the capability gives, for a refusal ("report pages, tables or figures").
    pub fn words(self) -> &'static str {
        match self {
            Capability::Present => "report pages, handouts, sweeps, figures or text tables yet",
            Capability::Explore => "explorer page yet",
            Capability::Exercise => "worksheets, nor the drawn parameter sets of `check`",
            Capability::Claims => "claims of the paper to check",
            Capability::Fit => "fit of tracked data",
        }
    }
}

/// `pick!(cap [caps…] {yes} {no})`: `yes` when `cap` is one of `caps`, else `no` (the branch
/// not taken is dropped before type checking: a model need not implement a capability it does
/// not list).
#[doc(hidden)]
macro_rules! pick {
    (present [present $($rest:ident)*] $yes:tt $no:tt) => { $yes };
    (explore [explore $($rest:ident)*] $yes:tt $no:tt) => { $yes };
    (exercise [exercise $($rest:ident)*] $yes:tt $no:tt) => { $yes };
    (claims [claims $($rest:ident)*] $yes:tt $no:tt) => { $yes };
    (fit [fit $($rest:ident)*] $yes:tt $no:tt) => { $yes };
    ($cap:ident [] $yes:tt $no:tt) => { $no };
    ($cap:ident [$first:ident $($rest:ident)*] $yes:tt $no:tt) => {
        $crate::models::pick!($cap [$($rest)*] $yes $no)
    };
}
pub(crate) use pick;

/// Lists the models once: the [`Model`] enum, [`Model::defaults`], [`Model::has`] and the
/// dispatch macros [`with_model!`] and [`with_capability!`] are generated from the one list.
/// Each entry lists the model's optional capabilities ([`Capability`]) in brackets.
macro_rules! registry {
    ($d:tt $($(#[$meta:meta])* $variant:ident($params:ty) [$($cap:ident)*]),+ $(,)?) => {
        /// A model with its parameters: the value the rest of the program passes around.
        #[derive(Clone, Copy, Debug, PartialEq, Serialize)]
        #[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
        #[serde(untagged)]
        pub enum Model {
            $($(#[$meta])* $variant($params)),+
        }

        impl Model {
            /// Every model with its default parameters, in the order of the registry.
            // Pushed one by one: an entry may be under `#[cfg]`, which an element of `vec![]`
            // cannot carry.
            #[allow(clippy::vec_init_then_push)]
            pub fn defaults() -> Vec<Model> {
                let mut all = Vec::new();
                $($(#[$meta])* all.push(Model::$variant(<$params>::default()));)+
                all
            }

            /// Whether the model offers `capability`.
            pub fn has(&self, capability: Capability) -> bool {
                let caps: &[&str] = match self {
                    $($(#[$meta])* Model::$variant(_) => &[$(stringify!($cap)),*],)+
                };
                caps.contains(&capability.id())
            }
        }

        /// `with_model!(model, p => expr)`: `expr` with `p` bound to the model's params struct
        /// (a `match` with one arm per registered model): for what every model has
        /// ([`Physics`]).
        macro_rules! with_model {
            ($d m:expr, $d p:ident => $d body:expr) => {
                match $d m {
                    $($(#[$meta])* $crate::models::Model::$variant($d p) => $d body,)+
                }
            };
        }

        /// `with_capability!(model, cap, p => expr, else missing)`: `expr` with `p` bound to
        /// the params struct of a model that offers capability `cap` (`present`, `explore`,
        /// `exercise`, `claims`), `missing` for the others.
        macro_rules! with_capability {
            ($d m:expr, $d cap:ident, $d p:ident => $d body:expr, else $d missing:expr) => {
                match $d m {
                    $($(#[$meta])* $crate::models::Model::$variant($d p) => $crate::models::pick!(
                        $d cap [$($cap)*] { $d body } { let _ = $d p; $d missing }
                    ),)+
                }
            };
        }
    };
}

registry! {$
    PulledMass(pulled_mass::PulledMassParams) [present explore exercise claims],
    Woodpecker(woodpecker::WoodpeckerParams) [present explore exercise claims fit],
    Belt(belt::BeltParams) [present explore exercise],
    // A test build's fourth model: its folder and this line, nothing else (README).
    #[cfg(test)]
    Dummy(dummy::DummyParams) [],
}

// The explorer and the presentation layer dispatch on the model too.
pub(crate) use {with_capability, with_model};

impl Model {
    /// The model's id ("pulled-mass", "woodpecker").
    pub fn id(&self) -> &'static str {
        fn id<M: Physics>(_: &M) -> &'static str {
            M::ID
        }
        with_model!(self, p => id(p))
    }

    /// The default parameters of the model with `id`.
    pub fn from_id(id: &str) -> Option<Model> {
        Self::defaults().into_iter().find(|m| m.id() == id)
    }

    /// The words of regime `id` of any registered model, in the order of the registry
    /// (`None`: no model defines it).
    pub fn regime_words(id: &str) -> Option<&'static str> {
        fn words<M: Physics>(_: &M, id: &str) -> Option<&'static str> {
            M::regime_words(id)
        }
        Self::defaults()
            .iter()
            .find_map(|m| with_model!(m, p => words(p, id)))
    }

    /// Every model id, in the order of the registry.
    pub fn ids() -> Vec<&'static str> {
        Self::defaults().iter().map(Model::id).collect()
    }

    /// Refuses the model when it lacks `capability`: the one-line error of a command that
    /// needs it.
    pub fn require(&self, capability: Capability) -> Result<()> {
        if self.has(capability) {
            Ok(())
        } else {
            Err(self.missing(capability))
        }
    }

    /// The refusal of a command that needs `capability` of this model.
    pub fn missing(&self, capability: Capability) -> crate::error::Error {
        crate::error::Error::Unsupported {
            model: self.id(),
            what: capability.words().to_string(),
        }
    }

    /// The registered models that offer `capability`, with their default parameters.
    pub fn offering(capability: Capability) -> Vec<Model> {
        Self::defaults()
            .into_iter()
            .filter(|m| m.has(capability))
            .collect()
    }

    /// Checks every parameter against its valid range.
    pub fn validate(&self) -> Result<()> {
        with_model!(self, p => p.validate())
    }

    /// Period T of the forcing (s).
    pub fn period(&self) -> f64 {
        with_model!(self, p => p.period())
    }

    /// The body the engine moves.
    pub fn body(&self) -> Body {
        with_model!(self, p => p.body())
    }

    /// The force law of `law`.
    pub fn force_law(&self, law: LawKind) -> Result<ForceLaw> {
        with_model!(self, p => p.force_law(law))
    }

    /// The id of the regime of the linearized law's closed forms.
    pub fn closed_form_regime(&self) -> &'static str {
        with_model!(self, p => p.closed_form_regime())
    }

    /// The keys of the numeric parameters.
    pub fn param_keys(&self) -> Vec<&'static str> {
        fn keys<M: Physics>(_: &M) -> Vec<&'static str> {
            M::PARAMS.iter().map(|s| s.key).collect()
        }
        with_model!(self, p => keys(p))
    }

    /// The value of numeric parameter `key` (`None`: no such parameter, or an unset optional).
    pub fn get(&self, key: &str) -> Option<f64> {
        fn get<M: Physics>(p: &M, key: &str) -> Option<f64> {
            M::PARAMS
                .iter()
                .find(|s| s.key == key)
                .and_then(|s| (s.get)(p))
        }
        with_model!(self, p => get(p, key))
    }

    /// Sets numeric parameter `key`; false when the model has no such parameter.
    pub fn set(&mut self, key: &str, value: f64) -> bool {
        fn set<M: Physics>(p: &mut M, key: &str, value: f64) -> bool {
            M::PARAMS
                .iter()
                .find(|s| s.key == key)
                .map(|s| (s.set)(p, value))
                .is_some()
        }
        with_model!(self, p => set(p, key, value))
    }

    /// A one-line hint when parameter `key` = `value` (SI) looks typed in the unit people think
    /// in rather than SI: a length or mass whose usual unit is mm or g given between 1 and
    /// 10 000 m or kg (`--z0 7` meant as 7 mm). `None` when nothing looks amiss.
    pub fn unit_hint(&self, key: &str, value: f64) -> Option<String> {
        fn hint<M: Physics>(_: &M, key: &str, value: f64) -> Option<String> {
            let spec = M::PARAMS.iter().find(|s| s.key == key)?;
            let (unit, factor) = spec.display;
            (factor == 1e3 && matches!(unit, "mm" | "g") && (1.0..1e4).contains(&value)).then(
                || {
                    format!(
                        "hint: {} = {} {} is large for a lab set-up; --{} takes {}: for {} {unit} \
                     give --{} {}",
                        spec.symbol,
                        crate::error::short(value),
                        spec.unit,
                        spec.flag(),
                        spec.unit,
                        crate::error::short(value),
                        spec.flag(),
                        crate::error::short(value / factor)
                    )
                },
            )
        }
        with_model!(self, p => hint(p, key, value))
    }

    /// Sets option `key` to `value` (one of its values); false when there is no such option.
    pub fn set_choice(&mut self, key: &str, value: &str) -> bool {
        fn set<M: Physics>(p: &mut M, key: &str, value: &str) -> bool {
            M::CHOICES
                .iter()
                .find(|s| s.key == key && s.values.contains(&value))
                .map(|s| (s.set)(p, value))
                .is_some()
        }
        with_model!(self, p => set(p, key, value))
    }

    /// The model with the parameters of a scenario's `[params]` table (defaults for the keys it
    /// omits); `path` names the file in errors.
    pub fn with_scenario_params(
        &self,
        table: &toml::Table,
        path: &std::path::Path,
    ) -> Result<Model> {
        fn read<M: Physics>(_: &M, table: &toml::Table, path: &std::path::Path) -> Result<Model> {
            crate::params::Scenario::read_params::<M>(table, path).map(M::into_model)
        }
        with_model!(self, p => read(p, table, path))
    }
}

impl Model {
    /// The inputs with their derived quantities, as the `params` object of `eval --json`
    /// (guide §14), without `periods`.
    pub fn derived_params(&self) -> serde_json::Map<String, serde_json::Value> {
        let mut map = match with_model!(self, p => p.params_json()) {
            serde_json::Value::Object(map) => map,
            _ => serde_json::Map::new(),
        };
        map.remove("periods");
        map
    }

    /// The keys of [`Model::derived_params`] that are derived, not inputs (`omega`, the value
    /// of ω, among them).
    pub fn derived_keys(&self) -> Vec<String> {
        let inputs = with_model!(self, p => serde_json::to_value(p).unwrap_or_default());
        self.derived_params()
            .keys()
            .filter(|k| inputs.get(k.as_str()).is_none())
            .cloned()
            .collect()
    }
}

/// The words of the regime whose id is `id` (the closed forms of any model, or an integration),
/// or `id` itself if it names none.
pub fn regime_words(id: &str) -> &str {
    use crate::engine::IntegrationRegime;
    Model::regime_words(id)
        .or_else(|| {
            IntegrationRegime::ALL
                .iter()
                .find(|r| r.id() == id)
                .map(|r| r.words())
        })
        .unwrap_or(id)
}

/// A parameter of a model as the command line shows it: its key, its help with the default,
/// and its values when it is a choice.
#[derive(Clone, Debug, PartialEq)]
pub struct FlagInfo {
    pub key: &'static str,
    pub help: String,
    /// `None` for a number.
    pub values: Option<&'static [&'static str]>,
}

impl Model {
    /// One line on what the model is.
    pub fn about(&self) -> &'static str {
        fn about<M: Physics>(_: &M) -> &'static str {
            M::ABOUT
        }
        with_model!(self, p => about(p))
    }

    /// Every parameter of the model as a flag, numbers first, with the defaults of `self`.
    pub fn flags(&self) -> Vec<FlagInfo> {
        fn flags<M: Physics>(p: &M) -> Vec<FlagInfo> {
            let numbers = M::PARAMS.iter().map(|s| FlagInfo {
                key: s.key,
                help: format!(
                    "{} [default: {}]",
                    s.help,
                    (s.get)(p).map_or(s.unset.to_string(), |v| v.to_string())
                ),
                values: None,
            });
            let choices = M::CHOICES.iter().map(|c| FlagInfo {
                key: c.key,
                help: format!("{} [default: {}]", c.help, (c.get)(p)),
                values: Some(c.values),
            });
            numbers.chain(choices).collect()
        }
        with_model!(self, p => flags(p))
    }
}
