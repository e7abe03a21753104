//! Textured fragments for the vector formats: triangles, each drawing the texture under
//! one affine map, small enough that the affine map stays within
//! [`MAX_PERSPECTIVE_ERROR`] pixels of the exact projective one.
//!
//! **How the error is measured.** A triangle with page corners `P₀, P₁, P₂` gets the
//! affine map `A` that agrees with the exact map `H` (page → texture) at its corners.
//! At a point `p`, the exact texture point is `H(p)`; the affine drawing puts that same
//! texture point at `A⁻¹(H(p))`. The error is the page distance `|A⁻¹(H(p)) − p|`,
//! taken at the 12 non-corner points of the barycentric grid of step ¼ (edge quarter
//! points, edge midpoints and three inner points). A triangle above the bound is split
//! into four at its page edge midpoints, down to [`MAX_DEPTH`] levels.

use crate::number::push_num;
use crate::TextureMap;

/// The largest perspective error accepted, in pixels.
///
/// A triangle with page corners `P₀, P₁, P₂` gets the affine map `A` that agrees with
/// the exact projective map `H` (page → texture) at its corners. At a point `p` the
/// exact texture point is `H(p)`; the affine drawing puts that texture point at
/// `A⁻¹(H(p))`. The error is the page distance `|A⁻¹(H(p)) − p|`, taken at the 12
/// non-corner points of the barycentric grid of step ¼; a triangle above the bound is
/// split into four at its page edge midpoints.
pub const MAX_PERSPECTIVE_ERROR: f64 = 0.5;

/// A fragment is cut into at most about this many pieces: past it, triangles are taken
/// as they are (only a fragment reaching the horizon of its plane over a huge page gets
/// there), so no map can make a writer's output grow without bound.
pub(crate) const MAX_PIECES: usize = 16_384;

/// Splits stop after this many levels (4¹⁰ pieces at most per fan triangle): only
/// triangles reaching the horizon of their plane get there.
pub(crate) const MAX_DEPTH: u32 = 10;

/// One page triangle drawn with one affine map.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AffinePiece {
    /// Page corners.
    pub points: [[f64; 2]; 3],
    /// The affine map from texture to page, `(a, b, c, d, e, f)` as in SVG's
    /// `matrix(…)`: `x = a·s + c·t + e`, `y = b·s + d·t + f`.
    pub st_to_page: [f64; 6],
}

/// A piece reaching more repetitions of its texture than this is filled with the
/// fragment's fill times the texture's mean colour instead (and counted as
/// approximated).
pub(crate) const MAX_TILES_PER_PIECE: u64 = 1024;

impl AffinePiece {
    /// The matrix `[a b c d e f]` that draws the unit square of texture repetition
    /// `(i, j)` (the image's first row at the top) on a page whose y axis points up and
    /// which is `height` high: PDF's `cm` and PostScript's matrices alike.
    pub(crate) fn flipped_tile_matrix(&self, (i, j): (f64, f64), height: f64) -> [f64; 6] {
        let [a, b, c, d, e, f] = self.st_to_page;
        // Unit point (u, v) is texture point (i + u, j + 1 − v); then y flips.
        let ex = a * i + c * (j + 1.0) + e;
        let fy = b * i + d * (j + 1.0) + f;
        [a, -b, -c, d, ex, height - fy]
    }

