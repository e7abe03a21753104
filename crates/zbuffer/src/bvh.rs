//! A bounding volume hierarchy over world-space triangles, for the ray caster.
//!
//! Boxes are inflated slightly (relative to their coordinates' magnitude) and the slab
//! test widens its interval, so a box test never rejects a triangle the exact test
//! would hit: a false positive only costs an exact test.

use glam::DVec3;

/// A node: leaves (`count > 0`) hold `count` triangles from `first` in the order array;
/// inner nodes have children `first` and `first + 1`.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Node {
    pub lo: DVec3,
    pub hi: DVec3,
    pub first: u32,
    pub count: u32,
}

/// The hierarchy: nodes (root first) and triangle order.
pub(crate) struct Bvh {
    pub nodes: Vec<Node>,
    pub order: Vec<u32>,
}

const LEAF: usize = 4;

impl Bvh {
    /// Builds by median splits along the longest axis of the centroids' bounds.
    pub fn build(tris: &[[DVec3; 3]]) -> Bvh {
        let mut order: Vec<u32> = (0..tris.len() as u32).collect();
        let centroids: Vec<DVec3> = tris.iter().map(|t| (t[0] + t[1] + t[2]) / 3.0).collect();
        let mut nodes = vec![Node {
            lo: DVec3::ZERO,
            hi: DVec3::ZERO,
            first: 0,
            count: 0,
        }];
        // (node, start, end) still to fill.
        let mut todo = vec![(0usize, 0usize, order.len())];
        while let Some((node, start, end)) = todo.pop() {
            let (mut lo, mut hi) = (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY));
            let (mut clo, mut chi) = (lo, hi);
            for &t in &order[start..end] {
                for p in tris[t as usize] {
                    lo = lo.min(p);
                    hi = hi.max(p);
                }
                clo = clo.min(centroids[t as usize]);
                chi = chi.max(centroids[t as usize]);
            }
            let pad = (lo.abs().max(hi.abs()) + (hi - lo)) * 1e-12 + DVec3::splat(1e-300);
            nodes[node].lo = lo - pad;
            nodes[node].hi = hi + pad;
            let ext = chi - clo;
            if end - start <= LEAF || ext.max_element() <= 0.0 {
                nodes[node].first = start as u32;
                nodes[node].count = (end - start) as u32;
                continue;
            }
            let axis = if ext.x >= ext.y && ext.x >= ext.z {
                0
            } else if ext.y >= ext.z {
                1
            } else {
                2
            };
            let mid = start + (end - start) / 2;
            order[start..end].select_nth_unstable_by(mid - start, |&a, &b| {
                centroids[a as usize][axis].total_cmp(&centroids[b as usize][axis])
            });
            let left = nodes.len();
            nodes[node].first = left as u32;
            nodes[node].count = 0;
            let blank = nodes[node];
            nodes.push(blank);
            nodes.push(blank);
            todo.push((left, start, mid));
            todo.push((left + 1, mid, end));
        }
        Bvh { nodes, order }
    }
}

/// A segment `o + t·d`, `t ∈ [0, 1]`, with precomputed reciprocals.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Segment {
    pub o: DVec3,
    pub d: DVec3,
    inv: DVec3,
}

impl Segment {
    /// The segment from `a` to `b`.
    pub fn new(a: DVec3, b: DVec3) -> Segment {
        let d = b - a;
        // A zero component gets a huge finite reciprocal instead of ∞, so the slab test
        // never computes 0 · ∞: a ray inside the slab gets an interval around 0.
        let inv = DVec3::from_array(d.to_array().map(|c| if c == 0.0 { 1e300 } else { 1.0 / c }));
        Segment { o: a, d, inv }
    }

    /// Entry parameter of the segment into the box, or `None` when it misses. The
    /// interval is widened by 1e-9 (the boxes are inflated as well), so rounding never
    /// loses a hit.
    #[inline]
    pub fn enter(&self, n: &Node) -> Option<f64> {
        let a = (n.lo - self.o) * self.inv;
        let b = (n.hi - self.o) * self.inv;
        let t0 = a.min(b).max_element().max(0.0);
        let t1 = a.max(b).min_element().min(1.0);
        (t0 <= t1 + 1e-9).then_some(t0)
    }
}
