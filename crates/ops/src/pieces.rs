//! B-spline and NURBS surfaces (and curves) piece by piece: the closed form, the derivatives
//! and the normal of each polynomial (rational) piece on its rectangle, and the continuity
//! across the knot lines where the pieces meet.
//!
//! A B-spline surface (notes, chapter 5, eq. (4)) is, on each rectangle
//! `[u_k, u_{k+1}] × [v_l, v_{l+1}]` of non-empty spans, a Bézier patch (a rational one for a
//! NURBS surface, eq. (6)): its mesh comes from inserting every breakpoint up to multiplicity
//! p in u and q in v (the notes' "algoritmo de obtención de polígonos de control", in two
//! passes; cagd-spline-surface's `bezier_patches`). Each piece keeps its rectangle as its
//! domain, so its closed form is written in the surface's own u and v (not in a local
//! parameter on [0, 1]): the closed form of a piece evaluates equal to De Boor's algorithm on
//! that rectangle. The answer lists the pieces, each as `{"u": [a, b], "v": [c, d], ...}`.

use crate::any::AnyCurve as Curve;
use crate::any::AnySurface as Patch;
use crate::message::curve::Curve as Say;
use crate::out::{at, num, Out, Run};
use crate::problem::At;
use crate::steps::Formula;
use crate::value::quantity::Corner;
use crate::value::Quantity;
use crate::value::{exact, exact_map, exact_point, exact_rational, Exact, ExactScalar};
use crate::ProblemError;
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_bspline::KnotVector;
use cagd_linalg::Point;
use cagd_poly::{contact_order, Var};
use cagd_spline_surface::{BezierPatches, Direction};
use cagd_surface::{BezierSurface, CornerNormal, RationalBezierSurface};

/// The pieces of a B-spline (polynomial) or NURBS (rational) surface.
pub(crate) enum SplinePieces<S> {
    /// Bézier patches of a B-spline surface.
    Polynomial(BezierPatches<S, BezierSurface<S>>),
    /// Rational Bézier patches of a NURBS surface.
    Rational(BezierPatches<S, RationalBezierSurface<S>>),
}

/// The closed form of one piece: a polynomial or a rational map (cagd-poly's).
pub(crate) use cagd_poly::ClosedForm as PieceForm;

/// A closed form as an answer value.
fn form_exact<S: ExactScalar>(f: &PieceForm<S>) -> Exact {
    match f {
        PieceForm::Polynomial(m) => Exact::Map(exact_map(m)),
        PieceForm::Rational(r) => Exact::Rational(exact_rational(r)),
    }
}

/// A surface's piece: its u interval, its v interval, its closed form.
pub(crate) type SurfacePiece<S> = ((S, S), (S, S), PieceForm<S>);

/// A curve's piece: its span and its closed form.
pub(crate) type CurvePiece<S> = ((S, S), PieceForm<S>);

/// The interval `[a, b]` as an exact pair.
fn interval<S: ExactScalar>((a, b): &(S, S)) -> Exact {
    Exact::Point(Point::new(vec![exact(a), exact(b)]))
}

/// The field `closed_form` of a piece, in the variables of `form`.
fn closed_form_field(form: Exact) -> (Quantity, Exact) {
    (Quantity::ClosedForm(form.variables()), form)
}

/// One piece of an answer: its rectangle, then `items`.
fn piece<S: ExactScalar>(iu: &(S, S), iv: &(S, S), items: Vec<(Quantity, Exact)>) -> Exact {
    let mut kv = vec![
        (Quantity::Variable(Var::U), interval(iu)),
        (Quantity::Variable(Var::V), interval(iv)),
    ];
    kv.extend(items);
    Exact::Object(kv)
}

impl<S: ExactScalar> SplinePieces<S> {
    /// The Bézier pieces of a B-spline or NURBS surface; `None` for any other surface.
    pub(crate) fn of(patch: &Patch<S>, path: &str) -> Result<Option<Self>, ProblemError> {
        Ok(match patch {
            Patch::BSpline(b) => Some(SplinePieces::Polynomial(
                b.bezier_patches().map_err(at(path))?,
            )),
            Patch::Nurbs(b) => Some(SplinePieces::Rational(
                b.bezier_patches().map_err(at(path))?,
            )),
            _ => None,
        })
    }

