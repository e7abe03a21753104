//! Texture coordinates that collapse: a fan triangle whose texture coordinates lie on
//! one point or one segment (real files have them: seams, caps, painted-over parts).
//!
//! Such a triangle shows one colour, or the colours along one segment of the image:
//! drawn as an image under an affine map, the map from texture to page is singular (or,
//! after rounding, has coefficients of 1e18), which viewers cannot draw. So it is drawn
//! as what its coordinates mean:
//!
//! - **A point**: a flat fill, the texture's colour there times the lit fill.
//! - **A segment**: a *strip*, a texture one texel high holding the colours sampled
//!   along the segment ([`STRIP_SAMPLES_PER_TEXEL`] samples per texel, one more texel
//!   at each end repeating the end colour, so that the strip's own wrapping never
//!   reaches the face), mapped onto the triangle by the projective map that sends each
//!   corner's position along the segment to the strip's and spreads the other direction
//!   over half the strip's height. The map is as well conditioned as the triangle on
//!   the page, so every writer draws the strip as any texture.
//!
//! **When coordinates count as collapsed.** Bilinear sampling changes colour by at most
//! `√2 · D` per texel of distance, where `D` is the largest difference of one channel
//! between neighbouring texels (wrapping included). A triangle whose texture
//! coordinates stay within a distance `δ` texels of a point (or of a segment) is drawn
//! within `√2 · D · δ` of its exact colours by the point's (the segment's). It counts as
//! collapsed when that is at most [`COLLAPSE_LEVELS`] of an 8-bit level, so exactly
//! collapsed coordinates always do, and a constant texture collapses every triangle to
//! its colour.

use std::collections::HashMap;
use std::sync::Arc;

use limn_scene::Texture;

/// The largest colour difference, in 8-bit levels, that drawing a triangle as a point
/// or a segment may make (see the module docs).
pub(crate) const COLLAPSE_LEVELS: f64 = 0.5;

/// Samples per texel of segment length in a strip.
pub(crate) const STRIP_SAMPLES_PER_TEXEL: f64 = 4.0;

/// The most samples a strip holds (a segment crossing the image 64 times over at 4,096
/// texels across gets fewer per texel).
pub(crate) const MAX_STRIP_SAMPLES: usize = 4096;

/// What a fan triangle's texture coordinates come to.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Collapse {
    /// Coordinates spanning an area: drawn under their own map.
    Area,
    /// One point (texture coordinates): one colour.
    Point([f64; 2]),
    /// A band along the segment from `from` to `to` (texture coordinates), `across` wide
    /// (the texture-coordinate offset from the segment to the far corner; zero when the
    /// coordinates lie on the segment); `along[i]` is where corner `i` lies along it,
    /// from 0 at `from` to 1 at `to`, and `side[i]` across it, 0 on the segment and 1 at
    /// `across`.
    Band(Band),
}

/// See [`Collapse::Band`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Band {
    pub from: [f64; 2],
    pub to: [f64; 2],
    pub across: [f64; 2],
    pub along: [f64; 3],
    pub side: [f64; 3],
}

/// The largest difference of one channel between neighbouring texels (horizontally or
/// vertically, wrapping included), in [0, 1]; alpha is a channel where it is drawn.
pub(crate) fn max_step(t: &Texture) -> f64 {
    let (w, h) = (t.width() as usize, t.height() as usize);
    let px = t.rgba();
    let at = |i: usize, j: usize| 4 * (j * w + i);
    let channels = if t.is_opaque() { 3 } else { 4 };
    let mut worst = 0u8;
    for j in 0..h {
        for i in 0..w {
            let p = at(i, j);
            for q in [at((i + 1) % w, j), at(i, (j + 1) % h)] {
                for k in 0..channels {
                    worst = worst.max(px[p + k].abs_diff(px[q + k]));
                }
            }
        }
    }
    f64::from(worst) / 255.0
}

/// Page pixels per texel beyond which a thin triangle (at most [`MAX_BAND_TEXELS`]
/// texels across) is drawn as a band resampled from the texture rather than under the
/// texture's own map: such a map blows a texel up past the page, and viewers transform
/// the whole image before clipping it.
pub(crate) const MAX_MAGNIFICATION: f64 = 64.0;

/// The widest band, in texels across (see [`MAX_MAGNIFICATION`]): wider triangles
/// keep their map however close they are seen.
pub(crate) const MAX_BAND_TEXELS: f64 = 1.0;

