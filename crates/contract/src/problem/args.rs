//! The arguments of each operation: one struct per operation, read with serde (unknown keys
//! refused), and the small types they share (a direction, a blend, a parametrization).

use crate::input::{CurveIn, SurfaceIn};
use crate::spec::{self, ExprIn, Int, List, Num, Orders, Pair, PointIn, Points};
use crate::triangle::net::TriangleIn;
use crate::value::exact::Number;
use schemars::JsonSchema;
use serde::de::{self, Deserializer, Visitor};
use serde::Deserialize;

/// `"u"` or `"v"`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum UorV {
    /// The direction u.
    U,
    /// The direction v.
    V,
}

/// The blending of a Coons patch.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum Blend {
    /// Linear blending functions 1 - u, u (the notes' bilinearly blended patch).
    #[serde(alias = "bilinear")]
    Linear,
    /// Cubic Hermite blending.
    Cubic,
}

/// The basis of an interpolant.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum Basis {
    /// A Bézier curve or patch.
    Bezier,
    /// A C² cubic spline (bicubic for a surface).
    #[serde(alias = "cubic", alias = "spline")]
    Bicubic,
    /// A B-spline curve of `degree` p through the points, on the averaged knots (The NURBS
    /// Book eq. (9.8)).
    Bspline,
}

/// How the parameters of a fit are computed from the data.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Parametrization {
    /// t_k = k/n.
    Uniform,
    /// Steps proportional to the chord lengths |a_k - a_{k-1}| (exact when their ratios are
    /// rational).
    ChordLength,
    /// Steps proportional to the square roots of the chord lengths.
    Centripetal,
}

/// End conditions of a cubic spline interpolant.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum End {
    /// Zero second derivative at the ends.
    Natural,
    /// Bessel's end tangents.
    Bessel,
    /// Given end derivatives c'(t_0), c'(t_n): `tangents`.
    Clamped,
}

/// A border `{"u": 1}` or `{"v": 0}` where a derivative is restricted.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct At {
    /// u fixed.
    pub u: Option<Num>,
    /// v fixed.
    pub v: Option<Num>,
}

/// A parameter: t for a curve, [u, v] for a surface.
#[derive(Debug, Clone, PartialEq)]
pub enum Param {
    /// t.
    One(Num),
    /// [u, v, ...] as written (a surface takes two).
    Many(Vec<Num>),
}

impl<'de> Deserialize<'de> for Param {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Param;
            fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str("a number t or a pair [u, v]")
            }
            fn visit_seq<A: de::SeqAccess<'de>>(self, mut seq: A) -> Result<Param, A::Error> {
                let mut xs = Vec::with_capacity(seq.size_hint().unwrap_or(2));
                while let Some(x) = seq.next_element::<Num>()? {
                    xs.push(x);
                    if xs.len() > 2 {
                        break;
                    }
                }
                Ok(Param::Many(xs))
            }
            fn visit_i64<E: de::Error>(self, n: i64) -> Result<Param, E> {
                Num::deserialize(de::value::I64Deserializer::new(n)).map(Param::One)
            }
            fn visit_u64<E: de::Error>(self, n: u64) -> Result<Param, E> {
                Num::deserialize(de::value::U64Deserializer::new(n)).map(Param::One)
            }
            fn visit_f64<E: de::Error>(self, n: f64) -> Result<Param, E> {
                Num::deserialize(de::value::F64Deserializer::new(n)).map(Param::One)
            }
            fn visit_i128<E: de::Error>(self, n: i128) -> Result<Param, E> {
                Num::deserialize(de::value::I128Deserializer::new(n)).map(Param::One)
            }
            fn visit_u128<E: de::Error>(self, n: u128) -> Result<Param, E> {
                Num::deserialize(de::value::U128Deserializer::new(n)).map(Param::One)
            }
            fn visit_str<E: de::Error>(self, s: &str) -> Result<Param, E> {
                Num::deserialize(de::value::StrDeserializer::new(s)).map(Param::One)
            }
            fn visit_bool<E: de::Error>(self, b: bool) -> Result<Param, E> {
                Err(E::custom(format!("expected a number, found {b}")))
            }
            fn visit_unit<E: de::Error>(self) -> Result<Param, E> {
                Err(E::custom("expected a number, found null"))
            }
            fn visit_map<A: de::MapAccess<'de>>(self, mut map: A) -> Result<Param, A::Error> {
                match spec::json_number(&mut map)? {
                    Some(text) => Num::from_json_number(&text)
                        .map(Param::One)
                        .map_err(de::Error::custom),
                    None => Err(de::Error::custom("expected a number, found an object")),
                }
            }
        }
        d.deserialize_any(V)
    }
}

