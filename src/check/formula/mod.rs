//! A formula as people type it or paste it from a PDF, read into an expression tree over a
//! model's symbols: plain (`g*T*phi^3*Gamma`), LaTeX (`\frac{gT}{16}\left(\mu_s^2+\mu_d\right)`)
//! or Unicode (`g T φ³ Γ`, `T/2 (1 + φΘ)`, `√(μs² − μd²)`), with an optional left side naming
//! the quantity (`\bar{v} = …`) and an optional comparison (`φ ≤ 1/Θ`, a condition).
//!
//! Precedence is the mathematical one, lowest first:
//!
//! ```text
//! comparison  <  + −  <  × ÷ and implicit products (left to right)  <  unary −  <  ^ (right)
//! so  −x² = −(x²),  2^−1 = ½,  T/2 (1 + φΘ) = (T/2)(1 + φΘ)
//! ```
//!
//! A run of letters is split into the model's symbols with the fewest names (`gT` → g·T,
//! `Theta` stays Θ); a Greek letter is the model's symbol of that name or its variant (φ is
//! `varphi` or `phi`, τ is the model's τ, never 2π), and one directly followed by letters takes
//! them as its subscript when that names a symbol (`μs` → μ_s, as PDFs paste it). Written by
//! hand rather than with an expression crate because the one used before read −x² as (−x)²,
//! which made `check` accept a wrong sign under a root; and because the reader has to know the
//! model's symbols to split implicit products. Input is bounded ([`MAX_CHARS`], [`MAX_DEPTH`]),
//! so no formula can exhaust the stack.

mod lex;
mod names;
mod parse;

use crate::error::{excerpt, Error, Result};
use lex::Lexer;
use parse::Parser;

/// Longest formula read (characters).
pub const MAX_CHARS: usize = 4000;
/// Deepest nesting of parentheses, groups, roots, fractions and powers.
pub const MAX_DEPTH: usize = 100;

/// A function of one argument.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Func {
    Sqrt,
    Abs,
    Ln,
    Log10,
    Exp,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
}

impl Func {
    /// Names as words of a plain formula and as LaTeX commands.
    const NAMES: [(&'static str, Func); 14] = [
        ("sqrt", Func::Sqrt),
        ("abs", Func::Abs),
        ("ln", Func::Ln),
        ("log10", Func::Log10),
        ("exp", Func::Exp),
        ("sin", Func::Sin),
        ("cos", Func::Cos),
        ("tan", Func::Tan),
        ("arcsin", Func::Asin),
        ("arccos", Func::Acos),
        ("arctan", Func::Atan),
        ("asin", Func::Asin),
        ("acos", Func::Acos),
        ("atan", Func::Atan),
    ];

    fn named(name: &str) -> Option<Func> {
        Self::NAMES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, f)| *f)
    }

    fn apply(self, x: f64) -> f64 {
        match self {
            Func::Sqrt => x.sqrt(),
            Func::Abs => x.abs(),
            Func::Ln => x.ln(),
            Func::Log10 => x.log10(),
            Func::Exp => x.exp(),
            Func::Sin => x.sin(),
            Func::Cos => x.cos(),
            Func::Tan => x.tan(),
            Func::Asin => x.asin(),
            Func::Acos => x.acos(),
            Func::Atan => x.atan(),
        }
    }

    fn plain(self) -> &'static str {
        match self {
            Func::Sqrt => "sqrt",
            Func::Abs => "abs",
            Func::Ln => "ln",
            Func::Log10 => "log10",
            Func::Exp => "exp",
            Func::Sin => "sin",
            Func::Cos => "cos",
            Func::Tan => "tan",
            Func::Asin => "arcsin",
            Func::Acos => "arccos",
            Func::Atan => "arctan",
        }
    }

    fn tex(self) -> &'static str {
        match self {
            Func::Sqrt => r"\sqrt",
            // Its bars pair round the argument: the opening one.
            Func::Abs => r"\left|",
            Func::Ln => r"\ln",
            Func::Log10 => r"\log_{10}",
            Func::Exp => r"\exp",
            Func::Sin => r"\sin",
            Func::Cos => r"\cos",
            Func::Tan => r"\tan",
            Func::Asin => r"\arcsin",
            Func::Acos => r"\arccos",
            Func::Atan => r"\arctan",
        }
    }
}

