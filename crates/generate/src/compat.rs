//! Two B-spline curves written with the same degree and the same knots, as the ruled and Coons
//! constructions need (notes, §3 and §5: "elevaríamos el grado ... y luego insertaríamos los
//! nudos no comunes"): the curve of lower degree is raised, then every knot that one curve has
//! more often than the other is inserted into the other. The curves do not change.

use crate::common::OneField;
use crate::{GenerateError, Note};
use cagd_bspline::{BSplineCurve, NurbsCurve};
use cagd_scalar::{Print, Scalar};

/// Two B-spline curves with the same degree and knot vector, and the notes of what made them
/// so.
#[derive(Clone, PartialEq, Debug)]
pub struct Compatible<S: Scalar> {
    /// The first curve, rewritten.
    pub first: BSplineCurve<S>,
    /// The second curve, rewritten.
    pub second: BSplineCurve<S>,
    /// One note per degree elevation and per knot insertion.
    pub notes: Vec<Note>,
}

/// An error unless the curve is clamped (it starts and ends at its end control points).
fn clamped<S: Scalar>(c: &BSplineCurve<S>, name: &str) -> Result<(), GenerateError> {
    if c.knots().is_clamped() {
        Ok(())
    } else {
        Err(GenerateError::NotClamped {
            curve: name.into(),
            knots: c.knots().to_text(),
        })
    }
}

/// The knots to insert into `c` so that every knot appears as often as in `other`.
fn missing<S: Scalar>(c: &BSplineCurve<S>, other: &BSplineCurve<S>) -> Vec<S> {
    let mut out = Vec::new();
    for (t, m) in other.knots().distinct() {
        let have = c.knots().multiplicity(&t);
        for _ in have..m {
            out.push(t.clone());
        }
    }
    out
}

/// Rewrites two clamped B-spline curves on the same domain with a common degree (the higher)
/// and a common knot vector (each knot with the larger multiplicity), by degree elevation and
/// knot insertion. Its notes say so: `c2 elevated from degree 2 to 3`,
/// `c1: knots 1/3 inserted`.
///
/// ```
/// use cagd_bspline::{BSplineCurve, KnotVector};
/// use cagd_generate::make_compatible;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
/// let c1 = BSplineCurve::try_new(KnotVector::clamped(2, &[q!(0), q!(1/2), q!(1)]).unwrap(),
///     vec![p(&[0, 0]), p(&[1, 1]), p(&[2, 1]), p(&[3, 0])]).unwrap();
/// let c2 = BSplineCurve::try_new(KnotVector::clamped(1, &[q!(0), q!(1)]).unwrap(),
///     vec![p(&[0, 2]), p(&[3, 2])]).unwrap();
/// let both = make_compatible(&c1, &c2, ("c1", "c2")).unwrap();
/// assert_eq!(both.second.knots(), both.first.knots());
/// let notes: Vec<String> = both.notes.iter().map(|n| n.to_string()).collect();
/// assert_eq!(notes, ["c2 elevated from degree 1 to 2", "c2: knots 1/2 inserted"]);
/// ```
pub fn make_compatible<S: Scalar>(
    first: &BSplineCurve<S>,
    second: &BSplineCurve<S>,
    names: (&str, &str),
) -> Result<Compatible<S>, GenerateError> {
    OneField::default().bspline(first)?.bspline(second)?;
    crate::common::same_dim(names.0, first.dim(), names.1, second.dim())?;
    clamped(first, names.0)?;
    clamped(second, names.1)?;
    if first.domain() != second.domain() {
        let text = |c: &BSplineCurve<S>| {
            let (a, b) = c.domain();
            format!("[{}, {}]", a.to_text(), b.to_text())
        };
        return Err(GenerateError::DomainMismatch {
            first: names.0.into(),
            first_domain: text(first),
            second: names.1.into(),
            second_domain: text(second),
        });
    }
    let mut notes = Vec::new();
    let p = first.degree().max(second.degree());
    let mut raise = |c: &BSplineCurve<S>, name: &str| -> Result<BSplineCurve<S>, GenerateError> {
        if c.degree() < p {
            notes.push(Note::CurveElevated {
                name: name.into(),
                from: c.degree(),
                to: p,
            });
        }
        Ok(c.elevate_degree(p - c.degree())?)
    };
    let (a, b) = (raise(first, names.0)?, raise(second, names.1)?);
    let (to_a, to_b) = (missing(&a, &b), missing(&b, &a));
    let mut insert = |c: BSplineCurve<S>, knots: &[S], name: &str| -> Result<_, GenerateError> {
        if knots.is_empty() {
            return Ok(c);
        }
        let list: Vec<String> = knots.iter().map(Print::to_text).collect();
        notes.push(Note::KnotsInserted {
            name: name.into(),
            knots: list.join(", "),
        });
        Ok(c.refine_knots(knots)?)
    };
    let first = insert(a, &to_a, names.0)?;
    let second = insert(b, &to_b, names.1)?;
    Ok(Compatible {
        first,
        second,
        notes,
    })
}

/// Two NURBS curves with the same degree and knot vector, and the notes of what made them so.
#[derive(Clone, PartialEq, Debug)]
pub struct CompatibleNurbs<S: Scalar> {
    /// The first curve, rewritten.
    pub first: NurbsCurve<S>,
    /// The second curve, rewritten.
    pub second: NurbsCurve<S>,
    /// One note per degree elevation and per knot insertion.
    pub notes: Vec<Note>,
}

/// [`make_compatible`] for NURBS curves, on their homogeneous B-spline curves (the weights
/// come along).
pub fn make_compatible_nurbs<S: Scalar>(
    first: &NurbsCurve<S>,
    second: &NurbsCurve<S>,
    names: (&str, &str),
) -> Result<CompatibleNurbs<S>, GenerateError> {
    let both = make_compatible(&first.homogeneous(), &second.homogeneous(), names)?;
    Ok(CompatibleNurbs {
        first: NurbsCurve::from_homogeneous(both.first)?,
        second: NurbsCurve::from_homogeneous(both.second)?,
        notes: both.notes,
    })
}
