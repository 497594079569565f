//! The steps of an answer as a teacher writes them: the formula applied (with the notes'
//! equation number), the values substituted, the intermediate values (schemes and tables),
//! then the result. Typed data: the words and the typesetting are cagd-keys' (`steps.rs`),
//! in each language.
//!
//! Symbols are written in a small LaTeX-like notation, `c_{1,2}^{1,0}`, `\alpha_{3}`,
//! `\Delta^{1,0} c_{0,0}`, `\hat{c}`; the key writers print them as text or LaTeX.

use crate::value::Exact;
use serde::Serialize;

/// An equation of the notes: chapter 5 (*Superficies*) or 6 (*Generación de superficies*),
/// and its number there.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Equation {
    /// The chapter (5 or 6).
    pub chapter: u8,
    /// The equation's number in that chapter.
    pub number: u8,
}

/// A formula applied by an operation. The notes number the formulas of chapters 5 and 6
/// ([`Formula::equation`]); the formulas on curves come from chapters 1-4, not in the notes
/// (Farin; Piegl and Tiller), and have no number here.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum Formula {
    /// c_i^r = (1 - t) c_i^{r-1} + t c_{i+1}^{r-1}, c(t) = c_0^n.
    DeCasteljau,
    /// The same on the homogeneous points (w_i c_i, w_i); divide by the weight.
    DeCasteljauRational,
    /// c(t) = Σ c_i B_i^n(t).
    BernsteinSum,
    /// d_i^r = (1 - α_i^r) d_{i-1}^{r-1} + α_i^r d_i^{r-1}.
    DeBoor,
    /// c(t) = Σ d_i N_i^p(t).
    BSplineSum,
    /// A parametrization c(u, v) evaluated by substitution.
    Substitution,
    /// A parametrization c(t) evaluated by substitution.
    SubstitutionCurve,
    /// De Casteljau on a patch, (9)-(11).
    DeCasteljauSurface,
    /// c(u, v) = Σ Σ c_ij B_i^m(u) B_j^n(v), (1).
    BernsteinSurface,
    /// The rational patch, (5).
    RationalSurface,
    /// The B-spline patch, (4).
    BSplineSurface,
    /// The NURBS patch, (6).
    NurbsSurface,
    /// c_i^{(1)} = (i/(n+1)) c_{i-1} + (1 - i/(n+1)) c_i.
    ElevateCurve,
    /// Degree elevation of a B-spline: Bézier pieces, each elevated, knots kept.
    ElevateBSpline,
    /// (14): the columns of the mesh, along u.
    ElevateU,
    /// (15): the rows of the mesh, along v.
    ElevateV,
    /// (14) applied r times at once on a column: c_{i,j}^{r,0} = Σ_k C(m, k) C(r, i - k) /
    /// C(m + r, i) c_{k,j} (the elevation by r of a Bézier polygon, Farin §5.1).
    ElevateUAtOnce,
    /// (15) applied s times at once on a row: c_{i,j}^{r,s} = Σ_l C(n, l) C(s, j - l) /
    /// C(n + s, j) c_{i,l}^{r,0}.
    ElevateVAtOnce,
    /// c̃_i = c[a^{<n-i>}, b^{<i>}].
    RestrictCurve,
    /// (12)-(13): the blossom of the patch, rows first.
    RestrictSurface,
    /// c^{(r)}(t) = n!/(n-r)! Σ Δ^r c_i B_i^{n-r}(t).
    DerivativeCurve,
    /// The derivative of a parametrization, term by term.
    DerivativeMap,
    /// (16)-(18).
    DerivativeSurface,
    /// (19): the derivative on the border u = 0.
    DerivativeBorder0,
    /// (20): the derivative on the border u = 1.
    DerivativeBorder1,
    /// The quotient rule on the rational patch (5).
    DerivativeRational,
    /// Boehm: d̂_i = (1 - α_i) d_{i-1} + α_i d_i, α_i = (t - u_{i-1})/(u_{i+p-1} - u_{i-1}).
    Boehm,
    /// n = c_u × c_v.
    Normal,
    /// (25): n(0, 0) = Δ^{1,0}c_{0,0} × Δ^{0,1}c_{0,0} (times mn).
    CornerNormal,
    /// (21): C^0.
    JoinC0,
    /// (22): C^1.
    JoinC1,
    /// (23): C^r.
    JoinCr,
    /// (26)-(27): B_U C B_V^t = A, in two passes.
    InterpolateSurface,
    /// B C = A with B_ij = B_j^n(t_i).
    InterpolateCurve,
    /// C^2 cubic spline interpolation, with its end conditions.
    InterpolateSpline,
    /// Bicubic spline interpolation: the curve method on the rows, then the columns.
    InterpolateBicubic,
    /// (28)-(29): B^t B C = B^t A.
    LeastSquaresSurface,
    /// B^t B C = B^t A for a curve.
    LeastSquaresCurve,
    /// c(t) = Σ c_i B_i^n(t) expanded.
    ClosedFormCurve,
    /// c(t) = Σ w_i c_i B_i^n(t) / Σ w_i B_i^n(t).
    ClosedFormRationalCurve,
    /// (3): c_ij = (i/m, j/n, ĉ_ij).
    Graph,
    /// The circle of N arcs: middle weights cos(π/N).
    Circle,
    /// (1): c(u, v) = c_1(u) + d_1(v) - a.
    Translational,
    /// (4)/(5): c_ij = c_{1i} + d_{1j} - a, w_ij = w_{1i} ω_{1j}.
    TranslationalMesh,
    /// (7): c(u, v) = (1 - v) c_1(u) + v c_2(u).
    Ruled,
    /// The ruled mesh: rows c_1 and c_2, bidegree (m, 1).
    RuledMesh,
    /// (9): c_uv · (c_u × c_v) = 0.
    Developable,
    /// (10): for a ruled surface.
    DevelopableRuled,
    /// (15): c_c and c_d.
    CoonsRuled,
    /// (16): c_cd.
    CoonsBilinear,
    /// (17): c = c_c + c_d - c_cd.
    Coons,
    /// (18)-(19): the mesh of the Bézier Coons patch.
    CoonsMesh,
    /// Coons with cubic blending functions.
    CoonsCubic,
    /// (21): c(u, v) = (f(u) cos v, f(u) sin v, g(u)).
    Revolution,
    /// The mesh of revolution: rows the circles C_i of the vertices, w_ij = w_i ω_j.
    RevolutionMesh,
    /// De Casteljau on a triangular net: b^l_{ijk} = r b^{l-1}_{i+1,j,k} + s b^{l-1}_{i,j+1,k}
    /// + t b^{l-1}_{i,j,k+1}.
    DeCasteljauTriangle,
    /// b(u, v) = Σ b_{ijk} n!/(i! j! k!) r^i s^j t^k, r = 1 - u - v, s = u, t = v.
    BernsteinTriangle,
    /// b^{(1)}_{ijk} = (i b_{i-1,j,k} + j b_{i,j-1,k} + k b_{i,j,k-1})/(n + 1).
    ElevateTriangle,
    /// D_d b = n Σ (d_1 b_{i+1,j,k} + d_2 b_{i,j+1,k} + d_3 b_{i,j,k+1}) B^{n-1}_{ijk}.
    DerivativeTriangle,
    /// b[x_1, ..., x_n]: De Casteljau with x_l at level l.
    BlossomTriangle,
    /// The split at x into three patches, read off the levels of De Casteljau at x.
    SubdivideTriangle,
    /// The boundary curves of a triangular net: its three edges.
    BoundaryTriangle,
    /// c[t_1, ..., t_n]: De Casteljau with t_r at level r.
    BlossomCurve,
    /// (12): c[u_1, ..., u_m; v_1, ..., v_n], rows then columns.
    BlossomSurface,
    /// The split at t: left c_0^0, ..., c_0^n; right c_0^n, ..., c_n^0.
    SubdivideCurve,
    /// The split at (u0, v0) into four patches (De Casteljau on rows, then columns).
    SubdivideSurface,
    /// The four boundary curves: the first and last rows and columns of the mesh.
    BoundarySurface,
    /// d_j = Σ_i c_{ij} B_i^m(u0) (u = u0), or e_i = Σ_j c_{ij} B_j^n(v0) (v = v0).
    Isocurve,
    /// Bézier extraction: every breakpoint inserted up to multiplicity p.
    Extract,
    /// Knot removal: the inverse of Boehm's insertion, exact only when the curve is unchanged.
    RemoveKnot,
    /// c̃_i = c_{n-i}; knots ũ = a + b - u in reverse order.
    Reverse,
    /// The curve is of lower degree: the elevation is inverted exactly.
    ReduceExact,
    /// Least squares of the polygon: E^t E c̃ = E^t c, E the elevation matrix.
    ReduceLeastSquares,
    /// A B-spline (NURBS) surface piece by piece: on each rectangle of spans a Bézier
    /// (rational Bézier) patch, from the breakpoints inserted to full multiplicity, (4)/(6).
    PiecewiseSurface,
    /// The derivative of a B-spline surface in u: Δ_u d_{i,j} = p (d_{i+1,j} - d_{i,j}) /
    /// (u_{i+p} - u_i), a B-spline of degree p - 1 in u.
    DerivativeBSplineSurface,
    /// Across a knot ξ of multiplicity μ a B-spline of degree p is C^{p-μ}.
    KnotLineContinuity,
    /// The derivative of a B-spline curve: Δ d_i = p (d_{i+1} - d_i) / (u_{i+p} - u_i).
    DerivativeBSplineCurve,
    /// The derivative of a rational curve: c' = (p' w - p w') / w^2, with c = p/w.
    DerivativeRationalCurve,
    /// A B-spline (NURBS) curve piece by piece: a Bézier (rational Bézier) curve per span.
    PiecewiseCurve,
    /// C^r join of two curves: c_1^{(k)}(b) = c_2^{(k)}(a), k = 0, ..., r.
    CurveJoinC,
    /// G^1 and G^2 joins: c_2' = α c_1' (α > 0), c_2'' = α² c_1'' + β c_1'.
    CurveJoinG,
    /// (8): L N - M² = 0, the Gaussian curvature vanishes.
    Developable8,
    /// K = (L N - M²)/|n|⁴; for c = p/w through det(P, P_u, P_v, P_xy) = -w⁴ (c_xy · n).
    GaussianNumerator,
    /// Averaged knots of a B-spline interpolant (The NURBS Book (9.8)).
    AveragedKnots,
    /// B-spline interpolant with end derivatives D_0, D_n (The NURBS Book (9.19)-(9.22)).
    EndDerivativeKnots,
    /// The conic arc (c_0, c_1, c_2) with weights (1, w, 1); shape factor w².
    ConicShape,
    /// c(u, v) = c(u) + v c'(u), normal v c'' × c'.
    TangentDevelopable,
    /// L = ∫ |c'(t)| dt, exact when c'·c' = σ².
    ArcLength,
    /// The restriction of a triangular patch to the sub-triangle (a, b, c):
    /// c_{ijk} = b[a^i, b^j, c^k].
    RestrictTriangle,
    /// The iso-line of a triangular patch over the segment p q of its domain:
    /// c_l = b[p^{n-l}, q^l].
    IsocurveTriangle,
    /// The vertices of a triangular patch relabelled: c_{ijk} = b[e_{σ1}^i, e_{σ2}^j, e_{σ3}^k].
    ReverseTriangle,
    /// A tensor-product patch reversed in u (c̃_{ij} = c_{m-i,j}) or in v (c̃_{ij} = c_{i,n-j}),
    /// knots ũ = a + b - u in reverse order.
    ReverseSurface,
    /// The graph of f(x, y) over a triangle (A, B, C) as a triangular patch:
    /// b_{ijk} = ((i A + j B + k C)/n, f̂_{ijk}).
    GraphTriangle,
    /// A rational triangular patch b = Σ w_{ijk} b_{ijk} B^n_{ijk} / Σ w_{ijk} B^n_{ijk}: every
    /// algorithm on the homogeneous net (w b, w), then divided by the last coordinate.
    RationalTriangle,
    /// Exact degree reduction of a triangular patch: its closed form (homogeneous when
    /// rational) has total degree ≤ n - r, and its Bernstein coefficients of degree n - r are
    /// the net.
    ReduceTriangle,
    /// Two B-spline (NURBS) surfaces joined along a border: the second moved to begin where
    /// the first ends, the derivatives of the pieces that meet compared at the border.
    SplinePatchesJoin,
    /// L = ∫ |σ|/w² dt for c = p/w with |p' w - p w'|² = σ², exact through g/w, g' w - g w' = σ.
    ArcLengthRational,
    /// The span of t (The NURBS Book, A2.1 FindSpan): the i with u_i ≤ t < u_{i+1}, the last
    /// non-empty span at the right end of the domain.
    FindSpan,
    /// A uniform knot vector: u_i = a + i (b - a)/(n + p), i = 0, ..., n + p (The NURBS Book's
    /// indices).
    UniformKnots,
    /// An open uniform knot vector: a and b each p + 1 times, u_{p+j} = a + j (b - a)/(n - p).
    OpenUniformKnots,
    /// Knots onto [0, 1]: ũ_i = (u_i - a)/(b - a), c̃(s) = c(a + s (b - a)).
    NormalizeKnots,
    /// Point inversion (The NURBS Book §6.1): the t with c(t) = P are the common roots of
    /// x_i(t) - P_i w(t), i = 1, ..., d: the roots of their gcd.
    PointInversion,
    /// ∫_0^1 B_i^n(t) dt = 1/(n + 1), so ∫_a^b c(t) dt = (b - a)/(n + 1) Σ b_i.
    BezierIntegral,
    /// ∫ c(t) dt of a polynomial curve, piece by piece from its closed forms.
    CurveIntegral,
    /// ∫ N_i^p = (t_{i+p+1} - t_i)/(p + 1) (full knots), ∫ c = Σ d_i ∫ N_i^p.
    BasisIntegral,
    /// A = ½ ∮ (x y' - y x') dt, positive counter-clockwise.
    EnclosedArea,
    /// ∬ |c_u × c_v| du dv = |∬ J du dv| |n| for c_u × c_v = J n, J of one sign.
    PatchArea,
    /// A lofted (skinned) surface: each column Σ_k Q_{i,k} N_k^q(v_l) = P_{i,l}.
    Loft,
}

