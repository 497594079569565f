//! Integrals that are exact: a polynomial map's definite integral `∫_a^b c(t) dt` (one point),
//! a polynomial integrated over one variable of several (`∫_a^b p(u, v) du`, a polynomial in
//! v), the area enclosed by a closed planar polynomial curve, `A = ½ ∮ (x y' - y x') dt`
//! (Green's theorem), and the area of a planar polynomial patch, `∬ |c_u × c_v| du dv`, where
//! `c_u × c_v = J(u, v) n` for the plane's normal n and J keeps one sign: `|∬ J| |n|`.
//! Everything else is refused with the reason ([`AreaError`]), never rounded.

use crate::{to_bernstein_2d, zero_set, Poly, PolyError, Var, VecPoly, ZeroSet};
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use cagd_words::{said, Lang, Message, Phrase};
use std::cmp::Ordering;

impl<S: Scalar> Poly<S> {
    /// `∫_a^b p d var`, the variable integrated out: each term `c var^e m` becomes
    /// `c (b^{e+1} - a^{e+1}) / (e + 1) m`, a polynomial in the other variables.
    ///
    /// ```
    /// use cagd_poly::{parse_poly, Var};
    /// use cagd_scalar::{q, BigRational};
    /// let p = parse_poly::<BigRational>("u v + 1").unwrap();
    /// assert_eq!(p.integrate_out(Var::U, &q!(0), &q!(2)).to_text(), "2 v + 2");
    /// ```
    pub fn integrate_out(&self, var: Var, a: &S, b: &S) -> Self {
        let mut out = Poly::zero();
        for (m, c) in self.terms.iter() {
            let e = m.exp(var) + 1;
            let factor = (b.powi(e) - a.powi(e)) / S::from_i64(i64::from(e));
            out.add_term(m.with_exp(var, 0), &c.mul_ref(&factor));
        }
        out
    }
}

impl<S: Scalar> VecPoly<S> {
    /// `∫_a^b c(var) d var`, componentwise: a point (the map in `var` alone).
    ///
    /// ```
    /// use cagd_poly::{parse_vec_poly, Var};
    /// use cagd_scalar::{q, BigRational};
    /// let c = parse_vec_poly::<BigRational>("(t, t^2)").unwrap();
    /// assert_eq!(c.definite_integral(Var::T, &q!(0), &q!(1)).to_text(), "(1/2, 1/3)");
    /// ```
    pub fn definite_integral(&self, var: Var, a: &S, b: &S) -> Point<S> {
        Point::new(
            self.components()
                .iter()
                .map(|p| p.definite_integral(var, a, b))
                .collect(),
        )
    }
}

/// The area a closed planar curve encloses, signed.
#[derive(Clone, Debug, PartialEq)]
pub struct EnclosedArea<S: Scalar> {
    /// `x y' - y x'` of each piece (in the piece's variable).
    pub integrands: Vec<Poly<S>>,
    /// `A = ½ Σ ∫ (x y' - y x') dt`: positive when the curve runs counter-clockwise (in the
    /// x, y plane seen from +z), negative clockwise.
    pub signed: S,
}

impl<S: Scalar> EnclosedArea<S> {
    /// The area |A|.
    pub fn area(&self) -> S {
        if self.signed.compare(&S::zero()) == Some(Ordering::Less) {
            -self.signed.clone()
        } else {
            self.signed.clone()
        }
    }

    /// The orientation the sign of A tells: `Greater` counter-clockwise, `Less` clockwise,
    /// `Equal` when A = 0 (a curve that runs back over itself, or a figure eight whose loops
    /// cancel), `None` when the sign is in letters.
    pub fn orientation(&self) -> Option<Ordering> {
        self.signed.compare(&S::zero())
    }
}

