//! Closed forms: the polynomial (or rational) map of a patch, and the graph of a polynomial
//! function as a patch (notes, chapter 5, §2, eq. (1)-(3) and (5)).

use crate::{BezierSurface, Domain, Mesh, RationalBezierSurface, SurfaceError};
use cagd_linalg::Point;
use cagd_poly::{
    from_bernstein_2d, from_bernstein_2d_rational, to_bernstein_2d, Poly, RationalMap, Var, VecPoly,
};
use cagd_scalar::Scalar;

/// `usize` as a scalar (mesh sizes are far below `i64::MAX`).
pub(crate) fn scalar_of<S: Scalar>(n: usize) -> S {
    S::from_i64(i64::try_from(n).unwrap_or(i64::MAX))
}

/// The polynomial map `Σ c_{i,j} B_i^m(u) B_j^n(v)` of a mesh on [0, 1] x [0, 1], with its
/// coefficients built in `T`, when every coordinate is a rational of machine size (the
/// integer fast path of [`from_bernstein_2d_rational`]); `None` otherwise.
fn unit_closed_form_in<S: Scalar, T: Scalar>(mesh: &Mesh<S>) -> Option<VecPoly<T>> {
    from_bernstein_2d_rational(mesh.iter(), (mesh.rows(), mesh.cols()), Var::U, Var::V)
}

/// The polynomial map `Σ c_{i,j} B_i^m(u) B_j^n(v)` of a mesh in the parameters of `domain`.
pub(crate) fn mesh_closed_form<S: Scalar>(
    mesh: &Mesh<S>,
    domain: &Domain<S>,
) -> Result<VecPoly<S>, SurfaceError> {
    if domain.is_unit() {
        if let Some(map) = unit_closed_form_in(mesh) {
            return Ok(map);
        }
    }
    let local = from_bernstein_2d(&mesh.to_rows(), Var::U, Var::V)?;
    if domain.is_unit() {
        return Ok(local);
    }
    let (a, b) = domain.u_interval();
    let (c, d) = domain.v_interval();
    Ok(local
        .reparametrize_affine(Var::U, a, b)?
        .reparametrize_affine(Var::V, c, d)?)
}

impl<S: Scalar> BezierSurface<S> {
    /// The closed form of the patch, a polynomial map in u, v (eq. (1) expanded in the monomial
    /// basis; on a domain [a, b] x [c, d] it is `c((u - a)/(b - a), (v - c)/(d - c))`).
    ///
    /// The notes' bidegree (1, 2) example of §3:
    ///
    /// ```
    /// use cagd_surface::BezierSurface;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::BigRational;
    /// let p = |c: &[i64]| Point::from_ints(c);
    /// let s = BezierSurface::<BigRational>::from_rows(vec![
    ///     vec![p(&[0, 0, 0]), p(&[1, 1, 0]), p(&[2, 0, 0])],
    ///     vec![p(&[0, 0, 1]), p(&[1, 1, 1]), p(&[2, 0, 1])],
    /// ]).unwrap();
    /// assert_eq!(s.closed_form().unwrap().to_text(), "(2 v, -2 v^2 + 2 v, u)");
    /// ```
    pub fn closed_form(&self) -> Result<VecPoly<S>, SurfaceError> {
        mesh_closed_form(self.mesh(), self.domain())
    }

