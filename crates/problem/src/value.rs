//! Answers as exact values, independent of the scalar a problem ran in.
//!
//! A problem runs over `BigRational` or over a quadratic field; its results are then converted,
//! exactly, to [`Number`] (every exact scalar converts: a rational is a + 0√d). Printing,
//! JSON and the comparison with a fixture's `expected` are written once, here, for all scalars.

use crate::input::{CurveIn, SurfaceIn};
use crate::message::check::{Check, Inner, SurfaceKind};
use crate::spec::{self, List, Num, PointIn, Points};
use cagd_linalg::Point;
use cagd_poly::{parse_expr, Poly, RationalMap, VecPoly};
/// The numbers of problems and answers: exact, in Q or Q(√d), and in letters when the problem
/// declares parameters (a constant is held as a plain [`cagd_scalar::Quadratic`]).
pub type Number = cagd_param::Param;
use crate::values::put_in;
use cagd_param::Name;
use cagd_scalar::{Print, Quadratic, Scalar};
use cagd_surface::{Grid, Mesh};
use serde::ser::{Serialize, SerializeMap, Serializer};
use serde_json::Value;

/// An exact result value.
#[derive(Debug, Clone, PartialEq)]
pub enum Exact {
    /// A yes/no answer (developable, planar...).
    Bool(bool),
    /// A count or order (the continuity order).
    Int(i64),
    /// Text as written: a keyword, a value read from a problem, a parametrization with cos
    /// and sin (mathematics).
    Text(String),
    /// A sentence of the engine (a continuity verdict, "infinite"), typed: worded in each
    /// language by its [`crate::Message`], written in JSON as its English text (and equal to
    /// an expected string of that text).
    Sentence(crate::Message),
    /// A number.
    Number(Number),
    /// A point or vector.
    Point(Point<Number>),
    /// A list of points.
    Points(Vec<Point<Number>>),
    /// A matrix of numbers.
    Matrix(Vec<Vec<Number>>),
    /// A scalar polynomial.
    Poly(Poly<Number>),
    /// A polynomial map (a closed form).
    Map(VecPoly<Number>),
    /// A rational map (the closed form of a rational curve or surface).
    Rational(RationalMap<Number>),
    /// A curve.
    Curve(CurveIn<Number>),
    /// A surface.
    Surface(SurfaceIn<Number>),
    /// A list of values.
    List(Vec<Exact>),
    /// Named values.
    Object(Vec<(String, Exact)>),
}

impl Exact {
    /// The value with the parameters of `values` replaced (an answer in letters specialized),
    /// or an error when a denominator vanishes at these values.
    ///
    /// Substituting is a ring homomorphism on polynomials, so for every operation whose
    /// algebra is polynomial or rational in the parameters, substituting into the answer in
    /// letters gives the answer of the problem with the values put in (tested for each).
    pub fn substitute(&self, values: &[(Name, Number)]) -> Result<Exact, String> {
        let failed = std::cell::Cell::new(None::<String>);
        let f = |x: &Number| -> Number {
            x.substitute(values).unwrap_or_else(|| {
                failed.set(Some(x.to_text()));
                <Number as num_traits::Zero>::zero()
            })
        };
        let out = self.map_numbers(&f)?;
        match failed.take() {
            Some(x) => Err(format!(
                "the value {x} has a denominator that vanishes at these values"
            )),
            None => Ok(out),
        }
    }

    /// The most decimal digits of a numerator or denominator among the value's numbers (of
    /// their coefficients, for a value in letters) when some number has more than `limit`
    /// digits, else `None`: what the digit limit bounds when the value is read back
    /// (`docs/format.md`, Limits). A first pass bounds the digits by the bits (a number of b
    /// bits has fewer than b·3/10 + 1 digits), so an answer within the limit prints nothing.
    pub(crate) fn digits_past(&self, limit: usize) -> Option<usize> {
        // a rational of machine words has at most 19 digits a part: no bits to count
        let words = |x: &Number| {
            x.as_const()
                .and_then(Quadratic::as_rat)
                .is_some_and(cagd_scalar::Rat::is_word)
        };
        let mut bound = 0u64;
        self.each_number(&mut |x| {
            bound = bound.max(if words(x) { 63 } else { x.max_bits() });
        });
        let bound = usize::try_from(bound.saturating_mul(3) / 10 + 1).unwrap_or(usize::MAX);
        if bound <= limit {
            return None;
        }
        let mut most = 0usize;
        self.each_number(&mut |x| {
            let text = cagd_scalar::Print::to_text(x);
            let longest = text
                .split(|c: char| !c.is_ascii_digit())
                .map(str::len)
                .max()
                .unwrap_or(0);
            most = most.max(longest);
        });
        (most > limit).then_some(most)
    }