    /// The Bézier pieces of a B-spline or NURBS surface; an error at `path` for any other
    /// surface.
    pub(crate) fn require(patch: &Patch<S>, path: &str) -> Result<Self, ProblemError> {
        Self::of(patch, path)?.ok_or_else(|| ProblemError::at(path, Say::ExpectedSplineSurface))
    }

    /// The rectangles, row by row (u outer), with the closed form of each piece.
    pub(crate) fn forms(&self, path: &str) -> Result<Vec<SurfacePiece<S>>, ProblemError> {
        let mut out = Vec::new();
        match self {
            SplinePieces::Polynomial(p) => {
                for ((iu, iv), b) in p.iter() {
                    let f = b.closed_form().map_err(at(path))?;
                    out.push((iu.clone(), iv.clone(), PieceForm::Polynomial(f)));
                }
            }
            SplinePieces::Rational(p) => {
                for ((iu, iv), b) in p.iter() {
                    let f = b.closed_form().map_err(at(path))?;
                    out.push((iu.clone(), iv.clone(), PieceForm::Rational(f)));
                }
            }
        }
        Ok(out)
    }

    /// The number of pieces in u and in v.
    fn shape(&self) -> (usize, usize) {
        match self {
            SplinePieces::Polynomial(p) => p.shape(),
            SplinePieces::Rational(p) => p.shape(),
        }
    }
}

/// `closed_form` of a B-spline or NURBS surface: one closed form per rectangle of spans, in
/// the surface's own u and v, `pieces` = [{"u": [a, b], "v": [c, d], "closed_form": ...}].
pub(crate) fn closed_form<S: ExactScalar>(
    patch: &Patch<S>,
    path: &str,
    mut out: Out,
) -> Result<Out, ProblemError> {
    let pieces = SplinePieces::require(patch, path)?;
    out.formula(Formula::PiecewiseSurface);
    let list = pieces
        .forms(path)?
        .into_iter()
        .map(|(iu, iv, f)| piece(&iu, &iv, vec![closed_form_field(form_exact(&f))]))
        .collect();
    Ok(out.result(Quantity::Pieces, Exact::List(list)))
}

/// The partial derivative surface of order (r, s) of a B-spline surface: the derivative rule
/// `Δ_u d_{i,j} = p (d_{i+1,j} - d_{i,j}) / (u_{i+p} - u_i)` (The NURBS Book eq. (3.7);
/// cagd-spline-surface's `derivative`) r times in u and s times in v. `Ok(None)` where it is
/// no B-spline of lower degree: order above the degree (the derivative is zero), degree 1
/// (piecewise constant), or a knot of full multiplicity (the derivative may jump).
fn derivative_surface<S: ExactScalar>(
    b: &cagd_spline_surface::BSplineSurface<S>,
    r: usize,
    s: usize,
) -> Option<cagd_spline_surface::BSplineSurface<S>> {
    let mut d = b.clone();
    for dir in std::iter::repeat_n(Direction::U, r).chain(std::iter::repeat_n(Direction::V, s)) {
        d = d.derivative(dir).ok()?;
    }
    Some(d)
}

/// Keeps the pieces whose rectangle contains the border `at` (both neighbours on a knot
/// line), with the value put in; the `at` of a derivative.
fn restrict_pieces<S: ExactScalar>(
    forms: Vec<SurfacePiece<S>>,
    border: Option<&At>,
) -> Result<Vec<SurfacePiece<S>>, ProblemError> {
    let Some(border) = border else {
        return Ok(forms);
    };
    let mut fixed = Vec::new();
    for (name, var, x) in [("at.u", Var::U, &border.u), ("at.v", Var::V, &border.v)] {
        if let Some(x) = x {
            fixed.push((name, var, num::<S>(x, name)?));
        }
    }
    let mut out = Vec::new();
    'pieces: for (iu, iv, mut f) in forms {
        for (name, var, x) in &fixed {
            let (a, b) = if *var == Var::U { &iu } else { &iv };
            let inside = matches!(
                a.compare(x),
                Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)
            ) && matches!(
                x.compare(b),
                Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)
            );
            let unknown = a.compare(x).is_none() || x.compare(b).is_none();
            if unknown {
                return Err(ProblemError::at(*name, Say::BorderInLetters));
            }
            if !inside {
                continue 'pieces;
            }
            f = f
                .substitute(*var, x)
                .ok_or_else(|| ProblemError::at(*name, Say::DerivativeUndefinedThere))?;
        }
        out.push((iu, iv, f));
    }
    if out.is_empty() {
        return Err(ProblemError::at("at", Say::BorderOutside));
    }
    Ok(out)
}

