//! A check: a closed form beside the value measured on the exact integration of the same law.

use std::borrow::Cow;
use std::fmt;

use serde::Serialize;

use crate::engine::IntegrationRegime;
use crate::params::DEFAULT_PERIODS;
use crate::results::quantity::{AnyKey, Quantity, Registry};
use crate::results::summary::Summary;

/// Relative tolerance of every numeric check (guide §12: observed ≤ 4e-13).
pub const TOLERANCE: f64 = 1e-9;

/// Relative width of the band around a regime boundary in which the closed form and the
/// integration may tell the regime apart by rounding alone (a stick at φ_c is a tangency,
/// classified correctly down to ~1e-13).
pub const BOUNDARY_BAND: f64 = 1e-11;

/// Why the steady state of a run of `periods` cannot be seen: no periodic motion found in a
/// run shorter than the standard one ([`DEFAULT_PERIODS`]).
pub fn unsettled(periods: u32, summary: &Summary) -> Option<String> {
    (summary.regime == IntegrationRegime::NotPeriodic && periods < DEFAULT_PERIODS).then(|| {
        format!(
            "{periods} period(s) integrated: too few to see the motion settle \
             (--periods {DEFAULT_PERIODS} or more)"
        )
    })
}

/// |a − b| / max(|a|, |b|) (0 when both vanish).
pub fn rel_diff(a: f64, b: f64) -> f64 {
    rel_diff_on_scale(a, b, 0.0)
}

/// |a − b| / max(|a|, |b|, scale): the error relative to at least `scale` (0 when all vanish).
pub fn rel_diff_on_scale(a: f64, b: f64, scale: f64) -> f64 {
    let denominator = a.abs().max(b.abs()).max(scale);
    if denominator == 0.0 {
        0.0
    } else {
        (a - b).abs() / denominator
    }
}

/// A checked value: a number, or a label such as a regime name.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
#[serde(untagged)]
pub enum CheckValue {
    Number(f64),
    Text(String),
}

/// What a check checks: a quantity of a model's registry, or a quantity a model numbers at run
/// time (the woodpecker's orbit: the speed of the second maximum of the first slip).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Checked {
    Key(AnyKey),
    Numbered(Numbered),
}

/// A quantity numbered at run time: its name is the stem followed by its indices
/// (`orbit_v_max_1_2`), and the section of the guide that derives it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Numbered {
    /// The name before the indices (`orbit_v_max`).
    pub stem: &'static str,
    /// The indices, from 1 (the second is absent for a quantity numbered once).
    pub indices: (usize, Option<usize>),
    /// The guide's section that derives it ("guide §8.6").
    pub equation: &'static str,
}

impl Numbered {
    /// The name in the guide §14 `checks` array.
    pub fn id(self) -> String {
        match self.indices {
            (i, None) => format!("{}_{i}", self.stem),
            (i, Some(j)) => format!("{}_{i}_{j}", self.stem),
        }
    }
}

