//! A formula as people write it, plain (`g*T*phi^3*Gamma`) or in a LaTeX subset
//! (`\frac{gT}{16}\left(\mu_s^2 + \mu_d\right)`), turned into the plain syntax the evaluator
//! reads, with every symbol as an identifier of [`super::symbols`] (`\mu_s` → `mu_s`,
//! `t_{SL}^{(I)}` → `t_SL_I`).
//!
//! LaTeX is recognised by a backslash, `{` or `}`; there a letter is a symbol of its own, so
//! `gT` is `g*T` (implicit products get their `*`). Supported: `\frac`, `\sqrt`, `\left`/`\right`,
//! `\sqrt[n]{}`, `\cdot`, `\times`, powers `^2` and `^{…}`, subscripts, Greek letters, `\pi`, and the
//! superscripts that belong to a name: `^{(I)}`, `^{(II)}`, `^{(+)}`, `^{(-)}`, `'`.

use crate::error::{Error, Result};

/// Whether `text` is LaTeX rather than plain syntax.
pub fn is_latex(text: &str) -> bool {
    text.contains('\\') || text.contains('{') || text.contains('}')
}

/// `text` in plain syntax: LaTeX converted, plain text as it is.
pub fn to_plain(text: &str) -> Result<String> {
    if is_latex(text) {
        Latex::new(text).expression()
    } else {
        Ok(text.to_string())
    }
}

/// A token of the LaTeX subset.
#[derive(Clone, Debug, PartialEq)]
enum Token {
    Number(String),
    Symbol(String),
    Open,
    Close,
    Op(char),
    /// A group `{…}` already converted (a fraction, a root, a braced power).
    Group(String),
}

impl Token {
    /// Ends an operand: a `*` goes between it and a following operand.
    fn ends_operand(&self) -> bool {
        matches!(
            self,
            Token::Number(_) | Token::Symbol(_) | Token::Close | Token::Group(_)
        )
    }

    /// Starts an operand.
    fn starts_operand(&self) -> bool {
        matches!(
            self,
            Token::Number(_) | Token::Symbol(_) | Token::Open | Token::Group(_)
        )
    }
}

struct Latex<'a> {
    chars: Vec<char>,
    at: usize,
    source: &'a str,
}

impl<'a> Latex<'a> {
    fn new(source: &'a str) -> Self {
        Self {
            chars: source.chars().collect(),
            at: 0,
            source,
        }
    }

    fn error(&self, reason: impl Into<String>) -> Error {
        Error::Formula {
            formula: crate::error::excerpt(self.source, 80),
            reason: reason.into(),
        }
    }

    fn peek(&self) -> Option<char> {
        self.chars.get(self.at).copied()
    }

    fn skip_spaces(&mut self) {
        while self.peek().is_some_and(char::is_whitespace) {
            self.at += 1;
        }
    }

    /// The whole text as one expression.
    fn expression(&mut self) -> Result<String> {
        let out = self.sequence(None)?;
        match self.peek() {
            None => Ok(out),
            Some(c) => Err(self.error(format!("unexpected `{c}`"))),
        }
    }

    /// Tokens up to `end` (a closing `}`), joined with the implicit products.
    fn sequence(&mut self, end: Option<char>) -> Result<String> {
        let mut tokens: Vec<Token> = Vec::new();
        loop {
            self.skip_spaces();
            let Some(c) = self.peek() else {
                if end.is_some() {
                    return Err(self.error("a `{` is not closed"));
                }
                break;
            };
            if Some(c) == end {
                self.at += 1;
                break;
            }
            let token = self.token(c)?;
            // A power binds to what it follows: `^` is an operator token, its exponent a group.
            tokens.push(token);
        }
        Ok(join(&tokens))
    }

    /// A braced group `{…}` converted, or one character/command as an argument.
    fn argument(&mut self) -> Result<String> {
        self.skip_spaces();
        match self.peek() {
            Some('{') => {
                self.at += 1;
                Ok(format!("({})", self.sequence(Some('}'))?))
            }
            Some(c) => {
                let t = self.token(c)?;
                Ok(join(&[t]))
            }
            None => Err(self.error("an argument is missing at the end")),
        }
    }

