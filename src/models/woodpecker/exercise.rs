//! The woodpecker on a worksheet: its questions and regimes, its introduction, how a
//! student's parameter set is drawn, and the μd,MIN threshold found on the engine.

use crate::draws::Draws;

use super::formula::OrbitRegime;
use super::quantity::{any, Key, Key as W};
use super::threshold::mu_d_sticking_at_half_period;
use super::{results, WoodpeckerParams};
use crate::derivation::Step;
use crate::engine::Run;
use crate::error::Result;
use crate::params::G_STANDARD;
use crate::results::quantity::AnyKey;
use crate::results::Check;
use crate::worksheet::answer::{applying, confirmed, Answer};
use crate::worksheet::exercise::Exercise;
use crate::worksheet::question::{Kind, Question, Regime};
use crate::worksheet::sample::round3;

/// The regimes a woodpecker worksheet can ask for, the default first.
pub(crate) const REGIMES: &[Regime] = &[
    Regime::new(OrbitRegime::DoubleSlipStick.id()),
    Regime::new(OrbitRegime::DoubleSlipNoHalt.id()),
    Regime::new(OrbitRegime::SingleSlipStick.id()),
    Regime::new(OrbitRegime::ContinuousOrMultiperiod.id()),
];
const STANDARD: &[Regime] = &[Regime::new(OrbitRegime::DoubleSlipStick.id())];
/// Where the first slip's speed peaks in the lobe after the zero of F_e, as (46)–(48) assume:
/// not with a single speed maximum (u_B h_B ≤ 1, no deceleration there). μd,MIN^(I) (51) is
/// left out there too: its threshold is then mostly 1/η, not (51), and the sets on which the
/// integration confirms it are too rare to draw together with t_SL^(I).
const PEAK_IN_LOBE_B: &[Regime] = &[
    Regime::new(OrbitRegime::DoubleSlipStick.id()),
    Regime::new(OrbitRegime::DoubleSlipNoHalt.id()),
    Regime::new(OrbitRegime::ContinuousOrMultiperiod.id()),
];

/// The question of a woodpecker quantity.
const fn w(k: W) -> AnyKey {
    any(k)
}

/// The woodpecker questions (physics.md §3.3–3.6), in sheet order.
pub const QUESTIONS: &[Question] = &[
    Question {
        kind: Kind::ClosedForm(w(W::TSlip1)),
        regimes: REGIMES,
    },
    Question {
        kind: Kind::ClosedForm(w(W::TStick1)),
        regimes: STANDARD,
    },
    Question {
        kind: Kind::ClosedForm(w(W::VMax1)),
        regimes: PEAK_IN_LOBE_B,
    },
    Question {
        kind: Kind::Threshold(w(W::MuDMin1)),
        regimes: PEAK_IN_LOBE_B,
    },
    Question {
        kind: Kind::ClosedForm(w(W::VAvg)),
        regimes: STANDARD,
    },
    Question {
        kind: Kind::Regime(w(W::Regime)),
        regimes: REGIMES,
    },
    Question {
        kind: Kind::ReadFigure(w(W::TSlip1)),
        regimes: REGIMES,
    },
];

/// The rules that decide the regime, as (regime, condition in LaTeX).
const REGIME_RULES: &[(Regime, &str)] = &[
    (
        Regime::new(OrbitRegime::DoubleSlipStick.id()),
        r"u_s^{(-)}\eta' \ge 1,\quad \mu_d \ge \mu_{d,HALT}^{(I)},\quad \mu_d \ge \mu_{d,HALT}^{(II)}",
    ),
    (
        Regime::new(OrbitRegime::DoubleSlipNoHalt.id()),
        r"\text{one slip per period, two speed maxima}",
    ),
    (
        Regime::new(OrbitRegime::SingleSlipStick.id()),
        r"\text{one slip per period, one speed maximum}",
    ),
    (
        Regime::new(OrbitRegime::ContinuousOrMultiperiod.id()),
        r"\text{the sleeve never halts}",
    ),
];

impl Exercise for WoodpeckerParams {
    const DEFINED: &'static [&'static str] = &[
        "W_S",
        r"\lambda",
        r"\omega",
        "T",
        r"\zeta_0",
        r"\delta_0",
        r"u_s^{(-)}",
        r"u_s^{(+)}",
        r"\eta",
        r"\eta'",
        r"\mu_{d,HALT}^{(I)}",
        r"\mu_{d,HALT}^{(II)}",
    ];

    fn catalogue() -> &'static [Question] {
        QUESTIONS
    }

    fn regimes() -> &'static [Regime] {
        REGIMES
    }

    fn sketch_givens(&self) -> String {
        crate::report::sketch::woodpecker_givens(self)
    }

    fn regime_rules() -> &'static [(Regime, &'static str)] {
        REGIME_RULES
    }

    fn draw(_regime: Regime, rng: &mut Draws) -> Self {
        draw_set(rng)
    }

    fn regime_comparisons(
        &self,
        value: &dyn Fn(AnyKey) -> Option<f64>,
    ) -> Vec<(&'static str, Option<f64>)> {
        vec![
            (
                r"u_s^{(-)}\eta'",
                value(Key::USMinus.into())
                    .zip(value(Key::EtaPrime.into()))
                    .map(|(u, h)| u * h),
            ),
            (r"\mu_d", Some(self.mu_d)),
            (r"\mu_{d,HALT}^{(I)}", value(Key::MuDHalt1.into())),
            (r"\mu_{d,HALT}^{(II)}", value(Key::MuDHalt2.into())),
        ]
    }

    fn threshold(
        &self,
        question: &'static Question,
        steps: &[Step],
        step: AnyKey,
    ) -> Result<Option<Answer>> {
        let Some((step, value)) = applying(steps, step).and_then(|s| Some((s, s.value?))) else {
            return Ok(None);
        };
        Ok(mu_d_sticking_at_half_period(self, value)?.and_then(|n| confirmed(question, step, n)))
    }

    fn checks_and_linear_run(
        &self,
        periods: u32,
        record_segments: bool,
    ) -> Result<(Vec<Check>, Option<Run>)> {
        let (e, runs) = results::evaluate_with_runs(self, periods, record_segments)?;
        Ok((e.checks, runs.linear))
    }
}

/// Around the paper's Fig. 15 toy: μs 0.5–0.8, μd/μs 0.3–1, k 10–40 N/m, m_S 4–12 g,
/// m_W 8–25 g, l 12–20 mm, h 5–10 mm, d0 6–12 mm, z0/d0 0.3–0.95; λ = l/h, ω = √(k/m_W) and the
/// `zeros` counterpart (the defaults).
fn draw_set(rng: &mut Draws) -> WoodpeckerParams {
    let mu_s = rng.between(0.5, 0.8);
    let d0 = rng.between(0.006, 0.012);
    WoodpeckerParams {
        mu_s: round3(mu_s),
        mu_d: round3(mu_s * rng.between(0.3, 1.0)),
        k: round3(rng.between(10.0, 40.0)),
        m_sleeve: round3(rng.between(0.004, 0.012)),
        m_bird: round3(rng.between(0.008, 0.025)),
        l: round3(rng.between(0.012, 0.020)),
        h: round3(rng.between(0.005, 0.010)),
        z0: round3(d0 * rng.between(0.3, 0.95)),
        d0: round3(d0),
        g: G_STANDARD,
        ..WoodpeckerParams::default()
    }
}
