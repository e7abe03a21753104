//! Arbitrary input never panics: every failure is a typed error or an empty result.

use glam::DVec3;
use limn_kernel::{ExactKernel, FloatKernel, Kernel};
use proptest::prelude::*;

/// Any f64, weighted toward awkward values.
fn any_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => -2.0f64..2.0,
        1 => any::<u64>().prop_map(f64::from_bits),
        1 => prop_oneof![
            Just(f64::NAN),
            Just(f64::INFINITY),
            Just(f64::NEG_INFINITY),
            Just(0.0),
            Just(-0.0),
            Just(f64::MIN_POSITIVE),
            Just(5e-324),
            Just(f64::MAX),
            Just(1e300),
        ],
    ]
}

fn point() -> impl Strategy<Value = DVec3> {
    [any_f64(), any_f64(), any_f64()].prop_map(DVec3::from_array)
}

fn exercise<K: Kernel>(k: &K, face: &[DVec3], p: DVec3, n: DVec3) {
    let polys = k.face_polygons(face).unwrap_or_default();
    let plane = k.plane_through(p, n);
    let eye = k.point(p);
    for poly in &polys {
        let mut out = Vec::new();
        k.vertices_world(poly, &mut out);
        assert!(k.vertex_count(poly) >= 3);
        // Out of range is simply not original.
        assert!(!k.edge_is_original(poly, k.vertex_count(poly)));
        if let Ok(h) = &plane {
            let _ = k.classify(poly, h);
            let _ = k.split(poly, h);
            let s = k.support(poly);
            let _ = k.split(poly, s);
        }
        if let Ok(e) = &eye {
            let _ = k.side_of_point(k.support(poly), e);
            let _ = k.point_world(e);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1500))]

    #[test]
    fn kernels_never_panic(
        lo in point(), hi in point(),
        face in prop::collection::vec(point(), 0..9),
        p in point(), n in point(),
    ) {
        exercise(&ExactKernel::new(), &face, p, n);
        exercise(&ExactKernel::new().without_filter(), &face, p, n);
        if let Ok(k) = FloatKernel::new(lo, hi) {
            exercise(&k, &face, p, n);
        }
        let k = FloatKernel::new(DVec3::splat(-2.0), DVec3::splat(2.0)).unwrap();
        exercise(&k, &face, p, n);
    }
}