    /// The closed form ([`BezierSurface::closed_form`]) with its coefficients in another
    /// scalar `T`, each the exact image of a coefficient by `convert`. A patch on
    /// [0, 1] x [0, 1] whose coordinates are rationals of machine size has its coefficients
    /// built in `T` directly (nothing is converted); any other is computed in `S` and mapped.
    ///
    /// ```
    /// use cagd_surface::BezierSurface;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{BigRational, ExactRational, Quadratic};
    /// let p = |c: &[i64]| Point::from_ints(c);
    /// let s = BezierSurface::<BigRational>::from_rows(vec![
    ///     vec![p(&[0, 0, 0]), p(&[1, 1, 0]), p(&[2, 0, 0])],
    ///     vec![p(&[0, 0, 1]), p(&[1, 1, 1]), p(&[2, 0, 1])],
    /// ]).unwrap();
    /// let c = s.closed_form_in(|x| Quadratic::from_rational(x)).unwrap();
    /// assert_eq!(c.to_text(), "(2 v, -2 v^2 + 2 v, u)");
    /// ```
    pub fn closed_form_in<T: Scalar>(
        &self,
        convert: impl FnMut(&S) -> T,
    ) -> Result<VecPoly<T>, SurfaceError> {
        if self.domain().is_unit() {
            if let Some(map) = unit_closed_form_in(self.mesh()) {
                return Ok(map);
            }
        }
        Ok(self.closed_form()?.map_coeffs(convert))
    }

    /// The graph of a polynomial function `f(x, y)` over [0, 1] x [0, 1] as a patch of
    /// bidegree (m, n), eq. (3): with the Bernstein coefficients `ĉ_{i,j}` of f,
    /// `f = Σ ĉ_{i,j} B_i^m(x) B_j^n(y)`, the mesh is
    ///
    /// `c_{i,j} = (i/m, j/n, ĉ_{i,j})`.
    ///
    /// f is written in x and y (or in u and v). An error when f has degree more than m in x or
    /// more than n in y, when m or n is 0 (x = u needs degree 1), or f uses another variable.
    ///
    /// ```
    /// use cagd_surface::BezierSurface;
    /// use cagd_poly::parse_poly;
    /// use cagd_scalar::BigRational;
    /// let xy = parse_poly::<BigRational>("x y").unwrap();
    /// let g = BezierSurface::graph(&xy, 1, 1).unwrap();
    /// assert_eq!(g.to_text(), "{(0, 0, 0), (0, 1, 0); (1, 0, 0), (1, 1, 1)}");
    /// assert_eq!(
    ///     BezierSurface::graph(&parse_poly::<BigRational>("x^2 y").unwrap(), 1, 1)
    ///         .unwrap_err()
    ///         .to_string(),
    ///     "f has degree 2 in x: its graph needs degree at least 2 in u, but the patch has degree 1"
    /// );
    /// ```
    pub fn graph(f: &Poly<S>, m: usize, n: usize) -> Result<Self, SurfaceError> {
        let uses_uv = f.degree_in(Var::U) > 0 || f.degree_in(Var::V) > 0;
        let uses_xy = f.degree_in(Var::X) > 0 || f.degree_in(Var::Y) > 0;
        let (x, y) = if uses_uv && !uses_xy {
            (Var::U, Var::V)
        } else {
            (Var::X, Var::Y)
        };
        for (var, max) in [(x, m), (y, n)] {
            let degree = f.degree_in(var);
            if max == 0 || degree as usize > max {
                return Err(SurfaceError::GraphDegree {
                    var: var.name().to_string(),
                    degree,
                    max,
                });
            }
        }
        let c_hat = to_bernstein_2d(f, x, y, m, n)?;
        let (mm, nn) = (scalar_of::<S>(m), scalar_of::<S>(n));
        let rows = c_hat
            .into_iter()
            .enumerate()
            .map(|(i, row)| {
                row.into_iter()
                    .enumerate()
                    .map(|(j, z)| {
                        Point::new(vec![scalar_of::<S>(i) / &mm, scalar_of::<S>(j) / &nn, z])
                    })
                    .collect()
            })
            .collect();
        BezierSurface::from_rows(rows)
    }
}

impl<S: Scalar> RationalBezierSurface<S> {
    /// The closed form of the rational patch (5): the homogeneous polynomial map
    /// `(Σ w c B B, Σ w B B)` (weight last) projected to a rational map
    /// `N(u, v) / D(u, v)`.
    pub fn closed_form(&self) -> Result<RationalMap<S>, SurfaceError> {
        let h = mesh_closed_form(&self.homogeneous(), self.domain())?;
        Ok(RationalMap::from_homogeneous(&h)?)
    }
}
