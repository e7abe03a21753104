//! The adaptive ordering: exact pairwise constraints between pieces whose projections may
//! overlap, a topological sort of the occlusion graph, and BSP splitting only inside its
//! strongly connected components (cycles and interpenetrations), recursively.

use limn_kernel::Kernel;
use rayon::prelude::*;

use crate::broad::{box_pairs, estimated_box_pairs};
use crate::bsp::{choose_splitter, partition, push_parts_as, Task, SCORE_SAMPLE};
use crate::geom::{boxes_meet, convex_disjoint, Box2};
use crate::occlusion::Pair;
use crate::pieces::Ctx;

/// Parts of a split component up to this size are always analysed again (the analysis
/// of a small set is cheap whatever its density).
const ALWAYS_ANALYSE: usize = 4;

/// Cost of one candidate-pair test in the units of the cost model of [`analysis_pays`]
/// (one polygon classified against a plane): two classifications, often two exact
/// splits into halves and their projections, and the separating-axis tests.
const PAIR_COST: usize = 32;

/// Strongly connected components of a graph given in CSR form, in topological order
/// (a component comes before every component it has edges to). Iterative Tarjan.
pub(crate) fn components(n: usize, start: &[u32], adj: &[u32]) -> Vec<Vec<u32>> {
    const UNSEEN: u32 = u32::MAX;
    let mut index = vec![UNSEEN; n];
    let mut low = vec![0u32; n];
    let mut on_stack = vec![false; n];
    let mut stack: Vec<u32> = Vec::new();
    let mut out: Vec<Vec<u32>> = Vec::new();
    let mut next = 0u32;
    let mut call: Vec<(u32, u32)> = Vec::new();
    for root in 0..n as u32 {
        if index[root as usize] != UNSEEN {
            continue;
        }
        call.push((root, start[root as usize]));
        index[root as usize] = next;
        low[root as usize] = next;
        next += 1;
        stack.push(root);
        on_stack[root as usize] = true;
        while let Some(&mut (v, ref mut e)) = call.last_mut() {
            let vi = v as usize;
            if *e < start[vi + 1] {
                let w = adj[*e as usize];
                *e += 1;
                let wi = w as usize;
                if index[wi] == UNSEEN {
                    index[wi] = next;
                    low[wi] = next;
                    next += 1;
                    stack.push(w);
                    on_stack[wi] = true;
                    call.push((w, start[wi]));
                } else if on_stack[wi] {
                    low[vi] = low[vi].min(index[wi]);
                }
            } else {
                call.pop();
                if let Some(&(parent, _)) = call.last() {
                    let pi = parent as usize;
                    low[pi] = low[pi].min(low[vi]);
                }
                if low[vi] == index[vi] {
                    let mut comp = Vec::new();
                    loop {
                        let w = stack.pop().expect("tarjan stack holds the component");
                        on_stack[w as usize] = false;
                        comp.push(w);
                        if w == v {
                            break;
                        }
                    }
                    out.push(comp);
                }
            }
        }
    }
    // Tarjan emits components after everything reachable from them.
    out.reverse();
    out
}

