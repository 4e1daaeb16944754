//! A small expression tree for worked substitutions: the same tree renders the closed form in
//! symbols, renders it again with the numbers put in (4 significant figures, parentheses where
//! a number needs them), and evaluates to the value, so the numbers shown provably give the
//! result shown.
//!
//! ```text
//! Var{ tex: "T", value: 0.2294 } × Var{ tex: "\tau_{SL}", value: 0.3938 }
//!     symbols:      T \tau_{SL}
//!     substituted:  0.2294 \times 0.3938
//!     value:        0.09035
//! ```

use std::ops::{Add, Div, Mul, Neg, Sub};

use crate::format::sig;

/// Significant figures of the numbers in a substituted formula.
pub const DIGITS: usize = 4;

/// A function applied to one argument.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Func {
    Sqrt,
    Arcsin,
    Arctan,
}

/// A closed form as a tree. Leaves are exact integers, named constants (π) and quantities
/// (a symbol with its value in SI units); inner nodes are the operations of the paper's
/// formulas.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    /// An exact integer, written the same in both renderings.
    Int(i64),
    /// A named constant such as π, written by name in both renderings.
    Const {
        tex: &'static str,
        value: f64,
    },
    /// A computed quantity: its symbol in the formula, its value (SI) to [`DIGITS`]
    /// significant figures in the substitution.
    Var {
        tex: &'static str,
        value: f64,
    },
    /// A given parameter: its symbol in the formula, its value as typed (SI, at most [`DIGITS`]
    /// significant figures, no trailing zeros) in the substitution.
    Given {
        tex: &'static str,
        value: f64,
    },
    Add(Box<Expr>, Box<Expr>),
    Sub(Box<Expr>, Box<Expr>),
    Mul(Box<Expr>, Box<Expr>),
    /// A fraction, written `\frac{a}{b}`.
    Div(Box<Expr>, Box<Expr>),
    /// A power with a rational exponent num/den (den > 0).
    Pow(Box<Expr>, i32, i32),
    Apply(Func, Box<Expr>),
    /// The larger of two values (a NaN argument is ignored, as by `f64::max`).
    Max(Box<Expr>, Box<Expr>),
    /// The opposite, written with a leading minus sign (−ωA).
    Neg(Box<Expr>),
}

