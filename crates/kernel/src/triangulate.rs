//! Triangulation of non-convex outlines with spade's constrained Delaunay triangulation,
//! shared by both kernels.

use spade::handles::FixedVertexHandle;
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};

/// One triangle of an outline: indices into the outline's corners, counter-clockwise in
/// the plane of projection, and per edge (`k` from corner `k` to `k + 1`) whether it lies
/// on the outline.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Tri {
    pub(crate) idx: [usize; 3],
    pub(crate) original: [bool; 3],
}

/// Triangulates a closed outline given in 2D and returns the triangles inside it
/// (even-odd rule on the constraint edges). `None` when the outline is not simple (a
/// constraint edge would cross another one) or spade rejects a coordinate.
pub(crate) fn triangulate(pts: &[[f64; 2]]) -> Option<Vec<Tri>> {
    let mut cdt: ConstrainedDelaunayTriangulation<Point2<f64>> =
        ConstrainedDelaunayTriangulation::new();
    let mut handles: Vec<FixedVertexHandle> = Vec::with_capacity(pts.len());
    let mut index_of: Vec<usize> = Vec::new();
    for (i, p) in pts.iter().enumerate() {
        let h = cdt.insert(Point2::new(p[0], p[1])).ok()?;
        if h.index() >= index_of.len() {
            index_of.resize(h.index() + 1, usize::MAX);
        }
        if index_of[h.index()] == usize::MAX {
            index_of[h.index()] = i;
        }
        handles.push(h);
    }
    let n = handles.len();
    for i in 0..n {
        let (a, b) = (handles[i], handles[(i + 1) % n]);
        if a == b {
            continue;
        }
        if cdt.try_add_constraint(a, b).is_empty() {
            return None;
        }
    }
    // Flood the faces from the outside; crossing a constraint edge toggles inside/outside.
    let faces = cdt.num_all_faces();
    let mut adjacent: Vec<Vec<(usize, bool)>> = vec![Vec::new(); faces];
    for e in cdt.directed_edges() {
        let constraint = cdt.is_constraint_edge(e.as_undirected().fix());
        let (f, g) = (e.face().fix().index(), e.rev().face().fix().index());
        adjacent[f].push((g, constraint));
    }
    let mut inside: Vec<Option<bool>> = vec![None; faces];
    let outer = cdt.outer_face().fix().index();
    inside[outer] = Some(false);
    let mut stack = vec![outer];
    while let Some(f) = stack.pop() {
        let here = inside[f].unwrap_or(false);
        for &(g, toggles) in &adjacent[f] {
            if inside[g].is_none() {
                inside[g] = Some(here ^ toggles);
                stack.push(g);
            }
        }
    }
    let mut out = Vec::new();
    for face in cdt.inner_faces() {
        if inside[face.fix().index()] != Some(true) {
            continue;
        }
        let vs = face.vertices();
        let idx = vs.map(|v| index_of[v.fix().index()]);
        if idx.contains(&usize::MAX) {
            return None;
        }
        let es = face.adjacent_edges();
        let mut original = [false; 3];
        for (k, e) in es.iter().enumerate() {
            // Edge k of the face runs from vertex k to vertex k + 1.
            let from = e.from().fix();
            let pos = vs.iter().position(|v| v.fix() == from).unwrap_or(k);
            original[pos] = cdt.is_constraint_edge(e.as_undirected().fix());
        }
        let p = idx.map(|i| pts[i]);
        let orient = robust::orient2d(
            robust::Coord {
                x: p[0][0],
                y: p[0][1],
            },
            robust::Coord {
                x: p[1][0],
                y: p[1][1],
            },
            robust::Coord {
                x: p[2][0],
                y: p[2][1],
            },
        );
        if orient > 0.0 {
            out.push(Tri { idx, original });
        } else if orient < 0.0 {
            out.push(Tri {
                idx: [idx[0], idx[2], idx[1]],
                original: [original[2], original[1], original[0]],
            });
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area(pts: &[[f64; 2]], t: &Tri) -> f64 {
        let [a, b, c] = t.idx.map(|i| pts[i]);
        0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
    }

    #[test]
    fn l_shape_is_covered() {
        let pts = [
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [1.0, 2.0],
            [0.0, 2.0],
        ];
        let tris = triangulate(&pts).unwrap();
        let total: f64 = tris.iter().map(|t| area(&pts, t)).sum();
        assert_eq!(total, 3.0);
        assert!(tris.iter().all(|t| area(&pts, t) > 0.0));
        let originals: usize = tris
            .iter()
            .map(|t| t.original.iter().filter(|o| **o).count())
            .sum();
        assert_eq!(originals, 6);
    }

    #[test]
    fn bow_tie_is_rejected() {
        let pts = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]];
        assert!(triangulate(&pts).is_none());
    }
}
