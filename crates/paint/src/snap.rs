//! A run's pieces on the writer's grid without cracks between them: snap rounding.
//!
//! The pieces of one face painted in one colour are written as one path, each a subpath.
//! Exactly, they tile their area: where a corner of one piece lies on an edge of its
//! neighbour (a T-junction: the neighbour was cut elsewhere), the two meet along the whole
//! edge. Written, every corner is rounded to the grid of the writer's last decimal, and
//! the neighbour's edge still runs straight between its own rounded ends: the rounded
//! corner lies up to half a unit off it, and a sliver between them is left unfilled, as
//! long as the edge. What lies beneath shows through it; in a browser (Skia samples a
//! pixel on a few lines) a sliver of 0.005 px showed as a scratch of 20–30 levels across
//! a shadow.
//!
//! Hot-pixel snap rounding (Hobby; Guibas and Marimont) closes them: every grid cell
//! that holds a rounded corner of the run is *hot*, and every edge is written through the
//! centre of each hot cell it passes through, in order along it. An edge passing through
//! the cell of a T-junction's corner (it passes within rounding of that corner) is thus
//! written through the same grid point as the corner, on both sides of the seam. Whether
//! an edge meets a cell is decided exactly: the edge's ends are the writer's own scaled
//! coordinates (the values it rounds), the cell's corners lie half a unit either side of
//! its centre (exact in `f64`), and the corners' sides of the edge come from exact
//! orientation tests. No tolerance decides anything; every point written is a grid point
//! within half a unit of the exact edge, as every rounded corner already is.

use crate::number::{round_i64, scaled};

/// A ring of grid points (units of the writer's last decimal).
pub(crate) type GridRing = Vec<[i64; 2]>;

/// The largest magnitude of a scaled coordinate snapped: beyond it a cell's corners
/// (centre ± 0.5) are no longer exact in `f64`.
const MAX_SCALED: f64 = (1u64 << 51) as f64;

/// `rings`, mapped to the page by `page`, snap-rounded together to the grid of
/// `decimals` decimals: each corner rounded as the writers round it, each edge through
/// every hot cell it meets (see the module docs). `None` when a coordinate is beyond the
/// grid's exact range (the writer then writes the rings as they are).
pub(crate) fn snapped_rings<R, P>(
    rings: R,
    decimals: u8,
    page: impl Fn([f64; 2]) -> [f64; 2],
) -> Option<Vec<GridRing>>
where
    R: IntoIterator<Item = P>,
    P: IntoIterator<Item = [f64; 2]>,
{
    let mut points: Vec<Vec<[f64; 2]>> = Vec::new();
    for ring in rings {
        let mut r = Vec::new();
        for q in ring {
            let q = page(q);
            let s = [scaled(q[0], decimals)?, scaled(q[1], decimals)?];
            if s[0].abs() >= MAX_SCALED || s[1].abs() >= MAX_SCALED {
                return None;
            }
            r.push(s);
        }
        points.push(r);
    }
    Some(snap(&points))
}

/// Snap-rounds `rings` (in grid units) together.
fn snap(rings: &[Vec<[f64; 2]>]) -> Vec<GridRing> {
    let rounded: Vec<GridRing> = rings
        .iter()
        .map(|r| {
            r.iter()
                .map(|p| [round_i64(p[0]), round_i64(p[1])])
                .collect()
        })
        .collect();
    if rings.len() < 2 {
        return rounded.into_iter().map(dedup).collect();
    }
    let hot = HotCells::new(rounded.iter().flatten().copied().collect());
    let mut found = Vec::new();
    rings
        .iter()
        .zip(&rounded)
        .map(|(ring, grid)| {
            let n = ring.len();
            let mut out = Vec::with_capacity(n);
            for i in 0..n {
                let j = (i + 1) % n;
                out.push(grid[i]);
                hot.met_by(ring[i], ring[j], grid[i], grid[j], &mut found);
                out.extend_from_slice(&found);
            }
            dedup(out)
        })
        .collect()
}

/// `ring` without a point equal to the one before it (cyclically).
fn dedup(mut ring: GridRing) -> GridRing {
    ring.dedup();
    while ring.len() > 1 && ring.first() == ring.last() {
        ring.pop();
    }
    ring
}

/// The hot cells of a run, bucketed by a coarse square grid for lookups along an edge.
struct HotCells {
    /// The hot cells, sorted by bucket.
    cells: Vec<[i64; 2]>,
    /// `starts[b]..starts[b + 1]` are bucket `b`'s cells.
    starts: Vec<usize>,
    /// The lowest cell coordinates.
    origin: [i64; 2],
    /// Cells per bucket side.
    side: i64,
    /// Buckets per row and per column.
    dims: [i64; 2],
}

