//! Evaluation: the matrix form (1), De Casteljau in two passes (9)-(11), the rational
//! quotient (5).

use crate::{BezierSurface, Mesh, RationalBezierSurface, SurfaceError};
use cagd_bezier::{bernstein_all, de_casteljau, de_casteljau_triangle};
use cagd_linalg::Point;
use cagd_record::{NoSteps, Record};
use cagd_scalar::Scalar;

/// The matrix form (1) at local parameters (s, t): `(B_0^m(s) ... B_m^m(s)) C (B_0^n(t) ...
/// B_n^n(t))^T`, the mesh times the column of Bernstein values first, then the row.
pub(crate) fn matrix_form<S: Scalar>(mesh: &Mesh<S>, s: &S, t: &S) -> Point<S> {
    let dim = mesh.dim();
    let bu = bernstein_all(mesh.rows() - 1, s);
    let bv = bernstein_all(mesh.cols() - 1, t);
    let column: Vec<Point<S>> = (0..mesh.rows())
        .map(|i| Point::combination(mesh.row(i).unwrap_or_default(), &bv, dim))
        .collect();
    Point::combination(&column, &bu, dim)
}

/// De Casteljau columns first (9), then on the row of results (10)-(11), at local (s, t),
/// recording each triangle when the steps are kept (the point alone otherwise).
pub(crate) fn columns_first<S: Scalar>(
    mesh: &Mesh<S>,
    s: &S,
    t: &S,
    rec: &mut impl Record<DeCasteljauStep<S>>,
) -> Result<Point<S>, SurfaceError> {
    let mut j = 0;
    let row = mesh.map_columns(|col| {
        let point = if rec.on() {
            let levels = de_casteljau_triangle(col, s)?;
            let point = apex(&levels)?;
            rec.record(|| DeCasteljauStep::Column { j, levels });
            point
        } else {
            de_casteljau(col, s)?
        };
        j += 1;
        Ok::<_, SurfaceError>(vec![point])
    })?;
    let polygon = row.row(0).unwrap_or_default();
    if rec.on() {
        let levels = de_casteljau_triangle(polygon, t)?;
        let point = apex(&levels)?;
        rec.record(|| DeCasteljauStep::Row(levels));
        return Ok(point);
    }
    Ok(de_casteljau(polygon, t)?)
}

/// The last point of a De Casteljau triangle.
fn apex<S: Scalar>(levels: &[Vec<Point<S>>]) -> Result<Point<S>, SurfaceError> {
    levels
        .last()
        .and_then(|level| level.first())
        .cloned()
        .ok_or(SurfaceError::EmptyMesh)
}

/// De Casteljau rows first, then on the column of results, at local (s, t).
pub(crate) fn rows_first<S: Scalar>(
    mesh: &Mesh<S>,
    s: &S,
    t: &S,
) -> Result<Point<S>, SurfaceError> {
    let col = mesh.map_rows(|row| Ok::<_, SurfaceError>(vec![de_casteljau(row, t)?]))?;
    Ok(de_casteljau(&col.column(0).unwrap_or_default(), s)?)
}

/// One step of De Casteljau's algorithm on a patch, columns first, as the notes write it in
/// (9)-(11): the triangle of each column, then the triangle of the row of their points.
#[derive(Clone, PartialEq, Debug)]
pub enum DeCasteljauStep<S> {
    /// The triangle (9) of column j: `levels[r][i] = c_{i,j}^{r,0}(u)`, r = 0, ..., m.
    Column {
        /// The column j.
        j: usize,
        /// The levels r = 0, ..., m.
        levels: Vec<Vec<Point<S>>>,
    },
    /// The triangle (10) on the polygon `c_{0,0}^{m,0}, ..., c_{0,n}^{m,0}`:
    /// `levels[s][j] = c_{0,j}^{m,s}(u, v)`, s = 0, ..., n; its last point is
    /// `c(u, v) = c_{0,0}^{m,n}(u, v)` of (11).
    Row(Vec<Vec<Point<S>>>),
}

impl<S: Scalar> BezierSurface<S> {
    /// The point c(u, v) for (u, v) in the domain, by De Casteljau's algorithm (9)-(11)
    /// (columns first). Outside the domain it is an [`SurfaceError::OutOfDomain`] error; the
    /// raw algorithms ([`BezierSurface::eval_matrix`], ...) extrapolate instead.
    ///
    /// ```
    /// use cagd_surface::BezierSurface;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// // the graph of f(x, y) = xy (notes, §2)
    /// let s = BezierSurface::<BigRational>::from_rows(vec![
    ///     vec![Point::from_ints(&[0, 0, 0]), Point::from_ints(&[0, 1, 0])],
    ///     vec![Point::from_ints(&[1, 0, 0]), Point::from_ints(&[1, 1, 1])],
    /// ]).unwrap();
    /// assert_eq!(s.eval(&q!(1/2), &q!(1/3)).unwrap().to_text(), "(1/2, 1/3, 1/6)");
    /// assert_eq!(
    ///     s.eval(&q!(2), &q!(0)).unwrap_err().to_string(),
    ///     "parameter u = 2 is outside the domain [0, 1] x [0, 1]"
    /// );
    /// ```
    pub fn eval(&self, u: &S, v: &S) -> Result<Point<S>, SurfaceError> {
        let (s, t) = self.domain().check(u, v)?;
        if let Some(p) = self
            .integer_mesh()
            .and_then(|coords| crate::fast::eval(self.mesh(), coords, &s, &t))
        {
            // the same point, by the matrix form on integer numerators
            return Ok(p);
        }
        columns_first(self.mesh(), &s, &t, &mut NoSteps)
    }

