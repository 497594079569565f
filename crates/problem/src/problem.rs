//! The typed problem: one variant per operation, read once from JSON with serde.
//!
//! A problem is an object `{"op": NAME, ...arguments}` (`docs/format.md`). Its arguments are
//! read into the operation's struct (unknown keys refused, with the nearest valid key named),
//! every number once, by the one grammar; the fixture fields (`name`, `title`, `source`,
//! `equation`, `note`, `expected`, `errata`) are a block of their own, [`Meta`]. The number
//! field (Q or Q(√d)) is the one the numbers were read in.

use crate::field::NumberField;
use crate::input::{CurveIn, SurfaceIn};
use crate::limits::Limits;
use crate::message::contract::{Contract, Found};
use crate::message::read::Read;
use crate::spec::{self, ExprIn, Int, List, MeshIn, Num, Orders, Pair, PointIn, Points};
use crate::triangle::TriangleIn;
use crate::value::Number;
use crate::{Exact, ProblemError};
use cagd_param::Name;
use cagd_scalar::FieldOps;
use schemars::JsonSchema;
use serde::de::{self, Deserializer, Visitor};
use serde::Deserialize;
use serde_json::value::RawValue;
use serde_json::Value;

/// What a fixture (or a teacher's problem for `cagd check`) says besides the problem.
#[derive(Debug, Clone, PartialEq, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Meta {
    /// A short name (`ch6-coons-bezier`).
    pub name: Option<String>,
    /// A title in words.
    pub title: Option<String>,
    /// Where in the notes.
    pub source: Option<String>,
    /// The notes' equation numbers.
    pub equation: Option<String>,
    /// A remark about the example.
    pub note: Option<String>,
    /// The exact answer, in the shapes of the answers (`docs/format.md`), checked by name.
    // Present is `Some`, even as `null` (which the check then refuses): a key written is
    // never taken for a key left out.
    #[schemars(with = "Option<crate::schema::Expected>")]
    #[serde(default, deserialize_with = "present")]
    pub expected: Option<Value>,
    /// What the notes print where they are wrong.
    #[serde(default)]
    pub errata: Vec<Erratum>,
    /// The letters the problem's numbers may use (`["R"]`, `["a", "b", "c", "d"]`): the
    /// problem then runs in the field of quotients of polynomials in them, and its answer is
    /// in letters. An undeclared letter is an error, so a typo is caught.
    #[serde(default)]
    pub parameters: Vec<String>,
    /// A general formula of the notes that the answer is compared with, entry by entry (see
    /// the module `formula`): the errata it finds are computed, and must be the ones
    /// recorded.
    #[serde(default)]
    pub formula: Option<crate::formula::Formulas>,
    /// Letters that stand for functions of u (`["f", "g"]`: the profile `(f, 0, g)` is the
    /// notes' `(f(u), 0, g(u))`); only `revolution` takes them, for its parametrization (21).
    #[serde(default)]
    pub functions: Vec<String>,
    /// Values of parameters (`{"R": 2}`): the problem is solved with them put into its numbers
    /// (each key a declared parameter, each value an exact number).
    #[serde(default)]
    pub values: serde_json::Map<String, Value>,
    /// The title and the note in Spanish, for the keys in Spanish (`--lang es`).
    #[serde(default)]
    pub es: Option<MetaEs>,
}

impl Meta {
    /// Whether the problem is an example of the notes: its `source` names one of their files
    /// (`002_20d988b092ff1833.txt §5`). Only then does a verdict say it matches *the notes*;
    /// any other problem matches its expected answer.
    pub fn from_notes(&self) -> bool {
        self.source.as_deref().is_some_and(|s| s.contains(".txt"))
    }
}

/// A fixture's words in Spanish: what the keys in Spanish print instead of `title` and `note`.
#[derive(Debug, Clone, PartialEq, Eq, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct MetaEs {
    /// The title.
    pub title: Option<String>,
    /// The note.
    pub note: Option<String>,
}

/// A value that is present, `null` included.
fn present<'de, D: serde::Deserializer<'de>>(d: D) -> Result<Option<Value>, D::Error> {
    Value::deserialize(d).map(Some)
}

/// An erratum of the notes, as a fixture records it.
#[derive(Debug, Clone, PartialEq, Eq, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Erratum {
    /// Where in the notes (a step, an equation).
    #[serde(rename = "where", default)]
    pub place: String,
    /// What the notes print.
    #[serde(default)]
    pub printed: String,
    /// The exact value.
    #[serde(default)]
    pub exact: String,
    /// Why.
    #[serde(default)]
    pub why: String,
    /// The same in Spanish (each field that has words), for the keys in Spanish.
    #[serde(default)]
    pub es: Option<ErratumEs>,
}

/// An erratum's words in Spanish; a field left out is printed as the English one (a formula).
#[derive(Debug, Clone, PartialEq, Eq, Default, Deserialize, JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct ErratumEs {
    /// Where in the notes.
    #[serde(rename = "where")]
    pub place: Option<String>,
    /// What the notes print.
    pub printed: Option<String>,
    /// The exact value.
    pub exact: Option<String>,
    /// Why.
    pub why: Option<String>,
}

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
    /// The curve (polynomial).
    pub curve: Option<CurveIn<Number>>,
    /// [a, b] (default: the curve's domain).
    pub t: Option<Pair>,
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

macro_rules! operations {
    ($($name:literal => $variant:ident($args:ident),)*) => {
        /// An operation and its arguments.
        // One value per problem, read once and kept: the size of the largest variant is no
        // cost worth a box.
        #[allow(clippy::large_enum_variant)]
        #[derive(Debug, Clone, PartialEq)]
        pub enum Op {
            $(
                #[doc = concat!("`", $name, "`")]
                $variant($args),
            )*
        }

        /// Every operation `solve` knows, in the order of `docs/format.md`.
        pub const NAMES: &[&str] = &[$($name),*];

        impl Op {
            /// The operation's name (`"coons"`).
            pub fn name(&self) -> &'static str {
                match self {
                    $(Op::$variant(_) => $name,)*
                }
            }

            /// Reads the arguments of the operation `name` from `args`.
            fn read<'de, D: Deserializer<'de>>(name: &str, args: D) -> Option<Result<Op, D::Error>> {
                match name {
                    $($name => Some($args::deserialize(args).map(Op::$variant)),)*
                    _ => None,
                }
            }
        }

        /// The schema of each operation's arguments (its struct's, as derived), by name, in
        /// the order of [`NAMES`].
        pub(crate) fn argument_schemas(
            generator: &mut schemars::SchemaGenerator,
        ) -> Vec<(&'static str, schemars::Schema)> {
            vec![$(($name, <$args as JsonSchema>::json_schema(generator)),)*]
        }
    };
}

