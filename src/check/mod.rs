//! `stickslip check`: a formula of the user's (a textbook variant, a student's derivation, the
//! paper's formula with a suspected misprint) put against the exact integration of the
//! linearized law, at the given parameters and on a seeded sample of the regimes where the
//! quantity is measured.
//!
//! ```text
//! formula (plain or LaTeX) → latex.rs → exmex expression over the case's symbols
//! case → symbols (parameters, derived symbols of the worked steps) → formula value
//!      → checks of the exact integration → the measured quantity → relative error
//! ```

pub mod latex;
mod render;

pub use render::{render, text};

use exmex::prelude::*;
use rayon::prelude::*;
use serde::Serialize;

use crate::draws::Draws;
use crate::error::{excerpt, Error, Result};
use crate::models::{with_model, Model, Physics};
use crate::params::DEFAULT_PERIODS;
use crate::results::{rel_diff, CheckValue, Checked};
use crate::worksheet::exercise::Exercise;
use crate::worksheet::question::{self, Regime};
use crate::worksheet::sample;

/// Default sample size.
pub const DEFAULT_SAMPLES: usize = 1000;
/// Largest sample.
pub const MAX_SAMPLES: usize = 100_000;
/// Sets per regime of the pilot that finds where the quantity is measured.
const PILOT: usize = 8;
/// Worst cases listed.
const WORST: usize = 5;

/// What to check.
#[derive(Clone, Debug)]
pub struct Request {
    /// The model with the given parameters.
    pub case: Model,
    /// The formula as typed.
    pub formula: String,
    /// The §7 key of the measured quantity (`v_avg`, `t_stick` …).
    pub quantity: String,
    pub samples: usize,
    pub seed: u64,
}

/// The formula and the integration on one parameter set.
#[derive(Clone, Debug, Serialize)]
pub struct Sample {
    /// The parameters (§7 `params` keys, SI).
    pub params: Model,
    /// The regime of the closed forms.
    pub regime: &'static str,
    /// The formula's value; `None` where it is undefined (a zero denominator, a negative root).
    pub formula: Option<f64>,
    /// The exact integration's value; `None` where the run does not measure the quantity.
    pub numeric: Option<f64>,
    pub rel_error: Option<f64>,
    /// The tolerance of the tool's own check of this quantity on this set.
    pub tolerance: f64,
    pub agrees: Option<bool>,
}

/// Agreement in one regime.
#[derive(Clone, Debug, Serialize)]
pub struct RegimeRow {
    pub regime: &'static str,
    pub compared: usize,
    pub disagree: usize,
    pub max_rel_error: Option<f64>,
}

/// The outcome of `stickslip check`, serialised as its JSON.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    pub model: &'static str,
    pub quantity: String,
    /// The quantity's symbol and words, for the page.
    #[serde(skip)]
    pub named: Named,
    pub formula: String,
    /// The formula in the evaluator's syntax.
    pub expression: String,
    pub seed: u64,
    /// At the given parameters.
    pub given: Sample,
    /// Sets drawn; of them, compared (formula defined and quantity measured), where the formula
    /// is undefined, and where the integration does not measure the quantity.
    pub samples: usize,
    pub compared: usize,
    pub undefined: usize,
    pub not_measured: usize,
    pub disagree: usize,
    pub max_rel_error: Option<f64>,
    pub median_rel_error: Option<f64>,
    /// `true` when every compared set agrees within its tolerance (and some were compared).
    pub agrees: bool,
    /// The sets where the formula is worst, worst first.
    pub worst: Vec<Sample>,
    pub by_regime: Vec<RegimeRow>,
    /// Regimes of the model where a pilot of a few sets never measured the quantity: not
    /// sampled.
    pub unmeasured_regimes: Vec<&'static str>,
}

