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
    // The median extent of the run's edges sizes the buckets.
    let mut extents: Vec<f64> = rings
        .iter()
        .flat_map(|r| {
            (0..r.len()).map(move |i| {
                let (a, b) = (r[i], r[(i + 1) % r.len()]);
                (a[0] - b[0]).abs().max((a[1] - b[1]).abs())
            })
        })
        .collect();
    let middle = extents.len() / 2;
    let edge = if extents.is_empty() {
        1.0
    } else {
        *extents.select_nth_unstable_by(middle, f64::total_cmp).1
    };
    let hot = HotCells::new(rounded.iter().flatten().copied().collect(), edge);
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

/// The hot cells of a run, bucketed by a coarse square grid for lookups along an edge:
/// buckets as wide as the run's median edge, so that an edge looks into a few buckets
/// and a bucket holds the cells of a few edges, however the corners cluster; only
/// buckets holding a cell are kept (sorted, found by binary search).
struct HotCells {
    /// The hot cells with their buckets, sorted by bucket (row, then column).
    cells: Vec<([i64; 2], [i64; 2])>,
    /// Cells per bucket side.
    side: i64,
}

impl HotCells {
    /// The hot cells `cells`, bucketed for edges of typical extent `edge` (grid units).
    fn new(mut cells: Vec<[i64; 2]>, edge: f64) -> HotCells {
        cells.sort_unstable();
        cells.dedup();
        let side = (edge.ceil() as i64).max(1);
        let mut cells: Vec<([i64; 2], [i64; 2])> = cells
            .into_iter()
            .map(|c| ([c[1].div_euclid(side), c[0].div_euclid(side)], c))
            .collect();
        cells.sort_unstable();
        HotCells { cells, side }
    }

    /// The cells whose bucket row lies in `rows` (inclusive).
    fn rows(&self, rows: [i64; 2]) -> &[([i64; 2], [i64; 2])] {
        let from = self.cells.partition_point(|(k, _)| k[0] < rows[0]);
        let to = from + self.cells[from..].partition_point(|(k, _)| k[0] <= rows[1]);
        &self.cells[from..to]
    }

    /// Calls `f` with every cell of `band` whose bucket column lies in `columns`, `band`
    /// being the cells of bucket row `row` (or, `None`, of several rows, looked through
    /// cell by cell): by bucket where there are fewer buckets than cells, else by cell
    /// (so that a long edge over few cells costs no more than those cells).
    fn each_in(
        band: &[([i64; 2], [i64; 2])],
        row: Option<i64>,
        columns: [i64; 2],
        f: &mut impl FnMut([i64; 2]),
    ) {
        let span = columns[1].saturating_sub(columns[0]).saturating_add(1);
        match row {
            Some(row) if span > 0 && (span as u64) < band.len() as u64 => {
                for bx in columns[0]..=columns[1] {
                    let key = [row, bx];
                    let from = band.partition_point(|(k, _)| *k < key);
                    for &(k, c) in &band[from..] {
                        if k != key {
                            break;
                        }
                        f(c);
                    }
                }
            }
            _ => {
                for &(k, c) in band {
                    if k[1] >= columns[0] && k[1] <= columns[1] {
                        f(c);
                    }
                }
            }
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
        let side = self.side;
        let (by0, by1) = (cell_lo(y0).div_euclid(side), cell_hi(y1).div_euclid(side));
        let band = self.rows([by0, by1]);
        let mut test = |c: [i64; 2]| {
            if c != gp && c != gq && meets(p, q, c) {
                found.push(c);
            }
        };
        if by1.saturating_sub(by0) as u64 >= band.len() as u64 {
            // Fewer cells than bucket rows: every cell of the band, by its bounding box.
            let columns = [cell_lo(x0).div_euclid(side), cell_hi(x1).div_euclid(side)];
            HotCells::each_in(band, None, columns, &mut test);
        } else {
            for by in by0..=by1 {
                // The edge's cells in this band of buckets: its x-range over the band's
                // y-range, widened by a cell (the exact test decides).
                let band_lo = (by * side) as f64 - 0.5;
                let band_hi = ((by + 1) * side) as f64 + 0.5;
                let (lo, hi) = x_range(p, q, band_lo.max(y0), band_hi.min(y1));
                let (cx0, cx1) = (cell_lo(lo.max(x0)) - 1, cell_hi(hi.min(x1)) + 1);
                let row = self.rows([by, by]);
                let columns = [cx0.div_euclid(side), cx1.div_euclid(side)];
                HotCells::each_in(row, Some(by), columns, &mut test);
            }
        }
        sort_along(found, p, q);
    }
}

/// Sorts `cells` along the edge `p`–`q`: by `c · d`, `d = q − p` as rounded, so that the
/// edge taken the other way (`d` negated exactly) gets exactly the reverse order; ties
/// broken by the cells' order, reversed with the direction.
fn sort_along(cells: &mut [[i64; 2]], p: [f64; 2], q: [f64; 2]) {
    let d = [q[0] - p[0], q[1] - p[1]];
    let forward = (d[0], d[1]) > (0.0, 0.0);
    cells.sort_unstable_by(|a, b| {
        let ka = a[0] as f64 * d[0] + a[1] as f64 * d[1];
        let kb = b[0] as f64 * d[0] + b[1] as f64 * d[1];
        let tie = if forward { a.cmp(b) } else { b.cmp(a) };
        ka.total_cmp(&kb).then(tie)
    });
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

    /// Numbers drawn uniformly from [0, 1) by a xorshift generator started at `seed`.
    fn uniform(mut seed: u64) -> impl FnMut() -> f64 {
        move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        }
    }

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

