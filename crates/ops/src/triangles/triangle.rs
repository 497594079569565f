//! Triangular Bézier patches (crate cagd-triangle) through the problem format: evaluation by
//! De Casteljau, closed form, degree elevation, directional derivatives, blossom, subdivision
//! at a point and the boundary curves; restriction to a sub-triangle, iso-lines, relabelled
//! vertices, the graph of a function over a triangle, exact degree reduction and the Gaussian
//! curvature's numerator; rational patches (`weights`) on their homogeneous net. A patch is `{"triangle": [[b_{n,0,0}], ...]}`
//! (`crate::triangle`); a point of its domain is [u, v] in the triangle (0, 0), (1, 0), (0, 1)
//! (r = 1 - u - v, s = u, t = v) or barycentric [r, s, t].

use crate::explain;
use crate::message::fitting::Fitting;
use crate::out::{at, num, pair, req, Out, Run};
use crate::problem::{
    Blossom, Boundary, ClosedForm, Derivative, Elevate, Evaluate, GaussianCurvature, Graph,
    Isocurve, Normal, Param, ReduceDegree, Restrict, Reverse, Subdivide,
};
use crate::spec::{Num, Orders};
use crate::steps::{Fact, Formula};
use crate::triangle::{exact_triangle, TriangleIn};
use crate::value::quantity::{Border, Corner, Quantity};
use crate::value::{exact_map, exact_points, Exact, ExactScalar};
use crate::ProblemError;
use cagd_bezier::BezierCurve;
use cagd_linalg::Point;
use cagd_poly::{Poly, Var, VecPoly};
use cagd_triangle::{multi_indices, Barycentric, Direction, Edge, TriangularPatch};

const TF: &str = "triangle";

/// A triangular patch of the problem: polynomial, or rational as its homogeneous net
/// (w b, w) (`rational`).
struct Tri<S: ExactScalar> {
    patch: TriangularPatch<S>,
    rational: bool,
}

fn read_any<S: ExactScalar>(t: &Option<TriangleIn>) -> Result<Tri<S>, ProblemError> {
    let (patch, rational) = req(t, TF)?.patch::<S>(TF)?;
    Ok(Tri { patch, rational })
}

/// A polynomial triangular patch; `what` is refused for a rational one, with the reason.
fn read<S: ExactScalar>(
    t: &Option<TriangleIn>,
    what: &str,
) -> Result<TriangularPatch<S>, ProblemError> {
    let tri = read_any::<S>(t)?;
    if tri.rational {
        return Err(ProblemError::at(
            format!("{TF}.weights"),
            Fitting::RationalHasNo {
                what: what.to_string(),
            },
        ));
    }
    Ok(tri.patch)
}

impl<S: ExactScalar> Tri<S> {
    /// A point of the patch from a point of its net (homogeneous when rational): w b / w.
    fn project(&self, p: &Point<S>, path: &str) -> Result<Point<S>, ProblemError> {
        if !self.rational {
            return Ok(p.clone());
        }
        let (w, xs) = p
            .coords()
            .split_last()
            .ok_or_else(|| ProblemError::at(path, Fitting::HomogeneousWithoutCoordinates))?;
        xs.iter()
            .map(|x| {
                x.checked_div(w)
                    .ok_or_else(|| ProblemError::at(path, Fitting::WeightZeroHere))
            })
            .collect::<Result<Vec<_>, _>>()
            .map(Point::new)
    }

    /// The net `patch` (homogeneous when rational) in the answer's shape:
    /// `{"triangle": rows}`, with `"weights": rows` for a rational patch.
    fn exact(&self, patch: &TriangularPatch<S>, path: &str) -> Result<Exact, ProblemError> {
        if !self.rational {
            return Ok(exact_triangle(patch));
        }
        let points = patch
            .points()
            .iter()
            .map(|p| self.project(p, path))
            .collect::<Result<Vec<_>, _>>()?;
        let weights: Vec<S> = patch
            .points()
            .iter()
            .map(|p| p.coords().last().cloned().unwrap_or_else(S::zero))
            .collect();
        let net = TriangularPatch::try_new(patch.degree(), points).map_err(at(path))?;
        let Exact::Object(mut kv) = exact_triangle(&net) else {
            return Ok(exact_triangle(&net));
        };
        let mut rows = Vec::with_capacity(patch.degree() + 1);
        let mut start = 0;
        for m in 0..=patch.degree() {
            let row = weights.get(start..start + m + 1).unwrap_or_default();
            rows.push(row.iter().map(crate::value::exact).collect());
            start += m + 1;
        }
        kv.push((Quantity::Weights, crate::triangle::weight_rows(&rows)));
        Ok(Exact::Object(kv))
    }

