//! Newell–Newell–Sancha depth sort (Foley et al. §15.5.1): sort by farthest depth, then
//! test the head P against every Q whose depth range overlaps P's with the five tests
//! (x extents, y extents, P behind Q's plane, Q in front of P's plane, projections
//! disjoint); if all fail, try the swapped plane tests and move Q to the head; a Q that
//! would be moved twice marks a cycle, broken by splitting. Plane tests are exact; the
//! extent and projection tests are conservative float prefilters.

use limn_kernel::Kernel;

use crate::bsp::bsp;
use crate::geom::convex_disjoint;
use crate::occlusion::Rel;
use crate::pieces::Ctx;

/// What to do with the head P after testing it against Q.
enum Verdict {
    /// P cannot hide Q.
    Pass,
    /// Q must be painted before P and may be moved.
    MoveQ,
    /// Split Q by P's plane.
    SplitQ,
    /// Split P by Q's plane.
    SplitP,
    /// No split between P and Q breaks the cycle.
    Stuck,
}

fn test_pair<K: Kernel>(ctx: &Ctx<'_, K>, p: u32, q: u32, q_marked: bool) -> Verdict {
    let (pp, qq) = (&ctx.pieces[p as usize], &ctx.pieces[q as usize]);
    let m = ctx.margin;
    // Tests 1 and 2: screen extents disjoint.
    if pp.bbox.max_x + m < qq.bbox.min_x || qq.bbox.max_x + m < pp.bbox.min_x {
        return Verdict::Pass;
    }
    if pp.bbox.max_y + m < qq.bbox.min_y || qq.bbox.max_y + m < pp.bbox.min_y {
        return Verdict::Pass;
    }
    // Test 3: P entirely behind Q's plane.
    let p_rel_q = ctx.rel(p, q);
    if p_rel_q == Rel::Far {
        return Verdict::Pass;
    }
    // Test 4: Q entirely in front of P's plane.
    let q_rel_p = ctx.rel(q, p);
    if q_rel_p == Rel::Eye {
        return Verdict::Pass;
    }
    // Coplanar pieces: the later face wins.
    if q_rel_p == Rel::Coplanar || p_rel_q == Rel::Coplanar {
        if pp.face <= qq.face {
            return Verdict::Pass;
        }
        return if q_marked {
            Verdict::Stuck
        } else {
            Verdict::MoveQ
        };
    }
    // Test 5: projections disjoint.
    if convex_disjoint(&pp.pts, &qq.pts, m) {
        return Verdict::Pass;
    }
    // Swapped tests 3' and 4': may Q go first?
    let q_may_go_first = q_rel_p == Rel::Far || p_rel_q == Rel::Eye;
    if q_may_go_first && !q_marked {
        return Verdict::MoveQ;
    }
    if q_rel_p == Rel::Span {
        Verdict::SplitQ
    } else if p_rel_q == Rel::Span {
        Verdict::SplitP
    } else {
        Verdict::Stuck
    }
}

/// Inserts `id` into the sorted tail `list[front..]` (farthest first).
fn insert_sorted<K: Kernel>(ctx: &Ctx<'_, K>, list: &mut Vec<u32>, front: usize, id: u32) {
    let key = ctx.pieces[id as usize].dmax;
    let tail = &list[front..];
    let pos = tail.partition_point(|&x| ctx.pieces[x as usize].dmax >= key);
    list.insert(front + pos, id);
}

/// The Newell–Newell–Sancha order of `set`.
pub(crate) fn newell<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    mut list: Vec<u32>,
    candidates: usize,
) -> Vec<u32> {
    list.sort_by(|&a, &b| {
        let (pa, pb) = (&ctx.pieces[a as usize], &ctx.pieces[b as usize]);
        pb.dmax.total_cmp(&pa.dmax).then(a.cmp(&b))
    });
    let mut out = Vec::with_capacity(list.len());
    let mut marked: Vec<bool> = Vec::new();
    // list[..front] holds pieces moved to the head (unsorted); list[front..] is sorted.
    let mut front = 0usize;
    let budget = 64 * list.len() + 10_000;
    let mut steps = 0usize;
    'outer: while !list.is_empty() {
        steps += 1;
        if steps > budget {
            break;
        }
        let p = list[0];
        let pmin = ctx.pieces[p as usize].dmin;
        let mut j = 1;
        while j < list.len() {
            let q = list[j];
            let qq = &ctx.pieces[q as usize];
            if qq.dmax < pmin - ctx.dmargin {
                if j >= front.max(1) {
                    break; // the rest of the sorted tail is nearer still
                }
                j += 1;
                continue;
            }
            if marked.len() < ctx.pieces.len() {
                marked.resize(ctx.pieces.len(), false);
            }
            match test_pair(ctx, p, q, marked[q as usize]) {
                Verdict::Pass => j += 1,
                Verdict::MoveQ => {
                    marked[q as usize] = true;
                    list.remove(j);
                    if j < front {
                        front -= 1;
                    }
                    list.insert(0, q);
                    front += 1;
                    continue 'outer;
                }
                Verdict::SplitQ => {
                    list.remove(j);
                    if j < front {
                        front -= 1;
                    }
                    let (e, f) = ctx.split_by(q, p);
                    for piece in e.into_iter().chain(f) {
                        insert_sorted(ctx, &mut list, front, piece);
                    }
                    ctx.stats.components += 1;
                    continue 'outer;
                }
                Verdict::SplitP => {
                    list.remove(0);
                    front = front.saturating_sub(1);
                    let (e, f) = ctx.split_by(p, q);
                    for piece in e.into_iter().chain(f) {
                        insert_sorted(ctx, &mut list, front, piece);
                    }
                    ctx.stats.components += 1;
                    continue 'outer;
                }
                Verdict::Stuck => break 'outer,
            }
        }
        out.push(list.remove(0));
        front = front.saturating_sub(1);
    }
    if !list.is_empty() {
        // A cycle no pairwise split resolves (or the step budget ran out): order the
        // rest with a BSP tree, which always succeeds. The rest comes after `out`:
        // everything in `out` passed its tests against every remaining piece.
        ctx.stats.largest_component = ctx.stats.largest_component.max(list.len());
        let rest = bsp(ctx, list, candidates);
        out.extend(rest);
    }
    out
}
