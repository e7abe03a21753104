//! The adaptive ordering's probe of a large set: whether its occlusion graph is certain to
//! be one cycle nearly everywhere (measured on a sample of its members), so that
//! analysing the whole set would be wasted and it is split at once.

use std::ops::Range;
use std::sync::atomic::AtomicUsize;
use std::sync::atomic::Ordering::Relaxed;

use limn_kernel::Kernel;
use rayon::prelude::*;

use crate::geom::{convex_disjoint, Box2};
use crate::occlusion::Pair;
use crate::pieces::Ctx;

/// Sets larger than this are probed ([`cycles_everywhere`]) before being analysed.
pub(crate) const PROBE_MIN: usize = 256;
/// Members of a set probed by [`cycles_everywhere`] (a power of two, at most 64: one bit
/// each in a mask).
const PROBE_SAMPLE: usize = 64;
const _: () = assert!(PROBE_SAMPLE.is_power_of_two() && PROBE_SAMPLE <= u64::BITS as usize);

/// Pieces per parallel task of the probe.
const PROBE_CHUNK: usize = 1024;

/// Members of the probe of [`cycles_everywhere`] tested before the first look at the
/// count: a dense set answers on them alone; any other set is read once more, for the
/// rest of the sample together (once per eight members cost a soup of 10,000 pieces
/// 0.6 ms of its 2 ms probe).
const PROBE_FIRST: usize = 8;

/// Whether the occlusion graph of `set` is, as measured on a sample, certain to be one
/// cycle nearly everywhere, so that analysing the whole set would be wasted. Pieces that
/// pierce each other (a conflict: each must be painted before the other) form two-cycles;
/// when a piece is in conflict with one other piece or more on average, the conflicts
/// form a giant connected part, as in a random graph of that mean degree, and so does the
/// occlusion graph's largest component. The mean is measured on [`PROBE_SAMPLE`] evenly
/// spaced members against the whole set, spread over the set in bit-reversed order: the
/// first [`PROBE_FIRST`] of them, then the rest (the set read in parallel chunks, once for
/// each block); the count stops as soon as it reaches the answer, which is the same as
/// counting them all (the count only grows), on any number of threads.
pub(crate) fn cycles_everywhere<K: Kernel>(ctx: &Ctx<'_, K>, set: &[u32]) -> bool {
    let probe = Probe::new(ctx, set);
    let mut conflicts = 0;
    for block in [0..PROBE_FIRST, PROBE_FIRST..PROBE_SAMPLE] {
        conflicts += probe.conflicts(block, PROBE_SAMPLE - conflicts);
        if conflicts >= PROBE_SAMPLE {
            return true;
        }
    }
    false
}

/// The sample of [`cycles_everywhere`]: its members and every piece's screen box.
struct Probe<'c, 'a, K: Kernel> {
    ctx: &'c Ctx<'a, K>,
    set: &'c [u32],
    /// The members, as places in `set`.
    members: [usize; PROBE_SAMPLE],
    /// Every box of `set` (grown by the margin) once, side by side: the pieces are
    /// large, and reading their boxes twice from them cost more than this copy.
    boxes: Vec<Box2>,
    /// The members' boxes coordinate by coordinate: a piece's box is tested against a
    /// whole block of them in one loop without branches, and only the members it meets
    /// are looked at further.
    min_x: [f64; PROBE_SAMPLE],
    max_x: [f64; PROBE_SAMPLE],
    min_y: [f64; PROBE_SAMPLE],
    max_y: [f64; PROBE_SAMPLE],
}

