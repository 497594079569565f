//! The expression reader: the one grammar of `cagd-scalar` (see `cagd_scalar::parse_with`)
//! with a [`Builder`] that builds polynomials and tuples of polynomials.

use crate::{BadRoot, Form, Misuse, Monomial, Poly, PolyError, TooLarge, Var, VecPoly};
use cagd_scalar::{
    parse_with, Builder, Expected, FieldOps, Found, Limits, Print, Quadratic, Scalar, ScalarError,
    Span,
};
use std::fmt;

/// Highest total degree an expression may expand to.
pub const MAX_DEGREE: u32 = 2000;
/// The work budget of expanding one expression: the term-by-term products of all its
/// multiplications, each weighted by the sizes of the coefficients in 64-bit words, so that
/// hostile input is refused in well under a second instead of expanded for minutes.
pub const MAX_PRODUCTS: usize = 100_000;
/// The largest coefficient a power of a single term may have, in 64-bit words (about 39,000
/// decimal digits): `((10^1000)^1000)^1000` is refused before it is computed.
pub const MAX_COEFFICIENT_WORDS: usize = 2048;

/// The value of an expression: a scalar polynomial or a tuple of polynomials, with exact
/// coefficients in a quadratic field (`√2` allowed, one root per expression).
#[derive(Clone, PartialEq, Eq, Debug)]
pub enum Expr {
    /// A scalar polynomial, such as `3/2*u^2 - sqrt2/2*v`.
    Scalar(Poly<Quadratic>),
    /// A tuple of polynomials, such as `(u, v + 1, u^2 + v^3)`.
    Vector(VecPoly<Quadratic>),
}

impl Expr {
    /// The scalar polynomial over `S`, or an error when this is a tuple or a coefficient does
    /// not fit `S` exactly.
    pub fn scalar<S: Scalar>(&self) -> Result<Poly<S>, PolyError> {
        match self {
            Expr::Scalar(p) => p.convert(),
            Expr::Vector(c) => Err(PolyError::Shape {
                expected: Form::ScalarPolynomial,
                found: Form::Tuple { dim: c.dim() },
            }),
        }
    }

    /// The tuple of polynomials over `S`, or an error when this is a scalar or a coefficient
    /// does not fit `S` exactly.
    pub fn vector<S: Scalar>(&self) -> Result<VecPoly<S>, PolyError> {
        match self {
            Expr::Vector(c) => c.convert(),
            Expr::Scalar(p) => Err(PolyError::Shape {
                expected: Form::TupleOfPolynomials,
                found: Form::Scalar { poly: p.to_text() },
            }),
        }
    }

    /// Plain text, see [`Poly::to_text`].
    pub fn to_text(&self) -> String {
        match self {
            Expr::Scalar(p) => p.to_text(),
            Expr::Vector(c) => c.to_text(),
        }
    }

    /// LaTeX, see [`Poly::to_latex`].
    pub fn to_latex(&self) -> String {
        match self {
            Expr::Scalar(p) => p.to_latex(),
            Expr::Vector(c) => c.to_latex(),
        }
    }

    /// The JSON form that [`parse_expr`] reads back exactly, see [`Poly::to_json_string`].
    pub fn to_json_string(&self) -> String {
        match self {
            Expr::Scalar(p) => p.to_json_string(),
            Expr::Vector(c) => c.to_json_string(),
        }
    }
}