/// A comparison between two sides: a condition, 1 where it holds and 0 where not.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Comparison {
    Le,
    Ge,
    Lt,
    Gt,
}

impl Comparison {
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

    fn tex(self) -> &'static str {
        match self {
            Comparison::Le => r"\le",
            Comparison::Ge => r"\ge",
            Comparison::Lt => "<",
            Comparison::Gt => ">",
        }
    }
}

/// The expression tree; a symbol is an index into [`Formula::names`].
#[derive(Clone, Debug, PartialEq)]
pub enum Node {
    Num(f64),
    Pi,
    Sym(usize),
    Neg(Box<Node>),
    Add(Box<Node>, Box<Node>),
    Sub(Box<Node>, Box<Node>),
    Mul(Box<Node>, Box<Node>),
    Div(Box<Node>, Box<Node>),
    Pow(Box<Node>, Box<Node>),
    Call(Func, Box<Node>),
}

impl Node {
    fn eval(&self, values: &[f64]) -> f64 {
        match self {
            Node::Num(x) => *x,
            Node::Pi => std::f64::consts::PI,
            Node::Sym(i) => values[*i],
            Node::Neg(a) => -a.eval(values),
            Node::Add(a, b) => a.eval(values) + b.eval(values),
            Node::Sub(a, b) => a.eval(values) - b.eval(values),
            Node::Mul(a, b) => a.eval(values) * b.eval(values),
            Node::Div(a, b) => a.eval(values) / b.eval(values),
            Node::Pow(a, b) => power(a.eval(values), b.eval(values)),
            Node::Call(f, a) => f.apply(a.eval(values)),
        }
    }

    /// Binding strength, for the parentheses of a rendering.
    fn precedence(&self) -> u8 {
        match self {
            Node::Add(..) | Node::Sub(..) => 1,
            Node::Mul(..) | Node::Div(..) => 2,
            Node::Neg(_) => 3,
            Node::Pow(..) => 4,
            Node::Num(x) if *x < 0.0 => 3,
            _ => 5,
        }
    }
}

/// x^y, with odd roots of negative numbers real (x^(1/3) for x < 0), as people mean them.
fn power(x: f64, y: f64) -> f64 {
    if x < 0.0 && y.fract() != 0.0 {
        let inverse = 1.0 / y;
        if inverse.fract() == 0.0 && inverse.rem_euclid(2.0) == 1.0 {
            return -(-x).powf(y);
        }
    }
    x.powf(y)
}

/// A formula read: the expression, an optional comparison with a right side, and the left
/// side's name when one was written (`\bar{v} = …`).
#[derive(Clone, Debug)]
pub struct Formula {
    pub lhs: Option<String>,
    pub expr: Node,
    pub condition: Option<(Comparison, Node)>,
    /// The symbols used, by name; [`Node::Sym`] indexes this.
    pub names: Vec<String>,
}

/// A symbol a formula may use: its name (an identifier), its LaTeX and its value.
#[derive(Clone, Debug, PartialEq)]
pub struct Symbol {
    pub name: String,
    pub tex: String,
    pub value: f64,
}

impl Formula {
    /// Reads `text` against the `known` symbols.
    pub fn read(text: &str, known: &[Symbol]) -> Result<Formula> {
        let error = |reason: String| Error::Formula {
            formula: excerpt(text, 80),
            reason,
        };
        let chars = text.chars().count();
        if chars > MAX_CHARS {
            return Err(error(format!(
                "the formula is {chars} characters long; at most {MAX_CHARS} are read"
            )));
        }
        let tokens = Lexer::new(text, known).tokens().map_err(error)?;
        Parser::new(tokens).formula().map_err(error)
    }

    /// The value with the symbols' values `values` (aligned with the `known` slice given to
    /// [`Formula::read`], looked up by name); a condition is 1 where it holds and 0 where not;
    /// `None` where the value is not a finite number.
    pub fn value(&self, known: &[Symbol]) -> Option<f64> {
        let values: Option<Vec<f64>> = self
            .names
            .iter()
            .map(|n| known.iter().find(|s| &s.name == n).map(|s| s.value))
            .collect();
        self.value_of(&values?)
    }

