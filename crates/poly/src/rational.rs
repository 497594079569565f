//! `RationalMap<S>`: a vector of polynomials over one common scalar denominator (rational
//! curves and surfaces).

use crate::{Control, Poly, PolyError, Vanishes, Var, VecPoly};
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use std::fmt;

/// A rational map `N(u, v, ...) / D(u, v, ...)`, with a vector numerator and a common scalar
/// denominator that is not the zero polynomial: the projection of a homogeneous polynomial map
/// `(w x, w y, w z, w)` (weight last, as [`Point::to_homogeneous`]).
///
/// ```
/// use cagd_poly::{parse_vec_poly, RationalMap, Var};
/// use cagd_scalar::{q, BigRational};
/// // the quarter circle (1 - t^2, 2t) / (1 + t^2) from its homogeneous form
/// let h = parse_vec_poly::<BigRational>("(1 - t^2, 2 t, 1 + t^2)").unwrap();
/// let c = RationalMap::from_homogeneous(&h).unwrap();
/// assert_eq!(c.eval(&[(Var::T, q!(1/2))]).unwrap().to_text(), "(3/5, 4/5)");
/// assert_eq!(c.to_text(), "(-t^2 + 1, 2 t) / (t^2 + 1)");
/// ```
#[derive(Clone, PartialEq)]
pub struct RationalMap<S> {
    numer: VecPoly<S>,
    denom: Poly<S>,
}

impl<S: Scalar> RationalMap<S> {
    /// The map `numer / denom`; fails when `denom` is the zero polynomial.
    pub fn new(numer: VecPoly<S>, denom: Poly<S>) -> Result<Self, PolyError> {
        if denom.is_zero() {
            return Err(PolyError::ZeroDenominator {
                at: Vanishes::Everywhere,
            });
        }
        Ok(RationalMap { numer, denom })
    }

    /// The polynomial map `c` as a rational map with denominator 1.
    pub fn from_polynomial(c: VecPoly<S>) -> Self {
        RationalMap {
            numer: c,
            denom: Poly::one(),
        }
    }

    /// The projection of a homogeneous map `(X_1, ..., X_d, W)` of R^{d+1} (weight last):
    /// `(X_1, ..., X_d) / W`. Fails when there is no component or `W` is zero.
    pub fn from_homogeneous(h: &VecPoly<S>) -> Result<Self, PolyError> {
        let Some((w, xs)) = h.components().split_last() else {
            return Err(PolyError::Empty {
                what: Control::HomogeneousMap,
            });
        };
        RationalMap::new(VecPoly::new(xs.to_vec()), w.clone())
    }

    /// The homogeneous map `(N_1, ..., N_d, D)` (weight last).
    pub fn to_homogeneous(&self) -> VecPoly<S> {
        let mut comps = self.numer.components().to_vec();
        comps.push(self.denom.clone());
        VecPoly::new(comps)
    }

    /// The numerator.
    pub fn numerator(&self) -> &VecPoly<S> {
        &self.numer
    }

    /// The denominator.
    pub fn denominator(&self) -> &Poly<S> {
        &self.denom
    }

    /// The dimension of the points.
    pub fn dim(&self) -> usize {
        self.numer.dim()
    }

    /// The point `N(point) / D(point)`; fails where the denominator vanishes.
    pub fn eval(&self, point: &[(Var, S)]) -> Result<Point<S>, PolyError> {
        let d = self.denom.eval(point)?;
        let n = self.numer.eval(point)?;
        let at = || {
            let parts: Vec<String> = point
                .iter()
                .map(|(v, x)| format!("{v} = {}", x.to_text()))
                .collect();
            Vanishes::At {
                point: parts.join(", "),
            }
        };
        let coords = n
            .coords()
            .iter()
            .map(|x| {
                x.checked_div(&d)
                    .ok_or_else(|| PolyError::ZeroDenominator { at: at() })
            })
            .collect::<Result<Vec<S>, _>>()?;
        if coords.is_empty() && d.is_zero() {
            return Err(PolyError::ZeroDenominator { at: at() });
        }
        Ok(Point::new(coords))
    }

