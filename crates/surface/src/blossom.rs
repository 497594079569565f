//! The polar form (12), the restriction to a sub-rectangle (13) and the subdivision into four
//! (notes, chapter 5, §4).

use crate::domain::check_interval;
use crate::{BezierSurface, Domain, Mesh, RationalBezierSurface, SurfaceError};
use cagd_bezier::{blossom, restrict, subdivide};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// The two steps of a restriction (13), as the notes compute them: first every row is
/// restricted in v, then every column of the result in u.
#[derive(Clone, PartialEq, Debug)]
pub struct Restriction<P> {
    /// The row step ĉ: each row `c_{i,0}, ..., c_{i,n}` restricted to [c, d] in v,
    /// `ĉ_{i,j} = c_i[c^<n-j>, d^<j>]`. As a patch it is the surface restricted in v only
    /// (domain [a₀, b₀] x [c, d]).
    pub rows_step: P,
    /// The result c̃: each column of ĉ restricted to [a, b] in u,
    /// `c̃_{i,j} = ĉ_j[a^<m-i>, b^<i>] = c[a^<m-i>, b^<i>; c^<n-j>, d^<j>]`, on the domain
    /// [a, b] x [c, d] (so it gives the same points as the patch at the same parameters; call
    /// `with_domain(0, 1, 0, 1)` to read it over the unit square, the mesh is the same).
    pub result: P,
}

/// The four pieces of a subdivision at (u₀, v₀), indexed as the mesh: `pieces[0][0]` on
/// [a, u₀] x [c, v₀], `pieces[0][1]` on [a, u₀] x [v₀, d], `pieces[1][0]` on [u₀, b] x [c, v₀],
/// `pieces[1][1]` on [u₀, b] x [v₀, d].
pub type Quadrants<P> = [[P; 2]; 2];

fn check_args(param: &'static str, degree: usize, found: usize) -> Result<(), SurfaceError> {
    if degree == found {
        Ok(())
    } else {
        Err(SurfaceError::BlossomArguments {
            param,
            degree,
            found,
        })
    }
}

/// The polar form of a mesh at local arguments, columns first.
fn mesh_blossom<S: Scalar>(mesh: &Mesh<S>, us: &[S], vs: &[S]) -> Result<Point<S>, SurfaceError> {
    check_args("u", mesh.rows() - 1, us.len())?;
    check_args("v", mesh.cols() - 1, vs.len())?;
    let row = mesh.map_columns(|col| Ok::<_, SurfaceError>(vec![blossom(col, us)?]))?;
    Ok(blossom(row.row(0).unwrap_or_default(), vs)?)
}

/// The polar form of a mesh at local arguments, rows first.
fn mesh_blossom_rows_first<S: Scalar>(
    mesh: &Mesh<S>,
    us: &[S],
    vs: &[S],
) -> Result<Point<S>, SurfaceError> {
    check_args("u", mesh.rows() - 1, us.len())?;
    check_args("v", mesh.cols() - 1, vs.len())?;
    let col = mesh.map_rows(|row| Ok::<_, SurfaceError>(vec![blossom(row, vs)?]))?;
    Ok(blossom(&col.column(0).unwrap_or_default(), us)?)
}

/// Both steps of (13) on a mesh, at local intervals [a, b] (u) and [c, d] (v).
fn mesh_restrict<S: Scalar>(
    mesh: &Mesh<S>,
    (a, b): (&S, &S),
    (c, d): (&S, &S),
) -> Result<(Mesh<S>, Mesh<S>), SurfaceError> {
    if let Some(both) = crate::fast::restrict(mesh, (a, b), (c, d)) {
        // the same two meshes, as C R_vᵀ and R_u C R_vᵀ on integer numerators
        return Ok(both);
    }
    let rows_step = mesh.map_rows(|row| Ok::<_, SurfaceError>(restrict(row, c, d)?))?;
    let result = rows_step.map_columns(|col| Ok::<_, SurfaceError>(restrict(col, a, b)?))?;
    Ok((rows_step, result))
}

/// The four meshes of the subdivision at local (s, t): rows split in v, then columns in u.
fn mesh_subdivide<S: Scalar>(
    mesh: &Mesh<S>,
    s: &S,
    t: &S,
) -> Result<Quadrants<Mesh<S>>, SurfaceError> {
    let (mut lower_v, mut upper_v) = (Vec::new(), Vec::new());
    for row in mesh.to_rows() {
        let (l, r) = subdivide(&row, t)?;
        lower_v.push(l);
        upper_v.push(r);
    }
    let split_u = |rows: Vec<Vec<Point<S>>>| -> Result<(Mesh<S>, Mesh<S>), SurfaceError> {
        let half = Mesh::mesh(rows)?;
        let (mut left, mut right) = (Vec::new(), Vec::new());
        for col in half.to_columns() {
            let (l, r) = subdivide(&col, s)?;
            left.push(l);
            right.push(r);
        }
        Ok((Mesh::from_columns(left)?, Mesh::from_columns(right)?))
    };
    let (m00, m10) = split_u(lower_v)?;
    let (m01, m11) = split_u(upper_v)?;
    Ok([[m00, m01], [m10, m11]])
}

