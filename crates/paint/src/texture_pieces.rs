//! Textured fragments for the vector formats: convex pieces, each drawing the texture
//! under one affine map, small enough that the affine map stays within
//! [`MAX_PERSPECTIVE_ERROR`] pixels of the exact projective one.
//!
//! **Quarters, or slices of constant depth.** A fragment's fan triangles are split into
//! four at their page edge midpoints until each is within the bound, down to
//! [`MAX_DEPTH`] levels. Quartering a long sliver makes hundreds of slivers, so a
//! fragment needing more than `SLICE_BEYOND` pieces is sliced instead when that takes
//! fewer. The exact map is `H(p) = N(p) / q(p)` with `N` and `q`
//! affine in the page point `p` (`q` is the depth of the face's plane at `p`). Along a
//! line where `q` is constant, `H` is affine; so a fragment is cut into slices between
//! lines of constant `q`, each slice drawn under the affine map that agrees with `H` at
//! three of its corners, and a slice whose map strays too far is cut in two at the
//! geometric mean of its `q` range. A long face seen in perspective so takes a few
//! slices, not the hundreds of triangles that splitting into quarters would make of it.
//!
//! **How the error is measured.** At a point `p` of a piece, the exact texture point is
//! `H(p)`; the affine drawing `A` puts that same texture point at `A⁻¹(H(p))`. The error
//! is the page distance `|A⁻¹(H(p)) − p|`, taken at the piece's corners, the quarter
//! points of its edges, its centroid and the midpoints between centroid and corners.
//! Where `q` changes sign over a fragment (it reaches the horizon of its plane), it is
//! only quartered, triangles where the map is undefined left out.

use crate::number::push_num;
use crate::TextureMap;

/// The largest perspective error accepted, in pixels.
///
/// A triangle with page corners `P₀, P₁, P₂` gets the affine map `A` that agrees with
/// the exact projective map `H` (page → texture) at its corners. At a point `p` the
/// exact texture point is `H(p)`; the affine drawing puts that texture point at
/// `A⁻¹(H(p))`. The error is the page distance `|A⁻¹(H(p)) − p|`, taken at the 15
/// points of the barycentric grid of step ¼; a triangle above the bound is split into
/// four at its page edge midpoints. (A sliver's map is the exact map's tangent at its
/// centroid, not the map through its corners.)
pub const MAX_PERSPECTIVE_ERROR: f64 = 0.5;

/// A fragment is cut into at most about this many pieces: past it, triangles are taken
/// as they are (only a fragment reaching the horizon of its plane over a huge page gets
/// there), so no map can make a writer's output grow without bound.
pub(crate) const MAX_PIECES: usize = 16_384;

/// Splits stop after this many levels (4¹⁰ pieces at most per fan triangle): only
/// triangles reaching the horizon of their plane get there.
pub(crate) const MAX_DEPTH: u32 = 10;

/// One page triangle drawn with one affine map.
#[derive(Debug, Clone, PartialEq)]
pub struct AffinePiece {
    /// Page corners of a convex polygon.
    pub points: Vec<[f64; 2]>,
    /// The affine map from texture to page, `(a, b, c, d, e, f)` as in SVG's
    /// `matrix(…)`: `x = a·s + c·t + e`, `y = b·s + d·t + f`.
    pub st_to_page: [f64; 6],
}

/// A piece reaching more repetitions of its texture than this is filled with the
/// fragment's fill times the texture's mean colour instead (and counted as
/// approximated).
pub(crate) const MAX_TILES_PER_PIECE: u64 = 1024;

/// How far (in texture units) a piece may reach into a repetition of the texture
/// without drawing it: far less than half a texel of the largest texture
/// ([`limn_scene::texture::MAX_TEXTURE_SIDE`] texels across), which the neighbouring
/// repetition's padded image covers with the same texels.
const REACH_SLACK: f64 = 1e-9;

