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

use crate::error::{excerpt, Error, Result};

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
            Func::Log10 => r"\log_{10}",
            Func::Exp => r"\exp",
            f => match f.plain() {
                "ln" => r"\ln",
                "sin" => r"\sin",
                "cos" => r"\cos",
                "tan" => r"\tan",
                "arcsin" => r"\arcsin",
                "arccos" => r"\arccos",
                _ => r"\arctan",
            },
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
        let values = values?;
        let lhs = Some(self.expr.eval(&values)).filter(|v| v.is_finite())?;
        match &self.condition {
            None => Some(lhs),
            Some((c, rhs)) => {
                let rhs = Some(rhs.eval(&values)).filter(|v| v.is_finite())?;
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
                    (Func::Sqrt, true) => format!(r"\sqrt{{{inner}}}"),
                    (Func::Abs, true) => format!(r"\left|{inner}\right|"),
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

/// A token of a formula.
#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Num(f64),
    /// A known symbol, by name.
    Sym(String),
    /// The name on the left of `=`, as written (`bar_v`, `v_avg`): a quantity, not a symbol.
    Lhs(String),
    Func(Func),
    Pi,
    /// `+ - * / ^`.
    Op(char),
    Open,
    Close,
    Bar,
    /// `\frac`: two arguments follow.
    Frac,
    /// `√` or `\sqrt`; `true` when an index in brackets follows (`\sqrt[3]{x}`, `∛`).
    Root(bool),
    Cmp(Comparison),
    Equals,
}

/// Greek letters by character, with the names their LaTeX gives.
const GREEK: [(char, &str); 38] = [
    ('α', "alpha"),
    ('β', "beta"),
    ('γ', "gamma"),
    ('δ', "delta"),
    ('ε', "epsilon"),
    ('ϵ', "epsilon"),
    ('ζ', "zeta"),
    ('η', "eta"),
    ('θ', "theta"),
    ('ϑ', "vartheta"),
    ('ι', "iota"),
    ('κ', "kappa"),
    ('λ', "lambda"),
    ('μ', "mu"),
    ('µ', "mu"),
    ('ν', "nu"),
    ('ξ', "xi"),
    ('ρ', "rho"),
    ('σ', "sigma"),
    ('τ', "tau"),
    ('υ', "upsilon"),
    ('φ', "varphi"),
    ('ϕ', "phi"),
    ('χ', "chi"),
    ('ψ', "psi"),
    ('ω', "omega"),
    ('Γ', "Gamma"),
    ('Δ', "Delta"),
    ('Θ', "Theta"),
    ('Λ', "Lambda"),
    ('Ξ', "Xi"),
    ('Π', "Pi"),
    ('Σ', "Sigma"),
    ('Φ', "Phi"),
    ('Ψ', "Psi"),
    ('Ω', "Omega"),
    ('ς', "varsigma"),
    ('ϱ', "varrho"),
];

/// LaTeX Greek commands (lower and upper case) and their variants.
const GREEK_COMMANDS: [&str; 35] = [
    "alpha", "beta", "gamma", "delta", "epsilon", "varepsilon", "zeta", "eta", "theta", "vartheta",
    "iota", "kappa", "lambda", "mu", "nu", "xi", "rho", "varrho", "sigma", "varsigma", "tau",
    "upsilon", "phi", "varphi", "chi", "psi", "omega", "Gamma", "Delta", "Theta", "Lambda", "Xi",
    "Sigma", "Phi", "Omega",
];

/// A Greek name and its variant spelling (`phi` ↔ `varphi`).
fn variant(name: &str) -> Option<String> {
    for base in ["phi", "theta", "epsilon", "rho", "sigma"] {
        if let Some(rest) = name.strip_prefix(base) {
            return Some(format!("var{base}{rest}"));
        }
        if let Some(rest) = name.strip_prefix(&format!("var{base}")) {
            return Some(format!("{base}{rest}"));
        }
    }
    None
}

/// Superscript digits and signs (`³`, `⁻¹`).
fn superscript(c: char) -> Option<char> {
    Some(match c {
        '⁰' => '0',
        '¹' => '1',
        '²' => '2',
        '³' => '3',
        '⁴' => '4',
        '⁵' => '5',
        '⁶' => '6',
        '⁷' => '7',
        '⁸' => '8',
        '⁹' => '9',
        '⁻' => '-',
        '⁺' => '+',
        _ => return None,
    })
}

/// Subscript digits and letters (`₀`, `ₛ`).
fn subscript(c: char) -> Option<char> {
    Some(match c {
        '₀'..='₉' => char::from(b'0' + (c as u32 - '₀' as u32) as u8),
        'ₐ' => 'a',
        'ₑ' => 'e',
        'ₒ' => 'o',
        'ₓ' => 'x',
        'ₕ' => 'h',
        'ₖ' => 'k',
        'ₗ' => 'l',
        'ₘ' => 'm',
        'ₙ' => 'n',
        'ₚ' => 'p',
        'ₛ' => 's',
        'ₜ' => 't',
        _ => return None,
    })
}

struct Lexer<'a> {
    chars: Vec<char>,
    at: usize,
    latex: bool,
    known: &'a [Symbol],
}

