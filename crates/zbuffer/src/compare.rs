//! Per-pixel comparison of face-id images, and the edge band of ambiguous pixels.

use std::collections::BTreeMap;

use crate::image::{IdImage, Mask};

/// A segment in pixel coordinates: `(start, end)`, each `[x, y]`.
pub type Segment2 = ([f64; 2], [f64; 2]);

/// The result of [`compare`].
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Comparison {
    /// Pixels compared (`width × height` of the larger image in each direction).
    pub pixels: usize,
    /// Pixels whose ids differ.
    pub mismatches: usize,
    /// Mismatching pixels outside the band (all mismatches when there is no band).
    pub mismatches_outside_band: usize,
    /// Pixels in the band.
    pub band_pixels: usize,
    /// Per face id (including `NO_FACE` for the background): (mismatching pixels outside
    /// the band where either image shows the face, pixels where either image shows it).
    pub per_face: BTreeMap<u32, (usize, usize)>,
}

impl Comparison {
    /// Whether no mismatch remains outside the band.
    pub fn agrees(&self) -> bool {
        self.mismatches_outside_band == 0
    }
}

/// Compares two id images pixel by pixel. Pixels in `band` are counted as mismatches
/// but not as mismatches outside the band. If the sizes differ, the larger extent is
/// compared and a pixel present in only one image is a mismatch.
pub fn compare(a: &IdImage, b: &IdImage, band: Option<&Mask>) -> Comparison {
    let w = a.width.max(b.width);
    let h = a.height.max(b.height);
    let mut c = Comparison {
        pixels: w as usize * h as usize,
        ..Comparison::default()
    };
    for y in 0..h {
        for x in 0..w {
            let (ia, ib) = (a.get(x, y), b.get(x, y));
            let in_band = band.is_some_and(|m| m.get(x, y));
            c.band_pixels += in_band as usize;
            let differ = ia != ib;
            if differ {
                c.mismatches += 1;
                if !in_band {
                    c.mismatches_outside_band += 1;
                }
            }
            let faces = [ia, ib];
            for (k, id) in faces.iter().enumerate() {
                let Some(id) = *id else { continue };
                if k == 1 && Some(id) == ia {
                    continue; // counted once per pixel
                }
                let e = c.per_face.entry(id).or_insert((0, 0));
                e.1 += 1;
                if differ && !in_band {
                    e.0 += 1;
                }
            }
        }
    }
    c
}

/// The default band tolerance in pixels for a `width × height` picture:
/// `1e-9 · max(width, height) + 1e-9`.
///
/// Why: limn's exact kernel decides on the input as given and rounds only the output
/// coordinates of vertices made by splitting (relative error about 1e-12 of the scene),
/// and the references compute their rays and projections in f64 (about 1e-15 of the
/// scene). Only pixel centres essentially *on* an edge can be decided differently; the
/// tolerance covers both roundings with a margin, plus a small absolute term, while
/// staying far below a pixel, so a real ordering error (which affects whole areas) is
/// never hidden.
pub fn default_band_tolerance(width: u32, height: u32) -> f64 {
    1e-9 * width.max(height) as f64 + 1e-9
}

/// Marks the pixels whose centre lies within `tolerance_px` of any of the segments
/// `edges` (pixel coordinates, y down). Non-finite segments and a non-finite or negative
/// tolerance mark nothing.
pub fn edge_band(edges: &[Segment2], width: u32, height: u32, tolerance_px: f64) -> Mask {
    let mut m = Mask::new(width, height);
    if !(tolerance_px >= 0.0 && tolerance_px.is_finite()) {
        return m;
    }
    let r = tolerance_px;
    for &(a, b) in edges {
        if !a.iter().chain(&b).all(|v| v.is_finite()) {
            continue;
        }
        let y_lo = a[1].min(b[1]) - r;
        let y_hi = a[1].max(b[1]) + r;
        let j0 = ((y_lo - 0.5).ceil().max(0.0)) as u64;
        let j1 = (y_hi - 0.5).floor().min(height as f64 - 1.0);
        if j1 < 0.0 {
            continue;
        }
        for j in j0..=j1 as u64 {
            let yc = j as f64 + 0.5;
            let Some((lo, hi)) = capsule_row(a, b, r, yc) else {
                continue;
            };
            // Widen by a hair so that rounding in the interval never drops a centre.
            let (lo, hi) = (lo - 1e-12 * (1.0 + lo.abs()), hi + 1e-12 * (1.0 + hi.abs()));
            let i0 = (lo - 0.5).ceil().max(0.0);
            let i1 = (hi - 0.5).floor().min(width as f64 - 1.0);
            if i0 > i1 {
                continue;
            }
            let base = j as usize * width as usize;
            m.bits[base + i0 as usize..=base + i1 as usize].fill(true);
        }
    }
    m
}