    /// The Bézier curve (rational when the patch is) with the control points `net` of the
    /// patch's kind.
    fn curve(&self, net: Vec<Point<S>>) -> Result<crate::any::AnyCurve<S>, ProblemError> {
        if !self.rational {
            return Ok(crate::any::AnyCurve::Bezier(
                BezierCurve::try_new(net).map_err(at(TF))?,
            ));
        }
        let points = net
            .iter()
            .map(|p| self.project(p, TF))
            .collect::<Result<Vec<_>, _>>()?;
        let weights = net
            .iter()
            .map(|p| p.coords().last().cloned().unwrap_or_else(S::zero))
            .collect();
        Ok(crate::any::AnyCurve::RationalBezier(
            cagd_bezier::RationalBezierCurve::try_new(points, weights).map_err(at(TF))?,
        ))
    }

    /// Records that the net is rational: the algorithms run on the homogeneous points.
    fn explain(&self, out: &mut Out) {
        if self.rational {
            out.formula(Formula::RationalTriangle);
        }
    }
}

/// A point of the domain triangle: [u, v], or barycentric [r, s, t] (r + s + t = 1).
fn point_of<S: ExactScalar>(p: &Param, path: &str) -> Result<Barycentric<S>, ProblemError> {
    match p {
        Param::Many(xs) => match xs.as_slice() {
            [u, v] => Ok(Barycentric::from_uv(num::<S>(u, path)?, num::<S>(v, path)?)),
            [r, s, t] => {
                Barycentric::try_new(num::<S>(r, path)?, num::<S>(s, path)?, num::<S>(t, path)?)
                    .map_err(at(path))
            }
            _ => Err(ProblemError::at(
                path,
                Fitting::DomainPointList { len: xs.len() },
            )),
        },
        Param::One(_) => Err(ProblemError::at(path, Fitting::DomainPointNumber)),
    }
}

/// Remarks a point where the patch is evaluated that lies outside the domain triangle (a
/// negative barycentric coordinate), as a curve refuses a parameter outside its domain: the
/// value there is the polynomial's, extended. `restrict` and `blossom` take such points
/// without a remark: their constructions reach outside the triangle by design.
fn say_if_outside<S: ExactScalar>(out: &mut Out, path: &str, x: &Barycentric<S>) {
    if let Some((k, value)) = x.first_negative() {
        let coordinate = ["r = 1 - u - v", "s = u", "t = v"].get(k).copied();
        out.remark(Fitting::OutsideTriangle {
            path: path.to_string(),
            point: x.to_text(),
            coordinate: coordinate.unwrap_or_default().to_string(),
            value: value.to_text(),
        });
    }
}

/// The De Casteljau levels 1, ..., n as values b_{i,j,k}^l.
fn explain_levels<S: ExactScalar>(out: &mut Out, n: usize, levels: &[Vec<Point<S>>]) {
    for (l, level) in levels.iter().enumerate().skip(1) {
        for ((i, j, k), p) in multi_indices(n - l).zip(level) {
            out.value(format!("b_{{{i},{j},{k}}}^{{{l}}}"), explain::point(p));
        }
    }
}

/// `evaluate` a triangular patch at `params`: De Casteljau on the net (with its levels as
/// steps), b(x) = b^n_{0,0,0}(x).
pub(crate) fn evaluate<S: ExactScalar>(a: &Evaluate, run: Run<'_>) -> Result<Out, ProblemError> {
    let tri = read_any::<S>(&a.triangle)?;
    let patch = &tri.patch;
    let params = req(&a.params, "params")?;
    let mut out = run.out();
    out.formula(Formula::DeCasteljauTriangle);
    tri.explain(&mut out);
    let mut points = Vec::with_capacity(params.0.len());
    for (i, p) in params.0.iter().enumerate() {
        let path = format!("params[{i}]");
        let x = point_of::<S>(p, &path)?;
        say_if_outside(&mut out, &path, &x);
        let worked = explain::worked(&out, i, explain::WORKED_POINTS);
        let value = if worked {
            out.fact(Fact::At {
                params: x.coords().iter().map(explain::number).collect(),
            });
            let dc = patch.de_casteljau(&x);
            explain_levels(&mut out, patch.degree(), dc.levels());
            dc.into_value()
        } else {
            patch.evaluate(&x)
        };
        let value = tri.project(&value, &path)?;
        if worked {
            out.value("b(r, s, t)", explain::point(&value));
        }
        points.push(value);
    }
    explain::same_for_the_others(&mut out, points.len(), explain::WORKED_POINTS);
    Ok(out.result(Quantity::Points, Exact::Points(exact_points(&points))))
}

