//! B-spline and NURBS surfaces and curves piece by piece through `cagd solve`: closed forms per
//! span, derivatives, normals and the continuity across knot lines, the joins of two curves or
//! two surfaces, subdivision and knot removal, each checked against an independent route: De
//! Boor's algorithm (evaluation and derivatives at a point, cagd-spline-surface and
//! cagd-bspline), and the exact limit of difference quotients.

use cagd_bspline::NurbsCurve;
use cagd_linalg::Point;
use cagd_poly::Var;
use cagd_problem::{solve, Exact, Number, Quantity};
use cagd_scalar::{BigRational, ExactRational, FieldOps};
use cagd_spline_surface::{BSplineSurface, NurbsSurface};
use cagd_surface::{Grid, Mesh};
use proptest::prelude::*;
use serde_json::{json, Value};

fn q(n: i64, d: i64) -> BigRational {
    BigRational::from_ratio(n, d)
}

fn num(x: &BigRational) -> Number {
    Number::from_rational(x)
}

fn point(p: &Point<BigRational>) -> Point<Number> {
    Point::new(p.coords().iter().map(num).collect())
}

/// A knot vector in the notes' convention: p copies of 0, interior knots 1, 2, ... with the
/// multiplicities `mults` (each at most p), p copies of the end.
fn knots(p: usize, mults: &[usize]) -> Vec<i64> {
    let end = i64::try_from(mults.len()).unwrap() + 1;
    let mut k = vec![0; p];
    for (i, m) in mults.iter().enumerate() {
        k.extend(std::iter::repeat_n(i64::try_from(i).unwrap() + 1, *m));
    }
    k.extend(std::iter::repeat_n(end, p));
    k
}

/// A random B-spline surface: bidegree, interior multiplicities in u and v, integer mesh and
/// positive weights.
#[derive(Debug, Clone)]
struct Spline {
    p: usize,
    q: usize,
    ku: Vec<i64>,
    kv: Vec<i64>,
    mesh: Vec<Vec<Vec<i64>>>,
    weights: Vec<Vec<i64>>,
}

impl Spline {
    fn json(&self, rational: bool) -> Value {
        let mut s =
            json!({"bspline": self.mesh, "degree": [self.p, self.q], "knots": [self.ku, self.kv]});
        if rational {
            s["weights"] = json!(self.weights);
        }
        s
    }
    fn mesh(&self) -> Mesh<BigRational> {
        Mesh::mesh(
            self.mesh
                .iter()
                .map(|r| r.iter().map(|c| Point::from_ints(c)).collect())
                .collect(),
        )
        .unwrap()
    }
    fn knots(&self) -> (Vec<BigRational>, Vec<BigRational>) {
        let k = |v: &[i64]| v.iter().map(|x| q(*x, 1)).collect();
        (k(&self.ku), k(&self.kv))
    }
    fn bspline(&self) -> BSplineSurface<BigRational> {
        BSplineSurface::read((self.p, self.q), self.knots(), self.mesh())
            .unwrap()
            .0
    }
    fn nurbs(&self) -> NurbsSurface<BigRational> {
        let w = Grid::from_rows(
            self.weights
                .iter()
                .map(|r| r.iter().map(|x| q(*x, 1)).collect())
                .collect(),
        )
        .unwrap();
        NurbsSurface::read((self.p, self.q), self.knots(), self.mesh(), w)
            .unwrap()
            .0
    }
    fn domain_ends(&self) -> (i64, i64) {
        (*self.ku.last().unwrap(), *self.kv.last().unwrap())
    }
}

