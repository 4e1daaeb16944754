//! The terminal output of `stickslip eval`: parameters, closed forms, checks, and the model's
//! laws side by side, each named by the model.

use std::fmt::Write;

use crate::format::{rel, short};
use crate::models::regime_words;
use crate::present::vocab::{LawName, LawWords};
use crate::results::quantity::Registry;
use crate::results::{Applicability, Check, CheckValue, Summary};

pub(crate) const DIGITS: usize = 10;

/// The numbers of the closed forms of model `K` with their symbols, units and equations.
pub(crate) fn closed_form_table<K: Registry>(
    out: &mut String,
    words: &LawWords,
    get: impl Fn(K) -> Option<f64>,
) {
    let _ = writeln!(out, "\nclosed forms ({})", words.closed_form_law);
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

pub(crate) fn checks_table(out: &mut String, words: &LawWords, checks: &[Check]) {
    let passed = checks.iter().filter(|c| c.passed()).count();
    let observable = checks.iter().filter(|c| c.pass.is_some()).count();
    let unobservable = match checks.len() - observable {
        0 => String::new(),
        n => format!(", {n} not observable"),
    };
    let _ = writeln!(
        out,
        "\nchecks: closed form vs {} ({passed}/{observable} pass{unobservable}, tolerance {:.0e})",
        words.checked_against,
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

/// The exact integrations of a model's `laws` side by side, one column per law that exists
/// for the parameters (`runs` in the order of `laws`; a `None` run is named with `missing`,
/// why it does not exist).
pub(crate) fn laws_table(
    out: &mut String,
    laws: &[LawName],
    runs: &[Option<&Summary>],
    missing: &str,
) {
    let names: Vec<&str> = laws.iter().map(|l| l.name).collect();
    let _ = writeln!(out, "\nexact integration: {}", names.join(" vs "));
    let mut columns: Vec<(&str, &Summary)> = Vec::with_capacity(laws.len());
    for (law, run) in laws.iter().zip(runs) {
        match run {
            Some(s) => columns.push((law.id, s)),
            None => {
                let _ = writeln!(out, "  (no {} law: {missing})", law.id);
            }
        }
    }
    let row = |out: &mut String, name: &str, values: Vec<String>| {
        let mut line = format!("  {name:<26}");
        for v in values {
            let _ = write!(line, " {v:>22}");
        }
        let _ = writeln!(out, "{line}");
    };
    let each = |f: &dyn Fn(&Summary) -> String| columns.iter().map(|(_, s)| f(s)).collect();
    // The regimes in words, one line each (too long for the table's columns).
    for (id, law) in &columns {
        let label = format!("regime, {id}:");
        let _ = writeln!(out, "  {label:<20}{}", regime_words(law.regime.id()));
    }
    row(
        out,
        "",
        columns.iter().map(|(id, _)| id.to_string()).collect(),
    );
    let s = |x: Option<f64>| short(x, DIGITS);
    row(
        out,
        "immediate slip",
        each(&|l| l.immediate_slip.to_string()),
    );
    row(out, "first slip (s)", each(&|l| s(l.first_slip_time)));
    let mult = |x: &Summary| x.period_multiplicity.map_or("—".into(), |n| n.to_string());
    row(out, "period multiplicity", each(&mult));
    row(
        out,
        "slips / sticks per period",
        each(&|l| format!("{} / {}", l.slips_per_period, l.sticks_per_period)),
    );
    row(
        out,
        "advance per period (m)",
        each(&|l| s(l.advance_per_period)),
    );
    row(out, "mean speed v̄ (m/s)", each(&|l| s(l.v_avg)));
    let powers: Vec<_> = columns.iter().map(|(_, l)| power_rows(l)).collect();
    for (i, (name, _)) in powers
        .first()
        .cloned()
        .unwrap_or_default()
        .iter()
        .enumerate()
    {
        row(out, name, powers.iter().map(|p| s(p[i].1)).collect());
    }
    for &(name, law) in &columns {
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
