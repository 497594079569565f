//! Expressions in the curve variables `u, v, ...` whose coefficients are in letters:
//! `(a + 1) u^2 + R v` (what `cagd expand --parameters` reads).

use crate::field::Param;
use crate::letters::Name;
use cagd_poly::{Monomial, Poly, Var, VecPoly};
use cagd_scalar::{
    parse_with, Builder, Exceeded, Expected, FieldOps, Found, Limits, Quadratic, ScalarError, Span,
};

/// A polynomial, or a tuple of polynomials, in `u, v, ...` with coefficients in letters.
#[derive(Clone, Debug, PartialEq)]
pub enum ParamExpr {
    /// A scalar polynomial.
    Scalar(Poly<Param>),
    /// A tuple.
    Vector(VecPoly<Param>),
}

struct ExprBuilder<'a> {
    names: &'a [Name],
}

type Res = Result<ParamExpr, ScalarError>;

fn scalar(e: ParamExpr, span: Span) -> Result<Poly<Param>, ScalarError> {
    match e {
        ParamExpr::Scalar(p) => Ok(p),
        ParamExpr::Vector(_) => Err(ScalarError::Parse {
            column: span.column,
            expected: Expected::ScalarNotTuple,
            found: Found::Tuple,
        }),
    }
}

impl Builder for ExprBuilder<'_> {
    type Value = ParamExpr;

    fn number(&mut self, x: Quadratic, _: Span) -> Res {
        Ok(ParamExpr::Scalar(Poly::constant(Param::Const(x))))
    }
    fn name(&mut self, name: &str, span: Span) -> Res {
        if let Some(n) = self.names.iter().find(|n| n.as_str() == name) {
            return Ok(ParamExpr::Scalar(Poly::constant(Param::named(n.clone()))));
        }
        let mut m = Monomial::one();
        for c in name.chars() {
            match Var::from_char(c) {
                Some(v) => m = m.mul(&Monomial::var(v)),
                None => {
                    return Err(ScalarError::Parse {
                        column: span.column,
                        expected: Expected::VariableOrParameter,
                        found: Found::Quoted(c.to_string()),
                    });
                }
            }
        }
        Ok(ParamExpr::Scalar(Poly::term(Param::from_i64(1), m)))
    }
    fn sqrt(&mut self, x: ParamExpr, span: Span) -> Res {
        let p = scalar(x, span)?;
        let q = p
            .as_constant()
            .and_then(|c| c.as_const().and_then(Quadratic::to_rational))
            .ok_or_else(|| ScalarError::Parse {
                column: span.column,
                expected: Expected::RationalUnderRoot,
                found: Found::Value(p.to_string()),
            })?;
        Quadratic::sqrt_of(&q).map(|r| ParamExpr::Scalar(Poly::constant(Param::Const(r))))
    }
    fn add(&mut self, a: ParamExpr, b: ParamExpr, span: Span) -> Res {
        Ok(ParamExpr::Scalar(scalar(a, span)? + scalar(b, span)?))
    }
    fn sub(&mut self, a: ParamExpr, b: ParamExpr, span: Span) -> Res {
        Ok(ParamExpr::Scalar(scalar(a, span)? - scalar(b, span)?))
    }
    fn mul(&mut self, a: ParamExpr, b: ParamExpr, span: Span) -> Res {
        Ok(ParamExpr::Scalar(scalar(a, span)? * scalar(b, span)?))
    }
    fn div(&mut self, a: ParamExpr, b: ParamExpr, span: Span) -> Res {
        let (a, b) = (scalar(a, span)?, scalar(b, span)?);
        let c = b.as_constant().ok_or_else(|| ScalarError::Parse {
            column: span.column,
            expected: Expected::ConstantDivisor,
            found: Found::Value(b.to_string()),
        })?;
        let inv = Param::from_i64(1)
            .checked_div(&c)
            .ok_or(ScalarError::DivisionByZero {
                column: Some(span.column),
            })?;
        Ok(ParamExpr::Scalar(a.scale(&inv)))
    }
    fn neg(&mut self, a: ParamExpr, span: Span) -> Res {
        Ok(ParamExpr::Scalar(-scalar(a, span)?))
    }
    fn pow(&mut self, a: ParamExpr, e: i64, span: Span) -> Res {
        let p = scalar(a, span)?;
        let n = u32::try_from(e).map_err(|_| ScalarError::Parse {
            column: span.column,
            expected: Expected::SmallPower,
            found: Found::Value(e.to_string()),
        })?;
        if n > 64 {
            return Err(ScalarError::Limit {
                what: Exceeded::PowerAbove64 {
                    column: span.column,
                },
            });
        }
        Ok(ParamExpr::Scalar(p.pow(n)))
    }
    fn tuple(&mut self, items: Vec<ParamExpr>, span: Span) -> Res {
        let comps = items
            .into_iter()
            .map(|e| scalar(e, span))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(ParamExpr::Vector(VecPoly::new(comps)))
    }
}

/// Reads and expands an expression in `u, v, ...` whose coefficients may use the parameters
/// `names`: `(a + 1)*u^2 + R*v`, `(R*u, R*v, 0)`.
///
/// ```
/// use cagd_param::{parse_param_expr, Name, ParamExpr};
/// use cagd_scalar::Limits;
/// let names = [Name::new("a")];
/// let ParamExpr::Scalar(p) = parse_param_expr("(u + a)^2", &names, &Limits::default()).unwrap() else { panic!() };
/// assert_eq!(p.to_text(), "u^2 + 2 a u + a^2");
/// ```
pub fn parse_param_expr(text: &str, names: &[Name], limits: &Limits) -> Res {
    parse_with(text, &mut ExprBuilder { names }, limits)
}
