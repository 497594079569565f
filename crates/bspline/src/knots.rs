//! Knot vectors in both conventions, their validation, domain and spans.

use crate::BSplineError;
use cagd_scalar::Scalar;
use std::cmp::Ordering;
use std::fmt;

/// How a knot vector is written.
///
/// For a curve of degree p with n control points `d_0, ..., d_{n-1}`:
///
/// - [`KnotConvention::Notes`] (Farin's, the notes'): n + p - 1 knots `u_0, ..., u_{n+p-2}`, and
///   the domain is `[u_{p-1}, u_{n-1}]`. The notes' quadratic circle with 9 control points has
///   the 10 knots `{0, 0, 1/4, 1/4, 1/2, 1/2, 3/4, 3/4, 1, 1}`; a clamped curve repeats each
///   end knot p times. Chapter 5: bidegree (m, n), M × N spans, knots `u_0, ..., u_{2m+M-2}`,
///   vertices `d_0, ..., d_{m+M-1}`, domain `[u_{m-1}, u_{m+M-1}]`.
/// - [`KnotConvention::Full`] (The NURBS Book and most libraries): one more knot at each end,
///   n + p + 1 knots, domain `[u_p, u_n]`; a clamped curve repeats each end knot p + 1 times.
///
/// The two extra end knots never affect the curve on its domain.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub enum KnotConvention {
    /// n + p - 1 knots, without end knots (the notes' convention, the default for output).
    #[default]
    Notes,
    /// n + p + 1 knots, one more at each end (The NURBS Book).
    Full,
}

impl KnotConvention {
    /// The number of knots of a curve of degree p with n control points in this convention:
    /// n + p - 1 (notes) or n + p + 1 (full).
    pub fn knot_count(self, degree: usize, points: usize) -> usize {
        match self {
            KnotConvention::Notes => (points + degree).saturating_sub(1),
            KnotConvention::Full => points + degree + 1,
        }
    }
}

/// A validated knot vector together with the degree it is read for.
///
/// Stored in one canonical form: the notes' knots with each end knot repeated once more (so
/// the full convention's slice is at hand for the algorithms of Piegl and Tiller, and the
/// notes' slice is the same vector without its first and last entries). Reading a vector in
/// the full convention therefore forgets its outermost two knots, which never affect the
/// curve: two vectors are equal exactly when they define the same B-spline basis on the
/// domain.
///
/// Rules (checked by every constructor): degree p ≥ 1; at least p + 1 control points; the
/// knots do not decrease; no knot appears more than p + 1 times in the notes' convention (an
/// interior knot of multiplicity p makes the curve C^0 through a control point, p + 1 lets it
/// jump there, as a derivative of a C^0 curve does; more would leave a basis function with no
/// support); and the domain has positive length. Any parameter interval is allowed, not only
/// [0, 1], and the ends may be clamped (multiplicity p in the notes) or not.
///
/// ```
/// use cagd_bspline::{KnotConvention, KnotVector};
/// use cagd_scalar::{q, BigRational, FieldOps, Print};
/// let full: Vec<BigRational> = [0, 0, 0, 1, 2, 2, 2].into_iter().map(BigRational::from_i64).collect();
/// let (u, conv) = KnotVector::read(full, 2, 4).unwrap();
/// assert_eq!(conv, KnotConvention::Full);
/// assert_eq!(u.to_text(), "{0, 0, 1, 2, 2}");
/// assert_eq!(u.to_text_in(KnotConvention::Full), "{0, 0, 0, 1, 2, 2, 2}");
/// assert_eq!(u.domain(), (q!(0), q!(2)));
/// assert_eq!(u.find_span(&q!(3/2)).unwrap(), 3);
/// assert_eq!(u.find_span(&q!(3)).unwrap_err().to_string(), "parameter t = 3 is outside the domain [0, 2]");
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct KnotVector<S> {
    degree: usize,
    /// The full convention: notes' knots with each end knot repeated once more.
    full: Vec<S>,
}