/// The plane coordinates (x, y) of a planar map: the two components of a map into R², or of
/// one into R³ whose z is identically zero.
fn plane<S: Scalar>(c: &VecPoly<S>) -> Result<(&Poly<S>, &Poly<S>), AreaError> {
    match c.components() {
        [x, y] => Ok((x, y)),
        [x, y, z] if z.is_zero() => Ok((x, y)),
        [_, _, _] => Err(AreaError::CurveNotInPlane),
        other => Err(AreaError::Dimension { found: other.len() }),
    }
}

/// `A = ½ ∮ (x y' - y x') dt` of a closed planar curve given by its polynomial pieces, each
/// `(c, var, (a, b))` on its interval, in order (one piece for a Bézier curve or an
/// expression; the B-spline pieces left to right). The curve must be closed (`c(a)` of the
/// first piece equal to `c(b)` of the last) and lie in the plane (2D, or z ≡ 0).
///
/// ```
/// use cagd_poly::{enclosed_area, parse_vec_poly, Var};
/// use cagd_scalar::{q, BigRational};
/// // the unit square's boundary would need four pieces; a parabola closed by its chord:
/// let arch = parse_vec_poly::<BigRational>("(t, 1 - t^2)").unwrap();
/// let chord = parse_vec_poly::<BigRational>("(-t, 0)").unwrap();
/// let a = enclosed_area(&[
///     (arch, Var::T, (q!(-1), q!(1))),
///     (chord, Var::T, (q!(-1), q!(1))),
/// ])
/// .unwrap();
/// assert_eq!(a.signed, q!(-4/3)); // clockwise: from (-1, 0) over the top to (1, 0), back
/// ```
pub fn enclosed_area<S: Scalar>(
    pieces: &[(VecPoly<S>, Var, (S, S))],
) -> Result<EnclosedArea<S>, AreaError> {
    let (Some((first, fv, (a, _))), Some((last, lv, (_, b)))) = (pieces.first(), pieces.last())
    else {
        return Err(AreaError::Dimension { found: 0 });
    };
    for (c, _, _) in pieces {
        plane(c)?;
    }
    let start = first.eval(&[(*fv, a.clone())]).map_err(AreaError::Poly)?;
    let end = last.eval(&[(*lv, b.clone())]).map_err(AreaError::Poly)?;
    if start != end {
        return Err(AreaError::NotClosed {
            start: start.to_text(),
            end: end.to_text(),
        });
    }
    let mut integrands = Vec::with_capacity(pieces.len());
    let mut total = S::zero();
    for (c, var, (a, b)) in pieces {
        let (x, y) = plane(c)?;
        let g = &(x * &y.partial(*var)) - &(y * &x.partial(*var));
        total += g.definite_integral(*var, a, b);
        integrands.push(g);
    }
    Ok(EnclosedArea {
        integrands,
        signed: total / S::from_i64(2),
    })
}

/// The area of a planar polynomial patch.
#[derive(Clone, Debug, PartialEq)]
pub struct PatchArea<S: Scalar> {
    /// n, the plane's normal with `c_u × c_v = J(u, v) n` ((0, 0, 1) for a patch in the x, y
    /// plane).
    pub normal: Point<S>,
    /// J(u, v).
    pub jacobian: Poly<S>,
    /// `∬ J du dv` over the domain.
    pub integral: S,
    /// |n|.
    pub normal_length: S,
    /// The area `|∬ J| |n|`.
    pub area: S,
}

