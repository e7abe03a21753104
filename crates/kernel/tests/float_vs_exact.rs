//! A near-coplanar case the float kernel gets wrong and the exact kernel gets right.

use glam::DVec3;
use limn_kernel::{ExactKernel, FloatKernel, Kernel, PolygonSide, Side};

/// The plane through A = (0,0,0), B = (L,1,0), C = (0,L,1) (units of 2^-25, L = 2^20) has
/// normal (1, -L, L²). The points D = (1,0,0) and D' = (-1,0,0) are at ±1/|n| ≈ 1e-12
/// units from it: far below any float epsilon, yet strictly off the plane.
#[test]
fn near_coplanar_triangle() {
    let lo = DVec3::splat(-1.0);
    let hi = DVec3::splat(1.0);
    let exact = ExactKernel::new();
    let float = FloatKernel::new(lo, hi).unwrap();
    let s = 2f64.powi(-25);
    let l = (1u64 << 20) as f64;
    let w = |x: f64, y: f64, z: f64| DVec3::new(x * s, y * s, z * s);
    let (a, b, c) = (w(0.0, 0.0, 0.0), w(l, 1.0, 0.0), w(0.0, l, 1.0));
    let (d, d2) = (w(1.0, 0.0, 0.0), w(-1.0, 0.0, 0.0));
    let plane_face = [a, b, c];
    // Triangle D, B, D' crosses the plane: D in front, D' behind, B on it.
    let probe = [d2, d, b];

    let he = exact
        .support(&exact.face_polygons(&plane_face).unwrap()[0])
        .clone();
    let pe = &exact.face_polygons(&probe).unwrap()[0];
    assert_eq!(exact.classify(pe, &he), PolygonSide::Spanning);
    let (f, bk) = exact.split(pe, &he);
    assert!(f.is_some() && bk.is_some());
    assert_eq!(
        exact.side_of_point(&he, &exact.point(d).unwrap()),
        Side::Front
    );
    assert_eq!(
        exact.side_of_point(&he, &exact.point(d2).unwrap()),
        Side::Back
    );

    let hf = *float.support(&float.face_polygons(&plane_face).unwrap()[0]);
    let pf = &float.face_polygons(&probe).unwrap()[0];
    // The float kernel calls the polygon coplanar: wrong.
    let got = float.classify(pf, &hf);
    assert!(
        matches!(got, PolygonSide::Coplanar | PolygonSide::CoplanarOpposite),
        "float kernel answered {got:?}"
    );
    assert_eq!(float.side_of_point(&hf, &d), Side::On);
    assert!(matches!(
        float.split(pf, &hf),
        (Some(_), None) | (None, Some(_))
    ));
}