/// The symbols of `case` by name, with their values: the parameters (by symbol, `m`), then
/// every derived symbol of its worked steps (`phi`, `T`, `Gamma`, `tau_SL` …, NaN where its
/// formula is undefined), then the parameters by key (`mass`); `PI` is the evaluator's.
pub fn symbols(case: &Model) -> Vec<(String, f64)> {
    fn params<M: Physics>(p: &M) -> Vec<(String, f64, String)> {
        M::PARAMS
            .iter()
            .filter_map(|s| Some((latex::identifier(s.tex), (s.get)(p)?, s.key.to_string())))
            .collect()
    }
    let given = with_model!(case, p => params(p));
    let mut out: Vec<(String, f64)> = given.iter().map(|(n, v, _)| (n.clone(), *v)).collect();
    for step in crate::worksheet::answer::steps(case) {
        // A derived symbol is its formula: defined also where the closed form does not describe
        // the motion (τ_ST > 1 past the period); NaN where it is not (a formula using it is then
        // undefined on that set, and counted so).
        // A symbol, not an expression (the slip duration is written `t_{ST} - t_{SL}`, the
        // boundary `1/\Theta`); `\bar v` is one symbol.
        let plain = step.symbol.replace("\\bar ", "");
        if plain.contains(' ') || plain.contains('/') {
            continue;
        }
        let v = step.value.unwrap_or_else(|| step.expr.eval());
        let v = if v.is_finite() { v } else { f64::NAN };
        let name = latex::identifier(step.symbol);
        if name == "varphi" {
            out.push(("phi".to_string(), v));
        }
        out.push((name, v));
    }
    // The parameters' keys (`mass`, `force`) as well, last.
    out.extend(given.into_iter().map(|(_, v, key)| (key, v)));
    let mut seen = std::collections::HashSet::new();
    out.retain(|(name, _)| {
        name.starts_with(|c: char| c.is_ascii_alphabetic()) && seen.insert(name.clone())
    });
    out
}

/// The symbols of `case` one per line with their values (`--symbols`).
pub fn symbols_text(case: &Model) -> String {
    let mut o = format!(
        "symbols of the {} for a formula (value at the given parameters, SI; PI and E are the \
         constants):\n",
        case.id()
    );
    for (name, value) in symbols(case) {
        let shown = if value.is_finite() {
            crate::output::format::people(Some(value), 6)
        } else {
            "undefined here".to_string()
        };
        o.push_str(&format!("  {name:<14} {shown}\n"));
    }
    o
}

/// A comparison between two expressions: a condition, 1 where it holds and 0 where not.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Comparison {
    Le,
    Ge,
    Lt,
    Gt,
}

impl Comparison {
    /// Spellings, longest first.
    const SPELLINGS: [(&'static str, Comparison); 10] = [
        ("\\leq", Comparison::Le),
        ("\\geq", Comparison::Ge),
        ("\\le", Comparison::Le),
        ("\\ge", Comparison::Ge),
        ("<=", Comparison::Le),
        (">=", Comparison::Ge),
        ("≤", Comparison::Le),
        ("≥", Comparison::Ge),
        ("<", Comparison::Lt),
        (">", Comparison::Gt),
    ];

    fn holds(self, a: f64, b: f64) -> bool {
        match self {
            Comparison::Le => a <= b,
            Comparison::Ge => a >= b,
            Comparison::Lt => a < b,
            Comparison::Gt => a > b,
        }
    }

    fn plain(self) -> &'static str {
        match self {
            Comparison::Le => "<=",
            Comparison::Ge => ">=",
            Comparison::Lt => "<",
            Comparison::Gt => ">",
        }
    }
}

/// The formula, parsed: an expression, or a condition `lhs op rhs`.
struct Formula {
    expression: String,
    expr: FlatEx<f64>,
    condition: Option<(Comparison, FlatEx<f64>)>,
}

