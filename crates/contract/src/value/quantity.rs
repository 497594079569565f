//! What a result or a step of an answer is ([`Quantity`]): one variant per kind of value the
//! operations produce (a closed form and its variables, the normal at a corner of the domain,
//! the first pass C̃ of a grid interpolation, BᵗB...). The JSON writes it by its name
//! ([`Quantity::name`], the identifiers of docs/format.md: `closed_form`, `corner_10`, `BtB`);
//! keys, figures and Python read it by type.

use cagd_poly::Var;
use std::borrow::Cow;

/// The kind of a result or of a named step of an answer.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Quantity {
    /// `closed_form`: the closed form c(u, v), c(t) (or the normal field N(u, v), the
    /// derivative c_u(1, v)...), in its variables.
    ClosedForm(Variables),
    /// `parametrization`: a parametrization written with cos and sin (a surface of
    /// revolution of a profile that is not rational).
    Parametrization,
    /// `curve`: a curve.
    Curve,
    /// `curves`: a list of curves (the two halves of a subdivided curve).
    Curves,
    /// `surface`: a surface.
    Surface,
    /// `surfaces`: a list of surfaces (the pieces of a subdivided or extracted surface).
    Surfaces,
    /// `triangle`: a triangular patch (`{"triangle": rows}`, its control net).
    Triangle,
    /// `triangles`: a list of triangular patches.
    Triangles,
    /// `point`: a point of a curve or surface.
    Point,
    /// `points`: points of a curve or surface.
    Points,
    /// `curve_u0`, `curve_u1`, `curve_v0`, `curve_v1`, `curve_uv1`: the boundary curve of a
    /// patch on one border of its domain.
    BoundaryCurve(Border),
    /// `intervals`: the parameter intervals of a curve's pieces.
    Intervals,
    /// `u_intervals`: the intervals in u of a surface's pieces.
    IntervalsU,
    /// `v_intervals`: the intervals in v of a surface's pieces.
    IntervalsV,
    /// `pieces`: the polynomial pieces of a spline, each on its interval or rectangle.
    Pieces,
    /// `knot_lines`: the knot lines of a spline surface and the continuity across each.
    KnotLines,
    /// `order`: the order of continuity (C^k), or a spline's order.
    Order,
    /// `geometric`: the order of geometric continuity (G^k) of two joined curves.
    GeometricOrder,
    /// `alpha`: α of a G¹ joint, c₂'(a) = α c₁'(b).
    Alpha,
    /// `beta`: β of a G² joint, c₂''(a) = α² c₁''(b) + β c₁'(b).
    Beta,
    /// `derivatives_first`, `derivatives_second`: the derivatives of the first (at its end)
    /// or the second curve (at its start) of a joint.
    JoinDerivatives(Side),
    /// `smoothness`: the continuity across the common border of two patches, in words.
    Smoothness,
    /// `fails`: the condition of continuity that fails.
    Fails,
    /// `closed_form_first`, `closed_form_second`: the closed forms c(u, v) and c̃(u, v) of
    /// the two patches of a continuity problem.
    PatchClosedForm(Side),
    /// `differences_first`, `differences_second`: the first differences of the two meshes
    /// across the common border (Δ^{1,0} c_{m-1,j} and Δ^{1,0} c̃_{0,j} on the border u).
    BorderDifferences(Side),
    /// `derivative_first`, `derivative_second`: the cross derivatives of the two patches on
    /// the common border (c_u(1, v) and c̃_u(0, v) on the border u).
    BorderDerivative(Side),
    /// `normal_first`, `normal_second`: the normals of the two patches on the common border.
    BorderNormal(Side),
    /// `corner_ij`, `corner_ij_limit`: the normal N(i, j) at a corner of the domain, or,
    /// where it vanishes, the direction of its limit.
    CornerNormal {
        /// The corner.
        corner: Corner,
        /// Whether this is the limit of N at the corner (N vanishes there).
        limit: bool,
    },
    /// `G_ij`: the numerator G of the Gaussian curvature at a corner of the domain.
    CornerNumerator(Corner),
    /// `corner_ij` of a triangular patch's curvature: the numerator G at the vertex (i, j)
    /// of its domain (written by the name of a corner's normal, as docs/format.md has it,
    /// so that [`Quantity::from_name`] reads the name back as [`Quantity::CornerNormal`]).
    VertexNumerator(Corner),
    /// `corners`: the values at the corners of the domain.
    Corners,
    /// `normal`: the normal field N(u, v).
    Normal,
    /// `normals`: normal vectors at points.
    Normals,
    /// `developable`: whether the surface is developable (eq. (8)).
    Developable,
    /// `polynomial`: c_uv · (c_u × c_v), which vanishes for a developable ruled surface.
    DevelopablePolynomial,
    /// `first_cell_planar`: whether the first cell of a ruled mesh is planar.
    FirstCellPlanar,
    /// `last_cell_planar`: whether the last cell of a ruled mesh is planar.
    LastCellPlanar,
    /// `edge_of_regression`: the edge of regression of a tangent developable.
    EdgeOfRegression,
    /// `numerator`: G = L N - M², the numerator of the Gaussian curvature.
    GaussianNumerator,
    /// `sign`: the sign of G on the domain.
    CurvatureSign,
    /// `zeros`: where G vanishes, in words.
    Zeros,
    /// `zero`: a zero of G on the domain.
    Zero,
    /// `sign_change`: points where G > 0 and G < 0.
    SignChange,
    /// `exact`: whether a degree reduction is exact, or a length exact.
    IsExact,
    /// `residual`: what a degree reduction leaves.
    Residual,
    /// `length`: the length of a curve.
    Length,
    /// `speed_squared`: c'·c'.
    SpeedSquared,
    /// `shape_factor`: the shape factor of a conic.
    ShapeFactor,
    /// `kind`: the kind of a conic.
    ConicKind,
    /// `integral`: ∫_a^b c(t) dt of a curve (a point).
    Integral,
    /// `mean`: the parametric mean (1/(b - a)) ∫_a^b c(t) dt of a curve (a point).
    Mean,
    /// `basis_integrals`: ∫ N_i of each B-spline basis function over the domain.
    BasisIntegrals,
    /// `area`: the area enclosed by a closed planar curve, or a planar patch's area.
    Area,
    /// `signed_area`: ½ ∮ (x y' - y x') dt, positive counter-clockwise.
    SignedArea,
    /// `orientation`: the orientation of a closed planar curve, in words.
    Orientation,
    /// `jacobian`: J(u, v) with c_u × c_v = J n, per piece.
    Jacobian,
    /// `plane_normal`: n, the constant normal of a planar patch's plane.
    PlaneNormal,
    /// `domain`: the domain of a fitted curve or surface.
    Domain,
    /// `segment`: the segment of a triangle's domain a curve runs over.
    Segment,
    /// `c_hat`: ĉ, the mesh after the first pass of a patch's subdivision.
    CHat,
    /// `c_tilde`: c̃.
    CTilde,
    /// `d_tilde`: d̃, the first pass of a bicubic spline interpolation.
    DTilde,
    /// `C_tilde`: C̃ = A (B_Vᵗ)⁻¹, the first pass of a grid interpolation (26)-(27).
    CTildeMesh,
    /// `B_U`: the collocation matrix in u of a grid interpolation.
    CollocationU,
    /// `B_V`: the collocation matrix in v of a grid interpolation.
    CollocationV,
    /// `C_x`, `C_y`, `C_z`, `C_w`: a coordinate matrix of a grid's mesh.
    CoordinateMatrix(Axis),
    /// `B`: the collocation matrix of a least-squares fit (28).
    Collocation,
    /// `BtB`: BᵗB, the matrix of the normal equations (29).
    NormalMatrix,
    /// `BtA`: BᵗA, the right-hand side of the normal equations (29).
    NormalRhs,
    /// `c_c`: the ruled patch c_c of a Coons surface.
    CoonsC,
    /// `c_d`: the ruled patch c_d of a Coons surface.
    CoonsD,
    /// `c_cd`: the bilinear patch c_cd of a Coons surface.
    CoonsCd,
    /// `u`, `v`, `t`: a field of a value named by a variable of the domain: a piece's
    /// interval in it (`u: [0, 1/2]`), the value it is fixed at on a border (u = 1).
    Variable(Var),
    /// `direction`: the direction of a knot line, u or v.
    KnotDirection,
    /// `knot`: the knot ξ of a knot line.
    Knot,
    /// `multiplicity`: the multiplicity μ of a knot line's knot.
    Multiplicity,
    /// `expected`: the order of continuity p - μ a knot line's multiplicity gives.
    ExpectedOrder,
    /// `knots`: a knot vector (built, or normalized).
    Knots,
    /// `multiplicities`: the distinct knots of a vector with their multiplicities.
    Multiplicities,
    /// `spans`: the span of each parameter, u_i ≤ t < u_{i+1}.
    Spans,
    /// `span`: the index i of a parameter's span.
    Span,
    /// `weights`: weights (of a rational triangular patch, row by row; of a construction's
    /// control mesh, as a step).
    Weights,
    /// `parameters`: the parameters of a fit's data points when they are computed from the
    /// data (`parametrization`): t_0, ..., t_n of a curve, or `{"u": [...], "v": [...]}` of a
    /// grid.
    DataParameters,
    /// `params`: the parameters t of the domain with c(t) = P (a point inversion).
    Inverse,
    /// `on_curve`: whether the point is on the curve (a point inversion).
    OnCurve,
    /// An intermediate value of a construction named as the notes write it (`a`, `c_u`,
    /// `c_c,1,1`, `s(u, v)`): a symbol that cagd-generate records, none of the names above.
    Symbol(String),
}

