//! Derivatives, evaluation and composition of polynomials.

use crate::{Monomial, Poly, PolyError, Var};
use cagd_scalar::Scalar;
use std::collections::BTreeMap;

impl<S: Scalar> Poly<S> {
    /// The partial derivative `∂p/∂var`: each term `c x^e ...` becomes `c e x^(e-1) ...`.
    ///
    /// ```
    /// use cagd_poly::{parse_poly, Var};
    /// use cagd_scalar::BigRational;
    /// let p = parse_poly::<BigRational>("u^3 - u^3 v + u^2 v").unwrap();
    /// assert_eq!(p.partial(Var::U).to_text(), "-3 u^2 v + 3 u^2 + 2 u v");
    /// assert_eq!(p.partial(Var::V).to_text(), "-u^3 + u^2");
    /// ```
    pub fn partial(&self, var: Var) -> Self {
        Poly::from_terms(self.terms.iter().filter_map(|(m, c)| {
            let e = m.exp(var);
            (e > 0).then(|| {
                (
                    m.with_exp(var, e - 1),
                    c.mul_ref(&S::from_i64(i64::from(e))),
                )
            })
        }))
    }

    /// The exact quotient `self / d` when the polynomial `d` divides `self`, else `None` (also
    /// for `d = 0`). Division by leading terms in the graded lexicographic order: while the
    /// remainder r is not zero, its leading term must be a multiple `t · lt(d)` of d's, and
    /// `r ← r − t d`; a leading term that is not a multiple means d does not divide.
    ///
    /// ```
    /// use cagd_poly::parse_poly;
    /// use cagd_scalar::BigRational;
    /// let p = parse_poly::<BigRational>("u^2 v - v^3").unwrap();
    /// let d = parse_poly::<BigRational>("u + v").unwrap();
    /// assert_eq!(p.divide_exact(&d).unwrap().to_text(), "u v - v^2");
    /// assert!(p.divide_exact(&parse_poly("u + 1").unwrap()).is_none());
    /// ```
    pub fn divide_exact(&self, d: &Poly<S>) -> Option<Poly<S>> {
        let (lead_m, lead_c) = d.terms.last()?;
        let mut rest = self.clone();
        let mut quotient: Vec<(Monomial, S)> = Vec::new();
        while let Some((&m, c)) = rest.terms.last() {
            let t_m = m.checked_div(lead_m)?;
            let t_c = c.checked_div(lead_c)?;
            for (dm, dc) in &d.terms {
                rest.add_term(t_m.mul(dm), &-(t_c.mul_ref(dc)));
            }
            if rest.terms.contains_key(&m) {
                return None; // inexact arithmetic (f64): the leading term did not cancel
            }
            quotient.push((t_m, t_c));
        }
        Some(Poly::from_terms(quotient))
    }

    /// The greatest common divisor of two polynomials in the one variable `var` (both must
    /// use no other variable), monic, by Euclid's algorithm over the field of coefficients;
    /// `None` when a polynomial uses another variable or both are zero.
    ///
    /// ```
    /// use cagd_poly::{parse_poly, Var};
    /// use cagd_scalar::BigRational;
    /// let a = parse_poly::<BigRational>("2 u^3 - 2 u").unwrap(); // 2 u (u - 1)(u + 1)
    /// let b = parse_poly::<BigRational>("u^2 + 2 u + 1").unwrap(); // (u + 1)^2
    /// assert_eq!(a.gcd_univariate(&b, Var::U).unwrap().to_text(), "u + 1");
    /// ```
    pub fn gcd_univariate(&self, other: &Poly<S>, var: Var) -> Option<Poly<S>> {
        let only = |p: &Poly<S>| p.terms.keys().all(|m| m.degree() == m.exp(var));
        if !only(self) || !only(other) {
            return None;
        }
        let (mut a, mut b) = (self.clone(), other.clone());
        while !b.is_zero() {
            // a mod b by leading terms (the order is by degree: the last term leads)
            let (lead_m, lead_c) = b.terms.last().map(|(m, c)| (*m, c.clone()))?;
            let mut r = a;
            while let Some((&m, c)) = r.terms.last() {
                let Some(t_m) = m.checked_div(&lead_m) else {
                    break;
                };
                let t_c = c.checked_div(&lead_c)?;
                for (bm, bc) in &b.terms {
                    r.add_term(t_m.mul(bm), &-(t_c.mul_ref(bc)));
                }
                if r.terms.contains_key(&m) {
                    return None; // inexact arithmetic (f64)
                }
            }
            a = b;
            b = r;
        }
        let lead = a.terms.values().next_back()?.clone();
        Some(a.scale(&S::one().checked_div(&lead)?))
    }

