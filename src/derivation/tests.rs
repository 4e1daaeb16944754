//! The worked substitutions are the closed forms: on random valid parameter sets of every
//! regime, each expression tree evaluates to the formula function's value and to the
//! `closed_form` (or `params`) value of the evaluation (guide §14), a step has a value exactly when its
//! form applies, and every LaTeX string renders to MathML.

use proptest::prelude::*;
use serde_json::Value;

use super::*;
use crate::models::pulled_mass::derivation::param as pm_param;
use crate::models::pulled_mass::derivation::pulled_mass;
use crate::models::pulled_mass::formula as pm;
use crate::models::pulled_mass::quantity::Key as P;
use crate::models::pulled_mass::PulledMassParams;
use crate::models::woodpecker::derivation::param as wp_param;
use crate::models::woodpecker::derivation::woodpecker;
use crate::models::woodpecker::formula::Counterpart;
use crate::models::woodpecker::quantity::Key as W;
use crate::models::woodpecker::{OmegaMode, WoodpeckerParams};
use crate::models::{pulled_mass::results as pm_results, woodpecker::results as wp_results};
use crate::report::math::mathml;

/// Evaluating a tree repeats the formula's arithmetic in another order: a few ulps apart.
const REL: f64 = 1e-12;

/// The guide §14 value of a step's key: `closed_form` first, then `params`.
fn section7_value(json: &Value, key: &str) -> Option<Value> {
    json["closed_form"]
        .get(key)
        .or_else(|| json["params"].get(key))
        .cloned()
}

fn close(a: f64, b: f64) -> bool {
    a == b || (a - b).abs() <= REL * a.abs().max(b.abs())
}

/// Every step against the guide §14 object `json` and the applicability list of the evaluation.
fn check_steps(steps: &[Step], json: &Value, applies: impl Fn(&str) -> bool) {
    assert!(!steps.is_empty());
    for step in steps {
        let key = step.key.id();
        let Some(expected) = section7_value(json, key) else {
            panic!("{key}: not a JSON key (guide §14)");
        };
        let evaluated = step.expr.eval();
        match expected.as_f64() {
            Some(x) => {
                // μd,HALT = (x₊ − σ)/(2λ) is a difference of O(1/(2λ)) terms: both sides carry
                // an absolute rounding error of that size, not of the (small) result's.
                let scale = match json["params"]["lambda"].as_f64() {
                    Some(lambda) if key.starts_with("mu_d_halt") => 1.0 / (2.0 * lambda),
                    _ => 0.0,
                };
                assert!(
                    close(evaluated, x) || (evaluated - x).abs() <= REL * scale,
                    "{key}: tree {evaluated} vs guide §14 {x}"
                );
                if applies(key) {
                    assert_eq!(step.value, Some(x), "{key}: value is the formula's");
                    assert!(step.reason.is_none(), "{key}");
                } else {
                    assert_eq!(step.value, None, "{key}");
                    assert!(step.reason.as_deref().is_some_and(|r| !r.is_empty()));
                }
            }
            None => {
                assert!(expected.is_null(), "{key}: {expected}");
                assert_eq!(step.value, None, "{key}: undefined has no value");
                assert!(step.reason.is_some(), "{key}");
            }
        }
    }
}

fn renders(tex: &str) {
    let m = mathml(tex);
    assert!(
        m.starts_with("<math") && !m.contains("merror"),
        "{tex}\n{m}"
    );
    // No entity escaped twice (`&amp;nbsp;` for `\ `).
    assert!(!m.contains("&amp;"), "{tex}\n{m}");
}

/// φ inside the interval of regime `which` (guide §9), as the property test of the results.
fn phi_in_regime(which: u8, frac: f64, mu_s: f64, mu_d: f64) -> f64 {
    let (stick, cont) = (
        pm::phi_stick_max(mu_s, mu_d),
        pm::phi_continuous(mu_s, mu_d),
    );
    let (lo, hi) = match which {
        0 => (0.0, stick),
        1 => (stick, cont),
        2 => (cont, 2.0 * mu_s),
        _ => (2.0 * mu_s, 4.0 * mu_s),
    };
    lo + (0.001 + 0.998 * frac) * (hi - lo)
}

