//! Seam flaps: closing the hairlines viewers leave between adjacent fills without moving
//! any boundary of the picture.
//!
//! A flap is painted in an earlier fragment's colour under a later fragment, so it must
//! lie inside that later fragment: the flap is clipped from it in f64, and kept only
//! where orientation tests exact on the f64 coordinates show that every point it fills
//! is one the later fragment fills ([`flap`]). Rounding alone cannot move a boundary
//! then, however far a corner of the later fragment lies (a crossing computed from a
//! corner 10¹² px away is off by 10⁻⁵ px, more than the edge band of a check).

use std::collections::HashMap;
use std::sync::atomic::{AtomicU32, Ordering};

use rayon::prelude::*;

use crate::chunked_queue::ChunkedQueue;
use crate::seams_across::Across;
use crate::{narrow_color, wide_color, PaintFragment, VertexColor};

/// The bits of an edge's end points, smaller end first (an undirected edge key).
pub(crate) type EdgeKey = ([u64; 2], [u64; 2]);

/// A hash of an edge key (a fixed mixing of its bits: the same on every run).
fn key_hash(k: &EdgeKey) -> u64 {
    const M: u64 = 0x9e37_79b9_7f4a_7c15;
    let mut h: u64 = 0;
    for w in [k.0[0], k.0[1], k.1[0], k.1[1]] {
        h = (h.rotate_left(5) ^ w).wrapping_mul(M);
    }
    h ^ (h >> 29)
}

pub(crate) fn edge_key(a: [f64; 2], b: [f64; 2]) -> EdgeKey {
    let (ka, kb) = (a.map(f64::to_bits), b.map(f64::to_bits));
    if ka <= kb {
        (ka, kb)
    } else {
        (kb, ka)
    }
}

/// Adds seam flaps: viewers anti-alias each path on its own, so where two fills meet
/// along an edge both edge pixels are only partly covered and the background shows
/// through as a hairline. For every edge an opaque fragment shares (end points equal)
/// with an opaque fragment of another face painted *later* (or of its own face, on the
/// other side of the edge, with fragments of other faces painted between them), a flap
/// in the first
/// fragment's paint (for a smooth fragment: vertex colours that run along the edge as
/// the fragment's do, constant across it; textured: the same texture map) is painted
/// right after it: the part of the later fragment within
/// `width` pixels of the shared edge (or, where that part cannot be shown to lie inside
/// the later fragment, the later fragment itself). The later fragment covers its flaps
/// entirely, decided exactly, so the picture stays exactly the same at every point (the
/// flap only fills the anti-aliased pixels under the shared edge): silhouettes, edges
/// against faces painted earlier and translucent faces get no flap. Every flap is a
/// fragment of its own ([`FlapJoin::Separate`]).
pub fn seam_flaps(fragments: Vec<PaintFragment>, width: f64) -> Vec<PaintFragment> {
    seam_flaps_indexed(fragments, width, FlapJoin::Separate).0
}

/// How the flaps of a flat fragment are painted.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FlapJoin {
    /// Each flap is a fragment of its own, painted right after its fragment; the
    /// fragment keeps its outline and which of its edges are original.
    Separate,
    /// The flaps of a flat, untextured fragment become part of its outline: the shared
    /// edge is replaced by the flap's far side, so fragment and flaps are one polygon
    /// (the same points painted, fewer paths, no edge between fragment and flap). The
    /// edges so replaced are no longer in the outline: for pictures without outline
    /// strokes. Smooth and textured fragments keep separate flaps.
    Joined,
}

/// [`seam_flaps`] with the flaps painted as `join` says, also returning where each input
/// fragment went in the output (so that marks placed among the fragments can follow
/// them).
pub fn seam_flaps_indexed(
    fragments: Vec<PaintFragment>,
    width: f64,
    join: FlapJoin,
) -> (Vec<PaintFragment>, Vec<usize>) {
    seam_flaps_beside_strokes(fragments, width, join, &[])
}

/// [`seam_flaps_indexed`] for a caller that strokes the original edges of some faces:
/// `stroked[k]` says that every original edge of face `k` is stroked, opaque and at
/// least `width` wide, right after the fragment's fill. Such an edge gets no flap,
/// whether the earlier or the later fragment along it strokes it: the stroke covers
/// the pixels the edge crosses, so the background cannot show through there (a
/// matplotlib surface whose polygons are edged in their own colour). Faces beyond
/// `stroked`'s length are not stroked.
pub fn seam_flaps_beside_strokes(
    mut fragments: Vec<PaintFragment>,
    width: f64,
    join: FlapJoin,
    stroked: &[bool],
) -> (Vec<PaintFragment>, Vec<usize>) {
    let later = LaterNeighbours::new(&fragments);
    let across = Across::new(&fragments);
    // The flaps first (they read the later fragments as they are), in blocks of fragments
    // in parallel, in the order of the fragments they follow.
    let mut parts: Vec<BlockFlaps> = fragments
        .par_chunks(FRAGMENTS_PER_TASK)
        .enumerate()
        .map(|(c, block)| {
            // Room for two flaps per fragment (a smooth mesh's triangles have about one
            // and a half): growing by doubling wrote each block's flaps again into
            // fresh pages, and room never written is address space only.
            let (mut flaps, mut joined) = (Vec::with_capacity(2 * block.len()), Vec::new());
            // What the block's flaps found out about the later fragments they go into.
            let mut shapes = HashMap::new();
            for (k, f) in block.iter().enumerate() {
                let i = c * FRAGMENTS_PER_TASK + k;
                let start = flaps.len();
                let near = (&later, &across, stroked);
                flaps_after(&fragments, i, f, near, (width, &mut shapes), &mut flaps);
                if join == FlapJoin::Joined && flaps.len() > start {
                    if let Some(outline) = joined_outline(f, &flaps[start..]) {
                        flaps.truncate(start);
                        joined.push((i, outline));
                        continue;
                    }
                }
            }
            (flaps, joined)
        })
        .collect();
    // The neighbours are not asked again: released before the picture makes room for
    // the flaps.
    drop((later, across));
    // Joined outlines replace their fragments' own in place, block by block (the blocks
    // of the flaps): no fragment is moved.
    fragments
        .par_chunks_mut(FRAGMENTS_PER_TASK)
        .zip(parts.par_iter_mut())
        .for_each(|(block, (_, joined))| {
            for (i, (points, original_edges)) in joined.drain(..) {
                let f = &mut block[i % FRAGMENTS_PER_TASK];
                f.points = points;
                f.original_edges = original_edges;
            }
        });
    let separate = parts.iter().map(|p| p.0.len()).sum::<usize>();
    if separate == 0 {
        let at = (0..fragments.len()).collect();
        return (fragments, at);
    }
    // Flaps of their own are put in after their fragments. A smooth fragment's flaps
    // wait until the consecutive smooth fragments of its face are out (Phong pieces): a
    // flap between them would split the painters' run of the face. Every later face is
    // painted after that run, so each flap still comes first. The blocks' flaps stay in
    // their blocks (one vector of all of them was a copy of every flap in fresh memory).
    let n = fragments.len();
    // The flaps come in order of their fragments: a run's end is found once. The places
    // stay in order: a run's later fragments are smooth fragments of the run, whose
    // flaps go after the run's end too.
    let mut run_end = None;
    for flap in parts.iter_mut().flat_map(|p| p.0.iter_mut()) {
        let i = flap.from as usize;
        if fragments[i].vertex_colors.is_none() {
            continue;
        }
        let end = match run_end {
            Some(end) if i <= end => end,
            _ => {
                let face = fragments[i].face;
                let mut end = i;
                while end + 1 < n
                    && fragments[end + 1].face == face
                    && fragments[end + 1].vertex_colors.is_some()
                {
                    end += 1;
                }
                end
            }
        };
        run_end = Some(end);
        flap.after = end as u32;
    }
    let flaps = parts.into_iter().flat_map(|p| p.0);
    flaps_in_place(fragments, flaps, separate)
}

