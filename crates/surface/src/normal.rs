//! The normal vector `c_u x c_v` (notes, chapter 5, §6) and its value at the corners (25).

use crate::{BezierSurface, Corner, Mesh, RationalBezierSurface, SurfaceError};
use cagd_linalg::Point;
use cagd_poly::{RationalMap, Var, VecPoly};
use cagd_scalar::Scalar;
use cagd_words::{said, Hole, Lang, Message, Phrase};
use std::fmt;

/// Why (25) gives no normal at a corner.
#[derive(Clone, Copy, PartialEq, Eq, Debug, strum::EnumIter)]
pub enum Degeneracy {
    /// Two vertices of (25) coincide, so one difference Δ is the zero vector (as at the pole of
    /// the sphere octant, where a whole row of the mesh is one point).
    RepeatedVertices {
        /// The corner vertex (i, j).
        corner: (usize, usize),
        /// The neighbour (i, j) equal to it.
        neighbour: (usize, usize),
    },
    /// The corner vertex and its two neighbours are collinear: the differences are parallel and
    /// their cross product vanishes.
    Collinear {
        /// The corner vertex, its neighbour along u, its neighbour along v.
        vertices: [(usize, usize); 3],
    },
    /// The patch has degree 0 in u or v: it is a curve, with no difference in that direction.
    ZeroDegree {
        /// The parameter of degree 0.
        param: &'static str,
    },
}

/// The vertex `c_{i,j}`, as mathematics.
fn vertex((i, j): (usize, usize)) -> Hole {
    Hole::Data(format!("c_{{{i},{j}}}"))
}

impl Message for Degeneracy {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Degeneracy::RepeatedVertices { corner, neighbour } => said(
                lang,
                "the vertices $‹›$ and $‹›$ coincide, so a difference of (25) is the zero vector",
                "los vértices $‹›$ y $‹›$ coinciden, así que una diferencia de (25) es el vector nulo",
                [vertex(*corner), vertex(*neighbour)],
            ),
            Degeneracy::Collinear {
                vertices: [a, b, c],
            } => said(
                lang,
                "the vertices $‹›$, $‹›$, $‹›$ are collinear, so the differences of (25) are parallel",
                "los vértices $‹›$, $‹›$, $‹›$ están alineados, así que las diferencias de (25) son paralelas",
                [vertex(*a), vertex(*b), vertex(*c)],
            ),
            Degeneracy::ZeroDegree { param } => said(
                lang,
                "the patch has degree 0 in ‹›: it has no tangent direction in ‹›",
                "la superficie tiene grado 0 en ‹›: no tiene dirección tangente en ‹›",
                [param.into(), param.into()],
            ),
        }
    }
}

cagd_words::display_english!(Degeneracy);

/// The normal of (25) at a corner, or why it cannot be computed there.
#[derive(Clone, PartialEq, Debug)]
pub enum NormalAtCorner<S> {
    /// The normal vector (not normalized).
    Normal(Point<S>),
    /// (25) gives the zero vector here. The surface may still have a normal (the sphere has
    /// one at its pole): the parametrization is what degenerates.
    Degenerate {
        /// The corner.
        corner: Corner,
        /// Why.
        reason: Degeneracy,
    },
}

impl<S: Scalar> NormalAtCorner<S> {
    /// The normal vector, if there is one.
    pub fn normal(&self) -> Option<&Point<S>> {
        match self {
            NormalAtCorner::Normal(p) => Some(p),
            NormalAtCorner::Degenerate { .. } => None,
        }
    }

    /// Plain text: the vector, or `degenerate at (1, 0): the vertices ...`.
    pub fn to_text(&self) -> String {
        self.english()
    }
}

/// The vector as data, or why there is none, in words.
impl<S: Scalar> Message for NormalAtCorner<S> {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            NormalAtCorner::Normal(p) => Phrase::data(p.to_text()),
            NormalAtCorner::Degenerate { corner, reason } => DegenerateCorner {
                corner: *corner,
                reason: *reason,
                limit: None,
            }
            .phrase(lang),
        }
    }
}

