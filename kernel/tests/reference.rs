//! Every predicate sign equals a big-rational reference computed on the raw f64 input
//! (no snap): random and near-degenerate points, planes through shared vertices, vertices
//! one ulp off a plane, implicit vertices made by splitting, and coordinates from 1e-300
//! to 1e300 in one case.

mod common;

use common::*;
use glam::DVec3;
use limn_kernel::predicates::orient3d;
use limn_kernel::{ExactKernel, ExactPolygon, Kernel, Plane, Side};
use num_traits::Signed;
use proptest::prelude::*;

/// The side of every vertex of `poly` against `h`, filtered and unfiltered, equals the
/// rational reference.
fn check_vertices(k: &ExactKernel, poly: &ExactPolygon, h: &Plane) {
    let raw = ExactKernel::new().without_filter();
    for i in 0..poly.len() {
        let want = vertex_side(poly, i, h);
        assert_eq!(
            k.side_of_vertex(poly, i, h),
            want,
            "vertex {i} of {poly:?} vs {h:?}"
        );
        assert_eq!(
            raw.side_of_vertex(poly, i, h),
            want,
            "unfiltered vertex {i}"
        );
    }
}

/// Splits `tri` by `cut` and checks every vertex of both pieces against `h` (the cut's
/// new vertices are implicit: intersections of three planes).
fn check_after_split(tri: [[f64; 3]; 3], cut: &Plane, hs: &[Plane]) {
    let k = ExactKernel::new();
    let corners: Vec<DVec3> = tri.iter().map(|p| DVec3::from_array(*p)).collect();
    for poly in k.face_polygons(&corners).unwrap() {
        let (f, b) = k.split(&poly, cut);
        for piece in [f, b].into_iter().flatten() {
            limn_kernel::check::check_polygon(&piece).unwrap();
            for h in hs {
                check_vertices(&k, &piece, h);
            }
            // The cut itself: every vertex on its side or on it.
            check_vertices(&k, &piece, cut);
        }
    }
}

fn rsign(v: num_rational::BigRational) -> std::cmp::Ordering {
    if v.is_positive() {
        std::cmp::Ordering::Greater
    } else if v.is_negative() {
        std::cmp::Ordering::Less
    } else {
        std::cmp::Ordering::Equal
    }
}

/// The reference orient3d: det[a − d; b − d; c − d].
fn orient_ref(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> std::cmp::Ordering {
    let (a, b, c, d) = (qp(a), qp(b), qp(c), qp(d));
    let r = |p: &RPoint| [&p[0] - &d[0], &p[1] - &d[1], &p[2] - &d[2]];
    let (a, b, c) = (r(&a), r(&b), r(&c));
    rsign(
        &a[0] * (&b[1] * &c[2] - &b[2] * &c[1]) - &a[1] * (&b[0] * &c[2] - &b[2] * &c[0])
            + &a[2] * (&b[0] * &c[1] - &b[1] * &c[0]),
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(600))]

    /// Input points against planes through input points and point-normal planes.
    #[test]
    fn points_against_planes(x in world_point(), h in any_plane()) {
        let want = side_at(&h, &qp(x));
        prop_assert_eq!(h.side_of(x), want);
        let k = ExactKernel::new();
        prop_assert_eq!(k.side_of_point(&h, &DVec3::from_array(x)), want);
    }

    /// A point exactly on a plane through three points (one of them, or on an edge
    /// between lattice points) and the same point moved by one ulp on each axis.
    #[test]
    fn one_ulp_off_a_plane(
        a in grid_point(), b in grid_point(), c in grid_point(),
        axis in 0usize..3, ulps in -1i64..=1, which in 0usize..3,
    ) {
        let Some(h) = plane_g(a, b, c) else { return Ok(()) };
        let mut x = gp([a, b, c][which]);
        x[axis] = nudge(x[axis], ulps);
        let want = side_at(&h, &qp(x));
        if ulps == 0 {
            prop_assert_eq!(want, Side::On);
        }
        prop_assert_eq!(h.side_of(x), want);
    }

    /// Orientation of four points, exactly, over the whole f64 range.
    #[test]
    fn orientation(a in world_point(), b in world_point(), c in world_point(), d in world_point()) {
        prop_assert_eq!(orient3d(a, b, c, d), orient_ref(a, b, c, d));
        // Coplanar: d on the line through a and b (a lattice midpoint is exact).
        let m = [0, 1, 2].map(|i| a[i] * 0.5 + b[i] * 0.5);
        prop_assert_eq!(orient3d(a, b, c, m), orient_ref(a, b, c, m));
    }

    /// Implicit vertices (a triangle cut by a plane) against random planes, planes
    /// through the triangle's corners, and the triangle's own support.
    #[test]
    fn implicit_vertices(
        tri in [world_point(), world_point(), world_point()],
        cut in any_plane(), h in any_plane(), p in world_point(),
    ) {
        let mut hs = vec![h];
        if let Ok(t) = Plane::through(tri[0], tri[1], p) {
            hs.push(t);
        }
        if let Ok(t) = Plane::through(tri[1], tri[2], p) {
            hs.push(t);
        }
        check_after_split(tri, &cut, &hs);
    }

    /// Nearly parallel cuts: the plane through two corners of a triangle and a point a
    /// few ulps off the triangle's plane.
    #[test]
    fn nearly_parallel_cuts(
        a in grid_point(), b in grid_point(), c in grid_point(),
        ulps in -3i64..=3, axis in 0usize..3, h in any_plane(),
    ) {
        let tri = [gp(a), gp(b), gp(c)];
        let mut m = [0, 1, 2].map(|i| tri[1][i] * 0.5 + tri[2][i] * 0.5);
        m[axis] = nudge(m[axis], ulps);
        let Ok(cut) = Plane::through(tri[0], m, [0, 1, 2].map(|i| tri[0][i] * 0.5 + tri[2][i] * 0.5)) else {
            return Ok(());
        };
        check_after_split(tri, &cut, &[h]);
    }

    /// The same triangle and cut translated by 1e7, and scaled by 1e-9 and 1e9 (powers
    /// of two keep the scaling exact): the same sides.
    #[test]
    fn translated_and_scaled(
        a in grid_point(), b in grid_point(), c in grid_point(),
        x in grid_point(), y in grid_point(), z in grid_point(), w in grid_point(),
    ) {
        for s in [1.0, 2f64.powi(-30), 2f64.powi(30)] {
            for t in [0.0, 1e7] {
                let f = |g: [i64; 3]| gp(g).map(|v| v * s + t);
                let tri = [f(a), f(b), f(c)];
                let (Ok(cut), Ok(h)) = (Plane::through(f(x), f(y), f(z)), Plane::through(f(x), f(w), f(a))) else {
                    continue;
                };
                check_after_split(tri, &cut, &[h]);
            }
        }
    }
}

