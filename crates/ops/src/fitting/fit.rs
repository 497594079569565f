//! Interpolation and least-squares approximation (chapter 5 §7, and curves).

use crate::any::AnyCurve as Curve;
use crate::any::AnySurface as Patch;
use crate::convert::convert;
use crate::convert::convert_points;
use crate::explain;
use crate::message::fitting::{Fitting, How};
use crate::message::inner::Inner;
use crate::out::{at, req, Out, Run};
use crate::problem::{Approximate, Basis, End, Interpolate, Param, Parametrization};
use crate::spec::{List, MeshIn, Num, Orders, PointData, Points};
use crate::steps::{Entries, Formula, Line};
use crate::value::quantity::{Axis, Quantity};
use crate::value::{exact, exact_map, exact_mesh, exact_points, Exact, ExactScalar};
use crate::ProblemError;
use cagd_bezier::BezierCurve;
use cagd_bspline::{BSplineCurve, KnotVector};
use cagd_fit::{
    approximate_bezier, approximate_bezier_surface, approximate_bezier_surface_by_normal_equations,
    approximate_bspline, coordinate_matrices, end_derivative_system, interpolate_bezier,
    interpolate_bezier_surface, interpolate_bezier_surface_in_passes, interpolate_bicubic_spline,
    interpolate_bicubic_spline_in_passes, interpolate_cubic_spline, EndConditions, FitError,
    GridStep, LeastSquaresStep, PassOrder, SurfaceEndConditions,
};
use cagd_linalg::{Matrix, Point};
use cagd_poly::Var;
use cagd_spline_surface::BSplineSurface;
use cagd_surface::BezierSurface;
use cagd_surface::Mesh;

fn matrix<S: ExactScalar>(m: &Matrix<S>) -> Exact {
    Exact::matrix(&m.to_rows())
}

/// The matrix B_{k,i} = B_i^n(t_k).
fn bernstein_rows<S: ExactScalar>(n: usize, ts: &[S]) -> Vec<Vec<S>> {
    ts.iter()
        .map(|t| cagd_bezier::bernstein_all(n, t))
        .collect()
}

/// The parameters on the fit's domain [a, b] ([`cagd_fit::bezier_domain`]: [0, 1] when they
/// all lie there), as the Bernstein matrix sees them: (t_k - a)/(b - a).
fn local<S: ExactScalar>(ts: &[S]) -> Vec<S> {
    let (a, b) = cagd_fit::bezier_domain(ts);
    if a == S::zero() && b == S::one() {
        return ts.to_vec();
    }
    let h = b - a.clone();
    ts.iter()
        .map(|t| (t.clone() - a.clone()) / h.clone())
        .collect()
}

/// The matrix B_{k,i} = B_i^n(t_k) as a value.
fn bernstein_matrix<S: ExactScalar>(n: usize, ts: &[S]) -> Exact {
    Exact::matrix(&bernstein_rows(n, ts))
}

/// Points as the rows of a matrix of coordinates (B^t A in the notes).
fn rows_of<S: ExactScalar>(ps: &[Point<S>]) -> Exact {
    Exact::matrix(&ps.iter().map(|p| p.coords().to_vec()).collect::<Vec<_>>())
}

/// The steps of a spline interpolation system N D = A: its knots u (the notes' convention),
/// the matrix N and the right-hand side A.
fn spline_system_steps<S: ExactScalar>(
    out: &mut Out,
    knots: &KnotVector<S>,
    n: &Matrix<S>,
    a: &[Point<S>],
) {
    out.value(
        "u",
        Exact::List(
            knots
                .to_convention(cagd_bspline::KnotConvention::Notes)
                .iter()
                .map(|x| Exact::Number(crate::value::exact(x)))
                .collect(),
        ),
    );
    out.value("N", matrix(n));
    out.value("A", rows_of(a));
}

/// The knots of a cubic spline in the notes' convention, as a list.
fn knots_list<S: ExactScalar>(knots: &KnotVector<S>) -> Exact {
    Exact::List(
        knots
            .to_convention(cagd_bspline::KnotConvention::Notes)
            .iter()
            .map(|x| Exact::Number(exact(x)))
            .collect(),
    )
}