    /// The value with `values[i]` the value of `names[i]`: the path that evaluates a formula
    /// on many sets without looking symbols up by name.
    pub fn value_of(&self, values: &[f64]) -> Option<f64> {
        let lhs = Some(self.expr.eval(values)).filter(|v| v.is_finite())?;
        match &self.condition {
            None => Some(lhs),
            Some((c, rhs)) => {
                let rhs = Some(rhs.eval(values)).filter(|v| v.is_finite())?;
                Some(f64::from(u8::from(c.holds(lhs, rhs))))
            }
        }
    }

    /// How the formula was read, in plain syntax with every product and parenthesis written.
    pub fn plain(&self) -> String {
        let mut s = self.render(&self.expr, Style::Plain, None);
        if let Some((c, rhs)) = &self.condition {
            s = format!("{s} {} {}", c.plain(), self.render(rhs, Style::Plain, None));
        }
        s
    }

    /// How the formula was read, in LaTeX with the symbols' own LaTeX.
    pub fn latex(&self, known: &[Symbol]) -> String {
        let mut s = self.render(&self.expr, Style::Latex, Some(known));
        if let Some((c, rhs)) = &self.condition {
            s = format!(
                "{s} {} {}",
                c.tex(),
                self.render(rhs, Style::Latex, Some(known))
            );
        }
        s
    }

