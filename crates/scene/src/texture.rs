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
//! modes become repetition of a larger texture (see [`crate::texture_wrap`]).
//!
//! **Alpha** is drawn as the texture's [`TextureAlpha`] says (glTF's `alphaMode`; other
//! formats' textures are [`TextureAlpha::Opaque`]): not at all; as opacity sampled like
//! the colour but on premultiplied texels (so a transparent texel's colour never shows),
//! multiplying the face's; or as a cut-out decided per texel: a point of the face shows
//! exactly when the texel it lies in does (the texel holding the sample point, not a
//! mix of neighbours), so the boundary runs along texel edges in every output, and the
//! colour there is sampled as for an opaque texture.

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

/// How a texture's alpha channel is drawn (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum TextureAlpha {
    /// Not drawn: every texel is opaque (OBJ's `map_Kd`, glTF `OPAQUE`, and every
    /// texture whose alpha is 255 throughout).
    #[default]
    Opaque,
    /// Opacity: the alpha sampled bilinearly multiplies the face's opacity.
    Blend,
    /// A cut-out: each texel is shown (alpha 255) or not (alpha 0), wholly.
    Mask,
}

/// A decoded texture image (RGBA, 8 bits per channel, rows top to bottom).
#[derive(Clone, PartialEq, Eq)]
pub struct Texture {
    name: String,
    width: u32,
    height: u32,
    rgba: Vec<u8>,
    alpha: TextureAlpha,
}

