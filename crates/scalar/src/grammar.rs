//! The one grammar of cagd-exact, for exact numbers and for expressions.
//!
//! ```text
//! expr     := term (('+' | '-') term)*
//! term     := unary (('*' | '/') unary | power)*      a power right after a factor multiplies it
//! unary    := ('-' | '+') unary | power
//! power    := atom ('^' exponent)?
//! exponent := INTEGER | '(' expr ')'                  an integer, |e| ≤ Limits::max_exponent
//! atom     := NUMBER | NAME | ROOT | '(' expr (',' expr)* ')'
//! ROOT     := ('sqrt' | '√') (DIGITS | '(' expr ')')
//! NUMBER   := DIGITS ('.' DIGITS)?                     exact: 0.125 is 1/8
//! ```
//!
//! `−` (U+2212) reads as `-`, `·` and `×` as `*`. Juxtaposition multiplies when the right
//! operand is a name, a root or a parenthesis: `3√2/4`, `u^2 v`, `(1 - v)(u, 0, u^3)`.
//!
//! The parser is generic over a [`Builder`], which says what a number, a name, a sum... are.
//! [`NumberBuilder`] evaluates to a [`Quadratic`]; the polynomial crate builds polynomials with
//! the same parser, so there is one grammar, written once.

use crate::{Exceeded, Expected, Found, Quadratic, ScalarError};
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// A stretch of the input, in 1-based character columns.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Span {
    /// First column.
    pub column: usize,
}

/// What a token is.
#[derive(Debug, Clone, PartialEq)]
pub enum TokenKind {
    /// A non-negative exact decimal literal.
    Number(BigRational),
    /// A one-letter name (a variable); a run of letters gives one token per letter.
    Name(String),
    /// `sqrt` or `√`.
    Root,
    /// `+`
    Plus,
    /// `-`
    Minus,
    /// `*`
    Star,
    /// `/`
    Slash,
    /// `^`
    Caret,
    /// `(`
    LParen,
    /// `)`
    RParen,
    /// `,`
    Comma,
    /// End of input.
    End,
}

/// A token and where it starts.
#[derive(Debug, Clone, PartialEq)]
pub struct Token {
    /// What it is.
    pub kind: TokenKind,
    /// Where it starts.
    pub span: Span,
}

/// Resource limits of the parser, so hostile input is refused quickly.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// Largest |exponent| in `x^e` (`(1/3)^(10^9)` is refused, not attempted).
    pub max_exponent: u32,
    /// Deepest nesting of parentheses and unary signs.
    pub max_depth: usize,
    /// Most decimal digits in one numeric literal, and in the numerator and the denominator
    /// of every value [`NumberBuilder`] computes (`2^5000` has 1506): a power that would be
    /// longer is refused before it is computed, so whatever is read prints to text that reads
    /// back.
    pub max_digits: usize,
    /// Longest input, in characters.
    pub max_length: usize,
}

impl Limits {
    /// The most bits a numerator or denominator may have: at least `max_digits` decimal
    /// digits' worth (the exact count is [`Limits::check_digits`]'s).
    pub fn max_bits(&self) -> u64 {
        // log2(10) < 3.3220; one more bit for rounding.
        let digits = u64::try_from(self.max_digits).unwrap_or(u64::MAX);
        digits.saturating_mul(33_220) / 10_000 + 1
    }

