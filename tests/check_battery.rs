//! `stickslip check` never gives a false verdict: a battery of correct formulas (each right
//! wherever the exact integration measures its quantity, or in the regime named with it) and
//! subtly wrong ones (a sign under a root, a coefficient, a threshold just above a boundary, a
//! term that matters only at small φ, a factor 1 + 3e-9, the wrong phase), in plain, LaTeX and
//! pasted-Unicode spellings. Every correct one must agree and every wrong one disagree.

use stickslip::check::{run, Request, Verdict};
use stickslip::models::pulled_mass::PulledMassParams;
use stickslip::models::woodpecker::WoodpeckerParams;
use stickslip::models::Model;

/// (model, formula, quantity, regime).
type Case = (
    &'static str,
    &'static str,
    Option<&'static str>,
    Option<&'static str>,
);

const SAMPLES: usize = 300;
const SLIP_STICK: Option<&str> = Some("slip_stick");
const LATE: Option<&str> = Some("slip_stick_late");
const DOUBLE: Option<&str> = Some("double_slip_stick");
const P: &str = "pulled-mass";
const W: &str = "woodpecker";

const CORRECT: &[Case] = &[
    (P, "T/2*(1-phi/(2*mu_s))", Some("t_slip"), None),
    (P, r"\frac{T}{2}\left(1-\frac{\varphi}{2\mu_s}\right)", Some("t_slip"), None),
    (P, "T/2·(1 − φ/(2μs))", Some("t_slip"), None),
    (P, "T*tau_SL", Some("t_slip"), None),
    (P, "T*(2*mu_s - phi)/(4*mu_s)", Some("t_slip"), None),
    (P, r"T\exp(\ln(\tau_{SL}))", Some("t_slip"), None),
    (P, "(g φ/2)(1 − μd/μs)", Some("a_slip"), None),
    (P, "g*phi*(mu_s-mu_d)/(2*mu_s)", Some("a_slip"), None),
    (P, r"\frac{g\varphi}{2}\left|1-\frac{\mu_d}{\mu_s}\right|", Some("a_slip"), None),
    (P, "T/2*(1+phi/(2*mu_d))", Some("t_max_speed"), None),
    (P, "g*T*phi^2*(-mu_d^2+mu_s^2+2*mu_s*mu_d)/(16*mu_s^2*mu_d)", Some("v_max"), None),
    (P, r"\frac{g T \varphi^2 (\mu_s^2 + 2\mu_s\mu_d - \mu_d^2)}{16 \mu_s^2 \mu_d}", Some("v_max"), None),
    (P, "gTφ²(μs² + 2μsμd − μd²)/(16μs²μd)", Some("v_max"), None),
    (P, "g*T*phi^2*(mu_s^2+2*mu_s*mu_d-mu_d^2)/(1.6e1*mu_s^2*mu_d)", Some("v_max"), None),
    (P, "T/2 (1 + φ Θ)", Some("t_stick"), SLIP_STICK),
    (P, r"\frac{T}{2}\left(1+\varphi\Theta\right)", Some("t_stick"), SLIP_STICK),
    (P, "T*tau_ST_late", Some("t_stick"), LATE),
    (P, r"g T \varphi^3 \Gamma", Some("v_avg"), SLIP_STICK),
    (P, "gTφ³Γ", Some("v_avg"), SLIP_STICK),
    (P, r"\bar{v} = g T \varphi^3 \Gamma", None, SLIP_STICK),
    (P, "g*T*phi^3*Gamma*1e6/1E6", Some("v_avg"), SLIP_STICK),
    (P, "g*T^2*phi^3*Gamma", Some("advance_per_period"), SLIP_STICK),
    (P, "F*g*T*phi^3*Gamma", Some("power"), SLIP_STICK),
    (
        P,
        "T*phi*(mu_s+mu_d+sqrt(mu_s^2+2*mu_s*mu_d-mu_d^2))/(4*mu_s*mu_d)",
        Some("slip_duration"),
        SLIP_STICK,
    ),
    (P, "phi <= varphi_c", Some("sticks"), None),
    (P, "φ ≤ 4μsμd/(2μs + √(2(μs² + 2μsμd − μd²)))", Some("sticks"), None),
    (W, r"t_0^{(I)} - \Delta^{(I)}", Some("t_slip_1"), None),
    (W, "τ(1 + δ0/ζ0) − τ W_S/(k ζ0 u_s^(−))", Some("t_slip_1"), None),
    (W, "tau*(1+delta_0/zeta_0) - tau*W_S/(k*zeta_0*u_s_minus)", Some("t_slip_1"), None),
    (W, "2λg(μs − μd)/(2λμs − 1)", Some("a_slip_1"), None),
    (W, "2*lambda*g*(mu_s-mu_d)/(2*lambda*mu_s+1)", Some("a_slip_2"), None),
    (W, "t_0_II - Delta_II", Some("t_slip_2"), None),
    (
        W,
        "t_0_I + Delta_I*(u_s_minus+sqrt(u_s_minus^2+2*u_s_minus*u_d_plus-u_d_minus*u_d_plus))/u_d_plus",
        Some("t_stick_1"),
        DOUBLE,
    ),
    (W, "g*tau*W_S^2*Gamma/(24*zeta_0^2*k^2)", Some("v_avg"), DOUBLE),
];

