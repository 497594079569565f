//! Reading numbers in letters with the one grammar of cagd-scalar.

use crate::field::Param;
use crate::letters::Name;
use cagd_scalar::{
    parse_with, Builder, Exceeded, Expected, FieldOps, Found, Limits, Quadratic, ScalarError, Span,
};
use num_traits::One;

/// The grammar's builder of [`Param`] values: numbers, roots, and the declared parameters.
///
/// A letter that is not declared is an error naming it, so that a typo is caught.
pub struct ParamBuilder<'a> {
    names: &'a [Name],
}

impl<'a> ParamBuilder<'a> {
    /// A builder that accepts the parameters `names`.
    pub fn new(names: &'a [Name]) -> Self {
        ParamBuilder { names }
    }
}

/// Reads an exact number in the declared parameters, as `2 R/3`, `(a + c)/2`, `sqrt2/2 R`.
///
/// ```
/// use cagd_param::{parse_param, Name};
/// use cagd_scalar::{Limits, Print};
/// let names = [Name::new("R")];
/// let x = parse_param("sqrt(2)/2*R", &names, &Limits::default()).unwrap();
/// assert_eq!(x.to_text(), "√2 R/2");
/// assert_eq!(parse_param(&x.to_json_string(), &names, &Limits::default()).unwrap(), x);
/// assert!(parse_param("2 r", &names, &Limits::default()).unwrap_err().to_string().contains("'r', which is not a declared parameter"));
/// ```
pub fn parse_param(text: &str, names: &[Name], limits: &Limits) -> Result<Param, ScalarError> {
    parse_with(text, &mut ParamBuilder::new(names), limits)
}

fn same_field(a: &Param, b: &Param) -> Result<(), ScalarError> {
    let (d, e) = (a.radicand(), b.radicand());
    if d != 0 && e != 0 && d != e {
        return Err(ScalarError::MixedRoots {
            first: d,
            second: e,
        });
    }
    Ok(())
}

impl Builder for ParamBuilder<'_> {
    type Value = Param;

    fn number(&mut self, x: Quadratic, _: Span) -> Result<Param, ScalarError> {
        Ok(Param::Const(x))
    }
    fn name(&mut self, name: &str, span: Span) -> Result<Param, ScalarError> {
        if let Some(n) = self.names.iter().find(|n| n.as_str() == name) {
            return Ok(Param::named(n.clone()));
        }
        let declared: Vec<&str> = self.names.iter().map(Name::as_str).collect();
        Err(ScalarError::Parse {
            column: span.column,
            expected: if declared.is_empty() {
                Expected::NumberNoParameters
            } else {
                Expected::NumberOrParameter {
                    declared: declared.join(", "),
                }
            },
            found: Found::Undeclared(name.to_string()),
        })
    }
    fn sqrt(&mut self, x: Param, span: Span) -> Result<Param, ScalarError> {
        let q = x
            .as_const()
            .and_then(Quadratic::to_rational)
            .ok_or_else(|| ScalarError::Parse {
                column: span.column,
                expected: Expected::RationalUnderRoot,
                found: Found::Value(x.to_string()),
            })?;
        Quadratic::sqrt_of(&q).map(Param::Const)
    }
    fn add(&mut self, a: Param, b: Param, _: Span) -> Result<Param, ScalarError> {
        same_field(&a, &b)?;
        Ok(a + b)
    }
    fn sub(&mut self, a: Param, b: Param, _: Span) -> Result<Param, ScalarError> {
        same_field(&a, &b)?;
        Ok(a - b)
    }
    fn mul(&mut self, a: Param, b: Param, _: Span) -> Result<Param, ScalarError> {
        same_field(&a, &b)?;
        Ok(a * b)
    }
    fn div(&mut self, a: Param, b: Param, span: Span) -> Result<Param, ScalarError> {
        same_field(&a, &b)?;
        a.checked_div(&b).ok_or(ScalarError::DivisionByZero {
            column: Some(span.column),
        })
    }
    fn neg(&mut self, a: Param, _: Span) -> Result<Param, ScalarError> {
        Ok(-a)
    }
    fn pow(&mut self, a: Param, e: i64, span: Span) -> Result<Param, ScalarError> {
        let base = if e < 0 {
            Param::one()
                .checked_div(&a)
                .ok_or(ScalarError::DivisionByZero {
                    column: Some(span.column),
                })?
        } else {
            a
        };
        let n = u32::try_from(e.unsigned_abs()).map_err(|_| ScalarError::Limit {
            what: Exceeded::PowerAt {
                column: span.column,
            },
        })?;
        if n > 64 && !base.is_const() {
            return Err(ScalarError::Limit {
                what: Exceeded::LetterPower {
                    column: span.column,
                },
            });
        }
        Ok(base.powi(n))
    }
    fn tuple(&mut self, _: Vec<Param>, span: Span) -> Result<Param, ScalarError> {
        Err(ScalarError::Parse {
            column: span.column,
            expected: Expected::Number,
            found: Found::Tuple,
        })
    }
}
