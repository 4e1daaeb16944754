//! The terminal output of `stickslip eval`: parameters, closed forms, checks, and the two laws
//! side by side.

use std::fmt::Write;

use super::format::{rel, sig};
use crate::models::pulled_mass::{formula::Regime, quantity as pm, results::Evaluation};
use crate::models::woodpecker::{quantity as wp, results as woodpecker};
use crate::results::quantity::Registry;
use crate::results::{Check, CheckValue, Summary};

const DIGITS: usize = 10;

/// Renders a pulled-mass evaluation as plain-text tables.
pub fn pulled_mass(e: &Evaluation) -> String {
    let p = &e.params;
    let c = &e.closed_form;
    let mut out = String::new();
    let _ = writeln!(out, "stickslip eval pulled-mass");
    let _ = writeln!(
        out,
        "parameters: mu_s = {}, mu_d = {}, m = {} kg, k = {} N/m, F = {} N, g = {} m/s², periods = {}",
        p.input.mu_s, p.input.mu_d, p.input.mass, p.input.k, p.input.force, p.input.g, p.periods
    );
    let _ = writeln!(
        out,
        "derived:    W = m g = {} N, omega = {} rad/s, T = {} s, phi = F/W = {}",
        sig(Some(p.weight), DIGITS),
        sig(Some(p.omega), DIGITS),
        sig(Some(p.period), DIGITS),
        sig(Some(p.phi), DIGITS)
    );
    let _ = writeln!(
        out,
        "\nregime (linearized law): {}  [{}]",
        c.regime.id(),
        regime_reason(e)
    );
    closed_form_table(&mut out, |k: pm::Key| c.get(k));
    checks_table(&mut out, &e.checks);
    laws_table(&mut out, &e.harmonic, Some(&e.linear));
    out
}

/// Renders a woodpecker evaluation as plain-text tables.
pub fn woodpecker(e: &woodpecker::Evaluation) -> String {
    let p = &e.params;
    let i = &p.input;
    let c = &e.closed_form;
    let mut out = String::new();
    let _ = writeln!(out, "stickslip eval woodpecker");
    let _ = writeln!(
        out,
        "parameters: mu_s = {}, mu_d = {}, k = {} N/m, m_S = {} kg, m_W = {} kg, l = {} m, h = {} m, \
         z0 = {} m, d0 = {} m, g = {} m/s², periods = {}",
        i.mu_s, i.mu_d, i.k, i.m_sleeve, i.m_bird, i.l, i.h, i.z0, i.d0, i.g, p.periods
    );
    let _ = writeln!(
        out,
        "options:    lambda = {} ({}), omega = {:?}, counterpart = {:?}",
        sig(Some(p.lambda), DIGITS),
        if i.lever.is_some() { "given" } else { "l/h" },
        i.omega,
        i.counterpart
    );
    let _ = writeln!(
        out,
        "derived:    W_S = m_S g = {} N, omega = {} rad/s, T = {} s, zeta0 = {} m, delta0 = {} m",
        sig(Some(p.sleeve_weight), DIGITS),
        sig(Some(p.omega), DIGITS),
        sig(Some(p.period), DIGITS),
        sig(p.zeta0, DIGITS),
        sig(p.delta0, DIGITS)
    );
    let _ = writeln!(
        out,
        "\nregime (linearized law, §3.6): {}; paper's standard regime valid: {}; immediate slip (38): {}",
        c.regime.id(),
        c.paper_regime_valid,
        c.immediate_slip
    );
    if let Some(note) = &e.domain_note {
        let _ = writeln!(out, "closed forms do not apply: {note}");
    }
    closed_form_table(&mut out, |k: wp::Key| c.get(k));
    let not_applying: Vec<_> = e.applicability.iter().filter(|a| !a.applies).collect();
    if !not_applying.is_empty() && e.domain_note.is_none() {
        let _ = writeln!(out, "\nformulas that do not describe this motion");
        for a in not_applying {
            let symbol = a.quantity.quantity().symbol;
            let _ = writeln!(out, "  {symbol:<14} {}", a.reason);
        }
    }
    checks_table(&mut out, &e.checks);
    laws_table(&mut out, &e.harmonic, e.linear.as_ref());
    out
}

/// The inequality of §1.5 that decides the regime, with its numbers.
fn regime_reason(e: &Evaluation) -> String {
    let c = &e.closed_form;
    let (phi, two_mu_s) = (sig(Some(c.phi), 6), sig(Some(2.0 * e.params.input.mu_s), 6));
    let (stick, cont) = (
        sig(Some(c.phi_stick_max), 6),
        sig(Some(c.phi_continuous), 6),
    );
    match c.regime {
        Regime::ImmediateContinuousSlip => format!("phi = {phi} > 2 mu_s = {two_mu_s}"),
        Regime::SlipStick => format!("phi = {phi} <= 1/Theta = {stick} (20)"),
        Regime::SlipStickLate => format!("1/Theta = {stick} < phi = {phi} <= phi_c = {cont}"),
        Regime::ContinuousSlip => format!("phi_c = {cont} < phi = {phi} <= 2 mu_s = {two_mu_s}"),
    }
}