/// Checks a subdivision parameter lies strictly inside its interval.
fn check_interior<S: Scalar>(
    param: &'static str,
    x: &S,
    lo: &S,
    hi: &S,
) -> Result<(), SurfaceError> {
    if x > lo && x < hi {
        Ok(())
    } else {
        Err(SurfaceError::NotInterior {
            param,
            value: x.to_text(),
            interval: format!("({}, {})", lo.to_text(), hi.to_text()),
        })
    }
}

/// The domains of the four quadrants of a subdivision at (u₀, v₀).
fn quadrant_domains<S: Scalar>(domain: &Domain<S>, u0: &S, v0: &S) -> Quadrants<Domain<S>> {
    let (a, b) = domain.u_interval();
    let (c, d) = domain.v_interval();
    let lower_u = domain.with_u(a.clone(), u0.clone());
    let upper_u = domain.with_u(u0.clone(), b.clone());
    [
        [
            lower_u.with_v(c.clone(), v0.clone()),
            lower_u.with_v(v0.clone(), d.clone()),
        ],
        [
            upper_u.with_v(c.clone(), v0.clone()),
            upper_u.with_v(v0.clone(), d.clone()),
        ],
    ]
}

impl<S: Scalar> BezierSurface<S> {
    /// The polar form (12), `c[u_1, ..., u_m; v_1, ..., v_n] = c[u_1, ..., u_m][v_1, ..., v_n]`:
    /// the curve blossom at `u_1, ..., u_m` on every column, then at `v_1, ..., v_n` on the
    /// resulting row. Symmetric in each group, affine in each argument, and
    /// `c[u, ..., u; v, ..., v] = c(u, v)`. Arguments are parameters of the domain (any values);
    /// exactly m values of u and n of v.
    ///
    /// ```
    /// use cagd_surface::BezierSurface;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// let p = |c: &[i64]| Point::from_ints(c);
    /// let s = BezierSurface::<BigRational>::from_rows(vec![
    ///     vec![p(&[0, 0, 0]), p(&[1, 0, 4]), p(&[2, 0, 3])],
    ///     vec![p(&[0, 2, 1]), p(&[1, 2, 5]), p(&[2, 2, 4])],
    ///     vec![p(&[0, 4, 0]), p(&[1, 4, 4]), p(&[2, 4, 3])],
    /// ]).unwrap();
    /// // c̃_{0,0} of the restriction to [1/2, 1] x [1/3, 1] (§4)
    /// let c00 = s.blossom(&[q!(1/2), q!(1/2)], &[q!(1/3), q!(1/3)]).unwrap();
    /// assert_eq!(c00.to_text(), "(2/3, 2, 47/18)");
    /// ```
    pub fn blossom(&self, us: &[S], vs: &[S]) -> Result<Point<S>, SurfaceError> {
        let (lu, lv) = self.local_args(us, vs);
        mesh_blossom(self.mesh(), &lu, &lv)
    }

    /// The polar form (12) in the other order, `c[v_1, ..., v_n][u_1, ..., u_m]`: rows first,
    /// then the resulting column. Equal to [`BezierSurface::blossom`].
    pub fn blossom_rows_first(&self, us: &[S], vs: &[S]) -> Result<Point<S>, SurfaceError> {
        let (lu, lv) = self.local_args(us, vs);
        mesh_blossom_rows_first(self.mesh(), &lu, &lv)
    }

    fn local_args(&self, us: &[S], vs: &[S]) -> (Vec<S>, Vec<S>) {
        let d = self.domain();
        (
            us.iter().map(|u| d.local_u(u)).collect(),
            vs.iter().map(|v| d.local_v(v)).collect(),
        )
    }