/// The two passes of bicubic spline interpolation, each a cubic spline system per line as
/// for curves: along v, for each row i of the data, N_V D̃_i = A_i (its solution row i of
/// the mesh d̃, `first`); along u, for each column j of d̃, N_U D_j = Ã_j (its solution
/// column j of the mesh, `last`). The matrix (tridiagonal but for its end rows) is the same
/// for every line of a pass and printed once; a pass of more than
/// [`explain::WORKED_LINES`] lines works its first one.
fn bicubic_passes<S: ExactScalar>(
    out: &mut Out,
    (u, v): (&[S], &[S]),
    data: &Mesh<S>,
    ends: &SurfaceEndConditions<S>,
    first: &Mesh<S>,
    last: &Mesh<S>,
) {
    let passes = [
        (
            Line::Row,
            "v",
            "N_V",
            data.to_rows(),
            first.to_rows(),
            v,
            &ends.v,
        ),
        (
            Line::Column,
            "u",
            "N_U",
            first.to_columns(),
            last.to_columns(),
            u,
            &ends.u,
        ),
    ];
    for (line, knots, matrix_name, lines, solutions, params, conditions) in passes {
        out.fact(crate::steps::Fact::SplinePass { line });
        let count = lines.len();
        for (k, (points, solution)) in lines.iter().zip(&solutions).enumerate() {
            if !explain::worked_line(k, count) {
                continue;
            }
            let Ok(system) = cagd_fit::cubic_spline_system(params, points, conditions) else {
                continue;
            };
            if k == 0 {
                out.value(knots, knots_list(&system.knots));
                out.value(matrix_name, matrix(&system.matrix));
            }
            let (rhs, unknown) = match line {
                Line::Row => (format!("A_{{{k}}}"), format!("\\tilde{{D}}_{{{k}}}")),
                Line::Column => (format!("\\tilde{{A}}_{{{k}}}"), format!("D_{{{k}}}")),
            };
            out.value(rhs, rows_of(&system.rhs));
            out.value(unknown, rows_of(solution));
        }
        if count > explain::WORKED_LINES {
            explain::same_in_the_other_lines(out, line, count);
        }
    }
}

/// A fitted Bézier curve as an answer. On [0, 1] (every parameter there, the notes' case) it
/// is the Bézier polygon. Parameters outside [0, 1] give the domain [min t_k, max t_k]: the
/// curve is then written as what it is on that domain, the B-spline of one piece with the knots
/// a (n times) and b (n times), so that the answer fed back is the curve of the closed form and
/// passes through the data at the given parameters, and `domain` states [a, b] (never the
/// silent mapping onto [0, 1] of old).
fn fitted_curve<S: ExactScalar>(c: BezierCurve<S>, mut out: Out) -> Out {
    let (a, b) = (c.domain().0.clone(), c.domain().1.clone());
    if a == S::zero() && b == S::one() {
        return out.result(Quantity::Curve, Curve::Bezier(c).to_exact());
    }
    let domain = Exact::Point(Point::new(vec![exact(&a), exact(&b)]));
    let spline = KnotVector::bezier(c.degree(), a.clone(), b.clone())
        .ok()
        .filter(|_| c.degree() > 0)
        .and_then(|k| BSplineCurve::try_new(k, c.points().to_vec()).ok());
    out.remark(Fitting::OutsideCurve {
        a: a.to_text(),
        b: b.to_text(),
    });
    let shape = match spline {
        Some(s) => Curve::BSpline(s).to_exact(),
        None => Curve::Bezier(c).to_exact(),
    };
    out.result(Quantity::Curve, shape)
        .result(Quantity::Domain, domain)
}

/// A fitted Bézier patch as an answer, as [`fitted_curve`]: on the unit square the Bézier
/// mesh; on another rectangle [a, b] x [c, d] (parameters outside [0, 1]) the B-spline
/// surface of one piece on it (so that the mesh and the closed form agree), and `domain`.
fn fitted_surface<S: ExactScalar>(s: BezierSurface<S>, out: Out) -> Out {
    let dom = s.domain().clone();
    if dom.is_unit() {
        return out.result(Quantity::Surface, Patch::Bezier(s).to_exact());
    }
    let ((a, b), (c, d)) = (dom.u_interval(), dom.v_interval());
    let ((a, b), (c, d)) = ((a.clone(), b.clone()), (c.clone(), d.clone()));
    let (m, n) = s.bidegree();
    let domain = Exact::Points(vec![
        Point::new(vec![exact(&a), exact(&b)]),
        Point::new(vec![exact(&c), exact(&d)]),
    ]);
    let spline = match (
        KnotVector::bezier(m, a.clone(), b.clone()),
        KnotVector::bezier(n, c.clone(), d.clone()),
    ) {
        (Ok(ku), Ok(kv)) if m > 0 && n > 0 => {
            BSplineSurface::try_new(ku, kv, s.mesh().clone()).ok()
        }
        _ => None,
    };
    let mut out = out;
    out.remark(Fitting::OutsidePatch {
        a: a.to_text(),
        b: b.to_text(),
        c: c.to_text(),
        d: d.to_text(),
    });
    let shape = match spline {
        Some(x) => Patch::BSpline(x).to_exact(),
        None => Patch::Bezier(s).to_exact(),
    };
    out.result(Quantity::Surface, shape)
        .result(Quantity::Domain, domain)
}

