//! The variables of polynomials and the monomials built from them.

use crate::PolyError;
use std::cmp::Ordering;
use std::fmt;

/// The number of variables a polynomial may use.
pub const NVARS: usize = 8;

/// A variable, in the fixed canonical order `u, v, w, t, s, x, y, z` used by the printers.
///
/// ```
/// use cagd_poly::Var;
/// assert_eq!(Var::parse("v").unwrap(), Var::V);
/// assert_eq!(Var::T.to_string(), "t");
/// assert!(Var::parse("q").unwrap_err().to_string().contains("unknown variable 'q'"));
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Var {
    /// `u`, the first parameter of curves and surfaces.
    U,
    /// `v`, the second parameter of surfaces.
    V,
    /// `w`, the third barycentric parameter of triangles.
    W,
    /// `t`
    T,
    /// `s`
    S,
    /// `x`
    X,
    /// `y`
    Y,
    /// `z`
    Z,
}

impl Var {
    /// All variables, in canonical order.
    pub const ALL: [Var; NVARS] = [
        Var::U,
        Var::V,
        Var::W,
        Var::T,
        Var::S,
        Var::X,
        Var::Y,
        Var::Z,
    ];

    /// The position in the canonical order (`u` is 0, `z` is 7).
    pub fn index(self) -> usize {
        self as usize
    }

    /// The variable at a position of the canonical order.
    pub fn from_index(i: usize) -> Option<Var> {
        Var::ALL.get(i).copied()
    }

    /// The one-letter name.
    pub fn name(self) -> &'static str {
        match self {
            Var::U => "u",
            Var::V => "v",
            Var::W => "w",
            Var::T => "t",
            Var::S => "s",
            Var::X => "x",
            Var::Y => "y",
            Var::Z => "z",
        }
    }

    /// The variable written with this letter.
    pub fn from_char(c: char) -> Option<Var> {
        match c {
            'u' => Some(Var::U),
            'v' => Some(Var::V),
            'w' => Some(Var::W),
            't' => Some(Var::T),
            's' => Some(Var::S),
            'x' => Some(Var::X),
            'y' => Some(Var::Y),
            'z' => Some(Var::Z),
            _ => None,
        }
    }

    /// The variable of this one-letter name, or [`PolyError::UnknownVariable`].
    pub fn parse(name: &str) -> Result<Var, PolyError> {
        let mut chars = name.chars();
        match (chars.next().and_then(Var::from_char), chars.next()) {
            (Some(v), None) => Ok(v),
            _ => Err(PolyError::UnknownVariable {
                name: name.to_string(),
                column: None,
            }),
        }
    }
}

impl fmt::Display for Var {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A monomial `u^a v^b w^c ...`: one exponent per variable.
///
/// Monomials are ordered **graded lexicographically**: first by total degree, then by the
/// exponent of `u`, then of `v`, and so on. The printers list the terms of a polynomial from the
/// largest monomial down: descending total degree, ties broken by the higher power of `u`, then
/// of `v`, ... (`u^3 v`, `u^3`, `u^2 v`, `u^2`, `u v`, `v^2`, `u`, `v`, `1`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub struct Monomial {
    exps: [u32; NVARS],
}

impl Monomial {
    /// The monomial `1`.
    #[inline]
    pub fn one() -> Self {
        Monomial::default()
    }

    /// The monomial `var`.
    pub fn var(var: Var) -> Self {
        Monomial::one().with_exp(var, 1)
    }

    /// The monomial `Π var^e` from `(var, e)` pairs; repeated variables multiply.
    pub fn from_powers(powers: &[(Var, u32)]) -> Self {
        let mut m = Monomial::one();
        for &(v, e) in powers {
            if let Some(x) = m.exps.get_mut(v.index()) {
                *x = x.saturating_add(e);
            }
        }
        m
    }

    /// The exponents in canonical order.
    #[inline]
    pub fn exponents(&self) -> &[u32; NVARS] {
        &self.exps
    }

    /// The variables of positive exponent, as bits by [`Var::index`] (bit `i` for
    /// `Var::ALL[i]`).
    #[inline]
    pub fn support(&self) -> u8 {
        self.exps
            .iter()
            .zip(0..)
            .fold(0, |bits, (&e, i)| if e > 0 { bits | 1 << i } else { bits })
    }

