//! The template context of a scene: every number already formatted, every formula already
//! rendered, so that the templates hold no computation (STYLE habit 7).

use crate::error::Result;
use crate::format::{people, people_rel, people_tolerance};
use crate::models::{with_capability, Model};
pub use crate::present::vocab::{
    ClaimCtx, Comparison, FigureCtx, LawWords, MotionLine, ParamRow, RegimeRow, SceneCtx, Table,
    VerificationRow,
};
use crate::present::vocab::{Phase, Scene};
use crate::present::Present;
use crate::report::math::mathml;
use crate::results::quantity::{Quantity, Registry};
use crate::results::{Applicability, Check, CheckValue, Checked, Summary};

/// Significant digits of the tables.
pub(crate) const DIGITS: usize = 8;

/// The numbers of a scene that do not depend on rendering: tables and regimes.
pub fn scene_tables(scene: &Scene) -> Result<SceneCtx> {
    /// The model's tables, with its sketch, the sketch's caption words and its law words.
    fn of<M: Present>(
        p: &M,
        scene: &Scene,
    ) -> Result<(SceneCtx, &'static str, &'static str, String, LawWords)> {
        let ctx = p.scene_tables(scene)?;
        Ok((
            ctx,
            M::SKETCH_WHAT,
            M::SKETCH_WHEN,
            p.sketch(Phase::Slipping),
            M::LAW_WORDS,
        ))
    }
    let (mut ctx, what, when, svg, words) = with_capability!(&scene.setup, present,
        p => of(p, scene)?,
        else return Err(scene.setup.missing(crate::models::Capability::Present)));
    ctx.words = words;
    ctx.sketch = FigureCtx {
        id: format!("{}-apparatus", scene.id),
        caption: format!(
            "The apparatus with this page's parameters, {what}; forces {when}, to scale."
        ),
        svg,
        file: format!("figures/{}-apparatus.svg", scene.id),
    };
    ctx.motion = motion_lines(&scene.setup);
    ctx.closed_regime = ctx
        .regimes
        .first()
        .map(|r| r.regime.clone())
        .unwrap_or_default();
    ctx.harmonic_regime = ctx
        .regimes
        .last()
        .map(|r| r.regime.clone())
        .unwrap_or_default();
    Ok(ctx)
}

/// A claim of the paper for the page.
pub fn claim(c: &crate::claims::Claim) -> ClaimCtx {
    let verdict_class = serde_json::to_value(c.verdict)
        .ok()
        .and_then(|v| v.as_str().map(str::to_string))
        .unwrap_or_default();
    let mut numbers: Vec<String> = c
        .numbers
        .iter()
        .map(|n| {
            let unit = if n.unit.is_empty() {
                String::new()
            } else {
                format!(" {}", n.unit)
            };
            format!("{} = {}{unit}", n.label, num(n.value))
        })
        .collect();
    if let Some(s) = &c.sample {
        numbers.push(format!(
            "random sample (seed {}): {} of {} sets contradict the statement ({:.1} %){}",
            s.seed,
            s.counterexamples,
            s.size,
            100.0 * s.share,
            s.example
                .as_ref()
                .map_or(String::new(), |e| format!("; e.g. {e}"))
        ));
    }
    ClaimCtx {
        id: c.id,
        title: c.title.clone(),
        paper_says: c.paper_says.clone(),
        verdict_class,
        verdict: c.verdict.words().to_string(),
        does_not_apply: c.does_not_apply.clone().unwrap_or_default(),
        finding: c.finding.clone(),
        numbers,
    }
}

pub(crate) fn num(x: f64) -> String {
    people(Some(x), DIGITS)
}

pub(crate) fn opt(x: Option<f64>) -> String {
    people(x, DIGITS)
}

/// The section of the physics guide that derives a formula the paper does not number, when
/// `equation` cites one ("guide §7.5"): its number and its anchor in guide.html (7.5,
/// late-stick); empty strings for the paper's equation numbers.
pub fn guide_link(equation: &str) -> (String, String) {
    super::guide::cite(equation).map_or_else(Default::default, |(section, anchor)| {
        (section.to_string(), anchor.to_string())
    })
}

/// A value in the unit people think in: lengths below 1 m in mm, masses below 1 kg in g.
fn human_unit(value: f64, unit: &str) -> (f64, &str) {
    match unit {
        "m" if value != 0.0 && value.abs() < 1.0 => (value * 1e3, "mm"),
        "kg" if value != 0.0 && value.abs() < 1.0 => (value * 1e3, "g"),
        _ => (value, unit),
    }
}

/// A derived value, to the table's significant digits, in the unit people think in.
pub(crate) fn row(name: &str, value: f64, unit: &str) -> ParamRow {
    let (value, unit) = human_unit(value, unit);
    ParamRow {
        name: name.to_string(),
        value: num(value),
        unit: unit.to_string(),
    }
}

