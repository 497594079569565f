//! Every error, with the message a student reads.

use crate::common::{pt, r, Q};
use cagd_triangle::{Barycentric, Direction, TriangleError, TriangularPatch};

fn linear() -> TriangularPatch<Q> {
    TriangularPatch::try_new(1, vec![pt(&[0, 0]), pt(&[1, 0]), pt(&[0, 1])]).unwrap()
}

#[test]
fn wrong_number_of_control_points() {
    let err = TriangularPatch::<Q>::try_new(3, vec![pt(&[0]); 9]).unwrap_err();
    assert_eq!(
        err,
        TriangleError::WrongPointCount {
            degree: 3,
            needed: 10,
            found: 9
        }
    );
    assert_eq!(
        err.to_string(),
        "a triangular patch of degree 3 needs (3 + 1)(3 + 2)/2 = 10 control points, found 9"
    );
    assert!(TriangularPatch::<Q>::try_new(0, vec![]).is_err());
    assert!(TriangularPatch::<Q>::try_new(0, vec![pt(&[7])]).is_ok());
}

#[test]
fn degree_too_large() {
    let err = TriangularPatch::<Q>::try_new(usize::MAX, vec![]).unwrap_err();
    assert!(matches!(err, TriangleError::DegreeTooLarge { .. }));
    assert!(err
        .to_string()
        .starts_with(&format!("degree {} is too large", usize::MAX)));
    let err = linear().elevate_degree_by(usize::MAX).unwrap_err();
    assert_eq!(
        err.to_string(),
        format!(
            "degree 1 + {} is too large: its (n + 1)(n + 2)/2 control points cannot be stored",
            usize::MAX
        )
    );
}

#[test]
fn mixed_dimensions() {
    let pts = vec![
        pt(&[0, 0, 0]),
        pt(&[1, 0, 0]),
        pt(&[0, 1, 0]),
        pt(&[2, 0, 0]),
        pt(&[1, 1]),
        pt(&[0, 2, 0]),
    ];
    let err = TriangularPatch::try_new(2, pts).unwrap_err();
    assert_eq!(
        err.to_string(),
        "control point b_{0,1,1} has dimension 2, but the first control point has dimension 3: \
         all control points need the same dimension"
    );
}

#[test]
fn barycentric_coordinates_must_sum_to_one() {
    let err = Barycentric::try_new(r(1, 2), r(1, 2), r(1, 2)).unwrap_err();
    assert_eq!(
        err.to_string(),
        "barycentric coordinates (1/2, 1/2, 1/2) sum to 3/2, not 1 (r + s + t = 1 is needed)"
    );
    // negative coordinates are fine: the point is outside the triangle
    assert!(Barycentric::try_new(r(-1, 1), r(3, 2), r(1, 2)).is_ok());
    // f64: the floating-point sum is checked, so build such points from (u, v)
    let err = Barycentric::try_new(0.3, 0.6, 0.1).unwrap_err();
    assert!(
        err.to_string().contains("sum to 0.9999999999999999, not 1"),
        "{err}"
    );
    assert_eq!(Barycentric::from_uv(0.6, 0.1).coords()[1], 0.6);
}

#[test]
fn directions_must_sum_to_zero() {
    let err = Direction::try_new(r(1, 3), r(1, 3), r(1, 3)).unwrap_err();
    assert_eq!(
        err.to_string(),
        "direction (1/3, 1/3, 1/3) has components summing to 1, not 0 \
         (a direction is a difference of two barycentric points)"
    );
    let d = Direction::between(&Barycentric::e1(), &Barycentric::<Q>::centroid());
    assert_eq!(d.to_text(), "(-2/3, 1/3, 1/3)");
    assert_eq!(Direction::<Q>::from_uv(r(1, 1), r(0, 1)), Direction::du());
    assert_eq!(Direction::<Q>::from_uv(r(0, 1), r(1, 1)), Direction::dv());
}

#[test]
fn blossom_needs_n_arguments() {
    let err = linear().blossom(&[]).unwrap_err();
    assert_eq!(
        err.to_string(),
        "the blossom of a patch of degree 1 takes 1 argument, found 0"
    );
    assert!(linear()
        .blossom_recorded(&[Barycentric::e1(), Barycentric::e2()], &mut Vec::new())
        .is_err());
}

#[test]
fn control_point_index_must_sum_to_degree() {
    let err = linear().point(1, 1, 0).unwrap_err();
    assert_eq!(
        err.to_string(),
        "b_{1,1,0} is not a control point of a patch of degree 1: 1 + 1 + 0 = 2, not 1"
    );
    assert_eq!(linear().point(0, 1, 0).unwrap(), &pt(&[1, 0]));
}

#[test]
fn normal_needs_r3() {
    let err = linear().normal(&Barycentric::centroid()).unwrap_err();
    assert_eq!(
        err.to_string(),
        "the normal vector needs control points in R^3, but they have dimension 2"
    );
    let flat =
        TriangularPatch::try_new(1, vec![pt(&[0, 0, 0]), pt(&[1, 0, 0]), pt(&[0, 1, 0])]).unwrap();
    assert_eq!(
        flat.normal(&Barycentric::centroid()).unwrap(),
        pt(&[0, 0, 1])
    );
    assert_eq!(flat.normal(&Barycentric::e1()).unwrap(), pt(&[0, 0, 1]));
}
