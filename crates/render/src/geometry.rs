//! The exact geometry of a figure: the surfaces and curves it may hold, their control nets,
//! and their piecewise closed forms in homogeneous coordinates, evaluated exactly.
//!
//! Every surface becomes a list of polynomial pieces `H(u, v) = (w x, w y, w z, w)` (weight
//! last; w = 1 for polynomial patches), one per Bézier piece, in the surface's own parameters.
//! A point is `H / w`; the normal direction is
//!
//! `(w H_u - w_u H) x (w H_v - w_v H) = w^4 c_u x c_v`
//!
//! (first three coordinates), which points as `c_u x c_v` because `w^4 > 0`. Curves are the
//! same in one parameter `t`.

use crate::{Drawn, RenderError};
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_linalg::Point;
use cagd_poly::{control_mesh, control_polygon, Poly, Var, VecPoly};
use cagd_scalar::Scalar;
use cagd_surface::{Grid, Mesh};

pub use cagd_contract::{AnyCurve, AnySurface};

/// A control net as drawn: the points c_ij (rows i along u) and, for rational surfaces, the
/// weights w_ij.
#[derive(Clone, Debug, PartialEq)]
pub struct ControlNet<S> {
    /// The control points.
    pub points: Mesh<S>,
    /// The weights, for a rational surface.
    pub weights: Option<Grid<S>>,
}

/// A control polygon as drawn: the points and, for a rational curve, the weights.
#[derive(Clone, Debug, PartialEq)]
pub struct ControlPolygon<S> {
    /// The control points.
    pub points: Vec<Point<S>>,
    /// The weights, for a rational curve.
    pub weights: Option<Vec<S>>,
}

/// The parameter `a + (b - a) k / n`, exactly.
pub(crate) fn parameter<S: Scalar>((a, b): &(S, S), k: usize, n: usize) -> S {
    let t = S::from_ratio(k as i64, n.max(1) as i64);
    a.clone() + (b.clone() - a) * t
}

/// The polynomial map of the Bernstein degrees of a map: its degree in each variable.
fn map_mesh<S: Scalar>(c: &VecPoly<S>) -> Result<Mesh<S>, RenderError> {
    let (m, n) = (c.degree_in(Var::U) as usize, c.degree_in(Var::V) as usize);
    Ok(Mesh::mesh(control_mesh(c, Var::U, Var::V, m, n)?)?)
}

/// What a figure draws of a surface besides its points: its control net.
pub trait SurfaceNet<S: Scalar> {
    /// The control net to draw: the mesh (and weights) of the patch or spline; for a
    /// polynomial map, its Bézier mesh of bidegree (degree in u, degree in v) on [0, 1]².
    fn control_net(&self) -> Result<ControlNet<S>, RenderError>;
}

/// What a figure draws of a curve besides its points: its control polygon.
pub trait CurvePolygon<S: Scalar> {
    /// The control polygon to draw (a map's Bézier polygon on [0, 1]).
    fn control_polygon(&self) -> Result<ControlPolygon<S>, RenderError>;
}

/// The exact homogeneous pieces of a surface, evaluated by the figures.
pub(crate) trait SurfacePieces<S: Scalar> {
    /// The homogeneous closed forms of the Bézier pieces, with their rectangles.
    fn exact(&self, what: &Drawn) -> Result<ExactSurface<S>, RenderError>;
}

/// The exact homogeneous pieces of a curve.
pub(crate) trait CurvePieces<S: Scalar> {
    /// The homogeneous closed forms of the Bézier pieces in `t`, with their intervals.
    fn exact(&self, what: &Drawn) -> Result<ExactCurve<S>, RenderError>;
}

