//! The sign of the Gaussian curvature, exactly.
//!
//! With `n = c_u x c_v`, the coefficients of the second fundamental form are
//! `L = c_uu·n / |n|`, `M = c_uv·n / |n|`, `N = c_vv·n / |n|`, and `EG - F^2 = |n|^2 > 0`, so
//!
//! `K = (LN - M^2) / (EG - F^2)` has the sign of `(c_uu·n)(c_vv·n) - (c_uv·n)^2`,
//!
//! a polynomial for a polynomial patch ([`gaussian_numerator`]). For a rational patch with
//! homogeneous form `P = (w c, w)` the same quantities are, up to the common positive factor
//! `w^4`, the 4 x 4 determinants `det(P_uu, P_u, P_v, P)`, `det(P_uv, ...)`, `det(P_vv, ...)`,
//! so the sign is computed from them ([`gaussian_signs`]); for w = 1 they are the triple
//! products above.

use crate::geometry::SurfacePieces;
use crate::geometry::{affine_derivative, parameter};
use crate::{AnySurface, Drawn, RenderError, Sampling, Unplotted};
use cagd_linalg::Point;
use cagd_poly::{Poly, Var, VecPoly};
use cagd_scalar::Scalar;
use std::fmt;

/// The sign of the Gaussian curvature at a point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CurvatureSign {
    /// K > 0: elliptic point (the surface bends the same way in every direction).
    Positive,
    /// K = 0: parabolic or flat point.
    Zero,
    /// K < 0: hyperbolic (saddle) point.
    Negative,
    /// `c_u x c_v = 0`: no tangent plane (a degenerate point such as the sphere's pole).
    Undefined,
}

impl fmt::Display for CurvatureSign {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            CurvatureSign::Positive => "+",
            CurvatureSign::Zero => "0",
            CurvatureSign::Negative => "-",
            CurvatureSign::Undefined => "?",
        })
    }
}

/// The numerator of the Gaussian curvature of a polynomial surface `c(u, v)` in R^3:
///
/// `(c_uu·n)(c_vv·n) - (c_uv·n)^2`, `n = c_u x c_v`,
///
/// which has the sign of K wherever `n ≠ 0`. For a ruled surface (degree 1 in v) `c_vv = 0`,
/// so it is `-(c_uv·n)^2 ≤ 0`:
///
/// ```
/// use cagd_render::gaussian_numerator;
/// use cagd_poly::parse_vec_poly;
/// use cagd_scalar::BigRational;
/// let saddle = parse_vec_poly::<BigRational>("(u, v, u v)").unwrap();
/// assert_eq!(gaussian_numerator(&saddle).unwrap().to_text(), "-1");
/// let paraboloid = parse_vec_poly::<BigRational>("(u, v, u^2 + v^2)").unwrap();
/// assert_eq!(gaussian_numerator(&paraboloid).unwrap().to_text(), "4");
/// ```
pub fn gaussian_numerator<S: Scalar>(c: &VecPoly<S>) -> Result<Poly<S>, RenderError> {
    if c.dim() != 3 {
        return Err(RenderError::Dimension {
            what: Drawn::CurvatureSurface,
            dim: c.dim(),
        });
    }
    let (cu, cv) = (c.partial(Var::U), c.partial(Var::V));
    let n = cu.cross(&cv)?;
    let l = cu.partial(Var::U).dot(&n)?;
    let m = cu.partial(Var::V).dot(&n)?;
    let nn = cv.partial(Var::V).dot(&n)?;
    Ok(&l * &nn - &m * &m)
}

/// `det(a, b, c, d)` of four vectors of R^4 (as columns), by 2 x 2 minors.
fn det4<S: Scalar>(a: &Point<S>, b: &Point<S>, c: &Point<S>, d: &Point<S>) -> S {
    let x = |p: &Point<S>, i: usize| p.coords().get(i).cloned().unwrap_or_else(S::zero);
    // minors of the first two columns (rows i < j) times the complementary minors
    let minor = |p: &Point<S>, q: &Point<S>, i: usize, j: usize| {
        x(p, i).mul_ref(&x(q, j)) - x(p, j).mul_ref(&x(q, i))
    };
    let pairs = [
        (0, 1, 2, 3, 1),
        (0, 2, 1, 3, -1),
        (0, 3, 1, 2, 1),
        (1, 2, 0, 3, 1),
        (1, 3, 0, 2, -1),
        (2, 3, 0, 1, 1),
    ];
    let mut sum = S::zero();
    for (i, j, k, l, sign) in pairs {
        let t = minor(a, b, i, j) * minor(c, d, k, l);
        if sign > 0 {
            sum += t;
        } else {
            sum -= t;
        }
    }
    sum
}