fn spline() -> impl Strategy<Value = Spline> {
    (1usize..=3, 1usize..=2)
        .prop_flat_map(|(p, q)| {
            (
                Just(p),
                Just(q),
                prop::collection::vec(1..=p, 0..=2),
                prop::collection::vec(1..=q, 0..=1),
            )
        })
        .prop_flat_map(|(p, q, mu, mv)| {
            let (ku, kv) = (knots(p, &mu), knots(q, &mv));
            // the notes' convention: n + p - 1 knots for n points
            let (rows, cols) = (ku.len() + 1 - p, kv.len() + 1 - q);
            (
                Just(p),
                Just(q),
                Just(ku),
                Just(kv),
                prop::collection::vec(
                    prop::collection::vec(prop::collection::vec(-4i64..=4, 3), cols),
                    rows,
                ),
                prop::collection::vec(prop::collection::vec(1i64..=3, cols), rows),
            )
        })
        .prop_map(|(p, q, ku, kv, mesh, weights)| Spline {
            p,
            q,
            ku,
            kv,
            mesh,
            weights,
        })
}

/// The pieces of an answer: (u interval, v interval, value), or (t interval, value).
fn pieces(answer: &cagd_problem::Answer) -> Vec<Vec<(Quantity, Exact)>> {
    let Some(Exact::List(list)) = answer.get("pieces") else {
        panic!("no pieces");
    };
    list.iter()
        .map(|x| match x {
            Exact::Object(kv) => kv.clone(),
            other => panic!("not a piece: {other:?}"),
        })
        .collect()
}

fn field<'a>(piece: &'a [(Quantity, Exact)], name: &str) -> &'a Exact {
    &piece.iter().find(|(k, _)| k.name() == name).unwrap().1
}

fn interval(e: &Exact) -> (Number, Number) {
    let Exact::Point(p) = e else {
        panic!("no interval")
    };
    (p.coords()[0].clone(), p.coords()[1].clone())
}

fn inside(x: &Number, (a, b): &(Number, Number)) -> bool {
    let le = |a: &Number, b: &Number| a.compare(b) != Some(std::cmp::Ordering::Greater);
    le(a, x) && le(x, b)
}

/// The value of a closed form (polynomial or rational) at the point `at`.
fn eval(e: &Exact, at: &[(Var, Number)]) -> Point<Number> {
    match e {
        Exact::Map(m) => m.eval(at).unwrap(),
        Exact::Rational(r) => r.eval(at).unwrap(),
        other => panic!("not a closed form: {other:?}"),
    }
}

/// The piece of a surface answer containing (u, v), and its closed form there.
fn surface_value(answer: &cagd_problem::Answer, u: &Number, v: &Number) -> Point<Number> {
    let ps = pieces(answer);
    let piece = ps
        .iter()
        .find(|p| inside(u, &interval(field(p, "u"))) && inside(v, &interval(field(p, "v"))))
        .expect("a piece contains the point");
    eval(
        field(piece, "closed_form"),
        &[(Var::U, u.clone()), (Var::V, v.clone())],
    )
}