/// The parameters of a grid in one direction from its data (The NURBS Book §9.2.5): those of
/// each line (the columns for u, the rows for v) by `how`, averaged over the lines,
/// `u_k = (1/(n + 1)) Σ_l u_k^l`. Each line's parameters are rational (ratios of lengths in
/// one √d, or refused, [`crate::fitting::params::parameters`]), and so is their average; they increase,
/// being averages of increasing lists.
fn averaged_parameters<S: ExactScalar>(
    how: crate::problem::Parametrization,
    lines: &[Vec<cagd_linalg::Point<S>>],
    key: &str,
) -> Result<Vec<S>, ProblemError> {
    let mut sum: Vec<S> = Vec::new();
    for (l, line) in lines.iter().enumerate() {
        let ts = crate::fitting::params::parameters(how, line).map_err(|e| {
            let inner = Inner::new(e.message);
            ProblemError::at(
                key,
                if key == "u" {
                    Fitting::ColumnParameters { line: l, inner }
                } else {
                    Fitting::RowParameters { line: l, inner }
                },
            )
        })?;
        if sum.is_empty() {
            sum = ts;
        } else {
            for (s, t) in sum.iter_mut().zip(ts) {
                *s = s.clone() + t;
            }
        }
    }
    let count = S::from_i64(i64::try_from(lines.len().max(1)).unwrap_or(1));
    Ok(sum.into_iter().map(|s| s / count.clone()).collect())
}

/// The parameters of an interpolation: they must be distinct, or the interpolation system is
/// singular (two equal rows of the Bernstein or spline matrix).
fn distinct_parameters<S: ExactScalar>(xs: &List<Num>, path: &str) -> Result<Vec<S>, ProblemError> {
    let mut values: Vec<S> = Vec::with_capacity(xs.0.len());
    for (k, x) in xs.0.iter().enumerate() {
        let item = || format!("{path}[{k}]");
        let x = S::from_number(&x.0).map_err(|e| at(&item())(e))?;
        if let Some(i) = values.iter().position(|y| *y == x) {
            return Err(ProblemError::at(
                item(),
                Fitting::RepeatsEntry {
                    value: x.to_text(),
                    entry: i,
                },
            ));
        }
        values.push(x);
    }
    Ok(values)
}

