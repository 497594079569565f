//! Checks and conversions shared by the constructions: curves in the right parameter, equal
//! dimensions, points of curves, closed forms and evaluation of patches.

use crate::error::{Input, Spatial};
use crate::GenerateError;
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_bspline::{BSplineCurve, NurbsCurve};
use cagd_linalg::Point;
use cagd_poly::{from_bernstein_1d, Poly, RationalMap, Var, VecPoly};
use cagd_scalar::{Scalar, ScalarError};
use cagd_surface::{BezierSurface, Mesh};

/// An error unless `c` is a curve in `var` alone (constants are allowed).
pub(crate) fn curve_in<S: Scalar>(
    c: &VecPoly<S>,
    name: &str,
    var: Var,
) -> Result<(), GenerateError> {
    match c.vars().into_iter().find(|v| *v != var) {
        None => Ok(()),
        Some(other) => Err(GenerateError::WrongVariable {
            curve: name.into(),
            expected: var.to_string(),
            found: other.to_string(),
        }),
    }
}

/// An error unless the two inputs have the same dimension.
pub(crate) fn same_dim(
    first: &str,
    first_dim: usize,
    second: &str,
    second_dim: usize,
) -> Result<(), GenerateError> {
    if first_dim == second_dim {
        Ok(())
    } else {
        Err(GenerateError::DimensionMismatch {
            first: first.into(),
            first_dim,
            second: second.into(),
            second_dim,
        })
    }
}

/// The quadratic field `Q(√d)` shared by all the numbers of a problem: exact quadratic numbers
/// with two different roots cannot be combined (the operators of `Quadratic` would panic), so
/// every construction checks its inputs first and reports [`ScalarError::MixedRoots`].
#[derive(Default)]
pub(crate) struct OneField {
    radicand: u64,
}

impl OneField {
    /// Records one number; an error if its root differs from those seen before.
    pub(crate) fn number<S: Scalar>(&mut self, x: &S) -> Result<&mut Self, GenerateError> {
        let d = x.to_number().map_or(0, |q| q.radicand());
        if d != 0 {
            if self.radicand == 0 {
                self.radicand = d;
            } else if self.radicand != d {
                return Err(GenerateError::Scalar(ScalarError::MixedRoots {
                    first: self.radicand,
                    second: d,
                }));
            }
        }
        Ok(self)
    }

    /// Records numbers.
    pub(crate) fn numbers<'a, S: Scalar>(
        &mut self,
        xs: impl IntoIterator<Item = &'a S>,
    ) -> Result<&mut Self, GenerateError> {
        for x in xs {
            self.number(x)?;
        }
        Ok(self)
    }

    /// Records the coordinates of points.
    pub(crate) fn points<S: Scalar>(
        &mut self,
        pts: &[Point<S>],
    ) -> Result<&mut Self, GenerateError> {
        self.numbers(pts.iter().flat_map(|p| p.coords()))
    }

    /// Records the control points of a Bézier curve.
    pub(crate) fn bezier<S: Scalar>(
        &mut self,
        c: &BezierCurve<S>,
    ) -> Result<&mut Self, GenerateError> {
        self.points(c.points())
    }

    /// Records the control points and weights of a rational Bézier curve.
    pub(crate) fn rational<S: Scalar>(
        &mut self,
        c: &RationalBezierCurve<S>,
    ) -> Result<&mut Self, GenerateError> {
        self.points(c.points())?.numbers(c.weights())
    }

    /// Records the knots and control points of a B-spline curve.
    pub(crate) fn bspline<S: Scalar>(
        &mut self,
        c: &BSplineCurve<S>,
    ) -> Result<&mut Self, GenerateError> {
        self.points(c.points())?.numbers(c.knots().notes())
    }

    /// Records the knots, control points and weights of a NURBS curve.
    pub(crate) fn nurbs<S: Scalar>(
        &mut self,
        c: &NurbsCurve<S>,
    ) -> Result<&mut Self, GenerateError> {
        self.points(c.points())?
            .numbers(c.weights())?
            .numbers(c.knots().notes())
    }

    /// Records the coefficients of a polynomial map.
    pub(crate) fn map<S: Scalar>(&mut self, c: &VecPoly<S>) -> Result<&mut Self, GenerateError> {
        self.numbers(
            c.components()
                .iter()
                .flat_map(|p| p.terms().map(|(_, x)| x)),
        )
    }
}

/// An error unless the input lives in R^3.
pub(crate) fn spatial(what: Spatial, input: Input, dim: usize) -> Result<(), GenerateError> {
    if dim == 3 {
        Ok(())
    } else {
        Err(GenerateError::NotSpatial { what, input, dim })
    }
}