operations! {
    "evaluate" => Evaluate(Evaluate),
    "closed_form" => ClosedForm(ClosedForm),
    "restrict" => Restrict(Restrict),
    "elevate" => Elevate(Elevate),
    "derivative" => Derivative(Derivative),
    "normal" => Normal(Normal),
    "continuity" => Continuity(Continuity),
    "curve_continuity" => CurveContinuity(CurveContinuity),
    "interpolate" => Interpolate(Interpolate),
    "approximate" => Approximate(Approximate),
    "translational" => Translational(Translational),
    "ruled" => Ruled(Ruled),
    "developable" => Developable(Developable),
    "gaussian_curvature" => GaussianCurvature(GaussianCurvature),
    "tangent_developable" => TangentDevelopable(TangentDevelopable),
    "coons" => Coons(Coons),
    "revolution" => Revolution(Revolution),
    "insert_knot" => InsertKnot(InsertKnot),
    "graph" => Graph(Graph),
    "circle" => Circle(Circle),
    "blossom" => Blossom(Blossom),
    "subdivide" => Subdivide(Subdivide),
    "boundary" => Boundary(Boundary),
    "isocurve" => Isocurve(Isocurve),
    "extract" => Extract(Extract),
    "remove_knot" => RemoveKnot(RemoveKnot),
    "reverse" => Reverse(Reverse),
    "reduce_degree" => ReduceDegree(ReduceDegree),
    "conic" => Conic(Conic),
    "arc_length" => ArcLength(ArcLength),
}

/// A problem: the operation with its arguments, the fixture's block, and the field it runs
/// in.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    /// The operation and its arguments.
    pub op: Op,
    /// The fixture's fields.
    pub meta: Meta,
    /// The number field of the problem's numbers (and of the operation's).
    pub field: NumberField,
    /// The keys of the arguments, in the order written (the answer key lists them so).
    pub order: Vec<String>,
    /// The parameters its numbers may use (from `meta.parameters`); empty for numbers only.
    pub parameters: Vec<Name>,
    /// The values the problem is solved at (from `meta.values`): put into its numbers before
    /// the solve.
    pub values: Vec<(Name, Number)>,
    /// Remarks on the reading, for the answer: a decimal such as `"0.3333"` is read exactly
    /// as 3333/10000, and 1/3 may be what is meant.
    pub hints: Vec<crate::Message>,
}

/// The field names of a struct read with serde's derive (its `deserialize_struct` call).
fn struct_fields<'de, T: Deserialize<'de>>() -> &'static [&'static str] {
    struct Fields(&'static [&'static str]);
    #[derive(Debug)]
    struct Stop;
    impl std::fmt::Display for Stop {
        fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
            f.write_str("stop")
        }
    }
    impl std::error::Error for Stop {}
    impl de::Error for Stop {
        fn custom<T: std::fmt::Display>(_: T) -> Self {
            Stop
        }
    }
    struct Probe<'a>(&'a mut Fields);
    impl<'de> Deserializer<'de> for Probe<'_> {
        type Error = Stop;
        fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value, Stop> {
            Err(Stop)
        }
        fn deserialize_struct<V: Visitor<'de>>(
            self,
            _: &'static str,
            fields: &'static [&'static str],
            _: V,
        ) -> Result<V::Value, Stop> {
            self.0 .0 = fields;
            Err(Stop)
        }
        serde::forward_to_deserialize_any! {
            bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string
            bytes byte_buf option unit unit_struct newtype_struct seq tuple
            tuple_struct map enum identifier ignored_any
        }
    }
    let mut fields = Fields(&[]);
    let _ = T::deserialize(Probe(&mut fields));
    fields.0
}

/// The key nearest to `key` among `keys`, when near enough to be a misspelling.
fn nearest<'a>(key: &str, keys: &[&'a str]) -> Option<&'a str> {
    keys.iter()
        .map(|k| (strsim::damerau_levenshtein(key, k), *k))
        .filter(|(d, k)| *d <= 2.max(k.len() / 3) && *d < k.len().max(key.len()))
        .min_by_key(|(d, _)| *d)
        .map(|(_, k)| k)
}

/// The names between backticks in a serde message (`unknown field `x`, expected one of `a`,
/// `b``): the first is the unknown name, the rest the valid ones.
fn backticked(message: &str) -> Vec<&str> {
    message.split('`').skip(1).step_by(2).collect()
}

/// Joins a path and a key: `c1` + `bezier[2]` = `c1.bezier[2]`.
fn join(path: &str, key: &str) -> String {
    match (path.is_empty(), key.starts_with('[')) {
        (true, _) => key.to_string(),
        (false, true) => format!("{path}{key}"),
        (false, false) => format!("{path}.{key}"),
    }
}

/// A leaf's error, typed, as the reading of the leaves hands it over: the keys below the value
/// that raised it, the message, and the limit it names.
type Leaf = (Vec<String>, crate::Message, Option<crate::Limit>);

/// A leaf reader (spec.rs, limits.rs, input.rs, triangle.rs, any.rs) stashes its typed error
/// in a thread-local and returns `de::Error::custom` of its English from its `Deserialize`;
/// given serde's text of that error, this takes the stashed error back ([`spec::take_typed`],
/// which checks the text is the stashed error's): `Some((keys below the value, message,
/// limit))`, `None` for serde's own words. The locating pass's stop is stashed too.
fn typed_leaf_error(serde_text: &str) -> Option<Leaf> {
    let t = spec::take_typed(serde_text)?;
    let below = if t.below.is_empty() {
        Vec::new()
    } else {
        vec![t.below]
    };
    Some((below, t.message, t.limit))
}