/// `interpolate`: a grid of `points` at parameters `u`, `v` (surface), or `points` at
/// `params` (curve).
pub(crate) fn interpolate<S: ExactScalar>(
    a: &Interpolate,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let pts = req(&a.points, "points")?;
    let basis = a.basis.unwrap_or(Basis::Bezier);
    let mut out = run.out();
    let grid = matches!(pts, PointData::Grid(_)) && a.parametrization.is_some();
    if a.u.is_some() || a.v.is_some() || grid {
        let data = match pts {
            PointData::Grid(MeshIn(m)) => m,
            PointData::List(_) => return Err(ProblemError::at("points", Fitting::GridForUV)),
        };
        let rows = data
            .row_slices()
            .map(|r| convert_points::<S>(r, "points"))
            .collect::<Result<Vec<_>, _>>()?;
        let data = Mesh::mesh(rows).map_err(at("points"))?;
        let (u, v) = match (&a.u, &a.v, a.parametrization) {
            (Some(u), Some(v), None) => (
                distinct_parameters::<S>(u, "u")?,
                distinct_parameters::<S>(v, "v")?,
            ),
            (None, None, Some(how)) => {
                let u = averaged_parameters(how, &data.to_columns(), "u")?;
                let v = averaged_parameters(how, &data.to_rows(), "v")?;
                let list = |xs: &[S]| {
                    xs.iter()
                        .map(|t| t.to_text())
                        .collect::<Vec<_>>()
                        .join(", ")
                };
                out.remark(Fitting::GridParameters {
                    how: how_words(how),
                    u: list(&u),
                    v: list(&v),
                });
                out = out.result(
                    Quantity::DataParameters,
                    Exact::Object(vec![
                        (Quantity::Variable(Var::U), numbers(&u)),
                        (Quantity::Variable(Var::V), numbers(&v)),
                    ]),
                );
                (u, v)
            }
            (_, _, Some(_)) => {
                return Err(ProblemError::at(
                    "parametrization",
                    Fitting::UVOrParametrization,
                ))
            }
            (None, _, None) => {
                return Err(ProblemError::at("u", Fitting::MissingOrParametrization))
            }
            (_, None, None) => {
                return Err(ProblemError::at("v", Fitting::MissingOrParametrization))
            }
        };
        if basis == Basis::Bezier {
            if !out.steps_on() {
                let surface = interpolate_bezier_surface(&u, &v, &data).map_err(at("points"))?;
                let closed = surface.closed_form().map_err(at(""))?;
                return Ok(fitted_surface(surface, out).closed_form(Exact::Map(exact_map(&closed))));
            }
            out.formula(Formula::InterpolateSurface);
            if [(u.len(), u.len()), (v.len(), v.len()), (u.len(), v.len())]
                .iter()
                .any(|&(r, c)| explain::too_big(r, c))
            {
                return grid_interpolation_summary(&u, &v, &data, out);
            }
            let mut steps = Vec::new();
            let surface = interpolate_bezier_surface_in_passes(
                &u,
                &v,
                &data,
                PassOrder::RowsFirst,
                &mut steps,
            )
            .map_err(at("points"))?;
            let closed = surface.closed_form().map_err(at(""))?;
            let named = grid_steps(&steps, &surface)?;
            let mut out = fitted_surface(surface, out).closed_form(Exact::Map(exact_map(&closed)));
            for (name, value) in named {
                out = out.step(name, value);
            }
            return Ok(out);
        }
        let ends = match a.end.unwrap_or(End::Natural) {
            End::Bessel => SurfaceEndConditions::bessel(),
            End::Natural => SurfaceEndConditions::natural(),
            End::Clamped => return Err(ProblemError::at("end", Fitting::GridEnds)),
        };
        if basis == Basis::Bspline {
            return Err(ProblemError::at("basis", Fitting::GridBasis));
        }
        if !out.steps_on() {
            let surface = interpolate_bicubic_spline(&u, &v, &data, &ends).map_err(at("points"))?;
            return Ok(out.result(Quantity::Surface, Patch::BSpline(surface).to_exact()));
        }
        out.formula(Formula::InterpolateBicubic);
        let mut steps = Vec::new();
        let surface = interpolate_bicubic_spline_in_passes(
            &u,
            &v,
            &data,
            &ends,
            PassOrder::RowsFirst,
            &mut steps,
        )
        .map_err(at("points"))?;
        if let Some(GridStep::FirstPass { mesh, .. }) = steps
            .iter()
            .find(|s| matches!(s, GridStep::FirstPass { .. }))
        {
            bicubic_passes(&mut out, (&u, &v), &data, &ends, mesh, surface.mesh());
        }
        let mut out = out.result(Quantity::Surface, Patch::BSpline(surface).to_exact());
        for step in &steps {
            if let GridStep::FirstPass { mesh, .. } = step {
                out = out.step(
                    Quantity::DTilde,
                    Exact::Surface(crate::input::SurfaceIn::Bezier {
                        mesh: exact_mesh(mesh),
                        weights: None,
                    }),
                );
            }
        }
        return Ok(out);
    }
    let points = match pts {
        PointData::List(Points(p)) => p,
        PointData::Grid(_) => return Err(ProblemError::at("points", Fitting::GridNeedsUV)),
    };
    let points = convert_points::<S>(points, "points")?;
    let params = match (&a.params, a.parametrization) {
        (Some(p), None) => distinct_parameters::<S>(p, "params")?,
        (None, Some(how)) => {
            let ts = crate::fitting::params::parameters(how, &points)?;
            out.remark(Fitting::CurveParameters {
                how: how_words(how),
                list: ts
                    .iter()
                    .map(|t| t.to_text())
                    .collect::<Vec<_>>()
                    .join(", "),
            });
            out = out.result(Quantity::DataParameters, numbers(&ts));
            ts
        }
        (Some(_), Some(_)) => {
            return Err(ProblemError::at(
                "parametrization",
                Fitting::ParamsOrParametrization,
            ))
        }
        (None, None) => {
            return Err(ProblemError::at(
                "params",
                Fitting::MissingOrParametrization,
            ))
        }
    };
    let tangents = || -> Result<[Point<S>; 2], ProblemError> {
        let Points(t) = req(&a.tangents, "tangents")?;
        let t = convert_points::<S>(t, "tangents")?;
        match <[Point<S>; 2]>::try_from(t) {
            Ok(pair) => Ok(pair),
            Err(t) => Err(ProblemError::at(
                "tangents",
                Fitting::EndDerivatives { found: t.len() },
            )),
        }
    };
    let ends = || -> Result<EndConditions<S>, ProblemError> {
        Ok(match a.end.unwrap_or(End::Natural) {
            End::Bessel => EndConditions::bessel(),
            End::Natural => EndConditions::natural(),
            End::Clamped => {
                let [m0, mn] = tangents()?;
                EndConditions::clamped(m0, mn)
            }
        })
    };
    if a.tangents.is_some() && a.end != Some(End::Clamped) {
        return Err(ProblemError::at("tangents", Fitting::TangentsNeedClamped));
    }
    if out.steps_on() {
        match basis {
            Basis::Bezier => {
                out.formula(Formula::InterpolateCurve);
                out.value(
                    "B",
                    bernstein_matrix(points.len().saturating_sub(1), &local(&params)),
                );
            }
            Basis::Bicubic => {
                out.formula(Formula::InterpolateSpline);
                if let Ok(system) = cagd_fit::cubic_spline_system(&params, &points, &ends()?) {
                    spline_system_steps(&mut out, &system.knots, &system.matrix, &system.rhs);
                }
            }
            Basis::Bspline => {}
        }
    }
    let curve = match basis {
        Basis::Bezier => {
            let c = interpolate_bezier(&params, &points).map_err(at("points"))?;
            return Ok(fitted_curve(c, out));
        }
        Basis::Bicubic => Curve::BSpline(
            interpolate_cubic_spline(&params, &points, &ends()?).map_err(at("points"))?,
        ),
        Basis::Bspline => {
            let p = run.degree("degree", *req(&a.degree, "degree")?)?;
            match a.end {
                Some(End::Clamped) => {
                    return bspline_with_end_derivatives(p, &params, &points, tangents()?, out)
                }
                Some(_) => return Err(ProblemError::at("end", Fitting::BSplineEnd)),
                None => {}
            }
            if out.steps_on() {
                out.formula(Formula::AveragedKnots);
            }
            if p == 0 || p >= points.len() {
                return Err(ProblemError::at(
                    "degree",
                    Fitting::BSplineDegreeRange {
                        points: points.len(),
                        max: points.len().saturating_sub(1),
                    },
                ));
            }
            let mut sorted = params.clone();
            sorted.sort_by(|x, y| x.compare(y).unwrap_or(std::cmp::Ordering::Equal));
            if sorted != params {
                return Err(ProblemError::at("params", Fitting::Increasing));
            }
            let knots = crate::fitting::params::averaged_knots(&params, p);
            if out.steps_on() {
                out.value(
                    "u",
                    Exact::List(
                        knots
                            .iter()
                            .map(|x| Exact::Number(crate::value::exact(x)))
                            .collect(),
                    ),
                );
            }
            let knots = KnotVector::from_notes(knots, p).map_err(at("params"))?;
            Curve::BSpline(approximate_bspline(&knots, &params, &points).map_err(at("points"))?)
        }
    };
    Ok(out.result(Quantity::Curve, curve.to_exact()))
}

