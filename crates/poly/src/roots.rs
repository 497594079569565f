//! The exact roots of a polynomial in one variable, where they are numbers the engine has:
//! in the polynomial's own field, or in Q(√d) for a quadratic factor with rational
//! coefficients. Point inversion (The NURBS Book §6.1) asks for them: the parameters t with
//! c(t) = P are the common roots of the coordinates x_i(t) - P_i w(t).
//!
//! The method: the monic gcd of the polynomials, made square-free (g / gcd(g, g')); then each
//! factor of degree 1 gives its root, t = -c_0/c_1; a factor of degree 2 its two roots
//! (-b ± √(b² - 4ac))/(2a), in the field when the discriminant is a square there, else in
//! Q(√d) when it is rational; a factor of degree 3 or more with rational coefficients gives up
//! its rational roots (p/q with p | c_0 and q | c_n, the rational root theorem) one at a time,
//! and what is left past degree 2 has no root the engine can write: refused, saying so.

use crate::{Poly, Var};
use cagd_scalar::{BigInt, FieldOps, Quadratic, Rat, Scalar};
use cagd_words::{said, Lang, Message, Phrase};
use num_traits::{Signed, ToPrimitive, Zero};

/// A root found exactly.
#[derive(Clone, Debug, PartialEq)]
pub enum ExactRoot<S> {
    /// A root in the polynomial's own field.
    Field(S),
    /// A root a + b√d of a quadratic factor with rational coefficients whose discriminant is
    /// not a square: in Q(√d).
    Surd(Quadratic),
}

impl<S: Scalar> ExactRoot<S> {
    /// The root as a number of Q(√d), when it is one (always for the rational and quadratic
    /// fields; not for a root in letters).
    pub fn to_number(&self) -> Option<Quadratic> {
        match self {
            ExactRoot::Field(x) => x.to_number(),
            ExactRoot::Surd(q) => Some(q.clone()),
        }
    }
}

/// Why the roots of a polynomial are not given.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum RootsError {
    /// The polynomial is zero: every value is a root.
    Zero,
    /// A factor of degree 3 or more without a rational root (or whose coefficients are not
    /// rational): its roots need more than one square root, or cube roots.
    NotExact {
        /// The factor's degree.
        degree: usize,
        /// The factor, as text.
        factor: String,
    },
    /// A quadratic factor whose discriminant is not a square of the field nor a rational.
    Discriminant {
        /// The discriminant, as text.
        value: String,
    },
    /// A factor with rational coefficients too large to search for rational roots (the
    /// divisors of its first and last coefficients beyond 10^12).
    TooLarge {
        /// The factor, as text.
        factor: String,
    },
}

impl Message for RootsError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            RootsError::Zero => said(
                lang,
                "the polynomial is zero: every parameter is a root",
                "el polinomio es cero: todo parámetro es una raíz",
                [],
            ),
            RootsError::NotExact { degree, factor } => said(
                lang,
                "the factor ‹› of degree ‹› has no rational root: its roots need cube roots or more than one square root, which are not numbers of the field (Q or one Q(√d))",
                "el factor ‹› de grado ‹› no tiene raíces racionales: sus raíces necesitan raíces cúbicas o más de una raíz cuadrada, que no son números del cuerpo (Q o un Q(√d))",
                [factor.into(), degree.into()],
            ),
            RootsError::Discriminant { value } => said(
                lang,
                "the discriminant ‹› of a quadratic factor is neither a square of the field nor a rational number: its roots are not in Q(√d)",
                "el discriminante ‹› de un factor cuadrático no es un cuadrado del cuerpo ni un número racional: sus raíces no están en Q(√d)",
                [value.into()],
            ),
            RootsError::TooLarge { factor } => said(
                lang,
                "the factor ‹› has coefficients too large to search for its rational roots (the divisors of its first and last coefficients)",
                "el factor ‹› tiene coeficientes demasiado grandes para buscar sus raíces racionales (los divisores de su primer y su último coeficiente)",
                [factor.into()],
            ),
        }
    }
}

cagd_words::display_english!(RootsError);

impl std::error::Error for RootsError {}

/// The dense coefficients c_0, ..., c_n of `p` in `var` (its other variables ignored: `p` is
/// a polynomial in `var` alone).
fn dense<S: Scalar>(p: &Poly<S>, var: Var) -> Vec<S> {
    let n = p.degree_in(var) as usize;
    let mut c = vec![S::zero(); n + 1];
    for (m, x) in p.terms() {
        if let Some(slot) = c.get_mut(m.exp(var) as usize) {
            *slot = slot.add_ref(x);
        }
    }
    trim(c)
}

