//! Texture images: PNG (the `png` crate) and JPEG (`zune-jpeg`), decoded to RGBA8.
//!
//! The size is read from the header and checked against
//! [`limn_scene::texture::MAX_TEXTURE_PIXELS`] and
//! [`limn_scene::texture::MAX_TEXTURE_SIDE`] before any pixel memory is allocated; the
//! decoders' own limits are set to the same bound. PNG of any colour type and bit depth
//! is expanded to 8-bit RGBA (16-bit samples keep their high byte); JPEG greyscale, YCbCr
//! and CMYK are converted to RGBA by the decoder.

use std::io::Cursor;
use std::sync::Arc;

use limn_scene::texture::{check_texture_size, MAX_TEXTURE_PIXELS, MAX_TEXTURE_SIDE};
use limn_scene::Texture;
use zune_jpeg::zune_core::colorspace::ColorSpace;
use zune_jpeg::zune_core::options::DecoderOptions;
use zune_jpeg::JpegDecoder;

use super::{LoadError, Location};

/// Decodes `bytes` (PNG or JPEG, told apart by their signatures) into a texture named
/// `name`; errors are reported at `at` (the line or record naming the image).
pub(crate) fn decode(bytes: &[u8], name: &str, at: &Location) -> Result<Arc<Texture>, LoadError> {
    let fail = |message: String| LoadError::Image {
        at: at.clone(),
        image: name.to_string(),
        message,
    };
    let (width, height, rgba) = if bytes.starts_with(b"\x89PNG\r\n\x1a\n") {
        decode_png(bytes).map_err(fail)?
    } else if bytes.starts_with(&[0xFF, 0xD8]) {
        decode_jpeg(bytes).map_err(fail)?
    } else if bytes.is_empty() {
        return Err(fail("the file is empty".into()));
    } else {
        return Err(fail("neither PNG nor JPEG (unknown signature)".into()));
    };
    Texture::new(name, width, height, rgba)
        .map(Arc::new)
        .map_err(|e| fail(e.to_string()))
}

fn size_error(width: u32, height: u32) -> String {
    check_texture_size(width, height)
        .err()
        .map_or_else(String::new, |e| e.to_string())
}

fn decode_png(bytes: &[u8]) -> Result<(u32, u32, Vec<u8>), String> {
    let mut decoder = png::Decoder::new_with_limits(
        Cursor::new(bytes),
        png::Limits {
            // Room for the largest texture at 16 bits per channel.
            bytes: (MAX_TEXTURE_PIXELS * 8) as usize,
        },
    );
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder
        .read_info()
        .map_err(|e| format!("corrupt PNG: {e}"))?;
    let (width, height) = (reader.info().width, reader.info().height);
    if check_texture_size(width, height).is_err() {
        return Err(size_error(width, height));
    }
    let mut buf = vec![0; reader.output_buffer_size()];
    let frame = reader
        .next_frame(&mut buf)
        .map_err(|e| format!("corrupt PNG: {e}"))?;
    buf.truncate(frame.buffer_size());
    let texels = width as usize * height as usize;
    let rgba = match frame.color_type {
        png::ColorType::Rgba => buf,
        png::ColorType::Rgb => buf
            .chunks_exact(3)
            .flat_map(|p| [p[0], p[1], p[2], 255])
            .collect(),
        png::ColorType::GrayscaleAlpha => buf
            .chunks_exact(2)
            .flat_map(|p| [p[0], p[0], p[0], p[1]])
            .collect(),
        png::ColorType::Grayscale => buf.iter().flat_map(|&g| [g, g, g, 255]).collect(),
        png::ColorType::Indexed => return Err("indexed PNG was not expanded".into()),
    };
    if rgba.len() != 4 * texels {
        return Err("PNG data does not match its size".into());
    }
    Ok((width, height, rgba))
}