    /// `Err` naming the digits when a part of `x` (a numerator or a denominator of a or b in
    /// a + b√d) has more than `max_digits` decimal digits.
    ///
    /// ```
    /// use cagd_scalar::{parse_number, Limits};
    /// let ten = Limits { max_digits: 10, ..Limits::default() };
    /// assert!(ten.check_digits(&parse_number("9999999999/7").unwrap()).is_ok());
    /// assert_eq!(
    ///     ten.check_digits(&parse_number("10^10").unwrap()).unwrap_err().to_string(),
    ///     "limit exceeded: a number of 11 digits is longer than the limit of 10 digits"
    /// );
    /// ```
    pub fn check_digits(&self, x: &Quadratic) -> Result<(), ScalarError> {
        // bits - 1 <= log2|n| < bits, so the digits are about bits · log10(2): only a
        // borderline part needs its digits counted, and a part far past the limit is not
        // printed to be counted.
        let low = self.max_bits().saturating_sub(8);
        let far = self.max_bits().saturating_mul(2).saturating_add(64);
        for part in [x.rational_part(), x.root_part()] {
            if part.bits() <= low {
                continue;
            }
            for n in [part.numer(), part.denom()] {
                if n.bits() > far {
                    return Err(ScalarError::Limit {
                        what: Exceeded::Digits {
                            max: self.max_digits,
                        },
                    });
                }
                if n.bits() > low {
                    let digits = n.magnitude().to_string().len();
                    if digits > self.max_digits {
                        return Err(ScalarError::Limit {
                            what: Exceeded::DigitsCounted {
                                digits,
                                max: self.max_digits,
                            },
                        });
                    }
                }
            }
        }
        Ok(())
    }
}

/// The largest bit length of the parts of `x`.
fn bits(x: &Quadratic) -> u64 {
    x.rational_part().bits().max(x.root_part().bits())
}

/// The most digits a value may reach while a parenthesized exponent is read, whatever the
/// limits: an exponent is an integer of a few digits in the end.
const EXPONENT_DIGITS: usize = 1000;

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_exponent: 1000,
            max_depth: 200,
            max_digits: 10_000,
            max_length: 1_000_000,
        }
    }
}

/// Describes a token for error messages.
fn describe(kind: &TokenKind) -> Found {
    let quoted = |s: &str| Found::Quoted(s.to_string());
    match kind {
        TokenKind::Number(q) => Found::Number(q.to_string()),
        TokenKind::Name(n) => Found::Quoted(n.clone()),
        TokenKind::Root => quoted("sqrt"),
        TokenKind::Plus => quoted("+"),
        TokenKind::Minus => quoted("-"),
        TokenKind::Star => quoted("*"),
        TokenKind::Slash => quoted("/"),
        TokenKind::Caret => quoted("^"),
        TokenKind::LParen => quoted("("),
        TokenKind::RParen => quoted(")"),
        TokenKind::Comma => quoted(","),
        TokenKind::End => Found::End,
    }
}

/// The token stream of a text.
#[derive(Debug, Clone)]
pub struct Tokens {
    tokens: Vec<Token>,
    pos: usize,
    end: Token,
}

