//! Worked substitutions of the pulled mass (guide §5.1, guide §7): W, ω, T, φ, then every
//! closed form of the linearized law in the order of a derivation. Values come from
//! [`crate::models::pulled_mass::formula`]; which forms apply, from [`crate::models::pulled_mass::results`].

use crate::derivation::expr::{half, pow, pow_ratio, sqrt, Term};
use crate::derivation::{Expr, Step, Steps, Value};
use crate::models::pulled_mass::formula as cf;
use crate::models::pulled_mass::quantity::Key;
use crate::models::pulled_mass::results::applicability;
use crate::models::pulled_mass::PulledMassParams;

/// The derived parameters with a step (guide §14 `params` keys).
pub mod param {
    use crate::derivation::Param;

    /// W = m g.
    pub const W: Param = Param {
        id: "W",
        tex: "W",
        equation: "(6)",
        unit: "N",
    };
    /// ω = √(k/m').
    pub const OMEGA: Param = Param {
        id: "omega",
        tex: r"\omega",
        equation: "(6)",
        unit: "rad/s",
    };
    /// T = 2π/ω.
    pub const T: Param = Param {
        id: "T",
        tex: "T",
        equation: "(7)",
        unit: "s",
    };
}

/// D ≡ μs² + 2μsμd − μd² (guide §7), written out wherever it appears.
fn big_d<E: Term>(mu_s: &E, mu_d: &E) -> E {
    pow(mu_s.clone(), 2) + E::int(2) * mu_s.clone() * mu_d.clone() - pow(mu_d.clone(), 2)
}

/// Every closed form of the pulled mass with `p`'s numbers, in the order a derivation reads.
pub fn pulled_mass(p: &PulledMassParams) -> Vec<Step> {
    steps::<Expr>(p)
}

/// [`pulled_mass`] without the expression trees: each step's formula as its value only (the
/// same numbers, bit for bit).
pub fn pulled_mass_values(p: &PulledMassParams) -> Vec<Step<Value>> {
    steps::<Value>(p)
}

fn steps<E: Term>(p: &PulledMassParams) -> Vec<Step<E>> {
    let (int, pi, given, half) = (E::int, E::pi, E::given, half::<E>);
    let (period, phi_value) = (p.period(), p.phi());
    let c = cf::evaluate(p.g, period, p.force, phi_value, p.mu_s, p.mu_d);
    let notes = applicability(&c);
    let mut s = Steps::<Key, E>::new(&notes);
    let (m, g, k, f) = (
        given("m", p.mass),
        given("g", p.g),
        given("k", p.k),
        given("F", p.force),
    );
    let (mu_s, mu_d) = (given(r"\mu_s", p.mu_s), given(r"\mu_d", p.mu_d));
    let d = || big_d(&mu_s, &mu_d);

    let w = s.push_param(param::W, m.clone() * g.clone(), Some(p.weight()));
    let omega = s.push_param(param::OMEGA, sqrt(k / m), Some(p.omega()));
    let t = s.push_param(param::T, int(2) * pi() / omega, Some(period));
    let phi = s.push(Key::Phi, f.clone() / w, Some(c.phi));
    let tau_sl = s.push(
        Key::TauSlip,
        half() * (int(1) - phi.clone() / (int(2) * mu_s.clone())),
        Some(c.tau_slip),
    );
    s.push(Key::TSlip, t.clone() * tau_sl, Some(c.t_slip));
    s.push(
        Key::ASlip,
        g.clone() * phi.clone() / int(2) * (int(1) - mu_d.clone() / mu_s.clone()),
        Some(c.a_slip),
    );
    let tau_m = s.push(
        Key::TauMaxSpeed,
        half() * (int(1) + phi.clone() / (int(2) * mu_d.clone())),
        Some(c.tau_max_speed),
    );
    s.push(
        Key::TMaxSpeed,
        t.clone() * tau_m.clone(),
        Some(c.t_max_speed),
    );
    let v_m = s.push(
        Key::VMax,
        g.clone() * t.clone() * pow(phi.clone(), 2) * d()
            / (int(16) * pow(mu_s.clone(), 2) * mu_d.clone()),
        Some(c.v_max),
    );
    let theta = s.push(
        Key::Theta,
        (mu_s.clone() + sqrt(d())) / (int(2) * mu_s.clone() * mu_d.clone()),
        Some(c.theta),
    );
    let tau_st = s.push(
        Key::TauStick,
        half() * (int(1) + phi.clone() * theta.clone()),
        Some(c.tau_stick),
    );
    s.push(Key::TStick, t.clone() * tau_st, Some(c.t_stick));
    s.push(
        Key::SlipDuration,
        t.clone() * phi.clone() / int(2)
            * ((mu_s.clone() + mu_d.clone() + sqrt(d())) / (int(2) * mu_s.clone() * mu_d.clone())),
        Some(c.slip_duration),
    );
    s.push(Key::PhiStickMax, int(1) / theta, Some(c.phi_stick_max));
    s.push(
        Key::PhiContinuous,
        int(4) * mu_s.clone() * mu_d.clone() / (int(2) * mu_s.clone() + sqrt(int(2) * d())),
        Some(c.phi_continuous),
    );
    s.push(
        Key::MuMinEqual,
        (int(1) + sqrt(int(2))) * phi.clone() / int(2),
        Some(c.mu_min_equal),
    );
    let gamma = s.push(
        Key::Gamma,
        (pow_ratio(d(), 3, 2)
            + pow(mu_s.clone(), 3)
            + int(3) * pow(mu_s.clone(), 2) * mu_d.clone()
            - pow(mu_d.clone(), 3))
            / (int(96) * pow(mu_s.clone(), 3) * pow(mu_d.clone(), 2)),
        Some(c.gamma),
    );
    let v_avg = s.push(
        Key::VAvg,
        g.clone() * t.clone() * pow(phi.clone(), 3) * gamma.clone(),
        Some(c.v_avg),
    );
    s.push(
        Key::AdvancePerPeriod,
        g.clone() * pow(t.clone(), 2) * pow(phi.clone(), 3) * gamma,
        Some(c.advance_per_period),
    );
    s.push(Key::Power, f * v_avg, Some(c.power));
    // 1 + τ'_M − √(2τ'_M² − v_M/(gTμd)) with τ'_M = 1 − τ_M, the other zero of a (guide §7.5).
    s.push(
        Key::TauStickLate,
        int(2) - tau_m.clone() - sqrt(int(2) * pow(int(1) - tau_m, 2) - v_m / (g * t * mu_d)),
        c.tau_stick_late,
    );
    s.steps
}