/// `∬ |c_u × c_v| du dv` of a planar polynomial patch c(u, v) on `[a, b] × [c, d]`: with
/// `c_u × c_v = J(u, v) n` for a constant normal n of the plane, the area is `|∬ J| |n|` when
/// J keeps one sign on the domain (all its Bernstein coefficients on the rectangle of one
/// sign); a patch in the x, y plane (2D, or z ≡ 0) has n = (0, 0, 1) and J the Jacobian
/// `x_u y_v - x_v y_u`. Refused, with the reason: a curved patch (the area is the integral
/// of a square root), J changing sign (the patch folds over itself), |n| not in the field.
///
/// ```
/// use cagd_poly::{planar_patch_area, parse_vec_poly};
/// use cagd_scalar::{q, BigRational};
/// let square = parse_vec_poly::<BigRational>("(2 u, 2 v)").unwrap();
/// let unit = (q!(0), q!(1));
/// assert_eq!(planar_patch_area(&square, &unit, &unit).unwrap().area, q!(4));
/// ```
pub fn planar_patch_area<S: Scalar>(
    c: &VecPoly<S>,
    du: &(S, S),
    dv: &(S, S),
) -> Result<PatchArea<S>, AreaError> {
    let (cu, cv) = (c.partial(Var::U), c.partial(Var::V));
    let (normal, jacobian) = match c.dim() {
        2 => {
            let (xu, yu, xv, yv) = match (cu.components(), cv.components()) {
                ([xu, yu], [xv, yv]) => (xu, yu, xv, yv),
                _ => return Err(AreaError::Dimension { found: 2 }),
            };
            (
                Point::new(vec![S::zero(), S::zero(), S::one()]),
                &(xu * yv) - &(xv * yu),
            )
        }
        3 => normal_of_plane(&cu.cross(&cv).map_err(AreaError::Poly)?)?,
        found => return Err(AreaError::Dimension { found }),
    };
    if jacobian.is_zero() {
        return Ok(PatchArea {
            normal,
            integral: S::zero(),
            normal_length: S::zero(),
            area: S::zero(),
            jacobian,
        });
    }
    keeps_sign(&jacobian, du, dv)?;
    let integral = jacobian
        .integrate_out(Var::U, &du.0, &du.1)
        .definite_integral(Var::V, &dv.0, &dv.1);
    let square: S = normal
        .coords()
        .iter()
        .fold(S::zero(), |acc, x| acc + x.clone() * x.clone());
    let normal_length = square
        .sqrt_exact()
        .ok_or_else(|| AreaError::NormalNotInField {
            square: square.to_text(),
        })?;
    let size = if integral.compare(&S::zero()) == Some(Ordering::Less) {
        -integral.clone()
    } else {
        integral.clone()
    };
    let area = size * normal_length.clone();
    Ok(PatchArea {
        normal,
        jacobian,
        integral,
        normal_length,
        area,
    })
}

/// n and J with `N = J n`, N = c_u × c_v: n the coefficients of one monomial of N (the first
/// with a coefficient not zero, read from the first component that is not zero), J = N_k / n_k;
/// a curved patch when `N ≠ J n`.
fn normal_of_plane<S: Scalar>(big_n: &VecPoly<S>) -> Result<(Point<S>, Poly<S>), AreaError> {
    let Some((k, nk)) = big_n
        .components()
        .iter()
        .enumerate()
        .find(|(_, p)| !p.is_zero())
    else {
        // c_u × c_v ≡ 0: the patch is a curve or a point, of area 0
        return Ok((Point::new(vec![S::zero(); 3]), Poly::zero()));
    };
    let Some((m, _)) = nk.terms().next() else {
        return Err(AreaError::CurvedPatch);
    };
    let n: Vec<S> = big_n.components().iter().map(|p| p.coeff(m)).collect();
    let lead = n.get(k).cloned().ok_or(AreaError::CurvedPatch)?;
    let j = nk.scale(&S::one().checked_div(&lead).ok_or(AreaError::CurvedPatch)?);
    let same = big_n
        .components()
        .iter()
        .zip(&n)
        .all(|(p, x)| (p - &j.scale(x)).is_zero());
    if !same {
        return Err(AreaError::CurvedPatch);
    }
    Ok((Point::new(n), j))
}

