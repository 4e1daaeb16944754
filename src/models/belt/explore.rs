//! What the explorer page asks of the belt: the regime sentence with the inequality that
//! decides it, the exact motion with the belt's travel as the apparatus coordinate (the
//! animation's belt marks move with it), the (μd, v_b) map ([`super::map`]) and the sketch's
//! geometry for the animation.

use super::body::{body, surface_law};
use super::formula::{self, Regime};
use super::map::{category, top, CATEGORIES};
use super::quantity::Key;
use super::results::Evaluation;
use super::BeltParams;
use crate::engine::autonomous::{Ending, SurfaceOptions};
use crate::engine::integrate_surface;
use crate::error::{Error, Result};
#[cfg(feature = "cli")]
use crate::explore::Apparatus;
use crate::explore::{Explore, ExploredLaw, MapAxis, RegimeText, Sample};
use crate::format::people;
use crate::models::LawKind;
use crate::results::quantity::{Quantity, Registry};
use crate::results::Applicability;

/// Significant digits of the numbers in the regime sentence (those of the report's tables).
const DIGITS: usize = 8;

/// The belt's one force law, the spring's −k x, in the harmonic slot of the page's curves.
const LAWS: &[ExploredLaw] = &[ExploredLaw {
    id: "harmonic",
    label: "spring force −k x (exact)",
    summary: "integration",
}];

/// The inequality that decides the belt's regime (docs/belt.md, (B4)), with numbers.
pub fn regime_reason(p: &BeltParams, delta: f64) -> String {
    let num = |x: f64| people(Some(x), DIGITS);
    match Regime::of(delta) {
        Regime::StickSlip => format!(
            "Δ = (μs − μd) m g/k = {} mm > 0: μd = {} < μs = {}",
            num(delta * 1e3),
            num(p.mu_d),
            num(p.mu_s)
        ),
        Regime::TouchingOscillation => format!("μd = μs = {}: Δ = 0", num(p.mu_s)),
    }
}

impl Explore for BeltParams {
    const NAME: &'static str = "block on a belt";
    const POSITION: &'static str = "x";
    const LAWS: &'static [ExploredLaw] = LAWS;
    const CLOSED_FORMS: &'static str = "exact for this system";
    const SUMMARY_REGIMES: &'static [&'static str] =
        &[Regime::StickSlip.id(), Regime::TouchingOscillation.id()];

    fn quantities() -> Vec<&'static Quantity> {
        Key::ENTRIES.iter().map(|e| &e.quantity).collect()
    }

    fn regime(e: &Evaluation) -> RegimeText {
        RegimeText {
            id: e.closed_form.regime.id(),
            words: e.closed_form.regime.words(),
            why: regime_reason(&e.params.input, e.closed_form.delta),
        }
    }

    /// None greyed: every closed form describes the motion in both regimes.
    fn applicability(_e: &Evaluation) -> &[Applicability] {
        &[]
    }

    /// The exact motion from x = 0 carried by the belt, over `shown` cycles of the closed
    /// forms' period (B11); the apparatus coordinate is the belt's travel v_b t (m).
    fn curve(&self, law: LawKind, shown: u32, samples: usize) -> Result<Option<Vec<Sample>>> {
        if law != LawKind::Harmonic {
            return Ok(None);
        }
        self.validate()?;
        // The first onset comes at x_s/v_b > 0, then a cycle per slip: `shown` slips cover
        // `shown` periods from t = 0.
        let opts = SurfaceOptions {
            x0: 0.0,
            slips: shown,
            record_segments: true,
        };
        let run = integrate_surface(&body(self), &surface_law(self)?, &opts)?;
        if run.ending != Ending::Slips {
            return Err(Error::Stalled {
                t: run.events.last().map_or(0.0, |e| e.t),
                reason: "the belt's run ended before its cycles",
            });
        }
        let end = f64::from(shown) * formula::evaluate(self).period;
        let n = samples.max(2);
        let mut times: Vec<f64> = (0..n)
            .map(|i| end * i as f64 / (n - 1) as f64)
            .chain(
                run.events
                    .iter()
                    .map(|e| e.t)
                    .filter(|&t| t > 0.0 && t < end),
            )
            .collect();
        times.sort_by(f64::total_cmp);
        Ok(Some(
            times
                .into_iter()
                .filter_map(|t| run.state_at(t).map(|(x, v, _)| [t, x, v, self.v_b * t]))
                .collect(),
        ))
    }

    #[cfg(feature = "cli")]
    fn apparatus() -> Apparatus {
        Apparatus::new(
            "belt",
            &super::sketch::APPARATUS,
            include_str!("explorer.js"),
        )
    }

    fn map_axes(&self) -> [MapAxis; 2] {
        let (mu_d, v_b) = top(self);
        [
            MapAxis {
                key: "mu_d",
                range: (0.0, mu_d),
            },
            MapAxis {
                key: "v_b",
                range: (0.0, v_b),
            },
        ]
    }

    /// The same cells under both laws: the belt has one.
    fn map_categories(_law: LawKind) -> &'static [(&'static str, usize)] {
        &CATEGORIES
    }

    fn map_cell(&self, _law: LawKind, mu_d: f64, v_b: f64) -> u8 {
        category(self, mu_d, v_b)
    }
}
