//! The arc length `∫_a^b |c'(t)| dt` of a polynomial or rational curve piece, exact where it
//! exists, or the reason it is not a number of the field.
//!
//! Polynomial c: the speed is `√(c'·c')`. When `c'·c' = σ(t)²` for a polynomial σ (a
//! Pythagorean-hodograph curve, Farouki; every line), the length is `∫_a^b |σ| dt`, exact:
//! `|∫_a^b σ dt|` when σ keeps its sign on [a, b], which the Bernstein coefficients of σ on
//! [a, b] decide (cagd-poly's [`sign_on`]). A line has a constant `c'·c' = q`: its length
//! `(b - a) √q` is exact in Q(√q). Otherwise the integral is in general no number of Q or of
//! one Q(√d) (a parabola's has a logarithm, most cubics' are elliptic integrals)
//! ([`polynomial_length`]).
//!
//! Rational c = p/w: the velocity is c' = (p' w - p w')/w², so `c'·c' = N/w⁴` with the
//! polynomial `N = |p' w - p w'|²`. When N = σ² for a polynomial σ (a rational
//! Pythagorean-hodograph curve: every conic arc of a circle, every line) the speed is `|σ|/w²`,
//! and the length `∫_a^b |σ|/w² dt` is exact when σ/w² has a rational antiderivative g/w:
//! `g' w - g w' = σ`, solved exactly for the coefficients of g with g(a) = 0 (the solutions
//! differ by multiples of w). Then, σ keeping its sign on [a, b], the length is
//! `|g(b)/w(b)|`. Otherwise the integral has a logarithm or an arctangent in its partial
//! fractions: a circle arc's length is R θ, with θ in radians, which is no number of Q or of
//! one Q(√d) ([`rational_length`]).

use crate::reduce::rows_of_columns;
use cagd_linalg::{LinalgError, Matrix, NormalEquations};
use cagd_poly::{sign_on, Poly, PolyError, RationalMap, Var, VecPoly, SIGN_HALVINGS};
use cagd_scalar::Scalar;
use cagd_words::{said, Lang, Message, Phrase};
use std::cmp::Ordering;

/// The length of one piece: `speed_squared` (c'·c' of a polynomial piece, the numerator N of
/// c'·c' = N/w⁴ of a rational one), σ with σ² = `speed_squared` when there is one, and the
/// length or why it is not given.
#[derive(Debug, Clone, PartialEq)]
pub struct PieceLength<S: Scalar> {
    /// c'·c' (polynomial), or N with c'·c' = N/w⁴ (rational).
    pub speed_squared: Poly<S>,
    /// σ with σ² = `speed_squared`, when found.
    pub sigma: Option<Poly<S>>,
    /// The exact length, or why it is not a number of the field.
    pub length: Result<S, NotExact<S>>,
}

/// Why a length is not given as a number.
#[derive(Debug, Clone, PartialEq)]
pub enum NotExact<S: Scalar> {
    /// |c'| = |σ| with σ changing sign (or not decided) on [from, to].
    SpeedChangesSign {
        /// σ.
        sigma: Poly<S>,
        /// The interval's start.
        from: S,
        /// The interval's end.
        to: S,
    },
    /// A line's length `span √square`, exact but the field has not √square.
    OutsideField {
        /// b - a.
        span: S,
        /// The constant c'·c'.
        square: S,
    },
    /// c'·c' not the square of a polynomial.
    SpeedNotSquare {
        /// c'·c'.
        speed: Poly<S>,
    },
    /// N not the square of a polynomial (rational piece).
    RationalSpeedNotSquare {
        /// N.
        numerator: Poly<S>,
    },
    /// |c'| = |σ|/w² with σ changing sign (or not decided) on [from, to].
    RationalSpeedChangesSign {
        /// σ.
        sigma: Poly<S>,
        /// The interval's start.
        from: S,
        /// The interval's end.
        to: S,
    },
    /// σ/w² without a rational antiderivative.
    NoRationalAntiderivative {
        /// σ.
        sigma: Poly<S>,
        /// w.
        weight: Poly<S>,
    },
}

/// What goes wrong while computing a length.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum LengthError {
    /// The weight function vanishing at an end of the interval.
    #[default]
    WeightVanishesAtEnd,
    /// A product or a value of the closed forms refused.
    Poly(PolyError),
    /// The antiderivative's system refused.
    Linalg(LinalgError),
}