/// An input value as given (to 12 significant figures, which undoes the rounding of a change
/// of unit), in the unit people think in.
pub(crate) fn input(name: &str, value: f64, unit: &str) -> ParamRow {
    let (value, unit) = human_unit(value, unit);
    ParamRow {
        name: name.to_string(),
        value: people(Some(value), 12),
        unit: unit.to_string(),
    }
}

/// A count (periods, points).
pub(crate) fn count(name: &str, n: u32) -> ParamRow {
    ParamRow {
        name: name.to_string(),
        value: n.to_string(),
        unit: String::new(),
    }
}

/// The equation of motion of the scene's model, line by line.
pub fn equation_of_motion(setup: &Model) -> &'static [(&'static str, &'static str)] {
    fn lines<M: Present>(_: &M) -> &'static [(&'static str, &'static str)] {
        M::equation_of_motion()
    }
    // A model without a presentation has no equation of motion to show (nor a handout).
    with_capability!(setup, present, p => lines(p), else &[])
}

/// The equation of motion of `setup`'s model, each line in MathML and LaTeX with its physics.
pub fn motion_lines(setup: &Model) -> Vec<MotionLine> {
    equation_of_motion(setup)
        .iter()
        .map(|(tex, note)| MotionLine {
            mathml: mathml(tex),
            tex: tex.to_string(),
            note: note.to_string(),
        })
        .collect()
}

pub(crate) fn blank(scene: &Scene, model: &str) -> SceneCtx {
    SceneCtx {
        id: scene.id.clone(),
        title: scene.title.clone(),
        model: model.to_string(),
        part: scene.part.heading(),
        why: scene.why.clone(),
        sketch: FigureCtx {
            id: String::new(),
            caption: String::new(),
            svg: String::new(),
            file: String::new(),
        },
        motion: Vec::new(),
        caption: scene.caption.clone(),
        description: scene.description.clone(),
        params: Vec::new(),
        regimes: Vec::new(),
        verification: Vec::new(),
        checks_passed: 0,
        checks_total: 0,
        all_pass: true,
        figures: Vec::new(),
        words: LawWords {
            closed_form_law: "",
            checked_against: "",
            numeric_from: "",
        },
        linearization: None,
        claims: Vec::new(),
        domain_note: String::new(),
        closed_regime: String::new(),
        harmonic_regime: String::new(),
    }
}

pub(crate) fn integration_regime(law: &str, s: &Summary) -> RegimeRow {
    let plural = |n: u32, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
    let slips = format!(
        "{} and {} in the last period, period multiplicity {}",
        plural(s.slips_per_period, "slip", "slips"),
        plural(s.sticks_per_period, "stick", "sticks"),
        s.period_multiplicity
            .map_or("—".to_string(), |n| n.to_string())
    );
    let why = if s.immediate_slip {
        format!("slips at t = 0 (|D| > μs N_f at t = 0); {slips}")
    } else {
        slips
    };
    RegimeRow {
        law: law.to_string(),
        regime: s.regime.words().to_string(),
        why,
    }
}

/// The verification rows: every closed form of model `K` with its check (or why it has none),
/// then the checks of quantities outside the table (orbit, regime).
pub(crate) fn fill_checks<K: Registry>(
    ctx: &mut SceneCtx,
    get: impl Fn(K) -> Option<f64>,
    checks: &[Check],
    applicability: &[Applicability],
) {
    let mut rows = Vec::new();
    for e in K::numbers() {
        let q = &e.quantity;
        let closed = get(e.key);
        let check = checks
            .iter()
            .find(|c| c.quantity == Checked::Key(e.key.into()));
        let note = applicability
            .iter()
            .find(|a| a.quantity == e.key.into() && !a.applies)
            .map(|a| a.reason.clone());
        rows.push(match (check, note) {
            (Some(c), _) => check_row(q, c),
            (None, Some(note)) => plain_row(q, closed, "n/a", "na", note),
            (None, None) => {
                let note = match e.key.time() {
                    Some(t) if checks.iter().any(|c| c.quantity == Checked::Key(t.into())) => {
                        "checked as t = T·τ (row below)"
                    }
                    _ => "no direct counterpart in the integration",
                };
                plain_row(q, closed, "—", "none", note.to_string())
            }
        });
    }
    for c in checks
        .iter()
        .filter(|c| !K::numbers().any(|e| c.quantity == Checked::Key(e.key.into())))
    {
        let q = c.quantity.quantity().copied().unwrap_or(Quantity {
            id: "",
            symbol: "",
            tex: "",
            unit: "",
            equation: "guide §8.6",
            tag: "[D]",
            latex: "",
            words: "",
        });
        let mut r = check_row(&q, c);
        if r.symbol.is_empty() {
            r.symbol = c.quantity.id().replace('_', " ");
        }
        rows.push(r);
    }
    // A check the run cannot show counts neither way; its row says why.
    ctx.checks_total = checks.iter().filter(|c| c.pass.is_some()).count();
    ctx.checks_passed = checks.iter().filter(|c| c.passed()).count();
    ctx.all_pass = ctx.checks_passed == ctx.checks_total;
    ctx.verification = rows;
}

