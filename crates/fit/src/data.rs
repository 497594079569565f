//! Checks of the data shared by every fit: counts, dimensions, parameters.

use crate::{Direction, FitError};
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use cagd_surface::Mesh;

/// The common dimension of the data points; an error when there are none or they differ.
pub(crate) fn check_points<S: Scalar>(points: &[Point<S>]) -> Result<usize, FitError> {
    let dim = points.first().ok_or(FitError::NoData)?.dim();
    for (i, p) in points.iter().enumerate() {
        if p.dim() != dim {
            return Err(FitError::DimensionMismatch {
                what: crate::Datum::DataPoint { index: i },
                expected: dim,
                found: p.dim(),
            });
        }
    }
    Ok(dim)
}

/// The common dimension of the data, checking one parameter per point.
pub(crate) fn check_data<S: Scalar>(params: &[S], points: &[Point<S>]) -> Result<usize, FitError> {
    let dim = check_points(points)?;
    if params.len() != points.len() {
        return Err(FitError::CountMismatch {
            points: points.len(),
            parameters: params.len(),
        });
    }
    Ok(dim)
}

/// The first pair i < j with u_i = u_j, as an error.
pub(crate) fn check_distinct<S: Scalar>(params: &[S]) -> Result<(), FitError> {
    for (j, uj) in params.iter().enumerate() {
        if let Some(i) = params.iter().take(j).position(|ui| ui == uj) {
            return Err(FitError::RepeatedParameter {
                first: i,
                second: j,
                value: uj.to_text(),
            });
        }
    }
    Ok(())
}

/// The number of distinct parameters.
pub(crate) fn count_distinct<S: Scalar>(params: &[S]) -> usize {
    count_distinct_up_to(params, usize::MAX)
}

/// The number of distinct parameters, counted until `enough` are found: each parameter is
/// compared with the distinct ones found so far only, so the check that a least-squares fit
/// has m + 1 distinct u_k among M is O(M m), not O(M²).
pub(crate) fn count_distinct_up_to<S: Scalar>(params: &[S], enough: usize) -> usize {
    let mut distinct: Vec<&S> = Vec::new();
    for u in params {
        if distinct.len() >= enough {
            break;
        }
        if !distinct.contains(&u) {
            distinct.push(u);
        }
    }
    distinct.len()
}

/// An error at the first knot that is not greater than the one before it.
pub(crate) fn check_increasing<S: Scalar>(knots: &[S]) -> Result<(), FitError> {
    for (i, (before, value)) in knots.iter().zip(knots.iter().skip(1)).enumerate() {
        if value <= before {
            return Err(FitError::NotIncreasing {
                index: i + 1,
                before: before.to_text(),
                value: value.to_text(),
            });
        }
    }
    Ok(())
}

/// A tangent (or other vector) given for the data: it must have the data's dimension.
pub(crate) fn check_vector<S: Scalar>(
    v: &Point<S>,
    dim: usize,
    what: crate::Datum,
) -> Result<(), FitError> {
    if v.dim() == dim {
        Ok(())
    } else {
        Err(FitError::DimensionMismatch {
            what,
            expected: dim,
            found: v.dim(),
        })
    }
}

/// The common dimension of a grid of data a_ij = c(u_i, v_j): one u_i per row, one v_j per
/// column, all points of one dimension.
pub(crate) fn check_grid<S: Scalar>(u: &[S], v: &[S], data: &Mesh<S>) -> Result<usize, FitError> {
    if data.rows() == 0 || data.cols() == 0 {
        return Err(FitError::NoData);
    }
    if data.rows() != u.len() || data.cols() != v.len() {
        return Err(FitError::GridShape {
            rows: data.rows(),
            cols: data.cols(),
            u_count: u.len(),
            v_count: v.len(),
        });
    }
    let dim = data.get(0, 0).map_or(0, Point::dim);
    for ((i, j), p) in data.indexed() {
        if p.dim() != dim {
            return Err(FitError::DimensionMismatch {
                what: crate::Datum::GridPoint { row: i, col: j },
                expected: dim,
                found: p.dim(),
            });
        }
    }
    Ok(dim)
}

/// [`check_distinct`] for the parameters of one direction of a grid.
pub(crate) fn check_distinct_in<S: Scalar>(
    direction: Direction,
    params: &[S],
) -> Result<(), FitError> {
    check_distinct(params).map_err(|e| match e {
        FitError::RepeatedParameter {
            first,
            second,
            value,
        } => FitError::RepeatedGridParameter {
            direction,
            first,
            second,
            value,
        },
        e => e,
    })
}

/// [`check_increasing`] for the parameters of one direction of a grid.
pub(crate) fn check_increasing_in<S: Scalar>(
    direction: Direction,
    params: &[S],
) -> Result<(), FitError> {
    check_increasing(params).map_err(|e| match e {
        FitError::NotIncreasing {
            index,
            before,
            value,
        } => FitError::GridNotIncreasing {
            direction,
            index,
            before,
            value,
        },
        e => e,
    })
}

/// Scattered surface data: one parameter pair (u_k, v_k) per point; the common dimension.
pub(crate) fn check_scattered<S: Scalar>(
    params: &[(S, S)],
    points: &[Point<S>],
) -> Result<usize, FitError> {
    let dim = check_points(points)?;
    if params.len() != points.len() {
        return Err(FitError::CountMismatch {
            points: points.len(),
            parameters: params.len(),
        });
    }
    Ok(dim)
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational};

    #[test]
    fn parameter_checks() {
        let u: Vec<BigRational> = vec![q!(0), q!(1 / 2), q!(0), q!(1 / 2)];
        assert_eq!(count_distinct(&u), 2);
        assert_eq!(count_distinct_up_to(&u, 1), 1);
        assert_eq!(count_distinct_up_to(&u, 5), 2);
        assert_eq!(
            check_distinct(&u).unwrap_err(),
            FitError::RepeatedParameter {
                first: 0,
                second: 2,
                value: "0".into()
            }
        );
        assert_eq!(
            check_increasing(&[q!(0), q!(1), q!(1 / 2)]).unwrap_err(),
            FitError::NotIncreasing {
                index: 2,
                before: "1".into(),
                value: "1/2".into()
            }
        );
        assert!(check_increasing::<BigRational>(&[q!(0), q!(1)]).is_ok());
        let pts: Vec<Point<BigRational>> = vec![Point::from_ints(&[1, 2])];
        assert_eq!(check_data(&[q!(0)], &pts).unwrap(), 2);
        assert_eq!(
            check_data(&[q!(0), q!(1)], &pts).unwrap_err(),
            FitError::CountMismatch {
                points: 1,
                parameters: 2
            }
        );
    }
}