impl<S: Scalar> SurfaceNet<S> for AnySurface<S> {
    /// The control net to draw: the mesh (and weights) of the patch or spline; for a polynomial
    /// map, its Bézier mesh of bidegree (degree in u, degree in v) on [0, 1] x [0, 1].
    fn control_net(&self) -> Result<ControlNet<S>, RenderError> {
        Ok(match self {
            AnySurface::Bezier(s) => ControlNet {
                points: s.mesh().clone(),
                weights: None,
            },
            AnySurface::RationalBezier(s) => ControlNet {
                points: s.mesh().clone(),
                weights: Some(s.weights().clone()),
            },
            AnySurface::BSpline(s) => ControlNet {
                points: s.mesh().clone(),
                weights: None,
            },
            AnySurface::Nurbs(s) => ControlNet {
                points: s.mesh().clone(),
                weights: Some(s.weights().clone()),
            },
            AnySurface::Map(c) => ControlNet {
                points: map_mesh(c)?,
                weights: None,
            },
        })
    }
}

impl<S: Scalar> SurfacePieces<S> for AnySurface<S> {
    /// The homogeneous closed forms of the Bézier pieces, with their rectangles.
    fn exact(&self, what: &Drawn) -> Result<ExactSurface<S>, RenderError> {
        let mut pieces = Vec::new();
        let rect = |s: &cagd_surface::Domain<S>| {
            let (a, b) = s.u_interval();
            let (c, d) = s.v_interval();
            ((a.clone(), b.clone()), (c.clone(), d.clone()))
        };
        match self {
            AnySurface::Bezier(s) => {
                pieces.push((rect(s.domain()), polynomial_h(s.closed_form()?)));
            }
            AnySurface::RationalBezier(s) => {
                pieces.push((rect(s.domain()), s.homogeneous_patch().closed_form()?));
            }
            AnySurface::BSpline(s) => {
                for ((iu, iv), p) in s.bezier_patches()?.iter() {
                    pieces.push(((iu.clone(), iv.clone()), polynomial_h(p.closed_form()?)));
                }
            }
            AnySurface::Nurbs(s) => {
                for ((iu, iv), p) in s.bezier_patches()?.iter() {
                    let h = p.homogeneous_patch().closed_form()?;
                    pieces.push(((iu.clone(), iv.clone()), h));
                }
            }
            AnySurface::Map(c) => {
                let vars = c.vars();
                if vars.iter().any(|v| !matches!(v, Var::U | Var::V)) {
                    return Err(RenderError::Variables {
                        what: what.clone(),
                        found: var_names(&vars),
                    });
                }
                pieces.push((self.domain(), polynomial_h(c.clone())));
            }
        }
        let pieces = pieces
            .into_iter()
            .map(|((u, v), h)| {
                let h = spatial(h, what)?;
                Ok(SurfacePiece {
                    hu: h.partial(Var::U),
                    hv: h.partial(Var::V),
                    h,
                    u,
                    v,
                })
            })
            .collect::<Result<Vec<_>, RenderError>>()?;
        Ok(ExactSurface {
            what: what.clone(),
            domain: self.domain(),
            pieces,
        })
    }
}

impl<S: Scalar> CurvePolygon<S> for AnyCurve<S> {
    /// The control polygon and, for a rational curve, its weights; for a polynomial map, its
    /// Bézier polygon on [0, 1].
    fn control_polygon(&self) -> Result<ControlPolygon<S>, RenderError> {
        let (points, weights) = match self {
            AnyCurve::Bezier(c) => (c.points().to_vec(), None),
            AnyCurve::RationalBezier(c) => (c.points().to_vec(), Some(c.weights().to_vec())),
            AnyCurve::BSpline(c) => (c.points().to_vec(), None),
            AnyCurve::Nurbs(c) => (c.points().to_vec(), Some(c.weights().to_vec())),
            AnyCurve::Map(c) => {
                let var = curve_var(c, &Drawn::PolynomialCurve)?;
                let n = c.degree_in(var) as usize;
                (control_polygon(c, var, n)?, None)
            }
        };
        Ok(ControlPolygon { points, weights })
    }
}