/// Classifies the texture coordinates `st` of a fan triangle with page corners `page`
/// on a texture of `size` texels whose neighbouring texels differ by at most `step`
/// (see the module docs).
pub(crate) fn classify(
    st: [[f64; 2]; 3],
    page: [[f64; 2]; 3],
    size: (u32, u32),
    step: f64,
) -> Collapse {
    if st.iter().chain(&page).flatten().any(|v| !v.is_finite()) {
        return Collapse::Area;
    }
    let (w, h) = (f64::from(size.0), f64::from(size.1));
    let p = st.map(|q| [q[0] * w, q[1] * h]);
    let levels = |texels: f64| std::f64::consts::SQRT_2 * step * texels * 255.0;
    let len = |a: usize, b: usize| (p[b][0] - p[a][0]).hypot(p[b][1] - p[a][1]);
    // The longest edge, from corner `a` to corner `b`.
    let (a, b) = [(0, 1), (1, 2), (2, 0)].into_iter().fold((0, 1), |m, e| {
        if len(e.0, e.1) > len(m.0, m.1) {
            e
        } else {
            m
        }
    });
    let long = len(a, b);
    if levels(long) <= COLLAPSE_LEVELS {
        let c = [0, 1].map(|k| (st[0][k] + st[1][k] + st[2][k]) / 3.0);
        return Collapse::Point(c);
    }
    let (ux, uy) = (p[b][0] - p[a][0], p[b][1] - p[a][1]);
    let c = 3 - a - b;
    let (vx, vy) = (p[c][0] - p[a][0], p[c][1] - p[a][1]);
    let thickness = (ux * vy - uy * vx).abs() / long;
    let collapsed = levels(thickness) <= COLLAPSE_LEVELS;
    if !collapsed && (thickness > MAX_BAND_TEXELS || magnification(p, page) <= MAX_MAGNIFICATION) {
        return Collapse::Area;
    }
    let mut along = [0.0; 3];
    along[b] = 1.0;
    along[c] = ((ux * vx + uy * vy) / (long * long)).clamp(0.0, 1.0);
    let mut side = [0.0; 3];
    let mut across = [0.0; 2];
    if !collapsed {
        side[c] = 1.0;
        // The far corner's offset from the segment, perpendicular to it.
        let t = along[c];
        across = [0, 1].map(|k| st[c][k] - (st[a][k] + (st[b][k] - st[a][k]) * t));
    }
    Collapse::Band(Band {
        from: st[a],
        to: st[b],
        across,
        along,
        side,
    })
}

/// The largest page length one texel takes (pixels per texel) under the affine map
/// taking texel points `t` to page points `page`; infinite when `t` is degenerate.
fn magnification(t: [[f64; 2]; 3], page: [[f64; 2]; 3]) -> f64 {
    stretch(t, page)
}

/// The linear part `[a11, a12, a21, a22]` (rows: the image's x, then y) of the affine
/// map taking triangle `from` to triangle `to`; `None` when `from` is degenerate.
pub(crate) fn linear_part(from: [[f64; 2]; 3], to: [[f64; 2]; 3]) -> Option<[f64; 4]> {
    let d = |q: &[[f64; 2]; 3], i: usize, k: usize| q[i][k] - q[0][k];
    let (t11, t12, t21, t22) = (
        d(&from, 1, 0),
        d(&from, 2, 0),
        d(&from, 1, 1),
        d(&from, 2, 1),
    );
    let det = t11 * t22 - t12 * t21;
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    // A = P · T⁻¹, P and T the differences of `to` and `from` as columns.
    let (p11, p12, p21, p22) = (d(&to, 1, 0), d(&to, 2, 0), d(&to, 1, 1), d(&to, 2, 1));
    Some([
        (p11 * t22 - p12 * t21) / det,
        (p12 * t11 - p11 * t12) / det,
        (p21 * t22 - p22 * t21) / det,
        (p22 * t11 - p21 * t12) / det,
    ])
}

/// The largest factor by which the affine map taking triangle `from` to triangle `to`
/// stretches a length (its largest singular value); infinite when `from` is degenerate.
pub(crate) fn stretch(from: [[f64; 2]; 3], to: [[f64; 2]; 3]) -> f64 {
    let Some([a11, a12, a21, a22]) = linear_part(from, to) else {
        return f64::INFINITY;
    };
    let f2 = a11 * a11 + a12 * a12 + a21 * a21 + a22 * a22;
    let dt = a11 * a22 - a12 * a21;
    let m = ((f2 + (f2 * f2 - 4.0 * dt * dt).max(0.0).sqrt()) / 2.0).sqrt();
    if m.is_finite() {
        m
    } else {
        f64::INFINITY
    }
}

/// Bands made so far, each once: by texture and band.
#[derive(Default)]
pub(crate) struct Strips {
    made: HashMap<(*const Texture, [u64; 6]), Arc<Texture>>,
}

/// A band's texture (see the module docs) and where its samples lie: the texture
/// coordinates of the point at position `λ` along the band and `μ` across it are
/// `(offset[0] + λ · scale[0], offset[1] + μ · scale[1])`.
pub(crate) struct Strip {
    pub texture: Arc<Texture>,
    pub offset: [f64; 2],
    pub scale: [f64; 2],
}

