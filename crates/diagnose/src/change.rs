//! The changes a mistake makes, on a problem's arguments (a curve reversed, a mesh
//! transposed) and on the key's values (a linear combination of the key's steps, a mesh
//! transposed, the weights dropped): each exact, each `None` where the value has another
//! shape.

use cagd_linalg::Point;
use cagd_problem::input::{CurveIn, SurfaceIn};
use cagd_problem::{Exact, Number};
use cagd_scalar::FieldOps;

/// The number `n`.
pub fn int(n: i64) -> Number {
    <Number as FieldOps>::from_i64(n)
}

/// `Σ c_k x_k` of points of one dimension.
fn combine_points(terms: &[(Number, &Point<Number>)]) -> Option<Point<Number>> {
    let (_, first) = terms.first()?;
    let mut out = Point::zero(first.dim());
    for (c, p) in terms {
        if p.dim() != out.dim() {
            return None;
        }
        out.add_scaled(p, c);
    }
    Some(out)
}

/// `Σ c_k x_k` of lists of points of one length.
fn combine_lists(terms: &[(Number, &[Point<Number>])]) -> Option<Vec<Point<Number>>> {
    let (_, first) = terms.first()?;
    (0..first.len())
        .map(|i| {
            let at: Option<Vec<(Number, &Point<Number>)>> = terms
                .iter()
                .map(|(c, ps)| ps.get(i).map(|p| (c.clone(), p)))
                .collect();
            combine_points(&at?)
        })
        .collect()
}

/// The linear combination `Σ c_k x_k` of values of one shape, entry by entry: points, lists
/// of points, Bézier polygons and meshes without weights, B-spline meshes of the same
/// degree and knots, and parametrizations. `None` for values of different shapes or with
/// weights (a combination of rational values is not one of their control points).
pub fn combine(terms: &[(Number, &Exact)]) -> Option<Exact> {
    let (_, first) = terms.first()?;
    match first {
        Exact::Point(_) => {
            let ps: Option<Vec<_>> = terms
                .iter()
                .map(|(c, x)| match x {
                    Exact::Point(p) => Some((c.clone(), p)),
                    _ => None,
                })
                .collect();
            combine_points(&ps?).map(Exact::Point)
        }
        Exact::Points(_) => {
            let ls: Option<Vec<_>> = terms
                .iter()
                .map(|(c, x)| match x {
                    Exact::Points(p) => Some((c.clone(), p.as_slice())),
                    _ => None,
                })
                .collect();
            combine_lists(&ls?).map(Exact::Points)
        }
        Exact::Curve(CurveIn::Bezier { weights: None, .. }) => {
            let ls: Option<Vec<_>> = terms
                .iter()
                .map(|(c, x)| match x {
                    Exact::Curve(CurveIn::Bezier {
                        points,
                        weights: None,
                    }) => Some((c.clone(), points.as_slice())),
                    _ => None,
                })
                .collect();
            combine_lists(&ls?).map(|points| {
                Exact::Curve(CurveIn::Bezier {
                    points,
                    weights: None,
                })
            })
        }
        Exact::Surface(SurfaceIn::Bezier { weights: None, .. })
        | Exact::Surface(SurfaceIn::BSpline { weights: None, .. }) => {
            let meshes: Option<Vec<_>> = terms
                .iter()
                .map(|(c, x)| match x {
                    Exact::Surface(s) if same_frame(first, x) => {
                        surface_mesh(s).map(|m| (c.clone(), m))
                    }
                    _ => None,
                })
                .collect();
            let meshes = meshes?;
            let (_, m0) = meshes.first()?;
            let mut bad = false;
            let mesh = cagd_surface::Grid::from_fn(m0.rows(), m0.cols(), |i, j| {
                let at: Option<Vec<_>> = meshes
                    .iter()
                    .map(|(c, m)| m.get(i, j).map(|p| (c.clone(), p)))
                    .collect();
                at.and_then(|at| combine_points(&at)).unwrap_or_else(|| {
                    bad = true;
                    Point::zero(0)
                })
            });
            if bad {
                return None;
            }
            let Exact::Surface(s) = first else {
                return None;
            };
            Some(Exact::Surface(with_mesh(s, mesh)))
        }
        Exact::Map(_) | Exact::Surface(SurfaceIn::Expr(_)) | Exact::Curve(CurveIn::Expr(_)) => {
            let mut sum: Option<cagd_poly::VecPoly<Number>> = None;
            for (c, x) in terms {
                let m = match x {
                    Exact::Map(m)
                    | Exact::Surface(SurfaceIn::Expr(m))
                    | Exact::Curve(CurveIn::Expr(m)) => m.scale(c),
                    _ => return None,
                };
                sum = Some(match sum {
                    None => m,
                    Some(s) => s.checked_add(&m).ok()?,
                });
            }
            let sum = sum?;
            Some(match first {
                Exact::Surface(_) => Exact::Surface(SurfaceIn::Expr(sum)),
                Exact::Curve(_) => Exact::Curve(CurveIn::Expr(sum)),
                _ => Exact::Map(sum),
            })
        }
        _ => None,
    }
}