impl HotCells {
    fn new(mut cells: Vec<[i64; 2]>) -> HotCells {
        cells.sort_unstable();
        cells.dedup();
        let lo = cells
            .iter()
            .fold([i64::MAX; 2], |m, c| [m[0].min(c[0]), m[1].min(c[1])]);
        let hi = cells
            .iter()
            .fold([i64::MIN; 2], |m, c| [m[0].max(c[0]), m[1].max(c[1])]);
        let extent = [(hi[0] - lo[0] + 1) as f64, (hi[1] - lo[1] + 1) as f64];
        // About one cell per bucket.
        let side = ((extent[0] * extent[1] / cells.len() as f64).sqrt().ceil() as i64).max(1);
        let dims = [(hi[0] - lo[0]) / side + 1, (hi[1] - lo[1]) / side + 1];
        let bucket =
            |c: &[i64; 2]| ((c[1] - lo[1]) / side * dims[0] + (c[0] - lo[0]) / side) as usize;
        cells.sort_unstable_by_key(|c| (bucket(c), *c));
        let mut starts = vec![0usize; (dims[0] * dims[1]) as usize + 1];
        for c in &cells {
            starts[bucket(c) + 1] += 1;
        }
        for b in 1..starts.len() {
            starts[b] += starts[b - 1];
        }
        HotCells {
            cells,
            starts,
            origin: lo,
            side,
            dims,
        }
    }

    /// Puts into `found` the hot cells other than `gp` and `gq` (the rounded ends) that
    /// the edge `p`–`q` meets, in order from `p` to `q`.
    fn met_by(
        &self,
        p: [f64; 2],
        q: [f64; 2],
        gp: [i64; 2],
        gq: [i64; 2],
        found: &mut Vec<[i64; 2]>,
    ) {
        found.clear();
        if gp == gq {
            return;
        }
        // Cells whose square meets the edge's bounding box.
        let (x0, x1) = (p[0].min(q[0]), p[0].max(q[0]));
        let (y0, y1) = (p[1].min(q[1]), p[1].max(q[1]));
        let cell_lo = |v: f64| (v - 0.5).ceil() as i64;
        let cell_hi = |v: f64| (v + 0.5).floor() as i64;
        let (cy0, cy1) = (cell_lo(y0), cell_hi(y1));
        let by0 = self.bucket_of(cy0, 1);
        let by1 = self.bucket_of(cy1, 1);
        for by in by0..=by1 {
            // The edge's cells in this band of buckets: its x-range over the band's
            // y-range, widened by a cell (the exact test below decides).
            let band_lo = (self.origin[1] + by * self.side) as f64 - 0.5;
            let band_hi = (self.origin[1] + (by + 1) * self.side) as f64 + 0.5;
            let (lo, hi) = x_range(p, q, band_lo.max(y0), band_hi.min(y1));
            let (cx0, cx1) = (cell_lo(lo.max(x0)) - 1, cell_hi(hi.min(x1)) + 1);
            let bx0 = self.bucket_of(cx0, 0);
            let bx1 = self.bucket_of(cx1, 0);
            for bx in bx0..=bx1 {
                let b = (by * self.dims[0] + bx) as usize;
                for &c in &self.cells[self.starts[b]..self.starts[b + 1]] {
                    if c != gp && c != gq && meets(p, q, c) {
                        found.push(c);
                    }
                }
            }
        }
        if found.len() > 1 {
            // Along the edge: by `c · d`, `d = q − p` as rounded, so that the edge taken
            // the other way (`d` negated exactly) gets exactly the reverse order; ties
            // broken by the cells' order, reversed with the direction.
            let d = [q[0] - p[0], q[1] - p[1]];
            let forward = (d[0], d[1]) > (0.0, 0.0);
            found.sort_unstable_by(|a, b| {
                let ka = a[0] as f64 * d[0] + a[1] as f64 * d[1];
                let kb = b[0] as f64 * d[0] + b[1] as f64 * d[1];
                let tie = if forward { a.cmp(b) } else { b.cmp(a) };
                ka.total_cmp(&kb).then(tie)
            });
        }
    }

    /// The bucket index along `axis` of cell coordinate `v`, clamped to the buckets.
    fn bucket_of(&self, v: i64, axis: usize) -> i64 {
        ((v - self.origin[axis]).max(0) / self.side).min(self.dims[axis] - 1)
    }
}