/// `derivative` of order (r, s) of a B-spline or NURBS surface: the derivative of each piece
/// (eq. (18) on each Bézier patch of the extraction, with the chain rule of its rectangle; for
/// a NURBS piece the quotient rule on (5), over w^(r+s+1)), as `pieces`; for a B-spline
/// surface also the derivative surface, a B-spline of bidegree (p - r, q - s) on the knots
/// without their first r (s) and last r (s) knots.
pub(crate) fn derivative<S: ExactScalar>(
    patch: &Patch<S>,
    (r, s): (usize, usize),
    border: Option<&At>,
    path: &str,
    mut out: Out,
) -> Result<Out, ProblemError> {
    let pieces = SplinePieces::require(patch, path)?;
    out.formula(Formula::PiecewiseSurface);
    if let Patch::BSpline(b) = patch {
        out.formula(Formula::DerivativeBSplineSurface);
        let (p, q) = b.bidegree();
        match derivative_surface(b, r, s) {
            Some(d) if r <= p && s <= q => {
                if border.is_none() {
                    out = out.result(Quantity::Surface, Patch::BSpline(d).to_exact());
                }
            }
            _ => out.remark(Say::SurfaceDerivativeNotSpline { r, s, p, q }),
        }
    } else {
        out.formula(Formula::DerivativeRational);
    }
    let forms: Vec<_> = pieces
        .forms(path)?
        .into_iter()
        .map(|(iu, iv, f)| (iu, iv, f.partial(r, s)))
        .collect();
    let list = restrict_pieces(forms, border)?
        .into_iter()
        .map(|(iu, iv, f)| piece(&iu, &iv, vec![closed_form_field(form_exact(&f))]))
        .collect();
    Ok(out.result(Quantity::Pieces, Exact::List(list)))
}

fn corner_value<S: ExactScalar>(n: &CornerNormal<S>) -> Exact {
    match n {
        CornerNormal::Normal(p) => Exact::Point(exact_point(p)),
        _ => Exact::Text(n.to_text()),
    }
}

/// `normal` of a B-spline or NURBS surface: `c_u × c_v` of each piece (on its rectangle, in
/// the surface's u and v) with its value at the piece's four corners, as `pieces`.
pub(crate) fn normal<S: ExactScalar>(
    patch: &Patch<S>,
    path: &str,
    mut out: Out,
) -> Result<Out, ProblemError> {
    let pieces = SplinePieces::require(patch, path)?;
    out.formula(Formula::PiecewiseSurface);
    let mut list = Vec::new();
    let mut push = |iu: &(S, S), iv: &(S, S), form: Exact, corners: [CornerNormal<S>; 4]| {
        let mut items = vec![closed_form_field(form)];
        for (corner, c) in Corner::ALL.into_iter().zip(corners.iter()) {
            let normal = |limit| Quantity::CornerNormal { corner, limit };
            items.push((normal(false), corner_value(c)));
            if let CornerNormal::Limit { direction, .. } = c {
                items.push((normal(true), Exact::Point(exact_point(direction))));
            }
        }
        list.push(piece(iu, iv, items));
    };
    match &pieces {
        SplinePieces::Polynomial(p) => {
            for ((iu, iv), b) in p.iter() {
                let field = b.normal().map_err(at(path))?;
                let corners = b.corner_normals(&field).map_err(at(path))?;
                push(iu, iv, Exact::Map(exact_map(&field)), corners);
            }
        }
        SplinePieces::Rational(p) => {
            for ((iu, iv), b) in p.iter() {
                let field = b.normal().map_err(at(path))?;
                let corners = b.corner_normals(&field).map_err(at(path))?;
                push(iu, iv, Exact::Rational(exact_rational(&field)), corners);
            }
        }
    }
    Ok(out.result(Quantity::Pieces, Exact::List(list)))
}

