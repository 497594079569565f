//! `area` of a planar polynomial patch: `∬ |c_u × c_v| du dv = |∬ J| |n|` where
//! `c_u × c_v = J n` and J keeps one sign (cagd-poly's `planar_patch_area`), piece by piece for
//! a B-spline surface; a curved patch, a fold or |n| outside the field refused with the
//! reason.

use crate::any::AnySurface as Patch;
use crate::convert::at;
use crate::message::curve::Curve as Say;
use crate::out::{Out, Run};
use crate::pieces::{PieceForm, SplinePieces};
use crate::problem::Area;
use crate::steps::Formula;
use crate::value::{exact, exact_point, exact_poly, Exact, ExactScalar, Quantity};
use crate::ProblemError;
use cagd_poly::{planar_patch_area, VecPoly};

/// `area` of a planar `surface` (Bézier, expression, B-spline piece by piece).
pub(crate) fn patch_area<S: ExactScalar>(a: &Area, run: Run<'_>) -> Result<Out, ProblemError> {
    let sf = "surface";
    let Some(s) = &a.surface else {
        return Err(ProblemError::at(sf, Say::AreaNeedsCurveOrSurface));
    };
    let patch = Patch::<S>::read(s, sf)?;
    type Piece<S> = (VecPoly<S>, (S, S), (S, S));
    let pieces: Vec<Piece<S>> = match &patch {
        Patch::Bezier(b) => {
            let (du, dv) = patch.domain();
            vec![(b.closed_form().map_err(at(sf))?, du, dv)]
        }
        Patch::Map(m) => {
            let (du, dv) = patch.domain();
            vec![(m.clone(), du, dv)]
        }
        Patch::BSpline(_) => SplinePieces::require(&patch, sf)?
            .forms(sf)?
            .into_iter()
            .filter_map(|(du, dv, f)| match f {
                PieceForm::Polynomial(m) => Some((m, du, dv)),
                PieceForm::Rational(_) => None,
            })
            .collect(),
        Patch::RationalBezier(_) | Patch::Nurbs(_) => {
            return Err(ProblemError::at(sf, Say::AreaRational))
        }
    };
    let mut out = run.out();
    out.formula(Formula::PatchArea);
    let mut total = S::zero();
    let mut jacobians = Vec::new();
    let mut normal = None;
    for (m, du, dv) in &pieces {
        let piece = planar_patch_area(m, du, dv).map_err(at(sf))?;
        out.value("J(u, v)", Exact::Poly(exact_poly(&piece.jacobian)));
        out.value("\\iint J du dv", Exact::Number(exact(&piece.integral)));
        out.value("|n|", Exact::Number(exact(&piece.normal_length)));
        total += piece.area;
        jacobians.push(Exact::Poly(exact_poly(&piece.jacobian)));
        normal.get_or_insert(piece.normal);
    }
    let mut out = out.result(Quantity::Area, Exact::Number(exact(&total)));
    if let Some(n) = normal {
        out = out.result(Quantity::PlaneNormal, Exact::Point(exact_point(&n)));
    }
    Ok(out.result(
        Quantity::Jacobian,
        match jacobians.as_slice() {
            [one] => one.clone(),
            _ => Exact::List(jacobians),
        },
    ))
}