/// Whether two surfaces have the same kind, degree and knots (their meshes combine).
fn same_frame(a: &Exact, b: &Exact) -> bool {
    match (a, b) {
        (
            Exact::Surface(SurfaceIn::Bezier {
                mesh: m,
                weights: None,
            }),
            Exact::Surface(SurfaceIn::Bezier {
                mesh: n,
                weights: None,
            }),
        ) => (m.rows(), m.cols()) == (n.rows(), n.cols()),
        (
            Exact::Surface(SurfaceIn::BSpline {
                mesh: m,
                degree: d,
                knots: k,
                weights: None,
            }),
            Exact::Surface(SurfaceIn::BSpline {
                mesh: n,
                degree: e,
                knots: l,
                weights: None,
            }),
        ) => d == e && k == l && (m.rows(), m.cols()) == (n.rows(), n.cols()),
        _ => false,
    }
}

/// A surface's control mesh (none for a parametrization).
pub fn surface_mesh(s: &SurfaceIn<Number>) -> Option<&cagd_surface::Mesh<Number>> {
    match s {
        SurfaceIn::Bezier { mesh, .. } | SurfaceIn::BSpline { mesh, .. } => Some(mesh),
        SurfaceIn::Expr(_) => None,
    }
}

/// The surface with its mesh replaced (same kind, degree, knots and weights).
pub fn with_mesh(s: &SurfaceIn<Number>, mesh: cagd_surface::Mesh<Number>) -> SurfaceIn<Number> {
    match s {
        SurfaceIn::Bezier { weights, .. } => SurfaceIn::Bezier {
            mesh,
            weights: weights.clone(),
        },
        SurfaceIn::BSpline {
            degree,
            knots,
            weights,
            ..
        } => SurfaceIn::BSpline {
            mesh,
            degree: *degree,
            knots: knots.clone(),
            weights: weights.clone(),
        },
        SurfaceIn::Expr(m) => SurfaceIn::Expr(m.clone()),
    }
}

/// The surface with rows and columns swapped (u and v exchanged): its mesh and weights
/// transposed, its degrees and knot vectors exchanged. `None` for a parametrization.
pub fn transpose_surface(s: &SurfaceIn<Number>) -> Option<SurfaceIn<Number>> {
    Some(match s {
        SurfaceIn::Bezier { mesh, weights } => SurfaceIn::Bezier {
            mesh: mesh.transpose(),
            weights: weights.as_ref().map(cagd_surface::Grid::transpose),
        },
        SurfaceIn::BSpline {
            mesh,
            degree,
            knots,
            weights,
        } => SurfaceIn::BSpline {
            mesh: mesh.transpose(),
            degree: (degree.1, degree.0),
            knots: (knots.1.clone(), knots.0.clone()),
            weights: weights.as_ref().map(cagd_surface::Grid::transpose),
        },
        SurfaceIn::Expr(_) => return None,
    })
}

/// A value with rows and columns swapped: a surface ([`transpose_surface`]) or a matrix.
pub fn transpose(x: &Exact) -> Option<Exact> {
    match x {
        Exact::Surface(s) => transpose_surface(s).map(Exact::Surface),
        Exact::Matrix(rows) => {
            let cols = rows.first().map_or(0, Vec::len);
            let t: Option<Vec<Vec<Number>>> = (0..cols)
                .map(|j| rows.iter().map(|r| r.get(j).cloned()).collect())
                .collect();
            t.map(Exact::Matrix)
        }
        _ => None,
    }
}