impl fmt::Display for Expr {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

/// Reads and expands an expression of the grammar of `cagd-scalar` in the variables
/// `u, v, w, t, s, x, y, z`.
///
/// Numbers are exact (`0.125`, `3/4`, `sqrt2/2`, `√3`); a run of letters such as `uv` is the
/// product of its one-letter variables, and a `^` binds to the last letter only (`vu^2` is
/// `v u^2`, as the notes write; `(vu)^2` is `u^2 v^2`). Tuples `(a, b, ...)` add and subtract componentwise,
/// and multiply by scalar polynomials on either side; a tuple times a tuple is an error, as is
/// a division by anything but a nonzero constant, or `sqrt` of anything but a non-negative
/// constant. Errors name the column.
///
/// ```
/// use cagd_poly::parse_expr;
/// let c = parse_expr("(1 - v)*(u, 0, u^3) + v*(u, 1, u^2)").unwrap();
/// assert_eq!(c.to_text(), "(u, v, -u^3 v + u^3 + u^2 v)");
/// assert_eq!(parse_expr("(1-v)(u,0,u^3)").unwrap().to_text(), "(-u v + u, 0, -u^3 v + u^3)");
/// assert_eq!(parse_expr("(sqrt2/2)^2").unwrap().to_text(), "1/2");
/// let e = parse_expr("u + q").unwrap_err().to_string();
/// assert_eq!(e, "at column 5: unknown variable 'q' (the variables are u, v, w, t, s, x, y, z; 'uv' means u v)");
/// assert!(parse_expr("(u, v) * (u, v)").unwrap_err().to_string().contains("at column 8"));
/// assert!(parse_expr("1/u").unwrap_err().to_string().contains("division by a polynomial"));
/// ```
pub fn parse_expr(text: &str) -> Result<Expr, PolyError> {
    parse_expr_with(text, &Limits::default())
}

/// [`parse_expr`] under other limits of the grammar (exponent, depth, digits, length); the
/// degree ([`MAX_DEGREE`]) and work ([`MAX_PRODUCTS`]) budgets stay.
///
/// ```
/// use cagd_poly::parse_expr_with;
/// use cagd_scalar::Limits;
/// let small = Limits { max_exponent: 3, ..Limits::default() };
/// assert!(parse_expr_with("u^3", &small).is_ok());
/// assert_eq!(
///     parse_expr_with("u^4", &small).unwrap_err().to_string(),
///     "limit exceeded: exponent 4 at column 2 is larger than 3"
/// );
/// ```
pub fn parse_expr_with(text: &str, limits: &Limits) -> Result<Expr, PolyError> {
    let mut builder = Bounded {
        inner: ExprBuilder::default(),
        limits: *limits,
    };
    match parse_with(text, &mut builder, limits) {
        Ok(e) => Ok(e),
        Err(e) => Err(builder.inner.error.take().unwrap_or(PolyError::Scalar(e))),
    }
}

/// Reads a scalar polynomial with coefficients in `S` (see [`parse_expr`]).
pub fn parse_poly<S: Scalar>(text: &str) -> Result<Poly<S>, PolyError> {
    parse_expr(text)?.scalar()
}

/// Reads a tuple of polynomials with coefficients in `S` (see [`parse_expr`]).
pub fn parse_vec_poly<S: Scalar>(text: &str) -> Result<VecPoly<S>, PolyError> {
    parse_expr(text)?.vector()
}

/// The builder: polynomials over Q(√d) for the one `d` of the expression.
struct ExprBuilder {
    /// The largest coefficient a power of one term may have, in 64-bit words.
    max_coefficient_words: usize,
    /// The radicand d of the first root met: every number must lie in Q(√d).
    root: Option<u64>,
    /// Work spent so far, in products of 64-bit words (see [`MAX_PRODUCTS`]).
    work: usize,
    /// The detailed error behind the last `ScalarError` returned (the grammar's errors are
    /// `ScalarError`s; this keeps the typed one).
    error: Option<PolyError>,
}

impl Default for ExprBuilder {
    fn default() -> Self {
        ExprBuilder {
            max_coefficient_words: MAX_COEFFICIENT_WORDS,
            root: None,
            work: 0,
            error: None,
        }
    }
}

type Res = Result<Expr, ScalarError>;

impl ExprBuilder {
    fn fail(&mut self, e: PolyError) -> ScalarError {
        let out = match &e {
            PolyError::Scalar(s) => s.clone(),
            // a stand-in, replaced by the typed error kept here when the parse ends
            other => ScalarError::Parse {
                column: 0,
                expected: Expected::Expression,
                found: Found::Value(other.to_string()),
            },
        };
        self.error = Some(e);
        out
    }

    fn op_error(&mut self, span: Span, message: Misuse) -> ScalarError {
        self.fail(PolyError::Operation {
            column: span.column,
            message,
        })
    }

