//! Mesh neighbours: prepared polygons that share an input edge used in opposite
//! directions. Two such polygons that face the eye alike never constrain each other, nor
//! do any pieces split from them.
//!
//! Why, exactly: a prepared polygon is convex and its corners turn counter-clockwise seen
//! from the front of its plane. Let polygon `P` have the edge `a → b` and `Q` the edge
//! `b → a`, and let `H` be the plane through the eye and `a`, `b` (for a view from
//! infinity: through `a`, `b` along the view direction). `P` is convex and contains `ab`,
//! and its plane does not hold the eye (polygons seen edge-on are culled), so `P` lies in
//! one closed half-space of `H`: the one where `orient3d(eye, a, b, c)` has the sign its
//! corners turn with as seen from the eye. `Q` turns the same way (it faces the eye
//! alike) along `b → a`, so it lies in the other half-space. Rays from the eye stay in
//! their half-space of `H`, so the projections of `P` and `Q` lie on the two sides of the
//! projected line `ab` and only touch along it: neither can hide any part of the other.
//! Every piece split from `P` (or clipped from it) lies inside `P`, so the same holds for
//! pieces. Only polygons that were not clipped at the near plane are recorded here, so
//! that their corners are input points (compared by canonical vertex id, that is bit for
//! bit); a polygon left out only costs the pair tests it would have saved.

use rayon::prelude::*;

/// An edge of a prepared polygon: the canonical vertex ids of its ends (smaller first),
/// whether the polygon runs along it from the larger to the smaller, and the polygon's
/// piece id (see [`mesh_edge`]).
pub(crate) type MeshEdge = (u32, u32, bool, u32);

/// The edge from vertex `a` to vertex `b` of polygon `polygon`.
#[inline]
pub(crate) fn mesh_edge(a: u32, b: u32, polygon: u32) -> MeshEdge {
    (a.min(b), a.max(b), a > b, polygon)
}

/// Edges shared by more polygons than this (non-manifold fans) are left out, so that the
/// table stays linear in the number of edges.
const MAX_SHARING: usize = 8;

/// For each prepared polygon (by piece id), the polygons that share one of its edges in
/// the opposite direction, in compressed rows.
#[derive(Debug, Default)]
pub(crate) struct MeshNeighbours {
    /// Where polygon `r`'s neighbours start in `list` (`r` past the end: none).
    start: Vec<u32>,
    /// Neighbours, sorted within each polygon's row.
    list: Vec<u32>,
}

impl MeshNeighbours {
    /// The table of the directed `edges` of polygons `0..polygons`.
    pub fn new(mut edges: Vec<MeshEdge>, polygons: usize) -> Self {
        // Undirected edge, then direction, then polygon: a total order, so the table does
        // not depend on the sort or on threads.
        edges.par_sort_unstable();
        let mut pairs: Vec<(u32, u32)> = Vec::new();
        for group in edges.chunk_by(|x, y| (x.0, x.1) == (y.0, y.1)) {
            if group.len() < 2 || group.len() > MAX_SHARING {
                continue;
            }
            for x in group.iter().filter(|x| !x.2) {
                for y in group.iter().filter(|y| y.2 && y.3 != x.3) {
                    pairs.push((x.3, y.3));
                    pairs.push((y.3, x.3));
                }
            }
        }
        pairs.par_sort_unstable();
        pairs.dedup();
        let mut start = vec![0u32; polygons + 1];
        for &(r, _) in &pairs {
            start[r as usize + 1] += 1;
        }
        for i in 0..polygons {
            start[i + 1] += start[i];
        }
        let list = pairs.into_iter().map(|(_, s)| s).collect();
        MeshNeighbours { start, list }
    }

    /// Whether polygons `r` and `s` share an edge used in opposite directions.
    #[inline]
    pub fn contains(&self, r: u32, s: u32) -> bool {
        let r = r as usize;
        if r + 1 >= self.start.len() {
            return false;
        }
        self.list[self.start[r] as usize..self.start[r + 1] as usize].contains(&s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn opposite_edges_make_neighbours_and_same_directions_do_not() {
        // Polygon 0: 1→2→3; polygon 1: 2→1→4 (shares 1–2 reversed); polygon 2: 1→2→5
        // (shares 1→2 in the same direction as polygon 0: not a mesh neighbour);
        // polygon 3: 3→2→6 (shares 2–3 reversed with polygon 0).
        let tri = |r: u32, v: [u32; 3]| {
            [
                mesh_edge(v[0], v[1], r),
                mesh_edge(v[1], v[2], r),
                mesh_edge(v[2], v[0], r),
            ]
        };
        let mut edges = Vec::new();
        edges.extend(tri(0, [1, 2, 3]));
        edges.extend(tri(1, [2, 1, 4]));
        edges.extend(tri(2, [1, 2, 5]));
        edges.extend(tri(3, [3, 2, 6]));
        let nb = MeshNeighbours::new(edges, 5);
        assert!(nb.contains(0, 1) && nb.contains(1, 0));
        assert!(nb.contains(0, 3) && nb.contains(3, 0));
        assert!(nb.contains(2, 1) && nb.contains(1, 2));
        assert!(!nb.contains(0, 2) && !nb.contains(2, 0));
        assert!(!nb.contains(1, 3) && !nb.contains(0, 0));
        assert!(!nb.contains(4, 0) && !nb.contains(99, 0));
    }

    #[test]
    fn crowded_edges_are_left_out() {
        let mut edges = Vec::new();
        for r in 0..(MAX_SHARING as u32 + 1) {
            edges.push(if r % 2 == 0 {
                mesh_edge(7, 8, r)
            } else {
                mesh_edge(8, 7, r)
            });
        }
        let nb = MeshNeighbours::new(edges, MAX_SHARING + 1);
        assert!(!nb.contains(0, 1));
        let nb = MeshNeighbours::new(vec![mesh_edge(7, 8, 0), mesh_edge(8, 7, 1)], 2);
        assert!(nb.contains(0, 1));
    }
}
