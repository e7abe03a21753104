//! A painter's rasteriser for checking vector output against the references.

use crate::image::IdImage;
use crate::setup::ScreenVert;
use crate::span::TriSetup;

/// Paints 2D polygons given in pixel coordinates (y down), in order, later ones over
/// earlier ones, and returns which polygon id covers each pixel centre.
///
/// Coverage uses the references' sampling exactly: a polygon is fanned from its first
/// corner and each triangle covers the pixel centres the z-buffer's edge test accepts,
/// with the same top-left rule, so a centre on an edge shared by two polygons goes to
/// exactly one of them when both polygons carry the same corner coordinates. Either
/// winding is accepted. A polygon that is not convex (a fragment with its seam flaps
/// joined in) covers the centres its boundary winds round, as the nonzero rule of the
/// vector formats fills it: its fan's triangles are counted with the signs of their
/// turns. Polygons with fewer than three corners or non-finite coordinates draw nothing.
pub fn rasterize_ids(polys: &[(Vec<[f64; 2]>, u32)], width: u32, height: u32) -> IdImage {
    let mut out = IdImage::new(width, height);
    let mut winding = Vec::new();
    for (poly, id) in polys {
        if is_convex(poly) {
            for (s, _) in fan(poly, width, height) {
                for row in s.row_lo..=s.row_hi {
                    if let Some((x0, x1)) = s.span(row) {
                        let base = row as usize * width as usize;
                        out.ids[base + x0 as usize..base + x1 as usize].fill(*id);
                    }
                }
            }
            continue;
        }
        // A polygon that is not convex covers the centres its boundary winds round
        // (the nonzero rule, as the vector formats fill): the fan's triangles counted
        // with their signs sum to that winding number at every centre.
        winding.clear();
        winding.resize(width as usize * height as usize, 0i32);
        let (mut lo, mut hi) = (u32::MAX, 0);
        for (s, sign) in fan(poly, width, height) {
            lo = lo.min(s.row_lo);
            hi = hi.max(s.row_hi);
            for row in s.row_lo..=s.row_hi {
                if let Some((x0, x1)) = s.span(row) {
                    let base = row as usize * width as usize;
                    for w in &mut winding[base + x0 as usize..base + x1 as usize] {
                        *w += sign;
                    }
                }
            }
        }
        for row in lo..=hi.min(height.saturating_sub(1)) {
            let base = row as usize * width as usize;
            let cells = base..base + width as usize;
            for (o, &w) in out.ids[cells.clone()].iter_mut().zip(&winding[cells]) {
                if w != 0 {
                    *o = *id;
                }
            }
        }
    }
    out
}

/// How many of `polys` (convex polygons in pixel coordinates, y down) cover each pixel
/// centre, with the sampling of [`rasterize_ids`] (the references' edge test and
/// top-left rule): polygons that tile a region without overlapping cover each centre of
/// it once. A polygon that is not convex counts once wherever its boundary winds round.
pub fn coverage_counts(polys: &[&[[f64; 2]]], width: u32, height: u32) -> Vec<u32> {
    let mut counts = vec![0u32; width as usize * height as usize];
    let mut winding = vec![0i32; counts.len()];
    for poly in polys {
        let mut rows = (u32::MAX, 0);
        for (s, sign) in fan(poly, width, height) {
            rows = (rows.0.min(s.row_lo), rows.1.max(s.row_hi));
            for row in s.row_lo..=s.row_hi {
                if let Some((x0, x1)) = s.span(row) {
                    let base = row as usize * width as usize;
                    for w in &mut winding[base + x0 as usize..base + x1 as usize] {
                        *w += sign;
                    }
                }
            }
        }
        for row in rows.0..=rows.1.min(height.saturating_sub(1)) {
            let base = row as usize * width as usize;
            let cells = base..base + width as usize;
            for (c, w) in counts[cells.clone()].iter_mut().zip(&mut winding[cells]) {
                *c += u32::from(*w != 0);
                *w = 0;
            }
        }
    }
    counts
}