    /// Every number entering the expression must be in the one field Q(√d).
    fn check_root(&mut self, x: &Quadratic, span: Span) -> Result<(), ScalarError> {
        let d = x.radicand();
        if d == 0 {
            return Ok(());
        }
        match self.root {
            None => {
                self.root = Some(d);
                Ok(())
            }
            Some(r) if r == d => Ok(()),
            Some(r) => Err(self.fail(PolyError::MixedRoots {
                column: span.column,
                first: r,
                second: d,
            })),
        }
    }

    fn check_product(
        &mut self,
        a: &Poly<Quadratic>,
        b: &Poly<Quadratic>,
        span: Span,
    ) -> Result<(), ScalarError> {
        let degree = a.degree().saturating_add(b.degree());
        if degree > MAX_DEGREE {
            return Err(self.too_large(
                span,
                TooLarge::Degree {
                    degree: u64::from(degree),
                    max: MAX_DEGREE,
                },
            ));
        }
        let cost = a
            .num_terms()
            .saturating_mul(b.num_terms())
            .saturating_mul(words(a).saturating_mul(words(b)));
        self.work = self.work.saturating_add(cost);
        if self.work > MAX_PRODUCTS {
            return Err(self.too_large(
                span,
                TooLarge::Products {
                    max: MAX_PRODUCTS,
                    first: a.num_terms(),
                    second: b.num_terms(),
                },
            ));
        }
        Ok(())
    }

    /// A power of one term: its coefficient's size grows n-fold, and nothing else does.
    fn check_coefficient_power(
        &mut self,
        p: &Poly<Quadratic>,
        n: u32,
        span: Span,
    ) -> Result<(), ScalarError> {
        let size = words(p).saturating_mul(usize::try_from(n).unwrap_or(usize::MAX));
        let max = self.max_coefficient_words;
        if size > max {
            return Err(self.too_large(span, TooLarge::Coefficient { size, max }));
        }
        Ok(())
    }

    fn too_large(&mut self, span: Span, what: TooLarge) -> ScalarError {
        self.fail(PolyError::TooLarge {
            column: span.column,
            what,
        })
    }

    fn constant_divisor(&mut self, b: Expr, span: Span) -> Result<Quadratic, ScalarError> {
        let p = match b {
            Expr::Scalar(p) => p,
            Expr::Vector(_) => return Err(self.op_error(span, Misuse::DivideByTuple)),
        };
        let Some(c) = p.as_constant() else {
            return Err(self.fail(PolyError::DivisionByPolynomial {
                column: span.column,
                divisor: p.to_text(),
            }));
        };
        c.checked_inv().map_err(|_| {
            self.fail(PolyError::Scalar(ScalarError::DivisionByZero {
                column: Some(span.column),
            }))
        })
    }
}

/// The size of the largest coefficient of `p`, in 64-bit words (at least 1).
fn words(p: &Poly<Quadratic>) -> usize {
    let bits = p
        .terms()
        .map(|(_, c)| {
            let (a, b) = (c.rational_part(), c.root_part());
            a.numer().bits() + a.denom().bits() + b.numer().bits() + b.denom().bits()
        })
        .max()
        .unwrap_or(0);
    usize::try_from(bits / 64 + 1).unwrap_or(usize::MAX)
}

impl Builder for ExprBuilder {
    type Value = Expr;

    fn number(&mut self, x: Quadratic, span: Span) -> Res {
        self.check_root(&x, span)?;
        Ok(Expr::Scalar(Poly::constant(x)))
    }

    fn name(&mut self, name: &str, span: Span) -> Res {
        let mut m = Monomial::one();
        for c in name.chars() {
            match Var::from_char(c) {
                Some(v) => m = m.mul(&Monomial::var(v)),
                None => {
                    return Err(self.fail(PolyError::UnknownVariable {
                        name: name.to_string(),
                        column: Some(span.column),
                    }))
                }
            }
        }
        Ok(Expr::Scalar(Poly::term(Quadratic::from_i64(1), m)))
    }