impl Formula {
    /// The notes' number of the formula, when they number it.
    pub fn equation(self) -> Option<Equation> {
        use Formula::*;
        let (chapter, number) = match self {
            BernsteinSurface => (5, 1),
            Graph => (5, 3),
            BSplineSurface | PiecewiseSurface => (5, 4),
            RationalSurface | DerivativeRational | ClosedFormRationalCurve => (5, 5),
            NurbsSurface => (5, 6),
            DeCasteljauSurface => (5, 9),
            RestrictSurface => (5, 13),
            ElevateU => (5, 14),
            ElevateV => (5, 15),
            DerivativeSurface => (5, 18),
            DerivativeBorder0 => (5, 19),
            DerivativeBorder1 => (5, 20),
            JoinC0 => (5, 21),
            JoinC1 => (5, 22),
            JoinCr | SplinePatchesJoin => (5, 23),
            CornerNormal => (5, 25),
            InterpolateSurface => (5, 27),
            LeastSquaresSurface => (5, 29),
            Translational => (6, 1),
            TranslationalMesh => (6, 5),
            Ruled => (6, 7),
            Developable => (6, 9),
            Developable8 | GaussianNumerator => (6, 8),
            DevelopableRuled => (6, 10),
            CoonsRuled => (6, 15),
            CoonsBilinear => (6, 16),
            Coons | CoonsCubic => (6, 17),
            CoonsMesh => (6, 19),
            Revolution | RevolutionMesh => (6, 21),
            BlossomSurface => (5, 12),
            SubdivideSurface => (5, 13),
            _ => return None,
        };
        Some(Equation { chapter, number })
    }
}