fn decode_jpeg(bytes: &[u8]) -> Result<(u32, u32, Vec<u8>), String> {
    let options = DecoderOptions::default()
        .set_max_width(MAX_TEXTURE_SIDE as usize)
        .set_max_height(MAX_TEXTURE_SIDE as usize)
        .jpeg_set_out_colorspace(ColorSpace::RGBA);
    let mut decoder = JpegDecoder::new_with_options(Cursor::new(bytes), options);
    decoder
        .decode_headers()
        .map_err(|e| format!("corrupt JPEG: {e:?}"))?;
    let info = decoder.info().ok_or("corrupt JPEG: no frame header")?;
    let (width, height) = (u32::from(info.width), u32::from(info.height));
    if check_texture_size(width, height).is_err() {
        return Err(size_error(width, height));
    }
    let rgba = decoder
        .decode()
        .map_err(|e| format!("corrupt JPEG: {e:?}"))?;
    if rgba.len() != 4 * width as usize * height as usize {
        return Err("JPEG data does not match its size".into());
    }
    Ok((width, height, rgba))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::Path;

    /// A PNG of `w` × `h` RGB texels, `f(i, j)` each.
    pub(crate) fn png_bytes(w: u32, h: u32, f: impl Fn(u32, u32) -> [u8; 3]) -> Vec<u8> {
        let mut out = Vec::new();
        let mut e = png::Encoder::new(&mut out, w, h);
        e.set_color(png::ColorType::Rgb);
        e.set_depth(png::BitDepth::Eight);
        let mut wr = e.write_header().unwrap();
        let f = &f;
        let data: Vec<u8> = (0..h)
            .flat_map(|j| (0..w).flat_map(move |i| f(i, j)))
            .collect();
        wr.write_image_data(&data).unwrap();
        drop(wr);
        out
    }

    #[test]
    fn png_is_decoded_to_rgba() {
        let bytes = png_bytes(3, 2, |i, j| [i as u8 * 100, j as u8 * 200, 7]);
        let at = Location::line(Path::new("m.mtl"), 4);
        let t = decode(&bytes, "t.png", &at).unwrap();
        assert_eq!((t.width(), t.height()), (3, 2));
        assert_eq!(&t.rgba()[..8], &[0, 0, 7, 255, 100, 0, 7, 255]);
        assert_eq!(&t.rgba()[4 * 5..], &[200, 200, 7, 255]);
    }

    #[test]
    fn corrupt_and_unknown_images_name_the_line() {
        let at = Location::line(Path::new("m.mtl"), 4);
        let mut bytes = png_bytes(4, 4, |_, _| [1, 2, 3]);
        let n = bytes.len();
        bytes.truncate(n - 20);
        for bad in [&bytes[..], b"GIF89a", b"", &[0xFF, 0xD8, 0xFF, 0x00][..]] {
            let e = decode(bad, "t.png", &at).unwrap_err();
            assert!(matches!(e, LoadError::Image { .. }), "{e}");
            assert!(
                e.to_string()
                    .starts_with("m.mtl:4: texture image \"t.png\""),
                "{e}"
            );
        }
    }

    #[test]
    fn huge_headers_are_refused_before_allocating() {
        // A valid header claiming 20000 × 20000 texels, and no data.
        let mut bytes = png_bytes(1, 1, |_, _| [0, 0, 0]);
        // IHDR width and height sit at bytes 16..24; fix the chunk's CRC after them.
        bytes[16..20].copy_from_slice(&20000u32.to_be_bytes());
        bytes[20..24].copy_from_slice(&20000u32.to_be_bytes());
        let crc = crc32(&bytes[12..29]);
        bytes[29..33].copy_from_slice(&crc.to_be_bytes());
        let at = Location::line(Path::new("m.mtl"), 2);
        let e = decode(&bytes, "big.png", &at).unwrap_err();
        assert!(e.to_string().contains("20000 × 20000"), "{e}");
    }

    fn crc32(data: &[u8]) -> u32 {
        let mut c = 0xFFFF_FFFFu32;
        for &b in data {
            c ^= u32::from(b);
            for _ in 0..8 {
                c = if c & 1 != 0 {
                    0xEDB8_8320 ^ (c >> 1)
                } else {
                    c >> 1
                };
            }
        }
        !c
    }
}