/// J keeps one sign on the rectangle: its Bernstein coefficients there are all ≥ 0 or all ≤ 0
/// (the convex hull property); otherwise the zero set says where it changes sign, or that it
/// was not decided.
fn keeps_sign<S: Scalar>(j: &Poly<S>, du: &(S, S), dv: &(S, S)) -> Result<(), AreaError> {
    let on_unit = j
        .affine_substitute(Var::U, &(du.1.clone() - du.0.clone()), &du.0)
        .affine_substitute(Var::V, &(dv.1.clone() - dv.0.clone()), &dv.0);
    let m = usize::try_from(on_unit.degree_in(Var::U)).unwrap_or(0);
    let n = usize::try_from(on_unit.degree_in(Var::V)).unwrap_or(0);
    let b = to_bernstein_2d(&on_unit, Var::U, Var::V, m, n).map_err(AreaError::Poly)?;
    let signs: Option<Vec<Ordering>> = b.iter().flatten().map(|x| x.compare(&S::zero())).collect();
    let Some(signs) = signs else {
        return Err(AreaError::SignInLetters {
            jacobian: j.to_text(),
        });
    };
    let up = signs.contains(&Ordering::Greater);
    let down = signs.contains(&Ordering::Less);
    if !(up && down) {
        return Ok(());
    }
    match zero_set(j, du, dv).map_err(AreaError::Poly)? {
        ZeroSet::SignChange((u0, v0), (u1, v1)) => Err(AreaError::Folds {
            jacobian: j.to_text(),
            positive: format!("({}, {})", u0.to_text(), v0.to_text()),
            negative: format!("({}, {})", u1.to_text(), v1.to_text()),
        }),
        ZeroSet::Sign { .. } | ZeroSet::Everywhere => Ok(()),
        _ => Err(AreaError::SignNotDecided {
            jacobian: j.to_text(),
        }),
    }
}

/// Why an enclosed area or a patch's area is not given.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum AreaError {
    /// A curve or patch that is not planar in the plane of x and y: its points have another
    /// number of coordinates than 2 or 3.
    Dimension {
        /// The number of coordinates found.
        found: usize,
    },
    /// A curve in space whose z is not identically zero.
    CurveNotInPlane,
    /// A curve whose end is not its start.
    NotClosed {
        /// c(a).
        start: String,
        /// c(b).
        end: String,
    },
    /// A patch whose normal c_u × c_v is not a multiple of one constant vector.
    CurvedPatch,
    /// J changes sign on the domain: the patch folds over itself.
    Folds {
        /// J.
        jacobian: String,
        /// A point where J > 0.
        positive: String,
        /// A point where J < 0.
        negative: String,
    },
    /// The sign of J not decided by its Bernstein coefficients.
    SignNotDecided {
        /// J.
        jacobian: String,
    },
    /// The sign of J is in letters.
    SignInLetters {
        /// J.
        jacobian: String,
    },
    /// |n| is not a number of the field.
    NormalNotInField {
        /// n·n.
        square: String,
    },
    /// An error of the polynomials.
    Poly(PolyError),
}