impl Tokens {
    /// Splits `text` into tokens.
    pub fn new(text: &str, limits: &Limits) -> Result<Self, ScalarError> {
        let chars: Vec<char> = text.chars().collect();
        if chars.len() > limits.max_length {
            return Err(ScalarError::Limit {
                what: Exceeded::Length {
                    length: chars.len(),
                    max: limits.max_length,
                },
            });
        }
        let mut tokens = Vec::new();
        let mut i = 0;
        while let Some(&c) = chars.get(i) {
            let span = Span { column: i + 1 };
            let single = match c {
                '+' => Some(TokenKind::Plus),
                '-' | '−' => Some(TokenKind::Minus),
                '*' | '·' | '×' => Some(TokenKind::Star),
                '/' => Some(TokenKind::Slash),
                '^' => Some(TokenKind::Caret),
                '(' => Some(TokenKind::LParen),
                ')' => Some(TokenKind::RParen),
                ',' => Some(TokenKind::Comma),
                '√' => Some(TokenKind::Root),
                _ => None,
            };
            if let Some(kind) = single {
                tokens.push(Token { kind, span });
                i += 1;
            } else if c.is_whitespace() {
                i += 1;
            } else if c.is_ascii_digit() || c == '.' {
                let int_part = run(&chars, &mut i, |c| c.is_ascii_digit());
                let mut frac_part = String::new();
                if chars.get(i) == Some(&'.') {
                    i += 1;
                    frac_part = run(&chars, &mut i, |c| c.is_ascii_digit());
                    if int_part.is_empty() && frac_part.is_empty() {
                        return Err(ScalarError::Parse {
                            column: span.column,
                            expected: Expected::Digit,
                            found: Found::Quoted(".".into()),
                        });
                    }
                }
                if int_part.len() + frac_part.len() > limits.max_digits {
                    return Err(ScalarError::Limit {
                        what: Exceeded::Literal {
                            column: span.column,
                            max: limits.max_digits,
                        },
                    });
                }
                tokens.push(Token {
                    kind: TokenKind::Number(decimal(&int_part, &frac_part)),
                    span,
                });
            } else if c.is_alphabetic() {
                let start = i;
                let name = run(&chars, &mut i, char::is_alphabetic);
                if name == "sqrt" {
                    tokens.push(Token {
                        kind: TokenKind::Root,
                        span,
                    });
                } else {
                    // Variables have one letter, so a run of letters is a product of
                    // variables, each its own token: `uv^3` is u·v^3, as the notes write it.
                    // The last letter may carry a subscript in braces, `c_{1,0}`: the name
                    // of a point of a generic mesh (its indices digits, commas and signs).
                    let subscript = subscript(&chars, &mut i);
                    let count = name.chars().count();
                    for (k, letter) in name.chars().enumerate() {
                        let mut n = letter.to_string();
                        if k + 1 == count {
                            if let Some(sub) = &subscript {
                                n = format!("{n}_{{{sub}}}");
                            }
                        }
                        tokens.push(Token {
                            kind: TokenKind::Name(n),
                            span: Span {
                                column: start + k + 1,
                            },
                        });
                    }
                }
            } else {
                return Err(ScalarError::Parse {
                    column: span.column,
                    expected: Expected::Token,
                    found: Found::Quoted(c.to_string()),
                });
            }
        }
        let end = Token {
            kind: TokenKind::End,
            span: Span {
                column: chars.len() + 1,
            },
        };
        Ok(Tokens {
            tokens,
            pos: 0,
            end,
        })
    }

    fn peek(&self) -> &Token {
        // `next` never moves past the last token; past it, every token is the end.
        self.tokens.get(self.pos).unwrap_or(&self.end)
    }

    fn next(&mut self) -> Token {
        let t = self.peek().clone();
        if t.kind != TokenKind::End {
            self.pos += 1;
        }
        t
    }

    fn error<T>(&self, expected: Expected) -> Result<T, ScalarError> {
        let t = self.peek();
        Err(ScalarError::Parse {
            column: t.span.column,
            expected,
            found: describe(&t.kind),
        })
    }
}

/// The subscript `_{1,0}` after a name (its text without spaces, `1,0`), consumed; `None`
/// (nothing consumed) when none follows.
fn subscript(chars: &[char], i: &mut usize) -> Option<String> {
    if chars.get(*i) != Some(&'_') || chars.get(*i + 1) != Some(&'{') {
        return None;
    }
    let mut k = *i + 2;
    let mut text = String::new();
    while let Some(&c) = chars.get(k) {
        match c {
            '}' => {
                *i = k + 1;
                return (!text.is_empty()).then_some(text);
            }
            '0'..='9' | ',' | '-' => text.push(c),
            ' ' => {}
            _ => return None,
        }
        k += 1;
    }
    None
}

/// The longest run of characters from `chars[*i]` on that satisfy `pred`; moves `i` past it.
fn run(chars: &[char], i: &mut usize, pred: impl Fn(char) -> bool) -> String {
    let mut out = String::new();
    while let Some(&c) = chars.get(*i).filter(|&&c| pred(c)) {
        out.push(c);
        *i += 1;
    }
    out
}

/// The exact value of a decimal literal `int.frac`.
fn decimal(int_part: &str, frac_part: &str) -> BigRational {
    crate::literal::decimal(int_part, frac_part)
}

/// Whether a part of `x` has more bits than the limits allow (the grammar's cheap check of
/// every value it builds).
pub(crate) fn too_many_bits(x: &Quadratic, limits: &Limits) -> bool {
    bits(x) > limits.max_bits()
}

