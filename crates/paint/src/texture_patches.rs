//! Patches: the part of a texture one face reads, as a texture of its own.
//!
//! Viewers draw an image by transforming all of it, then clipping: a 512 × 512 texture
//! drawn for each of four thousand small faces costs a PDF viewer a minute, whatever
//! the clips. So a fan triangle that reads a small part of its texture is given a patch
//! holding just the texels its bilinear samples reach (and [`REACH_PX`] pixels of page
//! beyond it, for the seam flaps), with its texture coordinates moved onto the patch:
//! every sample is the same texel mix as before, so the picture does not change.
//!
//! Patches are shared: the texture is divided into blocks of [`BLOCK`] texels
//! overlapping by half, and a triangle whose texels fit in one block uses that block;
//! a larger one gets a patch of its own, unless that would hold a quarter of the
//! texture or more, when it keeps the texture (which then serves every repetition).

use std::collections::HashMap;
use std::sync::Arc;

use limn_scene::Texture;

/// Side of a shared block, in texels (blocks start every `BLOCK / 2` texels). Small:
/// a viewer's time grows with the texels it draws (poppler takes about 3 ms for an
/// image of 66 × 66 texels, the same whether clipped to a few pixels or not).
pub(crate) const BLOCK: i64 = 16;

/// Page pixels beyond a face whose texels a patch also holds: seam flaps reach
/// half a pixel past the face by default.
pub(crate) const REACH_PX: f64 = 2.0;

/// The most texels beyond a face a patch holds: a face seen nearly edge-on spreads
/// more than this over a pixel, and keeps the texture (whose repetitions its flaps
/// then read, as they should).
pub(crate) const MAX_REACH_TEXELS: f64 = 8.0;

/// Patches made so far, each once: by texture and texel rectangle.
#[derive(Default)]
pub(crate) struct Patches {
    made: HashMap<(*const Texture, [i64; 4]), Arc<Texture>>,
}

