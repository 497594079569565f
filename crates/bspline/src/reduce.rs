//! Exact degree reduction of B-spline and NURBS curves.
//!
//! A B-spline (NURBS) curve of degree p is of degree p - r exactly when each of its Bézier
//! pieces (the extraction, every breakpoint to multiplicity p) is: each piece's polygon
//! (homogeneous polygon) reduced by cagd-bezier's [`reduce_polygon`] ([`reduce_homogeneous`])
//! must be exact. The reduced pieces, joined at full multiplicity p - r (C⁰), are one B-spline
//! of degree p - r; then every interior knot is removed as often as exact knot removal allows
//! (The NURBS Book §5.4), which gives back the continuity: elevating the result by r gives the
//! curve given (an interior knot of multiplicity μ' becomes μ' + r by elevation, The NURBS
//! Book §5.5). A least-squares reduction of each piece is not done: it would not join the
//! next.

use crate::{BSplineCurve, BSplineError, KnotVector, NurbsCurve};
use cagd_bezier::{reduce_homogeneous, reduce_polygon, ReductionError};
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use cagd_words::{said, Lang, Message, Phrase};

/// Why a B-spline or NURBS curve is not reduced exactly.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum SplineReductionError {
    /// A reduction below degree 1.
    SplineCannotReduce {
        /// The curve's degree.
        degree: usize,
        /// The reduction asked.
        by: usize,
    },
    /// A piece of a B-spline curve not of the lower degree.
    PieceNotReducible {
        /// The piece's start.
        from: String,
        /// The piece's end.
        to: String,
        /// The lower degree.
        degree: usize,
    },
    /// The homogeneous polygon of a piece of a NURBS curve not of the lower degree.
    PieceHomogeneousNotReducible {
        /// The piece's start.
        from: String,
        /// The piece's end.
        to: String,
        /// The lower degree.
        degree: usize,
    },
    /// A piece's reduction refused otherwise (a weight not positive, the normal equations).
    Reduction(ReductionError),
    /// The extraction, the joined curve or a knot removal refused.
    BSpline(BSplineError),
}

impl Default for SplineReductionError {
    fn default() -> Self {
        SplineReductionError::SplineCannotReduce { degree: 1, by: 1 }
    }
}

impl Message for SplineReductionError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            SplineReductionError::SplineCannotReduce { degree, by } => said(
                lang,
                "a B-spline curve of degree ‹› cannot be reduced by ‹›: its degree must stay at least 1",
                "una curva B-spline de grado ‹› no se puede reducir en ‹›: su grado ha de seguir siendo al menos 1",
                [degree.into(), by.into()],
            ),
            SplineReductionError::PieceNotReducible { from, to, degree } => said(
                lang,
                "the piece on [‹›, ‹›] is not of degree ‹›: a B-spline curve is reduced only exactly (a least-squares reduction of each piece would not join the next)",
                "el trozo en [‹›, ‹›] no es de grado ‹›: una curva B-spline solo se reduce de forma exacta (una reducción por mínimos cuadrados de cada trozo no empalmaría con el siguiente)",
                [from.into(), to.into(), degree.into()],
            ),
            SplineReductionError::PieceHomogeneousNotReducible { from, to, degree } => said(
                lang,
                "the homogeneous polygon (w_i c_i, w_i) of the piece on [‹›, ‹›] is not of degree ‹›, so the curve is not exactly of degree ‹›; a least-squares reduction of the homogeneous points can make a weight zero or negative (and is not the nearest curve), so it is not done",
                "el polígono homogéneo (w_i c_i, w_i) del trozo en [‹›, ‹›] no es de grado ‹›, así que la curva no es exactamente de grado ‹›; una reducción por mínimos cuadrados de los puntos homogéneos puede dar un peso nulo o negativo (y no es la curva más cercana), así que no se hace",
                [from.into(), to.into(), degree.into(), degree.into()],
            ),
            SplineReductionError::Reduction(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            SplineReductionError::BSpline(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
        }
    }
}

cagd_words::display_english!(SplineReductionError);

impl From<BSplineError> for SplineReductionError {
    fn from(e: BSplineError) -> Self {
        SplineReductionError::BSpline(e)
    }
}

impl From<ReductionError> for SplineReductionError {
    fn from(e: ReductionError) -> Self {
        SplineReductionError::Reduction(e)
    }
}