/// Arguments of `closed_form`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ClosedForm {
    /// The surface.
    pub surface: Option<SurfaceIn<Number>>,
    /// Or the curve.
    pub curve: Option<CurveIn<Number>>,
    /// Or a triangular patch.
    pub triangle: Option<TriangleIn>,
}

/// Arguments of `graph`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Graph {
    /// f(x, y).
    pub f: Option<ExprIn>,
    /// The bidegree [m, n] of the patch (default: the degrees of f); for a triangular patch
    /// its degree n (default: the total degree of f).
    pub degree: Option<Orders>,
    /// A triangle of the (x, y) plane, three points [x, y]: the graph over it as a triangular
    /// patch (without it, a tensor-product patch over [0, 1] × [0, 1]).
    pub domain: Option<Points>,
}

/// Arguments of `evaluate`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Evaluate {
    /// The surface.
    pub surface: Option<SurfaceIn<Number>>,
    /// Or the curve.
    pub curve: Option<CurveIn<Number>>,
    /// Or a triangular patch.
    pub triangle: Option<TriangleIn>,
    /// [u, v] pairs for a surface, numbers t for a curve; for a triangular patch, [u, v] in
    /// the domain triangle (0, 0), (1, 0), (0, 1), or barycentric [r, s, t].
    pub params: Option<List<Param>>,
}

/// Arguments of `restrict`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Restrict {
    /// The surface.
    pub surface: Option<SurfaceIn<Number>>,
    /// [a, b] in u.
    pub u: Option<Pair>,
    /// [c, d] in v.
    pub v: Option<Pair>,
    /// Or the curve.
    pub curve: Option<CurveIn<Number>>,
    /// [a, b] in t.
    pub t: Option<Pair>,
    /// Or a triangular patch.
    pub triangle: Option<TriangleIn>,
    /// For a triangular patch: the vertices a, b, c of the sub-triangle, three points [u, v]
    /// (or barycentric [r, s, t]) of the domain.
    pub vertices: Option<List<Param>>,
}

/// Arguments of `elevate`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Elevate {
    /// The surface.
    pub surface: Option<SurfaceIn<Number>>,
    /// Or the curve.
    pub curve: Option<CurveIn<Number>>,
    /// Or a triangular patch.
    pub triangle: Option<TriangleIn>,
    /// r (curve) or [r, s] (surface).
    pub by: Option<Orders>,
}

/// Arguments of `derivative`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Derivative {
    /// The surface.
    pub surface: Option<SurfaceIn<Number>>,
    /// Or the curve.
    pub curve: Option<CurveIn<Number>>,
    /// r (curve) or [r, s] (surface).
    pub order: Option<Orders>,
    /// A border the derivative is restricted to.
    pub at: Option<At>,
    /// Or a triangular patch.
    pub triangle: Option<TriangleIn>,
    /// For a triangular patch: the direction [du, dv] of the parameter plane (default [1, 0]).
    pub direction: Option<Pair>,
}

