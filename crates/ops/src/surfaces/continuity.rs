//! The continuity of two patches along their common border (chapter 5), and of a spline
//! surface across its knot lines.

use crate::explain;
use crate::message::surface::Surface;
use crate::out::{at, pair, req, Out, Run};
use crate::problem::{Continuity, UorV};
use crate::steps::Formula;
use crate::value::quantity::{Quantity, Side};
use crate::value::{exact_map, exact_points, Exact, ExactScalar};
use crate::{Message, ProblemError};
use cagd_linalg::Point;
use cagd_poly::Var;
use cagd_surface::{continuity as join_continuity, BezierSurface, Join, Smoothness};

/// A validated surface.
use crate::any::AnySurface as Patch;

/// `continuity` of one B-spline or NURBS `surface` across its knot lines.
pub(crate) fn knot_lines<S: ExactScalar>(
    a: &Continuity,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let sf = "surface";
    for (key, given) in [
        ("first", a.first.is_some()),
        ("second", a.second.is_some()),
        ("border", a.border.is_some()),
        ("lengths", a.lengths.is_some()),
    ] {
        if given {
            return Err(ProblemError::at(key, Surface::OneSurfaceKnotLines));
        }
    }
    let patch = Patch::<S>::read(req(&a.surface, sf)?, sf)?;
    crate::pieces::knot_lines(&patch, sf, run)
}

/// `continuity` of two Bézier patches across `border` (21)-(23).
pub(crate) fn continuity<S: ExactScalar>(
    a: &Continuity,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let join = match a.border {
        None | Some(UorV::U) => Join::U,
        Some(UorV::V) => Join::V,
    };
    let first = Patch::<S>::read(req(&a.first, "first")?, "first")?;
    let second = Patch::<S>::read(req(&a.second, "second")?, "second")?;
    let spline = |p: &Patch<S>| matches!(p, Patch::BSpline(_) | Patch::Nurbs(_));
    if spline(&first) || spline(&second) {
        // B-spline or NURBS surfaces: piece by piece, in their own parameters
        if a.lengths.is_some() {
            return Err(ProblemError::at("lengths", Surface::SplineLengths));
        }
        let var = if join == Join::U { Var::U } else { Var::V };
        return crate::pieces::two_surfaces(&first, &second, var, run);
    }
    let bezier = |p: Patch<S>, path: &str| match p {
        Patch::Bezier(s) => Ok(s),
        _ => Err(ProblemError::at(path, Surface::ContinuityTakes)),
    };
    let (first, second) = (bezier(first, "first")?, bezier(second, "second")?);
    let size = |s: &BezierSurface<S>| (s.bidegree().0 + 1).saturating_mul(s.bidegree().1 + 1);
    let (first, second, elevated) = same_border_degree(first, second, join)?;
    run.check_points(
        "first",
        size(&first),
        crate::message::limited::Limited::FirstPatchElevated,
    )?;
    run.check_points(
        "second",
        size(&second),
        crate::message::limited::Limited::SecondPatchElevated,
    )?;
    let (du0, du1) = match &a.lengths {
        Some(l) => pair::<S>(l, "lengths")?,
        None => (S::one(), S::one()),
    };
    let k = join_continuity(&first, &second, join, &du0, &du1).map_err(at(""))?;
    let mut steps = run.out();
    steps
        .remarks
        .extend(elevated.into_iter().map(Message::from));
    if steps.steps_on() {
        steps.formula(Formula::JoinC0);
        steps.formula(Formula::JoinC1);
        steps.formula(Formula::JoinCr);
        steps.value("\\Delta u_0", explain::number(&du0));
        steps.value("\\Delta u_1", explain::number(&du1));
        let top = match k.smoothness {
            Smoothness::NotContinuous => 0,
            Smoothness::C(r) => r + 1,
            Smoothness::Infinite => usize::MAX,
        };
        explain_join(&mut steps, &first, &second, join, &du0, &du1, top);
    }
    let order = match k.smoothness {
        Smoothness::NotContinuous => Exact::Int(-1),
        Smoothness::C(r) => Exact::Int(i64::try_from(r).unwrap_or(i64::MAX)),
        Smoothness::Infinite => Exact::Sentence(crate::message::curve::Curve::Infinite.into()),
    };
    let mut out = steps
        .result(Quantity::Order, order)
        .result(Quantity::Smoothness, Exact::Sentence(k.smoothness.into()));
    if let Some(f) = &k.failure {
        out = out.result(Quantity::Fails, Exact::Sentence(f.condition().into()));
    }
    out = out
        .result(
            Quantity::PatchClosedForm(Side::First),
            Exact::Map(exact_map(&first.closed_form().map_err(at("first"))?)),
        )
        .result(
            Quantity::PatchClosedForm(Side::Second),
            Exact::Map(exact_map(&second.closed_form().map_err(at("second"))?)),
        )
        .result(
            Quantity::BorderDifferences(Side::First),
            Exact::Points(exact_points(&k.differences_first)),
        )
        .result(
            Quantity::BorderDifferences(Side::Second),
            Exact::Points(exact_points(&k.differences_second)),
        )
        .result(
            Quantity::BorderDerivative(Side::First),
            Exact::Map(exact_map(&k.derivative_first)),
        )
        .result(
            Quantity::BorderDerivative(Side::Second),
            Exact::Map(exact_map(&k.derivative_second)),
        );
    if let (Some(n1), Some(n2)) = (&k.normal_first, &k.normal_second) {
        out = out
            .result(
                Quantity::BorderNormal(Side::First),
                Exact::Map(exact_map(n1)),
            )
            .result(
                Quantity::BorderNormal(Side::Second),
                Exact::Map(exact_map(n2)),
            );
    }
    Ok(out)
}

