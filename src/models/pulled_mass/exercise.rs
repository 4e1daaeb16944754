//! The pulled mass on a worksheet: its questions and regimes, its introduction, and how a
//! student's parameter set is drawn.

use crate::draws::Draws;

use super::formula as pm;
use super::formula::Regime as PulledRegime;
use super::params::PHI_RANGE;
use super::quantity::{any, Key, Key as P};
use super::{results, PulledMassParams};
use crate::engine::Run;
use crate::error::Result;
use crate::models::param::{MU_MAX, MU_MIN};
use crate::params::G_STANDARD;
use crate::results::quantity::AnyKey;
use crate::results::Check;
use crate::worksheet::exercise::{Exercise, Measured};
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

/// The pulled-mass questions (guide §7, guide §9), in sheet order.
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
        super::sketch::pulled_mass_givens(self)
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

    fn probe(rng: &mut Draws) -> Self {
        probe_set(rng)
    }

    fn boundaries() -> &'static [&'static str] {
        &BOUNDARIES
    }

    fn onto_boundary(&self, i: usize, offset: f64) -> Option<Self> {
        let at = match i {
            0 => pm::phi_stick_max(self.mu_s, self.mu_d),
            1 => pm::phi_continuous(self.mu_s, self.mu_d),
            _ => 2.0 * self.mu_s,
        };
        let phi = at * (1.0 + offset);
        (PHI_RANGE.0..=PHI_RANGE.1).contains(&phi).then_some(Self {
            force: phi * self.mass * self.g,
            ..*self
        })
    }

    fn measured_elsewhere(&self, quantity: &str, checks: &[Check]) -> Option<Measured> {
        // Past (20) the same motion quantities are checked by the late-stick forms.
        let check = |key: Key| checks.iter().find(|c| c.quantity == key.into());
        let passed = |key: Key| check(key).and_then(Measured::of);
        let late_stick = || {
            // τ_ST,late is measured in periods from t = 0.
            let tau = passed(Key::TauStickLate)?;
            let period = self.period();
            Some(Measured {
                value: tau.value * period,
                scale: period,
                tolerance: tau.tolerance,
            })
        };
        match quantity {
            "v_avg" => passed(Key::VAvgLate),
            "advance_per_period" => passed(Key::AdvancePerPeriodLate),
            "power" => passed(Key::PowerLate),
            "t_stick" => late_stick(),
            "slip_duration" => {
                let (stick, slip) = (late_stick()?, passed(Key::TSlip)?);
                Some(Measured {
                    value: stick.value - slip.value,
                    tolerance: stick.tolerance.max(slip.tolerance),
                    ..stick
                })
            }
            _ => None,
        }
    }

    fn checks_and_linear_run(
        &self,
        periods: u32,
        record_segments: bool,
    ) -> Result<(Vec<Check>, Option<Run>)> {
        let (checks, run) = results::linear_checks(self, periods, record_segments)?;
        Ok((checks, Some(run)))
    }
}

/// The regime boundaries of guide §9 on φ, in the order of [`Exercise::onto_boundary`].
const BOUNDARIES: [&str; 3] = ["φ = 1/Θ", "φ = φ_c", "φ = 2μs"];

/// A set anywhere in the valid domain, for `check`: μs mostly 0.05–1.5 and a quarter
/// log-uniform over its whole range; μd/μs uniform, or close to 1, or exactly 1, or small; m
/// and k log-uniform over twelve decades, g 0.1–100 m/s²; φ log-uniform from its lower limit
/// in one of the four regimes of guide §9, chosen in turn at random.
fn probe_set(rng: &mut Draws) -> PulledMassParams {
    let mu_s = if rng.unit() < 0.75 {
        rng.between(0.05, 1.5)
    } else {
        rng.log_between(MU_MIN * 10.0, MU_MAX)
    };
    let ratio = match rng.unit() {
        u if u < 0.4 => rng.between(0.01, 1.0),
        u if u < 0.7 => 1.0 - 10f64.powf(-rng.between(1.0, 9.0)),
        u if u < 0.8 => 1.0,
        _ => 10f64.powf(-rng.between(0.0, 3.0)),
    };
    let mu_d = (mu_s * ratio).clamp(MU_MIN, mu_s);
    let mass = rng.log_between(1e-6, 1e6);
    let k = rng.log_between(1e-6, 1e6);
    let g = rng.log_between(0.1, 100.0);
    let (stick, cont) = (
        pm::phi_stick_max(mu_s, mu_d),
        pm::phi_continuous(mu_s, mu_d),
    );
    let phi = match rng.unit() {
        u if u < 0.25 => rng.log_between(PHI_RANGE.0, stick),
        u if u < 0.5 => rng.between(stick, cont),
        u if u < 0.75 => rng.between(cont, 2.0 * mu_s),
        _ => 2.0 * mu_s * rng.between(1.0, 3.0),
    };
    PulledMassParams {
        mu_s,
        mu_d,
        mass,
        k,
        force: phi.max(PHI_RANGE.0) * mass * g,
        g,
    }
}

/// μs 0.25–0.8, μd/μs 0.5–1, m 20–200 g, k 10–100 N/m, and F = φW with φ inside the interval of
/// the regime (guide §9), away from its ends; the same period's slip-stick keeps φ ≥ 0.3/Θ so that
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
