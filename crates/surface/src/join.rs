//! Joining two patches along a border: the C^r conditions (21)-(23), the data on both sides
//! of the border, and the rows of a C^r neighbour (notes, chapter 5, §6).

use crate::closed_form::scalar_of;
use crate::derivative::mesh_differences;
use crate::{BezierSurface, Mesh, SurfaceError};
use cagd_bezier::blossom;
use cagd_linalg::Point;
use cagd_poly::{from_bernstein_1d, Var, VecPoly};
use cagd_scalar::Scalar;
use cagd_words::{said, Lang, Message, Phrase};
use std::cmp::Ordering;
use std::fmt;

/// The border two patches share.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub enum Join {
    /// u = 1 of the first patch is u = 0 of the second: the last row of the first mesh and
    /// the first row of the second (the notes' setting, eq. (21)-(23)).
    U,
    /// v = 1 of the first patch is v = 0 of the second: the last column of the first mesh and
    /// the first column of the second.
    V,
}

/// The highest order of continuity across the border.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Default, strum::EnumIter)]
pub enum Smoothness {
    /// The borders differ: (21) fails.
    #[default]
    NotContinuous,
    /// C^r and not C^{r+1}.
    C(usize),
    /// Every derivative agrees: the two patches are pieces of one polynomial surface.
    Infinite,
}

impl Message for Smoothness {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Smoothness::NotContinuous => said(lang, "not $C^0$", "no es $C^0$", []),
            Smoothness::C(r) => said(
                lang,
                "$C^‹›$, not $C^‹›$",
                "$C^‹›$, pero no $C^‹›$",
                [r.into(), (&(r + 1)).into()],
            ),
            Smoothness::Infinite => said(
                lang,
                "$C^∞$ (one polynomial surface)",
                "$C^∞$ (una sola superficie polinómica)",
                [],
            ),
        }
    }
}

cagd_words::display_english!(Smoothness);

/// A condition of (21)-(23) that fails, with both sides.
#[derive(Clone, PartialEq, Debug)]
pub struct FailedCondition<S> {
    /// The order r of the condition (0 for (21)).
    pub order: usize,
    /// The index along the border (j for [`Join::U`], i for [`Join::V`]).
    pub index: usize,
    /// The first patch's side.
    pub first: Point<S>,
    /// The second patch's side.
    pub second: Point<S>,
    /// The name of the index along the border: `j` for [`Join::U`], `i` for [`Join::V`].
    pub index_name: &'static str,
    /// The first patch's side with its value, as mathematics: `Δ^{1,0} c_{1,1} / Δu_0 =
    /// (0, 0, -1)`.
    pub left: String,
    /// The second patch's side with its value: `Δ^{1,0} c~_{0,1} / Δu_1 = (0, 0, -2)`.
    pub right: String,
    /// In words (the English of [`Message`]), e.g. `C^1 fails at j = 1: Δ^{1,0} c_{1,1} /
    /// Δu_0 = (0, 0, -1) but Δ^{1,0} c~_{0,1} / Δu_1 = (0, 0, -2)`.
    pub text: String,
}

impl<S> FailedCondition<S> {
    /// The condition as the notes write it, without its points: what is said of it.
    pub fn condition(&self) -> ConditionFails {
        ConditionFails {
            order: self.order,
            index_name: self.index_name,
            index: self.index,
            left: self.left.clone(),
            right: self.right.clone(),
        }
    }
}

impl<S> Message for FailedCondition<S> {
    fn phrase(&self, lang: Lang) -> Phrase {
        self.condition().phrase(lang)
    }
}

/// A condition of (21)-(23) that fails, as the notes write it: `C^r fails at j = k:` and its
/// two sides, each with its value (a [`FailedCondition`] without its points, for a sentence
/// that holds no scalar type).
#[derive(Clone, PartialEq, Eq, Hash, Debug, Default)]
pub struct ConditionFails {
    /// The order r of the condition (0 for (21)).
    pub order: usize,
    /// The name of the index along the border: `j` for [`Join::U`], `i` for [`Join::V`].
    pub index_name: &'static str,
    /// The index along the border.
    pub index: usize,
    /// The first patch's side with its value: `Δ^{1,0} c_{1,1} / Δu_0 = (0, 0, -1)`.
    pub left: String,
    /// The second patch's side with its value: `Δ^{1,0} c~_{0,1} / Δu_1 = (0, 0, -2)`.
    pub right: String,
}

