//! A painter's rasteriser for checking vector output against the references.

use crate::image::IdImage;
use crate::setup::ScreenVert;
use crate::span::TriSetup;

/// Paints 2D convex polygons given in pixel coordinates (y down), in order, later ones
/// over earlier ones, and returns which polygon id covers each pixel centre.
///
/// Coverage uses the references' sampling exactly: a polygon is fanned from its first
/// corner and each triangle covers the pixel centres the z-buffer's edge test accepts,
/// with the same top-left rule, so a centre on an edge shared by two polygons goes to
/// exactly one of them when both polygons carry the same corner coordinates. Either
/// winding is accepted. Polygons must be convex (a non-convex polygon is drawn as its
/// fan); polygons with fewer than three corners or non-finite coordinates draw nothing.
pub fn rasterize_ids(polys: &[(Vec<[f64; 2]>, u32)], width: u32, height: u32) -> IdImage {
    let mut out = IdImage::new(width, height);
    let sv = |p: [f64; 2]| ScreenVert {
        x: p[0],
        y: p[1],
        d: 0.0,
    };
    for (poly, id) in polys {
        for k in 1..poly.len().saturating_sub(1) {
            let Some(s) = TriSetup::new(sv(poly[0]), sv(poly[k]), sv(poly[k + 1]), width, height)
            else {
                continue;
            };
            for row in s.row_lo..=s.row_hi {
                if let Some((x0, x1)) = s.span(row) {
                    let base = row as usize * width as usize;
                    out.ids[base + x0 as usize..base + x1 as usize].fill(*id);
                }
            }
        }
    }
    out
}