impl<S: Scalar> CurvePieces<S> for AnyCurve<S> {
    /// The homogeneous closed forms of the Bézier pieces in `t`, with their intervals.
    fn exact(&self, what: &Drawn) -> Result<ExactCurve<S>, RenderError> {
        let mut pieces: Vec<((S, S), VecPoly<S>)> = Vec::new();
        match self {
            AnyCurve::Bezier(c) => {
                pieces.push((self.domain(), polynomial_h(c.closed_form(Var::T))));
            }
            AnyCurve::RationalBezier(c) => {
                pieces.push((self.domain(), c.closed_form(Var::T).to_homogeneous()));
            }
            AnyCurve::BSpline(c) => {
                for piece in c.bezier_pieces()? {
                    let (a, b) = piece.interval.clone();
                    let bez = BezierCurve::try_new(piece.points)?.with_domain(a, b)?;
                    pieces.push((piece.interval, polynomial_h(bez.closed_form(Var::T))));
                }
            }
            AnyCurve::Nurbs(c) => {
                for piece in c.bezier_pieces()? {
                    let (a, b) = piece.interval.clone();
                    let bez = RationalBezierCurve::try_new(piece.points, piece.weights)?
                        .with_domain(a, b)?;
                    pieces.push((piece.interval, bez.closed_form(Var::T).to_homogeneous()));
                }
            }
            AnyCurve::Map(c) => {
                let var = curve_var(c, what)?;
                let renamed = c.map(|p| p.substitute(var, &Poly::var(Var::T)));
                pieces.push((self.domain(), polynomial_h(renamed)));
            }
        }
        let pieces = pieces
            .into_iter()
            .map(|(t, h)| Ok((t, spatial(h, what)?)))
            .collect::<Result<Vec<_>, RenderError>>()?;
        Ok(ExactCurve {
            what: what.clone(),
            domain: self.domain(),
            pieces,
        })
    }
}

/// The one variable of a polynomial curve (u for a constant map).
fn curve_var<S: Scalar>(c: &VecPoly<S>, what: &Drawn) -> Result<Var, RenderError> {
    match c.vars().as_slice() {
        [] => Ok(Var::U),
        [v] => Ok(*v),
        vars => Err(RenderError::Variables {
            what: what.clone(),
            found: var_names(vars),
        }),
    }
}

fn var_names(vars: &[Var]) -> String {
    vars.iter().map(|v| v.name()).collect::<Vec<_>>().join(", ")
}

/// `(x, y, z)` as the homogeneous map `(x, y, z, 1)`.
fn polynomial_h<S: Scalar>(c: VecPoly<S>) -> VecPoly<S> {
    let mut comps = c.into_components();
    comps.push(Poly::one());
    VecPoly::new(comps)
}

/// A homogeneous map of the plane `(w x, w y, w)` lifted to space `(w x, w y, 0, w)`; one of
/// space unchanged; any other dimension is an error.
fn spatial<S: Scalar>(h: VecPoly<S>, what: &Drawn) -> Result<VecPoly<S>, RenderError> {
    match h.dim() {
        4 => Ok(h),
        3 => {
            let mut comps = h.into_components();
            comps.insert(2, Poly::zero());
            Ok(VecPoly::new(comps))
        }
        d => Err(RenderError::Dimension {
            what: what.clone(),
            dim: d.saturating_sub(1),
        }),
    }
}

/// A point of the plane or of space as a point of space (z = 0 in the plane), in f64 for
/// drawing; `None` in another dimension.
pub(crate) fn point3<S: Scalar>(p: &Point<S>) -> Option<[f64; 3]> {
    match p.coords() {
        [x, y] => Some([x.to_f64(), y.to_f64(), 0.0]),
        [x, y, z] => Some([x.to_f64(), y.to_f64(), z.to_f64()]),
        _ => None,
    }
}

