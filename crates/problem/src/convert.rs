//! A problem's numbers, points and maps in the scalar of its solve (the field was chosen so
//! they fit), and the errors of reading an argument at its path.

use crate::message::fitting::Fitting;
use crate::value::{ExactScalar, Number};
use crate::ProblemError;
use cagd_linalg::Point;

/// An error of an algorithm, at `path`.
pub(crate) fn at<E: Into<crate::Message>>(path: &str) -> impl Fn(E) -> ProblemError + '_ {
    move |e| ProblemError::at(path, e)
}

/// A required argument.
pub(crate) fn req<'a, T>(x: &'a Option<T>, path: &str) -> Result<&'a T, ProblemError> {
    x.as_ref()
        .ok_or_else(|| ProblemError::at(path, Fitting::Missing))
}

/// A number of the problem in its scalar.
pub(crate) fn num<S: ExactScalar>(x: &crate::spec::Num, path: &str) -> Result<S, ProblemError> {
    x.to::<S>().map_err(|e| ProblemError::at(path, e))
}

/// A pair of numbers of the problem in its scalar.
pub(crate) fn pair<S: ExactScalar>(
    x: &crate::spec::Pair,
    path: &str,
) -> Result<(S, S), ProblemError> {
    x.to::<S>().map_err(|e| ProblemError::at(path, e))
}

/// A number of the problem format in the scalar `S` (the field was chosen so it fits).
pub(crate) fn convert<S: ExactScalar>(x: &Number, path: &str) -> Result<S, ProblemError> {
    S::from_number(x).map_err(at(path))
}

/// Points of the problem format in the scalar `S`.
pub(crate) fn convert_points<S: ExactScalar>(
    ps: &[Point<Number>],
    path: &str,
) -> Result<Vec<Point<S>>, ProblemError> {
    ps.iter()
        .map(|p| {
            Ok(Point::new(
                p.coords()
                    .iter()
                    .map(|x| convert(x, path))
                    .collect::<Result<_, _>>()?,
            ))
        })
        .collect()
}

/// A polynomial map of the problem (its coefficients may be in letters) in the scalar `S`.
pub(crate) fn convert_map<S: ExactScalar>(
    m: &cagd_poly::VecPoly<Number>,
    path: &str,
) -> Result<cagd_poly::VecPoly<S>, ProblemError> {
    let comps = m
        .components()
        .iter()
        .map(|p| p.try_map_coeffs(S::from_number))
        .collect::<Result<Vec<_>, _>>()
        .map_err(at(path))?;
    Ok(cagd_poly::VecPoly::new(comps))
}

/// Numbers of the problem format in the scalar `S`.
pub(crate) fn convert_all<S: ExactScalar>(
    xs: &[Number],
    path: &str,
) -> Result<Vec<S>, ProblemError> {
    xs.iter().map(|x| convert(x, path)).collect()
}