/// The most a piece's map may stretch one direction of the texture more than another
/// (the ratio of its singular values): beyond it the face is seen so nearly edge-on
/// that hundreds of texels fall on each pixel across it, and viewers fail on the
/// nearly singular map (rsvg runs out of memory), so the piece takes the mean colour
/// as one reaching too many repetitions does.
pub(crate) const MAX_ANISOTROPY: f64 = 1000.0;

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
    /// than [`MAX_TILES_PER_PIECE`] of them, or the map is degenerate or stretches more
    /// than [`MAX_ANISOTROPY`].
    pub(crate) fn repetitions(&self) -> Option<Vec<(f64, f64)>> {
        let [a, b, c, d, e, f] = self.st_to_page;
        let det = a * d - b * c;
        if det == 0.0 || !det.is_finite() {
            return None;
        }
        // σ_max / σ_min of the linear part, from its Frobenius norm and determinant.
        let f2 = a * a + b * b + c * c + d * d;
        let root = (f2 * f2 - 4.0 * det * det).max(0.0).sqrt();
        let (big, small) = (f2 + root, (4.0 * det * det) / (f2 + root));
        let even = big <= MAX_ANISOTROPY * MAX_ANISOTROPY * small; // false for NaN
        if !even {
            return None;
        }
        let st: Vec<[f64; 2]> = self
            .points
            .iter()
            .map(|p| {
                let (x, y) = (p[0] - e, p[1] - f);
                [(d * x - c * y) / det, (a * y - b * x) / det]
            })
            .collect();
        // A repetition reached by less than REACH_SLACK is left out: the neighbouring
        // one's image reaches half a texel beyond its square (see `texture_images.rs`),
        // with the same texels, so rounding in the map adds no draw.
        let lo = |q: usize| {
            (st.iter().map(|v| v[q]).fold(f64::INFINITY, f64::min) + REACH_SLACK).floor()
        };
        let hi = |q: usize| {
            (st.iter().map(|v| v[q]).fold(f64::NEG_INFINITY, f64::max) - REACH_SLACK).ceil()
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

/// The affine pieces of the convex polygon `points` under `map`: quarters of its fan
/// triangles or slices of constant depth, each within `max_error` pixels as the module
/// docs say (triangles where the map is undefined left out). The SVG, PDF and EPS writers draw these with `max_error` =
/// [`MAX_PERSPECTIVE_ERROR`].
pub fn affine_pieces(points: &[[f64; 2]], map: &TextureMap, max_error: f64) -> Vec<AffinePiece> {
    let mut out = Vec::new();
    if points.len() < 3 {
        return out;
    }
    let h = &map.screen_to_st[2];
    let q = |p: [f64; 2]| h[0] * p[0] + h[1] * p[1] + h[2];
    let qs: Vec<f64> = points.iter().map(|&p| q(p)).collect();
    let lo = qs.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = qs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    for i in 1..points.len() - 1 {
        split(
            [points[0], points[i], points[i + 1]],
            map,
            max_error,
            0,
            &mut out,
        );
    }
    if out.len() > SLICE_BEYOND && lo.is_finite() && hi.is_finite() && (lo > 0.0 || hi < 0.0) {
        let mut slices = Vec::new();
        slice(points.to_vec(), (lo, hi), map, max_error, 0, &mut slices);
        if slices.len() < out.len() {
            return slices;
        }
    }
    out
}

/// A fragment split into more quarters than this is sliced instead when that takes
/// fewer pieces (a long sliver in perspective): quarters keep the anti-aliased edges
/// between pieces short, slices the count of pieces low.
const SLICE_BEYOND: usize = 32;

/// Cuts between slices stop after this many levels (2¹⁶ slices at most).
const MAX_SLICE_DEPTH: u32 = 16;

/// Pushes the pieces of `poly`, whose depths `q` lie in `range` (one sign), onto `out`.
fn slice(
    poly: Vec<[f64; 2]>,
    range: (f64, f64),
    map: &TextureMap,
    max_error: f64,
    depth: u32,
    out: &mut Vec<AffinePiece>,
) {
    if poly.len() < 3 {
        return;
    }
    let Some(affine) = polygon_affine(&poly, map) else {
        return; // degenerate on the page or in the texture: nothing to draw
    };
    if depth >= MAX_SLICE_DEPTH
        || out.len() >= MAX_PIECES
        || polygon_error(&poly, map, &affine) <= max_error
    {
        out.push(AffinePiece {
            points: poly,
            st_to_page: affine,
        });
        return;
    }
    let (a, b) = range;
    let mid = a.signum() * (a * b).sqrt();
    let h = map.screen_to_st[2];
    let near = cut(&poly, h, mid, true);
    let far = cut(&poly, h, mid, false);
    slice(near, (a, mid), map, max_error, depth + 1, out);
    slice(far, (mid, b), map, max_error, depth + 1, out);
}

/// The part of convex `poly` where `h · (x, y, 1)` is at most `level` (`below`) or at
/// least `level`.
fn cut(poly: &[[f64; 2]], h: [f64; 3], level: f64, below: bool) -> Vec<[f64; 2]> {
    let side = |p: [f64; 2]| {
        let v = h[0] * p[0] + h[1] * p[1] + h[2] - level;
        if below {
            -v
        } else {
            v
        }
    };
    let mut out = Vec::with_capacity(poly.len() + 1);
    for k in 0..poly.len() {
        let (p, q) = (poly[k], poly[(k + 1) % poly.len()]);
        let (dp, dq) = (side(p), side(q));
        if dp >= 0.0 {
            out.push(p);
        }
        if (dp > 0.0 && dq < 0.0) || (dp < 0.0 && dq > 0.0) {
            let t = dp / (dp - dq);
            out.push([p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t]);
        }
    }
    out
}

/// The affine map from texture to page agreeing with `map` at the three corners of
/// `poly` spanning the largest triangle.
fn polygon_affine(poly: &[[f64; 2]], map: &TextureMap) -> Option<[f64; 6]> {
    let area = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])).abs()
    };
    let n = poly.len();
    let mut best = (0.0, [0, 1, 2]);
    // Polygons here have a handful of corners: all triples.
    for i in 0..n {
        for j in i + 1..n {
            for k in j + 1..n {
                let a = area(poly[i], poly[j], poly[k]);
                if a > best.0 {
                    best = (a, [i, j, k]);
                }
            }
        }
    }
    triangle_affine(&best.1.map(|i| poly[i]), map)
}

