//! Translational surfaces (notes, chapter 6, §2): the curve c1(u) slid parallel to itself
//! along d1(v),
//!
//! ```text
//! c(u, v) = c1(u) + d1(v) - a,   a = c1(0) = d1(0)                               (1)
//! ```
//!
//! characterized by a zero twist `∂²c/∂u∂v ≡ 0` (2). As meshes: `c_ij = c1i + d1j - a` (4),
//! and for rational curves the weights multiply, `w_ij = w1i ω1j` (5).

use crate::common::{constant, curve_in, polygon_ends, same_dim, OneField};
use crate::{GenerateError, Step, StepValue};
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_bspline::{BSplineCurve, NurbsCurve};
use cagd_linalg::Point;
use cagd_poly::{RationalMap, Var, VecPoly};
use cagd_record::{NoSteps, Record};
use cagd_scalar::Scalar;
use cagd_spline_surface::{BSplineSurface, NurbsSurface};
use cagd_surface::{BezierSurface, Grid, Mesh, RationalBezierSurface};

/// A translational surface as a polynomial map, with its corner a.
#[derive(Clone, PartialEq, Debug)]
pub struct TranslationalSurface<S: Scalar> {
    /// The common point `a = c1(0) = d1(0)`.
    pub a: Point<S>,
    /// `c(u, v) = c1(u) + d1(v) - a`.
    pub surface: VecPoly<S>,
}

/// A translational Bézier patch (eq. (4)), with its corner a.
#[derive(Clone, PartialEq, Debug)]
pub struct TranslationalBezier<S: Scalar> {
    /// The common control point `a = c10 = d10`.
    pub a: Point<S>,
    /// The patch of bidegree (m, n) with mesh `c_ij = c1i + d1j - a`.
    pub surface: BezierSurface<S>,
}

/// A translational rational Bézier patch (eq. (5)), with its corner a.
#[derive(Clone, PartialEq, Debug)]
pub struct TranslationalRational<S: Scalar> {
    /// The common control point `a = c10 = d10`.
    pub a: Point<S>,
    /// The patch with mesh `c_ij = c1i + d1j - a` and weights `w_ij = w1i ω1j`.
    pub surface: RationalBezierSurface<S>,
}

/// The error when the two curves do not start at the same point.
fn check_meet<S: Scalar>(
    c10: &Point<S>,
    first: &str,
    d10: &Point<S>,
    second: &str,
) -> Result<(), GenerateError> {
    if c10 == d10 {
        Ok(())
    } else {
        Err(GenerateError::CurvesDoNotMeet {
            first: first.into(),
            first_point: c10.to_text(),
            second: second.into(),
            second_point: d10.to_text(),
        })
    }
}

