//! The adaptive ordering: exact pairwise constraints between pieces whose projections may
//! overlap, a topological sort of the occlusion graph, and BSP splitting only inside its
//! strongly connected components (cycles and interpenetrations), recursively.

use limn_kernel::Kernel;

use crate::broad::{box_pairs, estimated_box_pairs, Found};
use crate::bsp::{push_parts_as, Task};
use crate::components::Components;
use crate::detached::order_apart;
use crate::face_runs::FaceRuns;
use crate::geom::{boxes_meet, convex_disjoint, Box2};
use crate::occlusion::Pair;
use crate::partition::{split_set, SCORE_SAMPLE};
use crate::pieces::Ctx;
use crate::probe::{cycles_everywhere, PROBE_MIN};
use crate::separation::SeparatingAxes;
use crate::split_apart::{split_apart, splits_apart};

/// Parts of a split component up to this size are always analysed again (the analysis
/// of a small set is cheap whatever its density).
const ALWAYS_ANALYSE: usize = 4;

/// Cost of one candidate-pair test in the units of the cost model of [`analysis_pays`]
/// (one polygon classified against a plane): the separating-axis tests, two float-filtered
/// classifications, and for pieces spanning each other's planes a float piercing
/// estimate or two exact splits into halves and their projections. Set from ordering
/// soups of 2,000 to 50,000 triangles of sizes 0.1 to 0.5 (BENCHMARKS.md): 8 gives the
/// fewest fragments but costs up to 1.13× BSP's time on the densest; 24 and 32 give up
/// fragments without saving time.
const PAIR_COST: usize = 16;

/// Sets of at most this many pieces are tested all against all by [`order_set`] itself,
/// in the order the broad phase visits a set this small, in the working space (none of
/// the broad phase's vectors).
const SMALL_SET: usize = 16;

/// Working space of [`order_set`], kept from set to set: a dense scene is ordered as
/// thousands of sets of two to four pieces, where allocating the graph's vectors anew for
/// each cost more than the search.
#[derive(Default)]
struct Workspace {
    boxes: Vec<Box2>,
    /// The candidate pairs tested, and those of them that are not free.
    tested: Found<(u32, u32, Pair)>,
    edges: Vec<(u32, u32)>,
    start: Vec<u32>,
    fill: Vec<u32>,
    adj: Vec<u32>,
    comps: Components,
    face_runs: FaceRuns,
    /// Pieces alone in their component, waiting to be emitted together.
    run: Vec<u32>,
}

