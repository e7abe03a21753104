//! Seam flaps: closing the hairlines viewers leave between adjacent fills without moving
//! any boundary of the picture.

use crate::PaintFragment;

/// The bits of an edge's end points, smaller end first (an undirected edge key).
type EdgeKey = ([u64; 2], [u64; 2]);

fn edge_key(a: [f64; 2], b: [f64; 2]) -> EdgeKey {
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
/// with an opaque fragment of another face painted *later*, a flap in the first
/// fragment's colour (for a smooth fragment: the mean of the edge's end colours, flat)
/// is painted right after it: the part of the later fragment within
/// `width` pixels of the shared edge. The later fragment covers its flaps entirely, so
/// the picture stays exactly the same at every point (the flap only fills the
/// anti-aliased pixels under the shared edge): silhouettes, edges against faces painted
/// earlier and translucent faces get no flap.
pub fn seam_flaps(fragments: Vec<PaintFragment>, width: f64) -> Vec<PaintFragment> {
    seam_flaps_indexed(fragments, width).0
}

/// [`seam_flaps`], also returning where each input fragment went in the output (so that
/// marks placed among the fragments can follow them).
pub fn seam_flaps_indexed(
    fragments: Vec<PaintFragment>,
    width: f64,
) -> (Vec<PaintFragment>, Vec<usize>) {
    let later = LaterNeighbours::new(&fragments);
    // The flaps first (they read the later fragments), in the order of the fragments
    // they follow; then the fragments moved into the output with their flaps after
    // them: no fragment is copied.
    let mut flaps: Vec<(usize, PaintFragment)> = Vec::new();
    for (i, f) in fragments.iter().enumerate() {
        if !opaque(f) {
            continue;
        }
        let n = f.points.len();
        for e in 0..n {
            let (a, b) = (f.points[e], f.points[(e + 1) % n]);
            // The first fragment of another face painted after this one.
            let Some(j) = later.of(i, e) else {
                continue;
            };
            if let Some(points) = flap(&fragments[j].points, a, b, width) {
                // A smooth fragment's flap takes the colour half-way along the edge.
                let fill = match &f.vertex_colors {
                    Some(cs) if cs.len() == n => {
                        let (ca, cb) = (cs[e], cs[(e + 1) % n]);
                        [0, 1, 2, 3].map(|k| {
                            if k == 3 {
                                f.fill[3]
                            } else {
                                0.5 * (ca[k] + cb[k])
                            }
                        })
                    }
                    _ => f.fill,
                };
                let original_edges = vec![false; points.len()];
                flaps.push((
                    i,
                    PaintFragment {
                        points,
                        fill,
                        vertex_colors: None,
                        // A textured flap goes on with the fragment's texture, under the
                        // same map.
                        texture: f.texture,
                        face: f.face,
                        object: f.object,
                        original_edges,
                    },
                ));
            }
        }
    }
    // A smooth fragment's flaps wait until the consecutive smooth fragments of its face
    // are out (Phong pieces): a flap between them would split the painters' run of the
    // face. Every later face is painted after that run, so each flap still comes first.
    let mut out = Vec::with_capacity(fragments.len() + flaps.len());
    let mut at = Vec::with_capacity(fragments.len());
    let mut waiting: Vec<PaintFragment> = Vec::new();
    let mut flaps = flaps.into_iter().peekable();
    for (i, f) in fragments.into_iter().enumerate() {
        let smooth_run = out
            .last()
            .is_some_and(|l: &PaintFragment| l.face == f.face && l.vertex_colors.is_some());
        if !(smooth_run && f.vertex_colors.is_some()) {
            out.append(&mut waiting);
        }
        let smooth = f.vertex_colors.is_some();
        at.push(out.len());
        out.push(f);
        while let Some((_, fl)) = flaps.next_if(|(k, _)| *k == i) {
            if smooth {
                waiting.push(fl);
            } else {
                out.push(fl);
            }
        }
    }
    out.append(&mut waiting);
    (out, at)
}

fn opaque(f: &PaintFragment) -> bool {
    f.fill[3] >= 1.0
}

/// For every edge of every opaque fragment, the first opaque fragment of another face
/// painted later that has the same edge (end points equal). Found by sorting all
/// edges by key, then paint order: the fragments sharing an edge become neighbours in
/// one vector, read front to back (a hash table of the edges cost a cache miss per
/// edge on large pictures).
struct LaterNeighbours {
    /// Where fragment `i`'s edges start in `first_later`.
    starts: Vec<usize>,
    /// Per edge: the fragment found, or `usize::MAX`.
    first_later: Vec<usize>,
}

impl LaterNeighbours {
    fn new(fragments: &[PaintFragment]) -> Self {
        let mut starts = Vec::with_capacity(fragments.len() + 1);
        let mut edges: Vec<(EdgeKey, usize, usize)> = Vec::new();
        for (j, f) in fragments.iter().enumerate() {
            starts.push(edges.len());
            if !opaque(f) {
                continue;
            }
            let n = f.points.len();
            for e in 0..n {
                edges.push((edge_key(f.points[e], f.points[(e + 1) % n]), j, e));
            }
        }
        starts.push(edges.len());
        // A total order on (key, fragment, edge): the same result from any sort.
        edges.sort_unstable();
        let mut first_later = vec![usize::MAX; edges.len()];
        for group in edges.chunk_by(|a, b| a.0 == b.0) {
            if group.len() < 2 {
                continue;
            }
            for &(_, i, e) in group {
                let face = fragments[i].face;
                if let Some(&(_, j, _)) = group
                    .iter()
                    .find(|&&(_, j, _)| j > i && fragments[j].face != face)
                {
                    first_later[starts[i] + e] = j;
                }
            }
        }
        LaterNeighbours {
            starts,
            first_later,
        }
    }

    /// The first later fragment of another face sharing edge `e` of fragment `i`.
    fn of(&self, i: usize, e: usize) -> Option<usize> {
        let j = self.first_later[self.starts[i] + e];
        (j != usize::MAX).then_some(j)
    }
}

/// The part of `poly` within `width` of the line through `a` and `b` (on `poly`'s side),
/// by clipping `poly` with one half-plane; `None` when it is degenerate.
fn flap(poly: &[[f64; 2]], a: [f64; 2], b: [f64; 2], width: f64) -> Option<Vec<[f64; 2]>> {
    let d = [b[0] - a[0], b[1] - a[1]];
    let len = d[0].hypot(d[1]);
    if len.is_nan() || len <= 0.0 {
        return None;
    }
    let mut nrm = [-d[1] / len, d[0] / len];
    // Point the normal into the polygon (towards its centroid).
    let c = poly
        .iter()
        .fold([0.0, 0.0], |s, p| [s[0] + p[0], s[1] + p[1]]);
    let c = [c[0] / poly.len() as f64, c[1] / poly.len() as f64];
    if (c[0] - a[0]) * nrm[0] + (c[1] - a[1]) * nrm[1] < 0.0 {
        nrm = [-nrm[0], -nrm[1]];
    }
    // Keep the points with distance(x) = nrm·(x − a) ≤ width.
    let dist = |p: [f64; 2]| (p[0] - a[0]) * nrm[0] + (p[1] - a[1]) * nrm[1] - width;
    let mut out = Vec::with_capacity(poly.len() + 2);
    for k in 0..poly.len() {
        let (p, q) = (poly[k], poly[(k + 1) % poly.len()]);
        let (dp, dq) = (dist(p), dist(q));
        if dp <= 0.0 {
            out.push(p);
        }
        if (dp < 0.0 && dq > 0.0) || (dp > 0.0 && dq < 0.0) {
            let t = dp / (dp - dq);
            out.push([p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])]);
        }
    }
    (out.len() >= 3).then_some(out)
}