/// A Bézier curve's polygon (and weights) in reverse order: the curve c(1 − t). `None` for
/// a B-spline (its knots would be reflected too) or a parametrization.
pub fn reverse_curve(c: &CurveIn<Number>) -> Option<CurveIn<Number>> {
    match c {
        CurveIn::Bezier { points, weights } => Some(CurveIn::Bezier {
            points: points.iter().rev().cloned().collect(),
            weights: weights.as_ref().map(|w| w.iter().rev().cloned().collect()),
        }),
        _ => None,
    }
}

/// A value in reverse order: a Bézier curve ([`reverse_curve`]) or a list of points.
pub fn reverse(x: &Exact) -> Option<Exact> {
    match x {
        Exact::Curve(c) => reverse_curve(c).map(Exact::Curve),
        Exact::Points(ps) => Some(Exact::Points(ps.iter().rev().cloned().collect())),
        _ => None,
    }
}

/// A rational value written without its weights (the points kept): `None` for a value
/// without weights.
pub fn drop_weights(x: &Exact) -> Option<Exact> {
    match x {
        Exact::Curve(CurveIn::Bezier {
            points,
            weights: Some(_),
        }) => Some(Exact::Curve(CurveIn::Bezier {
            points: points.clone(),
            weights: None,
        })),
        Exact::Curve(CurveIn::BSpline {
            points,
            degree,
            knots,
            weights: Some(_),
        }) => Some(Exact::Curve(CurveIn::BSpline {
            points: points.clone(),
            degree: *degree,
            knots: knots.clone(),
            weights: None,
        })),
        Exact::Surface(
            s @ (SurfaceIn::Bezier {
                weights: Some(_), ..
            }
            | SurfaceIn::BSpline {
                weights: Some(_), ..
            }),
        ) => {
            let mut s = s.clone();
            match &mut s {
                SurfaceIn::Bezier { weights, .. } | SurfaceIn::BSpline { weights, .. } => {
                    *weights = None;
                }
                SurfaceIn::Expr(_) => {}
            }
            Some(Exact::Surface(s))
        }
        _ => None,
    }
}

/// The binomial coefficient `C(n, k)` (0 for k > n), `None` past the machine integers.
pub fn binomial(n: usize, k: usize) -> Option<Number> {
    if k > n {
        return Some(int(0));
    }
    // C(n, k) = Π_{j=1}^{k} (n − k + j) / j, each partial product an integer
    let mut c: u128 = 1;
    for j in 1..=k {
        let top = u128::try_from(n - k + j).ok()?;
        c = c.checked_mul(top)? / u128::try_from(j).ok()?;
    }
    Some(int(i64::try_from(c).ok()?))
}

/// Two grids of one size combined entry by entry, `f(a_ij, b_ij)`; `None` for grids of
/// different sizes.
pub fn grid_zip<T: Clone, U: Clone>(
    a: &cagd_surface::Grid<T>,
    b: &cagd_surface::Grid<U>,
    f: impl Fn(&T, &U) -> T,
) -> Option<cagd_surface::Grid<T>> {
    if (a.rows(), a.cols()) != (b.rows(), b.cols()) {
        return None;
    }
    let rows = a
        .to_rows()
        .iter()
        .zip(b.to_rows())
        .map(|(ra, rb)| ra.iter().zip(&rb).map(|(x, y)| f(x, y)).collect())
        .collect();
    cagd_surface::Grid::from_rows(rows).ok()
}

/// A value times `c`: a number, point, list of points or parametrization, or a Bézier
/// polygon, a Bézier or B-spline mesh without weights (every control point times `c`,
/// [`combine`] of one term). `None` for a rational value (its control points times `c` are
/// not the value times `c`).
pub fn times(x: &Exact, c: &Number) -> Option<Exact> {
    Some(match x {
        Exact::Number(n) => Exact::Number(n.clone() * c.clone()),
        Exact::Point(p) => Exact::Point(p.scale(c)),
        Exact::Points(ps) => Exact::Points(ps.iter().map(|p| p.scale(c)).collect()),
        Exact::Map(m) => Exact::Map(m.scale(c)),
        _ => return combine(&[(c.clone(), x)]),
    })
}

/// The falling factorial `n!/(n − r)! = n (n − 1) ⋯ (n − r + 1)` (0 when r > n), the factor
/// of a derivative of order r of a Bézier curve of degree n.
pub fn falling(n: usize, r: usize) -> Option<i64> {
    if r > n {
        return Some(0);
    }
    (0..r).try_fold(1i64, |acc, k| acc.checked_mul(i64::try_from(n - k).ok()?))
}

