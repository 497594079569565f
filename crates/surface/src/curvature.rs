//! The numerator of the Gaussian curvature as an exact polynomial: the notes' developability
//! criterion (chapter 6, eq. (8)) for polynomial and rational surfaces.
//!
//! With n = c_u × c_v (not normalized), L = c_uu · n, M = c_uv · n, N = c_vv · n, the Gaussian
//! curvature is `K = (L N - M²) / |n|⁴`, and (8) says the surface is developable where
//! `L N - M² = 0`. For a polynomial surface `G = L N - M²` is a polynomial in u and v
//! ([`gaussian_numerator`]). For a rational surface c = p/w, with the homogeneous
//! P = (p, w) = w (c, 1), column operations give `det(P, P_u, P_v, P_xy) = -w⁴ (c_xy · n)` for
//! xy = uu, uv, vv, so
//! `G = det(P, P_u, P_v, P_uu) det(P, P_u, P_v, P_vv) - det(P, P_u, P_v, P_uv)²
//!    = w⁸ (L N - M²)`,
//! again a polynomial, with the sign and the zeros of K wherever w ≠ 0:
//! `K = G / (w⁸ |n|⁴)` ([`gaussian_numerator_rational`]). A zero of G is a zero of K or a point
//! where n = 0 (a degenerate point, where K is not defined: the pole of a sphere octant).

use cagd_poly::{Poly, PolyError, RationalMap, Var, VecPoly};
use cagd_scalar::Scalar;
use cagd_words::{said, Lang, Message, Phrase};

/// Why the numerator of the Gaussian curvature is not computed.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum CurvatureError {
    /// A rational surface not in R³.
    CurvatureNeedsR3 {
        /// The dimension of the points.
        found: usize,
    },
    /// The products of the polynomial surface refused (a surface not in R³: no cross product).
    Poly(PolyError),
}

impl Default for CurvatureError {
    fn default() -> Self {
        CurvatureError::CurvatureNeedsR3 { found: 2 }
    }
}

impl Message for CurvatureError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            CurvatureError::CurvatureNeedsR3 { found } => said(
                lang,
                "the Gaussian curvature needs a surface in R³, found points of dimension ‹›",
                "la curvatura de Gauss necesita una superficie en R³, se encontraron puntos de dimensión ‹›",
                [found.into()],
            ),
            CurvatureError::Poly(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
        }
    }
}

cagd_words::display_english!(CurvatureError);

impl From<PolyError> for CurvatureError {
    fn from(e: PolyError) -> Self {
        CurvatureError::Poly(e)
    }
}

/// `G = L N - M²` of a polynomial surface `c(u, v)` in R³, with n = c_u × c_v,
/// L = c_uu · n, M = c_uv · n, N = c_vv · n (see [the module](self)): G ≡ 0 is the notes'
/// developability criterion, chapter 6, eq. (8).
///
/// ```
/// use cagd_poly::parse_vec_poly;
/// use cagd_scalar::BigRational;
/// use cagd_surface::gaussian_numerator;
/// let saddle = parse_vec_poly::<BigRational>("(u, v, u v)").unwrap();
/// assert_eq!(gaussian_numerator(&saddle).unwrap().to_text(), "-1");
/// ```
pub fn gaussian_numerator<S: Scalar>(c: &VecPoly<S>) -> Result<Poly<S>, CurvatureError> {
    let (cu, cv) = (c.partial(Var::U), c.partial(Var::V));
    let n = cu.cross(&cv)?;
    let l = cu.partial(Var::U).dot(&n)?;
    let m = cu.partial(Var::V).dot(&n)?;
    let nn = cv.partial(Var::V).dot(&n)?;
    Ok(&(&l * &nn) - &(&m * &m))
}