    /// The partial derivative by the quotient rule, `(N' D - N D') / D^2` (not reduced).
    pub fn partial(&self, var: Var) -> Self {
        let dn = self.numer.partial(var);
        let dd = self.denom.partial(var);
        let top = VecPoly::new(
            dn.components()
                .iter()
                .zip(self.numer.components())
                .map(|(dni, ni)| dni * &self.denom - ni * &dd)
                .collect(),
        );
        RationalMap {
            numer: top,
            denom: &self.denom * &self.denom,
        }
    }

    /// The mixed partial derivative `∂^{r+s} (N/D) / ∂u^r ∂v^s` through the homogeneous form,
    /// as `P_{r,s} / D^{r+s+1}`, reduced by the factors of D that divide the numerator
    /// ([`RationalMap::over_power`]).
    ///
    /// Leibniz's rule on `N = D c` gives
    /// `N^{(a,b)} = Σ_{i ≤ a, j ≤ b} C(a, i) C(b, j) D^{(i,j)} c^{(a-i,b-j)}`, so with
    /// `c^{(a,b)} = P_{a,b} / D^{a+b+1}`:
    ///
    /// `P_{a,b} = D^{a+b} N^{(a,b)} − Σ_{(i,j) ≠ (0,0)} C(a, i) C(b, j) D^{(i,j)} D^{i+j-1}
    /// P_{a-i,b-j}`, `P_{0,0} = N`.
    ///
    /// The degree grows by deg D per derivative, where applying the quotient rule
    /// ([`RationalMap::partial`]) r + s times squares the denominator each time (`D^{2^{r+s}}`).
    /// The two variables may be equal (then the order is r + s in it).
    ///
    /// ```
    /// use cagd_poly::{parse_vec_poly, RationalMap, Var};
    /// use cagd_scalar::{q, BigRational};
    /// let h = parse_vec_poly::<BigRational>("(1 - t^2, 2 t, 1 + t^2)").unwrap();
    /// let c = RationalMap::from_homogeneous(&h).unwrap();
    /// let d2 = c.mixed_partial(Var::T, 2, Var::U, 0);
    /// assert_eq!(d2.denominator().to_text(), "t^6 + 3 t^4 + 3 t^2 + 1");
    /// // the same function as the quotient rule twice
    /// let q = c.partial(Var::T).partial(Var::T);
    /// let at = [(Var::T, q!(3))];
    /// assert_eq!(d2.eval(&at).unwrap(), q.eval(&at).unwrap());
    /// ```
    pub fn mixed_partial(&self, u: Var, r: usize, v: Var, s: usize) -> Self {
        // N^{(a,b)} and D^{(a,b)}, a ≤ r, b ≤ s, row by row
        let mut derivs: Vec<Vec<(VecPoly<S>, Poly<S>)>> = Vec::with_capacity(r + 1);
        let mut first = (self.numer.clone(), self.denom.clone());
        for _ in 0..=r {
            let mut row = Vec::with_capacity(s + 1);
            let mut g = first.clone();
            for _ in 0..=s {
                let next = (g.0.partial(v), g.1.partial(v));
                row.push(g);
                g = next;
            }
            derivs.push(row);
            first = (first.0.partial(u), first.1.partial(u));
        }
        let deriv = |a: usize, b: usize| derivs.get(a).and_then(|row| row.get(b));
        // D^0, ..., D^{r+s+1}
        let d = &self.denom;
        let mut d_pow: Vec<Poly<S>> = vec![Poly::one()];
        while d_pow.len() <= r + s + 1 {
            let next = d_pow.last().map_or_else(Poly::one, |last| last * d);
            d_pow.push(next);
        }
        let power = |k: usize| d_pow.get(k).cloned().unwrap_or_else(Poly::one);
        let binomial = |n: usize, k: usize| -> S {
            (0..k).fold(S::one(), |c, i| {
                c * S::from_ratio(
                    i64::try_from(n - i).unwrap_or(i64::MAX),
                    i64::try_from(i + 1).unwrap_or(1),
                )
            })
        };
        let sub = |x: &VecPoly<S>, y: &VecPoly<S>| {
            VecPoly::new(
                x.components()
                    .iter()
                    .zip(y.components())
                    .map(|(a, b)| a - b)
                    .collect(),
            )
        };
        let mut p: Vec<Vec<VecPoly<S>>> = Vec::with_capacity(r + 1);
        for a in 0..=r {
            let mut row: Vec<VecPoly<S>> = Vec::with_capacity(s + 1);
            for b in 0..=s {
                let Some((n_ab, _)) = deriv(a, b) else { break };
                let mut sum = n_ab.mul_poly(&power(a + b));
                for i in 0..=a {
                    for j in 0..=b {
                        let Some((_, d_ij)) = deriv(i, j) else {
                            continue;
                        };
                        let prev = if i == 0 {
                            row.get(b - j)
                        } else {
                            p.get(a - i).and_then(|earlier| earlier.get(b - j))
                        };
                        let Some(prev) = prev else { continue };
                        if i + j == 0 || d_ij.is_zero() || prev.is_zero() {
                            continue;
                        }
                        let factor =
                            (d_ij * &power(i + j - 1)).scale(&(binomial(a, i) * binomial(b, j)));
                        sum = sub(&sum, &prev.mul_poly(&factor));
                    }
                }
                row.push(sum);
            }
            p.push(row);
        }
        let top = p
            .last()
            .and_then(|row| row.last())
            .cloned()
            .unwrap_or_else(|| VecPoly::zero(self.dim()));
        let exponent = u32::try_from(r + s + 1).unwrap_or(u32::MAX);
        RationalMap::over_power(top, d, exponent, u, v)
    }