impl Message for LengthError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            LengthError::WeightVanishesAtEnd => said(
                lang,
                "the weight function vanishes at the end of the interval",
                "la función peso se anula en el extremo del intervalo",
                [],
            ),
            LengthError::Poly(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            LengthError::Linalg(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
        }
    }
}

cagd_words::display_english!(LengthError);

/// Why a length is not given as a number, in words: a [`NotExact`] with its polynomials and
/// numbers written out, the sentence an answer gives instead of the length.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum LengthNotGiven {
    /// A polynomial speed σ that changes sign (or is not decided) on an interval.
    SpeedChangesSign {
        /// σ.
        sigma: String,
        /// The halvings tried ([`SIGN_HALVINGS`]).
        halvings: u32,
        /// The interval's start.
        from: String,
        /// The interval's end.
        to: String,
    },
    /// The length of a line, exact but outside the number field.
    OutsideField {
        /// The length, with its root.
        value: String,
    },
    /// c'·c' not the square of a polynomial.
    SpeedNotSquare {
        /// c'·c'.
        speed: String,
    },
    /// The numerator N of c'·c' = N/w⁴ not the square of a polynomial.
    RationalSpeedNotSquare {
        /// N.
        numerator: String,
    },
    /// The speed σ/w² of a rational curve that changes sign (or is not decided).
    RationalSpeedChangesSign {
        /// σ.
        sigma: String,
        /// The halvings tried ([`SIGN_HALVINGS`]).
        halvings: u32,
        /// The interval's start.
        from: String,
        /// The interval's end.
        to: String,
    },
    /// σ/w² without a rational antiderivative.
    NoRationalAntiderivative {
        /// σ.
        sigma: String,
        /// w.
        weight: String,
    },
}

impl Default for LengthNotGiven {
    fn default() -> Self {
        LengthNotGiven::OutsideField {
            value: "√(2)".into(),
        }
    }
}

impl<S: Scalar> From<NotExact<S>> for LengthNotGiven {
    fn from(why: NotExact<S>) -> Self {
        match why {
            NotExact::SpeedChangesSign { sigma, from, to } => LengthNotGiven::SpeedChangesSign {
                sigma: sigma.to_text(),
                halvings: SIGN_HALVINGS,
                from: from.to_text(),
                to: to.to_text(),
            },
            NotExact::OutsideField { span, square } => {
                let root = format!("√({})", square.to_text());
                let value = if span == S::one() {
                    root
                } else {
                    format!("({}) {root}", span.to_text())
                };
                LengthNotGiven::OutsideField { value }
            }
            NotExact::SpeedNotSquare { speed } => LengthNotGiven::SpeedNotSquare {
                speed: speed.to_text(),
            },
            NotExact::RationalSpeedNotSquare { numerator } => {
                LengthNotGiven::RationalSpeedNotSquare {
                    numerator: numerator.to_text(),
                }
            }
            NotExact::RationalSpeedChangesSign { sigma, from, to } => {
                LengthNotGiven::RationalSpeedChangesSign {
                    sigma: sigma.to_text(),
                    halvings: SIGN_HALVINGS,
                    from: from.to_text(),
                    to: to.to_text(),
                }
            }
            NotExact::NoRationalAntiderivative { sigma, weight } => {
                LengthNotGiven::NoRationalAntiderivative {
                    sigma: sigma.to_text(),
                    weight: weight.to_text(),
                }
            }
        }
    }
}

