//! Answers as exact values, independent of the scalar a problem ran in.
//!
//! A problem runs over `BigRational` or over a quadratic field; its results are then converted,
//! exactly, to [`Number`] (every exact scalar converts: a rational is a + 0√d). Printing,
//! JSON and the comparison with a fixture's `expected` are written once, for all scalars.

use super::quantity::Variables;
use crate::input::{CurveIn, SurfaceIn};
use cagd_linalg::Point;
use cagd_param::Name;
use cagd_poly::{Poly, RationalMap, VecPoly};
use cagd_scalar::{Print, Quadratic};

/// The numbers of problems and answers: exact, in Q or Q(√d), and in letters when the problem
/// declares parameters (a constant is held as a plain [`cagd_scalar::Quadratic`]).
pub type Number = cagd_param::Param;

/// An exact result value.
#[derive(Debug, Clone, PartialEq)]
pub enum Exact {
    /// A yes/no answer (developable, planar...).
    Bool(bool),
    /// A count or order (the continuity order).
    Int(i64),
    /// Text as written: a keyword, a value read from a problem, a parametrization with cos
    /// and sin (mathematics).
    Text(String),
    /// A sentence of the engine (a continuity verdict, "infinite"), typed: worded in each
    /// language by its [`crate::Message`], written in JSON as its English text (and equal to
    /// an expected string of that text).
    Sentence(crate::Message),
    /// A number.
    Number(Number),
    /// A point or vector.
    Point(Point<Number>),
    /// A list of points.
    Points(Vec<Point<Number>>),
    /// A matrix of numbers.
    Matrix(Vec<Vec<Number>>),
    /// A scalar polynomial.
    Poly(Poly<Number>),
    /// A polynomial map (a closed form).
    Map(VecPoly<Number>),
    /// A rational map (the closed form of a rational curve or surface).
    Rational(RationalMap<Number>),
    /// A curve.
    Curve(CurveIn<Number>),
    /// A surface.
    Surface(SurfaceIn<Number>),
    /// A list of values.
    List(Vec<Exact>),
    /// Named values: the fields of a value, each keyed by its kind (a piece's `u` interval
    /// and closed form, a knot line's knot, the corners' `G_10`), written in JSON by its name.
    Object(Vec<(crate::Quantity, Exact)>),
}

impl Exact {
    /// The variables of a closed form (this value): those of a polynomial map or polynomial; u, v and t
    /// for a rational map; none for other values.
    pub fn variables(&self) -> Variables {
        Variables(match self {
            Exact::Map(m) => m.vars(),
            Exact::Poly(p) => p.vars(),
            Exact::Rational(r) => {
                let (numerator, denominator) = (r.numerator().vars(), r.denominator().vars());
                [cagd_poly::Var::U, cagd_poly::Var::V, cagd_poly::Var::T]
                    .into_iter()
                    .filter(|v| numerator.contains(v) || denominator.contains(v))
                    .collect()
            }
            _ => Vec::new(),
        })
    }

    /// The value with the parameters of `values` replaced (an answer in letters specialized),
    /// or an error when a denominator vanishes at these values.
    ///
    /// Substituting is a ring homomorphism on polynomials, so for every operation whose
    /// algebra is polynomial or rational in the parameters, substituting into the answer in
    /// letters gives the answer of the problem with the values put in (tested for each).
    pub fn substitute(&self, values: &[(Name, Number)]) -> Result<Exact, String> {
        let failed = std::cell::Cell::new(None::<String>);
        let f = |x: &Number| -> Number {
            x.substitute(values).unwrap_or_else(|| {
                failed.set(Some(x.to_text()));
                <Number as num_traits::Zero>::zero()
            })
        };
        let out = self.map_numbers(&f)?;
        match failed.take() {
            Some(x) => Err(format!(
                "the value {x} has a denominator that vanishes at these values"
            )),
            None => Ok(out),
        }
    }

    /// The most decimal digits of a numerator or denominator among the value's numbers (of
    /// their coefficients, for a value in letters) when some number has more than `limit`
    /// digits, else `None`: what the digit limit bounds when the value is read back
    /// (`docs/format.md`, Limits). A first pass bounds the digits by the bits (a number of b
    /// bits has fewer than b·3/10 + 1 digits), so an answer within the limit prints nothing.
    pub fn digits_past(&self, limit: usize) -> Option<usize> {
        // a rational of machine words has at most 19 digits a part: no bits to count
        let words = |x: &Number| {
            x.as_const()
                .and_then(Quadratic::as_rat)
                .is_some_and(cagd_scalar::Rat::is_word)
        };
        let mut bound = 0u64;
        self.each_number(&mut |x| {
            bound = bound.max(if words(x) { 63 } else { x.max_bits() });
        });
        let bound = usize::try_from(bound.saturating_mul(3) / 10 + 1).unwrap_or(usize::MAX);
        if bound <= limit {
            return None;
        }
        let mut most = 0usize;
        self.each_number(&mut |x| {
            let text = cagd_scalar::Print::to_text(x);
            let longest = text
                .split(|c: char| !c.is_ascii_digit())
                .map(str::len)
                .max()
                .unwrap_or(0);
            most = most.max(longest);
        });
        (most > limit).then_some(most)
    }