/// The triangles of `poly`'s fan from its first corner that cover some pixel centre,
/// each with the sign of its turn (exact).
fn fan(poly: &[[f64; 2]], width: u32, height: u32) -> impl Iterator<Item = (TriSetup, i32)> + '_ {
    let sv = |p: [f64; 2]| ScreenVert {
        x: p[0],
        y: p[1],
        d: 0.0,
    };
    (1..poly.len().saturating_sub(1)).filter_map(move |k| {
        let (a, b, c) = (poly[0], poly[k], poly[k + 1]);
        let turn = turn(a, b, c);
        if turn == 0 {
            return None;
        }
        TriSetup::new(sv(a), sv(b), sv(c), width, height).map(|s| (s, turn))
    })
}

/// The sign of the turn `a → b → c` (exact): 1, −1 or 0.
fn turn(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> i32 {
    let o = robust::orient2d(
        robust::Coord { x: a[0], y: a[1] },
        robust::Coord { x: b[0], y: b[1] },
        robust::Coord { x: c[0], y: c[1] },
    );
    if o > 0.0 {
        1
    } else if o < 0.0 {
        -1
    } else {
        0
    }
}

/// Whether every turn along `poly` goes the same way (or is straight), and it goes
/// round once: convex, so its fan covers it once.
fn is_convex(poly: &[[f64; 2]]) -> bool {
    let n = poly.len();
    if n <= 3 {
        return true;
    }
    let mut seen = 0;
    let mut angle = 0.0f64;
    for k in 0..n {
        let (a, b, c) = (poly[k], poly[(k + 1) % n], poly[(k + 2) % n]);
        let t = turn(a, b, c);
        if t != 0 {
            if seen != 0 && t != seen {
                return false;
            }
            seen = t;
        }
        let (u, v) = ([b[0] - a[0], b[1] - a[1]], [c[0] - b[0], c[1] - b[1]]);
        angle += (u[0] * v[1] - u[1] * v[0]).atan2(u[0] * v[0] + u[1] * v[1]);
    }
    // Turning the same way throughout but round more than once (a star) is not convex.
    angle.abs() < 3.0 * std::f64::consts::PI
}

#[cfg(test)]
mod tests {
    use super::*;

    fn covered(polys: &[(Vec<[f64; 2]>, u32)]) -> Vec<bool> {
        rasterize_ids(polys, 30, 20)
            .ids
            .iter()
            .map(|&i| i == 7)
            .collect()
    }

    #[test]
    fn a_polygon_that_is_not_convex_covers_what_it_winds_round() {
        // An L (its fan from the inner corner's far side would cover the notch), and the
        // same as two rectangles.
        let l = vec![
            [2.3, 1.7],
            [20.6, 1.7],
            [20.6, 8.2],
            [9.1, 8.2],
            [9.1, 17.4],
            [2.3, 17.4],
        ];
        assert!(!is_convex(&l));
        let halves = [
            (vec![[2.3, 1.7], [20.6, 1.7], [20.6, 8.2], [2.3, 8.2]], 7),
            (vec![[2.3, 8.2], [9.1, 8.2], [9.1, 17.4], [2.3, 17.4]], 7),
        ];
        let fanned: usize = covered(&[(l.clone(), 7)]).iter().filter(|&&c| c).count();
        assert_eq!(covered(&[(l.clone(), 7)]), covered(&halves));
        assert!(fanned > 150, "{fanned}");
        // Started at a corner that does not see the whole L (its fan reaches into the
        // notch), and reversed: the same centres.
        let mut r = l.clone();
        r.rotate_left(2);
        assert_eq!(covered(&[(r.clone(), 7)]), covered(&halves));
        r.reverse();
        assert_eq!(covered(&[(r, 7)]), covered(&halves));
        // A detour that overlaps the polygon's own inside (winding 2 there) still fills.
        let overlap = vec![
            [2.3, 1.7],
            [20.6, 1.7],
            [20.6, 12.2],
            [14.0, 12.2],
            [14.0, 5.1],
            [17.0, 5.1],
            [17.0, 15.0],
            [2.3, 15.0],
        ];
        let union = [
            (vec![[2.3, 1.7], [20.6, 1.7], [20.6, 12.2], [2.3, 12.2]], 7),
            (
                vec![[2.3, 12.2], [17.0, 12.2], [17.0, 15.0], [2.3, 15.0]],
                7,
            ),
        ];
        assert_eq!(covered(&[(overlap, 7)]), covered(&union));
    }
}