/// A checked value for people: a number formatted, a regime id in words.
fn value(v: &CheckValue) -> String {
    match v {
        CheckValue::Number(x) => num(*x),
        CheckValue::Text(s) => regime_words(s).to_string(),
    }
}

pub use crate::models::regime_words;

fn check_row(q: &Quantity, c: &Check) -> VerificationRow {
    VerificationRow {
        symbol: q.symbol.to_string(),
        formula_mathml: if q.latex.is_empty() {
            String::new()
        } else {
            mathml(q.latex)
        },
        formula_tex: q.latex.to_string(),
        equation: c.equation.to_string(),
        guide: guide_link(c.equation).1,
        section: guide_link(c.equation).0,
        tag: q.tag.to_string(),
        closed_form: value(&c.closed_form),
        numeric: value(&c.numeric),
        unit: q.unit.to_string(),
        rel_error: people_rel(c.rel_error),
        tolerance: people_tolerance(c.tolerance),
        verdict: c.verdict().to_string(),
        class: match c.pass {
            Some(true) => "pass",
            Some(false) => "fail",
            None => "na",
        }
        .to_string(),
        note: c.note.clone().unwrap_or_default(),
    }
}

fn plain_row(
    q: &Quantity,
    closed: Option<f64>,
    verdict: &str,
    class: &str,
    note: String,
) -> VerificationRow {
    VerificationRow {
        symbol: q.symbol.to_string(),
        formula_mathml: mathml(q.latex),
        formula_tex: q.latex.to_string(),
        equation: q.equation.to_string(),
        guide: guide_link(q.equation).1,
        section: guide_link(q.equation).0,
        tag: q.tag.to_string(),
        closed_form: opt(closed),
        numeric: "—".to_string(),
        unit: q.unit.to_string(),
        rel_error: "—".to_string(),
        tolerance: "—".to_string(),
        verdict: verdict.to_string(),
        class: class.to_string(),
        note,
    }
}

/// The model's laws side by side: regime, first slip, steady slip/stick times (mod T), v̄, power.
pub(crate) fn laws_table(columns: &[(&str, Option<&Summary>)], period: f64) -> Table {
    let mut header = vec!["quantity".to_string()];
    header.extend(columns.iter().map(|(n, _)| n.to_string()));
    let cell = |f: &dyn Fn(&Summary) -> String| -> Vec<String> {
        columns
            .iter()
            .map(|(_, s)| s.map_or("— (undefined)".to_string(), f))
            .collect()
    };
    let events = |kind: &'static str| {
        move |s: &Summary| {
            let times: Vec<String> = s
                .steady_events
                .iter()
                .filter(|e| e.kind == kind)
                .map(|e| num(e.phase * period))
                .collect();
            if times.is_empty() {
                "—".to_string()
            } else {
                times.join(", ")
            }
        }
    };
    let mut rows = Vec::new();
    let mut push = |name: &str, values: Vec<String>| {
        let mut r = vec![name.to_string()];
        r.extend(values);
        rows.push(r);
    };
    push("regime", cell(&|s| s.regime.words().to_string()));
    push("first slip (s)", cell(&|s| opt(s.first_slip_time)));
    push(
        "slips / sticks per period",
        cell(&|s| format!("{} / {}", s.slips_per_period, s.sticks_per_period)),
    );
    push("steady slip times, t mod T (s)", cell(&events("slip")));
    push("steady stick times, t mod T (s)", cell(&events("stick")));
    push(
        "speed maxima (mm/s)",
        cell(&|s| {
            let v: Vec<String> = s
                .steady_speed_maxima
                .iter()
                .map(|m| num(1e3 * m.v))
                .collect();
            if v.is_empty() {
                "—".to_string()
            } else {
                v.join(", ")
            }
        }),
    );
    push(
        "mean speed v̄ (mm/s)",
        cell(&|s| opt(s.v_avg.map(|v| 1e3 * v))),
    );
    push("friction dissipation (W)", cell(&|s| opt(s.power.friction)));
    Table { header, rows }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Tables for people name regimes in words (the ids stay in JSON and CSV).
    #[test]
    fn every_regime_id_has_words() {
        use crate::engine::IntegrationRegime;
        use crate::models::pulled_mass::formula::Regime;
        use crate::models::woodpecker::formula::OrbitRegime;
        let ids = Regime::ALL
            .iter()
            .map(|r| r.id())
            .chain(IntegrationRegime::ALL.iter().map(|r| r.id()))
            .chain(OrbitRegime::ALL.iter().map(|r| r.id()));
        for id in ids {
            let words = regime_words(id);
            assert!(words.contains(' ') && !words.contains('_'), "{id}: {words}");
        }
        assert_eq!(regime_words("t_slip"), "t_slip");
    }

    /// A formula the paper does not number links to the section of the guide that derives it.
    #[test]
    fn an_unnumbered_equation_links_to_its_section_of_the_guide() {
        assert_eq!(
            guide_link("guide §7.5"),
            ("7.5".to_string(), "late-stick".to_string())
        );
        assert_eq!(guide_link("(13),(25)"), Default::default());
    }
}
