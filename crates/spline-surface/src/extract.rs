//! Bézier extraction: the grid of Bézier (or rational Bézier) patches of a B-spline (or NURBS)
//! surface, each on its parameter rectangle.

use crate::{BSplineSurface, Direction, NurbsSurface, SplineSurfaceError};
use cagd_bspline::insert_breakpoints;
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use cagd_surface::{BezierSurface, Mesh, RationalBezierSurface};

/// The polynomial pieces of a surface: `patches[a][b]` is the piece on the rectangle
/// `u_intervals[a] x v_intervals[b]`, with that rectangle as its domain.
#[derive(Clone, Debug, PartialEq)]
pub struct BezierPatches<S, P> {
    /// The spans `[u_k, u_{k+1}]` of the domain in u, left to right.
    pub u_intervals: Vec<(S, S)>,
    /// The spans `[v_l, v_{l+1}]` of the domain in v, left to right.
    pub v_intervals: Vec<(S, S)>,
    /// One patch per pair of spans: row a of this grid goes with `u_intervals[a]`, column b
    /// with `v_intervals[b]`.
    pub patches: Vec<Vec<P>>,
}

/// The parameter rectangle of a patch: its interval in u and its interval in v.
pub type Rectangle<'a, S> = (&'a (S, S), &'a (S, S));

impl<S: Scalar, P> BezierPatches<S, P> {
    /// The number of pieces (M, N) in u and in v.
    pub fn shape(&self) -> (usize, usize) {
        (self.u_intervals.len(), self.v_intervals.len())
    }

    /// The patch on `u_intervals[a] x v_intervals[b]`.
    pub fn get(&self, a: usize, b: usize) -> Option<&P> {
        self.patches.get(a).and_then(|row| row.get(b))
    }

    /// The patches with their rectangles, row by row.
    pub fn iter(&self) -> impl Iterator<Item = (Rectangle<'_, S>, &P)> {
        self.patches
            .iter()
            .zip(&self.u_intervals)
            .flat_map(move |(row, iu)| {
                row.iter()
                    .zip(&self.v_intervals)
                    .map(move |(patch, iv)| ((iu, iv), patch))
            })
    }

    /// One line per patch: `[a, b] x [c, d]: ` followed by `text(patch)`.
    fn text_with(&self, text: impl Fn(&P) -> String) -> String {
        self.iter()
            .map(|((iu, iv), patch)| {
                format!(
                    "[{}, {}] x [{}, {}]: {}",
                    iu.0.to_text(),
                    iu.1.to_text(),
                    iv.0.to_text(),
                    iv.1.to_text(),
                    text(patch)
                )
            })
            .collect::<Vec<_>>()
            .join("\n")
    }
}

impl<S: Scalar> BezierPatches<S, BezierSurface<S>> {
    /// One line per patch, `[0, 1] x [0, 2]: {(0, 0, 0), ...; ...}`.
    pub fn to_text(&self) -> String {
        self.text_with(BezierSurface::to_text)
    }
}

impl<S: Scalar> BezierPatches<S, RationalBezierSurface<S>> {
    /// One line per patch, `[0, 1] x [0, 1]: {...} with weights {...}`.
    pub fn to_text(&self) -> String {
        self.text_with(RationalBezierSurface::to_text)
    }
}

/// The meshes of the pieces of a surface whose breakpoints all have full multiplicity, with
/// their rectangles.
type Pieces<S> = (Vec<(S, S)>, Vec<(S, S)>, Vec<Vec<Mesh<S>>>);

impl<S: Scalar> BSplineSurface<S> {
    /// The same surface with every breakpoint of its domain (ends included) inserted up to
    /// multiplicity p in u and q in v ([`cagd_bspline::insert_breakpoints`] on every column,
    /// then on every row): the mesh of the piecewise Bézier form.
    pub fn insert_breakpoints(&self) -> Result<Self, SplineSurfaceError> {
        self.map_curves(Direction::U, insert_breakpoints)?
            .map_curves(Direction::V, insert_breakpoints)
    }

