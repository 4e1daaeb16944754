//! The pulled mass's parameters: the values, the paper's Fig. 6 set as defaults, and the
//! descriptor of each parameter (symbol, unit, range, help).

use serde::{Deserialize, Serialize};

use crate::error::Result;
use crate::models::param::{
    dynamic_friction, gravity, invalid, num, static_friction, validate_all, ParamSpec, Rule,
};
use crate::params::G_STANDARD;

/// The pulled mass of Sec. 2 (guide §5.1). Defaults: the paper's Fig. 6 set.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
#[serde(default, deny_unknown_fields)]
pub struct PulledMassParams {
    /// Static friction coefficient μs.
    pub mu_s: f64,
    /// Dynamic friction coefficient μd (0 < μd ≤ μs).
    pub mu_d: f64,
    /// Mass m of the block (kg); the hanging mass m' = m, so the inertial mass is 2m.
    pub mass: f64,
    /// Spring constant k (N/m) of the hanging mass' spring.
    pub k: f64,
    /// Constant pulling force F (N).
    pub force: f64,
    /// Gravitational acceleration g (m/s²).
    pub g: f64,
}

/// The range of φ = F/W accepted. Below 1e-9 the pull is nothing against the weight: the
/// slip is a difference of forces 10⁹ times larger and double precision cannot measure it
/// to the checks' tolerance. Above 1e6 (the block pulled with a million times its weight,
/// 10⁴ times the largest 2μs) the mean speed g T φ³ Γ is beyond any apparatus.
pub const PHI_RANGE: (f64, f64) = (1e-9, 1e6);

/// Where the defaults come from.
pub const DEFAULTS_SOURCE: &str = "the paper's Fig. 6 set";

impl Default for PulledMassParams {
    /// The Fig. 6 set: μs = 0.4, μd = 0.25, m = 0.06 kg, k = 45 N/m, F = 0.18 N.
    fn default() -> Self {
        Self {
            mu_s: 0.4,
            mu_d: 0.25,
            mass: 0.06,
            k: 45.0,
            force: 0.18,
            g: G_STANDARD,
        }
    }
}

/// Every parameter of the pulled mass, in the order of flags, tables and validation.
pub const PARAMS: &[ParamSpec<PulledMassParams>] = &[
    static_friction(|p| Some(p.mu_s), |p, v| p.mu_s = v),
    dynamic_friction(|p| Some(p.mu_d), |p, v| p.mu_d = v),
    ParamSpec {
        key: "mass",
        symbol: "m",
        tex: "m",
        what: "block; hanging mass m' = m",
        unit: "kg",
        display: ("g", 1e3),
        rule: Rule::Positive,
        help: "Mass m of the block in kg (the hanging mass is equal)",
        unset: "",
        get: |p| Some(p.mass),
        set: |p, v| p.mass = v,
    },
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
    ParamSpec {
        key: "force",
        symbol: "F",
        tex: "F",
        what: "pull",
        unit: "N",
        display: ("mN", 1e3),
        rule: Rule::Positive,
        help: "Pulling force F in N",
        unset: "",
        get: |p| Some(p.force),
        set: |p, v| p.force = v,
    },
    gravity(|p| Some(p.g), |p, v| p.g = v),
];

impl PulledMassParams {
    /// Checks every parameter against its valid range, then φ = F/W against [`PHI_RANGE`]
    /// (named by the force, which sets it).
    pub fn validate(&self) -> Result<()> {
        validate_all(PARAMS, self, self.mu_s)?;
        let phi = self.phi();
        let (lo, hi) = PHI_RANGE;
        if (lo..=hi).contains(&phi) {
            Ok(())
        } else {
            Err(invalid(
                "force",
                num(self.force),
                format!(
                    "{} <= phi = F/(m g) <= {} (here phi = {})",
                    num(lo),
                    num(hi),
                    num(phi)
                ),
            ))
        }
    }

    /// Weight W = m g (N).
    pub fn weight(&self) -> f64 {
        self.mass * self.g
    }

    /// Angular frequency ω = √(k/m') with m' = m (rad/s), eq. (6).
    pub fn omega(&self) -> f64 {
        (self.k / self.mass).sqrt()
    }

    /// Period T = 2π/ω (s).
    pub fn period(&self) -> f64 {
        std::f64::consts::TAU / self.omega()
    }

    /// φ = F/W.
    pub fn phi(&self) -> f64 {
        self.force / self.weight()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::error::Error;

    #[test]
    fn defaults_are_the_fig6_set_and_valid() {
        let p = PulledMassParams::default();
        p.validate().unwrap();
        assert!((p.period() - 0.229_429_488_381_819_04).abs() < 1e-15);
    }

    #[test]
    fn each_bad_value_names_its_parameter() {
        type Spoil = fn(&mut PulledMassParams);
        let cases: [(&str, Spoil); 7] = [
            ("mu_s", |p| p.mu_s = 0.0),
            ("mu_d", |p| p.mu_d = 0.5),
            ("mu_d", |p| p.mu_d = -0.1),
            ("mass", |p| p.mass = f64::NAN),
            ("k", |p| p.k = f64::INFINITY),
            ("force", |p| p.force = 0.0),
            ("g", |p| p.g = -9.81),
        ];
        for (name, spoil) in cases {
            let mut p = PulledMassParams::default();
            spoil(&mut p);
            match p.validate() {
                Err(Error::InvalidParam { name: got, .. }) => assert_eq!(got, name),
                other => panic!("{name}: expected an error, got {other:?}"),
            }
        }
    }

    #[test]
    fn every_descriptor_reads_and_writes_its_own_field() {
        for (i, spec) in PARAMS.iter().enumerate() {
            let mut p = PulledMassParams::default();
            (spec.set)(&mut p, 1000.0 + i as f64);
            assert_eq!((spec.get)(&p), Some(1000.0 + i as f64), "{}", spec.key);
            let others = PARAMS
                .iter()
                .filter(|s| (s.get)(&p) == Some(1000.0 + i as f64));
            assert_eq!(others.count(), 1, "{}", spec.key);
        }
    }
}