    fn command(&mut self) -> String {
        let start = self.at;
        while self.peek().is_some_and(|c| c.is_ascii_alphabetic()) {
            self.at += 1;
        }
        if self.at == start {
            // `\,`, `\;`, `\!`, `\ `: spacing.
            self.at += 1;
            return String::new();
        }
        self.chars[start..self.at].iter().collect()
    }

    fn token(&mut self, c: char) -> Result<Token> {
        if c.is_ascii_digit() || c == '.' {
            let start = self.at;
            while self.peek().is_some_and(|c| c.is_ascii_digit() || c == '.') {
                self.at += 1;
            }
            return Ok(Token::Number(self.chars[start..self.at].iter().collect()));
        }
        self.at += 1;
        match c {
            '(' | '[' => Ok(Token::Open),
            ')' | ']' => Ok(Token::Close),
            '+' | '-' | '*' | '/' => Ok(Token::Op(c)),
            '^' => {
                let exponent = self.argument()?;
                Ok(Token::Group(format!("^{exponent}")))
            }
            '{' => Ok(Token::Group(format!("({})", self.sequence(Some('}'))?))),
            '\\' => self.backslash(),
            c if c.is_alphabetic() => {
                let name = self.name_tail(c.to_string())?;
                Ok(Token::Symbol(name))
            }
            c => Err(self.error(format!("`{c}` is not part of a formula"))),
        }
    }

    /// A symbol's subscript and the superscripts that belong to its name.
    fn name_tail(&mut self, mut name: String) -> Result<String> {
        loop {
            match self.peek() {
                Some('_') => {
                    self.at += 1;
                    let sub = match self.peek() {
                        Some('{') => {
                            self.at += 1;
                            let start = self.at;
                            while self.peek().is_some_and(|c| c != '}') {
                                self.at += 1;
                            }
                            let sub: String = self.chars[start..self.at].iter().collect();
                            self.at += 1;
                            sub
                        }
                        Some('\\') => {
                            self.at += 1;
                            self.command()
                        }
                        Some(c) => {
                            self.at += 1;
                            c.to_string()
                        }
                        None => return Err(self.error("a subscript is missing")),
                    };
                    name = format!("{name}_{}", identifier(&sub));
                }
                Some('\'') => {
                    self.at += 1;
                    name.push_str("_prime");
                }
                Some('^') => {
                    let rest: String = self.chars[self.at..].iter().take(7).collect();
                    let part = [
                        ("^{(II)}", "_II"),
                        ("^{(I)}", "_I"),
                        ("^{(+)}", "_plus"),
                        ("^{(-)}", "_minus"),
                    ]
                    .into_iter()
                    .find(|(p, _)| rest.starts_with(p));
                    match part {
                        Some((p, suffix)) => {
                            self.at += p.chars().count();
                            name.push_str(suffix);
                        }
                        None => return Ok(name),
                    }
                }
                _ => return Ok(name),
            }
        }
    }

    fn backslash(&mut self) -> Result<Token> {
        let command = self.command();
        match command.as_str() {
            "" | "quad" | "qquad" => Ok(Token::Group(String::new())),
            "frac" | "dfrac" | "tfrac" => {
                let (num, den) = (self.argument()?, self.argument()?);
                Ok(Token::Group(format!("({num}/{den})")))
            }
            "sqrt" => {
                self.skip_spaces();
                if self.peek() == Some('[') {
                    // \sqrt[n]{x} = x^(1/n).
                    self.at += 1;
                    let start = self.at;
                    while self.peek().is_some_and(|c| c != ']') {
                        self.at += 1;
                    }
                    if self.peek().is_none() {
                        return Err(self.error("a `[` is not closed"));
                    }
                    let index: String = self.chars[start..self.at].iter().collect();
                    self.at += 1;
                    let index = Latex::new(&index).expression()?;
                    return Ok(Token::Group(format!(
                        "({})^(1/({index}))",
                        self.argument()?
                    )));
                }
                Ok(Token::Group(format!("sqrt({})", self.argument()?)))
            }
            "left" | "right" | "big" | "Big" | "bigl" | "bigr" | "Bigl" | "Bigr" => {
                self.skip_spaces();
                match self.peek() {
                    Some('(' | '[') => {
                        self.at += 1;
                        Ok(Token::Open)
                    }
                    Some(')' | ']') => {
                        self.at += 1;
                        Ok(Token::Close)
                    }
                    Some('.') => {
                        self.at += 1;
                        Ok(Token::Group(String::new()))
                    }
                    _ => Err(self.error(format!("`\\{command}` needs a bracket"))),
                }
            }
            "cdot" | "times" => Ok(Token::Op('*')),
            "pi" => Ok(Token::Symbol("PI".to_string())),
            name => Ok(Token::Symbol(self.name_tail(name.to_string())?)),
        }
    }
}