fn pulled_params() -> impl Strategy<Value = PulledMassParams> {
    (
        0u8..4,
        0.0..1.0f64,
        0.05..1.2f64,
        0.02..=1.0f64,
        0.005..2.0f64,
        0.5..2000.0f64,
        1.0..25.0f64,
    )
        .prop_map(|(which, frac, mu_s, ratio, mass, k, g)| {
            let mu_d = mu_s * ratio;
            let phi = phi_in_regime(which, frac, mu_s, mu_d);
            PulledMassParams {
                mu_s,
                mu_d,
                mass,
                k,
                force: phi * mass * g,
                g,
            }
        })
}

fn woodpecker_params() -> impl Strategy<Value = WoodpeckerParams> {
    (
        (0.2..1.0f64, 0.05..=1.0f64, 2.0..60.0f64, 0.001..0.03f64),
        (0.003..0.05f64, 0.002..0.02f64, -0.2..1.1f64),
        (0.8..5.0f64, 0u8..4, 0usize..3, 0usize..3),
    )
        .prop_map(
            |((mu_s, ratio, k, m_sleeve), (m_bird, d0, z0_ratio), (lever, lev, om, cp))| {
                WoodpeckerParams {
                    mu_s,
                    mu_d: mu_s * ratio,
                    k,
                    m_sleeve,
                    m_bird,
                    l: 0.016,
                    h: 0.007,
                    z0: d0 * z0_ratio,
                    d0,
                    g: 9.81,
                    // One case in four takes λ = l/h (a step of its own).
                    lever: (lev > 0).then_some(lever),
                    omega: [OmegaMode::Bird, OmegaMode::Reduced, OmegaMode::Total][om],
                    counterpart: [
                        Counterpart::Extremes,
                        Counterpart::Zeros,
                        Counterpart::Tangent,
                    ][cp],
                }
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(600))]

    #[test]
    fn pulled_mass_trees_are_the_closed_forms(p in pulled_params()) {
        let e = pm_results::evaluate(&p, 4).unwrap();
        let json = serde_json::to_value(&e).unwrap();
        let applies = |key: &str| e.applicability.iter().all(|a| a.quantity.id() != key || a.applies);
        check_steps(&pulled_mass(&p), &json, applies);
    }

    #[test]
    fn woodpecker_trees_are_the_closed_forms(p in woodpecker_params()) {
        let e = wp_results::evaluate(&p, 4).unwrap();
        let json = serde_json::to_value(&e).unwrap();
        let phase_key = |key: &str| {
            key.ends_with("_1") || key.ends_with("_2")
        };
        let applies = |key: &str| match e.applicability.iter().find(|a| a.quantity.id() == key) {
            Some(a) => a.applies,
            None => e.domain_note.is_none() || !phase_key(key),
        };
        let steps = woodpecker(&p);
        check_steps(&steps, &json, applies);
        prop_assert_eq!(
            steps.iter().any(|s| s.key == wp_param::LAMBDA.into()),
            p.lever.is_none()
        );
    }

    /// The values-only steps (`check`'s path) are the trees' steps without the trees: the same
    /// keys, applicability and values, and each formula's value bit for bit that of its tree.
    #[test]
    fn values_only_steps_are_the_trees_values_bit_for_bit(
        p in pulled_params(),
        w in woodpecker_params(),
    ) {
        fn same<E: Term>(trees: &[Step], values: &[Step<E>]) -> Result<(), TestCaseError> {
            prop_assert_eq!(trees.len(), values.len());
            for (t, v) in trees.iter().zip(values) {
                prop_assert_eq!(t.key, v.key);
                prop_assert_eq!(t.value.map(f64::to_bits), v.value.map(f64::to_bits));
                prop_assert_eq!(&t.reason, &v.reason);
                prop_assert_eq!(t.expr.eval().to_bits(), v.expr.eval().to_bits(), "{}", t.symbol);
                prop_assert_eq!(t.formula_value().to_bits(), v.formula_value().to_bits());
            }
            Ok(())
        }
        use crate::models::pulled_mass::derivation::pulled_mass_values;
        use crate::models::woodpecker::derivation::woodpecker_values;
        same(&pulled_mass(&p), &pulled_mass_values(&p))?;
        same(&woodpecker(&w), &woodpecker_values(&w))?;
    }

    #[test]
    fn every_string_renders_to_mathml(p in pulled_params(), w in woodpecker_params()) {
        for step in pulled_mass(&p).iter().chain(&woodpecker(&w)) {
            renders(step.symbol);
            renders(&step.formula());
            renders(&step.substituted());
            renders(&step.worked_tex());
        }
    }
}

