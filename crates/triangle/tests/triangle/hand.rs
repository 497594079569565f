//! Values computed by hand.

use crate::common::{pt, r, Q};
use cagd_linalg::Point;
use cagd_triangle::{bernstein_basis, Barycentric, Direction, Edge, TriangularPatch};

/// The quadratic net of the hand computations:
/// b200 = (0,0,0), b110 = (1,0,1), b101 = (0,1,2), b020 = (2,0,0), b011 = (1,1,3), b002 = (0,2,0).
fn quadratic() -> TriangularPatch<Q> {
    TriangularPatch::try_new(
        2,
        vec![
            pt(&[0, 0, 0]),
            pt(&[1, 0, 1]),
            pt(&[0, 1, 2]),
            pt(&[2, 0, 0]),
            pt(&[1, 1, 3]),
            pt(&[0, 2, 0]),
        ],
    )
    .unwrap()
}

#[test]
fn quadratic_patch_at_the_centroid() {
    // At (1/3, 1/3, 1/3): B_200 = B_020 = B_002 = 1/9, B_110 = B_101 = B_011 = 2/9, so
    // b = (1/9)(2, 2, 0) + (2/9)(2, 2, 6) = (2/3, 2/3, 4/3).
    let patch = quadratic();
    let c = Barycentric::centroid();
    assert_eq!(
        bernstein_basis(2, &c),
        vec![r(1, 9), r(2, 9), r(2, 9), r(1, 9), r(2, 9), r(1, 9)]
    );
    assert_eq!(patch.evaluate_bernstein(&c).to_text(), "(2/3, 2/3, 4/3)");
    // De Casteljau: level 1 is the average of each small triangle of the net,
    // b^1_100 = (1,1,3)/3, b^1_010 = (4,1,4)/3, b^1_001 = (1,4,5)/3; level 2 their average.
    let steps = patch.de_casteljau(&c);
    assert_eq!(
        steps.to_text(),
        "level 0:\n  b^0_{2,0,0} = (0, 0, 0)\n  b^0_{1,1,0} = (1, 0, 1)\n  b^0_{1,0,1} = (0, 1, 2)\n  \
         b^0_{0,2,0} = (2, 0, 0)\n  b^0_{0,1,1} = (1, 1, 3)\n  b^0_{0,0,2} = (0, 2, 0)\n\
         level 1:\n  b^1_{1,0,0} = (1/3, 1/3, 1)\n  b^1_{0,1,0} = (4/3, 1/3, 4/3)\n  \
         b^1_{0,0,1} = (1/3, 4/3, 5/3)\n\
         level 2:\n  b^2_{0,0,0} = (2/3, 2/3, 4/3)"
    );
    assert_eq!(
        steps.point(1, 0, 1, 0).unwrap().to_text(),
        "(4/3, 1/3, 4/3)"
    );
    assert_eq!(steps.point(1, 1, 1, 0), None);
    assert_eq!(steps.value(), &patch.evaluate(&c));
    assert_eq!(steps.into_value().to_text(), "(2/3, 2/3, 4/3)");
}

#[test]
fn quadratic_patch_derivatives_and_normal_at_the_centroid() {
    // ∂u = 2(b^1_010 - b^1_100) = (2, 0, 2/3); ∂v = 2(b^1_001 - b^1_100) = (0, 2, 4/3)
    let patch = quadratic();
    let c = Barycentric::centroid();
    let du = patch.directional_derivative(&c, &Direction::du());
    let dv = patch.directional_derivative(&c, &Direction::dv());
    assert_eq!(du.to_text(), "(2, 0, 2/3)");
    assert_eq!(dv.to_text(), "(0, 2, 4/3)");
    let steps = patch.de_casteljau(&c);
    assert_eq!(steps.directional_derivative(&Direction::du()), du);
    // (2, 0, 2/3) × (0, 2, 4/3) = (-4/3, -8/3, 4)
    assert_eq!(patch.normal(&c).unwrap().to_text(), "(-4/3, -8/3, 4)");
    // the u-derivative patch: 2(b_{i,j+1,k} - b_{i+1,j,k})
    let dpatch = patch.derivative(&Direction::du());
    assert_eq!(dpatch.degree(), 1);
    assert_eq!(
        dpatch.to_text(),
        "b_{1,0,0} = (2, 0, 2)\nb_{0,1,0} = (2, 0, -2)\nb_{0,0,1} = (2, 0, 2)"
    );
    // second derivative ∂uu = 2 (b200 - 2 b110 + b020) = (0, 0, -4)
    let duu = patch.higher_derivative(&c, &[Direction::du(), Direction::du()]);
    assert_eq!(duu.to_text(), "(0, 0, -4)");
    assert_eq!(
        patch.higher_derivative(&c, &vec![Direction::du(); 3]),
        pt(&[0, 0, 0])
    );
    assert_eq!(patch.higher_derivative(&c, &[]), patch.evaluate(&c));
}