/// The B-spline interpolant of degree p through the points with the end derivatives
/// [D_0, D_n] (Piegl and Tiller §9.2.2, eqs. (9.19)-(9.22)): n + 3 control points on the knots
/// averaged over p parameters, with the steps (knots, system N D = A) when asked.
fn bspline_with_end_derivatives<S: ExactScalar>(
    p: usize,
    params: &[S],
    points: &[Point<S>],
    [d0, dn]: [Point<S>; 2],
    mut out: Out,
) -> Result<Out, ProblemError> {
    let fit_error = |e: FitError| match e {
        FitError::DegreeOutOfRange { .. } => ProblemError::at("degree", e),
        FitError::DimensionMismatch { .. } => ProblemError::at("tangents", e),
        FitError::NotIncreasing { .. } => ProblemError::at("params", Fitting::Increasing),
        e => ProblemError::at("points", e),
    };
    let system = end_derivative_system(p, params, points, &d0, &dn).map_err(fit_error)?;
    if out.steps_on() {
        out.formula(Formula::EndDerivativeKnots);
        spline_system_steps(&mut out, &system.knots, &system.matrix, &system.rhs);
    }
    let control = cagd_linalg::solve_points(&system.matrix, &system.rhs)
        .map_err(|e| fit_error(FitError::Linalg(e)))?;
    let curve = BSplineCurve::try_new(system.knots, control).map_err(at("points"))?;
    Ok(out.result(Quantity::Curve, Curve::BSpline(curve).to_exact()))
}

/// The named steps of a grid interpolation (26)-(27): B_U, B_V, the mesh C̃ after the first
/// pass (as recorded), and the coordinate matrices C_x, C_y, ... of the answer's mesh.
fn grid_steps<S: ExactScalar>(
    recorded: &[GridStep<S>],
    surface: &BezierSurface<S>,
) -> Result<Vec<(Quantity, Exact)>, ProblemError> {
    let mut steps: Vec<(Quantity, Exact)> = recorded
        .iter()
        .map(|step| match step {
            GridStep::MatrixU(b_u) => (Quantity::CollocationU, matrix(b_u)),
            GridStep::MatrixV(b_v) => (Quantity::CollocationV, matrix(b_v)),
            GridStep::FirstPass { mesh, .. } => (
                Quantity::CTildeMesh,
                Exact::Surface(crate::input::SurfaceIn::Bezier {
                    mesh: exact_mesh(mesh),
                    weights: None,
                }),
            ),
        })
        .collect();
    let coords = coordinate_matrices(surface.mesh()).map_err(at(""))?;
    for (axis, c) in Axis::ALL.into_iter().zip(&coords) {
        steps.push((Quantity::CoordinateMatrix(axis), matrix(c)));
    }
    Ok(steps)
}

/// The named steps of a grid interpolation: B_U, B_V, C̃ and the coordinate matrices of a
/// grid's mesh, C = (C_x, C_y, ...).
const GRID_STEPS: [Quantity; 7] = [
    Quantity::CollocationU,
    Quantity::CollocationV,
    Quantity::CTildeMesh,
    Quantity::CoordinateMatrix(Axis::X),
    Quantity::CoordinateMatrix(Axis::Y),
    Quantity::CoordinateMatrix(Axis::Z),
    Quantity::CoordinateMatrix(Axis::W),
];

/// The named steps of a least-squares fit (28)-(29): B, BᵗB and BᵗA, as recorded.
fn least_squares_steps<S: ExactScalar>(recorded: &[LeastSquaresStep<S>]) -> Vec<(Quantity, Exact)> {
    recorded
        .iter()
        .map(|step| match step {
            LeastSquaresStep::Collocation(b) => (Quantity::Collocation, matrix(b)),
            LeastSquaresStep::NormalMatrix(btb) => (Quantity::NormalMatrix, matrix(btb)),
            LeastSquaresStep::NormalRhs(bta) => (Quantity::NormalRhs, rows_of(bta)),
        })
        .collect()
}

