//! The Bernstein basis `B_i^n(t) = C(n, i) t^i (1 - t)^(n - i)` and the change between the
//! Bernstein and the monomial bases, in one variable (curves) and two (tensor-product
//! surfaces of bidegree (m, n), chapter 5, eq. (2)).

use crate::{Control, Monomial, Operands, Poly, PolyError, Var, VecPoly};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// The binomial coefficients `C(n, 0), ..., C(n, n)` as scalars.
fn binomials<S: Scalar>(n: usize) -> Vec<S> {
    let mut row = Vec::with_capacity(n + 1);
    let mut c = S::one();
    row.push(c.clone());
    for k in 1..=n {
        // C(n, k) = C(n, k-1) (n - k + 1) / k
        c = c * S::from_i64(as_i64(n - k + 1)) / S::from_i64(as_i64(k));
        row.push(c.clone());
    }
    row
}

fn as_i64(n: usize) -> i64 {
    i64::try_from(n).unwrap_or(i64::MAX)
}

fn as_u32(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

/// Entry `i` of a list of coefficients whose length was checked (zero past the end, which
/// the callers never reach).
fn entry<S: Scalar>(list: &[S], i: usize) -> S {
    list.get(i).cloned().unwrap_or_else(S::zero)
}

/// Pascal's triangle up to row `n`, as scalars.
fn pascal<S: Scalar>(n: usize) -> Vec<Vec<S>> {
    (0..=n).map(binomials).collect()
}

/// The Bernstein polynomial `B_i^n(var) = C(n, i) var^i (1 - var)^(n - i)`; zero when `i > n`.
///
/// ```
/// use cagd_poly::{bernstein, Var};
/// use cagd_scalar::BigRational;
/// assert_eq!(bernstein::<BigRational>(1, 3, Var::V).to_text(), "3 v^3 - 6 v^2 + 3 v");
/// ```
pub fn bernstein<S: Scalar>(i: usize, n: usize, var: Var) -> Poly<S> {
    if i > n {
        return Poly::zero();
    }
    let c = binomials::<S>(n).into_iter().nth(i).unwrap_or_else(S::zero);
    let t = Poly::var(var);
    let one_minus_t = Poly::one() - &t;
    t.pow(as_u32(i)) * one_minus_t.pow(as_u32(n - i)) * Poly::constant(c)
}

/// Monomial coefficients `a_0..a_n` of `Σ c_i B_i^n(t)`:
/// `a_k = C(n, k) Σ_{i ≤ k} (-1)^(k-i) C(k, i) c_i` (the k-th forward difference).
fn bernstein_to_power<S: Scalar>(c: &[S], binom: &[Vec<S>]) -> Vec<S> {
    let Some(n) = c.len().checked_sub(1) else {
        return Vec::new();
    };
    let Some(row_n) = binom.get(n) else {
        return Vec::new();
    };
    // row k of Pascal's triangle has k + 1 entries: i runs over 0..=k
    binom
        .iter()
        .zip(row_n)
        .enumerate()
        .map(|(k, (row_k, c_nk))| {
            let mut diff = S::zero();
            for (i, (b, ci)) in row_k.iter().zip(c).enumerate() {
                let term = b.mul_ref(ci);
                if (k - i) % 2 == 0 {
                    diff += term;
                } else {
                    diff -= term;
                }
            }
            diff * c_nk
        })
        .collect()
}

/// Bernstein coefficients of degree `n` of `Σ a_k t^k` (`a.len() ≤ n + 1`):
/// `b_i = Σ_{k ≤ i} C(i, k) / C(n, k) a_k`.
fn power_to_bernstein<S: Scalar>(a: &[S], n: usize, binom: &[Vec<S>]) -> Vec<S> {
    let Some(row_n) = binom.get(n) else {
        return Vec::new();
    };
    // row i of Pascal's triangle has i + 1 entries: k runs over 0..=i
    binom
        .iter()
        .take(n + 1)
        .map(|row_i| {
            let mut b = S::zero();
            for ((ak, c_ik), c_nk) in a.iter().zip(row_i).zip(row_n) {
                if !ak.is_zero() {
                    b += ak.mul_ref(c_ik) / c_nk;
                }
            }
            b
        })
        .collect()
}

/// The polynomial `Σ_i c_i B_i^n(var)` of the coefficients `c_0..c_n` (the zero polynomial
/// for an empty list).
///
/// ```
/// use cagd_poly::{poly_from_bernstein_1d, Var};
/// use cagd_scalar::{q, BigRational};
/// // the monomial u on [0, 1] has equidistant Bernstein coefficients
/// let p = poly_from_bernstein_1d(&[q!(0), q!(1/3), q!(2/3), q!(1)], Var::U);
/// assert_eq!(p.to_text(), "u");
/// ```
pub fn poly_from_bernstein_1d<S: Scalar>(coefs: &[S], var: Var) -> Poly<S> {
    let n = coefs.len().saturating_sub(1);
    let a = bernstein_to_power(coefs, &pascal(n));
    Poly::from_terms(
        a.into_iter()
            .enumerate()
            .map(|(k, c)| (Monomial::from_powers(&[(var, as_u32(k))]), c)),
    )
}

/// The Bernstein coefficients `c_0..c_n` of a polynomial in `var` of degree at most `n`, so
/// that `p = Σ_i c_i B_i^n(var)`. Fails when `p` has degree more than `n` in `var` or uses
/// another variable.
///
/// ```
/// use cagd_poly::{parse_poly, to_bernstein_1d, Var};
/// use cagd_scalar::BigRational;
/// let p = parse_poly::<BigRational>("u^2").unwrap();
/// let c = to_bernstein_1d(&p, Var::U, 3).unwrap();
/// let text: Vec<String> = c.iter().map(|x| x.to_string()).collect();
/// assert_eq!(text, ["0", "0", "1/3", "1"]);
/// assert!(to_bernstein_1d(&p, Var::U, 1).is_err());
/// ```
pub fn to_bernstein_1d<S: Scalar>(p: &Poly<S>, var: Var, n: usize) -> Result<Vec<S>, PolyError> {
    p.check_vars(&[var])?;
    check_degree(p, var, n)?;
    let a: Vec<S> = (0..=p.degree_in(var))
        .map(|k| p.coeff(&Monomial::from_powers(&[(var, k)])))
        .collect();
    Ok(power_to_bernstein(&a, n, &pascal(n)))
}

fn check_degree<S: Scalar>(p: &Poly<S>, var: Var, n: usize) -> Result<(), PolyError> {
    let degree = p.degree_in(var);
    if degree as usize > n {
        return Err(PolyError::DegreeTooHigh {
            var: var.name().to_string(),
            degree,
            max: as_u32(n),
        });
    }
    Ok(())
}

/// Checks a grid is a non-empty rectangle; returns its (rows, columns).
fn grid_shape<T>(grid: &[Vec<T>]) -> Result<(usize, usize), PolyError> {
    let cols = grid.first().map_or(0, Vec::len);
    if cols == 0 {
        return Err(PolyError::Empty {
            what: Control::Mesh,
        });
    }
    for (row, r) in grid.iter().enumerate() {
        if r.len() != cols {
            return Err(PolyError::Ragged {
                row,
                len: r.len(),
                expected: cols,
            });
        }
    }
    Ok((grid.len(), cols))
}

fn distinct(var_u: Var, var_v: Var) -> Result<(), PolyError> {
    if var_u == var_v {
        return Err(PolyError::SameVariable {
            var: var_u.name().to_string(),
        });
    }
    Ok(())
}

/// The polynomial `Σ_i Σ_j c_ij B_i^m(var_u) B_j^n(var_v)` of a grid of coefficients: row `i`
/// runs along `var_u` (degree m = rows - 1), column `j` along `var_v` (degree n = columns - 1),
/// as the meshes `c_{i,j}` of chapter 5.
///
/// ```
/// use cagd_poly::{poly_from_bernstein_2d, Var};
/// use cagd_scalar::{q, BigRational};
/// // f(x, y) = xy has Bernstein coefficients [[0, 0], [0, 1]] at bidegree (1, 1), chapter 5
/// let grid = vec![vec![q!(0), q!(0)], vec![q!(0), q!(1)]];
/// assert_eq!(poly_from_bernstein_2d(&grid, Var::X, Var::Y).unwrap().to_text(), "x y");
/// ```
pub fn poly_from_bernstein_2d<S: Scalar>(
    grid: &[Vec<S>],
    var_u: Var,
    var_v: Var,
) -> Result<Poly<S>, PolyError> {
    let (rows, cols) = grid_shape(grid)?;
    distinct(var_u, var_v)?;
    if let Some(p) = crate::fast::poly_from_bernstein_2d(grid, var_u, var_v) {
        // the same polynomial, as M_m C M_nᵀ on integer numerators
        return Ok(p);
    }
    let binom = pascal(rows.max(cols) - 1);
    // along v in each row, then along u in each column
    let by_rows: Vec<Vec<S>> = grid
        .iter()
        .map(|row| bernstein_to_power(row, &binom))
        .collect();
    let mut p = Poly::zero();
    for l in 0..cols {
        let column: Vec<S> = by_rows.iter().map(|r| entry(r, l)).collect();
        for (k, a) in bernstein_to_power(&column, &binom).into_iter().enumerate() {
            p.add_term(
                Monomial::from_powers(&[(var_u, as_u32(k)), (var_v, as_u32(l))]),
                &a,
            );
        }
    }
    Ok(p)
}

/// The Bernstein coefficients `c_ij` of bidegree (m, n) of a polynomial in `var_u`, `var_v`,
/// so that `p = Σ c_ij B_i^m(var_u) B_j^n(var_v)`: `m + 1` rows of `n + 1`. Fails when the
/// degree in `var_u` exceeds `m`, in `var_v` exceeds `n`, or another variable occurs.
///
/// ```
/// use cagd_poly::{parse_poly, to_bernstein_2d, Var};
/// use cagd_scalar::{q, BigRational};
/// let xy = parse_poly::<BigRational>("x y").unwrap();
/// let c = to_bernstein_2d(&xy, Var::X, Var::Y, 1, 1).unwrap();
/// assert_eq!(c, vec![vec![q!(0), q!(0)], vec![q!(0), q!(1)]]);
/// ```
pub fn to_bernstein_2d<S: Scalar>(
    p: &Poly<S>,
    var_u: Var,
    var_v: Var,
    m: usize,
    n: usize,
) -> Result<Vec<Vec<S>>, PolyError> {
    distinct(var_u, var_v)?;
    p.check_vars(&[var_u, var_v])?;
    check_degree(p, var_u, m)?;
    check_degree(p, var_v, n)?;
    let binom = pascal(m.max(n));
    // a[k][l] = coefficient of u^k v^l
    let mut a = vec![vec![S::zero(); n + 1]; m + 1];
    for (mono, c) in p.terms() {
        // in range: the degrees were checked above
        if let Some(x) = a
            .get_mut(mono.exp(var_u) as usize)
            .and_then(|row| row.get_mut(mono.exp(var_v) as usize))
        {
            *x = c.clone();
        }
    }
    let by_rows: Vec<Vec<S>> = a
        .iter()
        .map(|row| power_to_bernstein(row, n, &binom))
        .collect();
    let mut out = vec![Vec::with_capacity(n + 1); m + 1];
    for j in 0..=n {
        let column: Vec<S> = by_rows.iter().map(|r| entry(r, j)).collect();
        for (row, b) in out.iter_mut().zip(power_to_bernstein(&column, m, &binom)) {
            row.push(b);
        }
    }
    Ok(out)
}

/// The common dimension of a list of points, or an error.
fn common_dim<'a, S: Scalar>(
    points: impl IntoIterator<Item = &'a Point<S>>,
    what: Control,
) -> Result<usize, PolyError> {
    let mut dim = None;
    for p in points {
        match dim {
            None => dim = Some(p.dim()),
            Some(d) if d != p.dim() => {
                return Err(PolyError::DimensionMismatch {
                    what: Operands::PointsOf(what),
                    expected: d,
                    found: p.dim(),
                })
            }
            Some(_) => {}
        }
    }
    dim.ok_or(PolyError::Empty { what })
}