    /// The control meshes of the pieces (see [`BSplineSurface::bezier_patches`]).
    fn piece_meshes(&self) -> Result<Pieces<S>, SplineSurfaceError> {
        let full = self.insert_breakpoints()?;
        let (p, q) = full.bidegree();
        let (ku, kv) = (full.knots_u().full(), full.knots_v().full());
        let spans_u = full.knots_u().spans();
        let spans_v = full.knots_v().spans();
        let mut patches = Vec::with_capacity(spans_u.len());
        for &k in &spans_u {
            let mut row = Vec::with_capacity(spans_v.len());
            for &l in &spans_v {
                let rows: Vec<Vec<Point<S>>> = (k - p..=k)
                    .filter_map(|i| full.mesh().row(i))
                    .filter_map(|r| r.get(l - q..=l))
                    .map(<[Point<S>]>::to_vec)
                    .collect();
                row.push(Mesh::mesh(rows)?);
            }
            patches.push(row);
        }
        // a span k of a knot vector has its knots u_k < u_{k+1}
        let interval = |u: &[S], k: usize| Some((u.get(k)?.clone(), u.get(k + 1)?.clone()));
        Ok((
            spans_u.iter().filter_map(|&k| interval(ku, k)).collect(),
            spans_v.iter().filter_map(|&l| interval(kv, l)).collect(),
            patches,
        ))
    }

    /// The Bézier patches of the surface, one per pair of non-empty spans
    /// `[u_k, u_{k+1}] x [v_l, v_{l+1}]` (the notes' "algoritmo de obtención de polígonos de
    /// control", in two passes): every breakpoint is inserted until it has multiplicity p in u
    /// and q in v ([`BSplineSurface::insert_breakpoints`]); then the (p + 1) x (q + 1) block
    /// `d_{k-p..k, l-q..l}` (full convention) of the mesh is the Bézier mesh of the piece, on
    /// that rectangle. Neighbouring patches share their common boundary row or column.
    ///
    /// ```
    /// use cagd_spline_surface::BSplineSurface;
    /// use cagd_surface::Mesh;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
    /// // Quadratic in u with a simple knot at 1 (4 rows), linear in v (2 columns).
    /// let mesh = Mesh::mesh(vec![
    ///     vec![p(&[0, 0]), p(&[0, 1])],
    ///     vec![p(&[1, 0]), p(&[1, 1])],
    ///     vec![p(&[3, 0]), p(&[3, 1])],
    ///     vec![p(&[4, 0]), p(&[4, 1])],
    /// ]).unwrap();
    /// let (s, _) = BSplineSurface::read((2, 1), (vec![q!(0), q!(0), q!(1), q!(2), q!(2)], vec![q!(0), q!(1)]), mesh)
    ///     .unwrap();
    /// let pieces = s.bezier_patches().unwrap();
    /// assert_eq!(pieces.shape(), (2, 1));
    /// assert_eq!(
    ///     pieces.to_text(),
    ///     "[0, 1] x [0, 1]: {(0, 0), (0, 1); (1, 0), (1, 1); (2, 0), (2, 1)}\n\
    ///      [1, 2] x [0, 1]: {(2, 0), (2, 1); (3, 0), (3, 1); (4, 0), (4, 1)}"
    /// );
    /// ```
    pub fn bezier_patches(&self) -> Result<BezierPatches<S, BezierSurface<S>>, SplineSurfaceError> {
        let (u_intervals, v_intervals, meshes) = self.piece_meshes()?;
        let mut patches = Vec::with_capacity(meshes.len());
        for (row, iu) in meshes.into_iter().zip(&u_intervals) {
            let mut out = Vec::with_capacity(row.len());
            for (mesh, iv) in row.into_iter().zip(&v_intervals) {
                let patch = BezierSurface::try_new(mesh)?.with_domain(
                    iu.0.clone(),
                    iu.1.clone(),
                    iv.0.clone(),
                    iv.1.clone(),
                )?;
                out.push(patch);
            }
            patches.push(out);
        }
        Ok(BezierPatches {
            u_intervals,
            v_intervals,
            patches,
        })
    }
}

impl<S: Scalar> NurbsSurface<S> {
    /// The rational Bézier patches (notes, eq. (5)), one per pair of non-empty spans: the
    /// Bézier extraction of the homogeneous mesh, each piece projected to its mesh and weights.
    pub fn bezier_patches(
        &self,
    ) -> Result<BezierPatches<S, RationalBezierSurface<S>>, SplineSurfaceError> {
        let (u_intervals, v_intervals, meshes) = self.homogeneous().piece_meshes()?;
        let mut patches = Vec::with_capacity(meshes.len());
        for (row, iu) in meshes.into_iter().zip(&u_intervals) {
            let mut out = Vec::with_capacity(row.len());
            for (hmesh, iv) in row.into_iter().zip(&v_intervals) {
                let patch = RationalBezierSurface::from_homogeneous(&hmesh)?.with_domain(
                    iu.0.clone(),
                    iu.1.clone(),
                    iv.0.clone(),
                    iv.1.clone(),
                )?;
                out.push(patch);
            }
            patches.push(out);
        }
        Ok(BezierPatches {
            u_intervals,
            v_intervals,
            patches,
        })
    }
}
