//! Layers of translucent fragments: runs of one object and one opacity whose fragments
//! do not overlap, decided exactly, so that a writer may paint them opaque in one group
//! and blend the group once.
//!
//! A translucent fragment cannot close its seams by overdraw (what is painted twice is
//! blended twice), and viewers anti-alias each path on its own, so the pixels of an edge
//! two translucent fragments share are blended with the page under both (coverage
//! conflation). Inside an opaque group the seams close as between opaque fragments;
//! the viewer then blends the group's content once with the opacity, as every point of
//! a fragment is blended in limn's own picture, provided that no point lies in two
//! fragments of the group: painted opaque, the later would hide the earlier, which
//! must show through it. So a layer holds only fragments whose interiors are disjoint:
//! their bounding boxes meet at most along a side, or some edge of the convex hull of
//! one (found with exact orientation tests) has every corner of the other's hull on its
//! line or outside it, by exact orientation tests. Two runs of different faces are also
//! disjoint when their faces' projected outlines are ([`Picture::face_outlines`]: a
//! fragment lies in its face's hull, while cut fragments' rounded corners can overlap
//! by a few units in the last place where the faces do not). Fragments for which no
//! such edge is found go in different layers: a seam, never a wrong colour.

use std::collections::BTreeMap;

use crate::runs::Frag;
#[cfg(doc)]
use crate::Picture;

/// Fragments held at most (each run is tested against those held, so the cost grows
/// with their number).
const MAX_FRAGMENTS: usize = 16384;

/// The convex hull of a fragment: its corners, the way it turns, its bounding box.
struct Shape {
    points: Vec<[f64; 2]>,
    side: f64,
    lo: [f64; 2],
    hi: [f64; 2],
}

impl Shape {
    /// The convex hull of `points` (found with exact orientation tests, so its corners
    /// are corners of the polygon and it contains the polygon); `side` 0 when every
    /// corner lies on one line (no interior).
    fn new(points: &[[f64; 2]]) -> Shape {
        let mut p = points.to_vec();
        p.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
        p.dedup();
        // Andrew's monotone chain: lower then upper hull, turning one way.
        let mut hull: Vec<[f64; 2]> = Vec::with_capacity(p.len() + 1);
        for pass in 0..2 {
            let start = hull.len();
            let points: Box<dyn Iterator<Item = &[f64; 2]>> = if pass == 0 {
                Box::new(p.iter())
            } else {
                Box::new(p.iter().rev())
            };
            for &x in points {
                while hull.len() >= start + 2
                    && turn(hull[hull.len() - 2], hull[hull.len() - 1], x) <= 0.0
                {
                    hull.pop();
                }
                hull.push(x);
            }
            hull.pop();
        }
        let side = if hull.len() >= 3 { 1.0 } else { 0.0 };
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for q in &p {
            for k in 0..2 {
                lo[k] = lo[k].min(q[k]);
                hi[k] = hi[k].max(q[k]);
            }
        }
        Shape {
            points: hull,
            side,
            lo,
            hi,
        }
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
        self.side == 0.0
            || other.side == 0.0
            || (0..2).any(|k| self.hi[k] <= other.lo[k] || other.hi[k] <= self.lo[k])
            || self.separates(other)
            || other.separates(self)
    }
}

/// Exact orientation of `r` against the line `p → q` (positive, negative or zero).
fn turn(p: [f64; 2], q: [f64; 2], r: [f64; 2]) -> f64 {
    let c = |p: [f64; 2]| robust::Coord { x: p[0], y: p[1] };
    robust::orient2d(c(p), c(q), c(r))
}

/// A run held: its fragments and their hulls, and its face with the hull of the face's
/// projected outline where the picture has it.
struct Held<'a> {
    frags: Vec<Frag<'a>>,
    shapes: Vec<Shape>,
    face: Option<(u32, Shape)>,
}

impl<'a> Held<'a> {
    /// The run `run` (fragments of one face), its face's outline from `outlines`.
    fn new(run: &[Frag<'a>], outlines: &BTreeMap<u32, Vec<[f64; 2]>>) -> Held<'a> {
        let face = run.first().and_then(|f| {
            let face = f.src.face;
            let one_face = run.iter().all(|g| g.src.face == face);
            let outline = outlines.get(&face).filter(|_| one_face)?;
            Some((face, Shape::new(outline)))
        });
        Held {
            frags: run.to_vec(),
            shapes: run.iter().map(|f| Shape::new(&f.points)).collect(),
            face,
        }
    }

    /// Whether some fragment of `self` may overlap one of `other` (not shown disjoint by
    /// their faces' outlines nor by their own corners).
    fn meets(&self, other: &Held<'_>) -> bool {
        if let (Some((a, s)), Some((b, t))) = (&self.face, &other.face) {
            if a != b && s.disjoint(t) {
                return false;
            }
        }
        self.shapes
            .iter()
            .any(|s| other.shapes.iter().any(|t| !s.disjoint(t)))
    }
}

/// The fragments of one layer, in paint order.
pub(crate) type Layer<'a> = Vec<Frag<'a>>;

/// Consecutive translucent runs of one object and opacity, waiting to be painted as
/// layers.
///
/// Two runs whose fragments are disjoint give the same picture in either order, so
/// the runs are put into layers greedily, in order: a run joins the first layer when it
/// is disjoint from every run in it and from every run held back so far; otherwise it is
/// held back (painted after the layer), and the runs held back form the next layers the
/// same way. A run is painted after every earlier run it may overlap, as in the
/// picture's order: a translucent sphere seen from outside becomes two layers, its
/// back and its front. Other runs that come between them and are disjoint from every
/// run held ([`Layers::clear_of`]) are painted first, without ending the layers.
pub(crate) struct Layers<'a> {
    runs: Vec<Held<'a>>,
    fragments: usize,
    /// Object and opacity (thousandths) of the runs held.
    key: Option<(u32, u16)>,
    /// The projected outlines of translucent faces ([`Picture::face_outlines`]).
    outlines: &'a BTreeMap<u32, Vec<[f64; 2]>>,
}

impl<'a> Layers<'a> {
    /// An empty holder; `outlines`: the picture's [`Picture::face_outlines`].
    pub(crate) fn new(outlines: &'a BTreeMap<u32, Vec<[f64; 2]>>) -> Self {
        Layers {
            runs: Vec::new(),
            fragments: 0,
            key: None,
            outlines,
        }
    }