/// Page triangles thinner than this (in pixels) take the exact map's tangent at their
/// centroid rather than the map through their corners: across a sliver, the corners'
/// small departures from an affine map would make a nearly singular one.
const SLIVER_WIDTH: f64 = 1.0;

/// The affine map from texture to page for page triangle `t`: through its corners'
/// texture coordinates, or for a sliver (see [`SLIVER_WIDTH`]) the inverse of the
/// exact map's tangent at its centroid.
fn triangle_affine(t: &[[f64; 2]; 3], map: &TextureMap) -> Option<[f64; 6]> {
    let (x1, y1) = (t[1][0] - t[0][0], t[1][1] - t[0][1]);
    let (x2, y2) = (t[2][0] - t[0][0], t[2][1] - t[0][1]);
    let long = x1.hypot(y1).max(x2.hypot(y2)).max((x2 - x1).hypot(y2 - y1));
    let area2 = (x1 * y2 - x2 * y1).abs();
    let wide = area2 > MIN_PIECE_WIDTH * long; // false for NaN
    if !wide {
        return None;
    }
    if area2 >= SLIVER_WIDTH * long {
        let st = corners_st(t, map)?;
        return st_to_page(t, &st);
    }
    let c = [0, 1].map(|k| (t[0][k] + t[1][k] + t[2][k]) / 3.0);
    let h = &map.screen_to_st;
    let q = h[2][0] * c[0] + h[2][1] * c[1] + h[2][2];
    let st = map.st_at(c)?;
    // d(rᵢ/q)/dx = (hᵢ₀ − stᵢ · h₂₀) / q, and likewise in y: the tangent J.
    let j = [0, 1].map(|i| [0, 1].map(|k| (h[i][k] - st[i] * h[2][k]) / q));
    let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    // page = c + J⁻¹ (st' − st).
    let (a, c2) = (j[1][1] / det, -j[0][1] / det);
    let (b, d) = (-j[1][0] / det, j[0][0] / det);
    let e = c[0] - a * st[0] - c2 * st[1];
    let f = c[1] - b * st[0] - d * st[1];
    let m = [a, b, c2, d, e, f];
    m.iter().all(|v| v.is_finite()).then_some(m)
}