impl Message for ConditionFails {
    fn phrase(&self, lang: Lang) -> Phrase {
        said(
            lang,
            "$C^‹›$ fails at $‹› = ‹›$: $‹›$ but $‹›$",
            "$C^‹›$ falla en $‹› = ‹›$: $‹›$, pero $‹›$",
            [
                (&self.order).into(),
                self.index_name.into(),
                (&self.index).into(),
                (&self.left).into(),
                (&self.right).into(),
            ],
        )
    }
}

cagd_words::display_english!(ConditionFails);

impl<S: Scalar> fmt::Display for FailedCondition<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

/// What [`continuity`] finds across a border.
#[derive(Clone, PartialEq)]
pub struct Continuity<S> {
    /// The highest order r with C^r.
    pub smoothness: Smoothness,
    /// The first condition that fails (none for [`Smoothness::Infinite`]).
    pub failure: Option<FailedCondition<S>>,
    /// The first differences of the first patch at the border: `Δ^{1,0} c_{m-1,j}` (for
    /// [`Join::V`], `Δ^{0,1} c_{i,n-1}`); empty when its degree across is 0.
    pub differences_first: Vec<Point<S>>,
    /// The first differences of the second patch at the border: `Δ^{1,0} c̃_{0,j}`.
    pub differences_second: Vec<Point<S>>,
    /// The cross derivative of the first patch on the border divided by its parameter length,
    /// `c_{1,u}(1, v) / Δu_0`, in the running parameter (v for [`Join::U`], u for [`Join::V`]).
    pub derivative_first: VecPoly<S>,
    /// The cross derivative of the second patch, `c_{2,u}(0, v) / Δu_1`.
    pub derivative_second: VecPoly<S>,
    /// The normal `c_u x c_v` of the first patch along the border (with the cross derivative
    /// divided by Δu_0), for points of R^3.
    pub normal_first: Option<VecPoly<S>>,
    /// The normal of the second patch along the border, for points of R^3.
    pub normal_second: Option<VecPoly<S>>,
}

impl<S: Scalar> Continuity<S> {
    /// `C^0, not C^1` and, when a condition fails, the condition.
    pub fn to_text(&self) -> String {
        match &self.failure {
            Some(f) => format!("{}; {}", self.smoothness, f.text),
            None => self.smoothness.to_string(),
        }
    }
}

impl<S: Scalar> fmt::Debug for Continuity<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Continuity")
            .field("smoothness", &self.smoothness)
            .field("failure", &self.failure)
            .field("differences_first", &self.differences_first)
            .field("differences_second", &self.differences_second)
            .field("derivative_first", &self.derivative_first)
            .field("derivative_second", &self.derivative_second)
            .field("normal_first", &self.normal_first)
            .field("normal_second", &self.normal_second)
            .finish()
    }
}

/// How to print the indices of the (possibly transposed) meshes.
struct Labels {
    join: Join,
}

impl Labels {
    /// `c_{i,j}` of the original mesh from indices (k along the cross direction, l along the
    /// border) of the mesh as used (transposed for [`Join::V`]).
    fn vertex(&self, tilde: bool, k: usize, l: usize) -> String {
        let name = if tilde { "c~" } else { "c" };
        match self.join {
            Join::U => format!("{name}_{{{k},{l}}}"),
            Join::V => format!("{name}_{{{l},{k}}}"),
        }
    }

    fn delta(&self, r: usize) -> String {
        match self.join {
            Join::U => format!("Δ^{{{r},0}}"),
            Join::V => format!("Δ^{{0,{r}}}"),
        }
    }

    fn length(&self, which: usize, r: usize) -> String {
        let p = match self.join {
            Join::U => "u",
            Join::V => "v",
        };
        if r == 1 {
            format!("Δ{p}_{which}")
        } else {
            format!("Δ{p}_{which}^{r}")
        }
    }

    fn index_name(&self) -> &'static str {
        match self.join {
            Join::U => "j",
            Join::V => "i",
        }
    }

    fn running(&self) -> Var {
        match self.join {
            Join::U => Var::V,
            Join::V => Var::U,
        }
    }
}

/// An error unless `x > 0` is decided (an order that cannot be decided is an error too).
fn check_length<S: Scalar>(name: &str, x: &S) -> Result<(), SurfaceError> {
    if x.compare(&S::zero()) == Some(Ordering::Greater) {
        Ok(())
    } else {
        Err(SurfaceError::NotPositive {
            what: crate::Positive::ParameterLength {
                name: name.to_string(),
            },
            value: x.to_text(),
        })
    }
}

/// `m!/(m-r)!` (0 when r > m).
fn falling<S: Scalar>(m: usize, r: usize) -> S {
    if r > m {
        return S::zero();
    }
    ((m - r + 1)..=m).fold(S::one(), |acc, k| acc * scalar_of::<S>(k))
}