/// One Bézier piece of a spline reduced: its interval, its points of the lower degree, and its
/// weights for a NURBS piece.
#[derive(Debug, Clone, PartialEq)]
pub struct ReducedPiece<S> {
    /// The piece's interval [u_k, u_{k+1}].
    pub interval: (S, S),
    /// Its control points of the lower degree.
    pub points: Vec<Point<S>>,
    /// Its weights (NURBS pieces only).
    pub weights: Option<Vec<S>>,
}

/// A spline curve reduced exactly: the curve of the lower degree, that degree, its pieces as
/// reduced, and how many knots the joined pieces lost to exact knot removal.
#[derive(Debug, Clone, PartialEq)]
pub struct SplineReduction<C, S> {
    /// The reduced curve.
    pub curve: C,
    /// Its degree p - r.
    pub degree: usize,
    /// The reduced Bézier pieces, in order.
    pub pieces: Vec<ReducedPiece<S>>,
    /// The knot removals done on the joined pieces.
    pub removed: usize,
}

/// The degree p - r of a reduced spline, at least 1.
fn spline_target(p: usize, r: usize) -> Result<usize, SplineReductionError> {
    match p.checked_sub(r) {
        Some(m) if m >= 1 => Ok(m),
        _ => Err(SplineReductionError::SplineCannotReduce { degree: p, by: r }),
    }
}

/// The knots of pieces of degree m on these intervals joined at full multiplicity (C⁰), in the
/// notes' convention.
fn joined_knots<S: Scalar>(intervals: &[(S, S)], m: usize) -> Result<KnotVector<S>, BSplineError> {
    let mut knots = Vec::new();
    for (k, (a, b)) in intervals.iter().enumerate() {
        if k == 0 {
            knots.extend(std::iter::repeat_n(a.clone(), m));
        }
        knots.extend(std::iter::repeat_n(b.clone(), m));
    }
    KnotVector::from_notes(knots, m)
}

/// Every interior breakpoint of `curve` removed as often as exact removal allows.
fn remove_all<S, C>(
    mut curve: C,
    interior: &[S],
    remove: impl Fn(&C, &S) -> Option<C>,
) -> (C, usize) {
    let mut removed = 0;
    for xi in interior {
        while let Some(c) = remove(&curve, xi) {
            cagd_scalar::cancel::checkpoint();
            curve = c;
            removed += 1;
        }
    }
    (curve, removed)
}

/// The interior joints of consecutive intervals.
fn interior<S: Scalar>(pieces: &[ReducedPiece<S>]) -> Vec<S> {
    pieces
        .iter()
        .skip(1)
        .map(|p| p.interval.0.clone())
        .collect()
}

impl<S: Scalar> BSplineCurve<S> {
    /// The same curve of degree p - r, exactly (see [the module](self)); refused when a piece
    /// is not of that degree, or p - r < 1.
    pub fn reduce_degree_exactly(
        &self,
        r: usize,
    ) -> Result<SplineReduction<BSplineCurve<S>, S>, SplineReductionError> {
        let m = spline_target(self.degree(), r)?;
        let mut points: Vec<Point<S>> = Vec::new();
        let mut pieces = Vec::new();
        for piece in self.bezier_pieces()? {
            let red = reduce_polygon(&piece.points, r)?;
            if !red.exact() {
                let (a, b) = &piece.interval;
                return Err(SplineReductionError::PieceNotReducible {
                    from: a.to_text(),
                    to: b.to_text(),
                    degree: m,
                });
            }
            let skip = usize::from(!points.is_empty());
            points.extend(red.reduced.iter().skip(skip).cloned());
            pieces.push(ReducedPiece {
                interval: piece.interval,
                points: red.reduced,
                weights: None,
            });
        }
        let intervals: Vec<(S, S)> = pieces.iter().map(|p| p.interval.clone()).collect();
        let joined = BSplineCurve::try_new(joined_knots(&intervals, m)?, points)?;
        let (curve, removed) = remove_all(joined, &interior(&pieces), |c, xi| {
            c.remove_knot(xi, 1).ok()
        });
        Ok(SplineReduction {
            curve,
            degree: m,
            pieces,
            removed,
        })
    }
}

