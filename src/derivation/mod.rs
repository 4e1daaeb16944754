//! Worked substitutions: for each closed form of a model, the formula in symbols, the same
//! formula with the numbers (SI) put in, and the result, in the order a derivation reads.
//!
//! ```text
//! params → formula::… (the values)  ─┐
//!        → expression trees (expr)  ─┴→ Step { formula, substituted, value, reason }
//! ```
//!
//! Each step's `value` is the value of the pure function in [`crate::formula`], never derived
//! again here; the expression tree only shows how that value comes about, and the tests assert
//! that evaluating the tree gives the same number. A step whose formula does not describe the
//! motion for the parameters (its regime, guide §9 and guide §8.6) has `value: None` and the
//! reason, taken from the applicability logic of [`crate::results`].

pub mod expr;

pub use expr::{Expr, Term, Value};

use crate::results::quantity::{AnyKey, Registry};
use crate::results::Applicability;

/// A derived parameter with a step of its own (W, ω, T, λ): its guide §14 `params` key, LaTeX symbol,
/// equation and unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Param {
    pub id: &'static str,
    pub tex: &'static str,
    pub equation: &'static str,
    pub unit: &'static str,
}

/// What a step works out: a derived parameter, or a closed-form quantity of a registry.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StepKey {
    Param(Param),
    Quantity(AnyKey),
}

impl StepKey {
    /// The JSON key (guide §14) (`closed_form`, or `params` for a derived parameter).
    pub fn id(self) -> &'static str {
        match self {
            StepKey::Param(p) => p.id,
            StepKey::Quantity(k) => k.id(),
        }
    }

    /// The plain-text symbol (a derived parameter: its key).
    pub fn symbol(self) -> &'static str {
        match self {
            StepKey::Param(p) => p.id,
            StepKey::Quantity(k) => k.quantity().symbol,
        }
    }
}

impl From<Param> for StepKey {
    fn from(p: Param) -> Self {
        StepKey::Param(p)
    }
}

impl<K: Registry> From<K> for StepKey {
    fn from(k: K) -> Self {
        StepKey::Quantity(k.into())
    }
}

/// One worked step: a closed form, the numbers put in, the result. Its formula is an
/// expression tree ([`Expr`]), or only its value ([`Value`], [`Step::formula_value`]) for a caller
/// that needs numbers alone.
#[derive(Clone, Debug, PartialEq)]
pub struct Step<E = Expr> {
    /// What the step works out.
    pub key: StepKey,
    /// LaTeX symbol, e.g. "t_{SL}".
    pub symbol: &'static str,
    /// The paper's equation number(s), as in the registry.
    pub equation: &'static str,
    /// SI result; `None` when the form does not apply for these params.
    pub value: Option<f64>,
    /// SI unit, "" when dimensionless.
    pub unit: &'static str,
    /// Why it does not apply (`None` when it does).
    pub reason: Option<String>,
    /// The expression tree behind `formula` and `substituted`; evaluating it gives the value
    /// of the formula function (also where the form does not apply but is defined).
    pub expr: E,
}

/// Why a step has no value when the formula function itself returns none.
pub const UNDEFINED: &str =
    "the expression is undefined for these parameters (a zero denominator or a negative root)";

impl<E: Term> Step<E> {
    /// A step of `key` with formula `expr`, the formula function's `value` (`None` when the
    /// expression is undefined) and why the form does not describe the motion, if so.
    pub(crate) fn new(
        key: StepKey,
        (symbol, equation, unit): (&'static str, &'static str, &'static str),
        expr: E,
        value: Option<f64>,
        not_applicable: Option<String>,
    ) -> Self {
        let reason = match value {
            None => Some(not_applicable.unwrap_or_else(|| UNDEFINED.to_string())),
            Some(_) => not_applicable,
        };
        Step {
            key,
            symbol,
            equation,
            value: value.filter(|_| reason.is_none()),
            unit,
            reason,
            expr,
        }
    }

    /// The value of the step's formula: the closed form's where it applies, else its
    /// expression's (defined also where the form does not describe the motion, e.g. τ_ST > 1
    /// past the period); NaN where neither is finite.
    pub fn formula_value(&self) -> f64 {
        let v = self.value.unwrap_or_else(|| self.expr.eval());
        if v.is_finite() {
            v
        } else {
            f64::NAN
        }
    }
}

impl Step {
    /// LaTeX: the closed form in symbols (the right-hand side: `symbol = formula`). Rendered on
    /// demand, so that a caller that needs only values (`stickslip check`) renders nothing.
    pub fn formula(&self) -> String {
        self.expr.symbols()
    }

    /// LaTeX: the same with numbers (SI) substituted.
    pub fn substituted(&self) -> String {
        self.expr.numbers()
    }