impl<S: Scalar> fmt::Display for NormalAtCorner<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

/// The normal `c_u × c_v` of a patch at a corner: its value there, or, where it vanishes, the
/// limit of its direction.
#[derive(Clone, PartialEq, Debug)]
pub enum CornerNormal<S> {
    /// `c_u × c_v` at the corner, not zero: on the unit square `m n` times (25) (times the
    /// weights' factor for a rational patch).
    Normal(Point<S>),
    /// `c_u × c_v` vanishes at the corner (as at the pole of the sphere octant) but its
    /// direction has a limit along a border into the corner: `direction` points as the
    /// normal does near the corner (not normalized).
    Limit {
        /// The corner.
        corner: Corner,
        /// Why (25) gives no normal there.
        reason: Degeneracy,
        /// The limit direction.
        direction: Point<S>,
        /// The border along which the limit is taken: `"v = 0"` means along c(u, 0).
        along: String,
    },
    /// `c_u × c_v` vanishes on both borders through the corner: no direction is found.
    Degenerate {
        /// The corner.
        corner: Corner,
        /// Why.
        reason: Degeneracy,
    },
}

impl<S: Scalar> CornerNormal<S> {
    /// The vector: the normal, or the limit direction; `None` when degenerate.
    pub fn vector(&self) -> Option<&Point<S>> {
        match self {
            CornerNormal::Normal(p) | CornerNormal::Limit { direction: p, .. } => Some(p),
            CornerNormal::Degenerate { .. } => None,
        }
    }

    /// Plain text: the vector, `degenerate at (1, 0): ...; the limit direction along v = 0 is
    /// (0, 0, 1)`, or `degenerate at (1, 0): ...`.
    pub fn to_text(&self) -> String {
        self.english()
    }

    /// Where `c_u × c_v` vanishes, what is said of the corner (its direction as text); `None`
    /// for a normal vector (a value, not a sentence).
    pub fn degenerate(&self) -> Option<DegenerateCorner> {
        match self {
            CornerNormal::Normal(_) => None,
            CornerNormal::Limit {
                corner,
                reason,
                direction,
                along,
            } => Some(DegenerateCorner {
                corner: *corner,
                reason: *reason,
                limit: Some(LimitDirection {
                    along: along.clone(),
                    direction: direction.to_text(),
                }),
            }),
            CornerNormal::Degenerate { corner, reason } => Some(DegenerateCorner {
                corner: *corner,
                reason: *reason,
                limit: None,
            }),
        }
    }
}

/// The vector as data, or why there is none (and the limit direction), in words.
impl<S: Scalar> Message for CornerNormal<S> {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            CornerNormal::Normal(p) => Phrase::data(p.to_text()),
            _ => self
                .degenerate()
                .map(|d| d.phrase(lang))
                .unwrap_or_default(),
        }
    }
}

/// A corner where `c_u × c_v` vanishes, in words: the corner, why (25) gives no normal there,
/// and the limit direction of the normal along a border into it when there is one (a
/// [`CornerNormal`] or [`NormalAtCorner`] without its scalars, for a sentence that holds no
/// scalar type).
#[derive(Clone, PartialEq, Eq, Debug)]
pub struct DegenerateCorner {
    /// The corner.
    pub corner: Corner,
    /// Why (25) gives no normal there.
    pub reason: Degeneracy,
    /// The limit direction of the normal, when one is found.
    pub limit: Option<LimitDirection>,
}

/// The limit direction of the normal at a corner along a border into it, as text.
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub struct LimitDirection {
    /// The border along which the limit is taken: `"v = 0"` means along c(u, 0).
    pub along: String,
    /// The limit direction: `(0, 0, 1)`.
    pub direction: String,
}

