//! Triangulation of non-convex outlines with spade's constrained Delaunay triangulation,
//! shared by both kernels.

use std::collections::HashMap;

use spade::handles::{FixedDirectedEdgeHandle, FixedVertexHandle};
use spade::{ConstrainedDelaunayTriangulation, Point2, Triangulation};

/// One triangle of an outline: indices into the outline's corners, counter-clockwise in
/// the plane of projection, and per edge (`k` from corner `k` to `k + 1`) whether it lies
/// on the outline.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Tri {
    pub(crate) idx: [usize; 3],
    pub(crate) original: [bool; 3],
}

/// The triangles inside a closed outline, and which way the outline runs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Triangulated {
    /// The triangles, counter-clockwise in the plane of projection.
    pub(crate) tris: Vec<Tri>,
    /// Whether the outline runs counter-clockwise around what it encloses.
    pub(crate) ccw: bool,
}

/// Triangulates a closed outline given in 2D and returns the triangles inside it, by
/// the winding number of the outline's edges (nonzero rule). The outline may touch
/// itself at a repeated corner and may run along one of its own edges back the other way,
/// as a region whose hole is joined to its outside by a cut does: the two runs of the cut
/// cancel, so the cut is inside and is not an outline edge. `None` when the outline is
/// not simple in that sense (a constraint edge would cross another one, or it winds
/// around some part twice or both ways round) or spade rejects a coordinate.
pub(crate) fn triangulate(pts: &[[f64; 2]]) -> Option<Triangulated> {
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
    // Per directed edge of the triangulation: how many outline edges run along it in its
    // direction, minus how many run the other way.
    let mut net: HashMap<FixedDirectedEdgeHandle, i64> = HashMap::new();
    for i in 0..n {
        let (a, b) = (handles[i], handles[(i + 1) % n]);
        if a == b {
            continue;
        }
        let along = cdt.try_add_constraint(a, b);
        if along.is_empty() {
            return None;
        }
        for e in along {
            *net.entry(e).or_insert(0) += 1;
            *net.entry(e.rev()).or_insert(0) -= 1;
        }
    }
    // Flood the faces from the outside (winding 0). An outline edge has what it encloses
    // on its left: crossing a directed edge from its left face to its right face lowers
    // the winding number by the edge's net count.
    let faces = cdt.num_all_faces();
    let mut adjacent: Vec<Vec<(usize, i64)>> = vec![Vec::new(); faces];
    for e in cdt.directed_edges() {
        let d = net.get(&e.fix()).copied().unwrap_or(0);
        let (f, g) = (e.face().fix().index(), e.rev().face().fix().index());
        adjacent[f].push((g, -d));
    }
    let mut winding: Vec<Option<i64>> = vec![None; faces];
    let outer = cdt.outer_face().fix().index();
    winding[outer] = Some(0);
    let mut stack = vec![outer];
    while let Some(f) = stack.pop() {
        let here = winding[f].unwrap_or(0);
        for &(g, delta) in &adjacent[f] {
            if winding[g].is_none() {
                winding[g] = Some(here + delta);
                stack.push(g);
            }
        }
    }
    // A simple outline encloses every inside triangle once, all the same way round.
    let mut sign = 0;
    for face in cdt.inner_faces() {
        match winding[face.fix().index()] {
            Some(0) => {}
            Some(w @ (1 | -1)) if sign == 0 || sign == w => sign = w,
            _ => return None,
        }
    }
    let mut out = Vec::new();
    for face in cdt.inner_faces() {
        if winding[face.fix().index()] != Some(sign) || sign == 0 {
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
            original[pos] = net.get(&e.fix()).is_some_and(|&d| d != 0);
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
    Some(Triangulated {
        tris: out,
        ccw: sign > 0,
    })
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
        let tris = triangulate(&pts).unwrap().tris;
        let total: f64 = tris.iter().map(|t| area(&pts, t)).sum();
        assert_eq!(total, 3.0);
        assert!(tris.iter().all(|t| area(&pts, t) > 0.0));
        let originals: usize = tris
            .iter()
            .map(|t| t.original.iter().filter(|o| **o).count())
            .sum();
        assert_eq!(originals, 6);
    }

    /// A square with a square hole joined to its outside by a cut from (0, 0) to (1, 1).
    const KEYHOLE: [[f64; 2]; 10] = [
        [0.0, 0.0],
        [4.0, 0.0],
        [4.0, 4.0],
        [0.0, 4.0],
        [0.0, 0.0],
        [1.0, 1.0],
        [1.0, 3.0],
        [3.0, 3.0],
        [3.0, 1.0],
        [1.0, 1.0],
    ];

    #[test]
    fn a_keyhole_covers_the_region_without_its_hole() {
        for reversed in [false, true] {
            let mut pts = KEYHOLE.to_vec();
            if reversed {
                pts.reverse();
            }
            let t = triangulate(&pts).unwrap();
            assert_eq!(t.ccw, !reversed);
            let total: f64 = t.tris.iter().map(|t| area(&pts, t)).sum();
            assert_eq!(total, 12.0, "reversed: {reversed}");
            assert!(t.tris.iter().all(|t| area(&pts, t) > 0.0));
            // The cut is inside: only the 4 + 4 sides of the square and the hole are
            // outline edges.
            let originals: usize = t
                .tris
                .iter()
                .map(|t| t.original.iter().filter(|o| **o).count())
                .sum();
            assert_eq!(originals, 8);
        }
    }

    #[test]
    fn keyholes_cut_from_any_corner_cover_the_region_without_its_holes() {
        // A 6 × 4 rectangle with two 1 × 1 holes, each joined by a cut from an outer
        // corner (every choice of corners), the second hole also from the first.
        let outer = [[0.0, 0.0], [6.0, 0.0], [6.0, 4.0], [0.0, 4.0]];
        let hole = |x: f64, y: f64| [[x, y], [x, y + 1.0], [x + 1.0, y + 1.0], [x + 1.0, y]];
        let (h1, h2) = (hole(1.0, 1.0), hole(4.0, 2.0));
        let mut simple = 0;
        for from in 0..4 {
            for at1 in 0..4 {
                for at2 in 0..4 {
                    // outer from `from` round to itself, into h1 at `at1` round to itself,
                    // on into h2 at `at2` round to itself, back to h1, back out.
                    let mut pts = Vec::new();
                    for k in 0..=4 {
                        pts.push(outer[(from + k) % 4]);
                    }
                    for k in 0..=4 {
                        pts.push(h1[(at1 + k) % 4]);
                    }
                    for k in 0..=4 {
                        pts.push(h2[(at2 + k) % 4]);
                    }
                    pts.push(h1[at1]);
                    let Some(t) = triangulate(&pts) else {
                        // The cuts cross each other or an edge: not simple.
                        continue;
                    };
                    let total: f64 = t.tris.iter().map(|t| area(&pts, t)).sum();
                    assert_eq!(total, 22.0, "corners {from} {at1} {at2}");
                    simple += 1;
                }
            }
        }
        assert!(simple >= 16, "only {simple} choices were simple");
    }

    #[test]
    fn an_outline_around_a_region_twice_is_rejected() {
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
        let twice: Vec<[f64; 2]> = square.iter().chain(square.iter()).copied().collect();
        assert!(triangulate(&twice).is_none());
    }

    #[test]
    fn bow_tie_is_rejected() {
        let pts = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]];
        assert!(triangulate(&pts).is_none());
    }
}