/// Points inside each rectangle of spans: its centre and a third of the way.
fn sample_points(s: &Spline) -> Vec<(BigRational, BigRational)> {
    let (eu, ev) = s.domain_ends();
    let mut out = Vec::new();
    for a in 0..eu {
        for b in 0..ev {
            out.push((q(2 * a + 1, 2), q(2 * b + 1, 2)));
            out.push((q(3 * a + 1, 3), q(3 * b + 2, 3)));
        }
    }
    out.push((q(eu, 1), q(ev, 1)));
    out
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// The closed form of each piece evaluates equal to De Boor's algorithm on its rectangle,
    /// for B-spline and NURBS surfaces.
    #[test]
    fn piecewise_closed_forms_equal_de_boor(s in spline()) {
        for rational in [false, true] {
            let a = solve(&json!({"op": "closed_form", "surface": s.json(rational)})).unwrap();
            for (u, v) in sample_points(&s) {
                let expected = if rational { s.nurbs().eval(&u, &v) } else { s.bspline().eval(&u, &v) };
                prop_assert_eq!(surface_value(&a, &num(&u), &num(&v)), point(&expected.unwrap()));
            }
        }
    }

    /// The derivative of order (r, s) of each piece equals De Boor's derivative at the point
    /// (cagd-spline-surface's `partial`; the quotient rule on the homogeneous surface for
    /// NURBS), and the derivative surface of a B-spline evaluates equal to the pieces.
    #[test]
    fn piecewise_derivatives_equal_de_boor(s in spline(), r in 0usize..=2, t in 0usize..=1) {
        let a = solve(&json!({"op": "derivative", "surface": s.json(false), "order": [r, t]})).unwrap();
        let b = s.bspline();
        for (u, v) in sample_points(&s) {
            let expected = b.partial(&u, &v, r, t).unwrap();
            // at a knot De Boor takes the derivative from the right: compare inside the spans
            let at_knot = s.ku.iter().any(|k| q(*k, 1) == u) || s.kv.iter().any(|k| q(*k, 1) == v);
            if !at_knot {
                prop_assert_eq!(surface_value(&a, &num(&u), &num(&v)), point(&expected));
            }
        }
        if let Some(Exact::Surface(surface)) = a.get("surface") {
            let surface = Exact::Surface(surface.clone()).to_json();
            let d = solve(&json!({"op": "evaluate", "surface": surface, "params": [["1/2", "1/2"]]})).unwrap();
            let Some(Exact::Points(pts)) = d.get("points") else { panic!("no points") };
            prop_assert_eq!(&pts[0], &surface_value(&a, &num(&q(1, 2)), &num(&q(1, 2))));
        }
        if r == 1 && t == 0 {
            let a = solve(&json!({"op": "derivative", "surface": s.json(true), "order": [1, 0]})).unwrap();
            let n = s.nurbs();
            for (u, v) in sample_points(&s) {
                let at_knot = s.ku.iter().any(|k| q(*k, 1) == u);
                if !at_knot {
                    let [_, cu, _] = n.first_partials(&u, &v).unwrap();
                    prop_assert_eq!(surface_value(&a, &num(&u), &num(&v)), point(&cu));
                }
            }
        }
    }

    /// The normal of each piece is c_u × c_v of De Boor's derivatives at the point.
    #[test]
    fn piecewise_normals_equal_the_cross_product(s in spline()) {
        let a = solve(&json!({"op": "normal", "surface": s.json(false)})).unwrap();
        let b = s.bspline();
        for (u, v) in sample_points(&s) {
            let at_knot = s.ku.iter().any(|k| q(*k, 1) == u) || s.kv.iter().any(|k| q(*k, 1) == v);
            if !at_knot {
                let n = b.partial(&u, &v, 1, 0).unwrap().cross(&b.partial(&u, &v, 0, 1).unwrap()).unwrap();
                prop_assert_eq!(surface_value(&a, &num(&u), &num(&v)), point(&n));
            }
        }
    }

    /// Across every knot line the order checked on the pieces is at least the order the
    /// multiplicity gives, p - μ (a B-spline is C^{p-μ} there whatever its mesh).
    #[test]
    fn knot_lines_are_at_least_as_smooth_as_the_knots_say(s in spline(), rational in any::<bool>()) {
        let a = solve(&json!({"op": "continuity", "surface": s.json(rational)})).unwrap();
        let Some(Exact::List(lines)) = a.get("knot_lines") else { panic!("no knot lines") };
        let interior = |k: &[i64]| {
            let mut d = k.to_vec();
            d.dedup();
            d.len().saturating_sub(2)
        };
        prop_assert_eq!(lines.len(), interior(&s.ku) + interior(&s.kv));
        for line in lines {
            let Exact::Object(kv) = line else { panic!("not a line") };
            let Exact::Int(expected) = field(kv, "expected") else { panic!("no expected") };
            match field(kv, "order") {
                Exact::Int(k) => prop_assert!(k >= expected, "{kv:?}"),
                Exact::Text(t) => prop_assert_eq!(t.as_str(), "infinite"),
                Exact::Sentence(m) => prop_assert_eq!(m.to_string(), "infinite"),
                other => panic!("{other:?}"),
            }
        }
    }

    /// The derivative of each piece of a B-spline curve equals the exact limit of its
    /// difference quotients: (c(t + h) - c(t))/h is a polynomial in h of degree < p, so its
    /// values at h = 1, ..., p extrapolate exactly to h = 0 (Lagrange).
    #[test]
    fn curve_derivative_is_the_limit_of_difference_quotients(
        p in 1usize..=3,
        mults in prop::collection::vec(1usize..=2, 0..=2),
        seed in prop::collection::vec(-5i64..=5, 24),
        weights in prop::collection::vec(1i64..=3, 12),
    ) {
        let mults: Vec<usize> = mults.into_iter().map(|m| m.min(p)).collect();
        let k = knots(p, &mults);
        let n = k.len() + 1 - p;
        let pts: Vec<[i64; 2]> = (0..n).map(|i| [seed[2 * i % 24], seed[(2 * i + 1) % 24]]).collect();
        let w: Vec<i64> = (0..n).map(|i| weights[i % 12]).collect();
        let closed = solve(&json!({"op": "closed_form", "curve": {"bspline": pts, "degree": p, "knots": k}})).unwrap();
        let deriv = solve(&json!({"op": "derivative", "curve": {"bspline": pts, "degree": p, "knots": k}, "order": 1})).unwrap();
        let (cs, ds) = (pieces(&closed), pieces(&deriv));
        prop_assert_eq!(cs.len(), ds.len());
        let t0 = num(&q(1, 3));
        for (c, d) in cs.iter().zip(&ds) {
            let span = interval(field(c, "t"));
            let t = span.0.clone() + t0.clone() * (span.1.clone() - span.0.clone());
            let f = |x: &Number| eval(field(c, "closed_form"), &[(Var::T, x.clone())]);
            let quotient = |h: i64| {
                let h = Number::from_i64(h);
                (f(&(t.clone() + h.clone())) - f(&t)).scale(&(Number::from_i64(1) / h))
            };
            // Lagrange at 0 through h = 1, ..., p: Σ_k q(k) Π_{j≠k} j/(j - k)
            let mut limit = Point::zero(2);
            for kk in 1..=i64::try_from(p).unwrap() {
                let mut coeff = Number::from_i64(1);
                for j in 1..=i64::try_from(p).unwrap() {
                    if j != kk {
                        coeff *= Number::from_ratio(j, j - kk);
                    }
                }
                limit = limit + quotient(kk).scale(&coeff);
            }
            prop_assert_eq!(eval(field(d, "closed_form"), &[(Var::T, t.clone())]), limit);
        }
        // the NURBS curve: each piece's derivative equals De Boor's on the homogeneous curve
        let nurbs = solve(&json!({"op": "derivative", "curve": {"bspline": pts, "degree": p, "knots": k, "weights": w}, "order": 1})).unwrap();
        let c = NurbsCurve::read(
            p,
            k.iter().map(|x| q(*x, 1)).collect(),
            pts.iter().map(|x| Point::from_ints(x)).collect(),
            w.iter().map(|x| q(*x, 1)).collect(),
        ).unwrap().0;
        let spans = c.knots().spans().len();
        prop_assert_eq!(pieces(&nurbs).len(), spans);
        for (i, piece) in pieces(&nurbs).iter().enumerate() {
            // the spans are [i, i + 1]: the point a third of the way
            let t = q(3 * i64::try_from(i).unwrap() + 1, 3);
            prop_assert!(inside(&num(&t), &interval(field(piece, "t"))));
            let expected = c.derivatives(&t, 1).unwrap();
            prop_assert_eq!(eval(field(piece, "closed_form"), &[(Var::T, num(&t))]), point(&expected[1]));
        }
    }
}

