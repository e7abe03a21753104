//! The adaptive ordering: exact pairwise constraints between pieces whose projections may
//! overlap, a topological sort of the occlusion graph, and BSP splitting only inside its
//! strongly connected components (cycles and interpenetrations), recursively.

use limn_kernel::Kernel;
use rayon::prelude::*;

use crate::bsp::{choose_splitter, partition, push_parts, push_parts_as, Task};
use crate::geom::{boxes_meet, convex_disjoint, Box2};
use crate::occlusion::Pair;
use crate::pieces::Ctx;

/// A component larger than this, holding more than four fifths of its set, is dense.
const DENSE_MIN: usize = 256;
/// BSP levels applied to a dense component before its parts are analysed again.
const DENSE_LEVELS: u32 = 5;

/// Pieces whose box covers more grid cells than this are tested against everything.
const MAX_CELLS_PER_ITEM: usize = 64;

/// Calls `f(i, j)` (indices into `set`, i ≠ j, each unordered pair once) for every pair
/// whose screen boxes meet, using a uniform grid over the set's extent.
pub(crate) fn box_pairs<K: Kernel>(ctx: &Ctx<'_, K>, set: &[u32], mut f: impl FnMut(usize, usize)) {
    let n = set.len();
    if n < 2 {
        return;
    }
    let m = ctx.margin;
    let boxes: Vec<Box2> = set
        .iter()
        .map(|&p| ctx.pieces[p as usize].bbox.grown(m))
        .collect();
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
    for b in &boxes {
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

/// Candidate pairs per parallel task: below this, splitting the work costs more than it
/// saves.
const PAIRS_PER_TASK: usize = 64;

/// Orders one set: constraints, components, and tasks for the stack.
fn order_set<K: Kernel>(ctx: &mut Ctx<'_, K>, set: Vec<u32>, stack: &mut Vec<Task>) {
    let n = set.len();
    let mut pairs = Vec::new();
    box_pairs(ctx, &set, |i, j| pairs.push((i as u32, j as u32)));
    // The pair tests only read the pieces: they run in parallel, and the results come
    // back in the order of `pairs` whatever the number of threads.
    let shared: &Ctx<'_, K> = ctx;
    let margin = shared.margin;
    let tested: Vec<Option<Pair>> = pairs
        .par_iter()
        .with_min_len(PAIRS_PER_TASK)
        .map(|&(i, j)| {
            let (p, q) = (set[i as usize], set[j as usize]);
            let (pp, qq) = (&shared.pieces[p as usize], &shared.pieces[q as usize]);
            if convex_disjoint(&pp.pts, &qq.pts, margin) {
                None
            } else {
                Some(shared.pair(p, q))
            }
        })
        .collect();
    let mut edges: Vec<(u32, u32)> = Vec::new();
    for (&(i, j), pair) in pairs.iter().zip(tested) {
        let Some(pair) = pair else { continue };
        ctx.stats.candidate_pairs += 1;
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
            let m = members.len();
            if m > DENSE_MIN && m * 5 > n * 4 {
                stack.push(Task::Deep(members, DENSE_LEVELS));
            } else {
                stack.push(Task::Split(members));
            }
        }
    }
}

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
                } else {
                    order_set(ctx, s, &mut stack);
                }
            }
            Task::Split(s) => {
                let sp = choose_splitter(ctx, &s, candidates);
                let (far, cop, near) = partition(ctx, &s, sp);
                push_parts(&mut stack, far, cop, near);
            }
            Task::Deep(s, levels) => {
                if levels == 0 || s.len() <= DENSE_MIN / 4 {
                    stack.push(Task::Order(s));
                    continue;
                }
                let sp = choose_splitter(ctx, &s, candidates);
                let (far, cop, near) = partition(ctx, &s, sp);
                push_parts_as(&mut stack, far, cop, near, |v| Task::Deep(v, levels - 1));
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