/// A fact of the work, stated in words by the key writers (in each language).
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "fact", rename_all = "snake_case")]
#[non_exhaustive]
pub enum Fact {
    /// The parameter t lies in the span u_{k-1} ≤ t < u_k (notes' indices) = [left, right).
    Span(Box<Span>),
    /// The points `first..=last` of the polygon change; the others are kept.
    Changed {
        /// The first new point.
        first: usize,
        /// The last new point.
        last: usize,
    },
    /// Insertion number `step` of `of`.
    Insertion {
        /// This insertion (from 1).
        step: usize,
        /// How many.
        of: usize,
    },
    /// The work is done on the homogeneous points (w c, w), then divided by the weight.
    Homogeneous,
    /// Along u: the algorithm is applied to each column j of the mesh.
    AlongU,
    /// Along v: to each row i of the mesh (of the points of the first pass).
    AlongV,
    /// Along u: the same work in each column j of the mesh (same knots, same ratios).
    EachColumn,
    /// Along v: the same work in each row i of the mesh.
    EachRow,
    /// From degree `from` to `to`.
    Degree {
        /// The degree before.
        from: usize,
        /// The degree after.
        to: usize,
    },
    /// The point at the parameter (u, v) or t, for a list of several.
    At {
        /// The parameter(s).
        params: Vec<Exact>,
    },
    /// The mesh is built by the construction's formula; the intermediate values follow.
    Construction,
    /// The steps are worked for the first `shown` points; the `more` others are found in the
    /// same way (a key with a scheme per point of a long list is not read).
    SameForTheOthers {
        /// The points worked.
        shown: usize,
        /// The points not worked.
        more: usize,
    },
    /// The steps are worked for the first `shown` columns (rows) of a mesh; the `more` others
    /// are worked in the same way (a key with a scheme per column of a big mesh is not read:
    /// beyond a few columns or rows).
    SameInTheOtherLines {
        /// Columns or rows.
        line: Line,
        /// The lines worked.
        shown: usize,
        /// The lines not worked.
        more: usize,
    },
    /// The restriction (13), first pass as the notes do it: each row i of the mesh, a
    /// polygon in v, restricted to [c, d] by the polar form of curves: the mesh ĉ.
    RestrictRows,
    /// The restriction (13), second pass: each column j of ĉ, a polygon in u, restricted to
    /// [a, b]: the mesh c̃.
    RestrictColumns,
    /// A curve of a construction (ruled, Coons) raised to the degree of its partner before
    /// the mesh is built: `curve` (a symbol, `c_1`) from degree `from` to `to`, the degree of
    /// `partner` (`c_2`).
    CurveElevated {
        /// The curve raised.
        curve: String,
        /// Its degree.
        from: usize,
        /// The degree it is raised to.
        to: usize,
        /// The curve whose degree that is.
        partner: String,
    },
    /// A pass of bicubic spline interpolation on a grid: along v, each row i of data points
    /// is a cubic spline interpolation N_V D̃_i = A_i (one matrix for every row), giving the
    /// mesh d̃; along u, each column j of d̃ likewise, N_U D_j = Ã_j.
    SplinePass {
        /// The rows of the data (first pass) or the columns of d̃ (second pass).
        line: Line,
    },
    /// The Bézier piece number `index` (from 0) of a B-spline, on [from, to].
    Piece {
        /// The piece.
        index: usize,
        /// Its interval [from, to].
        interval: Vec<Exact>,
    },
}