/// Which of two patches or curves: the first or the second.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// The first.
    First,
    /// The second.
    Second,
}

/// A corner (i, j) of a domain [a, b] x [c, d]: i, j = 0 at a, c and 1 at b, d.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Corner {
    /// i: 0 at u = a, 1 at u = b.
    pub i: u8,
    /// j: 0 at v = c, 1 at v = d.
    pub j: u8,
}

/// A border of a domain: u = 0, u = 1, v = 0, v = 1, or a triangle's u + v = 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Border {
    /// u = 0.
    U0,
    /// u = 1.
    U1,
    /// v = 0.
    V0,
    /// v = 1.
    V1,
    /// u + v = 1 (a triangle's).
    Uv1,
}

/// A coordinate of a point in space (or its weight w).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    /// x.
    X,
    /// y.
    Y,
    /// z.
    Z,
    /// w.
    W,
}

/// The variables a closed form is in (`u, v`, `t`, `u`), in the order u, v, w, t...; none for
/// a constant.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Variables(pub Vec<Var>);

impl Variables {
    /// The argument list, `u, v` or `t`; `u, v` for none.
    pub fn arguments(&self) -> String {
        if self.0.is_empty() {
            return "u, v".into();
        }
        self.0
            .iter()
            .map(|v| v.name())
            .collect::<Vec<_>>()
            .join(", ")
    }
}