impl Patches {
    /// The patch of `t` for a triangle with texture coordinates `st` whose samples may
    /// stray `reach` texels beyond them, and the coordinates moved onto it; `None` when
    /// the texture itself serves as well (see the module docs). A `magnified` triangle
    /// (a texel over more than a page pixel) gets the texels it reads and no more,
    /// never a shared block: a viewer resamples the whole image to the page, and a
    /// block's spare texels would cost it their enlarged area.
    pub fn patch(
        &mut self,
        t: &Arc<Texture>,
        st: [[f64; 2]; 3],
        reach: f64,
        magnified: bool,
    ) -> Option<(Arc<Texture>, [[f64; 2]; 3])> {
        let size = [i64::from(t.width()), i64::from(t.height())];
        if st.iter().flatten().any(|v| !v.is_finite()) {
            return None;
        }
        let near = reach <= MAX_REACH_TEXELS; // false for NaN
        if !near {
            return None;
        }
        // Whole repetitions off, so that the same texels make the same patch.
        let shift = [0, 1].map(|k| {
            st.iter()
                .map(|p| p[k])
                .fold(f64::INFINITY, f64::min)
                .floor()
        });
        let texel = st.map(|p| [0, 1].map(|k| (p[k] - shift[k]) * size[k] as f64));
        let mut range = [[0i64; 2]; 2];
        for k in 0..2 {
            let lo = texel.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min);
            let hi = texel.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max);
            // The texels whose centres surround every sample.
            let (a, b) = ((lo - 0.5 - reach).floor(), (hi - 0.5 + reach).floor() + 1.0);
            if b - a + 1.0 > (2 * size[k]) as f64 {
                return None;
            }
            let (a, b) = (a as i64, b as i64);
            let start = a.div_euclid(BLOCK / 2) * (BLOCK / 2);
            range[k] = if b < start + BLOCK && !magnified {
                [start, start + BLOCK - 1]
            } else {
                [a, b]
            };
        }
        let (w, h) = (range[0][1] - range[0][0] + 1, range[1][1] - range[1][0] + 1);
        if 4 * w * h >= size[0] * size[1] {
            return None;
        }
        let key = (
            Arc::as_ptr(t),
            [range[0][0], range[0][1], range[1][0], range[1][1]],
        );
        let patch = self
            .made
            .entry(key)
            .or_insert_with(|| {
                let mut rgba = Vec::with_capacity(4 * (w * h) as usize);
                for j in range[1][0]..=range[1][1] {
                    for i in range[0][0]..=range[0][1] {
                        let c = t.texel(i, j);
                        rgba.extend(c.map(|v| (v * 255.0).round() as u8));
                        rgba.push((t.texel_alpha(i, j) * 255.0).round() as u8);
                    }
                }
                let name = format!("{} (patch)", t.name());
                // Smaller than the texture: a valid size. Its texels are the texture's,
                // alpha included.
                let patch = Texture::new(&name, w as u32, h as u32, rgba).expect("patch size");
                Arc::new(patch.with_alpha(t.alpha()))
            })
            .clone();
        let moved = texel.map(|p| {
            [
                (p[0] - range[0][0] as f64) / w as f64,
                (p[1] - range[1][0] as f64) / h as f64,
            ]
        });
        Some((patch, moved))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 256 × 256 texels, each a colour of its own position.
    fn gradient() -> Arc<Texture> {
        let mut rgba = Vec::new();
        for j in 0..256u32 {
            for i in 0..256u32 {
                rgba.extend_from_slice(&[i as u8, j as u8, ((i * 7 + j * 13) % 256) as u8, 255]);
            }
        }
        Arc::new(Texture::new("g", 256, 256, rgba).unwrap())
    }

    #[test]
    fn a_patch_samples_as_its_texture() {
        let t = gradient();
        let mut patches = Patches::default();
        let st = [[1.1, 0.30], [1.15, 0.32], [1.12, 0.36]];
        let (p, moved) = patches.patch(&t, st, 2.0, false).unwrap();
        assert!(p.width() < 32 && p.height() < 32);
        // Corners, points between them, and points up to the reach beyond.
        for w in [
            [1.0, 0.0, 0.0],
            [0.2, 0.3, 0.5],
            [1.1, -0.05, -0.05],
            [-0.03, 1.02, 0.01],
        ] {
            let at = |s: &[[f64; 2]; 3]| {
                [0, 1].map(|k| w[0] * s[0][k] + w[1] * s[1][k] + w[2] * s[2][k])
            };
            let (a, b) = (t.sample(at(&st)), p.sample(at(&moved)));
            for k in 0..3 {
                assert!((a[k] - b[k]).abs() < 1e-9, "{a:?} {b:?}");
            }
        }
        // A neighbour in the same block shares the patch; a face reading a quarter of
        // the texture keeps the texture.
        let (q, _) = patches
            .patch(&t, st.map(|p| [p[0] - 1.0, p[1] + 2.0]), 2.0, false)
            .unwrap();
        assert!(Arc::ptr_eq(&p, &q));
        let small = [[0.1, 0.3], [0.11, 0.3], [0.1, 0.31]];
        let (a, _) = patches.patch(&t, small, 0.5, false).unwrap();
        let (b, _) = patches
            .patch(&t, small.map(|p| [p[0] + 0.003, p[1]]), 0.5, false)
            .unwrap();
        assert_eq!((a.width(), a.height()), (16, 16));
        assert!(Arc::ptr_eq(&a, &b), "a shared block");
        // Magnified, the same triangle gets only the texels it reads.
        let (c, _) = patches.patch(&t, small, 0.5, true).unwrap();
        assert!(c.width() < 8 && c.height() < 8, "{c:?}");
        assert!(patches
            .patch(&t, [[0.0, 0.0], [0.5, 0.0], [0.0, 0.5]], 2.0, false)
            .is_none());
        assert!(patches
            .patch(&t, [[0.0, 0.0], [9.0, 0.0], [0.0, 0.01]], 2.0, false)
            .is_none());
    }
}