/// Arguments of `normal`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Normal {
    /// The surface.
    pub surface: Option<SurfaceIn<Number>>,
    /// Or a triangular patch.
    pub triangle: Option<TriangleIn>,
    /// For a triangular patch: points [u, v] (or [r, s, t]) where the normal is wanted.
    pub params: Option<List<Param>>,
}

/// Arguments of `continuity`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Continuity {
    /// Or one B-spline or NURBS surface: its continuity across each of its knot lines (the
    /// order the knots' multiplicities give, and the order checked on the pieces).
    pub surface: Option<SurfaceIn<Number>>,
    /// The first patch.
    pub first: Option<SurfaceIn<Number>>,
    /// The second patch.
    pub second: Option<SurfaceIn<Number>>,
    /// Across which border (default u).
    pub border: Option<UorV>,
    /// The parameter lengths [Δu_0, Δu_1].
    pub lengths: Option<Pair>,
}

/// Arguments of `curve_continuity`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct CurveContinuity {
    /// The first curve, at its end.
    pub first: Option<CurveIn<Number>>,
    /// The second curve, at its start.
    pub second: Option<CurveIn<Number>>,
}

/// Arguments of `interpolate`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Interpolate {
    /// Bézier (default) or bicubic spline.
    pub basis: Option<Basis>,
    /// End conditions of a spline.
    pub end: Option<End>,
    /// Parameters in u (grid of a surface).
    pub u: Option<List<Num>>,
    /// Parameters in v.
    pub v: Option<List<Num>>,
    /// Parameters of a curve.
    pub params: Option<List<Num>>,
    /// Or how to compute them from the data: uniform, chord length, centripetal (a grid:
    /// those of each column (u) and row (v), averaged).
    pub parametrization: Option<Parametrization>,
    /// The degree p of a B-spline interpolant (`basis`: `bspline`).
    pub degree: Option<Int>,
    /// The end derivatives [c'(t_0), c'(t_n)] (`end`: `clamped`) of a cubic spline, or of a
    /// B-spline interpolant of `degree` p (`basis`: `bspline`, n + 3 control points).
    pub tangents: Option<Points>,
    /// The data: a grid of points (surface) or a list (curve).
    pub points: Option<spec::PointData>,
}

/// Arguments of `approximate`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Approximate {
    /// The degree p (curve) or bidegree [m, n] (surface).
    pub degree: Option<Orders>,
    /// The data points.
    pub points: Option<Points>,
    /// Their parameters: numbers t, or pairs [u, v].
    pub params: Option<List<Param>>,
    /// Or how to compute the parameters of a curve from the data.
    pub parametrization: Option<Parametrization>,
    /// The knots of a B-spline least-squares curve of `degree` p, in the notes' convention
    /// (without end knots: n + p - 1 knots for n control points).
    pub knots: Option<List<Num>>,
    /// The knots in u of a B-spline least-squares surface of bidegree `degree` [p, q] (the
    /// notes' convention), with `knots_v`.
    pub knots_u: Option<List<Num>>,
    /// The knots in v of a B-spline least-squares surface.
    pub knots_v: Option<List<Num>>,
}

/// Arguments of `translational`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Translational {
    /// c(u).
    pub c: Option<CurveIn<Number>>,
    /// d(v).
    pub d: Option<CurveIn<Number>>,
}

/// Arguments of `ruled` (and of `developable` with curves).
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Ruled {
    /// c1(u).
    pub c1: Option<CurveIn<Number>>,
    /// c2(u).
    pub c2: Option<CurveIn<Number>>,
}

/// Arguments of `developable`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Developable {
    /// A ruled surface.
    pub surface: Option<SurfaceIn<Number>>,
    /// Or its two curves.
    pub c1: Option<CurveIn<Number>>,
    /// The second curve.
    pub c2: Option<CurveIn<Number>>,
}

/// Arguments of `gaussian_curvature`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct GaussianCurvature {
    /// The surface (any kind).
    pub surface: Option<SurfaceIn<Number>>,
    /// Or a triangular patch (or rational).
    pub triangle: Option<TriangleIn>,
}

