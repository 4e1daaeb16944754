//! The woodpecker's parameters: the values, the paper's Fig. 15 set as defaults, and the
//! descriptor of each parameter (symbol, unit, range, help), the two options among them.

use serde::{Deserialize, Serialize};

use crate::error::Result;
use crate::models::param::{
    dynamic_friction, gravity, invalid, num, static_friction, validate_all, ChoiceSpec, ParamSpec,
    Rule,
};
use crate::models::woodpecker::formula::Counterpart;
use crate::params::G_STANDARD;

/// How ω of the harmonic woodpecker is defined (guide §5.2; regimes do not depend on it).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
#[serde(rename_all = "lowercase")]
pub enum OmegaMode {
    /// ω = √(k/m_W) (default: reproduces the paper's figures).
    Bird,
    /// ω = √(k (m_S + m_W)/(m_S m_W)), the reduced mass.
    Reduced,
    /// ω = √(k/(m_S + m_W)).
    Total,
}

impl OmegaMode {
    /// Every mode with its id, as typed on the command line and in scenario files.
    pub const ALL: [(Self, &'static str); 3] = [
        (Self::Bird, "bird"),
        (Self::Reduced, "reduced"),
        (Self::Total, "total"),
    ];

    /// The id of the mode, as typed.
    pub fn id(self) -> &'static str {
        Self::ALL
            .iter()
            .find(|(mode, _)| *mode == self)
            .map_or("bird", |(_, id)| id)
    }
}

/// The falling woodpecker of Sec. 3 (guide §5.2 and guide §8). Defaults: the paper's Fig. 15 set.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
#[serde(default, deny_unknown_fields)]
pub struct WoodpeckerParams {
    /// Static friction coefficient μs.
    pub mu_s: f64,
    /// Dynamic friction coefficient μd (0 < μd ≤ μs).
    pub mu_d: f64,
    /// Spring constant k (N/m).
    pub k: f64,
    /// Sleeve mass m_S (kg).
    pub m_sleeve: f64,
    /// Woodpecker (bird) mass m_W (kg).
    pub m_bird: f64,
    /// Lever arm l of the spring force about the sleeve centre (m).
    pub l: f64,
    /// Distance h between the two pole contacts (m).
    pub h: f64,
    /// Spring offset z0 (m).
    pub z0: f64,
    /// Spring oscillation amplitude d0 (m).
    pub d0: f64,
    /// Gravitational acceleration g (m/s²).
    pub g: f64,
    /// Lever ratio λ (N = λ|F_e| at each contact); `None` = l/h.
    pub lever: Option<f64>,
    /// Definition of ω (TOML key `omega`; written as `omega_mode` in JSON output, where
    /// `omega` is the value in rad/s).
    #[serde(rename(serialize = "omega_mode", deserialize = "omega"))]
    pub omega: OmegaMode,
    /// Linear counterpart of the harmonic spring coordinate (guide §5.2).
    pub counterpart: Counterpart,
}

/// Where the defaults come from.
pub const DEFAULTS_SOURCE: &str = "the paper's Fig. 15 set";

impl Default for WoodpeckerParams {
    /// The Fig. 15 set: μs = 0.65, μd = 0.32, k = 20 N/m, m_S = 6 g, m_W = 14 g, l = 16 mm,
    /// h = 7 mm, z0 = 7 mm, d0 = 9 mm; λ = l/h, ω = √(k/m_W), counterpart `zeros`.
    fn default() -> Self {
        Self {
            mu_s: 0.65,
            mu_d: 0.32,
            k: 20.0,
            m_sleeve: 0.006,
            m_bird: 0.014,
            l: 0.016,
            h: 0.007,
            z0: 0.007,
            d0: 0.009,
            g: G_STANDARD,
            lever: None,
            omega: OmegaMode::Bird,
            counterpart: Counterpart::Zeros,
        }
    }
}

