//! Smooth shading in SVG, which has no mesh gradient: each Gouraud triangle is drawn
//! as one linear gradient where its colours allow (exactly, up to the tolerance), and
//! otherwise split into flat pieces until every piece is within the tolerance of the
//! linear interpolation it stands for.
//!
//! A linear gradient is one colour ramp `c(λ) = c₀ + λ·d` along one direction. The
//! linear interpolation over a triangle is such a ramp exactly when its three corner
//! colours lie on one line in RGB (one light without highlights gives that: every
//! corner is `ambient + Kd · diffuse`); the writer accepts a triangle as a gradient
//! when the third colour lies within the budget of the line through the two most
//! different ones (the difference is largest at that corner and is the whole error).
//! Otherwise the triangle is split at its edge midpoints (the colour there is the
//! mean of the two ends, exactly) until the pieces are flat within the budget (their
//! colour is the mean of their corners; the difference is largest at a corner) or
//! gradients. The budget is half the tolerance: the other half covers rounding the
//! written colours to 8 bits (at most 0.5/255, which is half of the default 1/255).
//! Splitting stops at edges of [`MIN_EDGE_PX`] or after [`MAX_DEPTH`] levels.
//!
//! A triangle whose colours are far from one line (three unrelated vertex colours:
//! more than [`CHANNELS_FROM`] from the nearest gradient) would need thousands of
//! pieces, below a pixel each, which anti-aliasing blends with what lies under them.
//! It is drawn exactly instead as its three channels: each channel of the linear
//! interpolation is one ramp (black to red, to green, to blue) along its own
//! direction, and the three ramps, painted over each other with `mix-blend-mode:
//! lighten` inside an isolated group, give their per-channel maximum, which is their
//! sum since each holds one channel only.
use crate::phong::{MAX_DEPTH, MIN_EDGE_PX};
use crate::VertexColor;

/// A triangle whose third colour lies farther than this (per channel, colours in
/// [0, 1]) from the line through the other two is drawn as its channels.
pub(crate) const CHANNELS_FROM: f64 = 8.0 / 255.0;

/// One channel's ramp over a triangle: the channel's value goes from `v0` at `from`
/// to `v1` at `to` (padded beyond them).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Ramp {
    /// Where the ramp starts.
    pub from: [f64; 2],
    /// Where it ends.
    pub to: [f64; 2],
    /// The channel's value at `from`.
    pub v0: f64,
    /// The channel's value at `to`.
    pub v1: f64,
}

/// One piece of a smooth fill.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Piece {
    /// A triangle in one colour.
    Flat {
        /// Corners in pixels.
        tri: [[f64; 2]; 3],
        /// Linear RGB.
        rgb: [f64; 3],
    },
    /// A triangle filled with a linear gradient from `from` (colour `c0`) to `to`
    /// (colour `c1`), padded beyond them.
    Gradient {
        /// Corners in pixels.
        tri: [[f64; 2]; 3],
        /// Where the ramp starts.
        from: [f64; 2],
        /// Where it ends.
        to: [f64; 2],
        /// Colour at `from`.
        c0: [f64; 3],
        /// Colour at `to`.
        c1: [f64; 3],
    },
    /// A triangle filled with the sum of one ramp per channel (see the module docs).
    Channels {
        /// Corners in pixels.
        tri: [[f64; 2]; 3],
        /// The red, green and blue ramps.
        ramps: [Ramp; 3],
    },
}

impl Piece {
    /// The piece's triangle.
    pub(crate) fn tri(&self) -> [[f64; 2]; 3] {
        match *self {
            Piece::Flat { tri, .. } | Piece::Gradient { tri, .. } | Piece::Channels { tri, .. } => {
                tri
            }
        }
    }
}

/// The pieces of a fragment with corners `points` and corner colours `colors` (fanned
/// from the first corner), each within `tolerance` (per channel) of the linear
/// interpolation once written in 8 bits.
pub(crate) fn pieces(points: &[[f64; 2]], colors: &[VertexColor], tolerance: f64) -> Vec<Piece> {
    let budget = 0.5 * tolerance;
    let rgb = |i: usize| [0, 1, 2].map(|k| f64::from(colors[i][k]).clamp(0.0, 1.0));
    let mut out = Vec::new();
    for i in 1..points.len().saturating_sub(1) {
        split(
            [points[0], points[i], points[i + 1]],
            [rgb(0), rgb(i), rgb(i + 1)],
            budget,
            0,
            &mut out,
        );
    }
    out
}