#[test]
fn one_polynomial_with_a_knot_inserted_is_infinitely_smooth_across_it() {
    // a biquadratic Bézier patch on [0, 2] x [0, 1] with the knot u = 1 inserted: the knots
    // say C^1, the pieces are one polynomial
    let patch = json!({"bspline": [[[0, 0, 0], [0, 1, 1], [0, 2, 0]],
                                   [[1, 0, 2], [1, 1, 3], [1, 2, 2]],
                                   [[2, 0, 0], [2, 1, 1], [2, 2, 0]]],
                       "degree": [2, 2], "knots": [[0, 0, 2, 2], [0, 0, 1, 1]]});
    let inserted =
        solve(&json!({"op": "insert_knot", "surface": patch, "knot": 1, "direction": "u"}))
            .unwrap();
    let Some(Exact::Surface(s)) = inserted.get("surface") else {
        panic!("no surface")
    };
    let a = solve(&json!({"op": "continuity", "surface": Exact::Surface(s.clone()).to_json()}))
        .unwrap();
    assert_eq!(a.get("order").unwrap().to_json(), json!("infinite"));
    assert_eq!(
        a.get("knot_lines").unwrap().to_json(),
        json!([{"direction": "u", "knot": "1", "multiplicity": 1, "expected": 1, "order": "infinite"}])
    );
}

