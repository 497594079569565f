//! Coons surfaces of rational curves (notes, chapter 6, end of §5): the exact Coons
//! parametrization (15)-(17) of rational curves has no bidegree as a rational patch, and the
//! naive mesh built in R^4 by (19) is *not* it: its weights `w_c + w_d - w_cd` come from a
//! subtraction and may vanish or be negative, and its projection is another surface (which
//! still interpolates the four curves).

use crate::common::{
    curve_in, mesh_form, one_minus, polygon_ends, rational_curve_form, same_dim, OneField,
};
use crate::coons::{coons_bezier, quadrilateral};
use crate::{GenerateError, Note, Step, StepValue};
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_linalg::Point;
use cagd_poly::{Poly, RationalMap, Var, VecPoly};
use cagd_record::{NoSteps, Record};
use cagd_scalar::Scalar;
use cagd_surface::{Grid, Mesh, RationalBezierSurface};

/// The naive projective Coons construction for rational curves, and the true Coons surface.
#[derive(Clone, PartialEq, Debug)]
pub struct ProjectiveCoons<S: Scalar> {
    /// The Coons mesh (18)-(19) of the homogeneous curves `(w c, w)` in R^4 (weight last).
    pub homogeneous: Mesh<S>,
    /// Its last coordinates, the weights `w_ij = w_c,ij + w_d,ij - w_cd,ij`.
    pub weights: Grid<S>,
    /// The indices (i, j) of the weights that are zero or negative.
    pub nonpositive_weights: Vec<(usize, usize)>,
    /// The projected rational patch (mesh and weights), or `None` when a weight is zero (a
    /// control point at infinity).
    pub surface: Option<RationalBezierSurface<S>>,
    /// The projection of the homogeneous Coons patch, as a rational map.
    pub projection: RationalMap<S>,
    /// The true Coons surface `c_c + c_d - c_cd` of the rational curves (15)-(17).
    pub coons: RationalMap<S>,
    /// Whether the projection is the Coons surface (exact identity of rational maps).
    pub agrees: bool,
    /// A note for each degree elevation of a curve.
    pub notes: Vec<Note>,
}

/// The exact Coons parametrization (15)-(17) of four rational curves `c1(u)`, `c2(u)`,
/// `d1(v)`, `d2(v)` (closed quadrilateral (13)), over the common denominator
/// `D_c1 D_c2 D_d1 D_d2`:
///
/// `c = (1 - v) c1 + v c2 + (1 - u) d1 + u d2 - c_cd`.
pub fn coons_rational_map<S: Scalar>(
    c1: &RationalMap<S>,
    c2: &RationalMap<S>,
    d1: &RationalMap<S>,
    d2: &RationalMap<S>,
) -> Result<RationalMap<S>, GenerateError> {
    OneField::default()
        .map(&c1.to_homogeneous())?
        .map(&c2.to_homogeneous())?
        .map(&d1.to_homogeneous())?
        .map(&d2.to_homogeneous())?;
    let curves = [
        (c1, "c1", Var::U),
        (c2, "c2", Var::U),
        (d1, "d1", Var::V),
        (d2, "d2", Var::V),
    ];
    for (curve, name, var) in curves {
        curve_in(&curve.to_homogeneous(), name, var)?;
        same_dim("c1", c1.dim(), name, curve.dim())?;
    }
    let ends = |r: &RationalMap<S>, var: Var| -> Result<(Point<S>, Point<S>), GenerateError> {
        Ok((r.eval(&[(var, S::zero())])?, r.eval(&[(var, S::one())])?))
    };
    let e = [
        ends(c1, Var::U)?,
        ends(c2, Var::U)?,
        ends(d1, Var::V)?,
        ends(d2, Var::V)?,
    ];
    let [a, b, c, d] = quadrilateral([&e[0], &e[1], &e[2], &e[3]])?;
    let (u, v) = (Poly::var(Var::U), Poly::var(Var::V));
    let (one_u, one_v) = (one_minus::<S>(Var::U), one_minus::<S>(Var::V));
    let dens = [
        c1.denominator(),
        c2.denominator(),
        d1.denominator(),
        d2.denominator(),
    ];
    let all: Poly<S> = dens.iter().fold(Poly::one(), |acc, p| acc * *p);
    // each term f · N_k / D_k over the common denominator: f · N_k · Π_{l ≠ k} D_l
    let mut numer = VecPoly::zero(c1.dim());
    for (k, (curve, f)) in [(c1, &one_v), (c2, &v), (d1, &one_u), (d2, &u)]
        .into_iter()
        .enumerate()
    {
        let others = dens
            .iter()
            .enumerate()
            .filter(|(l, _)| *l != k)
            .fold(f.clone(), |acc, (_, p)| acc * *p);
        numer = numer.checked_add(&curve.numerator().mul_poly(&others))?;
    }
    let corner = |p: &Point<S>, f: &Poly<S>, g: &Poly<S>| VecPoly::constant(p).mul_poly(&(f * g));
    let c_cd = corner(&a, &one_u, &one_v)
        .checked_add(&corner(&b, &u, &one_v))?
        .checked_add(&corner(&c, &one_u, &v))?
        .checked_add(&corner(&d, &u, &v))?;
    numer = numer.checked_sub(&c_cd.mul_poly(&all))?;
    Ok(RationalMap::new(numer, all)?)
}

