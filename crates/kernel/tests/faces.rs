//! Input faces: bad input gives typed errors; non-convex, non-planar and degenerate faces
//! are converted with exactly the right area and the right original edges.

mod common;

use common::*;
use glam::DVec3;
use limn_kernel::check_polygon;
use limn_kernel::{ExactKernel, ExactPolygon, FloatKernel, Kernel, KernelError, PolygonSide, Side};
use num_rational::BigRational;
use num_traits::Zero;

/// Twice the area of an outline given in lattice units in the z = const plane (shoelace).
fn outline_area2(pts: &[[i64; 3]]) -> i128 {
    (0..pts.len())
        .map(|i| {
            let (p, q) = (pts[i], pts[(i + 1) % pts.len()]);
            p[0] as i128 * q[1] as i128 - q[0] as i128 * p[1] as i128
        })
        .sum()
}

/// Twice the projected area in lattice units (world area divided by `STEP²`).
fn total_area2(polys: &[ExactPolygon], axis: usize) -> BigRational {
    let step2 = q(STEP) * q(STEP);
    polys
        .iter()
        .map(|p| projected_area2(p, axis))
        .fold(BigRational::zero(), |s, a| s + a)
        / step2
}

fn originals(polys: &[ExactPolygon]) -> usize {
    polys
        .iter()
        .map(|p| (0..p.len()).filter(|&i| p.edge_is_original(i)).count())
        .sum()
}

fn check_all(polys: &[ExactPolygon]) {
    for p in polys {
        check_polygon(p).unwrap();
    }
}

#[test]
fn bad_input_is_a_typed_error() {
    let k = kernel();
    let f = FloatKernel::new(DVec3::splat(-1.0), DVec3::splat(1.0)).unwrap();
    let ok = DVec3::new(0.1, 0.2, 0.3);
    for bad in [
        DVec3::new(f64::NAN, 0.0, 0.0),
        DVec3::new(0.0, f64::INFINITY, 0.0),
    ] {
        let face = [ok, DVec3::ZERO, bad];
        assert!(matches!(
            k.face_polygons(&face),
            Err(KernelError::NonFinite(..))
        ));
        assert!(matches!(
            f.face_polygons(&face),
            Err(KernelError::NonFinite(..))
        ));
        assert!(matches!(k.point(bad), Err(KernelError::NonFinite(..))));
        assert!(k.plane_through(bad, DVec3::X).is_err());
        assert!(k.plane_through(ok, bad).is_err());
        assert!(f.plane_through(ok, bad).is_err());
    }
    // There is no grid: any finite corner, eye or plane point is accepted, however far.
    let far = [ok, DVec3::ZERO, DVec3::new(5e300, 0.0, 0.0)];
    assert_eq!(k.face_polygons(&far).unwrap().len(), 1);
    assert!(matches!(k.face_polygons(&[]), Err(KernelError::Empty)));
    assert!(matches!(f.face_polygons(&[]), Err(KernelError::Empty)));
    assert!(matches!(
        k.plane_through(ok, DVec3::ZERO),
        Err(KernelError::ZeroNormal)
    ));
    assert_eq!(k.point(DVec3::splat(1e300)).unwrap(), DVec3::splat(1e300));
    assert!(k.point(DVec3::splat(1e6)).is_ok());
    assert!(k.face_polygons(&[DVec3::ONE; 3]).unwrap().is_empty());
}

#[test]
fn degenerate_faces_are_empty() {
    let k = kernel();
    assert!(face(&k, &[[0, 0, 0], [5, 5, 5]]).is_empty());
    assert!(face(&k, &[[0, 0, 0], [5, 5, 5], [10, 10, 10]]).is_empty());
    assert!(face(&k, &[[1, 2, 3]; 4]).is_empty());
    // Nothing collapses that is not degenerate as given: a triangle of side 1e-300 is
    // a proper polygon.
    let tiny = [
        DVec3::ZERO,
        DVec3::new(1e-300, 0.0, 0.0),
        DVec3::new(0.0, 1e-300, 0.0),
    ];
    let polys = k.face_polygons(&tiny).unwrap();
    assert_eq!(polys.len(), 1);
    check_all(&polys);
}

#[test]
fn duplicate_and_collinear_corners_are_removed() {
    let k = kernel();
    let pts = [
        [0, 0, 0],
        [0, 0, 0],
        [5, 0, 0],
        [10, 0, 0],
        [10, 10, 0],
        [10, 10, 0],
        [0, 10, 0],
        [0, 0, 0],
    ];
    let polys = face(&k, &pts);
    check_all(&polys);
    assert_eq!(polys.len(), 1);
    assert_eq!(polys[0].len(), 4);
    assert_eq!(originals(&polys), 4);
    assert_eq!(
        total_area2(&polys, 2),
        BigRational::from_integer(200.into())
    );
}