impl<'a> Lexer<'a> {
    fn new(text: &str, known: &'a [Symbol]) -> Self {
        // Pasted typography as the ASCII it stands for.
        let chars: Vec<char> = text
            .chars()
            .map(|c| match c {
                '−' | '–' | '‐' | '‑' => '-',
                '·' | '⋅' | '×' | '∙' | '∗' => '*',
                '÷' | '∕' => '/',
                '∣' | '│' => '|',
                '\u{a0}' | '\u{2009}' | '\u{202f}' | '\u{2002}' | '\u{2003}' => ' ',
                c => c,
            })
            .collect();
        let latex = chars.iter().any(|c| matches!(c, '\\' | '{' | '}'));
        Self {
            chars,
            at: 0,
            latex,
            known,
        }
    }

    fn peek(&self) -> Option<char> {
        self.chars.get(self.at).copied()
    }

    fn peek_at(&self, n: usize) -> Option<char> {
        self.chars.get(self.at + n).copied()
    }

    fn rest_starts_with(&self, s: &str) -> bool {
        s.chars().enumerate().all(|(i, c)| self.peek_at(i) == Some(c))
    }

    fn tokens(mut self) -> std::result::Result<Vec<Tok>, String> {
        let mut out = Vec::new();
        while let Some(c) = self.peek() {
            if c.is_whitespace() {
                self.at += 1;
                continue;
            }
            self.token(c, &mut out)?;
        }
        Ok(out)
    }

    fn token(&mut self, c: char, out: &mut Vec<Tok>) -> std::result::Result<(), String> {
        if c.is_ascii_digit() || (c == '.' && self.peek_at(1).is_some_and(|d| d.is_ascii_digit()))
        {
            out.push(Tok::Num(self.number()?));
            return Ok(());
        }
        if superscript(c).is_some() {
            // `φ³`, `10⁻⁹`: a power with the superscript run as its exponent.
            let mut digits = String::new();
            while let Some(d) = self.peek().and_then(superscript) {
                digits.push(d);
                self.at += 1;
            }
            let exponent: f64 = digits
                .parse()
                .map_err(|_| format!("the superscript `{digits}` is not a number"))?;
            out.push(Tok::Op('^'));
            out.push(Tok::Num(exponent));
            return Ok(());
        }
        match c {
            '+' | '-' | '/' => {
                self.at += 1;
                out.push(Tok::Op(c));
            }
            '*' => {
                self.at += 1;
                if self.peek() == Some('*') {
                    self.at += 1;
                    out.push(Tok::Op('^'));
                } else {
                    out.push(Tok::Op('*'));
                }
            }
            '^' => {
                self.at += 1;
                out.push(Tok::Op('^'));
                // In LaTeX `x^23` is x²·3: an unbraced exponent is one character.
                if self.latex && self.peek().is_some_and(|d| d.is_ascii_digit()) {
                    let d = self.peek().unwrap_or('0');
                    self.at += 1;
                    out.push(Tok::Num(f64::from(d.to_digit(10).unwrap_or(0))));
                }
            }
            '(' | '[' | '{' => {
                self.at += 1;
                out.push(Tok::Open);
            }
            ')' | ']' | '}' => {
                self.at += 1;
                out.push(Tok::Close);
            }
            '|' => {
                self.at += 1;
                out.push(Tok::Bar);
            }
            '√' | '∛' | '∜' => {
                self.at += 1;
                match c {
                    '∛' | '∜' => out.extend([
                        Tok::Root(true),
                        Tok::Open,
                        Tok::Num(if c == '∛' { 3.0 } else { 4.0 }),
                        Tok::Close,
                    ]),
                    _ => out.push(Tok::Root(false)),
                }
            }
            'π' => {
                self.at += 1;
                out.push(self.pi_or_symbol());
            }
            '≤' | '⩽' => {
                self.at += 1;
                out.push(Tok::Cmp(Comparison::Le));
            }
            '≥' | '⩾' => {
                self.at += 1;
                out.push(Tok::Cmp(Comparison::Ge));
            }
            '<' | '>' => {
                self.at += 1;
                let strict = if c == '<' {
                    Comparison::Lt
                } else {
                    Comparison::Gt
                };
                if self.peek() == Some('=') {
                    self.at += 1;
                    out.push(Tok::Cmp(if c == '<' {
                        Comparison::Le
                    } else {
                        Comparison::Ge
                    }));
                } else {
                    out.push(Tok::Cmp(strict));
                }
            }
            '=' => {
                self.at += 1;
                out.push(Tok::Equals);
            }
            '\\' => self.command(out)?,
            c if c.is_ascii_alphabetic() || GREEK.iter().any(|(g, _)| *g == c) => {
                let word = self.word()?;
                self.classify(word, out)?;
            }
            '$' => self.at += 1,
            ',' | ';' if !self.latex => {
                return Err(format!(
                    "`{c}` is not part of a formula (decimals take a point: 0.5)"
                ))
            }
            ',' | ';' | '!' | ':' if self.latex => self.at += 1,
            c => return Err(format!("`{c}` is not part of a formula")),
        }
        Ok(())
    }

