//! The broad phase: which pieces' screen boxes meet. A uniform grid over the set's extent
//! where boxes are small against it (meshes, sparse soups); a sweep along x where large
//! overlapping boxes would crowd the grid's cells (dense soups). Both report every meeting
//! pair once, in an order that depends only on the boxes.

use limn_kernel::Kernel;

use crate::geom::{boxes_meet, Box2};
use crate::pieces::Ctx;

/// Calls `f(i, j)` (indices into `set`, i ≠ j, each unordered pair once) for every pair
/// whose screen boxes (grown by the prefilter margin) meet.
pub(crate) fn box_pairs<K: Kernel>(ctx: &Ctx<'_, K>, set: &[u32], f: impl FnMut(usize, usize)) {
    if set.len() < 2 {
        return;
    }
    let m = ctx.margin;
    let boxes: Vec<Box2> = set
        .iter()
        .map(|&p| ctx.pieces[p as usize].bbox.grown(m))
        .collect();
    grid_pairs(&boxes, f);
}

/// Pieces whose box covers more grid cells than this are tested against everything.
const MAX_CELLS_PER_ITEM: usize = 64;

/// What looking at a pair in a grid cell costs (a box test and the cell of the overlap's
/// corner, two divisions) against what a pair passed over by the sweep costs (one
/// comparison of x extents, then a box test).
const CELL_PAIR_COST: usize = 4;

/// Pairs looked at in grid cells per box below which the grid is used without comparing
/// it with the sweep (counting the sweep's pairs costs a sort).
const CROWDED: usize = 32;

/// Calls `f(i, j)` (i ≠ j, each unordered pair once) for every pair of `boxes` that
/// meet, using a uniform grid over their extent.
fn grid_pairs(boxes: &[Box2], mut f: impl FnMut(usize, usize)) {
    let n = boxes.len();
    if n <= 24 {
        for i in 0..n {
            for j in i + 1..n {
                if boxes_meet(&boxes[i], &boxes[j], 0.0) {
                    f(i, j);
                }
            }
        }
        return;
    }
    let mut u = Box2::EMPTY;
    let (mut sw, mut sh) = (0.0, 0.0);
    for b in boxes {
        u = u.union(b);
        sw += b.width();
        sh += b.height();
    }
    let (uw, uh) = (u.width().max(1e-300), u.height().max(1e-300));
    // Cells about the size of an average box, at most ~2n cells in all.
    let avg = ((sw / n as f64) * (sh / n as f64)).sqrt().max(1e-300);
    let mut gx = ((uw / avg).ceil() as usize).clamp(1, 4096);
    let mut gy = ((uh / avg).ceil() as usize).clamp(1, 4096);
    while gx * gy > 2 * n + 16 {
        gx = (gx / 2).max(1);
        gy = (gy / 2).max(1);
    }
    let (cw, ch) = (uw / gx as f64, uh / gy as f64);
    let cell_x = |x: f64| (((x - u.min_x) / cw) as isize).clamp(0, gx as isize - 1) as usize;
    let cell_y = |y: f64| (((y - u.min_y) / ch) as isize).clamp(0, gy as isize - 1) as usize;
    let mut big = Vec::new();
    let mut counts = vec![0u32; gx * gy + 1];
    let mut ranges = Vec::with_capacity(n);
    for (i, b) in boxes.iter().enumerate() {
        let (x0, x1, y0, y1) = (
            cell_x(b.min_x),
            cell_x(b.max_x),
            cell_y(b.min_y),
            cell_y(b.max_y),
        );
        if (x1 - x0 + 1) * (y1 - y0 + 1) > MAX_CELLS_PER_ITEM {
            big.push(i);
            ranges.push(None);
            continue;
        }
        ranges.push(Some((x0, x1, y0, y1)));
        for y in y0..=y1 {
            for x in x0..=x1 {
                counts[y * gx + x + 1] += 1;
            }
        }
    }
    // Large boxes crowd many cells, and a pair is looked at in every cell both cover:
    // when that costs more than sweeping along x, sweep instead (a pair in a cell costs
    // about [`CELL_PAIR_COST`] times a pair the sweep passes over).
    let cell_work: usize = counts
        .iter()
        .map(|&c| (c as usize) * (c as usize) / 2)
        .sum::<usize>()
        + big.len() * n;
    if cell_work > CROWDED * n && cell_work * CELL_PAIR_COST > x_overlaps(boxes) + n {
        return sweep_pairs(boxes, f);
    }
    for c in 1..counts.len() {
        counts[c] += counts[c - 1];
    }
    let mut fill = counts.clone();
    let mut cells = vec![0u32; counts[gx * gy] as usize];
    for (i, r) in ranges.iter().enumerate() {
        if let Some((x0, x1, y0, y1)) = *r {
            for y in y0..=y1 {
                for x in x0..=x1 {
                    let c = y * gx + x;
                    cells[fill[c] as usize] = i as u32;
                    fill[c] += 1;
                }
            }
        }
    }
    for c in 0..gx * gy {
        let list = &cells[counts[c] as usize..counts[c + 1] as usize];
        let (cx, cy) = (c % gx, c / gx);
        for (a, &i) in list.iter().enumerate() {
            for &j in &list[a + 1..] {
                let (bi, bj) = (&boxes[i as usize], &boxes[j as usize]);
                if !boxes_meet(bi, bj, 0.0) {
                    continue;
                }
                // Report the pair only in the cell holding the corner of the overlap.
                if cell_x(bi.min_x.max(bj.min_x)) == cx && cell_y(bi.min_y.max(bj.min_y)) == cy {
                    f(i as usize, j as usize);
                }
            }
        }
    }
    let mut is_big = vec![false; n];
    for &i in &big {
        is_big[i] = true;
    }
    for &i in &big {
        for j in 0..n {
            if j != i && (!is_big[j] || j > i) && boxes_meet(&boxes[i], &boxes[j], 0.0) {
                f(i, j);
            }
        }
    }
}

