//! The worked steps of the operations (only ever called when the steps are asked for): De
//! Casteljau schemes, De Boor tables, Boehm's α_i, the combinations of degree elevation,
//! basis values and differences, as typed [`Step`]s. Every table is built by the algorithm
//! crates' own step functions (`de_casteljau_triangle`, `de_boor_triangle`,
//! `insert_knot_recorded`, `elevate_degree`, `forward_differences`); a scheme is recorded only
//! when its last point is the operation's result.

use crate::out::Out;
use crate::steps::{Entries, Fact, Line, MatrixSummary, Span, Step, Table, TableTitle};
use crate::value::{exact, exact_point, Exact, ExactScalar};
use cagd_bspline::{DeBoorTriangle, KnotVector};
use cagd_linalg::Point;

/// The points of a list whose steps are worked (`evaluate`): the first few; the others are
/// found in the same way, and the key says so once ([`same_for_the_others`]).
pub(crate) const WORKED_POINTS: usize = 3;

/// The columns (rows) of a mesh whose De Casteljau schemes a key shows: a mesh with more
/// columns (rows) than this has its first column (row) worked in full, the results of the
/// others listed, and the key says they are found in the same way
/// ([`Fact::SameInTheOtherLines`]), as a teacher works one column on the board. The notes'
/// patches (bidegree up to (3, 3)) keep every scheme.
pub(crate) const WORKED_LINES: usize = 4;

/// The combinations a pass of degree elevation ((14) on the columns, (15) on the rows) writes
/// in full: a column of m + 1 points elevated r times has (m + 2) + ... + (m + r + 1) new
/// points, times the n + 1 columns. A pass that would write more works its first column (row)
/// only, elevated by r at once (one combination per new point), and the key says the others
/// are elevated in the same way. The notes' example (a (2, 2) patch by (1, 0)) writes 12; a
/// (3, 3) patch by (1, 1) writes 20 along u, and its 5 rows along v (25) are summarised.
pub(crate) const WORKED_COMBINATIONS: usize = 24;

/// The most entries of a matrix a key prints whole: a bigger one is shown by its size, what
/// its entries are and its first [`SHOWN_ROWS`] rows ([`Step::Matrix`]), and only those rows
/// are computed. The notes' matrices (B_U and B_V of a (2, 3) grid, B of five points on a
/// (1, 1) patch) and those of a grid up to (6, 6) are printed whole.
pub(crate) const WHOLE_MATRIX_ENTRIES: usize = 64;

/// The rows shown of a matrix too big to print whole.
pub(crate) const SHOWN_ROWS: usize = 2;

/// Whether a matrix of `rows` × `cols` is too big to print whole ([`WHOLE_MATRIX_ENTRIES`]).
pub(crate) fn too_big(rows: usize, cols: usize) -> bool {
    rows.saturating_mul(cols) > WHOLE_MATRIX_ENTRIES
}

/// A matrix of `rows` × `cols` shown by its size, what its entries are, and its first rows
/// (`row(i)` computes row i; only the [`SHOWN_ROWS`] first are asked for).
pub(crate) fn matrix_summary<S: ExactScalar>(
    symbol: &str,
    (rows, cols): (usize, usize),
    entries: Entries,
    row: impl Fn(usize) -> Vec<S>,
) -> Step {
    let first: Vec<Vec<S>> = (0..rows.min(SHOWN_ROWS)).map(row).collect();
    Step::Matrix(Box::new(MatrixSummary {
        symbol: symbol.to_string(),
        rows,
        cols,
        entries,
        first_rows: Exact::matrix(&first),
    }))
}

/// Whether the line `k` of a pass over `count` lines gets its worked steps
/// ([`WORKED_LINES`]).
pub(crate) fn worked_line(k: usize, count: usize) -> bool {
    count <= WORKED_LINES || k == 0
}

/// After the first line of a pass over `count` lines, when only it was worked: the others are
/// done in the same way.
pub(crate) fn same_in_the_other_lines(out: &mut Out, line: Line, count: usize) {
    if out.steps_on() && count > 1 {
        out.fact(Fact::SameInTheOtherLines {
            line,
            shown: 1,
            more: count - 1,
        });
    }
}

/// The points of a list worked on a patch of `columns` columns: [`WORKED_POINTS`], or the
/// first only when the patch has more than [`WORKED_LINES`] columns (each point is then a long
/// scheme, and one shows the way).
pub(crate) fn worked_points(columns: usize) -> usize {
    if columns > WORKED_LINES {
        1
    } else {
        WORKED_POINTS
    }
}

/// Whether the point `i` of a list gets its worked steps, the first `shown` being worked.
pub(crate) fn worked(out: &Out, i: usize, shown: usize) -> bool {
    out.steps_on() && i < shown
}

