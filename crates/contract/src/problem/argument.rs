//! What an argument of a problem is ([`Argument`]): one variant per key of the problem format
//! (docs/format.md), named after what the notes call it. The JSON and the order written use
//! its key ([`Argument::name`]); keys and figures label it by type.

/// An argument of a problem, by its key in the problem format.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Argument {
    /// `surface`: the surface (a Bézier, B-spline or NURBS patch, or a closed form).
    Surface,
    /// `curve`: the curve.
    Curve,
    /// `triangle`: a triangular patch.
    Triangle,
    /// `params`: the parameters (of points to evaluate, of data, of a blossom).
    Parameters,
    /// `u`: what is given in u (an interval [a, b], a split point, the parameters of a grid,
    /// a blossom's arguments u_1, ..., u_m, the isocurve u = u0).
    U,
    /// `v`: what is given in v.
    V,
    /// `t`: what is given in t (an interval [a, b], a split point).
    T,
    /// `w`: the isocurve w = 1 - u - v = w0 of a triangular patch.
    W,
    /// `vertices`: the vertices a, b, c of a sub-triangle of the domain.
    Vertices,
    /// `by`: by how much the degree is raised (or lowered).
    Elevation,
    /// `order`: the order r (or [r, s]) of a derivative; a triangle's vertices in their new
    /// order.
    Order,
    /// `at`: the border a derivative is restricted to (u = 1).
    AtBorder,
    /// `direction`: u or v; a direction [du, dv] of the parameter plane.
    Direction,
    /// `knot`: the knot inserted or removed.
    Knot,
    /// `times`: how many times a knot is inserted or removed.
    Times,
    /// `first`: the first patch (or curve) of a joint.
    First,
    /// `second`: the second patch (or curve) of a joint.
    Second,
    /// `border`: the common border of two patches, u or v.
    CommonBorder,
    /// `lengths`: the parameter lengths [Δu_0, Δu_1] of two patches.
    IntervalLengths,
    /// `basis`: the basis of an interpolant (Bézier, spline, B-spline).
    Basis,
    /// `end`: the end conditions of a spline.
    EndConditions,
    /// `parametrization`: how the parameters are computed from the data.
    Parametrization,
    /// `degree`: the degree p (or bidegree [m, n]).
    Degree,
    /// `tangents`: the end derivatives [c'(t_0), c'(t_n)] of an interpolant.
    EndDerivatives,
    /// `points`: the data points (or a conic's control points).
    Points,
    /// `knots`: the knots of a B-spline least-squares curve.
    Knots,
    /// `knots_u`: the knots in u of a B-spline least-squares surface.
    KnotsU,
    /// `knots_v`: the knots in v of a B-spline least-squares surface.
    KnotsV,
    /// `c`: the curve c(u) of a translational surface.
    C,
    /// `d`: the curve d(v) of a translational surface.
    D,
    /// `c1`: the curve c_1(u) (of a ruled surface; of a Coons patch, at v = 0).
    C1,
    /// `c2`: the curve c_2(u) (of a ruled surface; of a Coons patch, at v = 1).
    C2,
    /// `d1`: the curve d_1(v) of a Coons patch, at u = 0.
    D1,
    /// `d2`: the curve d_2(v) of a Coons patch, at u = 1.
    D2,
    /// `blend`: the blending functions of a Coons patch.
    Blend,
    /// `weight`: the middle weight w of a conic.
    Weight,
    /// `arcs`: the arcs of a circle or of a revolution.
    Arcs,
    /// `quadrant`: the quadrant of one arc of a revolution.
    Quadrant,
    /// `interval`: the parameter interval of a circle.
    Interval,
    /// `sweep`: the sweep angle θ in degrees of an arc or a partial revolution.
    Sweep,
    /// `start`: the start angle α in degrees.
    Start,
    /// `radius`: the radius of a circle.
    Radius,
    /// `center`: the center of a circle.
    Center,
    /// `f`: the function f(x, y) of a graph.
    Function,
    /// `domain`: the triangle of the (x, y) plane a graph is over.
    Domain,
    /// `convention`: how a knot vector is written (the notes' or The NURBS Book's).
    Convention,
    /// `spacing`: how a knot vector is built (uniform or open uniform).
    Spacing,
    /// `control_points`: the number of control points a knot vector is built for.
    ControlPoints,
    /// `point`: the point P of a point inversion.
    Point,
    /// `sections`: the section curves of a lofted surface.
    Sections,
}