    fn render(&self, node: &Node, style: Style, known: Option<&[Symbol]>) -> String {
        let latex = style == Style::Latex;
        let wrap = |child: &Node, min: u8| {
            let inner = self.render(child, style, known);
            if child.precedence() < min {
                if latex {
                    format!(r"\left({inner}\right)")
                } else {
                    format!("({inner})")
                }
            } else {
                inner
            }
        };
        match node {
            Node::Num(x) => number(*x, latex),
            Node::Pi => (if latex { r"\pi" } else { "pi" }).to_string(),
            Node::Sym(i) => {
                let name = &self.names[*i];
                match known.and_then(|k| k.iter().find(|s| &s.name == name)) {
                    Some(s) if latex => s.tex.clone(),
                    _ => name.clone(),
                }
            }
            Node::Neg(a) => format!("-{}", wrap(a, 3)),
            Node::Add(a, b) => format!("{} + {}", wrap(a, 1), wrap(b, 2)),
            Node::Sub(a, b) => format!("{} - {}", wrap(a, 1), wrap(b, 2)),
            Node::Mul(a, b) => {
                let op = if latex { r" \cdot " } else { "*" };
                format!("{}{op}{}", wrap(a, 2), wrap(b, 3))
            }
            Node::Div(a, b) if latex => format!(
                r"\frac{{{}}}{{{}}}",
                self.render(a, style, known),
                self.render(b, style, known)
            ),
            Node::Div(a, b) => format!("{}/{}", wrap(a, 2), wrap(b, 3)),
            Node::Pow(a, b) if latex => {
                format!("{{{}}}^{{{}}}", wrap(a, 5), self.render(b, style, known))
            }
            Node::Pow(a, b) => format!("{}^{}", wrap(a, 5), wrap(b, 4)),
            Node::Call(f, a) => {
                let inner = self.render(a, style, known);
                match (f, latex) {
                    (Func::Sqrt, true) => format!("{}{{{inner}}}", f.tex()),
                    (Func::Abs, true) => format!(r"{}{inner}\right|", f.tex()),
                    (f, true) => format!(r"{}\left({inner}\right)", f.tex()),
                    (f, false) => format!("{}({inner})", f.plain()),
                }
            }
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Style {
    Plain,
    Latex,
}

/// A number as read back: the shortest decimal, in e-notation when very small or large.
fn number(x: f64, latex: bool) -> String {
    let a = x.abs();
    if a != 0.0 && !(1e-4..1e6).contains(&a) {
        let s = format!("{x:e}");
        match (latex, s.split_once('e')) {
            (true, Some((m, e))) => format!(r"{m} \times 10^{{{e}}}"),
            _ => s,
        }
    } else {
        format!("{x}")
    }
}

/// A LaTeX subscript or symbol as an identifier: `\tau_{SL}` → `tau_SL`, `u_s^{(-)}` →
/// `u_s_minus`, `\eta'` → `eta_prime`, `\mu_{d,HALT}` → `mu_d_HALT`, `\bar v` → `bar_v`.
pub fn identifier(tex: &str) -> String {
    let mut s = tex.trim().to_string();
    for (from, to) in [
        ("^{(II)}", "_II"),
        ("^{(I)}", "_I"),
        ("^{(+)}", "_plus"),
        ("^{(-)}", "_minus"),
        ("'", "_prime"),
        ("\\bar ", "bar_"),
        ("\\bar", "bar_"),
        ("\\mathrm", ""),
        ("\\text", ""),
        (",", "_"),
    ] {
        s = s.replace(from, to);
    }
    s.chars()
        .filter(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect::<String>()
        .replace("__", "_")
}

#[cfg(test)]
mod tests {
    use super::*;

    fn known() -> Vec<Symbol> {
        [
            ("g", "g", 9.81),
            ("T", "T", 0.5),
            ("varphi", r"\varphi", 0.2),
            ("Theta", r"\Theta", 3.0),
            ("Gamma", r"\Gamma", 0.7),
            ("mu_s", r"\mu_s", 0.4),
            ("mu_d", r"\mu_d", 0.3),
            ("tau_SL", r"\tau_{SL}", 0.1),
            ("tau", r"\tau", 0.25),
            ("u_s_minus", r"u_s^{(-)}", 0.6),
            ("eta_prime", r"\eta'", 1.5),
            ("mu_d_HALT_II", r"\mu_{d,HALT}^{(II)}", 0.05),
            ("bar_v", r"\bar v", 0.01),
            ("m", "m", 0.1),
            ("mass", "m", 0.1),
        ]
        .into_iter()
        .map(|(n, t, v)| Symbol {
            name: n.to_string(),
            tex: t.to_string(),
            value: v,
        })
        .collect()
    }

    fn value(text: &str) -> f64 {
        let k = known();
        Formula::read(text, &k)
            .unwrap_or_else(|e| panic!("{text}: {e}"))
            .value(&k)
            .unwrap_or(f64::NAN)
    }

    fn plain(text: &str) -> String {
        Formula::read(text, &known()).unwrap().plain()
    }

    #[test]
    fn unary_minus_binds_less_tightly_than_a_power() {
        assert_eq!(value("-2^2"), -4.0);
        assert_eq!(value("-mu_s^2+mu_d^2"), -0.4f64.powi(2) + 0.3f64.powi(2));
        assert_eq!(value("2^-1"), 0.5);
        assert_eq!(value("2^3^2"), 512.0);
        assert_eq!(value("−2²"), -4.0);
        assert_eq!(value("(-2)^2"), 4.0);
        assert_eq!(value("2*-3"), -6.0);
    }

    #[test]
    fn scientific_literals_are_numbers() {
        assert_eq!(value("1e-6"), 1e-6);
        assert_eq!(value("1E-12"), 1e-12);
        assert_eq!(value("2.5e+3"), 2500.0);
        assert_eq!(value(".5"), 0.5);
        assert!((value(r"3 \times 10^{-9}") / 3e-9 - 1.0).abs() < 1e-15);
        assert!((value("3·10⁻⁹") / 3e-9 - 1.0).abs() < 1e-15);
    }

    #[test]
    fn implicit_products_split_into_known_symbols() {
        assert_eq!(plain("gT"), "g*T");
        assert_eq!(plain("g T φ^3 Γ"), "g*T*varphi^3*Gamma");
        assert_eq!(plain("gTφ³Γ"), "g*T*varphi^3*Gamma");
        assert_eq!(plain("g*T*φ^3*Γ"), "g*T*varphi^3*Gamma");
        assert_eq!(plain(r"g T \varphi^3 \Gamma"), "g*T*varphi^3*Gamma");
        assert_eq!(plain("T/2 (1 + φ Θ)"), "T/2*(1 + varphi*Theta)");
        assert_eq!(plain("Theta"), "Theta");
        assert_eq!(plain("phi"), "varphi");
        assert_eq!(plain("μs - μd"), "mu_s - mu_d");
        assert_eq!(plain("μ_s"), "mu_s");
        assert_eq!(plain("mass"), "mass");
    }

    #[test]
    fn greek_letters_are_the_models_symbols_never_constants() {
        assert_eq!(value("τ"), 0.25);
        assert_eq!(value(r"\tau"), 0.25);
        assert_eq!(value("π"), std::f64::consts::PI);
        assert_eq!(value(r"\tau_{SL}"), 0.1);
        assert_eq!(value("τ_SL"), 0.1);
    }

    #[test]
    fn latex_names_with_their_superscripts() {
        assert_eq!(value(r"u_s^{(-)}\eta'"), 0.6 * 1.5);
        assert_eq!(value(r"\mu_{d,HALT}^{(II)}"), 0.05);
        assert_eq!(value(r"\bar{v}"), 0.01);
        assert_eq!(value(r"\frac12"), 0.5);
        assert_eq!(
            value(r"\frac{T}{2}\left(1+\varphi\Theta\right)"),
            0.25 * 1.6
        );
        assert_eq!(value(r"\sqrt[3]{8}"), 2.0);
        assert_eq!(value(r"\sqrt{\mu_s^2}"), 0.4);
        assert_eq!(value(r"g^23 \cdot 1"), 9.81 * 9.81 * 3.0);
        assert_eq!(value("g^23"), 9.81f64.powi(23));
        assert_eq!(value(r"\log_{10}(g)"), 9.81f64.log10());
        assert_eq!(value("sqrt(g)^3"), 9.81f64.sqrt().powi(3));
        assert_eq!(value("∛(8)"), 2.0);
    }

    #[test]
    fn absolute_values_logs_and_roots() {
        assert_eq!(value("|mu_d - mu_s|"), (0.3f64 - 0.4).abs());
        assert_eq!(value(r"\left|\mu_d-\mu_s\right|"), (0.3f64 - 0.4).abs());
        assert_eq!(value(r"\ln(g)"), 9.81f64.ln());
        assert_eq!(value("√(mu_s^2)"), 0.4);
        assert_eq!(value("2|mu_d - mu_s|"), 2.0 * (0.3f64 - 0.4).abs());
        assert!(Formula::read("log(g)", &known()).is_err());
    }

    #[test]
    fn a_left_side_names_the_quantity() {
        let f = Formula::read(r"\bar{v} = g T \varphi^3 \Gamma", &known()).unwrap();
        assert_eq!(f.lhs.as_deref(), Some("bar_v"));
        assert_eq!(f.plain(), "g*T*varphi^3*Gamma");
        let f = Formula::read("v_avg = g*T", &known()).unwrap();
        assert_eq!(f.lhs.as_deref(), Some("v_avg"));
    }

    #[test]
    fn conditions_compare_two_sides() {
        assert_eq!(value(r"\varphi \le 1/\Theta"), 1.0);
        assert_eq!(value("φ ≥ 1/Θ"), 0.0);
        assert_eq!(value("phi <= 1.03*Theta"), 1.0);
    }

    #[test]
    fn the_reading_round_trips_through_both_renderings() {
        for text in [
            "-mu_s^2 + 2*mu_s*mu_d - mu_d^2",
            "g*T*varphi^3*Gamma/(16*mu_s^2)",
            "T/2*(1 + varphi*Theta)",
            "sqrt(mu_s - mu_d)^3",
            "2^-1",
            "(-2)^2",
        ] {
            let k = known();
            let f = Formula::read(text, &k).unwrap();
            let again = Formula::read(&f.plain(), &k).unwrap();
            assert_eq!(again.value(&k), f.value(&k), "{text} → {}", f.plain());
            let from_tex = Formula::read(&f.latex(&k), &k).unwrap();
            assert_eq!(from_tex.value(&k), f.value(&k), "{text} → {}", f.latex(&k));
        }
    }

    #[test]
    fn unreadable_formulas_get_one_pointed_hint() {
        let err = |t: &str| Formula::read(t, &known()).unwrap_err().to_string();
        assert!(
            err("g*T*(").contains("ends where an operand"),
            "{}",
            err("g*T*(")
        );
        assert!(err("(g*T").contains("not closed"));
        assert!(err("g*T)").contains("no `(`"));
        assert!(err("g*xi").contains("unknown symbol xi"));
        assert!(err("g # T").contains("`#` is not part"));
        assert!(err("0,5*g").contains("decimals take a point"));
        let deep = format!("{}g{}", "{".repeat(20_000), "}".repeat(20_000));
        assert!(err(&deep).contains("characters long"));
        let deep = format!("{}g{}", "(".repeat(500), ")".repeat(500));
        assert!(err(&deep).contains("levels deep"), "{}", err(&deep));
        for e in [err("g*T*("), err("g*xi"), err("1e")] {
            assert!(!e.contains("ops") && !e.contains("node"), "{e}");
        }
    }
}