/// `closed_form` of a triangular patch: b(u, v) = Σ b_{ijk} n!/(i! j! k!) (1 - u - v)^i u^j v^k.
pub(crate) fn closed_form<S: ExactScalar>(
    a: &ClosedForm,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let tri = read_any::<S>(&a.triangle)?;
    let mut out = run.out();
    out.formula(Formula::BernsteinTriangle);
    tri.explain(&mut out);
    let h = tri.patch.closed_form();
    if !tri.rational {
        return Ok(out.closed_form(Exact::Map(exact_map(&h))));
    }
    let q = cagd_poly::RationalMap::from_homogeneous(&h).map_err(at(TF))?;
    Ok(out.closed_form(Exact::Rational(crate::value::exact_rational(&q))))
}

/// `elevate` a triangular patch by `by` = r: r elevations by one,
/// b^{(1)}_{ijk} = (i b_{i-1,j,k} + j b_{i,j-1,k} + k b_{i,j,k-1})/(n + 1).
pub(crate) fn elevate<S: ExactScalar>(a: &Elevate, run: Run<'_>) -> Result<Out, ProblemError> {
    let tri = read_any::<S>(&a.triangle)?;
    let patch = tri.patch.clone();
    let r = match req(&a.by, "by")? {
        Orders::One(r) => r.get(),
        Orders::Two(..) => return Err(ProblemError::at("by", Fitting::OneDegreeBy)),
    };
    let n = patch.degree();
    let to = n.saturating_add(r);
    run.check_degree(
        "by",
        to,
        crate::message::limited::Limited::ElevatingDegree { from: n, by: r },
    )?;
    run.check_points(
        "by",
        cagd_triangle::control_point_count(to).unwrap_or(usize::MAX),
        Fitting::ElevatedPatch,
    )?;
    let mut out = run.out();
    out.formula(Formula::ElevateTriangle);
    tri.explain(&mut out);
    let mut p = patch;
    for _ in 0..r {
        let next = p.elevate_degree();
        out.fact(Fact::Degree {
            from: p.degree(),
            to: next.degree(),
        });
        p = next;
    }
    Ok(out.result(Quantity::Triangle, tri.exact(&p, "by")?))
}

/// `derivative` of a triangular patch along `direction` = [du, dv] (default [1, 0], ∂/∂u),
/// `order` times (default 1): D_d b = n Σ (d_1 b_{i+1,j,k} + d_2 b_{i,j+1,k} + d_3 b_{i,j,k+1})
/// B^{n-1}_{ijk}, d = (-du - dv, du, dv); a patch of degree n - r, and its closed form.
pub(crate) fn derivative<S: ExactScalar>(
    a: &Derivative,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let patch = read::<S>(&a.triangle, "derivative")?;
    if a.at.is_some() {
        return Err(ProblemError::at("at", Fitting::AtTensor));
    }
    let r = match &a.order {
        None => 1,
        Some(Orders::One(r)) => run.degree("order", *r)?,
        Some(Orders::Two(..)) => return Err(ProblemError::at("order", Fitting::OneDirection)),
    };
    let (du, dv) = match &a.direction {
        Some(d) => pair::<S>(d, "direction")?,
        None => (S::one(), S::zero()),
    };
    let d = Direction::from_uv(du, dv);
    let mut out = run.out();
    out.formula(Formula::DerivativeTriangle);
    if out.steps_on() {
        out.value(
            "d",
            Exact::Point(crate::value::exact_point(&Point::new(d.coords().to_vec()))),
        );
    }
    let mut p = patch;
    for _ in 0..r {
        p = p.derivative(&d);
    }
    Ok(out
        .result(Quantity::Triangle, exact_triangle(&p))
        .closed_form(Exact::Map(exact_map(&p.closed_form()))))
}