impl Message for DegenerateCorner {
    fn phrase(&self, lang: Lang) -> Phrase {
        let DegenerateCorner {
            corner,
            reason,
            limit,
        } = self;
        match limit {
            Some(LimitDirection { along, direction }) => said(
                lang,
                "degenerate at ‹›: «»; the limit direction of the normal along $‹›$ is $‹›$",
                "degenerado en ‹›: «»; la dirección límite del vector normal a lo largo de $‹›$ es $‹›$",
                [
                    corner.into(),
                    reason.phrase(lang).into(),
                    along.into(),
                    direction.into(),
                ],
            ),
            None => said(
                lang,
                "degenerate at ‹›: «»",
                "degenerado en ‹›: «»",
                [corner.into(), reason.phrase(lang).into()],
            ),
        }
    }
}

cagd_words::display_english!(DegenerateCorner);

/// The normal field `n(u, v)` (a numerator over a denominator that does not vanish at the
/// corner, `1` for a polynomial patch) at a corner of the domain: its value there, or, where it
/// vanishes, the limit of its direction along a border into the corner, with `reason` (from
/// (25)) saying why it vanishes.
///
/// The limit along the border v = v0: with `σ = ±1` pointing into the domain,
/// `n(u0 + σ x, v0) = x^k (a + x (...))` with `a ≠ 0` the first nonzero coefficient, so the
/// direction tends to `a` (divided by the denominator's value, which keeps its sign).
fn corner_normal_of_field<S: Scalar>(
    numer: &VecPoly<S>,
    denom: &cagd_poly::Poly<S>,
    corner: Corner,
    (u0, v0): (S, S),
    (su, sv): (S, S),
    reason: impl FnOnce() -> Result<Degeneracy, SurfaceError>,
) -> Result<CornerNormal<S>, SurfaceError> {
    let at = [(Var::U, u0.clone()), (Var::V, v0.clone())];
    let d = denom.eval(&at)?;
    let over_d = |p: Point<S>| -> Result<Point<S>, SurfaceError> {
        let coords = p
            .coords()
            .iter()
            .map(|x| x.checked_div(&d))
            .collect::<Option<Vec<S>>>()
            .ok_or(SurfaceError::WeightAtCorner { corner })?;
        Ok(Point::new(coords))
    };
    let value = numer.eval(&at)?;
    if !value.is_zero() {
        return Ok(CornerNormal::Normal(over_d(value)?));
    }
    let reason = reason()?;
    let paths = [
        (
            Var::U,
            &u0,
            &su,
            Var::V,
            &v0,
            format!("v = {}", v0.to_text()),
        ),
        (
            Var::V,
            &v0,
            &sv,
            Var::U,
            &u0,
            format!("u = {}", u0.to_text()),
        ),
    ];
    for (run, start, sign, fixed, value, along) in paths {
        let edge = numer
            .substitute_value(fixed, value)
            .affine_substitute(run, sign, start);
        let lowest = edge
            .components()
            .iter()
            .filter_map(|c| c.terms().next().map(|(m, _)| m.exp(run)))
            .min();
        if let Some(k) = lowest {
            let coords = edge
                .components()
                .iter()
                .map(|c| c.coeff_of(&[(run, k)]))
                .collect();
            return Ok(CornerNormal::Limit {
                corner,
                reason,
                direction: over_d(Point::new(coords))?,
                along,
            });
        }
    }
    Ok(CornerNormal::Degenerate { corner, reason })
}

/// The indices of (25) at a corner: the corner vertex, its neighbour along u and along v.
fn corner_stencil(
    corner: Corner,
    m: usize,
    n: usize,
) -> ((usize, usize), (usize, usize), (usize, usize)) {
    let (i, j) = corner.index(m, n);
    let iu = if i == 0 { 1 } else { m - 1 };
    let jv = if j == 0 { 1 } else { n - 1 };
    ((i, j), (iu, j), (i, jv))
}

