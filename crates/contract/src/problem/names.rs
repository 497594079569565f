//! The operations' table: each operation's name in the problem format and its variant of
//! [`super::Op`], whose arguments are the struct of the same name. One table, expanded twice:
//! into [`NAMES`] here, a leaf that any message may name, and into the typed operation
//! (`op.rs`), which reads the arguments.

/// Calls the macro `$then` with the table `"name" => Variant(Arguments),`, in the order of
/// `docs/format.md`.
macro_rules! operations_table {
    ($then:ident) => {
        $then! {
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
            "knot_vector" => KnotVector(KnotVector),
            "normalize" => Normalize(Normalize),
            "invert_point" => InvertPoint(InvertPoint),
            "integral" => Integral(Integral),
            "area" => Area(Area),
            "loft" => Loft(Loft),
        }
    };
}
pub(crate) use operations_table;

macro_rules! names {
    ($($name:literal => $variant:ident($args:ident),)*) => {
        /// Every operation `solve` knows, in the order of `docs/format.md`.
        pub const NAMES: &[&str] = &[$($name),*];
    };
}

operations_table!(names);
