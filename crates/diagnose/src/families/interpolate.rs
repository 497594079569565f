//! The answers of the interpolation mistakes (`cagd_problem::diagnosis::InterpolateMistake`):
//! the data written as the control points; the system of a curve solved with Bᵗ, that of a
//! grid with B_V untransposed (chapter 5, eq. (27)), both from the key's own matrices; the
//! problem solved again with natural ends or uniform parameters.

use crate::change::{solve_rows, transpose_rows};
use crate::{Context, Mistaken};
use cagd_linalg::Point;
use cagd_problem::diagnosis::InterpolateMistake;
use cagd_problem::input::{CurveIn, SurfaceIn};
use cagd_problem::problem::{Basis, End, Interpolate, Parametrization};
use cagd_problem::spec::{MeshIn, PointData, Points};
use cagd_problem::steps::Step;
use cagd_problem::{Exact, Number, Op, Quantity};

/// The answer a student who made `m` writes, or `None` where it does not apply.
pub(crate) fn mistaken(m: InterpolateMistake, cx: &Context) -> Option<Mistaken> {
    let Op::Interpolate(args) = &cx.problem.op else {
        return None;
    };
    let bezier = matches!(args.basis, None | Some(Basis::Bezier));
    match m {
        // c_k = a_k: the data as the polygon (or mesh) of the Bézier answer
        InterpolateMistake::DataAsControl if bezier => {
            let value = match (args.points.as_ref()?, cx.result(&Quantity::Curve)) {
                (PointData::List(Points(data)), Some(Exact::Curve(CurveIn::Bezier { .. }))) => (
                    Quantity::Curve,
                    Exact::Curve(CurveIn::Bezier {
                        points: data.clone(),
                        weights: None,
                    }),
                ),
                (PointData::Grid(MeshIn(data)), _) => match cx.result(&Quantity::Surface)? {
                    Exact::Surface(SurfaceIn::Bezier { .. }) => (
                        Quantity::Surface,
                        Exact::Surface(SurfaceIn::Bezier {
                            mesh: data.clone(),
                            weights: None,
                        }),
                    ),
                    _ => return None,
                },
                _ => return None,
            };
            Some(Mistaken {
                result: vec![value],
                steps: Vec::new(),
            })
        }
        // Bᵗ C = A with the key's B
        InterpolateMistake::TransposedMatrix if bezier => {
            let (Some(PointData::List(Points(data))), Some(Exact::Curve(CurveIn::Bezier { .. }))) =
                (args.points.as_ref(), cx.result(&Quantity::Curve))
            else {
                return None;
            };
            let Some(Exact::Matrix(b)) = derived(cx, "B") else {
                return None;
            };
            let points = solve_rows(&transpose_rows(b)?, data)?;
            Some(Mistaken {
                result: vec![(
                    Quantity::Curve,
                    Exact::Curve(CurveIn::Bezier {
                        points,
                        weights: None,
                    }),
                )],
                steps: Vec::new(),
            })
        }
        // B_U C B_V = A with the key's B_U, B_V: B_U Y = A column by column, then
        // B_Vᵗ c_i = y_i row by row (C B_V = Y)
        InterpolateMistake::UntransposedBv if bezier => {
            let (
                Some(PointData::Grid(MeshIn(data))),
                Some(Exact::Surface(SurfaceIn::Bezier { .. })),
            ) = (args.points.as_ref(), cx.result(&Quantity::Surface))
            else {
                return None;
            };
            let (Some(Exact::Matrix(b_u)), Some(Exact::Matrix(b_v))) =
                (cx.step("B_U"), cx.step("B_V"))
            else {
                return None;
            };
            let columns: Option<Vec<Vec<Point<Number>>>> = data
                .to_columns()
                .iter()
                .map(|col| solve_rows(b_u, col))
                .collect();
            let y = cagd_surface::Grid::from_columns(columns?).ok()?;
            let b_v_t = transpose_rows(b_v)?;
            let rows: Option<Vec<Vec<Point<Number>>>> = y
                .to_rows()
                .iter()
                .map(|row| solve_rows(&b_v_t, row))
                .collect();
            let mesh = cagd_surface::Grid::from_rows(rows?).ok()?;
            Some(Mistaken {
                result: vec![(
                    Quantity::Surface,
                    Exact::Surface(SurfaceIn::Bezier {
                        mesh,
                        weights: None,
                    }),
                )],
                steps: Vec::new(),
            })
        }
        // the cubic spline with natural ends where Bessel or clamped ones are asked
        InterpolateMistake::NaturalEnds => cx.solve_changed(|op| match op {
            Op::Interpolate(Interpolate {
                basis: Some(Basis::Bicubic),
                end: end @ Some(End::Bessel | End::Clamped),
                tangents,
                ..
            }) => {
                *end = Some(End::Natural);
                *tangents = None;
                true
            }
            _ => false,
        }),
        // t_k = k/n where the parameters by chord length are asked
        InterpolateMistake::UniformForChordLength => cx.solve_changed(|op| match op {
            Op::Interpolate(Interpolate {
                parametrization: p @ Some(Parametrization::ChordLength),
                ..
            }) => {
                *p = Some(Parametrization::Uniform);
                true
            }
            _ => false,
        }),
        _ => None,
    }
}

/// The value the key's derivation calls `symbol` (the matrix B of a curve's system).
fn derived<'a>(cx: &'a Context, symbol: &str) -> Option<&'a Exact> {
    cx.answer.derivation.iter().find_map(|s| match s {
        Step::Value {
            symbol: name,
            value,
        } if name == symbol => Some(value),
        _ => None,
    })
}