/// What the parser builds: a number, a polynomial, a vector of polynomials...
pub trait Builder {
    /// The value of a (sub)expression.
    type Value;
    /// A numeric literal or root.
    fn number(&mut self, x: Quadratic, span: Span) -> Result<Self::Value, ScalarError>;
    /// A one-letter name.
    fn name(&mut self, name: &str, span: Span) -> Result<Self::Value, ScalarError>;
    /// `sqrt(x)`.
    fn sqrt(&mut self, x: Self::Value, span: Span) -> Result<Self::Value, ScalarError>;
    /// `a + b`.
    fn add(
        &mut self,
        a: Self::Value,
        b: Self::Value,
        span: Span,
    ) -> Result<Self::Value, ScalarError>;
    /// `a - b`.
    fn sub(
        &mut self,
        a: Self::Value,
        b: Self::Value,
        span: Span,
    ) -> Result<Self::Value, ScalarError>;
    /// `a * b`.
    fn mul(
        &mut self,
        a: Self::Value,
        b: Self::Value,
        span: Span,
    ) -> Result<Self::Value, ScalarError>;
    /// `a / b`.
    fn div(
        &mut self,
        a: Self::Value,
        b: Self::Value,
        span: Span,
    ) -> Result<Self::Value, ScalarError>;
    /// `-a`.
    fn neg(&mut self, a: Self::Value, span: Span) -> Result<Self::Value, ScalarError>;
    /// `a^e`, with `|e|` already checked against the limits.
    fn pow(&mut self, a: Self::Value, e: i64, span: Span) -> Result<Self::Value, ScalarError>;
    /// `(a, b, ...)` with at least two items.
    fn tuple(&mut self, items: Vec<Self::Value>, span: Span) -> Result<Self::Value, ScalarError>;
}

/// Parses the whole of `text` with `builder`.
pub fn parse_with<B: Builder>(
    text: &str,
    builder: &mut B,
    limits: &Limits,
) -> Result<B::Value, ScalarError> {
    let mut p = Parser {
        tokens: Tokens::new(text, limits)?,
        limits: *limits,
        depth: 0,
    };
    if p.tokens.peek().kind == TokenKind::End {
        return p.tokens.error(Expected::Expression);
    }
    let v = p.expr(builder)?;
    if p.tokens.peek().kind != TokenKind::End {
        return p.tokens.error(Expected::OperatorOrEnd);
    }
    Ok(v)
}

/// Parses an exact number of the grammar: `5/6`, `-3`, `0.125`, `sqrt2/2`, `1/2 + 3/4*sqrt(2)`.
///
/// ```
/// use cagd_scalar::{parse_number, Print};
/// assert_eq!(parse_number("0.125").unwrap().to_text(), "1/8");
/// assert_eq!(parse_number("√8").unwrap().to_text(), "2√2");
/// assert!(parse_number("1/0").unwrap_err().to_string().contains("division by zero"));
/// assert!(parse_number("sqrt2 + sqrt3").unwrap_err().to_string().contains("√2 and √3"));
/// ```
pub fn parse_number(text: &str) -> Result<Quadratic, ScalarError> {
    parse_number_with(text, &Limits::default())
}

/// [`parse_number`] under other limits: no literal, intermediate value or result has more
/// than `max_digits` digits, and a power is refused before it is computed when it would.
///
/// ```
/// use cagd_scalar::{parse_number_with, Limits};
/// let small = Limits { max_digits: 100, ..Limits::default() };
/// assert!(parse_number_with("2^300", &small).is_ok()); // 91 digits
/// assert_eq!(
///     parse_number_with("((10^3)^1000)^1000", &small).unwrap_err().to_string(),
///     "limit exceeded: the power at column 8 would have more than 100 digits"
/// );
/// ```
pub fn parse_number_with(text: &str, limits: &Limits) -> Result<Quadratic, ScalarError> {
    // most numbers are plain literals (`-3`, `5/6`, `0.125`): one pass, no tokens
    if let Some(x) = crate::literal::parse_literal(text, limits) {
        return Ok(x);
    }
    let x = parse_with(text, &mut NumberBuilder::new(limits), limits)?;
    limits.check_digits(&x)?;
    Ok(x)
}

