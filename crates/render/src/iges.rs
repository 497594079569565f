//! IGES 5.3 export of the exact NURBS: each surface as a rational B-spline surface entity
//! (type 128), each curve as a rational B-spline curve entity (type 126), each with a colour
//! definition entity (type 314).
//!
//! IGES stores floating-point numbers, so this is where the exact numbers become decimals:
//! each is the f64 nearest to the exact value, written with all its digits (the shortest
//! decimal that reads back to the same f64). A Bézier patch is the NURBS with knots
//! `{a, ..., a, b, ..., b}` (each end `degree + 1` times) and weights 1.
//!
//! The file has the five fixed 80-column sections: Start (S), Global (G), Directory Entry
//! (D, two lines per entity), Parameter Data (P, columns 1-64 data, 66-72 the directory
//! pointer) and Terminate (T); columns 73-80 hold the section letter and the line number. The
//! date fields are fixed (`20000101.000000`) so the same scene gives the same file.

use crate::geometry::{CurvePolygon, SurfaceNet};
use crate::{AnyCurve, AnySurface, RenderError, Scene};
use cagd_bspline::KnotVector;
use cagd_linalg::Point;
use cagd_scalar::{ExactRational, Scalar};
use cagd_surface::{Grid, Mesh};

/// A surface in the form of a NURBS, exact: what an IGES entity 128 holds.
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsForm<S> {
    /// Degrees (p, q) in u and in v.
    pub degree: (usize, usize),
    /// The knots in u in the full convention (rows + p + 1 of them).
    pub knots_u: Vec<S>,
    /// The knots in v in the full convention (columns + q + 1 of them).
    pub knots_v: Vec<S>,
    /// The control points (rows along u).
    pub points: Mesh<S>,
    /// The weights, `None` for a polynomial surface.
    pub weights: Option<Grid<S>>,
}

/// A curve in the form of a NURBS, exact: what an IGES entity 126 holds.
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsCurveForm<S> {
    /// The degree.
    pub degree: usize,
    /// The knots in the full convention.
    pub knots: Vec<S>,
    /// The control points.
    pub points: Vec<Point<S>>,
    /// The weights, `None` for a polynomial curve.
    pub weights: Option<Vec<S>>,
}

fn bezier_knots<S: Scalar>(degree: usize, (a, b): (&S, &S)) -> Vec<S> {
    let mut k = vec![a.clone(); degree + 1];
    k.extend(std::iter::repeat_n(b.clone(), degree + 1));
    k
}

/// A surface written as a NURBS, for IGES.
pub trait SurfaceAsNurbs<S: Scalar> {
    /// The surface as a NURBS (see the implementation for [`AnySurface`]).
    fn nurbs_form(&self) -> Result<NurbsForm<S>, RenderError>;
}

/// A curve written as a NURBS, for IGES.
pub trait CurveAsNurbs<S: Scalar> {
    /// The curve as a NURBS (see the implementation for [`AnyCurve`]).
    fn nurbs_form(&self) -> Result<NurbsCurveForm<S>, RenderError>;
}

impl<S: Scalar> SurfaceAsNurbs<S> for AnySurface<S> {
    /// The surface as a NURBS: a Bézier patch of bidegree (m, n) on [a, b] x [c, d] has the
    /// knots `{a (m + 1 times), b (m + 1 times)}` and `{c (n + 1 times), d (n + 1 times)}`; a
    /// polynomial map is first written in the Bernstein basis of its degrees.
    fn nurbs_form(&self) -> Result<NurbsForm<S>, RenderError> {
        let net = self.control_net()?;
        let (m, n) = (net.points.rows() - 1, net.points.cols() - 1);
        let ((a, b), (c, d)) = self.domain();
        let (degree, knots_u, knots_v) = match self {
            AnySurface::BSpline(s) => (
                s.bidegree(),
                s.knots_u().full().to_vec(),
                s.knots_v().full().to_vec(),
            ),
            AnySurface::Nurbs(s) => (
                s.bidegree(),
                s.knots_u().full().to_vec(),
                s.knots_v().full().to_vec(),
            ),
            _ => ((m, n), bezier_knots(m, (&a, &b)), bezier_knots(n, (&c, &d))),
        };
        Ok(NurbsForm {
            degree,
            knots_u,
            knots_v,
            points: net.points,
            weights: net.weights,
        })
    }
}

