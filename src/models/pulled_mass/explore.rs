//! What the explorer page asks of the pulled mass: the regime sentence with the guide §9 inequality
//! that decides it, the apparatus' second coordinate (the hanging mass) and the (μd, μs) map.

use crate::error::Result;
#[cfg(feature = "cli")]
use crate::explore::Apparatus;
use crate::explore::{
    periodic_curve, Explore, ExploredLaw, MapAxis, RegimeText, Sample, LINEARIZED_AND_HARMONIC,
};
use crate::format::people;
use crate::models::pulled_mass::formula::{ClosedForm, Regime};
use crate::models::pulled_mass::map::{
    harmonic_category, linear_category, top, HARMONIC_CATEGORIES, LINEAR_CATEGORIES,
};
use crate::models::pulled_mass::quantity::Key;
use crate::models::pulled_mass::results::Evaluation;
use crate::models::pulled_mass::PulledMassParams;
use crate::models::LawKind;
use crate::results::quantity::{Quantity, Registry};
use crate::results::Applicability;

/// Significant digits of the numbers in the regime sentence (those of the report's tables).
const DIGITS: usize = 8;

/// The guide §9 inequality that decides the pulled-mass regime, with numbers (the report's and the
/// explorer's "why").
pub fn regime_reason(c: &ClosedForm, mu_s: f64) -> String {
    let num = |x: f64| people(Some(x), DIGITS);
    let (phi, stick, cont) = (num(c.phi), num(c.phi_stick_max), num(c.phi_continuous));
    let two_mu_s = num(2.0 * mu_s);
    match c.regime {
        Regime::ImmediateContinuousSlip => format!("φ = {phi} > 2μs = {two_mu_s}"),
        Regime::SlipStick => format!("φ = {phi} ≤ 1/Θ = {stick} (20)"),
        Regime::SlipStickLate => format!("1/Θ = {stick} < φ = {phi} ≤ φ_c = {cont}"),
        Regime::ContinuousSlip => format!("φ_c = {cont} < φ = {phi} ≤ 2μs = {two_mu_s}"),
    }
}

impl Explore for PulledMassParams {
    const NAME: &'static str = "pulled mass";
    const POSITION: &'static str = "x";
    const LAWS: &'static [ExploredLaw] = LINEARIZED_AND_HARMONIC;
    const CLOSED_FORMS: &'static str = "linearized law";
    const SUMMARY_REGIMES: &'static [&'static str] = &[];

    fn quantities() -> Vec<&'static Quantity> {
        Key::ENTRIES.iter().map(|e| &e.quantity).collect()
    }

    fn regime(e: &Evaluation) -> RegimeText {
        RegimeText {
            id: e.closed_form.regime.id(),
            words: e.closed_form.regime.words(),
            why: regime_reason(&e.closed_form, e.params.input.mu_s),
        }
    }

    fn applicability(e: &Evaluation) -> &[Applicability] {
        &e.applicability
    }

    /// The apparatus coordinate is the hanging mass' displacement below its rest position,
    /// (N(t) − W)/k: the spring presses the block with N = W + k·(that displacement).
    fn curve(&self, law: LawKind, shown: u32, samples: usize) -> Result<Option<Vec<Sample>>> {
        periodic_curve(self, law, shown, samples, |force_law, t| {
            (force_law.normal(t) - self.weight()) / self.k
        })
    }

    #[cfg(feature = "cli")]
    fn apparatus() -> Apparatus {
        Apparatus::new(
            "pulled-mass",
            &crate::models::pulled_mass::sketch::APPARATUS,
            include_str!("explorer.js"),
        )
    }

    fn map_axes(&self) -> [MapAxis; 2] {
        let range = (0.0, top(self.phi()));
        [
            MapAxis { key: "mu_d", range },
            MapAxis { key: "mu_s", range },
        ]
    }

    fn map_categories(law: LawKind) -> &'static [(&'static str, usize)] {
        match law {
            LawKind::Linear => &LINEAR_CATEGORIES,
            LawKind::Harmonic => &HARMONIC_CATEGORIES,
        }
    }

    fn map_cell(&self, law: LawKind, mu_d: f64, mu_s: f64) -> u8 {
        match law {
            LawKind::Linear => linear_category(self.phi(), mu_s, mu_d),
            LawKind::Harmonic => harmonic_category(self, mu_s, mu_d),
        }
    }
}