    /// The restriction (13) to [a, b] x [c, d]:
    ///
    /// `c̃_{i,j} = c[a^<m-i>, b^<i>; c^<n-j>, d^<j>]`,
    ///
    /// computed in the two steps of the notes (each row restricted in v to [c, d], giving ĉ,
    /// then each column in u to [a, b]); both are returned. a < b and c < d are required; the
    /// rectangle may reach outside the domain (extrapolation).
    ///
    /// ```
    /// use cagd_surface::BezierSurface;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// let p = |c: &[i64]| Point::from_ints(c);
    /// let s = BezierSurface::<BigRational>::from_rows(vec![
    ///     vec![p(&[0, 0, 0]), p(&[1, 0, 4]), p(&[2, 0, 3])],
    ///     vec![p(&[0, 2, 1]), p(&[1, 2, 5]), p(&[2, 2, 4])],
    ///     vec![p(&[0, 4, 0]), p(&[1, 4, 4]), p(&[2, 4, 3])],
    /// ]).unwrap();
    /// let r = s.restrict(&q!(1/2), &q!(1), &q!(1/3), &q!(1)).unwrap();
    /// assert_eq!(
    ///     r.rows_step.to_text(),
    ///     "{(2/3, 0, 19/9), (4/3, 0, 11/3), (2, 0, 3); \
    ///       (2/3, 2, 28/9), (4/3, 2, 14/3), (2, 2, 4); \
    ///       (2/3, 4, 19/9), (4/3, 4, 11/3), (2, 4, 3)}"
    /// );
    /// assert_eq!(
    ///     r.result.to_text(),
    ///     "{(2/3, 2, 47/18), (4/3, 2, 25/6), (2, 2, 7/2); \
    ///       (2/3, 3, 47/18), (4/3, 3, 25/6), (2, 3, 7/2); \
    ///       (2/3, 4, 19/9), (4/3, 4, 11/3), (2, 4, 3)}"
    /// );
    /// ```
    pub fn restrict(&self, a: &S, b: &S, c: &S, d: &S) -> Result<Restriction<Self>, SurfaceError> {
        check_interval("u", a, b)?;
        check_interval("v", c, d)?;
        let dom = self.domain();
        let (rows_step, result) = mesh_restrict(
            self.mesh(),
            (&dom.local_u(a), &dom.local_u(b)),
            (&dom.local_v(c), &dom.local_v(d)),
        )?;
        Ok(Restriction {
            rows_step: BezierSurface::from_parts(rows_step, dom.with_v(c.clone(), d.clone())),
            result: BezierSurface::from_parts(
                result,
                Domain::new(a.clone(), b.clone(), c.clone(), d.clone())?,
            ),
        })
    }

    /// The subdivision at (u₀, v₀) into four patches (De Casteljau on every row at v₀, then on
    /// every column of both halves at u₀; the sides of the triangles are the new meshes, as
    /// for curves). Each piece keeps its sub-rectangle as domain (see [`Quadrants`]);
    /// (u₀, v₀) must lie strictly inside the domain.
    pub fn subdivide(&self, u0: &S, v0: &S) -> Result<Quadrants<Self>, SurfaceError> {
        let dom = self.domain();
        let (a, b) = dom.u_interval();
        let (c, d) = dom.v_interval();
        check_interior("u", u0, a, b)?;
        check_interior("v", v0, c, d)?;
        let meshes = mesh_subdivide(self.mesh(), &dom.local_u(u0), &dom.local_v(v0))?;
        let domains = quadrant_domains(dom, u0, v0);
        let [[m00, m01], [m10, m11]] = meshes;
        let [[d00, d01], [d10, d11]] = domains;
        Ok([
            [
                BezierSurface::from_parts(m00, d00),
                BezierSurface::from_parts(m01, d01),
            ],
            [
                BezierSurface::from_parts(m10, d10),
                BezierSurface::from_parts(m11, d11),
            ],
        ])
    }
}

impl<S: Scalar> RationalBezierSurface<S> {
    /// The polar form (12) of the homogeneous patch, projected: the homogeneous blossom is
    /// `(Σ w c B.., Σ w B..)[u_1, ..., u_m; v_1, ..., v_n]`, and its projection is the point
    /// the notes' algorithms produce for rational patches. An error where its weight vanishes.
    pub fn blossom(&self, us: &[S], vs: &[S]) -> Result<Point<S>, SurfaceError> {
        let h = self.homogeneous_patch().blossom(us, vs)?;
        h.from_homogeneous()
            .map(|(p, _)| p)
            .ok_or_else(|| SurfaceError::ZeroDenominator {
                at: "the polar form (its homogeneous weight is 0)".into(),
            })
    }

    /// The restriction (13) to [a, b] x [c, d], on the homogeneous mesh and projected: both
    /// steps (rows in v, then columns in u), each as a rational patch.
    pub fn restrict(&self, a: &S, b: &S, c: &S, d: &S) -> Result<Restriction<Self>, SurfaceError> {
        let r = self.homogeneous_patch().restrict(a, b, c, d)?;
        Ok(Restriction {
            rows_step: Self::from_homogeneous_patch(&r.rows_step)?,
            result: Self::from_homogeneous_patch(&r.result)?,
        })
    }

    /// The subdivision at (u₀, v₀) into four rational patches (on the homogeneous mesh).
    pub fn subdivide(&self, u0: &S, v0: &S) -> Result<Quadrants<Self>, SurfaceError> {
        let [[h00, h01], [h10, h11]] = self.homogeneous_patch().subdivide(u0, v0)?;
        Ok([
            [
                Self::from_homogeneous_patch(&h00)?,
                Self::from_homogeneous_patch(&h01)?,
            ],
            [
                Self::from_homogeneous_patch(&h10)?,
                Self::from_homogeneous_patch(&h11)?,
            ],
        ])
    }
}