/// The x-range of segment `p`–`q` where its y lies in `[y0, y1]` (rounded outwards
/// enough for a lookup: the caller widens it by a cell).
fn x_range(p: [f64; 2], q: [f64; 2], y0: f64, y1: f64) -> (f64, f64) {
    if p[1] == q[1] || y0 > y1 {
        return (p[0].min(q[0]), p[0].max(q[0]));
    }
    let at = |y: f64| p[0] + (q[0] - p[0]) * ((y - p[1]) / (q[1] - p[1]));
    let (a, b) = (at(y0), at(y1));
    (a.min(b), a.max(b))
}

/// Whether the segment `p`–`q` meets the closed unit square centred on cell `c`: its
/// bounding box meets the square's, and the square's corners are not all strictly on one
/// side of its line (exact orientation tests).
fn meets(p: [f64; 2], q: [f64; 2], c: [i64; 2]) -> bool {
    let (cx, cy) = (c[0] as f64, c[1] as f64);
    let (sx0, sx1, sy0, sy1) = (cx - 0.5, cx + 0.5, cy - 0.5, cy + 0.5);
    if p[0].max(q[0]) < sx0 || p[0].min(q[0]) > sx1 || p[1].max(q[1]) < sy0 || p[1].min(q[1]) > sy1
    {
        return false;
    }
    let side = |x: f64, y: f64| {
        let o = robust::orient2d(
            robust::Coord { x: p[0], y: p[1] },
            robust::Coord { x: q[0], y: q[1] },
            robust::Coord { x, y },
        );
        if o > 0.0 {
            1
        } else if o < 0.0 {
            -1
        } else {
            0
        }
    };
    let s = [
        side(sx0, sy0),
        side(sx1, sy0),
        side(sx1, sy1),
        side(sx0, sy1),
    ];
    !(s.iter().all(|&v| v > 0) || s.iter().all(|&v| v < 0))
}

#[cfg(test)]
mod tests {
    use i_overlay::core::fill_rule::FillRule;
    use i_overlay::core::overlay::IntOverlayOptions;
    use i_overlay::core::simplify::Simplify;
    use i_overlay::i_float::int::point::IntPoint;

    use super::*;

    /// Twice the signed area of a ring of grid points (exact).
    fn area2(r: &[[i64; 2]]) -> i128 {
        (0..r.len())
            .map(|i| {
                let (a, b) = (r[i], r[(i + 1) % r.len()]);
                i128::from(a[0]) * i128::from(b[1]) - i128::from(b[0]) * i128::from(a[1])
            })
            .sum()
    }

    /// Rounded corners only, as the writers wrote runs before.
    fn rounded(rings: &[Vec<[f64; 2]>]) -> Vec<GridRing> {
        rings
            .iter()
            .map(|r| {
                r.iter()
                    .map(|p| [round_i64(p[0]), round_i64(p[1])])
                    .collect()
            })
            .collect()
    }

    /// The union of grid rings under the non-zero rule: its rings (outer and holes) and
    /// twice its area.
    fn union(rings: &[GridRing]) -> (usize, i128) {
        let contours: Vec<Vec<IntPoint<i32>>> = rings
            .iter()
            .map(|r| {
                r.iter()
                    .map(|p| IntPoint::new(p[0] as i32, p[1] as i32))
                    .collect()
            })
            .collect();
        let shapes = contours.simplify(FillRule::NonZero, IntOverlayOptions::default());
        let rings: Vec<GridRing> = shapes
            .iter()
            .flatten()
            .map(|r| r.iter().map(|p| [i64::from(p.x), i64::from(p.y)]).collect())
            .collect();
        (
            rings.len(),
            rings.iter().map(|r| area2(r)).sum::<i128>().abs(),
        )
    }

    /// A T-junction: the right pieces' shared corner lies on the left piece's edge, off
    /// the grid. Rounded, it lies right of the left piece's rounded edge, and a sliver
    /// opens between them; snapped, the left piece's edge passes through the corner's grid
    /// point and the three pieces tile their union.
    #[test]
    fn a_t_junction_closes() {
        let (a, b, t, r) = ([0.0, 0.0], [2.4, 30.0], [0.8, 10.0], [10.0, 10.0]);
        let rings = vec![vec![a, b, [-5.0, 15.0]], vec![a, r, t], vec![t, r, b]];
        let turned = |rs: &[GridRing]| -> i128 { rs.iter().map(|r| area2(r).abs()).sum() };
        // Twice the area of the pieces' outline, on the grid.
        let outline = area2(&[[0, 0], [10, 10], [2, 30], [-5, 15]]).abs();
        let (_, plain_union) = union(&rounded(&rings));
        assert!(plain_union < outline, "the sliver is there before");
        let snapped = snapped_rings(rings.iter().map(|r| r.iter().copied()), 0, |q| q).unwrap();
        assert_eq!(snapped[0], vec![[0, 0], [1, 10], [2, 30], [-5, 15]]);
        let (n, whole) = union(&snapped);
        assert_eq!((n, turned(&snapped), whole), (1, outline, outline));
    }