/// The largest page distance between where the affine map draws the exact texture point
/// of a sample of `poly` and the sample itself (see the module docs); infinite where the
/// exact map is undefined.
fn polygon_error(poly: &[[f64; 2]], map: &TextureMap, affine: &[f64; 6]) -> f64 {
    let [a, b, c, d, e, f] = *affine;
    let n = poly.len() as f64;
    let centre = [0, 1].map(|k| poly.iter().map(|p| p[k]).sum::<f64>() / n);
    let mut worst = 0.0f64;
    let mut probe = |p: [f64; 2]| -> bool {
        let Some(st) = map.st_at(p) else {
            return false;
        };
        let x = a * st[0] + c * st[1] + e;
        let y = b * st[0] + d * st[1] + f;
        worst = worst.max((x - p[0]).hypot(y - p[1]));
        true
    };
    let lerp =
        |p: [f64; 2], q: [f64; 2], t: f64| [p[0] + (q[0] - p[0]) * t, p[1] + (q[1] - p[1]) * t];
    if !probe(centre) {
        return f64::INFINITY;
    }
    for (i, &p) in poly.iter().enumerate() {
        let q = poly[(i + 1) % poly.len()];
        for t in [0.0, 0.25, 0.5, 0.75] {
            if !probe(lerp(p, q, t)) {
                return f64::INFINITY;
            }
        }
        if !probe(lerp(p, centre, 0.5)) {
            return f64::INFINITY;
        }
    }
    worst
}

/// The affine pieces of a textured fragment (see [`affine_pieces`]) to draw over its
/// run's underlay `whole` (the run under one affine map): none when the fragment is
/// the run's only one and its one piece is the underlay itself (drawing it twice would
/// only darken its anti-aliased edges, and double a viewer's work).
pub(crate) fn pieces_over(
    points: &[[f64; 2]],
    map: &TextureMap,
    whole: Option<&AffinePiece>,
    alone: bool,
) -> Vec<AffinePiece> {
    let pieces = affine_pieces(points, map, MAX_PERSPECTIVE_ERROR);
    if alone && pieces.len() == 1 && whole == pieces.first() {
        return Vec::new();
    }
    pieces
}

