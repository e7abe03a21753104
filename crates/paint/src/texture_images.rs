//! Texture images as the vector formats embed them: PNG for SVG `data:` URIs, raw RGB
//! rows for PDF image XObjects (which compress them themselves). Only a blended
//! texture ([`limn_scene::TextureAlpha::Blend`]) carries its alpha: an RGBA PNG, a PDF
//! soft mask of its alpha rows; every other texture is embedded opaque, RGB only (a
//! cut-out's texels are clipped instead, see `texture_mask.rs`).
//!
//! **Padding.** Viewers interpolate an image only within itself: near its border they
//! clamp (or fade to transparent), where limn's repeating sampler blends with the
//! opposite border. So each image is embedded with a border of [`PAD`] texel taken from
//! the opposite side (the repeat), and placed so that its inner `W × H` texels fill the
//! texture's unit square: inside the square every viewer then interpolates as limn
//! samples.

use base64::Engine as _;
use limn_scene::{Texture, TextureAlpha};
use tiny_skia::{IntSize, Pixmap};

/// Texels of wrapped border around each embedded image.
pub(crate) const PAD: u32 = 1;

/// The texture with its wrapped border (see the module docs), RGBA (opaque unless the
/// texture is blended), and its size.
fn padded(t: &Texture) -> (Vec<u8>, u32, u32) {
    let keep_alpha = t.alpha() == TextureAlpha::Blend;
    let (w, h) = (t.width(), t.height());
    let (pw, ph) = (w + 2 * PAD, h + 2 * PAD);
    let src = t.rgba();
    let mut out = Vec::with_capacity(4 * pw as usize * ph as usize);
    for j in 0..ph {
        let sj = (i64::from(j) - i64::from(PAD)).rem_euclid(i64::from(h)) as usize;
        for i in 0..pw {
            let si = (i64::from(i) - i64::from(PAD)).rem_euclid(i64::from(w)) as usize;
            let at = 4 * (sj * w as usize + si);
            let a = if keep_alpha { src[at + 3] } else { 255 };
            out.extend_from_slice(&[src[at], src[at + 1], src[at + 2], a]);
        }
    }
    (out, pw, ph)
}

/// Where an embedded (padded) image of `w` × `h` texels goes in the unit square of one
/// texture repetition, for PDF and PostScript: the clip rectangle `[x y width height]`
/// (the unit square grown by half a texel, so neighbouring repetitions meet without a
/// gap) and the matrix placing the padded image around the unit square (its inner
/// texels fill it).
pub(crate) fn unit_square_placement(w: u32, h: u32) -> ([f64; 4], [f64; 6]) {
    let (iw, ih) = (f64::from(w - 2 * PAD), f64::from(h - 2 * PAD));
    let (px, py) = (f64::from(PAD) / iw, f64::from(PAD) / ih);
    let (hx, hy) = (0.5 / iw, 0.5 / ih);
    (
        [-hx, -hy, 1.0 + 2.0 * hx, 1.0 + 2.0 * hy],
        [1.0 + 2.0 * px, 0.0, 0.0, 1.0 + 2.0 * py, -px, -py],
    )
}

/// The padded texture as a `data:image/png;base64,…` URI (opaque, or RGBA for a
/// blended texture); `None` if it cannot be encoded.
pub(crate) fn png_data_uri(t: &Texture) -> Option<String> {
    let (rgba, w, h) = padded(t);
    let png = if t.alpha() == TextureAlpha::Blend {
        rgba_png(&rgba, w, h)?
    } else {
        let size = IntSize::from_wh(w, h)?;
        Pixmap::from_vec(rgba, size)?.encode_png().ok()?
    };
    let mut uri = String::from("data:image/png;base64,");
    base64::engine::general_purpose::STANDARD.encode_string(png, &mut uri);
    Some(uri)
}

/// `t` as it is (no border): its RGB bytes, rows top to bottom, and its size.
pub(crate) fn plain_rgb_rows(t: &Texture) -> (Vec<u8>, u32, u32) {
    let rgb = t
        .rgba()
        .chunks_exact(4)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect();
    (rgb, t.width(), t.height())
}

/// `t` as it is (no border), opaque, as a `data:image/png;base64,…` URI; `None` if it
/// cannot be encoded.
pub(crate) fn plain_png_data_uri(t: &Texture) -> Option<String> {
    let (rgb, _, _) = plain_rgb_rows(t);
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, t.width(), t.height());
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().ok()?;
    writer.write_image_data(&rgb).ok()?;
    writer.finish().ok()?;
    let mut uri = String::from("data:image/png;base64,");
    base64::engine::general_purpose::STANDARD.encode_string(out, &mut uri);
    Some(uri)
}

/// `rgba` (`w` × `h`, straight alpha) as a PNG file.
fn rgba_png(rgba: &[u8], w: u32, h: u32) -> Option<Vec<u8>> {
    let mut out = Vec::new();
    let mut encoder = png::Encoder::new(&mut out, w, h);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().ok()?;
    writer.write_image_data(rgba).ok()?;
    writer.finish().ok()?;
    Some(out)
}

/// The padded alpha of a blended texture, rows top to bottom (a PDF soft mask);
/// `None` for every other texture.
pub(crate) fn alpha_rows(t: &Texture) -> Option<Vec<u8>> {
    if t.alpha() != TextureAlpha::Blend {
        return None;
    }
    let (rgba, _, _) = padded(t);
    Some(rgba.chunks_exact(4).map(|p| p[3]).collect())
}

/// The padded texture's RGB bytes, rows top to bottom, and its size.
pub(crate) fn rgb_rows(t: &Texture) -> (Vec<u8>, u32, u32) {
    let (rgba, w, h) = padded(t);
    let rgb = rgba
        .chunks_exact(4)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect();
    (rgb, w, h)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_border_repeats_the_opposite_side() {
        let rgba: Vec<u8> = (0..6u8).flat_map(|v| [v, v, v, 7]).collect();
        let t = Texture::new("t", 3, 2, rgba).unwrap();
        let (rgb, w, h) = rgb_rows(&t);
        assert_eq!((w, h), (5, 4));
        let row = |j: usize| -> Vec<u8> { (0..5).map(|i| rgb[3 * (j * 5 + i)]).collect() };
        assert_eq!(row(0), vec![5, 3, 4, 5, 3]);
        assert_eq!(row(1), vec![2, 0, 1, 2, 0]);
        assert_eq!(row(2), vec![5, 3, 4, 5, 3]);
        assert_eq!(row(3), vec![2, 0, 1, 2, 0]);
    }
}