const WRONG: &[Case] = &[
    (P, "-2^2", Some("t_stick"), None),
    (
        P,
        "T/2*(1+phi*(mu_s+sqrt(-mu_s^2+2*mu_s*mu_d-mu_d^2))/(2*mu_s*mu_d))",
        Some("t_stick"),
        SLIP_STICK,
    ),
    (P, r"2 g T \varphi^3 \Gamma", Some("v_avg"), SLIP_STICK),
    (P, r"g T \varphi^3 \Gamma", Some("v_avg"), None),
    (P, "T/2 (1 + φ Θ)", Some("t_stick"), None),
    (P, "phi <= 1.03*varphi_c", Some("sticks"), None),
    (P, r"\varphi \le 1/\Theta", Some("sticks"), None),
    (P, "phi < 2*mu_d", Some("sticks"), None),
    (P, "phi <= mu_d", Some("sticks"), None),
    (P, "g*T*phi^3*Gamma*(1+0.001*exp(-50*phi*Theta))", Some("v_avg"), SLIP_STICK),
    (P, "g*T*phi^3*Gamma*(1+3e-9)", Some("v_avg"), SLIP_STICK),
    (P, "T/2*(1+phi/(2*mu_s))", Some("t_slip"), None),
    (P, "T/2*(1-phi/(2*mu_d))", Some("t_slip"), None),
    (P, "T/2*(1-phi/(2*mu_s)) + 3e-9*T", Some("t_slip"), None),
    (P, "(g φ/2)(1 − μs/μd)", Some("a_slip"), None),
    (P, "g*T*phi^2*(mu_s^2-2*mu_s*mu_d-mu_d^2)/(16*mu_s^2*mu_d)", Some("v_max"), None),
    (P, "g*T*phi^2*(mu_s^2+2*mu_s*mu_d-mu_d^2)/(8*mu_s^2*mu_d)", Some("v_max"), None),
    (
        P,
        "gTφ²(μs² + 2μsμd − μd²)/(16μs²μd)·(1 + 1e-6(μs − μd)/μs)",
        Some("v_max"),
        None,
    ),
    (P, "T/2*(1+phi/(2*mu_s))", Some("t_max_speed"), None),
    (P, "g*T*phi^3*Gamma", Some("advance_per_period"), SLIP_STICK),
    (P, "F*g*T*phi^3*Gamma*(1+1e-6)", Some("power"), SLIP_STICK),
    (
        P,
        "T*phi*(mu_s+mu_d+sqrt(mu_s^2+2*mu_s*mu_d-mu_d^2))/(2*mu_s*mu_d)",
        Some("slip_duration"),
        SLIP_STICK,
    ),
    (P, "T/2 (1 + φ Θ)(1 + φ⁴)", Some("t_stick"), SLIP_STICK),
    (W, "τ", Some("t_slip_1"), None),
    (W, r"t_0^{(I)} + \Delta^{(I)}", Some("t_slip_1"), None),
    (W, "2λg(μs − μd)/(2λμs + 1)", Some("a_slip_1"), None),
    (
        W,
        "t_0_I + Delta_I*(u_s_minus+sqrt(-u_s_minus^2+2*u_s_minus*u_d_plus-u_d_minus*u_d_plus))/u_d_plus",
        Some("t_stick_1"),
        DOUBLE,
    ),
    (W, "t_0_II + Delta_II", Some("t_slip_2"), None),
    (W, "g*tau*W_S^2*Gamma/(12*zeta_0^2*k^2)", Some("v_avg"), DOUBLE),
    (W, "g*(u_s_plus-u_d_minus)/u_s_plus", Some("a_slip_2"), None),
    (W, "t_0_I - Delta_I*(1+1e-6)", Some("t_slip_1"), None),
];