/// The coordinates (x, y, z) of a point of R^3, or the error of [`spatial`].
pub(crate) fn xyz<S: Scalar>(
    what: Spatial,
    input: Input,
    p: &Point<S>,
) -> Result<[&S; 3], GenerateError> {
    match p.coords() {
        [x, y, z] => Ok([x, y, z]),
        c => Err(GenerateError::NotSpatial {
            what,
            input,
            dim: c.len(),
        }),
    }
}

/// The point `c(t)` of a curve in `var`.
pub(crate) fn point_at<S: Scalar>(
    c: &VecPoly<S>,
    var: Var,
    t: &S,
) -> Result<Point<S>, GenerateError> {
    Ok(c.eval(&[(var, t.clone())])?)
}

/// `c(0)` and `c(1)` of a curve in `var`.
pub(crate) fn ends<S: Scalar>(
    c: &VecPoly<S>,
    var: Var,
) -> Result<(Point<S>, Point<S>), GenerateError> {
    Ok((point_at(c, var, &S::zero())?, point_at(c, var, &S::one())?))
}

/// The first and last control points of a polygon (checked non-empty by the curve types).
pub(crate) fn polygon_ends<S: Scalar>(
    points: &[Point<S>],
) -> Result<(Point<S>, Point<S>), GenerateError> {
    match (points.first(), points.last()) {
        (Some(a), Some(b)) => Ok((a.clone(), b.clone())),
        _ => Err(GenerateError::Bezier(
            cagd_bezier::BezierError::EmptyPolygon,
        )),
    }
}

/// The constant map `p`, written as a polynomial map.
pub(crate) fn constant<S: Scalar>(p: &Point<S>) -> VecPoly<S> {
    VecPoly::constant(p)
}

/// The polynomial `1 - var`.
pub(crate) fn one_minus<S: Scalar>(var: Var) -> Poly<S> {
    Poly::one() - Poly::var(var)
}

/// `f · p + g · q` for maps `p`, `q` and scalar polynomials `f`, `g` (dimensions checked by the
/// caller).
pub(crate) fn blend<S: Scalar>(
    f: &Poly<S>,
    p: &VecPoly<S>,
    g: &Poly<S>,
    q: &VecPoly<S>,
) -> Result<VecPoly<S>, GenerateError> {
    Ok(p.mul_poly(f).checked_add(&q.mul_poly(g))?)
}

/// The Bézier curve of a control polygon as a polynomial map in `var`.
pub(crate) fn curve_form<S: Scalar>(
    c: &BezierCurve<S>,
    var: Var,
) -> Result<VecPoly<S>, GenerateError> {
    Ok(from_bernstein_1d(c.points(), var)?)
}

/// The rational Bézier curve as a rational map in `var` (projection of its homogeneous form).
pub(crate) fn rational_curve_form<S: Scalar>(
    c: &RationalBezierCurve<S>,
    var: Var,
) -> Result<RationalMap<S>, GenerateError> {
    let h = from_bernstein_1d(&c.homogeneous(), var)?;
    Ok(RationalMap::from_homogeneous(&h)?)
}

/// The closed form of a mesh read as a Bézier patch on [0, 1] x [0, 1].
pub(crate) fn mesh_form<S: Scalar>(m: &Mesh<S>) -> Result<VecPoly<S>, GenerateError> {
    Ok(BezierSurface::try_new(m.clone())?.closed_form()?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_poly::parse_vec_poly;
    use cagd_scalar::{q, BigRational};

    #[test]
    fn variables_and_dimensions_are_named() {
        let d: VecPoly<BigRational> = parse_vec_poly("(0, u + 1, u^3)").unwrap();
        assert_eq!(
            curve_in(&d, "d1", Var::V).unwrap_err().to_string(),
            "d1 must be a curve in v, but it uses u"
        );
        assert!(curve_in(&d, "c1", Var::U).is_ok());
        assert_eq!(
            same_dim("c1", 3, "d1", 2).unwrap_err().to_string(),
            "c1 has 3 coordinates but d1 has 2: they must live in the same space"
        );
        let (a, b) = ends(&d, Var::U).unwrap();
        assert_eq!(
            (a.to_text(), b.to_text()),
            ("(0, 1, 0)".into(), "(0, 2, 1)".into())
        );
        assert_eq!(
            point_at(&d, Var::U, &q!(1 / 2)).unwrap().to_text(),
            "(0, 3/2, 1/8)"
        );
    }
}