/// The `count` flaps (each with the index of the fragment it goes after, in order of
/// those indices) put into `fragments`, front to back: an item put in a place still
/// holding a fragment not yet placed sends that fragment to the back of a queue, and
/// each fragment comes from the front of the queue (or stays where it is). The blocks
/// of flaps are released as they are read and the queue's chunks as they are emptied,
/// so the flaps are held about once. Placed from the back, the whole room had to be
/// filled first (a vector of the final length) while every block was still held: a
/// million-face picture's 700,000 flaps were held twice, 90 MB more at the highest
/// point of its memory. The composed picture leaves room for the flaps (see
/// `compose.rs`), so that the fragments stay in their vector: a new vector of a large
/// picture's fragments cost more in fresh pages than the moves (118–156 ms of a cold
/// run on the 300² height fields). Also returns where each fragment went.
fn flaps_in_place(
    mut fragments: Vec<PaintFragment>,
    flaps: impl Iterator<Item = BlockFlap>,
    count: usize,
) -> (Vec<PaintFragment>, Vec<usize>) {
    let n = fragments.len();
    let mut at: Vec<usize> = Vec::with_capacity(n);
    // Exactly the room needed when there is none (growing by doubling would hold twice
    // the fragments' memory).
    fragments.reserve_exact(count);
    // Places `..write` are final; the fragments `at.len()..` not placed yet are those
    // in the queue, in order, then those in places `write..n`, each in its own.
    let mut waiting = ChunkedQueue::new();
    let mut write = 0;
    // Puts `item` in place `write`, sending a fragment there to the queue.
    let put = |fragments: &mut Vec<PaintFragment>,
               waiting: &mut ChunkedQueue<PaintFragment>,
               write: &mut usize,
               item| {
        if *write < n {
            waiting.push_back(std::mem::replace(&mut fragments[*write], item));
        } else {
            fragments.push(item);
        }
        *write += 1;
    };
    let mut flaps = flaps.peekable();
    for i in 0..n {
        if write == i {
            // Nothing placed before it that was not in a place of its own: it stays.
            write += 1;
        } else {
            let f = waiting
                .pop_front()
                .expect("the fragment waits in the queue");
            put(&mut fragments, &mut waiting, &mut write, f);
        }
        at.push(write - 1);
        while let Some(flap) = flaps.next_if(|flap| flap.after as usize == i) {
            // The fragment the flap was made of is in its place: it came no later.
            let of = at[flap.from as usize];
            let flap = flap.fragment(&fragments[of]);
            put(&mut fragments, &mut waiting, &mut write, flap);
        }
    }
    debug_assert!(flaps.next().is_none(), "every flap after a fragment");
    debug_assert_eq!(write, n + count);
    debug_assert!(waiting.is_empty(), "every fragment placed");
    (fragments, at)
}

/// A flap as its block keeps it until it is put in place: what is its own, the rest
/// taken from the fragment it was made of when it becomes a fragment
/// ([`BlockFlap::fragment`]). 96 bytes instead of a fragment's 136 and an index: a
/// million-face picture's 700,000 flaps are all held in their blocks before the first
/// is put in place.
/// Its indices are `u32`, as fragments' face ids are: a picture of 2³² fragments would
/// need more than half a terabyte.
#[derive(Debug)]
struct BlockFlap {
    /// The index of the fragment it is painted after.
    after: u32,
    /// The index of the fragment it was made of (its face, object and texture).
    from: u32,
    /// Whether it goes on with its fragment's texture.
    textured: bool,
    points: Vec<[f64; 2]>,
    fill: [f64; 4],
    vertex_colors: Option<Vec<VertexColor>>,
}

impl BlockFlap {
    /// The flap as a fragment of its own, with `of`, the fragment it was made of: none
    /// of its edges is original.
    fn fragment(self, of: &PaintFragment) -> PaintFragment {
        let original_edges = vec![false; self.points.len()];
        PaintFragment {
            points: self.points,
            fill: self.fill,
            vertex_colors: self.vertex_colors,
            face: of.face,
            object: of.object,
            original_edges,
            texture: if self.textured {
                of.texture.clone()
            } else {
                None
            },
            flap: true,
        }
    }
}

/// What a block of fragments makes: its flaps, and its fragments' joined outlines (with
/// their indices).
type BlockFlaps = (Vec<BlockFlap>, Vec<(usize, Outline)>);

/// A fragment's new corners and which of its edges are original.
type Outline = (Vec<[f64; 2]>, Vec<bool>);

/// The outline of flat, untextured fragment `f` with its `flaps` (as [`flaps_after`]
/// made them, in edge order) joined in: each shared edge `a → b` replaced by the flap's
/// boundary from `a` round to `b`, turning the way `f` turns. The result is `f` and its
/// flaps as one polygon (where flaps overlap, the nonzero rule fills them once).
/// `None` (the flaps stay separate) for a smooth or textured fragment, or when `f` or a
/// flap has no area or a flap does not hold the shared edge's end points exactly.
fn joined_outline(f: &PaintFragment, flaps: &[BlockFlap]) -> Option<Outline> {
    if f.vertex_colors.is_some() || f.texture.is_some() {
        return None;
    }
    let turn = area2(&f.points);
    if turn == 0.0 || !turn.is_finite() {
        return None;
    }
    let n = f.points.len();
    let extra: usize = flaps.iter().map(|fl| fl.points.len() - 2).sum();
    let mut points = Vec::with_capacity(n + extra);
    let mut original = Vec::with_capacity(n + extra);
    let mut flaps = flaps.iter().peekable();
    for e in 0..n {
        let (a, b) = (f.points[e], f.points[(e + 1) % n]);
        points.push(a);
        // Flaps come in edge order; the one of edge `e` starts at `a` and ends at `b`.
        let Some(fl) = flaps.next_if(|fl| holds_edge(&fl.points, a, b)) else {
            original.push(f.original_edges.get(e).copied().unwrap_or(false));
            continue;
        };
        let q = &fl.points;
        let m = q.len();
        let forward = area2(q);
        if forward == 0.0 || !forward.is_finite() {
            return None;
        }
        // Walking the flap the way `f` turns, its side on the shared edge runs b → a;
        // the rest of its boundary leads from a round to b.
        let step = |k: usize| {
            if (forward > 0.0) == (turn > 0.0) {
                (k + 1) % m
            } else {
                (k + m - 1) % m
            }
        };
        let mut k = q.iter().position(|&p| p == a)?;
        original.push(false);
        let before = points.len();
        loop {
            k = step(k);
            if q[k] == b {
                break;
            }
            points.push(q[k]);
            original.push(false);
        }
        // A flap on `f`'s own side of the edge (a fold) is not a detour: kept apart.
        if points.len() == before {
            return None;
        }
    }
    // Every flap must have found its edge.
    flaps.next().is_none().then_some((points, original))
}

/// Whether polygon `q` has `a` and `b` as consecutive corners (either way round).
fn holds_edge(q: &[[f64; 2]], a: [f64; 2], b: [f64; 2]) -> bool {
    let m = q.len();
    (0..m).any(|k| {
        let (p, r) = (q[k], q[(k + 1) % m]);
        (p == a && r == b) || (p == b && r == a)
    })
}

