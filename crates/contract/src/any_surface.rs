//! A surface of any kind read from the problem in the scalar of its solve, evaluated, sized
//! and written as an exact value.

use crate::any::AnySurface as Patch;
use crate::convert::{at, convert_all, convert_map};
use crate::input::SurfaceIn;
use crate::value::Number;
use crate::value::{exact_map, Exact, ExactScalar};
use crate::ProblemError;
use cagd_linalg::Point;
use cagd_poly::Var;
use cagd_spline_surface::{BSplineSurface, NurbsSurface};
use cagd_surface::{BezierSurface, RationalBezierSurface};

impl<S: ExactScalar> Patch<S> {
    /// Validates the surface written at `path`, in the scalar `S`.
    pub fn read(sf: &SurfaceIn<Number>, path: &str) -> Result<Self, ProblemError> {
        // the mesh read (rectangular, of one dimension), each number in `S`, into one vector
        // of points in the order read: the patch takes it as it is (no rows, no copy)
        let mesh = |m: &cagd_surface::Mesh<Number>| -> Result<cagd_surface::Mesh<S>, ProblemError> {
            let point = |p: &Point<Number>| -> Result<Point<S>, ProblemError> {
                let mut coords = Vec::with_capacity(p.dim());
                for x in p.coords() {
                    coords.push(S::from_number(x).map_err(at(path))?);
                }
                Ok(Point::new(coords))
            };
            m.try_map(point)
        };
        let grid = |g: &Option<cagd_surface::Grid<Number>>| {
            g.as_ref()
                .map(|g| {
                    let rows = g
                        .row_slices()
                        .map(|r| convert_all::<S>(r, path))
                        .collect::<Result<Vec<_>, _>>()?;
                    cagd_surface::Grid::from_rows(rows).map_err(at(path))
                })
                .transpose()
        };
        Ok(match sf {
            SurfaceIn::Bezier { mesh: m, weights } => match grid(weights)? {
                None => Patch::Bezier(BezierSurface::try_new(mesh(m)?).map_err(at(path))?),
                Some(w) => Patch::RationalBezier(
                    RationalBezierSurface::try_new(mesh(m)?, w).map_err(at(path))?,
                ),
            },
            SurfaceIn::Expr(e) => Patch::Map(convert_map::<S>(e, path)?),
            SurfaceIn::BSpline {
                mesh: m,
                degree,
                knots,
                weights,
            } => {
                let knots = (
                    convert_all::<S>(&knots.0, path)?,
                    convert_all::<S>(&knots.1, path)?,
                );
                match grid(weights)? {
                    None => Patch::BSpline(
                        BSplineSurface::read(*degree, knots, mesh(m)?)
                            .map_err(at(path))?
                            .0,
                    ),
                    Some(w) => Patch::Nurbs(
                        NurbsSurface::read(*degree, knots, mesh(m)?, w)
                            .map_err(at(path))?
                            .0,
                    ),
                }
            }
        })
    }

    pub fn to_exact(&self) -> Exact {
        match self {
            Patch::Bezier(s) => Exact::bezier_surface(s.mesh(), None),
            Patch::RationalBezier(s) => Exact::bezier_surface(s.mesh(), Some(s.weights())),
            Patch::BSpline(s) => Exact::spline_surface(s.knots_u(), s.knots_v(), s.mesh(), None),
            Patch::Nurbs(s) => {
                Exact::spline_surface(s.knots_u(), s.knots_v(), s.mesh(), Some(s.weights()))
            }
            Patch::Map(e) => Exact::Surface(SurfaceIn::Expr(exact_map(e))),
        }
    }

    /// The rows and columns of the control mesh; `None` for an expression.
    pub fn mesh_size(&self) -> Option<(usize, usize)> {
        let m = match self {
            Patch::Bezier(s) => s.mesh(),
            Patch::RationalBezier(s) => s.mesh(),
            Patch::BSpline(s) => s.mesh(),
            Patch::Nurbs(s) => s.mesh(),
            Patch::Map(_) => return None,
        };
        Some((m.rows(), m.cols()))
    }

    /// The mesh size after elevating the bidegree by (r, s), known before the work: each
    /// direction gains r (s) points per span, one span for a Bézier patch.
    pub fn elevated_size(&self, r: usize, s: usize) -> Option<(usize, usize)> {
        let (rows, cols) = self.mesh_size()?;
        let spans = |k: &cagd_bspline::KnotVector<S>| k.spans().len();
        let (su, sv) = match self {
            Patch::BSpline(p) => (spans(p.knots_u()), spans(p.knots_v())),
            Patch::Nurbs(p) => (spans(p.knots_u()), spans(p.knots_v())),
            _ => (1, 1),
        };
        Some((
            rows.saturating_add(r.saturating_mul(su)),
            cols.saturating_add(s.saturating_mul(sv)),
        ))
    }

    /// The bidegree (m, n) of a control mesh; `None` for an expression.
    pub fn bidegree(&self) -> Option<(usize, usize)> {
        match self {
            Patch::Bezier(s) => Some(s.bidegree()),
            Patch::RationalBezier(s) => Some(s.bidegree()),
            Patch::BSpline(s) => Some(s.bidegree()),
            Patch::Nurbs(s) => Some(s.bidegree()),
            Patch::Map(_) => None,
        }
    }

    pub fn eval(&self, path: &str, u: &S, v: &S) -> Result<Point<S>, ProblemError> {
        match self {
            Patch::Bezier(s) => s.eval(u, v).map_err(at(path)),
            Patch::RationalBezier(s) => s.eval(u, v).map_err(at(path)),
            Patch::BSpline(s) => s.eval(u, v).map_err(at(path)),
            Patch::Nurbs(s) => s.eval(u, v).map_err(at(path)),
            Patch::Map(e) => e
                .eval(&[(Var::U, u.clone()), (Var::V, v.clone())])
                .map_err(at(path)),
        }
    }
}
