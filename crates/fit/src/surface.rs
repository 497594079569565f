//! Tensor-grid interpolation by a Bézier patch (the notes' chapter 5, §7, eqs. (26)-(27)):
//! the data a_ij = c(u_i, v_j) fix a patch of bidegree (m, n), found by two passes of curve
//! interpolation.

use crate::bezier::local_parameters;
use crate::data::{check_distinct_in, check_grid};
use crate::{bernstein_matrix, Direction, FitError};
use cagd_linalg::{Factorization, Matrix, Point};
use cagd_record::{NoSteps, Record};
use cagd_scalar::Scalar;
use cagd_surface::{BezierSurface, Mesh};

/// The order of the two passes of a grid interpolation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum PassOrder {
    /// First each row of data (fixed u_i, interpolated in v), then each column of the result
    /// (interpolated in u): the notes' order, `C̃ B_Vᵗ = A`, then `B_U C = C̃`.
    #[default]
    RowsFirst,
    /// First each column of data (fixed v_j, interpolated in u), then each row of the result
    /// (interpolated in v): `B_U Ĉ = A`, then `C B_Vᵗ = Ĉ`. The same mesh.
    ColumnsFirst,
}

/// One step of a tensor-grid interpolation in two passes (§7), in the order they are made:
/// the matrix of the curve problems in u, the one in v, then the mesh after the first pass.
#[derive(Clone, Debug, PartialEq)]
pub enum GridStep<S: Scalar> {
    /// The matrix of every curve problem in u: for a Bézier patch `B_U = (B_k^m(u_i))`,
    /// (m + 1) × (m + 1), eq. (27); for a bicubic spline the (M + 3) × (M + 3) matrix of each
    /// cubic spline in u (start condition, M + 1 interpolation rows, end condition: see
    /// [`crate::cubic_spline_system`]).
    MatrixU(Matrix<S>),
    /// The matrix of every curve problem in v: `B_V = (B_l^n(v_j))`, eq. (27), or the
    /// (N + 3) × (N + 3) matrix of each cubic spline in v.
    MatrixV(Matrix<S>),
    /// The mesh after the first pass. Bézier: rows first, `C̃ = B_U C`, the solution of
    /// `C̃ B_Vᵗ = A` (row i of C̃ is the Bézier polygon through row i of the data); columns
    /// first, `Ĉ = C B_Vᵗ`, the solution of `B_U Ĉ = A`. Bicubic spline: rows first, the
    /// (M + 1) × (N + 3) points d̃_ij, row i the B-spline polygon through row i of the data;
    /// columns first, the (M + 3) × (N + 1) points, column j the polygon through column j.
    FirstPass {
        /// The order of the passes.
        order: PassOrder,
        /// The mesh.
        mesh: Mesh<S>,
    },
}

/// The two passes of a grid interpolation in `order`, `rows` solving one row of data and
/// `columns` one column; the mesh after the first pass is recorded.
pub(crate) fn two_passes<S: Scalar>(
    data: &Mesh<S>,
    order: PassOrder,
    rows: impl Fn(&[Point<S>]) -> Result<Vec<Point<S>>, FitError>,
    columns: impl Fn(&[Point<S>]) -> Result<Vec<Point<S>>, FitError>,
    rec: &mut impl Record<GridStep<S>>,
) -> Result<Mesh<S>, FitError> {
    let (first, mesh) = match order {
        PassOrder::RowsFirst => {
            let tilde = data.map_rows(rows)?;
            let mesh = tilde.map_columns(columns)?;
            (tilde, mesh)
        }
        PassOrder::ColumnsFirst => {
            let hat = data.map_columns(columns)?;
            let mesh = hat.map_rows(rows)?;
            (hat, mesh)
        }
    };
    rec.record(|| GridStep::FirstPass { order, mesh: first });
    Ok(mesh)
}

