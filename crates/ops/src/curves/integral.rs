//! `integral`: `∫_a^b c(t) dt` of a polynomial curve and its parametric mean, or the integrals
//! of B-spline basis functions; `area` of a closed planar curve, `½ ∮ (x y' - y x') dt`. The
//! mathematics is cagd-bezier's (the average of the control points), cagd-bspline's (the
//! basis functions' integrals) and cagd-poly's (definite integrals, the enclosed area); here
//! the values read and the answer written.

use crate::any::AnyCurve as Curve;
use crate::any_curve::curve_var;
use crate::convert::{at, convert};
use crate::message::curve::Curve as Say;
use crate::out::{pair, Out, Run};
use crate::problem::{Area, Integral};
use crate::steps::Formula;
use crate::value::{exact, exact_point, exact_poly, Exact, ExactScalar, Quantity};
use crate::ProblemError;
use cagd_bezier::{control_point_average, polygon_integral};
use cagd_bspline::{basis_integrals, curve_integral, KnotVector};
use cagd_linalg::Point;
use cagd_poly::{enclosed_area, Var, VecPoly};
use std::cmp::Ordering;

/// A list of numbers as an answer value.
fn numbers<S: ExactScalar>(xs: &[S]) -> Exact {
    Exact::List(xs.iter().map(|x| Exact::Number(exact(x))).collect())
}

/// A polynomial piece: its closed form, its variable and its interval.
type Piece<S> = (VecPoly<S>, Var, (S, S));

/// The polynomial pieces of a curve on [lo, hi] (each clipped to it), with their variable; a
/// rational curve refused with `rational`.
fn polynomial_pieces<S: ExactScalar>(
    curve: &Curve<S>,
    (lo, hi): (&S, &S),
    path: &str,
    rational: Say,
) -> Result<Vec<Piece<S>>, ProblemError> {
    Ok(match curve {
        Curve::Bezier(b) => vec![(b.closed_form(Var::T), Var::T, (lo.clone(), hi.clone()))],
        Curve::Map(e) => vec![(e.clone(), curve_var(e), (lo.clone(), hi.clone()))],
        Curve::BSpline(_) => crate::pieces::curve_forms(curve, path)?
            .unwrap_or_default()
            .into_iter()
            .filter_map(|((x, y), f)| match f {
                crate::pieces::PieceForm::Polynomial(m) => {
                    let x = if x.compare(lo) == Some(Ordering::Less) {
                        lo.clone()
                    } else {
                        x
                    };
                    let y = if y.compare(hi) == Some(Ordering::Greater) {
                        hi.clone()
                    } else {
                        y
                    };
                    (x.compare(&y) == Some(Ordering::Less)).then_some((m, Var::T, (x, y)))
                }
                crate::pieces::PieceForm::Rational(_) => None,
            })
            .collect(),
        Curve::RationalBezier(_) | Curve::Nurbs(_) => return Err(ProblemError::at(path, rational)),
    })
}

/// `integral` of a polynomial `curve` on its domain or on `t` = [a, b], with its mean; or,
/// without a curve, the integrals of the B-spline basis functions of `knots` and `degree`.
pub(crate) fn integral<S: ExactScalar>(a: &Integral, run: Run<'_>) -> Result<Out, ProblemError> {
    let Some(c) = &a.curve else {
        return basis::<S>(a, run);
    };
    let cf = "curve";
    let curve = Curve::<S>::read(c, cf)?;
    let domain = curve.domain();
    let (lo, hi) = match &a.t {
        Some(t) => pair::<S>(t, "t")?,
        None => domain.clone(),
    };
    if lo.compare(&hi) != Some(Ordering::Less) {
        return Err(ProblemError::at(
            "t",
            cagd_bezier::BezierError::DegenerateInterval {
                a: lo.to_text(),
                b: hi.to_text(),
            },
        ));
    }
    let whole = lo == domain.0 && hi == domain.1;
    let mut out = run.out();
    let mut extra = Vec::new();
    let total: Point<S> = match &curve {
        Curve::Bezier(b) if whole => {
            out.formula(Formula::BezierIntegral);
            let avg = control_point_average(b.points()).map_err(at(cf))?;
            out.value("(1/(n+1)) \\sum_i b_i", Exact::Point(exact_point(&avg)));
            polygon_integral(b.points(), &lo, &hi).map_err(at(cf))?
        }
        Curve::BSpline(b) if whole => {
            out.formula(Formula::BasisIntegral);
            let weights = basis_integrals(b.knots()).map_err(at(cf))?;
            out.value("\\int N_i", numbers(&weights));
            extra.push((Quantity::BasisIntegrals, numbers(&weights)));
            curve_integral(b.knots(), b.points()).map_err(at(cf))?
        }
        _ => {
            out.formula(Formula::CurveIntegral);
            let pieces = polynomial_pieces(&curve, (&lo, &hi), cf, Say::IntegralRational)?;
            let dim = pieces.first().map_or(0, |(m, _, _)| m.dim());
            let mut total = Point::zero(dim);
            for (m, var, (x, y)) in &pieces {
                let part = m.definite_integral(*var, x, y);
                if pieces.len() > 1 {
                    out.value(
                        format!("\\int_{{{}}}^{{{}}} c", x.to_text(), y.to_text()),
                        Exact::Point(exact_point(&part)),
                    );
                }
                total.add_scaled(&part, &S::one());
            }
            total
        }
    };
    let mean = total.scale(&(S::one() / (hi.clone() - lo.clone())));
    let mut out = out
        .result(Quantity::Integral, Exact::Point(exact_point(&total)))
        .result(Quantity::Mean, Exact::Point(exact_point(&mean)));
    for (q, v) in extra {
        out = out.result(q, v);
    }
    Ok(out)
}