/// One paint for a whole fragment, exact when its colours allow one gradient: the
/// gradient of its first three corners along the line through their two most different
/// colours (the third colour projected onto it), else the mean of its corners flat.
/// The piece's triangle is the first three corners.
pub(crate) fn fit(points: &[[f64; 2]], colors: &[VertexColor]) -> Piece {
    let rgb = |i: usize| [0, 1, 2].map(|k| f64::from(colors[i][k]).clamp(0.0, 1.0));
    let tri = [points[0], points[1], points[2]];
    let c = [rgb(0), rgb(1), rgb(2)];
    gradient(tri, c, f64::INFINITY).unwrap_or_else(|| {
        let n = colors.len() as f64;
        let mean = [0, 1, 2].map(|k| {
            colors
                .iter()
                .map(|c| f64::from(c[k]).clamp(0.0, 1.0))
                .sum::<f64>()
                / n
        });
        Piece::Flat { tri, rgb: mean }
    })
}

fn split(tri: [[f64; 2]; 3], c: [[f64; 3]; 3], budget: f64, depth: u32, out: &mut Vec<Piece>) {
    let mean = [0, 1, 2].map(|k| (c[0][k] + c[1][k] + c[2][k]) / 3.0);
    let off = |a: [f64; 3], b: [f64; 3]| (0..3).map(|k| (a[k] - b[k]).abs()).fold(0.0, f64::max);
    if c.iter().all(|&ci| off(ci, mean) <= budget) {
        out.push(Piece::Flat { tri, rgb: mean });
        return;
    }
    if let Some(g) = gradient(tri, c, budget) {
        out.push(g);
        return;
    }
    if depth == 0 && gradient(tri, c, CHANNELS_FROM).is_none() {
        if let Some(ch) = channels(tri, c) {
            out.push(ch);
            return;
        }
    }
    let longest = (0..3)
        .map(|i| (tri[i][0] - tri[(i + 1) % 3][0]).hypot(tri[i][1] - tri[(i + 1) % 3][1]))
        .fold(0.0, f64::max);
    if depth >= MAX_DEPTH || longest <= MIN_EDGE_PX || !longest.is_finite() {
        out.push(Piece::Flat { tri, rgb: mean });
        return;
    }
    let mid = |i: usize| {
        let j = (i + 1) % 3;
        (
            [0, 1].map(|k| (tri[i][k] + tri[j][k]) * 0.5),
            [0, 1, 2].map(|k| (c[i][k] + c[j][k]) * 0.5),
        )
    };
    let [(pab, cab), (pbc, cbc), (pca, cca)] = [mid(0), mid(1), mid(2)];
    let [a, b, cc] = tri;
    let d = depth + 1;
    split([a, pab, pca], [c[0], cab, cca], budget, d, out);
    split([pab, b, pbc], [cab, c[1], cbc], budget, d, out);
    split([pca, pbc, cc], [cca, cbc, c[2]], budget, d, out);
    split([pab, pbc, pca], [cab, cbc, cca], budget, d, out);
}

/// The triangle as one ramp per channel; `None` when it has no area on the page.
fn channels(tri: [[f64; 2]; 3], c: [[f64; 3]; 3]) -> Option<Piece> {
    let u = [tri[1][0] - tri[0][0], tri[1][1] - tri[0][1]];
    let v = [tri[2][0] - tri[0][0], tri[2][1] - tri[0][1]];
    let det = u[0] * v[1] - u[1] * v[0];
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let ramp = |k: usize| -> Option<Ramp> {
        let (f0, du, dv) = (c[0][k], c[1][k] - c[0][k], c[2][k] - c[0][k]);
        // The channel's gradient g: g·u = du, g·v = dv.
        let g = [(du * v[1] - dv * u[1]) / det, (dv * u[0] - du * v[0]) / det];
        let gg = g[0] * g[0] + g[1] * g[1];
        if !gg.is_finite() {
            return None;
        }
        if gg == 0.0 {
            return Some(Ramp {
                from: tri[0],
                to: tri[0],
                v0: f0,
                v1: f0,
            });
        }
        let lo = c.iter().map(|x| x[k]).fold(f64::INFINITY, f64::min);
        let hi = c.iter().map(|x| x[k]).fold(f64::NEG_INFINITY, f64::max);
        let at = |f: f64| [0, 1].map(|m| tri[0][m] + g[m] * (f - f0) / gg);
        Some(Ramp {
            from: at(lo),
            to: at(hi),
            v0: lo,
            v1: hi,
        })
    };
    Some(Piece::Channels {
        tri,
        ramps: [ramp(0)?, ramp(1)?, ramp(2)?],
    })
}

