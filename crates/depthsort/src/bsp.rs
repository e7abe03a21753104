//! The Fuchs–Kedem–Naylor BSP ordering, and the deferred-work tasks it shares with the
//! adaptive ordering.

use limn_kernel::Kernel;

use crate::partition::split_set;
use crate::pieces::Ctx;
use crate::split_apart::{split_apart, splits_apart};

/// A unit of deferred work; processed from a stack so deep trees need no recursion.
pub(crate) enum Task {
    /// Order this set (BSP: split it; adaptive: sort its occlusion graph).
    Order(Vec<u32>),
    /// Break this strongly connected component by a splitter, then order both sides.
    Split(Vec<u32>),
    /// Output these pieces in this order.
    Emit(Vec<u32>),
    /// A part of a split component: analyse it when that is expected to cost less than
    /// finishing it by BSP, split it further otherwise (analysing a set that is nearly
    /// all one cycle is wasted work). With the density of candidate pairs last estimated
    /// on a set it was split from (pairs per pair of members; infinite when none was).
    Deep(Vec<u32>, f64),
}

/// Pushes the three parts of a partition so that they are processed far, plane, near.
pub(crate) fn push_parts(stack: &mut Vec<Task>, far: Vec<u32>, cop: Vec<u32>, near: Vec<u32>) {
    push_parts_as(stack, far, cop, near, Task::Order);
}

/// Like [`push_parts`], with `side` making the task for each non-empty side.
pub(crate) fn push_parts_as(
    stack: &mut Vec<Task>,
    far: Vec<u32>,
    cop: Vec<u32>,
    near: Vec<u32>,
    side: impl Fn(Vec<u32>) -> Task,
) {
    if !near.is_empty() {
        stack.push(side(near));
    }
    stack.push(Task::Emit(cop));
    if !far.is_empty() {
        stack.push(side(far));
    }
}

/// The Fuchs–Kedem–Naylor BSP order of `set`: split by a splitter, recurse on both
/// sides, paint far side, splitter plane, near side. Large sets are split on every core
/// ([`split_apart`], when [`splits_apart`] says so).
pub(crate) fn bsp<K: Kernel>(ctx: &mut Ctx<'_, K>, set: Vec<u32>, candidates: usize) -> Vec<u32> {
    let mut out = Vec::with_capacity(set.len());
    let mut stack = vec![Task::Order(set)];
    while let Some(t) = stack.pop() {
        match t {
            Task::Emit(v) => out.extend(v),
            Task::Order(s) | Task::Split(s) | Task::Deep(s, _) => {
                if s.len() <= 1 {
                    out.extend(s);
                    continue;
                }
                if splits_apart(ctx, s.len()) {
                    out.extend(split_apart(
                        ctx,
                        s,
                        (),
                        candidates,
                        |_, _, (), _| Some(()),
                        |local, parts| {
                            parts
                                .into_iter()
                                .map(|(part, ())| bsp(local, part, candidates))
                                .collect()
                        },
                    ));
                    continue;
                }
                let (far, cop, near) = split_set(ctx, &s, candidates);
                push_parts(&mut stack, far, cop, near);
            }
        }
    }
    out
}
