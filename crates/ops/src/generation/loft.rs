//! `loft`: the surface through K section curves (skinning, The NURBS Book §10.3). The
//! construction is cagd-generate's ([`cagd_generate::loft`]); here the sections read, the
//! parameters and the degree decided, and the answer written: a Bézier patch when every
//! section is a Bézier curve and q = K - 1, else a B-spline surface.

use crate::any::AnyCurve as Curve;
use crate::any::AnySurface as Patch;
use crate::convert::{at, convert};
use crate::message::curve::Curve as Say;
use crate::out::{req, Out, Run};
use crate::problem::Loft;
use crate::steps::Formula;
use crate::value::{exact, exact_points, Exact, ExactScalar, Quantity};
use crate::ProblemError;
use cagd_bspline::{BSplineCurve, KnotConvention, KnotVector};
use cagd_generate::{loft as skin, uniform_parameters};
use cagd_spline_surface::BSplineSurface;
use cagd_surface::{BezierSurface, Mesh};

/// `loft` through `sections` at `v` (default uniform) with degree `degree` in v (default
/// min(K - 1, 3)).
pub(crate) fn loft<S: ExactScalar>(a: &Loft, run: Run<'_>) -> Result<Out, ProblemError> {
    let sf = "sections";
    let given = req(&a.sections, sf)?;
    let mut sections = Vec::with_capacity(given.len());
    let mut all_bezier = true;
    for (k, c) in given.iter().enumerate() {
        let path = format!("sections[{k}]");
        sections.push(match Curve::<S>::read(c, &path)? {
            Curve::Bezier(b) => {
                let (lo, hi) = (b.domain().0.clone(), b.domain().1.clone());
                let knots = KnotVector::bezier(b.degree(), lo, hi).map_err(at(&path))?;
                BSplineCurve::try_new(knots, b.points().to_vec()).map_err(at(&path))?
            }
            Curve::BSpline(b) => {
                all_bezier = false;
                b
            }
            Curve::Map(_) => return Err(ProblemError::at(&path, Say::LoftExpression)),
            Curve::RationalBezier(_) | Curve::Nurbs(_) => {
                return Err(ProblemError::at(&path, Say::LoftRational))
            }
        });
    }
    let k = sections.len();
    let params: Vec<S> = match &a.v {
        Some(v) => {
            v.0.iter()
                .enumerate()
                .map(|(i, x)| convert::<S>(&x.0, &format!("v[{i}]")))
                .collect::<Result<_, _>>()?
        }
        None => uniform_parameters(k),
    };
    let q = match a.degree {
        Some(d) => run.degree("degree", d)?,
        None => k.saturating_sub(1).clamp(1, 3),
    };
    let lofted = skin(&sections, &params, q).map_err(at(sf))?;
    let mut out = run.out();
    for n in &lofted.notes {
        out.remark(n.clone());
    }
    out.formula(Formula::Loft);
    if out.steps_on() {
        out.value(
            "c_k",
            Exact::List(
                lofted
                    .sections
                    .iter()
                    .map(|c| Curve::BSpline(c.clone()).to_exact())
                    .collect(),
            ),
        );
        out.value(
            "v_k",
            Exact::List(params.iter().map(|x| Exact::Number(exact(x))).collect()),
        );
        // the knot vector in v, V as The NURBS Book writes it (in the notes' convention)
        out.value(
            "V",
            Exact::List(
                lofted
                    .knots_v
                    .to_convention(KnotConvention::Notes)
                    .iter()
                    .map(|x| Exact::Number(exact(x)))
                    .collect(),
            ),
        );
        for (i, column) in lofted.net.iter().enumerate() {
            out.value(format!("Q_{{{i},k}}"), Exact::Points(exact_points(column)));
        }
    }
    let mesh = Mesh::mesh(lofted.net.clone()).map_err(at(sf))?;
    let knots_u = lofted
        .sections
        .first()
        .map(|c| c.knots().clone())
        .ok_or_else(|| ProblemError::at(sf, Say::LoftExpression))?;
    let surface = if all_bezier && q + 1 == k {
        let (lo, hi) = knots_u.domain();
        let (c, d) = lofted.knots_v.domain();
        Patch::Bezier(
            BezierSurface::try_new(mesh)
                .and_then(|s| s.with_domain(lo, hi, c, d))
                .map_err(at(sf))?,
        )
    } else {
        Patch::BSpline(
            BSplineSurface::try_new(knots_u, lofted.knots_v.clone(), mesh).map_err(at(sf))?,
        )
    };
    Ok(out.result(Quantity::Surface, surface.to_exact()))
}