#[test]
fn quadratic_patch_blossom_by_hand() {
    // b[e1, e2] = b110, and b[x, y] for x = (1/2, 1/2, 0), y = (0, 0, 1):
    // the first step at x gives b^1_{100} = (b200 + b110)/2 = (1/2, 0, 1/2),
    // b^1_{010} = (b110 + b020)/2 = (3/2, 0, 1/2), b^1_{001} = (b101 + b011)/2 = (1/2, 1, 5/2);
    // the step at y keeps b^1_{001}.
    let patch = quadratic();
    let (e1, e2, e3) = (Barycentric::e1(), Barycentric::e2(), Barycentric::e3());
    assert_eq!(
        patch.blossom(&[e1.clone(), e2.clone()]).unwrap(),
        pt(&[1, 0, 1])
    );
    let x = Barycentric::try_new(r(1, 2), r(1, 2), r(0, 1)).unwrap();
    assert_eq!(
        patch.blossom(&[x.clone(), e3.clone()]).unwrap().to_text(),
        "(1/2, 1, 5/2)"
    );
    assert_eq!(patch.blossom(&[e3, x]).unwrap().to_text(), "(1/2, 1, 5/2)");
    let mut levels = Vec::new();
    let value = patch.blossom_recorded(&[e1, e2], &mut levels).unwrap();
    assert_eq!(levels[1][0], pt(&[0, 0, 0]));
    assert_eq!(levels[2], [pt(&[1, 0, 1])]);
    assert_eq!(value, pt(&[1, 0, 1]));
}

#[test]
fn linear_patch_is_barycentric_interpolation() {
    let (p, q, s) = (pt(&[1, 2, 3]), pt(&[-4, 0, 5]), pt(&[2, -7, 1]));
    let patch = TriangularPatch::try_new(1, vec![p.clone(), q.clone(), s.clone()]).unwrap();
    for (a, b) in [(r(1, 3), r(1, 5)), (r(-1, 2), r(2, 3)), (r(0, 1), r(1, 1))] {
        let x = Barycentric::from_uv(a, b);
        let expected = Point::combination([&p, &q, &s], x.coords(), 3);
        assert_eq!(patch.evaluate(&x), expected);
        assert_eq!(patch.evaluate_bernstein(&x), expected);
    }
    // its derivative in the direction e2 - e1 is q - p everywhere
    assert_eq!(patch.derivative(&Direction::du()).points(), &[&q - &p]);
}

#[test]
fn elevation_and_split_by_hand() {
    // linear (0,0), (2,0), (0,2) elevated: the midpoints of the edges
    let lin =
        TriangularPatch::<Q>::try_new(1, vec![pt(&[0, 0]), pt(&[2, 0]), pt(&[0, 2])]).unwrap();
    assert_eq!(
        lin.elevate_degree().to_text(),
        "b_{2,0,0} = (0, 0)\nb_{1,1,0} = (1, 0)\nb_{1,0,1} = (0, 1)\nb_{0,2,0} = (2, 0)\nb_{0,1,1} = (1, 1)\nb_{0,0,2} = (0, 2)"
    );
    // quadratic: b^3_{111} = (b011 + b101 + b110)/3 = (2, 2, 6)/3
    let up = quadratic().elevate_degree();
    assert_eq!(up.point(1, 1, 1).unwrap().to_text(), "(2/3, 2/3, 2)");
    // b^3_{210} = (2 b110 + b200)/3 = (2/3, 0, 2/3)
    assert_eq!(up.point(2, 1, 0).unwrap().to_text(), "(2/3, 0, 2/3)");
    // split at the centroid: the patch over (x, e2, e3) has b^2_000 as its first corner and
    // keeps the edge r = 0 of the original
    let [a, _, _] = quadratic().split(&Barycentric::centroid());
    assert_eq!(a.point(2, 0, 0).unwrap().to_text(), "(2/3, 2/3, 4/3)");
    assert_eq!(a.point(1, 1, 0).unwrap().to_text(), "(4/3, 1/3, 4/3)");
    assert_eq!(
        a.boundary_curve(Edge::R0),
        quadratic().boundary_curve(Edge::R0)
    );
}

