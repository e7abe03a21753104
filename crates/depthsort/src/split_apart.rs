//! A large set split on every core: a few BSP levels on this thread, then the parts
//! (independent of each other once split apart) ordered on the pool by
//! [`order_apart`]. A dense soup is one set that BSP splits all the way down; without
//! this it was ordered on one core whatever the machine had.
//!
//! The levels split here and the parts they make depend on the set alone (and the
//! context's random source), never on the threads, so the order is the same on any
//! number of them.

use limn_kernel::Kernel;

use crate::detached::order_apart;
use crate::partition::split_set;
use crate::pieces::Ctx;

/// Sets of at least this many pieces are split into parts ordered apart; smaller parts
/// are ordered whole, on one core. Measured on random soups of 1,000 to 20,000 dense
/// triangles (BENCHMARKS.md): with 1,024 the soup of 1,000 was ordered on one core in
/// 10.9 ms, with 256 (and [`SHARE_OF_OUTERMOST`]) on both in 7.7 ms; end to end the
/// soup of 1,000 took 0.89× the time, 2,000 1.04×, 5,000 0.92×, the larger ones the same.
pub(crate) const APART_FROM: usize = 256;

/// Inside a set split apart, a part is split further (here, or apart again in the
/// context that orders it) only while it holds at least this share (1 / n) of the
/// outermost set split apart: a small dense soup is split into a few parts, one for each
/// core and some to balance them, while the parts of a large one are not cut into more
/// and smaller ones than the cores need (its soup of 5,000 took 61–67 ms instead of 57
/// when every part of 256 pieces or more was split apart again).
const SHARE_OF_OUTERMOST: usize = 4;

/// Whether a set of `pieces` ordered in `ctx` is split apart ([`split_apart`]).
pub(crate) fn splits_apart<K: Kernel>(ctx: &Ctx<'_, K>, pieces: usize) -> bool {
    ctx.may_split_apart() && pieces >= least_apart(ctx)
}

/// The fewest pieces of a set split apart, or of a part split further, in `ctx`.
fn least_apart<K: Kernel>(ctx: &Ctx<'_, K>) -> usize {
    APART_FROM.max(ctx.outermost_apart / SHARE_OF_OUTERMOST)
}

/// Levels split on this thread, at most, before the parts are ordered apart (up to
/// 2⁶ = 64 parts: enough for both halves of every split to be a part of its own on
/// small machines, and for the pool to balance parts of unequal sizes).
const LEVELS: usize = 6;

/// Work left in the splitting here, taken from a stack.
enum Pending<T> {
    /// A part, with what it inherits and its depth.
    Part(Vec<u32>, T, usize),
    /// The pieces in a splitter's plane.
    Plane(Vec<u32>),
}

/// One place in the order of a set split here.
enum Step {
    /// The pieces in a splitter's plane, painted between its far and near parts.
    Emit(Vec<u32>),
    /// The order of part k, ordered apart.
    Part(usize),
}

/// Orders `set` as BSP would, with its top levels split on this thread and the parts
/// below them ordered on the pool.
///
/// `split_here(ctx, part, with, depth)` says whether a part (`set` itself at depth 0),
/// with `with` as inherited from the set it was split from, is split here, and if so
/// what its parts inherit; it is asked only of parts above depth [`LEVELS`] large enough
/// to split further (see [`SHARE_OF_OUTERMOST`]). The parts it leaves whole are ordered
/// by `finish`, a group of them at a time in a context of their own (see
/// [`order_apart`]); `first` is what `set` starts with.
pub(crate) fn split_apart<'a, K: Kernel, T: Copy + Send>(
    ctx: &mut Ctx<'a, K>,
    set: Vec<u32>,
    first: T,
    candidates: usize,
    split_here: impl Fn(&Ctx<'a, K>, &[u32], T, usize) -> Option<T>,
    finish: impl Fn(&mut Ctx<'a, K>, Vec<(Vec<u32>, T)>) -> Vec<Vec<u32>> + Sync,
) -> Vec<u32> {
    let mut steps = Vec::new();
    let mut parts = Vec::new();
    let outer = ctx.outermost_apart;
    if outer == 0 {
        ctx.outermost_apart = set.len();
    }
    let least = least_apart(ctx);
    // Depth first, far side before plane before near side: the order of painting.
    let mut stack = vec![Pending::Part(set, first, 0)];
    while let Some(next) = stack.pop() {
        let (s, with, depth) = match next {
            Pending::Plane(cop) => {
                steps.push(Step::Emit(cop));
                continue;
            }
            Pending::Part(s, with, depth) => (s, with, depth),
        };
        if s.is_empty() {
            continue;
        }
        let split = if s.len() >= least && depth < LEVELS {
            split_here(ctx, &s, with, depth)
        } else {
            None
        };
        let Some(inherited) = split else {
            steps.push(Step::Part(parts.len()));
            parts.push((s, with));
            continue;
        };
        let (far, cop, near) = split_set(ctx, &s, candidates);
        stack.push(Pending::Part(near, inherited, depth + 1));
        stack.push(Pending::Plane(cop));
        stack.push(Pending::Part(far, inherited, depth + 1));
    }
    ctx.stats.parts_apart += parts.len();
    let orders = order_apart(ctx, parts, finish);
    ctx.outermost_apart = outer;
    let mut out = Vec::with_capacity(orders.iter().map(Vec::len).sum());
    for step in steps {
        match step {
            Step::Emit(cop) => out.extend(cop),
            Step::Part(k) => out.extend_from_slice(&orders[k]),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_scenes::soup;
    use limn_kernel::ExactKernel;

    /// Outside a split apart, sets from [`APART_FROM`] pieces are split apart; inside
    /// one, only parts holding a [`SHARE_OF_OUTERMOST`] of the outermost set.
    #[test]
    fn parts_are_split_apart_again_only_while_they_hold_a_share_of_the_outermost_set() {
        let k = ExactKernel::new();
        let scene = soup(10, 0.5, 1);
        let (mut ctx, _) = Ctx::framing(&k, &scene, 100, 100);
        assert!(!splits_apart(&ctx, APART_FROM - 1));
        assert!(splits_apart(&ctx, APART_FROM));
        let outermost = 40 * APART_FROM;
        ctx.outermost_apart = outermost;
        let share = outermost / SHARE_OF_OUTERMOST;
        assert!(!splits_apart(&ctx, share - 1));
        assert!(splits_apart(&ctx, share));
        // Contexts detached from it order parts of the same outermost set.
        let d = ctx.detached(Vec::new(), 1, ctx.split_counter());
        assert!(!splits_apart(&d, share - 1));
        assert!(splits_apart(&d, share));
    }
}