/// What serde said, read once.
enum Said {
    /// The key missing.
    Missing(String),
    /// An unknown key, and the keys its object takes.
    UnknownField { key: String, valid: Vec<String> },
    /// The locating pass stopped at the first number of the root it looks for.
    Located,
    /// A sentence, typed, and the limit it names.
    Typed(crate::Message, Option<crate::Limit>),
    /// A leaf's sentence not yet typed (its English, with its limit tag).
    Untyped(String),
}

/// Serde's words about a value, typed: THE one reader of serde's own messages (with
/// [`serde_error`], which reads a whole error). `text` is serde_json's message without its
/// place; the keys returned are those below the value that raised it (from the typed error a
/// reader stashed: [`typed_leaf_error`]).
fn said_by_serde(text: &str) -> (Vec<String>, Said) {
    use crate::message::contract::{Expected, Found};
    if let Some((below, m, limit)) = typed_leaf_error(text) {
        if matches!(&m, crate::Message::Read(r) if **r == Read::Located) {
            return (below, Said::Located);
        }
        return (below, Said::Typed(m, limit));
    }
    let below = Vec::new();
    let message = text;
    let typed = |c: Contract| Said::Typed(c.into(), None);
    if let Some(rest) = message.strip_prefix("missing field `") {
        let key = rest.trim_end_matches('`');
        return (below, Said::Missing(key.to_string()));
    }
    if message.starts_with("unknown field `") {
        let names = backticked(message);
        let (key, valid) = names.split_first().map_or(("", &[][..]), |(k, v)| (*k, v));
        let valid = valid.iter().map(|k| k.to_string()).collect();
        let key = key.to_string();
        return (below, Said::UnknownField { key, valid });
    }
    if message.starts_with("unknown variant `") {
        let names = backticked(message);
        if let Some((found, valid)) = names.split_first() {
            let valid = valid.iter().map(|k| k.to_string()).collect();
            let found = found.to_string();
            return (below, typed(Contract::UnknownWord { valid, found }));
        }
    }
    if let Some(rest) = message.strip_prefix("invalid type: ") {
        if let Some((found, expected)) = rest.split_once(", expected ") {
            let number = |s: &str| Found::Number(s.trim_matches('`').to_string());
            let found = match found {
                "sequence" => Found::List,
                "map" => Found::Object,
                "unit value" => Found::Null,
                "boolean `true`" => Found::Bool(true),
                "boolean `false`" => Found::Bool(false),
                f => match (
                    f.strip_prefix("integer "),
                    f.strip_prefix("floating point "),
                    f.strip_prefix("string "),
                ) {
                    (Some(n), _, _) | (_, Some(n), _) => number(n),
                    (_, _, Some(s)) => Found::Str(s.to_string()),
                    _ => Found::Other(f.replace('`', "")),
                },
            };
            let expected = Expected::from_words(expected);
            return (below, typed(Contract::InvalidType { found, expected }));
        }
    }
    if let Some(rest) = message.strip_prefix("invalid value: ") {
        if let Some((found, expected)) = rest.split_once(", expected ") {
            let (found, expected) = (found.to_string(), expected.to_string());
            return (below, typed(Contract::InvalidValue { found, expected }));
        }
    }
    if let Some(rest) = message.strip_prefix("invalid length ") {
        if let Some((len, expected)) = rest.split_once(", expected ") {
            if let Ok(len) = len.parse() {
                let expected = expected.to_string();
                return (below, typed(Contract::InvalidLength { len, expected }));
            }
        }
    }
    if let Some(rest) = message.strip_prefix("duplicate field `") {
        let key = rest.trim_end_matches('`').to_string();
        return (below, typed(Contract::DuplicateKey { key }));
    }
    (below, Said::Untyped(message.to_string()))
}

/// A whole error of serde_json, typed: a text that is not JSON (its place, line and column,
/// when it has one), or what serde said about a value ([`said_by_serde`]). The one function,
/// with [`said_by_serde`], that reads serde's words; a front end that reads a problem's text
/// itself (the CLI's stream of problems) words its errors through it.
pub fn serde_error(e: &serde_json::Error) -> Contract {
    use crate::message::contract::Syntax;
    use serde_json::error::Category;
    let text = e.to_string();
    let place = format!(" at line {} column {}", e.line(), e.column());
    let bare = match e.line() {
        0 => text.as_str(),
        _ => text.strip_suffix(&place).unwrap_or(&text),
    };
    match e.classify() {
        Category::Syntax | Category::Eof | Category::Io => {
            let what = Syntax::WORDS
                .iter()
                .find(|(w, _)| *w == bare)
                .map_or_else(|| Syntax::Other(bare.to_string()), |(_, s)| s.clone());
            Contract::Syntax {
                what,
                line: e.line(),
                column: e.column(),
            }
        }
        Category::Data => match said_by_serde(bare) {
            (below, Said::Typed(crate::Message::Contract(c), None))
                if below.is_empty() && e.line() == 0 =>
            {
                *c
            }
            _ => Contract::Serde { text },
        },
    }
}

/// A reading error as a [`ProblemError`]: the path of the value at fault, what serde said
/// typed ([`said_by_serde`]); `Err` with the path of the number found by the locating pass.
fn reading_error(path: &str, e: &serde_json::Error, op: &str) -> Result<ProblemError, String> {
    let text = e.to_string();
    let (below, said) = said_by_serde(&text);
    let path = below.iter().fold(path.to_string(), |p, k| join(&p, k));
    Ok(match said {
        Said::Located => return Err(path),
        Said::Missing(key) => ProblemError::at(join(&path, &key), Contract::Missing),
        Said::UnknownField { key, valid } => {
            // the tracked path already ends with the unknown key
            let parent = path
                .strip_suffix(key.as_str())
                .map(|p| p.trim_end_matches('.'))
                .unwrap_or(&path)
                .to_string();
            let mut candidates: Vec<&str> = valid.iter().map(String::as_str).collect();
            if parent.is_empty() {
                // the fixture's fields are valid everywhere at the top
                candidates.extend_from_slice(struct_fields::<Meta>());
            }
            let nearest = nearest(&key, &candidates).map(str::to_string);
            let owner = if parent.is_empty() {
                op.to_string()
            } else {
                parent.clone()
            };
            ProblemError::at(
                join(&parent, &key),
                Contract::UnknownKey {
                    nearest,
                    owner,
                    valid,
                },
            )
        }
        Said::Typed(m, limit) => ProblemError {
            limit,
            ..ProblemError::at(path, m)
        },
        Said::Untyped(text) => ProblemError::at(path, Contract::Serde { text }),
    })
}

