//! The terminal output of `stickslip eval`: parameters, closed forms, checks, and the two laws
//! side by side.

use std::fmt::Write;

use super::format::{rel, sig};
// Parameters as given, but never the 300 digits `{}` writes for 1e300.
use crate::models::param::num;
use crate::models::pulled_mass::results::Evaluation;
use crate::models::woodpecker::results as woodpecker;
use crate::results::quantity::{find, Quantity, PULLED_MASS, WOODPECKER};
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
        num(p.input.mu_s),
        num(p.input.mu_d),
        num(p.input.mass),
        num(p.input.k),
        num(p.input.force),
        num(p.input.g),
        p.periods
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
    let values = serde_json::to_value(c).unwrap_or_default();
    closed_form_table(&mut out, PULLED_MASS, &values);
    checks_table(&mut out, &e.checks, PULLED_MASS);
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
        num(i.mu_s),
        num(i.mu_d),
        num(i.k),
        num(i.m_sleeve),
        num(i.m_bird),
        num(i.l),
        num(i.h),
        num(i.z0),
        num(i.d0),
        num(i.g),
        p.periods
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
        woodpecker::orbit_regime_id(c.regime),
        c.paper_regime_valid,
        c.immediate_slip
    );
    if let Some(note) = &e.domain_note {
        let _ = writeln!(out, "closed forms do not apply: {note}");
    }
    let values = serde_json::to_value(c).unwrap_or_default();
    closed_form_table(&mut out, WOODPECKER, &values);
    let not_applying: Vec<_> = e.applicability.iter().filter(|a| !a.applies).collect();
    if !not_applying.is_empty() && e.domain_note.is_none() {
        let _ = writeln!(out, "\nformulas that do not describe this motion");
        for a in not_applying {
            let symbol = find(WOODPECKER, a.quantity).map_or(a.quantity, |q| q.symbol);
            let _ = writeln!(out, "  {symbol:<14} {}", a.reason);
        }
    }
    checks_table(&mut out, &e.checks, WOODPECKER);
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
    match c.regime.id() {
        "immediate_continuous_slip" => format!("phi = {phi} > 2 mu_s = {two_mu_s}"),
        "slip_stick" => format!("phi = {phi} <= 1/Theta = {stick} (20)"),
        "slip_stick_late" => format!("1/Theta = {stick} < phi = {phi} <= phi_c = {cont}"),
        _ => format!("phi_c = {cont} < phi = {phi} <= 2 mu_s = {two_mu_s}"),
    }
}

fn closed_form_table(out: &mut String, table: &[Quantity], values: &serde_json::Value) {
    let _ = writeln!(out, "\nclosed forms (linearized law)");
    let _ = writeln!(
        out,
        "  {:<14} {:>18}  {:<6} {:<11} tag",
        "symbol", "value", "unit", "eq."
    );
    for q in table {
        let v = values.get(q.key).and_then(serde_json::Value::as_f64);
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

fn checks_table(out: &mut String, checks: &[Check], table: &'static [Quantity]) {
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
        let symbol = find(table, &c.quantity).map_or(c.quantity.as_str(), |q| q.symbol);
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
        row(out, name, s(h), s(l));
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

fn power_rows(s: &Summary) -> Vec<(&'static str, Option<f64>)> {
    match s.power {
        crate::results::Power::PulledMass {
            power,
            power_friction,
        } => {
            vec![
                ("power F v̄ (W)", power),
                ("friction dissipation (W)", power_friction),
            ]
        }
        crate::results::Power::Woodpecker {
            power_weight,
            power_friction,
        } => {
            vec![
                ("power W_S v̄ (W)", power_weight),
                ("friction dissipation (W)", power_friction),
            ]
        }
    }
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