/// `continuity` of a B-spline or NURBS `surface` across its knot lines: for each interior
/// breakpoint ξ of multiplicity μ in u (v), the surface is C^{p-μ} there by the knot vector
/// (The NURBS Book §3.4; in the notes, chapter 5 §4 with the curve's rule), and the order is
/// checked exactly on the pieces: the derivatives ∂^k c/∂u^k of the pieces on either side,
/// put u = ξ, are compared as maps in v for k = 0, 1, ... (the notes' (21)-(23) on the
/// closed forms). Agreement up to the degree p (2p for NURBS pieces, whose difference has a
/// numerator of degree 2p) means the pieces are one map: C^∞ there.
pub(crate) fn knot_lines<S: ExactScalar>(
    patch: &Patch<S>,
    path: &str,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let mut out = run.out();
    let Some(pieces) = SplinePieces::of(patch, path)? else {
        return Err(ProblemError::at(path, Say::KnotLinesNeedSpline));
    };
    let (ku, kv, (p, q)) = match patch {
        Patch::BSpline(b) => (b.knots_u().clone(), b.knots_v().clone(), b.bidegree()),
        Patch::Nurbs(b) => (b.knots_u().clone(), b.knots_v().clone(), b.bidegree()),
        _ => return Err(ProblemError::at(path, Say::ExpectedSplineSurface)),
    };
    let rational = matches!(pieces, SplinePieces::Rational(_));
    out.formula(Formula::PiecewiseSurface);
    out.formula(Formula::KnotLineContinuity);
    let forms = pieces.forms(path)?;
    let (nu, nv) = pieces.shape();
    let form = |a: usize, b: usize| forms.get(a * nv + b).map(|(_, _, f)| f.clone());
    let mut lines = Vec::new();
    let mut lowest: Option<isize> = None;
    for (dir, knots, degree, count, var) in [("u", &ku, p, nu, Var::U), ("v", &kv, q, nv, Var::V)] {
        let interior = interior_breakpoints(knots);
        for (index, (xi, mu)) in interior.iter().enumerate() {
            if index + 1 >= count {
                break;
            }
            // the pieces left and right of the line, for each span of the other direction
            let pairs: Vec<_> = if var == Var::U {
                (0..nv)
                    .filter_map(|b| Some((form(index, b)?, form(index + 1, b)?)))
                    .collect()
            } else {
                (0..nu)
                    .filter_map(|a| Some((form(a, index)?, form(a, index + 1)?)))
                    .collect()
            };
            let top = if rational { 2 * degree } else { degree };
            let order = contact_order(&pairs, var, xi, top);
            let expected = isize::try_from(degree).unwrap_or(isize::MAX)
                - isize::try_from(*mu).unwrap_or(isize::MAX);
            if let Some(k) = order {
                lowest = Some(lowest.map_or(k, |l| l.min(k)));
            }
            let order_value = match order {
                Some(k) => Exact::Int(i64::try_from(k).unwrap_or(i64::MAX)),
                None => Exact::Sentence(Say::Infinite.into()),
            };
            if out.steps_on() {
                let at = format!("{dir} = {}", xi.to_text());
                out.value(
                    format!("\\mu({at})"),
                    Exact::Int(i64::try_from(*mu).unwrap_or(i64::MAX)),
                );
                out.value(
                    format!("p - \\mu({at})"),
                    Exact::Int(i64::try_from(expected).unwrap_or(i64::MAX)),
                );
                out.value(format!("r({at})"), order_value.clone());
            }
            lines.push(Exact::Object(vec![
                (Quantity::KnotDirection, Exact::Text(dir.into())),
                (Quantity::Knot, Exact::Number(exact(xi))),
                (
                    Quantity::Multiplicity,
                    Exact::Int(i64::try_from(*mu).unwrap_or(i64::MAX)),
                ),
                (
                    Quantity::ExpectedOrder,
                    Exact::Int(i64::try_from(expected).unwrap_or(i64::MAX)),
                ),
                (Quantity::Order, order_value),
            ]));
        }
    }
    let order = match lowest {
        Some(k) => Exact::Int(i64::try_from(k).unwrap_or(i64::MAX)),
        None => Exact::Sentence(Say::Infinite.into()),
    };
    Ok(out
        .result(Quantity::Order, order)
        .result(Quantity::KnotLines, Exact::List(lines)))
}