impl Message for LengthNotGiven {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            LengthNotGiven::SpeedChangesSign {
                sigma,
                halvings,
                from,
                to,
            } => said(
                lang,
                "|c'(t)| = |σ(t)| with σ = ‹› changing sign (or not decided by its Bernstein coefficients within ‹› halvings) on [‹›, ‹›]: the length ∫|σ| needs its roots, not computed here",
                "|c'(t)| = |σ(t)| con σ = ‹›, que cambia de signo (o sus coeficientes de Bernstein no lo deciden en ‹› bisecciones) en [‹›, ‹›]: la longitud ∫|σ| necesita sus raíces, que aquí no se calculan",
                [sigma.into(), halvings.into(), from.into(), to.into()],
            ),
            LengthNotGiven::OutsideField { value } => said(
                lang,
                "the length is ‹›: exact, but outside the problem's number field (write a number with that root in the problem to have it as a number)",
                "la longitud es ‹›: exacta, pero fuera del cuerpo de números del problema (escriba en el problema un número con esa raíz para obtenerla como número)",
                [value.into()],
            ),
            LengthNotGiven::SpeedNotSquare { speed } => said(
                lang,
                "c'·c' = ‹› is not the square of a polynomial: the arc length ∫√(c'·c') dt is then in general no number of Q or of one Q(√d) (for a parabola it has a logarithm, for most cubics it is an elliptic integral), and it is not given, neither rounded",
                "c'·c' = ‹› no es el cuadrado de un polinomio: la longitud de arco ∫√(c'·c') dt no es entonces en general un número de Q ni de un Q(√d) (para una parábola tiene un logaritmo, para la mayoría de las cúbicas es una integral elíptica), y no se da, ni redondeada",
                [speed.into()],
            ),
            LengthNotGiven::RationalSpeedNotSquare { numerator } => said(
                lang,
                "c'·c' = N/w⁴ with N = ‹› not the square of a polynomial: the arc length ∫√N/w² dt is then in general no number of Q or of one Q(√d), and it is not given, neither rounded",
                "c'·c' = N/w⁴ con N = ‹›, que no es el cuadrado de un polinomio: la longitud de arco ∫√N/w² dt no es entonces en general un número de Q ni de un Q(√d), y no se da, ni redondeada",
                [numerator.into()],
            ),
            LengthNotGiven::RationalSpeedChangesSign {
                sigma,
                halvings,
                from,
                to,
            } => said(
                lang,
                "|c'(t)| = |σ(t)|/w(t)² with σ = ‹› changing sign (or not decided by its Bernstein coefficients within ‹› halvings) on [‹›, ‹›]: the length needs its roots, not computed here",
                "|c'(t)| = |σ(t)|/w(t)² con σ = ‹›, que cambia de signo (o sus coeficientes de Bernstein no lo deciden en ‹› bisecciones) en [‹›, ‹›]: la longitud necesita sus raíces, que aquí no se calculan",
                [sigma.into(), halvings.into(), from.into(), to.into()],
            ),
            LengthNotGiven::NoRationalAntiderivative { sigma, weight } => said(
                lang,
                "c'·c' = σ²/w⁴ with σ = ‹› and w = ‹›: the length ∫|σ|/w² dt has no rational antiderivative (its partial fractions leave a logarithm or an arctangent; a circle arc's length R θ is one, θ in radians, no number of Q or of one Q(√d)), so it is not given, neither rounded nor written with π",
                "c'·c' = σ²/w⁴ con σ = ‹› y w = ‹›: la longitud ∫|σ|/w² dt no tiene primitiva racional (sus fracciones simples dejan un logaritmo o un arco tangente; la longitud R θ de un arco de circunferencia es una, con θ en radianes, que no es un número de Q ni de un Q(√d)), así que no se da, ni redondeada ni escrita con π",
                [sigma.into(), weight.into()],
            ),
        }
    }
}

cagd_words::display_english!(LengthNotGiven);

impl From<PolyError> for LengthError {
    fn from(e: PolyError) -> Self {
        LengthError::Poly(e)
    }
}

/// The length of the polynomial piece `c(var)` on [a, b] (see [the module](self)).
///
/// ```
/// use cagd_bezier::polynomial_length;
/// use cagd_poly::{parse_vec_poly, Var};
/// use cagd_scalar::{q, BigRational};
/// // c' = (3, 4): c'·c' = 25 = 5², length 5 (b - a)
/// let line = parse_vec_poly::<BigRational>("(3 t, 4 t)").unwrap();
/// let l = polynomial_length(&line, Var::T, (&q!(0), &q!(2))).unwrap();
/// assert_eq!(l.length, Ok(q!(10)));
/// ```
pub fn polynomial_length<S: Scalar>(
    c: &VecPoly<S>,
    var: Var,
    (a, b): (&S, &S),
) -> Result<PieceLength<S>, LengthError> {
    let d = c.partial(var);
    let f = d.dot(&d)?;
    if f.is_zero() {
        return Ok(PieceLength {
            speed_squared: f,
            sigma: None,
            length: Ok(S::zero()),
        });
    }
    if let Some(sigma) = f.square_root(var) {
        let length = match sign_on(&sigma, var, a, b) {
            Some(Ordering::Less) => Ok(-sigma.definite_integral(var, a, b)),
            Some(_) => Ok(sigma.definite_integral(var, a, b)),
            None => Err(NotExact::SpeedChangesSign {
                sigma: sigma.clone(),
                from: a.clone(),
                to: b.clone(),
            }),
        };
        return Ok(PieceLength {
            speed_squared: f,
            sigma: Some(sigma),
            length,
        });
    }
    let length = if f.degree_in(var) == 0 {
        // a line: (b - a) √q
        let q = f.as_constant().unwrap_or_else(S::zero);
        let span = b.clone() - a.clone();
        match q.sqrt_exact() {
            Some(r) => Ok(span * r),
            None => Err(NotExact::OutsideField { span, square: q }),
        }
    } else {
        Err(NotExact::SpeedNotSquare { speed: f.clone() })
    };
    Ok(PieceLength {
        speed_squared: f,
        sigma: None,
        length,
    })
}

