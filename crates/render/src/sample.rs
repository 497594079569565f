//! From exact geometry to drawing coordinates: every point is evaluated exactly at exact
//! parameters (`a + (b - a) k / n`) and only then converted to f64.

use crate::geometry::{parameter, point3};
use crate::geometry::{CurvePieces, CurvePolygon, SurfaceNet, SurfacePieces};
use crate::{Colour, Drawn, Magnitude, RenderError, Scene};
use cagd_scalar::{Print, Scalar};

/// How densely to sample a scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Density {
    /// Isoparametric cells in u and in v (cells + 1 lines each way).
    pub cells: (usize, usize),
    /// Samples per cell edge (a line of n cells has n * sub + 1 points).
    pub sub: usize,
    /// Normals on an n x n grid of interior parameters.
    pub normals: usize,
    /// Segments of each curve.
    pub curve_segments: usize,
}

/// A surface in drawing coordinates.
#[derive(Clone, Debug)]
pub(crate) struct SampledSurface {
    pub name: String,
    pub colour: Colour,
    pub mesh_colour: Colour,
    /// Drawn faint, without its mesh, under the others (the original of a restriction).
    pub faint: bool,
    /// `grid[k][l] = c(u_k, v_l)` on the fine grid of `cells.0 * sub + 1` by
    /// `cells.1 * sub + 1` points.
    pub grid: Vec<Vec<[f64; 3]>>,
    pub cells: (usize, usize),
    pub sub: usize,
    /// The control net.
    pub net: Vec<Vec<[f64; 3]>>,
    /// The exact control points as text, `(1/2, 5/6, 31/6)`.
    pub net_text: Vec<Vec<String>>,
    /// The exact weights as text, `√2/2`, for a rational surface.
    pub weights_text: Option<Vec<Vec<String>>>,
    /// Unit normals `c_u x c_v / |c_u x c_v|` at a few points: (foot, direction).
    pub normals: Vec<([f64; 3], [f64; 3])>,
}

impl SampledSurface {
    /// The four boundary curves: u = a, u = b, v = c, v = d.
    pub fn boundaries(&self) -> Vec<Vec<[f64; 3]>> {
        let first_row = self.grid.first().cloned().unwrap_or_default();
        let last_row = self.grid.last().cloned().unwrap_or_default();
        let first_col = self
            .grid
            .iter()
            .filter_map(|r| r.first().copied())
            .collect();
        let last_col = self.grid.iter().filter_map(|r| r.last().copied()).collect();
        vec![first_row, last_row, first_col, last_col]
    }
}

/// A curve in drawing coordinates.
#[derive(Clone, Debug)]
pub(crate) struct SampledCurve {
    pub name: String,
    pub colour: Colour,
    pub points: Vec<[f64; 3]>,
    pub polygon: Vec<[f64; 3]>,
    pub polygon_text: Vec<String>,
    pub weights_text: Option<Vec<String>>,
}

/// A scene in drawing coordinates.
#[derive(Clone, Debug)]
pub(crate) struct Sampled {
    pub title: Option<String>,
    pub surfaces: Vec<SampledSurface>,
    pub curves: Vec<SampledCurve>,
}

impl Sampled {
    /// Every point that is drawn (surfaces, nets, curves, polygons).
    pub fn all_points(&self) -> impl Iterator<Item = &[f64; 3]> {
        self.surfaces
            .iter()
            .flat_map(|s| s.grid.iter().chain(&s.net).flatten())
            .chain(
                self.curves
                    .iter()
                    .flat_map(|c| c.points.iter().chain(&c.polygon)),
            )
    }

    /// The bounding box `(lo, hi)` of every point drawn, coordinate by coordinate
    /// (`lo = [f64::MAX; 3]`, `hi = [f64::MIN; 3]` when nothing is drawn).
    pub fn bounds(&self) -> ([f64; 3], [f64; 3]) {
        let mut lo = [f64::MAX; 3];
        let mut hi = [f64::MIN; 3];
        for p in self.all_points() {
            for ((l, h), x) in lo.iter_mut().zip(hi.iter_mut()).zip(p) {
                *l = l.min(*x);
                *h = h.max(*x);
            }
        }
        (lo, hi)
    }

    /// The largest extent of the bounding box (0 when nothing is drawn).
    pub fn size(&self) -> f64 {
        let (lo, hi) = self.bounds();
        lo.iter().zip(&hi).map(|(l, h)| h - l).fold(0.0, f64::max)
    }
}

/// The largest magnitude of a coordinate drawn: the view's rotations and projections square
/// coordinates, which must stay finite in f64.
const LARGEST: f64 = 1e150;

/// An exact point in f64 for drawing: an error, never a point at the origin, when a
/// coordinate is beyond [`LARGEST`] (or beyond f64 altogether).
pub(crate) fn f64_point<S: Scalar>(
    p: &cagd_linalg::Point<S>,
    what: &Drawn,
) -> Result<[f64; 3], RenderError> {
    let x = point3(p).ok_or_else(|| RenderError::Dimension {
        what: what.clone(),
        dim: p.dim(),
    })?;
    for c in x {
        check_magnitude(c, what)?;
    }
    Ok(x)
}

