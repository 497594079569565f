//! `reverse` of a curve (its control points, weights and knots in the opposite order) and of a
//! tensor-product patch (its mesh read in the opposite order in one direction); a triangle's
//! relabelled vertices are the triangles' (`triangles::triangle::reverse`).

use crate::any::AnyCurve as Curve;
use crate::any::AnySurface as Patch;
use crate::curves::curve::knots_exact;
use crate::message::curve::Curve as Say;
use crate::out::{at, req, Out, Run};
use crate::problem::{Reverse, UorV};
use crate::steps::Formula;
use crate::value::ExactScalar;
use crate::value::Quantity;
use crate::ProblemError;
use cagd_bezier::RationalBezierCurve;
use cagd_bspline::{BSplineCurve, KnotVector, NurbsCurve};
use cagd_linalg::Point;
use cagd_poly::Var;
use cagd_spline_surface::{BSplineSurface, NurbsSurface};
use cagd_surface::{BezierSurface, Grid, RationalBezierSurface};

const SF: &str = "surface";

/// The grid with its rows in reverse (u) or each row in reverse (v).
fn flip<T: Clone>(g: &Grid<T>, direction: UorV) -> Result<Grid<T>, ProblemError> {
    let mut rows = g.to_rows();
    match direction {
        UorV::U => rows.reverse(),
        UorV::V => rows.iter_mut().for_each(|r| r.reverse()),
    }
    Grid::from_rows(rows).map_err(at(SF))
}

/// The knots ũ = a + b - u in reverse order, [a, b] the domain.
fn flip_knots<S: ExactScalar>(k: &KnotVector<S>) -> Result<KnotVector<S>, ProblemError> {
    let (lo, hi) = k.domain();
    let sum = lo.add_ref(&hi);
    let full: Vec<S> = k.full().iter().rev().map(|u| sum.sub_ref(u)).collect();
    KnotVector::from_full(full, k.degree()).map_err(at(SF))
}

/// `reverse`: the same curve traversed backwards, c̃(t) = c(a + b - t) on the same domain
/// [a, b]: the control points (and weights) in the opposite order; for a B-spline the knots
/// ũ_i = a + b - u_{N-1-i}; for an expression, t replaced by 1 - t.
pub(crate) fn curve<S: ExactScalar>(a: &Reverse, run: Run<'_>) -> Result<Out, ProblemError> {
    let cf = "curve";
    let c = Curve::<S>::read_with_vectors(req(&a.curve, cf)?, cf)?;
    let mut out = run.out();
    out.formula(Formula::Reverse);
    let rev = |ps: &[Point<S>]| ps.iter().rev().cloned().collect::<Vec<_>>();
    let rev_knots = |k: &KnotVector<S>| -> Result<KnotVector<S>, ProblemError> {
        let (lo, hi) = k.domain();
        let sum = lo.add_ref(&hi);
        let full: Vec<S> = k.full().iter().rev().map(|u| sum.sub_ref(u)).collect();
        KnotVector::from_full(full, k.degree()).map_err(at(cf))
    };
    let c = match c {
        Curve::Bezier(b) => Curve::Bezier(b.reverse()),
        Curve::RationalBezier(b) => Curve::RationalBezier(
            RationalBezierCurve::try_new(
                rev(b.points()),
                b.weights().iter().rev().cloned().collect(),
            )
            .map_err(at(cf))?,
        ),
        Curve::BSpline(b) => Curve::BSpline(
            BSplineCurve::try_new(rev_knots(b.knots())?, rev(b.points())).map_err(at(cf))?,
        ),
        Curve::Nurbs(b) => Curve::Nurbs(
            NurbsCurve::try_new(
                rev_knots(b.knots())?,
                rev(b.points()),
                b.weights().iter().rev().cloned().collect(),
            )
            .map_err(at(cf))?,
        ),
        Curve::Map(e) => {
            let var = crate::any_curve::curve_var(&e);
            Curve::Map(e.affine_substitute(var, &-S::one(), &S::one()))
        }
    };
    if out.steps_on() {
        if let Curve::BSpline(b) = &c {
            out.value("\\tilde{u}", knots_exact(b.knots()));
        }
        if let Curve::Nurbs(b) = &c {
            out.value("\\tilde{u}", knots_exact(b.knots()));
        }
    }
    Ok(out.result(Quantity::Curve, c.to_exact()))
}

