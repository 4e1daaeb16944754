//! The belt's parameters: the values, a lab set-up as defaults, and the descriptor of each
//! parameter (symbol, unit, lab range, help). docs/belt.md, "Parameters".

use serde::{Deserialize, Serialize};

use crate::error::Result;
use crate::models::param::{invalid, num, validate_all, ParamSpec, Rule};
use crate::params::G_STANDARD;

/// The block on a moving belt held by a spring (docs/belt.md). Defaults: a lab set-up.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
#[serde(default, deny_unknown_fields)]
pub struct BeltParams {
    /// Mass m of the block (kg).
    pub mass: f64,
    /// Spring constant k (N/m).
    pub k: f64,
    /// Speed v_b of the belt (m/s), > 0.
    pub v_b: f64,
    /// Static friction coefficient μs.
    pub mu_s: f64,
    /// Dynamic friction coefficient μd (0 ≤ μd ≤ μs).
    pub mu_d: f64,
    /// Gravitational acceleration g (m/s²).
    pub g: f64,
}

/// Where the defaults come from.
pub const DEFAULTS_SOURCE: &str = "a lab set-up (docs/belt.md)";

impl Default for BeltParams {
    /// m = 0.5 kg, k = 50 N/m, v_b = 0.05 m/s, μs = 0.6, μd = 0.4, g = 9.81 m/s².
    fn default() -> Self {
        Self {
            mass: 0.5,
            k: 50.0,
            v_b: 0.05,
            mu_s: 0.6,
            mu_d: 0.4,
            g: G_STANDARD,
        }
    }
}

/// The lab range of the friction coefficients.
pub const MU_RANGE: (f64, f64) = (0.0, 2.0);

/// A numeric parameter with a lab range.
#[allow(clippy::too_many_arguments)]
const fn spec(
    key: &'static str,
    symbol: &'static str,
    tex: &'static str,
    what: &'static str,
    unit: &'static str,
    display: (&'static str, f64),
    (lo, hi): (f64, f64),
    help: &'static str,
    get: fn(&BeltParams) -> Option<f64>,
    set: fn(&mut BeltParams, f64),
) -> ParamSpec<BeltParams> {
    ParamSpec {
        key,
        symbol,
        tex,
        what,
        unit,
        display,
        rule: Rule::Range { lo, hi },
        help,
        unset: "",
        get,
        set,
    }
}

/// Every parameter of the belt, in the order of flags, tables and validation.
pub const PARAMS: &[ParamSpec<BeltParams>] = &[
    spec(
        "mass",
        "m",
        "m",
        "block",
        "kg",
        ("g", 1e3),
        (0.01, 10.0),
        "Mass m of the block in kg",
        |p| Some(p.mass),
        |p, v| p.mass = v,
    ),
    spec(
        "k",
        "k",
        "k",
        "spring",
        "N/m",
        ("N/m", 1.0),
        (1.0, 1e4),
        "Spring constant k in N/m",
        |p| Some(p.k),
        |p, v| p.k = v,
    ),
    spec(
        "v_b",
        "v_b",
        "v_b",
        "belt",
        "m/s",
        ("mm/s", 1e3),
        (1e-4, 10.0),
        "Speed v_b of the belt in m/s",
        |p| Some(p.v_b),
        |p, v| p.v_b = v,
    ),
    spec(
        "mu_s",
        "μs",
        r"\mu_s",
        "static friction",
        "",
        ("", 1.0),
        MU_RANGE,
        "Static friction coefficient μs",
        |p| Some(p.mu_s),
        |p, v| p.mu_s = v,
    ),
    spec(
        "mu_d",
        "μd",
        r"\mu_d",
        "dynamic friction",
        "",
        ("", 1.0),
        MU_RANGE,
        "Dynamic friction coefficient μd, 0 ≤ μd ≤ μs",
        |p| Some(p.mu_d),
        |p, v| p.mu_d = v,
    ),
    spec(
        "g",
        "g",
        "g",
        "",
        "m/s²",
        ("m/s²", 1.0),
        (1.0, 25.0),
        "Gravitational acceleration g in m/s²",
        |p| Some(p.g),
        |p, v| p.g = v,
    ),
];

impl BeltParams {
    /// Checks every parameter against its lab range, then μd ≤ μs (docs/belt.md: with
    /// μd > μs the slip would not end in a stick).
    pub fn validate(&self) -> Result<()> {
        validate_all(PARAMS, self, self.mu_s)?;
        if self.mu_d <= self.mu_s {
            Ok(())
        } else {
            Err(invalid(
                "mu_d",
                num(self.mu_d),
                format!("0 <= mu_d <= mu_s (mu_s = {})", num(self.mu_s)),
            ))
        }
    }

    /// Weight W = m g (N), the normal force on the belt.
    pub fn weight(&self) -> f64 {
        self.mass * self.g
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_parameter_outside_its_lab_range_is_named_with_the_range() {
        let msg = |f: fn(&mut BeltParams)| {
            let mut p = BeltParams::default();
            f(&mut p);
            p.validate().unwrap_err().to_string()
        };
        assert_eq!(
            msg(|p| p.mass = 20.0),
            "invalid parameter mass = 20: must satisfy 0.01 <= mass <= 10"
        );
        assert_eq!(
            msg(|p| p.v_b = 0.0),
            "invalid parameter v_b = 0: must satisfy 0.0001 <= v_b <= 10"
        );
        assert_eq!(
            msg(|p| p.mu_d = 0.7),
            "invalid parameter mu_d = 0.7: must satisfy 0 <= mu_d <= mu_s (mu_s = 0.6)"
        );
        assert_eq!(
            msg(|p| p.g = f64::NAN),
            "invalid parameter g = NaN: must satisfy 1 <= g <= 25"
        );
        assert!(BeltParams::default().validate().is_ok());
    }
}
