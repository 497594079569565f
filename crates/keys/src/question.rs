//! The question of a problem on a statement sheet: one sentence in the notes' language that
//! asks for what the notes ask of the operation ([`Question`]), never a list of result keys
//! and never the answer.

use crate::Lang;
use cagd_contract::problem::{Basis, Blend, End, UorV};
use cagd_contract::{Op, Problem};
use cagd_words::{said, Message, Phrase};

/// What a problem is about: a curve, a tensor-product surface or a triangular surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Shape {
    /// A curve.
    Curve,
    /// A tensor-product surface.
    Surface,
    /// A triangular surface (Bézier triangle).
    Triangle,
}

impl Shape {
    /// The shape given: a triangle, else a curve when there is one and no surface, else a
    /// surface.
    fn of(surface: bool, curve: bool, triangle: bool) -> Shape {
        match (surface, curve, triangle) {
            (_, _, true) => Shape::Triangle,
            (false, true, false) => Shape::Curve,
            _ => Shape::Surface,
        }
    }
}

impl Message for Shape {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Shape::Curve => said(lang, "the curve", "la curva", []),
            Shape::Surface => said(lang, "the surface", "la superficie", []),
            Shape::Triangle => said(
                lang,
                "the triangular surface",
                "la superficie triangular",
                [],
            ),
        }
    }
}

/// How an interpolant is built: a Bézier curve or surface, a cubic (bicubic) spline with its
/// end conditions, or a B-spline of a given degree.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fit {
    /// A Bézier curve or surface (the default basis).
    Bezier,
    /// A C² cubic spline (bicubic for a surface), with its end conditions when given.
    Spline(Option<End>),
    /// A B-spline of the degree given.
    BSpline,
}

/// The end conditions of a spline in words ("natural", "Bessel's", "with given end
/// derivatives").
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
struct Ends(End);

impl Message for Ends {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self.0 {
            End::Natural => said(lang, "natural end conditions", "condiciones naturales", []),
            End::Bessel => said(
                lang,
                "Bessel's end tangents",
                "tangentes de Bessel en los extremos",
                [],
            ),
            End::Clamped => said(
                lang,
                "the given end derivatives",
                "las derivadas dadas en los extremos",
                [],
            ),
        }
    }
}

/// How far a profile turns about the Z axis.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Turn {
    /// A quadrant (one arc, the default), the quadrant's number when given.
    Quadrant(Option<u64>),
    /// A full turn in the arcs given.
    Full(u64),
    /// A sweep of the angle given (in degrees, as written), from the start angle when given.
    Sweep(String, Option<String>),
}

/// The question of a problem, by operation: what the notes ask of it, with what changes the
/// sentence (the shape given, the blending, the basis, the turn).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Question {
    /// `closed_form`.
    ClosedForm(Shape),
    /// `graph`: over the unit square, or over a triangle.
    Graph {
        /// Over a triangle of the plane.
        triangle: bool,
    },
    /// `evaluate`.
    Evaluate(Shape),
    /// `restrict`.
    Restrict(Shape),
    /// `elevate`.
    Elevate(Shape),
    /// `derivative`, on a border when `border`.
    Derivative {
        /// The shape derived.
        shape: Shape,
        /// Restricted to a border.
        border: bool,
    },
    /// `normal`.
    Normal(Shape),
    /// `continuity`: of two patches across their common border (u = 1 of the first and
    /// u = 0 of the second, or the same in v), or of the pieces of one B-spline surface
    /// (`None`).
    Continuity {
        /// The common border of two patches; `None` for one B-spline surface.
        border: Option<UorV>,
    },
    /// `curve_continuity`.
    CurveContinuity,
    /// `interpolate`.
    Interpolate {
        /// A surface through a grid (a curve otherwise).
        surface: bool,
        /// The interpolant.
        fit: Fit,
    },
    /// `approximate`.
    Approximate {
        /// A surface (a curve otherwise).
        surface: bool,
        /// A B-spline on the knots given (Bézier otherwise).
        bspline: bool,
    },
    /// `translational`, its mesh asked for when both curves have control points.
    Translational {
        /// Both curves have control points.
        mesh: bool,
    },
    /// `ruled`.
    Ruled {
        /// Both curves have control points.
        mesh: bool,
    },
    /// `developable`: a ruled surface, or the ruled surface of two curves.
    Developable {
        /// Given by its two curves.
        curves: bool,
    },
    /// `gaussian_curvature`.
    GaussianCurvature(Shape),
    /// `tangent_developable`.
    TangentDevelopable,
    /// `coons`.
    Coons {
        /// The blending functions.
        blend: Blend,
        /// All four curves have control points.
        mesh: bool,
    },
    /// `revolution`.
    Revolution(Turn),
    /// `insert_knot`, `times` times.
    InsertKnot {
        /// The shape.
        shape: Shape,
        /// How many times.
        times: u64,
    },
    /// `circle`: the unit circle when no radius or centre is given; an arc when a sweep is.
    Circle {
        /// An arc (a sweep angle given).
        arc: bool,
    },
    /// `blossom`.
    Blossom(Shape),
    /// `subdivide`.
    Subdivide(Shape),
    /// `boundary`.
    Boundary(Shape),
    /// `isocurve`.
    Isocurve(Shape),
    /// `extract`.
    Extract(Shape),
    /// `remove_knot`.
    RemoveKnot(Shape),
    /// `reverse`.
    Reverse(Shape),
    /// `reduce_degree`.
    ReduceDegree(Shape),
    /// `conic`.
    Conic,
    /// `arc_length`, on the interval given or the whole domain.
    ArcLength {
        /// An interval [a, b] is given.
        interval: bool,
    },
    /// `knot_vector`: a vector built (`spacing`), or the multiplicities of a vector's knots
    /// and, with parameters, their spans.
    KnotVector {
        /// A vector is built.
        build: bool,
        /// Parameters are given, whose spans are asked.
        spans: bool,
    },
    /// `invert_point`: the parameters of a point of a curve.
    InvertPoint,
    /// `normalize`: a curve's or a surface's knots (or the knots alone) onto [0, 1].
    Normalize {
        /// A curve is given.
        curve: bool,
        /// A surface is given.
        surface: bool,
    },
    /// `integral` of a curve, on the interval given or the whole domain.
    Integral {
        /// An interval [a, b] is given.
        interval: bool,
    },
    /// `integral` of the B-spline basis functions of a knot vector.
    BasisIntegrals,
    /// `area` enclosed by a closed curve.
    EnclosedArea,
    /// `area` of a planar patch.
    PatchArea,
    /// `loft`.
    Loft,
}