/// The results of a changed problem that a written answer can be compared with, each under
/// the key's quantity of the same name (a closed form in other variables is still the
/// student's `closed_form`): those the key has with a value of the same entries (a mesh of
/// as many rows and columns, a list as long; entry by entry is how they are compared),
/// without the values with an entry a student's answer is read as only when it equals the
/// key's (sentences, texts, rational closed forms).
pub fn comparable(
    key: &[cagd_problem::Named],
    results: Vec<cagd_problem::Named>,
) -> Vec<cagd_problem::Named> {
    results
        .into_iter()
        .filter(|(_, x)| {
            x.entries().iter().all(|(_, e)| {
                !matches!(e, Exact::Sentence(_) | Exact::Text(_) | Exact::Rational(_))
            })
        })
        .filter_map(|(q, x)| {
            let name = q.name();
            key.iter()
                .find(|(k, y)| k.name() == name && same_entries(y, &x))
                .map(|(k, _)| (k.clone(), x))
        })
        .collect()
}

/// Whether two values are of one kind with the same entries ([`Exact::entries`]).
fn same_entries(a: &Exact, b: &Exact) -> bool {
    std::mem::discriminant(a) == std::mem::discriminant(b) && {
        let (ea, eb) = (a.entries(), b.entries());
        ea.len() == eb.len() && ea.iter().zip(&eb).all(|((x, _), (y, _))| x == y)
    }
}

/// A value translated by the vector `p`: every control point of a mesh or polygon moved by
/// `p` (weights, degrees and knots kept: the rational patch moves with them), a polynomial
/// map plus the constant `p`. `None` for other values (a rational closed form).
pub fn translate(x: &Exact, p: &Point<Number>) -> Option<Exact> {
    let moved = |q: &Point<Number>| q.checked_add(p).ok();
    let moved_all =
        |ps: &[Point<Number>]| -> Option<Vec<Point<Number>>> { ps.iter().map(moved).collect() };
    Some(match x {
        Exact::Point(q) => Exact::Point(moved(q)?),
        Exact::Points(ps) => Exact::Points(moved_all(ps)?),
        Exact::Map(m) => Exact::Map(m.add_point(p).ok()?),
        Exact::Curve(CurveIn::Expr(m)) => Exact::Curve(CurveIn::Expr(m.add_point(p).ok()?)),
        Exact::Curve(c) => {
            let mut c = c.clone();
            if let CurveIn::Bezier { points, .. } | CurveIn::BSpline { points, .. } = &mut c {
                *points = moved_all(points)?;
            }
            Exact::Curve(c)
        }
        Exact::Surface(SurfaceIn::Expr(m)) => Exact::Surface(SurfaceIn::Expr(m.add_point(p).ok()?)),
        Exact::Surface(s) => {
            let mesh = surface_mesh(s)?;
            let mesh = mesh.try_map(|q| moved(q).ok_or(())).ok()?;
            Exact::Surface(with_mesh(s, mesh))
        }
        _ => return None,
    })
}

/// A polynomial map with u and v exchanged: c(v, u).
pub fn swap_uv(m: &cagd_poly::VecPoly<Number>) -> cagd_poly::VecPoly<Number> {
    use cagd_poly::{Poly, Var};
    m.substitute(Var::U, &Poly::var(Var::T))
        .substitute(Var::V, &Poly::var(Var::U))
        .substitute(Var::T, &Poly::var(Var::V))
}

/// The points x with M x = b of a square matrix `m` given by its rows (`None` when it is
/// singular or the sizes differ).
pub fn solve_rows(m: &[Vec<Number>], b: &[Point<Number>]) -> Option<Vec<Point<Number>>> {
    let matrix = cagd_linalg::Matrix::from_rows(m.to_vec()).ok()?;
    cagd_linalg::solve_points(&matrix, b).ok()
}

/// The rows of a matrix given by its rows, transposed (`None` when the rows differ in length).
pub fn transpose_rows(m: &[Vec<Number>]) -> Option<Vec<Vec<Number>>> {
    let cols = m.first().map_or(0, Vec::len);
    (0..cols)
        .map(|j| m.iter().map(|r| r.get(j).cloned()).collect())
        .collect()
}