/// The integrals over the domain of the B-spline basis functions of `knots` (the notes'
/// convention) and `degree`.
fn basis<S: ExactScalar>(a: &Integral, run: Run<'_>) -> Result<Out, ProblemError> {
    let (Some(knots), Some(degree)) = (&a.knots, &a.degree) else {
        return Err(ProblemError::at(
            if a.knots.is_some() { "degree" } else { "knots" },
            Say::IntegralNeedsCurveOrKnots,
        ));
    };
    let p = run.degree("degree", *degree)?;
    let knots = knots
        .0
        .iter()
        .enumerate()
        .map(|(k, x)| convert::<S>(&x.0, &format!("knots[{k}]")))
        .collect::<Result<Vec<_>, _>>()?;
    let knots = KnotVector::from_notes(knots, p).map_err(at("knots"))?;
    run.check_points(
        "knots",
        knots.control_point_count(),
        crate::message::fitting::Fitting::BSpline,
    )?;
    let mut out = run.out();
    out.formula(Formula::BasisIntegral);
    let weights = basis_integrals(&knots).map_err(at("knots"))?;
    let (lo, hi) = knots.domain();
    out.value("\\int N_i", numbers(&weights));
    out.value("\\sum_i \\int N_i", Exact::Number(exact(&(hi - lo))));
    Ok(out.result(Quantity::BasisIntegrals, numbers(&weights)))
}

/// `area` enclosed by a closed planar polynomial curve: `A = ½ ∮ (x y' - y x') dt`, signed
/// (positive counter-clockwise), its size and the orientation.
pub(crate) fn enclosed<S: ExactScalar>(a: &Area, run: Run<'_>) -> Result<Out, ProblemError> {
    let cf = "curve";
    let Some(c) = &a.curve else {
        return Err(ProblemError::at(cf, Say::AreaNeedsCurveOrSurface));
    };
    let curve = Curve::<S>::read(c, cf)?;
    let (lo, hi) = curve.domain();
    let pieces = polynomial_pieces(&curve, (&lo, &hi), cf, Say::AreaRational)?;
    let area = enclosed_area(&pieces).map_err(at(cf))?;
    let mut out = run.out();
    out.formula(Formula::EnclosedArea);
    let integrands: Vec<Exact> = area
        .integrands
        .iter()
        .map(|g| Exact::Poly(exact_poly(g)))
        .collect();
    out.value(
        "x y' - y x'",
        match integrands.as_slice() {
            [one] => one.clone(),
            _ => Exact::List(integrands),
        },
    );
    let orientation = match area.orientation() {
        Some(Ordering::Greater) => Say::CounterClockwise,
        Some(Ordering::Less) => Say::Clockwise,
        Some(Ordering::Equal) => Say::NoOrientation,
        None => Say::OrientationUndecided,
    };
    let out = out
        .result(Quantity::SignedArea, Exact::Number(exact(&area.signed)))
        .result(Quantity::Orientation, Exact::Sentence(orientation.into()));
    Ok(match area.orientation() {
        Some(_) => out.result(Quantity::Area, Exact::Number(exact(&area.area()))),
        None => out,
    })
}
