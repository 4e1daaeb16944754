//! Worked substitutions of the linearized woodpecker (guide §5.2 and guide §8): W_S, ω, T, λ,
//! the linear amplitudes, the dimensionless groups, phases I and II (one function for both,
//! by the swap u^(−) ↔ u^(+), η ↔ η'), and the whole period. Values come from
//! [`crate::models::woodpecker::formula`]; which forms apply, from [`crate::models::woodpecker::results`].

use crate::derivation::expr::{arcsin, max, pow, sqrt, Term};
use crate::derivation::{Expr, Step, Steps, Value};
use crate::models::woodpecker::formula::{self as cf, Counterpart, Groups, PhaseClosedForm};
use crate::models::woodpecker::quantity::Key;
use crate::models::woodpecker::results::{applicability, domain_note, linear_inputs};
use crate::models::woodpecker::{OmegaMode, WoodpeckerParams};

/// The derived parameters with a step (guide §14 `params` keys).
pub mod param {
    use crate::derivation::Param;

    /// W_S = m_S g.
    pub const W_S: Param = Param {
        id: "W_S",
        tex: "W_S",
        equation: "guide §5.2",
        unit: "N",
    };
    /// ω of the `--omega` mode.
    pub const OMEGA: Param = Param {
        id: "omega",
        tex: r"\omega",
        equation: "guide §5.2",
        unit: "rad/s",
    };
    /// T = 2π/ω.
    pub const T: Param = Param {
        id: "T",
        tex: "T",
        equation: "guide §5.2",
        unit: "s",
    };
    /// λ = l/h.
    pub const LAMBDA: Param = Param {
        id: "lambda",
        tex: r"\lambda",
        equation: "guide §5.2",
        unit: "",
    };
}

/// The keys of one phase, in the order of its steps.
struct PhaseNames {
    keys: [Key; 12],
    /// The ±1 of u_B = 2λμd ± 1: +1 in phase I, −1 in phase II.
    sigma: i64,
}

const PHASE_I: PhaseNames = PhaseNames {
    keys: [
        Key::T01,
        Key::Delta1,
        Key::TSlip1,
        Key::ASlip1,
        Key::TMaxSpeed1,
        Key::VMax1,
        Key::S1,
        Key::TStick1,
        Key::MuDMin1,
        Key::MuDHalt1,
        Key::Gamma1,
        Key::Distance1,
    ],
    sigma: 1,
};

const PHASE_II: PhaseNames = PhaseNames {
    keys: [
        Key::T02,
        Key::Delta2,
        Key::TSlip2,
        Key::ASlip2,
        Key::TMaxSpeed2,
        Key::VMax2,
        Key::S2,
        Key::TStick2,
        Key::MuDMin2,
        Key::MuDHalt2,
        Key::Gamma2,
        Key::Distance2,
    ],
    sigma: -1,
};

/// The quantities every phase formula is written in (leaves of earlier steps).
struct Common<E> {
    g: E,
    tau: E,
    w_s: E,
    k: E,
    zeta0: E,
    lambda: E,
}

/// The factors seen by the slip of a phase (formula::woodpecker module doc): U, u_A, u_B and
/// the height h_B of the lobe after the zero of F_e.
struct Factors<E> {
    u: E,
    u_a: E,
    u_b: E,
    h_b: E,
}

/// Every closed form of the woodpecker with `p`'s numbers, in the order a derivation reads.
pub fn woodpecker(p: &WoodpeckerParams) -> Vec<Step> {
    steps::<Expr>(p)
}

/// [`woodpecker`] without the expression trees: each step's formula as its value only (the
/// same numbers, bit for bit).
pub fn woodpecker_values(p: &WoodpeckerParams) -> Vec<Step<Value>> {
    steps::<Value>(p)
}

