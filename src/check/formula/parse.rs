//! Tokens into the expression tree, by precedence climbing: comparison < sum < product
//! (explicit and implicit) < unary minus < power (right-associative), with the nesting depth
//! bounded by [`super::MAX_DEPTH`].

use super::lex::Tok;
use super::{Formula, Func, Node, MAX_DEPTH};

pub(super) struct Parser {
    tokens: Vec<Tok>,
    at: usize,
    names: Vec<String>,
    depth: usize,
    /// Open `|…|` groups: a bar after an operand closes the innermost.
    bars: usize,
}

type Parsed<T> = std::result::Result<T, String>;

impl Parser {
    pub(super) fn new(tokens: Vec<Tok>) -> Self {
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

    pub(super) fn formula(mut self) -> Parsed<Formula> {
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
            Err(format!(
                "the formula nests more than {MAX_DEPTH} levels deep"
            ))
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