/// Reads `T` from `value` under the reading context, with the path of an error.
fn read_at<'de, D, T>(
    value: D,
    read: impl for<'b> FnOnce(
        serde_path_to_error::Deserializer<'static, 'b, D>,
    ) -> Result<T, serde_json::Error>,
) -> Result<T, (String, serde_json::Error)>
where
    D: Deserializer<'de, Error = serde_json::Error>,
{
    let mut track = serde_path_to_error::Track::new();
    let result = read(serde_path_to_error::Deserializer::new(value, &mut track));
    result.map_err(|e| {
        let path = track.path().to_string();
        let path = if path == "." { String::new() } else { path };
        (path, e)
    })
}

/// A root the operation itself needs: circles of quarter arcs (1 or 4) need √2/2 for their
/// weights; of 3 or 6 arcs, √3 (their control points lie on equilateral triangles).
fn needed_root(op: &str, args: &[(&str, &Value)]) -> Option<u64> {
    let get = |key: &str| args.iter().find(|(k, _)| *k == key).map(|(_, v)| *v);
    let arcs = get("arcs").and_then(|v| v.as_u64());
    if matches!(op, "revolution" | "circle") {
        if let Some(sweep) = get("sweep").and_then(angle_of) {
            let start = match get("start") {
                Some(v) => angle_of(v)?,
                None => cagd_scalar::BigRational::from_integer(0.into()),
            };
            let arcs = match arcs {
                Some(n) => usize::try_from(n).ok()?,
                None => crate::ops::default_arcs(&sweep),
            };
            return Some(crate::ops::root_of_angles(&start, &sweep, arcs).unwrap_or(2));
        }
    }
    match (op, arcs) {
        ("revolution" | "circle", Some(3 | 6)) => Some(3),
        ("revolution" | "circle", _) => Some(2),
        _ => None,
    }
}

/// An angle written as a JSON integer or a string "p" or "p/q" (degrees), before the reading.
fn angle_of(v: &Value) -> Option<cagd_scalar::BigRational> {
    use cagd_scalar::BigRational;
    if let Some(n) = v.as_i64() {
        return Some(BigRational::from_integer(n.into()));
    }
    let s = v.as_str()?.trim();
    let (p, q) = s.split_once('/').unwrap_or((s, "1"));
    let (p, q): (i64, i64) = (p.trim().parse().ok()?, q.trim().parse().ok()?);
    (q != 0).then(|| BigRational::new(p.into(), q.into()))
}

/// The top-level keys of a problem read from its text, each with the text of its value (not
/// yet read); `None` when the text is no object, or writes a key twice (the JSON value keeps
/// the last, where it first stood: that reading is [`Problem::read`]'s).
fn top_level(text: &str) -> Option<Vec<(std::borrow::Cow<'_, str>, &RawValue)>> {
    struct Entries<'a>(Vec<(std::borrow::Cow<'a, str>, &'a RawValue)>);
    impl<'de> Deserialize<'de> for Entries<'de> {
        fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
            struct V;
            impl<'de> Visitor<'de> for V {
                type Value = Entries<'de>;
                fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                    f.write_str("a problem object")
                }
                fn visit_map<A: de::MapAccess<'de>>(
                    self,
                    mut map: A,
                ) -> Result<Self::Value, A::Error> {
                    let mut out: Vec<(std::borrow::Cow<'de, str>, &'de RawValue)> = Vec::new();
                    while let Some(key) = map.next_key::<std::borrow::Cow<'de, str>>()? {
                        if out.iter().any(|(k, _)| *k == key) {
                            return Err(de::Error::custom("a key written twice"));
                        }
                        out.push((key, map.next_value()?));
                    }
                    Ok(Entries(out))
                }
            }
            d.deserialize_map(V)
        }
    }
    serde_json::from_str::<Entries<'_>>(text).ok().map(|e| e.0)
}

/// The reading of [`Problem::read_text_one_pass`]: the operation's name, then its arguments
/// read as they come, the fixture's keys kept as text and read at the end.
struct OnePass<'l> {
    limits: &'l Limits,
}

/// What [`OnePass`] reads: the operation, the fixture's block, the root met, the parameters
/// declared and the keys of the arguments in the order written.
type OnePassRead = (Op, Meta, Option<u64>, Vec<Name>, Vec<String>);

/// The error that gives a problem up to the two-pass reading (never shown).
const GIVE_UP: &str = "read in two passes";

impl<'de> Visitor<'de> for OnePass<'_> {
    type Value = OnePassRead;
    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("a problem object")
    }
    fn visit_map<A: de::MapAccess<'de>>(self, mut map: A) -> Result<OnePassRead, A::Error> {
        let give_up = || de::Error::custom(GIVE_UP);
        match map.next_key::<std::borrow::Cow<'de, str>>()? {
            Some(k) if k == "op" => {}
            _ => return Err(give_up()),
        }
        let name = map.next_value::<std::borrow::Cow<'de, str>>()?;
        let op = *NAMES.iter().find(|n| **n == name).ok_or_else(give_up)?;
        if matches!(op, "revolution" | "circle") {
            return Err(give_up());
        }
        let meta_keys = struct_fields::<Meta>();
        let mut meta_args: Vec<(std::borrow::Cow<'de, str>, &'de RawValue)> = Vec::new();
        let mut order: Vec<String> = Vec::new();
        let (result, root, declared) = spec::read_with(self.limits, &[], None, None, || {
            spec::from_text(|| {
                let rest = Arguments {
                    map: &mut map,
                    meta_keys,
                    meta: &mut meta_args,
                    order: &mut order,
                };
                Op::read(op, rest).unwrap_or_else(|| Err(give_up()))
            })
        });
        let op_value = result?;
        for (k, v) in &meta_args {
            // a value of any depth, which the whole problem's reading bounds
            if matches!(k.as_ref(), "expected" | "values")
                && nesting(v.get()) + 1 >= crate::field::MAX_NESTING
            {
                return Err(give_up());
            }
        }
        let meta_args: Vec<(&str, &RawValue)> =
            meta_args.iter().map(|(k, v)| (k.as_ref(), *v)).collect();
        let meta = Meta::deserialize(pairs(&meta_args)).map_err(|_| give_up())?;
        Ok((op_value, meta, root, declared, order))
    }
}