impl<S: Scalar> CurveAsNurbs<S> for AnyCurve<S> {
    /// The curve as a NURBS (a Bézier curve of degree n on [a, b] has the knots
    /// `{a (n + 1 times), b (n + 1 times)}`).
    fn nurbs_form(&self) -> Result<NurbsCurveForm<S>, RenderError> {
        if let AnyCurve::RationalBezier(c) = self {
            c.require_points()?; // IGES weights are positive: no control vector
        }
        let polygon = self.control_polygon()?;
        let (points, weights) = (polygon.points, polygon.weights);
        let n = points.len().saturating_sub(1);
        let (a, b) = self.domain();
        let (degree, knots) = match self {
            AnyCurve::BSpline(c) => (c.degree(), full(c.knots())),
            AnyCurve::Nurbs(c) => (c.degree(), full(c.knots())),
            _ => (n, bezier_knots(n, (&a, &b))),
        };
        Ok(NurbsCurveForm {
            degree,
            knots,
            points,
            weights,
        })
    }
}

fn full<S: Scalar>(k: &KnotVector<S>) -> Vec<S> {
    k.full().to_vec()
}

/// An f64 as an IGES real: every digit of the shortest round-trip decimal, always with a
/// decimal point, exponent `E` (`0.7071067811865476`, `-2.0`, `1.0E-7`).
pub(crate) fn iges_real(x: f64) -> String {
    let x = if x.is_finite() { x } else { 0.0 };
    let s = format!("{x:?}");
    match s.split_once('e') {
        Some((mantissa, exp)) => {
            let mantissa = if mantissa.contains('.') {
                mantissa.to_string()
            } else {
                format!("{mantissa}.0")
            };
            format!("{mantissa}E{exp}")
        }
        None if s.contains('.') => s,
        None => format!("{s}.0"),
    }
}

/// A Hollerith string `nHtext`.
fn hollerith(s: &str) -> String {
    format!("{}H{}", s.chars().count(), s)
}

/// ASCII text for IGES strings and labels (other characters become `_`).
fn ascii(s: &str) -> String {
    s.chars()
        .map(|c| {
            if c.is_ascii_graphic() || c == ' ' {
                c
            } else {
                '_'
            }
        })
        .collect::<String>()
        .replace([',', ';'], "_")
}

/// One entity: type, form, colour (directory pointer of a 314, negated, or 0), label,
/// status, parameters.
struct Entity {
    kind: u32,
    colour: i64,
    label: String,
    status: &'static str,
    params: Vec<String>,
}

/// Lines of a section: data in columns 1-72, letter, line number.
fn section_line(data: &str, letter: char, n: usize) -> String {
    format!("{data:<72}{letter}{n:>7}")
}