/// The x-interval of points on the line `y = yc` within distance `r` of segment `ab`.
fn capsule_row(a: [f64; 2], b: [f64; 2], r: f64, yc: f64) -> Option<(f64, f64)> {
    let mut lo = f64::INFINITY;
    let mut hi = f64::NEG_INFINITY;
    // The two end discs.
    for p in [a, b] {
        let dy = yc - p[1];
        let s = r * r - dy * dy;
        if s >= 0.0 {
            let s = s.sqrt();
            lo = lo.min(p[0] - s);
            hi = hi.max(p[0] + s);
        }
    }
    // The band around the segment's interior: |cross(d, p − a)| ≤ r·|d| with the
    // projection on d inside [0, |d|²].
    let d = [b[0] - a[0], b[1] - a[1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    if len2 > 0.0 {
        let len = len2.sqrt();
        // Interval from the distance condition.
        let (mut x0, mut x1) = if d[1] == 0.0 {
            if (yc - a[1]).abs() <= r {
                (f64::NEG_INFINITY, f64::INFINITY)
            } else {
                (f64::INFINITY, f64::NEG_INFINITY)
            }
        } else {
            // cross = d.x·(yc − a.y) − d.y·(x − a.x) ∈ [−r·len, r·len].
            let c = a[0] + d[0] * (yc - a[1]) / d[1];
            let half = (r * len / d[1]).abs();
            (c - half, c + half)
        };
        // Interval from the projection condition: 0 ≤ (x − a.x)·d.x + (yc − a.y)·d.y ≤ len².
        if d[0] != 0.0 {
            let base = (yc - a[1]) * d[1];
            let (mut p0, mut p1) = ((-base) / d[0] + a[0], (len2 - base) / d[0] + a[0]);
            if p0 > p1 {
                std::mem::swap(&mut p0, &mut p1);
            }
            x0 = x0.max(p0);
            x1 = x1.min(p1);
        } else {
            let t = (yc - a[1]) * d[1];
            if !(0.0..=len2).contains(&t) {
                x1 = f64::NEG_INFINITY;
            }
        }
        if x0 <= x1 {
            lo = lo.min(x0);
            hi = hi.max(x1);
        }
    }
    (lo <= hi).then_some((lo, hi))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn band_matches_pointwise_distance() {
        let edges = [
            ([1.3, 2.2], [17.6, 9.9]),
            ([4.0, 4.0], [4.0, 12.5]),
            ([2.0, 7.5], [15.0, 7.5]),
        ];
        let tol = 0.8;
        let m = edge_band(&edges, 20, 16, tol);
        for y in 0..16 {
            for x in 0..20 {
                let p = [x as f64 + 0.5, y as f64 + 0.5];
                let near = edges.iter().any(|&(a, b)| dist(p, a, b) <= tol);
                assert_eq!(m.get(x, y), near, "pixel {x},{y}");
            }
        }
    }

    fn dist(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
        let d = [b[0] - a[0], b[1] - a[1]];
        let t = (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / (d[0] * d[0] + d[1] * d[1]))
            .clamp(0.0, 1.0);
        let q = [a[0] + t * d[0] - p[0], a[1] + t * d[1] - p[1]];
        (q[0] * q[0] + q[1] * q[1]).sqrt()
    }

    #[test]
    fn compare_counts_per_face() {
        let mut a = IdImage::new(3, 1);
        let mut b = IdImage::new(3, 1);
        a.ids = vec![1, 2, 2];
        b.ids = vec![1, 2, 3];
        let c = compare(&a, &b, None);
        assert_eq!(
            (c.pixels, c.mismatches, c.mismatches_outside_band),
            (3, 1, 1)
        );
        assert_eq!(c.per_face[&1], (0, 1));
        assert_eq!(c.per_face[&2], (1, 2));
        assert_eq!(c.per_face[&3], (1, 1));
        let mut band = Mask::new(3, 1);
        band.bits[2] = true;
        let c = compare(&a, &b, Some(&band));
        assert_eq!(
            (c.mismatches, c.mismatches_outside_band, c.band_pixels),
            (1, 0, 1)
        );
        assert!(c.agrees());
        let small = IdImage::new(2, 1);
        assert_eq!(compare(&a, &small, None).mismatches, 3);
    }
}
