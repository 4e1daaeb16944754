//! A check: a closed form beside the value measured on the exact integration of the same law.

use std::borrow::Cow;
use std::fmt;

use serde::Serialize;

use crate::models::woodpecker::quantity as wp;
use crate::results::quantity::{AnyKey, Quantity, Registry};

/// Relative tolerance of every numeric check (physics.md §4: observed ≤ 4e-13).
pub const TOLERANCE: f64 = 1e-9;

/// |a − b| / max(|a|, |b|) (0 when both vanish).
pub fn rel_diff(a: f64, b: f64) -> f64 {
    let scale = a.abs().max(b.abs());
    if scale == 0.0 {
        0.0
    } else {
        (a - b).abs() / scale
    }
}

/// A checked value: a number, or a label such as a regime name.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(untagged)]
pub enum CheckValue {
    Number(f64),
    Text(String),
}

/// What a check checks: a quantity of a model's registry, or a quantity of the woodpecker's
/// lobe-engine orbit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Checked {
    Key(AnyKey),
    Orbit(wp::OrbitQuantity),
}

impl Checked {
    /// The name in the §7 `checks` array: the §7 key, or the orbit quantity's name.
    pub fn id(self) -> Cow<'static, str> {
        match self {
            Checked::Key(k) => Cow::Borrowed(k.id()),
            Checked::Orbit(o) => Cow::Owned(o.id()),
        }
    }

    /// The paper's equation of the quantity, or the physics.md section of a derived result:
    /// the registry's.
    pub fn equation(self) -> &'static str {
        match self {
            Checked::Key(k) => k.quantity().equation,
            Checked::Orbit(_) => wp::ORBIT,
        }
    }

    /// How the quantity is shown, when it has an entry in a registry.
    pub fn quantity(self) -> Option<&'static Quantity> {
        match self {
            Checked::Key(k) => Some(k.quantity()),
            Checked::Orbit(_) => None,
        }
    }
}

impl From<AnyKey> for Checked {
    fn from(k: AnyKey) -> Self {
        Checked::Key(k)
    }
}

impl<K: Registry> From<K> for Checked {
    fn from(k: K) -> Self {
        Checked::Key(k.into())
    }
}

impl From<wp::OrbitQuantity> for Checked {
    fn from(o: wp::OrbitQuantity) -> Self {
        Checked::Orbit(o)
    }
}

impl fmt::Display for Checked {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.id())
    }
}

impl Serialize for Checked {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&self.id())
    }
}

/// One entry of the §7 `checks` array.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Check {
    /// The quantity checked (serialized as its §7 key).
    pub quantity: Checked,
    /// Equation number in the paper, or the physics.md section of a derived result (from the
    /// registry: [`Checked::equation`]).
    pub equation: &'static str,
    pub closed_form: CheckValue,
    pub numeric: CheckValue,
    /// |closed − numeric| / max(|closed|, |numeric|); null for labels.
    pub rel_error: Option<f64>,
    pub tolerance: f64,
    pub pass: bool,
}

impl Check {
    /// A numeric check at the standard tolerance.
    pub fn number(quantity: impl Into<Checked>, closed_form: f64, numeric: f64) -> Self {
        Self::measured(quantity, closed_form, Some(numeric))
    }

    /// A numeric check whose numeric side may be missing; a missing value fails the check.
    pub fn measured(quantity: impl Into<Checked>, closed_form: f64, numeric: Option<f64>) -> Self {
        Self::measured_on_scale(quantity, closed_form, numeric, 0.0)
    }

    /// As [`Check::measured`], with the error taken relative to at least `scale`: for a
    /// quantity that can vanish while its measurement carries the rounding of larger terms (the
    /// acceleration at slip onset is (μs − μd) N/M, measured as D − μd N: scale g).
    pub fn measured_on_scale(
        quantity: impl Into<Checked>,
        closed_form: f64,
        numeric: Option<f64>,
        scale: f64,
    ) -> Self {
        let quantity = quantity.into();
        let rel_error = numeric.map(|n| {
            let scale = closed_form.abs().max(n.abs()).max(scale);
            if scale == 0.0 {
                0.0
            } else {
                (closed_form - n).abs() / scale
            }
        });
        Self {
            quantity,
            equation: quantity.equation(),
            closed_form: CheckValue::Number(closed_form),
            numeric: numeric.map_or(
                CheckValue::Text("not observed".to_string()),
                CheckValue::Number,
            ),
            rel_error,
            tolerance: TOLERANCE,
            pass: rel_error.is_some_and(|e| e <= TOLERANCE),
        }
    }

    /// A check of a label (regime, flag): passes when both are equal.
    pub fn label(quantity: impl Into<Checked>, closed_form: &str, numeric: &str) -> Self {
        Self::label_agreeing(quantity, closed_form, numeric, closed_form == numeric)
    }

    /// A check of two labels that agree when `agree` (e.g. a closed-form regime that admits
    /// several integration regimes).
    pub fn label_agreeing(
        quantity: impl Into<Checked>,
        closed_form: &str,
        numeric: &str,
        agree: bool,
    ) -> Self {
        let quantity = quantity.into();
        Self {
            quantity,
            equation: quantity.equation(),
            closed_form: CheckValue::Text(closed_form.to_string()),
            numeric: CheckValue::Text(numeric.to_string()),
            rel_error: None,
            tolerance: TOLERANCE,
            pass: agree,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::pulled_mass::quantity as pm;

    #[test]
    fn relative_error_and_verdict() {
        let c = Check::number(pm::Key::VMax, 2.0, 2.0 * (1.0 + 2e-9));
        assert!(!c.pass);
        assert!((c.rel_error.unwrap() - 2e-9).abs() < 1e-15);
        assert!(Check::number(pm::Key::Phi, 0.0, 0.0).pass);
        assert!(!Check::label(pm::Key::Regime, "a", "b").pass);
    }

    #[test]
    fn a_check_is_serialized_with_the_name_of_its_quantity() {
        let c = Check::number(wp::Key::TSlip1, 1.0, 1.0);
        let json = serde_json::to_value(&c).unwrap();
        assert_eq!(json["quantity"], wp::Key::TSlip1.id());
        assert_eq!(json["equation"], wp::Key::TSlip1.quantity().equation);
        let orbit = wp::OrbitQuantity::VMax {
            slip: 2,
            maximum: 1,
        };
        let json = serde_json::to_value(Check::number(orbit, 1.0, 1.0)).unwrap();
        assert_eq!(json["quantity"], "orbit_v_max_2_1");
        assert_eq!(json["equation"], wp::ORBIT);
    }
}
