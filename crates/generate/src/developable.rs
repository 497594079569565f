//! Developable surfaces (notes, chapter 6, §4): ruled surfaces of zero Gaussian curvature.
//!
//! For a ruled parametrization (straight lines v ↦ c(u, v)) the curvature condition (8)
//! reduces to
//!
//! ```text
//! c_uv · (c_u × c_v) ≡ 0                                                          (9)
//! ```
//!
//! which for `c = (1 - v) c1 + v c2` is `c2'(u) · (c1'(u) × (c2(u) - c1(u))) ≡ 0` (10): the two
//! tangents and the ruling are coplanar. Cylinders (11), cones (12) and tangent surfaces pass.

use crate::common::{blend, curve_in, one_minus, spatial, OneField};
use crate::error::{NotRuled, Spatial};
use crate::{GenerateError, Input, Step, StepValue};
use cagd_bezier::{derivative_points, elevate_degree, BezierCurve, RationalBezierCurve};
use cagd_linalg::Point;
use cagd_poly::{Poly, RationalMap, Var, VecPoly};
use cagd_record::Record;
use cagd_scalar::Scalar;
use cagd_surface::{BezierSurface, Grid, Mesh, RationalBezierSurface};

/// The developability test (9) of a ruled polynomial parametrization.
#[derive(Clone, PartialEq, Debug)]
pub struct Developability<S: Scalar> {
    /// The parametrization c(u, v).
    pub surface: VecPoly<S>,
    /// `c_u`.
    pub c_u: VecPoly<S>,
    /// `c_v`.
    pub c_v: VecPoly<S>,
    /// `c_uv`.
    pub c_uv: VecPoly<S>,
    /// `c_uv · (c_u × c_v)`.
    pub polynomial: Poly<S>,
    /// Whether the polynomial is identically zero (exact).
    pub developable: bool,
}

/// The developability test of a ruled Bézier patch of bidegree (m, 1), with the planarity of
/// its first and last mesh cells (necessary, not sufficient).
#[derive(Clone, PartialEq, Debug)]
pub struct BezierDevelopability<S: Scalar> {
    /// The test (9) on the closed form of the patch.
    pub test: Developability<S>,
    /// Whether `c10, c20, c11, c21` (the cell at u = 0) are coplanar.
    pub first_cell_planar: bool,
    /// Whether `c1m-1, c2m-1, c1m, c2m` (the cell at u = 1) are coplanar.
    pub last_cell_planar: bool,
}

/// The developability test (9) of a ruled rational parametrization `N/D` (both of degree at
/// most 1 in v, so that the lines v ↦ c(u, v) are straight).
#[derive(Clone, PartialEq, Debug)]
pub struct RationalDevelopability<S: Scalar> {
    /// The numerator of `c_uv · (c_u × c_v)` with the unreduced quotient-rule derivatives (its
    /// denominator is a power of D, never zero).
    pub polynomial: Poly<S>,
    /// Whether the numerator is identically zero (exact).
    pub developable: bool,
}