#[cfg(test)]
mod tests {
    use std::collections::HashMap;

    use super::*;

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
            for e in 0..n {
                let (a, b) = (f.points[e], f.points[(e + 1) % n]);
                let Some(js) = later.get(&edge_key(a, b)) else {
                    continue;
                };
                let Some(&j) = js.iter().find(|&&j| j > i && fragments[j].face != f.face) else {
                    continue;
                };
                if let Some(flap) = flap(&fragments[j].points, a, b, width) {
                    let fill = match &f.vertex_colors {
                        Some(cs) if cs.len() == n => {
                            let (ca, cb) = (cs[e], cs[(e + 1) % n]);
                            [0, 1, 2, 3].map(|k| {
                                if k == 3 {
                                    f.fill[3]
                                } else {
                                    0.5 * (ca[k] + cb[k])
                                }
                            })
                        }
                        _ => f.fill,
                    };
                    let mut p = PaintFragment::new(flap, fill);
                    p.texture = f.texture;
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
                        f.vertex_colors = Some(vec![[0.1, 0.2, 0.3, alpha], [0.9; 4], [0.5; 4]]);
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
            let (out, at) = seam_flaps_indexed(frags.clone(), 0.5);
            assert!(out.len() > frags.len(), "seed {seed}: some flaps");
            assert_eq!((out, at), seam_flaps_reference(frags, 0.5), "seed {seed}");
        }
    }
}
