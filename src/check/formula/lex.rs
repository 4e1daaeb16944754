//! The formula's characters as tokens: numbers (with exponents and superscripts), the model's
//! symbols (a run of letters split by [`super::names`]), functions, operators, brackets, the
//! LaTeX commands of the subset, and pasted typography (−, ·, ×, √, ≤) as what it stands for.

use super::names::{split, unknown};
use super::{identifier, Comparison, Func, Symbol};

/// A token of a formula.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Tok {
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
    "alpha",
    "beta",
    "gamma",
    "delta",
    "epsilon",
    "varepsilon",
    "zeta",
    "eta",
    "theta",
    "vartheta",
    "iota",
    "kappa",
    "lambda",
    "mu",
    "nu",
    "xi",
    "rho",
    "varrho",
    "sigma",
    "varsigma",
    "tau",
    "upsilon",
    "phi",
    "varphi",
    "chi",
    "psi",
    "omega",
    "Gamma",
    "Delta",
    "Theta",
    "Lambda",
    "Xi",
    "Sigma",
    "Phi",
    "Omega",
];

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

pub(super) struct Lexer<'a> {
    chars: Vec<char>,
    at: usize,
    latex: bool,
    known: &'a [Symbol],
}

impl<'a> Lexer<'a> {
    pub(super) fn new(text: &str, known: &'a [Symbol]) -> Self {
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
        s.chars()
            .enumerate()
            .all(|(i, c)| self.peek_at(i) == Some(c))
    }

    pub(super) fn tokens(mut self) -> std::result::Result<Vec<Tok>, String> {
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
        if c.is_ascii_digit() || (c == '.' && self.peek_at(1).is_some_and(|d| d.is_ascii_digit())) {
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
            let exponent = digits
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| format!("the superscript `{digits}` is not a number"))?;
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
        match text.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            Ok(_) => Err(format!("`{text}` is beyond double precision")),
            Err(_) => Err(format!("`{text}` is not a number")),
        }
    }

    /// A run of letters with the subscripts, primes and superscripts that belong to a name.
    fn word(&mut self) -> std::result::Result<Vec<(String, bool)>, String> {
        let mut units: Vec<(String, bool)> = Vec::new();
        while let Some(c) = self.peek() {
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

    /// The text of a braced group `{…}` (braces nested inside kept), the `{` next.
    fn braced(&mut self) -> std::result::Result<String, String> {
        self.at += 1;
        let start = self.at;
        let mut depth = 1;
        while let Some(c) = self.peek() {
            match c {
                '{' => depth += 1,
                '}' if depth == 1 => {
                    let inner: String = self.chars[start..self.at].iter().collect();
                    self.at += 1;
                    return Ok(inner);
                }
                '}' => depth -= 1,
                _ => {}
            }
            self.at += 1;
        }
        Err("a `{` is not closed".to_string())
    }

    /// A subscript after `_`: `{d,HALT}`, `\mathrm{HALT}`, `s`, `SL` (plain), `\text{…}`.
    fn subscript(&mut self) -> std::result::Result<String, String> {
        let raw: String = match self.peek() {
            Some('{') => self.braced()?,
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
                    self.braced()?
                } else {
                    let c = self.peek().ok_or("`\\bar` needs a symbol")?;
                    self.at += 1;
                    c.to_string()
                };
                let accent = if name == "overline" {
                    "bar"
                } else {
                    name.as_str()
                };
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