    /// `numer / base^exponent`, reduced by the factors of `base` found without factoring: its
    /// contents in u and in v (`base = f(u) g(v) h(u, v)`, f and g the gcds of its coefficients,
    /// [`Poly::content_in`]) and the rest h, each divided out of the numerator as many times
    /// as it divides every component (at most `exponent` times). The weights of a sphere
    /// octant or a surface of revolution are a tensor product, so `base = f(u) g(v)` there.
    pub fn over_power(numer: VecPoly<S>, base: &Poly<S>, exponent: u32, u: Var, v: Var) -> Self {
        // base = scale · f · g · h with f, g monic (when the contents are found)
        let mut factors: Vec<Poly<S>> = Vec::new();
        let mut rest = base.clone();
        let pairs = if u == v { vec![] } else { vec![(v, u), (u, v)] };
        for (var, other) in pairs {
            if let Some(f) = rest.content_in(var, other) {
                if f.degree() > 0 {
                    if let Some(q) = rest.divide_exact(&f) {
                        factors.push(f);
                        rest = q;
                    }
                }
            }
        }
        factors.push(rest);
        let mut numer = numer;
        let mut denom = Poly::one();
        for f in &factors {
            let mut k = exponent;
            while k > 0 && f.degree() > 0 {
                let quotient: Option<Vec<Poly<S>>> = numer
                    .components()
                    .iter()
                    .map(|c| c.divide_exact(f))
                    .collect();
                let Some(quotient) = quotient else { break };
                numer = VecPoly::new(quotient);
                k -= 1;
            }
            denom = denom * f.pow(k);
        }
        // a constant denominator divides into the numerator
        match denom.as_constant() {
            Some(c) if !c.is_zero() => {
                let inverse = S::one().checked_div(&c).unwrap_or_else(S::one);
                RationalMap {
                    numer: numer.scale(&inverse),
                    denom: Poly::one(),
                }
            }
            _ => RationalMap { numer, denom },
        }
    }

    /// Plain text: `(N_1, ..., N_d) / (D)`, or the numerator alone when `D = 1`.
    pub fn to_text(&self) -> String {
        if self.denom == Poly::one() {
            self.numer.to_text()
        } else {
            format!("{} / ({})", self.numer.to_text(), self.denom.to_text())
        }
    }

    /// LaTeX: `\frac{1}{D} \left(N_1, ..., N_d\right)`, or the numerator alone when `D = 1`.
    pub fn to_latex(&self) -> String {
        if self.denom == Poly::one() {
            self.numer.to_latex()
        } else {
            format!(
                "\\frac{{1}}{{{}}} {}",
                self.denom.to_latex(),
                self.numer.to_latex()
            )
        }
    }
}

impl<S: Scalar> fmt::Display for RationalMap<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

impl<S: Scalar> fmt::Debug for RationalMap<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "RationalMap({})", self.to_text())
    }
}
