//! The charts of scalar quantities.

use crate::debug_out::save;
use crate::scenes;
use cagd_poly::{parse_poly, Var};
use cagd_render::{
    gaussian_numerator, gaussian_signs, plot_gaussian_sign, plot_polynomial, plot_weights,
    AnySurface, CurvatureSign, PlotOptions,
};
use cagd_scalar::{parse_number, q, BigRational, Quadratic};

#[test]
fn developability_polynomial_marks_its_exact_zeros() {
    let p = parse_poly::<BigRational>("12 u - 8 u^3 - 4 u^2").unwrap();
    let svg = plot_polynomial(&p, Var::U, (q!(0), q!(1)), &PlotOptions::default()).unwrap();
    save("plot-developability", &svg);
    // p(0) = 0 and p(1) = 12 - 8 - 4 = 0: both marked, nothing else
    assert_eq!(svg.matches("<circle").count(), 2);
    assert!(svg.contains(">u = 0<") && svg.contains(">u = 1<"));
    assert!(svg.contains("p(u) = -8 u^3 - 4 u^2 + 12 u"));
    // the exact tick labels of [0, 1]
    for t in ["0", "1/4", "1/2", "3/4", "1"] {
        assert!(svg.contains(&format!(">{t}</text>")), "tick {t}");
    }
    assert!(plot_polynomial(&p, Var::V, (q!(0), q!(1)), &PlotOptions::default()).is_err());
    assert!(plot_polynomial(&p, Var::U, (q!(1), q!(0)), &PlotOptions::default()).is_err());
}

#[test]
fn weights_of_the_sphere_octant_show_exact_labels() {
    let w: Vec<Quadratic> = ["sqrt2/2", "1/2", "sqrt2/2"]
        .iter()
        .map(|t| parse_number(t).unwrap())
        .collect();
    let svg = plot_weights(&w, None, &PlotOptions::default()).unwrap();
    save("plot-weights", &svg);
    assert_eq!(svg.matches(">√2/2<").count(), 2);
    assert!(svg.contains(">1/2<") && svg.contains(">w_2<"));
    assert_eq!(svg.matches("<rect").count(), 4, "background and three bars");
    assert!(plot_weights::<BigRational>(&[], None, &PlotOptions::default()).is_err());
}

#[test]
fn ruled_patch_has_no_positive_curvature() {
    let ruled = AnySurface::Bezier(scenes::ruled_patch::<BigRational>());
    let signs = gaussian_signs(&ruled, 8).unwrap();
    assert!(signs
        .iter()
        .flatten()
        .all(|s| *s != CurvatureSign::Positive));
    assert!(signs
        .iter()
        .flatten()
        .any(|s| *s == CurvatureSign::Negative));
    // the polynomial route agrees: numerator = -(c_uv · n)^2 <= 0
    let AnySurface::Bezier(patch) = &ruled else {
        unreachable!()
    };
    let k = gaussian_numerator(&patch.closed_form().unwrap()).unwrap();
    for i in 0..8 {
        for j in 0..8 {
            let (u, v) = (
                q!(1 / 16) * BigRational::from_integer((2 * i + 1).into()),
                q!(1 / 16) * BigRational::from_integer((2 * j + 1).into()),
            );
            let value = k.eval(&[(Var::U, u), (Var::V, v)]).unwrap();
            let expected = if value < q!(0) {
                CurvatureSign::Negative
            } else if value == q!(0) {
                CurvatureSign::Zero
            } else {
                CurvatureSign::Positive
            };
            assert_eq!(signs[i][j], expected, "cell ({i}, {j})");
        }
    }
    let svg = plot_gaussian_sign(&ruled, 8, &PlotOptions::default()).unwrap();
    save("plot-curvature-ruled", &svg);
    assert!(svg.contains("K &lt; 0 (hyperbolic)"));
}

#[test]
fn sphere_octant_is_elliptic_everywhere() {
    let sphere = AnySurface::RationalBezier(scenes::sphere_octant());
    let signs = gaussian_signs(&sphere, 6).unwrap();
    assert!(
        signs
            .iter()
            .flatten()
            .all(|s| *s == CurvatureSign::Positive),
        "{signs:?}"
    );
    let svg = plot_gaussian_sign(&sphere, 6, &PlotOptions::default()).unwrap();
    save("plot-curvature-sphere", &svg);
    assert!(svg.contains("K &gt; 0 (elliptic): 36"));
}

#[test]
fn coons_patch_changes_sign() {
    let coons = AnySurface::Bezier(scenes::coons_patch::<BigRational>());
    let signs = gaussian_signs(&coons, 10).unwrap();
    let svg = plot_gaussian_sign(&coons, 10, &PlotOptions::default()).unwrap();
    save("plot-curvature-coons", &svg);
    assert_eq!(signs.len(), 10);
    assert!(signs.iter().all(|r| r.len() == 10));
    let count = |s: CurvatureSign| signs.iter().flatten().filter(|x| **x == s).count();
    assert_eq!(count(CurvatureSign::Positive), 89);
    assert_eq!(count(CurvatureSign::Negative), 11);
    assert!(svg.contains("K &gt; 0 (elliptic): 89") && svg.contains("K &lt; 0 (hyperbolic): 11"));
    // f64 evaluation of the same numerator agrees with the exact signs away from zero
    let AnySurface::Bezier(patch) = &coons else {
        unreachable!()
    };
    let k = gaussian_numerator(&patch.closed_form().unwrap()).unwrap();
    let kf = k.convert::<f64>().unwrap();
    for i in 0..10 {
        for j in 0..10 {
            let (u, v) = ((2 * i + 1) as f64 / 20.0, (2 * j + 1) as f64 / 20.0);
            let x = kf.eval(&[(Var::U, u), (Var::V, v)]).unwrap();
            if x.abs() > 1e-9 {
                let s = if x > 0.0 {
                    CurvatureSign::Positive
                } else {
                    CurvatureSign::Negative
                };
                assert_eq!(signs[i][j], s, "cell ({i}, {j}): {x}");
            }
        }
    }
}