/// An error when `c` (a coordinate, or the largest) is beyond [`LARGEST`] or not finite.
pub(crate) fn check_magnitude(c: f64, what: &Drawn) -> Result<(), RenderError> {
    if c.abs() <= LARGEST {
        return Ok(());
    }
    let why = if c.is_finite() {
        Magnitude::Coordinate {
            size: format!("{c:e}"),
        }
    } else {
        Magnitude::CoordinateBeyondF64
    };
    Err(RenderError::Range {
        what: what.clone(),
        why,
    })
}

/// An error when every point of the figure is within [`1/LARGEST`](LARGEST) of one point
/// while the exact geometry is not a point: its extent would be lost to rounding.
fn check_extent(sampled: &Sampled, exact_extent: bool) -> Result<(), RenderError> {
    let size = sampled.size();
    if exact_extent && size < 1.0 / LARGEST {
        return Err(RenderError::Range {
            what: Drawn::Figure,
            why: Magnitude::Extent {
                size: format!("{size:e}"),
            },
        });
    }
    Ok(())
}

/// Unit vector in f64, `None` for the zero vector.
pub(crate) fn unit(v: [f64; 3]) -> Option<[f64; 3]> {
    let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    (n > 0.0 && n.is_finite()).then(|| [v[0] / n, v[1] / n, v[2] / n])
}

/// Samples every surface and curve of the scene, exactly, then converts to f64.
pub(crate) fn sample<S: Scalar>(scene: &Scene<S>, d: Density) -> Result<Sampled, RenderError> {
    if scene.is_empty() {
        return Err(RenderError::EmptyScene);
    }
    // whether two exact control points differ: then the figure has an extent to draw
    let mut first: Option<cagd_linalg::Point<S>> = None;
    let mut extent = false;
    let mut spread = |p: &cagd_linalg::Point<S>| match &first {
        None => first = Some(p.clone()),
        Some(q) => extent |= q != p,
    };
    let mut surfaces = Vec::with_capacity(scene.surfaces.len());
    for (k, s) in scene.surfaces.iter().enumerate() {
        let what = Drawn::Surface {
            name: s.name.clone(),
        };
        let exact = s.geometry.exact(&what)?;
        let (nu, nv) = (d.cells.0 * d.sub, d.cells.1 * d.sub);
        let vs: Vec<S> = (0..=nv)
            .map(|j| parameter(&exact.domain.1, j, nv))
            .collect();
        let mut grid = Vec::with_capacity(nu + 1);
        for i in 0..=nu {
            let u = parameter(&exact.domain.0, i, nu);
            let row = exact.row(&u, &vs)?;
            grid.push(
                row.iter()
                    .map(|p| f64_point(p, &what))
                    .collect::<Result<Vec<_>, _>>()?,
            );
        }
        let mut normals = Vec::new();
        for i in 1..=d.normals {
            for j in 1..=d.normals {
                let (u, v) = exact.params(i, d.normals + 1, j, d.normals + 1);
                let foot = f64_point(&exact.point(&u, &v)?, &what)?;
                if let Some(n) = point3(&exact.normal(&u, &v)?).and_then(unit) {
                    normals.push((foot, n));
                }
            }
        }
        let net = s.geometry.control_net()?;
        net.points.to_rows().iter().flatten().for_each(&mut spread);
        let net_f64 = net
            .points
            .to_rows()
            .iter()
            .map(|row| row.iter().map(|p| f64_point(p, &what)).collect())
            .collect::<Result<Vec<Vec<_>>, _>>()?;
        surfaces.push(SampledSurface {
            name: s.name.clone(),
            colour: scene.surface_colour(k),
            mesh_colour: scene.mesh_colour(k),
            faint: s.faint,
            grid,
            cells: d.cells,
            sub: d.sub,
            net: net_f64,
            net_text: net
                .points
                .to_rows()
                .iter()
                .map(|row| row.iter().map(|p| p.to_text()).collect())
                .collect(),
            weights_text: net.weights.map(|w| {
                w.to_rows()
                    .iter()
                    .map(|row| row.iter().map(Print::to_text).collect())
                    .collect()
            }),
            normals,
        });
    }
    let mut curves = Vec::with_capacity(scene.curves.len());
    for (k, c) in scene.curves.iter().enumerate() {
        let what = Drawn::Curve {
            name: c.name.clone(),
        };
        let exact = c.geometry.exact(&what)?;
        let points = (0..=d.curve_segments)
            .map(|i| {
                let t = parameter(&exact.domain, i, d.curve_segments);
                f64_point(&exact.point(&t)?, &what)
            })
            .collect::<Result<Vec<_>, _>>()?;
        let control = c.geometry.control_polygon()?;
        let (mut polygon, weights) = (control.points, control.weights);
        // a control vector (weight zero) is no vertex of a polygon: the curve alone is drawn
        if weights
            .as_ref()
            .is_some_and(|w| w.iter().any(|x| x.is_zero()))
        {
            polygon.clear();
        }
        polygon.iter().for_each(&mut spread);
        curves.push(SampledCurve {
            name: c.name.clone(),
            colour: scene.curve_colour(k),
            points,
            polygon: polygon
                .iter()
                .map(|p| f64_point(p, &what))
                .collect::<Result<_, _>>()?,
            polygon_text: polygon.iter().map(|p| p.to_text()).collect(),
            weights_text: weights.map(|w| w.iter().map(Print::to_text).collect()),
        });
    }
    let sampled = Sampled {
        title: scene.title.clone(),
        surfaces,
        curves,
    };
    check_extent(&sampled, extent)?;
    Ok(sampled)
}