fn exponent(k: usize) -> u32 {
    u32::try_from(k).unwrap_or(u32::MAX)
}

/// The meshes as used: the shared border is the last row of `a` and the first row of `b`.
fn oriented<S: Scalar>(
    first: &BezierSurface<S>,
    second: &BezierSurface<S>,
    join: Join,
) -> (Mesh<S>, Mesh<S>) {
    match join {
        Join::U => (first.mesh().clone(), second.mesh().clone()),
        Join::V => (first.mesh().transpose(), second.mesh().transpose()),
    }
}

/// Whether two patches sharing a border are C^0, C^1, ... across it, with parameter lengths
/// Δu_0 (first patch) and Δu_1 (second) in the direction across (pass 1 and 1 for the notes'
/// default). The conditions, for [`Join::U`] and patches of the same degree m in u:
///
/// - C^0, (21): `c_{m,j} = c̃_{0,j}`, `j = 0..n`;
/// - C^1, (22): `Δ^{1,0} c_{m-1,j} / Δu_0 = Δ^{1,0} c̃_{0,j} / Δu_1`;
/// - C^r, (23): `Δ^{r,0} c_{m-r,j} / (Δu_0)^r = Δ^{r,0} c̃_{0,j} / (Δu_1)^r`.
///
/// For different degrees m, m̃ the derivatives (20) and (19) are compared, with their factors
/// `m!/(m-r)!` and `m̃!/(m̃-r)!`. Orders are checked up to max(m, m̃), beyond which both sides
/// vanish. The patches' own domains are not used: the lengths are `du0`, `du1`, and the
/// closed forms along the border are in the running parameter on [0, 1]. An error when the
/// borders have different degrees or dimensions, or a length is not positive.
///
/// The notes' example (§6) is C^0 and not C^1:
///
/// ```
/// use cagd_surface::{continuity, BezierSurface, Join};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let p = |c: &[i64]| Point::from_ints(c);
/// let c1 = BezierSurface::<BigRational>::from_rows(vec![
///     vec![p(&[-1, -2, 0]), p(&[0, -1, 1]), p(&[1, -2, 0])],
///     vec![p(&[-1, -1, 0]), p(&[0, 0, 1]), p(&[1, -1, 0])],
///     vec![p(&[-1, 0, 0]), p(&[0, 0, 0]), p(&[1, 0, 0])],
/// ]).unwrap();
/// let c2 = BezierSurface::<BigRational>::from_rows(vec![
///     vec![p(&[-1, 0, 0]), p(&[0, 0, 0]), p(&[1, 0, 0])],
///     vec![p(&[-1, 1, 0]), p(&[0, 0, -2]), p(&[1, 1, 0])],
///     vec![p(&[-1, 2, 0]), p(&[0, 1, -2]), p(&[1, 2, 0])],
/// ]).unwrap();
/// let k = continuity(&c1, &c2, Join::U, &q!(1), &q!(1)).unwrap();
/// assert_eq!(k.smoothness.to_string(), "C^0, not C^1");
/// assert_eq!(
///     k.failure.unwrap().text,
///     "C^1 fails at j = 1: Δ^{1,0} c_{1,1} / Δu_0 = (0, 0, -1) but Δ^{1,0} c~_{0,1} / Δu_1 = (0, 0, -2)"
/// );
/// assert_eq!(k.derivative_second.to_text(), "(0, 4 v^2 - 4 v + 2, 8 v^2 - 8 v)");
/// ```
pub fn continuity<S: Scalar>(
    first: &BezierSurface<S>,
    second: &BezierSurface<S>,
    join: Join,
    du0: &S,
    du1: &S,
) -> Result<Continuity<S>, SurfaceError> {
    let labels = Labels { join };
    check_length(&labels.length(0, 1), du0)?;
    check_length(&labels.length(1, 1), du1)?;
    let (a, b) = oriented(first, second, join);
    if a.dim() != b.dim() {
        return Err(SurfaceError::Dimension {
            what: crate::Computation::Join,
            expected: a.dim(),
            found: b.dim(),
        });
    }
    if a.cols() != b.cols() {
        return Err(SurfaceError::BorderDegree {
            param: if join == Join::U { "v" } else { "u" },
            first: a.cols() - 1,
            second: b.cols() - 1,
        });
    }
    let (smoothness, failure) = check_orders(&a, &b, &labels, du0, du1)?;
    let side = |mesh: &Mesh<S>, last: bool, du: &S| -> Result<Side<S>, SurfaceError> {
        border_side(mesh, last, du, &labels)
    };
    let s1 = side(&a, true, du0)?;
    let s2 = side(&b, false, du1)?;
    Ok(Continuity {
        smoothness,
        failure,
        differences_first: s1.differences,
        differences_second: s2.differences,
        derivative_first: s1.derivative,
        derivative_second: s2.derivative,
        normal_first: s1.normal,
        normal_second: s2.normal,
    })
}

