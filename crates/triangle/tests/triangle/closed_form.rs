//! The closed form in (u, v) (through cagd-poly), and back.

use crate::common::{bary, direction, patch, pt, Q};
use cagd_poly::{parse_vec_poly, Poly, Var};
use cagd_triangle::{Direction, TriangleError, TriangularPatch};
use proptest::prelude::*;

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
fn quadratic_closed_form_by_hand() {
    // x = 2rs + 2s^2 + 2st = 2s = 2u, y = 2v,
    // z = 2rs + 4rt + 6st = 2u(1-u-v) + 4v(1-u-v) + 6uv = -2u^2 - 4v^2 + 2u + 4v
    let f = quadratic().closed_form();
    assert_eq!(f.to_text(), "(2 u, 2 v, -2 u^2 - 4 v^2 + 2 u + 4 v)");
    assert_eq!(
        f,
        parse_vec_poly("(2u, 2v, 2u + 4v - 2u^2 - 4v^2)").unwrap()
    );
    assert_eq!(
        TriangularPatch::from_closed_form(&f, 2).unwrap(),
        quadratic()
    );
}

#[test]
fn from_closed_form_by_hand_and_errors() {
    // z = u v over the triangle as a quadratic patch: b_{011} = (1/2, 1/2, 1/2)
    let f = parse_vec_poly::<Q>("(u, v, u*v)").unwrap();
    let p = TriangularPatch::from_closed_form(&f, 2).unwrap();
    assert_eq!(p.point(0, 1, 1).unwrap().to_text(), "(1/2, 1/2, 1/2)");
    assert_eq!(p.point(1, 1, 0).unwrap().to_text(), "(1/2, 0, 0)");
    // as a cubic, it is the elevated quadratic
    assert_eq!(
        TriangularPatch::from_closed_form(&f, 3).unwrap(),
        p.elevate_degree()
    );
    let err = TriangularPatch::from_closed_form(&f, 1).unwrap_err();
    assert_eq!(
        err,
        TriangleError::DegreeTooHigh {
            found: 2,
            degree: 1
        }
    );
    assert_eq!(
        err.to_string(),
        "the polynomial map has total degree 2, more than the degree 1 of the patch asked for \
         (ask for degree 2 or more)"
    );
    let g = parse_vec_poly::<Q>("(u, v, w)").unwrap();
    assert_eq!(
        TriangularPatch::from_closed_form(&g, 1)
            .unwrap_err()
            .to_string(),
        "a triangular patch is a polynomial map in u and v only, but the map also uses w"
    );
}

#[test]
fn closed_form_of_a_degree_zero_patch() {
    let c = TriangularPatch::<Q>::try_new(0, vec![pt(&[3, -1])]).unwrap();
    assert_eq!(c.closed_form().to_text(), "(3, -1)");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn closed_form_agrees_with_evaluation(p in patch(), x in bary()) {
        let (u, v) = x.to_uv();
        let f = p.closed_form();
        prop_assert!(f.degree() as usize <= p.degree());
        prop_assert_eq!(f.eval(&[(Var::U, u), (Var::V, v)]).unwrap(), p.evaluate(&x));
        prop_assert_eq!(&TriangularPatch::from_closed_form(&f, p.degree()).unwrap(), &p);
        prop_assert_eq!(
            TriangularPatch::from_closed_form(&f, p.degree() + 1).unwrap(),
            p.elevate_degree()
        );
    }

    #[test]
    fn directional_derivative_agrees_with_the_closed_form(p in patch(), x in bary(), d in direction()) {
        // d = (-a - b, a, b) is the vector (a, b) of the (u, v) plane: D_d b = a ∂b/∂u + b ∂b/∂v
        let f = p.closed_form();
        let (a, b) = (d.coords()[1].clone(), d.coords()[2].clone());
        let df = f.partial(Var::U).scale(&a).checked_add(&f.partial(Var::V).scale(&b)).unwrap();
        let (u, v) = x.to_uv();
        prop_assert_eq!(
            df.eval(&[(Var::U, u), (Var::V, v)]).unwrap(),
            p.directional_derivative(&x, &d)
        );
        prop_assert_eq!(p.derivative(&Direction::du()).closed_form(), f.partial(Var::U));
        prop_assert_eq!(p.derivative(&Direction::dv()).closed_form(), f.partial(Var::V));
    }

    #[test]
    fn restriction_is_composition_with_the_affine_map(p in patch(), a in bary(), b in bary(), c in bary()) {
        // the sub-patch is b(ρ a + σ b + τ c) with (ρ, σ, τ) = (1 - u - v, u, v); compose the
        // closed forms through fresh variables x, y: u -> U(x, y), v -> V(x, y), then x -> u, y -> v
        let (x, y) = (Poly::var(Var::X), Poly::var(Var::Y));
        let rho = Poly::one() - &x - &y;
        let image = |m: usize| {
            rho.scale(&a.coords()[m]) + x.scale(&b.coords()[m]) + y.scale(&c.coords()[m])
        };
        let composed = p
            .closed_form()
            .substitute(Var::U, &image(1))
            .substitute(Var::V, &image(2))
            .substitute(Var::X, &Poly::var(Var::U))
            .substitute(Var::Y, &Poly::var(Var::V));
        prop_assert_eq!(p.restrict(&a, &b, &c).closed_form(), composed);
    }
}