/// Twice the signed area of a polygon (shoelace).
fn area2(p: &[[f64; 2]]) -> f64 {
    let n = p.len();
    (0..n)
        .map(|i| {
            let (a, b) = (p[i], p[(i + 1) % n]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum()
}

/// Fragments per parallel task in [`seam_flaps_indexed`].
const FRAGMENTS_PER_TASK: usize = 2048;

/// Pushes onto `out` the flaps painted right after fragment `i` (`f`): one per edge it
/// shares with a later opaque fragment ([`LaterNeighbours`]).
fn flaps_after(
    fragments: &[PaintFragment],
    i: usize,
    f: &PaintFragment,
    (later, across, stroked): (&LaterNeighbours, &Across, &[bool]),
    (width, shapes): (f64, &mut HashMap<usize, Shape>),
    out: &mut Vec<BlockFlap>,
) {
    if !opaque(f) {
        return;
    }
    let n = f.points.len();
    // Later fragments already given whole as a flap of this one (see `flap`): a flap
    // along another of their edges would add nothing (a non-convex cover shares many
    // edges with its neighbour, and each such flap repeated all its corners). Nor is one
    // computed: a flap of a large non-convex fragment costs the square of its corners.
    let mut given_whole: Vec<usize> = Vec::new();
    for e in 0..n {
        let (a, b) = (f.points[e], f.points[(e + 1) % n]);
        if strokes_edge(stroked, f, e) {
            continue;
        }
        // The first fragment of another face painted after this one.
        let Some(j) = later.of(i, e) else {
            // Else later pieces of its own face and colour it meets at T-junctions: a
            // flap along their whole edge, in their (and its) colour.
            for (j, k) in across.of(i, e) {
                if given_whole.contains(&j) {
                    continue;
                }
                let q = &fragments[j].points;
                let (u, v) = (q[k], q[(k + 1) % q.len()]);
                if let Some(points) = flap_kept(q, (j, shapes), u, v, width) {
                    if points == *q {
                        given_whole.push(j);
                    }
                    out.push(flat_flap(i, f, points));
                }
            }
            continue;
        };
        if given_whole.contains(&j) {
            continue;
        }
        let q = &fragments[j].points;
        let m = q.len();
        if !stroked.is_empty()
            && (0..m).any(|k| {
                let (u, v) = (q[k], q[(k + 1) % m]);
                ((u == a && v == b) || (u == b && v == a))
                    && strokes_edge(stroked, &fragments[j], k)
            })
        {
            continue;
        }
        let Some(points) = flap_kept(q, (j, shapes), a, b, width) else {
            continue;
        };
        if points == fragments[j].points {
            given_whole.push(j);
        }
        // A smooth fragment's flap takes the colours along the edge (its flat fill, the
        // colour half-way, stands for them where one colour is drawn).
        let (fill, vertex_colors) = match &f.vertex_colors {
            Some(cs) if cs.len() == n => {
                let (ca, cb) = (wide_color(cs[e]), wide_color(cs[(e + 1) % n]));
                let fill = [0, 1, 2, 3].map(|k| {
                    if k == 3 {
                        f.fill[3]
                    } else {
                        0.5 * (ca[k] + cb[k])
                    }
                });
                let colors = points
                    .iter()
                    .map(|&p| narrow_color(along(a, b, ca, cb, p)))
                    .collect();
                (fill, Some(colors))
            }
            _ => (f.fill, None),
        };
        out.push(BlockFlap {
            after: i as u32,
            from: i as u32,
            // A textured flap goes on with the fragment's texture, under the same map.
            textured: f.texture.is_some(),
            points,
            fill,
            vertex_colors,
        });
    }
}

/// Whether the caller strokes edge `e` of fragment `f`: an original edge of a face
/// `stroked` marks (see [`seam_flaps_beside_strokes`]).
fn strokes_edge(stroked: &[bool], f: &PaintFragment, e: usize) -> bool {
    stroked.get(f.face as usize).copied().unwrap_or(false)
        && f.original_edges.get(e).copied().unwrap_or(false)
}

/// A flap of flat fragment `f`, fragment `i`, with corners `points`.
fn flat_flap(i: usize, f: &PaintFragment, points: Vec<[f64; 2]>) -> BlockFlap {
    BlockFlap {
        after: i as u32,
        from: i as u32,
        textured: false,
        points,
        fill: f.fill,
        vertex_colors: None,
    }
}

/// The colour at `p` of the ramp from `ca` at `a` to `cb` at `b`: the colours of edge
/// `a`–`b`, carried across it unchanged (`p` projected onto the edge, clamped to it).
fn along(a: [f64; 2], b: [f64; 2], ca: [f64; 4], cb: [f64; 4], p: [f64; 2]) -> [f64; 4] {
    let d = [b[0] - a[0], b[1] - a[1]];
    let dd = d[0] * d[0] + d[1] * d[1];
    let t = ((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / dd;
    let t = if t.is_finite() {
        t.clamp(0.0, 1.0)
    } else {
        0.5
    };
    [0, 1, 2, 3].map(|k| ca[k] + t * (cb[k] - ca[k]))
}

/// Whether `f` takes part in seam flaps: opaque, or a cut-out (its flap is drawn with
/// its texture and cut by the same texels as the fragment beyond the edge wherever the
/// texture runs on across it). Blended textures, as translucent fills, are not flapped:
/// a flap would blend twice.
fn opaque(f: &PaintFragment) -> bool {
    f.fill[3] >= 1.0
        && f.texture
            .as_ref()
            .is_none_or(|t| t.alpha != limn_scene::TextureAlpha::Blend)
}

/// For every edge of every opaque fragment, the first opaque fragment of another face
/// painted later that has the same edge (end points equal), or of its own face beyond
/// the edge and beyond a fragment of another face. Found by sorting all
/// edges by key, then paint order: the fragments sharing an edge become neighbours in
/// one vector, read front to back (a hash table of the edges cost a cache miss per
/// edge on large pictures).
struct LaterNeighbours {
    /// Where fragment `i`'s edges start in `first_later`.
    starts: Vec<usize>,
    /// Per edge: the fragment found, or [`NO_FRAGMENT`] (written by the parallel scan of
    /// the sorted edges, each by the one task that holds its edge).
    first_later: Vec<AtomicU32>,
}

/// No later fragment (in [`LaterNeighbours`]).
const NO_FRAGMENT: u32 = u32::MAX;

/// An edge to sort: the hash of its key, its fragment and its place in the fragment.
type HashedEdge = (u64, u32, u32);

impl LaterNeighbours {
    /// The neighbours of `fragments`. Fragments are counted in `u32`: a picture of
    /// `u32::MAX` fragments or more (hundreds of gigabytes) gets no flaps.
    fn new(fragments: &[PaintFragment]) -> Self {
        let n = fragments.len();
        let key = |j: usize, e: u32| {
            let p = &fragments[j].points;
            edge_key(p[e as usize], p[(e as usize + 1) % p.len()])
        };
        let mut starts = Vec::with_capacity(n + 1);
        let mut count = 0;
        for f in fragments {
            starts.push(count);
            if opaque(f) {
                count += f.points.len();
            }
        }
        starts.push(count);
        let first_later: Vec<AtomicU32> = (0..count)
            .into_par_iter()
            .with_min_len(EDGES_PER_TASK)
            .map(|_| AtomicU32::new(NO_FRAGMENT))
            .collect();
        if u32::try_from(n).is_err() {
            return LaterNeighbours {
                starts,
                first_later,
            };
        }
        // Each edge as (hash of its key, fragment, edge): smaller than the key itself
        // to sort. A total order (fragment and edge are unique), so the same result
        // from any sort; edges with equal hashes are told apart by their keys below.
        // Written in blocks of fragments in parallel, each block into its own places.
        let mut edges: Vec<HashedEdge> = vec![(0, 0, 0); count];
        let mut blocks = Vec::with_capacity(n.div_ceil(FRAGMENTS_PER_TASK));
        let mut rest = edges.as_mut_slice();
        for b in (0..n).step_by(FRAGMENTS_PER_TASK) {
            let end = (b + FRAGMENTS_PER_TASK).min(n);
            let (mine, more) = std::mem::take(&mut rest).split_at_mut(starts[end] - starts[b]);
            blocks.push((b..end, mine));
            rest = more;
        }
        blocks.into_par_iter().for_each(|(block, out)| {
            let mut places = out.iter_mut();
            for j in block {
                if !opaque(&fragments[j]) {
                    continue;
                }
                for (e, place) in (0..fragments[j].points.len() as u32).zip(&mut places) {
                    *place = (key_hash(&key(j, e)), j as u32, e);
                }
            }
        });
        edges.par_sort_unstable();
        // Which stretch of consecutive fragments of one face each fragment is in: a piece
        // of a face gets flaps into the later pieces of its face across an edge (running
        // the other way round: on the other side) when other faces are painted between
        // them, which the writers cannot draw as one path with it.
        let mut stretch = Vec::with_capacity(n);
        let mut count = 0u32;
        for (j, f) in fragments.iter().enumerate() {
            if j > 0 && (f.face, f.object) != (fragments[j - 1].face, fragments[j - 1].object) {
                count += 1;
            }
            stretch.push(count);
        }
        let opposite = |i: usize, e: u32, j: usize, f: u32| {
            let (p, q) = (&fragments[i].points, &fragments[j].points);
            let (e, f) = (e as usize, f as usize);
            p[e] == q[(f + 1) % q.len()] && p[(e + 1) % p.len()] == q[f]
        };
        // Groups of one hash, in parallel. A fragment's key and face are read only when
        // a later fragment has the same hash (in a mesh, one of an edge's two
        // fragments), and the candidates' only then.
        edges
            .par_chunk_by(|a, b| a.0 == b.0)
            .filter(|group| group.len() >= 2)
            .for_each(|group| {
                for (g, &(_, i, e)) in group.iter().enumerate() {
                    let i = i as usize;
                    let mut own = None;
                    let found = group[g + 1..].iter().find(|&&(_, j, f)| {
                        let j = j as usize;
                        if j <= i {
                            return false;
                        }
                        let (face, k) = *own.get_or_insert_with(|| (fragments[i].face, key(i, e)));
                        k == key(j, f)
                            && (fragments[j].face != face
                                || (stretch[j] != stretch[i] && opposite(i, e, j, f)))
                    });
                    if let Some(&(_, j, _)) = found {
                        first_later[starts[i] + e as usize].store(j, Ordering::Relaxed);
                    }
                }
            });
        LaterNeighbours {
            starts,
            first_later,
        }
    }

    /// The first later fragment of another face (or of `i`'s, see [`LaterNeighbours`])
    /// sharing edge `e` of fragment `i`.
    fn of(&self, i: usize, e: usize) -> Option<usize> {
        let j = self.first_later[self.starts[i] + e].load(Ordering::Relaxed);
        (j != NO_FRAGMENT).then_some(j as usize)
    }
}

/// Edges per parallel task of [`LaterNeighbours::new`], at least.
const EDGES_PER_TASK: usize = 8192;

/// The flap along edge `a`–`b` of later fragment `poly`: the part of `poly` within `width`
/// of the line through `a` and `b`, by clipping `poly` with one half-plane, kept only where
/// it is shown to lie inside `poly`, exactly, so that `poly`, painted later, covers all of
/// it. Where rounding put a crossing of the half-plane's line with an edge of `poly`
/// outside that edge, the crossing is moved towards the inside (to a point found in a few
/// steps and checked exactly).
///
/// The flap is kept when it is all of `poly` (the same polygon), or when every corner
/// passes [`inside_edges`]: the crossings, checked one by one, and `poly`'s own corners,
/// which do when `poly` is convex ([`convex`]). Otherwise (`poly` turning the other way
/// somewhere, as rounded corners a few ulps apart can make it) the flap's corners other
/// than `a`, `b` and the crossings are left out, and the rest is kept if it is a convex
/// triangle or quadrilateral that [`convex_inside`] shows to lie in `poly`; if not, with
/// the crossings drawn 1/16, then 1/4 of the way towards their middle (clear of corners
/// of `poly` next to `a` and `b`); if not, the flap is all of `poly` (the same polygon,
/// painted again later: no pixel it covers differs). `None` when `poly` has no edge
/// `a`–`b` or no area.
pub(crate) fn flap(
    poly: &[[f64; 2]],
    a: [f64; 2],
    b: [f64; 2],
    width: f64,
) -> Option<Vec<[f64; 2]>> {
    flap_into(poly, &mut Shape::default(), a, b, width)
}

/// Later fragments of more corners than this have what their flaps find out kept
/// ([`Shape`]); for fewer, asking again costs less than keeping the answers (a mesh's
/// triangles: a table entry per flap cost a tenth of a million-face picture's time).
const SHAPE_KEPT_ABOVE: usize = 8;

/// [`flap`] into later fragment `j` (corners `poly`), with what is known of it kept in
/// `shapes` when it has many corners.
fn flap_kept(
    poly: &[[f64; 2]],
    (j, shapes): (usize, &mut HashMap<usize, Shape>),
    a: [f64; 2],
    b: [f64; 2],
    width: f64,
) -> Option<Vec<[f64; 2]>> {
    if poly.len() > SHAPE_KEPT_ABOVE {
        flap_into(poly, shapes.entry(j).or_default(), a, b, width)
    } else {
        flap(poly, a, b, width)
    }
}

/// What [`flap`] finds out about a later fragment, kept for its other flaps into the same
/// fragment (a fragment meets a long later neighbour along many edges, and each flap
/// asked the same questions of all its corners again): the way it turns, whether it is
/// convex, and per corner whether it passes [`inside_edges`], each found when first
/// needed.
#[derive(Debug, Default)]
pub(crate) struct Shape {
    side: Option<Option<f64>>,
    convex: Option<bool>,
    corners_inside: Vec<Option<bool>>,
}

impl Shape {
    /// [`orientation`] of `poly`.
    fn side(&mut self, poly: &[[f64; 2]]) -> Option<f64> {
        *self.side.get_or_insert_with(|| orientation(poly))
    }

    /// [`convex`] of `poly`, turning `side`.
    fn convex(&mut self, poly: &[[f64; 2]], side: f64) -> bool {
        *self.convex.get_or_insert_with(|| convex(poly, side))
    }

    /// [`inside_edges`] of `poly`'s corner `c`.
    fn corner_inside(&mut self, poly: &[[f64; 2]], side: f64, c: usize) -> bool {
        if self.corners_inside.len() != poly.len() {
            self.corners_inside = vec![None; poly.len()];
        }
        *self.corners_inside[c].get_or_insert_with(|| inside_edges(poly, side, poly[c]))
    }
}

/// [`flap`], with what is known of `poly` in `shape` (and what it finds out kept there).
pub(crate) fn flap_into(
    poly: &[[f64; 2]],
    shape: &mut Shape,
    a: [f64; 2],
    b: [f64; 2],
    width: f64,
) -> Option<Vec<[f64; 2]>> {
    let m = poly.len();
    // The edge as `poly` runs along it, u → v.
    let k = (0..m).find(|&k| {
        let (p, q) = (poly[k], poly[(k + 1) % m]);
        (p == a && q == b) || (p == b && q == a)
    })?;
    let (u, v) = (poly[k], poly[(k + 1) % m]);
    let d = [v[0] - u[0], v[1] - u[1]];
    let len = d[0].hypot(d[1]);
    if len.is_nan() || len <= 0.0 {
        return None;
    }
    // The way `poly` turns: its inside lies on that side of each of its edges.
    let side = shape.side(poly)?;
    // The normal of u → v towards the inside: turn(u, v, x) = (x − u) · (−d₁, d₀).
    let nrm = [-side * d[1] / len, side * d[0] / len];
    // Keep the points with distance(x) = nrm·(x − a) ≤ width.
    let dist = |p: [f64; 2]| (p[0] - a[0]) * nrm[0] + (p[1] - a[1]) * nrm[1] - width;
    // Where crossings that rounding put outside are moved towards: the mean corner.
    let c = poly
        .iter()
        .fold([0.0, 0.0], |s, p| [s[0] + p[0], s[1] + p[1]]);
    let c = [c[0] / m as f64, c[1] / m as f64];
    let mut out = Vec::with_capacity(m + 2);
    // Per point of `out`: the corner of `poly` it is, or `None` for a crossing.
    let mut corner = Vec::with_capacity(m + 2);
    let mut crossings_inside = true;
    for k in 0..m {
        let (p, q) = (poly[k], poly[(k + 1) % m]);
        let (dp, dq) = (dist(p), dist(q));
        if dp <= 0.0 {
            out.push(p);
            corner.push(Some(k));
        }
        if (dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0) {
            let t = dp / (dp - dq);
            let x = [p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])];
            // In a convex `poly`, a point in the triangle of `p`, `q` and a corner across
            // passes every edge (the triangle lies in the half-plane of each, as its
            // corners do): three exact turns instead of one per edge.
            let r = poly[(k + 1 + m / 2) % m];
            let (x, inside) = if shape.convex(poly, side)
                && [(p, q), (q, r), (r, p)]
                    .iter()
                    .all(|&(u, v)| turn(u, v, x) * side >= 0.0)
            {
                (x, true)
            } else {
                inside_towards(poly, side, (p, q), x, c)
            };
            crossings_inside &= inside;
            out.push(x);
            // A crossing rounded onto an end of its edge is that corner.
            corner.push(if x == p {
                Some(k)
            } else if x == q {
                Some((k + 1) % m)
            } else {
                None
            });
        }
    }
    if out.len() < 3 || !has_area(&out) {
        return None;
    }
    if out == poly
        || (crossings_inside && shape.convex(poly, side))
        || out.iter().zip(&corner).all(|(&x, &c)| match c {
            Some(c) => shape.corner_inside(poly, side, c),
            None => inside_edges(poly, side, x),
        })
    {
        return Some(out);
    }
    let crossing = corner.iter().map(Option::is_none);
    // Only `a`, `b` and the crossings (the corners that are not corners of `poly`), these
    // drawn towards their middle if the chord between them cuts a corner of `poly` off.
    let q: Vec<([f64; 2], bool)> = out
        .into_iter()
        .zip(crossing)
        .filter(|&(p, crossing)| crossing || p == a || p == b)
        .collect();
    let crossings = q.iter().filter(|&&(_, crossing)| crossing).count() as f64;
    let mid = q
        .iter()
        .filter(|&&(_, crossing)| crossing)
        .fold([0.0, 0.0], |s, &(p, _)| [s[0] + p[0], s[1] + p[1]]);
    let mid = [mid[0] / crossings, mid[1] / crossings];
    let q = [0.0, 0.0625, 0.25].into_iter().find_map(|t| {
        let q: Vec<[f64; 2]> = q
            .iter()
            .map(|&(p, crossing)| {
                if crossing {
                    [p[0] + t * (mid[0] - p[0]), p[1] + t * (mid[1] - p[1])]
                } else {
                    p
                }
            })
            .collect();
        convex_inside(poly, &q).then_some(q)
    });
    // Else all of `poly`: the same polygon covers itself.
    q.or_else(|| Some(poly.to_vec()))
}

/// Whether `q`, a triangle or quadrilateral turning one way (convex, with area), lies in
/// the closed region polygon `poly` fills (the nonzero rule: either way round), decided
/// exactly: no edge of `poly` meets the inside of `q` (each is separated from it by the
/// line of an edge of `q` or by its own line), so `poly` winds the same number of times
/// round every point inside `q`; and that number, at a point found inside `q`, is not 0.
fn convex_inside(poly: &[[f64; 2]], q: &[[f64; 2]]) -> bool {
    let n = q.len();
    if !(3..=4).contains(&n) {
        return false;
    }
    // The lines of `q`'s edges separate only if `q` is convex (no turn back along a line).
    let Some(qs) = orientation(q) else {
        return false;
    };
    if !convex(q, qs) {
        return false;
    }
    let m = poly.len();
    let separated = |s: [f64; 2], e: [f64; 2]| {
        (0..n).any(|k| {
            let (u, v) = (q[k], q[(k + 1) % n]);
            turn(u, v, s) * qs <= 0.0 && turn(u, v, e) * qs <= 0.0
        }) || (s != e && {
            let sides: Vec<f64> = q.iter().map(|&c| turn(s, e, c)).collect();
            sides.iter().all(|&o| o >= 0.0) || sides.iter().all(|&o| o <= 0.0)
        })
    };
    if !(0..m).all(|k| separated(poly[k], poly[(k + 1) % m])) {
        return false;
    }
    // A point strictly inside `q` (its mean corner, if rounding leaves it there).
    let y = q.iter().fold([0.0, 0.0], |s, p| [s[0] + p[0], s[1] + p[1]]);
    let y = [y[0] / n as f64, y[1] / n as f64];
    (0..n).all(|k| turn(q[k], q[(k + 1) % n], y) * qs > 0.0) && winding(poly, y) != 0
}

/// Whether `x` lies on side `side` (the sign of [`turn`]) of every edge of `poly`, or on
/// an edge's line, decided exactly. Such points form a convex set, inside `poly` where it
/// has an inside: at a point strictly on that side of every edge, each edge turns the same
/// way round it, so `poly` winds round it and the nonzero rule fills it. A polygon with
/// area whose corners all pass lies in that set (which then has an inside), so inside
/// `poly`.
fn inside_edges(poly: &[[f64; 2]], side: f64, x: [f64; 2]) -> bool {
    let m = poly.len();
    (0..m).all(|k| turn(poly[k], poly[(k + 1) % m], x) * side >= 0.0)
}

/// How many times `poly` winds round `y` (which must not lie on an edge), exactly: the
/// signed crossings of the ray from `y` towards +x.
fn winding(poly: &[[f64; 2]], y: [f64; 2]) -> i32 {
    let m = poly.len();
    let mut w = 0;
    for k in 0..m {
        let (p, q) = (poly[k], poly[(k + 1) % m]);
        if p[1] <= y[1] {
            if q[1] > y[1] && turn(p, q, y) > 0.0 {
                w += 1;
            }
        } else if q[1] <= y[1] && turn(p, q, y) < 0.0 {
            w -= 1;
        }
    }
    w
}

/// A crossing `x` computed on edge `e` of `poly` (turning `side`), moved inside if
/// rounding put it out, and whether it passes [`inside_edges`]: `x` if it does, else the
/// first point on the way from `x` to `c` (at 2⁻⁴⁸, 2⁻⁴⁴, …, 2⁻⁴ and ½ of the way) that
/// does, else the first one on the inner side of `e` at least, else `x` ([`flap`]
/// decides what to keep).
fn inside_towards(
    poly: &[[f64; 2]],
    side: f64,
    e: ([f64; 2], [f64; 2]),
    x: [f64; 2],
    c: [f64; 2],
) -> ([f64; 2], bool) {
    if inside_edges(poly, side, x) {
        return (x, true);
    }
    let towards = [c[0] - x[0], c[1] - x[1]];
    let steps = || {
        (0..=12)
            .map(|e| {
                if e == 12 {
                    0.5
                } else {
                    (-48.0 + 4.0 * e as f64).exp2()
                }
            })
            .map(|s| [x[0] + s * towards[0], x[1] + s * towards[1]])
    };
    if let Some(y) = steps().find(|&y| inside_edges(poly, side, y)) {
        return (y, true);
    }
    let y = steps()
        .find(|&y| turn(e.0, e.1, y) * side >= 0.0)
        .unwrap_or(x);
    (y, false)
}

/// Whether `poly`, turning `side` ([`orientation`]), is convex, exactly: no turn the other
/// way, no straight turn back along the same line, and its edges going round once (the
/// signs of their steps in y change at most twice round the polygon). Its corners then
/// pass [`inside_edges`].
fn convex(poly: &[[f64; 2]], side: f64) -> bool {
    let m = poly.len();
    if m == 3 {
        return true;
    }
    let step = |k: usize| {
        let (p, q) = (poly[k % m], poly[(k + 1) % m]);
        [q[0] - p[0], q[1] - p[1]]
    };
    // A step's direction along a line: the sign of its x, or of its y when x is 0 (exact:
    // a difference of two f64 has the sign of the exact difference).
    let along = |s: [f64; 2]| {
        if s[0] != 0.0 {
            s[0].signum()
        } else {
            s[1].signum()
        }
    };
    let turns_one_way = (0..m).all(|k| {
        let o = turn(poly[k], poly[(k + 1) % m], poly[(k + 2) % m]) * side;
        if o != 0.0 {
            return o > 0.0;
        }
        let (s, t) = (step(k), step(k + 1));
        s == [0.0, 0.0] || t == [0.0, 0.0] || along(s) == along(t)
    });
    if !turns_one_way {
        return false;
    }
    let signs: Vec<f64> = (0..m)
        .map(|k| step(k)[1])
        .filter(|&dy| dy != 0.0)
        .map(f64::signum)
        .collect();
    let changes = (0..signs.len())
        .filter(|&k| signs[k] != signs[(k + 1) % signs.len()])
        .count();
    changes <= 2
}

/// The way `poly` turns, exactly: the sign of the turn at its lowest-leftmost corner
/// (between the nearest other corners before and after it), which a simple polygon makes
/// the way it winds. `None` when that turn is straight (no area there).
fn orientation(poly: &[[f64; 2]]) -> Option<f64> {
    let m = poly.len();
    if m == 3 {
        let o = turn(poly[0], poly[1], poly[2]);
        return (o != 0.0).then(|| o.signum());
    }
    let lowest = (0..m).min_by(|&i, &j| {
        let (p, q) = (poly[i], poly[j]);
        p[0].total_cmp(&q[0]).then(p[1].total_cmp(&q[1]))
    })?;
    let v = poly[lowest];
    let before = (1..m)
        .map(|s| poly[(lowest + m - s) % m])
        .find(|&p| p != v)?;
    let after = (1..m).map(|s| poly[(lowest + s) % m]).find(|&p| p != v)?;
    let o = turn(before, v, after);
    (o != 0.0).then(|| o.signum())
}

/// Whether some three corners of `q` make a turn (exact): `q` encloses some area.
fn has_area(q: &[[f64; 2]]) -> bool {
    let Some(p) = q.iter().copied().find(|&p| p != q[0]) else {
        return false;
    };
    q.iter().any(|&r| turn(q[0], p, r) != 0.0)
}

/// The turn `p → q → r`: positive one way, negative the other, zero when the three are
/// collinear; its sign exact on the f64 coordinates (Shewchuk's adaptive predicate).
fn turn(p: [f64; 2], q: [f64; 2], r: [f64; 2]) -> f64 {
    let c = |p: [f64; 2]| robust::Coord { x: p[0], y: p[1] };
    robust::orient2d(c(p), c(q), c(r))
}

#[cfg(test)]
mod tests {
    use std::collections::HashMap;

    use super::*;

    /// A block holds a picture's flaps before any is put in place: guard their size.
    #[test]
    fn block_flaps_stay_compact() {
        assert!(std::mem::size_of::<BlockFlap>() <= 96);
    }

    /// The first implementation: one `Vec` of later fragments per edge key, and one of
    /// flaps per fragment. The reference the sorted edges are checked against.
    fn seam_flaps_reference(
        fragments: Vec<PaintFragment>,
        width: f64,
    ) -> (Vec<PaintFragment>, Vec<usize>) {
        let mut later: HashMap<EdgeKey, Vec<usize>> = HashMap::new();
        for (j, f) in fragments.iter().enumerate() {
            if !opaque(f) {
                continue;
            }
            let n = f.points.len();
            for i in 0..n {
                later
                    .entry(edge_key(f.points[i], f.points[(i + 1) % n]))
                    .or_default()
                    .push(j);
            }
        }
        let mut flaps: Vec<Vec<PaintFragment>> = vec![Vec::new(); fragments.len()];
        for (i, f) in fragments.iter().enumerate() {
            if !opaque(f) {
                continue;
            }
            let n = f.points.len();
            let mut given_whole = Vec::new();
            for e in 0..n {
                let (a, b) = (f.points[e], f.points[(e + 1) % n]);
                let Some(js) = later.get(&edge_key(a, b)) else {
                    continue;
                };
                // Of another face, or of this one on the other side of the edge with
                // another face painted between them.
                let beyond = |j: usize| {
                    let q = &fragments[j].points;
                    let m = q.len();
                    (0..m).any(|k| q[k] == b && q[(k + 1) % m] == a)
                        && (i..j)
                            .any(|k| (fragments[k].face, fragments[k].object) != (f.face, f.object))
                };
                let Some(&j) = js
                    .iter()
                    .find(|&&j| j > i && (fragments[j].face != f.face || beyond(j)))
                else {
                    continue;
                };
                if given_whole.contains(&j) {
                    continue;
                }
                if let Some(flap) = flap(&fragments[j].points, a, b, width) {
                    if flap == fragments[j].points {
                        given_whole.push(j);
                    }
                    let (fill, colors) = match &f.vertex_colors {
                        Some(cs) if cs.len() == n => {
                            let (ca, cb) = (wide_color(cs[e]), wide_color(cs[(e + 1) % n]));
                            let fill = [0, 1, 2, 3].map(|k| {
                                if k == 3 {
                                    f.fill[3]
                                } else {
                                    0.5 * (ca[k] + cb[k])
                                }
                            });
                            let colors = flap
                                .iter()
                                .map(|&p| narrow_color(along(a, b, ca, cb, p)))
                                .collect();
                            (fill, Some(colors))
                        }
                        _ => (f.fill, None),
                    };
                    let mut p = PaintFragment::new(flap, fill);
                    p.vertex_colors = colors;
                    p.flap = true;
                    p.texture = f.texture.clone();
                    p.face = f.face;
                    p.object = f.object;
                    p.original_edges = vec![false; p.points.len()];
                    flaps[i].push(p);
                }
            }
        }
        let mut out = Vec::new();
        let mut at = Vec::new();
        let mut waiting: Vec<PaintFragment> = Vec::new();
        for (f, fl) in fragments.into_iter().zip(flaps) {
            let smooth_run = out
                .last()
                .is_some_and(|l: &PaintFragment| l.face == f.face && l.vertex_colors.is_some());
            if !(smooth_run && f.vertex_colors.is_some()) {
                out.append(&mut waiting);
            }
            let smooth = f.vertex_colors.is_some();
            at.push(out.len());
            out.push(f);
            if smooth {
                waiting.extend(fl);
            } else {
                out.extend(fl);
            }
        }
        out.append(&mut waiting);
        (out, at)
    }

    /// Triangles of a 12 × 12 grid (two per cell, shared edges), in a shuffled order,
    /// with faces shared by runs of neighbours, some translucent, some smooth, and a few
    /// repeated (the same edge key many times).
    fn grid_fragments(seed: u64) -> Vec<PaintFragment> {
        let mut rng = seed;
        let mut next = move |n: u64| {
            rng = rng
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (rng >> 33) % n
        };
        let p = |x: u64, y: u64| [x as f64 * 7.5, y as f64 * 5.25];
        let mut frags = Vec::new();
        for x in 0..12 {
            for y in 0..12 {
                for tri in [
                    [p(x, y), p(x + 1, y), p(x + 1, y + 1)],
                    [p(x, y), p(x + 1, y + 1), p(x, y + 1)],
                ] {
                    let alpha = if next(7) == 0 { 0.5 } else { 1.0 };
                    let mut f = PaintFragment::new(tri.to_vec(), [0.2, 0.4, 0.6, alpha]);
                    f.face = next(40) as u32;
                    f.object = next(3) as u32;
                    if next(5) == 0 {
                        f.vertex_colors =
                            Some(vec![[0.1, 0.2, 0.3, alpha as f32], [0.9; 4], [0.5; 4]]);
                    }
                    frags.push(f);
                }
            }
        }
        for i in (1..frags.len()).rev() {
            frags.swap(i, next(i as u64 + 1) as usize);
        }
        for _ in 0..20 {
            let f = frags[next(frags.len() as u64) as usize].clone();
            frags.insert(next(frags.len() as u64) as usize, f);
        }
        frags
    }

    #[test]
    fn sorted_edges_give_the_reference_flaps() {
        for seed in 0..20 {
            let frags = grid_fragments(seed);
            let want = seam_flaps_reference(frags.clone(), 0.5);
            // Without room the vector grows first; with room for every flap the
            // fragments stay where they are.
            let (out, at) = seam_flaps_indexed(frags.clone(), 0.5, FlapJoin::Separate);
            assert!(out.len() > frags.len(), "seed {seed}: some flaps");
            assert_eq!((out, at), want, "seed {seed}");
            let mut roomy = Vec::with_capacity(4 * frags.len());
            roomy.extend(frags.iter().cloned());
            let (out, at) = seam_flaps_indexed(roomy, 0.5, FlapJoin::Separate);
            assert_eq!((out, at), want, "seed {seed}, in place");
        }
    }

    /// The picture of `frags` on a transparent page, without anti-aliasing.
    fn pixels(frags: Vec<PaintFragment>) -> Vec<u8> {
        use crate::{Picture, PngOptions, PngPainter};
        let mut pic = Picture::new(100, 70);
        pic.fragments = frags;
        let png = PngPainter::new(PngOptions {
            anti_alias: false,
            ..PngOptions::default()
        });
        let (pixmap, _) = png.render(&pic).expect("render");
        pixmap.data().to_vec()
    }

    #[test]
    fn joined_flaps_paint_the_same_pixels_as_separate_ones() {
        let mut joined_any = 0;
        for seed in 0..12 {
            let mut frags = grid_fragments(seed);
            // Fragments turning either way, at coordinates off the pixel grid.
            for (k, f) in frags.iter_mut().enumerate() {
                for p in &mut f.points {
                    *p = [p[0] * 0.9 + 0.37, p[1] + 0.21];
                }
                if k % 3 == 0 {
                    f.points.reverse();
                    if let Some(cs) = &mut f.vertex_colors {
                        cs.reverse();
                    }
                }
            }
            let (separate, _) = seam_flaps_indexed(frags.clone(), 2.0, FlapJoin::Separate);
            let (joined, at) = seam_flaps_indexed(frags.clone(), 2.0, FlapJoin::Joined);
            assert!(joined.len() < separate.len(), "seed {seed}: flaps joined");
            // Each input fragment is where `at` says, with its corners kept in order.
            for (i, f) in frags.iter().enumerate() {
                let g = &joined[at[i]];
                assert_eq!((g.face, g.fill), (f.face, f.fill), "seed {seed}");
                let mut corners = g.points.iter().filter(|p| f.points.contains(p));
                assert!(
                    f.points.iter().all(|p| corners.next() == Some(p)),
                    "seed {seed}"
                );
                if g.points.len() > f.points.len() {
                    joined_any += 1;
                    assert!(f.vertex_colors.is_none() && f.fill[3] >= 1.0, "seed {seed}");
                    assert!(g.original_edges.len() == g.points.len());
                }
            }
            assert_eq!(pixels(joined), pixels(separate), "seed {seed}");
        }
        assert!(joined_any > 100, "{joined_any} fragments with joined flaps");
    }

    #[test]
    fn a_flap_on_the_fragments_own_side_stays_separate() {
        // b overlaps a from a's side of their shared edge (a fold): no detour to join.
        let mut a = PaintFragment::new(vec![[0.0, 0.0], [10.0, 0.0], [10.0, 10.0]], [1.0; 4]);
        a.face = 0;
        let mut b = PaintFragment::new(vec![[0.0, 0.0], [10.0, 0.0], [9.0, 5.0]], [0.5; 4]);
        b.fill[3] = 1.0;
        b.face = 1;
        let (out, _) = seam_flaps_indexed(vec![a.clone(), b.clone()], 0.5, FlapJoin::Joined);
        assert_eq!(out.len(), 3, "{out:?}");
        assert_eq!(out[0].points, a.points);
        assert_eq!(
            pixels(out),
            pixels(seam_flaps_indexed(vec![a, b], 0.5, FlapJoin::Separate).0)
        );
    }

    /// How many times `poly` winds round `y`, or `None` when `y` lies on an edge (exact).
    fn winds(poly: &[[f64; 2]], y: [f64; 2]) -> Option<i32> {
        let m = poly.len();
        let mut w = 0;
        for k in 0..m {
            let (p, q) = (poly[k], poly[(k + 1) % m]);
            let within = |i: usize| p[i].min(q[i]) <= y[i] && y[i] <= p[i].max(q[i]);
            if turn(p, q, y) == 0.0 && within(0) && within(1) {
                return None;
            }
            if p[1] <= y[1] {
                if q[1] > y[1] && turn(p, q, y) > 0.0 {
                    w += 1;
                }
            } else if q[1] <= y[1] && turn(p, q, y) < 0.0 {
                w -= 1;
            }
        }
        Some(w)
    }

    /// Points near `p`: a few ulps off in each direction.
    fn around(p: [f64; 2]) -> impl Iterator<Item = [f64; 2]> {
        let step = |v: f64, k: i64| f64::from_bits((v.to_bits() as i64 + k) as u64);
        (-3..=3).flat_map(move |i| (-3..=3).map(move |j| [step(p[0], i), step(p[1], j)]))
    }

    /// Asserts that every point near the corners of `q` and on a grid over it that `q`
    /// fills, `poly` fills too (points on an edge of either are left out).
    fn assert_inside(q: &[[f64; 2]], poly: &[[f64; 2]], what: &str) {
        let (lo, hi) = q
            .iter()
            .fold(([f64::MAX; 2], [f64::MIN; 2]), |(lo, hi), p| {
                (
                    [lo[0].min(p[0]), lo[1].min(p[1])],
                    [hi[0].max(p[0]), hi[1].max(p[1])],
                )
            });
        let grid = (0..=40).flat_map(|i| {
            (0..=40).map(move |j| {
                let t = [i as f64 / 40.0, j as f64 / 40.0];
                [
                    lo[0] + t[0] * (hi[0] - lo[0]),
                    lo[1] + t[1] * (hi[1] - lo[1]),
                ]
            })
        });
        let near: Vec<[f64; 2]> = q.iter().chain(poly).flat_map(|&p| around(p)).collect();
        for y in grid.chain(near) {
            if let (Some(wq), Some(wp)) = (winds(q, y), winds(poly, y)) {
                assert!(
                    wq == 0 || wp != 0,
                    "{what}: {y:?} in the flap {q:?}, not in {poly:?}"
                );
            }
        }
    }

    #[test]
    fn flaps_lie_inside_the_later_triangle_however_far_its_corner() {
        let mut rng = 7u64;
        let mut next = move || {
            rng ^= rng << 13;
            rng ^= rng >> 7;
            rng ^= rng << 17;
            (rng >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut made = 0;
        for _ in 0..3000 {
            let a = [10.0 + 20.0 * next(), 10.0 + 20.0 * next()];
            let b = [a[0] + 1.0 + 10.0 * next(), a[1] + 10.0 * (next() - 0.5)];
            // The third corner 1 to 10¹³ px away, on either side of a–b.
            let far = 10f64.powf(13.0 * next());
            let c = [a[0] + far * (next() - 0.5), a[1] + far * (next() - 0.5)];
            let j = [a, b, c];
            let side = turn(a, b, c).signum();
            if side == 0.0 {
                continue;
            }
            let Some(q) = flap(&j, a, b, 0.5) else {
                continue;
            };
            made += 1;
            for x in &q {
                for k in 0..3 {
                    assert!(
                        turn(j[k], j[(k + 1) % 3], *x) * side >= 0.0,
                        "corner {x:?} of {q:?} outside {j:?}"
                    );
                }
            }
        }
        assert!(made > 2500, "{made} flaps");
    }

    #[test]
    fn flaps_into_fragments_whose_rounded_corners_turn_back_lie_inside_them() {
        // Fragments of two height fields 1e-6 apart as the exact ordering rounds them:
        // corners a few ulps apart, so that the outline turns back a little.
        let polys: [&[[f64; 2]]; 3] = [
            &[
                [572.0729321591806, 351.0551786280025],
                [581.9661419330993, 346.3159617122005],
                [571.6246000135313, 314.80090034161185],
                [572.0727834664935, 351.0550193807249],
                [572.0729321591807, 351.0551786280026],
            ],
            &[
                [237.924513390518, 469.9188319643267],
                [227.4063287864017, 474.0739464949276],
                [227.40601531533767, 474.07394076661217],
                [221.00680953502126, 460.38157342240174],
                [237.9246603265551, 469.9186404599667],
                [237.92466032655503, 469.9186404599667],
            ],
            &[
                [553.9399445071069, 287.63111485480096],
                [555.621326503819, 283.30780795630784],
                [552.929481859497, 288.10381358310855],
                [553.9396762324975, 287.63130584886],
                [553.9399445071069, 287.631114854801],
            ],
        ];
        for poly in polys {
            let m = poly.len();
            for k in 0..m {
                let (a, b) = (poly[k], poly[(k + 1) % m]);
                let q = flap(poly, a, b, 0.5);
                if (b[0] - a[0]).hypot(b[1] - a[1]) > 1.0 {
                    let q = q.as_ref().expect("a flap along every long edge");
                    assert!(holds_edge(q, a, b), "{q:?} holds {a:?}–{b:?}");
                }
                if let Some(q) = q {
                    assert_inside(&q, poly, &format!("edge {k}"));
                }
            }
        }
    }

    #[test]
    fn convex_is_decided_exactly() {
        let is_convex = |p: &[[f64; 2]]| convex(p, orientation(p).expect("turns"));
        let square = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0]];
        assert!(is_convex(&square));
        let mut back = square;
        back.reverse();
        assert!(is_convex(&back));
        // A corner in the middle of an edge, and a corner twice.
        assert!(is_convex(&[
            [0.0, 0.0],
            [2.0, 0.0],
            [4.0, 0.0],
            [4.0, 4.0],
            [0.0, 4.0]
        ]));
        assert!(is_convex(&[
            [0.0, 0.0],
            [4.0, 0.0],
            [4.0, 0.0],
            [4.0, 4.0],
            [0.0, 4.0]
        ]));
        // A spike out along an edge's line, a notch, a star going round twice.
        assert!(!is_convex(&[
            [0.0, 0.0],
            [6.0, 0.0],
            [4.0, 0.0],
            [4.0, 4.0],
            [0.0, 4.0]
        ]));
        assert!(!is_convex(&[
            [0.0, 0.0],
            [4.0, 0.0],
            [2.0, 1.0],
            [4.0, 4.0],
            [0.0, 4.0]
        ]));
        let star: Vec<[f64; 2]> = (0..5)
            .map(|k| {
                let a = std::f64::consts::TAU * (2 * k) as f64 / 5.0;
                [a.cos(), a.sin()]
            })
            .collect();
        assert!(!is_convex(&star));
        // Rounded corners a few ulps apart that turn back.
        let rounded = [
            [572.0729321591806, 351.0551786280025],
            [581.9661419330993, 346.3159617122005],
            [571.6246000135313, 314.80090034161185],
            [572.0727834664935, 351.0550193807249],
            [572.0729321591807, 351.0551786280026],
        ];
        assert!(!is_convex(&rounded));
    }

    #[test]
    fn a_later_fragment_given_whole_as_a_flap_is_given_once() {
        // A thin band bent along a zigzag, painted after the fragment below it whose top
        // is the same zigzag: every corner of the band lies within the flap's width of
        // each shared edge and the band is not convex, so each shared edge's flap is the
        // whole band. Once is enough: the band covers every shared edge.
        let zig: Vec<[f64; 2]> = (0..7)
            .map(|k| [10.0 * f64::from(k), if k % 2 == 0 { 0.0 } else { 3.0 }])
            .collect();
        let mut below = vec![[60.0, -20.0], [0.0, -20.0]];
        below.extend(zig.iter().copied());
        let mut band: Vec<[f64; 2]> = zig.iter().rev().copied().collect();
        band.extend(zig.iter().map(|p| [p[0], p[1] + 0.5]));
        let mut first = PaintFragment::new(below, [1.0, 0.0, 0.0, 1.0]);
        first.face = 0;
        let mut later = PaintFragment::new(band.clone(), [0.0, 0.0, 1.0, 1.0]);
        later.face = 1;
        let frags = vec![first, later];
        for out in [
            seam_flaps_indexed(frags.clone(), 1.0, FlapJoin::Separate).0,
            seam_flaps_reference(frags.clone(), 1.0).0,
        ] {
            let whole = out.iter().filter(|f| f.flap && f.points == band).count();
            assert_eq!(whole, 1);
        }
        // Joined into the fragment's outline: the band's corners once, not per edge.
        let (joined, _) = seam_flaps_indexed(frags, 1.0, FlapJoin::Joined);
        assert!(
            joined[0].points.len() <= 8 + band.len(),
            "{}",
            joined[0].points.len()
        );
    }

    #[test]
    fn an_edge_the_caller_strokes_gets_no_flap() {
        // Two squares of different faces sharing the edge x = 10; the right one is
        // painted later, so the left one gets a flap into it unless the edge is stroked.
        let square = |x0: f64| vec![[x0, 0.0], [x0 + 10.0, 0.0], [x0 + 10.0, 10.0], [x0, 10.0]];
        let mut left = PaintFragment::new(square(0.0), [1.0, 0.0, 0.0, 1.0]);
        left.face = 0;
        let mut right = PaintFragment::new(square(10.0), [0.0, 0.0, 1.0, 1.0]);
        right.face = 1;
        let flaps = |left: &PaintFragment, right: &PaintFragment, stroked: &[bool]| {
            let frags = vec![left.clone(), right.clone()];
            let (out, _) = seam_flaps_beside_strokes(frags, 1.0, FlapJoin::Separate, stroked);
            out.iter().filter(|f| f.flap).count()
        };
        assert_eq!(flaps(&left, &right, &[]), 1);
        assert_eq!(flaps(&left, &right, &[false, false]), 1);
        // Stroked by the earlier fragment, or by the later one: no flap.
        assert_eq!(flaps(&left, &right, &[true, false]), 0);
        assert_eq!(flaps(&left, &right, &[false, true]), 0);
        // A stroked face's edge that is not one of its own (a cut) is not stroked.
        let mut cut = left.clone();
        cut.original_edges = vec![true, false, true, true];
        assert_eq!(flaps(&cut, &right, &[true, false]), 1);
        let mut cut = right.clone();
        cut.original_edges = vec![true, true, true, false];
        assert_eq!(flaps(&left, &cut, &[false, true]), 1);
    }
}