/// The triangle as one linear gradient, when its third colour lies within `budget`
/// of the line through the other two (see the module docs).
fn gradient(tri: [[f64; 2]; 3], c: [[f64; 3]; 3], budget: f64) -> Option<Piece> {
    let diff = |a: [f64; 3], b: [f64; 3]| [0, 1, 2].map(|k| b[k] - a[k]);
    let size = |v: [f64; 3]| v.iter().map(|x| x.abs()).fold(0.0, f64::max);
    let (i, j) = [(0, 1), (1, 2), (2, 0)]
        .into_iter()
        .max_by(|&(a, b), &(p, q)| size(diff(c[a], c[b])).total_cmp(&size(diff(c[p], c[q]))))?;
    let k = 3 - i - j;
    let d = diff(c[i], c[j]);
    let dd: f64 = d.iter().map(|x| x * x).sum();
    if dd == 0.0 {
        return None;
    }
    let ck = diff(c[i], c[k]);
    let lk = (0..3).map(|m| ck[m] * d[m]).sum::<f64>() / dd;
    let residual = (0..3)
        .map(|m| (ck[m] - lk * d[m]).abs())
        .fold(0.0, f64::max);
    if residual > budget {
        return None;
    }
    // λ is affine on the screen with λ(p_i) = 0, λ(p_j) = 1, λ(p_k) = lk: its
    // gradient g solves g·(p_j − p_i) = 1, g·(p_k − p_i) = lk.
    let u = [tri[j][0] - tri[i][0], tri[j][1] - tri[i][1]];
    let v = [tri[k][0] - tri[i][0], tri[k][1] - tri[i][1]];
    let det = u[0] * v[1] - u[1] * v[0];
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let g = [(v[1] - lk * u[1]) / det, (lk * u[0] - v[0]) / det];
    let gg = g[0] * g[0] + g[1] * g[1];
    if gg == 0.0 || !gg.is_finite() {
        return None;
    }
    let (lo, hi) = (lk.min(0.0), lk.max(1.0));
    let at = |l: f64| [tri[i][0] + g[0] * l / gg, tri[i][1] + g[1] * l / gg];
    let colour = |l: f64| [0, 1, 2].map(|m| c[i][m] + l * d[m]);
    Some(Piece::Gradient {
        tri,
        from: at(lo),
        to: at(hi),
        c0: colour(lo),
        c1: colour(hi),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{narrow_color, wide_color};

    /// The colour a piece paints at `p` (before 8-bit rounding), or `None` outside.
    fn paint_at(piece: &Piece, p: [f64; 2]) -> Option<[f64; 3]> {
        let tri = piece.tri();
        let b = bary(tri, p);
        if b.iter().any(|&x| x < -1e-12) {
            return None;
        }
        Some(match *piece {
            Piece::Flat { rgb, .. } => rgb,
            Piece::Gradient {
                from, to, c0, c1, ..
            } => {
                let (dx, dy) = (to[0] - from[0], to[1] - from[1]);
                let t = (((p[0] - from[0]) * dx + (p[1] - from[1]) * dy) / (dx * dx + dy * dy))
                    .clamp(0.0, 1.0);
                [0, 1, 2].map(|k| c0[k] + t * (c1[k] - c0[k]))
            }
            Piece::Channels { ramps, .. } => ramps.map(|r| {
                let (dx, dy) = (r.to[0] - r.from[0], r.to[1] - r.from[1]);
                let dd = dx * dx + dy * dy;
                if dd == 0.0 {
                    return r.v1;
                }
                let t = (((p[0] - r.from[0]) * dx + (p[1] - r.from[1]) * dy) / dd).clamp(0.0, 1.0);
                r.v0 + t * (r.v1 - r.v0)
            }),
        })
    }

    fn bary(t: [[f64; 2]; 3], p: [f64; 2]) -> [f64; 3] {
        let det =
            (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[1][1] - t[0][1]) * (t[2][0] - t[0][0]);
        let b1 =
            ((p[0] - t[0][0]) * (t[2][1] - t[0][1]) - (p[1] - t[0][1]) * (t[2][0] - t[0][0])) / det;
        let b2 =
            ((t[1][0] - t[0][0]) * (p[1] - t[0][1]) - (t[1][1] - t[0][1]) * (p[0] - t[0][0])) / det;
        [1.0 - b1 - b2, b1, b2]
    }

    fn worst(points: &[[f64; 2]; 3], colors: &[[f64; 4]; 3], tol: f64) -> (f64, Vec<Piece>) {
        let stored = colors.map(narrow_color);
        let ps = pieces(points, &stored, tol);
        // The interpolation of the colours as a fragment keeps them.
        let colors = stored.map(wide_color);
        let mut worst = 0.0f64;
        for i in 0..=40 {
            for j in 0..=(40 - i) {
                let b = [i as f64 / 40.0, j as f64 / 40.0, (40 - i - j) as f64 / 40.0];
                let p = [0, 1].map(|k| (0..3).map(|m| b[m] * points[m][k]).sum::<f64>());
                let want = [0, 1, 2].map(|k| (0..3).map(|m| b[m] * colors[m][k]).sum::<f64>());
                let got = ps.iter().find_map(|pc| paint_at(pc, p)).expect("covered");
                for k in 0..3 {
                    worst = worst.max((got[k] - want[k]).abs());
                }
            }
        }
        (worst, ps)
    }

    const TRI: [[f64; 2]; 3] = [[0.0, 0.0], [200.0, 10.0], [30.0, 150.0]];

    #[test]
    fn collinear_colours_are_one_exact_gradient() {
        // On one line as kept (single precision): the third is the mean of the others.
        let c = [
            [0.125, 0.25, 0.375, 1.0],
            [0.5, 0.625, 0.75, 1.0],
            [0.3125, 0.4375, 0.5625, 1.0],
        ];
        let (w, ps) = worst(&TRI, &c, 1.0 / 255.0);
        assert_eq!(ps.len(), 1);
        assert!(matches!(ps[0], Piece::Gradient { .. }));
        assert!(w < 1e-12, "{w}");
    }

    #[test]
    fn unrelated_colours_are_three_exact_channel_ramps() {
        let c = [
            [1.0, 0.0, 0.0, 1.0],
            [0.0, 1.0, 0.0, 1.0],
            [0.2, 0.3, 1.0, 1.0],
        ];
        let (w, ps) = worst(&TRI, &c, 1.0 / 255.0);
        assert_eq!(ps.len(), 1);
        assert!(matches!(ps[0], Piece::Channels { .. }));
        assert!(w < 1e-9, "{w}");
    }

    #[test]
    fn other_colours_are_split_within_the_tolerance() {
        // Within CHANNELS_FROM of one line: split.
        let c = [
            [0.5, 0.5, 0.5, 1.0],
            [0.52, 0.5, 0.5, 1.0],
            [0.5, 0.52, 0.5, 1.0],
        ];
        for tol in [1.0 / 255.0, 4.0 / 255.0, 16.0 / 255.0] {
            let (w, ps) = worst(&TRI, &c, tol);
            assert!(
                w <= 0.5 * tol,
                "tolerance {tol}: {w} with {} pieces",
                ps.len()
            );
        }
        let fine = pieces(&TRI, &c.map(narrow_color), 1.0 / 255.0).len();
        let coarse = pieces(&TRI, &c.map(narrow_color), 4.0 / 255.0).len();
        assert!(coarse * 4 < fine, "{coarse} {fine}");
    }

    #[test]
    fn one_colour_is_one_flat_piece() {
        let c = [[0.5, 0.5, 0.5, 1.0]; 3];
        assert_eq!(
            pieces(&TRI, &c, 1.0 / 255.0),
            vec![Piece::Flat {
                tri: TRI,
                rgb: [0.5; 3]
            }]
        );
    }
}
