//! Curve algorithms on every line of a B-spline surface's mesh: the surface split at a
//! parameter, and a knot removed in one direction. In direction u each column
//! d_{0,j}, ..., d_{n,j} is a B-spline curve on the knots in u; in direction v each row is one
//! on the knots in v (the notes' "two passes", chapter 5 §4). A NURBS surface goes through its
//! homogeneous mesh (w d, w) ([`crate::NurbsSurface::homogeneous`]), whose lines are B-spline
//! curves of one dimension more.
//!
//! - Split at u = ξ strictly inside: each column split as a curve (ξ inserted until its
//!   multiplicity is p, Boehm; then cut, The NURBS Book A5.6; cagd-bspline's
//!   [`BSplineCurve::split_at`]): the surface on [a, ξ] × [c, d] and the one on [ξ, b] × [c, d],
//!   each on its own knots.
//! - Knot removal in u: the knot removed from every column (The NURBS Book §5.4,
//!   cagd-bspline's [`cagd_bspline::remove_knot`]); it is exact only when it is exact for every
//!   column, else refused naming the first column where it is not.

use crate::{BSplineSurface, Direction, SplineSurfaceError};
use cagd_bspline::{BSplineCurve, BSplineError, KnotVector, SplitError};
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use cagd_surface::{Grid, Mesh, SurfaceError};
use cagd_words::{said, Lang, Message, Phrase};
use std::cmp::Ordering;

/// Why a surface is not split, or a knot not removed, line by line.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum LinesError {
    /// A split parameter not strictly inside the domain in its direction.
    NotStrictlyInside {
        /// The parameter.
        x: String,
        /// The domain's start in that direction.
        a: String,
        /// The domain's end.
        b: String,
        /// The direction.
        direction: Direction,
    },
    /// A mesh without lines.
    #[default]
    NoControlPoints,
    /// A line (column for u, row for v) refused the knot removal.
    OnLine {
        /// The direction.
        direction: Direction,
        /// The line's index.
        index: usize,
        /// Why.
        because: Box<BSplineError>,
    },
    /// A line refused the split.
    Split(Box<SplitError>),
    /// The mesh of the new surface refused.
    Surface(Box<SurfaceError>),
    /// The new surface refused.
    SplineSurface(Box<SplineSurfaceError>),
}

impl Message for LinesError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            LinesError::NotStrictlyInside { x, a, b, direction } => said(
                lang,
                "‹› is not strictly inside the domain [‹›, ‹›] of the surface in ‹›",
                "‹› no está estrictamente dentro del recinto [‹›, ‹›] de la superficie en ‹›",
                [x.into(), a.into(), b.into(), direction.name().into()],
            ),
            LinesError::NoControlPoints => said(
                lang,
                "the surface has no control points",
                "la superficie no tiene puntos de control",
                [],
            ),
            LinesError::OnLine {
                direction: Direction::U,
                index,
                because,
            } => said(
                lang,
                "in ‹›, on column ‹› of the mesh: «»",
                "en ‹›, en la columna ‹› de la malla: «»",
                ["u".into(), index.into(), because.phrase(lang).into()],
            ),
            LinesError::OnLine {
                direction: Direction::V,
                index,
                because,
            } => said(
                lang,
                "in ‹›, on row ‹› of the mesh: «»",
                "en ‹›, en la fila ‹› de la malla: «»",
                ["v".into(), index.into(), because.phrase(lang).into()],
            ),
            LinesError::Split(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            LinesError::Surface(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            LinesError::SplineSurface(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
        }
    }
}

cagd_words::display_english!(LinesError);

/// The knots of a surface in a direction and its lines there: the columns (u) or rows (v).
fn lines<S: Scalar>(s: &BSplineSurface<S>, dir: Direction) -> (KnotVector<S>, Vec<Vec<Point<S>>>) {
    match dir {
        Direction::U => (s.knots_u().clone(), s.mesh().to_columns()),
        Direction::V => (s.knots_v().clone(), s.mesh().to_rows()),
    }
}

/// The surface with new knots and lines in `dir`, the other direction's knots kept.
fn rebuild<S: Scalar>(
    s: &BSplineSurface<S>,
    dir: Direction,
    knots: KnotVector<S>,
    lines: Vec<Vec<Point<S>>>,
) -> Result<BSplineSurface<S>, LinesError> {
    let (ku, kv, mesh) = match dir {
        Direction::U => (knots, s.knots_v().clone(), Grid::from_columns(lines)),
        Direction::V => (s.knots_u().clone(), knots, Grid::from_rows(lines)),
    };
    let mesh: Mesh<S> = mesh.map_err(|e| LinesError::Surface(Box::new(e)))?;
    BSplineSurface::try_new(ku, kv, mesh).map_err(|e| LinesError::SplineSurface(Box::new(e)))
}