/// Orders one set: constraints, components, and tasks for the stack.
fn order_set<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    set: Vec<u32>,
    stack: &mut Vec<Task>,
    ws: &mut Workspace,
) {
    let n = set.len();
    // The pair tests only read the pieces: each pair is tested as the broad phase finds
    // it (in parallel blocks for large sets), and the results come back in the order of
    // a visit on one thread whatever the number of threads.
    let shared: &Ctx<'_, K> = ctx;
    let margin = shared.margin;
    // A candidate pair is counted; only a constraint is kept.
    let found = |i: usize, j: usize, pair: Pair, out: &mut Found<(u32, u32, Pair)>| {
        out.counted += 1;
        if pair != Pair::Free {
            out.kept.push((i as u32, j as u32, pair));
        }
    };
    let test = |i: usize, j: usize, out: &mut Found<(u32, u32, Pair)>| {
        let (p, q) = (set[i], set[j]);
        let (pp, qq) = (&shared.pieces[p as usize], &shared.pieces[q as usize]);
        if !shared.apart_by_construction(p, q) && !convex_disjoint(&pp.pts, &qq.pts, margin) {
            found(i, j, shared.pair(p, q), out);
        }
    };
    if n <= SMALL_SET {
        ws.tested.clear();
        ws.boxes.clear();
        ws.boxes.extend(
            set.iter()
                .map(|&p| shared.pieces[p as usize].bbox.grown(margin)),
        );
        for i in 0..n {
            for j in i + 1..n {
                if boxes_meet(&ws.boxes[i], &ws.boxes[j], 0.0) {
                    test(i, j, &mut ws.tested);
                }
            }
        }
    } else if crowded(shared, &set) {
        // Each piece's own extents along its edge normals, once for the whole set.
        let axes = SeparatingAxes::new(
            set.iter().map(|&p| shared.pieces[p as usize].pts.as_ref()),
            margin,
        );
        ws.tested = box_pairs(shared, &set, |i, j, out: &mut Found<(u32, u32, Pair)>| {
            let (p, q) = (set[i], set[j]);
            // The axes first: they are read from one table, the pieces from all over.
            if !axes.disjoint(i, j) && !shared.apart_by_construction(p, q) {
                found(i, j, shared.pair(p, q), out);
            }
        });
    } else {
        ws.tested = box_pairs(shared, &set, test);
    }
    ctx.stats.candidate_pairs += ws.tested.counted;
    ws.edges.clear();
    for &(i, j, pair) in &ws.tested.kept {
        match pair {
            Pair::Free => {}
            Pair::FirstBefore => ws.edges.push((i, j)),
            Pair::SecondBefore => ws.edges.push((j, i)),
            Pair::Conflict => {
                ws.edges.push((i, j));
                ws.edges.push((j, i));
            }
        }
    }
    ctx.stats.constraints += ws.edges.len();
    ws.start.clear();
    ws.start.resize(n + 1, 0);
    for &(a, _) in &ws.edges {
        ws.start[a as usize + 1] += 1;
    }
    for i in 0..n {
        ws.start[i + 1] += ws.start[i];
    }
    ws.fill.clear();
    ws.fill.extend_from_slice(&ws.start);
    ws.adj.clear();
    ws.adj.resize(ws.edges.len(), 0);
    for &(a, b) in &ws.edges {
        ws.adj[ws.fill[a as usize] as usize] = b;
        ws.fill[a as usize] += 1;
    }
    ws.comps.find(n, &ws.start, &ws.adj);
    ws.face_runs.order(&ws.comps, n, &ws.start, &ws.adj, |v| {
        ctx.pieces[set[v as usize] as usize].face
    });
    let members: Vec<&[u32]> = ws.comps.in_topological_order().collect();

    // Tasks are pushed last component first, so that they are popped in topological
    // order (one that keeps the pieces of a face together); consecutive single pieces
    // are emitted by one task.
    ws.run.clear();
    for comp in ws
        .face_runs
        .order
        .iter()
        .rev()
        .map(|&k| members[k as usize])
    {
        if let [only] = comp {
            ws.run.push(set[*only as usize]);
            continue;
        }
        if !ws.run.is_empty() {
            stack.push(Task::Emit(ws.run.iter().rev().copied().collect()));
            ws.run.clear();
        }
        ctx.stats.components += 1;
        ctx.stats.largest_component = ctx.stats.largest_component.max(comp.len());
        stack.push(Task::Split(comp.iter().map(|&i| set[i as usize]).collect()));
    }
    if !ws.run.is_empty() {
        stack.push(Task::Emit(ws.run.iter().rev().copied().collect()));
    }
}

/// Whether the screen boxes of `set` are expected to meet [`CROWDED`] others each or
/// more (boxes of the mean width and height, spread evenly over the set's extent) beyond
/// the faces each piece's face meets at its corners: then the separating axes of each
/// piece are worth computing once for the set ([`SeparatingAxes`]). A mesh's neighbours
/// touch, so no axis ever separates them: on a mesh whose boxes meet little more than
/// its neighbours, the table of axes (its memory, and a second place read for every
/// pair) cost the 300² height fields a tenth of their whole run.
fn crowded<K: Kernel>(ctx: &Ctx<'_, K>, set: &[u32]) -> bool {
    let mut extent = Box2::EMPTY;
    let (mut w, mut h) = (0.0, 0.0);
    let mut met = 0u64;
    for &p in set {
        let piece = &ctx.pieces[p as usize];
        let b = &piece.bbox;
        extent = extent.union(b);
        w += b.width();
        h += b.height();
        met += u64::from(ctx.faces_met.get(piece.face as usize).copied().unwrap_or(0));
    }
    let n = set.len() as f64;
    let area = extent.width() * extent.height();
    // Two boxes meet when their centres are closer than the sum of their half sizes.
    4.0 * (w / n) * (h / n) * n >= (CROWDED + met as f64 / n) * area
}

