//! The broad phase: which pieces' screen boxes meet. A uniform grid over the set's extent
//! where boxes are small against it (meshes, sparse soups); a sweep along x in stripes
//! ([`Stripes`]) where large overlapping boxes would crowd the grid's cells (dense soups). Both report every meeting
//! pair once, in an order that depends only on the boxes.
//!
//! A pair is handed to the caller's test as soon as it is found (while both boxes are
//! still in cache). Large sets are visited in parallel, a block of grid cells (or a
//! stripe) per task, and the tests' results are put together block by block in the order
//! of one thread's visit, so they do not depend on the number of threads.

use std::ops::Range;

use limn_kernel::Kernel;
use rayon::prelude::*;

use crate::geom::{boxes_meet, Box2};
use crate::pieces::Ctx;
use crate::sweep::Stripes;

/// What the tests of pairs found: the results they kept, and how many pairs they
/// counted (a test may count a pair whose result it does not keep: most pairs of a mesh
/// are free, and 12 bytes each of them were 38 MB of a million-face ordering).
pub(crate) struct Found<T> {
    /// The results kept, in the order of a visit on one thread.
    pub kept: Vec<T>,
    /// The pairs counted.
    pub counted: usize,
}

impl<T> Default for Found<T> {
    fn default() -> Self {
        Found {
            kept: Vec::new(),
            counted: 0,
        }
    }
}

impl<T> Found<T> {
    /// Empties it, keeping its memory.
    pub fn clear(&mut self) {
        self.kept.clear();
        self.counted = 0;
    }
}

/// Calls `visit(i, j, out)` (indices into `set`, i ≠ j, each unordered pair once) for
/// every pair whose screen boxes (grown by the prefilter margin) meet, and returns what
/// the calls put into `out`, in the order of a visit on one thread whatever the number
/// of threads.
pub(crate) fn box_pairs<K: Kernel, T: Send>(
    ctx: &Ctx<'_, K>,
    set: &[u32],
    visit: impl Fn(usize, usize, &mut Found<T>) + Sync,
) -> Found<T> {
    if set.len() < 2 {
        return Found::default();
    }
    let m = ctx.margin;
    let boxes: Vec<Box2> = set
        .iter()
        .map(|&p| ctx.pieces[p as usize].bbox.grown(m))
        .collect();
    let threads = rayon::current_num_threads() > 1;
    let mut out = Found::default();
    match Plan::of(&boxes) {
        Plan::AllPairs => all_pairs(&boxes, |i, j| visit(i, j, &mut out)),
        Plan::Grid(g) if threads && g.work >= PARALLEL_WORK => {
            let blocks = blocks(g.cells(), CELLS_PER_TASK);
            let parts: Vec<Found<T>> = blocks
                .into_par_iter()
                .map(|r| {
                    let mut part = Found::default();
                    for c in r {
                        g.cell_pairs(&boxes, c, |i, j| visit(i, j, &mut part));
                    }
                    part
                })
                .collect();
            let bigs: Vec<Found<T>> = (0..g.big.len())
                .into_par_iter()
                .map(|k| {
                    let mut part = Found::default();
                    g.big_pairs(&boxes, k, |i, j| visit(i, j, &mut part));
                    part
                })
                .collect();
            out = joined(parts.into_iter().chain(bigs).collect());
        }
        Plan::Grid(g) => {
            for c in 0..g.cells() {
                g.cell_pairs(&boxes, c, |i, j| visit(i, j, &mut out));
            }
            for k in 0..g.big.len() {
                g.big_pairs(&boxes, k, |i, j| visit(i, j, &mut out));
            }
        }
        Plan::Sweep { work } if threads && work >= PARALLEL_WORK => {
            let stripes = Stripes::of(&boxes);
            let parts: Vec<Found<T>> = (0..stripes.len())
                .into_par_iter()
                .map(|k| {
                    let mut part = Found::default();
                    stripes.pairs_in(&boxes, k, |i, j| visit(i, j, &mut part));
                    part
                })
                .collect();
            out = joined(parts);
        }
        Plan::Sweep { .. } => {
            let stripes = Stripes::of(&boxes);
            for k in 0..stripes.len() {
                stripes.pairs_in(&boxes, k, |i, j| visit(i, j, &mut out));
            }
        }
    }
    out
}