    /// [`snap`] without the buckets: every hot cell tested against every edge.
    fn snap_everywhere(rings: &[Vec<[f64; 2]>]) -> Vec<GridRing> {
        let rounded = rounded(rings);
        let mut hot: Vec<[i64; 2]> = rounded.iter().flatten().copied().collect();
        hot.sort_unstable();
        hot.dedup();
        rings
            .iter()
            .zip(&rounded)
            .map(|(ring, grid)| {
                let mut out = Vec::new();
                for i in 0..ring.len() {
                    let j = (i + 1) % ring.len();
                    out.push(grid[i]);
                    if grid[i] == grid[j] {
                        continue;
                    }
                    let (p, q) = (ring[i], ring[j]);
                    let mut found: Vec<[i64; 2]> = hot
                        .iter()
                        .copied()
                        .filter(|&c| c != grid[i] && c != grid[j] && meets(p, q, c))
                        .collect();
                    sort_along(&mut found, p, q);
                    out.extend(found);
                }
                dedup(out)
            })
            .collect()
    }

    /// The buckets find every cell an edge meets: random triangles of very different
    /// sizes, crowded and spread, near-horizontal and near-vertical slivers among them,
    /// snapped with and without them.
    #[test]
    fn the_buckets_miss_no_cell() {
        let mut next = uniform(0x9e37_79b9_7f4a_7c15);
        for round in 0..40 {
            let mut rings = Vec::new();
            let n = 2 + round * 5;
            for k in 0..n {
                // Sizes from a tenth of a unit to ten thousand units.
                let size = 10f64.powf(-1.0 + 5.0 * next());
                let c = if k % 3 == 0 {
                    [next() * 20.0, next() * 20.0]
                } else {
                    [next() * 2e4, next() * 2e4]
                };
                let mut ring: Vec<[f64; 2]> = (0..3)
                    .map(|_| [c[0] + size * (next() - 0.5), c[1] + size * (next() - 0.5)])
                    .collect();
                if k % 5 == 0 {
                    // A sliver along an axis.
                    let axis = k % 2;
                    let v = ring[0][axis];
                    ring[1][axis] = v + 0.3 * next();
                }
                rings.push(ring);
            }
            assert_eq!(snap(&rings), snap_everywhere(&rings), "round {round}");
        }
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
        let mut next = uniform(0x2545_f491_4f6c_dd1d);
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
            // Half the strips have their cuts crowded near one end (tiny pieces beside a
            // long one: the lookups' buckets are sized by the median edge).
            let spread = if next() < 0.5 { 10.0 } else { 0.05 };
            let mut cuts = |n: usize| {
                let mut v: Vec<f64> = (0..n).map(|_| next() * spread).collect();
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