/// The [`Builder`] of exact numbers: evaluates in Q(√d), with every value within
/// [`Limits::max_digits`] digits.
#[derive(Debug, Clone, Copy)]
pub struct NumberBuilder {
    limits: Limits,
}

impl Default for NumberBuilder {
    fn default() -> Self {
        NumberBuilder::new(&Limits::default())
    }
}

impl NumberBuilder {
    /// A builder whose values have at most `limits.max_digits` digits.
    pub fn new(limits: &Limits) -> Self {
        NumberBuilder { limits: *limits }
    }

    /// Cheap check for every value: bit length only (the result gets the exact count).
    fn small(&self, x: Quadratic) -> Result<Quadratic, ScalarError> {
        if too_many_bits(&x, &self.limits) {
            return Err(ScalarError::Limit {
                what: Exceeded::Digits {
                    max: self.limits.max_digits,
                },
            });
        }
        Ok(x)
    }
}

impl Builder for NumberBuilder {
    type Value = Quadratic;

    fn number(&mut self, x: Quadratic, _: Span) -> Result<Quadratic, ScalarError> {
        self.small(x)
    }
    fn name(&mut self, name: &str, span: Span) -> Result<Quadratic, ScalarError> {
        Err(ScalarError::Parse {
            column: span.column,
            expected: Expected::NumberWithoutVariables,
            found: Found::Quoted(name.to_string()),
        })
    }
    fn sqrt(&mut self, x: Quadratic, span: Span) -> Result<Quadratic, ScalarError> {
        let q = x.to_rational().ok_or_else(|| ScalarError::Parse {
            column: span.column,
            expected: Expected::RationalUnderRoot,
            found: Found::Value(x.to_string()),
        })?;
        Quadratic::sqrt_of(&q).and_then(|x| self.small(x))
    }
    fn add(&mut self, a: Quadratic, b: Quadratic, _: Span) -> Result<Quadratic, ScalarError> {
        a.checked_add(&b).and_then(|x| self.small(x))
    }
    fn sub(&mut self, a: Quadratic, b: Quadratic, _: Span) -> Result<Quadratic, ScalarError> {
        a.checked_sub(&b).and_then(|x| self.small(x))
    }
    fn mul(&mut self, a: Quadratic, b: Quadratic, _: Span) -> Result<Quadratic, ScalarError> {
        a.checked_mul(&b).and_then(|x| self.small(x))
    }
    fn div(&mut self, a: Quadratic, b: Quadratic, span: Span) -> Result<Quadratic, ScalarError> {
        if num_traits::Zero::is_zero(&b) {
            return Err(ScalarError::DivisionByZero {
                column: Some(span.column),
            });
        }
        a.checked_quot(&b).and_then(|x| self.small(x))
    }
    fn neg(&mut self, a: Quadratic, _: Span) -> Result<Quadratic, ScalarError> {
        Ok(-a)
    }
    /// `a^e` by repeated squaring, refused before it starts when the result would be longer
    /// than the limit: the parts of (a + b√d)^e have at most e · (bits + bits(d)/2 + 1) bits.
    fn pow(&mut self, a: Quadratic, e: i64, span: Span) -> Result<Quadratic, ScalarError> {
        let base = if e < 0 {
            a.checked_inv().map_err(|_| ScalarError::DivisionByZero {
                column: Some(span.column),
            })?
        } else {
            a
        };
        let n = e.unsigned_abs();
        let root_bits = if base.root_part().is_zero() {
            0
        } else {
            u64::from(64 - base.radicand().leading_zeros()) + 2
        };
        let base_bits = bits(&base).saturating_sub(1) + root_bits;
        if base_bits.saturating_mul(n) > self.limits.max_bits() {
            return Err(ScalarError::Limit {
                what: Exceeded::Power {
                    column: span.column,
                    max: self.limits.max_digits,
                },
            });
        }
        let mut acc = Quadratic::one();
        let mut square = base;
        let mut k = n;
        while k > 0 {
            if k & 1 == 1 {
                acc = acc.checked_mul(&square)?;
            }
            k >>= 1;
            if k > 0 {
                square = square.checked_mul(&square)?;
            }
        }
        self.small(acc)
    }
    fn tuple(&mut self, _: Vec<Quadratic>, span: Span) -> Result<Quadratic, ScalarError> {
        Err(ScalarError::Parse {
            column: span.column,
            expected: Expected::SingleNumber,
            found: Found::Tuple,
        })
    }
}