/// What a derivation writes its formulas in: the expression tree ([`Expr`], rendered and
/// evaluated), or the value alone ([`Value`], for callers that need only numbers, such as
/// `stickslip check` per sampled set). Both evaluate with the same operations in the same
/// order, so a [`Value`] is bit-identical to [`Expr::eval`] of the tree built the same way.
pub trait Term:
    Clone
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// An exact integer.
    fn int(n: i64) -> Self;
    /// π.
    fn pi() -> Self;
    /// A computed quantity: symbol `tex`, value in SI units.
    fn var(tex: &'static str, value: f64) -> Self;
    /// A given parameter: symbol `tex`, value in SI units as typed.
    fn given(tex: &'static str, value: f64) -> Self;
    /// self^(num/den), den > 0.
    fn pow_ratio(self, num: i32, den: i32) -> Self;
    /// `f` applied to self.
    fn apply(self, f: Func) -> Self;
    /// The larger of self and `other` (a NaN argument is ignored, as by `f64::max`).
    fn max(self, other: Self) -> Self;
    /// The value, with every leaf at full precision.
    fn eval(&self) -> f64;
}

impl Term for Expr {
    fn int(n: i64) -> Self {
        Expr::Int(n)
    }
    fn pi() -> Self {
        Expr::Const {
            tex: r"\pi",
            value: std::f64::consts::PI,
        }
    }
    fn var(tex: &'static str, value: f64) -> Self {
        Expr::Var { tex, value }
    }
    fn given(tex: &'static str, value: f64) -> Self {
        Expr::Given { tex, value }
    }
    fn pow_ratio(self, num: i32, den: i32) -> Self {
        Expr::Pow(Box::new(self), num, den)
    }
    fn apply(self, f: Func) -> Self {
        Expr::Apply(f, Box::new(self))
    }
    fn max(self, other: Self) -> Self {
        Expr::Max(Box::new(self), Box::new(other))
    }
    fn eval(&self) -> f64 {
        Expr::eval(self)
    }
}

/// A formula's value without its tree: each operation done at once, as [`Expr::eval`] does it
/// on the tree.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Value(pub f64);

impl Term for Value {
    fn int(n: i64) -> Self {
        Value(n as f64)
    }
    fn pi() -> Self {
        Value(std::f64::consts::PI)
    }
    fn var(_: &'static str, value: f64) -> Self {
        Value(value)
    }
    fn given(_: &'static str, value: f64) -> Self {
        Value(value)
    }
    fn pow_ratio(self, num: i32, den: i32) -> Self {
        Value(power(self.0, num, den))
    }
    fn apply(self, f: Func) -> Self {
        Value(f.of(self.0))
    }
    fn max(self, other: Self) -> Self {
        Value(self.0.max(other.0))
    }
    fn eval(&self) -> f64 {
        self.0
    }
}

impl Add for Value {
    type Output = Value;
    fn add(self, rhs: Value) -> Value {
        Value(self.0 + rhs.0)
    }
}

impl Sub for Value {
    type Output = Value;
    fn sub(self, rhs: Value) -> Value {
        Value(self.0 - rhs.0)
    }
}

impl Mul for Value {
    type Output = Value;
    fn mul(self, rhs: Value) -> Value {
        Value(self.0 * rhs.0)
    }
}

impl Div for Value {
    type Output = Value;
    fn div(self, rhs: Value) -> Value {
        Value(self.0 / rhs.0)
    }
}

impl Neg for Value {
    type Output = Value;
    fn neg(self) -> Value {
        Value(-self.0)
    }
}

/// x^(num/den): `powi` for an integer power, as [`Expr::eval`] and [`Value`] both compute it.
fn power(x: f64, num: i32, den: i32) -> f64 {
    if den == 1 {
        x.powi(num)
    } else {
        x.powf(f64::from(num) / f64::from(den))
    }
}

impl Func {
    /// The function's value at `x`.
    fn of(self, x: f64) -> f64 {
        match self {
            Func::Sqrt => x.sqrt(),
            Func::Arcsin => x.asin(),
            Func::Arctan => crate::fmath::atan(x),
        }
    }
}

/// A computed quantity leaf: symbol `tex`, value in SI units.
pub fn var(tex: &'static str, value: f64) -> Expr {
    Expr::var(tex, value)
}

/// A given parameter leaf: symbol `tex`, value in SI units as typed.
pub fn given(tex: &'static str, value: f64) -> Expr {
    Expr::given(tex, value)
}

/// An exact integer leaf.
pub fn int(n: i64) -> Expr {
    Expr::Int(n)
}

/// π, written as π in both renderings.
pub fn pi() -> Expr {
    Expr::pi()
}

/// ½ as the fraction 1/2.
pub fn half<E: Term>() -> E {
    E::int(1) / E::int(2)
}

/// √e.
pub fn sqrt<E: Term>(e: E) -> E {
    e.apply(Func::Sqrt)
}

/// arcsin e.
pub fn arcsin<E: Term>(e: E) -> E {
    e.apply(Func::Arcsin)
}

/// arctan e (the crate's [`crate::fmath::atan`], that of the closed forms).
pub fn arctan<E: Term>(e: E) -> E {
    e.apply(Func::Arctan)
}

/// max(a, b).
pub fn max<E: Term>(a: E, b: E) -> E {
    a.max(b)
}

/// e^n for an integer n.
pub fn pow<E: Term>(e: E, n: i32) -> E {
    e.pow_ratio(n, 1)
}

/// e^(num/den).
pub fn pow_ratio<E: Term>(e: E, num: i32, den: i32) -> E {
    e.pow_ratio(num, den)
}

impl Add for Expr {
    type Output = Expr;
    fn add(self, rhs: Expr) -> Expr {
        Expr::Add(Box::new(self), Box::new(rhs))
    }
}

impl Sub for Expr {
    type Output = Expr;
    fn sub(self, rhs: Expr) -> Expr {
        Expr::Sub(Box::new(self), Box::new(rhs))
    }
}

impl Mul for Expr {
    type Output = Expr;
    fn mul(self, rhs: Expr) -> Expr {
        Expr::Mul(Box::new(self), Box::new(rhs))
    }
}

impl Div for Expr {
    type Output = Expr;
    fn div(self, rhs: Expr) -> Expr {
        Expr::Div(Box::new(self), Box::new(rhs))
    }
}

impl Neg for Expr {
    type Output = Expr;
    fn neg(self) -> Expr {
        Expr::Neg(Box::new(self))
    }
}

/// Binding strength of a rendered piece: a child weaker than its context needs parentheses.
mod prec {
    /// A sum or difference.
    pub const SUM: u8 = 10;
    /// A negative number: parenthesized everywhere but as the first term of a sum.
    pub const NEGATIVE: u8 = 5;
    /// A product (also a number in scientific notation, m × 10^e).
    pub const PRODUCT: u8 = 20;
    /// A fraction: fine as a factor, parenthesized as the base of a power.
    pub const FRACTION: u8 = 35;
    /// Symbols, plain numbers, roots, functions: never parenthesized.
    pub const ATOM: u8 = 40;
}

/// Which rendering: the formula in symbols, or with the numbers substituted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Mode {
    Symbols,
    Numbers,
}