impl Side {
    /// `first` or `second`.
    pub fn name(self) -> &'static str {
        match self {
            Side::First => "first",
            Side::Second => "second",
        }
    }
}

impl Border {
    /// `u0`, `u1`, `v0`, `v1`, `uv1`.
    pub fn name(self) -> &'static str {
        match self {
            Border::U0 => "u0",
            Border::U1 => "u1",
            Border::V0 => "v0",
            Border::V1 => "v1",
            Border::Uv1 => "uv1",
        }
    }

    const ALL: [Border; 5] = [Border::U0, Border::U1, Border::V0, Border::V1, Border::Uv1];
}

impl Axis {
    /// `x`, `y`, `z`, `w`.
    pub fn name(self) -> &'static str {
        match self {
            Axis::X => "x",
            Axis::Y => "y",
            Axis::Z => "z",
            Axis::W => "w",
        }
    }

    /// The axes of a point of `dim` coordinates, x, y, z, w in order.
    pub const ALL: [Axis; 4] = [Axis::X, Axis::Y, Axis::Z, Axis::W];
}

impl Quantity {
    /// The name in the JSON answer (docs/format.md): `closed_form`, `corner_10_limit`, `BtB`.
    pub fn name(&self) -> Cow<'static, str> {
        use Quantity as Q;
        let fixed = match self {
            Q::ClosedForm(_) => "closed_form",
            Q::Parametrization => "parametrization",
            Q::Curve => "curve",
            Q::Curves => "curves",
            Q::Surface => "surface",
            Q::Surfaces => "surfaces",
            Q::Triangle => "triangle",
            Q::Triangles => "triangles",
            Q::Point => "point",
            Q::Points => "points",
            Q::BoundaryCurve(b) => return format!("curve_{}", b.name()).into(),
            Q::Intervals => "intervals",
            Q::IntervalsU => "u_intervals",
            Q::IntervalsV => "v_intervals",
            Q::Pieces => "pieces",
            Q::KnotLines => "knot_lines",
            Q::Order => "order",
            Q::GeometricOrder => "geometric",
            Q::Alpha => "alpha",
            Q::Beta => "beta",
            Q::JoinDerivatives(s) => return format!("derivatives_{}", s.name()).into(),
            Q::Smoothness => "smoothness",
            Q::Fails => "fails",
            Q::PatchClosedForm(s) => return format!("closed_form_{}", s.name()).into(),
            Q::BorderDifferences(s) => return format!("differences_{}", s.name()).into(),
            Q::BorderDerivative(s) => return format!("derivative_{}", s.name()).into(),
            Q::BorderNormal(s) => return format!("normal_{}", s.name()).into(),
            Q::CornerNormal { corner, limit } => {
                let limit = if *limit { "_limit" } else { "" };
                return format!("corner_{}{}{limit}", corner.i, corner.j).into();
            }
            Q::CornerNumerator(c) => return format!("G_{}{}", c.i, c.j).into(),
            Q::VertexNumerator(c) => return format!("corner_{}{}", c.i, c.j).into(),
            Q::Corners => "corners",
            Q::Normal => "normal",
            Q::Normals => "normals",
            Q::Developable => "developable",
            Q::DevelopablePolynomial => "polynomial",
            Q::FirstCellPlanar => "first_cell_planar",
            Q::LastCellPlanar => "last_cell_planar",
            Q::EdgeOfRegression => "edge_of_regression",
            Q::GaussianNumerator => "numerator",
            Q::CurvatureSign => "sign",
            Q::Zeros => "zeros",
            Q::Zero => "zero",
            Q::SignChange => "sign_change",
            Q::IsExact => "exact",
            Q::Residual => "residual",
            Q::Length => "length",
            Q::SpeedSquared => "speed_squared",
            Q::ShapeFactor => "shape_factor",
            Q::ConicKind => "kind",
            Q::Integral => "integral",
            Q::Mean => "mean",
            Q::BasisIntegrals => "basis_integrals",
            Q::Area => "area",
            Q::SignedArea => "signed_area",
            Q::Orientation => "orientation",
            Q::Jacobian => "jacobian",
            Q::PlaneNormal => "plane_normal",
            Q::Domain => "domain",
            Q::Segment => "segment",
            Q::CHat => "c_hat",
            Q::CTilde => "c_tilde",
            Q::DTilde => "d_tilde",
            Q::CTildeMesh => "C_tilde",
            Q::CollocationU => "B_U",
            Q::CollocationV => "B_V",
            Q::CoordinateMatrix(a) => return format!("C_{}", a.name()).into(),
            Q::Collocation => "B",
            Q::NormalMatrix => "BtB",
            Q::NormalRhs => "BtA",
            Q::CoonsC => "c_c",
            Q::CoonsD => "c_d",
            Q::CoonsCd => "c_cd",
            Q::Variable(v) => v.name(),
            Q::KnotDirection => "direction",
            Q::Knot => "knot",
            Q::Multiplicity => "multiplicity",
            Q::ExpectedOrder => "expected",
            Q::Knots => "knots",
            Q::Multiplicities => "multiplicities",
            Q::Spans => "spans",
            Q::Span => "span",
            Q::Weights => "weights",
            Q::DataParameters => "parameters",
            Q::Inverse => "params",
            Q::OnCurve => "on_curve",
            Q::Symbol(s) => return s.clone().into(),
        };
        fixed.into()
    }

    /// The quantity called `name` in an answer (the inverse of [`Quantity::name`]); a closed
    /// form's variables are `variables()` (those of its value, `Exact::variables`): a name
    /// none of the kinds has is a [`Quantity::Symbol`]. Reads a name given from outside (a
    /// construction's step) into the type once.
    pub fn from_name(name: &str, variables: impl FnOnce() -> Variables) -> Quantity {
        use Quantity as Q;
        let side = |s: &str| match s {
            "first" => Some(Side::First),
            "second" => Some(Side::Second),
            _ => None,
        };
        /// A kind of value on one side.
        type Sided = fn(Side) -> Quantity;
        let sided: [(&str, Sided); 5] = [
            ("derivatives_", Q::JoinDerivatives),
            ("closed_form_", Q::PatchClosedForm),
            ("differences_", Q::BorderDifferences),
            ("derivative_", Q::BorderDerivative),
            ("normal_", Q::BorderNormal),
        ];
        for (prefix, make) in sided {
            if let Some(s) = name.strip_prefix(prefix).and_then(side) {
                return make(s);
            }
        }
        if let Some(b) = name
            .strip_prefix("curve_")
            .and_then(|b| Border::ALL.into_iter().find(|x| x.name() == b))
        {
            return Q::BoundaryCurve(b);
        }
        if let Some(a) = name
            .strip_prefix("C_")
            .and_then(|a| Axis::ALL.into_iter().find(|x| x.name() == a))
        {
            return Q::CoordinateMatrix(a);
        }
        if let Some(c) = name.strip_prefix("G_").and_then(Corner::read) {
            return Q::CornerNumerator(c);
        }
        if let Some(rest) = name.strip_prefix("corner_") {
            let (ij, limit) = match rest.strip_suffix("_limit") {
                Some(ij) => (ij, true),
                None => (rest, false),
            };
            if let Some(corner) = Corner::read(ij) {
                return Q::CornerNormal { corner, limit };
            }
        }
        match name {
            "closed_form" => Q::ClosedForm(variables()),
            "parametrization" => Q::Parametrization,
            "curve" => Q::Curve,
            "curves" => Q::Curves,
            "surface" => Q::Surface,
            "surfaces" => Q::Surfaces,
            "triangle" => Q::Triangle,
            "triangles" => Q::Triangles,
            "point" => Q::Point,
            "points" => Q::Points,
            "intervals" => Q::Intervals,
            "u_intervals" => Q::IntervalsU,
            "v_intervals" => Q::IntervalsV,
            "pieces" => Q::Pieces,
            "knot_lines" => Q::KnotLines,
            "order" => Q::Order,
            "geometric" => Q::GeometricOrder,
            "alpha" => Q::Alpha,
            "beta" => Q::Beta,
            "smoothness" => Q::Smoothness,
            "fails" => Q::Fails,
            "corners" => Q::Corners,
            "normal" => Q::Normal,
            "normals" => Q::Normals,
            "developable" => Q::Developable,
            "polynomial" => Q::DevelopablePolynomial,
            "first_cell_planar" => Q::FirstCellPlanar,
            "last_cell_planar" => Q::LastCellPlanar,
            "edge_of_regression" => Q::EdgeOfRegression,
            "numerator" => Q::GaussianNumerator,
            "sign" => Q::CurvatureSign,
            "zeros" => Q::Zeros,
            "zero" => Q::Zero,
            "sign_change" => Q::SignChange,
            "exact" => Q::IsExact,
            "residual" => Q::Residual,
            "length" => Q::Length,
            "speed_squared" => Q::SpeedSquared,
            "shape_factor" => Q::ShapeFactor,
            "kind" => Q::ConicKind,
            "integral" => Q::Integral,
            "mean" => Q::Mean,
            "basis_integrals" => Q::BasisIntegrals,
            "area" => Q::Area,
            "signed_area" => Q::SignedArea,
            "orientation" => Q::Orientation,
            "jacobian" => Q::Jacobian,
            "plane_normal" => Q::PlaneNormal,
            "domain" => Q::Domain,
            "segment" => Q::Segment,
            "c_hat" => Q::CHat,
            "c_tilde" => Q::CTilde,
            "d_tilde" => Q::DTilde,
            "C_tilde" => Q::CTildeMesh,
            "B_U" => Q::CollocationU,
            "B_V" => Q::CollocationV,
            "B" => Q::Collocation,
            "BtB" => Q::NormalMatrix,
            "BtA" => Q::NormalRhs,
            "c_c" => Q::CoonsC,
            "c_d" => Q::CoonsD,
            "c_cd" => Q::CoonsCd,
            "u" => Q::Variable(Var::U),
            "v" => Q::Variable(Var::V),
            "t" => Q::Variable(Var::T),
            "direction" => Q::KnotDirection,
            "knot" => Q::Knot,
            "multiplicity" => Q::Multiplicity,
            "expected" => Q::ExpectedOrder,
            "knots" => Q::Knots,
            "multiplicities" => Q::Multiplicities,
            "spans" => Q::Spans,
            "span" => Q::Span,
            "weights" => Q::Weights,
            "parameters" => Q::DataParameters,
            "params" => Q::Inverse,
            "on_curve" => Q::OnCurve,
            _ => Q::Symbol(name.to_string()),
        }
    }
}

