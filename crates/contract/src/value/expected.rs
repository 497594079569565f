//! An answer value compared with the exact value a fixture's `expected` writes: `Err` says
//! where they differ.

use super::exact::{Exact, Number};
use super::json::{matrix_text, numbers_text, rational_json};
use crate::input::{CurveIn, SurfaceIn};
use crate::message::check::{Check, SurfaceKind};
use crate::message::inner::Inner;
use crate::spec::{self, List, Num, PointIn, Points};
use cagd_linalg::Point;
use cagd_param::Name;
use cagd_poly::parse_expr;
use cagd_scalar::{Print, Scalar};
use cagd_surface::{Grid, Mesh};
use serde_json::Value;

impl Exact {
    /// Whether this value equals the exact value written in `expected` (fixture JSON, in the
    /// same shapes as the input). `Err` says where they differ.
    pub fn check(&self, expected: &Value) -> Result<(), Check> {
        self.check_in(expected, &[])
    }

    /// [`Exact::check`] for a problem in letters: `expected` may use `parameters`.
    pub fn check_in(&self, expected: &Value, parameters: &[Name]) -> Result<(), Check> {
        let differ = |expected: String, computed: String| Err(Check::Differ { expected, computed });
        match self {
            Exact::Bool(b) => match expected.as_bool() {
                Some(e) if e == *b => Ok(()),
                _ => differ(expected.to_string(), b.to_string()),
            },
            Exact::Int(i) => match expected.as_i64() {
                Some(e) if e == *i => Ok(()),
                _ => differ(expected.to_string(), i.to_string()),
            },
            Exact::Text(t) => match expected.as_str() {
                Some(e) if e == t => Ok(()),
                _ => differ(expected.to_string(), format!("{t:?}")),
            },
            Exact::Sentence(m) => {
                let t = m.to_string();
                match expected.as_str() {
                    Some(e) if e == t => Ok(()),
                    _ => differ(expected.to_string(), format!("{t:?}")),
                }
            }
            Exact::Number(x) => {
                let Num(e) = spec::read_value(expected, parameters).map_err(Check::unread)?;
                if &e == x {
                    Ok(())
                } else {
                    differ(e.to_text(), x.to_text())
                }
            }
            Exact::Point(p) => {
                let PointIn(e) = spec::read_value(expected, parameters).map_err(Check::unread)?;
                if &e == p {
                    Ok(())
                } else {
                    differ(e.to_text(), p.to_text())
                }
            }
            Exact::Points(ps) => {
                let Points(e) = spec::read_value(expected, parameters).map_err(Check::unread)?;
                first_difference_points(&e, ps)
            }
            Exact::Matrix(rows) => {
                let List(written) = spec::read_value::<List<List<Num>>>(expected, parameters)
                    .map_err(Check::unread)?;
                let e: Vec<Vec<Number>> = written
                    .into_iter()
                    .map(|List(r)| r.into_iter().map(|Num(x)| x).collect())
                    .collect();
                if &e == rows {
                    Ok(())
                } else {
                    differ(matrix_text(&e), matrix_text(rows))
                }
            }
            Exact::Poly(p) => {
                let e = parse_expected(expected)?
                    .scalar::<Number>()
                    .map_err(Check::unread)?;
                if &e == p {
                    Ok(())
                } else {
                    differ(e.to_text(), p.to_text())
                }
            }
            Exact::Map(m) => {
                let e = parse_expected(expected)?
                    .vector::<Number>()
                    .map_err(Check::unread)?;
                if &e == m {
                    Ok(())
                } else {
                    differ(e.to_text(), m.to_text())
                }
            }
            Exact::Rational(r) => {
                let text = expected.as_str().unwrap_or_default();
                if text == rational_json(r) || text == r.to_text() {
                    Ok(())
                } else {
                    differ(text.to_string(), r.to_text())
                }
            }
            Exact::Curve(c) => {
                let e: CurveIn<Number> =
                    spec::read_value(expected, parameters).map_err(Check::unread)?;
                compare_curves(&e, c)
            }
            Exact::Surface(s) => {
                let e: SurfaceIn<Number> =
                    spec::read_value(expected, parameters).map_err(Check::unread)?;
                compare_surfaces(&e, s)
            }
            Exact::List(xs) => {
                let items = expected.as_array().ok_or_else(|| Check::ComputedList {
                    expected: expected.to_string(),
                })?;
                if items.len() != xs.len() {
                    return Err(Check::Items {
                        expected: items.len(),
                        computed: xs.len(),
                    });
                }
                for (k, (x, e)) in xs.iter().zip(items).enumerate() {
                    x.check_in(e, parameters).map_err(|m| Check::Item {
                        index: k,
                        inner: Box::new(m),
                    })?;
                }
                Ok(())
            }
            Exact::Object(kv) => {
                let obj = expected.as_object().ok_or_else(|| Check::ComputedObject {
                    expected: expected.to_string(),
                })?;
                for (k, e) in obj {
                    let x = kv
                        .iter()
                        .find(|(name, _)| name.name() == k.as_str())
                        .map(|(_, v)| v)
                        .ok_or_else(|| Check::NoValue { key: k.clone() })?;
                    x.check_in(e, parameters).map_err(|m| Check::Entry {
                        key: k.clone(),
                        inner: Box::new(m),
                    })?;
                }
                Ok(())
            }
        }
    }
}

