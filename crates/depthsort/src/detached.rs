//! Ordering independent components on every core: consecutive components are gathered
//! into groups, each group's pieces are copied into a context of its own
//! ([`Ctx::detached`], under ids of its own), the groups are ordered on the pool, and
//! the pieces they made are added back to the shared context group after group, with
//! their ids, parents and children mapped. Groups are formed from the components' sizes
//! alone and each draws its random numbers from a source seeded in group order, so the
//! result is the same on any number of threads.

use std::sync::atomic::Ordering;
use std::sync::Arc;

use limn_kernel::Kernel;
use rayon::prelude::*;

use crate::pieces::{Ctx, NONE};

/// Pieces in a group, at least (the last group may have fewer): enough that copying them
/// and starting a task costs little against ordering them.
const GROUP_PIECES: usize = 512;

/// Sets to order apart (components, or the parts of a split apart), each with what its
/// ordering needs to know of it. Not `components.rs`'s strongly connected components.
type Sets<T> = Vec<(Vec<u32>, T)>;

/// One group ordered apart: its context, the shared ids of the pieces copied into it (its
/// first ids, in increasing order), and the order of each of its components.
struct Group<'a, K: Kernel> {
    ctx: Ctx<'a, K>,
    members: Vec<u32>,
    orders: Vec<Vec<u32>>,
}

/// Orders `comps` (sets of pieces of `ctx` that can be ordered independently of each
/// other, each with what its ordering needs to know of it) on the pool: `order` orders
/// the components of one group in its own context and returns their orders. Returns the
/// orders of all components in the order given, in ids of `ctx`, to which the pieces made
/// meanwhile are added (in group order). `ctx` may itself be a detached context: its
/// groups then count their splits where it counts its own.
pub(crate) fn order_apart<'a, K: Kernel, T: Send>(
    ctx: &mut Ctx<'a, K>,
    comps: Vec<(Vec<u32>, T)>,
    order: impl Fn(&mut Ctx<'a, K>, Vec<(Vec<u32>, T)>) -> Vec<Vec<u32>> + Sync,
) -> Vec<Vec<u32>> {
    // Each group's components and the seed of its random source.
    let mut groups: Vec<(Sets<T>, u64)> = Vec::new();
    let mut group = Vec::new();
    let mut size = 0;
    for c in comps {
        size += c.0.len();
        group.push(c);
        if size >= GROUP_PIECES {
            groups.push((std::mem::take(&mut group), ctx.next_random()));
            size = 0;
        }
    }
    if !group.is_empty() {
        groups.push((group, ctx.next_random()));
    }
    let count = groups.iter().map(|(comps, _)| comps.len()).sum();
    let counted = ctx.split_counter();
    // Each group's share of the pieces the limit still allows, by its members.
    let free = ctx.limit.saturating_sub(counted.load(Ordering::Relaxed));
    let total: usize = groups
        .iter()
        .flat_map(|(comps, _)| comps)
        .map(|c| c.0.len())
        .sum();
    let shared: &Ctx<'a, K> = ctx;
    let done: Vec<Group<'a, K>> = groups
        .into_par_iter()
        .map(|(comps, seed)| {
            let mut members: Vec<u32> = comps.iter().flat_map(|c| &c.0).copied().collect();
            members.sort_unstable();
            // Room for the group's share of the limit, as address space (see
            // `Ctx::make_room`): growing the vector would copy every piece into fresh
            // memory. Where that is refused, room for as many pieces again.
            let m = members.len();
            let share = (free as u128 * m as u128 / total.max(1) as u128) as usize;
            let mut pieces = Vec::new();
            if pieces.try_reserve_exact(m.saturating_add(share)).is_err() {
                pieces.reserve(2 * m + 8);
            }
            pieces.extend(members.iter().map(|&p| shared.pieces[p as usize].clone()));
            let mut local = shared.detached(pieces, seed, Arc::clone(&counted));
            let local_comps = comps
                .into_iter()
                .map(|(c, with)| (c.iter().map(|&p| local_id(&members, p)).collect(), with))
                .collect();
            let orders = order(&mut local, local_comps);
            Group {
                ctx: local,
                members,
                orders,
            }
        })
        .collect();
    let mut out = Vec::with_capacity(count);
    for g in done {
        ctx.stats.add_ordering(&g.ctx.stats);
        ctx.exceeded |= g.ctx.exceeded;
        let base = ctx.pieces.len() as u32;
        let m = g.members.len();
        let global = |l: u32| match l {
            NONE => NONE,
            l if (l as usize) < m => g.members[l as usize],
            l => base + (l - m as u32),
        };
        let pieces = g.ctx.pieces;
        for (l, piece) in pieces.iter().enumerate().take(m) {
            if piece.kids != [NONE, NONE] {
                ctx.pieces[g.members[l] as usize].kids = piece.kids.map(global);
            }
        }
        // Moved on every core, each to its place: the shared vector's memory is new
        // there, and touching it for the first time is most of the cost.
        ctx.pieces
            .par_extend(pieces.into_par_iter().skip(m).map(|mut piece| {
                piece.parent = global(piece.parent);
                piece.kids = piece.kids.map(global);
                piece
            }));
        out.extend(
            g.orders
                .into_iter()
                .map(|o| o.into_iter().map(global).collect::<Vec<u32>>()),
        );
    }
    out
}

/// The id in a detached context of the shared piece `p`, one of the sorted `members`.
fn local_id(members: &[u32], p: u32) -> u32 {
    members.partition_point(|&q| q < p) as u32
}