#[test]
fn a_double_knot_with_a_kink_is_c0() {
    // degree 2 in u with the knot 1 twice: C^0 by the knots, and the mesh has a kink there:
    // the pieces are the Bézier arcs z = 2u(1 - u) on [0, 1] and z = 6(u - 1)(2 - u) on [1, 2]
    let s = json!({"bspline": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 1], [1, 1, 1]], [[2, 0, 0], [2, 1, 0]],
                               [[3, 0, 3], [3, 1, 3]], [[4, 0, 0], [4, 1, 0]]],
                   "degree": [2, 1], "knots": [[0, 0, 1, 1, 2, 2], [0, 1]]});
    let a = solve(&json!({"op": "continuity", "surface": s})).unwrap();
    assert_eq!(a.get("order").unwrap().to_json(), json!(0));
    let closed = solve(&json!({"op": "closed_form", "surface": s})).unwrap();
    assert_eq!(
        closed.get("pieces").unwrap().to_json(),
        json!([
            {"u": ["0", "1"], "v": ["0", "1"], "closed_form": "(2*u, v, -2*u^2 + 2*u)"},
            {"u": ["1", "2"], "v": ["0", "1"], "closed_form": "(2*u, v, -6*u^2 + 18*u - 12)"}
        ])
    );
}

#[test]
fn a_rational_bezier_curve_derivative_is_the_quotient_rule() {
    // the quarter circle ((1 - t^2), 2t)/(1 + t^2): c' = (-4t, 2 - 2t^2)/(1 + t^2)^2
    let a = solve(&json!({"op": "derivative", "curve": {"bezier": [[1, 0], [1, 1], [0, 1]], "weights": [1, 1, 2]}, "order": 1})).unwrap();
    assert_eq!(
        a.get("closed_form").unwrap().to_json(),
        json!("(-4*t, -2*t^2 + 2)/(t^4 + 2*t^2 + 1)")
    );
}

#[test]
fn two_quarter_circles_meet_c1_and_g2() {
    let a = solve(&json!({"op": "curve_continuity",
        "first": {"bezier": [[1, 0], [1, 1], [0, 1]], "weights": [1, "sqrt2/2", 1]},
        "second": {"bezier": [[0, 1], [-1, 1], [-1, 0]], "weights": [1, "sqrt2/2", 1]}}))
    .unwrap();
    assert_eq!(a.get("order").unwrap().to_json(), json!(1));
    assert_eq!(a.get("geometric").unwrap().to_json(), json!(2));
    assert_eq!(a.get("alpha").unwrap().to_json(), json!("1"));
    assert_eq!(a.get("beta").unwrap().to_json(), json!("4 - 2*sqrt2"));
}