/// Other boxes met per box, expected, from which a set is [`crowded`].
const CROWDED: f64 = 8.0;

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
/// The estimate itself costs a few sorts of the set; a set of at most [`SMALL_SET`]
/// pieces counts its meeting boxes instead, all against all. `density` is the one
/// measured on a set this one was split from: while pairs at that density would cost
/// more than [`SKIP_ESTIMATE`] times the BSP, the set is split without measuring (splitting a
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
    let pairs = if n <= SMALL_SET {
        meeting_boxes(ctx, set)
    } else {
        estimated_box_pairs(ctx, set)
    };
    (pairs * PAIR_COST <= bsp as usize, pairs as f64 / all)
}

/// How many pairs of the small `set`'s screen boxes (grown by the prefilter margin) meet,
/// counted all against all: cheaper than estimating for a set of at most [`SMALL_SET`].
fn meeting_boxes<K: Kernel>(ctx: &Ctx<'_, K>, set: &[u32]) -> usize {
    let m = ctx.margin;
    let mut boxes = [Box2::EMPTY; SMALL_SET];
    for (b, &p) in boxes.iter_mut().zip(set) {
        *b = ctx.pieces[p as usize].bbox.grown(m);
    }
    let boxes = &boxes[..set.len()];
    let mut count = 0;
    for (i, a) in boxes.iter().enumerate() {
        count += boxes[i + 1..]
            .iter()
            .filter(|b| boxes_meet(a, b, 0.0))
            .count();
    }
    count
}

/// How far above the cost of BSP the pairs at an inherited density must be for a set to
/// be split without estimating its pairs (see [`analysis_pays`]).
const SKIP_ESTIMATE: f64 = 1.0;

/// The adaptive order of `set`. The components of its occlusion graph are split and
/// ordered on every core ([`order_apart`]).
pub(crate) fn adaptive<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    set: Vec<u32>,
    candidates: usize,
) -> Vec<u32> {
    let mut out = Vec::with_capacity(set.len());
    let mut ws = Workspace::default();
    if set.len() <= 1 {
        return set;
    }
    if set.len() > PROBE_MIN && cycles_everywhere(ctx, &set) {
        run(ctx, Task::Split(set), candidates, &mut ws, &mut out);
        return out;
    }
    // The tasks of the whole set, popped in order: runs of pieces alone in their
    // component, and components to split.
    let mut top = Vec::new();
    order_set(ctx, set, &mut top, &mut ws);
    let mut comps = Vec::new();
    let mut steps = Vec::with_capacity(top.len());
    for t in top.into_iter().rev() {
        match t {
            Task::Emit(alone) => steps.push(Ok(alone)),
            Task::Split(c) => {
                steps.push(Err(comps.len()));
                comps.push((c, ()));
            }
            // Not made by `order_set`; ordered here all the same (its pieces are its own).
            other => {
                let mut o = Vec::new();
                run(ctx, other, candidates, &mut ws, &mut o);
                steps.push(Ok(o));
            }
        }
    }
    let orders = order_apart(ctx, comps, |local, comps| {
        let mut ws = Workspace::default();
        comps
            .into_iter()
            .map(|(c, ())| {
                let mut o = Vec::with_capacity(c.len());
                run(local, Task::Split(c), candidates, &mut ws, &mut o);
                o
            })
            .collect()
    });
    for step in steps {
        match step {
            Ok(pieces) => out.extend(pieces),
            Err(k) => out.extend_from_slice(&orders[k]),
        }
    }
    out
}