impl<S: Scalar> KnotVector<S> {
    /// Reads a knot vector for a curve of degree `degree` with `points` control points, in
    /// either convention, telling them apart by length: n + p - 1 knots is the notes'
    /// convention, n + p + 1 the full one. Any other length is an error stating both.
    ///
    /// ```
    /// use cagd_bspline::{KnotConvention, KnotVector};
    /// use cagd_scalar::{q, BigRational};
    /// let notes = vec![q!(0), q!(0), q!(1/4), q!(1/4), q!(1/2), q!(1/2), q!(3/4), q!(3/4), q!(1), q!(1)];
    /// let (u, conv) = KnotVector::read(notes, 2, 9).unwrap();
    /// assert_eq!(conv, KnotConvention::Notes);
    /// assert_eq!(u.to_text(), "{0, 0, 1/4, 1/4, 1/2, 1/2, 3/4, 3/4, 1, 1}");
    /// let err = KnotVector::<BigRational>::read(vec![q!(0); 11], 2, 9).unwrap_err();
    /// assert_eq!(err.to_string(), "a curve of degree 2 with 9 control points needs 10 knots \
    ///     (the notes' convention, without end knots) or 12 (with one more knot at each end, as \
    ///     in The NURBS Book); found 11");
    /// ```
    pub fn read(
        knots: Vec<S>,
        degree: usize,
        points: usize,
    ) -> Result<(Self, KnotConvention), BSplineError> {
        check_degree_points(degree, points)?;
        let convention = if knots.len() == KnotConvention::Notes.knot_count(degree, points) {
            KnotConvention::Notes
        } else if knots.len() == KnotConvention::Full.knot_count(degree, points) {
            KnotConvention::Full
        } else {
            return Err(BSplineError::KnotCount {
                degree,
                points,
                found: knots.len(),
            });
        };
        check_non_decreasing(&knots)?;
        let full = match convention {
            KnotConvention::Notes => pad(knots),
            KnotConvention::Full => normalize_ends(knots),
        };
        let u = KnotVector { degree, full };
        u.check_multiplicities()?;
        u.check_domain()?;
        Ok((u, convention))
    }

    /// A knot vector in the notes' convention (n + p - 1 knots); the number of control points
    /// is `knots.len() - p + 1`.
    pub fn from_notes(knots: Vec<S>, degree: usize) -> Result<Self, BSplineError> {
        let points = (knots.len() + 1).saturating_sub(degree);
        Self::read_as(knots, degree, points, KnotConvention::Notes)
    }

    /// A knot vector in the full convention (n + p + 1 knots); the number of control points is
    /// `knots.len() - p - 1`.
    pub fn from_full(knots: Vec<S>, degree: usize) -> Result<Self, BSplineError> {
        let points = knots.len().saturating_sub(degree + 1);
        Self::read_as(knots, degree, points, KnotConvention::Full)
    }

    fn read_as(
        knots: Vec<S>,
        degree: usize,
        points: usize,
        convention: KnotConvention,
    ) -> Result<Self, BSplineError> {
        check_degree_points(degree, points)?;
        if knots.len() != convention.knot_count(degree, points) {
            return Err(BSplineError::KnotCount {
                degree,
                points,
                found: knots.len(),
            });
        }
        Self::read(knots, degree, points).map(|(u, _)| u)
    }

    /// The clamped knot vector with these breakpoints `x_0 < x_1 < ... < x_L`: each end
    /// repeated p times (notes' convention), each interior breakpoint once, so the curve is
    /// C^{p-1} with L spans and L + p control points.
    ///
    /// ```
    /// use cagd_bspline::KnotVector;
    /// use cagd_scalar::q;
    /// let u = KnotVector::clamped(3, &[q!(0), q!(1/2), q!(1)]).unwrap();
    /// assert_eq!(u.to_text(), "{0, 0, 0, 1/2, 1, 1, 1}");
    /// assert_eq!(u.control_point_count(), 5);
    /// ```
    pub fn clamped(degree: usize, breakpoints: &[S]) -> Result<Self, BSplineError> {
        let (first, last) = match breakpoints {
            [first, .., last] => (first, last),
            _ => {
                return Err(BSplineError::TooFewPoints {
                    degree,
                    found: breakpoints.len(),
                })
            }
        };
        let mut knots = vec![first.clone(); degree];
        let inner = breakpoints.get(1..breakpoints.len().saturating_sub(1));
        knots.extend(inner.unwrap_or_default().iter().cloned());
        knots.extend(std::iter::repeat_n(last.clone(), degree));
        Self::from_notes(knots, degree)
    }