impl Strips {
    /// The texture of `band` of `t`: samples along it and across it, one more texel
    /// repeating the edge on every side.
    pub fn strip(&mut self, t: &Arc<Texture>, band: &Band) -> Strip {
        let (w, h) = (f64::from(t.width()), f64::from(t.height()));
        let count = |d: [f64; 2], most: usize| {
            let texels = (d[0] * w).hypot(d[1] * h);
            ((texels * STRIP_SAMPLES_PER_TEXEL).ceil() as usize + 1).clamp(2, most)
        };
        let (from, to, across) = (band.from, band.to, band.across);
        let n = count([to[0] - from[0], to[1] - from[1]], MAX_STRIP_SAMPLES);
        let m = if across == [0.0; 2] {
            1
        } else {
            count(across, MAX_BAND_ROWS)
        };
        let key = (
            Arc::as_ptr(t),
            [from[0], from[1], to[0], to[1], across[0], across[1]].map(f64::to_bits),
        );
        let texture = self
            .made
            .entry(key)
            .or_insert_with(|| {
                let mut rgba = Vec::with_capacity(4 * (n + 2) * (m + 2));
                let rows = if m == 1 { 1 } else { m + 2 };
                for r in 0..rows {
                    let mu = if m == 1 {
                        0.0
                    } else {
                        (r.clamp(1, m) - 1) as f64 / (m - 1) as f64
                    };
                    for k in 0..n + 2 {
                        let l = (k.clamp(1, n) - 1) as f64 / (n - 1) as f64;
                        let st = [0, 1].map(|q| from[q] + (to[q] - from[q]) * l + across[q] * mu);
                        // Colour and alpha (a cut-out's: whether the texel holding
                        // the sample shows).
                        let c = t.sample_rgba(st);
                        rgba.extend(c.map(|v| (v * 255.0).round().clamp(0.0, 255.0) as u8));
                    }
                }
                let name = format!("{} (band)", t.name());
                // At most MAX_STRIP_SAMPLES + 2 by MAX_BAND_ROWS + 2 texels: a valid size.
                let band =
                    Texture::new(&name, (n + 2) as u32, rows as u32, rgba).expect("band size");
                Arc::new(band.with_alpha(t.alpha()))
            })
            .clone();
        let (tw, th) = (f64::from(texture.width()), f64::from(texture.height()));
        let (oy, sy) = if m == 1 {
            (0.25, 0.5)
        } else {
            (1.5 / th, (th - 3.0) / th)
        };
        Strip {
            offset: [1.5 / tw, oy],
            scale: [(tw - 3.0) / tw, sy],
            texture,
        }
    }
}

/// The most rows of samples across a band.
pub(crate) const MAX_BAND_ROWS: usize = 66;