impl<S: Scalar> BSplineSurface<S> {
    /// The surface split at `x` in `dir` (see [the module](self)): the surface on
    /// [a, x] × [c, d] and the one on [x, b] × [c, d] for u (for v, on [c, x] and [x, d]).
    pub fn split_at(
        &self,
        dir: Direction,
        x: &S,
    ) -> Result<(BSplineSurface<S>, BSplineSurface<S>), LinesError> {
        let (knots, lines) = lines(self, dir);
        let (a, b) = (knots.start(), knots.end());
        let inside =
            x.compare(a) == Some(Ordering::Greater) && x.compare(b) == Some(Ordering::Less);
        if !inside {
            return Err(LinesError::NotStrictlyInside {
                x: x.to_text(),
                a: a.to_text(),
                b: b.to_text(),
                direction: dir,
            });
        }
        let (mut left, mut right) = (Vec::new(), Vec::new());
        let (mut lk, mut rk) = (None, None);
        for line in lines {
            let c = BSplineCurve::try_new(knots.clone(), line)
                .map_err(|e| LinesError::Split(Box::new(SplitError::BSpline(e))))?;
            let (l, r) = c.split_at(x).map_err(|e| LinesError::Split(Box::new(e)))?;
            lk = Some(l.knots().clone());
            rk = Some(r.knots().clone());
            left.push(l.points().to_vec());
            right.push(r.points().to_vec());
        }
        let (Some(lk), Some(rk)) = (lk, rk) else {
            return Err(LinesError::NoControlPoints);
        };
        Ok((
            rebuild(self, dir, lk, left)?,
            rebuild(self, dir, rk, right)?,
        ))
    }

    /// The surface with the knot `x` removed `times` times in `dir` from every line (see
    /// [the module](self)); refused at the first line where the removal is not exact.
    pub fn remove_knot_in(
        &self,
        dir: Direction,
        x: &S,
        times: usize,
    ) -> Result<BSplineSurface<S>, LinesError> {
        let (knots, lines) = lines(self, dir);
        let mut out = Vec::with_capacity(lines.len());
        let mut new_knots = None;
        for (index, line) in lines.into_iter().enumerate() {
            let (k, points) =
                cagd_bspline::remove_knot(&knots, &line, x, times).map_err(|because| {
                    LinesError::OnLine {
                        direction: dir,
                        index,
                        because: Box::new(because),
                    }
                })?;
            new_knots = Some(k);
            out.push(points);
        }
        let Some(k) = new_knots else {
            return Err(LinesError::NoControlPoints);
        };
        rebuild(self, dir, k, out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational};
    use strum::IntoEnumIterator;

    fn p(x: BigRational, y: BigRational) -> Point<BigRational> {
        Point::new(vec![x, y, BigRational::from_integer(0.into())])
    }

    /// The plane x = u, y = v of degree (2, 1) on [0, 2] × [0, 1]: columns with x = 0, 1, 2
    /// over the notes' knots 0, 0, 2, 2.
    fn surface() -> BSplineSurface<BigRational> {
        let ku = KnotVector::from_notes(vec![q!(0), q!(0), q!(2), q!(2)], 2).unwrap();
        let kv = KnotVector::from_notes(vec![q!(0), q!(1)], 1).unwrap();
        let mesh = Grid::from_rows(vec![
            vec![p(q!(0), q!(0)), p(q!(0), q!(1))],
            vec![p(q!(1), q!(0)), p(q!(1), q!(1))],
            vec![p(q!(2), q!(0)), p(q!(2), q!(1))],
        ])
        .unwrap();
        BSplineSurface::try_new(ku, kv, mesh).unwrap()
    }

    #[test]
    fn split_in_u() {
        let (left, right) = surface().split_at(Direction::U, &q!(1)).unwrap();
        // x = u on [0, 2]: the halves have x 0, 1/2, 1 and 1, 3/2, 2 down their columns
        let xs = |s: &BSplineSurface<BigRational>| -> Vec<BigRational> {
            s.mesh()
                .to_columns()
                .first()
                .unwrap()
                .iter()
                .map(|pt| pt.coords()[0].clone())
                .collect()
        };
        assert_eq!(xs(&left), [q!(0), q!(1 / 2), q!(1)]);
        assert_eq!(xs(&right), [q!(1), q!(3 / 2), q!(2)]);
        assert_eq!(
            surface().split_at(Direction::V, &q!(1)),
            Err(LinesError::NotStrictlyInside {
                x: "1".into(),
                a: "0".into(),
                b: "1".into(),
                direction: Direction::V
            })
        );
    }

    #[test]
    fn knot_removed_in_u() {
        // degree 1 in u on the notes' knots 0, 1, 2 with x = 0, 1, 2: the knot 1 is removable
        let ku = KnotVector::from_notes(vec![q!(0), q!(1), q!(2)], 1).unwrap();
        let kv = KnotVector::from_notes(vec![q!(0), q!(1)], 1).unwrap();
        let row = |x: BigRational| vec![p(x.clone(), q!(0)), p(x, q!(1))];
        let mesh = Grid::from_rows(vec![row(q!(0)), row(q!(1)), row(q!(2))]).unwrap();
        let s = BSplineSurface::try_new(ku, kv.clone(), mesh).unwrap();
        let line = s.remove_knot_in(Direction::U, &q!(1), 1).unwrap();
        let expected = BSplineSurface::try_new(
            KnotVector::from_notes(vec![q!(0), q!(2)], 1).unwrap(),
            kv,
            Grid::from_rows(vec![row(q!(0)), row(q!(2))]).unwrap(),
        )
        .unwrap();
        assert_eq!(line, expected);
        // the quadratic surface's columns are not lines: 1 is no knot of theirs to remove
        assert!(matches!(
            surface().remove_knot_in(Direction::U, &q!(1), 1),
            Err(LinesError::OnLine {
                direction: Direction::U,
                index: 0,
                ..
            })
        ));
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in LinesError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        for direction in Direction::iter() {
            let m = LinesError::OnLine {
                direction,
                index: 0,
                because: Box::default(),
            };
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