fn assert_split(pts: &[[i64; 3]], expected_pieces: usize, outline_edges: usize) {
    let k = kernel();
    let polys = face(&k, pts);
    check_all(&polys);
    assert_eq!(polys.len(), expected_pieces, "{polys:?}");
    let want = BigRational::from_integer(outline_area2(pts).into());
    assert_eq!(total_area2(&polys, 2), want);
    // Every outline edge appears once as an original edge; diagonals are not original.
    assert_eq!(originals(&polys), outline_edges);
    // Same result for every rotation of the corner order.
    for r in 1..pts.len() {
        let mut q = pts.to_vec();
        q.rotate_left(r);
        let polys = face(&k, &q);
        assert_eq!(total_area2(&polys, 2), want);
        assert_eq!(originals(&polys), outline_edges);
    }
}

#[test]
fn l_shape() {
    let l = [
        [0, 0, 7],
        [20, 0, 7],
        [20, 10, 7],
        [10, 10, 7],
        [10, 20, 7],
        [0, 20, 7],
    ];
    // Planar: its triangles are merged into two convex pieces.
    assert_split(&l, 2, 6);
}

#[test]
fn star() {
    let mut pts = Vec::new();
    for i in 0..10 {
        let a = std::f64::consts::PI * i as f64 / 5.0;
        let r = if i % 2 == 0 { 1000.0 } else { 400.0 };
        pts.push([
            (r * a.cos()).round() as i64,
            (r * a.sin()).round() as i64,
            -3,
        ]);
    }
    // Planar: a heptagon through the centre and three spikes.
    assert_split(&pts, 4, 10);
}

#[test]
fn clockwise_l_shape_faces_down() {
    let mut l = vec![
        [0, 0, 7],
        [20, 0, 7],
        [20, 10, 7],
        [10, 10, 7],
        [10, 20, 7],
        [0, 20, 7],
    ];
    l.reverse();
    let k = kernel();
    let polys = face(&k, &l);
    check_all(&polys);
    assert!(polys.iter().all(|p| p.support().approx()[2] < 0.0));
    assert_eq!(
        total_area2(&polys, 2),
        BigRational::from_integer((-600).into())
    );
}

#[test]
fn non_planar_quad_is_two_triangles() {
    let k = kernel();
    let quad = [[0, 0, 0], [100, 0, 0], [100, 100, 30], [0, 100, 0]];
    let polys = face(&k, &quad);
    check_all(&polys);
    assert_eq!(polys.len(), 2);
    assert_eq!(originals(&polys), 4);
    // Both triangles face up; their projections cover the square exactly.
    assert!(polys.iter().all(|p| p.support().approx()[2] > 0.0));
    assert_eq!(
        total_area2(&polys, 2),
        BigRational::from_integer(20000.into())
    );
}

#[test]
fn off_plane_noise_is_triangulated_so_neighbours_share_corners_exactly() {
    // A square whose corner is one lattice step off the plane: two triangles whose corners
    // are the input grid points; the diagonal is not an original edge.
    let k = kernel();
    let quad = [[0, 0, 0], [1000, 0, 0], [1000, 1000, 1], [0, 1000, 0]];
    let polys = face(&k, &quad);
    check_all(&polys);
    assert_eq!(polys.len(), 2);
    assert_eq!(originals(&polys), 4);
    // The exactly planar square stays one polygon.
    let flat = [[0, 0, 0], [1000, 0, 0], [1000, 1000, 0], [0, 1000, 0]];
    let polys = face(&k, &flat);
    assert_eq!(polys.len(), 1);
    assert_eq!(originals(&polys), 4);
}

#[test]
fn self_intersecting_faces_are_fanned_from_their_first_corner() {
    // A bow tie crosses itself seen along every axis: no projection is simple, so it is
    // drawn as OpenGL draws it, the triangles (p0, p1, p2) and (p0, p2, p3), each with its
    // own plane and each keeping the face's winding.
    let k = kernel();
    let bow = [[0, 0, 0], [100, 100, 0], [100, 0, 0], [0, 100, 0]];
    let polys = face(&k, &bow);
    check_all(&polys);
    assert_eq!(polys.len(), 2);
    let areas: Vec<BigRational> = polys
        .iter()
        .map(|p| projected_area2(p, 2) / (q(STEP) * q(STEP)))
        .collect();
    assert_eq!(areas[0], q(-10000.0));
    assert_eq!(areas[1], q(10000.0));
    // The outline edges p0p1, p1p2 and p2p3, p3p0 are original; the diagonal is not.
    assert_eq!(originals(&polys), 4);
    let f = FloatKernel::new(DVec3::splat(-1.0), DVec3::splat(1.0)).unwrap();
    let bow_w: Vec<DVec3> = bow
        .iter()
        .map(|p| DVec3::new(p[0] as f64, p[1] as f64, 0.0) * 1e-3)
        .collect();
    assert_eq!(f.face_polygons(&bow_w).unwrap().len(), 2);
    // An unbalanced self-intersection (a figure with a crossing) is fanned too.
    let fig = [[0, 0, 0], [300, 300, 0], [300, 0, 0], [0, 100, 0]];
    let polys = face(&k, &fig);
    check_all(&polys);
    assert_eq!(polys.len(), 2);
    // Only a face whose corners all lie on one line draws nothing.
    let line = [[0, 0, 0], [100, 100, 100], [300, 300, 300], [200, 200, 200]];
    assert!(face(&k, &line).is_empty());
}

