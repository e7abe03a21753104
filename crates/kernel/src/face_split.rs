//! The triangles a face is drawn as when it is not one convex planar polygon: the one
//! rule both kernels follow, and the image-space references through
//! [`crate::face_triangles`] (a face's surface is defined once; how it is hidden is
//! computed independently).
//!
//! The corners are the face's as given (consecutive duplicates removed). The coordinate
//! axes are tried in order of the magnitude of the face's approximate Newell normal,
//! largest first (a choice of projection only; every decision below is exact). In the
//! projection along axis `k` (a coordinate dropped: exact) the outline is used if it is
//! *simple there*:
//!
//! 1. a quad is split along the diagonal `p₀p₂` when both its triangles turn strictly
//!    the same way, else along `p₁p₃` when both of those do (a quad is simple with area
//!    exactly when one of its diagonals does this);
//! 2. an outline that turns strictly the same way at every corner and winds once
//!    (strictly convex) is fanned from corner 0;
//! 3. any other outline whose corners project to distinct points (a corner repeated
//!    exactly is one point), whose edges do not cross, and which winds once around what
//!    it encloses is triangulated (constrained Delaunay, see [`crate::triangulate`]). It
//!    may touch itself at a repeated corner and run back along one of its own edges: a
//!    region whose hole is joined to its outside by a cut is drawn without its hole.
//!
//! When no projection is simple (a face that crosses itself from every axis, such as a
//! planar bow tie or star), the face is fanned from corner 0, as OpenGL and gl2ps draw
//! it: every triangle `(p₀, pᵢ, pᵢ₊₁)`. Every triangle keeps the face's winding and is
//! later given its own exact plane; a triangle of exactly zero area is dropped, so only
//! a face whose corners all lie on one line produces nothing.

use std::cmp::Ordering;

use crate::plane::plane_axes;
use crate::triangulate::{triangulate, Tri, Triangulated};

type P3 = [f64; 3];

/// The triangles of the outline `g` (at least 4 corners, no two consecutive ones equal)
/// by the rule in the module docs. `orient(a, b, c, k)` is the orientation of `a, b, c`
/// projected along axis `k` (`Greater`: counter-clockwise seen from `+e_k`); `newell`
/// only orders the axes. Each [`Tri`] lists corner indices in the face's winding and,
/// per edge, whether it is an edge of the outline.
pub(crate) fn split_face(
    g: &[P3],
    newell: P3,
    orient: impl Fn(P3, P3, P3, usize) -> Ordering,
) -> Vec<Tri> {
    let mut axes = [0, 1, 2];
    axes.sort_by(|&a, &b| newell[b].abs().total_cmp(&newell[a].abs()));
    for k in axes {
        if let Some(tris) = simple_in_projection(g, k, &orient) {
            return tris;
        }
    }
    fan(g.len())
}

/// The triangles of `g` in the projection along `k`, or `None` when the outline is not
/// simple there.
fn simple_in_projection(
    g: &[P3],
    k: usize,
    orient: &impl Fn(P3, P3, P3, usize) -> Ordering,
) -> Option<Vec<Tri>> {
    let n = g.len();
    let turn = |a: usize, b: usize, c: usize| orient(g[a], g[b], g[c], k);
    if n == 4 {
        for (a, b, c, d) in [(0, 1, 2, 3), (1, 2, 3, 0)] {
            let s = turn(a, b, c);
            if s != Ordering::Equal && turn(a, c, d) == s {
                // Edges: a→b, b→c original, c→a the diagonal; then a→c the diagonal,
                // c→d, d→a original.
                return Some(vec![
                    Tri {
                        idx: [a, b, c],
                        original: [true, true, false],
                    },
                    Tri {
                        idx: [a, c, d],
                        original: [false, true, true],
                    },
                ]);
            }
        }
        return None;
    }
    let sgn = turn(0, 1, 2);
    if sgn != Ordering::Equal
        && (0..n).all(|i| turn((i + n - 1) % n, i, (i + 1) % n) == sgn)
        && (2..n).all(|i| turn(0, 1, i) == sgn)
    {
        // Every turn the same way and every corner on one side of p₀p₁: the sweep around
        // p₀ stays below 180°, so the outline winds once and the fan covers it.
        return Some(fan(n));
    }
    let (u, v) = plane_axes(k);
    let pts2: Vec<[f64; 2]> = g.iter().map(|p| [p[u], p[v]]).collect();
    if projections_collide(g, &pts2) {
        return None;
    }
    let Triangulated { tris, ccw } = triangulate(&pts2)?;
    if tris.is_empty() {
        // Seen edge-on along `k`: no area in this projection.
        return None;
    }
    // The triangles are counter-clockwise in the projection: turned round when the
    // outline runs the other way.
    Some(if ccw {
        tris
    } else {
        tris.into_iter()
            .map(|t| Tri {
                idx: [t.idx[0], t.idx[2], t.idx[1]],
                original: [t.original[2], t.original[1], t.original[0]],
            })
            .collect()
    })
}