fn split(
    t: [[f64; 2]; 3],
    map: &TextureMap,
    max_error: f64,
    depth: u32,
    out: &mut Vec<AffinePiece>,
) {
    let Some(affine) = triangle_affine(&t, map) else {
        return; // degenerate on the page or in the texture: nothing to draw
    };
    if depth >= MAX_DEPTH
        || out.len() >= MAX_PIECES
        || perspective_error(&t, map, &affine) <= max_error
    {
        out.push(AffinePiece {
            points: t.to_vec(),
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

/// The thinnest page triangle drawn, in pixels: thinner ones show nothing, and their
/// maps are singular to viewers (rsvg refuses the whole file).
const MIN_PIECE_WIDTH: f64 = 1e-3;

/// The affine map from texture to page taking `st[i]` to `t[i]`; `None` when the
/// texture triangle is degenerate.
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
    use crate::TextureAlpha;

    /// The map of a unit square seen in perspective: a pure projective map.
    fn grazing() -> TextureMap {
        TextureMap {
            texture: 0,
            screen_to_st: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.004, 0.0, 1.0]],
            alpha: TextureAlpha::Opaque,
        }
    }

    fn area(poly: &[[f64; 2]]) -> f64 {
        let n = poly.len();
        (0..n)
            .map(|i| {
                let (p, q) = (poly[i], poly[(i + 1) % n]);
                p[0] * q[1] - q[0] * p[1]
            })
            .sum::<f64>()
            .abs()
            / 2.0
    }

    /// The largest error over a dense grid of each piece's fan triangles.
    fn worst_error(pieces: &[AffinePiece], map: &TextureMap) -> f64 {
        let mut worst = 0.0f64;
        for p in pieces {
            let [a, b, c, d, e, f] = p.st_to_page;
            for k in 1..p.points.len() - 1 {
                let t = [p.points[0], p.points[k], p.points[k + 1]];
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
        }
        worst
    }

    #[test]
    fn pieces_tile_the_polygon_and_stay_within_the_bound_everywhere() {
        let map = grazing();
        let quad = [[0.0, 0.0], [400.0, 0.0], [400.0, 300.0], [0.0, 300.0]];
        let pieces = affine_pieces(&quad, &map, MAX_PERSPECTIVE_ERROR);
        assert!(pieces.len() > 2, "perspective asks for splits");
        let total: f64 = pieces.iter().map(|p| area(&p.points)).sum();
        assert!((total - 120_000.0).abs() < 1e-6, "{total}");
        // Densely sampled, the error stays within the bound (with a little margin for
        // points between the samples the split decision used).
        let worst = worst_error(&pieces, &map);
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

    #[test]
    fn a_long_sliver_in_perspective_takes_a_few_slices() {
        // 400 px long, 3 px high, depth changing along it: quartering would make
        // hundreds of slivers.
        let map = grazing();
        let sliver = [[0.0, 0.0], [400.0, 3.0], [0.0, 3.0]];
        let pieces = affine_pieces(&sliver, &map, MAX_PERSPECTIVE_ERROR);
        assert!(pieces.iter().all(|p| p.points.len() >= 3));
        let mut quartered = Vec::new();
        split(sliver, &map, MAX_PERSPECTIVE_ERROR, 0, &mut quartered);
        assert!(
            pieces.len() * 8 <= quartered.len(),
            "{} slices, {} quarters",
            pieces.len(),
            quartered.len()
        );
        let total: f64 = pieces.iter().map(|p| area(&p.points)).sum();
        assert!((total - 600.0).abs() < 1e-9, "{total}");
        assert!(worst_error(&pieces, &map) <= MAX_PERSPECTIVE_ERROR * 1.05);
    }

    #[test]
    fn a_piece_with_no_width_draws_nothing() {
        let map = grazing();
        let flat = [[0.0, 0.0], [100.0, 50.0], [200.0, 100.0 + 1e-9]];
        assert!(affine_pieces(&flat, &map, MAX_PERSPECTIVE_ERROR).is_empty());
        let doubled = [[0.0, 0.0], [100.0, 50.0], [100.0, 50.0], [0.0, 10.0]];
        for p in affine_pieces(&doubled, &map, MAX_PERSPECTIVE_ERROR) {
            let [a, b, c, d, ..] = p.st_to_page;
            assert!((a * d - b * c).abs() > 1e-3, "{p:?}");
        }
    }

    #[test]
    fn a_nearly_singular_map_reaches_no_repetition() {
        let piece = AffinePiece {
            points: vec![[172.0, 284.13], [171.34, 283.99], [171.59, 284.07]],
            st_to_page: [
                46.999771, 14.680428, -13.354601, -4.179825, 141.9513, 274.8181,
            ],
        };
        assert_eq!(piece.repetitions(), None);
    }

    #[test]
    fn rounding_noise_reaches_no_further_repetition() {
        // Texture square [0, 1]² onto a 100 px square, corners a hair outside it.
        let piece = AffinePiece {
            points: vec![[0.0, 0.0], [100.0, 0.0], [100.0, 100.0]],
            st_to_page: [100.0 + 1e-12, 0.0, 0.0, 100.0, -1e-11, 1e-11],
        };
        assert_eq!(piece.repetitions().unwrap(), vec![(0.0, 0.0)]);
    }
}
