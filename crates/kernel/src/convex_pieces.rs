//! Convex pieces of an exactly planar face: its triangles merged across diagonals
//! (Hertel and Mehlhorn's rule), so that a non-convex planar face becomes a few convex
//! polygons instead of one triangle per corner.
//!
//! A diagonal is removed when the two pieces it separates stay strictly convex at both of
//! its ends; every turn is an exact orientation in a coordinate projection in which the
//! face has area (exact: a coordinate is dropped). The result has at most four times the
//! fewest convex pieces possible. A merged piece that would not wind once around its
//! inside (an outline that touches itself at a repeated corner) is never formed: each
//! piece is checked whole before it replaces the two it joins.

use std::cmp::Ordering;
use std::collections::HashMap;

use crate::triangulate::Tri;

/// One convex piece: corner indices in the face's winding and, per edge (from corner `k`
/// to corner `k + 1`), whether it lies on the face's outline.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Piece {
    pub(crate) idx: Vec<usize>,
    pub(crate) original: Vec<bool>,
}

/// Merges `tris` (the triangles of one planar face, in its winding) into convex pieces.
/// `turn(a, b, c)` is the exact orientation of corners `a, b, c` in a projection in which
/// the face has area. Triangles of zero area are left out.
pub(crate) fn convex_pieces(
    tris: &[Tri],
    turn: impl Fn(usize, usize, usize) -> Ordering,
) -> Vec<Piece> {
    let mut pieces: Vec<Option<Piece>> = Vec::with_capacity(tris.len());
    let mut sign: Vec<Ordering> = Vec::with_capacity(tris.len());
    for t in tris {
        let s = turn(t.idx[0], t.idx[1], t.idx[2]);
        if s == Ordering::Equal {
            continue;
        }
        pieces.push(Some(Piece {
            idx: t.idx.to_vec(),
            original: t.original.to_vec(),
        }));
        sign.push(s);
    }
    // Each diagonal (a directed edge that is not on the outline) and the piece it bounds.
    let mut owner: HashMap<(usize, usize), usize> = HashMap::new();
    for (p, piece) in pieces.iter().enumerate() {
        let piece = piece
            .as_ref()
            .expect("every piece is present before merging");
        for e in 0..3 {
            if !piece.original[e] {
                owner.insert((piece.idx[e], piece.idx[(e + 1) % 3]), p);
            }
        }
    }
    // Visit each diagonal once, from the piece on its left, in the order the triangles
    // came (the result does not depend on hashing).
    let mut diagonals: Vec<(usize, usize)> = Vec::new();
    for piece in pieces.iter().flatten() {
        for e in 0..3 {
            let (a, b) = (piece.idx[e], piece.idx[(e + 1) % 3]);
            if !piece.original[e] && a < b {
                diagonals.push((a, b));
            }
        }
    }
    for (a, b) in diagonals {
        let (Some(&p), Some(&q)) = (owner.get(&(a, b)), owner.get(&(b, a))) else {
            continue;
        };
        if p == q || sign[p] != sign[q] {
            continue;
        }
        let (Some(left), Some(right)) = (&pieces[p], &pieces[q]) else {
            continue;
        };
        let Some(merged) = join(left, right, a, b) else {
            continue;
        };
        if !strictly_convex(&merged.idx, sign[p], &turn) {
            continue;
        }
        let n = merged.idx.len();
        for e in 0..n {
            if !merged.original[e] {
                owner.insert((merged.idx[e], merged.idx[(e + 1) % n]), p);
            }
        }
        owner.remove(&(a, b));
        owner.remove(&(b, a));
        pieces[p] = Some(merged);
        pieces[q] = None;
    }
    pieces.into_iter().flatten().collect()
}

/// The piece `left ∪ right` across their common edge, `a → b` in `left` and `b → a` in
/// `right`: `left` from `b` round to `a`, then `right` from `a` round to `b`.
fn join(left: &Piece, right: &Piece, a: usize, b: usize) -> Option<Piece> {
    let (nl, nr) = (left.idx.len(), right.idx.len());
    let at_l = (0..nl).find(|&i| left.idx[i] == a && left.idx[(i + 1) % nl] == b)?;
    let at_r = (0..nr).find(|&i| right.idx[i] == b && right.idx[(i + 1) % nr] == a)?;
    let mut idx = Vec::with_capacity(nl + nr - 2);
    let mut original = Vec::with_capacity(nl + nr - 2);
    // left: edges b → … → a (all but the edge a → b).
    for s in 1..nl {
        let e = (at_l + s) % nl;
        idx.push(left.idx[e]);
        original.push(left.original[e]);
    }
    // right: edges a → … → b (all but the edge b → a).
    for s in 1..nr {
        let e = (at_r + s) % nr;
        idx.push(right.idx[e]);
        original.push(right.original[e]);
    }
    Some(Piece { idx, original })
}