    /// The knot vector of one Bézier piece of degree p on [a, b]: a and b each p times.
    pub fn bezier(degree: usize, a: S, b: S) -> Result<Self, BSplineError> {
        Self::clamped(degree, &[a, b])
    }

    /// A knot vector from the full convention that is known to be valid (built by an
    /// algorithm of this crate); the end knots are normalized.
    pub(crate) fn from_full_trusted(full: Vec<S>, degree: usize) -> Self {
        KnotVector {
            degree,
            full: normalize_ends(full),
        }
    }

    /// The degree p the vector is read for.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The number n of control points: n + p - 1 knots in the notes' convention.
    pub fn control_point_count(&self) -> usize {
        self.full.len() - self.degree - 1
    }

    /// The number of control points after elevating the degree by `r`: each span gains `r`
    /// (every distinct knot's multiplicity rises by `r`), `n + r·s` for `s` spans. Known before
    /// the work, so that a size limit refuses it at once.
    pub fn elevated_point_count(&self, r: usize) -> usize {
        self.control_point_count()
            .saturating_add(r.saturating_mul(self.spans().len()))
    }

    /// The knots in the notes' convention `u_0, ..., u_{n+p-2}`.
    pub fn notes(&self) -> &[S] {
        // the full convention has at least 2p + 2 >= 4 knots
        self.full
            .get(1..self.full.len().saturating_sub(1))
            .unwrap_or(&self.full)
    }

    /// The knots in the full convention (Piegl and Tiller's `U = {u_0, ..., u_{n+p}}`), with
    /// the end knots repeated.
    pub fn full(&self) -> &[S] {
        &self.full
    }

    /// The knots in a convention, for printing and export.
    pub fn to_convention(&self, convention: KnotConvention) -> Vec<S> {
        match convention {
            KnotConvention::Notes => self.notes().to_vec(),
            KnotConvention::Full => self.full.clone(),
        }
    }

    /// The domain `[u_{p-1}, u_{n-1}]` (notes) `= [u_p, u_n]` (full).
    pub fn domain(&self) -> (S, S) {
        (self.start().clone(), self.end().clone())
    }

    /// The left end of the domain.
    // In range by the invariant of every constructor: n >= p + 1 control points and
    // n + p + 1 knots, so p < n < n + p + 1.
    #[allow(clippy::indexing_slicing)]
    pub fn start(&self) -> &S {
        &self.full[self.degree]
    }

    /// The right end of the domain.
    #[allow(clippy::indexing_slicing)] // as `start`
    pub fn end(&self) -> &S {
        &self.full[self.control_point_count()]
    }

    /// Whether `start <= t <= end`.
    pub fn contains(&self, t: &S) -> bool {
        self.start() <= t && t <= self.end()
    }

    /// An error naming the domain when t lies outside it.
    pub fn check_parameter(&self, t: &S) -> Result<(), BSplineError> {
        if self.contains(t) {
            Ok(())
        } else {
            Err(BSplineError::OutsideDomain {
                t: t.to_text(),
                start: self.start().to_text(),
                end: self.end().to_text(),
            })
        }
    }