impl Argument {
    /// Every argument, in the order of the variants, for the tests of what reads them.
    pub const ALL: [Argument; 50] = [
        Argument::Surface,
        Argument::Curve,
        Argument::Triangle,
        Argument::Parameters,
        Argument::U,
        Argument::V,
        Argument::T,
        Argument::W,
        Argument::Vertices,
        Argument::Elevation,
        Argument::Order,
        Argument::AtBorder,
        Argument::Direction,
        Argument::Knot,
        Argument::Times,
        Argument::First,
        Argument::Second,
        Argument::CommonBorder,
        Argument::IntervalLengths,
        Argument::Basis,
        Argument::EndConditions,
        Argument::Parametrization,
        Argument::Degree,
        Argument::EndDerivatives,
        Argument::Points,
        Argument::Knots,
        Argument::KnotsU,
        Argument::KnotsV,
        Argument::C,
        Argument::D,
        Argument::C1,
        Argument::C2,
        Argument::D1,
        Argument::D2,
        Argument::Blend,
        Argument::Weight,
        Argument::Arcs,
        Argument::Quadrant,
        Argument::Interval,
        Argument::Sweep,
        Argument::Start,
        Argument::Radius,
        Argument::Center,
        Argument::Function,
        Argument::Domain,
        Argument::Convention,
        Argument::Spacing,
        Argument::ControlPoints,
        Argument::Point,
        Argument::Sections,
    ];

    /// The key in the problem format (docs/format.md): `params`, `by`, `knots_u`.
    pub fn name(self) -> &'static str {
        match self {
            Argument::Surface => "surface",
            Argument::Curve => "curve",
            Argument::Triangle => "triangle",
            Argument::Parameters => "params",
            Argument::U => "u",
            Argument::V => "v",
            Argument::T => "t",
            Argument::W => "w",
            Argument::Vertices => "vertices",
            Argument::Elevation => "by",
            Argument::Order => "order",
            Argument::AtBorder => "at",
            Argument::Direction => "direction",
            Argument::Knot => "knot",
            Argument::Times => "times",
            Argument::First => "first",
            Argument::Second => "second",
            Argument::CommonBorder => "border",
            Argument::IntervalLengths => "lengths",
            Argument::Basis => "basis",
            Argument::EndConditions => "end",
            Argument::Parametrization => "parametrization",
            Argument::Degree => "degree",
            Argument::EndDerivatives => "tangents",
            Argument::Points => "points",
            Argument::Knots => "knots",
            Argument::KnotsU => "knots_u",
            Argument::KnotsV => "knots_v",
            Argument::C => "c",
            Argument::D => "d",
            Argument::C1 => "c1",
            Argument::C2 => "c2",
            Argument::D1 => "d1",
            Argument::D2 => "d2",
            Argument::Blend => "blend",
            Argument::Weight => "weight",
            Argument::Arcs => "arcs",
            Argument::Quadrant => "quadrant",
            Argument::Interval => "interval",
            Argument::Sweep => "sweep",
            Argument::Start => "start",
            Argument::Radius => "radius",
            Argument::Center => "center",
            Argument::Function => "f",
            Argument::Domain => "domain",
            Argument::Convention => "convention",
            Argument::Spacing => "spacing",
            Argument::ControlPoints => "control_points",
            Argument::Point => "point",
            Argument::Sections => "sections",
        }
    }
}
