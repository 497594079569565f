//! A figure: named surfaces and curves with their colours.

use crate::{AnyCurve, AnySurface, RenderError};
use cagd_contract::{Argument, Quantity};
use cagd_scalar::Scalar;
use cagd_spline_surface::{BSplineSurface, NurbsSurface};
use std::fmt;

/// An sRGB colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Colour {
    /// Red, 0-255.
    pub r: u8,
    /// Green, 0-255.
    pub g: u8,
    /// Blue, 0-255.
    pub b: u8,
}

impl Colour {
    /// The colour `(r, g, b)`.
    pub const fn rgb(r: u8, g: u8, b: u8) -> Self {
        Colour { r, g, b }
    }

    /// `#rrggbb`.
    ///
    /// ```
    /// assert_eq!(cagd_render::Colour::rgb(255, 0, 128).hex(), "#ff0080");
    /// ```
    pub fn hex(self) -> String {
        format!("#{:02x}{:02x}{:02x}", self.r, self.g, self.b)
    }

    /// The colour mixed with `other`: `(1 - t) self + t other`, t in [0, 1].
    pub fn mix(self, other: Colour, t: f64) -> Colour {
        let t = t.clamp(0.0, 1.0);
        let m = |a: u8, b: u8| (f64::from(a) * (1.0 - t) + f64::from(b) * t).round() as u8;
        Colour::rgb(m(self.r, other.r), m(self.g, other.g), m(self.b, other.b))
    }

    /// White.
    pub const WHITE: Colour = Colour::rgb(255, 255, 255);
    /// Black.
    pub const BLACK: Colour = Colour::rgb(0, 0, 0);
}

impl fmt::Display for Colour {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.hex())
    }
}

/// The colours of surfaces, in order: the k-th surface of a scene takes `SURFACE_PALETTE[k % 6]`
/// unless it has its own. Light and medium fills (the shading darkens them), so that the dark
/// meshes and the saturated curves drawn over them stand out, in colour and in a greyscale
/// print alike.
///
/// The three palettes are one palette of roles: every colour of [`SURFACE_PALETTE`],
/// [`MESH_PALETTE`], [`CURVE_PALETTE`] and [`ORIGINAL`] differs from every other by a
/// CIELAB distance ΔE*ab of at least 20 (a test checks it), so the surface, each step of a
/// construction, each mesh and each data curve of one figure have colours that are told
/// apart (a Coons figure with its steps draws 4 surfaces, 4 meshes and 4 curves).
pub const SURFACE_PALETTE: [Colour; 6] = [
    Colour::rgb(0x4a, 0x86, 0xc8), // blue
    Colour::rgb(0xe6, 0xc0, 0x4a), // sand
    Colour::rgb(0x8c, 0xc4, 0x7a), // light green
    Colour::rgb(0xe8, 0x8f, 0xb5), // pink
    Colour::rgb(0xb8, 0xa8, 0x90), // khaki
    Colour::rgb(0xa0, 0xd4, 0xe8), // sky
];

/// The colours of control meshes, paired with [`SURFACE_PALETTE`]: dark strokes (near black on
/// the blue surface, dark brown on the sand one, ...), none of them a colour of a curve.
pub const MESH_PALETTE: [Colour; 6] = [
    Colour::rgb(0x1e, 0x1e, 0x1e), // near black
    Colour::rgb(0x7a, 0x3b, 0x0c), // dark brown
    Colour::rgb(0x3d, 0x2a, 0x78), // indigo
    Colour::rgb(0x0f, 0x5a, 0x4a), // dark teal
    Colour::rgb(0x6e, 0x1f, 0x4a), // wine
    Colour::rgb(0x5a, 0x6e, 0x8c), // slate
];

/// The colours of curves, in order (the data curves c1, c2, d1, d2 of a Coons patch take the
/// first four): saturated, none of them a colour of a surface or a mesh.
pub const CURVE_PALETTE: [Colour; 6] = [
    Colour::rgb(0xd6, 0x27, 0x28), // red
    Colour::rgb(0x2c, 0xa0, 0x2c), // green
    Colour::rgb(0x9c, 0x27, 0xb0), // purple
    Colour::rgb(0xff, 0x7f, 0x0e), // orange
    Colour::rgb(0x17, 0xbe, 0xcf), // cyan
    Colour::rgb(0x8a, 0x7a, 0x00), // olive
];