/// Arguments of `conic`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Conic {
    /// [c_0, c_1, c_2]: the ends and the point where the end tangents meet.
    pub points: Option<Points>,
    /// The middle weight w (the ends weigh 1): the shape factor is w².
    pub weight: Option<Num>,
}

/// Arguments of `tangent_developable`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct TangentDevelopable {
    /// The curve c(u) (polynomial): the edge of regression.
    pub curve: Option<CurveIn<Number>>,
}

/// Arguments of `arc_length`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ArcLength {
    /// The curve: polynomial (Bézier, expression, B-spline) or rational (rational Bézier, NURBS).
    pub curve: Option<CurveIn<Number>>,
    /// [a, b] (default: the curve's domain).
    pub t: Option<Pair>,
}

/// Arguments of `integral`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Integral {
    /// The curve: polynomial (Bézier, expression, B-spline); a rational one is refused.
    pub curve: Option<CurveIn<Number>>,
    /// [a, b] (default: the curve's domain).
    pub t: Option<Pair>,
    /// Without a curve: the knots of the B-spline basis functions N_0, ..., N_{n-1} of `degree`
    /// p, in the notes' convention (without end knots: n + p - 1 knots).
    pub knots: Option<List<Num>>,
    /// The degree p of the basis functions of `knots`.
    pub degree: Option<Int>,
}

/// Arguments of `area`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Area {
    /// A closed planar polynomial curve (Bézier, expression, B-spline; 2D, or z = 0): the area
    /// it encloses.
    pub curve: Option<CurveIn<Number>>,
    /// A planar polynomial patch (Bézier, expression, B-spline): its area.
    pub surface: Option<SurfaceIn<Number>>,
}

/// Arguments of `loft`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Loft {
    /// The section curves c_0, ..., c_{K-1} (K ≥ 2; Bézier or clamped B-spline, polynomial, on
    /// one parameter interval).
    pub sections: Option<Vec<CurveIn<Number>>>,
    /// The parameters v_0 < ... < v_{K-1} of the sections (default: uniform, k/(K - 1)).
    pub v: Option<List<Num>>,
    /// The degree q across the sections, 1 ≤ q ≤ K - 1 (default: min(K - 1, 3)).
    pub degree: Option<Int>,
}

/// Arguments of `coons`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Coons {
    /// c1(u), v = 0.
    pub c1: Option<CurveIn<Number>>,
    /// c2(u), v = 1.
    pub c2: Option<CurveIn<Number>>,
    /// d1(v), u = 0.
    pub d1: Option<CurveIn<Number>>,
    /// d2(v), u = 1.
    pub d2: Option<CurveIn<Number>>,
    /// Linear (default) or cubic.
    pub blend: Option<Blend>,
}

/// Arguments of `revolution`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Revolution {
    /// The profile in the XZ plane.
    pub curve: Option<CurveIn<Number>>,
    /// 1 (a quadrant, default) or the arcs of the full turn.
    pub arcs: Option<Int>,
    /// Which quadrant (for one arc).
    pub quadrant: Option<Int>,
    /// The circle's parameter interval.
    pub interval: Option<Pair>,
    /// A partial revolution: the sweep angle θ in degrees (0 < θ ≤ 360), in `arcs` arcs
    /// (default: arcs of at most 90°); its cos and sin must be exact (multiples of 30° or 45°).
    pub sweep: Option<Num>,
    /// The start angle α in degrees (default 0), with `sweep`.
    pub start: Option<Num>,
}