/// Tokens joined, with `*` between adjacent operands (`g T` → `g*T`, `2(` → `2*(`).
fn join(tokens: &[Token]) -> String {
    let mut out = String::new();
    let mut previous: Option<&Token> = None;
    for t in tokens {
        if let Token::Group(g) = t {
            if g.is_empty() {
                continue;
            }
        }
        let power = matches!(t, Token::Group(g) if g.starts_with('^'));
        if !power && previous.is_some_and(Token::ends_operand) && t.starts_operand() {
            out.push('*');
        }
        match t {
            Token::Number(s) | Token::Symbol(s) | Token::Group(s) => out.push_str(s),
            Token::Open => out.push('('),
            Token::Close => out.push(')'),
            Token::Op(c) => out.push(*c),
        }
        previous = Some(t);
    }
    out
}

/// A LaTeX symbol as an identifier: `\tau_{SL}` → `tau_SL`, `u_s^{(-)}` → `u_s_minus`,
/// `\eta'` → `eta_prime`, `\mu_{d,HALT}` → `mu_d_HALT`.
pub fn identifier(tex: &str) -> String {
    let mut s = tex.trim().to_string();
    for (from, to) in [
        ("^{(II)}", "_II"),
        ("^{(I)}", "_I"),
        ("^{(+)}", "_plus"),
        ("^{(-)}", "_minus"),
        ("'", "_prime"),
        ("\\bar ", "bar_"),
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

    #[test]
    fn latex_becomes_plain_syntax_with_explicit_products() {
        let cases = [
            (r"\frac{gT}{16}", "((g*T)/(16))"),
            (r"g T \varphi^3 \Gamma", "g*T*varphi^3*Gamma"),
            (r"\sqrt{\mu_s^2 + \mu_d}", "sqrt((mu_s^2+mu_d))"),
            (
                r"2\left(1 - \frac{\varphi}{2\mu_s}\right)",
                "2*(1-((varphi)/(2*mu_s)))",
            ),
            (r"T \tau_{SL}", "T*tau_SL"),
            (r"t_0^{(I)} - \Delta^{(I)}", "t_0_I-Delta_I"),
            (r"u_s^{(-)}\eta'", "u_s_minus*eta_prime"),
            (r"2\pi/\omega", "2*PI/omega"),
            (r"\mu_s \cdot 2", "mu_s*2"),
            (r"\sqrt[3]{\varphi}", "((varphi))^(1/(3))"),
        ];
        for (latex, plain) in cases {
            assert_eq!(to_plain(latex).unwrap(), plain, "{latex}");
        }
        assert_eq!(to_plain("g*T*phi^3").unwrap(), "g*T*phi^3");
        assert!(to_plain(r"\frac{1}{2").is_err());
        assert!(to_plain(r"3 # 4 \cdot x").is_err());
    }

    #[test]
    fn tex_symbols_become_identifiers() {
        assert_eq!(identifier(r"\tau_{SL}"), "tau_SL");
        assert_eq!(identifier(r"u_s^{(-)}"), "u_s_minus");
        assert_eq!(identifier(r"t_{SL}^{(I)}"), "t_SL_I");
        assert_eq!(identifier(r"\eta'"), "eta_prime");
        assert_eq!(identifier(r"\mu_{d,HALT}^{(II)}"), "mu_d_HALT_II");
    }
}