    fn sqrt(&mut self, x: Expr, span: Span) -> Res {
        let sqrt_error = |message: BadRoot| PolyError::Sqrt {
            column: span.column,
            message,
        };
        let p = match x {
            Expr::Scalar(p) => p,
            Expr::Vector(_) => return Err(self.fail(sqrt_error(BadRoot::OfTuple))),
        };
        let Some(c) = p.as_constant() else {
            return Err(self.fail(sqrt_error(BadRoot::OfPolynomial { poly: p.to_text() })));
        };
        let Some(q) = c.to_rational() else {
            return Err(self.fail(sqrt_error(BadRoot::OfRoot { value: c.to_text() })));
        };
        let root = Quadratic::sqrt_of(&q).map_err(|e| match e {
            ScalarError::NegativeSqrt { value } => {
                self.fail(sqrt_error(BadRoot::Negative { value }))
            }
            other => self.fail(PolyError::Scalar(other)),
        })?;
        self.check_root(&root, span)?;
        Ok(Expr::Scalar(Poly::constant(root)))
    }

    fn add(&mut self, a: Expr, b: Expr, span: Span) -> Res {
        match (a, b) {
            (Expr::Scalar(a), Expr::Scalar(b)) => Ok(Expr::Scalar(a + b)),
            (Expr::Vector(a), Expr::Vector(b)) => {
                a.checked_add(&b).map(Expr::Vector).map_err(|_| {
                    self.op_error(
                        span,
                        Misuse::AddTuples {
                            first: a.dim(),
                            second: b.dim(),
                        },
                    )
                })
            }
            _ => Err(self.op_error(span, Misuse::AddScalarAndTuple)),
        }
    }

    fn sub(&mut self, a: Expr, b: Expr, span: Span) -> Res {
        match (a, b) {
            (Expr::Scalar(a), Expr::Scalar(b)) => Ok(Expr::Scalar(a - b)),
            (Expr::Vector(a), Expr::Vector(b)) => {
                a.checked_sub(&b).map(Expr::Vector).map_err(|_| {
                    self.op_error(
                        span,
                        Misuse::SubtractTuples {
                            first: a.dim(),
                            second: b.dim(),
                        },
                    )
                })
            }
            _ => Err(self.op_error(span, Misuse::SubtractScalarAndTuple)),
        }
    }

    fn mul(&mut self, a: Expr, b: Expr, span: Span) -> Res {
        match (a, b) {
            (Expr::Scalar(a), Expr::Scalar(b)) => {
                self.check_product(&a, &b, span)?;
                Ok(Expr::Scalar(a * b))
            }
            (Expr::Scalar(f), Expr::Vector(c)) | (Expr::Vector(c), Expr::Scalar(f)) => {
                for p in c.components() {
                    self.check_product(&f, p, span)?;
                }
                Ok(Expr::Vector(c.mul_poly(&f)))
            }
            (Expr::Vector(_), Expr::Vector(_)) => Err(self.op_error(span, Misuse::MultiplyTuples)),
        }
    }

    fn div(&mut self, a: Expr, b: Expr, span: Span) -> Res {
        let inv = self.constant_divisor(b, span)?;
        Ok(match a {
            Expr::Scalar(p) => Expr::Scalar(p.scale(&inv)),
            Expr::Vector(c) => Expr::Vector(c.scale(&inv)),
        })
    }

    fn neg(&mut self, a: Expr, _: Span) -> Res {
        Ok(match a {
            Expr::Scalar(p) => Expr::Scalar(-p),
            Expr::Vector(c) => Expr::Vector(-c),
        })
    }