struct Parser {
    tokens: Tokens,
    limits: Limits,
    depth: usize,
}

impl Parser {
    /// One more level: the whole expression is level 1, each parenthesis or sign one more, so
    /// `max_depth` parentheses around a number still read.
    fn enter(&mut self) -> Result<(), ScalarError> {
        self.depth += 1;
        if self.depth > self.limits.max_depth.saturating_add(1) {
            return Err(ScalarError::Limit {
                what: Exceeded::Depth {
                    max: self.limits.max_depth,
                    column: self.tokens.peek().span.column,
                },
            });
        }
        Ok(())
    }

    fn expr<B: Builder>(&mut self, b: &mut B) -> Result<B::Value, ScalarError> {
        self.enter()?;
        let mut acc = self.term(b)?;
        loop {
            let t = self.tokens.peek().clone();
            match t.kind {
                TokenKind::Plus => {
                    self.tokens.next();
                    let rhs = self.term(b)?;
                    acc = b.add(acc, rhs, t.span)?;
                }
                TokenKind::Minus => {
                    self.tokens.next();
                    let rhs = self.term(b)?;
                    acc = b.sub(acc, rhs, t.span)?;
                }
                _ => break,
            }
        }
        self.depth -= 1;
        Ok(acc)
    }

    fn term<B: Builder>(&mut self, b: &mut B) -> Result<B::Value, ScalarError> {
        let mut acc = self.unary(b)?;
        loop {
            let t = self.tokens.peek().clone();
            match t.kind {
                TokenKind::Star => {
                    self.tokens.next();
                    let rhs = self.unary(b)?;
                    acc = b.mul(acc, rhs, t.span)?;
                }
                TokenKind::Slash => {
                    self.tokens.next();
                    let rhs = self.unary(b)?;
                    acc = b.div(acc, rhs, t.span)?;
                }
                TokenKind::Name(_) | TokenKind::Root | TokenKind::LParen => {
                    let rhs = self.power(b)?;
                    acc = b.mul(acc, rhs, t.span)?;
                }
                _ => break,
            }
        }
        Ok(acc)
    }

    fn unary<B: Builder>(&mut self, b: &mut B) -> Result<B::Value, ScalarError> {
        let t = self.tokens.peek().clone();
        match t.kind {
            TokenKind::Minus => {
                self.tokens.next();
                self.enter()?;
                let v = self.unary(b)?;
                self.depth -= 1;
                b.neg(v, t.span)
            }
            TokenKind::Plus => {
                self.tokens.next();
                self.enter()?;
                let v = self.unary(b);
                self.depth -= 1;
                v
            }
            _ => self.power(b),
        }
    }

    fn power<B: Builder>(&mut self, b: &mut B) -> Result<B::Value, ScalarError> {
        let base = self.atom(b)?;
        let t = self.tokens.peek().clone();
        if t.kind != TokenKind::Caret {
            return Ok(base);
        }
        self.tokens.next();
        let e = self.exponent(t.span)?;
        b.pow(base, e, t.span)
    }