impl Formula {
    fn parse(text: &str, known: &[(String, f64)]) -> Result<Self> {
        let formula_error = |reason: String| Error::Formula {
            formula: excerpt(text, 80),
            reason,
        };
        let split = Comparison::SPELLINGS.iter().find_map(|(spelling, c)| {
            // `\le` but not `\left`: a command ends where its letters do.
            text.match_indices(spelling).find_map(|(at, _)| {
                let rest = &text[at + spelling.len()..];
                let whole = !spelling.starts_with('\\')
                    || !rest.starts_with(|ch: char| ch.is_ascii_alphabetic());
                whole.then(|| (&text[..at], *c, rest))
            })
        });
        let (lhs, condition) = match split {
            Some((a, c, b)) => (a, Some((c, b))),
            None => (text, None),
        };
        let side = |text: &str| -> Result<(String, FlatEx<f64>)> {
            let expression = latex::to_plain(text)?;
            let expr = exmex::parse::<f64>(&expression)
                .map_err(|e| formula_error(format!("cannot be read: {e}")))?;
            let unknown: Vec<&str> = expr
                .var_names()
                .iter()
                .map(String::as_str)
                .filter(|v| !known.iter().any(|(k, _)| k == v))
                .collect();
            if !unknown.is_empty() {
                // In the order of `symbols`: the parameters first, then the derived symbols
                // as a derivation reaches them; `--symbols` lists them all.
                let names: Vec<&str> = known.iter().map(|(k, _)| k.as_str()).collect();
                return Err(formula_error(format!(
                    "unknown symbol {} (all with --symbols); known: {}",
                    unknown.join(", "),
                    names.join(", ")
                )));
            }
            Ok((expression, expr))
        };
        let (mut expression, expr) = side(lhs)?;
        let condition = match condition {
            Some((c, rhs)) => {
                let (rhs_expression, rhs) = side(rhs)?;
                expression = format!("{expression} {} {rhs_expression}", c.plain());
                Some((c, rhs))
            }
            None => None,
        };
        Ok(Self {
            expression,
            expr,
            condition,
        })
    }

    /// The value on `case` (a condition: 1 where it holds, 0 where not); `None` where it is not
    /// a finite number.
    fn value(&self, case: &Model) -> Option<f64> {
        let symbols = symbols(case);
        let eval = |expr: &FlatEx<f64>| -> Option<f64> {
            let values: Option<Vec<f64>> = expr
                .var_names()
                .iter()
                .map(|v| symbols.iter().find(|(k, _)| k == v).map(|s| s.1))
                .collect();
            expr.eval(&values?).ok().filter(|v| v.is_finite())
        };
        let lhs = eval(&self.expr)?;
        match &self.condition {
            None => Some(lhs),
            Some((c, rhs)) => Some(f64::from(u8::from(c.holds(lhs, eval(rhs)?)))),
        }
    }
}

/// The measured quantity that is a condition: whether the periodic motion has a stick (or
/// never slips), from the regime of the exact integration.
pub const STICKS: &str = "sticks";

/// The measured value of `quantity` on `case` and its check's tolerance, if the run measures
/// it; [`STICKS`] is 1 or 0, compared exactly.
fn measured(case: &Model, quantity: &str) -> Result<(Option<f64>, f64)> {
    let (checks, _) = with_model!(case, p => p.checks_and_linear_run(DEFAULT_PERIODS, false)?);
    if quantity == STICKS {
        let sticks = checks
            .iter()
            .find(|c| c.quantity.id() == "regime")
            .and_then(|c| match &c.numeric {
                CheckValue::Text(regime) => Some(!regime.contains("continuous")),
                CheckValue::Number(_) => None,
            });
        return Ok((sticks.map(|s| f64::from(u8::from(s))), 0.0));
    }
    Ok(checks
        .iter()
        .find(|c| c.quantity.id() == quantity && c.pass.is_some())
        .and_then(|c| match c.numeric {
            CheckValue::Number(x) => Some((Some(x), c.tolerance)),
            CheckValue::Text(_) => None,
        })
        .unwrap_or((None, crate::results::TOLERANCE)))
}

/// How a quantity is written: its LaTeX symbol and its words.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Named {
    pub id: String,
    pub tex: String,
    pub words: String,
}

/// The measurable quantities of the checks on `case`.
fn measurable(case: &Model) -> Result<Vec<Named>> {
    let (checks, _) = with_model!(case, p => p.checks_and_linear_run(DEFAULT_PERIODS, false)?);
    Ok(checks
        .iter()
        .filter(|c| matches!(c.numeric, CheckValue::Number(_)))
        .map(|c| match c.quantity {
            Checked::Key(k) => Named {
                id: k.id().to_string(),
                tex: k.quantity().tex.to_string(),
                words: k.quantity().words.to_string(),
            },
            other => Named {
                id: other.id().into_owned(),
                ..Named::default()
            },
        })
        .collect())
}