/// `reverse` a tensor-product patch in `direction`: in u, c̃_{i,j} = c_{m-i,j} (the rows of the
/// mesh, and of the weights, in reverse) and c̃(u, v) = c(a + b - u, v); in v,
/// c̃_{i,j} = c_{i,n-j} and c̃(u, v) = c(u, c + d - v). A B-spline (NURBS) surface's knots in
/// that direction become ũ = a + b - u in reverse order; a map in (u, v) on the unit square
/// has u replaced by 1 - u (v by 1 - v). The same surface, traced the other way.
pub(crate) fn surface<S: ExactScalar>(a: &Reverse, run: Run<'_>) -> Result<Out, ProblemError> {
    let s = Patch::<S>::read(req(&a.surface, SF)?, SF)?;
    let Some(direction) = a.direction else {
        return Err(ProblemError::at("direction", Say::ReverseDirectionMissing));
    };
    let mut out = run.out();
    out.formula(Formula::ReverseSurface);
    let (knot_dir, var) = match direction {
        UorV::U => (cagd_spline_surface::Direction::U, Var::U),
        UorV::V => (cagd_spline_surface::Direction::V, Var::V),
    };
    let reversed = match &s {
        Patch::Bezier(b) => {
            Patch::Bezier(BezierSurface::try_new(flip(b.mesh(), direction)?).map_err(at(SF))?)
        }
        Patch::RationalBezier(b) => Patch::RationalBezier(
            RationalBezierSurface::try_new(
                flip(b.mesh(), direction)?,
                flip(b.weights(), direction)?,
            )
            .map_err(at(SF))?,
        ),
        Patch::BSpline(b) => {
            let (ku, kv) = knots_of(b.knots_u(), b.knots_v(), direction)?;
            Patch::BSpline(
                BSplineSurface::try_new(ku, kv, flip(b.mesh(), direction)?).map_err(at(SF))?,
            )
        }
        Patch::Nurbs(b) => {
            let (ku, kv) = knots_of(b.knots_u(), b.knots_v(), direction)?;
            Patch::Nurbs(
                NurbsSurface::try_new(
                    ku,
                    kv,
                    flip(b.mesh(), direction)?,
                    flip(b.weights(), direction)?,
                )
                .map_err(at(SF))?,
            )
        }
        // t ↦ 1 - t in the reversed parameter.
        Patch::Map(e) => Patch::Map(e.affine_substitute(var, &-S::one(), &S::one())),
    };
    if out.steps_on() {
        let knots = match &reversed {
            Patch::BSpline(b) => Some(b.knots(knot_dir)),
            Patch::Nurbs(b) => Some(b.knots(knot_dir)),
            _ => None,
        };
        if let Some(k) = knots {
            let name = match direction {
                UorV::U => "\\tilde{u}",
                UorV::V => "\\tilde{v}",
            };
            out.value(name, knots_exact(k));
        }
    }
    Ok(out.result(Quantity::Surface, reversed.to_exact()))
}

/// The knot vectors with the one of `direction` reversed.
fn knots_of<S: ExactScalar>(
    ku: &KnotVector<S>,
    kv: &KnotVector<S>,
    direction: UorV,
) -> Result<(KnotVector<S>, KnotVector<S>), ProblemError> {
    Ok(match direction {
        UorV::U => (flip_knots(ku)?, kv.clone()),
        UorV::V => (ku.clone(), flip_knots(kv)?),
    })
}