/// An estimate of how many pairs of `set`'s screen boxes meet, without finding them:
/// the pairs overlapping in x times the fraction overlapping in y (exact when the two
/// are independent), in O(n log n).
pub(crate) fn estimated_box_pairs<K: Kernel>(ctx: &Ctx<'_, K>, set: &[u32]) -> usize {
    let n = set.len();
    if n < 2 {
        return 0;
    }
    let m = ctx.margin;
    let boxes: Vec<Box2> = set
        .iter()
        .map(|&p| ctx.pieces[p as usize].bbox.grown(m))
        .collect();
    let turned: Vec<Box2> = boxes
        .iter()
        .map(|b| Box2 {
            min_x: b.min_y,
            min_y: b.min_x,
            max_x: b.max_y,
            max_y: b.max_x,
        })
        .collect();
    let all = (n * (n - 1) / 2) as f64;
    (x_overlaps(&boxes) as f64 * (x_overlaps(&turned) as f64 / all)) as usize
}

/// How many pairs of `boxes` overlap in x (what [`sweep_pairs`] looks at): all pairs
/// less those where one box ends before the other begins.
fn x_overlaps(boxes: &[Box2]) -> usize {
    let n = boxes.len();
    let mut starts: Vec<f64> = boxes.iter().map(|b| b.min_x).collect();
    starts.sort_unstable_by(f64::total_cmp);
    let apart: usize = boxes
        .iter()
        .map(|b| n - starts.partition_point(|&s| s <= b.max_x))
        .sum();
    (n * (n - 1) / 2).saturating_sub(apart)
}

/// Calls `f(i, j)` (i < j, each pair once) for every pair of `boxes` that meet: boxes in
/// order of their left sides, each against the earlier ones whose right side it has not
/// passed.
fn sweep_pairs(boxes: &[Box2], mut f: impl FnMut(usize, usize)) {
    let mut by_x: Vec<u32> = (0..boxes.len() as u32).collect();
    by_x.sort_unstable_by(|&a, &b| {
        boxes[a as usize]
            .min_x
            .total_cmp(&boxes[b as usize].min_x)
            .then(a.cmp(&b))
    });
    let mut active: Vec<u32> = Vec::new();
    for &i in &by_x {
        let bi = &boxes[i as usize];
        active.retain(|&j| boxes[j as usize].max_x >= bi.min_x);
        for &j in &active {
            if boxes_meet(bi, &boxes[j as usize], 0.0) {
                f(i.min(j) as usize, i.max(j) as usize);
            }
        }
        active.push(i);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pairs(boxes: &[Box2], sweep: bool) -> Vec<(usize, usize)> {
        let mut v = Vec::new();
        let push = |i: usize, j: usize| v.push((i.min(j), i.max(j)));
        if sweep {
            sweep_pairs(boxes, push);
        } else {
            grid_pairs(boxes, push);
        }
        v.sort_unstable();
        v
    }

    fn random_boxes(n: usize, size: f64, seed: u64) -> Vec<Box2> {
        let mut r = crate::rng::SplitMix::new(seed);
        let mut u = || (r.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        (0..n)
            .map(|_| {
                let (x, y) = (u() * 100.0, u() * 100.0);
                let (w, h) = (u() * size, u() * size);
                Box2 {
                    min_x: x,
                    min_y: y,
                    max_x: x + w,
                    max_y: y + h,
                }
            })
            .collect()
    }

    #[test]
    fn grid_and_sweep_find_the_same_pairs_as_all_against_all() {
        for (n, size, seed) in [
            (30, 5.0, 1),
            (400, 3.0, 2),
            (400, 60.0, 3),
            (1000, 100.0, 4),
        ] {
            let b = random_boxes(n, size, seed);
            let mut all = Vec::new();
            for i in 0..n {
                for j in i + 1..n {
                    if boxes_meet(&b[i], &b[j], 0.0) {
                        all.push((i, j));
                    }
                }
            }
            assert_eq!(pairs(&b, false), all, "grid, n {n} size {size}");
            assert_eq!(pairs(&b, true), all, "sweep, n {n} size {size}");
        }
    }

    #[test]
    fn x_overlaps_counts_pairs_overlapping_in_x() {
        let b = random_boxes(300, 20.0, 5);
        let mut want = 0;
        for i in 0..b.len() {
            for j in i + 1..b.len() {
                want += (b[i].min_x <= b[j].max_x && b[j].min_x <= b[i].max_x) as usize;
            }
        }
        assert_eq!(x_overlaps(&b), want);
    }
}