    /// The span of t: the index k (full convention, as in Piegl and Tiller's `FindSpan`) with
    /// `u_k <= t < u_{k+1}`, p ≤ k ≤ n - 1; at the right end of the domain, the last non-empty
    /// span. The control points acting on it are `d_{k-p}, ..., d_k`; in the notes' convention
    /// the same span is `[u_{k-1}, u_k]`.
    pub fn find_span(&self, t: &S) -> Result<usize, BSplineError> {
        self.check_parameter(t)?;
        let n = self.control_point_count();
        if t == self.end() {
            return self.last_span();
        }
        // Largest k in [p, n - 1] with u_k <= t: binary search on the sorted knots.
        let (mut lo, mut hi) = (self.degree, n - 1);
        while lo < hi {
            let mid = (lo + hi).div_ceil(2);
            if self.full.get(mid).is_some_and(|u| u <= t) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        Ok(lo)
    }

    /// The last non-empty span of the domain.
    fn last_span(&self) -> Result<usize, BSplineError> {
        self.spans()
            .last()
            .copied()
            .ok_or(BSplineError::InvalidSpan { span: 0 })
    }

    /// The indices k (full convention) of the non-empty spans `[u_k, u_{k+1}]` of the domain,
    /// left to right.
    pub fn spans(&self) -> Vec<usize> {
        (self.degree..self.control_point_count())
            .filter(|&k| self.is_nonempty_span(k))
            .collect()
    }

    /// Whether u_k < u_{k+1}.
    fn is_nonempty_span(&self, k: usize) -> bool {
        match (self.full.get(k), self.full.get(k + 1)) {
            (Some(a), Some(b)) => a < b,
            _ => false,
        }
    }

    /// An error unless `span` is the index of a non-empty span of the domain.
    pub fn check_span(&self, span: usize) -> Result<(), BSplineError> {
        let ok =
            span >= self.degree && span < self.control_point_count() && self.is_nonempty_span(span);
        if ok {
            Ok(())
        } else {
            Err(BSplineError::InvalidSpan { span })
        }
    }

    /// How many times t appears in the notes' convention (0 if it is not a knot). The ends of
    /// a clamped vector have multiplicity p.
    pub fn multiplicity(&self, t: &S) -> usize {
        self.notes().iter().filter(|u| *u == t).count()
    }

    /// The distinct knots with their multiplicities (notes' convention), left to right.
    pub fn distinct(&self) -> Vec<(S, usize)> {
        let mut out: Vec<(S, usize)> = Vec::new();
        for u in self.notes() {
            match out.last_mut() {
                Some((v, m)) if v == u => *m += 1,
                _ => out.push((u.clone(), 1)),
            }
        }
        out
    }

    /// The breakpoints `a = x_0 < ... < x_L = b` of the domain with their multiplicities
    /// (notes' convention); the interior ones are where the polynomial pieces meet.
    pub fn breakpoints(&self) -> Vec<(S, usize)> {
        self.distinct()
            .into_iter()
            .filter(|(u, _)| self.contains(u))
            .collect()
    }

    /// The order of continuity p - s at a parameter t of multiplicity s (notes' convention)
    /// inside the domain: the curve is C^{p-s} there, and -1 means it may jump. A parameter
    /// that is not a knot gives p (the curve is polynomial, C^∞, around it).
    pub fn continuity(&self, t: &S) -> isize {
        let p = isize::try_from(self.degree).unwrap_or(isize::MAX);
        let s = isize::try_from(self.multiplicity(t)).unwrap_or(isize::MAX);
        p - s
    }

    /// Whether both ends are clamped: the first and the last knot of the notes' convention
    /// are repeated p times (at least), so the curve starts at d_0 and ends at d_{n-1}.
    pub fn is_clamped(&self) -> bool {
        let notes = self.notes();
        let p = self.degree;
        notes.iter().take(p).all(|u| u == self.start())
            && notes.iter().rev().take(p).all(|u| u == self.end())
    }

    /// Plain text in the notes' convention: `{0, 0, 1/4, 1/4, 1/2}`.
    pub fn to_text(&self) -> String {
        self.to_text_in(KnotConvention::Notes)
    }

    /// Plain text in a convention.
    pub fn to_text_in(&self, convention: KnotConvention) -> String {
        let parts: Vec<String> = match convention {
            KnotConvention::Notes => self.notes().iter().map(|u| u.to_text()).collect(),
            KnotConvention::Full => self.full.iter().map(|u| u.to_text()).collect(),
        };
        format!("{{{}}}", parts.join(", "))
    }

    /// LaTeX in a convention: `\{0, 0, \frac{1}{4}\}`.
    pub fn to_latex_in(&self, convention: KnotConvention) -> String {
        let parts: Vec<String> = self
            .to_convention(convention)
            .iter()
            .map(|u| u.to_latex())
            .collect();
        format!("\\{{{}\\}}", parts.join(", "))
    }

    /// The JSON form in a convention: one exact-number string per knot.
    pub fn to_json_strings(&self, convention: KnotConvention) -> Vec<String> {
        self.to_convention(convention)
            .iter()
            .map(|u| u.to_json_string())
            .collect()
    }

    fn check_multiplicities(&self) -> Result<(), BSplineError> {
        for (u, m) in self.distinct() {
            if m > self.degree + 1 {
                return Err(BSplineError::Multiplicity {
                    knot: u.to_text(),
                    multiplicity: m,
                    degree: self.degree,
                });
            }
        }
        Ok(())
    }

    fn check_domain(&self) -> Result<(), BSplineError> {
        if self.start() < self.end() {
            Ok(())
        } else {
            Err(BSplineError::EmptyDomain {
                start: self.start().to_text(),
                end: self.end().to_text(),
            })
        }
    }
}

/// How a knot vector is built from a degree p and a number of control points (The NURBS Book,
/// section 2.2 and eq. (2.13)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Spacing {
    /// Uniform: every knot of the full convention equally spaced, `u_i = a + i (b - a)/(n + p)`
    /// for n control points (the integers `0, 1, ..., n + p` when no interval is given).
    Uniform,
    /// Open uniform (clamped): each end knot p + 1 times in the full convention (p times in
    /// the notes'), the n - p - 1 interior knots equally spaced, so the curve starts at its
    /// first control point and ends at its last.
    OpenUniform,
}

