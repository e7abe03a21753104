//! Texture images and how they are sampled.
//!
//! A [`Texture`] is a decoded RGBA image, 8 bits per channel, top row first. Materials
//! hold it behind an [`Arc`], so a texture used by many faces is stored
//! once. Texture coordinates `(s, t)` are in image space: `s` runs left to right and `t`
//! top to bottom over `[0, 1]` (the glTF convention; the OBJ loader turns its `v`, which
//! runs bottom to top, into `t = 1 − v`).
//!
//! **Sampling** ([`Texture::sample`]) is bilinear between texel centres, texel `(i, j)`
//! having its centre at `((i + ½)/W, (j + ½)/H)`, and wraps by repetition in both
//! directions (the default of OBJ and glTF): coordinates are taken modulo 1, and the
//! neighbours of a texel on the last column or row are those of the first. Other wrap
//! modes become repetition of a larger texture (see [`crate::texture_wrap`]). The texture's
//! alpha channel is kept but not drawn: textured faces take their opacity from the
//! material.

use std::fmt;
use std::sync::Arc;

use glam::DVec3;
use thiserror::Error;

use crate::{fan_weights, Scene};

/// The most texels a texture may have: 2^26 (a 8192 × 8192 image), 256 MiB of RGBA.
pub const MAX_TEXTURE_PIXELS: u64 = 1 << 26;

/// The longest side a texture may have, in texels.
pub const MAX_TEXTURE_SIDE: u32 = 16384;

/// Why a texture cannot be made.
#[derive(Debug, Error, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum TextureError {
    /// Width or height is zero, a side is longer than [`MAX_TEXTURE_SIDE`], or there
    /// are more than [`MAX_TEXTURE_PIXELS`] texels.
    #[error(
        "texture of {width} × {height} texels: sides must be 1 to {MAX_TEXTURE_SIDE} and at \
         most {MAX_TEXTURE_PIXELS} texels in all"
    )]
    Size {
        /// Width in texels.
        width: u32,
        /// Height in texels.
        height: u32,
    },
    /// The pixel data is not `4 · width · height` bytes long.
    #[error("texture data has {got} bytes; {want} are needed for RGBA")]
    DataLength {
        /// Bytes given.
        got: usize,
        /// Bytes needed.
        want: usize,
    },
}

/// A decoded texture image (RGBA, 8 bits per channel, rows top to bottom).
#[derive(Clone, PartialEq, Eq)]
pub struct Texture {
    name: String,
    width: u32,
    height: u32,
    rgba: Vec<u8>,
}

impl fmt::Debug for Texture {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Texture")
            .field("name", &self.name)
            .field("width", &self.width)
            .field("height", &self.height)
            .finish_non_exhaustive()
    }
}

/// Checks a texture's size before anything is allocated for it.
pub fn check_texture_size(width: u32, height: u32) -> Result<(), TextureError> {
    let texels = u64::from(width) * u64::from(height);
    if width == 0
        || height == 0
        || width > MAX_TEXTURE_SIDE
        || height > MAX_TEXTURE_SIDE
        || texels > MAX_TEXTURE_PIXELS
    {
        return Err(TextureError::Size { width, height });
    }
    Ok(())
}

impl Texture {
    /// A texture from RGBA bytes (`4 · width · height` of them, rows top to bottom);
    /// `name` says where it came from (a file name, for messages and metadata).
    pub fn new(name: &str, width: u32, height: u32, rgba: Vec<u8>) -> Result<Self, TextureError> {
        check_texture_size(width, height)?;
        let want = 4 * width as usize * height as usize;
        if rgba.len() != want {
            return Err(TextureError::DataLength {
                got: rgba.len(),
                want,
            });
        }
        Ok(Texture {
            name: name.to_string(),
            width,
            height,
            rgba,
        })
    }

    /// Where the texture came from.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Width in texels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height in texels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The RGBA bytes, rows top to bottom.
    pub fn rgba(&self) -> &[u8] {
        &self.rgba
    }

    /// Texel `(i, j)` as RGB in [0, 1] (indices taken modulo the size).
    pub fn texel(&self, i: i64, j: i64) -> [f64; 3] {
        let i = i.rem_euclid(i64::from(self.width)) as usize;
        let j = j.rem_euclid(i64::from(self.height)) as usize;
        let at = 4 * (j * self.width as usize + i);
        let px = &self.rgba[at..at + 3];
        [px[0], px[1], px[2]].map(|v| f64::from(v) / 255.0)
    }