fn steps<E: Term>(p: &WoodpeckerParams) -> Vec<Step<E>> {
    let (int, pi, given) = (E::int, E::pi, E::given);
    let lw = linear_inputs(p);
    let c = cf::evaluate(&lw);
    let note = domain_note(p, &c);
    let notes = applicability(&c, note.as_deref());
    let mut s = Steps::<Key, E>::new(&notes);
    let (g, k) = (given("g", p.g), given("k", p.k));
    let (m_s, m_w) = (given("m_S", p.m_sleeve), given("m_W", p.m_bird));
    let (z0, d0) = (given("z_0", p.z0), given("d_0", p.d0));
    let (mu_s, mu_d) = (given(r"\mu_s", p.mu_s), given(r"\mu_d", p.mu_d));

    let w_s = s.push_param(param::W_S, m_s.clone() * g.clone(), Some(p.sleeve_weight()));
    let omega_expr = match p.omega {
        OmegaMode::Bird => sqrt(k.clone() / m_w),
        OmegaMode::Reduced => sqrt(k.clone() * (m_s.clone() + m_w.clone()) / (m_s * m_w)),
        OmegaMode::Total => sqrt(k.clone() / (m_s + m_w)),
    };
    let omega = s.push_param(param::OMEGA, omega_expr, Some(p.omega()));
    let t = s.push_param(param::T, int(2) * pi() / omega, Some(p.period()));
    let lambda = match p.lever {
        None => s.push_param(
            param::LAMBDA,
            given("l", p.l) / given("h", p.h),
            Some(p.lambda()),
        ),
        Some(lever) => given(r"\lambda", lever),
    };
    let tau = s.push(Key::TauQuarter, t / int(4), c.tau_quarter);
    let two_over_pi = || int(2) / pi();
    let zeta0_expr = match p.counterpart {
        Counterpart::Extremes | Counterpart::Zeros => d0.clone(),
        Counterpart::Tangent => pi() / int(2) * sqrt(pow(d0.clone(), 2) - pow(z0.clone(), 2)),
    };
    let zeta0 = s.push(Key::Zeta0, zeta0_expr, c.zeta0);
    let delta0_expr = match p.counterpart {
        Counterpart::Extremes => z0,
        Counterpart::Zeros => d0.clone() * two_over_pi() * arcsin(z0 / d0),
        Counterpart::Tangent => zeta0.clone() * two_over_pi() * arcsin(z0 / d0),
    };
    let delta0 = s.push(Key::Delta0, delta0_expr, c.delta0);
    let two_lambda = |mu: &E| int(2) * lambda.clone() * mu.clone();
    let u_s_minus = s.push(Key::USMinus, two_lambda(&mu_s) - int(1), c.u_s_minus);
    let u_s_plus = s.push(Key::USPlus, two_lambda(&mu_s) + int(1), c.u_s_plus);
    let u_d_minus = s.push(Key::UDMinus, two_lambda(&mu_d) - int(1), c.u_d_minus);
    let u_d_plus = s.push(Key::UDPlus, two_lambda(&mu_d) + int(1), c.u_d_plus);
    let eta = s.push(
        Key::Eta,
        k.clone() * (zeta0.clone() - delta0.clone()) / w_s.clone(),
        c.eta,
    );
    let eta_prime = s.push(
        Key::EtaPrime,
        k.clone() * (zeta0.clone() + delta0.clone()) / w_s.clone(),
        c.eta_prime,
    );

    // Outside the closed-form domain no formula of the phases describes the motion.
    s.fallback = note.as_deref();
    let common = Common {
        g,
        tau: tau.clone(),
        w_s: w_s.clone(),
        k,
        zeta0,
        lambda,
    };
    let ratio = || delta0.clone() / common.zeta0.clone();
    let groups = Groups::new(&lw);
    let gamma_1 = phase(
        &mut s,
        &PHASE_I,
        &common,
        &Factors {
            u: u_s_minus,
            u_a: u_d_minus.clone(),
            u_b: u_d_plus.clone(),
            h_b: eta,
        },
        tau.clone() * (int(1) + ratio()),
        &cf::phase_closed_form(&lw, &groups, c.t0_1),
    );
    let gamma_2 = phase(
        &mut s,
        &PHASE_II,
        &common,
        &Factors {
            u: u_s_plus,
            u_a: u_d_plus,
            u_b: u_d_minus,
            h_b: eta_prime,
        },
        tau * (int(3) - ratio()),
        &cf::phase_closed_form(&lw, &groups.swapped(), c.t0_2),
    );

    let Common {
        g,
        tau,
        w_s,
        k,
        zeta0,
        ..
    } = common;
    let gamma = s.push(Key::Gamma, gamma_1 + gamma_2, c.gamma);
    let lengths = || pow(zeta0.clone(), 2) * pow(k.clone(), 2);
    s.push(
        Key::DistancePerPeriod,
        g.clone() * pow(tau.clone(), 2) * pow(w_s.clone(), 2) * gamma.clone()
            / (int(6) * lengths()),
        c.distance_per_period,
    );
    let v_avg = s.push(
        Key::VAvg,
        g * tau * pow(w_s.clone(), 2) * gamma / (int(24) * lengths()),
        c.v_avg,
    );
    s.push(Key::PowerWeight, w_s * v_avg, c.power_weight);
    s.steps
}