    /// Calls `f` on every number of the value (without copying it).
    fn each_number<F: FnMut(&Number)>(&self, f: &mut F) {
        fn poly<F: FnMut(&Number)>(p: &Poly<Number>, f: &mut F) {
            for (_, c) in p.terms() {
                f(c);
            }
        }
        match self {
            Exact::Bool(_) | Exact::Int(_) | Exact::Text(_) | Exact::Sentence(_) => {}
            Exact::Number(x) => f(x),
            Exact::Point(p) => p.coords().iter().for_each(&mut *f),
            Exact::Points(ps) => ps.iter().flat_map(|p| p.coords()).for_each(&mut *f),
            Exact::Matrix(rows) => rows.iter().flatten().for_each(&mut *f),
            Exact::Poly(p) => poly(p, f),
            Exact::Map(m) => m.components().iter().for_each(|p| poly(p, f)),
            Exact::Rational(r) => {
                r.numerator().components().iter().for_each(|p| poly(p, f));
                poly(r.denominator(), f);
            }
            Exact::Curve(c) => match c {
                CurveIn::Bezier { points, weights } => {
                    points.iter().flat_map(|p| p.coords()).for_each(&mut *f);
                    weights.iter().flatten().for_each(&mut *f);
                }
                CurveIn::BSpline {
                    points,
                    knots,
                    weights,
                    ..
                } => {
                    points.iter().flat_map(|p| p.coords()).for_each(&mut *f);
                    knots.iter().for_each(&mut *f);
                    weights.iter().flatten().for_each(&mut *f);
                }
                CurveIn::Expr(m) => m.components().iter().for_each(|p| poly(p, f)),
            },
            Exact::Surface(sf) => match sf {
                SurfaceIn::Bezier { mesh, weights } => {
                    mesh.iter().flat_map(|p| p.coords()).for_each(&mut *f);
                    weights.iter().flat_map(|w| w.iter()).for_each(&mut *f);
                }
                SurfaceIn::BSpline {
                    mesh,
                    knots,
                    weights,
                    ..
                } => {
                    mesh.iter().flat_map(|p| p.coords()).for_each(&mut *f);
                    knots.0.iter().chain(&knots.1).for_each(&mut *f);
                    weights.iter().flat_map(|w| w.iter()).for_each(&mut *f);
                }
                SurfaceIn::Expr(m) => m.components().iter().for_each(|p| poly(p, f)),
            },
            Exact::List(xs) => xs.iter().for_each(|x| x.each_number(f)),
            Exact::Object(kv) => kv.iter().for_each(|(_, x)| x.each_number(f)),
        }
    }

    /// Every number of the value mapped by `f` (the structure kept).
    fn map_numbers(&self, f: &dyn Fn(&Number) -> Number) -> Result<Exact, String> {
        let point = |p: &Point<Number>| Point::new(p.coords().iter().map(f).collect());
        let numbers = |xs: &[Number]| xs.iter().map(f).collect::<Vec<_>>();
        let map = |m: &VecPoly<Number>| m.map_coeffs(f);
        Ok(match self {
            Exact::Bool(_) | Exact::Int(_) | Exact::Text(_) | Exact::Sentence(_) => self.clone(),
            Exact::Number(x) => Exact::Number(f(x)),
            Exact::Point(p) => Exact::Point(point(p)),
            Exact::Points(ps) => Exact::Points(ps.iter().map(point).collect()),
            Exact::Matrix(rows) => Exact::Matrix(rows.iter().map(|r| numbers(r)).collect()),
            Exact::Poly(p) => Exact::Poly(p.map_coeffs(f)),
            Exact::Map(m) => Exact::Map(map(m)),
            Exact::Rational(r) => Exact::Rational(
                RationalMap::new(map(r.numerator()), r.denominator().map_coeffs(f))
                    .map_err(|e| e.to_string())?,
            ),
            Exact::Curve(c) => Exact::Curve(match c {
                CurveIn::Bezier { points, weights } => CurveIn::Bezier {
                    points: points.iter().map(point).collect(),
                    weights: weights.as_deref().map(numbers),
                },
                CurveIn::BSpline {
                    points,
                    degree,
                    knots,
                    weights,
                } => CurveIn::BSpline {
                    points: points.iter().map(point).collect(),
                    degree: *degree,
                    knots: numbers(knots),
                    weights: weights.as_deref().map(numbers),
                },
                CurveIn::Expr(m) => CurveIn::Expr(map(m)),
            }),
            Exact::Surface(sf) => Exact::Surface(match sf {
                SurfaceIn::Bezier { mesh, weights } => SurfaceIn::Bezier {
                    mesh: mesh.map(point),
                    weights: weights.as_ref().map(|w| w.map(f)),
                },
                SurfaceIn::BSpline {
                    mesh,
                    degree,
                    knots,
                    weights,
                } => SurfaceIn::BSpline {
                    mesh: mesh.map(point),
                    degree: *degree,
                    knots: (numbers(&knots.0), numbers(&knots.1)),
                    weights: weights.as_ref().map(|w| w.map(f)),
                },
                SurfaceIn::Expr(m) => SurfaceIn::Expr(map(m)),
            }),
            Exact::List(xs) => Exact::List(
                xs.iter()
                    .map(|x| x.map_numbers(f))
                    .collect::<Result<_, _>>()?,
            ),
            Exact::Object(kv) => Exact::Object(
                kv.iter()
                    .map(|(k, x)| Ok((k.clone(), x.map_numbers(f)?)))
                    .collect::<Result<_, String>>()?,
            ),
        })
    }
}

