//! Expressions: a polynomial map or polynomial of the grammar, in letters when the problem
//! declares parameters.

use super::context::{expected, fail, limits, CONTEXT};
use super::number::{json_number, note_number};
use super::refuse::list_of;
use crate::input::quoted;
use crate::limits::Limits;
use crate::message::found::Found;
use crate::message::read::{Read, Wanted};
use cagd_param::{parse_param_expr, Name, ParamExpr};
use cagd_poly::{parse_expr_with, Expr};
use serde::de::{self, Deserializer, SeqAccess, Visitor};
use serde::Deserialize;
use std::fmt;

/// An expression of the grammar (`"(u, 0, u^2)"`, `"x*y"`), read under the limits: its
/// degree is at most [`Limits::max_degree`], its coefficients have at most
/// [`Limits::max_digits`] digits.
#[derive(Debug, Clone, PartialEq)]
pub struct ExprIn {
    /// The text as written.
    pub text: String,
    /// What it reads as.
    pub expr: Expr,
    /// What it reads as when its coefficients use the problem's parameters (`(f, 0, g)`,
    /// `(a u, 0, b)`); `expr` is then unused.
    pub letters: Option<ParamExpr>,
}

impl<'de> Deserialize<'de> for ExprIn {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = ExprIn;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("an expression")
            }
            fn visit_str<E: de::Error>(self, text: &str) -> Result<ExprIn, E> {
                read_expr::<E>(text)
            }
            fn visit_bool<E: de::Error>(self, b: bool) -> Result<ExprIn, E> {
                Err(expected(Wanted::Str, Found::Bool(b)))
            }
            fn visit_unit<E: de::Error>(self) -> Result<ExprIn, E> {
                Err(expected(Wanted::Str, Found::Null))
            }
            fn visit_map<A: de::MapAccess<'de>>(self, mut map: A) -> Result<ExprIn, A::Error> {
                Err(expected(
                    Wanted::Str,
                    match json_number(&mut map)? {
                        Some(text) => Found::Number(text),
                        None => Found::Object,
                    },
                ))
            }
            refuse_numbers!(Wanted::Str);
            refuse_lists!(Wanted::Str);
        }
        d.deserialize_any(V)
    }
}

/// Reads an expression under the limits of the reading context.
pub(super) fn read_expr<E: de::Error>(text: &str) -> Result<ExprIn, E> {
    let limits = limits();
    let q = quoted(text);
    let parameters = CONTEXT.with(|c| {
        c.borrow()
            .as_ref()
            .map(|ctx| ctx.parameters.clone())
            .unwrap_or_default()
    });
    let expr = match parse_expr_with(text, &limits.grammar()) {
        Ok(expr) => expr,
        Err(_) if !parameters.is_empty() => return read_expr_in_letters(text, &parameters),
        Err(e) => {
            return Err(fail(Read::Quoted {
                text: q,
                error: e.into(),
            }))
        }
    };
    let polys = match &expr {
        Expr::Scalar(p) => std::slice::from_ref(p),
        Expr::Vector(m) => m.components(),
    };
    for p in polys {
        check_expr_degree::<E>(&q, p.degree(), &limits)?;
        for (_, c) in p.terms() {
            limits.check_digits(c).map_err(|m| {
                fail::<E>(Read::Quoted {
                    text: q.clone(),
                    error: m.into(),
                })
            })?;
            note_number::<E>(c.radicand())?;
        }
    }
    Ok(ExprIn {
        text: text.to_string(),
        expr,
        letters: None,
    })
}

/// The degree of an expression's polynomial against the limit.
pub(super) fn check_expr_degree<E: de::Error>(
    q: &str,
    degree: u32,
    limits: &Limits,
) -> Result<(), E> {
    let degree = usize::try_from(degree).unwrap_or(usize::MAX);
    if degree > limits.max_degree {
        return Err(fail(Read::ExprDegree {
            text: q.to_string(),
            degree,
            max: limits.max_degree,
        }));
    }
    Ok(())
}

/// Reads an expression whose coefficients use the declared parameters.
pub(super) fn read_expr_in_letters<E: de::Error>(
    text: &str,
    parameters: &[Name],
) -> Result<ExprIn, E> {
    let limits = limits();
    let q = quoted(text);
    let letters = parse_param_expr(text, parameters, &limits.grammar()).map_err(|e| {
        fail::<E>(Read::Quoted {
            text: q.clone(),
            error: e.into(),
        })
    })?;
    let polys = match &letters {
        ParamExpr::Scalar(p) => std::slice::from_ref(p),
        ParamExpr::Vector(m) => m.components(),
    };
    for p in polys {
        check_expr_degree::<E>(&q, p.degree(), &limits)?;
        for (_, c) in p.terms() {
            note_number::<E>(c.radicand())?;
        }
    }
    Ok(ExprIn {
        text: text.to_string(),
        expr: Expr::Scalar(cagd_poly::Poly::zero()),
        letters: Some(letters),
    })
}
