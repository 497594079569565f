//! Tessellations for 3D viewers: Wavefront OBJ and STL (ASCII and binary), with normals.

use crate::error::check_density;
use crate::geometry::SurfacePieces;
use crate::geometry::{parameter, point3};
use crate::sample::unit;
use crate::view::{cross, sub};
use crate::{Drawn, Magnitude, RenderError, Sampling, Scene};
use cagd_scalar::Scalar;
use std::fmt::Write;

/// A triangulated surface: vertices on an exact parameter grid, unit normals, triangles.
#[derive(Clone, Debug, PartialEq)]
pub struct Tessellation {
    /// The surface's name in the scene.
    pub name: String,
    /// `c(u_k, v_l)` for the grid `u_k = a + (b - a) k / n`, `v_l = c + (d - c) l / n`, row by
    /// row (k outer): vertex `k (n + 1) + l`.
    pub vertices: Vec<[f64; 3]>,
    /// The unit normal `c_u x c_v / |c_u x c_v|` at each vertex, computed exactly and then
    /// normalized; where it vanishes (a degenerate point such as the pole of the sphere
    /// octant) the normalized sum of the normals of the triangles around that point.
    pub normals: Vec<[f64; 3]>,
    /// Triangles as vertex indices, counter-clockwise seen from the side `c_u x c_v` points
    /// to. Triangles with two equal vertices (a collapsed row of the mesh) are left out.
    pub triangles: Vec<[usize; 3]>,
}

/// The tessellation of every surface of the scene on an `n x n` grid of cells (n = `density`,
/// 1 to 256), each cell split into two triangles.
pub fn tessellate<S: Scalar>(
    scene: &Scene<S>,
    density: usize,
) -> Result<Vec<Tessellation>, RenderError> {
    let n = check_density(Sampling::Tessellation, density, 1, 256)?;
    if scene.surfaces.is_empty() {
        return Err(RenderError::EmptyScene);
    }
    let mut out = Vec::with_capacity(scene.surfaces.len());
    for s in &scene.surfaces {
        let what = Drawn::Surface {
            name: s.name.clone(),
        };
        let exact = s.geometry.exact(&what)?;
        let mut vertices = Vec::with_capacity((n + 1) * (n + 1));
        let mut normals: Vec<Option<[f64; 3]>> = Vec::with_capacity((n + 1) * (n + 1));
        let vs: Vec<S> = (0..=n).map(|l| parameter(&exact.domain.1, l, n)).collect();
        // whether two exact vertices differ: then a tessellation without a triangle has lost
        // the surface to rounding
        let (mut first, mut extent) = (None, false);
        for k in 0..=n {
            let u = parameter(&exact.domain.0, k, n);
            let row = exact.row(&u, &vs)?;
            let row_normals = exact.normal_row(&u, &vs)?;
            for (p, normal) in row.iter().zip(&row_normals) {
                match &first {
                    None => first = Some(p.clone()),
                    Some(q) => extent |= q != p,
                }
                vertices.push(crate::sample::f64_point(p, &what)?);
                normals.push(point3(normal).and_then(unit));
            }
        }
        let index = |k: usize, l: usize| k * (n + 1) + l;
        let mut triangles = Vec::with_capacity(2 * n * n);
        for k in 0..n {
            for l in 0..n {
                let (a, b, c, d) = (
                    index(k, l),
                    index(k + 1, l),
                    index(k + 1, l + 1),
                    index(k, l + 1),
                );
                for t in [[a, b, c], [a, c, d]] {
                    if let Some([p, q, r]) = corners(&vertices, &t) {
                        if p != q && q != r && r != p {
                            triangles.push(t);
                        }
                    }
                }
            }
        }
        if triangles.is_empty() && extent {
            return Err(RenderError::Range {
                what,
                why: Magnitude::PointsEqual,
            });
        }
        // Degenerate normals: the sum of the normals of the triangles around the point (all
        // the vertices at that point, as a collapsed row is one point many times).
        let mut sums = vec![[0.0f64; 3]; vertices.len()];
        for t in &triangles {
            let f = triangle_normal(&vertices, t);
            for &i in t {
                if let Some(sum) = sums.get_mut(i) {
                    add_assign(sum, &f);
                }
            }
        }
        let normals = normals
            .iter()
            .zip(&vertices)
            .map(|(normal, v)| {
                normal.unwrap_or_else(|| {
                    let mut s = [0.0; 3];
                    for (p, sum) in vertices.iter().zip(&sums) {
                        if p == v {
                            add_assign(&mut s, sum);
                        }
                    }
                    unit(s).unwrap_or([0.0, 0.0, 1.0])
                })
            })
            .collect();
        out.push(Tessellation {
            name: s.name.clone(),
            vertices,
            normals,
            triangles,
        });
    }
    Ok(out)
}

/// `sum += f`, coordinate by coordinate.
fn add_assign(sum: &mut [f64; 3], f: &[f64; 3]) {
    for (s, x) in sum.iter_mut().zip(f) {
        *s += x;
    }
}

/// The three corners of triangle `t`; `None` if an index is not a vertex (never for the
/// triangles of [`tessellate`], whose indices are those of its grid).
fn corners(vertices: &[[f64; 3]], t: &[usize; 3]) -> Option<[[f64; 3]; 3]> {
    let [a, b, c] = *t;
    Some([*vertices.get(a)?, *vertices.get(b)?, *vertices.get(c)?])
}