impl fmt::Debug for Texture {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Texture")
            .field("name", &self.name)
            .field("width", &self.width)
            .field("height", &self.height)
            .field("alpha", &self.alpha)
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
            alpha: TextureAlpha::Opaque,
        })
    }

    /// How the alpha channel is drawn.
    pub fn alpha(&self) -> TextureAlpha {
        self.alpha
    }

    /// Whether every point of the texture is drawn opaque (its alpha is not drawn, or
    /// is 255 throughout).
    pub fn is_opaque(&self) -> bool {
        self.alpha == TextureAlpha::Opaque
    }

    /// The texture with its alpha drawn as `mode`: under [`TextureAlpha::Mask`] a texel
    /// shows when its alpha is at least 128 (the alpha becomes 255, else 0; a loader
    /// decides which texels show with [`Texture::masked`]). A texture whose alpha is
    /// then 255 throughout is [`TextureAlpha::Opaque`]: drawn as it was.
    pub fn with_alpha(mut self, mode: TextureAlpha) -> Texture {
        if mode == TextureAlpha::Mask {
            for px in self.rgba.chunks_exact_mut(4) {
                px[3] = if px[3] >= 128 { 255 } else { 0 };
            }
            self.bleed_into_hidden();
        }
        let all_opaque = self.rgba.chunks_exact(4).all(|px| px[3] == 255);
        self.alpha = if all_opaque {
            TextureAlpha::Opaque
        } else {
            mode
        };
        self
    }

    /// Gives each hidden texel (alpha 0) of a cut-out next to shown ones (the eight
    /// around it, repeating) their mean colour: the colour is sampled bilinearly as an
    /// opaque texture's, and near the cut-out's edge it then mixes only shown colours,
    /// in every output alike. Shown texels do not change, so doing it twice changes
    /// nothing.
    fn bleed_into_hidden(&mut self) {
        let (w, h) = (i64::from(self.width), i64::from(self.height));
        let src = self.rgba.clone();
        let at = |i: i64, j: i64| 4 * (j.rem_euclid(h) * w + i.rem_euclid(w)) as usize;
        for j in 0..h {
            for i in 0..w {
                if src[at(i, j) + 3] != 0 {
                    continue;
                }
                let (mut sum, mut n) = ([0u32; 3], 0u32);
                for (di, dj) in [
                    (-1, -1),
                    (0, -1),
                    (1, -1),
                    (-1, 0),
                    (1, 0),
                    (-1, 1),
                    (0, 1),
                    (1, 1),
                ] {
                    let k = at(i + di, j + dj);
                    if src[k + 3] != 0 {
                        for c in 0..3 {
                            sum[c] += u32::from(src[k + c]);
                        }
                        n += 1;
                    }
                }
                let k = at(i, j);
                for (v, s) in self.rgba[k..k + 3].iter_mut().zip(sum) {
                    if let Some(mean) = (s + n / 2).checked_div(n) {
                        *v = mean as u8;
                    }
                }
            }
        }
    }

    /// The texture as a cut-out ([`TextureAlpha::Mask`]) in which the texels for which
    /// `shows(alpha)` holds are shown and the others are not (glTF: the base colour
    /// factor's alpha times the texel's at least `alphaCutoff`).
    pub fn masked(mut self, shows: impl Fn(u8) -> bool) -> Texture {
        for px in self.rgba.chunks_exact_mut(4) {
            px[3] = if shows(px[3]) { 255 } else { 0 };
        }
        self.with_alpha(TextureAlpha::Mask)
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

    /// Texel `(i, j)`'s alpha in [0, 1] (indices taken modulo the size; 1 when the
    /// alpha is not drawn).
    pub fn texel_alpha(&self, i: i64, j: i64) -> f64 {
        if self.alpha == TextureAlpha::Opaque {
            return 1.0;
        }
        let i = i.rem_euclid(i64::from(self.width)) as usize;
        let j = j.rem_euclid(i64::from(self.height)) as usize;
        f64::from(self.rgba[4 * (j * self.width as usize + i) + 3]) / 255.0
    }

    /// The colour and alpha at texture coordinates `st`, RGBA in [0, 1] (see the module
    /// docs): opaque, the colour of [`Texture::sample`], for [`TextureAlpha::Opaque`];
    /// under [`TextureAlpha::Mask`] the same colour with alpha 1 or 0 as the texel
    /// holding `st` shows or not; under [`TextureAlpha::Blend`] bilinear on
    /// premultiplied texels (the colour of a point of alpha 0 is [`Texture::sample`]'s).
    /// Non-finite coordinates give the means.
    pub fn sample_rgba(&self, st: [f64; 2]) -> [f64; 4] {
        let finite = st[0].is_finite() && st[1].is_finite();
        match self.alpha {
            TextureAlpha::Opaque => {
                let [r, g, b] = self.sample(st);
                [r, g, b, 1.0]
            }
            _ if !finite => {
                let [r, g, b] = self.mean();
                [r, g, b, self.mean_alpha()]
            }
            TextureAlpha::Mask => {
                let [r, g, b] = self.sample(st);
                let i = (st[0].rem_euclid(1.0) * f64::from(self.width)).floor() as i64;
                let j = (st[1].rem_euclid(1.0) * f64::from(self.height)).floor() as i64;
                [r, g, b, self.texel_alpha(i, j)]
            }
            TextureAlpha::Blend => {
                let x = st[0].rem_euclid(1.0) * f64::from(self.width) - 0.5;
                let y = st[1].rem_euclid(1.0) * f64::from(self.height) - 0.5;
                let (fx, fy) = (x.floor(), y.floor());
                let (ax, ay) = (x - fx, y - fy);
                let (i, j) = (fx as i64, fy as i64);
                let mut sum = [0.0; 4];
                for (di, dj, w) in [
                    (0, 0, (1.0 - ax) * (1.0 - ay)),
                    (1, 0, ax * (1.0 - ay)),
                    (0, 1, (1.0 - ax) * ay),
                    (1, 1, ax * ay),
                ] {
                    let c = self.texel(i + di, j + dj);
                    let a = self.texel_alpha(i + di, j + dj);
                    for k in 0..3 {
                        sum[k] += w * a * c[k];
                    }
                    sum[3] += w * a;
                }
                if sum[3] > 0.0 {
                    [0, 1, 2, 3].map(|k| if k < 3 { sum[k] / sum[3] } else { sum[3] })
                } else {
                    let [r, g, b] = self.sample(st);
                    [r, g, b, 0.0]
                }
            }
        }
    }

    /// The mean alpha of all texels in [0, 1] (1 when the alpha is not drawn).
    pub fn mean_alpha(&self) -> f64 {
        if self.alpha == TextureAlpha::Opaque {
            return 1.0;
        }
        let sum: u64 = self.rgba.chunks_exact(4).map(|p| u64::from(p[3])).sum();
        sum as f64 / ((self.rgba.len() / 4).max(1) as f64 * 255.0)
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

    /// The texture's colour and alpha at world point `p` ([`Texture::sample_rgba`]; the
    /// means on a degenerate face).
    pub fn rgba_at(&self, p: DVec3) -> [f64; 4] {
        let st = self.st_at(p).unwrap_or([f64::NAN; 2]);
        self.texture.sample_rgba(st)
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

    /// 2 × 1: an opaque red texel left of a transparent blue one.
    fn half_transparent(mode: TextureAlpha) -> Texture {
        let rgba = vec![255, 0, 0, 255, 0, 0, 255, 0];
        Texture::new("h", 2, 1, rgba).unwrap().with_alpha(mode)
    }

    #[test]
    fn a_mask_shows_whole_texels_and_blend_mixes_premultiplied() {
        let m = half_transparent(TextureAlpha::Mask);
        assert_eq!(m.alpha(), TextureAlpha::Mask);
        // Up to the texels' shared edge at s = 0.5 the red texel shows, beyond it
        // nothing, whatever the bilinear colour there.
        assert_eq!(m.sample_rgba([0.49, 0.5])[3], 1.0);
        assert_eq!(m.sample_rgba([0.5, 0.5])[3], 0.0);
        assert_eq!(m.sample_rgba([0.999, 0.5])[3], 0.0);
        assert_eq!(m.sample_rgba([0.25, 0.5]), [1.0, 0.0, 0.0, 1.0]);
        // The hidden texel took its shown neighbour's colour: the bilinear colour at the
        // edge is the shown texel's.
        assert_eq!(m.sample_rgba([0.49, 0.5]), [1.0, 0.0, 0.0, 1.0]);
        let b = half_transparent(TextureAlpha::Blend);
        // Half-way between the texel centres: half as opaque, and red (the transparent
        // texel's blue does not show).
        assert_eq!(b.sample_rgba([0.5, 0.5]), [1.0, 0.0, 0.0, 0.5]);
        assert_eq!(b.sample_rgba([0.75, 0.5])[3], 0.0);
        assert_eq!(b.mean_alpha(), 0.5);
        // Not drawn: opaque, the colour as before.
        let o = half_transparent(TextureAlpha::Opaque);
        assert_eq!(o.sample_rgba([0.5, 0.5]), [0.5, 0.0, 0.5, 1.0]);
        assert!(o.is_opaque() && !b.is_opaque() && !m.is_opaque());
        // Alpha 255 throughout is opaque whatever the mode.
        assert!(checker().with_alpha(TextureAlpha::Blend).is_opaque());
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