/// The Bézier curve `c(var) = Σ_i c_i B_i^n(var)` of a control polygon, as a polynomial map.
///
/// ```
/// use cagd_poly::{from_bernstein_1d, Var};
/// use cagd_linalg::Point;
/// use cagd_scalar::BigRational;
/// let polygon: Vec<Point<BigRational>> =
///     vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2]), Point::from_ints(&[2, 0])];
/// assert_eq!(from_bernstein_1d(&polygon, Var::T).unwrap().to_text(), "(2 t, -4 t^2 + 4 t)");
/// ```
pub fn from_bernstein_1d<S: Scalar>(
    points: &[Point<S>],
    var: Var,
) -> Result<VecPoly<S>, PolyError> {
    let dim = common_dim(points, Control::Polygon)?;
    Ok(VecPoly::new(
        (0..dim)
            .map(|d| {
                let coords: Vec<S> = points.iter().map(|p| p[d].clone()).collect();
                poly_from_bernstein_1d(&coords, var)
            })
            .collect(),
    ))
}

/// The tensor-product Bézier surface `c(u, v) = Σ_i Σ_j c_ij B_i^m(u) B_j^n(v)` of a control
/// mesh (row `i` along `var_u`, column `j` along `var_v`), as a polynomial map.
pub fn from_bernstein_2d<S: Scalar>(
    grid: &[Vec<Point<S>>],
    var_u: Var,
    var_v: Var,
) -> Result<VecPoly<S>, PolyError> {
    let shape = grid_shape(grid)?;
    let dim = common_dim(grid.iter().flatten(), Control::Mesh)?;
    distinct(var_u, var_v)?;
    if let Some(map) =
        crate::fast::map_from_bernstein_2d(grid.iter().flatten(), shape, var_u, var_v)
    {
        // every coordinate rational and of machine size: the same map, on machine integers
        return Ok(map);
    }
    let comps = (0..dim)
        .map(|d| {
            let coords: Vec<Vec<S>> = grid
                .iter()
                .map(|row| row.iter().map(|p| p[d].clone()).collect())
                .collect();
            poly_from_bernstein_2d(&coords, var_u, var_v)
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(VecPoly::new(comps))
}

/// The tensor-product Bézier surface `c(u, v) = Σ_i Σ_j c_ij B_i^m(u) B_j^n(v)` of a control
/// mesh given row by row (`rows · cols` points; row `i` along `var_u`), with its coefficients
/// built in the scalar `T`, when every coordinate is a rational whose numerator and
/// denominator fit machine integers: `a_kl = C(m, k) C(n, l) Δ_u^k Δ_v^l c_00` (chapter 5,
/// eq. (2) expanded) on integer numerators over each coordinate's common denominator, one
/// reduction per coefficient. `None` otherwise (a root, an `f64`, a long number, an overflow,
/// points of different dimensions, a count other than `rows · cols`): then
/// [`from_bernstein_2d`] computes the map in the mesh's own scalar.
///
/// A caller that needs the map in another exact scalar (the answers' numbers) gets it without
/// converting every coefficient.
///
/// ```
/// use cagd_poly::{from_bernstein_2d_rational, Var, VecPoly};
/// use cagd_linalg::Point;
/// use cagd_scalar::{BigRational, Quadratic};
/// let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
/// let mesh = [p(&[0, 0, 0]), p(&[1, 1, 0]), p(&[2, 0, 0]), p(&[0, 0, 1]), p(&[1, 1, 1]), p(&[2, 0, 1])];
/// let c: VecPoly<Quadratic> = from_bernstein_2d_rational(&mesh, (2, 3), Var::U, Var::V).unwrap();
/// assert_eq!(c.to_text(), "(2 v, -2 v^2 + 2 v, u)");
/// ```
pub fn from_bernstein_2d_rational<'a, S: Scalar + 'a, T: Scalar>(
    points: impl IntoIterator<Item = &'a Point<S>>,
    (rows, cols): (usize, usize),
    var_u: Var,
    var_v: Var,
) -> Option<VecPoly<T>> {
    crate::fast::map_from_bernstein_2d(points, (rows, cols), var_u, var_v)
}

/// The control polygon of degree `n` of a polynomial curve: the inverse of
/// [`from_bernstein_1d`].
pub fn control_polygon<S: Scalar>(
    c: &VecPoly<S>,
    var: Var,
    n: usize,
) -> Result<Vec<Point<S>>, PolyError> {
    let comps = c
        .components()
        .iter()
        .map(|p| to_bernstein_1d(p, var, n))
        .collect::<Result<Vec<_>, _>>()?;
    Ok((0..=n)
        .map(|i| Point::new(comps.iter().map(|col| entry(col, i)).collect()))
        .collect())
}

/// The control mesh of bidegree (m, n) of a polynomial surface: the inverse of
/// [`from_bernstein_2d`].
pub fn control_mesh<S: Scalar>(
    c: &VecPoly<S>,
    var_u: Var,
    var_v: Var,
    m: usize,
    n: usize,
) -> Result<Vec<Vec<Point<S>>>, PolyError> {
    let comps = c
        .components()
        .iter()
        .map(|p| to_bernstein_2d(p, var_u, var_v, m, n))
        .collect::<Result<Vec<_>, _>>()?;
    Ok((0..=m)
        .map(|i| {
            (0..=n)
                .map(|j| {
                    Point::new(
                        comps
                            .iter()
                            .map(|g| g.get(i).map_or_else(S::zero, |r| entry(r, j)))
                            .collect(),
                    )
                })
                .collect()
        })
        .collect())
}