#[test]
fn curve_joins_c0_g1_cusp_and_one_polynomial() {
    let first = json!({"bezier": [[0, 0], [1, 1], [2, 1]]});
    let join = |second: Value| {
        let a =
            solve(&json!({"op": "curve_continuity", "first": first, "second": second})).unwrap();
        (
            a.get("order").unwrap().to_json(),
            a.get("geometric").unwrap().to_json(),
        )
    };
    // tangents (2, 0) and (4, 0): G^1 with α = 2, but c_2'' - 4 c_1'' = (-2, 6) is not along
    // the tangent: not G^2
    assert_eq!(
        join(json!({"bezier": [[2, 1], [4, 1], [5, 0]]})),
        (json!(0), json!(1))
    );
    // the same parabola continued: one polynomial
    assert_eq!(
        join(json!({"bezier": [[2, 1], [3, 1], [4, 0]]})),
        (json!("infinite"), json!(2))
    );
    // opposite tangents: a cusp
    assert_eq!(
        join(json!({"bezier": [[2, 1], [1, 1], [5, 0]]})),
        (json!(0), json!(0))
    );
    // apart
    assert_eq!(
        join(json!({"bezier": [[3, 1], [4, 1]]})),
        (json!(-1), json!(-1))
    );
    // a B-spline's last piece against a Bézier curve: C^1 (the pieces are (2t, 4t - 2t^2) near
    // t = 2, and the second curve continues the tangent with another curvature)
    let a = solve(&json!({"op": "curve_continuity",
        "first": {"bspline": [[0, 0], [1, 2], [3, 2], [4, 0]], "degree": 2, "knots": [0, 0, 1, 2, 2]},
        "second": {"bezier": [[4, 0], [5, -2], [7, -5]]}}))
    .unwrap();
    assert_eq!(a.get("order").unwrap().to_json(), json!(1));
    assert_eq!(a.get("geometric").unwrap().to_json(), json!(1));
}

/// The points of a curve or surface answer evaluated at `params`.
fn points_of(shape: &str, answer: &Value, params: Value) -> Vec<Point<Number>> {
    let a = solve(&json!({"op": "evaluate", shape: answer, "params": params})).unwrap();
    let Some(Exact::Points(p)) = a.get("points") else {
        panic!("no points")
    };
    p.clone()
}

// --- the continuity of two separate B-spline or NURBS surfaces ---