/// The knots of a curve of degree p with `points` control points spaced as `spacing` asks, on
/// `[a, b]`, in the full convention (The NURBS Book's n + p + 1 knots); the notes' vector is
/// the same without its first and last knot.
///
/// ```
/// use cagd_bspline::{knots_spaced, Spacing};
/// use cagd_scalar::{q, BigRational, Print};
/// let text = |v: Vec<BigRational>| v.iter().map(|u| u.to_text()).collect::<Vec<_>>().join(", ");
/// let u = knots_spaced(Spacing::OpenUniform, 2, 5, &q!(0), &q!(1)).unwrap();
/// assert_eq!(text(u), "0, 0, 0, 1/3, 2/3, 1, 1, 1");
/// let u = knots_spaced(Spacing::Uniform, 2, 5, &q!(0), &q!(7)).unwrap();
/// assert_eq!(text(u), "0, 1, 2, 3, 4, 5, 6, 7");
/// ```
pub fn knots_spaced<S: Scalar>(
    spacing: Spacing,
    degree: usize,
    points: usize,
    a: &S,
    b: &S,
) -> Result<Vec<S>, BSplineError> {
    check_degree_points(degree, points)?;
    if !matches!(a.compare(b), Some(Ordering::Less)) {
        return Err(BSplineError::EmptyDomain {
            start: a.to_text(),
            end: b.to_text(),
        });
    }
    let length = b.sub_ref(a);
    let at = |i: usize, of: usize| -> Result<S, BSplineError> {
        let step = length
            .mul_ref(&scalar_of::<S>(i))
            .checked_div(&scalar_of::<S>(of))
            .ok_or_else(|| BSplineError::EmptyDomain {
                start: a.to_text(),
                end: b.to_text(),
            })?;
        Ok(a.add_ref(&step))
    };
    let count = points + degree + 1;
    match spacing {
        Spacing::Uniform => (0..count).map(|i| at(i, count - 1)).collect(),
        Spacing::OpenUniform => {
            let spans = points - degree;
            let mut out = vec![a.clone(); degree + 1];
            for j in 1..spans {
                out.push(at(j, spans)?);
            }
            out.extend(std::iter::repeat_n(b.clone(), degree + 1));
            Ok(out)
        }
    }
}