/// The numbers of the closed forms of model `K` with their symbols, units and equations.
fn closed_form_table<K: Registry>(out: &mut String, get: impl Fn(K) -> Option<f64>) {
    let _ = writeln!(out, "\nclosed forms (linearized law)");
    let _ = writeln!(
        out,
        "  {:<14} {:>18}  {:<6} {:<11} tag",
        "symbol", "value", "unit", "eq."
    );
    for e in K::numbers() {
        let (q, v) = (&e.quantity, get(e.key));
        let _ = writeln!(
            out,
            "  {:<14} {:>18}  {:<6} {:<11} {}",
            q.symbol,
            sig(v, DIGITS),
            q.unit,
            q.equation,
            q.tag
        );
    }
}

fn checks_table(out: &mut String, checks: &[Check]) {
    let passed = checks.iter().filter(|c| c.pass).count();
    let _ = writeln!(
        out,
        "\nchecks: closed form vs exact integration of the linearized law ({passed}/{} pass, tolerance {:.0e})",
        checks.len(),
        crate::results::TOLERANCE
    );
    let _ = writeln!(
        out,
        "  {:<24} {:<18} {:>18} {:>18} {:>9}  verdict",
        "quantity", "eq.", "closed form", "numeric", "rel.err"
    );
    for c in checks {
        let symbol = c
            .quantity
            .quantity()
            .map_or(c.quantity.id(), |q| q.symbol.into());
        let _ = writeln!(
            out,
            "  {:<24} {:<18} {:>18} {:>18} {:>9}  {}",
            symbol,
            c.equation,
            value(&c.closed_form),
            value(&c.numeric),
            rel(c.rel_error),
            if c.pass { "pass" } else { "FAIL" }
        );
    }
}

fn value(v: &CheckValue) -> String {
    match v {
        CheckValue::Number(x) => sig(Some(*x), DIGITS),
        CheckValue::Text(s) => s.clone(),
    }
}

fn laws_table(out: &mut String, harmonic: &Summary, linear: Option<&Summary>) {
    let _ = writeln!(out, "\nexact integration: harmonic law vs linearized law");
    let Some(linear) = linear else {
        let _ = writeln!(out, "  (no linear law: its counterpart is undefined)");
        laws_table_rows(out, harmonic, harmonic, true);
        return;
    };
    laws_table_rows(out, harmonic, linear, false);
}

fn laws_table_rows(out: &mut String, harmonic: &Summary, linear: &Summary, harmonic_only: bool) {
    let row = |out: &mut String, name: &str, h: String, l: String| {
        let _ = writeln!(out, "  {name:<26} {h:>22} {l:>22}");
    };
    row(out, "", "harmonic".into(), "linear".into());
    row(
        out,
        "regime",
        harmonic.regime.id().into(),
        linear.regime.id().into(),
    );
    let s = |x: Option<f64>| sig(x, DIGITS);
    row(
        out,
        "immediate slip",
        harmonic.immediate_slip.to_string(),
        linear.immediate_slip.to_string(),
    );
    row(
        out,
        "first slip (s)",
        s(harmonic.first_slip_time),
        s(linear.first_slip_time),
    );
    let mult = |x: &Summary| x.period_multiplicity.map_or("—".into(), |n| n.to_string());
    row(out, "period multiplicity", mult(harmonic), mult(linear));
    row(
        out,
        "slips / sticks per period",
        format!(
            "{} / {}",
            harmonic.slips_per_period, harmonic.sticks_per_period
        ),
        format!("{} / {}", linear.slips_per_period, linear.sticks_per_period),
    );
    row(
        out,
        "advance per period (m)",
        s(harmonic.advance_per_period),
        s(linear.advance_per_period),
    );
    row(
        out,
        "mean speed v̄ (m/s)",
        s(harmonic.v_avg),
        s(linear.v_avg),
    );
    let (hp, lp) = (power_rows(harmonic), power_rows(linear));
    for ((name, h), (_, l)) in hp.into_iter().zip(lp) {
        row(out, &name, s(h), s(l));
    }
    let laws: &[(&str, &Summary)] = if harmonic_only {
        &[("harmonic", harmonic)]
    } else {
        &[("harmonic", harmonic), ("linear", linear)]
    };
    for &(name, law) in laws {
        let events: Vec<String> = law
            .steady_events
            .iter()
            .map(|e| format!("{} at phase {}", e.kind, sig(Some(e.phase), 8)))
            .chain(law.steady_speed_maxima.iter().map(|m| {
                format!(
                    "v max {} m/s at phase {}",
                    sig(Some(m.v), 8),
                    sig(Some(m.phase), 8)
                )
            }))
            .collect();
        let list = if events.is_empty() {
            "none".to_string()
        } else {
            events.join("; ")
        };
        let _ = writeln!(out, "  steady period, {name}: {list}");
    }
}

fn power_rows(s: &Summary) -> Vec<(String, Option<f64>)> {
    vec![
        (format!("power {} (W)", s.power.symbol), s.power.driving),
        ("friction dissipation (W)".to_string(), s.power.friction),
    ]
}

/// Renders the claims of the paper with their verdicts and numbers.
pub fn claims(claims: &crate::claims::Claims) -> String {
    let mut out = String::new();
    for c in &claims.claims {
        let ctx = crate::report::context::claim(c);
        let _ = writeln!(
            out,
            "claim {}: {} — {}",
            c.id,
            c.title,
            ctx.verdict.to_uppercase()
        );
        let _ = writeln!(out, "  the paper: {}", c.paper_says);
        let _ = writeln!(out, "  finding:   {}", c.finding);
        for n in &ctx.numbers {
            let _ = writeln!(out, "    {n}");
        }
        let _ = writeln!(out);
    }
    out
}