/// The surface cut in two at its first interior knot in u, ξ: ξ inserted up to multiplicity p
/// (`insert_knot`), then the mesh's rows split at the row the two halves share (with ξ at
/// knots[j..j+p], the first half is rows 0..=j on knots[..j+p], the second rows j.. on
/// knots[j..], in the notes' convention).
fn halves(s: &Spline, rational: bool) -> Option<(i64, Value, Value)> {
    let mut ku = s.ku.clone();
    ku.dedup();
    let xi = *ku.get(1).filter(|x| **x != *ku.last().unwrap())?;
    let mu = s.ku.iter().filter(|k| **k == xi).count();
    let mut surface = s.json(rational);
    if mu < s.p {
        let a = solve(&json!({"op": "insert_knot", "surface": surface, "knot": xi, "times": s.p - mu, "direction": "u"})).unwrap();
        surface = a.get("surface").unwrap().to_json();
    }
    let knots_u: Vec<Value> = surface["knots"][0].as_array().unwrap().clone();
    let text = |k: &Value| k.as_str().map_or_else(|| k.to_string(), String::from);
    let j = knots_u
        .iter()
        .position(|k| text(k) == xi.to_string())
        .unwrap();
    let rows = surface["bspline"].as_array().unwrap().clone();
    let half = |r: std::ops::Range<usize>, k: Vec<Value>| {
        let mut h = surface.clone();
        h["bspline"] = json!(rows[r.clone()]);
        h["knots"][0] = json!(k);
        if rational {
            h["weights"] = json!(surface["weights"].as_array().unwrap()[r]);
        }
        h
    };
    let first = half(0..j + 1, knots_u[..j + s.p].to_vec());
    let second = half(j..rows.len(), knots_u[j..].to_vec());
    Some((xi, first, second))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 16, ..ProptestConfig::default() })]

    /// Two B-spline (NURBS) surfaces cut from one at a knot line u = ξ join with the order the
    /// one surface has across that line; inserting a knot in v into the second (the same
    /// surface, more pieces along the border) changes no order.
    #[test]
    fn the_halves_of_a_surface_join_as_its_knot_line(s in spline(), rational in any::<bool>(), refine in any::<bool>()) {
        let Some((xi, first, mut second)) = halves(&s, rational) else { return Ok(()) };
        let whole = solve(&json!({"op": "continuity", "surface": s.json(rational)})).unwrap();
        let Some(Exact::List(lines)) = whole.get("knot_lines") else { panic!("no knot lines") };
        let line = lines.iter().find_map(|l| {
            let Exact::Object(kv) = l else { return None };
            (field(kv, "direction").to_json() == json!("u") && field(kv, "knot").to_json() == json!(xi.to_string()))
                .then(|| field(kv, "order").to_json())
        }).unwrap();
        if refine {
            let (_, end) = s.domain_ends();
            let a = solve(&json!({"op": "insert_knot", "surface": second, "knot": format!("{end}/3"), "times": 1, "direction": "v"})).unwrap();
            second = a.get("surface").unwrap().to_json();
        }
        let join = solve(&json!({"op": "continuity", "first": first, "second": second})).unwrap();
        prop_assert_eq!(join.get("order").unwrap().to_json(), line);
        let Some(Exact::List(pieces)) = join.get("pieces") else { panic!("no pieces") };
        prop_assert!(!pieces.is_empty());
    }
}

#[test]
fn two_bspline_surfaces_along_a_border_v_and_the_refusals() {
    // c(u, v) on [0, 1] x [0, 2] with a C¹ knot at v = 1, cut at v = 1: the halves join C¹
    // along v, and the second moved from [5, 6] in v says so
    let first = json!({"bspline": [[[0, 0, 0], [0, 1, 1]], [[1, 0, 0], [1, 1, 2]]], "degree": [1, 1], "knots": [[0, 1], [0, 1]]});
    let second = json!({"bspline": [[[0, 1, 1], [0, 2, 0]], [[1, 1, 2], [1, 2, 0]]], "degree": [1, 1], "knots": [[0, 1], [5, 6]]});
    let a = solve(&json!({"op": "continuity", "first": first, "second": second, "border": "v"}))
        .unwrap();
    assert_eq!(a.get("order").unwrap().to_json(), json!(0));
    assert_eq!(
        a.get("pieces").unwrap().to_json(),
        json!([{"u": ["0", "1"], "order": 0}])
    );
    assert!(
        a.remarks
            .iter()
            .any(|r| r.to_string().contains("moved by -4 along v")),
        "{:?}",
        a.remarks
    );
    // different intervals along the border
    let other = json!({"bspline": [[[0, 1, 1], [0, 2, 0]], [[1, 1, 2], [1, 2, 0]]], "degree": [1, 1], "knots": [[0, 2], [1, 2]]});
    let e = solve(&json!({"op": "continuity", "first": first, "second": other, "border": "v"}))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("the borders run over different u intervals"),
        "{e}"
    );
    let e = solve(&json!({"op": "continuity", "first": first, "second": second, "border": "v", "lengths": [1, 2]})).unwrap_err().to_string();
    assert!(e.contains("leave out `lengths`"), "{e}");
}

// --- subdivision and knot removal of B-spline and NURBS surfaces ---

