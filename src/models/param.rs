//! Parameter descriptors: every input parameter of a model described once, with its symbol,
//! units, valid range and help text. The command-line flags, the scenario keys, the validation
//! and its messages, the parameter tables, the sweepable list and the worksheet tables all read
//! these descriptors; the model's params struct keeps only the values.

use crate::error::{Error, Result};

/// Largest friction coefficient accepted: far beyond any real pair of surfaces, and small
/// enough that μ² and μ³ in the closed forms cannot overflow.
pub const MU_MAX: f64 = 100.0;
/// Smallest friction coefficient accepted: a millionth is frictionless for any table, and the
/// closed forms divide by μs³μd² (Γ), which must not overflow.
pub const MU_MIN: f64 = 1e-6;
/// Smallest and largest magnitude of a dimensional parameter in SI units. Fifty orders of
/// magnitude either way hold every real apparatus many times over, and keep the products and
/// powers in the closed forms (W = m g, T = 2π√(m/k), v̄ = g T φ³ Γ, P = F v̄ …) finite and
/// normal in double precision.
pub const MAGNITUDE: (f64, f64) = (1e-50, 1e50);

/// The rule a parameter's value must satisfy; the error message states it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Rule {
    /// A positive magnitude: [`MAGNITUDE`].0 ≤ x ≤ [`MAGNITUDE`].1.
    Positive,
    /// A signed length: |x| ≤ [`MAGNITUDE`].1.
    Finite,
    /// The static friction coefficient: [`MU_MIN`] ≤ μs ≤ [`MU_MAX`].
    StaticFriction,
    /// The dynamic friction coefficient: [`MU_MIN`] ≤ μd ≤ μs (the model's `mu_s`).
    DynamicFriction,
    /// A closed range lo ≤ x ≤ hi in SI units (a model's lab ranges).
    Range { lo: f64, hi: f64 },
}

/// A numeric input parameter of the model whose parameters are `P`.
pub struct ParamSpec<P> {
    /// Key in scenario files, JSON and messages; the flag is `--key` with `-` for `_`.
    pub key: &'static str,
    /// Symbol as people write it in plain text ("μs", "m_S").
    pub symbol: &'static str,
    /// Symbol in LaTeX (`\mu_s`, `m_S`).
    pub tex: &'static str,
    /// What it is, in a few words ("static friction", "sleeve"); empty when the symbol says it.
    pub what: &'static str,
    /// SI unit as written in tables ("" for a pure number).
    pub unit: &'static str,
    /// The unit people think in for this parameter, and the factor from SI to it (g: 1e3).
    pub display: (&'static str, f64),
    /// The valid range.
    pub rule: Rule,
    /// Help text of the flag (the default is appended).
    pub help: &'static str,
    /// What the default is when the value is unset (only optional parameters: "l/h").
    pub unset: &'static str,
    /// The value in `P`; `None` when an optional parameter is unset.
    pub get: fn(&P) -> Option<f64>,
    /// Sets the value in `P`.
    pub set: fn(&mut P, f64),
}

impl<P> ParamSpec<P> {
    /// The command-line flag without its dashes (`mu-s`).
    pub fn flag(&self) -> String {
        self.key.replace('_', "-")
    }

    /// Label of a parameter table: "μs (static friction)", or the symbol alone.
    pub fn label(&self) -> String {
        if self.what.is_empty() {
            self.symbol.to_string()
        } else {
            format!("{} ({})", self.symbol, self.what)
        }
    }

    /// The unit as a CSV-column suffix: "N/m" → "N_m", "m/s²" → "m_s2".
    pub fn csv_unit(&self) -> String {
        self.unit.replace('/', "_").replace('²', "2")
    }

    /// Axis label in the unit people think in: "m (g)", "μs".
    pub fn axis_label(&self) -> String {
        match self.display.0 {
            "" => self.symbol.to_string(),
            unit => format!("{} ({unit})", self.symbol),
        }
    }

