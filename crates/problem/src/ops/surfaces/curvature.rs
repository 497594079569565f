//! `gaussian_curvature`: the notes' developability criterion (chapter 6, eq. (8)) for any
//! patch, with the numerator of the Gaussian curvature as an exact polynomial.
//!
//! With n = c_u × c_v (not normalized), L = c_uu · n, M = c_uv · n, N = c_vv · n, the Gaussian
//! curvature is `K = (L N - M²) / |n|⁴`, and (8) says the surface is developable where
//! `L N - M² = 0`. For a polynomial patch `G = L N - M²` is a polynomial in u and v. For a
//! rational patch c = p/w, with the homogeneous P = (p, w) = w (c, 1), column operations
//! give `det(P, P_u, P_v, P_xy) = -w⁴ (c_xy · n)` for xy = uu, uv, vv, so
//! `G = det(P, P_u, P_v, P_uu) det(P, P_u, P_v, P_vv) - det(P, P_u, P_v, P_uv)²
//!    = w⁸ (L N - M²)`,
//! again a polynomial, with the sign and the zeros of K wherever w ≠ 0:
//! `K = G / (w⁸ |n|⁴)`. A B-spline or NURBS surface is tested piece by piece.
//!
//! Where G vanishes on the domain is decided exactly by its Bernstein coefficients on the
//! domain, halved a bounded number of times ([`crate::ops::zeros`]): G has no zero and one strict
//! sign (K > 0, elliptic; K < 0, hyperbolic), or G = 0 at an exact point, or G changes sign
//! between two exact points, or the answer says it is not decided. A zero of G is a zero of K
//! or a point where n = 0 (a degenerate point, where K is not defined: the pole of a sphere
//! octant).

use crate::any::AnySurface as Patch;
use crate::message::curve::Curve as Say;
use crate::ops::out::{at, req, Out, Run};
use crate::ops::pieces::{PieceForm, SplinePieces};
use crate::ops::zeros::{combine, zero_set, ZeroSet};
use crate::problem::GaussianCurvature;
use crate::steps::Formula;
use crate::value::{exact_poly, Exact, ExactScalar};
use crate::ProblemError;
use cagd_poly::{Poly, Var, VecPoly};

/// The 3 × 3 determinant of the rows `a`, `b`, `c`.
fn det3<S: ExactScalar>(a: &[Poly<S>; 3], b: &[Poly<S>; 3], c: &[Poly<S>; 3]) -> Poly<S> {
    let ([a0, a1, a2], [b0, b1, b2], [c0, c1, c2]) = (a, b, c);
    let minor = |x: &Poly<S>, y: &Poly<S>, z: &Poly<S>, t: &Poly<S>| &(x * y) - &(z * t);
    let t0 = a0 * &minor(b1, c2, b2, c1);
    let t1 = a1 * &minor(b0, c2, b2, c0);
    let t2 = a2 * &minor(b0, c1, b1, c0);
    &(&t0 - &t1) + &t2
}

/// G = D_uu D_vv - D_uv² of the homogeneous form `h` = (x, y, z, w) (see the module).
fn numerator_homogeneous<S: ExactScalar>(
    h: &VecPoly<S>,
    path: &str,
) -> Result<Poly<S>, ProblemError> {
    if h.dim() != 4 {
        return Err(ProblemError::at(
            path,
            Say::CurvatureNeedsR3 {
                found: h.dim().saturating_sub(1),
            },
        ));
    }
    let hu = h.partial(Var::U);
    let hv = h.partial(Var::V);
    let comp = |m: &VecPoly<S>, r: usize| m.component(r).cloned().unwrap_or_else(Poly::zero);
    let row = |r: usize| [comp(h, r), comp(&hu, r), comp(&hv, r)];
    let rows = [row(0), row(1), row(2), row(3)];
    // the cofactors of the fourth column: D = Σ_r cof_r P_xy[r], cof_r = (-1)^(r+3) M_r
    let cofactor = |skip: usize| {
        let mut rest = rows
            .iter()
            .enumerate()
            .filter(|(k, _)| *k != skip)
            .map(|(_, r)| r);
        let d = match (rest.next(), rest.next(), rest.next()) {
            (Some(a), Some(b), Some(c)) => det3(a, b, c),
            _ => Poly::zero(),
        };
        if (skip + 3) % 2 == 0 {
            d
        } else {
            -d
        }
    };
    let cof = [cofactor(0), cofactor(1), cofactor(2), cofactor(3)];
    let d = |second: &VecPoly<S>| {
        cof.iter()
            .enumerate()
            .fold(Poly::zero(), |acc, (r, c)| &acc + &(c * &comp(second, r)))
    };
    let duu = d(&hu.partial(Var::U));
    let duv = d(&hu.partial(Var::V));
    let dvv = d(&hv.partial(Var::V));
    Ok(&(&duu * &dvv) - &(&duv * &duv))
}