/// Arguments of `circle`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Circle {
    /// The radius (default 1).
    pub radius: Option<Num>,
    /// The arcs (default 4).
    pub arcs: Option<Int>,
    /// The center (default the origin of R³).
    pub center: Option<PointIn>,
    /// The parameter interval (default [0, 1]).
    pub interval: Option<Pair>,
    /// An arc: the sweep angle θ in degrees (0 < θ ≤ 360), in `arcs` arcs (default: arcs of
    /// at most 90°); its cos and sin must be exact (multiples of 30° or 45°).
    pub sweep: Option<Num>,
    /// The start angle α in degrees (default 0), with `sweep`.
    pub start: Option<Num>,
}

/// Arguments of `insert_knot`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct InsertKnot {
    /// The curve.
    pub curve: Option<CurveIn<Number>>,
    /// Or the surface.
    pub surface: Option<SurfaceIn<Number>>,
    /// The knot.
    pub knot: Option<Num>,
    /// How many times (default 1).
    pub times: Option<Int>,
    /// For a surface: u or v.
    pub direction: Option<UorV>,
}

/// Arguments of `blossom`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Blossom {
    /// A Bézier curve (or rational).
    pub curve: Option<CurveIn<Number>>,
    /// Or a Bézier patch (or rational).
    pub surface: Option<SurfaceIn<Number>>,
    /// Or a triangular patch.
    pub triangle: Option<TriangleIn>,
    /// The n arguments t_1, ..., t_n of a curve; the n points [u, v] of a triangular patch.
    pub params: Option<List<Param>>,
    /// The m arguments u_1, ..., u_m of a patch.
    pub u: Option<List<Num>>,
    /// The n arguments v_1, ..., v_n of a patch.
    pub v: Option<List<Num>>,
}

/// Arguments of `subdivide`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Subdivide {
    /// A Bézier curve (or rational).
    pub curve: Option<CurveIn<Number>>,
    /// Or a Bézier patch (or rational), or a B-spline or NURBS surface.
    pub surface: Option<SurfaceIn<Number>>,
    /// Or a triangular patch.
    pub triangle: Option<TriangleIn>,
    /// Where a curve is split.
    pub t: Option<Num>,
    /// Where a patch is split in u (a triangular patch: at the point (u, v)).
    pub u: Option<Num>,
    /// Where a patch is split in v.
    pub v: Option<Num>,
}

/// Arguments of `reverse`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Reverse {
    /// The curve.
    pub curve: Option<CurveIn<Number>>,
    /// Or a tensor-product surface.
    pub surface: Option<SurfaceIn<Number>>,
    /// For a surface: the direction reversed, u (the rows of the mesh in reverse) or v (each
    /// row in reverse).
    pub direction: Option<UorV>,
    /// Or a triangular patch.
    pub triangle: Option<TriangleIn>,
    /// For a triangular patch: the old vertices in their new order, a permutation of
    /// [1, 2, 3] (default [1, 3, 2]: b_{ijk} → b_{ikj}, u and v exchanged).
    pub order: Option<List<Int>>,
}

/// Arguments of `extract`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Extract {
    /// A B-spline or NURBS curve.
    pub curve: Option<CurveIn<Number>>,
    /// Or a B-spline or NURBS surface.
    pub surface: Option<SurfaceIn<Number>>,
}

/// Arguments of `remove_knot`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct RemoveKnot {
    /// A B-spline or NURBS curve.
    pub curve: Option<CurveIn<Number>>,
    /// The knot.
    pub knot: Option<Num>,
    /// How many times (default 1).
    pub times: Option<Int>,
    /// Or a B-spline or NURBS surface.
    pub surface: Option<SurfaceIn<Number>>,
    /// For a surface: the direction of the knot, u (the default) or v.
    pub direction: Option<UorV>,
}

/// Arguments of `reduce_degree`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ReduceDegree {
    /// A Bézier curve.
    pub curve: Option<CurveIn<Number>>,
    /// By how much (default 1).
    pub by: Option<Int>,
    /// Or a triangular patch (or rational): reduced only when exact.
    pub triangle: Option<TriangleIn>,
}