/// The keys of a problem after `op`, as the map of the operation's arguments: the fixture's
/// keys are set aside as text, the others handed to the operation's struct as they come.
struct Arguments<'a, 'de, A> {
    map: &'a mut A,
    meta_keys: &'static [&'static str],
    meta: &'a mut Vec<(std::borrow::Cow<'de, str>, &'de RawValue)>,
    order: &'a mut Vec<String>,
}

impl<'de, A: de::MapAccess<'de>> de::MapAccess<'de> for Arguments<'_, 'de, A> {
    type Error = A::Error;
    fn next_key_seed<K: de::DeserializeSeed<'de>>(
        &mut self,
        seed: K,
    ) -> Result<Option<K::Value>, A::Error> {
        loop {
            let Some(key) = self.map.next_key::<std::borrow::Cow<'de, str>>()? else {
                return Ok(None);
            };
            let k = key.as_ref();
            if matches!(k, "op" | "formula" | "parameters" | "functions")
                || self.meta.iter().any(|(m, _)| m == k)
            {
                // a key written twice, or one the arguments' reading depends on
                return Err(de::Error::custom(GIVE_UP));
            }
            if self.meta_keys.contains(&k) {
                let v: &'de RawValue = self.map.next_value()?;
                self.meta.push((key, v));
                continue;
            }
            self.order.push(k.to_string());
            return seed
                .deserialize(de::value::StrDeserializer::<A::Error>::new(k))
                .map(Some);
        }
    }
    fn next_value_seed<V: de::DeserializeSeed<'de>>(
        &mut self,
        seed: V,
    ) -> Result<V::Value, A::Error> {
        self.map.next_value_seed(seed)
    }
}

impl<'de, A: de::MapAccess<'de>> Deserializer<'de> for Arguments<'_, 'de, A> {
    type Error = A::Error;
    fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, A::Error> {
        visitor.visit_map(self)
    }
    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string
        bytes byte_buf option unit unit_struct newtype_struct seq tuple
        tuple_struct map struct enum identifier ignored_any
    }
}