#[test]
fn set_b_reads_as_a_worked_example() {
    let p = PulledMassParams {
        mu_s: 0.4,
        mu_d: 0.35,
        force: 0.10,
        ..PulledMassParams::default()
    };
    let steps = pulled_mass(&p);
    let keys: Vec<StepKey> = steps.iter().map(|s| s.key).collect();
    for key in [
        pm_param::W.into(),
        pm_param::OMEGA.into(),
        pm_param::T.into(),
        P::Phi.into(),
        P::TSlip.into(),
        P::ASlip.into(),
        P::TMaxSpeed.into(),
        P::VMax.into(),
    ] {
        assert!(keys.contains(&key), "{key:?}");
    }
    let step = |key: P| steps.iter().find(|s| s.key == key.into()).unwrap();
    let t_slip = step(P::TSlip);
    assert_eq!(t_slip.formula(), r"T \tau_{SL}");
    assert_eq!(t_slip.substituted(), r"0.2294 \times 0.3938");
    assert!((t_slip.value.unwrap() - 0.090_352_965_35).abs() < 1e-11);
    assert_eq!(
        t_slip.worked_tex(),
        r"t_{SL} = T \tau_{SL} = 0.2294 \times 0.3938 = 0.09035\,\mathrm{s}"
    );
    let v_max = step(P::VMax);
    assert_eq!(
        v_max.formula(),
        r"\frac{g T \varphi^{2} \left(\mu_s^{2} + 2 \mu_s \mu_d - \mu_d^{2}\right)}{16 \mu_s^{2} \mu_d}"
    );
    assert_eq!(
        v_max.substituted(),
        r"\frac{9.81 \times 0.2294 \times 0.1699^{2} \times \left(0.4^{2} + 2 \times 0.4 \times 0.35 - 0.35^{2}\right)}{16 \times 0.4^{2} \times 0.35}"
    );
    // Set B is slip-stick: the late-stick form does not apply, with the reason.
    let late = step(P::TauStickLate);
    assert_eq!(late.value, None);
    assert!(late
        .reason
        .as_deref()
        .unwrap()
        .contains("within the period"));
}

#[test]
fn set_c_marks_the_same_period_stick_as_not_applying() {
    let p = PulledMassParams {
        mu_s: 0.4,
        mu_d: 0.35,
        force: 0.18,
        ..PulledMassParams::default()
    };
    let steps = pulled_mass(&p);
    let step = |key: P| steps.iter().find(|s| s.key == key.into()).unwrap();
    let t_stick = step(P::TStick);
    assert_eq!(t_stick.value, None);
    assert!(t_stick.reason.as_deref().unwrap().contains("(20) fails"));
    assert!(t_stick.result_tex().is_none());
    assert!(!t_stick.worked_tex().ends_with(r"\,\mathrm{s}"));
    let late = step(P::TauStickLate);
    assert!((late.value.unwrap() - 1.028_831_853).abs() < 1e-8);
}