/// Arguments of `isocurve`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Isocurve {
    /// The surface.
    pub surface: Option<SurfaceIn<Number>>,
    /// The curve u = u0 (running in v).
    pub u: Option<Num>,
    /// Or the curve v = v0 (running in u).
    pub v: Option<Num>,
    /// Or a triangular patch (`u`, `v` or `w` = 1 - u - v fixed).
    pub triangle: Option<TriangleIn>,
    /// For a triangular patch: the curve w = 1 - u - v = w0.
    pub w: Option<Num>,
}

/// Arguments of `boundary`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Boundary {
    /// A Bézier patch (or rational).
    pub surface: Option<SurfaceIn<Number>>,
    /// Or a triangular patch.
    pub triangle: Option<TriangleIn>,
}

/// How a knot vector is written: which knot the index 0 is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Convention {
    /// The notes' (Farin's): n + p - 1 knots for n control points, without end knots.
    Notes,
    /// The NURBS Book's (Piegl and Tiller's): n + p + 1 knots, one more at each end.
    NurbsBook,
}

/// How a knot vector is built from a degree p and a number of control points n.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(rename_all = "snake_case")]
pub enum Spacing {
    /// Every knot equally spaced: the integers 0, 1, ..., n + p (The NURBS Book's n + p + 1
    /// knots), or n + p + 1 knots equally spaced from a to b when `interval` [a, b] is given.
    Uniform,
    /// Open uniform (clamped): each end of `interval` (default [0, 1]) p + 1 times in The
    /// NURBS Book's convention (p times in the notes'), the n - p - 1 interior knots equally
    /// spaced.
    OpenUniform,
}

/// Arguments of `knot_vector`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct KnotVector {
    /// The knots, with `degree`, written in `convention`.
    pub knots: Option<List<Num>>,
    /// Or a B-spline or NURBS curve, whose knots are read (their convention told by their
    /// length: n + p - 1 knots the notes', n + p + 1 The NURBS Book's).
    pub curve: Option<CurveIn<Number>>,
    /// The degree p (with `knots` or `spacing`).
    pub degree: Option<Int>,
    /// How `knots` are written (default `notes`), or how the vector built by `spacing` is
    /// written; every index of the answer refers to it.
    pub convention: Option<Convention>,
    /// Parameters whose spans are found: the index i with u_i ≤ t < u_{i+1} in the vector as
    /// written (the last non-empty span at the right end of the domain).
    pub params: Option<List<Num>>,
    /// Or build a vector: `uniform` or `open_uniform`, with `degree` and `control_points`.
    pub spacing: Option<Spacing>,
    /// The number n of control points of the vector built.
    pub control_points: Option<Int>,
    /// The interval [a, b] of the vector built (`open_uniform`: default [0, 1]; `uniform`:
    /// default the integers 0, ..., n + p).
    pub interval: Option<Pair>,
}

/// Arguments of `normalize`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Normalize {
    /// A B-spline or NURBS curve: the same control points (and weights) on the knots
    /// (u - a)/(b - a), [a, b] its domain.
    pub curve: Option<CurveIn<Number>>,
    /// Or a B-spline or NURBS surface: its knots in u and in v each so mapped onto [0, 1], the
    /// same mesh (and weights).
    pub surface: Option<SurfaceIn<Number>>,
    /// Or the knots alone, with `degree`, written in `convention`.
    pub knots: Option<List<Num>>,
    /// The degree p of `knots`.
    pub degree: Option<Int>,
    /// How `knots` are written (default `notes`); the answer's are written so too.
    pub convention: Option<Convention>,
}

/// Arguments of `invert_point`.
#[derive(Debug, Clone, PartialEq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct InvertPoint {
    /// The curve: Bézier, rational Bézier, B-spline, NURBS or an expression.
    pub curve: Option<CurveIn<Number>>,
    /// The point P whose parameters t with c(t) = P are asked.
    pub point: Option<PointIn>,
}