/// The patch of bidegree (m, n) through a grid of (m + 1)(n + 1) data points,
/// `c(u_i, v_j) = a_ij` (eq. (26)), rows first. See [`interpolate_bezier_surface_in_passes`].
///
/// ```
/// use cagd_fit::interpolate_bezier_surface;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// use cagd_surface::Mesh;
/// // z = u v sampled at u, v ∈ {0, 1/2, 1}: the patch of bidegree (2, 2) of the function.
/// let t = [q!(0), q!(1/2), q!(1)];
/// let data: Mesh<BigRational> = Mesh::from_fn(3, 3, |i, j| {
///     Point::new(vec![t[i].clone(), t[j].clone(), t[i].clone() * &t[j]])
/// });
/// let s = interpolate_bezier_surface(&t, &t, &data).unwrap();
/// assert_eq!(s.eval(&q!(1/3), &q!(3/4)).unwrap().to_text(), "(1/3, 3/4, 1/4)");
/// ```
pub fn interpolate_bezier_surface<S: Scalar>(
    u: &[S],
    v: &[S],
    data: &Mesh<S>,
) -> Result<BezierSurface<S>, FitError> {
    check_grid(u, v, data)?;
    check_distinct_in(Direction::U, u)?;
    check_distinct_in(Direction::V, v)?;
    let (local_u, a, b) = local_parameters(u);
    let (local_v, c, d) = local_parameters(v);
    let points: Vec<&Point<S>> = data.iter().collect();
    if let Some(control) =
        crate::fast::interpolate_grid(&local_u, &local_v, data.rows(), data.cols(), &points)
    {
        // the same mesh, C = B_U⁻¹ A B_V⁻ᵀ with B⁻¹ from its Bernstein–Vandermonde structure
        let rows = control.chunks(data.cols()).map(<[_]>::to_vec).collect();
        return on_domain(BezierSurface::try_new(Mesh::mesh(rows)?)?, [a, b, c, d]);
    }
    interpolate_bezier_surface_in_passes(u, v, data, PassOrder::RowsFirst, &mut NoSteps)
}

/// The patch on [a, b] x [c, d] (kept on the unit square when that is the domain).
fn on_domain<S: Scalar>(
    surface: BezierSurface<S>,
    [a, b, c, d]: [S; 4],
) -> Result<BezierSurface<S>, FitError> {
    if a.is_zero() && b.is_one() && c.is_zero() && d.is_one() {
        Ok(surface)
    } else {
        Ok(surface.with_domain(a, b, c, d)?)
    }
}