/// (25) on a mesh at a corner, times `factor` (1 for polynomial patches).
fn corner_normal<S: Scalar>(
    mesh: &Mesh<S>,
    corner: Corner,
    factor: impl Fn((usize, usize), (usize, usize), (usize, usize)) -> S,
) -> Result<NormalAtCorner<S>, SurfaceError> {
    check_spatial(mesh.dim())?;
    let (m, n) = (mesh.rows() - 1, mesh.cols() - 1);
    for (param, degree) in [("u", m), ("v", n)] {
        if degree == 0 {
            return Ok(NormalAtCorner::Degenerate {
                corner,
                reason: Degeneracy::ZeroDegree { param },
            });
        }
    }
    let (c, cu, cv) = corner_stencil(corner, m, n);
    let get = |ij: (usize, usize)| mesh.get(ij.0, ij.1).cloned().ok_or(SurfaceError::EmptyMesh);
    let (p, pu, pv) = (get(c)?, get(cu)?, get(cv)?);
    // Δ^{1,0} and Δ^{0,1} at the corner, oriented along increasing u and v
    let du = if c.0 == 0 { &pu - &p } else { &p - &pu };
    let dv = if c.1 == 0 { &pv - &p } else { &p - &pv };
    for (d, nb) in [(&du, cu), (&dv, cv)] {
        if d.is_zero() {
            return Ok(NormalAtCorner::Degenerate {
                corner,
                reason: Degeneracy::RepeatedVertices {
                    corner: c,
                    neighbour: nb,
                },
            });
        }
    }
    let normal = du.cross(&dv).map_err(SurfaceError::Linalg)?;
    if normal.is_zero() {
        return Ok(NormalAtCorner::Degenerate {
            corner,
            reason: Degeneracy::Collinear {
                vertices: [c, cu, cv],
            },
        });
    }
    Ok(NormalAtCorner::Normal(normal.scale(&factor(c, cu, cv))))
}

/// [`corner_normal_of_field`] at the four corners of `mesh`'s domain, in the order of
/// [`Corner::ALL`], with the reasons of (25) on the mesh.
fn corner_normals_of_field<S: Scalar>(
    mesh: &Mesh<S>,
    domain: &crate::Domain<S>,
    numer: &VecPoly<S>,
    denom: &cagd_poly::Poly<S>,
) -> Result<[CornerNormal<S>; 4], SurfaceError> {
    let one = |corner: Corner| {
        let (u0, v0) = crate::derivative::corner_parameters(domain, corner);
        let (iu, iv) = corner.is_end();
        let sign = |end: bool| if end { -S::one() } else { S::one() };
        let reason = || {
            Ok(match corner_normal(mesh, corner, |_, _, _| S::one())? {
                NormalAtCorner::Degenerate { reason, .. } => reason,
                NormalAtCorner::Normal(_) => {
                    let (m, n) = (mesh.rows() - 1, mesh.cols() - 1);
                    let (c, cu, cv) = corner_stencil(corner, m, n);
                    Degeneracy::Collinear {
                        vertices: [c, cu, cv],
                    }
                }
            })
        };
        corner_normal_of_field(numer, denom, corner, (u0, v0), (sign(iu), sign(iv)), reason)
    };
    Ok([
        one(Corner::U0V0)?,
        one(Corner::U1V0)?,
        one(Corner::U0V1)?,
        one(Corner::U1V1)?,
    ])
}

fn check_spatial(dim: usize) -> Result<(), SurfaceError> {
    if dim == 3 {
        Ok(())
    } else {
        Err(SurfaceError::Dimension {
            what: crate::Computation::Normal,
            expected: 3,
            found: dim,
        })
    }
}

impl<S: Scalar> BezierSurface<S> {
    /// The normal vector field `n(u, v) = ∂c/∂u x ∂c/∂v` as a polynomial map (§6); its value
    /// at a point is normal to the surface wherever the partial derivatives are independent.
    /// Points must be in R^3.
    pub fn normal(&self) -> Result<VecPoly<S>, SurfaceError> {
        check_spatial(self.dim())?;
        let c = self.closed_form()?;
        Ok(c.partial(Var::U).cross(&c.partial(Var::V))?)
    }

