//! Texture levels: a texture averaged down to what the page can show.
//!
//! A face that spreads many texels over each page pixel (a 2048 × 2048 texture on a
//! truck 300 pixels wide) shows their average, whatever the viewer: a viewer drawing the
//! whole image for it resamples millions of texels per face (minutes for a PDF viewer),
//! and its samples at pixel centres alias. So each axis of a face's texture is averaged
//! by a power of two while at least [`MIN_TEXELS_PER_PX`] texel remains over a page
//! pixel along it: box filters over exact areas, the texture's unit square unchanged,
//! so texture coordinates stay as they are. Faces that spread fewer than two texels
//! over a pixel keep the texture itself. Boundaries are not touched: only the colours
//! inside a face are the average of what its pixels cover rather than samples. A
//! blended texture's alpha is averaged with its colours, these weighted by it
//! (premultiplied, as it is sampled); a cut-out is never averaged (its texels decide
//! its boundary).

use std::collections::HashMap;
use std::sync::Arc;

use limn_scene::Texture;

/// Texels kept over one page pixel, along each texture axis, at least.
pub(crate) const MIN_TEXELS_PER_PX: f64 = 1.0;

/// The averaging factors (powers of two, at least 1) along s and t for a face whose
/// map takes a page pixel over `per_px` texels of the texture along s and along t
/// (non-finite for a face seen edge-on: no averaging then, its map is not of use).
pub(crate) fn factors(per_px: [f64; 2], size: (u32, u32)) -> [u32; 2] {
    let side = [size.0, size.1];
    [0, 1].map(|k| {
        let mut f = 1u32;
        let n = per_px[k];
        if !n.is_finite() {
            return 1;
        }
        while n / f64::from(2 * f) >= MIN_TEXELS_PER_PX && 2 * f <= side[k] {
            f *= 2;
        }
        f
    })
}

/// Levels made so far, each once: by texture and factors.
#[derive(Default)]
pub(crate) struct Levels {
    made: HashMap<(*const Texture, [u32; 2]), Arc<Texture>>,
}

impl Levels {
    /// `t` averaged by `factors` along its axes (`t` itself for factors of 1).
    pub fn level(&mut self, t: &Arc<Texture>, factors: [u32; 2]) -> Arc<Texture> {
        if factors == [1, 1] {
            return t.clone();
        }
        self.made
            .entry((Arc::as_ptr(t), factors))
            .or_insert_with(|| Arc::new(averaged(t, factors)))
            .clone()
    }
}

/// `t` averaged by `factors`: `round(side / factor)` texels along each axis (at least
/// one), each the mean of the texels under its box weighted by their area in it.
fn averaged(t: &Texture, factors: [u32; 2]) -> Texture {
    let (w, h) = (t.width() as usize, t.height() as usize);
    let nw = ((w as f64 / f64::from(factors[0])).round() as usize).max(1);
    let nh = ((h as f64 / f64::from(factors[1])).round() as usize).max(1);
    // Rows first (w → nw), then columns (h → nh), four channels each.
    let mut rows = vec![0.0f32; 4 * nw * h];
    let row_boxes = boxes(w, nw);
    // Colours weighted by alpha where the alpha is drawn (1 elsewhere).
    let blended = !t.is_opaque();
    for (j, row) in t.rgba().chunks_exact(4 * w).enumerate() {
        let out = &mut rows[4 * nw * j..4 * nw * (j + 1)];
        for &(o, i, weight) in &row_boxes {
            let a = if blended {
                f32::from(row[4 * i + 3]) / 255.0
            } else {
                1.0
            };
            for c in 0..3 {
                out[4 * o + c] += weight * a * f32::from(row[4 * i + c]);
            }
            out[4 * o + 3] += weight * f32::from(row[4 * i + 3]);
        }
    }
    let mut out = vec![0.0f32; 4 * nw * nh];
    for (o, j, weight) in boxes(h, nh) {
        let (from, to) = (&rows[4 * nw * j..4 * nw * (j + 1)], 4 * nw * o);
        for (v, f) in out[to..to + 4 * nw].iter_mut().zip(from) {
            *v += weight * f;
        }
    }
    if blended {
        // Back from premultiplied: each colour over its texel's mean alpha.
        for px in out.chunks_exact_mut(4) {
            let a = px[3] / 255.0;
            for c in &mut px[..3] {
                *c = if a > 0.0 { *c / a } else { 0.0 };
            }
        }
    }
    let rgba = out
        .iter()
        .map(|v| v.round().clamp(0.0, 255.0) as u8)
        .collect();
    let name = format!("{} (averaged)", t.name());
    // No larger than the texture: a valid size.
    let level = Texture::new(&name, nw as u32, nh as u32, rgba).expect("level size");
    level.with_alpha(t.alpha())
}

/// The boxes of `m` samples averaging a line of `n` (`m ≤ n`): `(output, input,
/// weight)` for each input sample under each output's box of `n / m` samples, the
/// weight its share of the box's length.
fn boxes(n: usize, m: usize) -> Vec<(usize, usize, f32)> {
    let r = n as f64 / m as f64;
    let mut list = Vec::with_capacity(n + m);
    for o in 0..m {
        let (a, b) = (o as f64 * r, (o + 1) as f64 * r);
        let mut i = a.floor() as usize;
        while (i as f64) < b && i < n {
            let weight = (b.min(i as f64 + 1.0) - a.max(i as f64)) / r;
            if weight > 0.0 {
                list.push((o, i, weight as f32));
            }
            i += 1;
        }
    }
    list
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn factors_keep_a_texel_per_pixel() {
        assert_eq!(factors([0.5, 1.9], (512, 512)), [1, 1]);
        assert_eq!(factors([2.0, 5.0], (512, 512)), [2, 4]);
        assert_eq!(factors([f64::INFINITY, 32.0], (512, 8)), [1, 8]);
    }

    #[test]
    fn a_level_is_the_mean_over_each_box() {
        // 3 × 2 texels averaged to 2 × 1: boxes of 1.5 texels across.
        let rgba = [0u8, 30, 60, 90, 120, 150]
            .iter()
            .flat_map(|&v| [v, 255 - v, 0, 255])
            .collect();
        let t = Arc::new(Texture::new("t", 3, 2, rgba).unwrap());
        let mut levels = Levels::default();
        let l = levels.level(&t, [2, 2]);
        assert_eq!((l.width(), l.height()), (2, 1));
        // Left box: texels 0 and half of 1 in both rows: (0 + 15 + 90 + 60) / 3 = 55.
        assert_eq!(l.rgba()[0], 55);
        assert_eq!(l.rgba()[1], 200);
        // Right box: half of 1 and texel 2: (15 + 60 + 60 + 150) / 3 = 95.
        assert_eq!(l.rgba()[4], 95);
        assert!(Arc::ptr_eq(&l, &levels.level(&t, [2, 2])));
        assert!(Arc::ptr_eq(&t, &levels.level(&t, [1, 1])));
    }
}