/// Whether the corners turn strictly with `sgn` at every corner and wind once (the fan
/// from corner 0 turning the same way and every corner strictly on one side of the first
/// edge keep the sweep below a full turn).
fn strictly_convex(
    idx: &[usize],
    sgn: Ordering,
    turn: &impl Fn(usize, usize, usize) -> Ordering,
) -> bool {
    let n = idx.len();
    (0..n).all(|i| turn(idx[(i + n - 1) % n], idx[i], idx[(i + 1) % n]) == sgn)
        && (2..n).all(|i| turn(idx[0], idx[1], idx[i]) == sgn)
        && (1..n - 1).all(|i| turn(idx[0], idx[i], idx[i + 1]) == sgn)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn turn_of(pts: &[[f64; 2]]) -> impl Fn(usize, usize, usize) -> Ordering + '_ {
        move |a, b, c| {
            let (a, b, c) = (pts[a], pts[b], pts[c]);
            let o = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
            o.partial_cmp(&0.0).unwrap()
        }
    }

    fn area(pts: &[[f64; 2]], idx: &[usize]) -> f64 {
        let n = idx.len();
        (0..n)
            .map(|i| {
                let (a, b) = (pts[idx[i]], pts[idx[(i + 1) % n]]);
                a[0] * b[1] - a[1] * b[0]
            })
            .sum::<f64>()
            / 2.0
    }

    fn tri(idx: [usize; 3], original: [bool; 3]) -> Tri {
        Tri { idx, original }
    }

    #[test]
    fn a_fanned_convex_polygon_becomes_one_piece() {
        // A hexagon's fan: four triangles, three diagonals.
        let pts = [
            [0.0, 0.0],
            [2.0, 0.0],
            [3.0, 1.0],
            [2.0, 2.0],
            [0.0, 2.0],
            [-1.0, 1.0],
        ];
        let tris: Vec<Tri> = (1..5)
            .map(|i| tri([0, i, i + 1], [i == 1, true, i + 1 == 5]))
            .collect();
        let pieces = convex_pieces(&tris, turn_of(&pts));
        assert_eq!(pieces.len(), 1);
        assert_eq!(pieces[0].idx.len(), 6);
        assert!(pieces[0].original.iter().all(|&o| o));
        let whole: f64 = tris.iter().map(|t| area(&pts, &t.idx)).sum();
        assert_eq!(area(&pts, &pieces[0].idx), whole);
    }

    #[test]
    fn an_l_shape_keeps_two_pieces_and_its_area() {
        // 0 (0,0) 1 (2,0) 2 (2,1) 3 (1,1) 4 (1,2) 5 (0,2); reflex at 3.
        let pts = [
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [1.0, 2.0],
            [0.0, 2.0],
        ];
        let tris = [
            tri([0, 1, 2], [true, true, false]),
            tri([0, 2, 3], [false, true, false]),
            tri([0, 3, 5], [false, false, true]),
            tri([3, 4, 5], [true, true, false]),
        ];
        let pieces = convex_pieces(&tris, turn_of(&pts));
        assert_eq!(pieces.len(), 2);
        let total: f64 = pieces.iter().map(|p| area(&pts, &p.idx)).sum();
        assert_eq!(total, 3.0);
        for p in &pieces {
            assert!(strictly_convex(&p.idx, Ordering::Greater, &turn_of(&pts)));
            // Outline flags travel with their edges.
            let n = p.idx.len();
            for e in 0..n {
                let (a, b) = (p.idx[e], p.idx[(e + 1) % n]);
                assert_eq!(p.original[e], b == (a + 1) % 6, "edge {a}→{b}");
            }
        }
    }

    #[test]
    fn a_merge_that_would_leave_a_straight_corner_is_refused() {
        // A square split at the midpoint of its bottom edge into three triangles: merging
        // across both diagonals would leave corner 1 straight (collinear with 0 and 2).
        let pts = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]];
        let tris = [
            tri([0, 1, 4], [true, false, true]),
            tri([1, 2, 3], [true, true, false]),
            tri([1, 3, 4], [false, true, false]),
        ];
        let pieces = convex_pieces(&tris, turn_of(&pts));
        assert_eq!(pieces.len(), 2);
        for p in &pieces {
            assert!(strictly_convex(&p.idx, Ordering::Greater, &turn_of(&pts)));
        }
    }

    #[test]
    fn zero_area_triangles_are_left_out() {
        let pts = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [1.0, 1.0]];
        let tris = [
            tri([0, 1, 2], [true, true, false]),
            tri([0, 2, 3], [false, true, true]),
        ];
        let pieces = convex_pieces(&tris, turn_of(&pts));
        assert_eq!(pieces.len(), 1);
        assert_eq!(pieces[0].idx, vec![0, 2, 3]);
    }
}