impl Message for AreaError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            AreaError::Dimension { found } => said(
                lang,
                "an area is computed for points of 2 or 3 coordinates; these have ‹›",
                "el área se calcula para puntos de 2 o 3 coordenadas; estos tienen ‹›",
                [found.into()],
            ),
            AreaError::CurveNotInPlane => said(
                lang,
                "the curve is not planar in the plane z = 0 (its z is not identically zero): the enclosed area A = ½ ∮ (x y' - y x') dt is that of a curve in the x, y plane",
                "la curva no está en el plano z = 0 (su z no es idénticamente nula): el área encerrada A = ½ ∮ (x y' - y x') dt es la de una curva del plano x, y",
                [],
            ),
            AreaError::NotClosed { start, end } => said(
                lang,
                "the curve is not closed: c(a) = ‹› and c(b) = ‹› differ, so it encloses no area",
                "la curva no es cerrada: c(a) = ‹› y c(b) = ‹› son distintos, así que no encierra ningún área",
                [start.into(), end.into()],
            ),
            AreaError::CurvedPatch => said(
                lang,
                "the patch is not planar (c_u × c_v is not a multiple of one constant normal): the area of a curved patch is the integral of a square root, ∬ |c_u × c_v| du dv, in general no number of Q or of one Q(√d), and it is not given, neither rounded",
                "la superficie no es plana (c_u × c_v no es múltiplo de una normal constante): el área de una superficie curva es la integral de una raíz cuadrada, ∬ |c_u × c_v| du dv, en general no es un número de Q ni de un Q(√d), y no se da, ni redondeada",
                [],
            ),
            AreaError::Folds {
                jacobian,
                positive,
                negative,
            } => said(
                lang,
                "c_u × c_v = J n with J = ‹› changing sign on the domain (J > 0 at ‹›, J < 0 at ‹›): the patch folds over itself, and ∬ |J| needs the curve where J vanishes, not computed here",
                "c_u × c_v = J n con J = ‹›, que cambia de signo en el dominio (J > 0 en ‹›, J < 0 en ‹›): la superficie se pliega sobre sí misma, y ∬ |J| necesita la curva donde J se anula, que aquí no se calcula",
                [jacobian.into(), positive.into(), negative.into()],
            ),
            AreaError::SignNotDecided { jacobian } => said(
                lang,
                "c_u × c_v = J n with J = ‹›, whose sign on the domain its Bernstein coefficients do not decide: ∬ |J| is not given",
                "c_u × c_v = J n con J = ‹›, cuyo signo en el dominio no deciden sus coeficientes de Bernstein: no se da ∬ |J|",
                [jacobian.into()],
            ),
            AreaError::SignInLetters { jacobian } => said(
                lang,
                "c_u × c_v = J n with J = ‹›, whose sign is in letters: ∬ |J| needs it (give the letters values)",
                "c_u × c_v = J n con J = ‹›, cuyo signo está en letras: ∬ |J| lo necesita (dé valores a las letras)",
                [jacobian.into()],
            ),
            AreaError::NormalNotInField { square } => said(
                lang,
                "the plane's normal n has |n|² = ‹›, whose square root is not a number of the problem's field: the area |∬ J| |n| is not given (write the patch with a number of that root to have it)",
                "la normal del plano n tiene |n|² = ‹›, cuya raíz cuadrada no es un número del cuerpo del problema: no se da el área |∬ J| |n| (escriba la superficie con un número de esa raíz para obtenerla)",
                [square.into()],
            ),
            AreaError::Poly(e) => e.phrase(lang),
        }
    }
}