    /// The normal at a corner by (25): at (0, 0),
    ///
    /// `n(0, 0) = Δ^{1,0} c_{0,0} x Δ^{0,1} c_{0,0}`,
    ///
    /// and at the other corners the same with the differences of that corner, oriented along
    /// increasing u and v (at (1, 0): `Δ^{1,0} c_{m-1,0} x Δ^{0,1} c_{m,0}`), so it points as
    /// `c_u x c_v`, which is `m n` times it (and the chain rule on a domain other than
    /// [0, 1]^2). When two of the three vertices coincide or they are collinear the formula
    /// gives no normal, and the result says which.
    ///
    /// ```
    /// use cagd_surface::{BezierSurface, Corner};
    /// use cagd_linalg::Point;
    /// use cagd_scalar::BigRational;
    /// let p = |c: &[i64]| Point::from_ints(c);
    /// let s = BezierSurface::<BigRational>::from_rows(vec![
    ///     vec![p(&[0, 0, 0]), p(&[0, 1, 0])],
    ///     vec![p(&[1, 0, 0]), p(&[1, 1, 1])],
    /// ]).unwrap();
    /// assert_eq!(s.normal_at_corner(Corner::U0V0).unwrap().to_text(), "(0, 0, 1)");
    /// assert_eq!(s.normal_at_corner(Corner::U1V1).unwrap().to_text(), "(-1, -1, 1)");
    /// ```
    pub fn normal_at_corner(&self, corner: Corner) -> Result<NormalAtCorner<S>, SurfaceError> {
        corner_normal(self.mesh(), corner, |_, _, _| S::one())
    }

    /// (25) at the four corners, in the order of [`Corner::ALL`].
    pub fn normals_at_corners(&self) -> Result<[NormalAtCorner<S>; 4], SurfaceError> {
        Ok([
            self.normal_at_corner(Corner::U0V0)?,
            self.normal_at_corner(Corner::U1V0)?,
            self.normal_at_corner(Corner::U0V1)?,
            self.normal_at_corner(Corner::U1V1)?,
        ])
    }

    /// The normal `c_u × c_v` at the four corners (in the order of [`Corner::ALL`]), from the
    /// normal field `field` = [`BezierSurface::normal`]: on the unit square `m n` times (25)
    /// (at (0, 0), `m n Δ^{1,0} c_{0,0} × Δ^{0,1} c_{0,0}`). Where it vanishes, the limit of
    /// its direction along a border into the corner, with the reason (25) gives.
    ///
    /// ```
    /// use cagd_surface::{BezierSurface, CornerNormal};
    /// use cagd_linalg::Point;
    /// use cagd_scalar::BigRational;
    /// let p = |c: &[i64]| Point::from_ints(c);
    /// // c(u, v) = (2u, 2v, 0) as a (2, 2) patch: c_u × c_v = (0, 0, 4) = 4 (25)
    /// let s = BezierSurface::<BigRational>::from_rows(vec![
    ///     vec![p(&[0, 0, 0]), p(&[0, 1, 0]), p(&[0, 2, 0])],
    ///     vec![p(&[1, 0, 0]), p(&[1, 1, 0]), p(&[1, 2, 0])],
    ///     vec![p(&[2, 0, 0]), p(&[2, 1, 0]), p(&[2, 2, 0])],
    /// ]).unwrap();
    /// let n = s.corner_normals(&s.normal().unwrap()).unwrap();
    /// assert_eq!(n[0], CornerNormal::Normal(p(&[0, 0, 4])));
    /// assert_eq!(s.normal_at_corner(cagd_surface::Corner::U0V0).unwrap().to_text(), "(0, 0, 1)");
    /// ```
    pub fn corner_normals(&self, field: &VecPoly<S>) -> Result<[CornerNormal<S>; 4], SurfaceError> {
        corner_normals_of_field(self.mesh(), self.domain(), field, &cagd_poly::Poly::one())
    }
}

