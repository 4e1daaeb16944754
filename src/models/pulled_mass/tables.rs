//! The pulled mass in the report's tables and in the terminal: parameters, regimes with the
//! inequality that decides them, the closed forms and their checks, the laws side by side.

use std::fmt::Write;

use super::explore::regime_reason as report_regime_reason;
use super::formula::Regime;
use super::results::{self as pulled_mass, Evaluation};
use super::{quantity as pm, PulledMassParams};
use crate::error::Result;
use crate::format::short;
use crate::models::paper::{LAW_WORDS, LINEARIZATION};
use crate::models::param::num as pnum;
use crate::output::text::{
    checks_table, closed_form_table, laws_table as text_laws, not_describing, DIGITS as TEXT_DIGITS,
};
use crate::present::vocab::Comparison;
use crate::present::Present;
use crate::report::context::{
    blank, count, fill_checks, input, integration_regime, laws_table, row, RegimeRow, SceneCtx,
};
use crate::report::scene::Scene;

pub(crate) fn scene_tables(scene: &Scene, p: &PulledMassParams) -> Result<SceneCtx> {
    let e = pulled_mass::evaluate(p, scene.periods)?;
    let mut ctx = blank(scene, "pulled mass");
    let pp = &e.params;
    ctx.params = vec![
        input("μs (static friction)", p.mu_s, ""),
        input("μd (dynamic friction)", p.mu_d, ""),
        input("m (block; hanging mass m' = m)", p.mass, "kg"),
        input("k (spring)", p.k, "N/m"),
        input("F (pull)", p.force, "N"),
        input("g", p.g, "m/s²"),
        row("W = m g", pp.weight, "N"),
        row("ω = √(k/m')", pp.omega, "rad/s"),
        row("T = 2π/ω", pp.period, "s"),
        row("φ = F/W", pp.phi, ""),
        count("periods integrated", pp.periods),
    ];
    let c = &e.closed_form;
    let why = report_regime_reason(c, p.mu_s);
    ctx.regimes = vec![
        RegimeRow {
            law: "linearized law, closed forms".to_string(),
            regime: c.regime.words().to_string(),
            why,
        },
        integration_regime("linearized law, exact integration", &e.linear),
        integration_regime("harmonic law, exact integration", &e.harmonic),
    ];
    fill_checks(&mut ctx, |k: pm::Key| c.get(k), &e.checks, &e.applicability);
    ctx.linearization = Some(Comparison {
        heading: LINEARIZATION.to_string(),
        table: laws_table(
            &[
                ("harmonic", Some(&e.harmonic)),
                ("linearized", Some(&e.linear)),
            ],
            pp.period,
        ),
    });
    Ok(ctx)
}

/// Renders a pulled-mass evaluation as plain-text tables.
pub(crate) fn text(e: &Evaluation) -> String {
    let p = &e.params;
    let c = &e.closed_form;
    let mut out = String::new();
    let _ = writeln!(out, "stickslip eval pulled-mass");
    let _ = writeln!(
        out,
        "parameters: mu_s = {}, mu_d = {}, m = {} kg, k = {} N/m, F = {} N, g = {} m/s², periods = {}",
        // Parameters as given, but never the 300 digits `{}` writes for 1e300.
        pnum(p.input.mu_s), pnum(p.input.mu_d), pnum(p.input.mass), pnum(p.input.k),
        pnum(p.input.force), pnum(p.input.g), p.periods
    );
    let _ = writeln!(
        out,
        "derived:    W = m g = {} N, omega = {} rad/s, T = {} s, phi = F/W = {}",
        short(Some(p.weight), TEXT_DIGITS),
        short(Some(p.omega), TEXT_DIGITS),
        short(Some(p.period), TEXT_DIGITS),
        short(Some(p.phi), TEXT_DIGITS)
    );
    let _ = writeln!(
        out,
        "\nregime (linearized law): {} ({})  [{}]",
        c.regime.words(),
        c.regime.id(),
        regime_reason(e)
    );
    closed_form_table(&mut out, &LAW_WORDS, |k: pm::Key| c.get(k));
    not_describing(&mut out, &e.applicability);
    checks_table(&mut out, &LAW_WORDS, &e.checks);
    text_laws(
        &mut out,
        <PulledMassParams as Present>::LAWS,
        &[Some(&e.harmonic), Some(&e.linear)],
        "",
    );
    out
}

/// The inequality of guide §9 that decides the regime, with its numbers.
fn regime_reason(e: &Evaluation) -> String {
    let c = &e.closed_form;
    let (phi, two_mu_s) = (
        short(Some(c.phi), 6),
        short(Some(2.0 * e.params.input.mu_s), 6),
    );
    let (stick, cont) = (
        short(Some(c.phi_stick_max), 6),
        short(Some(c.phi_continuous), 6),
    );
    match c.regime {
        Regime::ImmediateContinuousSlip => format!("phi = {phi} > 2 mu_s = {two_mu_s}"),
        Regime::SlipStick => format!("phi = {phi} <= 1/Theta = {stick} (20)"),
        Regime::SlipStickLate => format!("1/Theta = {stick} < phi = {phi} <= phi_c = {cont}"),
        Regime::ContinuousSlip => format!("phi_c = {cont} < phi = {phi} <= 2 mu_s = {two_mu_s}"),
    }
}