/// A length in m, shown in mm.
const fn length(
    key: &'static str,
    symbol: &'static str,
    tex: &'static str,
    what: &'static str,
    help: &'static str,
    get: fn(&WoodpeckerParams) -> Option<f64>,
    set: fn(&mut WoodpeckerParams, f64),
) -> ParamSpec<WoodpeckerParams> {
    ParamSpec {
        key,
        symbol,
        tex,
        what,
        unit: "m",
        display: ("mm", 1e3),
        rule: Rule::Positive,
        help,
        unset: "",
        get,
        set,
    }
}

/// A mass in kg, shown in g.
const fn mass(
    key: &'static str,
    symbol: &'static str,
    what: &'static str,
    help: &'static str,
    get: fn(&WoodpeckerParams) -> Option<f64>,
    set: fn(&mut WoodpeckerParams, f64),
) -> ParamSpec<WoodpeckerParams> {
    ParamSpec {
        key,
        symbol,
        tex: symbol,
        what,
        unit: "kg",
        display: ("g", 1e3),
        rule: Rule::Positive,
        help,
        unset: "",
        get,
        set,
    }
}

/// Every numeric parameter of the woodpecker, in the order of flags, tables and validation.
pub const PARAMS: &[ParamSpec<WoodpeckerParams>] = &[
    static_friction(|p| Some(p.mu_s), |p, v| p.mu_s = v),
    dynamic_friction(|p| Some(p.mu_d), |p, v| p.mu_d = v),
    ParamSpec {
        key: "k",
        symbol: "k",
        tex: "k",
        what: "spring",
        unit: "N/m",
        display: ("N/m", 1.0),
        rule: Rule::Positive,
        help: "Spring constant k in N/m",
        unset: "",
        get: |p| Some(p.k),
        set: |p, v| p.k = v,
    },
    mass(
        "m_sleeve",
        "m_S",
        "sleeve",
        "Sleeve mass m_S in kg",
        |p| Some(p.m_sleeve),
        |p, v| p.m_sleeve = v,
    ),
    mass(
        "m_bird",
        "m_W",
        "woodpecker",
        "Woodpecker (bird) mass m_W in kg",
        |p| Some(p.m_bird),
        |p, v| p.m_bird = v,
    ),
    length(
        "l",
        "l",
        "l",
        "lever arm of the spring force",
        "Lever arm l of the spring force in m",
        |p| Some(p.l),
        |p, v| p.l = v,
    ),
    length(
        "h",
        "h",
        "h",
        "distance of the two contacts",
        "Distance h between the two pole contacts in m",
        |p| Some(p.h),
        |p, v| p.h = v,
    ),
    ParamSpec {
        rule: Rule::Finite,
        ..length(
            "z0",
            "z0",
            "z_0",
            "spring offset",
            "Spring offset z0 in m",
            |p| Some(p.z0),
            |p, v| p.z0 = v,
        )
    },
    length(
        "d0",
        "d0",
        "d_0",
        "spring amplitude",
        "Spring oscillation amplitude d0 in m",
        |p| Some(p.d0),
        |p, v| p.d0 = v,
    ),
    gravity(|p| Some(p.g), |p, v| p.g = v),
    ParamSpec {
        key: "lever",
        symbol: "λ",
        tex: r"\lambda",
        what: "lever ratio",
        unit: "",
        display: ("", 1.0),
        rule: Rule::Positive,
        help: "Lever ratio λ (each contact carries λ|F_e|)",
        unset: "l/h",
        get: |p| p.lever,
        set: |p, v| p.lever = Some(v),
    },
];

/// The two options of the woodpecker.
pub const CHOICES: &[ChoiceSpec<WoodpeckerParams>] = &[
    ChoiceSpec {
        key: "omega",
        help: "Definition of ω: bird √(k/m_W), reduced √(k(m_S+m_W)/(m_S m_W)), total \
               √(k/(m_S+m_W))",
        values: &["bird", "reduced", "total"],
        get: |p| {
            OmegaMode::ALL
                .iter()
                .find(|(m, _)| *m == p.omega)
                .map_or("", |m| m.1)
        },
        set: |p, id| {
            if let Some((m, _)) = OmegaMode::ALL.iter().find(|(_, name)| *name == id) {
                p.omega = *m;
            }
        },
    },
    ChoiceSpec {
        key: "counterpart",
        help: "Linear counterpart of the harmonic spring coordinate: extremes, zeros or tangent \
               (guide §5.2)",
        values: &["extremes", "zeros", "tangent"],
        get: |p| p.counterpart.id(),
        set: |p, id| {
            if let Some(c) = Counterpart::from_id(id) {
                p.counterpart = c;
            }
        },
    },
];