impl Corner {
    /// The four corners of a domain in the order the answers list them: (0, 0), (1, 0),
    /// (0, 1), (1, 1).
    pub const ALL: [Corner; 4] = [
        Corner { i: 0, j: 0 },
        Corner { i: 1, j: 0 },
        Corner { i: 0, j: 1 },
        Corner { i: 1, j: 1 },
    ];

    /// The corner written `ij`, two digits (`10`).
    fn read(ij: &str) -> Option<Corner> {
        match ij.as_bytes() {
            [i, j] if i.is_ascii_digit() && j.is_ascii_digit() => Some(Corner {
                i: i - b'0',
                j: j - b'0',
            }),
            _ => None,
        }
    }
}

impl Quantity {
    /// One quantity of every kind (both sides, every border, axis and corner; two symbols),
    /// for the tests of what reads them.
    pub fn kinds() -> Vec<Quantity> {
        use Quantity as Q;
        let mut all = vec![
            Q::ClosedForm(Variables::default()),
            Q::Parametrization,
            Q::Curve,
            Q::Curves,
            Q::Surface,
            Q::Surfaces,
            Q::Triangle,
            Q::Triangles,
            Q::Point,
            Q::Points,
            Q::Intervals,
            Q::IntervalsU,
            Q::IntervalsV,
            Q::Pieces,
            Q::KnotLines,
            Q::Order,
            Q::GeometricOrder,
            Q::Alpha,
            Q::Beta,
            Q::Smoothness,
            Q::Fails,
            Q::Corners,
            Q::Normal,
            Q::Normals,
            Q::Developable,
            Q::DevelopablePolynomial,
            Q::FirstCellPlanar,
            Q::LastCellPlanar,
            Q::EdgeOfRegression,
            Q::GaussianNumerator,
            Q::CurvatureSign,
            Q::Zeros,
            Q::Zero,
            Q::SignChange,
            Q::IsExact,
            Q::Residual,
            Q::Length,
            Q::SpeedSquared,
            Q::ShapeFactor,
            Q::ConicKind,
            Q::Integral,
            Q::Mean,
            Q::BasisIntegrals,
            Q::Area,
            Q::SignedArea,
            Q::Orientation,
            Q::Jacobian,
            Q::PlaneNormal,
            Q::Domain,
            Q::Segment,
            Q::CHat,
            Q::CTilde,
            Q::DTilde,
            Q::CTildeMesh,
            Q::CollocationU,
            Q::CollocationV,
            Q::Collocation,
            Q::NormalMatrix,
            Q::NormalRhs,
            Q::CoonsC,
            Q::CoonsD,
            Q::CoonsCd,
            Q::Variable(Var::U),
            Q::Variable(Var::V),
            Q::Variable(Var::T),
            Q::KnotDirection,
            Q::Knot,
            Q::Multiplicity,
            Q::ExpectedOrder,
            Q::Knots,
            Q::Multiplicities,
            Q::Spans,
            Q::Span,
            Q::Weights,
            Q::DataParameters,
            Q::Inverse,
            Q::OnCurve,
            Q::Symbol("c_u".into()),
            Q::Symbol("c_c,1,1".into()),
        ];
        for s in [Side::First, Side::Second] {
            all.extend([
                Q::JoinDerivatives(s),
                Q::PatchClosedForm(s),
                Q::BorderDifferences(s),
                Q::BorderDerivative(s),
                Q::BorderNormal(s),
            ]);
        }
        all.extend(Border::ALL.map(Q::BoundaryCurve));
        all.extend(Axis::ALL.map(Q::CoordinateMatrix));
        for corner in Corner::ALL {
            all.extend([
                Q::CornerNormal {
                    corner,
                    limit: false,
                },
                Q::CornerNormal {
                    corner,
                    limit: true,
                },
                Q::CornerNumerator(corner),
                Q::VertexNumerator(corner),
            ]);
        }
        all
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_reads_back_as_its_quantity() {
        let none = Variables::default;
        for q in Quantity::kinds() {
            if let Quantity::VertexNumerator(corner) = q {
                // written by the name of a corner's normal
                let normal = Quantity::CornerNormal {
                    corner,
                    limit: false,
                };
                assert_eq!(Quantity::from_name(&q.name(), none), normal);
                continue;
            }
            assert_eq!(Quantity::from_name(&q.name(), none), q, "{}", q.name());
        }
    }
}
