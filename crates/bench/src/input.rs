//! The inputs of the tasks, drawn from a fixed seed as small rationals, and their JSON form.

use crate::tasks::{Kind, Task};
use crate::Rng;
use cagd_fit::approximate_bezier_surface;
use cagd_linalg::Point;
use cagd_scalar::{BigRational, Scalar};
use cagd_surface::{BezierSurface, Mesh};
use serde_json::{json, Value};

/// A rational p/q as drawn (q > 0, not necessarily reduced).
pub type Rational = (i64, i64);

/// The input of one task at one size, in small rationals.
#[derive(Clone, Debug, PartialEq)]
pub struct Input {
    /// The task and its size.
    pub task: Task,
    /// The control mesh (T1, T2, T3, T5) or the grid of data (T4): `n + 1` rows of `n + 1`
    /// points of R^3.
    pub mesh: Vec<Vec<[Rational; 3]>>,
    /// Parameter pairs (u, v): the 100 evaluation points of T1, the M data parameters of T6.
    pub params: Vec<(Rational, Rational)>,
    /// The M data points of T6.
    pub points: Vec<[Rational; 3]>,
}

fn point3(rng: &mut Rng) -> [Rational; 3] {
    [rng.coordinate(), rng.coordinate(), rng.coordinate()]
}

fn scalar<S: Scalar>((p, q): Rational) -> S {
    S::from_ratio(p, q)
}

fn point<S: Scalar>(p: &[Rational; 3]) -> Point<S> {
    Point::new(p.iter().map(|&x| scalar(x)).collect())
}

fn text((p, q): Rational) -> String {
    if q == 1 {
        p.to_string()
    } else {
        format!("{p}/{q}")
    }
}

fn point_json(p: &[Rational; 3]) -> Value {
    json!(p.iter().map(|&x| text(x)).collect::<Vec<_>>())
}

/// The input of a task, made ready in a scalar type.
#[derive(Clone, Debug)]
pub struct Prepared<S: Scalar> {
    /// The patch of T1, T2, T3, T5.
    pub surface: Option<BezierSurface<S>>,
    /// The grid of data of T4.
    pub grid: Option<Mesh<S>>,
    /// The uniform parameters i/n of T4.
    pub uniform: Vec<S>,
    /// The parameter pairs of T1 and T6.
    pub params: Vec<(S, S)>,
    /// The data points of T6.
    pub points: Vec<Point<S>>,
}

impl Input {
    /// The input of `task`, drawn from a seed that depends only on the task and its sizes.
    /// For T6 the draw is repeated (with the next seed) until the data determine the patch
    /// (BᵗB nonsingular), so that the least-squares problem has its unique answer.
    pub fn new(task: Task) -> Self {
        let seed = 0x00CA_6D00 + 1000 * task.kind as u64 + 10 * task.n as u64 + task.extra as u64;
        let mut input = Self::draw(task, seed);
        let mut attempt = 0;
        while task.kind == Kind::LeastSquares && attempt < 100 && !input.determined() {
            attempt += 1;
            input = Self::draw(task, seed + 1_000_000 * attempt);
        }
        input
    }

    /// Whether the scattered data of T6 determine the patch (exactly).
    fn determined(&self) -> bool {
        let p = self.prepare::<BigRational>();
        approximate_bezier_surface(self.task.n, self.task.n, &p.params, &p.points).is_ok()
    }

    fn draw(task: Task, seed: u64) -> Self {
        let mut rng = Rng::new(seed);
        let n = task.n;
        let mesh = (0..=n)
            .map(|_| (0..=n).map(|_| point3(&mut rng)).collect())
            .collect();
        let count = match task.kind {
            Kind::Evaluate => 100,
            Kind::LeastSquares => task.extra,
            _ => 0,
        };
        let mut params: Vec<(Rational, Rational)> = Vec::with_capacity(count);
        while params.len() < count {
            let uv = (rng.parameter(), rng.parameter());
            // distinct pairs for T6 (a repeated pair adds no condition)
            if task.kind != Kind::LeastSquares || !params.contains(&uv) {
                params.push(uv);
            }
        }
        let points = match task.kind {
            Kind::LeastSquares => (0..count).map(|_| point3(&mut rng)).collect(),
            _ => Vec::new(),
        };
        Input {
            task,
            mesh,
            params,
            points,
        }
    }

    /// The input in the scalar type `S`.
    pub fn prepare<S: Scalar>(&self) -> Prepared<S> {
        let rows: Vec<Vec<Point<S>>> = self
            .mesh
            .iter()
            .map(|row| row.iter().map(point).collect())
            .collect();
        let mesh = Mesh::from_rows(rows).ok();
        let (surface, grid) = match self.task.kind {
            Kind::Interpolate => (None, mesh),
            Kind::LeastSquares => (None, None),
            _ => (mesh.and_then(|m| BezierSurface::try_new(m).ok()), None),
        };
        let n = i64::try_from(self.task.n.max(1)).unwrap_or(1);
        Prepared {
            surface,
            grid,
            uniform: (0..=n).map(|i| S::from_ratio(i, n)).collect(),
            params: self
                .params
                .iter()
                .map(|&(u, v)| (scalar(u), scalar(v)))
                .collect(),
            points: self.points.iter().map(point).collect(),
        }
    }

    /// The JSON form read by the peers' script: every number a string `"p/q"`.
    pub fn to_json(&self) -> Value {
        json!({
            "mesh": self.mesh.iter().map(|row| row.iter().map(point_json).collect::<Vec<_>>()).collect::<Vec<_>>(),
            "params": self.params.iter().map(|&(u, v)| json!([text(u), text(v)])).collect::<Vec<_>>(),
            "points": self.points.iter().map(point_json).collect::<Vec<_>>(),
        })
    }
}