#[test]
fn tiny_and_huge_coordinates_in_one_scene() {
    let k = ExactKernel::new();
    let tiny = 1e-300;
    let huge = 1e300;
    // A huge triangle, a tiny one near the origin, and a cut through both.
    let big = [[-huge, -huge, 0.0], [huge, -huge, 0.0], [0.0, huge, tiny]];
    let small = [[0.0, 0.0, 0.0], [tiny, 0.0, 0.0], [0.0, tiny, tiny]];
    let cut = Plane::through(
        [tiny * 0.5, -1.0, -1.0],
        [tiny * 0.5, 1.0, -1.0],
        [tiny * 0.5, 0.0, 1.0],
    )
    .unwrap();
    for tri in [big, small] {
        let corners: Vec<DVec3> = tri.iter().map(|p| DVec3::from_array(*p)).collect();
        let polys = k.face_polygons(&corners).unwrap();
        assert_eq!(polys.len(), 1);
        let (f, b) = k.split(&polys[0], &cut);
        assert!(
            f.is_some() && b.is_some(),
            "the cut x = tiny/2 crosses both"
        );
        for piece in [f, b].into_iter().flatten() {
            check_vertices(&k, &piece, &cut);
            check_vertices(&k, &piece, &polys[0].support());
        }
    }
    // Sides of points far apart in magnitude.
    let h = Plane::through(small[0], small[1], small[2]).unwrap();
    for x in [
        [huge, huge, huge],
        [0.0, 0.0, tiny * 1e-8],
        [tiny, tiny, 0.0],
    ] {
        assert_eq!(h.side_of(x), side_at(&h, &qp(x)));
    }
}

#[test]
fn shared_vertices_are_on_the_plane_without_arithmetic() {
    // Two triangles of a slightly non-planar quad: the shared vertices lie on both
    // planes, the fourth corner is off by one ulp.
    let k = ExactKernel::new();
    let p = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0f64.next_up()],
        [0.0, 1.0, 0.0],
    ];
    let t1 = Plane::through(p[0], p[1], p[2]).unwrap();
    let t2 = Plane::through(p[0], p[2], p[3]).unwrap();
    assert_eq!(t1.side_of(p[0]), Side::On);
    assert_eq!(t2.side_of(p[2]), Side::On);
    assert_eq!(t1.side_of(p[3]), side_at(&t1, &qp(p[3])));
    assert_ne!(t1.side_of(p[3]), Side::On);
    let corners: Vec<DVec3> = p.iter().map(|c| DVec3::from_array(*c)).collect();
    // Not exactly planar: two triangles.
    assert_eq!(k.face_polygons(&corners).unwrap().len(), 2);
}
