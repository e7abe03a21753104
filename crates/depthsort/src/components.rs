//! Strongly connected components of a small directed graph, with working space kept
//! between graphs: the adaptive ordering finds the components of thousands of graphs of
//! two to a few hundred nodes on a dense scene, and allocating a dozen vectors for each
//! cost more than the search itself.

/// Strongly connected components of a graph given in CSR form (the edges of node `v` are
/// `adj[start[v]..start[v + 1]]`), found by an iterative Tarjan search. The buffers are
/// reused by every [`Components::find`].
#[derive(Default)]
pub(crate) struct Components {
    index: Vec<u32>,
    low: Vec<u32>,
    on_stack: Vec<bool>,
    stack: Vec<u32>,
    call: Vec<(u32, u32)>,
    /// The members of every component, component after component.
    members: Vec<u32>,
    /// `members[ends[k - 1]..ends[k]]` is the `k`-th component (in the order found).
    ends: Vec<usize>,
}

impl Components {
    /// Finds the components of the graph on `n` nodes; read them with
    /// [`Components::in_topological_order`].
    pub(crate) fn find(&mut self, n: usize, start: &[u32], adj: &[u32]) {
        const UNSEEN: u32 = u32::MAX;
        self.index.clear();
        self.index.resize(n, UNSEEN);
        self.low.clear();
        self.low.resize(n, 0);
        self.on_stack.clear();
        self.on_stack.resize(n, false);
        self.stack.clear();
        self.call.clear();
        self.members.clear();
        self.ends.clear();
        let (index, low, on_stack) = (&mut self.index, &mut self.low, &mut self.on_stack);
        let mut next = 0u32;
        for root in 0..n as u32 {
            if index[root as usize] != UNSEEN {
                continue;
            }
            self.call.push((root, start[root as usize]));
            index[root as usize] = next;
            low[root as usize] = next;
            next += 1;
            self.stack.push(root);
            on_stack[root as usize] = true;
            while let Some(&mut (v, ref mut e)) = self.call.last_mut() {
                let vi = v as usize;
                if *e < start[vi + 1] {
                    let w = adj[*e as usize];
                    *e += 1;
                    let wi = w as usize;
                    if index[wi] == UNSEEN {
                        index[wi] = next;
                        low[wi] = next;
                        next += 1;
                        self.stack.push(w);
                        on_stack[wi] = true;
                        self.call.push((w, start[wi]));
                    } else if on_stack[wi] {
                        low[vi] = low[vi].min(index[wi]);
                    }
                } else {
                    self.call.pop();
                    if let Some(&(parent, _)) = self.call.last() {
                        let pi = parent as usize;
                        low[pi] = low[pi].min(low[vi]);
                    }
                    if low[vi] == index[vi] {
                        loop {
                            let w = self.stack.pop().expect("tarjan stack holds the component");
                            on_stack[w as usize] = false;
                            self.members.push(w);
                            if w == v {
                                break;
                            }
                        }
                        self.ends.push(self.members.len());
                    }
                }
            }
        }
    }

    /// The components found last, in topological order (a component comes before every
    /// component it has edges to); each lists its members in the order Tarjan's search
    /// left them.
    pub(crate) fn in_topological_order(&self) -> impl DoubleEndedIterator<Item = &[u32]> {
        // Tarjan emits a component after everything reachable from it.
        (0..self.ends.len()).rev().map(|k| {
            let begin = if k == 0 { 0 } else { self.ends[k - 1] };
            &self.members[begin..self.ends[k]]
        })
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::Components;

    /// A graph's edges in CSR form (`start`, `adj`), as the orderings build them.
    pub(crate) fn csr(n: usize, edges: &[(u32, u32)]) -> (Vec<u32>, Vec<u32>) {
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

    fn components(c: &mut Components, n: usize, edges: &[(u32, u32)]) -> Vec<Vec<u32>> {
        let (s, a) = csr(n, edges);
        c.find(n, &s, &a);
        c.in_topological_order().map(<[u32]>::to_vec).collect()
    }

    #[test]
    fn components_come_in_topological_order() {
        // 3 -> 0 -> 1 <-> 2, 4 alone
        let mut c = Components::default();
        let comps = components(&mut c, 5, &[(3, 0), (0, 1), (1, 2), (2, 1)]);
        let pos = |v: u32| comps.iter().position(|c| c.contains(&v)).unwrap();
        assert!(pos(3) < pos(0) && pos(0) < pos(1));
        assert_eq!(pos(1), pos(2));
        assert_eq!(comps.len(), 4);
    }

    #[test]
    fn reused_space_gives_the_same_answer_as_fresh_space() {
        let graphs: [(usize, &[(u32, u32)]); 3] = [
            (6, &[(0, 1), (1, 0), (2, 3), (3, 4), (4, 2), (5, 0)]),
            (2, &[(1, 0)]),
            (4, &[(0, 1), (1, 2), (2, 3), (3, 0)]),
        ];
        let mut reused = Components::default();
        for (n, edges) in graphs {
            let fresh = components(&mut Components::default(), n, edges);
            assert_eq!(components(&mut reused, n, edges), fresh);
        }
    }

    #[test]
    fn long_chain_does_not_recurse() {
        let n = 200_000;
        let edges: Vec<(u32, u32)> = (0..n as u32 - 1).map(|i| (i, i + 1)).collect();
        let comps = components(&mut Components::default(), n, &edges);
        assert_eq!(comps.len(), n);
        assert_eq!(comps[0], vec![0]);
        assert_eq!(comps[n - 1], vec![n as u32 - 1]);
    }
}