/// Packs tokens separated by `,` and ended by `;` into lines of at most `width` characters.
fn pack(tokens: &[String], width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for (i, t) in tokens.iter().enumerate() {
        let piece = format!("{t}{}", if i + 1 == tokens.len() { ';' } else { ',' });
        if !line.is_empty() && line.len() + piece.len() > width {
            lines.push(std::mem::take(&mut line));
        }
        if piece.len() > width {
            // a long string: split it (only Hollerith text can be this long)
            let chars: Vec<char> = piece.chars().collect();
            for chunk in chars.chunks(width) {
                lines.push(chunk.iter().collect());
            }
            continue;
        }
        line.push_str(&piece);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

/// The colour definition entity 314 of a colour: red, green, blue in percent.
fn colour_entity(c: crate::Colour, name: &str) -> Entity {
    let pct = |x: u8| iges_real((f64::from(x) * 10000.0 / 255.0).round() / 100.0);
    Entity {
        kind: 314,
        colour: 0,
        label: String::new(),
        status: "00000200",
        params: vec![
            "314".into(),
            pct(c.r),
            pct(c.g),
            pct(c.b),
            hollerith(&ascii(name)),
        ],
    }
}

fn coords3<S: Scalar>(p: &Point<S>) -> [f64; 3] {
    crate::geometry::point3(p).unwrap_or([0.0; 3])
}

/// The parameters of entity 128 for a surface in NURBS form.
fn surface_params<S: Scalar>(f: &NurbsForm<S>) -> Vec<String> {
    let (k1, k2) = (f.points.rows() - 1, f.points.cols() - 1);
    let (m1, m2) = f.degree;
    let polynomial = f
        .weights
        .as_ref()
        .is_none_or(|w| w.iter().all(|x| *x == *w.iter().next().unwrap_or(x)));
    let mut p: Vec<String> = vec![
        "128".into(),
        k1.to_string(),
        k2.to_string(),
        m1.to_string(),
        m2.to_string(),
        "0".into(),
        "0".into(),
        if polynomial { "1" } else { "0" }.into(),
        "0".into(),
        "0".into(),
    ];
    p.extend(f.knots_u.iter().map(|x| iges_real(x.to_f64())));
    p.extend(f.knots_v.iter().map(|x| iges_real(x.to_f64())));
    // weights and points with the first index (u) varying fastest
    for j in 0..=k2 {
        for i in 0..=k1 {
            let w = f
                .weights
                .as_ref()
                .and_then(|w| w.get(i, j))
                .map_or(1.0, ExactRational::to_f64);
            p.push(iges_real(w));
        }
    }
    for j in 0..=k2 {
        for i in 0..=k1 {
            let c = f.points.get(i, j).map_or([0.0; 3], coords3);
            p.extend(c.iter().map(|x| iges_real(*x)));
        }
    }
    let end = |k: &[S], d: usize, from_end: bool| {
        let i = if from_end { k.len() - 1 - d } else { d };
        k.get(i).map_or(0.0, ExactRational::to_f64)
    };
    p.push(iges_real(end(&f.knots_u, m1, false)));
    p.push(iges_real(end(&f.knots_u, m1, true)));
    p.push(iges_real(end(&f.knots_v, m2, false)));
    p.push(iges_real(end(&f.knots_v, m2, true)));
    p
}

/// The parameters of entity 126 for a curve in NURBS form.
fn curve_params<S: Scalar>(f: &NurbsCurveForm<S>) -> Vec<String> {
    let k = f.points.len() - 1;
    let m = f.degree;
    let polynomial = f
        .weights
        .as_ref()
        .is_none_or(|w| w.iter().all(|x| Some(x) == w.first()));
    let planar = f.points.iter().all(|p| coords3(p)[2] == 0.0);
    let mut p: Vec<String> = vec![
        "126".into(),
        k.to_string(),
        m.to_string(),
        if planar { "1" } else { "0" }.into(),
        "0".into(),
        if polynomial { "1" } else { "0" }.into(),
        "0".into(),
    ];
    p.extend(f.knots.iter().map(|x| iges_real(x.to_f64())));
    for i in 0..=k {
        let w = f
            .weights
            .as_ref()
            .and_then(|w| w.get(i))
            .map_or(1.0, ExactRational::to_f64);
        p.push(iges_real(w));
    }
    for pt in &f.points {
        p.extend(coords3(pt).iter().map(|x| iges_real(*x)));
    }
    let t = |i: usize| f.knots.get(i).map_or(0.0, ExactRational::to_f64);
    p.push(iges_real(t(m)));
    p.push(iges_real(t(f.knots.len().saturating_sub(m + 1))));
    p.extend(["0.0", "0.0", "1.0"].map(String::from));
    p
}

/// An entity label: up to 8 ASCII letters, digits or `_` of the name.
fn label(name: &str) -> String {
    name.chars()
        .filter(|c| c.is_ascii_alphanumeric() || *c == '_')
        .take(8)
        .collect()
}

/// The scene as an IGES 5.3 file: per surface a colour (314) and a rational B-spline surface
/// (128), per curve a colour and a rational B-spline curve (126).
pub fn to_iges<S: Scalar>(scene: &Scene<S>) -> Result<String, RenderError> {
    if scene.is_empty() {
        return Err(RenderError::EmptyScene);
    }
    let mut entities: Vec<Entity> = Vec::new();
    let mut max_coord: f64 = 0.0;
    let mut note = |p: &Point<S>| {
        for c in coords3(p) {
            max_coord = max_coord.max(c.abs());
        }
    };
    for (k, s) in scene.surfaces.iter().enumerate() {
        let form = s.geometry.nurbs_form()?;
        form.points.iter().for_each(&mut note);
        // the colour entity comes first: its directory line is 2 * index + 1
        let colour_de = 2 * entities.len() + 1;
        entities.push(colour_entity(scene.surface_colour(k), &s.name));
        entities.push(Entity {
            kind: 128,
            colour: -(colour_de as i64),
            label: label(&s.name),
            status: "00000000",
            params: surface_params(&form),
        });
    }
    for (k, c) in scene.curves.iter().enumerate() {
        let form = c.geometry.nurbs_form()?;
        if form.points.is_empty() {
            continue;
        }
        form.points.iter().for_each(&mut note);
        let colour_de = 2 * entities.len() + 1;
        entities.push(colour_entity(scene.curve_colour(k), &c.name));
        entities.push(Entity {
            kind: 126,
            colour: -(colour_de as i64),
            label: label(&c.name),
            status: "00000000",
            params: curve_params(&form),
        });
    }
    crate::sample::check_magnitude(max_coord, &crate::Drawn::Figure)?;

    let mut out = String::new();
    // Start section.
    let title = ascii(scene.title.as_deref().unwrap_or("cagd-exact figure"));
    let start = [
        format!("cagd-exact: {title}"),
        "Exact NURBS written as the nearest f64 numbers (all digits).".to_string(),
    ];
    for (i, s) in start.iter().enumerate() {
        let s: String = s.chars().take(72).collect();
        out.push_str(&section_line(&s, 'S', i + 1));
        out.push('\n');
    }
    // Global section.
    let date = hollerith("20000101.000000");
    let global: Vec<String> = vec![
        "1H,".into(),
        "1H;".into(),
        hollerith(&ascii(&title)),
        hollerith("figure.igs"),
        hollerith("cagd-exact"),
        hollerith(concat!("cagd-render ", env!("CARGO_PKG_VERSION"))),
        "32".into(),
        "38".into(),
        "6".into(),
        "308".into(),
        "15".into(),
        hollerith(&ascii(&title)),
        "1.0".into(),
        "2".into(),
        "2HMM".into(),
        "1".into(),
        "1.0".into(),
        date.clone(),
        "1.0E-10".into(),
        iges_real(max_coord),
        hollerith("cagd-exact"),
        hollerith("cagd-exact"),
        "11".into(),
        "0".into(),
        date,
    ];
    let g_lines = pack(&global, 72);
    for (i, l) in g_lines.iter().enumerate() {
        out.push_str(&section_line(l, 'G', i + 1));
        out.push('\n');
    }
    // Parameter data first (to know the pointers), then the directory.
    let mut p_lines: Vec<String> = Vec::new();
    let mut d_lines: Vec<String> = Vec::new();
    for (e_index, e) in entities.iter().enumerate() {
        let de = 2 * e_index + 1;
        let first = p_lines.len() + 1;
        let lines = pack(&e.params, 64);
        for l in &lines {
            let n = p_lines.len() + 1;
            p_lines.push(format!("{l:<64} {de:>7}P{n:>7}"));
        }
        let f = |x: &dyn std::fmt::Display| format!("{:>8}", x.to_string());
        d_lines.push(section_line(
            &[
                f(&e.kind),
                f(&first),
                f(&0),
                f(&0),
                f(&0),
                f(&0),
                f(&0),
                f(&0),
                e.status.to_string(),
            ]
            .concat(),
            'D',
            de,
        ));
        d_lines.push(section_line(
            &[
                f(&e.kind),
                f(&0),
                f(&e.colour),
                f(&lines.len()),
                f(&0),
                " ".repeat(8),
                " ".repeat(8),
                f(&e.label),
                f(&0),
            ]
            .concat(),
            'D',
            de + 1,
        ));
    }
    for l in &d_lines {
        out.push_str(l);
        out.push('\n');
    }
    for l in &p_lines {
        out.push_str(l);
        out.push('\n');
    }
    let terminate = format!(
        "S{:>7}G{:>7}D{:>7}P{:>7}",
        start.len(),
        g_lines.len(),
        d_lines.len(),
        p_lines.len()
    );
    out.push_str(&section_line(&terminate, 'T', 1));
    out.push('\n');
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reals_keep_every_digit_and_a_decimal_point() {
        assert_eq!(iges_real(1.0), "1.0");
        assert_eq!(iges_real(-2.0), "-2.0");
        assert_eq!(iges_real(0.5), "0.5");
        assert_eq!(
            iges_real(std::f64::consts::FRAC_1_SQRT_2),
            "0.7071067811865476"
        );
        assert_eq!(iges_real(1e-7), "1.0E-7");
        assert_eq!(iges_real(1.5e300), "1.5E300");
        assert_eq!(iges_real(1.0 / 3.0).parse::<f64>().unwrap(), 1.0 / 3.0);
    }

    #[test]
    fn packing_respects_the_width() {
        let tokens: Vec<String> = (0..40).map(|i| format!("{}.0", i * 1000)).collect();
        let lines = pack(&tokens, 64);
        assert!(lines.iter().all(|l| l.len() <= 64));
        assert_eq!(lines.concat().matches(',').count(), 39);
        assert!(lines.concat().ends_with(';'));
    }
}