    /// The matrix form (1):
    ///
    /// `c(u, v) = (B_0^m(u) ... B_m^m(u)) (c_{i,j}) (B_0^n(v) ... B_n^n(v))^T`.
    ///
    /// Any (u, v) is accepted (outside the domain it extrapolates).
    pub fn eval_matrix(&self, u: &S, v: &S) -> Point<S> {
        let (s, t) = self.domain().local(u, v);
        matrix_form(self.mesh(), &s, &t)
    }

    /// De Casteljau's algorithm on each column (9), `c_{i,j}^{r,0} = (1 - u) c_{i,j}^{r-1,0} +
    /// u c_{i+1,j}^{r-1,0}`, then on the resulting row (10),
    /// `c_{0,j}^{m,s} = (1 - v) c_{0,j}^{m,s-1} + v c_{0,j+1}^{m,s-1}`, giving
    /// `c(u, v) = c_{0,0}^{m,n}` (11). Any (u, v) is accepted.
    pub fn de_casteljau_columns_first(&self, u: &S, v: &S) -> Result<Point<S>, SurfaceError> {
        self.de_casteljau_columns_first_recorded(u, v, &mut NoSteps)
    }

    /// [`BezierSurface::de_casteljau_columns_first`], recording every intermediate point of
    /// (9)-(11) for a step-by-step answer: the triangle of each column j, then the triangle of
    /// the row. Any (u, v) is accepted.
    ///
    /// ```
    /// use cagd_surface::{BezierSurface, DeCasteljauStep};
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// let s = BezierSurface::<BigRational>::from_rows(vec![
    ///     vec![Point::from_ints(&[0, 0, 0]), Point::from_ints(&[0, 1, 0])],
    ///     vec![Point::from_ints(&[1, 0, 0]), Point::from_ints(&[1, 1, 1])],
    /// ]).unwrap();
    /// let mut steps = Vec::new();
    /// let p = s.de_casteljau_columns_first_recorded(&q!(1/2), &q!(1/3), &mut steps).unwrap();
    /// assert_eq!(p.to_text(), "(1/2, 1/3, 1/6)");
    /// assert_eq!(steps.len(), 3);
    /// assert!(matches!(&steps[2], DeCasteljauStep::Row(levels) if levels[1][0] == p));
    /// ```
    pub fn de_casteljau_columns_first_recorded(
        &self,
        u: &S,
        v: &S,
        rec: &mut impl Record<DeCasteljauStep<S>>,
    ) -> Result<Point<S>, SurfaceError> {
        let (s, t) = self.domain().local(u, v);
        columns_first(self.mesh(), &s, &t, rec)
    }

    /// De Casteljau's algorithm on each row (in v), then on the resulting column (in u): the
    /// symmetric order of §4, with the same point. Any (u, v) is accepted.
    pub fn de_casteljau_rows_first(&self, u: &S, v: &S) -> Result<Point<S>, SurfaceError> {
        let (s, t) = self.domain().local(u, v);
        rows_first(self.mesh(), &s, &t)
    }
}

/// Projects a homogeneous point (weight last), naming (u, v) when the weight vanishes.
pub(crate) fn project<S: Scalar>(h: &Point<S>, u: &S, v: &S) -> Result<Point<S>, SurfaceError> {
    h.from_homogeneous()
        .map(|(p, _)| p)
        .ok_or_else(|| SurfaceError::ZeroDenominator {
            at: format!("(u, v) = ({}, {})", u.to_text(), v.to_text()),
        })
}

impl<S: Scalar> RationalBezierSurface<S> {
    /// The point c(u, v) for (u, v) in the domain: De Casteljau (9)-(11) on the homogeneous
    /// mesh `(w_{i,j} c_{i,j}, w_{i,j})`, projected. An error outside the domain or where the
    /// denominator `Σ w_{i,j} B_i^m(u) B_j^n(v)` vanishes (possible with negative weights).
    pub fn eval(&self, u: &S, v: &S) -> Result<Point<S>, SurfaceError> {
        let (s, t) = self.domain().check(u, v)?;
        project(
            &columns_first(&self.homogeneous(), &s, &t, &mut NoSteps)?,
            u,
            v,
        )
    }

    /// The quotient (5),
    ///
    /// `c(u, v) = Σ_i Σ_j w_{i,j} c_{i,j} B_i^m(u) B_j^n(v) / Σ_i Σ_j w_{i,j} B_i^m(u) B_j^n(v)`,
    ///
    /// numerator and denominator by the matrix form (1). Any (u, v) is accepted; an error where
    /// the denominator vanishes.
    pub fn eval_quotient(&self, u: &S, v: &S) -> Result<Point<S>, SurfaceError> {
        let (s, t) = self.domain().local(u, v);
        project(&matrix_form(&self.homogeneous(), &s, &t), u, v)
    }

    /// The homogeneous point `(Σ w c B B, Σ w B B)` (weight last) at any (u, v).
    pub fn eval_homogeneous(&self, u: &S, v: &S) -> Result<Point<S>, SurfaceError> {
        let (s, t) = self.domain().local(u, v);
        columns_first(&self.homogeneous(), &s, &t, &mut NoSteps)
    }

    /// De Casteljau on the homogeneous mesh, rows first, projected. Any (u, v) is accepted.
    pub fn de_casteljau_rows_first(&self, u: &S, v: &S) -> Result<Point<S>, SurfaceError> {
        let (s, t) = self.domain().local(u, v);
        project(&rows_first(&self.homogeneous(), &s, &t)?, u, v)
    }
}
