//! `gaussian_curvature`: the notes' developability criterion (chapter 6, eq. (8)) for any
//! patch, with the numerator of the Gaussian curvature as an exact polynomial.
//!
//! The numerator G (`L N - M²` of a polynomial patch, `w⁸ (L N - M²)` of a rational one, with
//! the sign of K) is cagd-surface's ([`cagd_surface::gaussian_numerator`],
//! [`cagd_surface::gaussian_numerator_rational`]); where G vanishes on the domain is decided
//! exactly by cagd-poly ([`cagd_poly::zero_set`]). A B-spline or NURBS surface is tested piece
//! by piece. Here: the surface read, the answer written (G, its corner values, its zeros in
//! words).

use crate::any::AnySurface as Patch;
use crate::message::curve::Curve as Say;
use crate::out::{at, req, Out, Run};
use crate::pieces::{PieceForm, SplinePieces};
use crate::problem::GaussianCurvature;
use crate::steps::Formula;
use crate::value::quantity::{Corner, Quantity};
use crate::value::{exact_poly, Exact, ExactScalar};
use crate::ProblemError;
use cagd_poly::{combine_zero_sets, zero_set, Poly, Var, VecPoly, ZeroSet};
use cagd_surface::CurvatureError;

/// G = L N - M² of a polynomial patch `c` ([`cagd_surface::gaussian_numerator`]).
pub(crate) fn numerator_polynomial<S: ExactScalar>(
    c: &VecPoly<S>,
    path: &str,
) -> Result<Poly<S>, ProblemError> {
    cagd_surface::gaussian_numerator(c).map_err(|e| refusal(e, path))
}

/// The numerator's refusal at `path`: cagd-surface's words, a product's refusal as its own.
fn refusal(e: CurvatureError, path: &str) -> ProblemError {
    match e {
        CurvatureError::Poly(e) => ProblemError::at(path, e),
        e => ProblemError::at(path, e),
    }
}

/// G of a piece's closed form: L N - M² of a polynomial one, w⁸ (L N - M²) of a rational one
/// ([`cagd_surface::gaussian_numerator_rational`]).
pub(crate) fn numerator<S: ExactScalar>(
    f: &PieceForm<S>,
    path: &str,
) -> Result<Poly<S>, ProblemError> {
    match f {
        PieceForm::Polynomial(c) => numerator_polynomial(c, path),
        PieceForm::Rational(r) => {
            cagd_surface::gaussian_numerator_rational(r).map_err(|e| refusal(e, path))
        }
    }
}

/// G at the corners of [a, b] x [c, d], as `G_00` (G(a, c)), `G_10`, `G_01`, `G_11`.
fn corners<S: ExactScalar>(
    g: &Poly<S>,
    (a, b): &(S, S),
    (c, d): &(S, S),
) -> Result<Exact, ProblemError> {
    let mut out = Vec::new();
    for (corner, (u, v)) in Corner::ALL
        .into_iter()
        .zip([(a, c), (b, c), (a, d), (b, d)])
    {
        let x = g
            .eval(&[(Var::U, u.clone()), (Var::V, v.clone())])
            .map_err(at(""))?;
        out.push((
            Quantity::CornerNumerator(corner),
            Exact::Number(crate::value::exact(&x)),
        ));
    }
    Ok(Exact::Object(out))
}

fn point_exact<S: ExactScalar>((u, v): &(S, S)) -> Exact {
    Exact::Point(cagd_linalg::Point::new(vec![
        crate::value::exact(u),
        crate::value::exact(v),
    ]))
}