/// Whether a curve has control points (a Bézier or B-spline curve, not a closed form).
fn has_points(c: &Option<cagd_contract::input::CurveIn<cagd_contract::value::Number>>) -> bool {
    matches!(
        c,
        Some(cagd_contract::input::CurveIn::Bezier { .. })
            | Some(cagd_contract::input::CurveIn::BSpline { .. })
    )
}

impl Question {
    /// The question of a problem, read from its typed operation.
    pub fn of(problem: &Problem) -> Question {
        match &problem.op {
            Op::ClosedForm(a) => Question::ClosedForm(Shape::of(
                a.surface.is_some(),
                a.curve.is_some(),
                a.triangle.is_some(),
            )),
            Op::Graph(a) => Question::Graph {
                triangle: a.domain.is_some(),
            },
            Op::Evaluate(a) => Question::Evaluate(Shape::of(
                a.surface.is_some(),
                a.curve.is_some(),
                a.triangle.is_some(),
            )),
            Op::Restrict(a) => Question::Restrict(Shape::of(
                a.surface.is_some(),
                a.curve.is_some(),
                a.triangle.is_some(),
            )),
            Op::Elevate(a) => Question::Elevate(Shape::of(
                a.surface.is_some(),
                a.curve.is_some(),
                a.triangle.is_some(),
            )),
            Op::Derivative(a) => Question::Derivative {
                shape: Shape::of(a.surface.is_some(), a.curve.is_some(), a.triangle.is_some()),
                border: a.at.is_some(),
            },
            Op::Normal(a) => {
                Question::Normal(Shape::of(a.surface.is_some(), false, a.triangle.is_some()))
            }
            Op::Continuity(a) => Question::Continuity {
                border: match a.surface.is_some() && a.first.is_none() {
                    true => None,
                    false => Some(a.border.unwrap_or(UorV::U)),
                },
            },
            Op::CurveContinuity(_) => Question::CurveContinuity,
            Op::Interpolate(a) => Question::Interpolate {
                surface: matches!(a.points, Some(cagd_contract::spec::PointData::Grid(_))),
                fit: match a.basis {
                    None | Some(Basis::Bezier) => Fit::Bezier,
                    Some(Basis::Bicubic) => Fit::Spline(a.end),
                    Some(Basis::Bspline) => Fit::BSpline,
                },
            },
            Op::Approximate(a) => Question::Approximate {
                surface: matches!(a.degree, Some(cagd_contract::spec::Orders::Two(..))),
                bspline: a.knots.is_some() || a.knots_u.is_some(),
            },
            Op::Translational(a) => Question::Translational {
                mesh: has_points(&a.c) && has_points(&a.d),
            },
            Op::Ruled(a) => Question::Ruled {
                mesh: has_points(&a.c1) && has_points(&a.c2),
            },
            Op::Developable(a) => Question::Developable {
                curves: a.surface.is_none(),
            },
            Op::GaussianCurvature(a) => Question::GaussianCurvature(Shape::of(
                a.surface.is_some(),
                false,
                a.triangle.is_some(),
            )),
            Op::TangentDevelopable(_) => Question::TangentDevelopable,
            Op::Coons(a) => Question::Coons {
                blend: a.blend.unwrap_or(Blend::Linear),
                mesh: [&a.c1, &a.c2, &a.d1, &a.d2].into_iter().all(has_points),
            },
            Op::Revolution(a) => Question::Revolution(match (&a.sweep, a.arcs) {
                (Some(s), _) => Turn::Sweep(
                    cagd_scalar::Print::to_text(&s.0),
                    a.start.as_ref().map(|x| cagd_scalar::Print::to_text(&x.0)),
                ),
                (None, Some(n)) if n.0 > 1 => Turn::Full(n.0),
                (None, _) => Turn::Quadrant(a.quadrant.map(|q| q.0)),
            }),
            Op::InsertKnot(a) => Question::InsertKnot {
                shape: Shape::of(a.surface.is_some(), a.curve.is_some(), false),
                times: a.times.map_or(1, |t| t.0),
            },
            Op::Circle(a) => Question::Circle {
                arc: a.sweep.is_some(),
            },
            Op::Blossom(a) => Question::Blossom(Shape::of(
                a.surface.is_some(),
                a.curve.is_some(),
                a.triangle.is_some(),
            )),
            Op::Subdivide(a) => Question::Subdivide(Shape::of(
                a.surface.is_some(),
                a.curve.is_some(),
                a.triangle.is_some(),
            )),
            Op::Boundary(a) => {
                Question::Boundary(Shape::of(a.surface.is_some(), false, a.triangle.is_some()))
            }
            Op::Isocurve(a) => {
                Question::Isocurve(Shape::of(a.surface.is_some(), false, a.triangle.is_some()))
            }
            Op::Extract(a) => {
                Question::Extract(Shape::of(a.surface.is_some(), a.curve.is_some(), false))
            }
            Op::RemoveKnot(a) => {
                Question::RemoveKnot(Shape::of(a.surface.is_some(), a.curve.is_some(), false))
            }
            Op::Reverse(a) => Question::Reverse(Shape::of(
                a.surface.is_some(),
                a.curve.is_some(),
                a.triangle.is_some(),
            )),
            Op::ReduceDegree(a) => {
                Question::ReduceDegree(Shape::of(false, a.curve.is_some(), a.triangle.is_some()))
            }
            Op::Conic(_) => Question::Conic,
            Op::ArcLength(a) => Question::ArcLength {
                interval: a.t.is_some(),
            },
            Op::KnotVector(a) => Question::KnotVector {
                build: a.spacing.is_some(),
                spans: a.params.is_some(),
            },
            Op::InvertPoint(_) => Question::InvertPoint,
            Op::Normalize(a) => Question::Normalize {
                curve: a.curve.is_some(),
                surface: a.surface.is_some(),
            },
            Op::Integral(a) if a.curve.is_none() => Question::BasisIntegrals,
            Op::Integral(a) => Question::Integral {
                interval: a.t.is_some(),
            },
            Op::Area(a) if a.surface.is_some() => Question::PatchArea,
            Op::Area(_) => Question::EnclosedArea,
            Op::Loft(_) => Question::Loft,
        }
    }
}

