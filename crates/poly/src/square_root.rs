//! The square root of a polynomial that is a square, and the definite integral in one
//! variable: the exact arc length of a Pythagorean-hodograph curve, `∫_a^b |σ(t)| dt` with
//! `c'·c' = σ²`, is made of the two.

use crate::{Poly, Var};
use cagd_scalar::Scalar;

impl<S: Scalar> Poly<S> {
    /// σ with σ² = self, when self is the square of a polynomial in `var`: the coefficients of
    /// σ from the top down (`σ_k = √f_{2k}`, then `σ_j = (f_{k+j} - Σ_{i=j+1}^{k-1} σ_i
    /// σ_{k+j-i}) / (2 σ_k)`), or, when the top coefficient's root is not found in the field
    /// (the scalar's `sqrt_exact` of an a + b√d), from the constant term up (the same on
    /// `t^d f(1/t)`). `None` when self is not a square in the field.
    ///
    /// ```
    /// use cagd_poly::{parse_poly, Var};
    /// use cagd_scalar::BigRational;
    /// let f = parse_poly::<BigRational>("4 t^2 + 4 t + 1").unwrap();
    /// assert_eq!(f.square_root(Var::T), Some(parse_poly("2 t + 1").unwrap()));
    /// assert_eq!(parse_poly::<BigRational>("t^2 + 1").unwrap().square_root(Var::T), None);
    /// ```
    pub fn square_root(&self, var: Var) -> Option<Poly<S>> {
        let f = self;
        sqrt_from_top(f, var).or_else(|| {
            let d = f.degree_in(var);
            let reversed = |g: &Poly<S>, n: u32| {
                (0..=n).fold(Poly::zero(), |acc, i| {
                    &acc + &Poly::monomial(g.coeff_of(&[(var, i)]), &[(var, n - i)])
                })
            };
            let s = sqrt_from_top(&reversed(f, d), var)?;
            let sigma = reversed(&s, d / 2);
            (&(&sigma * &sigma) - f).is_zero().then_some(sigma)
        })
    }

    /// `∫_a^b p(var) d var = Σ_i p_i (b^{i+1} - a^{i+1}) / (i + 1)`, p a polynomial in `var`
    /// alone.
    ///
    /// ```
    /// use cagd_poly::{parse_poly, Var};
    /// use cagd_scalar::{q, BigRational};
    /// let p = parse_poly::<BigRational>("3 t^2").unwrap();
    /// assert_eq!(p.definite_integral(Var::T, &q!(0), &q!(2)), q!(8));
    /// ```
    pub fn definite_integral(&self, var: Var, a: &S, b: &S) -> S {
        let mut total = S::zero();
        for i in 0..=self.degree_in(var) {
            let c = self.coeff_of(&[(var, i)]);
            let e = i + 1;
            let n = S::from_i64(i64::from(e));
            total += c * (b.powi(e) - a.powi(e)) / n;
        }
        total
    }
}

/// σ from the top coefficient down (see [`Poly::square_root`]).
fn sqrt_from_top<S: Scalar>(f: &Poly<S>, var: Var) -> Option<Poly<S>> {
    let d = f.degree_in(var);
    if d % 2 == 1 {
        return None;
    }
    let k = d / 2;
    let c = |i: u32| f.coeff_of(&[(var, i)]);
    let top = c(d).sqrt_exact()?;
    let two_top = top.clone() + top.clone();
    let mut s: Vec<S> = vec![S::zero(); usize::try_from(k).ok()? + 1];
    *s.last_mut()? = top;
    for j in (0..k).rev() {
        let mut rest = c(k + j);
        for i in (j + 1)..k {
            let l = k + j - i;
            rest -=
                s.get(usize::try_from(i).ok()?)?.clone() * s.get(usize::try_from(l).ok()?)?.clone();
        }
        *s.get_mut(usize::try_from(j).ok()?)? = rest.checked_div(&two_top)?;
    }
    let sigma = s.iter().enumerate().fold(Poly::zero(), |acc, (i, x)| {
        &acc + &Poly::monomial(x.clone(), &[(var, u32::try_from(i).unwrap_or(0))])
    });
    (&(&sigma * &sigma) - f).is_zero().then_some(sigma)
}

#[cfg(test)]
mod tests {
    use crate::{parse_poly, Poly, Var};
    use cagd_scalar::{q, BigRational, Quadratic};

    fn poly(s: &str) -> Poly<BigRational> {
        parse_poly(s).unwrap()
    }

    #[test]
    fn square_roots() {
        // (3t² - 2t + 1)² = 9t⁴ - 12t³ + 10t² - 4t + 1
        let f = poly("9 t^4 - 12 t^3 + 10 t^2 - 4 t + 1");
        assert_eq!(f.square_root(Var::T), Some(poly("3 t^2 - 2 t + 1")));
        assert_eq!(poly("t^3").square_root(Var::T), None);
        assert_eq!(poly("2 t^2").square_root(Var::T), None);
        assert_eq!(poly("0").square_root(Var::T), Some(poly("0")));
    }

    #[test]
    fn square_root_in_a_quadratic_field() {
        // (√2 t + 1)² = 2t² + 2√2 t + 1 in Q(√2): the top 2 has the root √2 there
        let f: Poly<Quadratic> = parse_poly("2 t^2 + 2 sqrt2 t + 1").unwrap();
        let s: Poly<Quadratic> = parse_poly("sqrt2 t + 1").unwrap();
        assert_eq!(f.square_root(Var::T), Some(s));
    }

    #[test]
    fn integrals() {
        // ∫_1^3 (2t + 1) dt = (9 + 3) - (1 + 1) = 10
        assert_eq!(
            poly("2 t + 1").definite_integral(Var::T, &q!(1), &q!(3)),
            q!(10)
        );
        assert_eq!(poly("0").definite_integral(Var::T, &q!(0), &q!(1)), q!(0));
    }
}
