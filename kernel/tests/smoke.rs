//! Quick end-to-end checks of both kernels through the trait.

use glam::DVec3;
use limn_kernel::check::check_split;
use limn_kernel::{ExactKernel, FloatKernel, Kernel, PolygonSide};

fn square(z: f64) -> Vec<DVec3> {
    vec![
        DVec3::new(-1.0, -1.0, z),
        DVec3::new(1.0, -1.0, z),
        DVec3::new(1.0, 1.0, z),
        DVec3::new(-1.0, 1.0, z),
    ]
}

#[test]
fn exact_square_split_many_times() {
    let k = ExactKernel::new(DVec3::splat(-2.0), DVec3::splat(2.0)).unwrap();
    let polys = k.face_polygons(&square(0.5)).unwrap();
    assert_eq!(polys.len(), 1);
    let mut p = polys[0].clone();
    limn_kernel::check::check_polygon(&p).unwrap();
    for i in 0..50 {
        let a = i as f64 * 0.7;
        let n = DVec3::new(a.cos(), a.sin(), 0.1 * (i % 3) as f64);
        let plane = k
            .plane_through(DVec3::new(0.01 * i as f64, -0.013 * i as f64, 0.5), n)
            .unwrap();
        let (f, b) = k.split(&p, &plane);
        check_split(&p, &plane, f.as_ref(), b.as_ref()).unwrap();
        p = f.or(b).unwrap();
    }
    let mut out = Vec::new();
    k.vertices_world(&p, &mut out);
    assert!(out.iter().all(|v| (v.z - 0.5).abs() < 1e-12));
}

#[test]
fn float_square_split() {
    let k = FloatKernel::new(DVec3::splat(-2.0), DVec3::splat(2.0)).unwrap();
    let polys = k.face_polygons(&square(0.0)).unwrap();
    let plane = k.plane_through(DVec3::ZERO, DVec3::X).unwrap();
    assert_eq!(k.classify(&polys[0], &plane), PolygonSide::Spanning);
    let (f, b) = k.split(&polys[0], &plane);
    assert_eq!(k.classify(&f.unwrap(), &plane), PolygonSide::Front);
    assert_eq!(k.classify(&b.unwrap(), &plane), PolygonSide::Back);
}
