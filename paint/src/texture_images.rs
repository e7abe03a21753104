//! Texture images as the vector formats embed them: PNG for SVG `data:` URIs, raw RGB
//! rows for PDF image XObjects (which compress them themselves). Texture alpha is not
//! drawn (see [`limn_scene::texture`]), so both carry RGB only.

use base64::Engine as _;
use limn_scene::Texture;
use tiny_skia::{IntSize, Pixmap};

/// The texture as a `data:image/png;base64,…` URI (opaque: alpha set to 255); `None`
/// if it cannot be encoded.
pub(crate) fn png_data_uri(t: &Texture) -> Option<String> {
    let mut rgba = t.rgba().to_vec();
    for px in rgba.chunks_exact_mut(4) {
        px[3] = 255;
    }
    let size = IntSize::from_wh(t.width(), t.height())?;
    let png = Pixmap::from_vec(rgba, size)?.encode_png().ok()?;
    let mut uri = String::from("data:image/png;base64,");
    base64::engine::general_purpose::STANDARD.encode_string(png, &mut uri);
    Some(uri)
}

/// The texture's RGB bytes, rows top to bottom.
pub(crate) fn rgb_rows(t: &Texture) -> Vec<u8> {
    t.rgba()
        .chunks_exact(4)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect()
}