/// The steps of a grid interpolation whose matrices are too big to print whole
/// ([`explain::WHOLE_MATRIX_ENTRIES`]): the patch by the fast path, once; B_U and B_V by their
/// size and first rows; the first pass worked on the first row of the data (the Bézier curve
/// through it, the first row of C̃), the others said to be done in the same way. The second
/// pass gives the answer's mesh. A named step the problem's `expected` checks ([`grid_steps`])
/// is computed in full (the whole step-by-step route then runs) and recorded, so the check
/// compares all of it.
fn grid_interpolation_summary<S: ExactScalar>(
    u: &[S],
    v: &[S],
    data: &Mesh<S>,
    mut out: Out,
) -> Result<Out, ProblemError> {
    let surface = if out.checks_any(&GRID_STEPS) {
        let mut steps = Vec::new();
        let surface =
            interpolate_bezier_surface_in_passes(u, v, data, PassOrder::RowsFirst, &mut steps)
                .map_err(at("points"))?;
        for (name, value) in grid_steps(&steps, &surface)? {
            if out.checks(&name) {
                out = out.step(name, value);
            }
        }
        surface
    } else {
        interpolate_bezier_surface(u, v, data).map_err(at("points"))?
    };
    for (symbol, ts) in [("B_U", local(u)), ("B_V", local(v))] {
        let degree = ts.len().saturating_sub(1);
        out.explain(explain::matrix_summary(
            symbol,
            (ts.len(), ts.len()),
            Entries::Bernstein,
            |i| {
                ts.get(i)
                    .map_or_else(Vec::new, |t| cagd_bezier::bernstein_all(degree, t))
            },
        ));
    }
    if let Some(row) = data.row(0) {
        let first = interpolate_bezier(v, row).map_err(at("points"))?;
        out.value(
            "\\tilde{c}_{0,\\cdot}",
            Exact::Points(exact_points(first.points())),
        );
    }
    explain::same_in_the_other_lines(&mut out, Line::Row, data.rows());
    let closed = surface.closed_form().map_err(at(""))?;
    Ok(fitted_surface(surface, out).closed_form(Exact::Map(exact_map(&closed))))
}

/// The steps of a least-squares fit whose collocation matrix is too big to print whole
/// ([`explain::WHOLE_MATRIX_ENTRIES`]): the patch by the fast path (the normal equations on
/// integers), once; B, BᵗB and BᵗA of (28)-(29) by their size and first rows, only those rows
/// computed (BᵗB and BᵗA on integers, [`cagd_fit::normal_equations_first_rows`]). A named
/// step the problem's `expected` checks ([`least_squares_steps`]) is computed in full (by the
/// step-by-step route) and recorded, so the check compares all of it.
fn least_squares_summary<S: ExactScalar>(
    (m, n): (usize, usize),
    pairs: &[(S, S)],
    points: &[Point<S>],
    mut out: Out,
) -> Result<Out, ProblemError> {
    let surface = if out.checks_any(&[
        Quantity::Collocation,
        Quantity::NormalMatrix,
        Quantity::NormalRhs,
    ]) {
        let mut steps = Vec::new();
        let surface =
            approximate_bezier_surface_by_normal_equations(m, n, pairs, points, &mut steps)
                .map_err(at("params"))?;
        for (name, value) in least_squares_steps(&steps) {
            if out.checks(&name) {
                out = out.step(name, value);
            }
        }
        surface
    } else {
        approximate_bezier_surface(m, n, pairs, points).map_err(at("params"))?
    };
    let unknowns = (m + 1) * (n + 1);
    let dim = points.first().map_or(0, Point::dim);
    // the first rows of B, at the parameters on the fit's domain
    let us = local(&pairs.iter().map(|p| p.0.clone()).collect::<Vec<_>>());
    let vs = local(&pairs.iter().map(|p| p.1.clone()).collect::<Vec<_>>());
    let first: Vec<(S, S)> = us.into_iter().zip(vs).take(explain::SHOWN_ROWS).collect();
    let b = cagd_fit::bezier_surface_matrix(m, n, &first).to_rows();
    out.explain(explain::matrix_summary(
        "B",
        (pairs.len(), unknowns),
        Entries::TensorBernstein,
        |k| b.get(k).cloned().unwrap_or_default(),
    ));
    let (btb, bta) =
        cagd_fit::normal_equations_first_rows(m, n, pairs, points, explain::SHOWN_ROWS);
    out.explain(explain::matrix_summary(
        "B^t B",
        (unknowns, unknowns),
        Entries::NormalMatrix,
        |a| btb.get(a).cloned().unwrap_or_default(),
    ));
    out.explain(explain::matrix_summary(
        "B^t A",
        (unknowns, dim),
        Entries::NormalRhs,
        |a| bta.get(a).map(|p| p.coords().to_vec()).unwrap_or_default(),
    ));
    let closed = surface.closed_form().map_err(at(""))?;
    Ok(fitted_surface(surface, out).closed_form(Exact::Map(exact_map(&closed))))
}