/// The distinct knots of a vector as it is written, with how many times each appears, left to
/// right (the knots are assumed sorted, as a valid vector's are).
///
/// ```
/// use cagd_bspline::multiplicities;
/// assert_eq!(multiplicities(&[0, 0, 0, 1, 2, 2, 3, 3, 3]), vec![(0, 3), (1, 1), (2, 2), (3, 3)]);
/// ```
pub fn multiplicities<S: PartialEq + Clone>(knots: &[S]) -> Vec<(S, usize)> {
    let mut out: Vec<(S, usize)> = Vec::new();
    for u in knots {
        match out.last_mut() {
            Some((v, m)) if v == u => *m += 1,
            _ => out.push((u.clone(), 1)),
        }
    }
    out
}

impl<S: Scalar> KnotVector<S> {
    /// The span of t as an index of the vector written in `convention`: the i with
    /// `u_i <= t < u_{i+1}` (The NURBS Book's `FindSpan`, algorithm A2.1, in the full
    /// convention; one less in the notes', which lacks the first knot), the last non-empty
    /// span at the right end of the domain.
    ///
    /// ```
    /// use cagd_bspline::{KnotConvention, KnotVector};
    /// use cagd_scalar::{q, BigRational, FieldOps};
    /// let full = [0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5].map(BigRational::from_i64).to_vec();
    /// let u = KnotVector::from_full(full, 2).unwrap();
    /// assert_eq!(u.span_in(&q!(5/2), KnotConvention::Full).unwrap(), 4);
    /// assert_eq!(u.span_in(&q!(5/2), KnotConvention::Notes).unwrap(), 3);
    /// assert_eq!(u.span_in(&q!(5), KnotConvention::Full).unwrap(), 7);
    /// ```
    pub fn span_in(&self, t: &S, convention: KnotConvention) -> Result<usize, BSplineError> {
        let k = self.find_span(t)?;
        Ok(match convention {
            KnotConvention::Full => k,
            KnotConvention::Notes => k - 1,
        })
    }

    /// The same vector reparametrized affinely onto [0, 1]: each knot u becomes
    /// (u - a)/(b - a), with [a, b] the domain. A curve on these knots with the same control
    /// points (and weights) is c((b - a) s + a): the same point set.
    ///
    /// ```
    /// use cagd_bspline::KnotVector;
    /// use cagd_scalar::q;
    /// let u = KnotVector::from_notes(vec![q!(2), q!(2), q!(3), q!(6), q!(6)], 2).unwrap();
    /// assert_eq!(u.normalized().to_text(), "{0, 0, 1/4, 1, 1}");
    /// ```
    pub fn normalized(&self) -> Self {
        KnotVector {
            degree: self.degree,
            full: normalize_list(&self.full, self.start(), self.end()),
        }
    }
}

/// The knots u of a list mapped to (u - a)/(b - a), for a < b (else the list as it is).
pub fn normalize_list<S: Scalar>(knots: &[S], a: &S, b: &S) -> Vec<S> {
    let length = b.sub_ref(a);
    knots
        .iter()
        .map(|u| {
            u.sub_ref(a)
                .checked_div(&length)
                .unwrap_or_else(|| u.clone())
        })
        .collect()
}

impl<S: Scalar> fmt::Display for KnotVector<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

fn check_degree_points(degree: usize, points: usize) -> Result<(), BSplineError> {
    if degree == 0 {
        return Err(BSplineError::InvalidDegree { degree });
    }
    if points < degree + 1 {
        return Err(BSplineError::TooFewPoints {
            degree,
            found: points,
        });
    }
    Ok(())
}