#[test]
fn boundary_and_corners() {
    let patch = quadratic();
    let [c1, c2, c3] = patch.corners();
    assert_eq!(
        (c1, c2, c3),
        (&pt(&[0, 0, 0]), &pt(&[2, 0, 0]), &pt(&[0, 2, 0]))
    );
    assert_eq!(
        patch.boundary_curve(Edge::T0),
        vec![pt(&[0, 0, 0]), pt(&[1, 0, 1]), pt(&[2, 0, 0])]
    );
    assert_eq!(
        patch.boundary_curve(Edge::R0),
        vec![pt(&[2, 0, 0]), pt(&[1, 1, 3]), pt(&[0, 2, 0])]
    );
    assert_eq!(
        patch.boundary_curve(Edge::S0),
        vec![pt(&[0, 2, 0]), pt(&[0, 1, 2]), pt(&[0, 0, 0])]
    );
    // the middle of edge r = 0 is (b020 + 2 b011 + b002)/4 = (1, 1, 3/2)
    let mid = Edge::R0.point_at(&r(1, 2));
    assert_eq!(mid.to_text(), "(0, 1/2, 1/2)");
    assert_eq!(patch.evaluate(&mid).to_text(), "(1, 1, 3/2)");
    assert_eq!(patch.evaluate(&Barycentric::e2()), *c2);
}

#[test]
fn degree_zero_is_a_constant() {
    let c = TriangularPatch::<Q>::try_new(0, vec![pt(&[4, 5])]).unwrap();
    let x = Barycentric::from_uv(r(1, 7), r(3, 7));
    assert_eq!(c.evaluate(&x), pt(&[4, 5]));
    assert_eq!(c.evaluate_bernstein(&x), pt(&[4, 5]));
    assert_eq!(c.blossom(&[]).unwrap(), pt(&[4, 5]));
    assert_eq!(c.directional_derivative(&x, &Direction::du()), pt(&[0, 0]));
    assert_eq!(
        c.de_casteljau(&x).directional_derivative(&Direction::du()),
        pt(&[0, 0])
    );
    assert_eq!(
        c.elevate_degree().points(),
        &[pt(&[4, 5]), pt(&[4, 5]), pt(&[4, 5])]
    );
    assert_eq!(c.split(&x)[1], c);
    assert_eq!(c.boundary_curve(Edge::S0), vec![pt(&[4, 5])]);
}

#[test]
fn from_fn_and_printing() {
    // the net of z = u v: b_{ijk} = (j/2, k/2, [j = k = 1]/2)
    let patch = TriangularPatch::from_fn(2, |(_, j, k)| {
        let z = if (j, k) == (1, 1) { r(1, 2) } else { r(0, 1) };
        Point::new(vec![r(j as i64, 2), r(k as i64, 2), z])
    })
    .unwrap();
    assert_eq!(
        patch.evaluate_uv(r(2, 3), r(1, 4)).to_text(),
        "(2/3, 1/4, 1/6)"
    );
    assert_eq!(
        patch.to_latex().lines().nth(4),
        Some(r"b_{0,1,1} = \left(\frac{1}{2}, \frac{1}{2}, \frac{1}{2}\right) \\")
    );
    assert_eq!(
        patch.indexed_points().nth(2).map(|(idx, _)| idx),
        Some((1, 0, 1))
    );
    assert!(format!("{patch:?}").starts_with("TriangularPatch(degree 2; (0, 0, 0), (1/2, 0, 0)"));
}