    /// An integer exponent: a literal, or a parenthesized exact expression that is an integer.
    fn exponent(&mut self, caret: Span) -> Result<i64, ScalarError> {
        let negative = self.tokens.peek().kind == TokenKind::Minus;
        if negative {
            self.tokens.next();
        }
        let t = self.tokens.peek().clone();
        let value = match &t.kind {
            TokenKind::Number(q) => {
                self.tokens.next();
                q.clone()
            }
            TokenKind::LParen => {
                self.tokens.next();
                // under a tight bound whatever builder reads the rest: an exponent is a small
                // integer, and a tower such as 2^(((10^3)^1000)^1000) is refused, not built
                let tight = Limits {
                    max_digits: self.limits.max_digits.min(EXPONENT_DIGITS),
                    ..self.limits
                };
                let v = self.expr(&mut NumberBuilder::new(&tight))?;
                if self.tokens.peek().kind != TokenKind::RParen {
                    return self.tokens.error(Expected::CloseExponent);
                }
                self.tokens.next();
                v.to_rational().ok_or_else(|| ScalarError::Parse {
                    column: t.span.column,
                    expected: Expected::IntegerExponent,
                    found: Found::Value(v.to_string()),
                })?
            }
            _ => return self.tokens.error(Expected::IntegerExponent),
        };
        if !value.is_integer() {
            return Err(ScalarError::Parse {
                column: t.span.column,
                expected: Expected::IntegerExponent,
                found: Found::Value(value.to_string()),
            });
        }
        let max = self.limits.max_exponent;
        match value.to_integer().to_i64() {
            Some(e) if e.unsigned_abs() <= u64::from(max) => Ok(if negative { -e } else { e }),
            _ => Err(ScalarError::Limit {
                what: Exceeded::Exponent {
                    exponent: value.to_integer().abs().to_string(),
                    column: caret.column,
                    max,
                },
            }),
        }
    }

    fn atom<B: Builder>(&mut self, b: &mut B) -> Result<B::Value, ScalarError> {
        let t = self.tokens.next();
        match t.kind {
            TokenKind::Number(q) => b.number(Quadratic::from_rational(q), t.span),
            TokenKind::Name(name) => b.name(&name, t.span),
            TokenKind::Root => {
                let next = self.tokens.peek().clone();
                match next.kind {
                    // sqrt2, √3: the radicand is the integer right after
                    TokenKind::Number(q) if q.is_integer() => {
                        self.tokens.next();
                        let arg = b.number(Quadratic::from_rational(q), next.span)?;
                        b.sqrt(arg, t.span)
                    }
                    TokenKind::LParen => {
                        self.tokens.next();
                        let arg = self.expr(b)?;
                        if self.tokens.peek().kind != TokenKind::RParen {
                            return self.tokens.error(Expected::CloseRoot);
                        }
                        self.tokens.next();
                        b.sqrt(arg, t.span)
                    }
                    _ => self.tokens.error(Expected::RootArgument),
                }
            }
            TokenKind::LParen => {
                let first = self.expr(b)?;
                if self.tokens.peek().kind != TokenKind::Comma {
                    if self.tokens.peek().kind != TokenKind::RParen {
                        return self.tokens.error(Expected::CloseParenthesis);
                    }
                    self.tokens.next();
                    return Ok(first);
                }
                let mut items = vec![first];
                while self.tokens.peek().kind == TokenKind::Comma {
                    self.tokens.next();
                    items.push(self.expr(b)?);
                }
                if self.tokens.peek().kind != TokenKind::RParen {
                    return self.tokens.error(Expected::CommaOrClose);
                }
                self.tokens.next();
                b.tuple(items, t.span)
            }
            kind => Err(ScalarError::Parse {
                column: t.span.column,
                expected: Expected::Operand,
                found: describe(&kind),
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(text: &str) -> Vec<TokenKind> {
        Tokens::new(text, &Limits::default())
            .map(|t| {
                t.tokens
                    .into_iter()
                    .chain([t.end])
                    .map(|t| t.kind)
                    .collect()
            })
            .unwrap_or_default()
    }

    #[test]
    fn a_run_of_letters_is_a_product_of_one_letter_names() {
        let name = |c: &str| TokenKind::Name(c.to_string());
        assert_eq!(
            kinds("uv^3"),
            vec![
                name("u"),
                name("v"),
                TokenKind::Caret,
                TokenKind::Number(BigRational::from_integer(3.into())),
                TokenKind::End
            ]
        );
        assert_eq!(kinds("sqrt2")[0], TokenKind::Root);
        let t = Tokens::new("2 uv", &Limits::default())
            .map(|t| t.tokens)
            .unwrap_or_default();
        assert_eq!(t.get(2).map(|t| t.span.column), Some(4));
    }
}