impl<'c, 'a, K: Kernel> Probe<'c, 'a, K> {
    fn new(ctx: &'c Ctx<'a, K>, set: &'c [u32]) -> Self {
        let n = set.len();
        let m = ctx.margin;
        let spread = |j: usize| j.reverse_bits() >> (usize::BITS - PROBE_SAMPLE.trailing_zeros());
        let members: [usize; PROBE_SAMPLE] = std::array::from_fn(|t| spread(t) * n / PROBE_SAMPLE);
        let boxes: Vec<Box2> = set
            .par_iter()
            .with_min_len(PROBE_CHUNK)
            .map(|&p| ctx.pieces[p as usize].bbox.grown(m))
            .collect();
        let grown = members.map(|a| boxes[a]);
        Probe {
            ctx,
            set,
            members,
            min_x: grown.map(|b| b.min_x),
            max_x: grown.map(|b| b.max_x),
            min_y: grown.map(|b| b.min_y),
            max_y: grown.map(|b| b.max_y),
            boxes,
        }
    }

    /// The conflicts of the members `block` with every piece of the set (the set read
    /// once for the block, each piece against the block's members, rather than once per
    /// member), counted until they reach `need`: pieces met after that are skipped.
    /// The count only grows, so whether the result reaches `need` is the same as when
    /// every piece is counted, on any number of threads (the result itself is not).
    fn conflicts(&self, block: Range<usize>, need: usize) -> usize {
        let (set, ctx, m) = (self.set, self.ctx, self.ctx.margin);
        let counted = AtomicUsize::new(0);
        (0..set.len())
            .into_par_iter()
            .with_min_len(PROBE_CHUNK)
            .for_each(|b| {
                if counted.load(Relaxed) >= need {
                    return;
                }
                let (q, bq) = (set[b], &self.boxes[b]);
                let mut met = 0u64;
                for t in block.clone() {
                    let meets = (self.min_x[t] <= bq.max_x)
                        & (bq.min_x <= self.max_x[t])
                        & (self.min_y[t] <= bq.max_y)
                        & (bq.min_y <= self.max_y[t]);
                    met |= u64::from(meets) << t;
                }
                let mut count = 0;
                while met != 0 {
                    let t = met.trailing_zeros() as usize;
                    met &= met - 1;
                    let (a, p) = (self.members[t], set[self.members[t]]);
                    if a != b
                        && !convex_disjoint(
                            &ctx.pieces[p as usize].pts,
                            &ctx.pieces[q as usize].pts,
                            m,
                        )
                        && ctx.pair(p, q) == Pair::Conflict
                    {
                        count += 1;
                    }
                }
                if count > 0 {
                    counted.fetch_add(count, Relaxed);
                }
            });
        counted.into_inner()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::options::CullMode;
    use crate::test_scenes::soup;
    use limn_kernel::ExactKernel;

    /// Counting stops early only where that cannot change the answer: for every bound,
    /// whether the count reaches it is what counting every piece says, on one thread and
    /// on several; and the probe tells the densest soup from the sparse one.
    #[test]
    fn counts_stopped_early_give_the_answer_of_whole_counts() {
        let k = ExactKernel::new();
        let mut answers = Vec::new();
        for (n, size) in [(400, 0.05), (500, 0.3), (700, 0.6)] {
            let scene = soup(n, size, 11);
            let (mut ctx, near) = Ctx::framing(&k, &scene, 400, 300);
            let set = crate::prepare::prepare(&mut ctx, &scene, CullMode::Off, near)
                .expect("a valid scene")
                .items;
            let probe = Probe::new(&ctx, &set);
            for block in [0..PROBE_FIRST, PROBE_FIRST..PROBE_SAMPLE] {
                let all = probe.conflicts(block.clone(), usize::MAX);
                for need in [1, 2, PROBE_FIRST, PROBE_SAMPLE, all, all + 1] {
                    for threads in [1, 2] {
                        let pool = rayon::ThreadPoolBuilder::new()
                            .num_threads(threads)
                            .build()
                            .expect("a pool");
                        let got = pool.install(|| probe.conflicts(block.clone(), need));
                        assert_eq!(got >= need, all >= need, "{n} × {size}: need {need}");
                        assert!(got <= all);
                    }
                }
            }
            answers.push(cycles_everywhere(&ctx, &set));
        }
        assert_eq!(
            (answers[0], answers[2]),
            (false, true),
            "the sparse soup is analysed, the densest split at once"
        );
    }
}
