//! Checked access for the index arithmetic of the algorithms (De Boor, Boehm, Cox–de Boor):
//! the indices follow from a span the knot vector has validated, so they are in range; if an
//! invariant were ever broken, the algorithm returns [`BSplineError::InvalidSpan`] instead of
//! panicking.

use crate::BSplineError;

/// `list[i]`.
pub(crate) fn at<T>(list: &[T], i: usize, span: usize) -> Result<&T, BSplineError> {
    list.get(i).ok_or(BSplineError::InvalidSpan { span })
}

/// `&mut list[i]`.
pub(crate) fn at_mut<T>(list: &mut [T], i: usize, span: usize) -> Result<&mut T, BSplineError> {
    list.get_mut(i).ok_or(BSplineError::InvalidSpan { span })
}

/// `list[first..=last]`.
pub(crate) fn slice<T>(
    list: &[T],
    first: usize,
    last: usize,
    span: usize,
) -> Result<&[T], BSplineError> {
    list.get(first..=last)
        .ok_or(BSplineError::InvalidSpan { span })
}