impl Message for Question {
    fn phrase(&self, lang: Lang) -> Phrase {
        use Shape::{Curve, Surface, Triangle};
        match self {
            Question::ClosedForm(Curve) => said(
                lang,
                "Find the parametrization of the curve.",
                "Calcula la parametrización de la curva.",
                [],
            ),
            Question::ClosedForm(Surface) => said(
                lang,
                "Find the parametrization $c(u, v)$ of the surface.",
                "Calcula la parametrización $c(u, v)$ de la superficie.",
                [],
            ),
            Question::ClosedForm(Triangle) => said(
                lang,
                "Find the parametrization of the triangular surface.",
                "Calcula la parametrización de la superficie triangular.",
                [],
            ),
            Question::Graph { triangle: false } => said(
                lang,
                "Write the graph of $f$ over $[0, 1] × [0, 1]$ as a Bézier surface: find its control mesh and its parametrization $c(u, v)$.",
                "Escribe la gráfica de $f$ sobre $[0, 1] × [0, 1]$ como una superficie de Bézier: calcula su malla de control y su parametrización $c(u, v)$.",
                [],
            ),
            Question::Graph { triangle: true } => said(
                lang,
                "Write the graph of $f$ over the given triangle as a triangular Bézier surface: find its control points.",
                "Escribe la gráfica de $f$ sobre el triángulo dado como una superficie triangular de Bézier: calcula sus puntos de control.",
                [],
            ),
            Question::Evaluate(shape) => said(
                lang,
                "Find the points of «» at the given parameters.",
                "Calcula los puntos de «» en los parámetros dados.",
                [shape.phrase(lang).into()],
            ),
            Question::Restrict(Curve) => said(
                lang,
                "Find the control polygon of the piece of the curve over the given interval of $t$.",
                "Calcula el polígono de control del trozo de la curva sobre el intervalo de $t$ dado.",
                [],
            ),
            Question::Restrict(Surface) => said(
                lang,
                "Find the control mesh of the surface restricted to the subdomain given by the intervals in $u$ and in $v$.",
                "Calcula la malla de control de la superficie restringida al subrecinto que dan los intervalos en $u$ y en $v$.",
                [],
            ),
            Question::Restrict(Triangle) => said(
                lang,
                "Find the control points of the triangular surface restricted to the sub-triangle of the given vertices.",
                "Calcula los puntos de control de la superficie triangular restringida al subtriángulo de los vértices dados.",
                [],
            ),
            Question::Elevate(Curve) => said(
                lang,
                "Raise the degree of the curve as given and find its new control polygon.",
                "Eleva el grado de la curva en lo indicado y calcula su nuevo polígono de control.",
                [],
            ),
            Question::Elevate(Surface) => said(
                lang,
                "Raise the degree of the surface as given and find its new control mesh.",
                "Eleva el grado de la superficie en lo indicado y calcula su nueva malla de control.",
                [],
            ),
            Question::Elevate(Triangle) => said(
                lang,
                "Raise the degree of the triangular surface as given and find its new control points.",
                "Eleva el grado de la superficie triangular en lo indicado y calcula sus nuevos puntos de control.",
                [],
            ),
            Question::Derivative { shape: Curve, .. } => said(
                lang,
                "Find the derivative of the given order of the curve.",
                "Calcula la derivada del orden dado de la curva.",
                [],
            ),
            Question::Derivative {
                shape: Surface,
                border: false,
            } => said(
                lang,
                "Find the partial derivative of the given order of the surface.",
                "Calcula la derivada parcial del orden dado de la superficie.",
                [],
            ),
            Question::Derivative {
                shape: Surface,
                border: true,
            } => said(
                lang,
                "Find the partial derivative of the given order of the surface on the given border.",
                "Calcula la derivada parcial del orden dado de la superficie en el borde dado.",
                [],
            ),
            Question::Derivative {
                shape: Triangle, ..
            } => said(
                lang,
                "Find the derivative of the triangular surface in the given direction.",
                "Calcula la derivada de la superficie triangular en la dirección dada.",
                [],
            ),
            Question::Normal(Triangle) => said(
                lang,
                "Find the normal vector of the triangular surface at the given points.",
                "Calcula el vector normal de la superficie triangular en los puntos dados.",
                [],
            ),
            Question::Normal(_) => said(
                lang,
                "Find the normal vector $c_u × c_v$ of the surface: its parametrization and its value at the four corners.",
                "Calcula el vector normal $c_u × c_v$ de la superficie: su parametrización y su valor en las cuatro esquinas.",
                [],
            ),
            Question::Continuity {
                border: Some(UorV::U),
            } => said(
                lang,
                "With what order of continuity do the two pieces join along their common border, $u = 1$ of the first and $u = 0$ of the second? Justify it with the conditions of the notes.",
                "¿Con qué orden de continuidad se unen los dos trozos a lo largo del borde común, $u = 1$ del primero y $u = 0$ del segundo? Justifícalo con las condiciones de los apuntes.",
                [],
            ),
            Question::Continuity {
                border: Some(UorV::V),
            } => said(
                lang,
                "With what order of continuity do the two pieces join along their common border, $v = 1$ of the first and $v = 0$ of the second? Justify it with the conditions of the notes.",
                "¿Con qué orden de continuidad se unen los dos trozos a lo largo del borde común, $v = 1$ del primero y $v = 0$ del segundo? Justifícalo con las condiciones de los apuntes.",
                [],
            ),
            Question::Continuity { border: None } => said(
                lang,
                "With what order of continuity do the pieces of the surface join along each knot line? Justify it with the conditions of the notes.",
                "¿Con qué orden de continuidad se unen los trozos de la superficie a lo largo de cada línea de nudos? Justifícalo con las condiciones de los apuntes.",
                [],
            ),
            Question::CurveContinuity => said(
                lang,
                "With what order of continuity does the end of the first curve join the start of the second? Justify it with the conditions of the notes.",
                "¿Con qué orden de continuidad se une el final de la primera curva con el principio de la segunda? Justifícalo con las condiciones de los apuntes.",
                [],
            ),
            Question::Interpolate {
                surface: true,
                fit: Fit::Bezier,
            } => said(
                lang,
                "Find the Bézier surface that interpolates the data points: its control mesh and its parametrization $c(u, v)$.",
                "Calcula la superficie de Bézier que interpola los puntos dato: su malla de control y su parametrización $c(u, v)$.",
                [],
            ),
            Question::Interpolate {
                surface: false,
                fit: Fit::Bezier,
            } => said(
                lang,
                "Find the Bézier curve that interpolates the data points: its control polygon.",
                "Calcula la curva de Bézier que interpola los puntos dato: su polígono de control.",
                [],
            ),
            Question::Interpolate {
                surface: true,
                fit: Fit::Spline(Some(end)),
            } => said(
                lang,
                "Find the bicubic spline surface, with «», that interpolates the data points.",
                "Calcula la superficie spline bicúbica, con «», que interpola los puntos dato.",
                [Ends(*end).phrase(lang).into()],
            ),
            Question::Interpolate {
                surface: false,
                fit: Fit::Spline(Some(end)),
            } => said(
                lang,
                "Find the cubic spline curve, with «», that interpolates the data points.",
                "Calcula la curva spline cúbica, con «», que interpola los puntos dato.",
                [Ends(*end).phrase(lang).into()],
            ),
            Question::Interpolate {
                surface: true,
                fit: Fit::Spline(None),
            } => said(
                lang,
                "Find the bicubic spline surface that interpolates the data points.",
                "Calcula la superficie spline bicúbica que interpola los puntos dato.",
                [],
            ),
            Question::Interpolate {
                surface: false,
                fit: Fit::Spline(None),
            } => said(
                lang,
                "Find the cubic spline curve that interpolates the data points.",
                "Calcula la curva spline cúbica que interpola los puntos dato.",
                [],
            ),
            Question::Interpolate {
                fit: Fit::BSpline, ..
            } => said(
                lang,
                "Find the B-spline curve of the given degree that interpolates the data points: its control polygon and its knots.",
                "Calcula la curva B-spline del grado dado que interpola los puntos dato: su polígono de control y sus nudos.",
                [],
            ),
            Question::Approximate {
                surface: true,
                bspline: false,
            } => said(
                lang,
                "Find the Bézier surface of the given bidegree that approximates the data points by least squares: its control mesh and its parametrization $c(u, v)$.",
                "Calcula la superficie de Bézier del bigrado dado que aproxima por mínimos cuadrados los puntos dato: su malla de control y su parametrización $c(u, v)$.",
                [],
            ),
            Question::Approximate {
                surface: true,
                bspline: true,
            } => said(
                lang,
                "Find the B-spline surface of the given bidegree and knots that approximates the data points by least squares: its control mesh.",
                "Calcula la superficie B-spline del bigrado y los nudos dados que aproxima por mínimos cuadrados los puntos dato: su malla de control.",
                [],
            ),
            Question::Approximate {
                surface: false,
                bspline: false,
            } => said(
                lang,
                "Find the Bézier curve of the given degree that approximates the data points by least squares: its control polygon.",
                "Calcula la curva de Bézier del grado dado que aproxima por mínimos cuadrados los puntos dato: su polígono de control.",
                [],
            ),
            Question::Approximate {
                surface: false,
                bspline: true,
            } => said(
                lang,
                "Find the B-spline curve of the given degree and knots that approximates the data points by least squares: its control polygon.",
                "Calcula la curva B-spline del grado y los nudos dados que aproxima por mínimos cuadrados los puntos dato: su polígono de control.",
                [],
            ),
            Question::Translational { mesh: true } => said(
                lang,
                "Find the control mesh of the translational surface of the curves $c$ and $d$, and its parametrization $c(u, v)$.",
                "Calcula la malla de control de la superficie traslacional de las curvas $c$ y $d$, y su parametrización $c(u, v)$.",
                [],
            ),
            Question::Translational { mesh: false } => said(
                lang,
                "Find the parametrization $c(u, v)$ of the translational surface of the curves $c$ and $d$.",
                "Calcula la parametrización $c(u, v)$ de la superficie traslacional de las curvas $c$ y $d$.",
                [],
            ),
            Question::Ruled { mesh: true } => said(
                lang,
                "Find the control mesh of the ruled surface between the curves $c_1$ and $c_2$, and its parametrization $c(u, v)$.",
                "Calcula la malla de control de la superficie reglada entre las curvas $c_1$ y $c_2$, y su parametrización $c(u, v)$.",
                [],
            ),
            Question::Ruled { mesh: false } => said(
                lang,
                "Find the parametrization $c(u, v)$ of the ruled surface between the curves $c_1$ and $c_2$.",
                "Calcula la parametrización $c(u, v)$ de la superficie reglada entre las curvas $c_1$ y $c_2$.",
                [],
            ),
            Question::Developable { curves: false } => said(
                lang,
                "Is the ruled surface developable? Justify it with the criterion of the notes.",
                "¿Es desarrollable la superficie reglada? Justifícalo con el criterio de los apuntes.",
                [],
            ),
            Question::Developable { curves: true } => said(
                lang,
                "Is the ruled surface between the curves $c_1$ and $c_2$ developable? Justify it with the criterion of the notes.",
                "¿Es desarrollable la superficie reglada entre las curvas $c_1$ y $c_2$? Justifícalo con el criterio de los apuntes.",
                [],
            ),
            Question::GaussianCurvature(shape) => said(
                lang,
                "Find the Gaussian curvature of «» and study its sign.",
                "Calcula la curvatura de Gauss de «» y estudia su signo.",
                [shape.phrase(lang).into()],
            ),
            Question::TangentDevelopable => said(
                lang,
                "Find the tangent (developable) surface of the curve, $c(u) + v c'(u)$.",
                "Calcula la superficie tangente (desarrollable) de la curva, $c(u) + v c'(u)$.",
                [],
            ),
            Question::Coons {
                blend: Blend::Linear,
                mesh: true,
            } => said(
                lang,
                "Find the control mesh of the bilinear Coons surface of the boundary curves $c_1$, $c_2$, $d_1$, $d_2$, and its parametrization $c(u, v)$.",
                "Calcula la malla de control de la superficie de Coons bilineal de las curvas borde $c_1$, $c_2$, $d_1$, $d_2$, y su parametrización $c(u, v)$.",
                [],
            ),
            Question::Coons {
                blend: Blend::Linear,
                mesh: false,
            } => said(
                lang,
                "Find the parametrization $c(u, v)$ of the bilinear Coons surface of the boundary curves $c_1$, $c_2$, $d_1$, $d_2$.",
                "Calcula la parametrización $c(u, v)$ de la superficie de Coons bilineal de las curvas borde $c_1$, $c_2$, $d_1$, $d_2$.",
                [],
            ),
            Question::Coons {
                blend: Blend::Cubic,
                ..
            } => said(
                lang,
                "Find the Coons surface of the boundary curves $c_1$, $c_2$, $d_1$, $d_2$ with cubic interpolation functions.",
                "Calcula la superficie de Coons de las curvas borde $c_1$, $c_2$, $d_1$, $d_2$ con funciones de interpolación cúbicas.",
                [],
            ),
            Question::Revolution(Turn::Quadrant(None)) => said(
                lang,
                "Find the control mesh and the weights of the surface of revolution that the curve of the XZ plane sweeps turning a quadrant about the Z axis.",
                "Calcula la malla de control y los pesos de la superficie de revolución que genera la curva del plano XZ al girar un cuadrante alrededor del eje Z.",
                [],
            ),
            Question::Revolution(Turn::Quadrant(Some(q))) => said(
                lang,
                "Find the control mesh and the weights of the surface of revolution that the curve of the XZ plane sweeps turning about the Z axis over quadrant ‹›.",
                "Calcula la malla de control y los pesos de la superficie de revolución que genera la curva del plano XZ al girar alrededor del eje Z en el cuadrante ‹›.",
                [q.into()],
            ),
            Question::Revolution(Turn::Full(arcs)) => said(
                lang,
                "Find the control mesh and the weights of the surface of revolution that the curve of the XZ plane sweeps in a full turn about the Z axis, in ‹› arcs.",
                "Calcula la malla de control y los pesos de la superficie de revolución que genera la curva del plano XZ al dar una vuelta completa alrededor del eje Z, en ‹› arcos.",
                [arcs.into()],
            ),
            Question::Revolution(Turn::Sweep(angle, None)) => said(
                lang,
                "Find the control mesh and the weights of the surface of revolution that the curve of the XZ plane sweeps turning $‹›°$ about the Z axis.",
                "Calcula la malla de control y los pesos de la superficie de revolución que genera la curva del plano XZ al girar $‹›°$ alrededor del eje Z.",
                [angle.into()],
            ),
            Question::Revolution(Turn::Sweep(angle, Some(start))) => said(
                lang,
                "Find the control mesh and the weights of the surface of revolution that the curve of the XZ plane sweeps turning $‹›°$ about the Z axis from the angle $‹›°$.",
                "Calcula la malla de control y los pesos de la superficie de revolución que genera la curva del plano XZ al girar $‹›°$ alrededor del eje Z desde el ángulo $‹›°$.",
                [angle.into(), start.into()],
            ),
            Question::InsertKnot {
                shape: Curve,
                times: 1,
            } => said(
                lang,
                "Insert the given knot in the curve and find its new control polygon.",
                "Inserta el nudo dado en la curva y calcula su nuevo polígono de control.",
                [],
            ),
            Question::InsertKnot {
                shape: Curve,
                times,
            } => said(
                lang,
                "Insert the given knot ‹› times in the curve and find its new control polygon.",
                "Inserta el nudo dado ‹› veces en la curva y calcula su nuevo polígono de control.",
                [times.into()],
            ),
            Question::InsertKnot { times: 1, .. } => said(
                lang,
                "Insert the given knot in the surface, in the given direction, and find its new control mesh.",
                "Inserta el nudo dado en la superficie, en la dirección dada, y calcula su nueva malla de control.",
                [],
            ),
            Question::InsertKnot { times, .. } => said(
                lang,
                "Insert the given knot ‹› times in the surface, in the given direction, and find its new control mesh.",
                "Inserta el nudo dado ‹› veces en la superficie, en la dirección dada, y calcula su nueva malla de control.",
                [times.into()],
            ),
            Question::Circle { arc: false } => said(
                lang,
                "Write the circle of the data as a rational curve: find its control polygon, its weights and its knots.",
                "Escribe la circunferencia de los datos como una curva racional: calcula su polígono de control, sus pesos y sus nudos.",
                [],
            ),
            Question::Circle { arc: true } => said(
                lang,
                "Write the arc of circle of the data as a rational curve: find its control polygon, its weights and its knots.",
                "Escribe el arco de circunferencia de los datos como una curva racional: calcula su polígono de control, sus pesos y sus nudos.",
                [],
            ),
            Question::Blossom(shape) => said(
                lang,
                "Find the value of the blossom of «» at the given arguments.",
                "Calcula el valor de la forma polar de «» en los argumentos dados.",
                [shape.phrase(lang).into()],
            ),
            Question::Subdivide(Curve) => said(
                lang,
                "Subdivide the curve at the given parameter and find the control polygons of the two pieces.",
                "Subdivide la curva en el parámetro dado y calcula los polígonos de control de los dos trozos.",
                [],
            ),
            Question::Subdivide(Surface) => said(
                lang,
                "Subdivide the surface at the given parameters and find the control meshes of the pieces.",
                "Subdivide la superficie en los parámetros dados y calcula las mallas de control de los trozos.",
                [],
            ),
            Question::Subdivide(Triangle) => said(
                lang,
                "Subdivide the triangular surface at the given point and find the control points of the pieces.",
                "Subdivide la superficie triangular en el punto dado y calcula los puntos de control de los trozos.",
                [],
            ),
            Question::Boundary(shape) => said(
                lang,
                "Find the boundary curves of «»: their control polygons.",
                "Calcula las curvas borde de «»: sus polígonos de control.",
                [shape.phrase(lang).into()],
            ),
            Question::Isocurve(shape) => said(
                lang,
                "Find the given iso-parametric curve of «»: its control polygon.",
                "Calcula la curva isoparamétrica dada de «»: su polígono de control.",
                [shape.phrase(lang).into()],
            ),
            Question::Extract(Curve) => said(
                lang,
                "Find the Bézier pieces of the B-spline curve: their control polygons.",
                "Calcula los trozos de Bézier de la curva B-spline: sus polígonos de control.",
                [],
            ),
            Question::Extract(_) => said(
                lang,
                "Find the Bézier pieces of the B-spline surface: their control meshes.",
                "Calcula los trozos de Bézier de la superficie B-spline: sus mallas de control.",
                [],
            ),
            Question::RemoveKnot(Curve) => said(
                lang,
                "Remove the given knot from the curve where it can be removed, and find its new control polygon.",
                "Elimina el nudo dado de la curva, si es posible, y calcula su nuevo polígono de control.",
                [],
            ),
            Question::RemoveKnot(_) => said(
                lang,
                "Remove the given knot from the surface where it can be removed, and find its new control mesh.",
                "Elimina el nudo dado de la superficie, si es posible, y calcula su nueva malla de control.",
                [],
            ),
            Question::Reverse(Curve) => said(
                lang,
                "Reverse the direction of the curve and find its new control polygon.",
                "Invierte el sentido de la curva y calcula su nuevo polígono de control.",
                [],
            ),
            Question::Reverse(Surface) => said(
                lang,
                "Reverse the surface in the given direction and find its new control mesh.",
                "Invierte el sentido de la superficie en la dirección dada y calcula su nueva malla de control.",
                [],
            ),
            Question::Reverse(Triangle) => said(
                lang,
                "Relabel the vertices of the triangular surface in the given order and find its new control points.",
                "Renombra los vértices de la superficie triangular en el orden dado y calcula sus nuevos puntos de control.",
                [],
            ),
            Question::ReduceDegree(Triangle) => said(
                lang,
                "Reduce the degree of the triangular surface, if it can be done exactly, and find its new control points.",
                "Reduce el grado de la superficie triangular, si es posible sin cambiarla, y calcula sus nuevos puntos de control.",
                [],
            ),
            Question::ReduceDegree(_) => said(
                lang,
                "Reduce the degree of the curve as given and find its new control polygon.",
                "Reduce el grado de la curva en lo indicado y calcula su nuevo polígono de control.",
                [],
            ),
            Question::Conic => said(
                lang,
                "Which conic is the quadratic rational Bézier curve of the given control points and middle weight? Find its parametrization.",
                "¿Qué cónica es la curva racional de Bézier cuadrática de los puntos de control y el peso central dados? Calcula su parametrización.",
                [],
            ),
            Question::ArcLength { interval: true } => said(
                lang,
                "Find the arc length of the curve over the given interval.",
                "Calcula la longitud de arco de la curva en el intervalo dado.",
                [],
            ),
            Question::ArcLength { interval: false } => said(
                lang,
                "Find the arc length of the curve over its whole domain.",
                "Calcula la longitud de arco de la curva en todo su dominio.",
                [],
            ),
            Question::KnotVector { build: true, .. } => said(
                lang,
                "Write the knot vector of the given spacing for a curve of the given degree and number of control points.",
                "Escribe la sucesión de nudos del espaciado dado para una curva del grado y el número de puntos de control dados.",
                [],
            ),
            Question::KnotVector { spans: true, .. } => said(
                lang,
                "Find the multiplicity of each knot of the knot vector and the span $u_i ≤ t < u_{i+1}$ of each given parameter.",
                "Calcula la multiplicidad de cada nudo de la sucesión de nudos y el tramo $u_i ≤ t < u_{i+1}$ de cada parámetro dado.",
                [],
            ),
            Question::KnotVector { .. } => said(
                lang,
                "Find the multiplicity of each knot of the knot vector.",
                "Calcula la multiplicidad de cada nudo de la sucesión de nudos.",
                [],
            ),
            Question::InvertPoint => said(
                lang,
                "Find the parameters $t$ of the domain with $c(t) = P$, or show that $P$ is not a point of the curve.",
                "Calcula los parámetros $t$ del dominio con $c(t) = P$, o muestra que $P$ no es un punto de la curva.",
                [],
            ),
            Question::Normalize { surface: true, .. } => said(
                lang,
                "Reparametrize the surface onto $[0, 1] × [0, 1]$: find its knots in $u$ and in $v$, each $(u - a)/(b - a)$ with $[a, b]$ the domain in that direction.",
                "Reparametriza la superficie sobre $[0, 1] × [0, 1]$: calcula sus nudos en $u$ y en $v$, cada uno $(u - a)/(b - a)$ con $[a, b]$ el dominio en esa dirección.",
                [],
            ),
            Question::Normalize { curve: true, .. } => said(
                lang,
                "Reparametrize the curve onto $[0, 1]$: find its knots $(u - a)/(b - a)$, with $[a, b]$ its domain.",
                "Reparametriza la curva sobre $[0, 1]$: calcula sus nudos $(u - a)/(b - a)$, con $[a, b]$ su dominio.",
                [],
            ),
            Question::Normalize { .. } => said(
                lang,
                "Normalize the knot vector onto $[0, 1]$: find the knots $(u - a)/(b - a)$, with $[a, b]$ its domain.",
                "Normaliza la sucesión de nudos sobre $[0, 1]$: calcula los nudos $(u - a)/(b - a)$, con $[a, b]$ su dominio.",
                [],
            ),
            Question::Integral { interval: true } => said(
                lang,
                "Find the integral of the curve c(t) over the given interval, and its parametric mean.",
                "Integra la curva c(t) en el intervalo dado, y calcula su media paramétrica.",
                [],
            ),
            Question::Integral { interval: false } => said(
                lang,
                "Find the integral of the curve c(t) over its whole domain, and its parametric mean.",
                "Integra la curva c(t) en todo su dominio, y calcula su media paramétrica.",
                [],
            ),
            Question::BasisIntegrals => said(
                lang,
                "Find the integral over the domain of each B-spline basis function of the given knots and degree.",
                "Integra en el dominio cada función base B-spline de los nudos y el grado dados.",
                [],
            ),
            Question::EnclosedArea => said(
                lang,
                "Find the area enclosed by the closed plane curve, and the direction in which it is traversed.",
                "Calcula el área encerrada por la curva cerrada plana, y su sentido de recorrido.",
                [],
            ),
            Question::Loft => said(
                lang,
                "Find the surface through the given section curves (lofting), at the given parameters, and its control points.",
                "Calcula la superficie que pasa por las curvas sección dadas (superficie por secciones), en los parámetros dados, y sus puntos de control.",
                [],
            ),
            Question::PatchArea => said(
                lang,
                "Find the area of the planar patch.",
                "Calcula el área de la superficie plana.",
                [],
            ),
        }
    }
}