/// An error at the first index where the knots decrease (or where their order cannot be
/// decided, a NaN).
fn check_non_decreasing<S: Scalar>(knots: &[S]) -> Result<(), BSplineError> {
    for (index, (a, b)) in knots.iter().zip(knots.iter().skip(1)).enumerate() {
        let order = a.compare(b);
        if order.is_none() && S::is_exact() {
            return Err(BSplineError::KnotOrderUnknown {
                index: index + 1,
                difference: b.sub_ref(a).to_text(),
            });
        }
        if !matches!(order, Some(Ordering::Less | Ordering::Equal)) {
            return Err(BSplineError::DecreasingKnots {
                index: index + 1,
                before: a.to_text(),
                after: b.to_text(),
            });
        }
    }
    Ok(())
}

/// Notes' convention to full: repeat each end knot once more.
fn pad<S: Scalar>(notes: Vec<S>) -> Vec<S> {
    let mut full = Vec::with_capacity(notes.len() + 2);
    if let Some(first) = notes.first() {
        full.push(first.clone());
    }
    let last = notes.last().cloned();
    full.extend(notes);
    full.extend(last);
    full
}

/// The outermost knots of the full convention set to their neighbours (they never affect the
/// curve), so that each vector has one canonical form.
fn normalize_ends<S: Scalar>(mut full: Vec<S>) -> Vec<S> {
    if let [first, second, ..] = full.as_mut_slice() {
        *first = second.clone();
    }
    if let [.., before_last, last] = full.as_mut_slice() {
        *last = before_last.clone();
    }
    full
}

