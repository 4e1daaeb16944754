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

use std::ops::{Add, Div, Mul, Sub};

use crate::output::format::sig;

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
}

/// A computed quantity leaf: symbol `tex`, value in SI units.
pub fn var(tex: &'static str, value: f64) -> Expr {
    Expr::Var { tex, value }
}

/// A given parameter leaf: symbol `tex`, value in SI units as typed.
pub fn given(tex: &'static str, value: f64) -> Expr {
    Expr::Given { tex, value }
}

/// An exact integer leaf.
pub fn int(n: i64) -> Expr {
    Expr::Int(n)
}

/// π, written as π in both renderings.
pub fn pi() -> Expr {
    Expr::Const {
        tex: r"\pi",
        value: std::f64::consts::PI,
    }
}

/// ½ as the fraction 1/2.
pub fn half() -> Expr {
    int(1) / int(2)
}

/// √e.
pub fn sqrt(e: Expr) -> Expr {
    Expr::Apply(Func::Sqrt, Box::new(e))
}

/// arcsin e.
pub fn arcsin(e: Expr) -> Expr {
    Expr::Apply(Func::Arcsin, Box::new(e))
}

/// arctan e.
pub fn arctan(e: Expr) -> Expr {
    Expr::Apply(Func::Arctan, Box::new(e))
}

/// max(a, b).
pub fn max(a: Expr, b: Expr) -> Expr {
    Expr::Max(Box::new(a), Box::new(b))
}

/// e^n for an integer n.
pub fn pow(e: Expr, n: i32) -> Expr {
    Expr::Pow(Box::new(e), n, 1)
}

/// e^(num/den).
pub fn pow_ratio(e: Expr, num: i32, den: i32) -> Expr {
    Expr::Pow(Box::new(e), num, den)
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
                Expr::Pow(a, ..) | Expr::Apply(_, a) => walk(a, out),
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
            Expr::Pow(e, n, 1) => e.eval().powi(*n),
            Expr::Pow(e, n, d) => e.eval().powf(f64::from(*n) / f64::from(*d)),
            Expr::Apply(Func::Sqrt, e) => e.eval().sqrt(),
            Expr::Apply(Func::Arcsin, e) => e.eval().asin(),
            Expr::Apply(Func::Arctan, e) => e.eval().atan(),
            Expr::Max(a, b) => a.eval().max(b.eval()),
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