/// The order of continuity and the first failing condition.
fn check_orders<S: Scalar>(
    a: &Mesh<S>,
    b: &Mesh<S>,
    labels: &Labels,
    du0: &S,
    du1: &S,
) -> Result<(Smoothness, Option<FailedCondition<S>>), SurfaceError> {
    let (m, mt) = (a.rows() - 1, b.rows() - 1);
    let same = m == mt;
    for r in 0..=m.max(mt) {
        let lhs = side_values(a, r, true, du0, same)?;
        let rhs = side_values(b, r, false, du1, same)?;
        // both sides have one value per column (the meshes have as many columns)
        let mismatch = lhs.iter().zip(&rhs).enumerate().find(|(_, (p, q))| p != q);
        if let Some((j, (p, q))) = mismatch {
            let (p, q) = (p.clone(), q.clone());
            let (left, right) = failure_sides(labels, r, j, (m, mt), &p, &q);
            let index_name = labels.index_name();
            let smoothness = if r == 0 {
                Smoothness::NotContinuous
            } else {
                Smoothness::C(r - 1)
            };
            let condition = ConditionFails {
                order: r,
                index_name,
                index: j,
                left,
                right,
            };
            let failure = FailedCondition {
                order: r,
                index: j,
                first: p,
                second: q,
                index_name,
                text: condition.english(),
                left: condition.left,
                right: condition.right,
            };
            return Ok((smoothness, Some(failure)));
        }
    }
    Ok((Smoothness::Infinite, None))
}

/// One side of the condition of order r at every index along the border: for equal degrees
/// `Δ^{r,0} c_{m-r,j} / Δu^r` (or `Δ^{r,0} c̃_{0,j} / Δu^r`), otherwise the derivative
/// `m!/(m-r)! Δ^{r,0} ... / Δu^r` (zero when r > m).
fn side_values<S: Scalar>(
    mesh: &Mesh<S>,
    r: usize,
    last: bool,
    du: &S,
    same: bool,
) -> Result<Vec<Point<S>>, SurfaceError> {
    let m = mesh.rows() - 1;
    if r > m {
        return Ok(vec![Point::zero(mesh.dim()); mesh.cols()]);
    }
    let diffs = mesh_differences(mesh, r, 0)?;
    let row = if last { diffs.rows() - 1 } else { 0 };
    let mut factor = S::one()
        .checked_div(&du.powi(exponent(r)))
        .unwrap_or_else(S::zero);
    if !same {
        factor *= falling::<S>(m, r);
    }
    Ok(diffs
        .row(row)
        .unwrap_or_default()
        .iter()
        .map(|p| p.scale(&factor))
        .collect())
}

/// The two sides of the condition that fails, each with its value: `c_{1,0} = (1, 0, 0)`.
fn failure_sides<S: Scalar>(
    labels: &Labels,
    r: usize,
    j: usize,
    (m, mt): (usize, usize),
    p: &Point<S>,
    q: &Point<S>,
) -> (String, String) {
    if r == 0 {
        return (
            format!("{} = {}", labels.vertex(false, m, j), p.to_text()),
            format!("{} = {}", labels.vertex(true, 0, j), q.to_text()),
        );
    }
    let side = |tilde: bool, degree: usize, k: usize, which: usize| -> String {
        let base = format!(
            "{} {} / {}",
            labels.delta(r),
            labels.vertex(tilde, k, j),
            labels.length(which, r)
        );
        if m == mt {
            base
        } else if r > degree {
            format!("0 (degree {degree} < {r})")
        } else {
            format!("{} {base}", falling::<S>(degree, r).to_text())
        }
    };
    (
        format!(
            "{} = {}",
            side(false, m, m.saturating_sub(r), 0),
            p.to_text()
        ),
        format!("{} = {}", side(true, mt, 0, 1), q.to_text()),
    )
}

/// The data on one side of the border.
struct Side<S> {
    differences: Vec<Point<S>>,
    derivative: VecPoly<S>,
    normal: Option<VecPoly<S>>,
}