/// The scalars a problem can run in: the exact ones. Each converts to [`Number`] exactly
/// (a rational is a + 0√d), so no float ever reaches an answer.
pub trait ExactScalar: Scalar {
    /// The same number as a [`Number`].
    fn exact(&self) -> Number;

    /// A number of the problem in this scalar, with the values of a problem's `"values"` put
    /// in during its solve ([`crate::values`]), or why it does not fit (a root the field has
    /// not, a letter in a numeric field, a denominator that vanishes at the values).
    fn from_number(x: &Number) -> Result<Self, crate::Message>;
}

/// The constant of a number that must have no letters.
fn constant(x: &Number) -> Result<&Quadratic, crate::Message> {
    x.as_const().ok_or_else(|| {
        crate::message::contract::Contract::InLetters {
            number: x.to_text(),
        }
        .into()
    })
}

impl ExactScalar for cagd_scalar::BigRational {
    fn exact(&self) -> Number {
        Number::Const(Quadratic::from_rational(self.clone()))
    }
    fn from_number(x: &Number) -> Result<Self, crate::Message> {
        // a constant has no letter to put a value in: read as it is (the common case)
        if let Some(c) = x.as_const() {
            return <Self as cagd_scalar::ExactRational>::try_from_number(c)
                .map_err(crate::Message::from);
        }
        <Self as cagd_scalar::ExactRational>::try_from_number(constant(put_in(x)?.as_ref())?)
            .map_err(crate::Message::from)
    }
}

impl ExactScalar for cagd_scalar::Rat {
    fn exact(&self) -> Number {
        Number::Const(Quadratic::from_rat(self.clone()))
    }
    fn from_number(x: &Number) -> Result<Self, crate::Message> {
        // a constant has no letter to put a value in: read as it is (the common case)
        if let Some(c) = x.as_const() {
            return <Self as cagd_scalar::ExactRational>::try_from_number(c)
                .map_err(crate::Message::from);
        }
        <Self as cagd_scalar::ExactRational>::try_from_number(constant(put_in(x)?.as_ref())?)
            .map_err(crate::Message::from)
    }
}

impl ExactScalar for Quadratic {
    fn exact(&self) -> Number {
        Number::Const(self.clone())
    }
    fn from_number(x: &Number) -> Result<Self, crate::Message> {
        if let Some(c) = x.as_const() {
            return Ok(c.clone());
        }
        Ok(constant(put_in(x)?.as_ref())?.clone())
    }
}

impl ExactScalar for Number {
    fn exact(&self) -> Number {
        self.clone()
    }
    fn from_number(x: &Number) -> Result<Self, crate::Message> {
        Ok(put_in(x)?.into_owned())
    }
}

/// A scalar as an exact number.
pub fn exact<S: ExactScalar>(x: &S) -> Number {
    x.exact()
}

/// A point as an exact point.
pub fn exact_point<S: ExactScalar>(p: &Point<S>) -> Point<Number> {
    Point::new(p.coords().iter().map(exact).collect())
}