    /// `π` or `\pi`: the model's symbol of that name if it has one, else the constant.
    fn pi_or_symbol(&self) -> Tok {
        if self.known.iter().any(|s| s.name == "pi") {
            Tok::Sym("pi".to_string())
        } else {
            Tok::Pi
        }
    }

    /// Digits, a decimal point, and an exponent `e-6` / `E+12` when digits follow it.
    fn number(&mut self) -> std::result::Result<f64, String> {
        let start = self.at;
        while self.peek().is_some_and(|c| c.is_ascii_digit()) {
            self.at += 1;
        }
        if self.peek() == Some('.') {
            self.at += 1;
            while self.peek().is_some_and(|c| c.is_ascii_digit()) {
                self.at += 1;
            }
        }
        if matches!(self.peek(), Some('e' | 'E')) {
            let sign = usize::from(matches!(self.peek_at(1), Some('+' | '-')));
            if self.peek_at(1 + sign).is_some_and(|c| c.is_ascii_digit()) {
                self.at += 1 + sign;
                while self.peek().is_some_and(|c| c.is_ascii_digit()) {
                    self.at += 1;
                }
            }
        }
        let text: String = self.chars[start..self.at].iter().collect();
        if self.peek() == Some('.') {
            return Err(format!("`{text}.` is not a number"));
        }
        text.parse()
            .map_err(|_| format!("`{text}` is not a number"))
    }

    /// A run of letters with the subscripts, primes and superscripts that belong to a name.
    fn word(&mut self) -> std::result::Result<Vec<(String, bool)>, String> {
        let mut units: Vec<(String, bool)> = Vec::new();
        loop {
            let Some(c) = self.peek() else { break };
            if c.is_ascii_alphabetic() {
                self.at += 1;
                // A combining macron makes v̄ the symbol \bar v.
                if self.peek() == Some('\u{304}') {
                    self.at += 1;
                    units.push((format!("bar_{c}"), false));
                } else {
                    units.push((c.to_string(), false));
                }
            } else if let Some((_, name)) = GREEK.iter().find(|(g, _)| *g == c) {
                self.at += 1;
                units.push((name.to_string(), true));
            } else if c == '\\' && !units.is_empty() && self.greek_command_follows() {
                self.at += 1;
                let name = self.command_name();
                units.push((name, true));
            } else if let Some(s) = subscript(c) {
                self.at += 1;
                let mut sub = s.to_string();
                while let Some(s) = self.peek().and_then(subscript) {
                    sub.push(s);
                    self.at += 1;
                }
                units.push((format!("_{sub}"), false));
            } else if c == '_' && !units.is_empty() {
                self.at += 1;
                let sub = self.subscript()?;
                units.push((format!("_{sub}"), false));
            } else if c == '\'' && !units.is_empty() {
                self.at += 1;
                units.push(("_prime".to_string(), false));
            } else if c == '^' && !units.is_empty() {
                match self.name_superscript() {
                    Some(suffix) => units.push((suffix.to_string(), false)),
                    None => break,
                }
            } else if self.rest_starts_with("10")
                && units.iter().map(|u| u.0.as_str()).collect::<String>() == "log"
            {
                self.at += 2;
                return Ok(vec![("log10".to_string(), false)]);
            } else if c.is_ascii_digit() && !units.is_empty() && !self.latex {
                // `δ0`, `z0`, `t0` as PDFs paste δ_0, z_0, t_0: digits that follow a letter
                // belong to its name (spelled with or without `_`).
                let start = self.at;
                while self.peek().is_some_and(|c| c.is_ascii_digit()) {
                    self.at += 1;
                }
                units.push((self.chars[start..self.at].iter().collect(), false));
            } else {
                break;
            }
        }
        if units.is_empty() {
            return Err("a name is expected".to_string());
        }
        Ok(units)
    }

