//! The lines of a check: the painter's visible line pieces rasterised with Bresenham,
//! against the z-buffer's depth-tested lines ([`scene_lines`]).
//!
//! A pixel counts as a mismatch when one side draws a line there and the other draws none
//! in the 3 × 3 pixels around it (the two sides step along the same projected segments,
//! but a piece's rounded ends can move its pixels by one), outside a band of 2 pixels
//! around every end of a visible piece (where a line passes behind a silhouette or
//! pierces a face, and the depth test is ambiguous).

use limn_depthsort::VisibleMarks;
use limn_scene::Scene;
use limn_zbuffer::{
    bresenham, edge_band, scene_lines, IdImage, LineAlgorithm, Mask, Segment2, NO_FACE,
};

use crate::{CheckError, Painted};

/// The outcome of comparing line pixels.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct LineComparison {
    /// Pixels either side draws a line on.
    pub pixels: usize,
    /// Of those, pixels only one side draws (with the 3 × 3 slack).
    pub mismatches: usize,
    /// Mismatches outside the band.
    pub mismatches_outside_band: usize,
}

impl LineComparison {
    /// Whether the lines disagree: more mismatches outside the band than 1 % of the line
    /// pixels. The z-buffer's depth test is not exact where a line runs along or just
    /// behind a fold of a surface (its depth there differs from the surface's by less than
    /// the depth change across one pixel), so a few such pixels are expected; a line drawn
    /// where it is hidden, or left out where it shows, costs many more.
    pub fn fails(&self) -> bool {
        self.mismatches_outside_band * 100 > self.pixels
    }
}

/// Window depth slack of the reference's depth test (lines on faces show).
const DEPTH_BIAS: f64 = 1e-6;

/// The line pixels of the visible pieces.
pub(crate) fn painted_lines(marks: &VisibleMarks, width: u32, height: u32) -> IdImage {
    let mut out = IdImage::new(width, height);
    for p in &marks.pieces {
        for w in p.points.windows(2) {
            let ok = w.iter().flatten().all(|v| v.is_finite() && v.abs() < 1e9);
            if !ok {
                continue;
            }
            bresenham(
                w[0][0].floor() as i64,
                w[0][1].floor() as i64,
                w[1][0].floor() as i64,
                w[1][1].floor() as i64,
                |x, y| {
                    if x >= 0 && y >= 0 && x < width as i64 && y < height as i64 {
                        out.ids[y as usize * width as usize + x as usize] = p.line;
                    }
                },
            );
        }
    }
    out
}

/// The band of ambiguous line pixels: around the ends of the visible pieces (where a
/// line passes behind a silhouette or pierces a face, and the z-buffer's depth test
/// flips within a pixel or two).
pub(crate) fn line_band(painted: &Painted, tolerance: f64) -> Mask {
    let c = painted.camera();
    let mut edges: Vec<Segment2> = Vec::new();
    for p in &painted.marks.pieces {
        for q in [p.points[0], p.points[p.points.len() - 1]] {
            edges.push((q, q));
        }
    }
    edge_band(&edges, c.width, c.height, tolerance)
}

impl Painted {
    /// Renders the reference lines and compares them with the painter's.
    pub fn compare_lines(&self, scene: &Scene) -> Result<LineComparison, CheckError> {
        let reference = scene_lines(
            scene,
            self.camera(),
            &self.ropts,
            LineAlgorithm::Bresenham,
            DEPTH_BIAS,
        )?;
        Ok(compare_line_images(
            &self.line_ids,
            &reference,
            &self.line_band,
        ))
    }
}

/// Compares two line images with the 3 × 3 slack, outside `band`.
pub fn compare_line_images(a: &IdImage, b: &IdImage, band: &Mask) -> LineComparison {
    let (w, h) = (a.width as i64, a.height as i64);
    let near = |img: &IdImage, x: i64, y: i64| {
        (-1..=1).any(|dy| {
            (-1..=1).any(|dx| {
                let (u, v) = (x + dx, y + dy);
                u >= 0 && v >= 0 && u < w && v < h && img.ids[(v * w + u) as usize] != NO_FACE
            })
        })
    };
    let mut c = LineComparison::default();
    for y in 0..h {
        for x in 0..w {
            let i = (y * w + x) as usize;
            let (la, lb) = (a.ids[i] != NO_FACE, b.ids[i] != NO_FACE);
            if !la && !lb {
                continue;
            }
            c.pixels += 1;
            let bad = (la && !near(b, x, y)) || (lb && !near(a, x, y));
            if bad {
                c.mismatches += 1;
                if !band.bits[i] {
                    c.mismatches_outside_band += 1;
                }
            }
        }
    }
    c
}
