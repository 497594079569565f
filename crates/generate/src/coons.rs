//! Coons surfaces (notes, chapter 6, §5): the patch bounded by a closed curvilinear
//! quadrilateral of four curves,
//!
//! ```text
//! c1(0) = a = d1(0),  c1(1) = b = d2(0),  c2(0) = c = d1(1),  c2(1) = d = d2(1)    (13)
//! c_c(u, v) = (1 - v) c1(u) + v c2(u),  c_d(u, v) = (1 - u) d1(v) + u d2(v)       (15)
//! c_cd(u, v) = (1 - u)((1 - v) a + v c) + u((1 - v) b + v d)                      (16)
//! c(u, v) = c_c(u, v) + c_d(u, v) - c_cd(u, v)                                    (17)
//! ```
//!
//! As a Bézier patch: the three auxiliary patches raised to bidegree (m, n) and combined
//! vertex by vertex, (18)-(19). The rational caveat of the notes is in `coons_rational.rs`.

use crate::common::{curve_in, polygon_ends, same_dim, OneField};
use crate::{GenerateError, Note, Step};
use cagd_bezier::BezierCurve;
use cagd_linalg::Point;
use cagd_poly::{bernstein, Poly, Var, VecPoly};
use cagd_record::{NoSteps, Record};
use cagd_scalar::Scalar;
use cagd_surface::{BezierSurface, Border};

/// The blending functions of a Coons patch.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Blending {
    /// `1 - t` and `t`: the bilinearly blended patch (15)-(17) of the notes.
    Bilinear,
    /// `B_0^3(t) + B_1^3(t)` and `B_2^3(t) + B_3^3(t)`: their derivatives vanish at t = 0 and
    /// t = 1, so the derivative across a border does not depend on the opposite curve (notes,
    /// end of §5).
    Cubic,
}

/// A Coons patch as a polynomial map, with its corners and the three auxiliary surfaces.
#[derive(Clone, PartialEq, Debug)]
pub struct CoonsSurface<S: Scalar> {
    /// The blending functions used.
    pub blending: Blending,
    /// The corner `a = c1(0) = d1(0)`.
    pub a: Point<S>,
    /// The corner `b = c1(1) = d2(0)`.
    pub b: Point<S>,
    /// The corner `c = c2(0) = d1(1)`.
    pub c: Point<S>,
    /// The corner `d = c2(1) = d2(1)`.
    pub d: Point<S>,
    /// The ruled surface `c_c` between c1 and c2 (15).
    pub c_c: VecPoly<S>,
    /// The ruled surface `c_d` between d1 and d2 (15).
    pub c_d: VecPoly<S>,
    /// The bilinear patch `c_cd` of the corners (16).
    pub c_cd: VecPoly<S>,
    /// `c = c_c + c_d - c_cd` (17).
    pub surface: VecPoly<S>,
}

/// A Bézier Coons patch of bidegree (m, n), with the three auxiliary patches raised to (m, n).
#[derive(Clone, PartialEq, Debug)]
pub struct CoonsBezier<S: Scalar> {
    /// The corner a.
    pub a: Point<S>,
    /// The corner b.
    pub b: Point<S>,
    /// The corner c.
    pub c: Point<S>,
    /// The corner d.
    pub d: Point<S>,
    /// The boundary curves at their common degrees: c1, c2 of degree m, d1, d2 of degree n.
    pub curves: [BezierCurve<S>; 4],
    /// The ruled patch between c1 and c2, raised from (m, 1) to (m, n): mesh `c_c,ij` of (19).
    pub c_c: BezierSurface<S>,
    /// The ruled patch between d1 and d2, raised from (1, n) to (m, n): mesh `c_d,ij` of (19).
    pub c_d: BezierSurface<S>,
    /// The bilinear patch of the corners, raised from (1, 1) to (m, n): mesh `c_cd,ij` of (19).
    pub c_cd: BezierSurface<S>,
    /// The Coons patch, `c_ij = c_c,ij + c_d,ij - c_cd,ij` (18).
    pub surface: BezierSurface<S>,
    /// Degree elevations of the curves.
    pub notes: Vec<Note>,
}