/// Two patches and the remarks on what was done to them.
type Elevated<S> = (BezierSurface<S>, BezierSurface<S>, Vec<Surface>);

/// The two patches with the same degree along their common border: the patch of lower degree
/// along it (v for a border u, u for a border v) is elevated to the other's (degree elevation,
/// eq. (12), changes no point of the patch), with a remark saying so. Without it the border's
/// control points could not be compared one by one.
fn same_border_degree<S: ExactScalar>(
    first: BezierSurface<S>,
    second: BezierSurface<S>,
    join: Join,
) -> Result<Elevated<S>, ProblemError> {
    let along = |s: &BezierSurface<S>| match join {
        Join::U => s.bidegree().1,
        Join::V => s.bidegree().0,
    };
    let (n1, n2) = (along(&first), along(&second));
    let (p, q) = match join {
        Join::U => ("v", "u"),
        Join::V => ("u", "v"),
    };
    let by = |r: usize| match join {
        Join::U => (0, r),
        Join::V => (r, 0),
    };
    if n1 < n2 {
        let (r, s) = by(n2 - n1);
        let remark = Surface::FirstElevated {
            first: n1,
            second: n2,
            along: p.into(),
            across: q.into(),
        };
        Ok((
            first.elevate(r, s).map_err(at("first"))?,
            second,
            vec![remark],
        ))
    } else if n2 < n1 {
        let (r, s) = by(n1 - n2);
        let remark = Surface::SecondElevated {
            first: n1,
            second: n2,
            along: p.into(),
            across: q.into(),
        };
        Ok((
            first,
            second.elevate(r, s).map_err(at("second"))?,
            vec![remark],
        ))
    } else {
        Ok((first, second, Vec::new()))
    }
}

