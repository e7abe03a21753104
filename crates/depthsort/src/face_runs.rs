//! A topological order of the components of an occlusion graph that keeps the pieces of
//! one face together wherever the graph allows.
//!
//! Any topological order paints the same picture; which one is chosen decides how the
//! picture is written. Pieces of one face painted one after another are joined by the
//! writers into one path (and need no seam flaps between them), so among the components
//! free to come next this order takes a single piece of the face of the piece it took
//! last when there is one, else one of the next face in the input (the triangles a
//! polygon was given as, a quad's two halves: faces listed together come together),
//! and otherwise the first free component of Tarjan's order.

use crate::components::Components;

/// The bottom of a face's stack in [`FaceRuns::below`].
const NONE: u32 = u32::MAX;

/// Working space of [`FaceRuns::order`], kept from graph to graph.
#[derive(Default)]
pub(crate) struct FaceRuns {
    comp_of: Vec<u32>,
    /// Edges between components still to be taken, per component (CSR).
    indegree: Vec<u32>,
    start: Vec<u32>,
    adj: Vec<u32>,
    /// Free components in Tarjan's topological order, smallest rank last taken first.
    free: std::collections::BinaryHeap<std::cmp::Reverse<u32>>,
    /// Free single pieces by face: the last one made free (a component rank), each
    /// linked to the one made free before it through `below` (a stack per face, in one
    /// vector rather than a vector per face: a million faces made a million of them).
    by_face: rustc_hash::FxHashMap<u32, u32>,
    /// Per component rank, the free single piece of its face made free before it
    /// (`NONE` at the bottom of a face's stack).
    below: Vec<u32>,
    taken: Vec<bool>,
    /// The order found: component ranks (indices into Tarjan's topological order).
    pub(crate) order: Vec<u32>,
}