fn border_side<S: Scalar>(
    mesh: &Mesh<S>,
    last: bool,
    du: &S,
    labels: &Labels,
) -> Result<Side<S>, SurfaceError> {
    let m = mesh.rows() - 1;
    let var = labels.running();
    let differences = if m == 0 {
        Vec::new()
    } else {
        let d = mesh_differences(mesh, 1, 0)?;
        let row = if last { d.rows() - 1 } else { 0 };
        d.row(row).map(<[Point<S>]>::to_vec).unwrap_or_default()
    };
    let derivative = if differences.is_empty() {
        VecPoly::zero(mesh.dim())
    } else {
        let factor = scalar_of::<S>(m).checked_div(du).unwrap_or_else(S::zero);
        let vectors: Vec<Point<S>> = differences.iter().map(|p| p.scale(&factor)).collect();
        from_bernstein_1d(&vectors, var)?
    };
    let border_row = mesh
        .row(if last { m } else { 0 })
        .map(<[Point<S>]>::to_vec)
        .unwrap_or_default();
    let tangent = from_bernstein_1d(&border_row, var)?.partial(var);
    let normal = if mesh.dim() == 3 {
        Some(match labels.join {
            Join::U => derivative.cross(&tangent)?,
            Join::V => tangent.cross(&derivative)?,
        })
    } else {
        None
    };
    Ok(Side {
        differences,
        derivative,
        normal,
    })
}

/// The first r + 1 rows of a patch of the same bidegree that joins `first` with C^r across its
/// border u = 1, for parameter lengths Δu_0 (first) and Δu_1 (next): solving (23) for
/// `c̃_{0,j}, ..., c̃_{r,j}` gives the control points of each column curve extended past
/// u = 1, by the curve blossom,
///
/// `c̃_{k,j} = c_j[1^<m-k>, (1 + Δu_1/Δu_0)^<k>]`, `k = 0..r`
///
/// (so `c̃_{0,j} = c_{m,j}` and, for r = 1, `c̃_{1,j} = c_{m,j} + (Δu_1/Δu_0) Δ^{1,0}
/// c_{m-1,j}`). The remaining rows are free. An error unless r <= m and the lengths are
/// positive.
///
/// ```
/// use cagd_surface::{c1_neighbour_rows, BezierSurface};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let p = |c: &[i64]| Point::from_ints(c);
/// let s = BezierSurface::<BigRational>::from_rows(vec![
///     vec![p(&[0, 0, 0]), p(&[1, 0, 1])],
///     vec![p(&[0, 1, 1]), p(&[1, 1, 0])],
/// ]).unwrap();
/// let rows = c1_neighbour_rows(&s, 1, &q!(1), &q!(1/2)).unwrap();
/// assert_eq!(rows.to_text(), "{(0, 1, 1), (1, 1, 0); (0, 3/2, 3/2), (1, 3/2, -1/2)}");
/// ```
pub fn c1_neighbour_rows<S: Scalar>(
    first: &BezierSurface<S>,
    r: usize,
    du0: &S,
    du1: &S,
) -> Result<Mesh<S>, SurfaceError> {
    neighbour(first.mesh(), r, du0, du1, "u")
}

/// The first r + 1 columns of a patch joining `first` with C^r across its border v = 1, for
/// parameter lengths Δv_0, Δv_1: [`c1_neighbour_rows`] with u and v exchanged,
/// `c̃_{i,k} = c_i[1^<n-k>, (1 + Δv_1/Δv_0)^<k>]`, `k = 0..r`.
pub fn c1_neighbour_columns<S: Scalar>(
    first: &BezierSurface<S>,
    r: usize,
    dv0: &S,
    dv1: &S,
) -> Result<Mesh<S>, SurfaceError> {
    Ok(neighbour(&first.mesh().transpose(), r, dv0, dv1, "v")?.transpose())
}

fn neighbour<S: Scalar>(
    mesh: &Mesh<S>,
    r: usize,
    d0: &S,
    d1: &S,
    param: &str,
) -> Result<Mesh<S>, SurfaceError> {
    check_length(&format!("Δ{param}_0"), d0)?;
    check_length(&format!("Δ{param}_1"), d1)?;
    let m = mesh.rows() - 1;
    if r > m {
        return Err(SurfaceError::Order {
            r,
            degree: m,
            param: param.to_string(),
        });
    }
    let end = S::one() + d1.checked_div(d0).unwrap_or_else(S::zero);
    let columns = mesh
        .to_columns()
        .iter()
        .map(|col| {
            (0..=r)
                .map(|k| {
                    let args: Vec<S> = std::iter::repeat_n(S::one(), m - k)
                        .chain(std::iter::repeat_n(end.clone(), k))
                        .collect();
                    blossom(col, &args)
                })
                .collect::<Result<Vec<_>, _>>()
        })
        .collect::<Result<Vec<_>, _>>()?;
    Mesh::from_columns(columns)
}