/// One Bézier piece of a surface: its rectangle and its homogeneous closed form with the first
/// partial derivatives.
#[derive(Clone, Debug)]
pub(crate) struct SurfacePiece<S: Scalar> {
    pub u: (S, S),
    pub v: (S, S),
    pub h: VecPoly<S>,
    pub hu: VecPoly<S>,
    pub hv: VecPoly<S>,
}

/// A surface as exact piecewise closed forms.
#[derive(Clone, Debug)]
pub(crate) struct ExactSurface<S: Scalar> {
    pub what: Drawn,
    pub domain: ((S, S), (S, S)),
    pub pieces: Vec<SurfacePiece<S>>,
}

fn within<S: Scalar>(t: &S, (a, b): &(S, S)) -> bool {
    a <= t && t <= b
}

impl<S: Scalar> ExactSurface<S> {
    /// The piece whose rectangle holds (u, v) (the first one, on a shared border).
    pub fn piece(&self, u: &S, v: &S) -> Option<&SurfacePiece<S>> {
        self.pieces
            .iter()
            .find(|p| within(u, &p.u) && within(v, &p.v))
    }

    /// The parameters `(u_k, v_l)` of a regular grid of `nu x nv` cells.
    pub fn params(&self, k: usize, nu: usize, l: usize, nv: usize) -> (S, S) {
        (
            parameter(&self.domain.0, k, nu),
            parameter(&self.domain.1, l, nv),
        )
    }

    fn at_text(u: &S, v: &S) -> String {
        format!("(u, v) = ({}, {})", u.to_text(), v.to_text())
    }

    fn piece_or_err(&self, u: &S, v: &S) -> Result<&SurfacePiece<S>, RenderError> {
        self.piece(u, v)
            .ok_or_else(|| RenderError::PointAtInfinity {
                what: Drawn::OutsideDomain(Box::new(self.what.clone())),
                at: Self::at_text(u, v),
            })
    }

    /// The point c(u, v), exactly.
    pub fn point(&self, u: &S, v: &S) -> Result<Point<S>, RenderError> {
        let piece = self.piece_or_err(u, v)?;
        let h = piece.h.eval(&[(Var::U, u.clone()), (Var::V, v.clone())])?;
        h.from_homogeneous()
            .map(|(p, _)| p)
            .ok_or_else(|| RenderError::PointAtInfinity {
                what: self.what.clone(),
                at: Self::at_text(u, v),
            })
    }

    /// The points `c(u, v_j)` along the isoparametric curve of constant u, exactly: each
    /// piece's closed form is restricted to that u once, `H(u, v)` as a polynomial in v, and
    /// then evaluated at every `v_j` (the same values as [`ExactSurface::point`], faster).
    pub fn row(&self, u: &S, vs: &[S]) -> Result<Vec<Point<S>>, RenderError> {
        self.along_row(
            u,
            vs,
            |piece| piece.h.substitute_value(Var::U, u),
            |curve, v| {
                let h = curve.eval(&[(Var::V, v.clone())])?;
                h.from_homogeneous()
                    .map(|(p, _)| p)
                    .ok_or_else(|| RenderError::PointAtInfinity {
                        what: self.what.clone(),
                        at: Self::at_text(u, v),
                    })
            },
        )
    }

    /// The normal directions at `(u, v_j)` along the isoparametric curve of constant u, as
    /// [`ExactSurface::normal`] gives them: each piece's `H`, `H_u`, `H_v` restricted to that u
    /// once, then evaluated at every `v_j` (as [`ExactSurface::row`] does for the points).
    pub fn normal_row(&self, u: &S, vs: &[S]) -> Result<Vec<Point<S>>, RenderError> {
        self.along_row(
            u,
            vs,
            |piece| {
                (
                    piece.h.substitute_value(Var::U, u),
                    piece.hu.substitute_value(Var::U, u),
                    piece.hv.substitute_value(Var::U, u),
                )
            },
            |(h, hu, hv), v| {
                let at = [(Var::V, v.clone())];
                let (h, hu, hv) = (h.eval(&at)?, hu.eval(&at)?, hv.eval(&at)?);
                Ok(affine_derivative(&h, &hu)
                    .cross(&affine_derivative(&h, &hv))
                    .unwrap_or_else(|_| Point::zero(3)))
            },
        )
    }

