//! A problem's numbers, points and maps in the scalar of its solve (the field was chosen so
//! they fit), and the errors of reading an argument at its path.

use crate::input::quoted;
use crate::message::read::Read;
use crate::spec::{ExprIn, Num, Pair};
use crate::value::{ExactScalar, Number};
use crate::Message;
use crate::ProblemError;
use cagd_linalg::Point;
use cagd_param::ParamExpr;
use cagd_poly::VecPoly;

/// An error of an algorithm, at `path`.
pub fn at<E: Into<crate::Message>>(path: &str) -> impl Fn(E) -> ProblemError + '_ {
    move |e| ProblemError::at(path, e)
}

/// A required argument.
pub fn req<'a, T>(x: &'a Option<T>, path: &str) -> Result<&'a T, ProblemError> {
    x.as_ref()
        .ok_or_else(|| ProblemError::at(path, crate::message::contract::Contract::Missing))
}

/// A number of the problem in its scalar.
pub fn num<S: ExactScalar>(x: &crate::spec::Num, path: &str) -> Result<S, ProblemError> {
    x.to::<S>().map_err(|e| ProblemError::at(path, e))
}

/// A pair of numbers of the problem in its scalar.
pub fn pair<S: ExactScalar>(x: &crate::spec::Pair, path: &str) -> Result<(S, S), ProblemError> {
    x.to::<S>().map_err(|e| ProblemError::at(path, e))
}

/// A number of the problem format in the scalar `S` (the field was chosen so it fits).
pub fn convert<S: ExactScalar>(x: &Number, path: &str) -> Result<S, ProblemError> {
    S::from_number(x).map_err(at(path))
}

/// Points of the problem format in the scalar `S`.
pub fn convert_points<S: ExactScalar>(
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

impl Num {
    /// The number in the scalar `S` of the problem.
    pub fn to<S: ExactScalar>(&self) -> Result<S, Message> {
        S::from_number(&self.0)
    }
}

impl Pair {
    /// Both numbers in the scalar `S`.
    pub fn to<S: ExactScalar>(&self) -> Result<(S, S), Message> {
        Ok((self.0.to()?, self.1.to()?))
    }
}

impl ExprIn {
    /// The polynomial map over `S` (`"(u, 0, u^2)"`).
    pub fn vector<S: ExactScalar>(&self) -> Result<VecPoly<S>, Read> {
        let text = quoted(&self.text);
        let quoted = |e: Message| Read::Quoted {
            text: text.clone(),
            error: e.into(),
        };
        match &self.letters {
            Some(ParamExpr::Vector(m)) => {
                let comps = m
                    .components()
                    .iter()
                    .map(|p| p.try_map_coeffs(S::from_number))
                    .collect::<Result<Vec<_>, _>>()
                    .map_err(quoted)?;
                Ok(VecPoly::new(comps))
            }
            Some(ParamExpr::Scalar(p)) => Err(Read::NotTuple {
                text,
                poly: p.to_string(),
            }),
            None => self.expr.vector::<S>().map_err(|e| quoted(e.into())),
        }
    }

    /// The scalar polynomial over `S` (`"x*y"`).
    pub fn scalar<S: ExactScalar>(&self) -> Result<cagd_poly::Poly<S>, Read> {
        let text = quoted(&self.text);
        let quoted = |e: Message| Read::Quoted {
            text: text.clone(),
            error: e.into(),
        };
        match &self.letters {
            Some(ParamExpr::Scalar(p)) => p.try_map_coeffs(S::from_number).map_err(quoted),
            Some(ParamExpr::Vector(_)) => Err(Read::NotScalar { text }),
            None => self.expr.scalar::<S>().map_err(|e| quoted(e.into())),
        }
    }
}