/// Orders one set: constraints, components, and tasks for the stack.
fn order_set<K: Kernel>(ctx: &mut Ctx<'_, K>, set: Vec<u32>, stack: &mut Vec<Task>) {
    let n = set.len();
    // The pair tests only read the pieces: each pair is tested as the broad phase finds
    // it (in parallel blocks for large sets), and the results come back in the order of
    // a visit on one thread whatever the number of threads.
    let shared: &Ctx<'_, K> = ctx;
    let margin = shared.margin;
    let tested = box_pairs(shared, &set, |i, j, out: &mut Vec<(u32, u32, Pair)>| {
        let (p, q) = (set[i], set[j]);
        let (pp, qq) = (&shared.pieces[p as usize], &shared.pieces[q as usize]);
        if !shared.apart_by_construction(p, q) && !convex_disjoint(&pp.pts, &qq.pts, margin) {
            out.push((i as u32, j as u32, shared.pair(p, q)));
        }
    });
    ctx.stats.candidate_pairs += tested.len();
    let mut edges: Vec<(u32, u32)> = Vec::with_capacity(tested.len());
    for (i, j, pair) in tested {
        match pair {
            Pair::Free => {}
            Pair::FirstBefore => edges.push((i, j)),
            Pair::SecondBefore => edges.push((j, i)),
            Pair::Conflict => {
                edges.push((i, j));
                edges.push((j, i));
            }
        }
    }
    ctx.stats.constraints += edges.len();
    let mut start = vec![0u32; n + 1];
    for &(a, _) in &edges {
        start[a as usize + 1] += 1;
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let mut fill = start.clone();
    let mut adj = vec![0u32; edges.len()];
    for &(a, b) in &edges {
        adj[fill[a as usize] as usize] = b;
        fill[a as usize] += 1;
    }
    let comps = components(n, &start, &adj);

    for comp in comps.into_iter().rev() {
        let members: Vec<u32> = comp.iter().map(|&i| set[i as usize]).collect();
        if members.len() == 1 {
            stack.push(Task::Emit(members));
        } else {
            ctx.stats.components += 1;
            ctx.stats.largest_component = ctx.stats.largest_component.max(members.len());
            stack.push(Task::Split(members));
        }
    }
}

/// Sets larger than this are probed ([`cycles_everywhere`]) before being analysed.
const PROBE_MIN: usize = 256;
/// Members of a set probed by [`cycles_everywhere`].
const PROBE_SAMPLE: usize = 64;

/// Whether the occlusion graph of `set` is, as measured on a sample, certain to be one
/// cycle nearly everywhere, so that analysing the whole set would be wasted. Pieces that
/// pierce each other (a conflict: each must be painted before the other) form two-cycles;
/// when a piece is in conflict with one other piece or more on average, the conflicts
/// form a giant connected part, as in a random graph of that mean degree, and so does the
/// occlusion graph's largest component. The mean is measured on [`PROBE_SAMPLE`] evenly
/// spaced members against the whole set (in parallel; the count does not depend on the
/// threads).
fn cycles_everywhere<K: Kernel>(ctx: &Ctx<'_, K>, set: &[u32]) -> bool {
    let n = set.len();
    let m = ctx.margin;
    let boxes: Vec<Box2> = set
        .iter()
        .map(|&p| ctx.pieces[p as usize].bbox.grown(m))
        .collect();
    let conflicts: usize = (0..PROBE_SAMPLE)
        .into_par_iter()
        .map(|k| {
            let a = k * n / PROBE_SAMPLE;
            let (p, bp) = (set[a], &boxes[a]);
            let pp = &ctx.pieces[p as usize];
            (0..n)
                .filter(|&b| {
                    let q = set[b];
                    b != a
                        && boxes_meet(bp, &boxes[b], 0.0)
                        && !convex_disjoint(&pp.pts, &ctx.pieces[q as usize].pts, m)
                        && ctx.pair(p, q) == Pair::Conflict
                })
                .count()
        })
        .sum();
    conflicts >= PROBE_SAMPLE
}

/// Whether analysing `set`, a part of a split component (testing its candidate pairs), is
/// expected to cost less than finishing it by BSP, and the density of candidate pairs
/// (per pair of members) the answer was based on. The cost is counted, not timed, so the
/// decision is the same on every run, machine and thread count: the analysis costs its
/// candidate pairs (estimated on the set itself from how its screen boxes overlap in x
/// and in y) at [`PAIR_COST`] each; BSP costs, per level of a balanced tree, one
/// classification per member plus the scoring of `candidates` splitters on a sample.
/// Until the analysis pays, the set is split one BSP level further and its parts are
/// asked again.
///
/// The estimate itself costs a few sorts of the set. `density` is the one measured on a
/// set this one was split from: while pairs at that density would cost more than
/// [`SKIP_ESTIMATE`] times the BSP, the set is split without measuring (splitting a
/// dense set changes its density by a small factor a level).
fn analysis_pays<K: Kernel>(
    ctx: &Ctx<'_, K>,
    set: &[u32],
    candidates: usize,
    density: f64,
) -> (bool, f64) {
    let n = set.len();
    let levels = (usize::BITS - n.leading_zeros()) as usize;
    let bsp = (levels * (n + candidates * n.min(SCORE_SAMPLE))) as f64;
    let all = (n * (n - 1) / 2) as f64;
    if density.is_finite() && density * all * PAIR_COST as f64 > SKIP_ESTIMATE * bsp {
        return (false, density);
    }
    let pairs = estimated_box_pairs(ctx, set);
    (pairs * PAIR_COST <= bsp as usize, pairs as f64 / all)
}

/// How far above the cost of BSP the pairs at an inherited density must be for a set to
/// be split without estimating its pairs (see [`analysis_pays`]).
const SKIP_ESTIMATE: f64 = 4.0;

/// The adaptive order of `set`.
pub(crate) fn adaptive<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    set: Vec<u32>,
    candidates: usize,
) -> Vec<u32> {
    let mut out = Vec::with_capacity(set.len());
    let mut stack = vec![Task::Order(set)];
    while let Some(t) = stack.pop() {
        match t {
            Task::Emit(v) => out.extend(v),
            Task::Order(s) => {
                if s.len() <= 1 {
                    out.extend(s);
                } else if s.len() > PROBE_MIN && cycles_everywhere(ctx, &s) {
                    stack.push(Task::Split(s));
                } else {
                    order_set(ctx, s, &mut stack);
                }
            }
            Task::Split(s) => {
                let sp = choose_splitter(ctx, &s, candidates);
                let (far, cop, near) = partition(ctx, &s, sp);
                push_parts_as(&mut stack, far, cop, near, |v| Task::Deep(v, f64::INFINITY));
            }
            Task::Deep(s, density) => {
                if s.len() <= ALWAYS_ANALYSE {
                    stack.push(Task::Order(s));
                    continue;
                }
                let (pays, density) = analysis_pays(ctx, &s, candidates, density);
                if pays {
                    order_set(ctx, s, &mut stack);
                    continue;
                }
                let sp = choose_splitter(ctx, &s, candidates);
                let (far, cop, near) = partition(ctx, &s, sp);
                push_parts_as(&mut stack, far, cop, near, |v| Task::Deep(v, density));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::components;

    fn csr(n: usize, edges: &[(u32, u32)]) -> (Vec<u32>, Vec<u32>) {
        let mut start = vec![0u32; n + 1];
        for &(a, _) in edges {
            start[a as usize + 1] += 1;
        }
        for i in 0..n {
            start[i + 1] += start[i];
        }
        let mut fill = start.clone();
        let mut adj = vec![0; edges.len()];
        for &(a, b) in edges {
            adj[fill[a as usize] as usize] = b;
            fill[a as usize] += 1;
        }
        (start, adj)
    }

    #[test]
    fn components_come_in_topological_order() {
        // 3 -> 0 -> 1 <-> 2, 4 alone
        let (s, a) = csr(5, &[(3, 0), (0, 1), (1, 2), (2, 1)]);
        let comps = components(5, &s, &a);
        let pos = |v: u32| comps.iter().position(|c| c.contains(&v)).unwrap();
        assert!(pos(3) < pos(0) && pos(0) < pos(1));
        assert_eq!(pos(1), pos(2));
        assert_eq!(comps.len(), 4);
    }

    #[test]
    fn long_chain_does_not_recurse() {
        let n = 200_000;
        let edges: Vec<(u32, u32)> = (0..n as u32 - 1).map(|i| (i, i + 1)).collect();
        let (s, a) = csr(n, &edges);
        let comps = components(n, &s, &a);
        assert_eq!(comps.len(), n);
        assert_eq!(comps[0], vec![0]);
        assert_eq!(comps[n - 1], vec![n as u32 - 1]);
    }
}
