//! Exact angles of a problem's arcs (`circle`, `revolution`), read before its numbers: the
//! square root their cosines and sines need (which decides the number field) and the default
//! number of arcs. Cos and sin of a rational number of degrees are both in a quadratic field
//! exactly for the multiples of 30° (Q(√3)) and of 45° (Q(√2)).

use cagd_scalar::BigRational;

/// The whole multiple k of `step` degrees that `deg` is, if it is one.
pub(crate) fn multiple(deg: &BigRational, step: i64) -> Option<i64> {
    let k = deg / BigRational::from_integer(step.into());
    if !k.is_integer() {
        return None;
    }
    i64::try_from(k.to_integer()).ok()
}

/// The root (2 or 3) the angles `start + k sweep/(2 arcs)` need, read from the problem's JSON
/// before its numbers are read (None when they are not plain rationals, or need none).
pub(crate) fn root_of_angles(start: &BigRational, sweep: &BigRational, arcs: usize) -> Option<u64> {
    let n = i64::try_from(arcs.max(1)).ok()?;
    let h = sweep / BigRational::from_integer((2 * n).into());
    let angles: Vec<BigRational> = (0..=2 * n)
        .map(|k| start + &h * BigRational::from_integer(k.into()))
        .collect();
    if angles.iter().all(|a| multiple(a, 90).is_some()) {
        None
    } else if angles.iter().all(|a| multiple(a, 30).is_some()) {
        Some(3)
    } else {
        Some(2)
    }
}

/// The default number of arcs of a sweep: arcs of at most 90°.
pub(crate) fn default_arcs(sweep: &BigRational) -> usize {
    let q = sweep / BigRational::from_integer(90.into());
    let n = q.ceil().to_integer();
    usize::try_from(n).unwrap_or(1).max(1)
}