/// The steps of one phase (guide §8.3, or guide §8.4 by the swap); returns the leaf of its Γ.
fn phase<E: Term>(
    s: &mut Steps<Key, E>,
    names: &PhaseNames,
    c: &Common<E>,
    f: &Factors<E>,
    t0_expr: E,
    v: &PhaseClosedForm,
) -> E {
    let int = E::int;
    let [k_t0, k_delta, k_sl, k_a, k_tm, k_vm, k_s, k_st, k_min, k_halt, k_gamma, k_y] = names.keys;
    let (u, u_a, u_b, h) = (&f.u, &f.u_a, &f.u_b, &f.h_b);
    let t0 = s.push(k_t0, t0_expr, v.t0);
    let delta = s.push(
        k_delta,
        c.tau.clone() * c.w_s.clone() / (c.k.clone() * c.zeta0.clone() * u.clone()),
        v.delta,
    );
    s.push(k_sl, t0.clone() - delta.clone(), v.t_slip);
    s.push(
        k_a,
        c.g.clone() * ((u.clone() - u_a.clone()) / u.clone()),
        v.a_slip,
    );
    s.push(
        k_tm,
        t0.clone() + delta.clone() * u.clone() / u_b.clone(),
        v.t_max_speed,
    );
    s.push(
        k_vm,
        c.g.clone() * delta.clone() / int(2)
            * ((u_b.clone() * (int(2) * u.clone() - u_a.clone()) + pow(u.clone(), 2))
                / (u.clone() * u_b.clone())),
        v.v_max,
    );
    let s_factor = s.push(
        k_s,
        (u.clone()
            + sqrt(
                pow(u.clone(), 2) + int(2) * u.clone() * u_b.clone() - u_a.clone() * u_b.clone(),
            ))
            / u_b.clone(),
        v.s,
    );
    s.push(k_st, t0 + delta * s_factor.clone(), v.t_stick);
    let sigma = |e: E| match names.sigma {
        1 => e + int(1),
        _ => e - int(1),
    };
    // (51) and (65) as printed: U²η(2 − η) + 2U + 1 and U²η'(η' + 2) + 2U − 1.
    let lobe = match names.sigma {
        1 => int(2) - h.clone(),
        _ => h.clone() + int(2),
    };
    let numerator = sigma(pow(u.clone(), 2) * h.clone() * lobe + int(2) * u.clone());
    let two_lambda = || int(2) * c.lambda.clone();
    s.push(
        k_min,
        int(1) / two_lambda() * (numerator / (pow(u.clone(), 2) * pow(h.clone(), 2) + int(1))),
        v.mu_d_min,
    );
    // guide §8.6: x₊ = [B + √(B² − A U²)]/A with A = 1 + 2h²U², B = U ± 1 + 2hU²; when the root is
    // imaginary the threshold is 1/h alone.
    let a = int(1) + int(2) * pow(h.clone(), 2) * pow(u.clone(), 2);
    let b = sigma(u.clone()) + int(2) * h.clone() * pow(u.clone(), 2);
    let x_plus = (b.clone() + sqrt(pow(b, 2) - a.clone() * pow(u.clone(), 2))) / a;
    let floor = int(1) / h.clone();
    let threshold = if x_plus.eval().is_finite() {
        max(x_plus, floor)
    } else {
        floor
    };
    let threshold = match names.sigma {
        1 => threshold - int(1),
        _ => threshold + int(1),
    };
    s.push(k_halt, threshold / two_lambda(), v.mu_d_halt);
    let s1 = || s_factor.clone() + int(1);
    let gamma = s.push(
        k_gamma,
        (int(3) * u.clone() * pow(s1(), 2)
            - u_b.clone() * pow(s_factor.clone(), 3)
            - int(3) * u_a.clone() * s_factor.clone()
            - int(2) * u_a.clone())
            / pow(u.clone(), 3),
        v.gamma,
    );
    s.push(
        k_y,
        c.g.clone() * pow(c.tau.clone(), 2) * pow(c.w_s.clone(), 2) * gamma.clone()
            / (int(6) * pow(c.zeta0.clone(), 2) * pow(c.k.clone(), 2)),
        v.distance,
    );
    gamma
}
