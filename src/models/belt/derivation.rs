//! Worked substitutions of the belt (docs/belt.md (B1)–(B17)): ω, x_s, x_d, Δ, then every
//! closed form in the order of a derivation. Values come from [`super::formula`] (never
//! derived again here); every form describes the motion in both regimes, so every step has
//! its value.

use super::formula as cf;
use super::quantity::Key;
use super::BeltParams;
use crate::derivation::expr::{arctan, pow, sqrt, Term};
use crate::derivation::{Expr, Step, Steps, Value};

/// The derived parameters with a step (the `params` keys of `eval belt --json`).
pub mod param {
    use crate::derivation::Param;

    /// ω = √(k/m) (B1).
    pub const OMEGA: Param = Param {
        id: "omega",
        tex: r"\omega",
        equation: "(B1)",
        unit: "rad/s",
    };
    /// x_s = μs m g/k (B2).
    pub const X_S: Param = Param {
        id: "x_s",
        tex: "x_s",
        equation: "(B2)",
        unit: "m",
    };
    /// x_d = μd m g/k (B3).
    pub const X_D: Param = Param {
        id: "x_d",
        tex: "x_d",
        equation: "(B3)",
        unit: "m",
    };
    /// Δ = (μs − μd) m g/k (B4).
    pub const DELTA: Param = Param {
        id: "delta",
        tex: r"\Delta",
        equation: "(B4)",
        unit: "m",
    };
}

/// Every closed form of the belt with `p`'s numbers, in the order a derivation reads.
pub fn belt(p: &BeltParams) -> Vec<Step> {
    steps::<Expr>(p)
}

/// [`belt`] without the expression trees: each step's formula as its value only (the same
/// numbers, bit for bit).
pub fn belt_values(p: &BeltParams) -> Vec<Step<Value>> {
    steps::<Value>(p)
}

fn steps<E: Term>(p: &BeltParams) -> Vec<Step<E>> {
    let (int, pi, given) = (E::int, E::pi, E::given);
    let c = cf::evaluate(p);
    let mut s = Steps::<Key, E>::new(&[]);
    let (m, g, k, v_b) = (
        given("m", p.mass),
        given("g", p.g),
        given("k", p.k),
        given("v_b", p.v_b),
    );
    let (mu_s, mu_d) = (given(r"\mu_s", p.mu_s), given(r"\mu_d", p.mu_d));

    let omega = s.push_param(param::OMEGA, sqrt(k.clone() / m.clone()), Some(c.omega));
    let x_s = s.push_param(
        param::X_S,
        mu_s.clone() * m.clone() * g.clone() / k.clone(),
        Some(c.x_s),
    );
    let x_d = s.push_param(
        param::X_D,
        mu_d.clone() * m.clone() * g.clone() / k.clone(),
        Some(c.x_d),
    );
    let delta = s.push_param(
        param::DELTA,
        (mu_s - mu_d.clone()) * m.clone() * g.clone() / k,
        Some(c.delta),
    );
    s.push(
        Key::FirstSlipTime,
        x_s / v_b.clone(),
        Some(c.first_slip_time),
    );
    let t_slip = s.push(
        Key::TSlip,
        int(2) / omega.clone() * (pi() - arctan(omega.clone() * delta.clone() / v_b.clone())),
        Some(c.t_slip),
    );
    let t_stick = s.push(
        Key::TStick,
        int(2) * delta.clone() / v_b.clone(),
        Some(c.t_stick),
    );
    let period = s.push(
        Key::Period,
        t_slip.clone() + t_stick.clone(),
        Some(c.period),
    );
    let a = s.push(
        Key::Amplitude,
        sqrt(pow(delta.clone(), 2) + pow(v_b.clone() / omega.clone(), 2)),
        Some(c.amplitude),
    );
    s.push(
        Key::XSlipEnd,
        x_d.clone() - delta.clone(),
        Some(c.x_slip_end),
    );
    s.push(Key::XMax, x_d.clone() + a.clone(), Some(c.x_max));
    s.push(Key::XMin, x_d - a.clone(), Some(c.x_min));
    s.push(Key::VMin, -(omega.clone() * a.clone()), Some(c.v_min));
    s.push(
        Key::SlipSpeedMax,
        v_b.clone() + omega * a,
        Some(c.slip_speed_max),
    );
    let e = s.push(
        Key::EnergyPerCycle,
        mu_d * m * g * (int(2) * delta + v_b * t_slip.clone()),
        Some(c.energy_per_cycle),
    );
    s.push(
        Key::PowerFriction,
        e.clone() / period.clone(),
        Some(c.power),
    );
    s.push(Key::PowerBelt, e / period.clone(), Some(c.power));
    s.push(
        Key::StickShare,
        t_stick / period.clone(),
        Some(c.stick_share),
    );
    s.push(Key::SlipShare, t_slip / period, Some(c.slip_share));
    s.steps
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::derivation::StepKey;

    #[test]
    fn every_steps_value_is_the_closed_forms_and_its_tree_gives_it() {
        for p in super::super::test_sets() {
            let c = cf::evaluate(&p);
            let steps = belt(&p);
            // The values-only steps are the same numbers, bit for bit.
            for (tree, value) in steps.iter().zip(belt_values(&p)) {
                assert_eq!(tree.value, value.value, "{}", tree.symbol);
                assert_eq!(tree.expr.eval(), value.expr.eval(), "{}", tree.symbol);
            }
            // Every numeric quantity of the registry once, after the four derived parameters.
            let numeric = super::super::quantity::ALL.len() - 1;
            assert_eq!(steps.len(), 4 + numeric);
            for step in &steps {
                let value = step.value.expect("every form applies");
                let want = match step.key {
                    StepKey::Param(q) => match q.id {
                        "omega" => c.omega,
                        "x_s" => c.x_s,
                        "x_d" => c.x_d,
                        "delta" => c.delta,
                        other => panic!("unexpected parameter {other}"),
                    },
                    StepKey::Quantity(k) => {
                        let key = super::super::quantity::ALL
                            .into_iter()
                            .find(|&key| crate::results::quantity::AnyKey::from(key) == k)
                            .unwrap();
                        c.value(key).number().unwrap()
                    }
                };
                assert_eq!(value, want, "{}", step.symbol);
                // The tree shown gives the value, to the rounding of its operations (the
                // shares of a touch are 0 and 1 exactly).
                let tree = step.expr.eval();
                assert!(
                    (tree - value).abs() <= 1e-14 * value.abs().max(c.x_max.min(1.0)),
                    "{}: {tree} vs {value}",
                    step.symbol
                );
            }
        }
    }

    #[test]
    fn the_slip_time_is_worked_with_the_arctangent() {
        let steps = belt(&BeltParams::default());
        let t_slip = steps.iter().find(|s| s.symbol == r"t_{slip}").unwrap();
        assert_eq!(
            t_slip.formula(),
            r"\frac{2}{\omega} \left(\pi - \arctan\left(\frac{\omega \Delta}{v_b}\right)\right)"
        );
        assert_eq!(
            t_slip.worked_pieces()[1],
            r"= \frac{2}{10.00} \times \left(\pi - \arctan\left(\frac{10.00 \times 0.01962}{0.05}\right)\right)"
        );
        assert_eq!(t_slip.result_tex().unwrap(), r"0.3641\,\mathrm{s}");
        // The working toward it: ω, then Δ (from which t_slip is computed).
        let working: Vec<&str> = crate::derivation::working(&steps, t_slip)
            .iter()
            .map(|s| s.symbol)
            .collect();
        assert_eq!(working, [r"\omega", r"\Delta"]);
    }
}
