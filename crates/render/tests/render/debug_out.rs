//! Writes the figures to the temporary folder (`/tmp/cagd-render/`) as SVG and PNG so a person
//! can look at them.

use crate::raster::rasterize;
use crate::scenes;
use cagd_render::{render_svg, Layers, SvgOptions};

pub fn out_dir() -> std::path::PathBuf {
    let d = std::env::temp_dir().join("cagd-render");
    std::fs::create_dir_all(&d).unwrap();
    d
}

pub fn save(name: &str, svg: &str) {
    let d = out_dir();
    std::fs::write(d.join(format!("{name}.svg")), svg).unwrap();
    rasterize(svg)
        .save_png(d.join(format!("{name}.png")))
        .unwrap();
}

#[test]
fn write_figures_for_a_look() {
    let o = SvgOptions::default();
    save(
        "look-coons",
        &render_svg(&scenes::coons_scene(), &o).unwrap(),
    );
    save(
        "look-ruled",
        &render_svg(&scenes::ruled_scene(), &o).unwrap(),
    );
    save("look-c1", &render_svg(&scenes::c1_scene(), &o).unwrap());
    let normals = SvgOptions {
        layers: Layers {
            normals: true,
            ..Layers::default()
        },
        ..SvgOptions::default()
    };
    save(
        "look-sphere-normals",
        &render_svg(&scenes::sphere_scene(), &normals).unwrap(),
    );
}
