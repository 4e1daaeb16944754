//! The woodpecker in the report's tables and in the terminal: parameters, regimes, the closed
//! forms and their checks, the harmonic law against each linear counterpart.

use std::fmt::Write;

use super::formula::Counterpart;
use super::results::{self as woodpecker};
use super::{quantity as wp, WoodpeckerParams};
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
    blank, count, fill_checks, input, integration_regime, laws_table, opt, row, ParamRow,
    RegimeRow, SceneCtx,
};
use crate::report::scene::Scene;
use crate::results::Summary;

pub(crate) fn scene_tables(scene: &Scene, p: &WoodpeckerParams) -> Result<SceneCtx> {
    let e = woodpecker::evaluate(p, scene.periods)?;
    let mut ctx = blank(scene, "woodpecker");
    let pp = &e.params;
    ctx.params = vec![
        input("μs (static friction)", p.mu_s, ""),
        input("μd (dynamic friction)", p.mu_d, ""),
        input("k (spring)", p.k, "N/m"),
        input("m_S (sleeve)", p.m_sleeve, "kg"),
        input("m_W (woodpecker)", p.m_bird, "kg"),
        input("l (lever arm of the spring force)", p.l, "m"),
        input("h (distance of the two contacts)", p.h, "m"),
        input("z0 (spring offset)", p.z0, "m"),
        input("d0 (spring amplitude)", p.d0, "m"),
        input("g", p.g, "m/s²"),
        row("λ (lever ratio)", pp.lambda, ""),
        row("W_S = m_S g", pp.sleeve_weight, "N"),
        row("ω", pp.omega, "rad/s"),
        row("T = 2π/ω", pp.period, "s"),
        ParamRow {
            name: "ζ0, δ0 (linear counterpart)".to_string(),
            value: format!(
                "{}, {}",
                opt(pp.zeta0.map(|z| 1e3 * z)),
                opt(pp.delta0.map(|d| 1e3 * d))
            ),
            unit: "mm".to_string(),
        },
        ParamRow {
            name: "options".to_string(),
            value: format!("ω: {}, counterpart: {}", p.omega.id(), p.counterpart.id()),
            unit: String::new(),
        },
        count("periods integrated", pp.periods),
    ];
    let c = &e.closed_form;
    ctx.regimes = vec![RegimeRow {
        law: "linearized law, closed forms".to_string(),
        regime: c.regime.words().to_string(),
        why: format!(
            "paper's standard regime (both sticks within their half periods): {}; immediate \
             slip (38): {}",
            if c.paper_regime_valid { "yes" } else { "no" },
            if c.immediate_slip { "yes" } else { "no" }
        ),
    }];
    if let Some(linear) = &e.linear {
        ctx.regimes.push(integration_regime(
            "linearized law, exact integration",
            linear,
        ));
    }
    ctx.regimes.push(integration_regime(
        "harmonic law, exact integration",
        &e.harmonic,
    ));
    ctx.domain_note = e.domain_note.clone().unwrap_or_default();
    fill_checks(&mut ctx, |k: wp::Key| c.get(k), &e.checks, &e.applicability);
    // Harmonic against each linear counterpart.
    let mut columns: Vec<(String, Option<Summary>)> = vec![("harmonic".into(), Some(e.harmonic))];
    for cp in [
        Counterpart::Extremes,
        Counterpart::Zeros,
        Counterpart::Tangent,
    ] {
        let q = WoodpeckerParams {
            counterpart: cp,
            ..*p
        };
        let linear = woodpecker::evaluate(&q, scene.periods)?.linear;
        columns.push((format!("linear, {cp:?}").to_lowercase(), linear));
    }
    let cols: Vec<(&str, Option<&Summary>)> = columns
        .iter()
        .map(|(n, s)| (n.as_str(), s.as_ref()))
        .collect();
    ctx.linearization = Some(Comparison {
        heading: LINEARIZATION.to_string(),
        table: laws_table(&cols, pp.period),
    });
    Ok(ctx)
}

/// Renders a woodpecker evaluation as plain-text tables.
pub(crate) fn text(e: &woodpecker::Evaluation) -> String {
    let p = &e.params;
    let i = &p.input;
    let c = &e.closed_form;
    let mut out = String::new();
    let _ = writeln!(out, "stickslip eval woodpecker");
    let _ = writeln!(
        out,
        "parameters: mu_s = {}, mu_d = {}, k = {} N/m, m_S = {} kg, m_W = {} kg, l = {} m, h = {} m, \
         z0 = {} m, d0 = {} m, g = {} m/s², periods = {}",
        // Parameters as given, but never the 300 digits `{}` writes for 1e300.
        pnum(i.mu_s), pnum(i.mu_d), pnum(i.k), pnum(i.m_sleeve), pnum(i.m_bird), pnum(i.l),
        pnum(i.h), pnum(i.z0), pnum(i.d0), pnum(i.g), p.periods
    );
    let _ = writeln!(
        out,
        "options:    lambda = {} ({}), omega = {}, counterpart = {}",
        short(Some(p.lambda), TEXT_DIGITS),
        if i.lever.is_some() { "given" } else { "l/h" },
        i.omega.id(),
        i.counterpart.id()
    );
    let _ = writeln!(
        out,
        "derived:    W_S = m_S g = {} N, omega = {} rad/s, T = {} s, zeta0 = {} m, delta0 = {} m",
        short(Some(p.sleeve_weight), TEXT_DIGITS),
        short(Some(p.omega), TEXT_DIGITS),
        short(Some(p.period), TEXT_DIGITS),
        short(p.zeta0, TEXT_DIGITS),
        short(p.delta0, TEXT_DIGITS)
    );
    let _ = writeln!(
        out,
        "\nregime (linearized law, guide §10): {} ({}); paper's standard regime valid: {}; immediate slip (38): {}",
        c.regime.words(),
        c.regime.id(),
        c.paper_regime_valid,
        c.immediate_slip
    );
    if let Some(note) = &e.domain_note {
        let _ = writeln!(out, "closed forms do not apply: {note}");
    }
    closed_form_table(&mut out, &LAW_WORDS, |k: wp::Key| c.get(k));
    if e.domain_note.is_none() {
        not_describing(&mut out, &e.applicability);
    }
    checks_table(&mut out, &LAW_WORDS, &e.checks);
    text_laws(
        &mut out,
        <WoodpeckerParams as Present>::LAWS,
        &[Some(&e.harmonic), e.linear.as_ref()],
        "its counterpart is undefined",
    );
    out
}