    /// The result in LaTeX, to 4 significant figures with its unit, e.g. `0.09035\,\mathrm{s}`;
    /// `None` when the form does not apply.
    pub fn result_tex(&self) -> Option<String> {
        let value = expr::number_tex(self.value?);
        Some(match unit_tex(self.unit) {
            Some(unit) => format!(r"{value}\,{unit}"),
            None => value,
        })
    }

    /// The whole worked line in LaTeX: `symbol = formula = substituted = result`, or without the
    /// result when the form does not apply.
    pub fn worked_tex(&self) -> String {
        self.worked_pieces().join(" ")
    }

    /// [`Step::worked_tex`] in the pieces a long line may wrap between: "symbol = formula",
    /// "= substituted", "= result".
    pub fn worked_pieces(&self) -> Vec<String> {
        let mut pieces = vec![
            format!("{} = {}", self.symbol, self.formula()),
            format!("= {}", self.substituted()),
        ];
        pieces.extend(self.result_tex().map(|r| format!("= {r}")));
        pieces
    }
}

/// The steps that `step` uses, each before the steps that use it (the computed symbols of its
/// formula, found among `steps` by symbol, recursively): the working a student writes down on
/// the way to `step`, for partial credit.
pub fn working<'a>(steps: &'a [Step], step: &Step) -> Vec<&'a Step> {
    fn visit<'a>(steps: &'a [Step], step: &Step, out: &mut Vec<&'a Step>, depth: usize) {
        if depth > steps.len() {
            return;
        }
        for symbol in step.expr.vars() {
            let Some(used) = steps.iter().find(|s| s.symbol == symbol) else {
                continue;
            };
            if out.iter().any(|s| std::ptr::eq(*s, used)) {
                continue;
            }
            visit(steps, used, out, depth + 1);
            if !out.iter().any(|s| std::ptr::eq(*s, used)) {
                out.push(used);
            }
        }
    }
    let mut out = Vec::new();
    visit(steps, step, &mut out, 0);
    out
}

/// Collects the steps of one model (key `K`) in order; each step's symbol and value become a
/// quantity leaf for the steps after it.
pub(crate) struct Steps<'a, K, E = Expr> {
    model: std::marker::PhantomData<K>,
    applicability: &'a [Applicability],
    /// Why no closed form of a key applies when the results' list does not name it (e.g. the
    /// woodpecker outside the closed-form domain); `None`: such keys apply.
    pub(crate) fallback: Option<&'a str>,
    pub(crate) steps: Vec<Step<E>>,
}

impl<'a, K: Registry, E: Term> Steps<'a, K, E> {
    pub(crate) fn new(applicability: &'a [Applicability]) -> Self {
        Steps {
            model: std::marker::PhantomData,
            applicability,
            fallback: None,
            steps: Vec::new(),
        }
    }

    /// Adds the step `symbol = expr` of the quantity `key` whose formula function gives
    /// `value` (symbol, equation and unit from the registry), and returns the quantity leaf of
    /// its symbol for later steps (NaN when undefined).
    pub(crate) fn push(&mut self, key: K, expr: E, value: Option<f64>) -> E {
        let q = key.quantity();
        let any: AnyKey = key.into();
        let not_applicable = match self.applicability.iter().find(|a| a.quantity == any) {
            Some(a) => (!a.applies).then(|| a.reason.clone()),
            None => self.fallback.map(str::to_string),
        };
        self.add(
            StepKey::Quantity(any),
            (q.tex, q.equation, q.unit),
            expr,
            value,
            not_applicable,
        )
    }

    /// Adds the step of the derived parameter `param`, as [`Steps::push`].
    pub(crate) fn push_param(&mut self, param: Param, expr: E, value: Option<f64>) -> E {
        let not_applicable = self.fallback.map(str::to_string);
        self.add(
            StepKey::Param(param),
            (param.tex, param.equation, param.unit),
            expr,
            value,
            not_applicable,
        )
    }

    fn add(
        &mut self,
        key: StepKey,
        shown: (&'static str, &'static str, &'static str),
        expr: E,
        value: Option<f64>,
        not_applicable: Option<String>,
    ) -> E {
        let symbol = shown.0;
        self.steps
            .push(Step::new(key, shown, expr, value, not_applicable));
        E::var(symbol, value.unwrap_or(f64::NAN))
    }
}

/// An SI unit in LaTeX (`m/s²` → `\mathrm{m/s^{2}}`); `None` for a dimensionless quantity.
pub fn unit_tex(unit: &str) -> Option<String> {
    (!unit.is_empty()).then(|| format!(r"\mathrm{{{}}}", unit.replace('²', "^{2}")))
}

#[cfg(test)]
mod tests;
