//! Surfaces of revolution (notes, chapter 6, §6): a curve of the XZ plane,
//! `c1(u) = (f(u), 0, g(u))`, rotated about the Z axis,
//!
//! ```text
//! c(u, v) = (f(u) cos v, f(u) sin v, g(u)),   v ∈ [0, 2π]                        (21)
//! ```
//!
//! The parallels are circles, which are rational: a quarter circle of radius r at height h
//! has control points `(r, 0, h), (r, r, h), (0, r, h)` and weights `1, √2/2, 1`. So the
//! rational Bézier mesh of a quadrant has as row i the quarter circle of the vertex c_i, with
//! the weights of that row multiplied by w_i: `{w_i, w_i √2/2, w_i}`.

use crate::common::{curve_in, spatial, xyz, OneField};
use crate::error::{Needs, Spatial};
use crate::{GenerateError, Input, Note, Step, StepValue};
use cagd_bezier::RationalBezierCurve;
use cagd_bspline::{circle_of_arcs, KnotVector, NurbsCurve};
use cagd_linalg::Point;
use cagd_poly::{Poly, Var, VecPoly};
use cagd_record::Record;
use cagd_scalar::{Scalar, ScalarError};
use cagd_spline_surface::NurbsSurface;
use cagd_surface::{Grid, Mesh, RationalBezierSurface};

/// The parametric surface of revolution (21), which is not polynomial (cos v, sin v): kept
/// as its two functions f(u), g(u) and printed as text.
#[derive(Clone, PartialEq, Debug)]
pub struct RevolutionSurface<S: Scalar> {
    /// The radius function f(u) (the first coordinate of the curve).
    pub f: Poly<S>,
    /// The height function g(u) (the third coordinate of the curve).
    pub g: Poly<S>,
}

/// A quadrant of a surface of revolution as a rational Bézier patch.
#[derive(Clone, PartialEq, Debug)]
pub struct RevolutionBezier<S: Scalar> {
    /// The generating curve of the XZ plane.
    pub curve: RationalBezierCurve<S>,
    /// Which quadrant: v from `quadrant · π/2` to `(quadrant + 1) · π/2`.
    pub quadrant: usize,
    /// The patch of bidegree (n, 2): row i is the quarter circle of c_i, with weights
    /// `w_i · {1, √2/2, 1}`.
    pub surface: RationalBezierSurface<S>,
}

/// The surface of revolution of a polynomial curve `c1(u) = (f(u), 0, g(u))` about the Z axis:
///
/// `c(u, v) = (f(u) cos v, f(u) sin v, g(u))`   (notes, eq. (21)).
///
/// ```
/// use cagd_generate::revolution_surface;
/// use cagd_poly::parse_vec_poly;
/// use cagd_scalar::{q, BigRational};
/// let c1 = parse_vec_poly::<BigRational>("(u + 1, 0, u^2)").unwrap();
/// let s = revolution_surface(&c1).unwrap();
/// assert_eq!(s.to_text(), "((u + 1) cos v, (u + 1) sin v, u^2)");
/// // cos v = 3/5, sin v = 4/5 is a rational point of the circle
/// assert_eq!(s.point(&q!(1), &q!(3/5), &q!(4/5)).unwrap().to_text(), "(6/5, 8/5, 1)");
/// let bad = parse_vec_poly::<BigRational>("(u, u, 0)").unwrap();
/// assert!(revolution_surface(&bad).unwrap_err().to_string().contains("not in the XZ plane"));
/// ```
pub fn revolution_surface<S: Scalar>(
    c1: &VecPoly<S>,
) -> Result<RevolutionSurface<S>, GenerateError> {
    spatial(Spatial::Revolution, Input::Named("c1".into()), c1.dim())?;
    curve_in(c1, "c1", Var::U)?;
    let comp = |i: usize| c1.component(i).cloned().unwrap_or_else(Poly::zero);
    let y = comp(1);
    if !y.is_zero() {
        return Err(GenerateError::CurveNotInXzPlane { y: y.to_text() });
    }
    Ok(RevolutionSurface {
        f: comp(0),
        g: comp(2),
    })
}

