//! Items grouped by a vertex id (a counting sort): the edges at each vertex of a mesh,
//! the faces whose smallest corner is each vertex. Two passes over the items and none
//! over pairs of them, where sorting every item by its vertex compared them
//! `log n` times each (on a million triangles, most of the time spent before ordering).

use rayon::prelude::*;

/// Items in groups by vertex: group `v` is `items[start[v]..start[v + 1]]`, its items in
/// the order they were given.
pub(crate) struct ByVertex<T> {
    /// Offsets (`usize`: a huge mesh can have more edges than `u32` counts).
    start: Vec<usize>,
    items: Vec<T>,
}

impl<T: Copy + Default + Send + Sync> ByVertex<T> {
    /// The items `each` gives, grouped by their vertices (each below `vertices`).
    /// `each` is called twice with a callback: once to count the items at each vertex,
    /// once to place them; it must give the same items both times.
    pub(crate) fn new(vertices: usize, each: impl Fn(&mut dyn FnMut(u32, T))) -> Self {
        let mut start = vec![0usize; vertices + 1];
        each(&mut |v, _| start[v as usize + 1] += 1);
        for v in 1..start.len() {
            start[v] += start[v - 1];
        }
        let mut items = vec![T::default(); start[vertices]];
        let mut fill = start.clone();
        each(&mut |v, item| {
            let at = &mut fill[v as usize];
            items[*at] = item;
            *at += 1;
        });
        ByVertex { start, items }
    }

    /// Calls `check(group, out)` on every group with at least one item (which it may
    /// reorder), in parallel blocks of vertices, and returns what the calls pushed, in
    /// vertex order.
    pub(crate) fn flat_map_groups<U: Send>(
        &mut self,
        check: impl Fn(&mut [T], &mut Vec<U>) + Sync,
    ) -> Vec<U> {
        let vertices = self.start.len() - 1;
        let per = VERTICES_PER_TASK.max(vertices.div_ceil(MAX_TASKS));
        // The items of each block of vertices, apart.
        let mut blocks = Vec::with_capacity(vertices.div_ceil(per));
        let mut rest = self.items.as_mut_slice();
        for first in (0..vertices).step_by(per) {
            let end = (first + per).min(vertices);
            let len = self.start[end] - self.start[first];
            let (block, after) = rest.split_at_mut(len);
            blocks.push((first..end, block));
            rest = after;
        }
        let start = &self.start;
        let parts: Vec<Vec<U>> = blocks
            .into_par_iter()
            .map(|(vs, block)| {
                let mut out = Vec::new();
                let base = start[vs.start];
                for v in vs {
                    let group = &mut block[start[v] - base..start[v + 1] - base];
                    if !group.is_empty() {
                        check(group, &mut out);
                    }
                }
                out
            })
            .collect();
        parts.into_iter().flatten().collect()
    }
}

/// Vertices per parallel task of [`ByVertex::flat_map_groups`], at least.
const VERTICES_PER_TASK: usize = 8192;

/// Parallel tasks of [`ByVertex::flat_map_groups`] at most.
const MAX_TASKS: usize = 256;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn groups_hold_their_items_in_order() {
        let items: Vec<(u32, u32)> = (0..5000u32).map(|i| ((i * 7919) % 97, i)).collect();
        let mut g = ByVertex::new(100, |f| {
            for &(v, i) in &items {
                f(v, i);
            }
        });
        let got: Vec<(u32, Vec<u32>)> = g
            .flat_map_groups(|group, out| out.push(group.to_vec()))
            .into_iter()
            .map(|group| (items[group[0] as usize].0, group))
            .collect();
        assert_eq!(got.len(), 97, "vertices 97..100 hold nothing");
        for (k, (v, group)) in got.iter().enumerate() {
            assert_eq!(*v, k as u32);
            let want: Vec<u32> = items.iter().filter(|p| p.0 == *v).map(|p| p.1).collect();
            assert_eq!(group, &want);
        }
    }
}