impl Checked {
    /// The name in the guide §14 `checks` array: the JSON key (guide §14), or the numbered
    /// quantity's name.
    pub fn id(self) -> Cow<'static, str> {
        match self {
            Checked::Key(k) => Cow::Borrowed(k.id()),
            Checked::Numbered(n) => Cow::Owned(n.id()),
        }
    }

    /// The paper's equation of the quantity, or the section of the guide that derives it ("guide §7.5"):
    /// the registry's.
    pub fn equation(self) -> &'static str {
        match self {
            Checked::Key(k) => k.quantity().equation,
            Checked::Numbered(n) => n.equation,
        }
    }

    /// How the quantity is shown, when it has an entry in a registry.
    pub fn quantity(self) -> Option<&'static Quantity> {
        match self {
            Checked::Key(k) => Some(k.quantity()),
            Checked::Numbered(_) => None,
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

impl From<Numbered> for Checked {
    fn from(n: Numbered) -> Self {
        Checked::Numbered(n)
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

/// One entry of the guide §14 `checks` array.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[cfg_attr(feature = "cli", derive(schemars::JsonSchema))]
pub struct Check {
    /// The quantity checked (serialized as its JSON key (guide §14)).
    pub quantity: Checked,
    /// Equation number in the paper, or the section of the guide that derives the result (from the
    /// registry: [`Checked::equation`]).
    pub equation: &'static str,
    pub closed_form: CheckValue,
    pub numeric: CheckValue,
    /// |closed − numeric| / max(|closed|, |numeric|, scale); null for labels.
    pub rel_error: Option<f64>,
    /// [`TOLERANCE`], or the accuracy double precision allows for this measurement when that is
    /// coarser (the note says why).
    pub tolerance: f64,
    /// `true` or `false`; `null` when the run cannot show the quantity (too few periods, a
    /// regime boundary within rounding): the note says why.
    pub pass: Option<bool>,
    /// Why the check is not observable, or why its tolerance is coarser than [`TOLERANCE`].
    #[serde(skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
    /// The floor of the error's denominator (the period for an event time, the forces per
    /// unit mass for an acceleration; 0 for a plain relative error), so that another value of
    /// the quantity (`stickslip check`) is compared on the same scale.
    #[serde(skip)]
    pub scale: f64,
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
    /// quantity that can vanish while its measurement carries the rounding of larger terms (an
    /// event time is measured as a fraction of the period; the acceleration at slip onset as a
    /// fraction of the forces whose difference it is).
    pub fn measured_on_scale(
        quantity: impl Into<Checked>,
        closed_form: f64,
        numeric: Option<f64>,
        scale: f64,
    ) -> Self {
        let quantity = quantity.into();
        let rel_error = numeric.map(|n| rel_diff_on_scale(closed_form, n, scale));
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
            pass: Some(rel_error.is_some_and(|e| e <= TOLERANCE)),
            note: None,
            scale,
        }
    }

    /// The check with its tolerance widened to `floor` when that is coarser than
    /// [`TOLERANCE`]: `floor` is the relative accuracy that double precision allows for this
    /// measurement (a small difference of large terms, a root of double multiplicity), `why`
    /// says which.
    pub fn conditioned(mut self, floor: f64, why: &str) -> Self {
        if floor > self.tolerance {
            self.tolerance = floor;
            self.pass = Some(self.rel_error.is_some_and(|e| e <= floor));
            self.note = Some(format!(
                "tolerance {floor:.0e} = the attainable accuracy: {why}"
            ));
        }
        self
    }

    /// The check marked not observable when it has not passed and `reason` is `Some`: what the
    /// run cannot show is no failure of the formula.
    pub fn unobservable_if(mut self, reason: Option<String>) -> Self {
        if let (false, Some(reason)) = (self.passed(), reason) {
            self.pass = None;
            self.note = Some(reason);
        }
        self
    }

    /// Whether the check passed.
    pub fn passed(&self) -> bool {
        self.pass == Some(true)
    }

    /// Whether the check failed (a not-observable check has not).
    pub fn failed(&self) -> bool {
        self.pass == Some(false)
    }

    /// The verdict in words: "pass", "FAIL" or "not observable".
    pub fn verdict(&self) -> &'static str {
        match self.pass {
            Some(true) => "pass",
            Some(false) => "FAIL",
            None => "not observable",
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
            pass: Some(agree),
            note: None,
            scale: 0.0,
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
        assert!(c.failed());
        assert!((c.rel_error.unwrap() - 2e-9).abs() < 1e-15);
        assert!(Check::number(pm::Key::Phi, 0.0, 0.0).passed());
        assert!(Check::label(pm::Key::Regime, "a", "b").failed());
    }

    #[test]
    fn a_coarser_floor_widens_the_tolerance_and_says_why() {
        let c = Check::number(pm::Key::VMax, 2.0, 2.0 * (1.0 + 2e-9));
        let widened = c.clone().conditioned(1e-8, "small slip");
        assert!(widened.passed());
        assert_eq!(widened.tolerance, 1e-8);
        assert!(widened.note.as_deref().unwrap().contains("small slip"));
        // A floor finer than the standard tolerance changes nothing.
        assert_eq!(c.clone().conditioned(1e-12, "x"), c);
    }

    #[test]
    fn a_check_the_run_cannot_show_is_not_observable_not_failed() {
        let missing = Check::measured(pm::Key::VAvg, 1.0, None);
        assert!(missing.failed());
        let short = missing.unobservable_if(Some("1 period".to_string()));
        assert_eq!((short.pass, short.verdict()), (None, "not observable"));
        let json = serde_json::to_value(&short).unwrap();
        assert!(json["pass"].is_null() && json["note"] == "1 period");
        // A passing check stays passed, and a reason of None changes nothing.
        let ok = Check::number(pm::Key::VAvg, 1.0, 1.0);
        assert!(ok.clone().unobservable_if(Some("x".into())).passed());
        assert!(Check::measured(pm::Key::VAvg, 1.0, None)
            .unobservable_if(None)
            .failed());
    }

    #[test]
    fn a_check_is_serialized_with_the_name_of_its_quantity() {
        let c = Check::number(pm::Key::TSlip, 1.0, 1.0);
        let json = serde_json::to_value(&c).unwrap();
        assert_eq!(json["quantity"], pm::Key::TSlip.id());
        assert_eq!(json["equation"], pm::Key::TSlip.quantity().equation);
        let numbered = Numbered {
            stem: "orbit_v_max",
            indices: (2, Some(1)),
            equation: "guide §8.6",
        };
        let json = serde_json::to_value(Check::number(numbered, 1.0, 1.0)).unwrap();
        assert_eq!(json["quantity"], "orbit_v_max_2_1");
        assert_eq!(json["equation"], "guide §8.6");
        let once = Numbered {
            indices: (3, None),
            ..numbered
        };
        assert_eq!(Checked::from(once).id(), "orbit_v_max_3");
    }
}
