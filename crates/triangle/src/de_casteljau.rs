//! The De Casteljau algorithm on triangles, with every intermediate level.

use crate::bernstein::int;
use crate::index::{multi_indices, pos};
use crate::{Barycentric, Direction, MultiIndex, TriangularPatch};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// One step of De Casteljau on triangles: from a net of degree m + 1 to the net of degree m
///
/// b'_{ijk} = x_1 b_{i+1,j,k} + x_2 b_{i,j+1,k} + x_3 b_{i,j,k+1},  i + j + k = m.
///
/// `x` is any triple: a barycentric point, a direction (the derivative), or a mix (the blossom
/// is multilinear in its arguments, so any triple is allowed here).
pub(crate) fn step<S: Scalar>(net: &[Point<S>], new_degree: usize, x: &[S; 3]) -> Vec<Point<S>> {
    // a net of degree new_degree + 1 holds every position read here
    let dim = net.first().map_or(0, Point::dim);
    let at = |j: usize, k: usize| {
        net.get(pos(j, k))
            .cloned()
            .unwrap_or_else(|| Point::zero(dim))
    };
    multi_indices(new_degree)
        .map(|(_, j, k)| {
            let mut p = at(j, k).scale(&x[0]);
            p.add_scaled(&at(j + 1, k), &x[1]);
            p.add_scaled(&at(j, k + 1), &x[2]);
            p
        })
        .collect()
}

/// One level of the De Casteljau algorithm on a triangle (or of a blossom): the points
/// b^l_{ijk}, i + j + k = n - l, in the order of a control net of degree n - l (see
/// [`crate::multi_indices`]); level 0 is the control net.
pub type Level<S> = Vec<Point<S>>;

/// All the levels of the De Casteljau algorithm on a triangle (or of a blossom, which takes a
/// different argument at each level).
///
/// Level 0 is the control net b^0_{ijk} = b_{ijk} (i + j + k = n); level l holds the points
///
/// b^l_{ijk} = x_1 b^{l-1}_{i+1,j,k} + x_2 b^{l-1}_{i,j+1,k} + x_3 b^{l-1}_{i,j,k+1},
/// i + j + k = n - l,
///
/// in the same order as a control net of degree n - l (see [`crate::multi_indices`]); level n
/// is the single point b^n_{000} = b(x).
#[derive(Clone, PartialEq)]
pub struct DeCasteljau<S> {
    degree: usize,
    levels: Vec<Vec<Point<S>>>,
    /// The origin of the points' space (what an empty net would evaluate to).
    origin: Point<S>,
}