    fn pow(&mut self, a: Expr, e: i64, span: Span) -> Res {
        let p = match a {
            Expr::Scalar(p) => p,
            Expr::Vector(_) => return Err(self.op_error(span, Misuse::PowerOfTuple)),
        };
        let n = u32::try_from(e.unsigned_abs()).unwrap_or(u32::MAX);
        if e < 0 {
            let Some(c) = p.as_constant() else {
                return Err(self.op_error(span, Misuse::NegativePower { poly: p.to_text() }));
            };
            let inv = c.checked_inv().map_err(|_| {
                self.fail(PolyError::Scalar(ScalarError::DivisionByZero {
                    column: Some(span.column),
                }))
            })?;
            let inv = Poly::constant(inv);
            self.check_coefficient_power(&inv, n, span)?;
            return Ok(Expr::Scalar(inv.pow(n)));
        }
        let degree = u64::from(p.degree()) * u64::from(n);
        if degree > u64::from(MAX_DEGREE) {
            return Err(self.too_large(
                span,
                TooLarge::Degree {
                    degree,
                    max: MAX_DEGREE,
                },
            ));
        }
        if p.num_terms() <= 1 {
            self.check_coefficient_power(&p, n, span)?;
            return Ok(Expr::Scalar(p.pow(n)));
        }
        // repeated multiplication, so that every step is counted against the budget
        let mut acc = Poly::one();
        for _ in 0..n {
            self.check_product(&acc, &p, span)?;
            acc = acc * &p;
        }
        Ok(Expr::Scalar(acc))
    }

    fn tuple(&mut self, items: Vec<Expr>, span: Span) -> Res {
        let mut comps = Vec::with_capacity(items.len());
        for item in items {
            match item {
                Expr::Scalar(p) => comps.push(p),
                Expr::Vector(_) => return Err(self.op_error(span, Misuse::TupleInTuple)),
            }
        }
        Ok(Expr::Vector(VecPoly::new(comps)))
    }
}

/// [`ExprBuilder`] with every value within the grammar's limits, so that whatever is read
/// prints to text that reads back: no exponent of a variable above `max_exponent` (`(u^37)^37`
/// is u^1369, which no one could type back), no coefficient longer than `max_digits`.
struct Bounded {
    inner: ExprBuilder,
    limits: Limits,
}

impl Bounded {
    fn within(&mut self, e: Expr, span: Span) -> Res {
        let polys = match &e {
            Expr::Scalar(p) => std::slice::from_ref(p),
            Expr::Vector(v) => v.components(),
        };
        let max = self.limits.max_exponent;
        let mut problem = None;
        'terms: for p in polys {
            for (m, c) in p.terms() {
                if let Some((var, exp)) = m.powers().find(|&(_, exp)| exp > max) {
                    problem = Some(TooLarge::Power {
                        var: var.to_string(),
                        exponent: exp,
                        max,
                    });
                    break 'terms;
                }
                if let Err(ScalarError::Limit { what }) = self.limits.check_digits(c) {
                    problem = Some(TooLarge::CoefficientDigits(what));
                    break 'terms;
                }
            }
        }
        match problem {
            Some(what) => Err(self.inner.too_large(span, what)),
            None => Ok(e),
        }
    }
}

impl Builder for Bounded {
    type Value = Expr;

    fn number(&mut self, x: Quadratic, span: Span) -> Res {
        self.inner.number(x, span)
    }
    fn name(&mut self, name: &str, span: Span) -> Res {
        self.inner.name(name, span)
    }
    fn sqrt(&mut self, x: Expr, span: Span) -> Res {
        let e = self.inner.sqrt(x, span)?;
        self.within(e, span)
    }
    fn add(&mut self, a: Expr, b: Expr, span: Span) -> Res {
        let e = self.inner.add(a, b, span)?;
        self.within(e, span)
    }
    fn sub(&mut self, a: Expr, b: Expr, span: Span) -> Res {
        let e = self.inner.sub(a, b, span)?;
        self.within(e, span)
    }
    fn mul(&mut self, a: Expr, b: Expr, span: Span) -> Res {
        let e = self.inner.mul(a, b, span)?;
        self.within(e, span)
    }
    fn div(&mut self, a: Expr, b: Expr, span: Span) -> Res {
        let e = self.inner.div(a, b, span)?;
        self.within(e, span)
    }
    fn neg(&mut self, a: Expr, span: Span) -> Res {
        self.inner.neg(a, span)
    }
    fn pow(&mut self, a: Expr, e: i64, span: Span) -> Res {
        let e = self.inner.pow(a, e, span)?;
        self.within(e, span)
    }
    fn tuple(&mut self, items: Vec<Expr>, span: Span) -> Res {
        self.inner.tuple(items, span)
    }
}