fn verdict((model, formula, quantity, regime): &Case) -> stickslip::check::Report {
    let case = if *model == P {
        Model::PulledMass(PulledMassParams::default())
    } else {
        Model::Woodpecker(WoodpeckerParams::default())
    };
    run(&Request {
        case,
        formula: formula.to_string(),
        quantity: quantity.map(str::to_string),
        regime: regime.map(str::to_string),
        samples: SAMPLES,
        seed: 7,
    })
    .unwrap_or_else(|e| panic!("{formula}: {e}"))
}

#[test]
fn the_battery_has_enough_of_each_kind() {
    assert!(CORRECT.len() >= 30 && WRONG.len() >= 30);
}

#[test]
fn every_correct_formula_agrees() {
    let mut false_rejects = Vec::new();
    for case in CORRECT {
        let r = verdict(case);
        // Agreement on a handful of sets would prove little.
        if r.verdict != Verdict::Agrees || r.compared < SAMPLES / 5 {
            false_rejects.push(format!(
                "{} ({:?}, {} compared): {}",
                case.1,
                r.verdict,
                r.compared,
                stickslip::check::text(&r)
            ));
        }
    }
    assert!(false_rejects.is_empty(), "{}", false_rejects.join("\n\n"));
}

#[test]
fn every_wrong_formula_disagrees() {
    let false_accepts: Vec<String> = WRONG
        .iter()
        .filter_map(|case| {
            let r = verdict(case);
            (r.verdict != Verdict::Disagrees).then(|| format!("{}: {:?}", case.1, r.verdict))
        })
        .collect();
    assert!(false_accepts.is_empty(), "{}", false_accepts.join("\n"));
}

/// At μs = μd the acceleration at slip onset is exactly 0: compared on the scale of the
/// forces, as `eval` compares it, the right formula agrees there.
#[test]
fn an_exact_zero_is_compared_on_the_quantitys_scale() {
    let p = PulledMassParams {
        mu_d: 0.4,
        ..PulledMassParams::default()
    };
    for (case, formula, quantity) in [
        (Model::PulledMass(p), "g*phi/2*(1-mu_d/mu_s)", "a_slip"),
        (
            Model::Woodpecker(WoodpeckerParams {
                mu_d: 0.65,
                ..WoodpeckerParams::default()
            }),
            "2*lambda*g*(mu_s-mu_d)/(2*lambda*mu_s-1)",
            "a_slip_1",
        ),
    ] {
        let r = run(&Request {
            case,
            formula: formula.to_string(),
            quantity: Some(quantity.to_string()),
            regime: None,
            samples: 20,
            seed: 1,
        })
        .unwrap();
        assert_eq!(r.given.formula, Some(0.0));
        assert_eq!(r.given.agrees, Some(true), "{}", stickslip::check::text(&r));
    }
}