/// A list of points.
pub fn exact_points<S: ExactScalar>(ps: &[Point<S>]) -> Vec<Point<Number>> {
    ps.iter().map(exact_point).collect()
}

/// A mesh.
pub fn exact_mesh<S: ExactScalar>(m: &Mesh<S>) -> Mesh<Number> {
    m.map(exact_point)
}

/// A grid of numbers.
pub fn exact_grid<S: ExactScalar>(g: &Grid<S>) -> Grid<Number> {
    g.map(exact)
}

/// A polynomial.
pub fn exact_poly<S: ExactScalar>(p: &Poly<S>) -> Poly<Number> {
    p.map_coeffs(exact)
}

/// A polynomial map.
pub fn exact_map<S: ExactScalar>(p: &VecPoly<S>) -> VecPoly<Number> {
    p.map_coeffs(exact)
}

/// A rational map.
pub fn exact_rational<S: ExactScalar>(r: &RationalMap<S>) -> RationalMap<Number> {
    RationalMap::new(exact_map(r.numerator()), exact_poly(r.denominator()))
        .unwrap_or_else(|_| RationalMap::from_polynomial(exact_map(r.numerator())))
}

impl Exact {
    /// A Bézier (or rational Bézier) surface.
    pub fn bezier_surface<S: ExactScalar>(mesh: &Mesh<S>, weights: Option<&Grid<S>>) -> Exact {
        Exact::Surface(SurfaceIn::Bezier {
            mesh: exact_mesh(mesh),
            weights: weights.map(exact_grid),
        })
    }

    /// A B-spline (or NURBS) surface, knots in the notes' convention.
    pub fn spline_surface<S: ExactScalar>(
        knots_u: &cagd_bspline::KnotVector<S>,
        knots_v: &cagd_bspline::KnotVector<S>,
        mesh: &Mesh<S>,
        weights: Option<&Grid<S>>,
    ) -> Exact {
        let notes = |k: &cagd_bspline::KnotVector<S>| {
            k.to_convention(cagd_bspline::KnotConvention::Notes)
                .iter()
                .map(exact)
                .collect::<Vec<_>>()
        };
        Exact::Surface(SurfaceIn::BSpline {
            mesh: exact_mesh(mesh),
            degree: (knots_u.degree(), knots_v.degree()),
            knots: (notes(knots_u), notes(knots_v)),
            weights: weights.map(exact_grid),
        })
    }

    /// A matrix of scalars given by rows.
    pub fn matrix<S: ExactScalar>(rows: &[Vec<S>]) -> Exact {
        Exact::Matrix(rows.iter().map(|r| r.iter().map(exact).collect()).collect())
    }

    /// The JSON form (numbers as exact strings; closed forms as parseable strings). A surface or
    /// curve has the input shape, so an answer can be fed back as a problem. The same JSON is
    /// written without this tree by the [`Serialize`] impl (`serde_json::to_writer`).
    pub fn to_json(&self) -> Value {
        serde_json::to_value(self).unwrap_or(Value::Null)
    }

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
                        .find(|(name, _)| name == k)
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

fn parse_expected(expected: &Value) -> Result<cagd_poly::Expr, Check> {
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

fn compare_weights(e: Option<&Grid<Number>>, c: Option<&Grid<Number>>) -> Result<(), Check> {
    match (e, c) {
        (None, _) => Ok(()),
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
            if ke != kc {
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

fn compare_curves(e: &CurveIn<Number>, c: &CurveIn<Number>) -> Result<(), Check> {
    let weights = |we: &Option<Vec<Number>>, wc: &Option<Vec<Number>>| match (we, wc) {
        (Some(a), Some(b)) if a != b => Err(Check::Weights {
            expected: numbers_text(a),
            computed: numbers_text(b),
        }),
        (Some(_), None) => Err(Check::WeightsOfPolynomialCurve),
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
            if ke != kc {
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

/// A rational map as one string: `(numerator)/(denominator)` with both in the JSON form of
/// the expression grammar.
pub fn rational_json(r: &RationalMap<Number>) -> String {
    format!(
        "{}/({})",
        r.numerator().to_json_string(),
        r.denominator().to_json_string()
    )
}

/// `{a, b, c}` in plain text.
pub fn numbers_text(xs: &[Number]) -> String {
    format!(
        "{{{}}}",
        xs.iter().map(Print::to_text).collect::<Vec<_>>().join(", ")
    )
}

/// Rows of numbers in plain text: `[1, 0; 1/4, 1/2]`.
pub fn matrix_text(rows: &[Vec<Number>]) -> String {
    let rs: Vec<String> = rows
        .iter()
        .map(|r| r.iter().map(Print::to_text).collect::<Vec<_>>().join(", "))
        .collect();
    format!("[{}]", rs.join("; "))
}

/// One exact number, as the JSON string that reads back to it.
struct NumberJson<'a>(&'a Number);

impl Serialize for NumberJson<'_> {
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        // a rational, the common case, is written from the stack
        match self.0.as_const().and_then(Quadratic::as_rat) {
            Some(r) => r.with_text(|text| s.serialize_str(text)),
            None => s.serialize_str(&self.0.to_json_string()),
        }
    }
}

/// A list of numbers (a point, a row, knots, weights).
struct Numbers<'a>(&'a [Number]);

impl Serialize for Numbers<'_> {
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        s.collect_seq(self.0.iter().map(NumberJson))
    }
}

/// A list of points.
struct PointsJson<'a>(&'a [Point<Number>]);

impl Serialize for PointsJson<'_> {
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        s.collect_seq(self.0.iter().map(|p| Numbers(p.coords())))
    }
}