pub(crate) fn parse_expected(expected: &Value) -> Result<cagd_poly::Expr, Check> {
    let text = expected.as_str().ok_or_else(|| Check::ExpressionString {
        found: expected.to_string(),
    })?;
    parse_expr(text).map_err(|e| Check::DoesNotParse {
        text: format!("{text:?}"),
        inner: Inner::new(e),
    })
}

fn first_difference_points(e: &[Point<Number>], c: &[Point<Number>]) -> Result<(), Check> {
    if e.len() != c.len() {
        return Err(Check::Points {
            expected: e.len(),
            computed: c.len(),
        });
    }
    for (k, (a, b)) in e.iter().zip(c).enumerate() {
        if a != b {
            return Err(Check::Point {
                index: k,
                expected: a.to_text(),
                computed: b.to_text(),
            });
        }
    }
    Ok(())
}

/// The first difference of two grids, entry `{name}_{i},{j}`, or of their shapes (a mesh, or
/// a grid of weights: `weights`).
fn compare_grids<T: Clone + PartialEq>(
    weights: bool,
    name: &str,
    e: &Grid<T>,
    c: &Grid<T>,
    text: impl Fn(&T) -> String,
) -> Result<(), Check> {
    if (e.rows(), e.cols()) != (c.rows(), c.cols()) {
        let (rows, cols, found_rows, found_cols) = (e.rows(), e.cols(), c.rows(), c.cols());
        return Err(if weights {
            Check::WeightsSize {
                rows,
                cols,
                found_rows,
                found_cols,
            }
        } else {
            Check::MeshSize {
                rows,
                cols,
                found_rows,
                found_cols,
            }
        });
    }
    for ((i, j), a) in e.indexed() {
        if let Some(b) = c.get(i, j).filter(|b| *b != a) {
            return Err(Check::GridEntry {
                name: name.to_string(),
                i,
                j,
                expected: text(a),
                computed: text(b),
            });
        }
    }
    Ok(())
}

fn compare_meshes(e: &Mesh<Number>, c: &Mesh<Number>) -> Result<(), Check> {
    compare_grids(false, "c", e, c, Point::to_text)
}

/// Whether all the weights are equal (none or one included): then the rational curve or
/// surface is the polynomial one with the same control points.
fn all_equal<'a>(mut ws: impl Iterator<Item = &'a Number>) -> bool {
    match ws.next() {
        Some(first) => ws.all(|w| w == first),
        None => true,
    }
}

/// Two knot vectors compared modulo the convention: the notes' vector and The NURBS Book's
/// (one end knot more at each end) are the same knots ([`same_knots`]).
fn same_knot_vectors(e: &[Number], c: &[Number]) -> bool {
    let list = |ks: &[Number]| Exact::List(ks.iter().cloned().map(Exact::Number).collect());
    same_knots(&list(e), &list(c))
}

/// The expected grid of weights against the computed one: a polynomial surface expected of
/// a rational answer is a mismatch ([`Check::WeightsMissing`]) unless all its weights are
/// equal.
fn compare_weights(e: Option<&Grid<Number>>, c: Option<&Grid<Number>>) -> Result<(), Check> {
    match (e, c) {
        (None, None) => Ok(()),
        (None, Some(c)) if all_equal(c.iter()) => Ok(()),
        (None, Some(c)) => Err(Check::WeightsMissing {
            computed: matrix_text(&c.to_rows()),
        }),
        (Some(_), None) => Err(Check::WeightsOfPolynomialSurface),
        (Some(e), Some(c)) => compare_grids(true, "w", e, c, Print::to_text),
    }
}