/// The length of a rational piece `r(var)` = p/w on [a, b] (see [the module](self)), with
/// N, the numerator of c'·c' = N/w⁴.
///
/// ```
/// use cagd_bezier::rational_length;
/// use cagd_poly::{parse_poly, parse_vec_poly, RationalMap, Var};
/// use cagd_scalar::{q, BigRational};
/// // the line (t, 0) over w = 1 + t: c = t/(1 + t), c' = 1/(1 + t)², from 0 to 1: 1/2
/// let r = RationalMap::new(
///     parse_vec_poly::<BigRational>("(t, 0)").unwrap(),
///     parse_poly("1 + t").unwrap(),
/// )
/// .unwrap();
/// assert_eq!(rational_length(&r, Var::T, (&q!(0), &q!(1))).unwrap().length, Ok(q!(1/2)));
/// ```
pub fn rational_length<S: Scalar>(
    r: &RationalMap<S>,
    var: Var,
    (a, b): (&S, &S),
) -> Result<PieceLength<S>, LengthError> {
    let (p, w) = (r.numerator(), r.denominator());
    // N = Σ_k (p_k' w - p_k w')²
    let dw = w.partial(var);
    let n = p.components().iter().fold(Poly::zero(), |acc, pk| {
        let qk = &(&pk.partial(var) * w) - &(pk * &dw);
        &acc + &(&qk * &qk)
    });
    let piece = |sigma: Option<Poly<S>>, length| PieceLength {
        speed_squared: n.clone(),
        sigma,
        length,
    };
    if n.is_zero() {
        return Ok(piece(None, Ok(S::zero())));
    }
    let Some(sigma) = n.square_root(var) else {
        let why = NotExact::RationalSpeedNotSquare {
            numerator: n.clone(),
        };
        return Ok(piece(None, Err(why)));
    };
    let Some(sign) = sign_on(&sigma, var, a, b) else {
        let why = NotExact::RationalSpeedChangesSign {
            sigma: sigma.clone(),
            from: a.clone(),
            to: b.clone(),
        };
        return Ok(piece(Some(sigma), Err(why)));
    };
    match antiderivative(&sigma, w, var, a)? {
        Some(g) => {
            let at = |x: &S| -> Result<S, LengthError> {
                let gx = g.eval(&[(var, x.clone())])?;
                let wx = w.eval(&[(var, x.clone())])?;
                gx.checked_div(&wx).ok_or(LengthError::WeightVanishesAtEnd)
            };
            let length = at(b)? - at(a)?;
            let length = if sign == Ordering::Less {
                -length
            } else {
                length
            };
            Ok(piece(Some(sigma), Ok(length)))
        }
        None => {
            let why = NotExact::NoRationalAntiderivative {
                sigma: sigma.clone(),
                weight: w.clone(),
            };
            Ok(piece(Some(sigma), Err(why)))
        }
    }
}