/// The test of a ruled polynomial surface c(u, v) (degree at most 1 in v), in R^3:
///
/// `c_uv · (c_u × c_v) ≡ 0`   (notes, eq. (9); (10) at v = 0),
///
/// returning c_u, c_v, c_uv and the polynomial (and recording c, c_u, c_v, c_uv and the
/// polynomial); the surface is developable exactly when the polynomial is the zero polynomial.
///
/// ```
/// use cagd_generate::developability;
/// use cagd_poly::parse_vec_poly;
/// use cagd_record::NoSteps;
/// use cagd_scalar::BigRational;
/// // the hyperbolic paraboloid is not developable, the cone over a parabola is
/// let h = parse_vec_poly::<BigRational>("(u, v, u v)").unwrap();
/// let t = developability(&h, &mut NoSteps).unwrap();
/// assert_eq!(t.polynomial.to_text(), "1");
/// assert!(!t.developable);
/// let cone = parse_vec_poly::<BigRational>("(1 - v)*(u, u^2, 1)").unwrap();
/// assert!(developability(&cone, &mut NoSteps).unwrap().developable);
/// ```
pub fn developability<S: Scalar>(
    c: &VecPoly<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<Developability<S>, GenerateError> {
    spatial(Spatial::Developability, Input::Named("c".into()), c.dim())?;
    if let Some(other) = c.vars().into_iter().find(|v| *v != Var::U && *v != Var::V) {
        return Err(GenerateError::WrongVariable {
            curve: "c".into(),
            expected: "u, v".into(),
            found: other.to_string(),
        });
    }
    if c.degree_in(Var::V) > 1 {
        return Err(GenerateError::NotRuled {
            detail: NotRuled::DegreeInV {
                degree: c.degree_in(Var::V),
            },
        });
    }
    let c_u = c.partial(Var::U);
    let c_v = c.partial(Var::V);
    let c_uv = c_u.partial(Var::V);
    let polynomial = c_uv.dot(&c_u.cross(&c_v)?)?;
    let developable = polynomial.is_zero();
    rec.record(|| Step::map("c", c));
    rec.record(|| Step::map("c_u", &c_u));
    rec.record(|| Step::map("c_v", &c_v));
    rec.record(|| Step::map("c_uv", &c_uv));
    rec.record(|| Step::new("c_uv · (c_u × c_v)", StepValue::Poly(polynomial.clone())));
    Ok(Developability {
        surface: c.clone(),
        c_u,
        c_v,
        c_uv,
        polynomial,
        developable,
    })
}

/// Whether the four points of a mesh cell lie in one plane:
/// `det(c01 - c00, c10 - c00, c11 - c00) = 0`.
pub fn cell_is_planar<S: Scalar>(
    c00: &Point<S>,
    c01: &Point<S>,
    c10: &Point<S>,
    c11: &Point<S>,
) -> Result<bool, GenerateError> {
    OneField::default().points(&[c00.clone(), c01.clone(), c10.clone(), c11.clone()])?;
    spatial(Spatial::CellPlanarity, Input::Cell, c00.dim())?;
    let e1 = c01.checked_sub(c00)?;
    let e2 = c10.checked_sub(c00)?;
    let e3 = c11.checked_sub(c00)?;
    Ok(e1.cross(&e2)?.dot(&e3).is_zero())
}

/// The test (9) for a ruled Bézier patch of bidegree (m, 1) (mesh `{c10, c20; ...; c1m, c2m}`),
/// on its closed form, and the planarity of the first and last cells of the mesh, which (10)
/// at u = 0 and u = 1 requires. Planar end cells do not make the patch developable (notes, §4).
///
/// ```
/// use cagd_generate::developability_bezier;
/// use cagd_linalg::Point;
/// use cagd_poly::{parse_poly, parse_vec_poly};
/// use cagd_scalar::BigRational;
/// use cagd_surface::BezierSurface;
/// let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
/// let s = BezierSurface::from_rows(vec![
///     vec![p(&[0, -1, 1]), p(&[0, -2, 0])],
///     vec![p(&[0, 0, 1]), p(&[0, 0, 0])],
///     vec![p(&[2, 0, 1]), p(&[1, 0, -1])],
/// ]).unwrap();
/// let d = developability_bezier(&s, &mut cagd_record::NoSteps).unwrap();
/// assert_eq!(d.test.surface, parse_vec_poly(
///     "(2u^2 - u^2 v, 2u v - v - u^2 v - 1 + 2u - u^2, 1 - u^2 v - v)").unwrap());
/// assert_eq!(d.test.c_uv, parse_vec_poly("(-2u, 2 - 2u, -2u)").unwrap());
/// assert_eq!(d.test.polynomial, parse_poly("12u - 8u^3 - 4u^2").unwrap());
/// assert!(d.first_cell_planar && d.last_cell_planar && !d.test.developable);
/// ```
pub fn developability_bezier<S: Scalar>(
    s: &BezierSurface<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<BezierDevelopability<S>, GenerateError> {
    let (m, n) = s.bidegree();
    if n != 1 {
        return Err(GenerateError::NotRuled {
            detail: NotRuled::Bidegree { m, n },
        });
    }
    let test = developability(&s.closed_form()?, rec)?;
    let cell = |i: usize| -> Result<bool, GenerateError> {
        let g = |i: usize, j: usize| {
            s.mesh()
                .get(i, j)
                .cloned()
                .unwrap_or_else(|| Point::zero(3))
        };
        cell_is_planar(&g(i, 0), &g(i, 1), &g(i + 1, 0), &g(i + 1, 1))
    };
    let (first_cell_planar, last_cell_planar) = if m == 0 {
        (true, true)
    } else {
        (cell(0)?, cell(m - 1)?)
    };
    Ok(BezierDevelopability {
        test,
        first_cell_planar,
        last_cell_planar,
    })
}

/// The test (9) for a ruled rational surface `c = N/D` in R^3 whose numerator and denominator
/// have degree at most 1 in v (such as the projective parametrization of a rational ruled
/// patch): the lines v ↦ c(u, v) are straight, so c_vv is parallel to c_v and the curvature
/// condition (8) is again `c_uv · (c_u × c_v) ≡ 0`, tested on its numerator.
pub fn developability_rational<S: Scalar>(
    c: &RationalMap<S>,
) -> Result<RationalDevelopability<S>, GenerateError> {
    spatial(Spatial::Developability, Input::Named("c".into()), c.dim())?;
    let v_degree = c
        .numerator()
        .degree_in(Var::V)
        .max(c.denominator().degree_in(Var::V));
    if v_degree > 1 {
        return Err(GenerateError::NotRuled {
            detail: NotRuled::Lines { degree: v_degree },
        });
    }
    let c_u = c.partial(Var::U);
    let c_v = c.partial(Var::V);
    let c_uv = c_u.partial(Var::V);
    let polynomial = c_uv
        .numerator()
        .dot(&c_u.numerator().cross(c_v.numerator())?)?;
    let developable = polynomial.is_zero();
    Ok(RationalDevelopability {
        polynomial,
        developable,
    })
}

/// The cylindrical surface over c1(u) with rulings parallel to `w`:
///
/// `c(u, v) = c1(u) + v w`   (notes, eq. (11)),
///
/// the ruled surface between c1 and its translate c1 + w.
///
/// ```
/// use cagd_generate::{cylindrical_surface, developability};
/// use cagd_linalg::Point;
/// use cagd_poly::parse_vec_poly;
/// use cagd_scalar::BigRational;
/// let c1 = parse_vec_poly::<BigRational>("(u, u^2, u^3)").unwrap();
/// let c = cylindrical_surface(&c1, &Point::from_ints(&[0, 0, 1])).unwrap();
/// assert_eq!(c.to_text(), "(u, u^2, u^3 + v)");
/// assert!(developability(&c, &mut cagd_record::NoSteps).unwrap().developable);
/// ```
pub fn cylindrical_surface<S: Scalar>(
    c1: &VecPoly<S>,
    w: &Point<S>,
) -> Result<VecPoly<S>, GenerateError> {
    OneField::default()
        .map(c1)?
        .points(std::slice::from_ref(w))?;
    curve_in(c1, "c1", Var::U)?;
    crate::common::same_dim("c1", c1.dim(), "w", w.dim())?;
    Ok(c1.checked_add(&VecPoly::constant(w).mul_poly(&Poly::var(Var::V)))?)
}

/// The conical surface joining c1(u) to the apex `a`:
///
/// `c(u, v) = (1 - v) c1(u) + v a`   (notes, eq. (12)),
///
/// the ruled surface whose second curve has degenerated to the point a.
///
/// ```
/// use cagd_generate::{conical_surface, developability};
/// use cagd_linalg::Point;
/// use cagd_poly::parse_vec_poly;
/// use cagd_scalar::BigRational;
/// let c1 = parse_vec_poly::<BigRational>("(u, u^2, 0)").unwrap();
/// let c = conical_surface(&c1, &Point::from_ints(&[0, 0, 1])).unwrap();
/// assert_eq!(c.to_text(), "(-u v + u, -u^2 v + u^2, v)");
/// assert!(developability(&c, &mut cagd_record::NoSteps).unwrap().developable);
/// ```
pub fn conical_surface<S: Scalar>(
    c1: &VecPoly<S>,
    a: &Point<S>,
) -> Result<VecPoly<S>, GenerateError> {
    OneField::default()
        .map(c1)?
        .points(std::slice::from_ref(a))?;
    curve_in(c1, "c1", Var::U)?;
    crate::common::same_dim("c1", c1.dim(), "a", a.dim())?;
    blend(
        &one_minus(Var::V),
        c1,
        &Poly::var(Var::V),
        &VecPoly::constant(a),
    )
}

/// The tangent developable surface of the curve c(u) (its edge of regression), ruled by the
/// tangent lines:
///
/// `c(u, v) = c(u) + v c'(u)`   (slides, "superficies tangentes").
///
/// ```
/// use cagd_generate::{developability, tangent_surface};
/// use cagd_poly::parse_vec_poly;
/// use cagd_scalar::BigRational;
/// let c = parse_vec_poly::<BigRational>("(u, u^2, u^3)").unwrap();
/// let t = tangent_surface(&c).unwrap();
/// assert_eq!(t.to_text(), "(u + v, u^2 + 2 u v, u^3 + 3 u^2 v)");
/// assert!(developability(&t, &mut cagd_record::NoSteps).unwrap().developable);
/// ```
pub fn tangent_surface<S: Scalar>(c: &VecPoly<S>) -> Result<VecPoly<S>, GenerateError> {
    curve_in(c, "c", Var::U)?;
    Ok(c.checked_add(&c.partial(Var::U).mul_poly(&Poly::var(Var::V)))?)
}

/// The (m, 1) mesh of two polygons side by side.
fn columns<S: Scalar>(p1: &[Point<S>], p2: &[Point<S>]) -> Result<Mesh<S>, GenerateError> {
    let rows = p1
        .iter()
        .zip(p2)
        .map(|(a, b)| vec![a.clone(), b.clone()])
        .collect();
    Ok(Mesh::mesh(rows)?)
}

/// The cylindrical Bézier patch of bidegree (m, 1) over a Bézier curve: columns `c1i` and
/// `c1i + w` (eq. (11) on the control polygon).
pub fn cylindrical_bezier<S: Scalar>(
    c1: &BezierCurve<S>,
    w: &Point<S>,
) -> Result<BezierSurface<S>, GenerateError> {
    OneField::default()
        .bezier(c1)?
        .points(std::slice::from_ref(w))?;
    crate::common::same_dim("c1", c1.dim(), "w", w.dim())?;
    let moved: Vec<Point<S>> = c1.points().iter().map(|p| p + w).collect();
    Ok(BezierSurface::try_new(columns(c1.points(), &moved)?)?)
}

/// The conical Bézier patch of bidegree (m, 1) over a Bézier curve: columns `c1i` and the apex
/// `a` repeated (eq. (12) on the control polygon).
pub fn conical_bezier<S: Scalar>(
    c1: &BezierCurve<S>,
    a: &Point<S>,
) -> Result<BezierSurface<S>, GenerateError> {
    OneField::default()
        .bezier(c1)?
        .points(std::slice::from_ref(a))?;
    crate::common::same_dim("c1", c1.dim(), "a", a.dim())?;
    let apex = vec![a.clone(); c1.points().len()];
    Ok(BezierSurface::try_new(columns(c1.points(), &apex)?)?)
}

/// The tangent developable Bézier patch of bidegree (m, 1) of a Bézier curve of degree m:
/// columns `c_i` and `c_i + h_i`, where `h_i` are the control points of the hodograph
/// `c'(u) = m Σ Δc_i B_i^{m-1}(u)` raised to degree m; its closed form is `c(u) + v c'(u)`.
pub fn tangent_bezier<S: Scalar>(c: &BezierCurve<S>) -> Result<BezierSurface<S>, GenerateError> {
    let points = c.points();
    let hodograph = if c.degree() == 0 {
        vec![Point::zero(c.dim())]
    } else {
        elevate_degree(&derivative_points(points, 1)?, 1)?
    };
    let moved: Vec<Point<S>> = points.iter().zip(&hodograph).map(|(p, h)| p + h).collect();
    Ok(BezierSurface::try_new(columns(points, &moved)?)?)
}

/// The cylindrical rational patch over a rational Bézier curve: columns `c1i` and `c1i + w`,
/// both with the weights `w1i` (then the projective parametrization is exactly (11)).
pub fn cylindrical_rational<S: Scalar>(
    c1: &RationalBezierCurve<S>,
    w: &Point<S>,
) -> Result<RationalBezierSurface<S>, GenerateError> {
    OneField::default()
        .rational(c1)?
        .points(std::slice::from_ref(w))?;
    crate::common::same_dim("c1", c1.dim(), "w", w.dim())?;
    let moved: Vec<Point<S>> = c1.points().iter().map(|p| p + w).collect();
    let weights = Grid::from_columns(vec![c1.weights().to_vec(), c1.weights().to_vec()])?;
    Ok(RationalBezierSurface::try_new(
        columns(c1.points(), &moved)?,
        weights,
    )?)
}

/// The conical rational patch over a rational Bézier curve: columns `c1i` and the apex `a`,
/// both with the weights `w1i` (then the projective parametrization is exactly (12)).
pub fn conical_rational<S: Scalar>(
    c1: &RationalBezierCurve<S>,
    a: &Point<S>,
) -> Result<RationalBezierSurface<S>, GenerateError> {
    OneField::default()
        .rational(c1)?
        .points(std::slice::from_ref(a))?;
    crate::common::same_dim("c1", c1.dim(), "a", a.dim())?;
    let apex = vec![a.clone(); c1.points().len()];
    let weights = Grid::from_columns(vec![c1.weights().to_vec(), c1.weights().to_vec()])?;
    Ok(RationalBezierSurface::try_new(
        columns(c1.points(), &apex)?,
        weights,
    )?)
}