/// A list of parameters as an answer's value.
fn numbers<S: ExactScalar>(ts: &[S]) -> Exact {
    Exact::List(ts.iter().map(|t| Exact::Number(exact(t))).collect())
}

/// The words of a parametrization.
fn how_words(how: Parametrization) -> How {
    match how {
        Parametrization::Uniform => How::Uniform,
        Parametrization::ChordLength => How::ChordLength,
        Parametrization::Centripetal => How::Centripetal,
    }
}

/// `approximate`: least squares, eq. (28)-(29), of `points` at `params` — pairs [u, v] for a
/// patch of bidegree `degree` = [m, n], numbers t for a Bézier curve of degree `degree` = p.
pub(crate) fn approximate<S: ExactScalar>(
    a: &Approximate,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let pf = "params";
    let Points(points) = req(&a.points, "points")?;
    let points = convert_points::<S>(points, "points")?;
    let computed;
    let mut found = None;
    let params = match (&a.params, a.parametrization) {
        (Some(p), None) => p,
        (None, Some(how)) => {
            let ts = crate::fitting::params::parameters(how, &points)?;
            found = Some(numbers(&ts));
            computed = List(
                ts.iter()
                    .map(|t| Param::One(Num(crate::value::exact(t))))
                    .collect(),
            );
            &computed
        }
        (Some(_), Some(_)) => {
            return Err(ProblemError::at(
                "parametrization",
                Fitting::ParamsOrParametrization,
            ))
        }
        (None, None) => return Err(ProblemError::at(pf, Fitting::MissingOrParametrizationShort)),
    };
    let surface_params = matches!(params.0.first(), Some(Param::Many(_)));
    let mut out = run.out();
    if let Some(ts) = found {
        out = out.result(Quantity::DataParameters, ts);
    }
    if surface_params {
        let mut pairs = Vec::with_capacity(params.0.len());
        for (k, p) in params.0.iter().enumerate() {
            // the path is written only for an error (a fit may have thousands of parameters)
            let item = || format!("{pf}[{k}]");
            match p {
                Param::Many(xs) => match xs.as_slice() {
                    [u, v] => match (S::from_number(&u.0), S::from_number(&v.0)) {
                        (Ok(u), Ok(v)) => pairs.push((u, v)),
                        (Err(e), _) | (_, Err(e)) => return Err(at(&item())(e)),
                    },
                    _ => {
                        return Err(ProblemError::at(
                            item(),
                            crate::message::read::Read::TwoNumbers { found: xs.len() },
                        ))
                    }
                },
                Param::One(_) => return Err(ProblemError::at(item(), Fitting::UVNotNumber)),
            }
        }
        let (m, n) = match req(&a.degree, "degree")? {
            Orders::Two(m, n) => (run.degree("degree[0]", *m)?, run.degree("degree[1]", *n)?),
            Orders::One(d) => {
                return Err(ProblemError::at(
                    "degree",
                    Fitting::PatchDegreeNumber { n: d.0 },
                ))
            }
        };
        run.check_points(
            "degree",
            m.saturating_add(1).saturating_mul(n.saturating_add(1)),
            Fitting::PatchOfBidegree { m, n },
        )?;
        if a.knots_u.is_some() || a.knots_v.is_some() {
            // B-spline least squares: BᵗB D = BᵗA with B_{k, iC+j} = N_i^m(u_k) N_j^n(v_k)
            let read = |k: &Option<List<Num>>,
                        path: &str,
                        p: usize|
             -> Result<KnotVector<S>, ProblemError> {
                let k = req(k, path)?;
                let xs =
                    k.0.iter()
                        .enumerate()
                        .map(|(i, x)| convert::<S>(&x.0, &format!("{path}[{i}]")))
                        .collect::<Result<Vec<_>, _>>()?;
                KnotVector::from_notes(xs, p).map_err(at(path))
            };
            let (ku, kv) = (
                read(&a.knots_u, "knots_u", m)?,
                read(&a.knots_v, "knots_v", n)?,
            );
            run.check_points(
                "knots_u",
                ku.control_point_count()
                    .saturating_mul(kv.control_point_count()),
                Fitting::BSplineSurface,
            )?;
            let mut out = out;
            out.formula(Formula::LeastSquaresSurface);
            if out.steps_on() {
                let b = cagd_fit::bspline_surface_matrix(&ku, &kv, &pairs).map_err(at(pf))?;
                out.value("B", matrix(&b));
            }
            let s =
                cagd_fit::approximate_bspline_surface(&ku, &kv, &pairs, &points).map_err(at(pf))?;
            return Ok(out.result(Quantity::Surface, Patch::BSpline(s).to_exact()));
        }
        if !out.steps_on() {
            let surface = approximate_bezier_surface(m, n, &pairs, &points).map_err(at(pf))?;
            let closed = surface.closed_form().map_err(at(""))?;
            return Ok(fitted_surface(surface, out).closed_form(Exact::Map(exact_map(&closed))));
        }
        let mut out = out;
        out.formula(Formula::LeastSquaresSurface);
        if explain::too_big(pairs.len(), (m + 1) * (n + 1)) {
            return least_squares_summary((m, n), &pairs, &points, out);
        }
        let mut steps = Vec::new();
        let surface =
            approximate_bezier_surface_by_normal_equations(m, n, &pairs, &points, &mut steps)
                .map_err(at(pf))?;
        let closed = surface.closed_form().map_err(at(""))?;
        let mut out = fitted_surface(surface, out).closed_form(Exact::Map(exact_map(&closed)));
        for (name, value) in least_squares_steps(&steps) {
            out = out.step(name, value);
        }
        return Ok(out);
    }
    let mut ts = Vec::with_capacity(params.0.len());
    for (k, p) in params.0.iter().enumerate() {
        let item = || format!("{pf}[{k}]");
        match p {
            Param::One(t) => ts.push(S::from_number(&t.0).map_err(|e| at(&item())(e))?),
            Param::Many(_) => return Err(ProblemError::at(item(), Fitting::FirstIsNumber)),
        }
    }
    let degree = match req(&a.degree, "degree")? {
        Orders::One(d) => run.degree("degree", *d)?,
        Orders::Two(..) => return Err(ProblemError::at("degree", Fitting::DegreeNotList)),
    };
    let mut out = out;
    if let Some(knots) = &a.knots {
        // B-spline least squares with the given knots: B^t B D = B^t A, B_kj = N_j^p(t_k)
        let knots = knots
            .0
            .iter()
            .enumerate()
            .map(|(k, x)| convert::<S>(&x.0, &format!("knots[{k}]")))
            .collect::<Result<Vec<_>, _>>()?;
        // the notes' convention (no end knots: n + p - 1 knots for n control points)
        let (given, looks_full) = (knots.len(), ends_repeated(&knots, degree + 1));
        let knots = KnotVector::from_notes(knots, degree).map_err(at("knots"))?;
        run.check_points("knots", knots.control_point_count(), Fitting::BSpline)?;
        let unknowns = knots.control_point_count();
        if points.len() < unknowns {
            // say the convention: a vector of The NURBS Book (ends p + 1 times) read as the
            // notes' makes two control points more than meant
            let (knots, found) = (given, points.len());
            return Err(ProblemError::at(
                "knots",
                if looks_full {
                    Fitting::KnotsLookFull {
                        knots,
                        degree,
                        unknowns,
                        found,
                    }
                } else {
                    Fitting::KnotsForTooFewPoints {
                        knots,
                        degree,
                        unknowns,
                        found,
                    }
                },
            ));
        }
        out.formula(Formula::LeastSquaresCurve);
        if out.steps_on() {
            let b = cagd_fit::bspline_matrix(&knots, &ts).map_err(at(pf))?;
            out.value("B", matrix(&b));
        }
        let c = approximate_bspline(&knots, &ts, &points).map_err(at(pf))?;
        return Ok(out.result(Quantity::Curve, Curve::BSpline(c).to_exact()));
    }
    if out.steps_on() {
        out.formula(Formula::LeastSquaresCurve);
        let b = bernstein_rows(degree, &local(&ts));
        let cols = degree + 1;
        let btb: Vec<Vec<S>> = (0..cols)
            .map(|i| {
                (0..cols)
                    .map(|j| {
                        b.iter()
                            .fold(S::zero(), |acc, row| match (row.get(i), row.get(j)) {
                                (Some(x), Some(y)) => acc + x.mul_ref(y),
                                _ => acc,
                            })
                    })
                    .collect()
            })
            .collect();
        let bta: Vec<Point<S>> = (0..cols)
            .map(|i| {
                b.iter().zip(&points).fold(
                    Point::zero(points.first().map_or(0, Point::dim)),
                    |acc, (row, p)| match row.get(i) {
                        Some(x) => acc + p.scale(x),
                        None => acc,
                    },
                )
            })
            .collect();
        out.value("B", Exact::matrix(&b));
        out.value("B^t B", Exact::matrix(&btb));
        out.value("B^t A", rows_of(&bta));
    }
    let c = approximate_bezier(degree, &ts, &points).map_err(at(pf))?;
    Ok(fitted_curve(c, out))
}

/// Whether the first and the last `times` knots are each one knot: the ends of a clamped
/// vector in The NURBS Book's convention (p + 1 times), one more than the notes' p.
fn ends_repeated<S: ExactScalar>(knots: &[S], times: usize) -> bool {
    let same = |run: &[S]| run.windows(2).all(|w| w.first() == w.get(1));
    match (knots.get(..times), knots.len().checked_sub(times)) {
        (Some(head), Some(start)) => same(head) && knots.get(start..).is_some_and(same),
        _ => false,
    }
}
