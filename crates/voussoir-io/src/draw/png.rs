//! PNG rendering of the SVG drawings with `resvg`, using only the bundled font (DejaVu Sans,
//! `assets/fonts/`, Bitstream Vera licence): no system fonts are read, so a PNG is the same on
//! every machine.

use crate::IoError;
use resvg::{tiny_skia, usvg};
use std::sync::{Arc, OnceLock};

/// DejaVu Sans, embedded in the binary.
pub static FONT_DATA: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

fn fontdb() -> Arc<usvg::fontdb::Database> {
    static DB: OnceLock<Arc<usvg::fontdb::Database>> = OnceLock::new();
    DB.get_or_init(|| {
        let mut db = usvg::fontdb::Database::new();
        db.load_font_data(FONT_DATA.to_vec());
        db.set_sans_serif_family("DejaVu Sans");
        db.set_serif_family("DejaVu Sans");
        db.set_monospace_family("DejaVu Sans");
        db.set_cursive_family("DejaVu Sans");
        db.set_fantasy_family("DejaVu Sans");
        Arc::new(db)
    })
    .clone()
}

/// Render an SVG document to PNG bytes, `zoom` pixels per SVG pixel (1.5 gives crisp text).
pub fn svg_to_png(svg: &str, zoom: f32) -> Result<Vec<u8>, IoError> {
    let pixmap = render(svg, zoom)?;
    pixmap
        .encode_png()
        .map_err(|e| IoError(format!("cannot encode PNG: {e}")))
}

/// Render an SVG document to an RGBA pixmap (for tests and further processing).
pub fn render(svg: &str, zoom: f32) -> Result<tiny_skia::Pixmap, IoError> {
    if !(zoom.is_finite() && zoom > 0.0 && zoom <= 16.0) {
        return Err(IoError(format!("PNG zoom must be in (0, 16], got {zoom}")));
    }
    let opt = usvg::Options {
        font_family: "DejaVu Sans".to_string(),
        fontdb: fontdb(),
        ..usvg::Options::default()
    };
    let tree =
        usvg::Tree::from_str(svg, &opt).map_err(|e| IoError(format!("cannot parse SVG: {e}")))?;
    let size = tree
        .size()
        .to_int_size()
        .scale_by(zoom)
        .ok_or_else(|| IoError("empty drawing".into()))?;
    if u64::from(size.width()) * u64::from(size.height()) > 400_000_000 {
        return Err(IoError(format!(
            "PNG of {}×{} pixels is too large",
            size.width(),
            size.height()
        )));
    }
    let mut pixmap = tiny_skia::Pixmap::new(size.width(), size.height())
        .ok_or_else(|| IoError("cannot allocate the PNG image".into()))?;
    pixmap.fill(tiny_skia::Color::WHITE);
    resvg::render(
        &tree,
        tiny_skia::Transform::from_scale(zoom, zoom),
        &mut pixmap.as_mut(),
    );
    Ok(pixmap)
}