fn sample(formula: &Formula, case: Model, quantity: &str) -> Result<Sample> {
    let value = formula.value(&case);
    let (numeric, tolerance) = measured(&case, quantity)?;
    let rel_error = value.zip(numeric).map(|(a, b)| rel_diff(a, b));
    Ok(Sample {
        params: case,
        regime: case.closed_form_regime(),
        formula: value,
        numeric,
        rel_error,
        tolerance,
        agrees: rel_error.map(|e| e <= tolerance),
    })
}

/// The (formula, quantity) pairs of a `--formulas` file: `[[check]]` tables with the keys
/// `formula` and `quantity`.
pub fn read_formulas(path: &std::path::Path) -> Result<Vec<(String, String)>> {
    #[derive(serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    struct File {
        check: Vec<Entry>,
    }
    #[derive(serde::Deserialize)]
    #[serde(deny_unknown_fields)]
    struct Entry {
        formula: String,
        quantity: String,
    }
    let scenario_error = |reason: String| Error::Scenario {
        path: path.display().to_string(),
        reason,
    };
    let text = crate::params::read_input_text(path, "--formulas").map_err(scenario_error)?;
    let file: File = toml::from_str(&text).map_err(|e| scenario_error(e.message().to_string()))?;
    if file.check.is_empty() {
        return Err(scenario_error("no [[check]] table".to_string()));
    }
    Ok(file
        .check
        .into_iter()
        .map(|e| (e.formula, e.quantity))
        .collect())
}

/// Runs the check: the given parameters, then `samples` seeded sets drawn in turn from every
/// regime a worksheet of the model can ask for (in parallel).
pub fn run(req: &Request) -> Result<Report> {
    if !(1..=MAX_SAMPLES).contains(&req.samples) {
        return Err(crate::models::param::invalid(
            "samples",
            req.samples,
            format!("1 <= samples <= {MAX_SAMPLES}"),
        ));
    }
    req.case.validate()?;
    let formula = Formula::parse(&req.formula, &symbols(&req.case))?;
    let regimes = question::regimes(req.case);
    let mut rng = Draws::new(req.seed);
    // A pilot of a few sets per regime: which quantities the runs measure, and where.
    let pilot: Vec<(Regime, Model)> = regimes
        .iter()
        .flat_map(|&r| std::iter::repeat_n(r, PILOT))
        .map(|r| (r, sample::draw(req.case, r, &mut rng)))
        .collect();
    let mut names = measurable(&req.case)?;
    names.push(Named {
        id: STICKS.to_string(),
        tex: r"\text{sticks}".to_string(),
        words: "whether the motion has a stick (a condition: 1 or 0)".to_string(),
    });
    let mut measured_in: Vec<Regime> = Vec::new();
    for (regime, case) in &pilot {
        let here = measurable(case)?;
        let measured = req.quantity == STICKS || here.iter().any(|n| n.id == req.quantity);
        if measured && !measured_in.contains(regime) {
            measured_in.push(*regime);
        }
        names.extend(here);
    }
    let Some(named) = names.iter().find(|n| n.id == req.quantity).cloned() else {
        let mut ids: Vec<String> = names.into_iter().map(|n| n.id).collect();
        ids.sort();
        ids.dedup();
        return Err(Error::InvalidChoice {
            flag: "--quantity",
            value: req.quantity.clone(),
            valid: ids.join(", "),
        });
    };
    // The sample: in turn from the regimes where the quantity is measured.
    let kept: Vec<Regime> = regimes
        .iter()
        .copied()
        .filter(|r| measured_in.contains(r))
        .collect();
    let unmeasured: Vec<&'static str> = regimes
        .iter()
        .filter(|r| !kept.contains(r))
        .map(|r| r.id())
        .collect();
    let cases: Vec<Model> = (0..req.samples)
        .map(|i| sample::draw(req.case, kept[i % kept.len()], &mut rng))
        .collect();
    let given = sample(&formula, req.case, &req.quantity)?;
    let samples = cases
        .into_par_iter()
        .map(|case| sample(&formula, case, &req.quantity))
        .collect::<Result<Vec<_>>>()?;
    let mut report = summarise(req, formula.expression, named, given, samples);
    report.unmeasured_regimes = unmeasured;
    Ok(report)
}