    /// An edge shared by two pieces, taken one way by the one and the other way by the
    /// other, passes through the same cells in reverse order.
    #[test]
    fn a_shared_edge_is_written_alike_both_ways() {
        let (a, b) = ([0.3, 0.2], [40.7, 13.9]);
        // Corners near the edge on both sides, some on it as nearly as f64 allows.
        let on = |s: f64| [a[0] + s * (b[0] - a[0]), a[1] + s * (b[1] - a[1])];
        let rings = [
            vec![a, on(0.25), b, [20.0, 30.0]],
            vec![b, on(0.75), on(0.5), a, [20.0, -30.0]],
        ];
        let snapped = snapped_rings(rings.iter().map(|r| r.iter().copied()), 0, |q| q).unwrap();
        let from = |r: &GridRing, p: [i64; 2], q: [i64; 2]| -> GridRing {
            let n = r.len();
            let i = r.iter().position(|&x| x == p).unwrap();
            let mut path = vec![];
            for k in 0..n {
                let x = r[(i + k) % n];
                path.push(x);
                if x == q {
                    break;
                }
            }
            path
        };
        let (ga, gb) = ([0, 0], [41, 14]);
        let one = from(&snapped[0], ga, gb);
        let mut other = from(&snapped[1], gb, ga);
        other.reverse();
        assert_eq!(one, other);
        assert!(one.len() >= 5, "{one:?}");
    }

    /// A strip cut at different places above and below its middle line, turned by an
    /// angle and scaled: every cut is a T-junction, each corner within rounding of the
    /// edges it lies on. Snapped, the pieces tile one outline without holes on every
    /// grid; only rounded, slivers open.
    #[test]
    fn a_strip_cut_differently_on_each_side_tiles_its_outline() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut slivers = 0;
        for _ in 0..50 {
            let angle = next() * std::f64::consts::TAU;
            let (c, s) = (angle.cos(), angle.sin());
            let scale = 20.0 + 300.0 * next();
            let shift = [next() * 50.0, next() * 50.0];
            let map = |p: [f64; 2]| {
                [
                    shift[0] + scale * (c * p[0] - s * p[1]),
                    shift[1] + scale * (s * p[0] + c * p[1]),
                ]
            };
            let mut cuts = |n: usize| {
                let mut v: Vec<f64> = (0..n).map(|_| next() * 10.0).collect();
                v.push(0.0);
                v.push(10.0);
                v.sort_by(f64::total_cmp);
                v
            };
            let (top, bottom) = (cuts(7), cuts(5));
            let mut rings: Vec<Vec<[f64; 2]>> = Vec::new();
            for (cuts, y) in [(&top, 1.0), (&bottom, -1.0)] {
                for w in cuts.windows(2) {
                    // Each piece's edge on the middle line holds the other side's cuts.
                    let other = if y > 0.0 { &bottom } else { &top };
                    let mut ring = vec![[w[0], y], [w[1], y]];
                    let mid: Vec<[f64; 2]> = other
                        .iter()
                        .filter(|&&x| x > w[0] && x < w[1])
                        .map(|&x| [x, 0.0])
                        .collect();
                    ring.push([w[1], 0.0]);
                    ring.extend(mid.iter().rev());
                    ring.push([w[0], 0.0]);
                    // Only the piece's own corners: the other side's cuts are T-junctions.
                    ring.retain(|p| p[1] != 0.0 || p[0] == w[0] || p[0] == w[1]);
                    rings.push(ring.into_iter().map(map).collect());
                }
            }
            let snapped = snapped_rings(rings.iter().map(|r| r.iter().copied()), 0, |q| q).unwrap();
            let (n, whole) = union(&snapped);
            let sum: i128 = snapped.iter().map(|r| area2(r).abs()).sum();
            assert_eq!((n, sum), (1, whole), "snapped: one outline, no overlap");
            let plain = rounded(&rings);
            let (m, plain_whole) = union(&plain);
            let plain_sum: i128 = plain.iter().map(|r| area2(r).abs()).sum();
            slivers += usize::from(m > 1 || plain_sum != plain_whole);
        }
        assert!(
            slivers > 25,
            "rounding alone left slivers in only {slivers} of 50"
        );
    }
}