/// The blending pair `(F0(t), F1(t))` in the variable `var`: `(1 - t, t)` for
/// [`Blending::Bilinear`], `(B_0^3 + B_1^3, B_2^3 + B_3^3) = ((1 - t)^2 (1 + 2t), t^2 (3 - 2t))`
/// for [`Blending::Cubic`]. Both satisfy `F0 + F1 = 1`, `F0(0) = 1`, `F0(1) = 0`.
///
/// ```
/// use cagd_generate::{blending_functions, Blending};
/// use cagd_poly::Var;
/// use cagd_scalar::BigRational;
/// let (f0, f1) = blending_functions::<BigRational>(Blending::Cubic, Var::U);
/// assert_eq!(f0.to_text(), "2 u^3 - 3 u^2 + 1");
/// assert_eq!(f1.to_text(), "-2 u^3 + 3 u^2");
/// ```
pub fn blending_functions<S: Scalar>(blending: Blending, var: Var) -> (Poly<S>, Poly<S>) {
    match blending {
        Blending::Bilinear => (Poly::one() - Poly::var(var), Poly::var(var)),
        Blending::Cubic => (
            bernstein(0, 3, var) + bernstein(1, 3, var),
            bernstein(2, 3, var) + bernstein(3, 3, var),
        ),
    }
}

/// The corners a, b, c, d of a closed curvilinear quadrilateral (13), from the ends
/// `(x(0), x(1))` of c1, c2, d1, d2; an error names the first corner where two curves do not
/// meet.
pub(crate) fn quadrilateral<S: Scalar>(
    ends: [&(Point<S>, Point<S>); 4],
) -> Result<[Point<S>; 4], GenerateError> {
    let [c1, c2, d1, d2] = ends;
    let checks = [
        ('a', "c1(0)", &c1.0, "d1(0)", &d1.0),
        ('b', "c1(1)", &c1.1, "d2(0)", &d2.0),
        ('c', "c2(0)", &c2.0, "d1(1)", &d1.1),
        ('d', "c2(1)", &c2.1, "d2(1)", &d2.1),
    ];
    for (corner, first_at, p, second_at, q) in checks {
        if p != q {
            return Err(GenerateError::CornerMismatch {
                corner,
                first_at: first_at.into(),
                first_point: p.to_text(),
                second_at: second_at.into(),
                second_point: q.to_text(),
            });
        }
    }
    Ok([c1.0.clone(), c1.1.clone(), c2.0.clone(), c2.1.clone()])
}