impl<S: Scalar> NurbsCurve<S> {
    /// The same curve of degree p - r, exactly (see [the module](self)): each piece's
    /// homogeneous polygon reduced exactly, with positive weights; refused otherwise.
    pub fn reduce_degree_exactly(
        &self,
        r: usize,
    ) -> Result<SplineReduction<NurbsCurve<S>, S>, SplineReductionError> {
        let m = spline_target(self.degree(), r)?;
        let (mut points, mut weights) = (Vec::new(), Vec::new());
        let mut pieces = Vec::new();
        for piece in self.bezier_pieces()? {
            let (ps, ws) =
                reduce_homogeneous(&piece.points, &piece.weights, r).map_err(|e| match e {
                    ReductionError::HomogeneousNotReducible { degree } => {
                        let (a, b) = &piece.interval;
                        SplineReductionError::PieceHomogeneousNotReducible {
                            from: a.to_text(),
                            to: b.to_text(),
                            degree,
                        }
                    }
                    other => SplineReductionError::Reduction(other),
                })?;
            let skip = usize::from(!points.is_empty());
            points.extend(ps.iter().skip(skip).cloned());
            weights.extend(ws.iter().skip(skip).cloned());
            pieces.push(ReducedPiece {
                interval: piece.interval,
                points: ps,
                weights: Some(ws),
            });
        }
        let intervals: Vec<(S, S)> = pieces.iter().map(|p| p.interval.clone()).collect();
        let joined = NurbsCurve::try_new(joined_knots(&intervals, m)?, points, weights)?;
        let (curve, removed) = remove_all(joined, &interior(&pieces), |c, xi| {
            c.remove_knot(xi, 1).ok()
        });
        Ok(SplineReduction {
            curve,
            degree: m,
            pieces,
            removed,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational};
    use strum::IntoEnumIterator;

    fn p(x: BigRational, y: BigRational) -> Point<BigRational> {
        Point::new(vec![x, y])
    }

    #[test]
    fn a_line_elevated_is_reduced_back() {
        // the line (0, 0) → (2, 2) as a quadratic B-spline on the notes' knots 0, 0, 1, 2, 2:
        // four points on the line, two pieces of degree 2, each a line
        let knots = KnotVector::from_notes(vec![q!(0), q!(0), q!(1), q!(2), q!(2)], 2).unwrap();
        let c = BSplineCurve::try_new(
            knots,
            vec![
                p(q!(0), q!(0)),
                p(q!(1 / 2), q!(1 / 2)),
                p(q!(3 / 2), q!(3 / 2)),
                p(q!(2), q!(2)),
            ],
        )
        .unwrap();
        let red = c.reduce_degree_exactly(1).unwrap();
        assert_eq!(red.degree, 1);
        assert_eq!(red.pieces.len(), 2);
        // the joint at 1 removed: one segment
        assert_eq!(red.removed, 1);
        assert_eq!(red.curve.points(), [p(q!(0), q!(0)), p(q!(2), q!(2))]);
    }

    #[test]
    fn refusals() {
        let knots = KnotVector::from_notes(vec![q!(0), q!(0), q!(1), q!(1)], 2).unwrap();
        let parabola = BSplineCurve::try_new(
            knots,
            vec![p(q!(0), q!(0)), p(q!(1), q!(1)), p(q!(2), q!(0))],
        )
        .unwrap();
        assert_eq!(
            parabola.reduce_degree_exactly(1),
            Err(SplineReductionError::PieceNotReducible {
                from: "0".into(),
                to: "1".into(),
                degree: 1
            })
        );
        assert_eq!(
            parabola.reduce_degree_exactly(2),
            Err(SplineReductionError::SplineCannotReduce { degree: 2, by: 2 })
        );
    }

    #[test]
    fn a_rational_piece_not_reducible() {
        // the quarter circle (1, 0), (1, 1), (0, 1) with weights 1, 1, 2 on [0, 1]
        let knots = KnotVector::from_notes(vec![q!(0), q!(0), q!(1), q!(1)], 2).unwrap();
        let arc = NurbsCurve::try_new(
            knots,
            vec![p(q!(1), q!(0)), p(q!(1), q!(1)), p(q!(0), q!(1))],
            vec![q!(1), q!(1), q!(2)],
        )
        .unwrap();
        assert_eq!(
            arc.reduce_degree_exactly(1),
            Err(SplineReductionError::PieceHomogeneousNotReducible {
                from: "0".into(),
                to: "1".into(),
                degree: 1
            })
        );
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in SplineReductionError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