    /// Checks `value` against the rule; `mu_s` is the model's static friction (for μd).
    pub fn check(&self, value: f64, mu_s: f64) -> Result<()> {
        let key = self.key;
        let (lo, hi) = MAGNITUDE;
        let ok = match self.rule {
            Rule::Positive => (lo..=hi).contains(&value),
            Rule::Finite => (-hi..=hi).contains(&value),
            Rule::StaticFriction => (MU_MIN..=MU_MAX).contains(&value),
            Rule::DynamicFriction => (MU_MIN..=mu_s).contains(&value),
            Rule::Range { lo, hi } => (lo..=hi).contains(&value),
        };
        if ok {
            return Ok(());
        }
        // The rule is written only for the message (validation runs on every sampled set).
        let rule = match self.rule {
            Rule::Positive => format!("{} <= {key} <= {}", num(lo), num(hi)),
            Rule::Finite => format!("{} <= {key} <= {}", num(-hi), num(hi)),
            Rule::StaticFriction => format!("{} <= {key} <= {MU_MAX}", num(MU_MIN)),
            Rule::DynamicFriction => {
                format!("{} <= {key} <= mu_s (mu_s = {})", num(MU_MIN), num(mu_s))
            }
            Rule::Range { lo, hi } => format!("{} <= {key} <= {}", num(lo), num(hi)),
        };
        Err(invalid(key, num(value), rule))
    }
}

/// The static friction coefficient μs, shared by every model with dry friction.
pub const fn static_friction<P>(get: fn(&P) -> Option<f64>, set: fn(&mut P, f64)) -> ParamSpec<P> {
    ParamSpec {
        key: "mu_s",
        symbol: "μs",
        tex: r"\mu_s",
        what: "static friction",
        unit: "",
        display: ("", 1.0),
        rule: Rule::StaticFriction,
        help: "Static friction coefficient μs",
        unset: "",
        get,
        set,
    }
}

/// The dynamic friction coefficient μd (at most μs).
pub const fn dynamic_friction<P>(get: fn(&P) -> Option<f64>, set: fn(&mut P, f64)) -> ParamSpec<P> {
    ParamSpec {
        key: "mu_d",
        symbol: "μd",
        tex: r"\mu_d",
        what: "dynamic friction",
        unit: "",
        display: ("", 1.0),
        rule: Rule::DynamicFriction,
        help: "Dynamic friction coefficient μd, 0 < μd ≤ μs",
        unset: "",
        get,
        set,
    }
}

/// The gravitational acceleration g.
pub const fn gravity<P>(get: fn(&P) -> Option<f64>, set: fn(&mut P, f64)) -> ParamSpec<P> {
    ParamSpec {
        key: "g",
        symbol: "g",
        tex: "g",
        what: "",
        unit: "m/s²",
        display: ("m/s²", 1.0),
        rule: Rule::Positive,
        help: "Gravitational acceleration g in m/s²",
        unset: "",
        get,
        set,
    }
}

/// A parameter that takes one of a few named values (the woodpecker's ω and counterpart).
pub struct ChoiceSpec<P> {
    /// Key in scenario files and the flag without dashes.
    pub key: &'static str,
    /// Help text of the flag (the default is appended).
    pub help: &'static str,
    /// The valid values, as typed.
    pub values: &'static [&'static str],
    /// The current value's name.
    pub get: fn(&P) -> &'static str,
    /// Sets the value from one of `values`.
    pub set: fn(&mut P, &str),
}

/// Checks every numeric parameter of `p`, in the order of `specs`.
pub fn validate_all<P>(specs: &[ParamSpec<P>], p: &P, mu_s: f64) -> Result<()> {
    specs.iter().try_for_each(|spec| match (spec.get)(p) {
        Some(value) => spec.check(value, mu_s),
        None => Ok(()),
    })
}

/// An error for parameter `name` with `value`, which must satisfy `rule`.
pub fn invalid(name: &'static str, value: impl ToString, rule: impl Into<String>) -> Error {
    Error::InvalidParam {
        name,
        value: value.to_string(),
        rule: rule.into(),
    }
}

/// A parameter value as written in messages: plain for ordinary magnitudes, else scientific.
pub fn num(x: f64) -> String {
    crate::error::short(x)
}

#[cfg(test)]
mod tests {
    use super::*;

    struct P {
        mu_s: f64,
        mu_d: f64,
    }

    const SPECS: [ParamSpec<P>; 2] = [
        ParamSpec {
            key: "mu_s",
            symbol: "μs",
            tex: r"\mu_s",
            what: "static friction",
            unit: "",
            display: ("", 1.0),
            rule: Rule::StaticFriction,
            help: "Static friction coefficient μs",
            unset: "",
            get: |p| Some(p.mu_s),
            set: |p, v| p.mu_s = v,
        },
        ParamSpec {
            key: "mu_d",
            symbol: "μd",
            tex: r"\mu_d",
            what: "dynamic friction",
            unit: "m/s²",
            display: ("mm", 1e3),
            rule: Rule::DynamicFriction,
            help: "",
            unset: "",
            get: |p| Some(p.mu_d),
            set: |p, v| p.mu_d = v,
        },
    ];

    #[test]
    fn each_rule_names_its_range() {
        let msg = |p: P| validate_all(&SPECS, &p, p.mu_s).unwrap_err().to_string();
        assert_eq!(
            msg(P {
                mu_s: 0.4,
                mu_d: 0.5
            }),
            "invalid parameter mu_d = 0.5: must satisfy 1e-6 <= mu_d <= mu_s (mu_s = 0.4)"
        );
        assert_eq!(
            msg(P {
                mu_s: 200.0,
                mu_d: 0.5
            }),
            "invalid parameter mu_s = 200: must satisfy 1e-6 <= mu_s <= 100"
        );
        assert_eq!(
            msg(P {
                mu_s: -1.0,
                mu_d: 0.5
            }),
            "invalid parameter mu_s = -1: must satisfy 1e-6 <= mu_s <= 100"
        );
        assert!(validate_all(
            &SPECS,
            &P {
                mu_s: 0.4,
                mu_d: 0.4
            },
            0.4
        )
        .is_ok());
    }

    #[test]
    fn labels_and_units_follow_the_descriptor() {
        assert_eq!(SPECS[0].label(), "μs (static friction)");
        assert_eq!(SPECS[0].flag(), "mu-s");
        assert_eq!(SPECS[1].csv_unit(), "m_s2");
        assert_eq!(SPECS[1].axis_label(), "μd (mm)");
        assert_eq!(SPECS[0].axis_label(), "μs");
    }
}