/// Carries out `first` and the tasks it makes, appending the order to `out`.
fn run<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    first: Task,
    candidates: usize,
    ws: &mut Workspace,
    out: &mut Vec<u32>,
) {
    let mut stack = vec![first];
    while let Some(t) = stack.pop() {
        match t {
            Task::Emit(v) => out.extend(v),
            Task::Order(s) => {
                if s.len() <= 1 {
                    out.extend(s);
                } else if s.len() > PROBE_MIN && cycles_everywhere(ctx, &s) {
                    stack.push(Task::Split(s));
                } else {
                    order_set(ctx, s, &mut stack, ws);
                }
            }
            Task::Split(s) if splits_apart(ctx, s.len()) => {
                split_on_every_core(ctx, s, f64::INFINITY, candidates, out);
            }
            Task::Split(s) => {
                let (far, cop, near) = split_set(ctx, &s, candidates);
                push_parts_as(&mut stack, far, cop, near, |v| Task::Deep(v, f64::INFINITY));
            }
            Task::Deep(s, density) => {
                if s.len() <= ALWAYS_ANALYSE {
                    stack.push(Task::Order(s));
                    continue;
                }
                let (pays, density) = analysis_pays(ctx, &s, candidates, density);
                if pays {
                    order_set(ctx, s, &mut stack, ws);
                    continue;
                }
                if splits_apart(ctx, s.len()) {
                    split_on_every_core(ctx, s, density, candidates, out);
                    continue;
                }
                let (far, cop, near) = split_set(ctx, &s, candidates);
                push_parts_as(&mut stack, far, cop, near, |v| Task::Deep(v, density));
            }
        }
    }
}

/// Orders `s`, a set to split rather than analyse (a component, or a part where the
/// analysis does not pay) whose parts inherit `density`, appending the order to `out`:
/// its top levels are split on this thread and the parts below them ordered on every
/// core ([`split_apart`]), each part analysed when that pays and split further
/// otherwise, as a [`Task::Deep`] part is. The order emitted here is the whole order of
/// `s`, at the place of its task.
fn split_on_every_core<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    s: Vec<u32>,
    density: f64,
    candidates: usize,
    out: &mut Vec<u32>,
) {
    out.extend(split_apart(
        ctx,
        s,
        density,
        candidates,
        |ctx, part, density, depth| {
            if depth == 0 {
                // `s` itself: known to be split.
                return Some(density);
            }
            let (pays, density) = analysis_pays(ctx, part, candidates, density);
            (!pays).then_some(density)
        },
        |local, parts| {
            let mut ws = Workspace::default();
            parts
                .into_iter()
                .map(|(part, density)| {
                    let mut o = Vec::with_capacity(part.len());
                    run(
                        local,
                        Task::Deep(part, density),
                        candidates,
                        &mut ws,
                        &mut o,
                    );
                    o
                })
                .collect()
        },
    ));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::options::CullMode;
    use crate::test_scenes::torus;
    use limn_kernel::ExactKernel;

    /// A mesh whose boxes meet hardly more than its neighbours is not crowded; the same
    /// boxes without the count of neighbours would be.
    #[test]
    fn a_mesh_is_crowded_only_beyond_its_neighbours() {
        let k = ExactKernel::new();
        let scene = torus(100, 100);
        let (mut ctx, near) = Ctx::framing(&k, &scene, 400, 300);
        let set = crate::prepare::prepare(&mut ctx, &scene, CullMode::Auto, near)
            .expect("a valid scene")
            .items;
        assert!(!crowded(&ctx, &set));
        ctx.faces_met = std::sync::Arc::from([]);
        assert!(crowded(&ctx, &set));
    }
}