fn compare_surfaces(e: &SurfaceIn<Number>, c: &SurfaceIn<Number>) -> Result<(), Check> {
    match (e, c) {
        (
            SurfaceIn::Bezier {
                mesh: me,
                weights: we,
            },
            SurfaceIn::Bezier {
                mesh: mc,
                weights: wc,
            },
        ) => {
            compare_meshes(me, mc)?;
            compare_weights(we.as_ref(), wc.as_ref())
        }
        (
            SurfaceIn::BSpline {
                mesh: me,
                degree: de,
                knots: ke,
                weights: we,
            },
            SurfaceIn::BSpline {
                mesh: mc,
                degree: dc,
                knots: kc,
                weights: wc,
            },
        ) => {
            if de != dc {
                return Err(Check::Bidegree {
                    expected: *de,
                    computed: *dc,
                });
            }
            if !(same_knot_vectors(&ke.0, &kc.0) && same_knot_vectors(&ke.1, &kc.1)) {
                return Err(Check::KnotsUV {
                    expected_u: numbers_text(&ke.0),
                    expected_v: numbers_text(&ke.1),
                    computed_u: numbers_text(&kc.0),
                    computed_v: numbers_text(&kc.1),
                });
            }
            compare_meshes(me, mc)?;
            compare_weights(we.as_ref(), wc.as_ref())
        }
        (SurfaceIn::Expr(a), SurfaceIn::Expr(b)) if a == b => Ok(()),
        _ => Err(Check::SurfaceKinds {
            expected: surface_kind(e),
            computed: surface_kind(c),
        }),
    }
}

/// The expected curve against the computed one: knots modulo the convention, and a
/// polynomial curve expected of a rational answer is a mismatch ([`Check::WeightsMissing`])
/// unless all its weights are equal.
fn compare_curves(e: &CurveIn<Number>, c: &CurveIn<Number>) -> Result<(), Check> {
    let weights = |we: &Option<Vec<Number>>, wc: &Option<Vec<Number>>| match (we, wc) {
        (Some(a), Some(b)) if a != b => Err(Check::Weights {
            expected: numbers_text(a),
            computed: numbers_text(b),
        }),
        (Some(_), None) => Err(Check::WeightsOfPolynomialCurve),
        (None, Some(b)) if !all_equal(b.iter()) => Err(Check::WeightsMissing {
            computed: numbers_text(b),
        }),
        _ => Ok(()),
    };
    match (e, c) {
        (
            CurveIn::Bezier {
                points: pe,
                weights: we,
            },
            CurveIn::Bezier {
                points: pc,
                weights: wc,
            },
        ) => {
            first_difference_points(pe, pc)?;
            weights(we, wc)
        }
        (
            CurveIn::BSpline {
                points: pe,
                degree: de,
                knots: ke,
                weights: we,
            },
            CurveIn::BSpline {
                points: pc,
                degree: dc,
                knots: kc,
                weights: wc,
            },
        ) => {
            if de != dc {
                return Err(Check::Degree {
                    expected: *de,
                    computed: *dc,
                });
            }
            if !same_knot_vectors(ke, kc) {
                return Err(Check::Knots {
                    expected: numbers_text(ke),
                    computed: numbers_text(kc),
                });
            }
            first_difference_points(pe, pc)?;
            weights(we, wc)
        }
        (CurveIn::Expr(a), CurveIn::Expr(b)) if a == b => Ok(()),
        _ => Err(Check::AnotherCurve),
    }
}

fn surface_kind<S: Scalar>(s: &SurfaceIn<S>) -> SurfaceKind {
    match s {
        SurfaceIn::Bezier { weights: None, .. } => SurfaceKind::Bezier,
        SurfaceIn::Bezier { .. } => SurfaceKind::RationalBezier,
        SurfaceIn::BSpline { weights: None, .. } => SurfaceKind::BSpline,
        SurfaceIn::BSpline { .. } => SurfaceKind::Nurbs,
        SurfaceIn::Expr(_) => SurfaceKind::Parametric,
    }
}

/// Whether two knot vectors are the same in either convention: equal, or one is the other
/// with one end knot more at each end (The NURBS Book's vector against the notes').
pub fn same_knots(a: &Exact, b: &Exact) -> bool {
    if a == b {
        return true;
    }
    let (Exact::List(a), Exact::List(b)) = (a, b) else {
        return false;
    };
    let inner = |long: &[Exact], short: &[Exact]| {
        long.len() == short.len() + 2 && long.get(1..long.len() - 1) == Some(short)
    };
    inner(a, b) || inner(b, a)
}