/// The breakpoints strictly inside the domain, with their multiplicities (notes' convention).
fn interior_breakpoints<S: ExactScalar>(knots: &KnotVector<S>) -> Vec<(S, usize)> {
    let (a, b) = knots.domain();
    knots
        .breakpoints()
        .into_iter()
        .filter(|(x, _)| x != &a && x != &b)
        .collect()
}

/// The closed forms of the pieces of a B-spline or NURBS curve, in t, each with its span
/// `[u_k, u_{k+1}]` (the Bézier extraction, each piece on its span, so in the curve's own t);
/// `None` for any other curve.
pub(crate) fn curve_forms<S: ExactScalar>(
    c: &Curve<S>,
    path: &str,
) -> Result<Option<Vec<CurvePiece<S>>>, ProblemError> {
    Ok(Some(match c {
        Curve::BSpline(b) => b
            .bezier_pieces()
            .map_err(at(path))?
            .into_iter()
            .map(|piece| {
                let (a, b) = piece.interval.clone();
                let curve = BezierCurve::try_new(piece.points)
                    .and_then(|c| c.with_domain(a, b))
                    .map_err(at(path))?;
                Ok((
                    piece.interval,
                    PieceForm::Polynomial(curve.closed_form(Var::T)),
                ))
            })
            .collect::<Result<Vec<_>, ProblemError>>()?,
        Curve::Nurbs(b) => b
            .bezier_pieces()
            .map_err(at(path))?
            .into_iter()
            .map(|piece| {
                let (a, b) = piece.interval.clone();
                let curve = RationalBezierCurve::try_new(piece.points, piece.weights)
                    .and_then(|c| c.with_domain(a, b))
                    .map_err(at(path))?;
                Ok((
                    piece.interval,
                    PieceForm::Rational(curve.closed_form(Var::T)),
                ))
            })
            .collect::<Result<Vec<_>, ProblemError>>()?,
        _ => return Ok(None),
    }))
}

/// One piece of a curve's answer: `{"t": [a, b], "closed_form": ...}`.
fn curve_piece<S: ExactScalar>(span: &(S, S), f: &PieceForm<S>) -> Exact {
    Exact::Object(vec![
        (Quantity::Variable(Var::T), interval(span)),
        closed_form_field(form_exact(f)),
    ])
}

/// `closed_form` of a B-spline or NURBS curve: `pieces` = [{"t": [a, b], "closed_form": ...}],
/// one per span, in the curve's own t.
pub(crate) fn curve_closed_form<S: ExactScalar>(
    c: &Curve<S>,
    path: &str,
    mut out: Out,
) -> Result<Out, ProblemError> {
    let Some(forms) = curve_forms(c, path)? else {
        return Err(ProblemError::at(path, Say::ExpectedSplineCurve));
    };
    out.formula(Formula::PiecewiseCurve);
    let list = forms.iter().map(|(span, f)| curve_piece(span, f)).collect();
    Ok(out.result(Quantity::Pieces, Exact::List(list)))
}