    fn greek_command_follows(&self) -> bool {
        let mut name = String::new();
        let mut i = 1;
        while let Some(c) = self.peek_at(i).filter(char::is_ascii_alphabetic) {
            name.push(c);
            i += 1;
        }
        GREEK_COMMANDS.contains(&name.as_str())
    }

    /// The superscripts that belong to a name: `^{(I)}`, `^{(II)}`, `^{(+)}`, `^{(-)}`, also
    /// without braces.
    fn name_superscript(&mut self) -> Option<&'static str> {
        for (spelling, suffix) in [
            ("^{(II)}", "_II"),
            ("^{(I)}", "_I"),
            ("^{(+)}", "_plus"),
            ("^{(-)}", "_minus"),
            ("^(II)", "_II"),
            ("^(I)", "_I"),
            ("^(+)", "_plus"),
            ("^(-)", "_minus"),
        ] {
            if self.rest_starts_with(spelling) {
                self.at += spelling.chars().count();
                return Some(suffix);
            }
        }
        None
    }

    /// A subscript after `_`: `{d,HALT}`, `\mathrm{HALT}`, `s`, `SL` (plain), `\text{…}`.
    fn subscript(&mut self) -> std::result::Result<String, String> {
        let raw: String = match self.peek() {
            Some('{') => {
                self.at += 1;
                let start = self.at;
                let mut depth = 1;
                while let Some(c) = self.peek() {
                    match c {
                        '{' => depth += 1,
                        '}' => {
                            depth -= 1;
                            if depth == 0 {
                                break;
                            }
                        }
                        _ => {}
                    }
                    self.at += 1;
                }
                if self.peek().is_none() {
                    return Err("a `{` is not closed".to_string());
                }
                let inner: String = self.chars[start..self.at].iter().collect();
                self.at += 1;
                inner
            }
            Some('\\') => {
                self.at += 1;
                let name = self.command_name();
                if matches!(name.as_str(), "mathrm" | "text" | "mathit" | "rm") {
                    return self.subscript();
                }
                name
            }
            Some(c) if c.is_ascii_alphanumeric() => {
                if self.latex {
                    self.at += 1;
                    c.to_string()
                } else {
                    let start = self.at;
                    while self.peek().is_some_and(|c| c.is_ascii_alphanumeric()) {
                        self.at += 1;
                    }
                    self.chars[start..self.at].iter().collect()
                }
            }
            _ => return Err("a subscript is missing after `_`".to_string()),
        };
        Ok(identifier(&raw))
    }

    fn command_name(&mut self) -> String {
        let start = self.at;
        while self.peek().is_some_and(|c| c.is_ascii_alphabetic()) {
            self.at += 1;
        }
        self.chars[start..self.at].iter().collect()
    }

    /// A word as tokens: the quantity's name when `=` follows it at the start, a function or π
    /// when it names one and no symbol does, else the fewest known symbols that spell it (a
    /// word is a run of letters, each unit a letter, a Greek letter's name flagged `true`, or a
    /// subscript or superscript of a name: `_s`, `_prime`, `_I`).
    fn classify(
        &mut self,
        units: Vec<(String, bool)>,
        out: &mut Vec<Tok>,
    ) -> std::result::Result<(), String> {
        let text: String = units.iter().map(|u| u.0.as_str()).collect();
        if out.is_empty() {
            let mut next = self.at;
            while self.chars.get(next).is_some_and(|c| c.is_whitespace()) {
                next += 1;
            }
            if self.chars.get(next) == Some(&'=') {
                out.push(Tok::Lhs(text));
                return Ok(());
            }
        }
        let is_symbol = self.known.iter().any(|s| s.name == text);
        if !is_symbol {
            if let Some(f) = Func::named(&text) {
                out.push(Tok::Func(f));
                return Ok(());
            }
            if matches!(text.as_str(), "pi" | "PI") {
                out.push(Tok::Pi);
                return Ok(());
            }
        }
        let names = split(&units, self.known).ok_or_else(|| unknown(&text, self.known))?;
        out.extend(names.into_iter().map(Tok::Sym));
        Ok(())
    }

    fn command(&mut self, out: &mut Vec<Tok>) -> std::result::Result<(), String> {
        self.at += 1;
        let name = self.command_name();
        if name.is_empty() {
            // `\,` `\;` `\!` `\ ` (spacing), `\{` `\}` `\|`.
            let c = self.peek();
            self.at += 1;
            match c {
                Some('{') => out.push(Tok::Open),
                Some('}') => out.push(Tok::Close),
                Some('|') => out.push(Tok::Bar),
                Some(',' | ';' | '!' | ' ' | ':' | '>') => {}
                Some(c) => return Err(format!("`\\{c}` is not part of a formula")),
                None => return Err("a `\\` ends the formula".to_string()),
            }
            return Ok(());
        }
        match name.as_str() {
            "quad" | "qquad" | "displaystyle" | "textstyle" | "mathrm" | "mathit" | "rm"
            | "operatorname" | "mathbf" | "boldsymbol" => {}
            "frac" | "dfrac" | "tfrac" => {
                out.push(Tok::Frac);
                // `\frac12`: unbraced arguments are one character each.
                for _ in 0..2 {
                    while self.peek() == Some(' ') {
                        self.at += 1;
                    }
                    if let Some(d) = self.peek().filter(char::is_ascii_digit) {
                        self.at += 1;
                        out.push(Tok::Num(f64::from(d.to_digit(10).unwrap_or(0))));
                    } else {
                        break;
                    }
                }
            }
            "sqrt" => {
                while self.peek() == Some(' ') {
                    self.at += 1;
                }
                // The index's `[…]` is lexed as a group.
                out.push(Tok::Root(self.peek() == Some('[')));
            }
            "left" | "right" | "big" | "Big" | "bigg" | "Bigg" | "bigl" | "bigr" | "Bigl"
            | "Bigr" | "biggl" | "biggr" => {
                while self.peek() == Some(' ') {
                    self.at += 1;
                }
                match self.peek() {
                    Some('(' | '[') => out.push(Tok::Open),
                    Some(')' | ']') => out.push(Tok::Close),
                    Some('|') => out.push(Tok::Bar),
                    Some('.') => {}
                    Some('\\') => {
                        self.at += 1;
                        let delim = self.command_name();
                        match delim.as_str() {
                            "lbrace" | "langle" | "lbrack" => out.push(Tok::Open),
                            "rbrace" | "rangle" | "rbrack" => out.push(Tok::Close),
                            "vert" | "lvert" | "rvert" | "mid" => out.push(Tok::Bar),
                            "{" | "" if self.peek() == Some('{') => {
                                self.at += 1;
                                out.push(Tok::Open);
                            }
                            "" if self.peek() == Some('}') => {
                                self.at += 1;
                                out.push(Tok::Close);
                            }
                            _ => return Err(format!("`\\{name}` needs a bracket")),
                        }
                        return Ok(());
                    }
                    _ => return Err(format!("`\\{name}` needs a bracket")),
                }
                self.at += 1;
            }
            "vert" | "lvert" | "rvert" | "mid" => out.push(Tok::Bar),
            "cdot" | "times" | "ast" => out.push(Tok::Op('*')),
            "div" => out.push(Tok::Op('/')),
            "le" | "leq" | "leqslant" => out.push(Tok::Cmp(Comparison::Le)),
            "ge" | "geq" | "geqslant" => out.push(Tok::Cmp(Comparison::Ge)),
            "lt" => out.push(Tok::Cmp(Comparison::Lt)),
            "gt" => out.push(Tok::Cmp(Comparison::Gt)),
            "pi" => out.push(self.pi_or_symbol()),
            "log" => {
                // `\log_{10}` is the decimal logarithm; a bare `\log` is ambiguous.
                if self.rest_starts_with("_{10}") || self.rest_starts_with("_10") {
                    self.at += if self.peek_at(1) == Some('{') { 5 } else { 3 };
                    out.push(Tok::Func(Func::Log10));
                } else {
                    return Err("`\\log` is ambiguous: write \\ln (natural) or log10".to_string());
                }
            }
            "bar" | "overline" | "hat" | "tilde" => {
                // `\bar{v}`, `\bar v`: one symbol, `bar_v`.
                while self.peek() == Some(' ') {
                    self.at += 1;
                }
                let inner = if self.peek() == Some('{') {
                    self.at += 1;
                    let start = self.at;
                    while self.peek().is_some_and(|c| c != '}') {
                        self.at += 1;
                    }
                    if self.peek().is_none() {
                        return Err("a `{` is not closed".to_string());
                    }
                    let inner: String = self.chars[start..self.at].iter().collect();
                    self.at += 1;
                    inner
                } else {
                    let c = self.peek().ok_or("`\\bar` needs a symbol")?;
                    self.at += 1;
                    c.to_string()
                };
                let accent = if name == "overline" { "bar" } else { name.as_str() };
                let mut units = vec![(format!("{accent}_{}", identifier(&inner)), false)];
                // Its own subscript and superscripts.
                let rest = self.word_tail()?;
                units.extend(rest);
                self.classify(units, out)?;
            }
            name if GREEK_COMMANDS.contains(&name) => {
                let mut units = vec![(name.to_string(), true)];
                units.extend(self.word_tail()?);
                self.classify(units, out)?;
            }
            name => match Func::named(name) {
                Some(f) => out.push(Tok::Func(f)),
                None => {
                    return Err(format!(
                        "`\\{name}` is not part of a formula this reader knows (\\frac, \\sqrt, \
                         \\left, \\cdot, \\ln, \\exp, Greek letters …)"
                    ))
                }
            },
        }
        Ok(())
    }

    /// After a Greek command or `\bar{…}`: subscripts, primes and name superscripts, and
    /// letters that follow directly (`\mu_s`, `\varphi_c`, `\eta'`).
    fn word_tail(&mut self) -> std::result::Result<Vec<(String, bool)>, String> {
        let mut units = Vec::new();
        loop {
            match self.peek() {
                Some('_') => {
                    self.at += 1;
                    units.push((format!("_{}", self.subscript()?), false));
                }
                Some('\'') => {
                    self.at += 1;
                    units.push(("_prime".to_string(), false));
                }
                Some('^') => match self.name_superscript() {
                    Some(s) => units.push((s.to_string(), false)),
                    None => break,
                },
                _ => break,
            }
        }
        Ok(units)
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

struct Parser {
    tokens: Vec<Tok>,
    at: usize,
    names: Vec<String>,
    depth: usize,
    /// Open `|…|` groups: a bar after an operand closes the innermost.
    bars: usize,
}

type Parsed<T> = std::result::Result<T, String>;

impl Parser {
    fn new(tokens: Vec<Tok>) -> Self {
        Self {
            tokens,
            at: 0,
            names: Vec::new(),
            depth: 0,
            bars: 0,
        }
    }

    fn peek(&self) -> Option<&Tok> {
        self.tokens.get(self.at)
    }

    fn next(&mut self) -> Option<Tok> {
        let t = self.tokens.get(self.at).cloned();
        self.at += 1;
        t
    }

    fn formula(mut self) -> Parsed<Formula> {
        if self.tokens.is_empty() {
            return Err("the formula is empty".to_string());
        }
        // An optional left side: one name, then `=`.
        let lhs = match (self.tokens.first(), self.tokens.get(1)) {
            (Some(Tok::Lhs(name)), Some(Tok::Equals)) => {
                let name = name.clone();
                self.at = 2;
                Some(name)
            }
            _ => None,
        };
        if self.tokens[self.at..].contains(&Tok::Equals) {
            return Err(
                "an `=` is read only after the quantity's name on the left (`v_avg = …`)"
                    .to_string(),
            );
        }
        let expr = self.sum()?;
        let condition = match self.peek() {
            Some(Tok::Cmp(c)) => {
                let c = *c;
                self.at += 1;
                Some((c, self.sum()?))
            }
            _ => None,
        };
        match self.peek() {
            None => {}
            Some(Tok::Cmp(_)) => return Err("only one comparison is read".to_string()),
            Some(Tok::Close) => return Err("a `)` has no `(`".to_string()),
            Some(Tok::Bar) => return Err("a `|` has no partner".to_string()),
            Some(t) => return Err(format!("unexpected {}", describe(t))),
        }
        Ok(Formula {
            lhs,
            expr,
            condition,
            names: self.names,
        })
    }

    fn enter(&mut self) -> Parsed<()> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            Err(format!("the formula nests more than {MAX_DEPTH} levels deep"))
        } else {
            Ok(())
        }
    }

    fn sum(&mut self) -> Parsed<Node> {
        let mut left = self.product()?;
        while let Some(Tok::Op(c @ ('+' | '-'))) = self.peek() {
            let c = *c;
            self.at += 1;
            let right = self.product()?;
            left = if c == '+' {
                Node::Add(Box::new(left), Box::new(right))
            } else {
                Node::Sub(Box::new(left), Box::new(right))
            };
        }
        Ok(left)
    }

    /// Whether the next token starts an operand (an implicit product follows).
    fn operand_follows(&self) -> bool {
        match self.peek() {
            Some(Tok::Num(_) | Tok::Sym(_) | Tok::Func(_) | Tok::Pi | Tok::Open)
            | Some(Tok::Frac | Tok::Root(_)) => true,
            Some(Tok::Bar) => self.bars == 0,
            _ => false,
        }
    }

    fn product(&mut self) -> Parsed<Node> {
        let mut left = self.unary()?;
        loop {
            match self.peek() {
                Some(Tok::Op(c @ ('*' | '/'))) => {
                    let c = *c;
                    self.at += 1;
                    let right = self.unary()?;
                    left = if c == '*' {
                        Node::Mul(Box::new(left), Box::new(right))
                    } else {
                        Node::Div(Box::new(left), Box::new(right))
                    };
                }
                _ if self.operand_follows() => {
                    let right = self.power()?;
                    left = Node::Mul(Box::new(left), Box::new(right));
                }
                _ => return Ok(left),
            }
        }
    }

    /// A unary minus binds less tightly than a power: −x² = −(x²).
    fn unary(&mut self) -> Parsed<Node> {
        match self.peek() {
            Some(Tok::Op('-')) => {
                self.at += 1;
                self.enter()?;
                let operand = self.unary()?;
                self.depth -= 1;
                Ok(match operand {
                    Node::Num(x) => Node::Num(-x),
                    other => Node::Neg(Box::new(other)),
                })
            }
            Some(Tok::Op('+')) => {
                self.at += 1;
                self.enter()?;
                let operand = self.unary()?;
                self.depth -= 1;
                Ok(operand)
            }
            _ => self.power(),
        }
    }

    fn power(&mut self) -> Parsed<Node> {
        let base = self.primary()?;
        if let Some(Tok::Op('^')) = self.peek() {
            self.at += 1;
            self.enter()?;
            // Right-associative, and the exponent may carry its own sign: 2^-1.
            let exponent = self.unary()?;
            self.depth -= 1;
            return Ok(Node::Pow(Box::new(base), Box::new(exponent)));
        }
        Ok(base)
    }

    fn primary(&mut self) -> Parsed<Node> {
        self.enter()?;
        let node = match self.next() {
            Some(Tok::Num(x)) => Node::Num(x),
            Some(Tok::Pi) => Node::Pi,
            Some(Tok::Sym(name)) => Node::Sym(self.intern(&name)),
            Some(Tok::Open) => {
                let inner = self.sum()?;
                match self.next() {
                    Some(Tok::Close) => inner,
                    _ => return Err("a `(` is not closed".to_string()),
                }
            }
            Some(Tok::Bar) => {
                self.bars += 1;
                let inner = self.sum()?;
                self.bars -= 1;
                match self.next() {
                    Some(Tok::Bar) => Node::Call(Func::Abs, Box::new(inner)),
                    _ => return Err("a `|` is not closed".to_string()),
                }
            }
            // The argument: a parenthesised group, to which a power then applies (`sqrt(x)^3`
            // is (√x)³), or the next power (`\ln x^2` is ln(x²), `√x`).
            Some(Tok::Func(f)) => Node::Call(f, Box::new(self.argument()?)),
            Some(Tok::Root(false)) => Node::Call(Func::Sqrt, Box::new(self.argument()?)),
            Some(Tok::Root(true)) => {
                let index = self.primary()?;
                let arg = self.argument()?;
                let inverse = Node::Div(Box::new(Node::Num(1.0)), Box::new(index));
                Node::Pow(Box::new(arg), Box::new(inverse))
            }
            Some(Tok::Frac) => {
                let num = self.primary()?;
                let den = self.primary()?;
                Node::Div(Box::new(num), Box::new(den))
            }
            Some(t) => return Err(format!("an operand is missing before {}", describe(&t))),
            None => return Err("the formula ends where an operand is expected".to_string()),
        };
        self.depth -= 1;
        Ok(node)
    }

    /// A function's argument: a group alone, or else a power.
    fn argument(&mut self) -> Parsed<Node> {
        if self.peek() == Some(&Tok::Open) {
            self.primary()
        } else {
            self.power()
        }
    }

    fn intern(&mut self, name: &str) -> usize {
        match self.names.iter().position(|n| n == name) {
            Some(i) => i,
            None => {
                self.names.push(name.to_string());
                self.names.len() - 1
            }
        }
    }

}