    /// `at(restricted, v_j)` for every `v_j`, where `restricted` is `restrict(piece)` of the
    /// piece holding `(u, v_j)`, computed once per piece: the walk along an isoparametric
    /// curve of constant u shared by [`ExactSurface::row`] and [`ExactSurface::normal_row`].
    fn along_row<T, R>(
        &self,
        u: &S,
        vs: &[S],
        restrict: impl Fn(&SurfacePiece<S>) -> T,
        at: impl Fn(&T, &S) -> Result<R, RenderError>,
    ) -> Result<Vec<R>, RenderError> {
        let mut restricted: Vec<Option<T>> = self.pieces.iter().map(|_| None).collect();
        vs.iter()
            .map(|v| {
                cagd_scalar::cancel::checkpoint();
                let (piece, slot) = self
                    .pieces
                    .iter()
                    .zip(restricted.iter_mut())
                    .find(|(p, _)| within(u, &p.u) && within(v, &p.v))
                    .ok_or_else(|| RenderError::PointAtInfinity {
                        what: Drawn::OutsideDomain(Box::new(self.what.clone())),
                        at: Self::at_text(u, v),
                    })?;
                at(slot.get_or_insert_with(|| restrict(piece)), v)
            })
            .collect()
    }

    /// The direction of the normal `c_u x c_v` at (u, v), exactly (scaled by `w^4`); the zero
    /// vector where the partial derivatives are dependent (a degenerate corner).
    pub fn normal(&self, u: &S, v: &S) -> Result<Point<S>, RenderError> {
        let piece = self.piece_or_err(u, v)?;
        let at = [(Var::U, u.clone()), (Var::V, v.clone())];
        let h = piece.h.eval(&at)?;
        let hu = piece.hu.eval(&at)?;
        let hv = piece.hv.eval(&at)?;
        Ok(affine_derivative(&h, &hu)
            .cross(&affine_derivative(&h, &hv))
            .unwrap_or_else(|_| Point::zero(3)))
    }
}

/// `w P' - w' P` on the first three coordinates of homogeneous P = (p, w): `w^2` times the
/// derivative of the projection `p / w`.
pub(crate) fn affine_derivative<S: Scalar>(h: &Point<S>, hd: &Point<S>) -> Point<S> {
    let w = h.coords().get(3).cloned().unwrap_or_else(S::one);
    let wd = hd.coords().get(3).cloned().unwrap_or_else(S::zero);
    Point::new(
        hd.coords()
            .iter()
            .zip(h.coords())
            .take(3)
            .map(|(d, p)| w.mul_ref(d) - wd.mul_ref(p))
            .collect(),
    )
}

/// A curve as exact piecewise closed forms in `t`.
#[derive(Clone, Debug)]
pub(crate) struct ExactCurve<S: Scalar> {
    pub what: Drawn,
    pub domain: (S, S),
    pub pieces: Vec<((S, S), VecPoly<S>)>,
}

impl<S: Scalar> ExactCurve<S> {
    /// The point c(t), exactly.
    pub fn point(&self, t: &S) -> Result<Point<S>, RenderError> {
        let err = || RenderError::PointAtInfinity {
            what: self.what.clone(),
            at: format!("t = {}", t.to_text()),
        };
        let (_, h) = self
            .pieces
            .iter()
            .find(|(i, _)| within(t, i))
            .ok_or_else(err)?;
        let h = h.eval(&[(Var::T, t.clone())])?;
        h.from_homogeneous().map(|(p, _)| p).ok_or_else(err)
    }
}
