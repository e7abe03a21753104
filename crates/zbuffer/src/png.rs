//! PNG writers: colour, depth (grey), face ids (hash colours) and comparison diffs.

use std::path::Path;

use tiny_skia::Pixmap;

use crate::image::{ColorImage, DepthImage, IdImage, Mask, NO_FACE};
use crate::ZError;

fn encode(width: u32, height: u32, pixel: impl Fn(usize) -> [u8; 3]) -> Result<Vec<u8>, ZError> {
    let mut pm = Pixmap::new(width, height)
        .ok_or_else(|| ZError::Png(format!("cannot make a {width}x{height} picture")))?;
    for (i, px) in pm.data_mut().chunks_exact_mut(4).enumerate() {
        let [r, g, b] = pixel(i);
        px.copy_from_slice(&[r, g, b, 255]);
    }
    pm.encode_png().map_err(|e| ZError::Png(e.to_string()))
}

fn save(path: &Path, bytes: &[u8]) -> Result<(), ZError> {
    std::fs::write(path, bytes).map_err(|e| ZError::Io {
        path: path.display().to_string(),
        message: e.to_string(),
    })
}

/// A colour for a face id: a hash of the id, never very dark; black for [`NO_FACE`].
pub fn id_color(id: u32) -> [u8; 3] {
    if id == NO_FACE {
        return [0, 0, 0];
    }
    // A 32-bit integer mix (lowbias32) so that neighbouring ids get unrelated colours.
    let mut x = id.wrapping_add(0x9e37_79b9);
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^= x >> 16;
    let c = x.to_le_bytes();
    [c[0] | 0x40, c[1] | 0x40, c[2] | 0x40]
}

impl ColorImage {
    /// Encodes as an 8-bit RGB PNG.
    pub fn encode_png(&self) -> Result<Vec<u8>, ZError> {
        encode(self.width, self.height, |i| self.pixels[i])
    }

    /// Writes [`ColorImage::encode_png`] to a file.
    pub fn save_png(&self, path: &Path) -> Result<(), ZError> {
        save(path, &self.encode_png()?)
    }
}

impl DepthImage {
    /// Encodes as grey levels: the nearest depth in the picture black, the farthest a
    /// light grey (220), linearly between; pixels without a face white.
    pub fn encode_png(&self) -> Result<Vec<u8>, ZError> {
        let finite = self.depths.iter().copied().filter(|d| d.is_finite());
        let lo = finite.clone().fold(f64::INFINITY, f64::min);
        let hi = finite.fold(f64::NEG_INFINITY, f64::max);
        let span = if hi > lo { hi - lo } else { 1.0 };
        encode(self.width, self.height, |i| {
            let d = self.depths[i];
            if !d.is_finite() {
                return [255; 3];
            }
            let g = (((d - lo) / span) * 220.0).round().clamp(0.0, 220.0) as u8;
            [g; 3]
        })
    }

    /// Writes [`DepthImage::encode_png`] to a file.
    pub fn save_png(&self, path: &Path) -> Result<(), ZError> {
        save(path, &self.encode_png()?)
    }
}

impl IdImage {
    /// Encodes with one hash colour per face ([`id_color`]).
    pub fn encode_png(&self) -> Result<Vec<u8>, ZError> {
        encode(self.width, self.height, |i| id_color(self.ids[i]))
    }

    /// Writes [`IdImage::encode_png`] to a file.
    pub fn save_png(&self, path: &Path) -> Result<(), ZError> {
        save(path, &self.encode_png()?)
    }
}

/// A picture of a comparison: mismatches outside the band red, band pixels grey,
/// matching pixels in their face's colour dimmed to a third. Both images must have the
/// same size (and the band too, when given).
pub fn diff_png(a: &IdImage, b: &IdImage, band: Option<&Mask>) -> Result<Vec<u8>, ZError> {
    if (a.width, a.height) != (b.width, b.height) {
        return Err(ZError::SizeMismatch(a.width, a.height, b.width, b.height));
    }
    if let Some(m) = band {
        if (m.width, m.height) != (a.width, a.height) {
            return Err(ZError::SizeMismatch(a.width, a.height, m.width, m.height));
        }
    }
    encode(a.width, a.height, |i| {
        if band.is_some_and(|m| m.bits[i]) {
            [128; 3]
        } else if a.ids[i] != b.ids[i] {
            [255, 0, 0]
        } else {
            id_color(a.ids[i]).map(|c| c / 3)
        }
    })
}

/// Writes [`diff_png`] to a file.
pub fn save_diff_png(
    a: &IdImage,
    b: &IdImage,
    band: Option<&Mask>,
    path: &Path,
) -> Result<(), ZError> {
    save(path, &diff_png(a, b, band)?)
}
