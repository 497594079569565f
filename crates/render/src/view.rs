//! The axonometric view, the fit of a drawing into its frame, and fixed number formatting.
//!
//! Drawing coordinates are the only place where f64 geometry lives: every point reaching this
//! module was computed exactly and converted with `Scalar::to_f64`.

/// A fixed axonometric (orthographic) view: the eye looks at the scene from the direction
/// `(cos e cos a, cos e sin a, sin e)` (azimuth a around the z axis from the x axis,
/// elevation e above the xy plane, both in degrees), with z up on the page.
///
/// The default, azimuth 30° and elevation 25°, shows the x axis coming toward the viewer on
/// the left, y to the right and z up, as the figures of the notes do.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// Degrees around the z axis, from the x axis toward the y axis.
    pub azimuth: f64,
    /// Degrees above the xy plane (90 looks straight down).
    pub elevation: f64,
}

impl Default for View {
    fn default() -> Self {
        View {
            azimuth: 30.0,
            elevation: 25.0,
        }
    }
}

impl View {
    /// The view from these angles, in degrees.
    pub fn new(azimuth: f64, elevation: f64) -> Self {
        View { azimuth, elevation }
    }

    /// The screen basis: right, up (on the page) and toward the viewer, as unit vectors.
    pub fn basis(&self) -> [[f64; 3]; 3] {
        let (a, e) = (self.azimuth.to_radians(), self.elevation.to_radians());
        let (sa, ca, se, ce) = (a.sin(), a.cos(), e.sin(), e.cos());
        [
            [-sa, ca, 0.0],
            [-se * ca, -se * sa, ce],
            [ce * ca, ce * sa, se],
        ]
    }

    /// `(x to the right, y up, depth toward the viewer)` of a point.
    pub fn project(&self, p: [f64; 3]) -> [f64; 3] {
        let [r, u, t] = self.basis();
        [dot(p, r), dot(p, u), dot(p, t)]
    }

    /// The direction of the light: from the viewer, somewhat above and to the left.
    pub fn light(&self) -> [f64; 3] {
        let [r, u, t] = self.basis();
        let l = [
            t[0] + 0.6 * u[0] - 0.4 * r[0],
            t[1] + 0.6 * u[1] - 0.4 * r[1],
            t[2] + 0.6 * u[2] - 0.4 * r[2],
        ];
        crate::sample::unit(l).unwrap_or(t)
    }
}

pub(crate) fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(crate) fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

pub(crate) fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The affine map from projected coordinates to the page: uniform scale, y down.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Frame {
    scale: f64,
    cx: f64,
    cy: f64,
    px: f64,
    py: f64,
}

impl Frame {
    /// The frame fitting the projected points `(x, y)` into the rectangle
    /// `(left, top, width, height)`, keeping the aspect ratio.
    pub fn fit(points: impl Iterator<Item = (f64, f64)>, rect: (f64, f64, f64, f64)) -> Frame {
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for (x, y) in points.filter(|(x, y)| x.is_finite() && y.is_finite()) {
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        if x0 > x1 {
            (x0, x1, y0, y1) = (-1.0, 1.0, -1.0, 1.0);
        }
        let (w, h) = ((x1 - x0).max(1e-9), (y1 - y0).max(1e-9));
        let (left, top, rw, rh) = rect;
        Frame {
            scale: (rw / w).min(rh / h),
            cx: (x0 + x1) / 2.0,
            cy: (y0 + y1) / 2.0,
            px: left + rw / 2.0,
            py: top + rh / 2.0,
        }
    }

    /// Page coordinates of projected `(x, y)`.
    pub fn page(&self, x: f64, y: f64) -> (f64, f64) {
        (
            self.px + (x - self.cx) * self.scale,
            self.py - (y - self.cy) * self.scale,
        )
    }
}

/// A number with one decimal, never `-0.0`: the fixed format of page coordinates.
pub(crate) fn n1(x: f64) -> String {
    fixed(x, 1)
}

/// A number with two decimals, never `-0.00`.
pub(crate) fn n2(x: f64) -> String {
    fixed(x, 2)
}

fn fixed(x: f64, decimals: usize) -> String {
    let x = if x.is_finite() { x } else { 0.0 };
    let s = format!("{x:.decimals$}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

/// Text escaped for XML and HTML, attribute values in either quotes included (`&`, `<`, `>`,
/// `"`, `'`): the one escape of the figures and of `cagd serve`'s pages.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixed_numbers_have_no_negative_zero() {
        assert_eq!(n1(-0.04), "0.0");
        assert_eq!(n1(-0.06), "-0.1");
        assert_eq!(n2(1.0 / 3.0), "0.33");
        assert_eq!(n1(f64::NAN), "0.0");
    }

    #[test]
    fn default_view_shows_x_left_y_right_z_up() {
        let v = View::default();
        let [x, y, z] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]].map(|p| v.project(p));
        assert!(
            x[0] < 0.0 && x[1] < 0.0 && x[2] > 0.0,
            "x comes toward the viewer, left"
        );
        assert!(y[0] > 0.0, "y goes right");
        assert!(z[1] > 0.0 && z[0] == 0.0, "z goes up");
        let [r, u, t] = v.basis();
        assert!((dot(r, u)).abs() < 1e-15 && dot(r, t).abs() < 1e-15 && dot(u, t).abs() < 1e-15);
    }

    #[test]
    fn escape_xml() {
        assert_eq!(escape("a<b & \"c\""), "a&lt;b &amp; &quot;c&quot;");
    }
}