/// The deepest nesting of lists and objects in a JSON text (brackets outside strings).
fn nesting(text: &str) -> usize {
    let (mut depth, mut deepest, mut in_string, mut escaped) = (0usize, 0usize, false, false);
    for b in text.bytes() {
        if in_string {
            match b {
                _ if escaped => escaped = false,
                b'\\' => escaped = true,
                b'"' => in_string = false,
                _ => {}
            }
            continue;
        }
        match b {
            b'"' => in_string = true,
            b'[' | b'{' => {
                depth += 1;
                deepest = deepest.max(depth);
            }
            b']' | b'}' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    deepest
}

impl Problem {
    /// Reads a problem from its JSON text under `limits`, as [`Problem::read`] reads its JSON
    /// value, with the same answer and the same errors: `invalid` says what is wrong with a
    /// text that is not JSON.
    ///
    /// The text is read straight into the typed problem, without a JSON value in between and
    /// without tracking field paths; should that reading fail (a bad problem, or one of the
    /// rare texts it leaves to the value's reading: a key written twice, a `formula`, values
    /// nested near the limit), the problem is read again as a JSON value by
    /// [`Problem::read`], whose error names the field at fault.
    pub fn read_text(
        text: &str,
        limits: &Limits,
        invalid: impl FnOnce(serde_json::Error) -> ProblemError,
    ) -> Result<Problem, ProblemError> {
        if let Some(problem) = Problem::read_text_fast(text, limits) {
            return Ok(problem);
        }
        let value: Value = serde_json::from_str(text).map_err(invalid)?;
        Problem::read(&value, limits)
    }

    /// The reading of [`Problem::read_text`] without a JSON value; `None` where it leaves the
    /// problem to [`Problem::read`] (every error among them).
    fn read_text_fast(text: &str, limits: &Limits) -> Option<Problem> {
        spec::take_hints();
        if let Some(problem) = Problem::read_text_one_pass(text, limits) {
            return Some(problem);
        }
        // the remarks of the pass given up are made again below
        spec::take_hints();
        let entries = top_level(text)?;
        let (_, op) = entries.iter().find(|(k, _)| k == "op")?;
        let op: std::borrow::Cow<'_, str> = serde_json::from_str(op.get()).ok()?;
        let op = *NAMES.iter().find(|n| **n == op)?;
        let meta_keys = struct_fields::<Meta>();
        let mut meta_args: Vec<(&str, &RawValue)> = Vec::new();
        let mut args: Vec<(&str, &RawValue)> = Vec::new();
        for (k, v) in &entries {
            match k.as_ref() {
                "op" => {}
                // formulas are read through serde's untagged enums, which buffer numbers
                // differently from a value: left to the value's reading
                "formula" => return None,
                // a value of any depth, which the whole problem's reading bounds
                "expected" | "values" if nesting(v.get()) + 1 >= crate::field::MAX_NESTING => {
                    return None
                }
                k if meta_keys.contains(&k) => meta_args.push((k, v)),
                k => args.push((k, v)),
            }
        }
        let meta = Meta::deserialize(pairs(&meta_args)).ok()?;
        let mut parameters = read_parameters(&meta.parameters, "parameters").ok()?;
        if !meta.functions.is_empty() {
            if op != "revolution" {
                return None;
            }
            for f in read_parameters(&meta.functions, "functions").ok()? {
                if parameters.contains(&f) {
                    return None;
                }
                parameters.push(Name::function(f.as_str(), "u"));
            }
        }
        let needed = if matches!(op, "revolution" | "circle") {
            let angles: Vec<(&str, Value)> = args
                .iter()
                .filter(|(k, _)| matches!(*k, "arcs" | "sweep" | "start"))
                .map(|(k, v)| Some((*k, serde_json::from_str(v.get()).ok()?)))
                .collect::<Option<_>>()?;
            let angles: Vec<(&str, &Value)> = angles.iter().map(|(k, v)| (*k, v)).collect();
            needed_root(op, &angles)
        } else {
            None
        };
        let (result, root, declared) = spec::read_with(limits, &parameters, needed, None, || {
            spec::from_text(|| Op::read(op, pairs(&args)))
        });
        let op_value = result?.ok()?;
        let order = args.iter().map(|(k, _)| k.to_string()).collect();
        Problem::assemble(op_value, meta, root, declared, order).ok()
    }

    /// The reading of [`Problem::read_text_fast`] in one pass over the text, for a problem that
    /// names its operation first (`{"op": "closed_form", ...}`): each argument is read into the
    /// operation's struct where it stands, with no text kept for a second reading. `None`
    /// for every other problem (the key `op` later, `parameters`, `functions` or `formula`
    /// given, a circle or revolution, whose root is found from its arguments before they are
    /// read) and at any error: [`Problem::read_text_fast`] then reads it in two passes.
    fn read_text_one_pass(text: &str, limits: &Limits) -> Option<Problem> {
        let mut de = serde_json::Deserializer::from_str(text);
        let (op_value, meta, root, declared, order) =
            de.deserialize_map(OnePass { limits }).ok()?;
        de.end().ok()?;
        Problem::assemble(op_value, meta, root, declared, order).ok()
    }

    /// The problem of an operation read: its field from the root its numbers need and the
    /// letters declared, the values of `meta`, the remarks of the reading.
    fn assemble(
        op: Op,
        meta: Meta,
        root: Option<u64>,
        declared: Vec<Name>,
        order: Vec<String>,
    ) -> Result<Problem, ProblemError> {
        let values = read_values(&meta.values, &declared)?;
        Ok(Problem {
            op,
            meta,
            field: match (root, declared.is_empty()) {
                (None, true) => NumberField::Rational,
                (Some(d), true) => NumberField::Quadratic(d),
                (d, false) => NumberField::Letters(d.unwrap_or(0)),
            },
            order,
            parameters: declared,
            values,
            hints: spec::take_hints(),
        })
    }

    /// Reads a problem under `limits`: every number once, every key known.
    pub fn read(problem: &Value, limits: &Limits) -> Result<Problem, ProblemError> {
        // the remarks of an earlier reading on this thread are not this problem's
        spec::take_hints();
        let Value::Object(map) = problem else {
            return Err(ProblemError::at(
                "",
                Contract::NotAProblem {
                    found: Found::of(problem),
                },
            ));
        };
        let op = match map.get("op") {
            None | Some(Value::Null) => {
                return Err(ProblemError::at("op", Contract::MissingOperation))
            }
            Some(Value::String(s)) => s.as_str(),
            Some(other) => {
                return Err(ProblemError::at(
                    "op",
                    Contract::OperationNotAString {
                        found: Found::of(other),
                    },
                ))
            }
        };
        if !NAMES.contains(&op) {
            return Err(ProblemError::at(
                "op",
                Contract::UnknownOperation {
                    found: op.to_string(),
                    nearest: nearest(op, NAMES).map(str::to_string),
                },
            ));
        }
        let meta_keys = struct_fields::<Meta>();
        let mut meta_args: Vec<(&str, &Value)> = Vec::new();
        let mut args: Vec<(&str, &Value)> = Vec::new();
        for (k, v) in map {
            if k == "op" {
                continue;
            }
            if meta_keys.contains(&k.as_str()) {
                meta_args.push((k.as_str(), v));
            } else {
                args.push((k.as_str(), v));
            }
        }
        let meta = read_at(pairs(&meta_args), |d| Meta::deserialize(d))
            .map_err(|(path, e)| reading_error(&path, &e, op).unwrap_or_else(located))?;
        let mut parameters = read_parameters(&meta.parameters, "parameters")?;
        if !meta.functions.is_empty() {
            if op != "revolution" {
                return Err(ProblemError::at(
                    "functions",
                    Contract::FunctionsOnlyInRevolution { op: op.to_string() },
                ));
            }
            for f in read_parameters(&meta.functions, "functions")? {
                if parameters.contains(&f) {
                    return Err(ProblemError::at(
                        "functions",
                        Contract::DeclaredBoth {
                            name: f.as_str().to_string(),
                        },
                    ));
                }
                parameters.push(Name::function(f.as_str(), "u"));
            }
        }
        let needed = needed_root(op, &args);
        let read_args = |locate: Option<u64>| {
            spec::read_with(limits, &parameters, needed, locate, || {
                read_at(pairs(&args), |d| {
                    Op::read(op, d).unwrap_or_else(|| Err(de::Error::custom("unknown operation")))
                })
            })
        };
        let (result, root, declared) = read_args(None);
        let op_value = match result {
            Ok(v) => v,
            Err((path, e)) => {
                let mut error = reading_error(&path, &e, op).unwrap_or_else(located);
                if let crate::Message::Read(r) = &mut error.message
                    && let Read::RootAgainstEarlier { needs, first } = **r
                {
                    // find where the first number of the other root is, to name it
                    if let (Err((at, e)), _, _) = read_args(Some(first)) {
                        if let Err(at) = reading_error(&at, &e, op) {
                            **r = Read::RootAgainstAt { needs, at, first };
                        }
                    }
                }
                return Err(error);
            }
        };
        let order = args.iter().map(|(k, _)| k.to_string()).collect();
        Problem::assemble(op_value, meta, root, declared, order)
    }

    /// The operation's name.
    pub fn op_name(&self) -> &'static str {
        self.op.name()
    }
}

/// The declared parameters: each one letter (the grammar reads a run of letters as a
/// product), possibly with a subscript as a generic mesh names its points (`c_{1,0}`), none
/// twice.
fn read_parameters(names: &[String], key: &str) -> Result<Vec<Name>, ProblemError> {
    let mut out: Vec<Name> = Vec::with_capacity(names.len());
    for (i, n) in names.iter().enumerate() {
        let mut chars = n.chars();
        let first = chars.next();
        let rest: String = chars.collect();
        let subscript = rest
            .strip_prefix("_{")
            .and_then(|r| r.strip_suffix('}'))
            .is_some_and(|r| !r.is_empty() && r.chars().all(|c| c.is_ascii_digit() || c == ','));
        let one_letter = first.is_some_and(char::is_alphabetic)
            && (rest.is_empty() || (subscript && key == "parameters"));
        if !one_letter {
            return Err(ProblemError::at(
                format!("{key}[{i}]"),
                Contract::NotOneLetter { found: n.clone() },
            ));
        }
        if out.iter().any(|m| m.as_str() == n) {
            return Err(ProblemError::at(
                format!("{key}[{i}]"),
                Contract::DeclaredTwice { name: n.clone() },
            ));
        }
        out.push(Name::new(n));
    }
    Ok(out)
}

/// The values of `values`: each key a declared parameter, each value an exact number (which
/// may itself use the parameters).
fn read_values(
    values: &serde_json::Map<String, Value>,
    parameters: &[Name],
) -> Result<Vec<(Name, Number)>, ProblemError> {
    values
        .iter()
        .map(|(k, v)| {
            let path = format!("values.{k}");
            let Some(name) = parameters.iter().find(|n| n.as_str() == k) else {
                return Err(ProblemError::at(
                    &path,
                    Contract::NotDeclared { name: k.clone() },
                ));
            };
            let spec::Num(x) = spec::read_value_typed(v, parameters).map_err(|t| ProblemError {
                limit: t.limit,
                ..ProblemError::at(&path, t.message)
            })?;
            Ok((name.clone(), x))
        })
        .collect()
}

/// The error of a reading stopped by the locating pass, outside it (never: only the locating
/// pass looks for a root's first number).
fn located(path: String) -> ProblemError {
    ProblemError::at(
        path,
        Contract::InternalError {
            what: "a number located outside the locating pass".into(),
        },
    )
}

/// A map deserializer over borrowed key-value pairs of the problem object: its values as JSON
/// values (`&Value`) or as their texts (`&RawValue`).
fn pairs<'a, V>(
    items: &'a [(&'a str, V)],
) -> de::value::MapDeserializer<'a, impl Iterator<Item = (&'a str, V)> + 'a, serde_json::Error>
where
    V: Copy + de::IntoDeserializer<'a, serde_json::Error> + 'a,
{
    de::value::MapDeserializer::new(items.iter().copied())
}