/// The homogeneous polygon `(w_i c_i, w_i)` of a rational curve raised to degree `to`.
fn homogeneous_at<S: Scalar>(
    curve: &RationalBezierCurve<S>,
    to: usize,
    name: &str,
    notes: &mut Vec<Note>,
) -> Result<BezierCurve<S>, GenerateError> {
    let raised = if curve.degree() < to {
        notes.push(Note::CurveElevated {
            name: name.into(),
            from: curve.degree(),
            to,
        });
        curve.elevate_degree(to - curve.degree())?
    } else {
        curve.clone()
    };
    Ok(BezierCurve::try_new(raised.homogeneous())?)
}

/// The naive projective Coons construction for four rational Bézier curves: the Coons mesh
/// (18)-(19) of the homogeneous curves in R^4, projected (notes, end of §5), compared with
/// the true Coons surface of the curves.
///
/// The homogeneous curves must form a closed quadrilateral in R^4, so the curves must meet
/// at each corner with equal weights there (an error says which corner otherwise). The weights
/// `w_ij = w_c,ij + w_d,ij - w_cd,ij` are a subtraction and may be zero or negative; the
/// projection still interpolates the four curves, but it is not their Coons surface.
///
/// Example (documented in the tests): the four quadratic arcs over the square of side 2 with
/// middle control points lifted to height 1 and all middle weights 1/2 give
/// `w_11 = (1/2 + 1/2 + 1/2 + 1/2)/2 - 1 = 0`: the central control point is at infinity.
/// With middle weights 1/4 it is `-1/2`, and with middle weights 2 (all weights positive) the
/// projection and the Coons surface still differ at (u, v) = (1/2, 1/2).
///
/// Records the homogeneous meshes `c_c`, `c_d`, `c_cd` and `c` in R^4, and the weights.
///
/// ```
/// use cagd_bezier::RationalBezierCurve;
/// use cagd_generate::coons_projective;
/// use cagd_linalg::Point;
/// use cagd_record::NoSteps;
/// use cagd_scalar::{q, BigRational};
/// let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
/// let arc = |a: &[i64], m: &[i64], b: &[i64]| {
///     RationalBezierCurve::try_new(vec![p(a), p(m), p(b)], vec![q!(1), q!(1/2), q!(1)]).unwrap()
/// };
/// let c1 = arc(&[0, 0, 0], &[1, 0, 1], &[2, 0, 0]);
/// let c2 = arc(&[0, 2, 0], &[1, 2, 1], &[2, 2, 0]);
/// let d1 = arc(&[0, 0, 0], &[0, 1, 1], &[0, 2, 0]);
/// let d2 = arc(&[2, 0, 0], &[2, 1, 1], &[2, 2, 0]);
/// let naive = coons_projective(&c1, &c2, &d1, &d2, &mut NoSteps).unwrap();
/// assert_eq!(naive.weights.to_text_numbers(), "{1, 1/2, 1; 1/2, 0, 1/2; 1, 1/2, 1}");
/// assert_eq!(naive.homogeneous.get(1, 1).unwrap().to_text(), "(0, 0, 1, 0)"); // at infinity
/// assert!(naive.surface.is_none() && !naive.agrees);
/// ```
pub fn coons_projective<S: Scalar>(
    c1: &RationalBezierCurve<S>,
    c2: &RationalBezierCurve<S>,
    d1: &RationalBezierCurve<S>,
    d2: &RationalBezierCurve<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<ProjectiveCoons<S>, GenerateError> {
    OneField::default()
        .rational(c1)?
        .rational(c2)?
        .rational(d1)?
        .rational(d2)?;
    let named = [(c1, "c1"), (c2, "c2"), (d1, "d1"), (d2, "d2")];
    for (curve, name) in named {
        same_dim("c1", c1.dim(), name, curve.dim())?;
    }
    let ends = [
        polygon_ends(c1.points())?,
        polygon_ends(c2.points())?,
        polygon_ends(d1.points())?,
        polygon_ends(d2.points())?,
    ];
    quadrilateral([&ends[0], &ends[1], &ends[2], &ends[3]])?;
    let first = |c: &RationalBezierCurve<S>| c.weights().first().cloned().unwrap_or_else(S::one);
    let last = |c: &RationalBezierCurve<S>| c.weights().last().cloned().unwrap_or_else(S::one);
    let corner_weights = [
        ('a', "c1", first(c1), "d1", first(d1)),
        ('b', "c1", last(c1), "d2", first(d2)),
        ('c', "c2", first(c2), "d1", last(d1)),
        ('d', "c2", last(c2), "d2", last(d2)),
    ];
    for (corner, first, fw, second, sw) in corner_weights {
        if fw != sw {
            return Err(GenerateError::CornerWeights {
                corner,
                first: first.into(),
                first_weight: fw.to_text(),
                second: second.into(),
                second_weight: sw.to_text(),
            });
        }
    }
    let m = c1.degree().max(c2.degree()).max(1);
    let n = d1.degree().max(d2.degree()).max(1);
    let mut notes = Vec::new();
    let h = [
        homogeneous_at(c1, m, "c1", &mut notes)?,
        homogeneous_at(c2, m, "c2", &mut notes)?,
        homogeneous_at(d1, n, "d1", &mut notes)?,
        homogeneous_at(d2, n, "d2", &mut notes)?,
    ];
    let lifted = coons_bezier(&h[0], &h[1], &h[2], &h[3], &mut NoSteps)?;
    let homogeneous = lifted.surface.mesh().clone();
    let weights = homogeneous.map(|p| p.coords().last().cloned().unwrap_or_else(S::zero));
    let nonpositive_weights: Vec<(usize, usize)> = weights
        .indexed()
        .filter(|(_, w)| **w <= S::zero())
        .map(|(ij, _)| ij)
        .collect();
    let surface = RationalBezierSurface::from_homogeneous(&homogeneous).ok();
    let projection = RationalMap::from_homogeneous(&mesh_form(&homogeneous)?)?;
    let coons = coons_rational_map(
        &rational_curve_form(c1, Var::U)?,
        &rational_curve_form(c2, Var::U)?,
        &rational_curve_form(d1, Var::V)?,
        &rational_curve_form(d2, Var::V)?,
    )?;
    let agrees = projection.numerator().mul_poly(coons.denominator())
        == coons.numerator().mul_poly(projection.denominator());
    for (name, mesh) in [
        ("c_c (R^4)", &lifted.c_c),
        ("c_d (R^4)", &lifted.c_d),
        ("c_cd (R^4)", &lifted.c_cd),
    ] {
        rec.record(|| Step::mesh(name, mesh.mesh()));
    }
    rec.record(|| Step::mesh("c (R^4)", &homogeneous));
    rec.record(|| Step::new("weights", StepValue::Weights(weights.clone())));
    Ok(ProjectiveCoons {
        homogeneous,
        weights,
        nonpositive_weights,
        surface,
        projection,
        coons,
        agrees,
        notes,
    })
}