/// `blossom` of a triangular patch at the n points `params`: De Casteljau with x_l at level l
/// (symmetric, affine in each argument, b[x, ..., x] = b(x)).
pub(crate) fn blossom<S: ExactScalar>(a: &Blossom, run: Run<'_>) -> Result<Out, ProblemError> {
    let tri = read_any::<S>(&a.triangle)?;
    let patch = &tri.patch;
    let params = req(&a.params, "params")?;
    let args = params
        .0
        .iter()
        .enumerate()
        .map(|(i, p)| point_of::<S>(p, &format!("params[{i}]")))
        .collect::<Result<Vec<_>, _>>()?;
    let mut out = run.out();
    out.formula(Formula::BlossomTriangle);
    tri.explain(&mut out);
    let value = if out.steps_on() {
        let mut levels = Vec::new();
        let value = patch
            .blossom_recorded(&args, &mut levels)
            .map_err(at("params"))?;
        explain_levels(&mut out, patch.degree(), &levels);
        value
    } else {
        patch.blossom(&args).map_err(at("params"))?
    };
    let value = tri.project(&value, "params")?;
    Ok(out.result(
        Quantity::Point,
        Exact::Point(crate::value::exact_point(&value)),
    ))
}

/// `subdivide` a triangular patch at the point (`u`, `v`) of its domain into the three patches
/// over (x, e2, e3), (e1, x, e3), (e1, e2, x): c_{ijk} = b^i_{0,j,k}(x), b^j_{i,0,k}(x),
/// b^k_{i,j,0}(x), the levels of De Casteljau at x.
pub(crate) fn subdivide<S: ExactScalar>(a: &Subdivide, run: Run<'_>) -> Result<Out, ProblemError> {
    let tri = read_any::<S>(&a.triangle)?;
    let patch = &tri.patch;
    if a.t.is_some() {
        return Err(ProblemError::at("t", Fitting::SplitAtPoint));
    }
    let u = num::<S>(req(&a.u, "u")?, "u")?;
    let v = num::<S>(req(&a.v, "v")?, "v")?;
    let x = Barycentric::from_uv(u, v);
    let mut out = run.out();
    out.formula(Formula::SubdivideTriangle);
    tri.explain(&mut out);
    if out.steps_on() {
        let dc = patch.de_casteljau(&x);
        explain_levels(&mut out, patch.degree(), dc.levels());
    }
    let parts = patch
        .split(&x)
        .iter()
        .map(|p| tri.exact(p, "u"))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(out.result(Quantity::Triangles, Exact::List(parts)))
}

/// `boundary` of a triangular patch: the Bézier curves over the edges t = 0 (v = 0, from
/// (0, 0) to (1, 0)), r = 0 (u + v = 1, from (1, 0) to (0, 1)) and s = 0 (u = 0, from (0, 1) to
/// (0, 0)), whose control points are the net's points on that edge.
pub(crate) fn boundary<S: ExactScalar>(a: &Boundary, run: Run<'_>) -> Result<Out, ProblemError> {
    let tri = read_any::<S>(&a.triangle)?;
    let mut out = run.out();
    out.formula(Formula::BoundaryTriangle);
    tri.explain(&mut out);
    for (edge, border) in Edge::ALL.iter().zip([Border::V0, Border::Uv1, Border::U0]) {
        let curve = tri.curve(tri.patch.boundary_curve(*edge))?;
        out = out.result(Quantity::BoundaryCurve(border), curve.to_exact());
    }
    Ok(out)
}