fn summarise(
    req: &Request,
    expression: String,
    named: Named,
    given: Sample,
    samples: Vec<Sample>,
) -> Report {
    let n = samples.len();
    let undefined = samples.iter().filter(|s| s.formula.is_none()).count();
    let not_measured = samples
        .iter()
        .filter(|s| s.formula.is_some() && s.numeric.is_none())
        .count();
    let mut compared: Vec<&Sample> = samples.iter().filter(|s| s.rel_error.is_some()).collect();
    compared.sort_by(|a, b| {
        b.rel_error
            .unwrap_or(0.0)
            .total_cmp(&a.rel_error.unwrap_or(0.0))
    });
    let errors: Vec<f64> = compared.iter().filter_map(|s| s.rel_error).collect();
    let disagree = compared.iter().filter(|s| s.agrees == Some(false)).count();
    let median = (!errors.is_empty()).then(|| {
        let mut e = errors.clone();
        e.sort_by(f64::total_cmp);
        e[e.len() / 2]
    });
    let mut by_regime: Vec<RegimeRow> = Vec::new();
    for s in &samples {
        let row = match by_regime.iter_mut().find(|r| r.regime == s.regime) {
            Some(row) => row,
            None => {
                by_regime.push(RegimeRow {
                    regime: s.regime,
                    compared: 0,
                    disagree: 0,
                    max_rel_error: None,
                });
                by_regime.last_mut().expect("just pushed")
            }
        };
        if let Some(e) = s.rel_error {
            row.compared += 1;
            row.disagree += usize::from(s.agrees == Some(false));
            row.max_rel_error = Some(row.max_rel_error.map_or(e, |m: f64| m.max(e)));
        }
    }
    let worst = compared.iter().take(WORST).map(|s| (*s).clone()).collect();
    Report {
        model: req.case.id(),
        quantity: req.quantity.clone(),
        named,
        formula: req.formula.clone(),
        expression,
        seed: req.seed,
        given,
        samples: n,
        compared: errors.len(),
        undefined,
        not_measured,
        disagree,
        max_rel_error: errors.first().copied(),
        median_rel_error: median,
        agrees: !errors.is_empty() && disagree == 0,
        worst,
        by_regime,
        unmeasured_regimes: Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::models::pulled_mass::PulledMassParams;

    fn check(formula: &str, quantity: &str) -> Report {
        run(&Request {
            case: Model::PulledMass(PulledMassParams::default()),
            formula: formula.to_string(),
            quantity: quantity.to_string(),
            samples: 200,
            seed: 1,
        })
        .unwrap()
    }

    /// The paper's Γ with coefficient 1 agrees; with 2 it does not.
    #[test]
    fn gamma_with_coefficient_one_passes_and_with_two_fails() {
        let right = check("g*T*phi^3*Gamma", "v_avg");
        assert!(right.agrees, "{}", text(&right));
        assert!(right.compared > 50 && right.max_rel_error.unwrap() < 1e-9);
        let wrong = check(r"2 g T \varphi^3 \Gamma", "v_avg");
        assert!(
            !wrong.agrees && wrong.disagree == wrong.compared,
            "{}",
            text(&wrong)
        );
        assert!((wrong.max_rel_error.unwrap() - 0.5).abs() < 1e-9);
    }

    /// Eq. (20), φ ≤ 1/Θ, read as the condition to stick at all: it fails exactly in the
    /// late-stick band, where the mass sticks early in the next period.
    #[test]
    fn eq_20_as_a_stick_condition_fails_in_the_late_stick_band() {
        let r = check(r"\varphi \le 1/\Theta", STICKS);
        assert!(!r.agrees, "{}", text(&r));
        for row in &r.by_regime {
            assert!(row.compared > 30, "{row:?}");
            let late = row.regime == "slip_stick_late";
            assert_eq!(row.disagree == row.compared, late, "{row:?}");
            assert_eq!(row.disagree == 0, !late, "{row:?}");
        }
    }

    /// A student's t_ST with a sign error (1 − φΘ for 1 + φΘ) fails, with counterexamples.
    #[test]
    fn a_sign_error_in_t_stick_is_caught_with_counterexamples() {
        let right = check(r"\frac{T}{2}\left(1 + \varphi\Theta\right)", "t_stick");
        assert!(right.agrees, "{}", text(&right));
        let wrong = check(r"\frac{T}{2}\left(1 - \varphi\Theta\right)", "t_stick");
        assert!(!wrong.agrees, "{}", text(&wrong));
        assert_eq!(wrong.worst.len(), WORST);
        assert!(text(&wrong).contains("DISAGREES") && text(&wrong).contains("worst sets"));
        // Only where the mass sticks within the period is t_ST measured: the other regimes
        // are named, not sampled.
        assert_eq!(
            wrong.unmeasured_regimes,
            ["slip_stick_late", "continuous_slip"]
        );
        assert_eq!(wrong.compared, 200);
    }

    #[test]
    fn bad_formulas_and_quantities_are_refused_with_what_is_known() {
        let err = |f: &str, q: &str| {
            run(&Request {
                case: Model::PulledMass(PulledMassParams::default()),
                formula: f.to_string(),
                quantity: q.to_string(),
                samples: 10,
                seed: 1,
            })
            .unwrap_err()
            .to_string()
        };
        let e = err("g*T*xi", "v_avg");
        assert!(
            e.contains("unknown symbol xi") && e.contains("--symbols") && e.contains("tau_SL"),
            "{e}"
        );
        let all = symbols_text(&Model::PulledMass(PulledMassParams::default()));
        for name in ["mu_s", "phi", "Theta", "Gamma", "tau_ST", "bar_v", "mass"] {
            assert!(all.contains(&format!("  {name} ")), "{name}: {all}");
        }
        assert!(err("g*T*(", "v_avg").contains("cannot be read"));
        let e = err("g*T", "speed");
        assert!(e.contains("--quantity") && e.contains("v_avg"), "{e}");
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(400))]

        /// Any text made of formula pieces is read or refused with an error, never a panic,
        /// and a formula that is read has a finite value or none.
        #[test]
        fn any_formula_text_is_read_or_refused_without_panicking(
            pieces in proptest::collection::vec(proptest::sample::select(vec![
                "phi", "T", "g", r"\varphi", r"\Theta", r"\frac", r"\sqrt", "[", "]", "{",
                "}", "(", ")", "^", "_", "+", "-", "*", "/", "2", "0.5", "1e308", r"\left(",
                r"\right)", r"\le", "<=", ">", "mu_s", r"\mu_s", "'", r"^{(I)}", " ", ",",
                r"\cdot", "PI", "sqrt", r"\", "x", "é", "0",
            ]), 0..12)
        ) {
            let text: String = pieces.concat();
            let case = Model::PulledMass(PulledMassParams::default());
            if let Ok(f) = Formula::parse(&text, &symbols(&case)) {
                if let Some(v) = f.value(&case) {
                    proptest::prop_assert!(v.is_finite());
                }
            }
        }
    }

    /// Every derived symbol is known whatever the regime of the given set: τ_ST on a set that
    /// slips continuously (the default pulled mass) still reads, and checks where it applies.
    #[test]
    fn derived_symbols_are_known_in_every_regime() {
        let r = check("T*tau_ST", "t_stick");
        assert!(r.agrees, "{}", text(&r));
        assert!(r.given.formula.is_some());
    }

    /// Undefined values are counted, not dropped: 1/(phi - phi) is nowhere defined.
    #[test]
    fn undefined_values_are_counted() {
        let r = check("1/(phi - phi)", "v_avg");
        assert_eq!(r.undefined, r.samples);
        assert!(!r.agrees && r.compared == 0);
    }
}