/// The colour of a faint surface: the original patch a restriction is drawn inside.
pub const ORIGINAL: Colour = Colour::rgb(0xda, 0xda, 0xda);

/// What a surface or curve of a figure is, for a legend written in a language by the caller
/// (the name is the key: `c1`, `surface`).
#[derive(Clone, Debug, PartialEq)]
pub enum Legend {
    /// An argument of the problem (`c1`, `surface`).
    Argument(Argument),
    /// A result or a step of the answer, by kind (`surface`, `c_c`).
    Quantity(Quantity),
    /// The argument a result was computed from, drawn faint behind it (the original patch of
    /// a restriction): `surface (original)`.
    Original(Argument),
    /// Only its name (an item of a list of results, a piece, a figure built by hand).
    Name,
}

impl Legend {
    /// The name of what it is: the argument's key, the quantity's name in the JSON answer.
    fn name(&self) -> Option<String> {
        match self {
            Legend::Argument(a) => Some(a.name().to_string()),
            Legend::Quantity(q) => Some(q.name().into_owned()),
            Legend::Original(a) => Some(format!("{} (original)", a.name())),
            Legend::Name => None,
        }
    }
}

/// A named surface of a figure.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneSurface<S: Scalar> {
    /// The name shown in the legend (`surface`, `c_c`, `first`).
    pub name: String,
    /// What it is, for a legend in a language.
    pub legend: Legend,
    /// The exact surface.
    pub geometry: AnySurface<S>,
    /// Its colour; `None` takes the palette's.
    pub colour: Option<Colour>,
    /// Its mesh colour; `None` takes the palette's.
    pub mesh_colour: Option<Colour>,
    /// Whether it is drawn faint, in [`ORIGINAL`] grey without its mesh, under the others
    /// (the original patch of a restriction, with the restricted patch inside it).
    pub faint: bool,
}

/// A named curve of a figure.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneCurve<S: Scalar> {
    /// The name shown in the legend and next to the curve (`c1`, `d2`).
    pub name: String,
    /// What it is, for a legend in a language.
    pub legend: Legend,
    /// The exact curve.
    pub geometry: AnyCurve<S>,
    /// Its colour; `None` takes the palette's.
    pub colour: Option<Colour>,
}

/// What a figure shows: surfaces and curves, each with a name and a colour, in order (the
/// order fixes the colours and the legend, so the same scene always draws the same bytes).
///
/// ```
/// use cagd_render::{Scene, render_svg, SvgOptions};
/// use cagd_surface::BezierSurface;
/// use cagd_linalg::Point;
/// use cagd_scalar::BigRational;
/// let p = |c: &[i64]| Point::from_ints(c);
/// let s = BezierSurface::<BigRational>::from_rows(vec![
///     vec![p(&[0, 0, 0]), p(&[0, 1, 0])],
///     vec![p(&[1, 0, 0]), p(&[1, 1, 1])],
/// ]).unwrap();
/// let mut scene = Scene::new();
/// scene.add_surface("xy", s);
/// let svg = render_svg(&scene, &SvgOptions::default()).unwrap();
/// assert!(svg.starts_with("<svg"));
/// assert_eq!(svg, render_svg(&scene, &SvgOptions::default()).unwrap());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Scene<S: Scalar> {
    /// A title drawn above the figure.
    pub title: Option<String>,
    /// The surfaces, drawn with [`SURFACE_PALETTE`] in order.
    pub surfaces: Vec<SceneSurface<S>>,
    /// The curves, drawn with [`CURVE_PALETTE`] in order.
    pub curves: Vec<SceneCurve<S>>,
}

impl<S: Scalar> Default for Scene<S> {
    fn default() -> Self {
        Scene {
            title: None,
            surfaces: Vec::new(),
            curves: Vec::new(),
        }
    }
}

impl<S: Scalar> Scene<S> {
    /// An empty scene.
    pub fn new() -> Self {
        Self::default()
    }