    /// Calls `f` on every number of the value (without copying it).
    fn each_number<F: FnMut(&Number)>(&self, f: &mut F) {
        fn poly<F: FnMut(&Number)>(p: &Poly<Number>, f: &mut F) {
            for (_, c) in p.terms() {
                f(c);
            }
        }
        match self {
            Exact::Bool(_) | Exact::Int(_) | Exact::Text(_) | Exact::Sentence(_) => {}
            Exact::Number(x) => f(x),
            Exact::Point(p) => p.coords().iter().for_each(&mut *f),
            Exact::Points(ps) => ps.iter().flat_map(|p| p.coords()).for_each(&mut *f),
            Exact::Matrix(rows) => rows.iter().flatten().for_each(&mut *f),
            Exact::Poly(p) => poly(p, f),
            Exact::Map(m) => m.components().iter().for_each(|p| poly(p, f)),
            Exact::Rational(r) => {
                r.numerator().components().iter().for_each(|p| poly(p, f));
                poly(r.denominator(), f);
            }
            Exact::Curve(c) => match c {
                CurveIn::Bezier { points, weights } => {
                    points.iter().flat_map(|p| p.coords()).for_each(&mut *f);
                    weights.iter().flatten().for_each(&mut *f);
                }
                CurveIn::BSpline {
                    points,
                    knots,
                    weights,
                    ..
                } => {
                    points.iter().flat_map(|p| p.coords()).for_each(&mut *f);
                    knots.iter().for_each(&mut *f);
                    weights.iter().flatten().for_each(&mut *f);
                }
                CurveIn::Expr(m) => m.components().iter().for_each(|p| poly(p, f)),
            },
            Exact::Surface(sf) => match sf {
                SurfaceIn::Bezier { mesh, weights } => {
                    mesh.iter().flat_map(|p| p.coords()).for_each(&mut *f);
                    weights.iter().flat_map(|w| w.iter()).for_each(&mut *f);
                }
                SurfaceIn::BSpline {
                    mesh,
                    knots,
                    weights,
                    ..
                } => {
                    mesh.iter().flat_map(|p| p.coords()).for_each(&mut *f);
                    knots.0.iter().chain(&knots.1).for_each(&mut *f);
                    weights.iter().flat_map(|w| w.iter()).for_each(&mut *f);
                }
                SurfaceIn::Expr(m) => m.components().iter().for_each(|p| poly(p, f)),
            },
            Exact::List(xs) => xs.iter().for_each(|x| x.each_number(f)),
            Exact::Object(kv) => kv.iter().for_each(|(_, x)| x.each_number(f)),
        }
    }

    /// Every number of the value mapped by `f` (the structure kept).
    fn map_numbers(&self, f: &dyn Fn(&Number) -> Number) -> Result<Exact, String> {
        let point = |p: &Point<Number>| Point::new(p.coords().iter().map(f).collect());
        let numbers = |xs: &[Number]| xs.iter().map(f).collect::<Vec<_>>();
        let map = |m: &VecPoly<Number>| m.map_coeffs(f);
        Ok(match self {
            Exact::Bool(_) | Exact::Int(_) | Exact::Text(_) | Exact::Sentence(_) => self.clone(),
            Exact::Number(x) => Exact::Number(f(x)),
            Exact::Point(p) => Exact::Point(point(p)),
            Exact::Points(ps) => Exact::Points(ps.iter().map(point).collect()),
            Exact::Matrix(rows) => Exact::Matrix(rows.iter().map(|r| numbers(r)).collect()),
            Exact::Poly(p) => Exact::Poly(p.map_coeffs(f)),
            Exact::Map(m) => Exact::Map(map(m)),
            Exact::Rational(r) => Exact::Rational(
                RationalMap::new(map(r.numerator()), r.denominator().map_coeffs(f))
                    .map_err(|e| e.to_string())?,
            ),
            Exact::Curve(c) => Exact::Curve(match c {
                CurveIn::Bezier { points, weights } => CurveIn::Bezier {
                    points: points.iter().map(point).collect(),
                    weights: weights.as_deref().map(numbers),
                },
                CurveIn::BSpline {
                    points,
                    degree,
                    knots,
                    weights,
                } => CurveIn::BSpline {
                    points: points.iter().map(point).collect(),
                    degree: *degree,
                    knots: numbers(knots),
                    weights: weights.as_deref().map(numbers),
                },
                CurveIn::Expr(m) => CurveIn::Expr(map(m)),
            }),
            Exact::Surface(sf) => Exact::Surface(match sf {
                SurfaceIn::Bezier { mesh, weights } => SurfaceIn::Bezier {
                    mesh: mesh.map(point),
                    weights: weights.as_ref().map(|w| w.map(f)),
                },
                SurfaceIn::BSpline {
                    mesh,
                    degree,
                    knots,
                    weights,
                } => SurfaceIn::BSpline {
                    mesh: mesh.map(point),
                    degree: *degree,
                    knots: (numbers(&knots.0), numbers(&knots.1)),
                    weights: weights.as_ref().map(|w| w.map(f)),
                },
                SurfaceIn::Expr(m) => SurfaceIn::Expr(map(m)),
            }),
            Exact::List(xs) => Exact::List(
                xs.iter()
                    .map(|x| x.map_numbers(f))
                    .collect::<Result<_, _>>()?,
            ),
            Exact::Object(kv) => Exact::Object(
                kv.iter()
                    .map(|(k, x)| Ok((k.clone(), x.map_numbers(f)?)))
                    .collect::<Result<_, String>>()?,
            ),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Quantity;
    use cagd_poly::Var;

    #[test]
    fn a_closed_form_is_in_the_variables_of_its_value() {
        let u = Exact::Map(VecPoly::new(vec![Poly::var(Var::U)]));
        assert_eq!(u.variables(), Variables(vec![Var::U]));
        assert_eq!(Quantity::ClosedForm(u.variables()).name(), "closed_form");
        assert_eq!(Exact::Bool(true).variables(), Variables::default());
    }
}