#[test]
fn float_kernel_splits_into_the_same_convex_pieces() {
    let f = FloatKernel::new(DVec3::splat(-50.0), DVec3::splat(50.0)).unwrap();
    let l: Vec<DVec3> = [
        [0., 0.],
        [20., 0.],
        [20., 10.],
        [10., 10.],
        [10., 20.],
        [0., 20.],
    ]
    .iter()
    .map(|p| DVec3::new(p[0], p[1], 1.0))
    .collect();
    let polys = f.face_polygons(&l).unwrap();
    // Planar: merged into two convex pieces, as the exact kernel merges it (`l_shape`).
    assert_eq!(polys.len(), 2);
    let mut area = 0.0;
    let mut originals = 0;
    for p in &polys {
        let v: Vec<DVec3> = p.vertices().collect();
        area += (1..v.len() - 1)
            .map(|i| 0.5 * (v[i] - v[0]).cross(v[i + 1] - v[0]).z)
            .sum::<f64>();
        originals += (0..v.len()).filter(|&i| f.edge_is_original(p, i)).count();
    }
    assert_eq!(area, 300.0);
    assert_eq!(originals, 6);
}

/// Found by the `kernel_split` fuzz target: an outline whose turns all have the same sign
/// but which winds around twice (after removing a collinear spike) was taken for convex.
#[test]
fn fuzz_double_winding_original() {
    let k = kernel();
    let pts = [
        [327679, -1, -1],
        [33554432, -1, -1],
        [-1, -1, -1],
        [-16514824, -1, -1],
        [33554176, 33554432, -1],
        [33554432, -171, -1],
        [65535, 0, 0],
    ];
    for p in face(&k, &pts) {
        check_polygon(&p).unwrap();
    }
}

/// The same, reduced: five corners in one plane, every turn clockwise, winding twice.
#[test]
fn fuzz_double_winding_reduced() {
    let k = kernel();
    let pts = [
        [327679, -1, -1],
        [-16514824, -1, -1],
        [33554176, 33554432, -1],
        [33554432, -171, -1],
        [65535, 0, -1],
    ];
    let polys = face(&k, &pts);
    check_all(&polys);
    // Not a simple outline: it is dropped, never returned as one convex polygon.
    assert!(polys.len() != 1);
}

/// Every corner of a planar quad lies on its support plane, the one outside the plane's
/// definition too: classifying a neighbour that shares that corner (and the edge) against
/// it needs no exact evaluation, far from the origin as near it.
#[test]
fn a_quads_fourth_corner_is_known_on_its_plane() {
    for off in [0.0, 1e7, 1e9] {
        let k = ExactKernel::new();
        let p = |x: f64, y: f64, z: f64| DVec3::new(x + off, y + off, z + off);
        let a = k
            .face_polygons(&[
                p(0.0, 0.0, 0.0),
                p(1.0, 0.0, 0.0),
                p(1.0, 1.0, 0.0),
                p(0.0, 1.0, 0.0),
            ])
            .unwrap();
        assert_eq!(a.len(), 1);
        let plane = k.support(&a[0]);
        // Shares the edge from corner 2 to corner 3 of `a`, rising out of its plane.
        let b = k
            .face_polygons(&[
                p(0.0, 1.0, 0.0),
                p(1.0, 1.0, 0.0),
                p(1.0, 2.0, 1.0),
                p(0.0, 2.0, 1.0),
            ])
            .unwrap();
        for poly in &b {
            assert_eq!(k.classify(poly, plane), PolygonSide::Front, "offset {off}");
        }
        assert_eq!(k.fallbacks(), 0, "offset {off}");
        for q in [p(0.0, 1.0, 0.0), p(1.0, 1.0, 0.0)] {
            assert_eq!(k.side_of_point(plane, &q), Side::On);
        }
        assert_eq!(k.fallbacks(), 0, "offset {off}");
    }
}
