//! A large set split on every core: a few BSP levels on this thread, then the parts
//! (independent of each other once split apart) ordered on the pool by
//! [`order_apart`]. A dense soup is one set that BSP splits all the way down; without
//! this it was ordered on one core whatever the machine had.
//!
//! The levels split here and the parts they make depend on the set alone (and the
//! context's random source), never on the threads, so the order is the same on any
//! number of them.

use limn_kernel::Kernel;

use crate::bsp::{choose_splitter, partition};
use crate::detached::order_apart;
use crate::pieces::Ctx;

/// Sets of at least this many pieces are split into parts ordered apart; smaller parts
/// are ordered whole, on one core. Measured on random soups of 1,000 to 20,000 dense
/// triangles (BENCHMARKS.md): 1,024 orders the soup of 2,000 in 42 ms where 2,048 (which
/// leaves it on one core) took 52; the larger soups are the same either way.
pub(crate) const APART_FROM: usize = 1024;

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
/// what its parts inherit; it is asked only of parts of at least [`APART_FROM`] pieces
/// above depth [`LEVELS`]. The parts it leaves whole are ordered by `finish`, a group of
/// them at a time in a context of their own (see [`order_apart`]); `first` is what `set`
/// starts with.
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
        let split = if s.len() >= APART_FROM && depth < LEVELS {
            split_here(ctx, &s, with, depth)
        } else {
            None
        };
        let Some(inherited) = split else {
            steps.push(Step::Part(parts.len()));
            parts.push((s, with));
            continue;
        };
        let sp = choose_splitter(ctx, &s, candidates);
        let (far, cop, near) = partition(ctx, &s, sp);
        stack.push(Pending::Part(near, inherited, depth + 1));
        stack.push(Pending::Plane(cop));
        stack.push(Pending::Part(far, inherited, depth + 1));
    }
    ctx.stats.parts_apart += parts.len();
    let orders = order_apart(ctx, parts, finish);
    let mut out = Vec::with_capacity(orders.iter().map(Vec::len).sum());
    for step in steps {
        match step {
            Step::Emit(cop) => out.extend(cop),
            Step::Part(k) => out.extend_from_slice(&orders[k]),
        }
    }
    out
}