/// The translational surface of two polynomial curves `c1(u)`, `d1(v)` that meet at
/// `a = c1(0) = d1(0)`:
///
/// `c(u, v) = c1(u) + d1(v) - a`   (notes, eq. (1)).
///
/// `c1` must be a curve in u and `d1` a curve in v, of the same dimension; an error names the
/// two points when `c1(0) ≠ d1(0)`. Records a and `c(u, v)`.
///
/// ```
/// use cagd_generate::translational_surface;
/// use cagd_poly::parse_vec_poly;
/// use cagd_record::NoSteps;
/// use cagd_scalar::BigRational;
/// let c1 = parse_vec_poly::<BigRational>("(u, 1, u^2)").unwrap();
/// let d1 = parse_vec_poly("(0, v + 1, v^3)").unwrap();
/// let t = translational_surface(&c1, &d1, &mut NoSteps).unwrap();
/// assert_eq!(t.a.to_text(), "(0, 1, 0)");
/// assert_eq!(t.surface, parse_vec_poly("(u, v + 1, u^2 + v^3)").unwrap());
///
/// let d1 = parse_vec_poly::<BigRational>("(v, v, 0)").unwrap();
/// let c1 = parse_vec_poly("(1 + u, 0, 0)").unwrap();
/// assert_eq!(
///     translational_surface(&c1, &d1, &mut NoSteps).unwrap_err().to_string(),
///     "the curves do not meet: c1(0) = (1, 0, 0) but d1(0) = (0, 0, 0)"
/// );
/// ```
pub fn translational_surface<S: Scalar>(
    c1: &VecPoly<S>,
    d1: &VecPoly<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<TranslationalSurface<S>, GenerateError> {
    OneField::default().map(c1)?.map(d1)?;
    curve_in(c1, "c1", Var::U)?;
    curve_in(d1, "d1", Var::V)?;
    same_dim("c1", c1.dim(), "d1", d1.dim())?;
    let a = c1.eval(&[(Var::U, S::zero())])?;
    let d10 = d1.eval(&[(Var::V, S::zero())])?;
    check_meet(&a, "c1(0)", &d10, "d1(0)")?;
    let surface = c1.checked_add(d1)?.checked_sub(&constant(&a))?;
    rec.record(|| Step::point("a", &a));
    rec.record(|| Step::map("c(u, v)", &surface));
    Ok(TranslationalSurface { a, surface })
}

/// The twist `∂²c/∂u∂v` of a polynomial surface; it is identically zero exactly for the
/// translational surfaces (notes, eq. (2)).
///
/// ```
/// use cagd_generate::{has_zero_twist, twist};
/// use cagd_poly::parse_vec_poly;
/// use cagd_scalar::BigRational;
/// let c = parse_vec_poly::<BigRational>("(u, v + 1, u^2 + v^3)").unwrap();
/// assert!(has_zero_twist(&c));
/// let h = parse_vec_poly::<BigRational>("(u, v, u v)").unwrap();
/// assert_eq!(twist(&h).to_text(), "(0, 0, 1)");
/// assert!(!has_zero_twist(&h));
/// ```
pub fn twist<S: Scalar>(c: &VecPoly<S>) -> VecPoly<S> {
    c.partial(Var::U).partial(Var::V)
}

/// Whether the twist `∂²c/∂u∂v` vanishes identically (exact), eq. (2).
pub fn has_zero_twist<S: Scalar>(c: &VecPoly<S>) -> bool {
    twist(c).is_zero()
}

/// The twist `∂²c/∂u∂v` of a rational surface `N/D`, by the quotient rule twice (not
/// reduced). It is the zero function exactly when its numerator is the zero polynomial.
pub fn rational_twist<S: Scalar>(c: &RationalMap<S>) -> RationalMap<S> {
    c.partial(Var::U).partial(Var::V)
}

/// The twists of a control mesh, `c_{i+1,j+1} - c_{i+1,j} - c_{i,j+1} + c_{i,j}`: all zero
/// exactly for the meshes of translational patches (notes, eq. (3)).
pub fn mesh_twists<S: Scalar>(mesh: &Mesh<S>) -> Grid<Point<S>> {
    let rows = mesh.rows().saturating_sub(1);
    let cols = mesh.cols().saturating_sub(1);
    Grid::from_fn(rows, cols, |i, j| {
        match (
            mesh.get(i, j),
            mesh.get(i, j + 1),
            mesh.get(i + 1, j),
            mesh.get(i + 1, j + 1),
        ) {
            (Some(c00), Some(c01), Some(c10), Some(c11)) => &(&(c11 - c10) - c01) + c00,
            _ => Point::zero(mesh.dim()),
        }
    })
}

/// The corner a and the mesh of eq. (4).
struct Translated<S: Scalar> {
    a: Point<S>,
    mesh: Mesh<S>,
}

/// The mesh `c_ij = c1i + d1j - a` of eq. (4), recording a and one step per vertex.
fn translate_polygons<S: Scalar>(
    c1: &[Point<S>],
    d1: &[Point<S>],
    rec: &mut impl Record<Step<S>>,
) -> Result<Translated<S>, GenerateError> {
    let (a, _) = polygon_ends(c1)?;
    let (d10, _) = polygon_ends(d1)?;
    same_dim("c1", a.dim(), "d1", d10.dim())?;
    check_meet(&a, "c1(0)", &d10, "d1(0)")?;
    rec.record(|| Step::point("a", &a));
    let mut rows = Vec::with_capacity(c1.len());
    for (i, ci) in c1.iter().enumerate() {
        let mut row = Vec::with_capacity(d1.len());
        for (j, dj) in d1.iter().enumerate() {
            let p = &(ci + dj) - &a;
            rec.record(|| Step::point(format!("c_{i},{j}"), &p));
            row.push(p);
        }
        rows.push(row);
    }
    Ok(Translated {
        a,
        mesh: Mesh::mesh(rows)?,
    })
}

/// The translational Bézier patch of two Bézier curves of degrees m and n with a common first
/// control point `a = c10 = d10`:
///
/// `c_ij = c1i + d1j - a`,  i = 0..m, j = 0..n   (notes, eq. (4), from the zero twist (3)).
///
/// Records a, every `c_i,j` and the mesh.
///
/// ```
/// use cagd_bezier::BezierCurve;
/// use cagd_generate::translational_bezier;
/// use cagd_linalg::Point;
/// use cagd_record::NoSteps;
/// use cagd_scalar::BigRational;
/// let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
/// let c1 = BezierCurve::try_new(vec![p(&[1, 0, 0]), p(&[2, 0, 1]), p(&[3, 0, 0])]).unwrap();
/// let d1 = BezierCurve::try_new(vec![p(&[1, 0, 0]), p(&[1, 1, -1]), p(&[1, 2, 0])]).unwrap();
/// let t = translational_bezier(&c1, &d1, &mut NoSteps).unwrap();
/// assert_eq!(
///     t.surface.mesh().to_text(),
///     "{(1, 0, 0), (1, 1, -1), (1, 2, 0); (2, 0, 1), (2, 1, 0), (2, 2, 1); \
///       (3, 0, 0), (3, 1, -1), (3, 2, 0)}"
/// );
/// ```
pub fn translational_bezier<S: Scalar>(
    c1: &BezierCurve<S>,
    d1: &BezierCurve<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<TranslationalBezier<S>, GenerateError> {
    OneField::default().bezier(c1)?.bezier(d1)?;
    let Translated { a, mesh } = translate_polygons(c1.points(), d1.points(), rec)?;
    let surface = BezierSurface::try_new(mesh)?;
    rec.record(|| Step::mesh("mesh", surface.mesh()));
    Ok(TranslationalBezier { a, surface })
}

/// The translational rational Bézier patch of two rational Bézier curves with a common first
/// control point a: the mesh of (4) and the products of the weights,
///
/// `w_ij = w1i ω1j`,  `c_ij = c1i + d1j - a`   (notes, eq. (5)),
///
/// read from `c1(u) + d1(v) - a` over the common denominator. (Applying (4) to the weights
/// instead could give negative weights.) The weights are nonzero since those of the curves are.
/// Records a, the mesh and the weights.
///
/// ```
/// use cagd_bezier::RationalBezierCurve;
/// use cagd_generate::translational_rational;
/// use cagd_linalg::Point;
/// use cagd_record::NoSteps;
/// use cagd_scalar::{q, BigRational};
/// let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
/// let c1 = RationalBezierCurve::try_new(
///     vec![p(&[1, 0, 0]), p(&[1, 1, 0]), p(&[0, 1, 0])], vec![q!(1), q!(1/2), q!(1)]).unwrap();
/// let d1 = RationalBezierCurve::try_new(vec![p(&[1, 0, 0]), p(&[1, 0, 1])], vec![q!(2), q!(3)])
///     .unwrap();
/// let t = translational_rational(&c1, &d1, &mut NoSteps).unwrap();
/// assert_eq!(t.surface.weights().to_text_numbers(), "{2, 3; 1, 3/2; 2, 3}");
/// assert_eq!(t.surface.mesh().to_text(), "{(1, 0, 0), (1, 0, 1); (1, 1, 0), (1, 1, 1); (0, 1, 0), (0, 1, 1)}");
/// ```
pub fn translational_rational<S: Scalar>(
    c1: &RationalBezierCurve<S>,
    d1: &RationalBezierCurve<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<TranslationalRational<S>, GenerateError> {
    OneField::default().rational(c1)?.rational(d1)?;
    let Translated { a, mesh } = translate_polygons(c1.points(), d1.points(), &mut NoSteps)?;
    rec.record(|| Step::point("a", &a));
    let weights = Grid::from_fn(c1.weights().len(), d1.weights().len(), |i, j| {
        match (c1.weights().get(i), d1.weights().get(j)) {
            (Some(wi), Some(oj)) => wi.mul_ref(oj),
            _ => S::zero(),
        }
    });
    let surface = RationalBezierSurface::try_new(mesh, weights)?;
    rec.record(|| Step::mesh("mesh", surface.mesh()));
    rec.record(|| Step::new("weights", StepValue::Weights(surface.weights().clone())));
    Ok(TranslationalRational { a, surface })
}

/// A translational B-spline surface (eq. (4) on B-spline meshes).
#[derive(Clone, PartialEq, Debug)]
pub struct TranslationalBSpline<S: Scalar> {
    /// The common point `a = c1(u_start) = d1(v_start)`.
    pub a: Point<S>,
    /// The surface with the knots of c1 in u, those of d1 in v, and mesh `c_ij = c1i + d1j - a`.
    pub surface: BSplineSurface<S>,
}

/// A translational NURBS surface (eq. (5) on NURBS meshes).
#[derive(Clone, PartialEq, Debug)]
pub struct TranslationalNurbs<S: Scalar> {
    /// The common point `a = c1(u_start) = d1(v_start)`.
    pub a: Point<S>,
    /// The surface with mesh `c_ij = c1i + d1j - a` and weights `w_ij = w1i ω1j`.
    pub surface: NurbsSurface<S>,
}

/// The mesh `c_ij = c1i + d1j - a` for any polygons and point a (no checks).
fn translated_mesh<S: Scalar>(
    c1: &[Point<S>],
    d1: &[Point<S>],
    a: &Point<S>,
) -> Result<Mesh<S>, GenerateError> {
    Ok(Mesh::mesh(
        c1.iter()
            .map(|ci| d1.iter().map(|dj| &(ci + dj) - a).collect())
            .collect(),
    )?)
}

/// The common start point `c1(u0) = d1(v0)` of two curves on [u0, u1] and [v0, v1].
fn start_point<S: Scalar>(
    c1: impl Fn(&S) -> Result<Point<S>, GenerateError>,
    u0: &S,
    d1: impl Fn(&S) -> Result<Point<S>, GenerateError>,
    v0: &S,
) -> Result<Point<S>, GenerateError> {
    let (c10, d10) = (c1(u0)?, d1(v0)?);
    same_dim("c1", c10.dim(), "d1", d10.dim())?;
    let first = format!("c1({})", u0.to_text());
    check_meet(&c10, &first, &d10, &format!("d1({})", v0.to_text()))?;
    Ok(c10)
}

/// The translational B-spline surface of two B-spline curves that start at the same point
/// `a = c1(u_start) = d1(v_start)`: knots of c1 in u, of d1 in v, and the mesh
///
/// `c_ij = c1i + d1j - a`   (notes, eq. (4), "también válida para superficies B-spline"):
///
/// since the B-spline bases sum to 1, `Σ Σ (c1i + d1j - a) N_i(u) N_j(v) = c1(u) + d1(v) - a`.
/// Records a and the mesh.
pub fn translational_bspline<S: Scalar>(
    c1: &BSplineCurve<S>,
    d1: &BSplineCurve<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<TranslationalBSpline<S>, GenerateError> {
    OneField::default().bspline(c1)?.bspline(d1)?;
    let a = start_point(
        |t| Ok(c1.eval(t)?),
        &c1.domain().0,
        |t| Ok(d1.eval(t)?),
        &d1.domain().0,
    )?;
    let mesh = translated_mesh(c1.points(), d1.points(), &a)?;
    let surface = BSplineSurface::try_new(c1.knots().clone(), d1.knots().clone(), mesh)?;
    rec.record(|| Step::point("a", &a));
    rec.record(|| Step::mesh("mesh", surface.mesh()));
    Ok(TranslationalBSpline { a, surface })
}

/// The translational NURBS surface of two NURBS curves that start at the same point a: the
/// mesh of (4) with the products of the weights,
///
/// `w_ij = w1i ω1j`, `c_ij = c1i + d1j - a`   (notes, eq. (5), valid for NURBS). Records a, the
/// mesh and the weights.
pub fn translational_nurbs<S: Scalar>(
    c1: &NurbsCurve<S>,
    d1: &NurbsCurve<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<TranslationalNurbs<S>, GenerateError> {
    OneField::default().nurbs(c1)?.nurbs(d1)?;
    let a = start_point(
        |t| Ok(c1.eval(t)?),
        &c1.domain().0,
        |t| Ok(d1.eval(t)?),
        &d1.domain().0,
    )?;
    let mesh = translated_mesh(c1.points(), d1.points(), &a)?;
    let weights = Grid::from_fn(c1.weights().len(), d1.weights().len(), |i, j| {
        match (c1.weights().get(i), d1.weights().get(j)) {
            (Some(wi), Some(oj)) => wi.mul_ref(oj),
            _ => S::zero(),
        }
    });
    let surface = NurbsSurface::try_new(c1.knots().clone(), d1.knots().clone(), mesh, weights)?;
    rec.record(|| Step::point("a", &a));
    rec.record(|| Step::mesh("mesh", surface.mesh()));
    rec.record(|| Step::weights("weights", surface.weights()));
    Ok(TranslationalNurbs { a, surface })
}
