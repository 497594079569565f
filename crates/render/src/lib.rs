//! Figures of cagd-exact: see the surface, its mesh and its construction.
//!
//! A [`Scene`] holds named surfaces and curves, exactly as the engine computed them (Bézier,
//! rational Bézier, B-spline and NURBS patches, polynomial maps; Bézier, rational, B-spline,
//! NURBS and polynomial curves), generic over [`Scalar`](cagd_scalar::Scalar). Every point
//! drawn is evaluated **exactly** at an exact parameter `a + (b - a) k / n` and converted to
//! f64 only to be drawn: this crate is the one place of the engine where f64 geometry lives.
//! It does no I/O: every output is a `String` or bytes.
//!
//! | output | function | what |
//! | --- | --- | --- |
//! | SVG | [`render_svg`] | isoparametric net over shaded cells (painter's order), control meshes, boundaries, normals, input curves, axes, legend; deterministic bytes |
//! | OBJ, STL | [`to_obj`], [`to_stl_ascii`], [`to_stl_binary`], [`tessellate`] | triangles on an exact parameter grid, with unit normals |
//! | IGES | [`to_iges`] | the exact NURBS as entities 128 (surfaces) and 126 (curves), full-precision decimals |
//! | HTML | [`to_html`] | one self-contained page: drag to rotate, wheel to zoom, toggles, hover for exact coordinates |
//! | charts | [`plot_polynomial`], [`plot_gaussian_sign`], [`plot_weights`] | a polynomial over an interval, the sign of K across a patch, weights as bars |
//!
//! A scene comes from the geometry crates ([`Scene::add_surface`], [`Scene::add_curve`],
//! [`Scene::add_bezier_pieces`]) or from a problem of the JSON format and its answer
//! ([`Scene::from_json`], [`Scene::from_answer`]).
//!
//! ```
//! use cagd_render::{render_svg, to_iges, Scene, SvgOptions};
//! use cagd_surface::RationalBezierSurface;
//! use cagd_linalg::Point;
//! use cagd_scalar::{parse_number, Quadratic};
//! // the sphere octant of chapter 6 over the quadratic field
//! let n = |t: &str| parse_number(t).unwrap();
//! let p = |c: &[i64]| Point::<Quadratic>::from_ints(c);
//! let octant = RationalBezierSurface::from_rows(
//!     vec![
//!         vec![p(&[1, 0, 0]), p(&[1, 1, 0]), p(&[0, 1, 0])],
//!         vec![p(&[1, 0, 1]), p(&[1, 1, 1]), p(&[0, 1, 1])],
//!         vec![p(&[0, 0, 1]), p(&[0, 0, 1]), p(&[0, 0, 1])],
//!     ],
//!     vec![
//!         vec![n("1"), n("sqrt2/2"), n("1")],
//!         vec![n("sqrt2/2"), n("1/2"), n("sqrt2/2")],
//!         vec![n("1"), n("sqrt2/2"), n("1")],
//!     ],
//! ).unwrap();
//! let mut scene = Scene::new().with_title("Sphere octant");
//! scene.add_surface("octant", octant);
//! let svg = render_svg(&scene, &SvgOptions::default()).unwrap();
//! assert!(svg.contains(">octant</text>"));
//! let iges = to_iges(&scene).unwrap();
//! assert!(iges.contains("0.7071067811865476"));
//! ```

mod answer;
mod curvature;
mod error;
mod geometry;
mod html;
mod iges;
mod mesh_export;
mod plot;
#[cfg(feature = "png")]
mod png;
mod sample;
mod scene;
mod svg;
mod view;

pub use answer::{curve_geometry, surface_geometry};
pub use curvature::{gaussian_numerator, gaussian_signs, CurvatureSign};
pub use error::{Drawn, Magnitude, Raster, RenderError, Sampling, Unplotted};
pub use geometry::{AnyCurve, AnySurface, ControlNet, ControlPolygon, CurvePolygon, SurfaceNet};
pub use html::{inline_script, to_html, HtmlOptions};
pub use iges::{to_iges, CurveAsNurbs, NurbsCurveForm, NurbsForm, SurfaceAsNurbs};
pub use mesh_export::{tessellate, to_obj, to_stl_ascii, to_stl_binary, Tessellation};
pub use plot::{plot_gaussian_sign, plot_polynomial, plot_weights, PlotOptions};
#[cfg(feature = "png")]
pub use png::svg_to_png;
pub use scene::{
    Colour, Legend, Scene, SceneCurve, SceneSurface, CURVE_PALETTE, MESH_PALETTE, ORIGINAL,
    SURFACE_PALETTE,
};
pub use svg::{render_svg, Layers, SvgOptions};
pub use view::{escape as escape_xml, View};