#[test]
fn fig15_phases_read_with_the_papers_symbols() {
    let steps = woodpecker(&WoodpeckerParams::default());
    let step = |key: StepKey| steps.iter().find(|s| s.key == key).unwrap();
    let w = |key: W| step(key.into());
    assert!((w(W::TSlip1).value.unwrap() - 0.058_242_816_14).abs() < 1e-11);
    assert!((w(W::MuDMin1).value.unwrap() - 0.236_080_561_4).abs() < 1e-10);
    assert!((w(W::MuDHalt2).value.unwrap() - 0.298_683_430_3).abs() < 1e-10);
    assert!((w(W::VAvg).value.unwrap() - 0.049_658_438_62).abs() < 1e-11);
    assert_eq!(w(W::TSlip1).formula(), r"t_0^{(I)} - \Delta^{(I)}");
    assert_eq!(
        w(W::MuDMin2).formula(),
        r"\frac{1}{2 \lambda} \frac{{u_s^{(+)}}^{2} \eta' \left(\eta' + 2\right) + 2 u_s^{(+)} - 1}{{u_s^{(+)}}^{2} {\eta'}^{2} + 1}"
    );
    assert_eq!(w(W::Zeta0).formula(), "d_0");
    assert_eq!(
        w(W::Delta0).formula(),
        r"d_0 \frac{2}{\pi} \arcsin\left(\frac{z_0}{d_0}\right)"
    );
    assert_eq!(
        step(wp_param::LAMBDA.into()).substituted(),
        r"\frac{0.016}{0.007}"
    );
    assert_eq!(
        step(wp_param::T.into()).substituted(),
        r"\frac{2 \pi}{37.80}"
    );
}

#[test]
fn outside_the_domain_every_phase_step_says_why() {
    // |z0| > d0: the zeros counterpart is undefined, so are ζ0, δ0 and everything after.
    let p = WoodpeckerParams {
        z0: 0.02,
        ..WoodpeckerParams::default()
    };
    let steps = woodpecker(&p);
    let t_slip = steps.iter().find(|s| s.key == W::TSlip1.into()).unwrap();
    assert_eq!(t_slip.value, None);
    assert!(t_slip.reason.as_deref().unwrap().contains("counterpart"));
    assert!(t_slip.substituted().contains(r"\text{undefined}"));
    let omega = steps
        .iter()
        .find(|s| s.key == wp_param::OMEGA.into())
        .unwrap();
    assert!(omega.value.is_some());
}

#[test]
fn the_working_of_a_step_is_its_chain_of_earlier_steps() {
    for steps in [
        pulled_mass(&PulledMassParams::default()),
        woodpecker(&WoodpeckerParams::default()),
    ] {
        for step in &steps {
            let chain = working(&steps, step);
            let symbols: Vec<&str> = chain.iter().map(|s| s.symbol).collect();
            // Every computed symbol of the formula is worked out in the chain...
            for v in step.expr.vars() {
                if steps.iter().any(|s| s.symbol == v) {
                    assert!(symbols.contains(&v), "{}: {v} missing", step.symbol);
                }
            }
            // ... after the steps it uses, each once, and never the step itself.
            for (i, s) in chain.iter().enumerate() {
                assert!(!std::ptr::eq(*s, step));
                for v in s.expr.vars() {
                    if let Some(j) = symbols.iter().position(|x| *x == v) {
                        assert!(j < i, "{} uses {v} worked later", s.symbol);
                    }
                }
                assert_eq!(symbols.iter().filter(|x| **x == s.symbol).count(), 1);
            }
        }
    }
    let steps = pulled_mass(&PulledMassParams::default());
    let t_slip = steps
        .iter()
        .find(|s| s.key == StepKey::Quantity(P::TSlip.into()))
        .unwrap();
    let symbols: Vec<&str> = working(&steps, t_slip).iter().map(|s| s.symbol).collect();
    assert!(symbols.contains(&"T"), "{symbols:?}");
}

/// arctan (the belt's slip time (B8)) evaluates as `f64::atan`, renders as `\arctan` around its
/// argument in both the symbols and the numbers, and converts to MathML.
#[test]
fn arctan_evaluates_and_renders_in_both_modes() {
    use crate::derivation::expr::{arctan, given, var};
    let e = arctan(var(r"\omega", 10.0) * given(r"\Delta", 0.01962) / given("v_b", 0.05));
    assert!((e.eval() - 3.924f64.atan()).abs() < 1e-15);
    assert_eq!(
        e.symbols(),
        r"\arctan\left(\frac{\omega \Delta}{v_b}\right)"
    );
    assert!(e.numbers().starts_with(r"\arctan\left("), "{}", e.numbers());
    assert!(e.numbers().contains("0.01962"), "{}", e.numbers());
    renders(&e.symbols());
    renders(&e.numbers());
}