fn sign_of<S: Scalar>(x: &S) -> CurvatureSign {
    if *x > S::zero() {
        CurvatureSign::Positive
    } else if *x < S::zero() {
        CurvatureSign::Negative
    } else {
        CurvatureSign::Zero
    }
}

/// The sign of the Gaussian curvature at the centres of an `n x n` grid of cells of the
/// domain, `(u_i, v_j)` with `u_i = a + (b - a)(2i + 1)/(2n)` (i along u, the rows of the
/// result), computed exactly (see the module documentation). `n` is 1 to 64.
pub fn gaussian_signs<S: Scalar>(
    surface: &AnySurface<S>,
    n: usize,
) -> Result<Vec<Vec<CurvatureSign>>, RenderError> {
    crate::error::check_density(Sampling::CurvatureGrid, n, 1, 64)?;
    let exact = surface.exact(&Drawn::CurvatureSurface)?;
    let second: Vec<[VecPoly<S>; 3]> = exact
        .pieces
        .iter()
        .map(|p| {
            [
                p.hu.partial(Var::U),
                p.hu.partial(Var::V),
                p.hv.partial(Var::V),
            ]
        })
        .collect();
    let mut rows = Vec::with_capacity(n);
    for i in 0..n {
        let mut row = Vec::with_capacity(n);
        for j in 0..n {
            let u = parameter(&exact.domain.0, 2 * i + 1, 2 * n);
            let v = parameter(&exact.domain.1, 2 * j + 1, 2 * n);
            let (piece, [huu, huv, hvv]) = exact
                .pieces
                .iter()
                .zip(&second)
                .find(|(p, _)| p.u.0 <= u && u <= p.u.1 && p.v.0 <= v && v <= p.v.1)
                .ok_or_else(|| {
                    RenderError::Plot(Unplotted::NoPiece {
                        at: format!("(u, v) = ({}, {})", u.to_text(), v.to_text()),
                    })
                })?;
            let at = [(Var::U, u.clone()), (Var::V, v.clone())];
            let h = piece.h.eval(&at)?;
            let hu = piece.hu.eval(&at)?;
            let hv = piece.hv.eval(&at)?;
            let normal = affine_derivative(&h, &hu)
                .cross(&affine_derivative(&h, &hv))
                .map_err(|_| RenderError::Plot(Unplotted::NormalNeedsSpace))?;
            if normal.is_zero() {
                row.push(CurvatureSign::Undefined);
                continue;
            }
            let l = det4(&huu.eval(&at)?, &hu, &hv, &h);
            let m = det4(&huv.eval(&at)?, &hu, &hv, &h);
            let nn = det4(&hvv.eval(&at)?, &hu, &hv, &h);
            row.push(sign_of(&(l * &nn - m.mul_ref(&m))));
        }
        rows.push(row);
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational};

    fn p(c: &[i64]) -> Point<BigRational> {
        Point::from_ints(c)
    }

    #[test]
    fn det4_of_the_identity_and_a_swap() {
        let e = |i: usize| {
            let mut c = vec![0; 4];
            c[i] = 1;
            p(&c)
        };
        assert_eq!(det4(&e(0), &e(1), &e(2), &e(3)), q!(1));
        assert_eq!(det4(&e(1), &e(0), &e(2), &e(3)), q!(-1));
        let a = p(&[2, 1, 0, 3]);
        let b = p(&[1, 1, 1, 1]);
        let c = p(&[0, 5, 2, 1]);
        let d = p(&[4, 0, 1, 2]);
        // cofactor expansion along the first row gives 18
        assert_eq!(det4(&a, &b, &c, &d), q!(18));
        assert_eq!(det4(&a, &a, &c, &d), q!(0));
    }

    #[test]
    fn numerator_of_the_cylinder_is_zero() {
        let c = cagd_poly::parse_vec_poly::<BigRational>("(u, u^2, v)").unwrap();
        assert!(gaussian_numerator(&c).unwrap().is_zero());
    }
}
