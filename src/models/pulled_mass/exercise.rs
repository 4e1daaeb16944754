//! The pulled mass on a worksheet: its questions and regimes, its introduction, and how a
//! student's parameter set is drawn.

use crate::draws::Draws;

use super::formula as pm;
use super::formula::Regime as PulledRegime;
use super::quantity::{any, Key, Key as P};
use super::{results, PulledMassParams};
use crate::engine::Run;
use crate::error::Result;
use crate::params::G_STANDARD;
use crate::results::quantity::AnyKey;
use crate::results::Check;
use crate::worksheet::exercise::Exercise;
use crate::worksheet::question::{Kind, Question, Regime};
use crate::worksheet::sample::round3;

/// The regimes a pulled-mass worksheet can ask for, the default first.
pub(crate) const REGIMES: &[Regime] = &[
    Regime::new(PulledRegime::SlipStick.id()),
    Regime::new(PulledRegime::SlipStickLate.id()),
    Regime::new(PulledRegime::ContinuousSlip.id()),
];
const SAME_PERIOD: &[Regime] = &[Regime::new(PulledRegime::SlipStick.id())];
/// Where the mass does not stick within the period: fewer closed forms apply, so the sheet
/// also asks for the acceleration at the slip onset (which the same-period sheet leaves out to
/// keep to one printed page).
const BEYOND_THE_PERIOD: &[Regime] = &[
    Regime::new(PulledRegime::SlipStickLate.id()),
    Regime::new(PulledRegime::ContinuousSlip.id()),
];

/// The question of a pulled-mass quantity.
const fn p(k: P) -> AnyKey {
    any(k)
}

/// The pulled-mass questions (physics.md §1.3, §1.5), in sheet order.
pub const QUESTIONS: &[Question] = &[
    Question {
        kind: Kind::ClosedForm(p(P::TSlip)),
        regimes: REGIMES,
    },
    Question {
        kind: Kind::ClosedForm(p(P::ASlip)),
        regimes: BEYOND_THE_PERIOD,
    },
    Question {
        kind: Kind::ClosedForm(p(P::TStick)),
        regimes: SAME_PERIOD,
    },
    Question {
        kind: Kind::ClosedForm(p(P::VMax)),
        regimes: REGIMES,
    },
    Question {
        kind: Kind::ClosedForm(p(P::VAvg)),
        regimes: SAME_PERIOD,
    },
    Question {
        kind: Kind::ClosedForm(p(P::Power)),
        regimes: SAME_PERIOD,
    },
    Question {
        kind: Kind::Regime(p(P::Regime)),
        regimes: REGIMES,
    },
    Question {
        kind: Kind::ReadFigure(p(P::TSlip)),
        regimes: REGIMES,
    },
];

/// The rules that decide the regime, as (regime, condition in LaTeX).
const REGIME_RULES: &[(Regime, &str)] = &[
    (
        Regime::new(PulledRegime::ImmediateContinuousSlip.id()),
        r"\varphi > 2\mu_s",
    ),
    (
        Regime::new(PulledRegime::SlipStick.id()),
        r"\varphi \le 1/\Theta",
    ),
    (
        Regime::new(PulledRegime::SlipStickLate.id()),
        r"1/\Theta < \varphi \le \varphi_c",
    ),
    (
        Regime::new(PulledRegime::ContinuousSlip.id()),
        r"\varphi_c < \varphi \le 2\mu_s",
    ),
];

impl Exercise for PulledMassParams {
    const DEFINED: &'static [&'static str] =
        &["W", r"\omega", "T", r"\varphi", r"\Theta", r"\varphi_c"];

    fn catalogue() -> &'static [Question] {
        QUESTIONS
    }

    fn regimes() -> &'static [Regime] {
        REGIMES
    }

    fn sketch_givens(&self) -> String {
        crate::report::sketch::pulled_mass_givens(self)
    }

    fn regime_rules() -> &'static [(Regime, &'static str)] {
        REGIME_RULES
    }

    fn draw(regime: Regime, rng: &mut Draws) -> Self {
        draw_set(regime, rng)
    }

    fn regime_comparisons(
        &self,
        value: &dyn Fn(AnyKey) -> Option<f64>,
    ) -> Vec<(&'static str, Option<f64>)> {
        vec![
            (r"\varphi", value(Key::Phi.into())),
            (r"1/\Theta", value(Key::PhiStickMax.into())),
            (r"\varphi_c", value(Key::PhiContinuous.into())),
            (r"2\mu_s", Some(2.0 * self.mu_s)),
        ]
    }

    fn checks_and_linear_run(
        &self,
        periods: u32,
        record_segments: bool,
    ) -> Result<(Vec<Check>, Option<Run>)> {
        let (e, runs) = results::evaluate_with_runs(self, periods, record_segments)?;
        Ok((e.checks, Some(runs.linear)))
    }
}

/// μs 0.25–0.8, μd/μs 0.5–1, m 20–200 g, k 10–100 N/m, and F = φW with φ inside the interval of
/// the regime (§1.5), away from its ends; the same period's slip-stick keeps φ ≥ 0.3/Θ so that
/// the motion is large enough to see.
fn draw_set(regime: Regime, rng: &mut Draws) -> PulledMassParams {
    let mu_s = rng.between(0.25, 0.8);
    let mu_d = mu_s * rng.between(0.5, 1.0);
    let mass = rng.between(0.02, 0.2);
    let k = rng.between(10.0, 100.0);
    let (stick, cont) = (
        pm::phi_stick_max(mu_s, mu_d),
        pm::phi_continuous(mu_s, mu_d),
    );
    let late = Regime::new(PulledRegime::SlipStickLate.id());
    let continuous = Regime::new(PulledRegime::ContinuousSlip.id());
    let (lo, hi) = match regime {
        r if r == late => (stick, cont),
        r if r == continuous => (cont, 2.0 * mu_s),
        _ => (0.3 * stick, stick),
    };
    let phi = lo + rng.between(0.02, 0.98) * (hi - lo);
    PulledMassParams {
        mu_s: round3(mu_s),
        mu_d: round3(mu_d),
        mass: round3(mass),
        k: round3(k),
        force: round3(phi * mass * G_STANDARD),
        g: G_STANDARD,
    }
}