/// Without its zero leading coefficients.
fn trim<S: Scalar>(mut c: Vec<S>) -> Vec<S> {
    while c.last().is_some_and(|x| x.is_zero()) {
        c.pop();
    }
    c
}

/// The quotient and remainder of a / b (b nonzero).
fn div_rem<S: Scalar>(a: &[S], b: &[S]) -> Option<(Vec<S>, Vec<S>)> {
    let lead = b.last()?;
    let mut r = a.to_vec();
    if a.len() < b.len() {
        return Some((Vec::new(), r));
    }
    let mut q = vec![S::zero(); a.len() - b.len() + 1];
    for k in (0..q.len()).rev() {
        cagd_scalar::cancel::checkpoint();
        let top = r.get(k + b.len() - 1)?.clone();
        let f = top.checked_div(lead)?;
        for (j, bj) in b.iter().enumerate() {
            let slot = r.get_mut(k + j)?;
            *slot = slot.sub_ref(&f.mul_ref(bj));
        }
        *q.get_mut(k)? = f;
    }
    r.truncate(b.len() - 1);
    Some((q, trim(r)))
}

/// The monic gcd of a and b.
fn gcd<S: Scalar>(a: &[S], b: &[S]) -> Option<Vec<S>> {
    let (mut a, mut b) = (trim(a.to_vec()), trim(b.to_vec()));
    while !b.is_empty() {
        let (_, r) = div_rem(&a, &b)?;
        a = b;
        b = r;
    }
    monic(a)
}

/// The polynomial divided by its leading coefficient.
fn monic<S: Scalar>(a: Vec<S>) -> Option<Vec<S>> {
    let lead = a.last()?.clone();
    a.iter().map(|x| x.checked_div(&lead)).collect()
}

/// The derivative's coefficients.
fn derivative<S: Scalar>(a: &[S]) -> Vec<S> {
    a.iter()
        .enumerate()
        .skip(1)
        .map(|(k, x)| x.mul_ref(&S::from_i64(k as i64)))
        .collect()
}

/// The polynomial c_0 + c_1 t + ... as text in `var`.
fn text<S: Scalar>(c: &[S], var: Var) -> String {
    Poly::from_terms(
        c.iter()
            .enumerate()
            .map(|(k, x)| (crate::Monomial::from_powers(&[(var, k as u32)]), x.clone())),
    )
    .to_text()
}

/// The common roots of some polynomials found exactly, and the factor of their gcd whose
/// roots are not numbers the engine has (with why), if one is left.
#[derive(Clone, Debug, PartialEq)]
pub struct Roots<S: Scalar> {
    /// The monic gcd g of the polynomials, whose roots these are.
    pub gcd: Poly<S>,
    /// Each root found, once.
    pub found: Vec<ExactRoot<S>>,
    /// A factor without rational roots whose roots are not found, and why: the caller may
    /// show it has none where it looks (its sign on an interval).
    pub rest: Option<(Poly<S>, RootsError)>,
}

/// The common real roots of `polys` (in `var` alone), each once, exactly; [`RootsError::Zero`]
/// when every polynomial is zero. Each root is a root of every polynomial (of their gcd),
/// found as the module says; a factor whose roots are not in the field is returned as
/// [`Roots::rest`].
pub fn common_roots<S: Scalar>(polys: &[Poly<S>], var: Var) -> Result<Roots<S>, RootsError> {
    let mut g: Vec<S> = Vec::new();
    for p in polys {
        let c = dense(p, var);
        g = if g.is_empty() {
            c
        } else if c.is_empty() {
            g
        } else {
            gcd(&g, &c).unwrap_or_default()
        };
    }
    if g.is_empty() {
        return Err(RootsError::Zero);
    }
    let g = monic(g).unwrap_or_default();
    Ok(Roots {
        gcd: poly(&g, var),
        ..roots(&g, var)
    })
}

/// The polynomial of coefficients `c` in `var`.
fn poly<S: Scalar>(c: &[S], var: Var) -> Poly<S> {
    Poly::from_terms(
        c.iter()
            .enumerate()
            .map(|(k, x)| (crate::Monomial::from_powers(&[(var, k as u32)]), x.clone())),
    )
}

