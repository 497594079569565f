//! The arguments of a problem as exact values, for the answer key and the figures.

use super::args::*;
use super::argument::Argument;
use super::op::{Op, Problem};
use crate::input::{CurveIn, SurfaceIn};
use crate::spec::{self, ExprIn, Int, List, MeshIn, Num, Orders, Pair, PointIn, Points};
use crate::triangle::TriangleIn;
use crate::value::Number;
use crate::{Exact, Quantity};
use cagd_poly::Var;
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

impl ToExact for Vec<CurveIn<Number>> {
    fn to_exact(&self) -> Exact {
        Exact::List(self.iter().map(|c| Exact::Curve(c.clone())).collect())
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
        for (k, x) in [(Var::U, &self.u), (Var::V, &self.v)] {
            if let Some(x) = x {
                parts.push((Quantity::Variable(k), Exact::Number(x.0.clone())));
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

impl ToExact for Convention {
    fn to_exact(&self) -> Exact {
        let word = match self {
            Convention::Notes => "notes",
            Convention::NurbsBook => "nurbs_book",
        };
        Exact::Text(word.into())
    }
}

impl ToExact for Spacing {
    fn to_exact(&self) -> Exact {
        let word = match self {
            Spacing::Uniform => "uniform",
            Spacing::OpenUniform => "open_uniform",
        };
        Exact::Text(word.into())
    }
}

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

/// The arguments of an operation as exact values, by kind.
trait Inputs {
    fn inputs(&self) -> Vec<(Argument, Exact)>;
    fn shapes(&self) -> Vec<(Argument, Exact)>;
}

/// The table of each operation's arguments, `Struct { field => Argument, ... }`: the one place
/// a field of an argument struct is said to be an [`Argument`]. Expanded into [`Inputs`] and,
/// for the tests, into the fields of each struct with their kinds.
macro_rules! inputs {
    ($($t:ident { $($field:ident => $kind:ident),* $(,)? })*) => {
        $(
            impl Inputs for $t {
                fn inputs(&self) -> Vec<(Argument, Exact)> {
                    let mut out = Vec::new();
                    $(
                        if let Some(x) = &self.$field {
                            out.push((Argument::$kind, x.to_exact()));
                        }
                    )*
                    out
                }
                fn shapes(&self) -> Vec<(Argument, Exact)> {
                    let mut out = Vec::new();
                    $(
                        if let Some(x) = self.$field.as_ref().filter(|x| x.is_shape()) {
                            out.push((Argument::$kind, x.to_exact()));
                        }
                    )*
                    out
                }
            }
        )*

        /// Each argument struct's fields as the table lists them, with their kinds, and the
        /// properties of its derived schema: what the tests compare.
        #[cfg(test)]
        fn table() -> Vec<(&'static str, Vec<(&'static str, Argument)>, Vec<String>)> {
            vec![$((
                stringify!($t),
                vec![$((stringify!($field), Argument::$kind)),*],
                schema_properties(&schemars::schema_for!($t)),
            )),*]
        }
    };
}

inputs! {
    Evaluate {
        surface => Surface,
        curve => Curve,
        triangle => Triangle,
        params => Parameters,
    }
    ClosedForm {
        surface => Surface,
        curve => Curve,
        triangle => Triangle,
    }
    Restrict {
        surface => Surface,
        u => U,
        v => V,
        curve => Curve,
        t => T,
        triangle => Triangle,
        vertices => Vertices,
    }
    Elevate {
        surface => Surface,
        curve => Curve,
        triangle => Triangle,
        by => Elevation,
    }
    Derivative {
        surface => Surface,
        curve => Curve,
        order => Order,
        at => AtBorder,
        triangle => Triangle,
        direction => Direction,
    }
    Blossom {
        curve => Curve,
        surface => Surface,
        triangle => Triangle,
        params => Parameters,
        u => U,
        v => V,
    }
    Subdivide {
        curve => Curve,
        surface => Surface,
        triangle => Triangle,
        t => T,
        u => U,
        v => V,
    }
    Reverse {
        curve => Curve,
        surface => Surface,
        direction => Direction,
        triangle => Triangle,
        order => Order,
    }
    Extract {
        curve => Curve,
        surface => Surface,
    }
    RemoveKnot {
        curve => Curve,
        knot => Knot,
        times => Times,
        surface => Surface,
        direction => Direction,
    }
    ReduceDegree {
        curve => Curve,
        by => Elevation,
        triangle => Triangle,
    }
    Isocurve {
        surface => Surface,
        u => U,
        v => V,
        triangle => Triangle,
        w => W,
    }
    Boundary {
        surface => Surface,
        triangle => Triangle,
    }
    Normal {
        surface => Surface,
        triangle => Triangle,
        params => Parameters,
    }
    Continuity {
        surface => Surface,
        first => First,
        second => Second,
        border => CommonBorder,
        lengths => IntervalLengths,
    }
    CurveContinuity {
        first => First,
        second => Second,
    }
    Interpolate {
        basis => Basis,
        end => EndConditions,
        u => U,
        v => V,
        params => Parameters,
        parametrization => Parametrization,
        degree => Degree,
        tangents => EndDerivatives,
        points => Points,
    }
    Approximate {
        degree => Degree,
        points => Points,
        params => Parameters,
        parametrization => Parametrization,
        knots => Knots,
        knots_u => KnotsU,
        knots_v => KnotsV,
    }
    Translational {
        c => C,
        d => D,
    }
    Ruled {
        c1 => C1,
        c2 => C2,
    }
    Developable {
        surface => Surface,
        c1 => C1,
        c2 => C2,
    }
    GaussianCurvature {
        surface => Surface,
        triangle => Triangle,
    }
    TangentDevelopable {
        curve => Curve,
    }
    Conic {
        points => Points,
        weight => Weight,
    }
    ArcLength {
        curve => Curve,
        t => T,
    }
    Integral {
        curve => Curve,
        t => T,
        knots => Knots,
        degree => Degree,
    }
    Area {
        curve => Curve,
        surface => Surface,
    }
    Loft {
        sections => Sections,
        v => V,
        degree => Degree,
    }
    Coons {
        c1 => C1,
        c2 => C2,
        d1 => D1,
        d2 => D2,
        blend => Blend,
    }
    Revolution {
        curve => Curve,
        arcs => Arcs,
        quadrant => Quadrant,
        interval => Interval,
        sweep => Sweep,
        start => Start,
    }
    Circle {
        radius => Radius,
        arcs => Arcs,
        center => Center,
        interval => Interval,
        sweep => Sweep,
        start => Start,
    }
    InsertKnot {
        curve => Curve,
        surface => Surface,
        knot => Knot,
        times => Times,
        direction => Direction,
    }
    Graph {
        f => Function,
        degree => Degree,
        domain => Domain,
    }
    KnotVector {
        knots => Knots,
        curve => Curve,
        degree => Degree,
        convention => Convention,
        params => Parameters,
        spacing => Spacing,
        control_points => ControlPoints,
        interval => Interval,
    }
    Normalize {
        curve => Curve,
        surface => Surface,
        knots => Knots,
        degree => Degree,
        convention => Convention,
    }
    InvertPoint {
        curve => Curve,
        point => Point,
    }
}

impl Problem {
    /// The arguments of the problem as exact values, in the order written, for the answer
    /// key.
    pub fn inputs(&self) -> Vec<(Argument, Exact)> {
        self.arguments(false)
    }

    /// The curves and surfaces among the arguments (`Exact::Curve`, `Exact::Surface`), in the
    /// order written: what a figure draws of the problem.
    pub fn shapes(&self) -> Vec<(Argument, Exact)> {
        self.arguments(true)
    }

    fn arguments(&self, shapes: bool) -> Vec<(Argument, Exact)> {
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
            Integral,
            Area,
            Loft,
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
            Boundary,
            KnotVector,
            Normalize,
            InvertPoint
        );
        items.sort_by_key(|(k, _)| self.order.iter().position(|w| w == k.name()));
        items
    }
}

/// The property names of a derived schema (the keys of an argument struct).
#[cfg(test)]
fn schema_properties(schema: &schemars::Schema) -> Vec<String> {
    schema
        .get("properties")
        .and_then(serde_json::Value::as_object)
        .map(|p| p.keys().cloned().collect())
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_field_of_every_argument_struct_is_an_argument_of_its_key() {
        for (name, fields, properties) in table() {
            let mut listed: Vec<String> = fields.iter().map(|(f, _)| f.to_string()).collect();
            let mut properties = properties;
            listed.sort();
            properties.sort();
            assert_eq!(listed, properties, "{name}: the table lists every field");
            for (field, argument) in fields {
                assert_eq!(argument.name(), field, "{name}.{field}");
            }
        }
    }

    #[test]
    fn every_argument_is_a_field_and_named_once() {
        let used: Vec<Argument> = table()
            .into_iter()
            .flat_map(|(_, fields, _)| fields.into_iter().map(|(_, a)| a))
            .collect();
        for a in Argument::ALL {
            assert!(used.contains(&a), "{a:?} is no struct's field");
            let same = Argument::ALL
                .iter()
                .filter(|b| b.name() == a.name())
                .count();
            assert_eq!(same, 1, "{}", a.name());
        }
        for a in used {
            assert!(Argument::ALL.contains(&a), "{a:?} is not in Argument::ALL");
        }
    }
}