/// `normal` of a triangular patch in R³: n = b_u × b_v (not normalized, so it stays exact), as a
/// closed form in (u, v) (the cross product of the derivative patches' closed forms, ∂/∂u along
/// d = (-1, 1, 0) and ∂/∂v along (-1, 0, 1)), and at the points `params` when given.
pub(crate) fn normal<S: ExactScalar>(a: &Normal, run: Run<'_>) -> Result<Out, ProblemError> {
    let patch = read::<S>(&a.triangle, "normal")?;
    if patch.dim() != 3 {
        return Err(ProblemError::at(
            TF,
            Fitting::NormalDimension { dim: patch.dim() },
        ));
    }
    let mut out = run.out();
    out.formula(Formula::DerivativeTriangle);
    out.formula(Formula::Normal);
    let bu = patch.derivative(&Direction::du()).closed_form();
    let bv = patch.derivative(&Direction::dv()).closed_form();
    if out.steps_on() {
        out.value("b_u", Exact::Map(exact_map(&bu)));
        out.value("b_v", Exact::Map(exact_map(&bv)));
    }
    let n = bu.cross(&bv).map_err(at(TF))?;
    out = out.closed_form(Exact::Map(exact_map(&n)));
    if let Some(params) = &a.params {
        let mut points = Vec::with_capacity(params.0.len());
        for (i, p) in params.0.iter().enumerate() {
            let path = format!("params[{i}]");
            let x = point_of::<S>(p, &path)?;
            say_if_outside(&mut out, &path, &x);
            points.push(patch.normal(&x).map_err(at(&path))?);
        }
        out = out.result(Quantity::Normals, Exact::Points(exact_points(&points)));
    }
    Ok(out)
}

/// A barycentric point as a value of the steps: (r, s, t).
fn exact_barycentric<S: ExactScalar>(x: &Barycentric<S>) -> Exact {
    explain::point(&Point::new(x.coords().to_vec()))
}

/// `restrict` a triangular patch to the sub-triangle with `vertices` a, b, c (points of the
/// domain, [u, v] or [r, s, t]; it may reach outside the domain), reparametrized so that the
/// vertices e1, e2, e3 of the new patch go to a, b, c: c_{ijk} = b[a^i, b^j, c^k] (the
/// blossom with a repeated i times, b j times, c k times), and c(ρ, σ, τ) = b(ρ a + σ b + τ c).
pub(crate) fn restrict<S: ExactScalar>(a: &Restrict, run: Run<'_>) -> Result<Out, ProblemError> {
    let tri = read_any::<S>(&a.triangle)?;
    let patch = &tri.patch;
    for (key, given) in [
        ("u", a.u.is_some()),
        ("v", a.v.is_some()),
        ("t", a.t.is_some()),
    ] {
        if given {
            return Err(ProblemError::at(key, Fitting::RestrictVertices));
        }
    }
    let vertices = req(&a.vertices, "vertices")?;
    let [va, vb, vc] = match vertices.0.as_slice() {
        [x, y, z] => [
            point_of::<S>(x, "vertices[0]")?,
            point_of::<S>(y, "vertices[1]")?,
            point_of::<S>(z, "vertices[2]")?,
        ],
        other => {
            return Err(ProblemError::at(
                "vertices",
                Fitting::SubTriangle { found: other.len() },
            ))
        }
    };
    let mut out = run.out();
    out.formula(Formula::RestrictTriangle);
    tri.explain(&mut out);
    let sub = patch.restrict(&va, &vb, &vc);
    if out.steps_on() {
        for (name, x) in [("a", &va), ("b", &vb), ("c", &vc)] {
            out.value(name, exact_barycentric(x));
        }
        for ((i, j, k), p) in multi_indices(sub.degree()).zip(sub.points()) {
            out.value(
                format!("c_{{{i},{j},{k}}} = b[a^{i}, b^{j}, c^{k}]"),
                explain::point(p),
            );
        }
    }
    Ok(out.result(Quantity::Triangle, tri.exact(&sub, "vertices")?))
}

/// The ends p, q (barycentric) of the iso-line `key` = x0 of the domain triangle: u = u0 from
/// (u0, 0) to (u0, 1 - u0), v = v0 from (0, v0) to (1 - v0, v0), w = 1 - u - v = w0 from
/// (1 - w0, 0) to (0, 1 - w0).
fn iso_segment<S: ExactScalar>(
    key: &str,
    x0: &S,
) -> Result<(Barycentric<S>, Barycentric<S>), ProblemError> {
    let rest = S::one() - x0;
    let (z, x) = (S::zero, || x0.clone());
    let (p, q) = match key {
        "u" => ((rest.clone(), x(), z()), (z(), x(), rest)),
        "v" => ((rest.clone(), z(), x()), (z(), rest, x())),
        _ => ((x(), rest.clone(), z()), (x(), z(), rest)),
    };
    let bary = |(r, s, t): (S, S, S)| Barycentric::try_new(r, s, t).map_err(at(key));
    Ok((bary(p)?, bary(q)?))
}