/// The bilinearly blended Coons patch of four polynomial curves c1(u), c2(u), d1(v), d2(v)
/// forming a closed curvilinear quadrilateral (13):
///
/// `c(u, v) = c_c + c_d - c_cd`, with `c_c = (1 - v) c1(u) + v c2(u)`,
/// `c_d = (1 - u) d1(v) + u d2(v)`, `c_cd = (1 - u)((1 - v) a + v c) + u((1 - v) b + v d)`
/// (notes, eqs. (15)-(17)).
///
/// It interpolates the four curves, `c(u, 0) = c1(u)`, `c(u, 1) = c2(u)`, `c(0, v) = d1(v)`,
/// `c(1, v) = d2(v)` (14). An error names the corner where two curves do not meet. Records the
/// corners, `c_c`, `c_d`, `c_cd` and `c(u, v)`.
///
/// ```
/// use cagd_generate::coons_surface;
/// use cagd_poly::parse_vec_poly;
/// use cagd_record::NoSteps;
/// use cagd_scalar::BigRational;
/// let e = |t: &str| parse_vec_poly::<BigRational>(t).unwrap();
/// let coons = coons_surface(&e("(u, 0, u^2)"), &e("(u, 1, u^3 + 1)"), &e("(0, v, v)"),
///     &e("(1, v, v^2 + 1)"), &mut NoSteps).unwrap();
/// assert_eq!(coons.surface, e("(u, v, u^2 - v u^2 + v + v u^3 - u v + u v^2)"));
/// assert_eq!(coons.d.to_text(), "(1, 1, 2)");
///
/// let err = coons_surface(&e("(2u, 0, 0)"), &e("(2u, 1, 0)"), &e("(0, v, 0)"),
///     &e("(2, v, 1)"), &mut NoSteps).unwrap_err();
/// assert_eq!(err.to_string(),
///     "curves c1 and d2 do not meet at corner b: c1(1) = (2, 0, 0), d2(0) = (2, 0, 1)");
/// ```
pub fn coons_surface<S: Scalar>(
    c1: &VecPoly<S>,
    c2: &VecPoly<S>,
    d1: &VecPoly<S>,
    d2: &VecPoly<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<CoonsSurface<S>, GenerateError> {
    coons_surface_blended(c1, c2, d1, d2, Blending::Bilinear, rec)
}

/// The Coons patch with other blending functions `F0, F1` ([`blending_functions`]):
///
/// `c = F0(v) c1(u) + F1(v) c2(u) + F0(u) d1(v) + F1(u) d2(v)
///    - [F0(u) F0(v) a + F1(u) F0(v) b + F0(u) F1(v) c + F1(u) F1(v) d]`,
///
/// which is (15)-(17) for [`Blending::Bilinear`]. With [`Blending::Cubic`] the derivative
/// across each border depends only on the curves that meet it (notes, end of §5).
pub fn coons_surface_blended<S: Scalar>(
    c1: &VecPoly<S>,
    c2: &VecPoly<S>,
    d1: &VecPoly<S>,
    d2: &VecPoly<S>,
    blending: Blending,
    rec: &mut impl Record<Step<S>>,
) -> Result<CoonsSurface<S>, GenerateError> {
    OneField::default().map(c1)?.map(c2)?.map(d1)?.map(d2)?;
    for (curve, name, var) in [
        (c1, "c1", Var::U),
        (c2, "c2", Var::U),
        (d1, "d1", Var::V),
        (d2, "d2", Var::V),
    ] {
        curve_in(curve, name, var)?;
        same_dim("c1", c1.dim(), name, curve.dim())?;
    }
    let ends = [
        crate::common::ends(c1, Var::U)?,
        crate::common::ends(c2, Var::U)?,
        crate::common::ends(d1, Var::V)?,
        crate::common::ends(d2, Var::V)?,
    ];
    let [a, b, c, d] = quadrilateral([&ends[0], &ends[1], &ends[2], &ends[3]])?;
    let (f0u, f1u) = blending_functions::<S>(blending, Var::U);
    let (f0v, f1v) = blending_functions::<S>(blending, Var::V);
    let c_c = crate::common::blend(&f0v, c1, &f1v, c2)?;
    let c_d = crate::common::blend(&f0u, d1, &f1u, d2)?;
    let corner = |p: &Point<S>, f: &Poly<S>, g: &Poly<S>| VecPoly::constant(p).mul_poly(&(f * g));
    let c_cd = corner(&a, &f0u, &f0v)
        .checked_add(&corner(&b, &f1u, &f0v))?
        .checked_add(&corner(&c, &f0u, &f1v))?
        .checked_add(&corner(&d, &f1u, &f1v))?;
    let surface = c_c.checked_add(&c_d)?.checked_sub(&c_cd)?;
    for (name, p) in [("a", &a), ("b", &b), ("c", &c), ("d", &d)] {
        rec.record(|| Step::point(name, p));
    }
    rec.record(|| Step::map("c_c(u, v)", &c_c));
    rec.record(|| Step::map("c_d(u, v)", &c_d));
    rec.record(|| Step::map("c_cd(u, v)", &c_cd));
    rec.record(|| Step::map("c(u, v)", &surface));
    Ok(CoonsSurface {
        blending,
        a,
        b,
        c,
        d,
        c_c,
        c_d,
        c_cd,
        surface,
    })
}

impl<S: Scalar> CoonsSurface<S> {
    /// The derivative across a border, computed from the parametrization: `∂c/∂u` at u = 0 or
    /// u = 1 (a curve in v), `∂c/∂v` at v = 0 or v = 1 (a curve in u). For the bilinear patch
    /// at u = 1 it equals (20) with the corrected sign, see [`cross_boundary_formula`].
    ///
    /// ```
    /// use cagd_generate::{coons_surface, Border};
    /// use cagd_poly::parse_vec_poly;
    /// use cagd_record::NoSteps;
    /// use cagd_scalar::BigRational;
    /// let e = |t: &str| parse_vec_poly::<BigRational>(t).unwrap();
    /// let coons = coons_surface(&e("(u, 0, u^2)"), &e("(u, 1, u^3 + 1)"), &e("(0, v, v)"),
    ///     &e("(1, v, v^2 + 1)"), &mut NoSteps).unwrap();
    /// assert_eq!(coons.cross_boundary_derivative(Border::U1).to_text(), "(1, 0, v^2 + 2)");
    /// ```
    pub fn cross_boundary_derivative(&self, border: Border) -> VecPoly<S> {
        let (var, at) = match border {
            Border::U0 => (Var::U, S::zero()),
            Border::U1 => (Var::U, S::one()),
            Border::V0 => (Var::V, S::zero()),
            Border::V1 => (Var::V, S::one()),
        };
        self.surface.partial(var).substitute_value(var, &at)
    }
}

/// The derivative of the bilinear Coons patch across the border u = 1 by the formula of the
/// notes, with its sign corrected:
///
/// `∂c/∂u|_{u=1} = (1 - v) c1'(1) + v c2'(1) + d2(v) - d1(v) - (1 - v)(b - a) - v(d - c)`
///
/// (notes, eq. (20), where `c1'(1) = m Δc_{1,m-1}` for a Bézier curve). **Erratum:** the notes
/// print the last two terms with `+`; they come from `- ∂c_cd/∂u` and enter with `-` (for the
/// notes' example the printed formula gives `(3, 0, v^2 + 4)`, the derivative is
/// `(1, 0, v^2 + 2)`, and `x = u` forces 1). It depends on d1, the opposite curve.
///
/// ```
/// use cagd_generate::cross_boundary_formula;
/// use cagd_poly::parse_vec_poly;
/// use cagd_scalar::BigRational;
/// let e = |t: &str| parse_vec_poly::<BigRational>(t).unwrap();
/// let d = cross_boundary_formula(&e("(u, 0, u^2)"), &e("(u, 1, u^3 + 1)"), &e("(0, v, v)"),
///     &e("(1, v, v^2 + 1)")).unwrap();
/// assert_eq!(d, e("(1, 0, 2 + v^2)"));
/// ```
pub fn cross_boundary_formula<S: Scalar>(
    c1: &VecPoly<S>,
    c2: &VecPoly<S>,
    d1: &VecPoly<S>,
    d2: &VecPoly<S>,
) -> Result<VecPoly<S>, GenerateError> {
    let coons = coons_surface(c1, c2, d1, d2, &mut NoSteps)?;
    let one = S::one();
    let dc1 = crate::common::point_at(&c1.partial(Var::U), Var::U, &one)?;
    let dc2 = crate::common::point_at(&c2.partial(Var::U), Var::U, &one)?;
    let (one_v, v) = (crate::common::one_minus::<S>(Var::V), Poly::var(Var::V));
    let tangents = crate::common::blend(
        &one_v,
        &VecPoly::constant(&dc1),
        &v,
        &VecPoly::constant(&dc2),
    )?;
    let sides = crate::common::blend(
        &one_v,
        &VecPoly::constant(&(&coons.b - &coons.a)),
        &v,
        &VecPoly::constant(&(&coons.d - &coons.c)),
    )?;
    Ok(tangents
        .checked_add(&d2.checked_sub(d1)?)?
        .checked_sub(&sides)?)
}

/// The Bézier Coons patch of bidegree (m, n) of two Bézier curves c1, c2 of degree m and two
/// d1, d2 of degree n forming a closed quadrilateral (13): the ruled patches c_c (m, 1), c_d
/// (1, n) and the bilinear c_cd (1, 1) are raised to bidegree (m, n), giving
///
/// `c_c,ij = (n-j)/n c1i + j/n c2i`, `c_d,ij = (m-i)/m d1j + i/m d2j`,
/// `c_cd,ij = (n-j)/n ((m-i)/m a + i/m b) + j/n ((m-i)/m c + i/m d)`   (19),
///
/// and the mesh `c_ij = c_c,ij + c_d,ij - c_cd,ij` (18). Opposite curves of different degrees
/// are first raised to the same degree (and degree 0 to 1), with a note saying so. Records the
/// corners, the interior vertices `c_c,i,j`, `c_d,i,j`, `c_cd,i,j`, `c,i,j` and the meshes
/// `c_c`, `c_d`, `c_cd`, `c`.
///
/// ```
/// use cagd_bezier::BezierCurve;
/// use cagd_generate::coons_bezier;
/// use cagd_linalg::Point;
/// use cagd_record::NoSteps;
/// use cagd_scalar::BigRational;
/// let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
/// let curve = |pts: &[&[i64]]| BezierCurve::try_new(pts.iter().map(|c| p(c)).collect()).unwrap();
/// let c1 = curve(&[&[0, 0, 0], &[2, 0, 0]]);
/// let c2 = curve(&[&[0, 2, 0], &[2, 2, 0]]);
/// let d1 = curve(&[&[0, 0, 0], &[0, 1, 1], &[0, 2, 0]]);
/// let d2 = curve(&[&[2, 0, 0], &[2, 1, 0], &[2, 2, 0]]);
/// let coons = coons_bezier(&c1, &c2, &d1, &d2, &mut NoSteps).unwrap();
/// assert_eq!(coons.surface.mesh().to_text(),
///     "{(0, 0, 0), (0, 1, 1), (0, 2, 0); (2, 0, 0), (2, 1, 0), (2, 2, 0)}");
/// let bad = curve(&[&[2, 0, 1], &[2, 1, 0], &[2, 2, 0]]);
/// assert_eq!(coons_bezier(&c1, &c2, &d1, &bad, &mut NoSteps).unwrap_err().to_string(),
///     "curves c1 and d2 do not meet at corner b: c1(1) = (2, 0, 0), d2(0) = (2, 0, 1)");
/// ```
pub fn coons_bezier<S: Scalar>(
    c1: &BezierCurve<S>,
    c2: &BezierCurve<S>,
    d1: &BezierCurve<S>,
    d2: &BezierCurve<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<CoonsBezier<S>, GenerateError> {
    OneField::default()
        .bezier(c1)?
        .bezier(c2)?
        .bezier(d1)?
        .bezier(d2)?;
    for (curve, name) in [(c2, "c2"), (d1, "d1"), (d2, "d2")] {
        same_dim("c1", c1.dim(), name, curve.dim())?;
    }
    let ends = [
        polygon_ends(c1.points())?,
        polygon_ends(c2.points())?,
        polygon_ends(d1.points())?,
        polygon_ends(d2.points())?,
    ];
    let [a, b, c, d] = quadrilateral([&ends[0], &ends[1], &ends[2], &ends[3]])?;
    let m = c1.degree().max(c2.degree()).max(1);
    let n = d1.degree().max(d2.degree()).max(1);
    let mut notes = Vec::new();
    let mut raise = |curve: &BezierCurve<S>, name: &str, to: usize| {
        if curve.degree() < to {
            notes.push(Note::CurveElevated {
                name: name.into(),
                from: curve.degree(),
                to,
            });
        }
        curve.elevate_degree(to - curve.degree())
    };
    let curves = [
        raise(c1, "c1", m),
        raise(c2, "c2", m),
        raise(d1, "d1", n),
        raise(d2, "d2", n),
    ];
    let [c1, c2, d1, d2] = &curves;
    for (name, p) in [("a", &a), ("b", &b), ("c", &c), ("d", &d)] {
        rec.record(|| Step::point(name, p));
    }
    // c_c: bidegree (m, 1), row i = {c1i, c2i}; raised in v to n
    let ruled_c = BezierSurface::from_rows(
        c1.points()
            .iter()
            .zip(c2.points())
            .map(|(p, q)| vec![p.clone(), q.clone()])
            .collect(),
    )?;
    let c_c = ruled_c.elevate(0, n - 1)?;
    // c_d: bidegree (1, n), rows d1 and d2; raised in u to m
    let ruled_d = BezierSurface::from_rows(vec![d1.points().to_vec(), d2.points().to_vec()])?;
    let c_d = ruled_d.elevate(m - 1, 0)?;
    // c_cd: bidegree (1, 1), {a, c; b, d}; raised to (m, n)
    let bilinear =
        BezierSurface::from_rows(vec![vec![a.clone(), c.clone()], vec![b.clone(), d.clone()]])?;
    let c_cd = bilinear.elevate(m - 1, n - 1)?;
    let mut rows = Vec::with_capacity(m + 1);
    for i in 0..=m {
        let mut row = Vec::with_capacity(n + 1);
        for j in 0..=n {
            match (
                c_c.mesh().get(i, j),
                c_d.mesh().get(i, j),
                c_cd.mesh().get(i, j),
            ) {
                (Some(p), Some(q), Some(r)) => row.push(&(p + q) - r),
                _ => {
                    return Err(GenerateError::Surface(
                        cagd_surface::SurfaceError::EmptyMesh,
                    ))
                }
            }
        }
        rows.push(row);
    }
    let surface = BezierSurface::from_rows(rows)?;
    // the interior vertices, as the notes list them: c_c,i,j, c_d,i,j, c_cd,i,j, then c_i,j
    for (name, s) in [
        ("c_c", &c_c),
        ("c_d", &c_d),
        ("c_cd", &c_cd),
        ("c", &surface),
    ] {
        for ((i, j), p) in s.mesh().indexed() {
            if i > 0 && i < m && j > 0 && j < n {
                rec.record(|| Step::point(format!("{name},{i},{j}"), p));
            }
        }
    }
    rec.record(|| Step::mesh("c_c", c_c.mesh()));
    rec.record(|| Step::mesh("c_d", c_d.mesh()));
    rec.record(|| Step::mesh("c_cd", c_cd.mesh()));
    rec.record(|| Step::mesh("c", surface.mesh()));
    Ok(CoonsBezier {
        a,
        b,
        c,
        d,
        curves: curves.clone(),
        c_c,
        c_d,
        c_cd,
        surface,
        notes,
    })
}

impl<S: Scalar> CoonsBezier<S> {
    /// The derivative across u = 1 by eq. (20) of the notes (sign corrected, see
    /// [`cross_boundary_formula`]), from the control points:
    ///
    /// `(1 - v) m Δc_{1,m-1} + v m Δc_{2,m-1} + d2(v) - d1(v) - (1 - v)(b - a) - v(d - c)`.
    pub fn cross_boundary_u1(&self) -> Result<VecPoly<S>, GenerateError> {
        let [c1, c2, d1, d2] = &self.curves;
        let m = S::from_i64(i64::try_from(c1.degree()).unwrap_or(i64::MAX));
        let last_difference = |c: &BezierCurve<S>| -> Point<S> {
            let pts = c.points();
            match (
                pts.len().checked_sub(2).and_then(|k| pts.get(k)),
                pts.last(),
            ) {
                (Some(p), Some(q)) => (q - p).scale(&m),
                _ => Point::zero(c.dim()),
            }
        };
        let (one_v, v) = (crate::common::one_minus::<S>(Var::V), Poly::var(Var::V));
        let tangents = crate::common::blend(
            &one_v,
            &VecPoly::constant(&last_difference(c1)),
            &v,
            &VecPoly::constant(&last_difference(c2)),
        )?;
        let sides = crate::common::blend(
            &one_v,
            &VecPoly::constant(&(&self.b - &self.a)),
            &v,
            &VecPoly::constant(&(&self.d - &self.c)),
        )?;
        let d1v = crate::common::curve_form(d1, Var::V)?;
        let d2v = crate::common::curve_form(d2, Var::V)?;
        Ok(tangents
            .checked_add(&d2v.checked_sub(&d1v)?)?
            .checked_sub(&sides)?)
    }
}