/// A grid of numbers, by rows.
struct GridJson<'a>(&'a Grid<Number>);

impl Serialize for GridJson<'_> {
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        s.collect_seq((0..self.0.rows()).map(|i| Numbers(self.0.row(i).unwrap_or(&[]))))
    }
}

/// A mesh of points, by rows.
struct MeshJson<'a>(&'a Mesh<Number>);

impl Serialize for MeshJson<'_> {
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        s.collect_seq((0..self.0.rows()).map(|i| PointsJson(self.0.row(i).unwrap_or(&[]))))
    }
}

impl Serialize for CurveIn<Number> {
    /// The input shape: `{"bezier": [...], "weights": [...]}`, `{"bspline": [...], "degree",
    /// "knots", "weights"}` or `{"expr": "..."}`.
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        let mut m = s.serialize_map(None)?;
        match self {
            CurveIn::Bezier { points, weights } => {
                m.serialize_entry("bezier", &PointsJson(points))?;
                if let Some(w) = weights {
                    m.serialize_entry("weights", &Numbers(w))?;
                }
            }
            CurveIn::BSpline {
                points,
                degree,
                knots,
                weights,
            } => {
                m.serialize_entry("bspline", &PointsJson(points))?;
                m.serialize_entry("degree", degree)?;
                m.serialize_entry("knots", &Numbers(knots))?;
                if let Some(w) = weights {
                    m.serialize_entry("weights", &Numbers(w))?;
                }
            }
            CurveIn::Expr(e) => m.serialize_entry("expr", &e.to_json_string())?,
        }
        m.end()
    }
}

impl Serialize for SurfaceIn<Number> {
    /// The input shape: `{"bezier": mesh, "weights": grid}`, `{"bspline": mesh, "degree":
    /// [p, q], "knots": [[...], [...]], "weights"}` or `{"expr": "..."}`.
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        let mut m = s.serialize_map(None)?;
        match self {
            SurfaceIn::Bezier { mesh, weights } => {
                m.serialize_entry("bezier", &MeshJson(mesh))?;
                if let Some(w) = weights {
                    m.serialize_entry("weights", &GridJson(w))?;
                }
            }
            SurfaceIn::BSpline {
                mesh,
                degree,
                knots,
                weights,
            } => {
                m.serialize_entry("bspline", &MeshJson(mesh))?;
                m.serialize_entry("degree", &[degree.0, degree.1])?;
                m.serialize_entry("knots", &[Numbers(&knots.0), Numbers(&knots.1)])?;
                if let Some(w) = weights {
                    m.serialize_entry("weights", &GridJson(w))?;
                }
            }
            SurfaceIn::Expr(e) => m.serialize_entry("expr", &e.to_json_string())?,
        }
        m.end()
    }
}