/// Tensor-grid interpolation by a Bézier patch in two passes of curve problems, recording
/// B_U, B_V and the mesh after the first pass ([`GridStep`]; the notes' eqs. (26)-(27)).
///
/// The data a_ij = c(u_i, v_j), i = 0..m (row i of `data`), j = 0..n (column j), fix the patch
/// of bidegree (m, n) with
///
/// `B_U C B_Vᵗ = A`,  `B_U = (B_k^m(u_i))`,  `B_V = (B_l^n(v_j))`,
///
/// one system per coordinate (A_x, A_y, A_z, see [`coordinate_matrices`]). Instead of one
/// system of (m + 1)(n + 1) unknowns it solves two families of curve problems: rows first,
/// `C̃ B_Vᵗ = A` (the Bézier curve through each row of data) and then `B_U C = C̃` (through each
/// column of C̃); columns first, `B_U Ĉ = A` and then `C B_Vᵗ = Ĉ`. Both orders give the same
/// mesh `C = B_U⁻¹ A (B_Vᵗ)⁻¹`. B_U and B_V are each factored once, for every row, column and
/// coordinate.
///
/// The parameters must be distinct in each direction (any order). The domain is [0, 1] in a
/// direction whose parameters all lie there, else [min, max] of them (as for curves,
/// [`crate::bezier_domain`]). [`interpolate_bezier_surface`] gives the same patch, from the
/// integers when it can.
///
/// ```
/// use cagd_fit::{interpolate_bezier_surface_in_passes, GridStep, PassOrder};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// use cagd_surface::Mesh;
/// // A bilinear patch through four corners: the mesh is the data.
/// let data: Mesh<BigRational> = Mesh::mesh(vec![
///     vec![Point::from_ints(&[0, 0, 1]), Point::from_ints(&[0, 1, 2])],
///     vec![Point::from_ints(&[1, 0, 3]), Point::from_ints(&[1, 1, 5])],
/// ]).unwrap();
/// let mut steps = Vec::new();
/// let (u, v) = ([q!(0), q!(1)], [q!(0), q!(1)]);
/// let surface =
///     interpolate_bezier_surface_in_passes(&u, &v, &data, PassOrder::RowsFirst, &mut steps)
///         .unwrap();
/// assert!(matches!(&steps[0], GridStep::MatrixU(b_u) if b_u.to_text() == "1  0\n0  1"));
/// assert_eq!(surface.mesh(), &data);
/// ```
pub fn interpolate_bezier_surface_in_passes<S: Scalar>(
    u: &[S],
    v: &[S],
    data: &Mesh<S>,
    order: PassOrder,
    rec: &mut impl Record<GridStep<S>>,
) -> Result<BezierSurface<S>, FitError> {
    check_grid(u, v, data)?;
    check_distinct_in(Direction::U, u)?;
    check_distinct_in(Direction::V, v)?;
    let (local_u, a, b) = local_parameters(u);
    let (local_v, c, d) = local_parameters(v);
    let b_u = bernstein_matrix(u.len() - 1, &local_u);
    let b_v = bernstein_matrix(v.len() - 1, &local_v);
    let in_u = Factorization::new(&b_u)?;
    let in_v = Factorization::new(&b_v)?;
    rec.record(|| GridStep::MatrixU(b_u));
    rec.record(|| GridStep::MatrixV(b_v));
    let rows = |row: &[Point<S>]| Ok::<_, FitError>(in_v.solve_points(row)?);
    let columns = |column: &[Point<S>]| Ok::<_, FitError>(in_u.solve_points(column)?);
    let mesh = two_passes(data, order, rows, columns, rec)?;
    on_domain(BezierSurface::try_new(mesh)?, [a, b, c, d])
}

/// The coordinate matrices of a grid of points: for a mesh C, `C_x, C_y, C_z` (one matrix per
/// coordinate, entry (i, j) the coordinate of c_ij), as the notes split A and C in eq. (27).
///
/// ```
/// use cagd_fit::coordinate_matrices;
/// use cagd_linalg::Point;
/// use cagd_scalar::BigRational;
/// use cagd_surface::Mesh;
/// let c: Mesh<BigRational> = Mesh::mesh(vec![
///     vec![Point::from_ints(&[0, 0, 1]), Point::from_ints(&[0, 1, 2])],
///     vec![Point::from_ints(&[1, 0, 3]), Point::from_ints(&[1, 1, 5])],
/// ]).unwrap();
/// let [x, y, z] = <[_; 3]>::try_from(coordinate_matrices(&c).unwrap()).unwrap();
/// assert_eq!((x.to_text(), y.to_text(), z.to_text()),
///     ("0  0\n1  1".into(), "0  1\n0  1".into(), "1  2\n3  5".into()));
/// ```
pub fn coordinate_matrices<S: Scalar>(mesh: &Mesh<S>) -> Result<Vec<Matrix<S>>, FitError> {
    let dim = mesh.get(0, 0).map_or(0, Point::dim);
    for ((i, j), p) in mesh.indexed() {
        if p.dim() != dim {
            return Err(FitError::DimensionMismatch {
                what: crate::Datum::GridEntry { row: i, col: j },
                expected: dim,
                found: p.dim(),
            });
        }
    }
    Ok((0..dim)
        .map(|k| {
            Matrix::from_fn(mesh.rows(), mesh.cols(), |i, j| {
                mesh.get(i, j)
                    .and_then(|p| p.coords().get(k))
                    .cloned()
                    .unwrap_or_else(S::zero)
            })
        })
        .collect())
}
