//! Layers of translucent fragments: consecutive runs of one object and one opacity whose
//! fragments do not overlap, decided exactly, so that a writer may paint them opaque in
//! one group and blend the group once.
//!
//! A translucent fragment cannot close its seams by overdraw (what is painted twice is
//! blended twice), and viewers anti-alias each path on its own, so the pixels of an edge
//! two translucent fragments share are blended with the page under both (coverage
//! conflation). Inside an opaque group the seams close as between opaque fragments;
//! the viewer then blends the group's content once with the opacity, as every point of
//! a fragment is blended in limn's own picture, provided that no point lies in two
//! fragments of the group: painted opaque, the later would hide the earlier, which
//! must show through it. So a layer holds only fragments whose interiors are disjoint:
//! for two fragments that are each convex (every turn of its corners the same way, by
//! exact orientation tests), some edge of one has every corner of the other on its
//! line or outside it, by exact orientation tests. Fragments that are not convex, or
//! for which no such edge is found, start a new layer: a seam, never a wrong colour.

use crate::runs::Frag;

/// Fragments a layer holds at most (each joining fragment is tested against those
/// whose boxes meet its own, so the cost grows with the layer).
const MAX_FRAGMENTS: usize = 4096;

/// A convex fragment: its corners, the way it turns, its bounding box.
struct Shape {
    points: Vec<[f64; 2]>,
    side: f64,
    lo: [f64; 2],
    hi: [f64; 2],
}

impl Shape {
    /// `None` unless the polygon is convex with area (exactly).
    fn new(points: &[[f64; 2]]) -> Option<Shape> {
        let n = points.len();
        if n < 3 {
            return None;
        }
        let mut side = 0.0;
        for i in 0..n {
            let t = turn(points[i], points[(i + 1) % n], points[(i + 2) % n]);
            if t != 0.0 {
                if side * t < 0.0 {
                    return None;
                }
                side = t.signum();
            }
        }
        if side == 0.0 {
            return None;
        }
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in points {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        Some(Shape {
            points: points.to_vec(),
            side,
            lo,
            hi,
        })
    }

    /// Whether some edge of `self` has every corner of `other` on its line or on the
    /// outer side.
    fn separates(&self, other: &Shape) -> bool {
        let n = self.points.len();
        (0..n).any(|i| {
            let (p, q) = (self.points[i], self.points[(i + 1) % n]);
            other
                .points
                .iter()
                .all(|&x| self.side * turn(p, q, x) <= 0.0)
        })
    }

    /// Whether the interiors of `self` and `other` are disjoint (shown exactly).
    fn disjoint(&self, other: &Shape) -> bool {
        (0..2).any(|k| self.hi[k] <= other.lo[k] || other.hi[k] <= self.lo[k])
            || self.separates(other)
            || other.separates(self)
    }
}

/// Exact orientation of `r` against the line `p → q` (positive, negative or zero).
fn turn(p: [f64; 2], q: [f64; 2], r: [f64; 2]) -> f64 {
    let c = |p: [f64; 2]| robust::Coord { x: p[0], y: p[1] };
    robust::orient2d(c(p), c(q), c(r))
}

/// Consecutive runs of translucent fragments with disjoint interiors, waiting to be
/// painted as one group.
pub(crate) struct Layer<'a> {
    frags: Vec<Frag<'a>>,
    shapes: Vec<Shape>,
    /// Object and opacity (thousandths) of the runs held.
    key: Option<(u32, u16)>,
    /// Whether the layer takes no more runs (its first was not shown disjoint).
    closed: bool,
}

impl<'a> Layer<'a> {
    pub(crate) fn new() -> Self {
        Layer {
            frags: Vec::new(),
            shapes: Vec::new(),
            key: None,
            closed: false,
        }
    }

    /// Adds `run` (the fragments of one face, of object and opacity `key`) when it may
    /// join: same key, and every fragment convex and disjoint from every fragment held
    /// and from the run's others. An empty layer takes any run (the fragments of one
    /// face tile it), but one not shown disjoint closes it. Returns whether it was added.
    pub(crate) fn join(&mut self, key: (u32, u16), run: &[Frag<'a>]) -> bool {
        let empty = self.frags.is_empty();
        if !empty && (self.closed || self.key != Some(key) || self.frags.len() >= MAX_FRAGMENTS) {
            return false;
        }
        let mut shapes = Vec::with_capacity(run.len());
        let mut clear = true;
        for f in run {
            let Some(s) = Shape::new(&f.points) else {
                clear = false;
                break;
            };
            if !self.shapes.iter().chain(&shapes).all(|h| h.disjoint(&s)) {
                clear = false;
                break;
            }
            shapes.push(s);
        }
        if !clear && !empty {
            return false;
        }
        self.closed = !clear;
        self.key = Some(key);
        self.frags.extend_from_slice(run);
        self.shapes.append(&mut shapes);
        true
    }

    /// The fragments held (in paint order) with their object and opacity, emptying
    /// the layer.
    pub(crate) fn take(&mut self) -> Option<(Vec<Frag<'a>>, (u32, u16))> {
        let key = self.key.take()?;
        self.shapes.clear();
        self.closed = false;
        Some((std::mem::take(&mut self.frags), key))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shape(p: &[[f64; 2]]) -> Shape {
        Shape::new(p).unwrap()
    }

    #[test]
    fn neighbours_are_disjoint_overlaps_are_not() {
        let a = shape(&[[0.0, 0.0], [10.0, 0.0], [0.0, 10.0]]);
        // Sharing the edge (10,0)–(0,10), either way round.
        let b = shape(&[[10.0, 0.0], [10.0, 10.0], [0.0, 10.0]]);
        let b_reversed = shape(&[[0.0, 10.0], [10.0, 10.0], [10.0, 0.0]]);
        assert!(a.disjoint(&b) && b.disjoint(&a) && a.disjoint(&b_reversed));
        // A hair across the shared edge.
        let c = shape(&[[10.0, 0.0], [10.0, 10.0], [0.0, 9.999_999_999]]);
        assert!(!a.disjoint(&c));
        // Touching at one corner only; and far apart.
        let d = shape(&[[10.0, 0.0], [20.0, 0.0], [20.0, -10.0]]);
        assert!(a.disjoint(&d));
        assert!(Shape::new(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]).is_none());
        assert!(Shape::new(&[[0.0, 0.0], [4.0, 0.0], [1.0, 1.0], [0.0, 4.0]]).is_none());
    }
}
