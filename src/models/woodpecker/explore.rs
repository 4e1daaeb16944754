//! What the explorer page asks of the woodpecker: the regime sentence with the inequalities that
//! decide it, the apparatus' second coordinate (the bird on its spring) and the (μd, z0) map.

use crate::error::Result;
#[cfg(feature = "cli")]
use crate::explore::Apparatus;
use crate::explore::{
    periodic_curve, Explore, ExploredLaw, MapAxis, RegimeText, Sample, LINEARIZED_AND_HARMONIC,
};
use crate::format::people;
use crate::models::woodpecker::formula::OrbitRegime;
use crate::models::woodpecker::map::{integrated_cell, linear_cell, ranges, MAP_PERIODS, REGIMES};
use crate::models::woodpecker::quantity::Key;
use crate::models::woodpecker::results::Evaluation;
use crate::models::woodpecker::{spring_coordinate, WoodpeckerParams};
use crate::models::LawKind;
use crate::results::quantity::{Quantity, Registry};
use crate::results::Applicability;

/// Significant digits of the numbers in the regime sentence (those of the report's tables).
const DIGITS: usize = 8;

/// The legend of both maps: every category of [`REGIMES`], in its order.
const CATEGORIES: [(&str, usize); REGIMES.len()] = {
    let mut out = [("", 0); REGIMES.len()];
    let mut i = 0;
    while i < REGIMES.len() {
        out[i] = (REGIMES[i].1, REGIMES[i].2);
        i += 1;
    }
    out
};

/// The inequalities that decide the regime of the closed forms (guide §8.6, (38), (39)), with numbers.
fn regime_reason(e: &Evaluation) -> String {
    let c = &e.closed_form;
    let num = |x: Option<f64>| people(x, DIGITS);
    let mu_d = e.params.input.mu_d;
    let halts = [("I", c.mu_d_halt_1), ("II", c.mu_d_halt_2)];
    let compare = |below: bool| {
        halts
            .iter()
            .filter(|(_, halt)| halt.is_some_and(|h| (mu_d < h) == below))
            .map(|(phase, halt)| {
                let sign = if below { "<" } else { "≥" };
                format!(
                    "μd = {} {sign} μd,HALT({phase}) = {}",
                    num(Some(mu_d)),
                    num(*halt)
                )
            })
            .collect::<Vec<_>>()
            .join(" and ")
    };
    let why = match c.regime {
        OrbitRegime::NoSlip => format!(
            "u_s^(−) k (δ0 − ζ0) = {} ≥ W_S = {} (39): the spring never overcomes static friction",
            num(c
                .u_s_minus
                .zip(e.params.zeta0.zip(e.params.delta0))
                .map(|(u, (z, d))| u * e.params.input.k * (d - z))),
            num(Some(e.params.sleeve_weight))
        ),
        OrbitRegime::OutsideClosedFormDomain => e.domain_note.clone().unwrap_or_default(),
        OrbitRegime::DoubleSlipStick => compare(false),
        _ => match compare(true) {
            below if below.is_empty() => "no halt threshold is defined".to_string(),
            below => below,
        },
    };
    let immediate = if c.immediate_slip { "yes" } else { "no" };
    format!("{why}; immediate slip at t = 0 (38): {immediate}")
}

impl Explore for WoodpeckerParams {
    const NAME: &'static str = "woodpecker";
    const POSITION: &'static str = "y_S";
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
            why: regime_reason(e),
        }
    }

    fn applicability(e: &Evaluation) -> &[Applicability] {
        &e.applicability
    }

    /// The apparatus coordinate is the spring coordinate z(t) of the law: the bird's position
    /// relative to the sleeve (y_W = y_S + z, positive downward).
    fn curve(&self, law: LawKind, shown: u32, samples: usize) -> Result<Option<Vec<Sample>>> {
        let period = self.period();
        periodic_curve(self, law, shown, samples, |_, t| {
            spring_coordinate(self, law, t.rem_euclid(period)).unwrap_or(0.0)
        })
    }

    #[cfg(feature = "cli")]
    fn apparatus() -> Apparatus {
        Apparatus::new(
            "woodpecker",
            &crate::models::woodpecker::sketch::WOODPECKER_APPARATUS,
            include_str!("explorer.js"),
        )
    }

    fn map_axes(&self) -> [MapAxis; 2] {
        let (mu_d, z0) = ranges(self);
        [
            MapAxis {
                key: "mu_d",
                range: mu_d,
            },
            MapAxis {
                key: "z0",
                range: z0,
            },
        ]
    }

    fn map_categories(_law: LawKind) -> &'static [(&'static str, usize)] {
        &CATEGORIES
    }

    fn map_cell(&self, law: LawKind, mu_d: f64, z0: f64) -> u8 {
        match law {
            LawKind::Linear => linear_cell(self, mu_d, z0),
            LawKind::Harmonic => integrated_cell(self, law, mu_d, z0, MAP_PERIODS),
        }
    }
}