/// `f cos v` as text: `u cos v`, `(u + 1) cos v`, `cos v`, `-cos v`, `0`.
fn times_trig<S: Scalar>(f: &Poly<S>, trig: &str, latex: bool) -> String {
    let text = if latex { f.to_latex() } else { f.to_text() };
    if f.is_zero() {
        "0".into()
    } else if f.as_constant().is_some_and(|c| c.is_one()) {
        trig.into()
    } else if f.as_constant().is_some_and(|c| (-c).is_one()) {
        format!("-{trig}")
    } else if f.num_terms() > 1 {
        format!("({text}) {trig}")
    } else {
        format!("{text} {trig}")
    }
}

impl<S: Scalar> RevolutionSurface<S> {
    /// Plain text: `(f(u) cos v, f(u) sin v, g(u))`.
    pub fn to_text(&self) -> String {
        format!(
            "({}, {}, {})",
            times_trig(&self.f, "cos v", false),
            times_trig(&self.f, "sin v", false),
            self.g.to_text()
        )
    }

    /// LaTeX: `\left(f(u) \cos v, f(u) \sin v, g(u)\right)`.
    pub fn to_latex(&self) -> String {
        format!(
            "\\left({}, {}, {}\\right)",
            times_trig(&self.f, "\\cos v", true),
            times_trig(&self.f, "\\sin v", true),
            self.g.to_latex()
        )
    }

    /// The point `(f(u) cos v, f(u) sin v, g(u))` for exact values of cos v and sin v; an
    /// error unless `cos² v + sin² v = 1` (checked exactly for the exact types).
    pub fn point(&self, u: &S, cos_v: &S, sin_v: &S) -> Result<Point<S>, GenerateError> {
        OneField::default()
            .numbers(self.f.terms().chain(self.g.terms()).map(|(_, x)| x))?
            .numbers([u, cos_v, sin_v])?;
        if S::is_exact() && !(cos_v.mul_ref(cos_v) + sin_v.mul_ref(sin_v)).is_one() {
            return Err(GenerateError::NotOnUnitCircle {
                cos: cos_v.to_text(),
                sin: sin_v.to_text(),
            });
        }
        let at = [(Var::U, u.clone())];
        let f = self.f.eval(&at)?;
        let g = self.g.eval(&at)?;
        Ok(Point::new(vec![f.mul_ref(cos_v), f.mul_ref(sin_v), g]))
    }
}

/// `√2/2 = cos(π/4)`, the middle weight of a quarter circle, in the scalar type:
/// `S::sqrt_of(2)` divided by `S::from_i64(2)`. Over exact rationals (no √2) it is an error
/// that says the construction needs the quadratic field.
///
/// ```
/// use cagd_generate::sqrt2_over_2;
/// use cagd_scalar::{BigRational, Print, Quadratic};
/// assert_eq!(sqrt2_over_2::<Quadratic>().unwrap().to_text(), "√2/2");
/// assert!(sqrt2_over_2::<BigRational>().unwrap_err().to_string().contains("quadratic field"));
/// ```
pub fn sqrt2_over_2<S: Scalar>() -> Result<S, GenerateError> {
    S::sqrt_of(2)
        .map(|root| root / S::from_i64(2))
        .ok_or_else(|| GenerateError::NeedsQuadraticField {
            what: Needs::QuarterCircleWeight,
            number: "√2/2".into(),
            // what converting the number √2/2 to a field without it says
            source: ScalarError::NotRational {
                value: "√2/2".into(),
            },
        })
}

/// The control points of the quarter circle described by `p = (x, 0, z)` turning about the Z
/// axis through the quadrant `quadrant` (0 to 3; v from `k π/2` to `(k+1) π/2`): for k = 0,
/// `(x, 0, z), (x, x, z), (0, x, z)`, with weights `1, √2/2, 1`; each further quadrant turns
/// them by π/2, `(x, y) ↦ (-y, x)`.
///
/// ```
/// use cagd_generate::quarter_circle;
/// use cagd_linalg::Point;
/// use cagd_scalar::BigRational;
/// let arc = quarter_circle(&Point::<BigRational>::from_ints(&[2, 0, 1]), 1).unwrap();
/// let text: Vec<String> = arc.iter().map(|p| p.to_text()).collect();
/// assert_eq!(text, ["(0, 2, 1)", "(-2, 2, 1)", "(-2, 0, 1)"]);
/// ```
pub fn quarter_circle<S: Scalar>(
    p: &Point<S>,
    quadrant: usize,
) -> Result<[Point<S>; 3], GenerateError> {
    let [x, _, z] = xyz(Spatial::CircleAboutZ, Input::Point, p)?;
    let (x, z) = (x.clone(), z.clone());
    let zero = S::zero();
    let mut arc = [[x.clone(), zero.clone()], [x.clone(), x.clone()], [zero, x]];
    for _ in 0..quadrant % 4 {
        for q in arc.iter_mut() {
            let [a, b] = q.clone();
            *q = [-b, a];
        }
    }
    Ok(arc.map(|[a, b]| Point::new(vec![a, b, z.clone()])))
}