cagd_words::display_english!(AreaError);

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse_vec_poly;
    use cagd_scalar::{q, BigRational};
    use proptest::prelude::*;
    use strum::IntoEnumIterator;

    type Q = BigRational;

    fn map(s: &str) -> VecPoly<Q> {
        parse_vec_poly(s).unwrap()
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in AreaError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }

    #[test]
    fn unit_circle_like_square_counter_clockwise() {
        // the unit square's boundary, counter-clockwise, four segments on [0, 1]
        let sides = ["(t, 0)", "(1, t)", "(1 - t, 1)", "(0, 1 - t)"];
        let pieces: Vec<_> = sides
            .iter()
            .map(|s| (map(s), Var::T, (q!(0), q!(1))))
            .collect();
        let a = enclosed_area(&pieces).unwrap();
        assert_eq!(a.signed, q!(1));
        assert_eq!(a.orientation(), Some(Ordering::Greater));
    }

    #[test]
    fn not_closed_and_not_planar_refused() {
        let open = [(map("(t, t^2)"), Var::T, (q!(0), q!(1)))];
        assert!(matches!(
            enclosed_area(&open),
            Err(AreaError::NotClosed { .. })
        ));
        let space = [(map("(t, 0, t - t^2)"), Var::T, (q!(0), q!(1)))];
        assert_eq!(enclosed_area(&space), Err(AreaError::CurveNotInPlane));
        let flat = [(map("(t - t^2, t^2 - t^3, 0)"), Var::T, (q!(0), q!(1)))];
        assert!(enclosed_area(&flat).is_ok());
    }

    #[test]
    fn tilted_plane_and_curved_patch() {
        let unit = (q!(0), q!(1));
        // the plane z = 0 turned: (u, v, 0) scaled: normal (0, 0, 1)
        let flat3 = map("(u, v, 0)");
        assert_eq!(planar_patch_area(&flat3, &unit, &unit).unwrap().area, q!(1));
        // x + y... the plane z = x: c = (u, v, u), c_u × c_v = (-1, 0, 1), |n| = √2 not in Q
        let tilted = map("(u, v, u)");
        assert!(matches!(
            planar_patch_area(&tilted, &unit, &unit),
            Err(AreaError::NormalNotInField { .. })
        ));
        // the plane 3z = 4x... c = (3u, v, 4u): c_u × c_v = (-4, 0, 3): |n| = 5
        let plane = map("(3 u, v, 4 u)");
        assert_eq!(planar_patch_area(&plane, &unit, &unit).unwrap().area, q!(5));
        let curved = map("(u, v, u v)");
        assert_eq!(
            planar_patch_area(&curved, &unit, &unit),
            Err(AreaError::CurvedPatch)
        );
        // folding: x = u^2 - u/2... J = 2u - 1/2 changes sign on [0, 1]
        let folds = map("(u^2 - 1/2 u, v)");
        assert!(matches!(
            planar_patch_area(&folds, &unit, &unit),
            Err(AreaError::Folds { .. })
        ));
    }

    proptest! {
        /// A square patch (bilinear on [0, s]²) has area s².
        #[test]
        fn square_patch(n in 1i64..20, d in 1i64..20) {
            let s = Q::new(n.into(), d.into());
            let unit = (q!(0), q!(1));
            let corners = parse_vec_poly::<Q>(&format!("({n}/{d} u, {n}/{d} v)")).unwrap();
            let a = planar_patch_area(&corners, &unit, &unit).unwrap();
            prop_assert_eq!(a.area, s.clone() * s);
        }

        /// Reversing a closed curve changes the sign of the enclosed area, not its size.
        #[test]
        fn reversal_changes_sign(xs in proptest::collection::vec((-9i64..9, -9i64..9), 3..6)) {
            // the closed polygon through the points, each side a segment on [0, 1]
            let pts: Vec<(i64, i64)> = xs;
            let side = |(x0, y0): (i64, i64), (x1, y1): (i64, i64)| {
                map(&format!("({x0} + ({x1} - {x0}) t, {y0} + ({y1} - {y0}) t)"))
            };
            let k = pts.len();
            let forward: Vec<_> = (0..k)
                .map(|i| (side(pts[i], pts[(i + 1) % k]), Var::T, (q!(0), q!(1))))
                .collect();
            let backward: Vec<_> = (0..k)
                .map(|i| (side(pts[(k - i) % k], pts[(2 * k - i - 1) % k]), Var::T, (q!(0), q!(1))))
                .collect();
            let f = enclosed_area(&forward).unwrap();
            let b = enclosed_area(&backward).unwrap();
            prop_assert_eq!(f.signed.clone(), -b.signed.clone());
            // the shoelace formula
            let shoelace: i64 = (0..k)
                .map(|i| pts[i].0 * pts[(i + 1) % k].1 - pts[(i + 1) % k].0 * pts[i].1)
                .sum();
            prop_assert_eq!(f.signed, Q::new(shoelace.into(), 2.into()));
        }

        /// ∫_a^b = ∫_a^m + ∫_m^b.
        #[test]
        fn integral_splits(c in proptest::collection::vec(-9i64..9, 4), m in 1i64..9) {
            let p = map(&format!("({} + {} t + {} t^2, {} t^3)", c[0], c[1], c[2], c[3]));
            let m = Q::new(m.into(), 9.into());
            let whole = p.definite_integral(Var::T, &q!(0), &q!(1));
            let left = p.definite_integral(Var::T, &q!(0), &m);
            let right = p.definite_integral(Var::T, &m, &q!(1));
            prop_assert_eq!(whole, left + right);
        }
    }
}