/// Both sides of (21)-(23) for r = 0, ..., `top` (the first order that fails, or the
/// degree): Δ^{r,0} c_{m-r,j} / (Δu_0)^r and Δ^{r,0} c̃_{0,j} / (Δu_1)^r (along v for a
/// border v, on the transposed meshes).
fn explain_join<S: ExactScalar>(
    out: &mut Out,
    first: &BezierSurface<S>,
    second: &BezierSurface<S>,
    join: Join,
    du0: &S,
    du1: &S,
    top: usize,
) {
    let (a, b) = match join {
        Join::U => (first.mesh().clone(), second.mesh().clone()),
        Join::V => (first.mesh().transpose(), second.mesh().transpose()),
    };
    let (ca, cb) = (a.to_columns(), b.to_columns());
    let degree = a.rows().min(b.rows()).saturating_sub(1);
    let d = if join == Join::U { "u" } else { "v" };
    let sup = |r: usize| {
        if join == Join::U {
            format!("{r},0")
        } else {
            format!("0,{r}")
        }
    };
    let m = a.rows().saturating_sub(1);
    for r in 0..=top.min(degree) {
        let side = |cols: &[Vec<Point<S>>], last: bool, du: &S| -> Option<Vec<Point<S>>> {
            let scale = S::one() / du.powi(u32::try_from(r).ok()?);
            cols.iter()
                .map(|col| {
                    let part = if last {
                        col.get(col.len().checked_sub(r + 1)?..)?
                    } else {
                        col.get(..=r)?
                    };
                    cagd_bezier::forward_differences(part, r)
                        .ok()?
                        .first()
                        .map(|p| p.scale(&scale))
                })
                .collect()
        };
        let (Some(left), Some(right)) = (side(&ca, true, du0), side(&cb, false, du1)) else {
            return;
        };
        let (i, name) = match join {
            Join::U => (format!("{},j", m - r), "c"),
            Join::V => (format!("i,{}", m - r), "c"),
        };
        let i2 = match join {
            Join::U => "0,j".to_string(),
            Join::V => "i,0".to_string(),
        };
        let (l, rr) = if r == 0 {
            (format!("{name}_{{{i}}}"), format!("\\tilde{{c}}_{{{i2}}}"))
        } else {
            (
                format!(
                    "\\Delta^{{{}}} {name}_{{{i}}} / (\\Delta {d}_0)^{r}",
                    sup(r)
                ),
                format!(
                    "\\Delta^{{{}}} \\tilde{{c}}_{{{i2}}} / (\\Delta {d}_1)^{r}",
                    sup(r)
                ),
            )
        };
        out.value(l, Exact::Points(exact_points(&left)));
        out.value(rr, Exact::Points(exact_points(&right)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::BigRational;

    fn patch(rows: &[&[[i64; 3]]]) -> BezierSurface<BigRational> {
        let rows = rows
            .iter()
            .map(|r| r.iter().map(|p| Point::from_ints(p)).collect())
            .collect();
        BezierSurface::try_new(cagd_surface::Grid::from_rows(rows).unwrap()).unwrap()
    }

    /// Each failing condition in words, as typed, reads as cagd-surface writes it: C^0, C^1
    /// of patches of the same degree across, and of different degrees (with a side of degree
    /// below the order), along u and v.
    #[test]
    fn the_failing_condition_is_typed() {
        let cases = [
            (
                patch(&[&[[0, 0, 0], [0, 1, 0]], &[[1, 0, 0], [1, 1, 0]]]),
                patch(&[&[[1, 0, 1], [1, 1, 0]], &[[2, 0, 0], [2, 1, 0]]]),
                Join::U,
            ),
            (
                patch(&[&[[0, 0, 0], [0, 1, 0]], &[[1, 0, 0], [1, 1, 0]]]),
                patch(&[&[[1, 0, 0], [1, 1, 0]], &[[3, 0, 0], [3, 1, 0]]]),
                Join::U,
            ),
            (
                patch(&[
                    &[[0, 0, 0], [0, 1, 0], [0, 2, 0]],
                    &[[1, 0, 0], [1, 1, 0], [1, 2, 0]],
                ]),
                patch(&[&[[0, 2, 0], [0, 5, 0]], &[[1, 2, 0], [1, 5, 0]]]),
                Join::V,
            ),
            (
                patch(&[
                    &[[0, 0, 0], [0, 1, 0]],
                    &[[1, 0, 0], [1, 1, 0]],
                    &[[2, 0, 1], [2, 1, 1]],
                ]),
                patch(&[&[[2, 0, 1], [2, 1, 1]], &[[4, 0, 3], [4, 1, 3]]]),
                Join::U,
            ),
        ];
        let mut orders = Vec::new();
        for (a, b, join) in cases {
            let one = BigRational::from_integer(1.into());
            let k = join_continuity(&a, &b, join, &one, &one).unwrap();
            let f = k.failure.unwrap();
            let m = Message::from(f.condition());
            assert!(matches!(m, Message::ConditionFails(_)), "{}", f.text);
            assert_eq!(m.to_string(), f.text);
            orders.push(f.order);
        }
        assert_eq!(orders, [0, 1, 1, 2]);
    }
}
