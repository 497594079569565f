//! Surface generation (chapter 6 of the notes, `000_4f266b7df5f64f70.txt`, and its slides):
//! surfaces built from curves, exactly, over any [`Scalar`].
//!
//! | construction | closed form | Bézier / rational mesh | B-spline / NURBS |
//! | --- | --- | --- | --- |
//! | translational (§2) | [`translational_surface`]: `c1(u) + d1(v) - a` (1), [`twist`] (2) | [`translational_bezier`] (4), [`translational_rational`] (5) | [`translational_bspline`], [`translational_nurbs`] |
//! | ruled (§3) | [`ruled_surface`]: `(1 - v) c1(u) + v c2(u)` (7) | [`ruled_bezier`], [`ruled_rational`] ([`RuledRational::parametrizations`]) | [`ruled_bspline`], [`ruled_nurbs`] ([`make_compatible`]) |
//! | developable (§4) | [`developability`]: `c_uv · (c_u × c_v) ≡ 0` (9); [`cylindrical_surface`] (11), [`conical_surface`] (12), [`tangent_surface`] | [`developability_bezier`], [`developability_rational`], [`cylindrical_bezier`], [`conical_bezier`], [`tangent_bezier`], [`cylindrical_rational`], [`conical_rational`] | |
//! | Coons (§5) | [`coons_surface`]: `c_c + c_d - c_cd` (15)-(17), [`coons_surface_blended`], [`cross_boundary_formula`] (20) | [`coons_bezier`] (18)-(19), [`coons_projective`] (the rational caveat), [`coons_rational_map`] | [`coons_bspline`] |
//! | revolution (§6) | [`revolution_surface`]: `(f cos v, f sin v, g)` (21) | [`revolution_bezier`], [`revolution_bezier_quadrant`] | [`revolution_nurbs`], [`revolution_nurbs_arcs`] |
//!
//! Every construction records the intermediate values the notes print as [`Step`]s
//! (`a = (1, 0, 0)`, `c_c = {...}`) into the step recorder it is given
//! (`rec: &mut impl Record<Step<S>>`: a `Vec` keeps them, [`cagd_record::NoSteps`] builds
//! nothing), and its result carries its remarks as typed [`Note`]s (`c2 elevated from degree 2
//! to 3`), so that an answer key can show them; nothing rounds: the Coons mesh of the notes
//! comes out as
//!
//! ```
//! use cagd_bezier::BezierCurve;
//! use cagd_generate::coons_bezier;
//! use cagd_record::NoSteps;
//! use cagd_linalg::Point;
//! use cagd_scalar::{parse_rational, BigRational};
//! let curve = |pts: &[[&str; 3]]| {
//!     BezierCurve::try_new(pts.iter().map(|p| {
//!         Point::new(p.iter().map(|x| parse_rational(x).unwrap()).collect::<Vec<BigRational>>())
//!     }).collect()).unwrap()
//! };
//! let c1 = curve(&[["0", "0", "0"], ["1/2", "0", "2"], ["1", "0", "3"], ["2", "0", "0"]]);
//! let c2 = curve(&[["0", "3", "0"], ["1/2", "3", "3"], ["1", "3", "1"], ["2", "4", "0"]]);
//! let d1 = curve(&[["0", "0", "0"], ["0", "1", "3"], ["0", "3", "0"]]);
//! let d2 = curve(&[["2", "0", "0"], ["2", "1", "2"], ["2", "4", "0"]]);
//! let coons = coons_bezier(&c1, &c2, &d1, &d2, &mut NoSteps).unwrap();
//! assert_eq!(coons.surface.mesh().get(1, 1).unwrap().to_text(), "(1/2, 5/6, 31/6)");
//! ```
//!
//! Curves given as polynomial maps ([`cagd_poly::VecPoly`]) must use the notes' parameters: u
//! for c1, c2 and v for d1, d2. Bézier curves are read in their local parameter on [0, 1] (a
//! curve's domain [a, b] does not enter the mesh) and the patches come out on [0, 1] x [0, 1];
//! B-spline curves keep their knots (opposite curves must share the domain). Bad input (curves
//! that do not meet, different dimensions, zero weights, a √2/2 asked of exact rationals,
//! numbers with two different roots) is a [`GenerateError`] naming what is wrong, never a
//! panic.

mod common;
mod compat;
mod coons;
mod coons_rational;
mod coons_spline;
mod developable;
mod error;
mod loft;
mod note;
mod revolution;
mod ruled;
mod step;
mod translational;

pub use compat::{make_compatible, make_compatible_nurbs, Compatible, CompatibleNurbs};
pub use coons::{
    blending_functions, coons_bezier, coons_surface, coons_surface_blended, cross_boundary_formula,
    Blending, CoonsBezier, CoonsSurface,
};
pub use coons_rational::{coons_projective, coons_rational_map, ProjectiveCoons};
pub use coons_spline::{coons_bspline, CoonsBSpline};
pub use developable::{
    cell_is_planar, conical_bezier, conical_rational, conical_surface, cylindrical_bezier,
    cylindrical_rational, cylindrical_surface, developability, developability_bezier,
    developability_rational, tangent_bezier, tangent_surface, BezierDevelopability, Developability,
    RationalDevelopability,
};
pub use error::{GenerateError, Input, Needs, NotRuled, Spatial};
pub use loft::{loft, uniform_parameters, Lofted};
pub use note::Note;
pub use revolution::{
    nurbs_from_bezier, quarter_circle, revolution_bezier, revolution_bezier_quadrant,
    revolution_nurbs, revolution_nurbs_arcs, revolution_surface, sqrt2_over_2, RevolutionBezier,
    RevolutionNurbs, RevolutionSurface,
};
pub use ruled::{
    ruled_bezier, ruled_bspline, ruled_nurbs, ruled_rational, ruled_surface, RuledBSpline,
    RuledBezier, RuledNurbs, RuledParametrizations, RuledRational, RuledSurface,
};
pub use step::{find_step, steps_to_text, Step, StepValue};
pub use translational::{
    has_zero_twist, mesh_twists, rational_twist, translational_bezier, translational_bspline,
    translational_nurbs, translational_rational, translational_surface, twist,
    TranslationalBSpline, TranslationalBezier, TranslationalNurbs, TranslationalRational,
    TranslationalSurface,
};

pub use cagd_scalar::Scalar;
pub use cagd_surface::Border;