impl Expr {
    /// The symbols of the computed quantities (the [`Expr::Var`] leaves), in the order they
    /// are written, each once.
    pub fn vars(&self) -> Vec<&'static str> {
        fn walk(e: &Expr, out: &mut Vec<&'static str>) {
            match e {
                Expr::Var { tex, .. } => {
                    if !out.contains(tex) {
                        out.push(tex);
                    }
                }
                Expr::Int(_) | Expr::Const { .. } | Expr::Given { .. } => {}
                Expr::Add(a, b)
                | Expr::Sub(a, b)
                | Expr::Mul(a, b)
                | Expr::Div(a, b)
                | Expr::Max(a, b) => {
                    walk(a, out);
                    walk(b, out);
                }
                Expr::Pow(a, ..) | Expr::Apply(_, a) | Expr::Neg(a) => walk(a, out),
            }
        }
        let mut out = Vec::new();
        walk(self, &mut out);
        out
    }

    /// The value, with every leaf at full precision.
    pub fn eval(&self) -> f64 {
        match self {
            Expr::Int(n) => *n as f64,
            Expr::Const { value, .. } | Expr::Var { value, .. } | Expr::Given { value, .. } => {
                *value
            }
            Expr::Add(a, b) => a.eval() + b.eval(),
            Expr::Sub(a, b) => a.eval() - b.eval(),
            Expr::Mul(a, b) => a.eval() * b.eval(),
            Expr::Div(a, b) => a.eval() / b.eval(),
            Expr::Pow(e, n, d) => power(e.eval(), *n, *d),
            Expr::Apply(f, e) => f.of(e.eval()),
            Expr::Max(a, b) => a.eval().max(b.eval()),
            Expr::Neg(e) => -e.eval(),
        }
    }

    /// LaTeX of the formula in symbols.
    pub fn symbols(&self) -> String {
        self.render(Mode::Symbols).0
    }

    /// LaTeX of the formula with every quantity replaced by its value (SI, 4 significant
    /// figures).
    pub fn numbers(&self) -> String {
        self.render(Mode::Numbers).0
    }

    /// LaTeX and binding strength.
    fn render(&self, mode: Mode) -> (String, u8) {
        match self {
            Expr::Int(n) if *n < 0 => (n.to_string(), prec::NEGATIVE),
            Expr::Int(n) => (n.to_string(), prec::ATOM),
            Expr::Const { tex, .. } => ((*tex).to_string(), prec::ATOM),
            Expr::Var { tex, .. } | Expr::Given { tex, .. } if mode == Mode::Symbols => {
                ((*tex).to_string(), prec::ATOM)
            }
            Expr::Var { value, .. } => number(*value, false),
            Expr::Given { value, .. } => number(*value, true),
            Expr::Add(a, b) => (
                format!(
                    "{} + {}",
                    a.child(mode, prec::NEGATIVE),
                    b.child(mode, prec::SUM)
                ),
                prec::SUM,
            ),
            Expr::Sub(a, b) => (
                format!(
                    "{} - {}",
                    a.child(mode, prec::NEGATIVE),
                    b.child(mode, prec::PRODUCT)
                ),
                prec::SUM,
            ),
            Expr::Mul(a, b) => {
                let (l, r) = (a.child(mode, prec::PRODUCT), b.child(mode, prec::PRODUCT));
                // Juxtaposition reads as a product in symbols unless two numbers would merge.
                let numeral = r.starts_with(|c: char| c.is_ascii_digit());
                let constant = matches!(**b, Expr::Const { .. });
                let op = if (mode == Mode::Numbers && !constant) || numeral {
                    r" \times "
                } else {
                    " "
                };
                (format!("{l}{op}{r}"), prec::PRODUCT)
            }
            Expr::Div(a, b) => (
                format!(r"\frac{{{}}}{{{}}}", a.child(mode, 0), b.child(mode, 0)),
                prec::FRACTION,
            ),
            Expr::Pow(e, n, d) => {
                let (base, p) = e.render(mode);
                // A symbol that already carries a superscript (u_s^{(-)}, η') is grouped first.
                let base = if p < prec::ATOM {
                    paren(&base)
                } else if base.contains(['^', '\'']) {
                    format!("{{{base}}}")
                } else {
                    base
                };
                let exponent = if *d == 1 {
                    n.to_string()
                } else {
                    format!("{n}/{d}")
                };
                (format!("{base}^{{{exponent}}}"), prec::ATOM)
            }
            Expr::Apply(Func::Sqrt, e) => (format!(r"\sqrt{{{}}}", e.child(mode, 0)), prec::ATOM),
            Expr::Apply(Func::Arcsin, e) => {
                (format!(r"\arcsin{}", paren(&e.child(mode, 0))), prec::ATOM)
            }
            Expr::Apply(Func::Arctan, e) => {
                (format!(r"\arctan{}", paren(&e.child(mode, 0))), prec::ATOM)
            }
            Expr::Max(a, b) => (
                format!(
                    r"\max{}",
                    paren(&format!("{}, {}", a.child(mode, 0), b.child(mode, 0)))
                ),
                prec::ATOM,
            ),
            // A product or anything tighter follows the sign as it is: −ωA, −10.00 × 0.02025.
            Expr::Neg(e) => (format!("-{}", e.child(mode, prec::PRODUCT)), prec::NEGATIVE),
        }
    }

    /// The rendering of a child in a context that binds with strength `min`.
    fn child(&self, mode: Mode, min: u8) -> String {
        let (tex, p) = self.render(mode);
        if p < min {
            paren(&tex)
        } else {
            tex
        }
    }
}

