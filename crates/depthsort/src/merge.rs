//! After ordering: fragments of one face that are adjacent in the order are joined again.
//! Two halves of one split are replaced by the piece they were split from, recursively,
//! so a face that did not need splitting comes out as one polygon, exactly (no
//! coordinate is compared).

use std::collections::HashSet;

use limn_kernel::Kernel;
use rayon::prelude::*;

use crate::occlusion::Rel;
use crate::pieces::{Ctx, NONE};

/// Joins sibling pieces inside each run of consecutive pieces of the same face lying in
/// the same plane. A non-planar face is triangulated into polygons of different planes,
/// which may hide each other: a run never crosses from one such plane to another, or a
/// join could move a piece across one it must be painted before or after.
///
/// A run never spans a change of face, so the order is cut at changes of face into
/// blocks of about [`PIECES_PER_TASK`] that are joined on the pool and put together in
/// order (the same result as one pass).
pub(crate) fn merge<K: Kernel>(ctx: &Ctx<'_, K>, order: &[u32]) -> Vec<u32> {
    let face = |k: usize| ctx.pieces[order[k] as usize].face;
    let mut cuts = vec![0];
    let mut k = PIECES_PER_TASK;
    while k < order.len() {
        while k < order.len() && face(k) == face(k - 1) {
            k += 1;
        }
        if k < order.len() {
            cuts.push(k);
        }
        k += PIECES_PER_TASK;
    }
    cuts.push(order.len());
    let parts: Vec<Vec<u32>> = cuts
        .par_windows(2)
        .map(|w| merge_block(ctx, &order[w[0]..w[1]]))
        .collect();
    let mut out = Vec::with_capacity(parts.iter().map(Vec::len).sum());
    for mut p in parts {
        out.append(&mut p);
    }
    out
}

/// Pieces of the order per parallel task of [`merge`], about.
const PIECES_PER_TASK: usize = 8192;

/// [`merge`] on a block of the order that starts and ends at changes of face.
fn merge_block<K: Kernel>(ctx: &Ctx<'_, K>, order: &[u32]) -> Vec<u32> {
    let mut out = Vec::with_capacity(order.len());
    let mut i = 0;
    while i < order.len() {
        let face = ctx.pieces[order[i] as usize].face;
        let mut j = i + 1;
        while j < order.len()
            && ctx.pieces[order[j] as usize].face == face
            && (root(ctx, order[j]) == root(ctx, order[i])
                || ctx.rel(order[j], order[i]) == Rel::Coplanar)
        {
            j += 1;
        }
        if j - i == 1 {
            out.push(order[i]);
        } else {
            merge_run(ctx, &order[i..j], &mut out);
        }
        i = j;
    }
    out
}

/// The polygon piece `p` was split from (itself when it was not split from one): pieces
/// with the same root lie in its plane, which needs no test.
fn root<K: Kernel>(ctx: &Ctx<'_, K>, mut p: u32) -> u32 {
    while ctx.pieces[p as usize].parent != NONE {
        p = ctx.pieces[p as usize].parent;
    }
    p
}

/// Pieces of one face in one plane never overlap each other in projection, so any order within the
/// run is valid: join every pair of siblings present until none is left.
fn merge_run<K: Kernel>(ctx: &Ctx<'_, K>, run: &[u32], out: &mut Vec<u32>) {
    let mut present: HashSet<u32> = run.iter().copied().collect();
    let mut list: Vec<u32> = run.to_vec();
    loop {
        let mut changed = false;
        let mut next = Vec::with_capacity(list.len());
        for &p in &list {
            if !present.contains(&p) {
                continue;
            }
            let parent = ctx.pieces[p as usize].parent;
            if parent != NONE {
                let [a, b] = ctx.pieces[parent as usize].kids;
                if a != NONE && b != NONE && present.contains(&a) && present.contains(&b) {
                    present.remove(&a);
                    present.remove(&b);
                    present.insert(parent);
                    next.push(parent);
                    changed = true;
                    continue;
                }
            }
            next.push(p);
        }
        list = next;
        if !changed {
            break;
        }
    }
    out.extend(list.into_iter().filter(|p| present.contains(p)));
}