impl<S: Scalar> DeCasteljau<S> {
    /// Runs the steps with the arguments `args` in turn (all of them x for the evaluation at x;
    /// x_1, ..., x_n for the blossom). There must be exactly n arguments.
    pub(crate) fn run<'a>(
        patch: &TriangularPatch<S>,
        args: impl IntoIterator<Item = &'a [S; 3]>,
    ) -> Self {
        let n = patch.degree();
        let mut levels = vec![patch.points().to_vec()];
        for (l, x) in (1..=n).zip(args) {
            let next = match levels.last() {
                Some(previous) => step(previous, n - l, x),
                None => break,
            };
            levels.push(next);
        }
        let origin = Point::zero(patch.dim());
        DeCasteljau {
            degree: n,
            levels,
            origin,
        }
    }

    /// The degree n of the patch (level n is the last one).
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// All levels, level 0 (the control net) first.
    pub fn levels(&self) -> &[Vec<Point<S>>] {
        &self.levels
    }

    /// The points of level l, or `None` if l > n.
    pub fn level(&self, l: usize) -> Option<&[Point<S>]> {
        self.levels.get(l).map(Vec::as_slice)
    }

    /// The point b^l_{ijk}, or `None` unless i + j + k = n - l.
    pub fn point(&self, l: usize, i: usize, j: usize, k: usize) -> Option<&Point<S>> {
        let level = self.levels.get(l)?;
        let p = crate::position(self.degree.checked_sub(l)?, i, j, k)?;
        level.get(p)
    }

    /// The last point b^n_{000}: the value b(x) of the patch (or of the blossom).
    pub fn value(&self) -> &Point<S> {
        // Level n always exists and holds one point: `run` makes n steps from a valid net.
        self.levels
            .get(self.degree)
            .and_then(|level| level.first())
            .or_else(|| self.levels.last().and_then(|level| level.first()))
            .unwrap_or(&self.origin)
    }

    /// The value, consuming the levels.
    pub fn into_value(self) -> Point<S> {
        let degree = self.degree;
        let origin = self.origin;
        self.levels
            .into_iter()
            .nth(degree)
            .and_then(|level| level.into_iter().next())
            .unwrap_or(origin)
    }

    /// The directional derivative read off level n - 1 (the three points that span the tangent
    /// plane at b(x)):
    ///
    /// D_d b(x) = n (d_1 b^{n-1}_{100} + d_2 b^{n-1}_{010} + d_3 b^{n-1}_{001}).
    ///
    /// Meaningful when the levels are those of [`TriangularPatch::de_casteljau`]; zero for
    /// degree 0.
    pub fn directional_derivative(&self, d: &Direction<S>) -> Point<S> {
        match self.degree.checked_sub(1) {
            None => Point::zero(self.value().dim()),
            Some(m) => {
                let level = self.levels.get(m).map_or(&[][..], Vec::as_slice);
                match step(level, 0, d.coords()).into_iter().next() {
                    Some(last) => last.scale(&int::<S>(self.degree)),
                    None => Point::zero(self.value().dim()),
                }
            }
        }
    }

    /// The points of every level as text, e.g. for degree 1 at the centroid:
    ///
    /// ```text
    /// level 0:
    ///   b^0_{1,0,0} = (0, 0)
    ///   ...
    /// level 1:
    ///   b^1_{0,0,0} = (1/3, 1/3)
    /// ```
    pub fn to_text(&self) -> String {
        let mut out = Vec::new();
        for (l, level) in self.levels.iter().enumerate() {
            out.push(format!("level {l}:"));
            let indices: Vec<MultiIndex> = multi_indices(self.degree - l).collect();
            for ((i, j, k), p) in indices.into_iter().zip(level) {
                out.push(format!("  b^{l}_{{{i},{j},{k}}} = {}", p.to_text()));
            }
        }
        out.join("\n")
    }
}

impl<S: Scalar> std::fmt::Debug for DeCasteljau<S> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("DeCasteljau")
            .field("degree", &self.degree)
            .field("levels", &self.levels)
            .finish()
    }
}

impl<S: Scalar> TriangularPatch<S> {
    /// Every level of the De Casteljau algorithm at x, for step-by-step output;
    /// [`DeCasteljau::value`] is b(x).
    ///
    /// ```
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// use cagd_triangle::{Barycentric, TriangularPatch};
    /// let net = vec![
    ///     Point::from_ints(&[0, 0]),
    ///     Point::from_ints(&[3, 0]),
    ///     Point::from_ints(&[0, 3]),
    /// ];
    /// let patch = TriangularPatch::<BigRational>::try_new(1, net).unwrap();
    /// let steps = patch.de_casteljau(&Barycentric::centroid());
    /// assert_eq!(steps.value().to_text(), "(1, 1)");
    /// assert_eq!(steps.level(0).unwrap().len(), 3);
    /// ```
    pub fn de_casteljau(&self, x: &Barycentric<S>) -> DeCasteljau<S> {
        DeCasteljau::run(self, std::iter::repeat(x.coords()))
    }

    /// The point b(x) of the patch by the De Casteljau algorithm on triangles
    /// (n steps of b^l_{ijk} = r b^{l-1}_{i+1,j,k} + s b^{l-1}_{i,j+1,k} + t b^{l-1}_{i,j,k+1}).
    ///
    /// It equals the Bernstein sum [`TriangularPatch::evaluate_bernstein`] exactly.
    pub fn evaluate(&self, x: &Barycentric<S>) -> Point<S> {
        let n = self.degree();
        let mut net = self.points().to_vec();
        for l in 1..=n {
            net = step(&net, n - l, x.coords());
        }
        net.swap_remove(0)
    }

    /// The point at the parameters (u, v) of the domain triangle: b(1 - u - v, u, v).
    pub fn evaluate_uv(&self, u: S, v: S) -> Point<S> {
        self.evaluate(&Barycentric::from_uv(u, v))
    }
}