/// The roots of the polynomial with coefficients `c` (not zero), each once.
fn roots<S: Scalar>(c: &[S], var: Var) -> Roots<S> {
    // square-free: c / gcd(c, c')
    let d = derivative(c);
    let mut f = match gcd(c, &d) {
        Some(g) if g.len() > 1 => div_rem(c, &g).map(|(q, _)| q).unwrap_or_else(|| c.to_vec()),
        _ => c.to_vec(),
    };
    let mut found = Vec::new();
    loop {
        let left = |f: &[S], why| Roots {
            gcd: Poly::zero(),
            found: Vec::new(),
            rest: Some((poly(f, var), why)),
        };
        match f.len() {
            0 | 1 => {
                return Roots {
                    gcd: Poly::zero(),
                    found,
                    rest: None,
                }
            }
            2 => {
                if let (Some(c0), Some(c1)) = (f.first(), f.get(1)) {
                    if let Some(t) = (-c0.clone()).checked_div(c1) {
                        found.push(ExactRoot::Field(t));
                    }
                }
                return Roots {
                    gcd: Poly::zero(),
                    found,
                    rest: None,
                };
            }
            3 => {
                return match quadratic(&f) {
                    Ok(two) => {
                        found.extend(two);
                        Roots {
                            gcd: Poly::zero(),
                            found,
                            rest: None,
                        }
                    }
                    Err(why) => Roots {
                        found,
                        ..left(&f, why)
                    },
                }
            }
            _ => match rational_root(&f, var) {
                Ok(Some(r)) => {
                    let linear = [-r.clone(), S::one()];
                    f = div_rem(&f, &linear).map(|(q, _)| q).unwrap_or_default();
                    found.push(ExactRoot::Field(r));
                }
                Ok(None) => {
                    let why = RootsError::NotExact {
                        degree: f.len() - 1,
                        factor: text(&f, var),
                    };
                    return Roots {
                        found,
                        ..left(&f, why)
                    };
                }
                Err(why) => {
                    return Roots {
                        found,
                        ..left(&f, why)
                    }
                }
            },
        }
    }
}

/// The two roots of c_0 + c_1 t + c_2 t² (a square-free factor: two different roots).
fn quadratic<S: Scalar>(f: &[S]) -> Result<Vec<ExactRoot<S>>, RootsError> {
    let (Some(a), Some(b), Some(c)) = (f.get(2), f.get(1), f.first()) else {
        return Ok(Vec::new());
    };
    let disc = b.mul_ref(b) - a.mul_ref(c) * S::from_i64(4);
    if disc.compare(&S::zero()) == Some(std::cmp::Ordering::Less) {
        return Ok(Vec::new()); // no real root
    }
    let two_a = a.add_ref(a);
    if let Some(root) = disc.sqrt_exact() {
        return Ok([-b.clone() - &root, -b.clone() + &root]
            .into_iter()
            .filter_map(|x| x.checked_div(&two_a).map(ExactRoot::Field))
            .collect());
    }
    let surd = |x: &S| x.to_number();
    let (Some(d), Some(b), Some(two_a)) = (surd(&disc), surd(b), surd(&two_a)) else {
        return Err(RootsError::Discriminant {
            value: disc.to_text(),
        });
    };
    let root = d
        .to_rat()
        .and_then(|q: Rat| Quadratic::sqrt_of_rat(&q).ok())
        .ok_or_else(|| RootsError::Discriminant {
            value: disc.to_text(),
        })?;
    let minus_b = -b;
    Ok([minus_b.clone() - &root, minus_b + &root]
        .into_iter()
        .filter_map(|x| x.checked_div(&two_a).map(ExactRoot::Surd))
        .collect())
}

/// The largest absolute value searched for divisors.
const MAX_SEARCHED: i128 = 1_000_000_000_000;