/// An argument of a problem as an exact value, for the answer key.
trait ToExact {
    fn to_exact(&self) -> Exact;
    /// Whether the argument is a curve or a surface (for figures).
    fn is_shape(&self) -> bool {
        false
    }
}

impl ToExact for Num {
    fn to_exact(&self) -> Exact {
        Exact::Number(self.0.clone())
    }
}

impl ToExact for Int {
    fn to_exact(&self) -> Exact {
        Exact::Number(<Number as cagd_scalar::ExactRational>::from_rational_owned(
            cagd_scalar::BigRational::from_integer(self.0.into()),
        ))
    }
}

impl ToExact for List<Int> {
    fn to_exact(&self) -> Exact {
        Exact::Point(cagd_linalg::Point::new(
            self.0
                .iter()
                .map(|n| Number::from_i64(i64::try_from(n.0).unwrap_or(i64::MAX)))
                .collect(),
        ))
    }
}

impl ToExact for Pair {
    fn to_exact(&self) -> Exact {
        Exact::Point(cagd_linalg::Point::new(vec![
            self.0 .0.clone(),
            self.1 .0.clone(),
        ]))
    }
}

impl ToExact for List<Num> {
    fn to_exact(&self) -> Exact {
        Exact::Point(cagd_linalg::Point::new(
            self.0.iter().map(|x| x.0.clone()).collect(),
        ))
    }
}

impl ToExact for List<Param> {
    fn to_exact(&self) -> Exact {
        let all_numbers: Option<Vec<Number>> = self
            .0
            .iter()
            .map(|p| match p {
                Param::One(x) => Some(x.0.clone()),
                Param::Many(_) => None,
            })
            .collect();
        match all_numbers {
            Some(xs) => Exact::Point(cagd_linalg::Point::new(xs)),
            None => Exact::Points(
                self.0
                    .iter()
                    .map(|p| match p {
                        Param::One(x) => cagd_linalg::Point::new(vec![x.0.clone()]),
                        Param::Many(xs) => {
                            cagd_linalg::Point::new(xs.iter().map(|x| x.0.clone()).collect())
                        }
                    })
                    .collect(),
            ),
        }
    }
}

impl ToExact for Orders {
    fn to_exact(&self) -> Exact {
        match self {
            Orders::One(n) => n.to_exact(),
            Orders::Two(a, b) => Exact::Point(cagd_linalg::Point::new(vec![
                Number::from_i64(i64::try_from(a.0).unwrap_or(i64::MAX)),
                Number::from_i64(i64::try_from(b.0).unwrap_or(i64::MAX)),
            ])),
        }
    }
}

impl ToExact for PointIn {
    fn to_exact(&self) -> Exact {
        Exact::Point(self.0.clone())
    }
}

impl ToExact for Points {
    fn to_exact(&self) -> Exact {
        Exact::Points(self.0.clone())
    }
}

impl ToExact for spec::PointData {
    fn to_exact(&self) -> Exact {
        match self {
            spec::PointData::Grid(MeshIn(mesh)) => Exact::Surface(SurfaceIn::Bezier {
                mesh: mesh.clone(),
                weights: None,
            }),
            spec::PointData::List(p) => p.to_exact(),
        }
    }
}