/// The known symbol a spelling names, allowing a Greek variant (`phi` for `varphi`).
fn resolve(spelling: &str, known: &[Symbol]) -> Option<String> {
    if known.iter().any(|s| s.name == spelling) {
        return Some(spelling.to_string());
    }
    let v = variant(spelling)?;
    known.iter().any(|s| s.name == v).then_some(v)
}

/// `units` split into the fewest known symbols; a subscript unit never starts a symbol, and a
/// Greek letter followed by a letter may take it as its subscript (`μs` → `mu_s`).
fn split(units: &[(String, bool)], known: &[Symbol]) -> Option<Vec<String>> {
    let n = units.len();
    // best[i]: the fewest symbols spelling units[..i], with the spelling.
    let mut best: Vec<Option<Vec<String>>> = vec![None; n + 1];
    best[0] = Some(Vec::new());
    for i in 0..n {
        let Some(prefix) = best[i].clone() else {
            continue;
        };
        if units[i].0.starts_with(|c: char| c == '_' || c.is_ascii_digit()) {
            continue;
        }
        for j in (i + 1..=n).rev() {
            for spelling in spellings(&units[i..j]) {
                if let Some(name) = resolve(&spelling, known) {
                    let mut candidate = prefix.clone();
                    candidate.push(name);
                    if best[j].as_ref().is_none_or(|b| candidate.len() < b.len()) {
                        best[j] = Some(candidate);
                    }
                    break;
                }
            }
        }
    }
    best[n].take()
}