/// `isocurve` of a triangular patch: the iso-line u = u0 (or v = v0, or w = 1 - u - v = w0) of
/// the domain is the segment from p to q (`iso_segment`), and the patch over it is the Bézier
/// curve of degree n c(λ) = b((1 - λ) p + λ q), λ ∈ [0, 1], with the control points
/// c_l = b[p^{n-l}, q^l] (the blossom, p repeated n - l times and q l times).
pub(crate) fn isocurve<S: ExactScalar>(a: &Isocurve, run: Run<'_>) -> Result<Out, ProblemError> {
    if a.triangle.is_none() {
        return Err(ProblemError::at("w", Fitting::WNeedsTriangle));
    }
    let tri = read_any::<S>(&a.triangle)?;
    let patch = &tri.patch;
    let given: Vec<(&str, &Num)> = [("u", &a.u), ("v", &a.v), ("w", &a.w)]
        .into_iter()
        .filter_map(|(k, x)| x.as_ref().map(|x| (k, x)))
        .collect();
    let (key, x0) = match given.as_slice() {
        [(key, x)] => (*key, num::<S>(x, key)?),
        [] => return Err(ProblemError::at("u", Fitting::IsoMissing)),
        [_, (second, _), ..] => return Err(ProblemError::at(*second, Fitting::IsoTwo)),
    };
    let (p, q) = iso_segment(key, &x0)?;
    let points = patch.polar_segment(&p, &q);
    let mut out = run.out();
    out.formula(Formula::IsocurveTriangle);
    tri.explain(&mut out);
    if out.steps_on() {
        out.value("p", exact_barycentric(&p));
        out.value("q", exact_barycentric(&q));
        for (l, c) in points.iter().enumerate() {
            out.value(format!("c_{{{l}}}"), explain::point(c));
        }
    }
    let uv = |x: &Barycentric<S>| {
        let (u, v) = x.to_uv();
        Point::new(vec![u, v])
    };
    let curve = tri.curve(points)?;
    Ok(out.result(Quantity::Curve, curve.to_exact()).result(
        Quantity::Segment,
        Exact::Points(exact_points(&[uv(&p), uv(&q)])),
    ))
}

/// The permutation `order` of the vertices (default [1, 3, 2]), checked.
fn vertex_order(
    order: Option<&crate::spec::List<crate::spec::Int>>,
) -> Result<[usize; 3], ProblemError> {
    let Some(order) = order else {
        return Ok([1, 3, 2]);
    };
    let xs: Vec<u64> = order.0.iter().map(|n| n.0).collect();
    let mut sorted = xs.clone();
    sorted.sort_unstable();
    match (xs.as_slice(), sorted.as_slice()) {
        (&[a, b, c], [1, 2, 3]) => Ok([a, b, c].map(|m| usize::try_from(m).unwrap_or(1))),
        _ => Err(ProblemError::at(
            "order",
            Fitting::Permutation {
                found: format!("{xs:?}"),
            },
        )),
    }
}

/// `reverse` a triangular patch: its vertices relabelled, new vertex m the old vertex σ_m
/// (`order` = [σ1, σ2, σ3], default [1, 3, 2]). The control point c_{ijk} is the old point
/// whose index has i at place σ1, j at σ2 and k at σ3 (for [1, 3, 2]: c_{ijk} = b_{ikj}), and
/// c(x_1, x_2, x_3) = b(y) with y_{σm} = x_m: the same surface.
pub(crate) fn reverse<S: ExactScalar>(a: &Reverse, run: Run<'_>) -> Result<Out, ProblemError> {
    let tri = read_any::<S>(&a.triangle)?;
    let patch = &tri.patch;
    let order = vertex_order(a.order.as_ref())?;
    let relabelled = TriangularPatch::from_fn(patch.degree(), |(i, j, k)| {
        let mut old = [0; 3];
        for (&sigma, e) in order.iter().zip([i, j, k]) {
            if let Some(slot) = old.get_mut(sigma - 1) {
                *slot = e;
            }
        }
        let [oi, oj, ok] = old;
        patch
            .point(oi, oj, ok)
            .cloned()
            .unwrap_or_else(|_| Point::zero(patch.dim()))
    })
    .map_err(at(TF))?;
    let mut out = run.out();
    out.formula(Formula::ReverseTriangle);
    tri.explain(&mut out);
    if out.steps_on() {
        let sigma = order.map(|m| {
            <crate::value::Number as cagd_scalar::FieldOps>::from_i64(i64::try_from(m).unwrap_or(0))
        });
        out.value("σ", Exact::Point(Point::new(sigma.to_vec())));
    }
    Ok(out.result(Quantity::Triangle, tri.exact(&relabelled, "order")?))
}

