//! Every predicate sign equals a big-rational reference computed on the raw f64 input
//! (no snap): random and near-degenerate points, planes through shared vertices, vertices
//! one ulp off a plane, implicit vertices made by splitting, and coordinates from 1e-300
//! to 1e300 in one case.

mod common;

use common::*;
use glam::DVec3;
use limn_kernel::check_split;
use limn_kernel::orient3d;
use limn_kernel::{ExactKernel, ExactPolygon, Kernel, Plane, PolygonSide, Side};
use num_traits::Signed;
use proptest::prelude::*;

/// The side of every vertex of `poly` against `h`, filtered and unfiltered, and the
/// classification of `poly` against `h`, equal the rational reference.
fn check_vertices(k: &ExactKernel, poly: &ExactPolygon, h: &Plane) {
    let raw = ExactKernel::new().without_filter();
    let want = reference_classify(poly, h);
    assert_eq!(k.classify(poly, h), want, "classify {poly:?} vs {h:?}");
    assert_eq!(raw.classify(poly, h), want, "unfiltered classify");
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
        for h in hs {
            check_vertices(&k, &poly, h);
        }
        let (f, b) = k.split(&poly, cut);
        check_split(&poly, cut, f.as_ref(), b.as_ref()).unwrap();
        for piece in [f, b].into_iter().flatten() {
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
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

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

    /// The same triangle and cut translated by 1e7, and scaled by about 1e-9 and 1e9
    /// (2^-30 and 2^30, which keep lattice points exact): every side as the reference.
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

/// A point uniform in [-1, 1)³.
fn unit_point() -> impl Strategy<Value = [f64; 3]> {
    [-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0]
}

/// Positions of `pt` after moving coordinate `axis` by `ulps` representable values.
fn nudged(mut pt: [f64; 3], axis: usize, ulps: i64) -> [f64; 3] {
    pt[axis] = nudge(pt[axis], ulps);
    pt
}

/// The point with coordinate `axis` set to `c` and the others `u`, `v` (in the order of
/// the axes after `axis`).
fn on_axis_plane(axis: usize, c: f64, u: f64, v: f64) -> [f64; 3] {
    let mut p = [0.0; 3];
    p[axis] = c;
    p[(axis + 1) % 3] = u;
    p[(axis + 2) % 3] = v;
    p
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// The reference itself: the integer rows used for implicit vertices are positive
    /// multiples of the rational coefficients built from each f64 exactly.
    #[test]
    fn oracle_rows_are_positive_multiples(h in any_plane(), flip in any::<bool>()) {
        let h = if flip { h.flipped() } else { h };
        let (n, d) = coefficients(&h);
        let c = [n[0].clone(), n[1].clone(), n[2].clone(), d];
        let r = integer_row(&h).map(num_rational::BigRational::from_integer);
        let i = (0..4).find(|&i| !num_traits::Zero::is_zero(&c[i])).unwrap();
        let lambda = &r[i] / &c[i];
        prop_assert!(lambda.is_positive());
        for j in 0..4 {
            prop_assert_eq!(&r[j], &(&c[j] * &lambda));
        }
    }

    /// A plane through axis-aligned points (coordinate `axis` equal to `c` at all three:
    /// any f64, from 1e-300 to 1e300) and a point on it that is not one of them, exactly
    /// on it or one ulp off along the normal; one ulp along another axis stays on it. As
    /// a point, as a vertex of a triangle with its other corners on the plane (Front or
    /// Back, never coplanar, unless the offset is zero), and after splitting a triangle
    /// that straddles it by one ulp.
    #[test]
    fn one_ulp_off_an_axis_aligned_plane(
        axis in 0usize..3, c in world_coord(),
        uv in [world_coord(), world_coord(), world_coord(), world_coord(), world_coord(), world_coord()],
        ulps in -1i64..=1, along in 1usize..3, h in any_plane(),
    ) {
        let k = ExactKernel::new();
        let a = on_axis_plane(axis, c, uv[0], uv[1]);
        let b = on_axis_plane(axis, c, uv[2], uv[1]);
        let d = on_axis_plane(axis, c, uv[0], uv[3]);
        let Ok(plane) = Plane::through(a, b, d) else { return Ok(()) };
        let mut normal = [0.0; 3];
        normal[axis] = 1.0;
        let pn = Plane::point_normal(a, normal).unwrap();
        let api = k.plane_through(DVec3::from_array(b), DVec3::from_array(normal)).unwrap();
        let on = on_axis_plane(axis, c, uv[4], uv[5]);
        let x = nudged(on, axis, ulps);
        let sideways = nudged(on, (axis + along) % 3, 1);
        for pl in [&plane, &pn, &api, &plane.flipped()] {
            let want = side_at(pl, &qp(x));
            prop_assert_eq!(want == Side::On, ulps == 0 || x[axis] == c);
            prop_assert_eq!(pl.side_of(x), want);
            prop_assert_eq!(k.side_of_point(pl, &DVec3::from_array(x)), want);
            prop_assert_eq!(pl.side_of(sideways), Side::On);
            prop_assert_eq!(pl.side_of(on), Side::On);
        }
        // A triangle with two corners on the plane and the third one ulp off.
        let corners = [a, b, x].map(DVec3::from_array);
        for poly in k.face_polygons(&corners).unwrap() {
            for pl in [&plane, &pn, &api] {
                check_vertices(&k, &poly, pl);
                let got = k.classify(&poly, pl);
                if ulps != 0 && x[axis] != c {
                    prop_assert!(matches!(got, PolygonSide::Front | PolygonSide::Back));
                }
            }
        }
        // A triangle with a corner one ulp on each side: cut by the plane, the new vertices
        // lie exactly on it, and each piece is checked against the plane, another plane
        // and the plane through the rounded new vertex.
        let lo = nudged(on, axis, -1);
        let hi = nudged(d, axis, 1);
        let tri = [lo, hi, b];
        let mut hs = vec![h, plane.clone(), pn.clone()];
        let corners = tri.map(DVec3::from_array);
        for poly in k.face_polygons(&corners).unwrap() {
            prop_assert_eq!(k.classify(&poly, &pn), PolygonSide::Spanning);
            let (f, bk) = k.split(&poly, &pn);
            check_split(&poly, &pn, f.as_ref(), bk.as_ref()).unwrap();
            for piece in [&f, &bk].into_iter().flatten() {
                for i in 0..piece.len() {
                    let r = k.vertex_rounded(piece, i);
                    if let Ok(t) = Plane::through(r, lo, hi) {
                        hs.push(t);
                    }
                }
            }
            for piece in [f, bk].into_iter().flatten() {
                for t in &hs {
                    check_vertices(&k, &piece, t);
                }
            }
        }
    }

    /// One ulp off a plane through three raw f64 points (any magnitude), along every
    /// axis, starting from one of the defining points (exactly on the plane).
    #[test]
    fn one_ulp_off_a_raw_plane(
        a in world_point(), b in world_point(), c in world_point(),
        axis in 0usize..3, ulps in -2i64..=2, which in 0usize..3,
    ) {
        let Ok(h) = Plane::through(a, b, c) else { return Ok(()) };
        let x = nudged([a, b, c][which], axis, ulps);
        let want = side_at(&h, &qp(x));
        prop_assert_eq!(h.side_of(x), want);
        prop_assert_eq!(h.flipped().side_of(x), want.flip());
        let k = ExactKernel::new().without_filter();
        prop_assert_eq!(k.side_of_point(&h, &DVec3::from_array(x)), want);
    }

    /// Two successive cuts: the second cut crosses the first cut's edge, making a vertex
    /// that is the intersection of the support and two cut planes (no input point at
    /// all). Every vertex of every piece against random planes and against planes through
    /// the rounded vertices (within an ulp or so of them).
    #[test]
    fn vertices_of_two_cuts(
        tri in [world_point(), world_point(), world_point()],
        n1 in world_point(), n2 in world_point(), s in 0.05f64..0.95, t in 0.05f64..0.95,
        h in any_plane(), other in world_point(),
    ) {
        let k = ExactKernel::new();
        let corners = tri.map(DVec3::from_array);
        let Ok(polys) = k.face_polygons(&corners) else { return Ok(()) };
        for poly in polys {
            // Points inside the triangle (rounded barycentric combinations).
            let inner = |s: f64, t: f64| {
                [0, 1, 2].map(|i| tri[0][i] * (1.0 - s) * (1.0 - t) + tri[1][i] * s * (1.0 - t) + tri[2][i] * t)
            };
            let (Ok(c1), Ok(c2)) = (
                Plane::point_normal(inner(s, t), n1),
                Plane::point_normal(inner(t, s), n2),
            ) else { continue };
            let (f, b) = k.split(&poly, &c1);
            check_split(&poly, &c1, f.as_ref(), b.as_ref()).unwrap();
            for piece in [f, b].into_iter().flatten() {
                let (f2, b2) = k.split(&piece, &c2);
                check_split(&piece, &c2, f2.as_ref(), b2.as_ref()).unwrap();
                for p2 in [f2, b2].into_iter().flatten() {
                    let mut hs = vec![h.clone(), c1.clone(), c2.clone()];
                    for i in 0..p2.len() {
                        if let Ok(t) = Plane::through(k.vertex_rounded(&p2, i), other, tri[i % 3]) {
                            hs.push(t);
                        }
                    }
                    for pl in &hs {
                        check_vertices(&k, &p2, pl);
                    }
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(60))]

    /// Raw f64 triangles (not lattice points) translated by 1e7 and scaled by 1e-9 and
    /// 1e9 (inexact operations: the input is whatever f64 results), every side and
    /// classification as the reference, including a plane through a corner and a point
    /// one ulp off the triangle's plane.
    #[test]
    fn raw_translated_and_scaled(
        tri in [unit_point(), unit_point(), unit_point()],
        p in unit_point(), n in unit_point(),
        axis in 0usize..3, ulps in -1i64..=1,
    ) {
        for s in [1.0, 1e-9, 1e9] {
            for t in [0.0, 1e7, -1e7] {
                let f = |v: [f64; 3]| v.map(|x| x * s + t);
                let ft = tri.map(f);
                let Ok(cut) = Plane::point_normal(f(p), n) else { continue };
                let mut hs = vec![];
                if let Ok(h) = Plane::through(ft[0], ft[1], nudged(ft[2], axis, ulps)) {
                    hs.push(h);
                }
                if let Ok(h) = Plane::through(ft[0], f(p), [ft[1][0], ft[1][1], ft[2][2]]) {
                    hs.push(h);
                }
                check_after_split(ft, &cut, &hs);
            }
        }
    }
}