    /// Writes a tile matrix: the linear part with `d + 4` decimals, the offset with
    /// `d + 2`, separated by spaces, without brackets.
    pub(crate) fn push_tile_matrix(buf: &mut Vec<u8>, m: [f64; 6], d: u8) {
        for v in &m[..4] {
            push_num(buf, *v, d + 4);
            buf.push(b' ');
        }
        push_num(buf, m[4], d + 2);
        buf.push(b' ');
        push_num(buf, m[5], d + 2);
    }
    /// The repetitions of the texture (unit squares of texture space, `[i, i + 1] ×
    /// [j, j + 1]`) the piece reaches, as `(i, j)` pairs; `None` when there are more
    /// than [`MAX_TILES_PER_PIECE`] of them, or the map is degenerate.
    pub(crate) fn repetitions(&self) -> Option<Vec<(f64, f64)>> {
        let [a, b, c, d, e, f] = self.st_to_page;
        let det = a * d - b * c;
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        let st = self.points.map(|p| {
            let (x, y) = (p[0] - e, p[1] - f);
            [(d * x - c * y) / det, (a * y - b * x) / det]
        });
        let lo = |q: usize| {
            st.iter()
                .map(|v| v[q])
                .fold(f64::INFINITY, f64::min)
                .floor()
        };
        let hi = |q: usize| {
            st.iter()
                .map(|v| v[q])
                .fold(f64::NEG_INFINITY, f64::max)
                .ceil()
        };
        let (s0, s1, t0, t1) = (lo(0), hi(0).max(lo(0) + 1.0), lo(1), hi(1).max(lo(1) + 1.0));
        if ![s0, s1, t0, t1].iter().all(|v| v.is_finite()) {
            return None;
        }
        if (s1 - s0) * (t1 - t0) > MAX_TILES_PER_PIECE as f64 {
            return None;
        }
        let mut out = Vec::new();
        let mut j = t0;
        while j < t1 {
            let mut i = s0;
            while i < s1 {
                out.push((i, j));
                i += 1.0;
            }
            j += 1.0;
        }
        Some(out)
    }
}

/// Writes polygons in page coordinates (y down) as one path on a page whose y axis
/// points up and which is `height` high, with PDF's and PostScript's abbreviations
/// `x y m`, `x y l`, `h` (the EPS prolog defines them), ready to be a clip.
pub(crate) fn push_flipped_outline(buf: &mut Vec<u8>, polys: &[Vec<[f64; 2]>], height: f64, d: u8) {
    for poly in polys {
        for (i, &p) in poly.iter().enumerate() {
            push_num(buf, p[0], d);
            buf.push(b' ');
            push_num(buf, height - p[1], d);
            buf.extend_from_slice(if i == 0 { b" m " } else { b" l " });
        }
        buf.extend_from_slice(b"h ");
    }
}

/// The affine pieces of the convex polygon `points` under `map` (fan triangles split
/// until within `max_error` pixels, measured as [`MAX_PERSPECTIVE_ERROR`] says);
/// triangles where the map is undefined at a corner are left out. The SVG and PDF
/// writers draw these with `max_error` = [`MAX_PERSPECTIVE_ERROR`].
pub fn affine_pieces(points: &[[f64; 2]], map: &TextureMap, max_error: f64) -> Vec<AffinePiece> {
    let mut out = Vec::new();
    for i in 1..points.len().saturating_sub(1) {
        split(
            [points[0], points[i], points[i + 1]],
            map,
            max_error,
            0,
            &mut out,
        );
    }
    out
}