/// `graph` of f(x, y) over the triangle `domain` = (A, B, C) of the (x, y) plane as a
/// triangular patch of degree n: with x(u, v) = A + u (B - A) + v (C - A), the patch is the
/// polynomial map (x(u, v), f(x(u, v))), whose control points are
/// b_{ijk} = ((i A + j B + k C)/n, f̂_{ijk}), f̂_{ijk} the Bernstein (blossom) coefficients of
/// f ∘ x of total degree ≤ n (for the triangle (0, 0), (1, 0), (0, 1): (j/n, k/n, f̂_{ijk})).
pub(crate) fn graph<S: ExactScalar>(a: &Graph, run: Run<'_>) -> Result<Out, ProblemError> {
    let f = req(&a.f, "f")?;
    let poly: Poly<S> = f.scalar().map_err(|e| ProblemError::at("f", e))?;
    let domain = req(&a.domain, "domain")?;
    let corners = crate::convert::convert_points::<S>(&domain.0, "domain")?;
    let [ca, cb, cc] = match corners.as_slice() {
        [x, y, z] if [x, y, z].iter().all(|p| p.dim() == 2) => [x, y, z],
        _ => {
            return Err(ProblemError::at(
                "domain",
                Fitting::TriangleDomain {
                    found: corners.len(),
                    dims: format!("{:?}", corners.iter().map(Point::dim).collect::<Vec<_>>()),
                },
            ))
        }
    };
    let coord = |p: &Point<S>, c: usize| p.coords().get(c).cloned().unwrap_or_else(S::zero);
    // x(u, v) = A + u (B - A) + v (C - A), coordinate by coordinate
    let affine: Vec<Poly<S>> = (0..2)
        .map(|c| {
            Poly::constant(coord(ca, c))
                + Poly::var(Var::U).scale(&(coord(cb, c) - coord(ca, c)))
                + Poly::var(Var::V).scale(&(coord(cc, c) - coord(ca, c)))
        })
        .collect();
    let (e1, e2) = (
        (coord(cb, 0) - coord(ca, 0), coord(cb, 1) - coord(ca, 1)),
        (coord(cc, 0) - coord(ca, 0), coord(cc, 1) - coord(ca, 1)),
    );
    if (e1.0 * &e2.1 - e1.1 * &e2.0).is_zero() {
        return Err(ProblemError::at("domain", Fitting::Collinear));
    }
    let [x, y] = [0, 1].map(|c| affine.get(c).cloned().unwrap_or_else(Poly::zero));
    // the notes write f(x, y); u and v are read as x and y, as for the tensor-product graph
    let height = poly
        .substitute(Var::U, &Poly::var(Var::X))
        .substitute(Var::V, &Poly::var(Var::Y))
        .substitute(Var::X, &x)
        .substitute(Var::Y, &y);
    let found = usize::try_from(height.degree()).unwrap_or(usize::MAX);
    let n = match &a.degree {
        None => found.max(1),
        Some(Orders::One(n)) => run.degree("degree", *n)?,
        Some(Orders::Two(..)) => return Err(ProblemError::at("degree", Fitting::OneDegreeN)),
    };
    if found > n {
        return Err(ProblemError::at(
            "degree",
            Fitting::GraphDegree { found, n },
        ));
    }
    run.check_points(
        "degree",
        cagd_triangle::control_point_count(n).unwrap_or(usize::MAX),
        Fitting::GraphOfDegree { n },
    )?;
    let map = VecPoly::new(vec![x, y, height]);
    let patch = TriangularPatch::from_closed_form(&map, n).map_err(at("f"))?;
    let mut out = run.out();
    out.formula(Formula::GraphTriangle);
    if out.steps_on() {
        for ((i, j, k), p) in patch.indexed_points() {
            let z = p.coords().last().cloned().unwrap_or_else(S::zero);
            out.value(format!("\\hat{{f}}_{{{i},{j},{k}}}"), explain::number(&z));
        }
    }
    Ok(out
        .result(Quantity::Triangle, exact_triangle(&patch))
        .closed_form(Exact::Map(exact_map(&map))))
}