/// An error unless every control point is a point of the XZ plane of R^3.
fn check_profile<S: Scalar>(points: &[Point<S>]) -> Result<(), GenerateError> {
    for (index, p) in points.iter().enumerate() {
        let [_, y, _] = xyz(Spatial::Revolution, Input::Curve, p)?;
        if !y.is_zero() {
            return Err(GenerateError::NotInXzPlane {
                index,
                point: p.to_text(),
            });
        }
    }
    Ok(())
}

/// The first quadrant (v ∈ [0, π/2]) of the surface of revolution of a rational Bézier curve
/// of the XZ plane, as a rational Bézier patch of bidegree (n, 2) (notes, §6): row i is the
/// quarter circle of the vertex `c_i = (x_i, 0, z_i)`,
///
/// `{(x_i, 0, z_i), (x_i, x_i, z_i), (0, x_i, z_i)}`, weights `{w_i, w_i √2/2, w_i}`.
///
/// Needs √2/2: compute over the quadratic field ([`cagd_scalar::Quadratic`]). A polynomial
/// curve is the rational one with all weights 1.
///
/// ```
/// use cagd_bezier::RationalBezierCurve;
/// use cagd_generate::{revolution_bezier, sqrt2_over_2};
/// use cagd_linalg::Point;
/// use cagd_scalar::{FieldOps, Print, Quadratic};
/// let p = |c: &[i64]| Point::<Quadratic>::from_ints(c);
/// let one = Quadratic::from_i64(1);
/// // the sphere octant: the quarter circle of the XZ plane turned about Z
/// let arc = RationalBezierCurve::try_new(vec![p(&[1, 0, 0]), p(&[1, 0, 1]), p(&[0, 0, 1])],
///     vec![one.clone(), sqrt2_over_2().unwrap(), one]).unwrap();
/// let octant = revolution_bezier(&arc, &mut cagd_record::NoSteps).unwrap();
/// assert_eq!(octant.surface.mesh().to_text(),
///     "{(1, 0, 0), (1, 1, 0), (0, 1, 0); (1, 0, 1), (1, 1, 1), (0, 1, 1); \
///       (0, 0, 1), (0, 0, 1), (0, 0, 1)}");
/// assert_eq!(octant.surface.weights().to_text_numbers(),
///     "{1, √2/2, 1; √2/2, 1/2, √2/2; 1, √2/2, 1}");
/// ```
pub fn revolution_bezier<S: Scalar>(
    curve: &RationalBezierCurve<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<RevolutionBezier<S>, GenerateError> {
    revolution_bezier_quadrant(curve, 0, rec)
}

/// The quadrant `quadrant` (0 to 3, v from `k π/2` to `(k+1) π/2`) of the surface of
/// revolution, as [`revolution_bezier`]: the same weights, the mesh turned by `k π/2`. Records
/// the mesh and the weights.
pub fn revolution_bezier_quadrant<S: Scalar>(
    curve: &RationalBezierCurve<S>,
    quadrant: usize,
    rec: &mut impl Record<Step<S>>,
) -> Result<RevolutionBezier<S>, GenerateError> {
    OneField::default()
        .rational(curve)?
        .number(&sqrt2_over_2::<S>()?)?;
    check_profile(curve.points())?;
    let middle = sqrt2_over_2::<S>()?;
    let mut rows = Vec::with_capacity(curve.points().len());
    let mut weights = Vec::with_capacity(curve.points().len());
    for (p, w) in curve.points().iter().zip(curve.weights()) {
        rows.push(quarter_circle(p, quadrant)?.to_vec());
        weights.push(vec![w.clone(), w.mul_ref(&middle), w.clone()]);
    }
    let surface = RationalBezierSurface::try_new(Mesh::mesh(rows)?, Grid::from_rows(weights)?)?;
    rec.record(|| Step::mesh("mesh", surface.mesh()));
    rec.record(|| Step::new("weights", StepValue::Weights(surface.weights().clone())));
    Ok(RevolutionBezier {
        curve: curve.clone(),
        quadrant: quadrant % 4,
        surface,
    })
}

impl<S: Scalar> RevolutionBezier<S> {
    /// Checks the point of the patch at (u, v) exactly against the curve: its parallel is the
    /// circle of radius |f(u)| at height g(u), so `x² + y² = f(u)²` and `z = g(u)`, where
    /// `(f(u), 0, g(u))` is the point of the curve.
    pub fn on_parallel(&self, u: &S, v: &S) -> Result<bool, GenerateError> {
        OneField::default()
            .rational(&self.curve)?
            .numbers(self.surface.weights().iter())?
            .numbers([u, v])?;
        let p = self.surface.eval(u, v)?;
        let q = self.curve.eval(u)?;
        let [x, y, z] = xyz(Spatial::Revolution, Input::Surface, &p)?;
        let [f, _, g] = xyz(Spatial::Revolution, Input::Curve, &q)?;
        Ok(x.mul_ref(x) + y.mul_ref(y) == f.mul_ref(f) && z == g)
    }
}

/// A whole surface of revolution as a NURBS surface: the profile in u, a circle in v.
#[derive(Clone, PartialEq, Debug)]
pub struct RevolutionNurbs<S: Scalar> {
    /// The generating curve of the XZ plane.
    pub profile: NurbsCurve<S>,
    /// The unit circle of the XY plane whose polygon, weights and knots give the parallels.
    pub circle: NurbsCurve<S>,
    /// The surface: row i is the circle's polygon scaled by x_i at height z_i, weights
    /// `w_i ω_j`, knots of the profile in u and of the circle in v.
    pub surface: NurbsSurface<S>,
    /// The two knot vectors.
    pub notes: Vec<Note>,
}

/// A rational Bézier curve as a NURBS curve of one span: knots `{a, ..., a, b, ..., b}` (each
/// end n times, notes' convention) on its domain [a, b], same points and weights (the B-spline
/// basis of these knots is the Bernstein basis).
pub fn nurbs_from_bezier<S: Scalar>(
    curve: &RationalBezierCurve<S>,
) -> Result<NurbsCurve<S>, GenerateError> {
    let (a, b) = curve.domain();
    let knots = KnotVector::bezier(curve.degree(), a.clone(), b.clone())?;
    Ok(NurbsCurve::try_new(
        knots,
        curve.points().to_vec(),
        curve.weights().to_vec(),
    )?)
}

/// The surface of revolution of a NURBS curve of the XZ plane about the Z axis, with the
/// parallels drawn by a unit circle of the XY plane given as a NURBS curve (notes, §6, "la
/// construcción anterior también es válida para curvas B-spline"): with the profile's
/// polygon `c_i = (x_i, 0, z_i)`, weights `w_i`, and the circle's polygon `(X_j, Y_j)`,
/// weights `ω_j`,
///
/// `c_ij = (x_i X_j, x_i Y_j, z_i)`,  `w_ij = w_i ω_j`,
///
/// knots of the profile in u and of the circle in v. The circle must be the unit circle
/// centred at the origin ([`cagd_bspline::unit_circle`], [`cagd_bspline::circle_slides`] with
/// R = 1, [`cagd_bspline::circle_of_arcs`]); its points may be given in R^2 or in R^3 with
/// z = 0. Records the mesh and the weights; its notes give the two knot vectors.
pub fn revolution_nurbs<S: Scalar>(
    profile: &NurbsCurve<S>,
    circle: &NurbsCurve<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<RevolutionNurbs<S>, GenerateError> {
    OneField::default().nurbs(profile)?.nurbs(circle)?;
    check_profile(profile.points())?;
    let planar: Vec<(S, S)> = circle
        .points()
        .iter()
        .enumerate()
        .map(|(j, p)| match p.coords() {
            [x, y] => Ok((x.clone(), y.clone())),
            [x, y, z] if z.is_zero() => Ok((x.clone(), y.clone())),
            _ => Err(GenerateError::NotACircleOfXy {
                index: j,
                point: p.to_text(),
            }),
        })
        .collect::<Result<_, _>>()?;
    let rows = profile
        .points()
        .iter()
        .map(|c| {
            let [x, _, z] = xyz(Spatial::Revolution, Input::Curve, c)?;
            Ok(planar
                .iter()
                .map(|(cx, cy)| Point::new(vec![x.mul_ref(cx), x.mul_ref(cy), z.clone()]))
                .collect())
        })
        .collect::<Result<Vec<Vec<Point<S>>>, GenerateError>>()?;
    let weights = Grid::from_fn(
        profile.weights().len(),
        circle.weights().len(),
        |i, j| match (profile.weights().get(i), circle.weights().get(j)) {
            (Some(w), Some(o)) => w.mul_ref(o),
            _ => S::zero(),
        },
    );
    let surface = NurbsSurface::try_new(
        profile.knots().clone(),
        circle.knots().clone(),
        Mesh::mesh(rows)?,
        weights,
    )?;
    rec.record(|| Step::mesh("mesh", surface.mesh()));
    rec.record(|| Step::weights("weights", surface.weights()));
    let notes = vec![
        Note::KnotsInU {
            knots: surface.knots_u().to_text(),
        },
        Note::KnotsInV {
            knots: surface.knots_v().to_text(),
        },
    ];
    Ok(RevolutionNurbs {
        profile: profile.clone(),
        circle: circle.clone(),
        surface,
        notes,
    })
}

/// [`revolution_nurbs`] with the unit circle of `arcs` arcs on `domain`
/// ([`cagd_bspline::circle_of_arcs`]): 4 arcs on [0, 1] is the notes' 9-point circle (knots
/// `{0, 0, 1/4, 1/4, 1/2, 1/2, 3/4, 3/4, 1, 1}`, weights `1, √2/2, ...`), on [0, 4] the slides'
/// (knots `[0, 0, 1, 1, 2, 2, 3, 3, 4, 4]`); 3 arcs has middle weights 1/2 but vertices with √3.
///
/// ```
/// use cagd_bezier::RationalBezierCurve;
/// use cagd_generate::{nurbs_from_bezier, revolution_nurbs_arcs, sqrt2_over_2};
/// use cagd_linalg::Point;
/// use cagd_scalar::{FieldOps, Print, Quadratic};
/// let p = |c: &[i64]| Point::<Quadratic>::from_ints(c);
/// let one = Quadratic::from_i64(1);
/// let arc = RationalBezierCurve::try_new(vec![p(&[1, 0, 0]), p(&[1, 0, 1]), p(&[0, 0, 1])],
///     vec![one.clone(), sqrt2_over_2().unwrap(), one]).unwrap();
/// let hemisphere = revolution_nurbs_arcs(&nurbs_from_bezier(&arc).unwrap(), 4,
///     (Quadratic::from_i64(0), Quadratic::from_i64(4)), &mut cagd_record::NoSteps).unwrap();
/// assert_eq!(hemisphere.surface.knots_u().to_text(), "{0, 0, 1, 1}");
/// assert_eq!(hemisphere.surface.knots_v().to_text(), "{0, 0, 1, 1, 2, 2, 3, 3, 4, 4}");
/// assert_eq!(hemisphere.surface.weights().row(1).unwrap()[1].to_text(), "1/2");
/// ```
pub fn revolution_nurbs_arcs<S: Scalar>(
    profile: &NurbsCurve<S>,
    arcs: usize,
    domain: (S, S),
    rec: &mut impl Record<Step<S>>,
) -> Result<RevolutionNurbs<S>, GenerateError> {
    let circle = circle_of_arcs(arcs, &S::one(), None, domain)?;
    revolution_nurbs(profile, &circle, rec)
}

impl<S: Scalar> RevolutionNurbs<S> {
    /// Checks the point of the surface at (u, v) exactly against the profile:
    /// `x² + y² = f(u)²` and `z = g(u)`, with `(f(u), 0, g(u))` the point of the profile.
    pub fn on_parallel(&self, u: &S, v: &S) -> Result<bool, GenerateError> {
        OneField::default()
            .nurbs(&self.profile)?
            .nurbs(&self.circle)?
            .numbers([u, v])?;
        let p = self.surface.eval(u, v)?;
        let q = self.profile.eval(u)?;
        let [x, y, z] = xyz(Spatial::Revolution, Input::Surface, &p)?;
        let [f, _, g] = xyz(Spatial::Revolution, Input::Curve, &q)?;
        Ok(x.mul_ref(x) + y.mul_ref(y) == f.mul_ref(f) && z == g)
    }
}