/// The lines of a mesh: its columns j (along u) or its rows i (along v).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Line {
    /// The columns j of the mesh (the work along u).
    Column,
    /// The rows i of the mesh (the work along v).
    Row,
}

/// What the entries of a matrix are (a matrix shown by its size and first rows).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum Entries {
    /// B_U = (B_k^m(u_i)) (or B_V): row i holds the Bernstein polynomials at the parameter
    /// u_i, (27).
    Bernstein,
    /// B of (28): row k holds B_i^m(u_k) B_j^n(v_k) in column i (n + 1) + j.
    TensorBernstein,
    /// BᵗB of (29): entry (a, b) = Σ_k B_{k,a} B_{k,b}, a symmetric matrix.
    NormalMatrix,
    /// BᵗA of (29): row a = Σ_k B_{k,a} a_k, the coordinates of a point.
    NormalRhs,
}

/// A matrix too big to print whole: its size, what its entries are, and its first rows.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MatrixSummary {
    /// The matrix's symbol.
    pub symbol: String,
    /// Its rows.
    pub rows: usize,
    /// Its columns.
    pub cols: usize,
    /// What its entries are.
    pub entries: Entries,
    /// Its first rows, whole (a matrix of a few rows).
    pub first_rows: Exact,
}

/// Where a parameter lies: u_{k-1} ≤ t < u_k (notes' indices) = [left, right).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Span {
    /// The name of the knots: `u` (curves, and a patch along u) or `v`.
    pub knots: String,
    /// The parameter.
    pub t: Exact,
    /// The notes' index k of the right end of the span.
    pub k: usize,
    /// u_{k-1}.
    pub left: Exact,
    /// u_k.
    pub right: Exact,
}