/// The unit normal of a triangle, `(q - p) x (r - p)` normalized (zero if degenerate).
fn triangle_normal(vertices: &[[f64; 3]], t: &[usize; 3]) -> [f64; 3] {
    corners(vertices, t)
        .and_then(|[p, q, r]| unit(cross(sub(q, p), sub(r, p))))
        .unwrap_or([0.0; 3])
}

impl Tessellation {
    /// Every triangle as its unit normal and its three corners.
    fn facets(&self) -> impl Iterator<Item = ([f64; 3], [[f64; 3]; 3])> + '_ {
        self.triangles.iter().filter_map(|t| {
            let c = corners(&self.vertices, t)?;
            Some((triangle_normal(&self.vertices, t), c))
        })
    }
}

/// A number for OBJ and ASCII STL: six decimals, never `-0.000000`.
fn n6(x: f64) -> String {
    let s = format!("{:.6}", if x.is_finite() { x } else { 0.0 });
    match s.strip_prefix('-') {
        Some(abs) if abs.chars().all(|c| c == '0' || c == '.') => abs.to_string(),
        _ => s,
    }
}

/// A name usable in OBJ and STL: spaces and other characters outside `[A-Za-z0-9_.-]`
/// become `_`.
fn identifier(name: &str) -> String {
    let s: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || "_.-".contains(c) {
                c
            } else {
                '_'
            }
        })
        .collect();
    if s.is_empty() {
        "surface".into()
    } else {
        s
    }
}

/// The scene as a Wavefront OBJ file: one object `o` per surface with its vertices `v`, unit
/// normals `vn` and triangles `f v//vn` (see [`tessellate`]).
pub fn to_obj<S: Scalar>(scene: &Scene<S>, density: usize) -> Result<String, RenderError> {
    let parts = tessellate(scene, density)?;
    let mut out = String::new();
    let _ = writeln!(
        out,
        "# cagd-exact: tessellation on a {density} x {density} grid per surface"
    );
    let mut base = 1;
    for t in &parts {
        let _ = writeln!(out, "o {}", identifier(&t.name));
        for v in &t.vertices {
            let _ = writeln!(out, "v {} {} {}", n6(v[0]), n6(v[1]), n6(v[2]));
        }
        for n in &t.normals {
            let _ = writeln!(out, "vn {} {} {}", n6(n[0]), n6(n[1]), n6(n[2]));
        }
        for tri in &t.triangles {
            let [a, b, c] = tri.map(|i| i + base);
            let _ = writeln!(out, "f {a}//{a} {b}//{b} {c}//{c}");
        }
        base += t.vertices.len();
    }
    Ok(out)
}

/// The scene as an ASCII STL file: one `solid` holding every triangle of every surface, each
/// facet with its unit normal.
pub fn to_stl_ascii<S: Scalar>(scene: &Scene<S>, density: usize) -> Result<String, RenderError> {
    let parts = tessellate(scene, density)?;
    let name = identifier(scene.title.as_deref().unwrap_or("cagd"));
    let mut out = format!("solid {name}\n");
    for (n, corners) in parts.iter().flat_map(Tessellation::facets) {
        let _ = writeln!(out, "  facet normal {} {} {}", n6(n[0]), n6(n[1]), n6(n[2]));
        out.push_str("    outer loop\n");
        for v in corners {
            let _ = writeln!(out, "      vertex {} {} {}", n6(v[0]), n6(v[1]), n6(v[2]));
        }
        out.push_str("    endloop\n  endfacet\n");
    }
    let _ = writeln!(out, "endsolid {name}");
    Ok(out)
}

/// The scene as a binary STL file: an 80-byte header, the triangle count (u32, little
/// endian), then per triangle its normal and three vertices as f32 and a zero u16.
pub fn to_stl_binary<S: Scalar>(scene: &Scene<S>, density: usize) -> Result<Vec<u8>, RenderError> {
    let parts = tessellate(scene, density)?;
    let facets: Vec<_> = parts.iter().flat_map(Tessellation::facets).collect();
    let count = facets.len();
    let mut out = Vec::with_capacity(84 + 50 * count);
    let mut header = b"cagd-exact binary STL".to_vec();
    header.resize(80, b' ');
    out.extend(header);
    out.extend((count as u32).to_le_bytes());
    for (n, corners) in facets {
        let mut put = |v: [f64; 3]| {
            for c in v {
                out.extend((c as f32).to_le_bytes());
            }
        };
        put(n);
        for v in corners {
            put(v);
        }
        out.extend(0u16.to_le_bytes());
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn six_decimals_without_negative_zero() {
        assert_eq!(n6(-0.0000001), "0.000000");
        assert_eq!(n6(-0.5), "-0.500000");
        assert_eq!(n6(f64::NAN), "0.000000");
    }

    #[test]
    fn triangle_corners_and_normal() {
        let v = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
        assert_eq!(triangle_normal(&v, &[0, 1, 2]), [0.0, 0.0, 1.0]);
        assert_eq!(triangle_normal(&v, &[0, 2, 1]), [0.0, 0.0, -1.0]);
        // a missing vertex is no triangle rather than a panic
        assert_eq!(corners(&v, &[0, 1, 3]), None);
        assert_eq!(triangle_normal(&v, &[0, 1, 3]), [0.0; 3]);
    }
}