/// `derivative` of order r of a rational Bézier, B-spline or NURBS curve.
///
/// - rational Bézier: c = p/w, the quotient rule r times in closed form, written over
///   w^(r+1) (Leibniz's rule on p = w c; a lower power when w divides the numerator);
/// - B-spline: the derivative curve, a B-spline of degree p - r on the knots without their
///   first r and last r (notes' convention), control points
///   `Δd_i = p (d_{i+1} - d_i) / (u_{i+p} - u_i)` (The NURBS Book eq. (3.7)) r times, and
///   the derivative of each piece;
/// - NURBS: the derivative of each rational piece, as for a rational Bézier curve.
pub(crate) fn curve_derivative<S: ExactScalar>(
    c: &Curve<S>,
    r: usize,
    path: &str,
    mut out: Out,
) -> Result<Out, ProblemError> {
    if let Curve::RationalBezier(b) = c {
        out.formula(Formula::ClosedFormRationalCurve);
        out.formula(Formula::DerivativeRationalCurve);
        let f = b.closed_form(Var::T);
        if out.steps_on() {
            out.value("p(t)", Exact::Map(exact_map(f.numerator())));
            out.value(
                "w(t)",
                Exact::Poly(crate::value::exact_poly(f.denominator())),
            );
        }
        let d = PieceForm::Rational(f).derivative_in(Var::T, r);
        return Ok(out.closed_form(form_exact(&d)));
    }
    let Some(forms) = curve_forms(c, path)? else {
        return Err(ProblemError::at(path, Say::ExpectedRationalOrSplineCurve));
    };
    out.formula(Formula::PiecewiseCurve);
    if let Curve::BSpline(b) = c {
        out.formula(Formula::DerivativeBSplineCurve);
        let p = b.degree();
        let mut d = Some(b.clone());
        for _ in 0..r {
            d = d.and_then(|x| x.derivative().ok());
        }
        match d {
            Some(d) if r <= p => out = out.result(Quantity::Curve, Curve::BSpline(d).to_exact()),
            _ => out.remark(Say::CurveDerivativeNotSpline { r, p }),
        }
    } else {
        out.formula(Formula::DerivativeRationalCurve);
    }
    let list = forms
        .iter()
        .map(|(span, f)| curve_piece(span, &f.derivative_in(Var::T, r)))
        .collect();
    Ok(out.result(Quantity::Pieces, Exact::List(list)))
}

// --- the continuity of two separate surfaces, B-spline or NURBS, piece by piece ---

/// The pieces of any patch: a B-spline or NURBS surface's Bézier pieces, or a Bézier (rational
/// Bézier) patch as one piece on its domain.
fn patch_pieces<S: ExactScalar>(
    patch: &Patch<S>,
    path: &str,
) -> Result<Vec<SurfacePiece<S>>, ProblemError> {
    if let Some(pieces) = SplinePieces::of(patch, path)? {
        return pieces.forms(path);
    }
    let (iu, iv) = patch.domain();
    let form = match patch {
        Patch::Bezier(s) => PieceForm::Polynomial(s.closed_form().map_err(at(path))?),
        Patch::RationalBezier(s) => PieceForm::Rational(s.closed_form().map_err(at(path))?),
        Patch::Map(e) => PieceForm::Polynomial(e.clone()),
        Patch::BSpline(_) | Patch::Nurbs(_) => {
            return Err(ProblemError::at(path, Say::ExpectedPatch));
        }
    };
    Ok(vec![(iu, iv, form)])
}

/// The degree of a patch across a border in `var` (u: its degree in u), doubled for a
/// rational one (the difference of two of its derivatives has a numerator of that degree).
fn degree_across<S: ExactScalar>(patch: &Patch<S>, var: Var) -> usize {
    let pick = |(p, q): (usize, usize)| if var == Var::U { p } else { q };
    match patch {
        Patch::Bezier(s) => pick(s.bidegree()),
        Patch::RationalBezier(s) => 2 * pick(s.bidegree()),
        Patch::BSpline(s) => pick(s.bidegree()),
        Patch::Nurbs(s) => 2 * pick(s.bidegree()),
        Patch::Map(e) => usize::try_from(e.degree_in(var)).unwrap_or(usize::MAX),
    }
}