/// After the first `shown` points of a list of `count`, worked: the others are found in the
/// same way.
pub(crate) fn same_for_the_others(out: &mut Out, count: usize, shown: usize) {
    if out.steps_on() && count > shown {
        out.fact(Fact::SameForTheOthers {
            shown,
            more: count - shown,
        });
    }
}

/// An exact number.
pub(crate) fn number<S: ExactScalar>(x: &S) -> Exact {
    Exact::Number(exact(x))
}

/// An exact point.
pub(crate) fn point<S: ExactScalar>(p: &Point<S>) -> Exact {
    Exact::Point(exact_point(p))
}

/// The De Casteljau scheme of `levels` (level r holds the points c_i^r): a column per r, a
/// row per i.
pub(crate) fn casteljau_table<S: ExactScalar>(levels: &[Vec<Point<S>>]) -> Step {
    let n = levels.first().map_or(0, Vec::len);
    let columns = (0..levels.len()).map(|r| format!("r = {r}")).collect();
    let rows = (0..n)
        .map(|i| {
            (
                format!("i = {i}"),
                levels.iter().map(|l| l.get(i).map(point)).collect(),
            )
        })
        .collect();
    Step::Table {
        title: TableTitle::DeCasteljau,
        table: Table { columns, rows },
    }
}

/// Basis values in one row: `name_i` for each value.
pub(crate) fn basis_table<S: ExactScalar>(label: String, names: Vec<String>, values: &[S]) -> Step {
    Step::Table {
        title: TableTitle::Basis,
        table: Table {
            columns: names,
            rows: vec![(label, values.iter().map(|x| Some(number(x))).collect())],
        },
    }
}

/// The Bernstein values B_0^n(t), ..., B_n^n(t).
pub(crate) fn bernstein_table<S: ExactScalar>(n: usize, t: &S, var: &str) -> Step {
    let values = cagd_bezier::bernstein_all(n, t);
    basis_table(
        format!("{var} = {}", t.to_text()),
        (0..=n)
            .map(|i| format!("B_{{{i}}}^{{{n}}}({var})"))
            .collect(),
        &values,
    )
}

/// The span of t, in the notes' indices, for a De Boor triangle or an insertion (k in the
/// full convention: u_k ≤ t < u_{k+1} there, u_{k-1} ≤ t < u_k in the notes).
pub(crate) fn span<S: ExactScalar>(knots: &KnotVector<S>, k: usize, t: &S, name: &str) -> Step {
    let full = knots.full();
    let at = |i: usize| {
        full.get(i)
            .map(number)
            .unwrap_or(Exact::Text(String::new()))
    };
    Step::Fact(Fact::Span(Box::new(Span {
        knots: name.to_string(),
        t: number(t),
        k,
        left: at(k),
        right: at(k + 1),
    })))
}

/// A De Boor triangle: the span, the α_i^r and the points d_i^r, in the notes' indices.
pub(crate) fn de_boor<S: ExactScalar>(
    out: &mut Out,
    knots: &KnotVector<S>,
    tri: &DeBoorTriangle<S>,
    name: &str,
) {
    out.explain(span(knots, tri.span, &tri.t, name));
    let Some(first) = tri.levels.first() else {
        return;
    };
    let start = first.first;
    let count = first.points.len();
    let columns = (0..tri.levels.len()).map(|r| format!("r = {r}")).collect();
    let rows = (0..count)
        .map(|k| {
            let i = start + k;
            let cells = tri
                .levels
                .iter()
                .map(|l| {
                    i.checked_sub(l.first)
                        .and_then(|at| l.points.get(at))
                        .map(point)
                })
                .collect();
            (format!("d_{{{i}}}"), cells)
        })
        .collect();
    if tri.levels.len() > 1 {
        let alpha_cols = (1..tri.levels.len()).map(|r| format!("r = {r}")).collect();
        let alpha_rows = (0..count)
            .filter_map(|k| {
                let i = start + k;
                let cells: Vec<Option<Exact>> = tri
                    .levels
                    .iter()
                    .skip(1)
                    .map(|l| {
                        i.checked_sub(l.first)
                            .and_then(|at| l.alphas.get(at))
                            .map(number)
                    })
                    .collect();
                cells
                    .iter()
                    .any(Option::is_some)
                    .then(|| (format!("\\alpha_{{{i}}}"), cells))
            })
            .collect();
        out.explain(Step::Table {
            title: TableTitle::Alphas,
            table: Table {
                columns: alpha_cols,
                rows: alpha_rows,
            },
        });
    }
    out.explain(Step::Table {
        title: TableTitle::DeBoor,
        table: Table { columns, rows },
    });
}