/// A rational root of c (rational coefficients), or `None`; an error when the coefficients
/// are not rational or too large to search.
fn rational_root<S: Scalar>(f: &[S], var: Var) -> Result<Option<S>, RootsError> {
    let not_exact = || RootsError::NotExact {
        degree: f.len().saturating_sub(1),
        factor: text(f, var),
    };
    let too_large = || RootsError::TooLarge {
        factor: text(f, var),
    };
    if f.first().is_some_and(|c| c.is_zero()) {
        return Ok(Some(S::zero()));
    }
    // integer coefficients: times the lcm of the denominators
    let rationals = f
        .iter()
        .map(|x| x.as_rational().map(|q| q.into_owned()))
        .collect::<Option<Vec<_>>>()
        .ok_or_else(not_exact)?;
    let mut lcm = BigInt::from(1);
    for q in &rationals {
        let d = q.denom();
        let g = num_integer::Integer::gcd(&lcm, d);
        lcm = &lcm / g * d;
    }
    let ints: Vec<BigInt> = rationals
        .iter()
        .map(|q| q.numer() * (&lcm / q.denom()))
        .collect();
    let (Some(c0), Some(cn)) = (ints.first(), ints.last()) else {
        return Ok(None);
    };
    let small = |x: &BigInt| {
        x.abs()
            .to_i128()
            .filter(|v| *v <= MAX_SEARCHED && !v.is_zero())
    };
    let (Some(p0), Some(pn)) = (small(c0), small(cn)) else {
        return Err(too_large());
    };
    for q in divisors(pn) {
        for p in divisors(p0) {
            for sign in [1, -1] {
                let (Ok(num), Ok(den)) = (i64::try_from(sign * p), i64::try_from(q)) else {
                    continue;
                };
                let r = S::from_ratio(num, den);
                if eval(f, &r).is_zero() {
                    return Ok(Some(r));
                }
            }
        }
    }
    Ok(None)
}

/// The positive divisors of n > 0 (n ≤ 10^12: trial division up to 10^6).
fn divisors(n: i128) -> Vec<i128> {
    let mut small = Vec::new();
    let mut large = Vec::new();
    let mut k: i128 = 1;
    while k * k <= n {
        if k % 4096 == 0 {
            cagd_scalar::cancel::checkpoint();
        }
        if n % k == 0 {
            small.push(k);
            if k * k != n {
                large.push(n / k);
            }
        }
        k += 1;
    }
    small.extend(large.into_iter().rev());
    small
}

/// c(x) by Horner's rule.
fn eval<S: Scalar>(c: &[S], x: &S) -> S {
    c.iter()
        .rev()
        .fold(S::zero(), |acc, a| acc.mul_ref(x).add_ref(a))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse_poly;
    use cagd_scalar::{BigRational, Print};
    use strum::IntoEnumIterator;

    fn roots_of(ps: &[&str]) -> Result<Vec<String>, RootsError> {
        let ps: Vec<Poly<BigRational>> = ps.iter().map(|p| parse_poly(p).unwrap()).collect();
        common_roots(&ps, Var::T).and_then(|rs| {
            if let Some((_, why)) = rs.rest {
                return Err(why);
            }
            Ok(rs
                .found
                .iter()
                .map(|r| match r {
                    ExactRoot::Field(x) => x.to_text(),
                    ExactRoot::Surd(q) => q.to_text(),
                })
                .collect())
        })
    }

    #[test]
    fn common_roots_are_the_roots_of_the_gcd() {
        // (t - 1/2)(t - 3) and (t - 1/2)(t + 1): 1/2
        assert_eq!(
            roots_of(&["t^2 - 7/2 t + 3/2", "t^2 + 1/2 t - 1/2"]).unwrap(),
            ["1/2"]
        );
        // no common root
        assert_eq!(roots_of(&["t - 1", "t - 2"]).unwrap(), Vec::<String>::new());
        // a double root counts once
        assert_eq!(roots_of(&["t^2 - 2 t + 1"]).unwrap(), ["1"]);
        // a quadratic with rational roots, and one in Q(√2)
        assert_eq!(roots_of(&["t^2 - 1/4"]).unwrap(), ["-1/2", "1/2"]);
        assert_eq!(roots_of(&["t^2 - 2"]).unwrap(), ["-√2", "√2"]);
        // a cubic with a rational root and a quadratic factor left: (t - 2)(t² - 3)
        assert_eq!(
            roots_of(&["t^3 - 2 t^2 - 3 t + 6"]).unwrap(),
            ["2", "-√3", "√3"]
        );
        // complex roots only: none
        assert_eq!(roots_of(&["t^2 + 1"]).unwrap(), Vec::<String>::new());
        // the zero polynomial
        assert_eq!(roots_of(&["0"]), Err(RootsError::Zero));
        // t³ - 2: no rational root, refused
        assert!(matches!(
            roots_of(&["t^3 - 2"]),
            Err(RootsError::NotExact { degree: 3, .. })
        ));
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in RootsError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