/// G = L N - M² of a polynomial patch `c`, with n = c_u × c_v.
pub(crate) fn numerator_polynomial<S: ExactScalar>(
    c: &VecPoly<S>,
    path: &str,
) -> Result<Poly<S>, ProblemError> {
    let (cu, cv) = (c.partial(Var::U), c.partial(Var::V));
    let n = cu.cross(&cv).map_err(at(path))?;
    let l = cu.partial(Var::U).dot(&n).map_err(at(path))?;
    let m = cu.partial(Var::V).dot(&n).map_err(at(path))?;
    let nn = cv.partial(Var::V).dot(&n).map_err(at(path))?;
    Ok(&(&l * &nn) - &(&m * &m))
}

pub(crate) fn numerator<S: ExactScalar>(
    f: &PieceForm<S>,
    path: &str,
) -> Result<Poly<S>, ProblemError> {
    match f {
        PieceForm::Polynomial(c) => numerator_polynomial(c, path),
        PieceForm::Rational(r) => numerator_homogeneous(&r.to_homogeneous(), path),
    }
}

/// G at the corners of [a, b] x [c, d], as `G_00` (G(a, c)), `G_10`, `G_01`, `G_11`.
fn corners<S: ExactScalar>(
    g: &Poly<S>,
    (a, b): &(S, S),
    (c, d): &(S, S),
) -> Result<Exact, ProblemError> {
    let mut out = Vec::new();
    for (name, u, v) in [("00", a, c), ("10", b, c), ("01", a, d), ("11", b, d)] {
        let x = g
            .eval(&[(Var::U, u.clone()), (Var::V, v.clone())])
            .map_err(at(""))?;
        out.push((format!("G_{name}"), Exact::Number(crate::value::exact(&x))));
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
fn zero_results<S: ExactScalar>(z: &ZeroSet<S>) -> Vec<(String, Exact)> {
    let words = ("zeros".to_string(), Exact::Sentence(z.verdict().into()));
    match z {
        ZeroSet::Everywhere => vec![("sign".into(), Exact::Int(0)), words],
        ZeroSet::Sign { sign, .. } => {
            let s = if *sign == std::cmp::Ordering::Less {
                -1
            } else {
                1
            };
            vec![("sign".into(), Exact::Int(s)), words]
        }
        ZeroSet::Zero(u, v) => vec![
            ("sign".into(), Exact::Int(0)),
            ("zero".into(), point_exact(&(u.clone(), v.clone()))),
            words,
        ],
        ZeroSet::SignChange(p, q) => vec![
            ("sign".into(), Exact::Int(0)),
            (
                "sign_change".into(),
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
                    "u".into(),
                    Exact::Point(cagd_linalg::Point::new(vec![
                        crate::value::exact(&iu.0),
                        crate::value::exact(&iu.1),
                    ])),
                ),
                (
                    "v".into(),
                    Exact::Point(cagd_linalg::Point::new(vec![
                        crate::value::exact(&iv.0),
                        crate::value::exact(&iv.1),
                    ])),
                ),
                ("numerator".into(), Exact::Poly(exact_poly(&g))),
                ("corners".into(), corners(&g, &iu, &iv)?),
            ]));
            let z = zero_set(&g, &iu, &iv).map_err(at(sf))?;
            // the piece's sign and points (its verdict in words is the whole's)
            if let Some(Exact::Object(fields)) = list.last_mut() {
                fields.extend(zero_results(&z).into_iter().filter(|(k, _)| k != "zeros"));
            }
            zeros.push((iu, iv, z));
        }
        out = out
            .result("developable", Exact::Bool(developable))
            .result("pieces", Exact::List(list));
        for (k, v) in zero_results(&combine(&zeros)) {
            out = out.result(&k, v);
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
        .result("developable", Exact::Bool(g.is_zero()))
        .result("numerator", Exact::Poly(exact_poly(&g)))
        .result("corners", corners(&g, &iu, &iv)?);
    for (k, v) in zero_results(&z) {
        out = out.result(&k, v);
    }
    Ok(out)
}