fn paren(tex: &str) -> String {
    format!(r"\left({tex}\right)")
}

/// A number in LaTeX to [`DIGITS`] significant figures (trailing zeros dropped when `as_typed`)
/// and its binding strength; "undefined" for a non-finite value.
fn number(x: f64, as_typed: bool) -> (String, u8) {
    if !x.is_finite() {
        return (r"\text{undefined}".to_string(), prec::ATOM);
    }
    let text = sig(Some(x), DIGITS);
    let (mantissa, exponent) = match text.split_once('e') {
        Some((m, e)) => (m, Some(e)),
        None => (text.as_str(), None),
    };
    let mantissa = if as_typed && mantissa.contains('.') {
        mantissa.trim_end_matches('0').trim_end_matches('.')
    } else {
        mantissa
    };
    let p = if x < 0.0 {
        prec::NEGATIVE
    } else if exponent.is_some() {
        prec::PRODUCT
    } else {
        prec::ATOM
    };
    let tex = match exponent {
        Some(e) => format!(r"{mantissa} \times 10^{{{e}}}"),
        None => mantissa.to_string(),
    };
    (tex, p)
}

/// `x` in LaTeX to [`DIGITS`] significant figures.
pub fn number_tex(x: f64) -> String {
    number(x, false).0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arctan_renders_in_both_modes_and_evaluates_as_the_closed_forms() {
        let e = int(2) / var(r"\omega", 10.0)
            * (pi() - arctan(var(r"\omega", 10.0) * var(r"\Delta", 0.01962) / given("v_b", 0.05)));
        assert_eq!(
            e.symbols(),
            r"\frac{2}{\omega} \left(\pi - \arctan\left(\frac{\omega \Delta}{v_b}\right)\right)"
        );
        assert_eq!(
            e.numbers(),
            r"\frac{2}{10.00} \times \left(\pi - \arctan\left(\frac{10.00 \times 0.01962}{0.05}\right)\right)"
        );
        assert_eq!(
            e.eval(),
            2.0 / 10.0 * (std::f64::consts::PI - crate::fmath::atan(10.0 * 0.01962 / 0.05))
        );
    }

    #[test]
    fn a_negation_is_a_leading_minus_in_both_modes_and_evaluates_bit_for_bit() {
        let (omega, a) = (var(r"\omega", 10.0), var("A", 0.020_247_084));
        let e = -(omega.clone() * a.clone());
        assert_eq!(e.symbols(), r"-\omega A");
        assert_eq!(e.numbers(), r"-10.00 \times 0.02025");
        assert_eq!(e.eval().to_bits(), (-10.0 * 0.020_247_084f64).to_bits());
        let v = -(Value(10.0) * Value(0.020_247_084));
        assert_eq!(v.eval().to_bits(), e.eval().to_bits());
        // A negated sum keeps its parentheses; a negation inside a product gets them.
        assert_eq!(
            (-(omega.clone() + a.clone())).symbols(),
            r"-\left(\omega + A\right)"
        );
        assert_eq!((a * -omega).symbols(), r"A \left(-\omega\right)");
    }

    #[test]
    fn renders_symbols_numbers_and_evaluates() {
        let e = var("T", 0.229_429_5) * var(r"\tau_{SL}", 0.393_815_8);
        assert_eq!(e.symbols(), r"T \tau_{SL}");
        assert_eq!(e.numbers(), r"0.2294 \times 0.3938");
        assert!((e.eval() - 0.229_429_5 * 0.393_815_8).abs() < 1e-17);
    }

    #[test]
    fn parentheses_where_numbers_need_them() {
        let u = given(r"u_d^{(-)}", -0.36);
        assert_eq!(
            (int(2) * u.clone()).numbers(),
            r"2 \times \left(-0.36\right)"
        );
        assert_eq!((u.clone() + int(1)).numbers(), r"-0.36 + 1");
        assert_eq!((int(1) - u.clone()).numbers(), r"1 - \left(-0.36\right)");
        assert_eq!(pow(u.clone(), 2).symbols(), r"{u_d^{(-)}}^{2}");
        assert_eq!(pow(u, 2).numbers(), r"\left(-0.36\right)^{2}");
        let small = var("x", 5.397e-4);
        assert_eq!(
            pow(small.clone(), 3).numbers(),
            r"\left(5.397 \times 10^{-4}\right)^{3}"
        );
        assert_eq!(
            (int(1) - (small.clone() + int(2))).symbols(),
            r"1 - \left(x + 2\right)"
        );
        assert_eq!(
            pow(var("a", 2.0) / var("b", 3.0), 2).symbols(),
            r"\left(\frac{a}{b}\right)^{2}"
        );
        assert_eq!((int(2) * int(3)).symbols(), r"2 \times 3");
        assert_eq!(given("k", 45.0).numbers(), "45");
        assert_eq!(given("g", 9.81).numbers(), "9.81");
        assert_eq!(var("T", 0.154_98).numbers(), "0.1550");
        assert_eq!(var("y", f64::NAN).numbers(), r"\text{undefined}");
    }

    #[test]
    fn max_ignores_an_undefined_argument() {
        let e = max(sqrt(int(-1)), var("a", 2.0));
        assert_eq!(e.eval(), 2.0);
        assert_eq!(e.symbols(), r"\max\left(\sqrt{-1}, a\right)");
    }
}