proptest! {
    #![proptest_config(ProptestConfig { cases: 16, ..ProptestConfig::default() })]

    /// Subdividing a B-spline (NURBS) surface at (u, v) gives four surfaces that evaluate, each
    /// on its rectangle, equal to the surface; inserting a knot in a direction and removing it
    /// again gives the surface back.
    #[test]
    fn subdivision_and_knot_removal_reproduce_the_surface(
        s in spline(), rational in any::<bool>(), a in 1i64..=4, b in 1i64..=4, in_v in any::<bool>(),
    ) {
        let (eu, ev) = s.domain_ends();
        // the split point: a/5 and b/5 of the domain
        let (x, y) = (q(a * eu, 5), q(b * ev, 5));
        let text = |r: &BigRational| r.to_string();
        let parts = solve(&json!({"op": "subdivide", "surface": s.json(rational), "u": text(&x), "v": text(&y)})).unwrap();
        let Some(Exact::List(list)) = parts.get("surfaces") else { panic!("no surfaces") };
        prop_assert_eq!(list.len(), 4);
        let rects = [
            (q(0, 1), x.clone(), q(0, 1), y.clone()),
            (q(0, 1), x.clone(), y.clone(), q(ev, 1)),
            (x.clone(), q(eu, 1), q(0, 1), y.clone()),
            (x.clone(), q(eu, 1), y.clone(), q(ev, 1)),
        ];
        for (part, (u0, u1, v0, v1)) in list.iter().zip(&rects) {
            // two points inside the rectangle, at 1/3 and 3/4 of it
            let at = |t: &BigRational, lo: &BigRational, hi: &BigRational| lo + (hi - lo) * t;
            let params: Vec<Value> = [(q(1, 3), q(1, 3)), (q(3, 4), q(1, 4))]
                .iter()
                .map(|(su, sv)| json!([text(&at(su, u0, u1)), text(&at(sv, v0, v1))]))
                .collect();
            prop_assert_eq!(
                points_of("surface", &part.to_json(), json!(params.clone())),
                points_of("surface", &s.json(rational), json!(params))
            );
        }
        // a knot inserted and removed again
        let (dir, end) = if in_v { ("v", ev) } else { ("u", eu) };
        let knot = q(a * end, 5).to_string();
        let ins = solve(&json!({"op": "insert_knot", "surface": s.json(rational), "knot": knot, "times": 1, "direction": dir})).unwrap();
        let back = solve(&json!({"op": "remove_knot", "surface": ins.get("surface").unwrap().to_json(), "knot": knot, "direction": dir})).unwrap();
        let params = json!([["1/3", "1/2"], [format!("{eu}/2"), format!("{ev}/3")]]);
        let back = back.get("surface").unwrap().to_json();
        prop_assert_eq!(&back["knots"], &s.json(false)["knots"].as_array().unwrap().iter().map(|k| json!(k.as_array().unwrap().iter().map(|x| json!(x.to_string())).collect::<Vec<_>>())).collect::<Value>());
        prop_assert_eq!(points_of("surface", &back, params.clone()), points_of("surface", &s.json(rational), params));
    }
}

#[test]
fn an_essential_knot_of_a_surface_is_refused_naming_the_column() {
    // z = 0, 0, 1 on the columns: the knot 1 of multiplicity 1 (C⁰ for degree 1) is essential
    let s = json!({"bspline": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]], [[2, 0, 0], [2, 1, 0]]], "degree": [1, 1], "knots": [[0, 1, 2], [0, 1]]});
    let e = solve(&json!({"op": "remove_knot", "surface": s, "knot": 1}))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("in u, on column 1 of the mesh: knot 1 cannot be removed"),
        "{e}"
    );
    // column 0 is a line in u: removing the knot from it alone would be exact
    let e = solve(&json!({"op": "subdivide", "surface": s, "u": 2}))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("2 is not strictly inside the domain [0, 2] of the surface in u"),
        "{e}"
    );
}