/// The least ε = W_S/(k d0) accepted. The slips happen where the spring force F_e crosses zero
/// and last about ε of the period: below this the sleeve's weight, which drives them, is a
/// difference of spring forces more than 1/ε times larger, and double precision cannot
/// resolve the slip to the checks' tolerance (at ε ≈ 1e-13 not even its regime). The pulled
/// mass refuses φ < 1e-9 for the same reason.
pub const EPS_MIN: f64 = 1e-9;

impl WoodpeckerParams {
    /// Checks every parameter against its valid range.
    pub fn validate(&self) -> Result<()> {
        validate_all(PARAMS, self, self.mu_s)
    }

    /// Checks ε = W_S/(k d0) against [`EPS_MIN`] (named by the sleeve mass, which sets W_S):
    /// a combination of valid parameters whose slips double precision cannot resolve. Asked by
    /// the force laws ([`super::force_law`]), so that every evaluation, figure and fit refuses
    /// it; not by [`WoodpeckerParams::validate`], whose ranges hold parameter by parameter (a
    /// fit maps its whole internal space into them).
    pub fn check_resolution(&self) -> Result<()> {
        let eps = self.eps();
        if eps >= EPS_MIN {
            return Ok(());
        }
        Err(invalid(
            "m_sleeve",
            num(self.m_sleeve),
            format!(
                "eps = W_S/(k d0) = m_sleeve g/(k d0) >= {} (here eps = {}): slips shorter than \
                 that are beyond double precision",
                num(EPS_MIN),
                num(eps)
            ),
        ))
    }

    /// ε = W_S/(k d0): the sleeve's weight against the spring force's amplitude, about the
    /// length of a slip in periods.
    pub fn eps(&self) -> f64 {
        self.sleeve_weight() / (self.k * self.d0)
    }

    /// Lever ratio λ: the given one, else l/h.
    pub fn lambda(&self) -> f64 {
        self.lever.unwrap_or(self.l / self.h)
    }

    /// Sleeve weight W_S = m_S g (N).
    pub fn sleeve_weight(&self) -> f64 {
        self.m_sleeve * self.g
    }

    /// Angular frequency ω (rad/s) of the chosen mode.
    pub fn omega(&self) -> f64 {
        let (k, ms, mw) = (self.k, self.m_sleeve, self.m_bird);
        match self.omega {
            OmegaMode::Bird => (k / mw).sqrt(),
            OmegaMode::Reduced => (k * (ms + mw) / (ms * mw)).sqrt(),
            OmegaMode::Total => (k / (ms + mw)).sqrt(),
        }
    }

    /// Period T = 2π/ω (s).
    pub fn period(&self) -> f64 {
        std::f64::consts::TAU / self.omega()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_descriptor_reads_and_writes_its_own_field() {
        for (i, spec) in PARAMS.iter().enumerate() {
            let mut p = WoodpeckerParams::default();
            let v = 1000.0 + i as f64;
            (spec.set)(&mut p, v);
            assert_eq!((spec.get)(&p), Some(v), "{}", spec.key);
            let hits = PARAMS.iter().filter(|s| (s.get)(&p) == Some(v)).count();
            assert_eq!(hits, 1, "{}", spec.key);
        }
    }

    #[test]
    fn every_choice_round_trips_through_its_id_and_serde() {
        for choice in CHOICES {
            for id in choice.values {
                let mut p = WoodpeckerParams::default();
                (choice.set)(&mut p, id);
                assert_eq!((choice.get)(&p), *id);
                let json = serde_json::to_value(p).unwrap();
                let key = if choice.key == "omega" {
                    "omega_mode"
                } else {
                    choice.key
                };
                assert_eq!(json[key], *id);
            }
        }
    }
}
