//! Tessellations for 3D viewers: Wavefront OBJ and STL (ASCII and binary), with normals.

use crate::error::check_density;
use crate::geometry::{parameter, point3};
use crate::sample::unit;
use crate::view::{cross, sub};
use crate::{RenderError, Scene};
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
    let n = check_density("tessellation density", density, 1, 256)?;
    if scene.surfaces.is_empty() {
        return Err(RenderError::EmptyScene);
    }
    let mut out = Vec::with_capacity(scene.surfaces.len());
    for s in &scene.surfaces {
        let what = format!("surface {:?}", s.name);
        let exact = s.geometry.exact(&what)?;
        let mut vertices = Vec::with_capacity((n + 1) * (n + 1));
        let mut normals: Vec<Option<[f64; 3]>> = Vec::with_capacity((n + 1) * (n + 1));
        let vs: Vec<S> = (0..=n).map(|l| parameter(&exact.domain.1, l, n)).collect();
        for k in 0..=n {
            let u = parameter(&exact.domain.0, k, n);
            for (p, v) in exact.row(&u, &vs)?.iter().zip(&vs) {
                vertices.push(point3(p).ok_or_else(|| RenderError::Dimension {
                    what: what.clone(),
                    dim: p.dim(),
                })?);
                normals.push(point3(&exact.normal(&u, v)?).and_then(unit));
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
                    let [p, q, r] = t.map(|i| vertices[i]);
                    if p != q && q != r && r != p {
                        triangles.push(t);
                    }
                }
            }
        }
        // Degenerate normals: the sum of the normals of the triangles around the point (all
        // the vertices at that point, as a collapsed row is one point many times).
        let mut sums = vec![[0.0f64; 3]; vertices.len()];
        for t in &triangles {
            let f = triangle_normal(&vertices, t);
            for &i in t {
                for c in 0..3 {
                    sums[i][c] += f[c];
                }
            }
        }
        let normals = (0..vertices.len())
            .map(|i| {
                normals[i].unwrap_or_else(|| {
                    let mut s = [0.0; 3];
                    for (j, p) in vertices.iter().enumerate() {
                        if *p == vertices[i] {
                            for c in 0..3 {
                                s[c] += sums[j][c];
                            }
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

/// The unit normal of a triangle, `(q - p) x (r - p)` normalized (zero if degenerate).
fn triangle_normal(vertices: &[[f64; 3]], t: &[usize; 3]) -> [f64; 3] {
    let [p, q, r] = t.map(|i| vertices[i]);
    unit(cross(sub(q, p), sub(r, p))).unwrap_or([0.0; 3])
}

/// A number for OBJ and ASCII STL: six decimals, never `-0.000000`.
fn n6(x: f64) -> String {
    let s = format!("{:.6}", if x.is_finite() { x } else { 0.0 });
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
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
    for t in &parts {
        for tri in &t.triangles {
            let n = triangle_normal(&t.vertices, tri);
            let _ = writeln!(out, "  facet normal {} {} {}", n6(n[0]), n6(n[1]), n6(n[2]));
            out.push_str("    outer loop\n");
            for &i in tri {
                let v = t.vertices[i];
                let _ = writeln!(out, "      vertex {} {} {}", n6(v[0]), n6(v[1]), n6(v[2]));
            }
            out.push_str("    endloop\n  endfacet\n");
        }
    }
    let _ = writeln!(out, "endsolid {name}");
    Ok(out)
}

/// The scene as a binary STL file: an 80-byte header, the triangle count (u32, little
/// endian), then per triangle its normal and three vertices as f32 and a zero u16.
pub fn to_stl_binary<S: Scalar>(scene: &Scene<S>, density: usize) -> Result<Vec<u8>, RenderError> {
    let parts = tessellate(scene, density)?;
    let count: usize = parts.iter().map(|t| t.triangles.len()).sum();
    let mut out = Vec::with_capacity(84 + 50 * count);
    let mut header = b"cagd-exact binary STL".to_vec();
    header.resize(80, b' ');
    out.extend(header);
    out.extend((count as u32).to_le_bytes());
    for t in &parts {
        for tri in &t.triangles {
            let n = triangle_normal(&t.vertices, tri);
            let mut put = |v: [f64; 3]| {
                for c in v {
                    out.extend((c as f32).to_le_bytes());
                }
            };
            put(n);
            for &i in tri {
                put(t.vertices[i]);
            }
            out.extend(0u16.to_le_bytes());
        }
    }
    Ok(out)
}