/// Converts a count to a scalar (counts are far below `i64::MAX`).
pub(crate) fn scalar_of<S: Scalar>(n: usize) -> S {
    S::from_i64(i64::try_from(n).unwrap_or(i64::MAX))
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational};

    fn qs(text: &[&str]) -> Vec<BigRational> {
        text.iter()
            .map(|t| cagd_scalar::parse_rational(t).unwrap())
            .collect()
    }

    #[test]
    fn circle_knots_in_both_conventions() {
        let notes = qs(&["0", "0", "1/4", "1/4", "1/2", "1/2", "3/4", "3/4", "1", "1"]);
        let full = qs(&[
            "0", "0", "0", "1/4", "1/4", "1/2", "1/2", "3/4", "3/4", "1", "1", "1",
        ]);
        let (a, ca) = KnotVector::read(notes.clone(), 2, 9).unwrap();
        let (b, cb) = KnotVector::read(full.clone(), 2, 9).unwrap();
        assert_eq!((ca, cb), (KnotConvention::Notes, KnotConvention::Full));
        assert_eq!(a, b);
        assert_eq!(a.to_convention(KnotConvention::Notes), notes);
        assert_eq!(a.to_convention(KnotConvention::Full), full);
        assert_eq!(a.domain(), (q!(0), q!(1)));
        assert!(a.is_clamped());
        assert_eq!(a.multiplicity(&q!(1 / 4)), 2);
        assert_eq!(a.multiplicity(&q!(0)), 2);
        assert_eq!(a.multiplicity(&q!(1 / 3)), 0);
        assert_eq!(a.continuity(&q!(1 / 2)), 0);
        // Full knots {0, 0, 0, 1/4, 1/4, 1/2, 1/2, 3/4, 3/4, 1, 1, 1}: spans u_2 < u_3, ...
        assert_eq!(a.spans(), vec![2, 4, 6, 8]);
        assert_eq!(a.find_span(&q!(0)).unwrap(), 2);
        assert_eq!(a.find_span(&q!(1 / 4)).unwrap(), 4);
        assert_eq!(a.find_span(&q!(1 / 8)).unwrap(), 2);
        assert_eq!(a.find_span(&q!(1)).unwrap(), 8);
        assert_eq!(
            a.find_span(&q!(3 / 2)).unwrap_err().to_string(),
            "parameter t = 3/2 is outside the domain [0, 1]"
        );
        assert_eq!(
            a.distinct(),
            vec![
                (q!(0), 2),
                (q!(1 / 4), 2),
                (q!(1 / 2), 2),
                (q!(3 / 4), 2),
                (q!(1), 2)
            ]
        );
        assert_eq!(
            a.to_latex_in(KnotConvention::Notes),
            r"\{0, 0, \frac{1}{4}, \frac{1}{4}, \frac{1}{2}, \frac{1}{2}, \frac{3}{4}, \frac{3}{4}, 1, 1\}"
        );
        assert_eq!(a.to_json_strings(KnotConvention::Notes)[2], "1/4");
    }

    #[test]
    fn full_convention_forgets_only_the_outer_knots() {
        // Unclamped, on [2, 5]: the outermost knots -7 and 100 never matter.
        let (a, _) =
            KnotVector::read(qs(&["-7", "1", "2", "3", "4", "5", "6", "100"]), 2, 5).unwrap();
        let b = KnotVector::from_notes(qs(&["1", "2", "3", "4", "5", "6"]), 2).unwrap();
        assert_eq!(a, b);
        assert_eq!(a.domain(), (q!(2), q!(5)));
        assert!(!a.is_clamped());
        assert_eq!(
            a.to_text_in(KnotConvention::Full),
            "{1, 1, 2, 3, 4, 5, 6, 6}"
        );
        assert_eq!(a.find_span(&q!(5)).unwrap(), 4);
        assert_eq!(a.find_span(&q!(2)).unwrap(), 2);
        assert_eq!(a.find_span(&q!(7 / 2)).unwrap(), 3);
    }

    #[test]
    fn validation_messages() {
        let e = KnotVector::read(qs(&["0", "0", "1/2", "1/4", "1", "1"]), 2, 5).unwrap_err();
        assert_eq!(e.to_string(), "knot vector decreases at index 3: 1/2 > 1/4");
        let e = KnotVector::read(qs(&["0", "0", "1", "1", "1", "1"]), 2, 5).unwrap_err();
        assert_eq!(
            e.to_string(),
            "knot 1 appears 4 times, but a curve of degree 2 allows at most 3 (the notes' \
             convention, without end knots)"
        );
        let e = KnotVector::read(qs(&["0", "1", "1", "2"]), 2, 3).unwrap_err();
        assert_eq!(
            e.to_string(),
            "the domain [1, 1] of the knot vector is empty: its ends must differ"
        );
        let e = KnotVector::read(qs(&["0", "1"]), 0, 3).unwrap_err();
        assert!(e.to_string().starts_with("degree 0 is not allowed"));
        let e = KnotVector::read(qs(&["0", "1"]), 3, 3).unwrap_err();
        assert_eq!(
            e.to_string(),
            "a B-spline curve of degree 3 needs at least 4 control points, found 3"
        );
        let e = KnotVector::from_full(qs(&["0", "0", "1", "1", "1"]), 2).unwrap_err();
        assert!(e.to_string().contains("needs at least 3 control points"));
        let e = KnotVector::read(vec![0.0, f64::NAN, 1.0], 1, 3).unwrap_err();
        assert_eq!(e.to_string(), "knot vector decreases at index 1: 0 > NaN");
    }

    #[test]
    fn clamped_and_jumps() {
        let u = KnotVector::clamped(2, &qs(&["-1", "0", "3"])).unwrap();
        assert_eq!(u.to_text(), "{-1, -1, 0, 3, 3}");
        assert_eq!(u.control_point_count(), 4);
        assert_eq!(u.breakpoints(), vec![(q!(-1), 2), (q!(0), 1), (q!(3), 2)]);
        // Multiplicity p + 1 inside the domain: allowed, the curve may jump.
        let j = KnotVector::from_notes(qs(&["0", "0", "1", "1", "1", "2", "2"]), 2).unwrap();
        assert_eq!(j.continuity(&q!(1)), -1);
        assert_eq!(j.find_span(&q!(1)).unwrap(), 5);
        assert_eq!(j.spans(), vec![2, 5]);
        assert!(KnotVector::<BigRational>::clamped(2, &qs(&["0"])).is_err());
    }
}