    /// The same scene with a title.
    pub fn with_title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }

    /// Adds a surface with the next colour of the palette.
    pub fn add_surface(
        &mut self,
        name: impl Into<String>,
        geometry: impl Into<AnySurface<S>>,
    ) -> &mut Self {
        self.surfaces.push(SceneSurface {
            name: name.into(),
            legend: Legend::Name,
            geometry: geometry.into(),
            colour: None,
            mesh_colour: None,
            faint: false,
        });
        self
    }

    /// Adds a surface with its own colour.
    pub fn add_surface_coloured(
        &mut self,
        name: impl Into<String>,
        geometry: impl Into<AnySurface<S>>,
        colour: Colour,
    ) -> &mut Self {
        self.surfaces.push(SceneSurface {
            name: name.into(),
            legend: Legend::Name,
            geometry: geometry.into(),
            colour: Some(colour),
            mesh_colour: None,
            faint: false,
        });
        self
    }

    /// Adds a curve with the next colour of the palette.
    pub fn add_curve(
        &mut self,
        name: impl Into<String>,
        geometry: impl Into<AnyCurve<S>>,
    ) -> &mut Self {
        self.curves.push(SceneCurve {
            name: name.into(),
            legend: Legend::Name,
            geometry: geometry.into(),
            colour: None,
        });
        self
    }

    /// Adds a surface that is an argument of the problem or a result of the answer, named by
    /// its key, with the next colour of the palette.
    pub fn add_surface_as(
        &mut self,
        legend: Legend,
        geometry: impl Into<AnySurface<S>>,
    ) -> &mut Self {
        let name = legend.name().unwrap_or_default();
        self.add_surface_with(name, legend, geometry)
    }

    /// Adds a surface with its name and what it is, with the next colour of the palette.
    pub(crate) fn add_surface_with(
        &mut self,
        name: String,
        legend: Legend,
        geometry: impl Into<AnySurface<S>>,
    ) -> &mut Self {
        self.surfaces.push(SceneSurface {
            name,
            legend,
            geometry: geometry.into(),
            colour: None,
            mesh_colour: None,
            faint: false,
        });
        self
    }

    /// Adds a faint surface (see [`SceneSurface::faint`]): the original a result was computed
    /// from, drawn in [`ORIGINAL`] grey without its mesh.
    pub fn add_faint_surface_as(
        &mut self,
        legend: Legend,
        geometry: impl Into<AnySurface<S>>,
    ) -> &mut Self {
        self.surfaces.push(SceneSurface {
            name: legend.name().unwrap_or_default(),
            legend,
            geometry: geometry.into(),
            colour: Some(ORIGINAL),
            mesh_colour: None,
            faint: true,
        });
        self
    }

    /// Adds a curve that is an argument of the problem or a result of the answer, named by
    /// its key, with the next colour of the palette.
    pub fn add_curve_as(&mut self, legend: Legend, geometry: impl Into<AnyCurve<S>>) -> &mut Self {
        self.curves.push(SceneCurve {
            name: legend.name().unwrap_or_default(),
            legend,
            geometry: geometry.into(),
            colour: None,
        });
        self
    }

    /// Adds each Bézier piece of a B-spline surface as its own surface, named
    /// `name [a, b] x [c, d]`, so the pieces show in distinct colours.
    pub fn add_bezier_pieces(
        &mut self,
        name: &str,
        surface: &BSplineSurface<S>,
    ) -> Result<&mut Self, RenderError> {
        for ((iu, iv), piece) in surface.bezier_patches()?.iter() {
            self.add_surface(format!("{name} {}", rectangle_text(iu, iv)), piece.clone());
        }
        Ok(self)
    }

    /// Adds each rational Bézier piece of a NURBS surface as its own surface, named
    /// `name [a, b] x [c, d]`.
    pub fn add_rational_bezier_pieces(
        &mut self,
        name: &str,
        surface: &NurbsSurface<S>,
    ) -> Result<&mut Self, RenderError> {
        for ((iu, iv), piece) in surface.bezier_patches()?.iter() {
            self.add_surface(format!("{name} {}", rectangle_text(iu, iv)), piece.clone());
        }
        Ok(self)
    }

    /// Whether the scene has nothing to draw.
    pub fn is_empty(&self) -> bool {
        self.surfaces.is_empty() && self.curves.is_empty()
    }

    /// The colour of surface k.
    pub fn surface_colour(&self, k: usize) -> Colour {
        self.surfaces
            .get(k)
            .and_then(|s| s.colour)
            .unwrap_or_else(|| cyclic(&SURFACE_PALETTE, k))
    }

    /// The mesh colour of surface k.
    pub fn mesh_colour(&self, k: usize) -> Colour {
        self.surfaces
            .get(k)
            .and_then(|s| s.mesh_colour)
            .unwrap_or_else(|| cyclic(&MESH_PALETTE, k))
    }

    /// The colour of curve k.
    pub fn curve_colour(&self, k: usize) -> Colour {
        self.curves
            .get(k)
            .and_then(|c| c.colour)
            .unwrap_or_else(|| cyclic(&CURVE_PALETTE, k))
    }
}