    /// Holds `run` (the fragments of one face, of object and opacity `key`) when it
    /// may join the runs held: same key, and not too many fragments. Returns whether it
    /// was held (an empty holder takes any run).
    pub(crate) fn join(&mut self, key: (u32, u16), run: &[Frag<'a>]) -> bool {
        if !self.runs.is_empty() && (self.key != Some(key) || self.fragments >= MAX_FRAGMENTS) {
            return false;
        }
        self.key = Some(key);
        self.fragments += run.len();
        self.runs.push(Held::new(run, self.outlines));
        true
    }

    /// Whether every fragment of `run` is shown disjoint from every fragment held: then
    /// `run` may be painted before the runs held, the same picture as after them.
    pub(crate) fn clear_of(&self, run: &[Frag<'_>]) -> bool {
        if self.runs.is_empty() {
            return true;
        }
        let other = Held::new(run, self.outlines);
        !self.runs.iter().any(|h| h.meets(&other))
    }

    /// The layers of the runs held, in paint order (each the fragments of its runs in
    /// order), with the runs' object and opacity; empties the holder.
    ///
    /// The layers are taken from the front: the last layer holds every run that no
    /// later run may overlap (and that overlaps none of the runs held back for earlier
    /// layers), and so on backwards. A surface seen through nothing is then one layer
    /// even where some of it has nothing behind it (a translucent sphere cut into by an
    /// opaque one: the front's parts over the cut are its own), so no boundary between
    /// layers crosses it.
    pub(crate) fn take(&mut self) -> Option<(Vec<Layer<'a>>, (u32, u16))> {
        let key = self.key.take()?;
        self.fragments = 0;
        let mut rest = std::mem::take(&mut self.runs);
        rest.reverse();
        let mut out = Vec::new();
        while !rest.is_empty() {
            // In reverse paint order: a run goes in this layer unless a run after it in
            // paint order, in this layer or held for an earlier one, may overlap it.
            let (mut layer, mut front): (Vec<Held<'a>>, Vec<Held<'a>>) = (Vec::new(), Vec::new());
            for r in rest {
                let held = front.iter().any(|b| b.meets(&r));
                if held || layer.iter().any(|l| l.meets(&r)) {
                    front.push(r);
                } else {
                    layer.push(r);
                }
            }
            layer.reverse();
            out.push(layer.into_iter().flat_map(|h| h.frags).collect());
            rest = front;
        }
        out.reverse();
        Some((out, key))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shape(p: &[[f64; 2]]) -> Shape {
        Shape::new(p)
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
        // On one line: no interior.
        let line = shape(&[[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]);
        assert!(line.disjoint(&a) && a.disjoint(&line));
        // A dent: its hull, the corners round it.
        let hull = shape(&[[0.0, 0.0], [4.0, 0.0], [1.0, 1.0], [0.0, 4.0]]);
        assert_eq!(hull.points, vec![[0.0, 0.0], [4.0, 0.0], [0.0, 4.0]]);
        assert!(!hull.disjoint(&shape(&[[1.5, 1.5], [2.0, 1.5], [1.5, 2.0]])));
    }

    #[test]
    fn runs_are_layered_in_paint_order() {
        use crate::runs::{check, walk};
        use crate::{PaintFragment, Picture};
        // Back A, back B (beside A), front C (over A and B), back D (beside all, after
        // C), front E (over A, B and C): taken from the front, layers [A, B], [C],
        // [D, E] (D, beside everything, goes as late as it can).
        let sq = |x: f64, y: f64| vec![[x, y], [x + 10.0, y], [x + 10.0, y + 10.0], [x, y + 10.0]];
        let mut p = Picture::new(100, 100);
        for (face, pts) in [
            sq(0.0, 0.0),
            sq(10.0, 0.0),
            sq(5.0, 5.0),
            sq(30.0, 0.0),
            sq(8.0, 8.0),
        ]
        .into_iter()
        .enumerate()
        {
            let mut f = PaintFragment::new(pts, [0.5, 0.5, 0.5, 0.5]);
            f.face = face as u32;
            p.fragments.push(f);
        }
        let guard = check(&p).unwrap().guard;
        let mut layers = Layers::new(&p.face_outlines);
        walk(
            &p,
            &guard,
            |_| (),
            |run, _| {
                assert!(layers.join((0, 500), run));
                Ok(())
            },
        )
        .unwrap();
        let (out, key) = layers.take().unwrap();
        assert_eq!(key, (0, 500));
        let faces: Vec<Vec<u32>> = out
            .iter()
            .map(|l| l.iter().map(|f| f.src.face).collect())
            .collect();
        assert_eq!(faces, vec![vec![0, 1], vec![2], vec![3, 4]]);
        assert!(layers.take().is_none());
    }
}