    /// The colour at texture coordinates `st` (see the module docs: bilinear, repeating);
    /// non-finite coordinates give the mean colour.
    pub fn sample(&self, st: [f64; 2]) -> [f64; 3] {
        if !st[0].is_finite() || !st[1].is_finite() {
            return self.mean();
        }
        let x = st[0].rem_euclid(1.0) * f64::from(self.width) - 0.5;
        let y = st[1].rem_euclid(1.0) * f64::from(self.height) - 0.5;
        let (fx, fy) = (x.floor(), y.floor());
        let (ax, ay) = (x - fx, y - fy);
        let (i, j) = (fx as i64, fy as i64);
        let (c00, c10) = (self.texel(i, j), self.texel(i + 1, j));
        let (c01, c11) = (self.texel(i, j + 1), self.texel(i + 1, j + 1));
        [0, 1, 2].map(|k| {
            let top = c00[k] + (c10[k] - c00[k]) * ax;
            let bottom = c01[k] + (c11[k] - c01[k]) * ax;
            top + (bottom - top) * ay
        })
    }

    /// The mean colour of all texels (RGB in [0, 1]).
    pub fn mean(&self) -> [f64; 3] {
        let mut sum = [0u64; 3];
        for px in self.rgba.chunks_exact(4) {
            for k in 0..3 {
                sum[k] += u64::from(px[k]);
            }
        }
        let n = (self.rgba.len() / 4).max(1) as f64 * 255.0;
        sum.map(|s| s as f64 / n)
    }
}

/// A textured face's corners and texture coordinates, gathered once for many look-ups
/// (the image-space renderers ask once per pixel).
///
/// A triangle maps its texture affinely in world space (so perspective-correctly on
/// screen). A larger face uses the fan triangle from its first corner that contains the
/// point, as vertex normals do ([`fan_weights`]).
#[derive(Debug, Clone, PartialEq)]
pub struct FaceTexcoords {
    corners: Vec<DVec3>,
    st: Vec<[f64; 2]>,
    texture: Arc<Texture>,
}

impl FaceTexcoords {
    /// The texture mapping of `face`; `None` unless the face has texture coordinates and
    /// its material a texture.
    pub fn new(scene: &Scene, face: u32) -> Option<FaceTexcoords> {
        let f = &scene.faces[face as usize];
        let ts = f.texcoords.as_ref()?;
        let texture = scene.materials[f.material as usize].texture.clone()?;
        Some(FaceTexcoords {
            corners: f
                .vertices
                .iter()
                .map(|&v| scene.vertices[v as usize])
                .collect(),
            st: ts.iter().map(|&t| scene.texcoords[t as usize]).collect(),
            texture,
        })
    }

    /// The face's corners.
    pub fn corners(&self) -> &[DVec3] {
        &self.corners
    }

    /// The texture coordinates of the face's corners.
    pub fn st(&self) -> &[[f64; 2]] {
        &self.st
    }

    /// The texture.
    pub fn texture(&self) -> &Arc<Texture> {
        &self.texture
    }

    /// The texture coordinates at world point `p` of the face; `None` when every fan
    /// triangle is degenerate.
    pub fn st_at(&self, p: DVec3) -> Option<[f64; 2]> {
        let ([a, b, c], w) = fan_weights(&self.corners, p)?;
        let st = &self.st;
        Some([0, 1].map(|k| st[a][k] * w[0] + st[b][k] * w[1] + st[c][k] * w[2]))
    }

    /// The texture's colour at world point `p` (the mean colour on a degenerate face).
    pub fn color_at(&self, p: DVec3) -> [f64; 3] {
        match self.st_at(p) {
            Some(st) => self.texture.sample(st),
            None => self.texture.mean(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn checker() -> Texture {
        // 2 × 2: black, white / white, black.
        let mut rgba = Vec::new();
        for v in [0u8, 255, 255, 0] {
            rgba.extend_from_slice(&[v, v, v, 255]);
        }
        Texture::new("c", 2, 2, rgba).unwrap()
    }

    #[test]
    fn texel_centres_are_exact_and_between_is_bilinear() {
        let t = checker();
        assert_eq!(t.sample([0.25, 0.25]), [0.0; 3]);
        assert_eq!(t.sample([0.75, 0.25]), [1.0; 3]);
        assert_eq!(t.sample([0.75, 0.75]), [0.0; 3]);
        assert_eq!(t.sample([0.5, 0.25]), [0.5; 3]);
        // Repeat: one period further is the same colour; the edge mixes first and last.
        assert_eq!(t.sample([1.25, -0.75]), [0.0; 3]);
        assert_eq!(t.sample([0.0, 0.25]), [0.5; 3]);
        assert_eq!(t.mean(), [0.5; 3]);
    }

    #[test]
    fn sizes_are_guarded() {
        assert!(matches!(
            Texture::new("x", 0, 4, vec![]),
            Err(TextureError::Size { .. })
        ));
        assert!(check_texture_size(MAX_TEXTURE_SIDE + 1, 1).is_err());
        assert!(check_texture_size(16384, 16384).is_err());
        assert!(check_texture_size(8192, 8192).is_ok());
        assert!(matches!(
            Texture::new("x", 2, 2, vec![0; 15]),
            Err(TextureError::DataLength { got: 15, want: 16 })
        ));
    }
}
