//! Seams between pieces of one face that meet at T-junctions, with fragments of other
//! faces painted between them (interpenetrating boxes split each other's faces so): the
//! writers cannot draw them as one path, and their shared cut has no end points in
//! common for [`crate::seams`]' edge keys to find.

use std::collections::HashMap;

use crate::PaintFragment;

/// For fragments of a face: edges that lie along an edge of a later piece of the same
/// face and colour, running the other way round (the later piece lies on the other
/// side), with a fragment of another face painted between the two.
pub(crate) struct Across {
    /// Per fragment with any: (its edge, the later piece, the piece's edge).
    edges: HashMap<usize, Vec<(usize, usize, usize)>>,
}

/// Pieces of one face looked at, at most: the pairs are tried one by one, so a picture
/// of n fragments costs at most about 64 n pairs of pieces.
const MAX_PIECES: usize = 64;

/// How far from the line of the later piece's edge the end points of an edge may lie
/// (in pixels): cut points are rounded to f64, so pieces meeting at a T-junction are
/// not exactly collinear. Only which flaps are made depends on it, never where a flap
/// lies (inside the later piece, see [`crate::seams`]).
const TOLERANCE: f64 = 1e-6;

impl Across {
    /// The edges of `fragments` along later pieces of their faces, for opaque, flat,
    /// untextured pieces of faces painted in more than one stretch of consecutive
    /// fragments and of at most [`MAX_PIECES`] such pieces.
    pub(crate) fn new(fragments: &[PaintFragment]) -> Self {
        let mut stretch = Vec::with_capacity(fragments.len());
        let mut count = 0usize;
        let mut faces: HashMap<u32, Vec<usize>> = HashMap::new();
        for (j, f) in fragments.iter().enumerate() {
            if j > 0 && (f.face, f.object) != (fragments[j - 1].face, fragments[j - 1].object) {
                count += 1;
            }
            stretch.push(count);
            if f.fill[3] >= 1.0 && f.vertex_colors.is_none() && f.texture.is_none() {
                faces.entry(f.face).or_default().push(j);
            }
        }
        let mut edges: HashMap<usize, Vec<(usize, usize, usize)>> = HashMap::new();
        for pieces in faces.values() {
            let first = stretch[pieces[0]];
            if pieces.len() > MAX_PIECES || pieces.iter().all(|&j| stretch[j] == first) {
                continue;
            }
            for (s, &i) in pieces.iter().enumerate() {
                let p = &fragments[i];
                for &j in &pieces[s + 1..] {
                    let q = &fragments[j];
                    if stretch[j] == stretch[i] || q.fill != p.fill || q.object != p.object {
                        continue;
                    }
                    let (n, m) = (p.points.len(), q.points.len());
                    for e in 0..n {
                        let (a, b) = (p.points[e], p.points[(e + 1) % n]);
                        for k in 0..m {
                            let (u, v) = (q.points[k], q.points[(k + 1) % m]);
                            if along(a, b, u, v) {
                                edges.entry(i).or_default().push((e, j, k));
                            }
                        }
                    }
                }
            }
        }
        Across { edges }
    }

    /// The later pieces (and their edges) edge `e` of fragment `i` lies along.
    pub(crate) fn of(&self, i: usize, e: usize) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.edges
            .get(&i)
            .into_iter()
            .flatten()
            .filter(move |&&(ee, _, _)| ee == e)
            .map(|&(_, j, k)| (j, k))
    }
}

/// Whether edge `a → b` runs along edge `u → v` the other way, overlapping it over more
/// than [`TOLERANCE`].
fn along(a: [f64; 2], b: [f64; 2], u: [f64; 2], v: [f64; 2]) -> bool {
    let d = [v[0] - u[0], v[1] - u[1]];
    let len = d[0].hypot(d[1]);
    // Long enough (not NaN), and the other way round.
    let back = (b[0] - a[0]) * d[0] + (b[1] - a[1]) * d[1] < 0.0;
    if !(len.is_finite() && len > TOLERANCE && back) {
        return false;
    }
    let off = |p: [f64; 2]| (d[0] * (p[1] - u[1]) - d[1] * (p[0] - u[0])).abs() / len;
    if off(a).is_nan() || off(a) > TOLERANCE || off(b).is_nan() || off(b) > TOLERANCE {
        return false;
    }
    // Positions along u → v, in pixels.
    let at = |p: [f64; 2]| ((p[0] - u[0]) * d[0] + (p[1] - u[1]) * d[1]) / len;
    let (ta, tb) = (at(a), at(b));
    let overlap = ta.max(tb).min(len) - ta.min(tb).max(0.0);
    overlap > TOLERANCE
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edges_along_longer_edges_the_other_way() {
        // A piece whose edge is part of a longer edge of another, running back.
        assert!(along([0.0, 0.0], [0.0, 1.0], [0.0, 3.0], [0.0, -1.0]));
        // The same way round: the same side.
        assert!(!along([0.0, 1.0], [0.0, 0.0], [0.0, 3.0], [0.0, -1.0]));
        // Parallel, apart.
        assert!(!along([0.1, 0.0], [0.1, 1.0], [0.0, 3.0], [0.0, -1.0]));
        // On the line, not overlapping (touching at an end).
        assert!(!along([0.0, 4.0], [0.0, 3.0], [0.0, 3.0], [0.0, -1.0]));
        // Off the line by rounding.
        assert!(along([1e-9, 0.0], [0.0, 1.0], [0.0, 3.0], [0.0, -1.0]));
    }

    #[test]
    fn pieces_of_a_face_with_another_face_between() {
        let tri = |p: Vec<[f64; 2]>, face: u32| {
            let mut f = PaintFragment::new(p, [0.5, 0.5, 0.5, 1.0]);
            f.face = face;
            f
        };
        // Face 0: a square's left triangle, then (after face 1) two triangles on the
        // right of its diagonal, meeting it at a T-junction.
        let frags = vec![
            tri(vec![[0.0, 0.0], [2.0, 2.0], [0.0, 2.0]], 0),
            tri(vec![[5.0, 5.0], [6.0, 5.0], [5.0, 6.0]], 1),
            tri(vec![[0.0, 0.0], [2.0, 0.0], [1.0, 1.0]], 0),
            tri(vec![[1.0, 1.0], [2.0, 0.0], [2.0, 2.0]], 0),
        ];
        let across = Across::new(&frags);
        assert_eq!(across.of(0, 0).collect::<Vec<_>>(), vec![(2, 2), (3, 2)]);
        assert_eq!(across.of(0, 1).count(), 0);
        // Consecutive pieces of one face get none (the writers join them).
        let mut next = frags.clone();
        next.swap(1, 3);
        assert_eq!(Across::new(&next).of(0, 0).count(), 0);
    }
}