/// The spellings of a run of units: joined as they are, and with `_` after a Greek letter
/// that a letter follows.
fn spellings(units: &[(String, bool)]) -> Vec<String> {
    let mut out = vec![String::new()];
    for (k, (text, _)) in units.iter().enumerate() {
        let digits = text.starts_with(|c: char| c.is_ascii_digit());
        let after_greek = k > 0 && (units[k - 1].1 || digits) && !text.starts_with('_');
        let mut next = Vec::new();
        for s in &out {
            next.push(format!("{s}{text}"));
            if after_greek {
                next.push(format!("{s}_{text}"));
            }
        }
        out = next;
        if out.len() > 64 {
            out.truncate(64);
        }
    }
    out
}

/// The message for a name that spells no known symbol: the nearest known names.
fn unknown(text: &str, known: &[Symbol]) -> String {
    let mut near: Vec<(usize, &str)> = known
        .iter()
        .map(|s| (distance(&text.to_lowercase(), &s.name.to_lowercase()), s.name.as_str()))
        .collect();
    near.sort_by_key(|(d, _)| *d);
    let near: Vec<&str> = near.iter().take(3).map(|(_, n)| *n).collect();
    if text == "log" {
        return "`log` is ambiguous: write ln (natural) or log10".to_string();
    }
    if text == "tau" || text == "e" || text == "E" {
        return format!(
            "unknown symbol {text} (the model has no symbol of that name; the constants are pi \
             and exp(1)); nearest: {}; all with --symbols",
            near.join(", ")
        );
    }
    format!(
        "unknown symbol {text}; nearest: {} (all with --symbols)",
        near.join(", ")
    )
}

/// Levenshtein distance.
fn distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != *cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}

fn describe(t: &Tok) -> String {
    match t {
        Tok::Op(c) => format!("`{c}`"),
        Tok::Close => "`)`".to_string(),
        Tok::Bar => "`|`".to_string(),
        Tok::Cmp(c) => format!("`{}`", c.plain()),
        Tok::Equals => "`=`".to_string(),
        _ => "this".to_string(),
    }
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
        assert_eq!(value(r"\frac{T}{2}\left(1+\varphi\Theta\right)"), 0.25 * 1.6);
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
        assert!(err("g*T*(").contains("ends where an operand"), "{}", err("g*T*("));
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