impl ToExact for CurveIn<Number> {
    fn to_exact(&self) -> Exact {
        Exact::Curve(self.clone())
    }
    fn is_shape(&self) -> bool {
        true
    }
}

impl ToExact for SurfaceIn<Number> {
    fn to_exact(&self) -> Exact {
        Exact::Surface(self.clone())
    }
    fn is_shape(&self) -> bool {
        true
    }
}

impl ToExact for ExprIn {
    /// The polynomial (or polynomial map) the expression reads as, which the keys print as
    /// mathematics (`"x*y"` is x y); the text as written only where it reads as neither.
    fn to_exact(&self) -> Exact {
        self.scalar::<Number>()
            .map(Exact::Poly)
            .or_else(|_| self.vector::<Number>().map(Exact::Map))
            .unwrap_or_else(|_| Exact::Text(self.text.clone()))
    }
}

impl ToExact for TriangleIn {
    fn to_exact(&self) -> Exact {
        crate::triangle::exact_input(self)
    }
    fn is_shape(&self) -> bool {
        true
    }
}

impl ToExact for At {
    /// The border fixed: `u = 1`.
    fn to_exact(&self) -> Exact {
        let mut parts = Vec::new();
        for (k, x) in [("u", &self.u), ("v", &self.v)] {
            if let Some(x) = x {
                parts.push((k.to_string(), Exact::Number(x.0.clone())));
            }
        }
        Exact::Object(parts)
    }
}

/// A keyword of the problem (`bspline`, `natural`, `u`) as the word typed, without quotes:
/// the keys print it as a word.
macro_rules! words {
    ($($t:ty),*) => {$(
        impl ToExact for $t {
            fn to_exact(&self) -> Exact {
                Exact::Text(format!("{self:?}").to_lowercase())
            }
        }
    )*};
}

words!(UorV, Blend, Basis, End);

impl ToExact for Parametrization {
    fn to_exact(&self) -> Exact {
        let word = match self {
            Parametrization::Uniform => "uniform",
            Parametrization::ChordLength => "chord_length",
            Parametrization::Centripetal => "centripetal",
        };
        Exact::Text(word.into())
    }
}

/// The arguments of an operation as exact values, by key.
trait Inputs {
    fn inputs(&self) -> Vec<(&'static str, Exact)>;
    fn shapes(&self) -> Vec<(&'static str, Exact)>;
}

macro_rules! inputs {
    ($($t:ident { $($field:ident),* })*) => {$(
        impl Inputs for $t {
            fn inputs(&self) -> Vec<(&'static str, Exact)> {
                let mut out = Vec::new();
                $(
                    if let Some(x) = &self.$field {
                        out.push((stringify!($field), x.to_exact()));
                    }
                )*
                out
            }
            fn shapes(&self) -> Vec<(&'static str, Exact)> {
                let mut out = Vec::new();
                $(
                    if let Some(x) = self.$field.as_ref().filter(|x| x.is_shape()) {
                        out.push((stringify!($field), x.to_exact()));
                    }
                )*
                out
            }
        }
    )*};
}

inputs! {
    Evaluate { surface, curve, triangle, params }
    ClosedForm { surface, curve, triangle }
    Restrict { surface, u, v, curve, t, triangle, vertices }
    Elevate { surface, curve, triangle, by }
    Derivative { surface, curve, order, at, triangle, direction }
    Blossom { curve, surface, triangle, params, u, v }
    Subdivide { curve, surface, triangle, t, u, v }
    Reverse { curve, surface, direction, triangle, order }
    Extract { curve, surface }
    RemoveKnot { curve, knot, times, surface, direction }
    ReduceDegree { curve, by, triangle }
    Isocurve { surface, u, v, triangle, w }
    Boundary { surface, triangle }
    Normal { surface, triangle, params }
    Continuity { surface, first, second, border, lengths }
    CurveContinuity { first, second }
    Interpolate { basis, end, u, v, params, parametrization, degree, tangents, points }
    Approximate { degree, points, params, parametrization, knots, knots_u, knots_v }
    Translational { c, d }
    Ruled { c1, c2 }
    Developable { surface, c1, c2 }
    GaussianCurvature { surface, triangle }
    TangentDevelopable { curve }
    Conic { points, weight }
    ArcLength { curve, t }
    Coons { c1, c2, d1, d2, blend }
    Revolution { curve, arcs, quadrant, interval, sweep, start }
    Circle { radius, arcs, center, interval, sweep, start }
    InsertKnot { curve, surface, knot, times, direction }
    Graph { f, degree, domain }
}

impl Problem {
    /// The arguments of the problem as exact values, in the order written, for the answer
    /// key.
    pub fn inputs(&self) -> Vec<(String, Exact)> {
        self.arguments(false)
    }

    /// The curves and surfaces among the arguments (`Exact::Curve`, `Exact::Surface`), in the
    /// order written: what a figure draws of the problem.
    pub fn shapes(&self) -> Vec<(String, Exact)> {
        self.arguments(true)
    }

    fn arguments(&self, shapes: bool) -> Vec<(String, Exact)> {
        macro_rules! each {
            ($($v:ident),*) => {
                match &self.op {
                    $(Op::$v(a) => if shapes { a.shapes() } else { a.inputs() },)*
                }
            };
        }
        let mut items = each!(
            Evaluate,
            ClosedForm,
            Restrict,
            Elevate,
            Derivative,
            Normal,
            Continuity,
            CurveContinuity,
            Interpolate,
            Approximate,
            Translational,
            Ruled,
            Developable,
            GaussianCurvature,
            TangentDevelopable,
            Conic,
            ArcLength,
            Coons,
            Revolution,
            Circle,
            InsertKnot,
            Graph,
            Blossom,
            Subdivide,
            Reverse,
            Extract,
            RemoveKnot,
            ReduceDegree,
            Isocurve,
            Boundary
        );
        items.sort_by_key(|(k, _)| self.order.iter().position(|w| w == k));
        items.into_iter().map(|(k, v)| (k.to_string(), v)).collect()
    }
}
