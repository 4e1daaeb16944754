//! The terminal output of `stickslip eval`: parameters, closed forms, checks, and the two laws
//! side by side.

use std::fmt::Write;

use super::format::{rel, short};
use crate::models::regime_words;
use crate::results::quantity::Registry;
use crate::results::{Applicability, Check, CheckValue, Summary};

pub(crate) const DIGITS: usize = 10;

/// The numbers of the closed forms of model `K` with their symbols, units and equations.
pub(crate) fn closed_form_table<K: Registry>(out: &mut String, get: impl Fn(K) -> Option<f64>) {
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
            short(v, DIGITS),
            q.unit,
            q.equation,
            q.tag
        );
    }
}

/// The closed forms that do not describe this motion, each with why (the report greys them).
pub(crate) fn not_describing(out: &mut String, applicability: &[Applicability]) {
    let not_applying: Vec<_> = applicability.iter().filter(|a| !a.applies).collect();
    if !not_applying.is_empty() {
        let _ = writeln!(out, "\nformulas that do not describe this motion");
        for a in not_applying {
            let symbol = a.quantity.quantity().symbol;
            let _ = writeln!(out, "  {symbol:<14} {}", a.reason);
        }
    }
}

pub(crate) fn checks_table(out: &mut String, checks: &[Check]) {
    let passed = checks.iter().filter(|c| c.passed()).count();
    let observable = checks.iter().filter(|c| c.pass.is_some()).count();
    let unobservable = match checks.len() - observable {
        0 => String::new(),
        n => format!(", {n} not observable"),
    };
    let _ = writeln!(
        out,
        "\nchecks: closed form vs exact integration of the linearized law ({passed}/{observable} pass{unobservable}, tolerance {:.0e})",
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
        if let (CheckValue::Text(closed), CheckValue::Text(numeric)) = (&c.closed_form, &c.numeric)
        {
            // Words do not fit the number columns: one line, both sides named when they differ.
            let words = if closed == numeric {
                format!("{} (both)", regime_words(closed))
            } else {
                format!(
                    "closed form: {}; integration: {}",
                    regime_words(closed),
                    regime_words(numeric)
                )
            };
            let _ = writeln!(
                out,
                "  {:<24} {:<18} {words}  {}",
                symbol,
                c.equation,
                c.verdict()
            );
        } else {
            let _ = writeln!(
                out,
                "  {:<24} {:<18} {:>18} {:>18} {:>9}  {}",
                symbol,
                c.equation,
                value(&c.closed_form),
                value(&c.numeric),
                rel(c.rel_error),
                c.verdict()
            );
        }
        if let Some(note) = &c.note {
            let _ = writeln!(out, "  {:<24} ({note})", "");
        }
    }
}

fn value(v: &CheckValue) -> String {
    match v {
        CheckValue::Number(x) => short(Some(*x), DIGITS),
        CheckValue::Text(s) => regime_words(s).to_string(),
    }
}

pub(crate) fn laws_table(out: &mut String, harmonic: &Summary, linear: Option<&Summary>) {
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
    // The regimes in words, one line each (too long for the table's columns).
    let _ = writeln!(
        out,
        "  regime, harmonic:   {}",
        regime_words(harmonic.regime.id())
    );
    if !harmonic_only {
        let _ = writeln!(
            out,
            "  regime, linear:     {}",
            regime_words(linear.regime.id())
        );
    }
    row(out, "", "harmonic".into(), "linear".into());
    let s = |x: Option<f64>| short(x, DIGITS);
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
            .map(|e| format!("{} at phase {}", e.kind, short(Some(e.phase), 8)))
            .chain(law.steady_speed_maxima.iter().map(|m| {
                format!(
                    "v max {} m/s at phase {}",
                    short(Some(m.v), 8),
                    short(Some(m.phase), 8)
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
        if let Some(why) = &c.does_not_apply {
            let _ = writeln!(out, "  why:       {why}");
        }
        let _ = writeln!(out, "  finding:   {}", c.finding);
        for n in &ctx.numbers {
            let _ = writeln!(out, "    {n}");
        }
        let _ = writeln!(out);
    }
    out
}
