//! PNG figures: the SVG rasterized with resvg (feature `png`), for LaTeX answer keys, which
//! pdflatex cannot include as SVG.

use crate::{Raster, RenderError};

/// The PNG of an SVG figure, at `scale` times its size (2 gives a sharp figure in print).
pub fn svg_to_png(svg: &str, scale: f32) -> Result<Vec<u8>, RenderError> {
    let mut opt = resvg::usvg::Options::default();
    opt.fontdb_mut().load_system_fonts();
    let tree = resvg::usvg::Tree::from_str(svg, &opt)
        .map_err(|e| RenderError::Raster(Raster::Library(e.to_string())))?;
    let size = tree.size().to_int_size().scale_by(scale).ok_or_else(|| {
        RenderError::Raster(Raster::Scale {
            scale: scale.to_string(),
        })
    })?;
    let mut pixmap = resvg::tiny_skia::Pixmap::new(size.width(), size.height())
        .ok_or_else(|| RenderError::Raster(Raster::NoArea))?;
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::from_scale(scale, scale),
        &mut pixmap.as_mut(),
    );
    pixmap
        .encode_png()
        .map_err(|e| RenderError::Raster(Raster::Library(e.to_string())))
}
