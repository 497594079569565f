//! The scalars a problem runs in ([`ExactScalar`]) and their results as exact values.

use super::exact::{Exact, Number};
use crate::input::SurfaceIn;
use crate::values::put_in;
use cagd_linalg::Point;
use cagd_poly::{Poly, RationalMap, VecPoly};
use cagd_scalar::{Print, Quadratic, Scalar};
use cagd_surface::{Grid, Mesh};

/// The scalars a problem can run in: the exact ones. Each converts to [`Number`] exactly
/// (a rational is a + 0√d), so no float ever reaches an answer.
pub trait ExactScalar: Scalar {
    /// The same number as a [`Number`].
    fn exact(&self) -> Number;

    /// A number of the problem in this scalar, with the values of a problem's `"values"` put
    /// in during its solve ([`crate::values`]), or why it does not fit (a root the field has
    /// not, a letter in a numeric field, a denominator that vanishes at the values).
    fn from_number(x: &Number) -> Result<Self, crate::Message>;
}

/// The constant of a number that must have no letters.
fn constant(x: &Number) -> Result<&Quadratic, crate::Message> {
    x.as_const().ok_or_else(|| {
        crate::message::contract::Contract::InLetters {
            number: x.to_text(),
        }
        .into()
    })
}

impl ExactScalar for cagd_scalar::BigRational {
    fn exact(&self) -> Number {
        Number::Const(Quadratic::from_rational(self.clone()))
    }
    fn from_number(x: &Number) -> Result<Self, crate::Message> {
        // a constant has no letter to put a value in: read as it is (the common case)
        if let Some(c) = x.as_const() {
            return <Self as cagd_scalar::ExactRational>::try_from_number(c)
                .map_err(crate::Message::from);
        }
        <Self as cagd_scalar::ExactRational>::try_from_number(constant(put_in(x)?.as_ref())?)
            .map_err(crate::Message::from)
    }
}

impl ExactScalar for cagd_scalar::Rat {
    fn exact(&self) -> Number {
        Number::Const(Quadratic::from_rat(self.clone()))
    }
    fn from_number(x: &Number) -> Result<Self, crate::Message> {
        // a constant has no letter to put a value in: read as it is (the common case)
        if let Some(c) = x.as_const() {
            return <Self as cagd_scalar::ExactRational>::try_from_number(c)
                .map_err(crate::Message::from);
        }
        <Self as cagd_scalar::ExactRational>::try_from_number(constant(put_in(x)?.as_ref())?)
            .map_err(crate::Message::from)
    }
}

impl ExactScalar for Quadratic {
    fn exact(&self) -> Number {
        Number::Const(self.clone())
    }
    fn from_number(x: &Number) -> Result<Self, crate::Message> {
        if let Some(c) = x.as_const() {
            return Ok(c.clone());
        }
        Ok(constant(put_in(x)?.as_ref())?.clone())
    }
}

impl ExactScalar for Number {
    fn exact(&self) -> Number {
        self.clone()
    }
    fn from_number(x: &Number) -> Result<Self, crate::Message> {
        Ok(put_in(x)?.into_owned())
    }
}

/// A scalar as an exact number.
pub fn exact<S: ExactScalar>(x: &S) -> Number {
    x.exact()
}

/// A point as an exact point.
pub fn exact_point<S: ExactScalar>(p: &Point<S>) -> Point<Number> {
    Point::new(p.coords().iter().map(exact).collect())
}

/// A list of points.
pub fn exact_points<S: ExactScalar>(ps: &[Point<S>]) -> Vec<Point<Number>> {
    ps.iter().map(exact_point).collect()
}

/// A mesh.
pub fn exact_mesh<S: ExactScalar>(m: &Mesh<S>) -> Mesh<Number> {
    m.map(exact_point)
}

/// A grid of numbers.
pub fn exact_grid<S: ExactScalar>(g: &Grid<S>) -> Grid<Number> {
    g.map(exact)
}

/// A polynomial.
pub fn exact_poly<S: ExactScalar>(p: &Poly<S>) -> Poly<Number> {
    p.map_coeffs(exact)
}

/// A polynomial map.
pub fn exact_map<S: ExactScalar>(p: &VecPoly<S>) -> VecPoly<Number> {
    p.map_coeffs(exact)
}

/// A rational map.
pub fn exact_rational<S: ExactScalar>(r: &RationalMap<S>) -> RationalMap<Number> {
    RationalMap::new(exact_map(r.numerator()), exact_poly(r.denominator()))
        .unwrap_or_else(|_| RationalMap::from_polynomial(exact_map(r.numerator())))
}

impl Exact {
    /// A Bézier (or rational Bézier) surface.
    pub fn bezier_surface<S: ExactScalar>(mesh: &Mesh<S>, weights: Option<&Grid<S>>) -> Exact {
        Exact::Surface(SurfaceIn::Bezier {
            mesh: exact_mesh(mesh),
            weights: weights.map(exact_grid),
        })
    }

    /// A B-spline (or NURBS) surface, knots in the notes' convention.
    pub fn spline_surface<S: ExactScalar>(
        knots_u: &cagd_bspline::KnotVector<S>,
        knots_v: &cagd_bspline::KnotVector<S>,
        mesh: &Mesh<S>,
        weights: Option<&Grid<S>>,
    ) -> Exact {
        let notes = |k: &cagd_bspline::KnotVector<S>| {
            k.to_convention(cagd_bspline::KnotConvention::Notes)
                .iter()
                .map(exact)
                .collect::<Vec<_>>()
        };
        Exact::Surface(SurfaceIn::BSpline {
            mesh: exact_mesh(mesh),
            degree: (knots_u.degree(), knots_v.degree()),
            knots: (notes(knots_u), notes(knots_v)),
            weights: weights.map(exact_grid),
        })
    }

    /// A matrix of scalars given by rows.
    pub fn matrix<S: ExactScalar>(rows: &[Vec<S>]) -> Exact {
        Exact::Matrix(rows.iter().map(|r| r.iter().map(exact).collect()).collect())
    }
}