/// `reduce_degree` of a triangular patch of degree n by `by` = r (default 1), exactly or not
/// at all: when its closed form (the homogeneous one for a rational patch) has total degree
/// ≤ n - r, the patch is of degree n - r and its net is the Bernstein coefficients of that
/// degree (`TriangularPatch::from_closed_form`, the inverse of r elevations); otherwise no
/// patch of degree n - r is the same surface, and the reduction is refused with the degree
/// found (a least-squares reduction of triangular nets is not available).
pub(crate) fn reduce_degree<S: ExactScalar>(
    a: &ReduceDegree,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let tri = read_any::<S>(&a.triangle)?;
    let n = tri.patch.degree();
    let r = match a.by {
        Some(by) => run.degree("by", by)?,
        None => 1,
    };
    let to = n
        .checked_sub(r)
        .ok_or_else(|| ProblemError::at("by", Fitting::PatchCannotReduce { n, r }))?;
    let h = tri.patch.closed_form();
    let found = usize::try_from(h.degree()).unwrap_or(usize::MAX);
    if found > to {
        return Err(ProblemError::at(
            "by",
            if tri.rational {
                Fitting::NoExactReductionRational { found, to }
            } else {
                Fitting::NoExactReduction { found, to }
            },
        ));
    }
    let reduced = TriangularPatch::from_closed_form(&h, to).map_err(at(TF))?;
    let mut out = run.out();
    out.formula(Formula::ReduceTriangle);
    tri.explain(&mut out);
    out.fact(Fact::Degree { from: n, to });
    Ok(out
        .result(Quantity::Triangle, tri.exact(&reduced, "by")?)
        .result(Quantity::IsExact, Exact::Bool(true)))
}

/// `gaussian_curvature` of a triangular patch in R³ (eq. (8)): the numerator G = L N - M² of
/// K (n = b_u × b_v, L = b_uu · n, M = b_uv · n, N = b_vv · n), computed on the closed form in
/// (u, v), a polynomial; for a rational patch on its homogeneous closed form,
/// G = det(P, P_u, P_v, P_uu) det(P, P_u, P_v, P_vv) - det(P, P_u, P_v, P_uv)² = w⁸ (L N - M²).
/// `developable` when G ≡ 0, and G at the vertices (0, 0), (1, 0), (0, 1).
pub(crate) fn gaussian_curvature<S: ExactScalar>(
    a: &GaussianCurvature,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let tri = read_any::<S>(&a.triangle)?;
    let h = tri.patch.closed_form();
    let form = if tri.rational {
        crate::pieces::PieceForm::Rational(
            cagd_poly::RationalMap::from_homogeneous(&h).map_err(at(TF))?,
        )
    } else {
        crate::pieces::PieceForm::Polynomial(h)
    };
    let g = crate::surfaces::curvature::numerator(&form, TF)?;
    let mut out = run.out();
    out.formula(Formula::BernsteinTriangle);
    tri.explain(&mut out);
    out.formula(Formula::Developable8);
    out.formula(Formula::GaussianNumerator);
    let mut corners = Vec::with_capacity(3);
    for corner in Corner::ALL.into_iter().take(3) {
        let (u, v) = (i64::from(corner.i), i64::from(corner.j));
        let x = g
            .eval(&[(Var::U, S::from_i64(u)), (Var::V, S::from_i64(v))])
            .map_err(at(TF))?;
        // G at the vertex (i, j), written `corner_ij` (docs/format.md)
        corners.push((Quantity::VertexNumerator(corner), explain::number(&x)));
    }
    if !g.is_zero() {
        out.remark(Fitting::SignOfK);
    }
    Ok(out
        .result(Quantity::Developable, Exact::Bool(g.is_zero()))
        .result(
            Quantity::GaussianNumerator,
            Exact::Poly(crate::value::exact_poly(&g)),
        )
        .result(Quantity::Corners, Exact::Object(corners)))
}