    /// The content of the polynomial as one in `var` with coefficients polynomials in `other`
    /// only: the monic gcd (in `other`) of its coefficients of `var^k`. For a tensor-product
    /// weight `w(u, v) = f(u) g(v)` the content in v (coefficients in u) is f, made monic.
    /// `None` when a third variable occurs or the polynomial is zero.
    pub fn content_in(&self, var: Var, other: Var) -> Option<Poly<S>> {
        let mut coefficients: BTreeMap<u32, Vec<(Monomial, S)>> = BTreeMap::new();
        for (m, c) in &self.terms {
            if m.degree() != m.exp(var) + m.exp(other) {
                return None;
            }
            coefficients
                .entry(m.exp(var))
                .or_default()
                .push((m.with_exp(var, 0), c.clone()));
        }
        let mut content: Option<Poly<S>> = None;
        for terms in coefficients.into_values() {
            let c = Poly::from_terms(terms);
            content = Some(match content {
                None => c.gcd_univariate(&Poly::zero(), other)?,
                Some(g) => g.gcd_univariate(&c, other)?,
            });
        }
        content
    }

    /// The value at a point given as `(variable, value)` pairs, e.g.
    /// `p.eval(&[(Var::U, q!(1/2)), (Var::V, q!(1))])`. Variables the polynomial does not use
    /// may be omitted; a variable it uses without a value is [`PolyError::MissingVariable`].
    /// When a variable is given twice, the first value counts.
    pub fn eval(&self, point: &[(Var, S)]) -> Result<S, PolyError> {
        let mut values: [Option<&S>; crate::NVARS] = Default::default();
        for (v, x) in point.iter().rev() {
            if let Some(slot) = values.get_mut(v.index()) {
                *slot = Some(x);
            }
        }
        // the powers x^0, x^1, ... of each variable, computed once (one product each) instead
        // of once per term
        let mut powers: [Vec<S>; crate::NVARS] = Default::default();
        let mut sum = S::zero();
        for (m, c) in &self.terms {
            let mut t = c.clone();
            for (v, e) in m.powers() {
                let x = values.get(v.index()).copied().flatten().ok_or_else(|| {
                    PolyError::MissingVariable {
                        var: v.name().to_string(),
                    }
                })?;
                match powers.get_mut(v.index()) {
                    Some(table) => t *= power(table, x, e),
                    None => t *= x.powi(e),
                }
            }
            sum += t;
        }
        Ok(sum)
    }

    /// The polynomial with `var` fixed to a value, `p(..., var = x, ...)`: the iso-parametric
    /// curve `c(u, v0)` of a surface is `c.substitute_value(Var::V, &v0)`.
    pub fn substitute_value(&self, var: Var, x: &S) -> Self {
        let mut table = Vec::new();
        Poly::from_terms(self.terms.iter().map(|(m, c)| {
            let e = m.exp(var);
            (m.with_exp(var, 0), c.mul_ref(power(&mut table, x, e)))
        }))
    }