impl FaceRuns {
    /// Orders the components `comps` found on the graph of `n` nodes with edges
    /// `adj[start[v]..start[v + 1]]` (the graph `comps` was found on); `face(v)` is node
    /// `v`'s face. Read the result from [`FaceRuns::order`]: ranks `k` of
    /// `comps.in_topological_order().nth(k)`.
    pub(crate) fn order(
        &mut self,
        comps: &Components,
        n: usize,
        start: &[u32],
        adj: &[u32],
        face: impl Fn(u32) -> u32,
    ) {
        let members: Vec<&[u32]> = comps.in_topological_order().collect();
        let m = members.len();
        self.comp_of.clear();
        self.comp_of.resize(n, 0);
        for (k, c) in members.iter().enumerate() {
            for &v in *c {
                self.comp_of[v as usize] = k as u32;
            }
        }
        // The condensation's edges, grouped by their source component.
        self.indegree.clear();
        self.indegree.resize(m, 0);
        self.start.clear();
        self.start.resize(m + 1, 0);
        for v in 0..n {
            let a = self.comp_of[v];
            for &w in &adj[start[v] as usize..start[v + 1] as usize] {
                let b = self.comp_of[w as usize];
                if a != b {
                    self.start[a as usize + 1] += 1;
                    self.indegree[b as usize] += 1;
                }
            }
        }
        for k in 0..m {
            self.start[k + 1] += self.start[k];
        }
        self.adj.clear();
        self.adj.resize(self.start[m] as usize, 0);
        let mut fill = self.start.clone();
        for v in 0..n {
            let a = self.comp_of[v] as usize;
            for &w in &adj[start[v] as usize..start[v + 1] as usize] {
                let b = self.comp_of[w as usize];
                if a as u32 != b {
                    self.adj[fill[a] as usize] = b;
                    fill[a] += 1;
                }
            }
        }
        let single_face = |k: u32| match members[k as usize] {
            [only] => Some(face(*only)),
            _ => None,
        };
        self.free.clear();
        self.by_face.clear();
        self.below.clear();
        self.below.resize(m, NONE);
        self.taken.clear();
        self.taken.resize(m, false);
        self.order.clear();
        for k in 0..m as u32 {
            if self.indegree[k as usize] == 0 {
                self.free.push(std::cmp::Reverse(k));
                if let Some(f) = single_face(k) {
                    self.below[k as usize] = self.by_face.insert(f, k).unwrap_or(NONE);
                }
            }
        }
        let mut last: Option<u32> = None;
        while self.order.len() < m {
            let mut free_of = |f: u32| {
                let top = self.by_face.get_mut(&f)?;
                while *top != NONE {
                    let k = *top;
                    *top = self.below[k as usize];
                    if !self.taken[k as usize] {
                        return Some(k);
                    }
                }
                None
            };
            let same = last.and_then(|f| free_of(f).or_else(|| free_of(f.checked_add(1)?)));
            let k = match same {
                Some(k) => k,
                None => loop {
                    let std::cmp::Reverse(k) = self
                        .free
                        .pop()
                        .expect("a graph's condensation has no cycle");
                    if !self.taken[k as usize] {
                        break k;
                    }
                },
            };
            self.taken[k as usize] = true;
            self.order.push(k);
            last = single_face(k);
            for e in self.start[k as usize]..self.start[k as usize + 1] {
                let b = self.adj[e as usize];
                self.indegree[b as usize] -= 1;
                if self.indegree[b as usize] == 0 {
                    self.free.push(std::cmp::Reverse(b));
                    if let Some(f) = single_face(b) {
                        self.below[b as usize] = self.by_face.insert(f, b).unwrap_or(NONE);
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::FaceRuns;
    use crate::components::tests::csr;
    use crate::components::Components;

    /// The nodes in the order found (members of a component in Tarjan's order).
    fn nodes(n: usize, edges: &[(u32, u32)], faces: &[u32]) -> Vec<u32> {
        let (s, a) = csr(n, edges);
        let mut c = Components::default();
        c.find(n, &s, &a);
        let mut r = FaceRuns::default();
        r.order(&c, n, &s, &a, |v| faces[v as usize]);
        let members: Vec<&[u32]> = c.in_topological_order().collect();
        r.order
            .iter()
            .flat_map(|&k| members[k as usize].iter().copied())
            .collect()
    }

    fn position(order: &[u32], v: u32) -> usize {
        order.iter().position(|&w| w == v).unwrap()
    }

    #[test]
    fn free_pieces_of_one_face_come_together() {
        // Faces alternate 0, 1, 0, 1, 0, 1 with no constraint: two runs.
        let faces = [0, 1, 0, 1, 0, 1];
        let order = nodes(6, &[], &faces);
        let runs = order
            .windows(2)
            .filter(|w| faces[w[0] as usize] != faces[w[1] as usize])
            .count();
        assert_eq!(runs, 1, "{order:?}");
    }

    #[test]
    fn free_pieces_of_consecutive_faces_come_in_input_order() {
        // Pieces of faces 0..4, two each, listed in reverse with no constraint.
        let faces = [3, 3, 2, 2, 1, 1, 0, 0];
        let order = nodes(8, &[], &faces);
        let seen: Vec<u32> = order.iter().map(|&v| faces[v as usize]).collect();
        let runs = seen.windows(2).filter(|w| w[0] != w[1]).count();
        assert_eq!(runs, 3, "{seen:?}");
        let ascending = seen.windows(2).filter(|w| w[1] == w[0] + 1).count();
        assert!(ascending >= 2, "{seen:?}");
    }

    #[test]
    fn every_edge_is_kept_and_runs_form_where_edges_allow() {
        // 0 (face 0) before 1 (face 1) before 2 (face 0); 3 (face 0) free; a cycle 4 ⇄ 5.
        let faces = [0, 1, 0, 0, 2, 2];
        let edges = [(0, 1), (1, 2), (4, 5), (5, 4), (3, 4)];
        let order = nodes(6, &edges, &faces);
        assert_eq!(order.len(), 6);
        for &(a, b) in &edges[..2] {
            assert!(position(&order, a) < position(&order, b), "{order:?}");
        }
        assert!(position(&order, 3) < position(&order, 4));
        // 3 goes with 0 or with 2, never alone between others.
        let p = position(&order, 3);
        assert!(
            (p > 0 && faces[order[p - 1] as usize] == 0)
                || (p + 1 < 6 && faces[order[p + 1] as usize] == 0),
            "{order:?}"
        );
    }
}