impl Serialize for Exact {
    /// The JSON form of [`Exact::to_json`], written straight to a serializer.
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        match self {
            Exact::Bool(b) => s.serialize_bool(*b),
            Exact::Int(i) => s.serialize_i64(*i),
            Exact::Text(t) => s.serialize_str(t),
            Exact::Sentence(m) => s.collect_str(m),
            Exact::Number(x) => NumberJson(x).serialize(s),
            Exact::Point(p) => Numbers(p.coords()).serialize(s),
            Exact::Points(ps) => PointsJson(ps).serialize(s),
            Exact::Matrix(rows) => s.collect_seq(rows.iter().map(|r| Numbers(r))),
            Exact::Poly(p) => s.serialize_str(&p.to_json_string()),
            Exact::Map(m) => s.serialize_str(&m.to_json_string()),
            Exact::Rational(r) => s.serialize_str(&rational_json(r)),
            Exact::Curve(c) => c.serialize(s),
            Exact::Surface(surface) => surface.serialize(s),
            Exact::List(xs) => s.collect_seq(xs),
            Exact::Object(kv) => s.collect_map(kv.iter().map(|(k, v)| (k, v))),
        }
    }
}

use crate::pretty::JsonWriter;

impl JsonWriter<'_> {
    /// One exact number, as [`NumberJson`] writes it: a rational's digits straight into the
    /// buffer.
    pub(crate) fn number(&mut self, x: &Number) {
        match x.as_const().and_then(Quadratic::as_rat) {
            Some(r) => self.plain_string(|out| r.push_text(out)),
            None => self.string(&x.to_json_string()),
        }
    }

    /// A list of numbers, as [`Numbers`] writes it.
    fn numbers(&mut self, xs: &[Number]) {
        self.seq(xs, |w, x| w.number(x));
    }

    /// A list of points, as [`PointsJson`] writes it.
    fn points(&mut self, ps: &[Point<Number>]) {
        self.seq(ps, |w, p| w.numbers(p.coords()));
    }

    /// A mesh by rows, as [`MeshJson`] writes it.
    fn mesh(&mut self, m: &Mesh<Number>) {
        self.seq(0..m.rows(), |w, i| w.points(m.row(i).unwrap_or(&[])));
    }

    /// A grid of numbers by rows, as [`GridJson`] writes it.
    fn grid(&mut self, g: &Grid<Number>) {
        self.seq(0..g.rows(), |w, i| w.numbers(g.row(i).unwrap_or(&[])));
    }

    /// An exact value: the bytes its [`Serialize`] impl writes through serde_json with
    /// [`crate::pretty::Pretty`].
    pub(crate) fn exact(&mut self, x: &Exact) {
        match x {
            Exact::Bool(b) => self.bool(*b),
            Exact::Int(i) => self.int(*i),
            Exact::Text(t) => self.string(t),
            Exact::Sentence(m) => self.string(&m.to_string()),
            Exact::Number(x) => self.number(x),
            Exact::Point(p) => self.numbers(p.coords()),
            Exact::Points(ps) => self.points(ps),
            Exact::Matrix(rows) => self.seq(rows, |w, r| w.numbers(r)),
            Exact::Poly(p) => self.string(&p.to_json_string()),
            Exact::Map(m) => self.string(&m.to_json_string()),
            Exact::Rational(r) => self.string(&rational_json(r)),
            Exact::Curve(c) => self.object(|o| match c {
                CurveIn::Bezier { points, weights } => {
                    o.key("bezier").points(points);
                    if let Some(w) = weights {
                        o.key("weights").numbers(w);
                    }
                }
                CurveIn::BSpline {
                    points,
                    degree,
                    knots,
                    weights,
                } => {
                    o.key("bspline").points(points);
                    o.key("degree").int(*degree);
                    o.key("knots").numbers(knots);
                    if let Some(w) = weights {
                        o.key("weights").numbers(w);
                    }
                }
                CurveIn::Expr(e) => o.key("expr").string(&e.to_json_string()),
            }),
            Exact::Surface(sf) => self.object(|o| match sf {
                SurfaceIn::Bezier { mesh, weights } => {
                    o.key("bezier").mesh(mesh);
                    if let Some(w) = weights {
                        o.key("weights").grid(w);
                    }
                }
                SurfaceIn::BSpline {
                    mesh,
                    degree,
                    knots,
                    weights,
                } => {
                    o.key("bspline").mesh(mesh);
                    o.key("degree").seq([degree.0, degree.1], |w, d| w.int(d));
                    o.key("knots")
                        .seq([&knots.0, &knots.1], |w, k| w.numbers(k));
                    if let Some(w) = weights {
                        o.key("weights").grid(w);
                    }
                }
                SurfaceIn::Expr(e) => o.key("expr").string(&e.to_json_string()),
            }),
            Exact::List(xs) => self.seq(xs, |w, x| w.exact(x)),
            Exact::Object(kv) => self.object(|o| {
                for (k, v) in kv {
                    o.key(k).exact(v);
                }
            }),
        }
    }
}