    /// The variables whose bits are set in `bits` ([`Monomial::support`]), in canonical
    /// order.
    pub fn vars_of(bits: u8) -> Vec<Var> {
        Var::ALL
            .iter()
            .copied()
            .filter(|v| bits & 1 << v.index() != 0)
            .collect()
    }

    /// The exponent of `var`.
    #[inline]
    pub fn exp(&self, var: Var) -> u32 {
        self.exps.get(var.index()).copied().unwrap_or(0)
    }

    /// The same monomial with the exponent of `var` replaced by `e`.
    #[inline]
    pub fn with_exp(mut self, var: Var, e: u32) -> Self {
        if let Some(x) = self.exps.get_mut(var.index()) {
            *x = e;
        }
        self
    }

    /// The total degree, the sum of the exponents.
    pub fn degree(&self) -> u32 {
        self.exps.iter().fold(0u32, |a, &e| a.saturating_add(e))
    }

    /// Whether this is the monomial `1`.
    #[inline]
    pub fn is_one(&self) -> bool {
        self.exps.iter().all(|&e| e == 0)
    }

    /// The product: exponents add (saturating at `u32::MAX`; the expression reader refuses
    /// degrees above [`crate::MAX_DEGREE`] long before).
    pub fn mul(&self, other: &Monomial) -> Monomial {
        let mut exps = self.exps;
        for (a, b) in exps.iter_mut().zip(other.exps) {
            *a = a.saturating_add(b);
        }
        Monomial { exps }
    }

    /// The quotient `self / other` when `other` divides `self` (every exponent at most
    /// `self`'s), else `None`.
    pub fn checked_div(&self, other: &Monomial) -> Option<Monomial> {
        let mut exps = self.exps;
        for (a, b) in exps.iter_mut().zip(other.exps) {
            *a = a.checked_sub(b)?;
        }
        Some(Monomial { exps })
    }

    /// The variables with a positive exponent, with their exponents, in canonical order.
    pub fn powers(&self) -> impl Iterator<Item = (Var, u32)> + '_ {
        Var::ALL
            .iter()
            .zip(self.exps)
            .filter(|(_, e)| *e > 0)
            .map(|(v, e)| (*v, e))
    }
}

/// Graded lexicographic order: by total degree, then by the exponents in the variables' order.
/// The degrees are compared as wide sums (no saturation, so the order is total for any
/// exponents, and cheaper than the saturating chain): building and printing a closed form
/// compares its monomials several times each.
impl Ord for Monomial {
    fn cmp(&self, other: &Self) -> Ordering {
        let wide = |m: &Self| m.exps.iter().map(|&e| u64::from(e)).sum::<u64>();
        wide(self)
            .cmp(&wide(other))
            .then_with(|| self.exps.cmp(&other.exps))
    }
}

impl PartialOrd for Monomial {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for v in Var::ALL {
            assert_eq!(Var::parse(v.name()).unwrap(), v);
            assert_eq!(Var::from_index(v.index()), Some(v));
        }
        assert!(Var::parse("uv").is_err());
        assert!(Var::parse("").is_err());
        assert!(Var::parse("U").is_err());
        assert_eq!(Var::from_index(8), None);
    }

    #[test]
    fn graded_lex_order() {
        let m = |p: &[(Var, u32)]| Monomial::from_powers(p);
        let mut ms = [
            m(&[]),
            m(&[(Var::V, 1)]),
            m(&[(Var::U, 1)]),
            m(&[(Var::V, 2)]),
            m(&[(Var::U, 2), (Var::V, 1)]),
            m(&[(Var::U, 3)]),
            m(&[(Var::U, 3), (Var::V, 1)]),
            m(&[(Var::U, 1), (Var::V, 1)]),
        ];
        ms.sort();
        ms.reverse();
        let degrees: Vec<u32> = ms.iter().map(|m| m.degree()).collect();
        assert_eq!(degrees, vec![4, 3, 3, 2, 2, 1, 1, 0]);
        assert_eq!(ms[1], m(&[(Var::U, 3)]));
        assert_eq!(ms[3], m(&[(Var::U, 1), (Var::V, 1)]));
        assert_eq!(ms[5], m(&[(Var::U, 1)]));
        assert_eq!(
            m(&[(Var::U, 2), (Var::U, 1)]).mul(&m(&[(Var::Z, 4)])),
            m(&[(Var::U, 3), (Var::Z, 4)])
        );
    }
}
