//! Ruled surfaces (notes, chapter 6, §3): each point c1(u) joined to c2(u) by a segment,
//!
//! ```text
//! c(u, v) = (1 - v) c1(u) + v c2(u),   u, v ∈ [0, 1]                               (7)
//! ```
//!
//! As a Bézier patch it has bidegree (m, 1) and its mesh is the two polygons side by side,
//! `{c10, c20; ...; c1m, c2m}` (with the weights beside them for rational curves).

use crate::common::{blend, curve_in, one_minus, rational_curve_form, same_dim, OneField};
use crate::{GenerateError, Note, Step, StepValue};
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_bspline::{BSplineCurve, KnotVector, NurbsCurve};
use cagd_poly::{Poly, RationalMap, Var, VecPoly};
use cagd_record::Record;
use cagd_scalar::Scalar;
use cagd_spline_surface::{BSplineSurface, NurbsSurface};
use cagd_surface::{BezierSurface, Grid, Mesh, RationalBezierSurface};

/// A ruled surface as a polynomial map.
#[derive(Clone, PartialEq, Debug)]
pub struct RuledSurface<S: Scalar> {
    /// `c(u, v) = (1 - v) c1(u) + v c2(u)`.
    pub surface: VecPoly<S>,
}

/// A ruled Bézier patch of bidegree (m, 1).
#[derive(Clone, PartialEq, Debug)]
pub struct RuledBezier<S: Scalar> {
    /// The first curve, at the common degree m.
    pub c1: BezierCurve<S>,
    /// The second curve, at the common degree m.
    pub c2: BezierCurve<S>,
    /// The patch with mesh `{c10, c20; ...; c1m, c2m}`.
    pub surface: BezierSurface<S>,
    /// A note for each degree elevation.
    pub notes: Vec<Note>,
}

/// A ruled rational Bézier patch of bidegree (m, 1).
#[derive(Clone, PartialEq, Debug)]
pub struct RuledRational<S: Scalar> {
    /// The first curve, at the common degree m.
    pub c1: RationalBezierCurve<S>,
    /// The second curve, at the common degree m.
    pub c2: RationalBezierCurve<S>,
    /// The patch with mesh `{c10, c20; ...; c1m, c2m}` and weights `{w10, w20; ...; w1m, w2m}`.
    pub surface: RationalBezierSurface<S>,
    /// A note for each degree elevation.
    pub notes: Vec<Note>,
}

/// The two parametrizations of a rational ruled surface that the notes compare (§3).
#[derive(Clone, PartialEq, Debug)]
pub struct RuledParametrizations<S: Scalar> {
    /// The projective one, read from the mesh and weights:
    /// `c(u, v) = Σ {w1i c1i B_i (1 - v) + w2i c2i B_i v} / Σ {w1i B_i (1 - v) + w2i B_i v}`.
    pub projective: RationalMap<S>,
    /// The one of eq. (7) with the rational curves: `c̃(u, v) = (1 - v) c1(u) + v c2(u)`.
    pub blended: RationalMap<S>,
    /// The parameter s(u, v) on the segment from c1(u) to c2(u) of the projective point:
    /// `c(u, v) = (1 - s) c1(u) + s c2(u)` with `s = v W2(u) / ((1 - v) W1(u) + v W2(u))`,
    /// `W_k = Σ w_ki B_i^m(u)` (a rational map of dimension 1).
    pub segment_parameter: RationalMap<S>,
    /// Whether `c(u, v) = (1 - s) c1(u) + s c2(u)` holds identically (exact polynomial
    /// identity): the projective points lie on the same segments. Always true.
    pub same_segments: bool,
    /// Whether `c ≡ c̃` (exact): true only when the weight functions W1, W2 are proportional.
    pub same_points: bool,
}