/// The verdict on the zeros of G as results: `sign` (1 or -1 where G keeps a strict sign, 0
/// where it vanishes), `zero` or `sign_change` (the exact points that prove a zero), and
/// `zeros`, the verdict in words.
fn zero_results<S: ExactScalar>(z: &ZeroSet<S>) -> Vec<(Quantity, Exact)> {
    let words = (
        Quantity::Zeros,
        Exact::Sentence(crate::zeros::verdict(z).into()),
    );
    match z {
        ZeroSet::Everywhere => vec![(Quantity::CurvatureSign, Exact::Int(0)), words],
        ZeroSet::Sign { sign, .. } => {
            let s = if *sign == std::cmp::Ordering::Less {
                -1
            } else {
                1
            };
            vec![(Quantity::CurvatureSign, Exact::Int(s)), words]
        }
        ZeroSet::Zero(u, v) => vec![
            (Quantity::CurvatureSign, Exact::Int(0)),
            (Quantity::Zero, point_exact(&(u.clone(), v.clone()))),
            words,
        ],
        ZeroSet::SignChange(p, q) => vec![
            (Quantity::CurvatureSign, Exact::Int(0)),
            (
                Quantity::SignChange,
                Exact::List(vec![point_exact(p), point_exact(q)]),
            ),
            words,
        ],
        ZeroSet::Mixed | ZeroSet::Undecided { .. } => vec![words],
    }
}

/// `gaussian_curvature` of a `surface` of any kind: `developable` (G ≡ 0, eq. (8)),
/// `numerator` G (the sign of K), its values at the corners of the domain, and where it
/// vanishes on the domain (`sign`, `zero` or `sign_change`, and `zeros` in words); for a
/// B-spline or NURBS surface, `pieces` with G and its zeros on each rectangle.
pub(crate) fn gaussian_curvature<S: ExactScalar>(
    a: &GaussianCurvature,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let sf = "surface";
    let patch = Patch::<S>::read(req(&a.surface, sf)?, sf)?;
    let mut out = run.out();
    out.formula(Formula::Developable8);
    out.formula(Formula::GaussianNumerator);
    if let Some(pieces) = SplinePieces::of(&patch, sf)? {
        out.formula(Formula::PiecewiseSurface);
        let mut list = Vec::new();
        let mut developable = true;
        let mut zeros = Vec::new();
        for (iu, iv, f) in pieces.forms(sf)? {
            let g = numerator(&f, sf)?;
            developable &= g.is_zero();
            list.push(Exact::Object(vec![
                (
                    Quantity::Variable(Var::U),
                    Exact::Point(cagd_linalg::Point::new(vec![
                        crate::value::exact(&iu.0),
                        crate::value::exact(&iu.1),
                    ])),
                ),
                (
                    Quantity::Variable(Var::V),
                    Exact::Point(cagd_linalg::Point::new(vec![
                        crate::value::exact(&iv.0),
                        crate::value::exact(&iv.1),
                    ])),
                ),
                (Quantity::GaussianNumerator, Exact::Poly(exact_poly(&g))),
                (Quantity::Corners, corners(&g, &iu, &iv)?),
            ]));
            let z = zero_set(&g, &iu, &iv).map_err(at(sf))?;
            // the piece's sign and points (its verdict in words is the whole's)
            if let Some(Exact::Object(fields)) = list.last_mut() {
                fields.extend(
                    zero_results(&z)
                        .into_iter()
                        .filter(|(k, _)| *k != Quantity::Zeros),
                );
            }
            zeros.push((iu, iv, z));
        }
        out = out
            .result(Quantity::Developable, Exact::Bool(developable))
            .result(Quantity::Pieces, Exact::List(list));
        for (k, v) in zero_results(&combine_zero_sets(&zeros)) {
            out = out.result(k, v);
        }
        return Ok(out);
    }
    let form = match &patch {
        Patch::Bezier(s) => PieceForm::Polynomial(s.closed_form().map_err(at(sf))?),
        Patch::RationalBezier(s) => PieceForm::Rational(s.closed_form().map_err(at(sf))?),
        Patch::Map(e) => PieceForm::Polynomial(e.clone()),
        Patch::BSpline(_) | Patch::Nurbs(_) => {
            return Err(ProblemError::at(sf, Say::ExpectedPatch));
        }
    };
    let g = numerator(&form, sf)?;
    let (iu, iv) = patch.domain();
    let z = zero_set(&g, &iu, &iv).map_err(at(sf))?;
    out = out
        .result(Quantity::Developable, Exact::Bool(g.is_zero()))
        .result(Quantity::GaussianNumerator, Exact::Poly(exact_poly(&g)))
        .result(Quantity::Corners, corners(&g, &iu, &iv)?);
    for (k, v) in zero_results(&z) {
        out = out.result(k, v);
    }
    Ok(out)
}