    /// The composition `p(..., var = q, ...)`: every occurrence of `var` replaced by the
    /// polynomial `q`, evaluated by Horner's rule in `q`.
    ///
    /// ```
    /// use cagd_poly::{parse_poly, Var};
    /// use cagd_scalar::BigRational;
    /// let p = parse_poly::<BigRational>("u^2 + v").unwrap();
    /// let q = parse_poly("1 - v").unwrap();
    /// assert_eq!(p.substitute(Var::U, &q).to_text(), "v^2 - v + 1");
    /// ```
    pub fn substitute(&self, var: Var, q: &Poly<S>) -> Self {
        // p = Σ_k p_k q^k, where p_k collects the terms with var^k (var removed)
        let mut by_power: BTreeMap<u32, Poly<S>> = BTreeMap::new();
        for (m, c) in &self.terms {
            by_power
                .entry(m.exp(var))
                .or_insert_with(Poly::zero)
                .add_term(m.with_exp(var, 0), c);
        }
        let top = by_power.keys().next_back().copied().unwrap_or(0);
        let mut acc = Poly::zero();
        for k in (0..=top).rev() {
            acc = &acc * q;
            if let Some(pk) = by_power.get(&k) {
                acc = acc + pk;
            }
        }
        acc
    }

    /// The composition with an affine change of variable, `var ↦ α var + β`: the polynomial
    /// `p(α var + β)`. Restricting a curve on `[0, 1]` to `[a, b]` is
    /// `p.affine_substitute(var, b - a, a)`.
    pub fn affine_substitute(&self, var: Var, alpha: &S, beta: &S) -> Self {
        let q = Poly::var(var).scale(alpha) + Poly::constant(beta.clone());
        self.substitute(var, &q)
    }

    /// The reparametrization onto `[a, b]`: `var ↦ (var - a)/(b - a)`, so that the new
    /// polynomial takes at `var = a` and `var = b` the values the old one took at 0 and 1.
    /// Fails when `a = b`.
    ///
    /// ```
    /// use cagd_poly::{parse_poly, Var};
    /// use cagd_scalar::{q, BigRational};
    /// let p = parse_poly::<BigRational>("u^2").unwrap();
    /// let r = p.reparametrize_affine(Var::U, &q!(1), &q!(3)).unwrap();
    /// assert_eq!(r.to_text(), "1/4 u^2 - 1/2 u + 1/4");
    /// assert!(p.reparametrize_affine(Var::U, &q!(2), &q!(2)).is_err());
    /// ```
    pub fn reparametrize_affine(&self, var: Var, a: &S, b: &S) -> Result<Self, PolyError> {
        let len = b.sub_ref(a);
        let alpha = S::one()
            .checked_div(&len)
            .ok_or_else(|| PolyError::DegenerateInterval { at: a.to_text() })?;
        let beta = -(a.mul_ref(&alpha));
        Ok(self.affine_substitute(var, &alpha, &beta))
    }

    /// An error naming the first variable that occurs but is not in `allowed`.
    pub(crate) fn check_vars(&self, allowed: &[Var]) -> Result<(), PolyError> {
        for v in self.vars() {
            if !allowed.contains(&v) {
                let basis: Vec<&str> = allowed.iter().map(|a| a.name()).collect();
                return Err(PolyError::ExtraVariable {
                    var: v.name().to_string(),
                    basis: basis.join(", "),
                });
            }
        }
        Ok(())
    }

    /// The coefficient of `Π var^e` (zero when absent).
    pub fn coeff_of(&self, powers: &[(Var, u32)]) -> S {
        self.coeff(&Monomial::from_powers(powers))
    }
}

/// `x^e` from `table` = [x^0, x^1, ...], extended (one product a power) as far as `e` needs.
fn power<'t, S: Scalar>(table: &'t mut Vec<S>, x: &S, e: u32) -> &'t S {
    let e = e as usize;
    if table.is_empty() {
        table.push(S::one());
    }
    while table.len() <= e {
        cagd_scalar::cancel::checkpoint();
        let next = table.last().map_or_else(S::one, |p| p.mul_ref(x));
        table.push(next);
    }
    // in range: the table was extended to e
    #[allow(clippy::indexing_slicing)]
    &table[e]
}
