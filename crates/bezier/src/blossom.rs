//! The polar form (blossom) of a Bézier curve and the restriction to an interval.

use crate::polygon::{check_polygon, lerp_level};
use crate::BezierError;
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// The blossom (polar form) `c[t_1, ..., t_n]` of the degree-n curve with control points
/// `c_0, ..., c_n`: De Casteljau's algorithm with the parameter `t_r` at level r,
///
/// `c_i^r = (1 - t_r) c_i^{r-1} + t_r c_{i+1}^{r-1}`, `c[t_1, ..., t_n] = c_0^n`.
///
/// It is symmetric, affine in each argument, and `c[t, ..., t] = c(t)`; the control points
/// are `c_i = c[0^<n-i>, 1^<i>]`. `args.len()` must equal the degree n.
///
/// ```
/// use cagd_bezier::blossom;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let c: Vec<Point<BigRational>> =
///     vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2]), Point::from_ints(&[3, 3])];
/// assert_eq!(blossom(&c, &[q!(0), q!(1)]).unwrap().to_text(), "(1, 2)");
/// assert_eq!(blossom(&c, &[q!(1/3), q!(1/2)]).unwrap().to_text(), "(1, 3/2)");
/// assert!(blossom(&c, &[q!(1/3)]).is_err());
/// ```
pub fn blossom<S: Scalar>(points: &[Point<S>], args: &[S]) -> Result<Point<S>, BezierError> {
    check_polygon(points)?;
    let degree = points.len() - 1;
    if args.len() != degree {
        return Err(BezierError::BlossomArguments {
            degree,
            found: args.len(),
        });
    }
    let mut work = points.to_vec();
    for t in args {
        lerp_level(&mut work, t);
    }
    work.into_iter().next().ok_or(BezierError::EmptyPolygon)
}

/// The control points of the curve restricted to [a, b] and reparametrized over [0, 1]
/// (`c̃(s) = c((1 - s) a + s b)`), by the blossom:
///
/// `c̃_i = c[a^<n-i>, b^<i>]`, `i = 0..n`.
///
/// Any a ≠ b is accepted (a > b reverses the orientation; [a, b] may reach outside [0, 1]);
/// a = b is an error, since the restriction would collapse to a point.
///
/// ```
/// use cagd_bezier::restrict;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let c: Vec<Point<BigRational>> =
///     vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2]), Point::from_ints(&[3, 3])];
/// let r = restrict(&c, &q!(1/3), &q!(1/2)).unwrap();
/// let text: Vec<String> = r.iter().map(|p| p.to_text()).collect();
/// assert_eq!(text, ["(7/9, 11/9)", "(1, 3/2)", "(5/4, 7/4)"]);
/// ```
pub fn restrict<S: Scalar>(
    points: &[Point<S>],
    a: &S,
    b: &S,
) -> Result<Vec<Point<S>>, BezierError> {
    check_polygon(points)?;
    if a == b {
        return Err(BezierError::DegenerateInterval {
            a: a.to_text(),
            b: b.to_text(),
        });
    }
    let n = points.len() - 1;
    // c[a^<n-i>, b^<i>]: the blossom is symmetric, so the order of the arguments is free.
    (0..=n)
        .map(|i| {
            let args: Vec<S> = std::iter::repeat_n(a.clone(), n - i)
                .chain(std::iter::repeat_n(b.clone(), i))
                .collect();
            blossom(points, &args)
        })
        .collect()
}