/// `continuity` of two surfaces, at least one a B-spline or NURBS surface, along the border
/// where the first ends (u = b₁ for `border` u) and the second begins (u = a₂): the second is
/// moved along u by b₁ - a₂ so that the two are consecutive, c̃(u - b₁ + a₂, v), and the
/// derivatives are taken in the surfaces' own parameters. Along the border (v), every piece
/// of the first at u = b₁ meets the pieces of the second at u = a₂ whose v intervals overlap
/// its own; on each overlap the derivatives ∂^k/∂u^k of the two pieces at the border are
/// compared as maps in v (equal on an interval, so identical) for k = 0, 1, ..., as the
/// notes' (21)-(23) on the closed forms; agreement up to the higher degree in u (twice it for
/// rational pieces) means one map: C^∞. Both borders must run over the same v interval.
pub(crate) fn two_surfaces<S: ExactScalar>(
    first: &Patch<S>,
    second: &Patch<S>,
    var: Var,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let mut out = run.out();
    out.formula(Formula::PiecewiseSurface);
    out.formula(Formula::SplinePatchesJoin);
    let split = |d: ((S, S), (S, S))| if var == Var::U { d } else { (d.1, d.0) };
    let (across_1, along_1) = split(first.domain());
    let (across_2, along_2) = split(second.domain());
    let other = if var == Var::U { Var::V } else { Var::U };
    let dir = if var == Var::U { "u" } else { "v" };
    if along_1 != along_2 {
        return Err(ProblemError::at(
            "second",
            Say::BordersDiffer {
                along: other.name().to_string(),
                first_from: along_1.0.to_text(),
                first_to: along_1.1.to_text(),
                second_from: along_2.0.to_text(),
                second_to: along_2.1.to_text(),
            },
        ));
    }
    let (xi, start) = (across_1.1.clone(), across_2.0.clone());
    let delta = xi.clone() - start.clone();
    let interval_of = |iu: &(S, S), iv: &(S, S)| {
        if var == Var::U {
            (iu.clone(), iv.clone())
        } else {
            (iv.clone(), iu.clone())
        }
    };
    // the first's pieces that end at the border, the second's that start there (moved)
    let ending: Vec<((S, S), PieceForm<S>)> = patch_pieces(first, "first")?
        .into_iter()
        .filter_map(|(iu, iv, f)| {
            let (a, b) = interval_of(&iu, &iv);
            (a.1 == xi).then_some((b, f))
        })
        .collect();
    let starting: Vec<((S, S), PieceForm<S>)> = patch_pieces(second, "second")?
        .into_iter()
        .filter_map(|(iu, iv, f)| {
            let (a, b) = interval_of(&iu, &iv);
            (a.0 == start).then(|| (b, f.shifted(var, &delta)))
        })
        .collect();
    let top = degree_across(first, var).max(degree_across(second, var));
    let less = |x: &S, y: &S| x.compare(y) == Some(std::cmp::Ordering::Less);
    let mut list = Vec::new();
    let mut lowest: Option<isize> = None;
    for (i1, f1) in &ending {
        for (i2, f2) in &starting {
            // the overlap [lo, hi] of the two pieces' intervals along the border
            let lo = if less(&i1.0, &i2.0) {
                i2.0.clone()
            } else {
                i1.0.clone()
            };
            let hi = if less(&i1.1, &i2.1) {
                i1.1.clone()
            } else {
                i2.1.clone()
            };
            if !less(&lo, &hi) {
                continue;
            }
            let order = contact_order(&[(f1.clone(), f2.clone())], var, &xi, top);
            if let Some(k) = order {
                lowest = Some(lowest.map_or(k, |l| l.min(k)));
            }
            let order = match order {
                Some(k) => Exact::Int(i64::try_from(k).unwrap_or(i64::MAX)),
                None => Exact::Sentence(Say::Infinite.into()),
            };
            if out.steps_on() {
                out.value(
                    format!("r([{}, {}])", lo.to_text(), hi.to_text()),
                    order.clone(),
                );
            }
            list.push(Exact::Object(vec![
                (Quantity::Variable(other), interval(&(lo, hi))),
                (Quantity::Order, order),
            ]));
        }
    }
    if list.is_empty() {
        return Err(ProblemError::at(
            "second",
            Say::NoMatchingPieces {
                dir: dir.to_string(),
                end: xi.to_text(),
                start: start.to_text(),
            },
        ));
    }
    if delta != S::zero() {
        out.remark(Say::SecondMoved {
            dir: dir.to_string(),
            start: start.to_text(),
            end: xi.to_text(),
            delta: delta.to_text(),
        });
    }
    let order = match lowest {
        Some(k) => Exact::Int(i64::try_from(k).unwrap_or(i64::MAX)),
        None => Exact::Sentence(Say::Infinite.into()),
    };
    Ok(out
        .result(Quantity::Order, order)
        .result(Quantity::Pieces, Exact::List(list)))
}