fn split(
    t: [[f64; 2]; 3],
    map: &TextureMap,
    max_error: f64,
    depth: u32,
    out: &mut Vec<AffinePiece>,
) {
    let Some(st) = corners_st(&t, map) else {
        return;
    };
    let Some(affine) = st_to_page(&t, &st) else {
        return; // degenerate on the page or in the texture: nothing to draw
    };
    if depth >= MAX_DEPTH
        || out.len() >= MAX_PIECES
        || perspective_error(&t, map, &affine) <= max_error
    {
        out.push(AffinePiece {
            points: t,
            st_to_page: affine,
        });
        return;
    }
    let mid = |a: [f64; 2], b: [f64; 2]| [(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0];
    let (m01, m12, m20) = (mid(t[0], t[1]), mid(t[1], t[2]), mid(t[2], t[0]));
    for sub in [
        [t[0], m01, m20],
        [m01, t[1], m12],
        [m20, m12, t[2]],
        [m01, m12, m20],
    ] {
        split(sub, map, max_error, depth + 1, out);
    }
}

fn corners_st(t: &[[f64; 2]; 3], map: &TextureMap) -> Option<[[f64; 2]; 3]> {
    Some([map.st_at(t[0])?, map.st_at(t[1])?, map.st_at(t[2])?])
}

/// The affine map from texture to page taking `st[i]` to `t[i]`.
fn st_to_page(t: &[[f64; 2]; 3], st: &[[f64; 2]; 3]) -> Option<[f64; 6]> {
    let (s1, t1) = (st[1][0] - st[0][0], st[1][1] - st[0][1]);
    let (s2, t2) = (st[2][0] - st[0][0], st[2][1] - st[0][1]);
    let det = s1 * t2 - s2 * t1;
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let (x1, y1) = (t[1][0] - t[0][0], t[1][1] - t[0][1]);
    let (x2, y2) = (t[2][0] - t[0][0], t[2][1] - t[0][1]);
    // [x1 x2; y1 y2] = M · [s1 s2; t1 t2]  ⇒  M = [x1 x2; y1 y2] · [s1 s2; t1 t2]⁻¹.
    let a = (x1 * t2 - x2 * t1) / det;
    let c = (x2 * s1 - x1 * s2) / det;
    let b = (y1 * t2 - y2 * t1) / det;
    let d = (y2 * s1 - y1 * s2) / det;
    let e = t[0][0] - a * st[0][0] - c * st[0][1];
    let f = t[0][1] - b * st[0][0] - d * st[0][1];
    let m = [a, b, c, d, e, f];
    m.iter().all(|v| v.is_finite()).then_some(m)
}

/// The largest page distance between where the affine map draws the exact texture point
/// of a sample and the sample itself (see the module docs); infinite where the exact map
/// is undefined.
pub(crate) fn perspective_error(t: &[[f64; 2]; 3], map: &TextureMap, affine: &[f64; 6]) -> f64 {
    let [a, b, c, d, e, f] = *affine;
    let mut worst = 0.0f64;
    for i in 0..=4u32 {
        for j in 0..=(4 - i) {
            let k = 4 - i - j;
            if i == 4 || j == 4 || k == 4 {
                continue; // corners agree by construction
            }
            let w = [i, j, k].map(|v| f64::from(v) / 4.0);
            let p = [0, 1].map(|q| w[0] * t[0][q] + w[1] * t[1][q] + w[2] * t[2][q]);
            let Some(st) = map.st_at(p) else {
                return f64::INFINITY;
            };
            let x = a * st[0] + c * st[1] + e;
            let y = b * st[0] + d * st[1] + f;
            worst = worst.max((x - p[0]).hypot(y - p[1]));
        }
    }
    worst
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The map of a unit square seen in perspective: a pure projective map.
    fn grazing() -> TextureMap {
        TextureMap {
            texture: 0,
            screen_to_st: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.004, 0.0, 1.0]],
        }
    }

    #[test]
    fn pieces_tile_the_polygon_and_stay_within_the_bound_everywhere() {
        let map = grazing();
        let quad = [[0.0, 0.0], [400.0, 0.0], [400.0, 300.0], [0.0, 300.0]];
        let pieces = affine_pieces(&quad, &map, MAX_PERSPECTIVE_ERROR);
        assert!(pieces.len() > 2, "perspective asks for splits");
        let area: f64 = pieces
            .iter()
            .map(|p| {
                let [a, b, c] = p.points;
                ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])).abs() / 2.0
            })
            .sum();
        assert!((area - 120_000.0).abs() < 1e-6, "{area}");
        // Densely sampled, the error stays within the bound (with a little margin for
        // points between the samples the split decision used).
        let mut worst = 0.0f64;
        for p in &pieces {
            let [a, b, c, d, e, f] = p.st_to_page;
            let t = p.points;
            for i in 0..=20 {
                for j in 0..=(20 - i) {
                    let w = [i, j, 20 - i - j].map(|v| f64::from(v) / 20.0);
                    let q = [0, 1].map(|k| w[0] * t[0][k] + w[1] * t[1][k] + w[2] * t[2][k]);
                    let st = map.st_at(q).unwrap();
                    let x = a * st[0] + c * st[1] + e;
                    let y = b * st[0] + d * st[1] + f;
                    worst = worst.max((x - q[0]).hypot(y - q[1]));
                }
            }
        }
        assert!(worst <= MAX_PERSPECTIVE_ERROR * 1.05, "worst {worst}");
        // A looser bound needs fewer pieces; an affine map needs none.
        assert!(affine_pieces(&quad, &map, 4.0).len() < pieces.len());
        let affine = TextureMap {
            screen_to_st: [[0.01, 0.0, 0.0], [0.0, 0.01, 0.0], [0.0, 0.0, 1.0]],
            ..map
        };
        assert_eq!(
            affine_pieces(&quad, &affine, MAX_PERSPECTIVE_ERROR).len(),
            2
        );
    }
}
