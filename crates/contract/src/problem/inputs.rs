//! The arguments of a problem as exact values, for the answer key and the figures.

use super::args::*;
use super::op::{Op, Problem};
use crate::input::{CurveIn, SurfaceIn};
use crate::spec::{self, ExprIn, Int, List, MeshIn, Num, Orders, Pair, PointIn, Points};
use crate::triangle::TriangleIn;
use crate::value::Number;
use crate::Exact;
use cagd_scalar::FieldOps;

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