impl<S: Scalar> RationalBezierSurface<S> {
    /// The normal vector field `c_u x c_v` of the rational patch in closed form, through the
    /// homogeneous form: with `c = N/w`, `c_u = (w N_u − w_u N)/w^2` and `c_v` alike, and since
    /// `N × N = 0`,
    ///
    /// `c_u × c_v = (w N_u × N_v + w_v N × N_u + w_u N_v × N) / w^3`
    ///
    /// (the 3 × 3 minors of the homogeneous `(N, w)`, `(N_u, w_u)`, `(N_v, w_v)`), reduced by
    /// the factors of w that divide the numerator ([`RationalMap::over_power`]: for the sphere
    /// octant, whose weights are a tensor product, w = f(u) g(v)). Points must be in R^3.
    pub fn normal(&self) -> Result<RationalMap<S>, SurfaceError> {
        check_spatial(self.mesh().dim())?;
        let c = self.closed_form()?;
        let (n, w) = (c.numerator(), c.denominator());
        let (n_u, n_v) = (n.partial(Var::U), n.partial(Var::V));
        let (w_u, w_v) = (w.partial(Var::U), w.partial(Var::V));
        let terms = [
            n_u.cross(&n_v)?.mul_poly(w),
            n.cross(&n_u)?.mul_poly(&w_v),
            n_v.cross(n)?.mul_poly(&w_u),
        ];
        let numer = VecPoly::new(
            (0..3)
                .map(|k| {
                    terms
                        .iter()
                        .filter_map(|t| t.component(k))
                        .fold(cagd_poly::Poly::zero(), |acc, p| acc + p)
                })
                .collect(),
        );
        Ok(RationalMap::over_power(numer, w, 3, Var::U, Var::V))
    }

    /// The normal at a corner by (25) on the control points, scaled by the weights: at (0, 0)
    /// `∂c/∂u = m (w_{1,0}/w_{0,0}) Δ^{1,0} c_{0,0}` and `∂c/∂v = n (w_{0,1}/w_{0,0})
    /// Δ^{0,1} c_{0,0}`, so the normal along `c_u x c_v` is
    /// `(w_{1,0} w_{0,1} / w_{0,0}^2) Δ^{1,0} c_{0,0} x Δ^{0,1} c_{0,0}` (the same at the other
    /// corners with their vertices). Degenerate cases as for polynomial patches: the pole of the
    /// sphere octant has repeated vertices.
    pub fn normal_at_corner(&self, corner: Corner) -> Result<NormalAtCorner<S>, SurfaceError> {
        let w = self.weights();
        let weight = |ij: (usize, usize)| w.get(ij.0, ij.1).cloned().unwrap_or_else(S::one);
        corner_normal(self.mesh(), corner, |c, cu, cv| {
            let wc = weight(c);
            (weight(cu) * weight(cv))
                .checked_div(&wc.mul_ref(&wc))
                .unwrap_or_else(S::zero)
        })
    }

    /// (25) at the four corners, in the order of [`Corner::ALL`].
    pub fn normals_at_corners(&self) -> Result<[NormalAtCorner<S>; 4], SurfaceError> {
        Ok([
            self.normal_at_corner(Corner::U0V0)?,
            self.normal_at_corner(Corner::U1V0)?,
            self.normal_at_corner(Corner::U0V1)?,
            self.normal_at_corner(Corner::U1V1)?,
        ])
    }

    /// The normal `c_u × c_v` at the four corners (in the order of [`Corner::ALL`]), from the
    /// normal field `field` = [`RationalBezierSurface::normal`]: on the unit square
    /// `m n (w_{1,0} w_{0,1} / w_{0,0}^2) Δ^{1,0} c_{0,0} × Δ^{0,1} c_{0,0}` at (0, 0), and
    /// alike at the others. Where it vanishes (the pole of the sphere octant), the limit of its
    /// direction along a border into the corner, with the reason (25) gives.
    pub fn corner_normals(
        &self,
        field: &RationalMap<S>,
    ) -> Result<[CornerNormal<S>; 4], SurfaceError> {
        corner_normals_of_field(
            self.mesh(),
            self.domain(),
            field.numerator(),
            field.denominator(),
        )
    }
}