/// Entry `k` of a palette, starting over after its last entry.
fn cyclic(palette: &[Colour], k: usize) -> Colour {
    palette
        .iter()
        .cycle()
        .nth(k)
        .copied()
        .unwrap_or(Colour::BLACK)
}

fn rectangle_text<S: Scalar>(iu: &(S, S), iv: &(S, S)) -> String {
    format!(
        "[{}, {}] x [{}, {}]",
        iu.0.to_text(),
        iu.1.to_text(),
        iv.0.to_text(),
        iv.1.to_text()
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::BigRational;

    #[test]
    fn palettes_start_over_after_their_last_colour() {
        let scene = Scene::<BigRational>::new();
        assert_eq!(scene.surface_colour(0), SURFACE_PALETTE[0]);
        assert_eq!(scene.surface_colour(7), SURFACE_PALETTE[1]);
        assert_eq!(scene.mesh_colour(13), MESH_PALETTE[1]);
        assert_eq!(scene.curve_colour(6), CURVE_PALETTE[0]);
        assert_eq!(cyclic(&[], 3), Colour::BLACK);
    }

    /// CIELAB (D65) of an sRGB colour.
    fn lab(c: Colour) -> [f64; 3] {
        let lin = |v: u8| {
            let v = f64::from(v) / 255.0;
            if v <= 0.04045 {
                v / 12.92
            } else {
                ((v + 0.055) / 1.055).powf(2.4)
            }
        };
        let (r, g, b) = (lin(c.r), lin(c.g), lin(c.b));
        let x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
        let y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
        let z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
        let f = |t: f64| {
            if t > 0.008856 {
                t.cbrt()
            } else {
                7.787 * t + 16.0 / 116.0
            }
        };
        [
            116.0 * f(y) - 16.0,
            500.0 * (f(x) - f(y)),
            200.0 * (f(y) - f(z)),
        ]
    }

    #[test]
    fn every_role_has_a_colour_of_its_own() {
        // surfaces, meshes, curves and the faint original: one palette of roles
        let roles: Vec<(String, Colour)> = SURFACE_PALETTE
            .iter()
            .enumerate()
            .map(|(k, c)| (format!("surface {k}"), *c))
            .chain(
                MESH_PALETTE
                    .iter()
                    .enumerate()
                    .map(|(k, c)| (format!("mesh {k}"), *c)),
            )
            .chain(
                CURVE_PALETTE
                    .iter()
                    .enumerate()
                    .map(|(k, c)| (format!("curve {k}"), *c)),
            )
            .chain([("original".to_string(), ORIGINAL)])
            .collect();
        for (i, (a, ca)) in roles.iter().enumerate() {
            for (b, cb) in roles.iter().skip(i + 1) {
                let [l1, a1, b1] = lab(*ca);
                let [l2, a2, b2] = lab(*cb);
                let delta = ((l1 - l2).powi(2) + (a1 - a2).powi(2) + (b1 - b2).powi(2)).sqrt();
                assert!(delta >= 20.0, "{a} {ca} and {b} {cb}: ΔE = {delta:.1}");
            }
        }
        // in a greyscale print, the surfaces are light, the meshes dark, the curves between
        let lightness = |c: &Colour| lab(*c)[0];
        let darkest_surface = SURFACE_PALETTE.iter().map(lightness).fold(100.0, f64::min);
        let lightest_mesh = MESH_PALETTE.iter().map(lightness).fold(0.0, f64::max);
        assert!(lightest_mesh + 5.0 < darkest_surface);
    }
}