/// Whether two different corners of `g` have the same projection `pts2` (an edge or a
/// part of the face seen edge-on: not simple there). A corner repeated exactly, as in an
/// outline that touches itself, is one point of the triangulation.
fn projections_collide(g: &[P3], pts2: &[[f64; 2]]) -> bool {
    let mut order: Vec<usize> = (0..g.len()).collect();
    // `+ 0.0` makes -0 and +0 one key.
    let key = |i: usize| pts2[i].map(|x| (x + 0.0).to_bits());
    order.sort_unstable_by_key(|&i| key(i));
    order
        .windows(2)
        .any(|w| pts2[w[0]] == pts2[w[1]] && g[w[0]] != g[w[1]])
}

/// The fan of an outline of `n` corners from corner 0, in its winding.
fn fan(n: usize) -> Vec<Tri> {
    (1..n - 1)
        .map(|i| Tri {
            idx: [0, i, i + 1],
            original: [i == 1, true, i + 1 == n - 1],
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn orient(a: P3, b: P3, c: P3, k: usize) -> Ordering {
        let (u, v) = plane_axes(k);
        let o = (b[u] - a[u]) * (c[v] - a[v]) - (b[v] - a[v]) * (c[u] - a[u]);
        o.partial_cmp(&0.0).unwrap()
    }

    fn newell(g: &[P3]) -> P3 {
        let mut n = [0.0; 3];
        for i in 0..g.len() {
            let (a, b) = (g[i], g[(i + 1) % g.len()]);
            n[0] += (a[1] - b[1]) * (a[2] + b[2]);
            n[1] += (a[2] - b[2]) * (a[0] + b[0]);
            n[2] += (a[0] - b[0]) * (a[1] + b[1]);
        }
        n
    }

    /// Twice the area of the triangles projected along z, signed.
    fn area_z(g: &[P3], tris: &[Tri]) -> f64 {
        tris.iter()
            .map(|t| {
                let [a, b, c] = t.idx.map(|i| g[i]);
                (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
            })
            .sum()
    }

    #[test]
    fn a_steep_twisted_quad_is_split_where_it_is_simple() {
        // Seen along x (the largest Newell component) this quad is a bow tie; along z it
        // is the unit square.
        let g = [
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 1.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 9.5],
        ];
        let n = newell(&g);
        assert!(n[0].abs() > n[2].abs());
        let tris = split_face(&g, n, orient);
        assert_eq!(tris.len(), 2);
        assert_eq!(tris[0].idx, [0, 1, 2]);
        assert_eq!(tris[1].idx, [0, 2, 3]);
        assert_eq!(area_z(&g, &tris), 2.0);
    }

    #[test]
    fn a_dart_is_split_along_its_inner_diagonal() {
        // Reflex at corner 3, slightly out of plane.
        let g = [
            [0.0, 0.0, 0.0],
            [2.0, 0.0, 0.0],
            [2.0, 2.0, 1e-9],
            [1.5, 0.5, 0.0],
        ];
        let tris = split_face(&g, newell(&g), orient);
        assert_eq!(tris[0].idx, [1, 2, 3]);
        assert_eq!(tris[1].idx, [1, 3, 0]);
        assert_eq!(area_z(&g, &tris), 2.0);
    }

    #[test]
    fn a_clockwise_l_shape_keeps_its_winding_and_outline_edges() {
        let mut g: Vec<P3> = [
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 1.0],
            [1.0, 1.0],
            [1.0, 2.0],
            [0.0, 2.0],
        ]
        .iter()
        .enumerate()
        .map(|(i, p)| [p[0], p[1], i as f64 * 1e-3])
        .collect();
        g.reverse();
        let tris = split_face(&g, newell(&g), orient);
        assert_eq!(area_z(&g, &tris), -6.0);
        let outline: usize = tris
            .iter()
            .map(|t| t.original.iter().filter(|&&o| o).count())
            .sum();
        assert_eq!(outline, 6);
        for t in &tris {
            for e in 0..3 {
                let (a, b) = (t.idx[e], t.idx[(e + 1) % 3]);
                assert_eq!(t.original[e], b == (a + 1) % 6, "edge {a}→{b}");
            }
        }
    }

    #[test]
    fn a_keyhole_is_drawn_without_its_hole() {
        // A square with a square hole joined by a cut, tilted out of the plane z = 0 so
        // that it is seen along z: fanned from corner 0 it would cover the hole.
        let g: Vec<P3> = [
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
        ]
        .iter()
        .map(|p| [p[0], p[1], 0.25 * p[0]])
        .collect();
        let tris = split_face(&g, newell(&g), orient);
        assert_eq!(area_z(&g, &tris), 24.0);
        let outline: usize = tris
            .iter()
            .map(|t| t.original.iter().filter(|&&o| o).count())
            .sum();
        assert_eq!(outline, 8);
    }

    #[test]
    fn a_star_crossing_itself_from_every_axis_is_fanned() {
        // A pentagram in the plane z = 0 (its edges cross in every projection).
        let g: Vec<P3> = (0..5)
            .map(|i| {
                let t = (i * 2) as f64 * std::f64::consts::TAU / 5.0;
                [t.cos(), t.sin(), 0.0]
            })
            .collect();
        let tris = split_face(&g, newell(&g), orient);
        assert_eq!(tris.len(), 3);
        assert!(tris.iter().all(|t| t.idx[0] == 0));
        assert_eq!(tris[0].original, [true, true, false]);
        assert_eq!(tris[2].original, [false, true, true]);
    }
}