/// A table of intermediate values: a De Casteljau scheme (columns r = 0, ..., n), a De Boor
/// table, basis values.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Table {
    /// The heading of each column (a symbol).
    pub columns: Vec<String>,
    /// The rows: a label (a symbol) and a cell per column (empty outside the scheme).
    pub rows: Vec<(String, Vec<Option<Exact>>)>,
}

/// One step of the work.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum Step {
    /// The formula applied, with the notes' equation.
    Formula {
        /// Which formula.
        formula: Formula,
        /// Its number in the notes.
        #[serde(skip_serializing_if = "Option::is_none")]
        equation: Option<Equation>,
    },
    /// A value: `symbol = value` (a parameter substituted, an intermediate value).
    Value {
        /// The symbol.
        symbol: String,
        /// The value.
        value: Exact,
    },
    /// `symbol = Σ coefficient · term = Σ coefficient · value = value`: the substitution into
    /// a formula.
    Combination {
        /// The symbol computed.
        symbol: String,
        /// The terms: coefficient, symbol, and the symbol's value.
        terms: Vec<(Exact, String, Exact)>,
        /// The value.
        value: Exact,
    },
    /// A table of intermediate values, with what it is.
    Table {
        /// What the table is (its title).
        title: TableTitle,
        /// The table.
        table: Table,
    },
    /// A fact in words.
    Fact(Fact),
    /// A matrix too big to print whole: its size, what its entries are, its first rows.
    Matrix(Box<MatrixSummary>),
    /// `symbol = Π factor = Π value = value`: a product (a weight w_{1i} ω_{1j} of (5)).
    Product {
        /// The symbol computed.
        symbol: String,
        /// The factors: their symbols and values.
        factors: Vec<(String, Exact)>,
        /// The value.
        value: Exact,
    },
    /// `symbol = equals`, both symbols: a general formula in the notes' factored form, as
    /// the notes print it, where its expansion in the letters of a generic mesh would not be
    /// read (n(0, 0) = mn (c_{1,0} - c_{0,0}) × (c_{0,1} - c_{0,0}), (25)).
    Identity {
        /// The left side.
        symbol: String,
        /// The right side, factored.
        equals: String,
    },
}

/// What a table holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
#[non_exhaustive]
pub enum TableTitle {
    /// A De Casteljau scheme.
    DeCasteljau,
    /// A De Boor table.
    DeBoor,
    /// Basis values (Bernstein or B-spline).
    Basis,
    /// Forward differences.
    Differences,
    /// The ratios α_i.
    Alphas,
}

impl Step {
    /// The formula `f`, with its equation number.
    pub fn formula(f: Formula) -> Step {
        Step::Formula {
            formula: f,
            equation: f.equation(),
        }
    }

    /// `symbol = value`.
    pub fn value(symbol: impl Into<String>, value: Exact) -> Step {
        Step::Value {
            symbol: symbol.into(),
            value,
        }
    }
}