/// The parts one after another, in one vector allocated once (collecting a flattened
/// iterator grows it by doubling, touching twice its memory).
fn joined<T>(parts: Vec<Found<T>>) -> Found<T> {
    let mut out = Found {
        kept: Vec::with_capacity(parts.iter().map(|p| p.kept.len()).sum()),
        counted: 0,
    };
    for mut p in parts {
        out.kept.append(&mut p.kept);
        out.counted += p.counted;
    }
    out
}

/// Pairs of boxes looked at below which a set is visited on the calling thread (handing
/// out tasks costs more than it saves).
const PARALLEL_WORK: usize = 2048;

/// Grid cells per parallel task, at least.
const CELLS_PER_TASK: usize = 32;

/// `0..n` in consecutive blocks of about `per` (at most 256 blocks).
fn blocks(n: usize, per: usize) -> Vec<Range<usize>> {
    let per = per.max(n.div_ceil(256)).max(1);
    (0..n).step_by(per).map(|s| s..(s + per).min(n)).collect()
}

/// Sets of at most this many boxes are visited all against all.
const ALL_PAIRS_MAX: usize = 24;

/// Calls `f(i, j)` (i < j) for every pair of `boxes` that meet, all against all.
fn all_pairs(boxes: &[Box2], mut f: impl FnMut(usize, usize)) {
    let n = boxes.len();
    for i in 0..n {
        for j in i + 1..n {
            if boxes_meet(&boxes[i], &boxes[j], 0.0) {
                f(i, j);
            }
        }
    }
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

/// How the pairs of one set of boxes are found.
enum Plan {
    /// Few boxes: all against all.
    AllPairs,
    /// A uniform grid.
    Grid(Grid),
    /// A sweep along x, looking at `work` pairs.
    Sweep { work: usize },
}

/// A uniform grid over a set of boxes: each small box listed in every cell it covers,
/// the large ones apart.
struct Grid {
    /// The extent of all boxes.
    u: Box2,
    gx: usize,
    gy: usize,
    /// Cell width and height.
    cw: f64,
    ch: f64,
    /// `cells[start[c]..start[c + 1]]` lists the boxes in cell `c`.
    start: Vec<u32>,
    cells: Vec<u32>,
    /// Boxes covering too many cells, tested against every box.
    big: Vec<usize>,
    is_big: Vec<bool>,
    /// Pairs looked at in cells, and by the large boxes.
    work: usize,
}

impl Plan {
    /// The cheaper way to find the pairs of `boxes` that meet.
    fn of(boxes: &[Box2]) -> Plan {
        let n = boxes.len();
        if n <= ALL_PAIRS_MAX {
            return Plan::AllPairs;
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
        let mut g = Grid {
            u,
            gx,
            gy,
            cw: uw / gx as f64,
            ch: uh / gy as f64,
            start: vec![0u32; gx * gy + 1],
            cells: Vec::new(),
            big: Vec::new(),
            is_big: vec![false; n],
            work: 0,
        };
        let mut ranges = Vec::with_capacity(n);
        for (i, b) in boxes.iter().enumerate() {
            let (x0, x1, y0, y1) = (
                g.cell_x(b.min_x),
                g.cell_x(b.max_x),
                g.cell_y(b.min_y),
                g.cell_y(b.max_y),
            );
            if (x1 - x0 + 1) * (y1 - y0 + 1) > MAX_CELLS_PER_ITEM {
                g.big.push(i);
                g.is_big[i] = true;
                ranges.push(None);
                continue;
            }
            ranges.push(Some((x0, x1, y0, y1)));
            for y in y0..=y1 {
                for x in x0..=x1 {
                    g.start[y * gx + x + 1] += 1;
                }
            }
        }
        // Large boxes crowd many cells, and a pair is looked at in every cell both cover:
        // when that costs more than sweeping along x, sweep instead (a pair in a cell costs
        // about [`CELL_PAIR_COST`] times a pair the sweep passes over).
        g.work = g
            .start
            .iter()
            .map(|&c| (c as usize) * (c as usize) / 2)
            .sum::<usize>()
            + g.big.len() * n;
        if g.work > CROWDED * n {
            let swept = x_overlaps(boxes);
            if g.work * CELL_PAIR_COST > swept + n {
                return Plan::Sweep { work: swept };
            }
        }
        for c in 1..g.start.len() {
            g.start[c] += g.start[c - 1];
        }
        let mut fill = g.start.clone();
        g.cells = vec![0u32; g.start[gx * gy] as usize];
        for (i, r) in ranges.iter().enumerate() {
            if let Some((x0, x1, y0, y1)) = *r {
                for y in y0..=y1 {
                    for x in x0..=x1 {
                        let c = y * gx + x;
                        g.cells[fill[c] as usize] = i as u32;
                        fill[c] += 1;
                    }
                }
            }
        }
        Plan::Grid(g)
    }
}

impl Grid {
    /// The column of x (clamped to the grid).
    fn cell_x(&self, x: f64) -> usize {
        (((x - self.u.min_x) / self.cw) as isize).clamp(0, self.gx as isize - 1) as usize
    }

    /// The row of y (clamped to the grid).
    fn cell_y(&self, y: f64) -> usize {
        (((y - self.u.min_y) / self.ch) as isize).clamp(0, self.gy as isize - 1) as usize
    }

    /// How many cells the grid has.
    fn cells(&self) -> usize {
        self.gx * self.gy
    }

    /// Calls `f(i, j)` for the pairs of small boxes that meet with the corner of their
    /// overlap in cell `c` (so each such pair in exactly one cell).
    fn cell_pairs(&self, boxes: &[Box2], c: usize, mut f: impl FnMut(usize, usize)) {
        let list = &self.cells[self.start[c] as usize..self.start[c + 1] as usize];
        let (cx, cy) = (c % self.gx, c / self.gx);
        for (a, &i) in list.iter().enumerate() {
            for &j in &list[a + 1..] {
                let (bi, bj) = (&boxes[i as usize], &boxes[j as usize]);
                if !boxes_meet(bi, bj, 0.0) {
                    continue;
                }
                // Report the pair only in the cell holding the corner of the overlap.
                if self.cell_x(bi.min_x.max(bj.min_x)) == cx
                    && self.cell_y(bi.min_y.max(bj.min_y)) == cy
                {
                    f(i as usize, j as usize);
                }
            }
        }
    }

    /// Calls `f(i, j)` for the pairs of the `k`-th large box `i` with every box it meets
    /// (a pair of large boxes once, from the earlier one).
    fn big_pairs(&self, boxes: &[Box2], k: usize, mut f: impl FnMut(usize, usize)) {
        let i = self.big[k];
        for j in 0..boxes.len() {
            if j != i && (!self.is_big[j] || j > i) && boxes_meet(&boxes[i], &boxes[j], 0.0) {
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

/// How many pairs of `boxes` overlap in x (what a sweep over the whole set looks at, an
/// upper bound on what [`Stripes`] look at): all pairs
/// less those where one box ends before the other begins. Counted in parallel (a count:
/// the same on any number of threads).
fn x_overlaps(boxes: &[Box2]) -> usize {
    let n = boxes.len();
    let mut starts: Vec<f64> = boxes.iter().map(|b| b.min_x).collect();
    starts.par_sort_unstable_by(f64::total_cmp);
    let apart: usize = boxes
        .par_iter()
        .with_min_len(4096)
        .map(|b| n - starts.partition_point(|&s| s <= b.max_x))
        .sum();
    (n * (n - 1) / 2).saturating_sub(apart)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pairs(boxes: &[Box2], sweep: bool) -> Vec<(usize, usize)> {
        let mut v = Vec::new();
        let mut push = |i: usize, j: usize| v.push((i.min(j), i.max(j)));
        if sweep {
            let st = Stripes::of(boxes);
            for k in 0..st.len() {
                st.pairs_in(boxes, k, &mut push);
            }
        } else {
            planned_pairs(boxes, push);
        }
        v.sort_unstable();
        v
    }

    /// The pairs as [`box_pairs`] visits them on one thread.
    fn planned_pairs(boxes: &[Box2], mut f: impl FnMut(usize, usize)) {
        match Plan::of(boxes) {
            Plan::AllPairs => all_pairs(boxes, f),
            Plan::Grid(g) => {
                for c in 0..g.cells() {
                    g.cell_pairs(boxes, c, &mut f);
                }
                for k in 0..g.big.len() {
                    g.big_pairs(boxes, k, &mut f);
                }
            }
            Plan::Sweep { .. } => {
                let st = Stripes::of(boxes);
                for k in 0..st.len() {
                    st.pairs_in(boxes, k, &mut f);
                }
            }
        }
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
