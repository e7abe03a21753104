//! The broad phase's sweep for crowded sets: the boxes' extent in y is cut into stripes
//! about as high as the mean box, and within each stripe the boxes covering it are swept
//! along x. A pair is reported in the one stripe holding the lower edge of its overlap,
//! so every meeting pair comes out once. A sweep over the whole set looks at every pair
//! overlapping in x (on a dense soup about fifteen times the pairs that meet); in stripes
//! it looks at the pairs overlapping in x within a stripe, about twice those that meet,
//! and the stripes can be swept in parallel.

use crate::geom::Box2;

/// Stripes at most (more would list tall boxes in too many of them).
const MAX_STRIPES: usize = 256;

/// Boxes per stripe at least, on average, below which fewer stripes are cut.
const MIN_PER_STRIPE: usize = 32;

/// A set of boxes cut into horizontal stripes, each listing the boxes that cover it in
/// order of their left sides (ties by index).
pub(crate) struct Stripes {
    y0: f64,
    h: f64,
    lists: Vec<Vec<u32>>,
    /// Per box, the stripe of its bottom side.
    bottom: Vec<u32>,
}

impl Stripes {
    /// The stripes of `boxes`: as many as the extent holds boxes of the mean height, at
    /// most [`MAX_STRIPES`] and about one per [`MIN_PER_STRIPE`] boxes.
    pub(crate) fn of(boxes: &[Box2]) -> Stripes {
        let n = boxes.len();
        let mut u = Box2::EMPTY;
        let mut sh = 0.0;
        for b in boxes {
            u = u.union(b);
            sh += b.height();
        }
        let mean = (sh / n.max(1) as f64).max(1e-300);
        let tall = u.height().max(1e-300);
        let count = ((tall / mean).ceil() as usize)
            .min(MAX_STRIPES)
            .min(n / MIN_PER_STRIPE)
            .max(1);
        let mut s = Stripes {
            y0: u.min_y,
            h: tall / count as f64,
            lists: vec![Vec::new(); count],
            bottom: Vec::new(),
        };
        let mut by_x: Vec<u32> = (0..n as u32).collect();
        by_x.sort_unstable_by(|&a, &b| {
            boxes[a as usize]
                .min_x
                .total_cmp(&boxes[b as usize].min_x)
                .then(a.cmp(&b))
        });
        for i in by_x {
            let b = &boxes[i as usize];
            for k in s.stripe(b.min_y)..=s.stripe(b.max_y) {
                s.lists[k].push(i);
            }
        }
        s.bottom = boxes.iter().map(|b| s.stripe(b.min_y) as u32).collect();
        s
    }

    /// How many stripes there are.
    pub(crate) fn len(&self) -> usize {
        self.lists.len()
    }

    /// The stripe holding height `y` (clamped; monotone in `y`, so a box covers the
    /// stripes from that of its bottom to that of its top).
    fn stripe(&self, y: f64) -> usize {
        (((y - self.y0) / self.h) as isize).clamp(0, self.lists.len() as isize - 1) as usize
    }

    /// Calls `f(i, j)` (i < j) for every pair of `boxes` that meet with the lower edge of
    /// their overlap in stripe `k`: the higher of their bottoms' stripes, as
    /// [`Stripes::stripe`] is monotone (one look-up per pair instead of a division).
    pub(crate) fn pairs_in(&self, boxes: &[Box2], k: usize, mut f: impl FnMut(usize, usize)) {
        sweep(boxes, &self.lists[k], |i, j| {
            if self.bottom[i].max(self.bottom[j]) as usize == k {
                f(i, j);
            }
        });
    }
}

/// Calls `f(i, j)` (i < j, each pair once) for every pair of the boxes `by_x` lists (in
/// order of their left sides) that meet: each box against the earlier ones whose right
/// side it has not passed. The active boxes are kept side by side (index, right side, y
/// extent) in the order they became active; one pass drops those that ended and tests
/// the rest in y (the only test left: an active box began no later and ends no earlier),
/// writing the boxes met without a branch on the outcome (random outcomes mispredict).
fn sweep(boxes: &[Box2], by_x: &[u32], mut f: impl FnMut(usize, usize)) {
    let mut index: Vec<u32> = Vec::new();
    let mut right: Vec<f64> = Vec::new();
    let mut span_y: Vec<[f64; 2]> = Vec::new();
    let mut met: Vec<u32> = Vec::new();
    for &i in by_x {
        let bi = &boxes[i as usize];
        let (mut kept, mut hits) = (0, 0);
        met.resize(index.len(), 0);
        for k in 0..index.len() {
            if right[k] < bi.min_x {
                continue;
            }
            let (j, [y0, y1]) = (index[k], span_y[k]);
            index[kept] = j;
            right[kept] = right[k];
            span_y[kept] = [y0, y1];
            kept += 1;
            met[hits] = j;
            hits += usize::from((y0 <= bi.max_y) & (bi.min_y <= y1));
        }
        for &j in &met[..hits] {
            f(i.min(j) as usize, i.max(j) as usize);
        }
        index.truncate(kept);
        right.truncate(kept);
        span_y.truncate(kept);
        index.push(i);
        right.push(bi.max_x);
        span_y.push([bi.min_y, bi.max_y]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::boxes_meet;

    fn boxes(n: usize, w: f64, h: f64, seed: u64) -> Vec<Box2> {
        let mut r = crate::rng::SplitMix::new(seed);
        let mut u = || (r.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        (0..n)
            .map(|_| {
                let (x, y) = (u() * 100.0, u() * 100.0);
                Box2 {
                    min_x: x,
                    min_y: y,
                    max_x: x + u() * w,
                    max_y: y + u() * h,
                }
            })
            .collect()
    }

    /// Every meeting pair once, in stripes: small, tall, wide and mixed boxes, boxes
    /// touching at an edge (the overlap's lower edge on a stripe's border), and a set of
    /// one height (a single stripe).
    #[test]
    fn stripes_report_every_meeting_pair_once() {
        let mut sets = vec![
            boxes(2000, 4.0, 4.0, 1),
            boxes(2000, 2.0, 60.0, 2),
            boxes(2000, 60.0, 2.0, 3),
            [boxes(1500, 3.0, 3.0, 4), boxes(100, 50.0, 90.0, 5)].concat(),
        ];
        let grid: Vec<Box2> = (0..40 * 40)
            .map(|k| {
                let (x, y) = ((k % 40) as f64 * 2.5, (k / 40) as f64 * 2.5);
                Box2 {
                    min_x: x,
                    min_y: y,
                    max_x: x + 2.5,
                    max_y: y + 2.5,
                }
            })
            .collect();
        sets.push(grid);
        for (n, b) in sets.iter().enumerate() {
            let mut all = Vec::new();
            for i in 0..b.len() {
                for j in i + 1..b.len() {
                    if boxes_meet(&b[i], &b[j], 0.0) {
                        all.push((i, j));
                    }
                }
            }
            let st = Stripes::of(b);
            assert!(st.len() > 1, "set {n}: {} stripes", st.len());
            let mut got = Vec::new();
            for k in 0..st.len() {
                st.pairs_in(b, k, |i, j| got.push((i, j)));
            }
            assert!(got.iter().all(|&(i, j)| i < j), "set {n}");
            got.sort_unstable();
            assert_eq!(got, all, "set {n}");
        }
    }
}