impl Strip {
    /// Band texture coordinates for the corners of `band`. A strip (one row, the
    /// coordinates on a segment) spreads the corners across it as ¼ for the first and
    /// last corners by position along it and ¾ for the middle one, so the three never
    /// fall on a line.
    pub fn corner_st(&self, band: &Band) -> [[f64; 2]; 3] {
        let along = band.along;
        let mut side = band.side;
        if self.texture.height() == 1 {
            let mut order = [0, 1, 2];
            order.sort_by(|&i, &j| along[i].total_cmp(&along[j]));
            side[order[1]] = 1.0;
        }
        [0, 1, 2].map(|i| {
            [
                self.offset[0] + along[i] * self.scale[0],
                self.offset[1] + side[i] * self.scale[1],
            ]
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ramp() -> Arc<Texture> {
        // 4 × 2: red rising left to right, the same on both rows.
        let mut rgba = Vec::new();
        for _ in 0..2 {
            for v in [0u8, 85, 170, 255] {
                rgba.extend_from_slice(&[v, 0, 0, 255]);
            }
        }
        Arc::new(Texture::new("ramp", 4, 2, rgba).unwrap())
    }

    const PAGE: [[f64; 2]; 3] = [[0.0, 0.0], [100.0, 0.0], [0.0, 100.0]];

    #[test]
    fn points_segments_bands_and_areas() {
        let t = ramp();
        let step = max_step(&t);
        assert_eq!(step, 1.0, "255 → 0 across the wrap");
        let size = (4, 2);
        let p = [0.3, 0.6];
        assert_eq!(classify([p, p, p], PAGE, size, step), Collapse::Point(p));
        let seg = classify([[0.1, 0.25], [0.9, 0.25], [0.5, 0.25]], PAGE, size, step);
        assert_eq!(
            seg,
            Collapse::Band(Band {
                from: [0.1, 0.25],
                to: [0.9, 0.25],
                across: [0.0, 0.0],
                along: [0.0, 1.0, 0.5],
                side: [0.0; 3],
            })
        );
        // A texel across on 100 pixels is a close-up, drawn as a band; on 10, its map.
        let wide = [[0.1, 0.25], [0.9, 0.25], [0.5, 0.75]];
        assert!(matches!(
            classify(wide, PAGE, size, step),
            Collapse::Band(_)
        ));
        let page = PAGE.map(|q| q.map(|v| v / 10.0));
        assert_eq!(classify(wide, page, size, step), Collapse::Area);
        // Thin (a tenth of a texel) on 100 pixels: a band, 0.05 texture units across.
        let thin = classify([[0.1, 0.25], [0.9, 0.25], [0.5, 0.3]], PAGE, size, step);
        let Collapse::Band(b) = thin else {
            panic!("{thin:?}")
        };
        assert_eq!(b.side, [0.0, 0.0, 1.0]);
        assert!((b.across[1] - 0.05).abs() < 1e-12 && b.across[0].abs() < 1e-12);
        // The same on 4 pixels: its own map.
        let small = PAGE.map(|q| q.map(|v| v / 25.0));
        let st = [[0.1, 0.25], [0.9, 0.25], [0.5, 0.3]];
        assert_eq!(classify(st, small, size, step), Collapse::Area);
        // A constant texture: every triangle is one colour.
        let flat = Texture::new("c", 2, 2, [9u8, 8, 7, 255].repeat(4)).unwrap();
        assert_eq!(max_step(&flat), 0.0);
        assert!(matches!(
            classify([[0.0, 0.0], [5.0, 0.0], [0.0, 5.0]], PAGE, (2, 2), 0.0),
            Collapse::Point(_)
        ));
    }

    #[test]
    fn a_strip_holds_the_colours_along_its_segment() {
        let t = ramp();
        let mut strips = Strips::default();
        let band = Band {
            from: [0.125, 0.25],
            to: [0.875, 0.25],
            across: [0.0; 2],
            along: [0.0, 1.0, 0.5],
            side: [0.0; 3],
        };
        let s = strips.strip(&t, &band);
        let n = s.texture.width() as usize;
        assert_eq!(s.texture.height(), 1);
        assert!(n >= 3 * 4 + 3);
        // The ends repeat; inner samples are the texture's along the segment.
        let red = |k: usize| s.texture.rgba()[4 * k];
        assert_eq!((red(0), red(1), red(n - 2), red(n - 1)), (0, 0, 255, 255));
        for k in 1..n - 1 {
            let l = (k - 1) as f64 / (n - 3) as f64;
            let st = [band.from[0] + (band.to[0] - band.from[0]) * l, 0.25];
            // The strip coordinate of position l samples texel k's centre.
            let sc = s.offset[0] + l * s.scale[0];
            assert!((sc * n as f64 - (k as f64 + 0.5)).abs() < 1e-9);
            let want = (t.sample(st)[0] * 255.0).round() as u8;
            assert_eq!(red(k), want);
        }
        // Asked again: the same strip.
        let again = strips.strip(&t, &band);
        assert!(Arc::ptr_eq(&s.texture, &again.texture));
        let st = s.corner_st(&band);
        let area = (st[1][0] - st[0][0]) * (st[2][1] - st[0][1])
            - (st[2][0] - st[0][0]) * (st[1][1] - st[0][1]);
        assert!(area.abs() > 0.1);
    }

    #[test]
    fn a_band_resamples_the_texture_between_its_sides() {
        let t = ramp();
        let band = Band {
            from: [0.1, 0.2],
            to: [0.9, 0.2],
            across: [0.0, 0.3],
            along: [0.0, 1.0, 0.4],
            side: [0.0, 0.0, 1.0],
        };
        let s = Strips::default().strip(&t, &band);
        let (w, h) = (s.texture.width(), s.texture.height());
        assert!(h > 3);
        // Each inner texel centre holds the texture at its band position.
        for j in 1..h - 1 {
            for i in 1..w - 1 {
                let centre = [
                    (f64::from(i) + 0.5) / f64::from(w),
                    (f64::from(j) + 0.5) / f64::from(h),
                ];
                let l = (centre[0] - s.offset[0]) / s.scale[0];
                let m = (centre[1] - s.offset[1]) / s.scale[1];
                let st = [0, 1]
                    .map(|q| band.from[q] + (band.to[q] - band.from[q]) * l + band.across[q] * m);
                let want = t.sample(st).map(|v| (v * 255.0).round() as u8);
                let at = 4 * (j * w + i) as usize;
                assert_eq!(&s.texture.rgba()[at..at + 3], &want, "{i} {j}");
            }
        }
        let st = s.corner_st(&band);
        assert!((st[2][1] - (s.offset[1] + s.scale[1])).abs() < 1e-12);
    }
}