/// The B-spline basis values N_{k-p}^p(t), ..., N_k^p(t) on the span of t.
pub(crate) fn bspline_basis<S: ExactScalar>(
    knots: &KnotVector<S>,
    t: &S,
    var: &str,
) -> Option<Step> {
    let k = knots.find_span(t).ok()?;
    let p = knots.degree();
    let values = cagd_bspline::basis_functions(knots, k, t).ok()?;
    Some(basis_table(
        format!("{var} = {}", t.to_text()),
        (0..values.len())
            .map(|j| format!("N_{{{}}}^{{{p}}}({var})", k - p + j))
            .collect(),
        &values,
    ))
}

/// `symbol = Σ coefficient · term = value`, terms with a zero coefficient left out.
pub(crate) fn combination<S: ExactScalar>(
    symbol: String,
    terms: Vec<(S, String, Exact)>,
    value: Exact,
) -> Step {
    Step::Combination {
        symbol,
        terms: terms
            .into_iter()
            .filter(|(c, _, _)| !c.is_zero())
            .map(|(c, s, v)| (number(&c), s, v))
            .collect(),
        value,
    }
}

/// One degree elevation of a polygon (n → n + 1) as combinations
/// `c_i^{(1)} = i/(n+1) c_{i-1} + (1 - i/(n+1)) c_i`, with `name(i)` the symbol of point i
/// before and `new(i)` after; returns the elevated points.
pub(crate) fn elevate_once<S: ExactScalar>(
    out: &mut Out,
    points: &[Point<S>],
    name: &dyn Fn(usize) -> String,
    new: &dyn Fn(usize) -> String,
) -> Vec<Point<S>> {
    let Ok(next) = cagd_bezier::elevate_degree(points, 1) else {
        return points.to_vec();
    };
    let n1 = S::from_i64(i64::try_from(points.len()).unwrap_or(i64::MAX));
    for (i, p) in next.iter().enumerate() {
        let a = S::from_i64(i64::try_from(i).unwrap_or(i64::MAX)) / n1.clone();
        let mut terms = Vec::new();
        if let Some(prev) = i.checked_sub(1).and_then(|k| points.get(k)) {
            terms.push((a.clone(), name(i - 1), point(prev)));
        }
        if let Some(this) = points.get(i) {
            terms.push((S::one() - a, name(i), point(this)));
        }
        out.explain(combination(new(i), terms, point(p)));
    }
    next
}

/// The binomial coefficient C(n, k) (0 when k > n), exactly.
fn binomial<S: ExactScalar>(n: usize, k: usize) -> S {
    if k > n {
        return S::zero();
    }
    let of = |x: usize| S::from_i64(i64::try_from(x).unwrap_or(i64::MAX));
    (1..=k).fold(S::one(), |acc, t| acc * of(n - k + t) / of(t))
}

/// The degree elevation of a polygon by r at once (n → n + r) as combinations
/// `c_i^{(r)} = Σ_k C(n, k) C(r, i - k) / C(n + r, i) c_k`, k = max(0, i - r), ..., min(n, i)
/// (r steps of [`elevate_once`] in one formula), with `name(k)` the symbol of point k before
/// and `new(i)` after; returns the elevated points (from [`cagd_bezier::elevate_degree`]).
pub(crate) fn elevate_at_once<S: ExactScalar>(
    out: &mut Out,
    points: &[Point<S>],
    r: usize,
    name: &dyn Fn(usize) -> String,
    new: &dyn Fn(usize) -> String,
) -> Vec<Point<S>> {
    let Ok(next) = cagd_bezier::elevate_degree(points, r) else {
        return points.to_vec();
    };
    let n = points.len().saturating_sub(1);
    for (i, p) in next.iter().enumerate() {
        let whole = binomial::<S>(n + r, i);
        let terms = (i.saturating_sub(r)..=n.min(i))
            .filter_map(|k| {
                let c = binomial::<S>(n, k) * binomial::<S>(r, i - k) / whole.clone();
                points.get(k).map(|q| (c, name(k), point(q)))
            })
            .collect();
        out.explain(combination(new(i), terms, point(p)));
    }
    next
}

/// n! / (n - r)!.
pub(crate) fn falling<S: ExactScalar>(n: usize, r: usize) -> S {
    let mut f = S::one();
    for k in 0..r {
        f *= S::from_i64(i64::try_from(n.saturating_sub(k)).unwrap_or(i64::MAX));
    }
    f
}

/// The table `step`, titled as forward differences (a column per order r).
pub(crate) fn titled_differences(step: Step) -> Step {
    match step {
        Step::Table { table, .. } => Step::Table {
            title: TableTitle::Differences,
            table,
        },
        other => other,
    }
}