/// g with `g' w - g w' = σ` and g(a) = 0, when one exists: (g/w)' = σ/w².
fn antiderivative<S: Scalar>(
    sigma: &Poly<S>,
    w: &Poly<S>,
    var: Var,
    a: &S,
) -> Result<Option<Poly<S>>, LengthError> {
    let ds = usize::try_from(sigma.degree_in(var)).unwrap_or(usize::MAX);
    let dw = usize::try_from(w.degree_in(var)).unwrap_or(usize::MAX);
    let dg = (ds + 1).max(dw);
    let rows = dg + dw + 1;
    // column k: the image of t^k, (t^k)' w - t^k w'
    let mut columns = Vec::with_capacity(dg + 1);
    for k in 0..=dg {
        let tk = Poly::monomial(S::one(), &[(var, u32::try_from(k).unwrap_or(0))]);
        let image = &tk.partial(var) * w - &tk * &w.partial(var);
        let mut col: Vec<S> = (0..rows)
            .map(|i| image.coeff_of(&[(var, u32::try_from(i).unwrap_or(0))]))
            .collect();
        // the row g(a) = 0
        col.push(a.powi(u32::try_from(k).unwrap_or(0)));
        columns.push(col);
    }
    let matrix = rows_of_columns(&columns, rows + 1);
    let mut rhs: Vec<S> = (0..rows)
        .map(|i| sigma.coeff_of(&[(var, u32::try_from(i).unwrap_or(0))]))
        .collect();
    rhs.push(S::zero());
    let m = Matrix::from_rows(matrix).map_err(LengthError::Linalg)?;
    let Ok(g) = NormalEquations::new(&m).and_then(|ne| ne.solve(&rhs)) else {
        return Ok(None);
    };
    let g = g.iter().enumerate().fold(Poly::zero(), |acc, (k, c)| {
        &acc + &Poly::monomial(c.clone(), &[(var, u32::try_from(k).unwrap_or(0))])
    });
    // the least-squares solution solves the system only when it is consistent
    let check = &(&g.partial(var) * w) - &(&g * &w.partial(var));
    Ok((&check - sigma).is_zero().then_some(g))
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_poly::{parse_poly, parse_vec_poly};
    use cagd_scalar::{q, BigRational};
    use strum::IntoEnumIterator;

    fn map(s: &str) -> VecPoly<BigRational> {
        parse_vec_poly(s).unwrap()
    }

    fn poly(s: &str) -> Poly<BigRational> {
        parse_poly(s).unwrap()
    }

    #[test]
    fn polynomial_lengths() {
        // a Pythagorean-hodograph cubic: c' = (1 - t², 2t), |c'| = 1 + t², length on [0, 1]
        // ∫ (1 + t²) = 4/3
        let ph = polynomial_length(&map("(t - t^3/3, t^2)"), Var::T, (&q!(0), &q!(1))).unwrap();
        assert_eq!(ph.sigma, Some(poly("t^2 + 1")));
        assert_eq!(ph.length, Ok(q!(4 / 3)));
        // the line (t, t): c'·c' = 2, its length √2 is not rational
        let diagonal = polynomial_length(&map("(t, t)"), Var::T, (&q!(0), &q!(3))).unwrap();
        assert_eq!(
            diagonal.length,
            Err(NotExact::OutsideField {
                span: q!(3),
                square: q!(2)
            })
        );
        // a parabola: c'·c' = 1 + 4t², no square
        let parabola = polynomial_length(&map("(t, t^2)"), Var::T, (&q!(0), &q!(1))).unwrap();
        assert_eq!(
            parabola.length,
            Err(NotExact::SpeedNotSquare {
                speed: poly("4 t^2 + 1")
            })
        );
        // (t², 0) backwards through 0: σ = 2t changes sign on [-1, 1]
        let back = polynomial_length(&map("(t^2, 0)"), Var::T, (&q!(-1), &q!(1))).unwrap();
        assert_eq!(
            back.length,
            Err(NotExact::SpeedChangesSign {
                sigma: poly("2 t"),
                from: q!(-1),
                to: q!(1)
            })
        );
    }

    #[test]
    fn rational_lengths() {
        // the quarter circle (1 - t², 2t)/(1 + t²): N = 4 (1 + t²)², σ = 2 + 2t², no rational
        // antiderivative of 2/(1 + t²) (an arctangent)
        let circle = RationalMap::new(map("(1 - t^2, 2 t)"), poly("1 + t^2")).unwrap();
        let l = rational_length(&circle, Var::T, (&q!(0), &q!(1))).unwrap();
        assert_eq!(l.sigma, Some(poly("2 t^2 + 2")));
        assert_eq!(
            l.length,
            Err(NotExact::NoRationalAntiderivative {
                sigma: poly("2 t^2 + 2"),
                weight: poly("t^2 + 1")
            })
        );
        // (t, 0)/(1 + t) from 0 to 2: 2/3
        let line = RationalMap::new(map("(t, 0)"), poly("1 + t")).unwrap();
        let l = rational_length(&line, Var::T, (&q!(0), &q!(2))).unwrap();
        assert_eq!(l.length, Ok(q!(2 / 3)));
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in LengthError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        for m in LengthNotGiven::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