/// The ruled surface between two polynomial curves in u:
///
/// `c(u, v) = (1 - v) c1(u) + v c2(u)`   (notes, eq. (7)),
///
/// so that `c(u, 0) = c1(u)`, `c(u, 1) = c2(u)` (6). Records `c(u, v)`.
///
/// ```
/// use cagd_generate::ruled_surface;
/// use cagd_poly::parse_vec_poly;
/// use cagd_record::NoSteps;
/// use cagd_scalar::BigRational;
/// let c1 = parse_vec_poly::<BigRational>("(u, 0, u^3)").unwrap();
/// let c2 = parse_vec_poly("(u, 1, u^2)").unwrap();
/// let r = ruled_surface(&c1, &c2, &mut NoSteps).unwrap();
/// assert_eq!(r.surface, parse_vec_poly("(u, v, u^3 - u^3 v + u^2 v)").unwrap());
/// assert_eq!(r.surface.to_text(), "(u, v, -u^3 v + u^3 + u^2 v)");
/// ```
pub fn ruled_surface<S: Scalar>(
    c1: &VecPoly<S>,
    c2: &VecPoly<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<RuledSurface<S>, GenerateError> {
    OneField::default().map(c1)?.map(c2)?;
    curve_in(c1, "c1", Var::U)?;
    curve_in(c2, "c2", Var::U)?;
    same_dim("c1", c1.dim(), "c2", c2.dim())?;
    let surface = blend(&one_minus(Var::V), c1, &Poly::var(Var::V), c2)?;
    rec.record(|| Step::map("c(u, v)", &surface));
    Ok(RuledSurface { surface })
}

/// The note of a degree elevation.
fn elevation_note(name: &str, from: usize, to: usize) -> Note {
    Note::CurveElevated {
        name: name.into(),
        from,
        to,
    }
}

/// The mesh `{c10, c20; ...; c1m, c2m}` of two polygons of the same length.
fn side_by_side<T: Clone>(p1: &[T], p2: &[T]) -> Vec<Vec<T>> {
    p1.iter()
        .zip(p2)
        .map(|(a, b)| vec![a.clone(), b.clone()])
        .collect()
}

/// The ruled Bézier patch of bidegree (m, 1) between two Bézier curves: its mesh is formed by
/// the two control polygons as columns,
///
/// `{c10, c20; c11, c21; ...; c1m, c2m}`   (notes, §3).
///
/// When the degrees differ, the curve of lower degree is first raised to the higher one, and a
/// note says so (`c2 elevated from degree 2 to 3`). Records the mesh.
///
/// ```
/// use cagd_bezier::BezierCurve;
/// use cagd_generate::ruled_bezier;
/// use cagd_linalg::Point;
/// use cagd_record::NoSteps;
/// use cagd_scalar::{parse_rational, BigRational};
/// let p = |c: [&str; 3]| Point::<BigRational>::new(c.map(|x| parse_rational(x).unwrap()).to_vec());
/// let c1 = BezierCurve::try_new(vec![p(["0", "0", "0"]), p(["1", "0", "1"]), p(["2", "0", "0"])])
///     .unwrap();
/// let c2 = BezierCurve::try_new(vec![p(["0", "1", "0"]), p(["3/2", "1", "2"]), p(["3", "2", "1"])])
///     .unwrap();
/// let r = ruled_bezier(&c1, &c2, &mut NoSteps).unwrap();
/// assert_eq!(
///     r.surface.mesh().to_text(),
///     "{(0, 0, 0), (0, 1, 0); (1, 0, 1), (3/2, 1, 2); (2, 0, 0), (3, 2, 1)}"
/// );
/// ```
pub fn ruled_bezier<S: Scalar>(
    c1: &BezierCurve<S>,
    c2: &BezierCurve<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<RuledBezier<S>, GenerateError> {
    OneField::default().bezier(c1)?.bezier(c2)?;
    same_dim("c1", c1.dim(), "c2", c2.dim())?;
    let mut notes = Vec::new();
    let m = c1.degree().max(c2.degree());
    let mut raise = |c: &BezierCurve<S>, name: &str| {
        if c.degree() < m {
            notes.push(elevation_note(name, c.degree(), m));
        }
        c.elevate_degree(m - c.degree())
    };
    let (c1, c2) = (raise(c1, "c1"), raise(c2, "c2"));
    let surface = BezierSurface::from_rows(side_by_side(c1.points(), c2.points()))?;
    rec.record(|| Step::mesh("mesh", surface.mesh()));
    Ok(RuledBezier {
        c1,
        c2,
        surface,
        notes,
    })
}

/// The ruled rational Bézier patch of bidegree (m, 1) between two rational Bézier curves: the
/// two polygons as columns of the mesh and the two lists of weights as columns of the weights,
///
/// `{c10, c20; ...; c1m, c2m}`, `{w10, w20; ...; w1m, w2m}`   (notes, §3).
///
/// The curve of lower degree is raised first (a note says so). Records the mesh and the
/// weights. See
/// [`RuledRational::parametrizations`] for the comparison with (7).
///
/// ```
/// use cagd_bezier::RationalBezierCurve;
/// use cagd_generate::ruled_rational;
/// use cagd_linalg::Point;
/// use cagd_record::NoSteps;
/// use cagd_scalar::{q, BigRational};
/// let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
/// let w = vec![q!(1), q!(1/2), q!(1)];
/// let c1 = RationalBezierCurve::try_new(vec![p(&[1, 0, 0]), p(&[1, 1, 0]), p(&[0, 1, 0])], w.clone())
///     .unwrap();
/// let c2 = RationalBezierCurve::try_new(vec![p(&[2, 0, 1]), p(&[2, 2, 1]), p(&[0, 2, 1])], w).unwrap();
/// let r = ruled_rational(&c1, &c2, &mut NoSteps).unwrap();
/// assert_eq!(
///     r.surface.mesh().to_text(),
///     "{(1, 0, 0), (2, 0, 1); (1, 1, 0), (2, 2, 1); (0, 1, 0), (0, 2, 1)}"
/// );
/// assert_eq!(r.surface.weights().to_text_numbers(), "{1, 1; 1/2, 1/2; 1, 1}");
/// ```
pub fn ruled_rational<S: Scalar>(
    c1: &RationalBezierCurve<S>,
    c2: &RationalBezierCurve<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<RuledRational<S>, GenerateError> {
    OneField::default().rational(c1)?.rational(c2)?;
    same_dim("c1", c1.dim(), "c2", c2.dim())?;
    let mut notes = Vec::new();
    let m = c1.degree().max(c2.degree());
    let mut raise = |c: &RationalBezierCurve<S>, name: &str| {
        if c.degree() < m {
            notes.push(elevation_note(name, c.degree(), m));
        }
        c.elevate_degree(m - c.degree())
    };
    let (c1, c2) = (raise(c1, "c1")?, raise(c2, "c2")?);
    let mesh = Mesh::mesh(side_by_side(c1.points(), c2.points()))?;
    let weights = Grid::from_rows(side_by_side(c1.weights(), c2.weights()))?;
    let surface = RationalBezierSurface::try_new(mesh, weights)?;
    rec.record(|| Step::mesh("mesh", surface.mesh()));
    rec.record(|| Step::weights("weights", surface.weights()));
    Ok(RuledRational {
        c1,
        c2,
        surface,
        notes,
    })
}

impl<S: Scalar> RuledRational<S> {
    /// The projective parametrization `c` (from the mesh and weights) and the blended one
    /// `c̃ = (1 - v) c1(u) + v c2(u)` of eq. (7), compared exactly (notes, end of §3): with
    /// `c_k = N_k / W_k`,
    ///
    /// `c(u, v) = ((1 - v) N1 + v N2) / ((1 - v) W1 + v W2) = (1 - s) c1(u) + s c2(u)`,
    /// `s = v W2 / ((1 - v) W1 + v W2)`,
    ///
    /// so both join c1(u) to c2(u) by the same segment, but reach its points at different
    /// (u, v) unless W1 and W2 are proportional. Records the three maps c, c̃ and s.
    ///
    /// ```
    /// use cagd_bezier::RationalBezierCurve;
    /// use cagd_generate::ruled_rational;
    /// use cagd_linalg::Point;
    /// use cagd_record::NoSteps;
    /// use cagd_scalar::{q, BigRational};
    /// let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
    /// let c1 = RationalBezierCurve::try_new(
    ///     vec![p(&[1, 0, 0]), p(&[1, 1, 0]), p(&[0, 1, 0])], vec![q!(1), q!(1/2), q!(1)]).unwrap();
    /// let c2 = RationalBezierCurve::try_new(
    ///     vec![p(&[2, 0, 1]), p(&[2, 2, 1]), p(&[0, 2, 1])], vec![q!(1), q!(2), q!(1)]).unwrap();
    /// let r = ruled_rational(&c1, &c2, &mut NoSteps).unwrap();
    /// let mut steps = Vec::new();
    /// let cmp = r.parametrizations(&mut steps).unwrap();
    /// assert!(cmp.same_segments);
    /// assert!(!cmp.same_points);
    /// assert_eq!(steps.len(), 3);
    /// ```
    pub fn parametrizations(
        &self,
        rec: &mut impl Record<Step<S>>,
    ) -> Result<RuledParametrizations<S>, GenerateError> {
        let projective = self.surface.closed_form()?;
        let r1 = rational_curve_form(&self.c1, Var::U)?;
        let r2 = rational_curve_form(&self.c2, Var::U)?;
        let (n1, w1) = (r1.numerator(), r1.denominator());
        let (n2, w2) = (r2.numerator(), r2.denominator());
        let (one_v, v) = (one_minus::<S>(Var::V), Poly::var(Var::V));
        // c̃ = ((1 - v) N1 W2 + v N2 W1) / (W1 W2)
        let blended = RationalMap::new(blend(&(&one_v * w2), n1, &(&v * w1), n2)?, w1 * w2)?;
        let denom_s = &(&one_v * w1) + &(&v * w2);
        let segment_parameter = RationalMap::new(VecPoly::new(vec![&v * w2]), denom_s)?;
        // c - c1 = s (c2 - c1)  ⇔  N_c W1 - N1 D_c = v (N2 W1 - N1 W2)
        let (nc, dc) = (projective.numerator(), projective.denominator());
        let lhs = nc.mul_poly(w1).checked_sub(&n1.mul_poly(dc))?;
        let rhs = n2.mul_poly(w1).checked_sub(&n1.mul_poly(w2))?.mul_poly(&v);
        let same_segments = lhs == rhs;
        // c ≡ c̃  ⇔  N_c D_c̃ = N_c̃ D_c
        let same_points = nc.mul_poly(blended.denominator()) == blended.numerator().mul_poly(dc);
        rec.record(|| Step::new("c(u, v)", StepValue::Rational(projective.clone())));
        rec.record(|| Step::new("c~(u, v)", StepValue::Rational(blended.clone())));
        rec.record(|| Step::new("s(u, v)", StepValue::Rational(segment_parameter.clone())));
        Ok(RuledParametrizations {
            projective,
            blended,
            segment_parameter,
            same_segments,
            same_points,
        })
    }
}

/// A ruled B-spline surface of degree 1 in v.
#[derive(Clone, PartialEq, Debug)]
pub struct RuledBSpline<S: Scalar> {
    /// The first curve, with the common degree and knots.
    pub c1: BSplineCurve<S>,
    /// The second curve, with the common degree and knots.
    pub c2: BSplineCurve<S>,
    /// The surface: knots of the curves in u, `{0, 1}` (degree 1) in v, mesh
    /// `{c10, c20; ...; c1L, c2L}`.
    pub surface: BSplineSurface<S>,
    /// Degree elevations and knot insertions.
    pub notes: Vec<Note>,
}

/// A ruled NURBS surface of degree 1 in v.
#[derive(Clone, PartialEq, Debug)]
pub struct RuledNurbs<S: Scalar> {
    /// The first curve, with the common degree and knots.
    pub c1: NurbsCurve<S>,
    /// The second curve, with the common degree and knots.
    pub c2: NurbsCurve<S>,
    /// The surface: mesh and weights of the two curves side by side.
    pub surface: NurbsSurface<S>,
    /// Degree elevations and knot insertions.
    pub notes: Vec<Note>,
}

/// The knots `{0, 1}` of degree 1 (notes' convention): v ∈ [0, 1], linear.
fn linear_knots<S: Scalar>() -> Result<KnotVector<S>, GenerateError> {
    Ok(KnotVector::clamped(1, &[S::zero(), S::one()])?)
}

/// The ruled B-spline surface between two clamped B-spline curves on the same domain
/// (notes, §3: "este resultado es válido asimismo para superficies regladas B-spline"): the
/// curves are first given the same degree and knots ([`crate::make_compatible`], with the
/// notes saying what was done), then the mesh is their polygons side by side,
/// `{c10, c20; ...; c1L, c2L}`, with knots `{0, 1}` (degree 1) in v. Records the mesh.
pub fn ruled_bspline<S: Scalar>(
    c1: &BSplineCurve<S>,
    c2: &BSplineCurve<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<RuledBSpline<S>, GenerateError> {
    let both = crate::make_compatible(c1, c2, ("c1", "c2"))?;
    let mesh = Mesh::mesh(side_by_side(both.first.points(), both.second.points()))?;
    let surface = BSplineSurface::try_new(both.first.knots().clone(), linear_knots()?, mesh)?;
    rec.record(|| Step::mesh("mesh", surface.mesh()));
    Ok(RuledBSpline {
        c1: both.first,
        c2: both.second,
        surface,
        notes: both.notes,
    })
}

/// The ruled NURBS surface between two clamped NURBS curves on the same domain: as
/// [`ruled_bspline`], with the weights of the two curves side by side,
/// `{w10, w20; ...; w1L, w2L}` (notes, §3). Records the mesh and the weights.
pub fn ruled_nurbs<S: Scalar>(
    c1: &NurbsCurve<S>,
    c2: &NurbsCurve<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<RuledNurbs<S>, GenerateError> {
    let both = crate::make_compatible_nurbs(c1, c2, ("c1", "c2"))?;
    let mesh = Mesh::mesh(side_by_side(both.first.points(), both.second.points()))?;
    let weights = Grid::from_rows(side_by_side(both.first.weights(), both.second.weights()))?;
    let surface =
        NurbsSurface::try_new(both.first.knots().clone(), linear_knots()?, mesh, weights)?;
    rec.record(|| Step::mesh("mesh", surface.mesh()));
    rec.record(|| Step::weights("weights", surface.weights()));
    Ok(RuledNurbs {
        c1: both.first,
        c2: both.second,
        surface,
        notes: both.notes,
    })
}