/// The 3 × 3 determinant of the rows `a`, `b`, `c`.
fn det3<S: Scalar>(a: &[Poly<S>; 3], b: &[Poly<S>; 3], c: &[Poly<S>; 3]) -> Poly<S> {
    let ([a0, a1, a2], [b0, b1, b2], [c0, c1, c2]) = (a, b, c);
    let minor = |x: &Poly<S>, y: &Poly<S>, z: &Poly<S>, t: &Poly<S>| &(x * y) - &(z * t);
    let t0 = a0 * &minor(b1, c2, b2, c1);
    let t1 = a1 * &minor(b0, c2, b2, c0);
    let t2 = a2 * &minor(b0, c1, b1, c0);
    &(&t0 - &t1) + &t2
}

/// `G = D_uu D_vv - D_uv²`, `D_xy = det(P, P_u, P_v, P_xy)`, of a rational surface c = p/w in
/// R³ through its homogeneous form P = (p, w) (see [the module](self)): G = w⁸ (L N - M²), with
/// the sign and the zeros of K wherever w ≠ 0.
///
/// ```
/// use cagd_poly::{parse_poly, parse_vec_poly, RationalMap};
/// use cagd_scalar::BigRational;
/// use cagd_surface::gaussian_numerator_rational;
/// // the saddle (u, v, u v) over w = 1: G = w⁸ (L N - M²) = -1
/// let p = parse_vec_poly::<BigRational>("(u, v, u v)").unwrap();
/// let r = RationalMap::new(p, parse_poly("1").unwrap()).unwrap();
/// assert_eq!(gaussian_numerator_rational(&r).unwrap().to_text(), "-1");
/// ```
pub fn gaussian_numerator_rational<S: Scalar>(
    r: &RationalMap<S>,
) -> Result<Poly<S>, CurvatureError> {
    let h = r.to_homogeneous();
    if h.dim() != 4 {
        return Err(CurvatureError::CurvatureNeedsR3 {
            found: h.dim().saturating_sub(1),
        });
    }
    let hu = h.partial(Var::U);
    let hv = h.partial(Var::V);
    let comp = |m: &VecPoly<S>, r: usize| m.component(r).cloned().unwrap_or_else(Poly::zero);
    let row = |r: usize| [comp(&h, r), comp(&hu, r), comp(&hv, r)];
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

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_poly::{parse_poly, parse_vec_poly};
    use cagd_scalar::BigRational;
    use strum::IntoEnumIterator;

    fn map(s: &str) -> VecPoly<BigRational> {
        parse_vec_poly(s).unwrap()
    }

    #[test]
    fn numerators_of_polynomial_surfaces() {
        // c_u = (1, 0, 2u), c_v = (0, 1, 2v), n = (-2u, -2v, 1), c_uu·n = 2, c_vv·n = 2, c_uv·n = 0
        let g = gaussian_numerator(&map("(u, v, u^2 + v^2)")).unwrap();
        assert_eq!(g, parse_poly("4").unwrap());
        // a cylinder over a parabola is developable (eq. (8))
        assert!(gaussian_numerator(&map("(u, v, u^2)")).unwrap().is_zero());
        assert!(matches!(
            gaussian_numerator(&map("(u, v)")),
            Err(CurvatureError::Poly(_))
        ));
    }

    #[test]
    fn numerators_of_rational_surfaces() {
        // (u, v, u² + v²) over w = 2: c = (u/2, v/2, (u² + v²)/2), c_u = (1/2, 0, u),
        // c_v = (0, 1/2, v), n = (-u/2, -v/2, 1/4), L = N = 1/4, M = 0: L N - M² = 1/16, and
        // G = w⁸ (L N - M²) = 256/16 = 16
        let r = RationalMap::new(map("(u, v, u^2 + v^2)"), parse_poly("2").unwrap()).unwrap();
        assert_eq!(
            gaussian_numerator_rational(&r).unwrap(),
            parse_poly("16").unwrap()
        );
        let plane = RationalMap::new(map("(u, v)"), parse_poly("1 + u").unwrap()).unwrap();
        assert_eq!(
            gaussian_numerator_rational(&plane),
            Err(CurvatureError::CurvatureNeedsR3 { found: 2 })
        );
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in CurvatureError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
