//! The same classifications after translating by whole lattice steps (exact in f64), rotating by 90°,
//! mirroring, and rotating the vertex order.

mod common;

use common::*;
use limn_kernel::{ExactPolygon, Kernel, Plane, PolygonSide};
use proptest::prelude::*;

type Map = fn([i64; 3]) -> [i64; 3];

/// Lattice transformations (exact on the f64 input); the bool says whether it reverses orientation.
const MAPS: [(Map, bool); 5] = [
    (|p| [p[0] + 12_345, p[1] - 777, p[2] + 1], false),
    (|p| [-p[1], p[0], p[2]], false),
    (|p| [p[0], -p[2], p[1]], false),
    (|p| [p[2], p[1], -p[0]], false),
    (|p| [-p[0], p[1], p[2]], true),
];

/// A plane through three grid points, as the face of the triangle they form.
fn plane_of(k: &limn_kernel::ExactKernel, t: &[[i64; 3]; 3]) -> Option<Plane> {
    face(k, t).first().map(|p| p.support())
}

fn classify_all(polys: &[ExactPolygon], planes: &[Option<Plane>]) -> Vec<Option<PolygonSide>> {
    let k = kernel();
    polys
        .iter()
        .flat_map(|p| planes.iter().map(|h| h.as_ref().map(|h| k.classify(p, h))))
        .collect()
}

fn split_shape(polys: &[ExactPolygon], planes: &[Option<Plane>]) -> Vec<(usize, usize)> {
    let k = kernel();
    let mut out = Vec::new();
    for p in polys {
        for h in planes.iter().flatten() {
            let (f, b) = k.split(p, h);
            out.push((f.map_or(0, |f| f.len()), b.map_or(0, |b| b.len())));
        }
    }
    out
}

fn flip_side(s: PolygonSide) -> PolygonSide {
    match s {
        PolygonSide::Coplanar => PolygonSide::CoplanarOpposite,
        PolygonSide::CoplanarOpposite => PolygonSide::Coplanar,
        s => s,
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn transforms_preserve_classification(
        pts in lattice_polygon(),
        tri in prop::collection::vec([-2000i64..2000, -2000i64..2000, -2000i64..2000], 3..12),
        rot in 0usize..6,
    ) {
        let k = kernel();
        // Planes: some through corners of the polygon (degenerate), some arbitrary, and
        // the polygon's own plane.
        let mut tris: Vec<[[i64; 3]; 3]> = tri.chunks(3).filter(|c| c.len() == 3).map(|c| [c[0], c[1], c[2]]).collect();
        tris.push([pts[0], pts[1], tri[0]]);
        tris.push([pts[0], pts[1], pts[2]]);
        tris.push([pts[1], pts[2], pts[0]]);
        let planes: Vec<Option<Plane>> = tris.iter().map(|t| plane_of(&k, t)).collect();
        let base = classify_all(&face(&k, &pts), &planes);
        let shape = split_shape(&face(&k, &pts), &planes);

        // Rotating the vertex order.
        let mut rotated = pts.clone();
        let r = rot % pts.len();
        rotated.rotate_left(r);
        prop_assert_eq!(&classify_all(&face(&k, &rotated), &planes), &base);

        for (m, mirror) in MAPS {
            let mut q: Vec<[i64; 3]> = pts.iter().map(|&p| m(p)).collect();
            let mut tq: Vec<[[i64; 3]; 3]> = tris.iter().map(|t| t.map(m)).collect();
            if mirror {
                // Mirroring reverses orientation; reversing the order restores it.
                q.reverse();
                for t in &mut tq {
                    t.swap(1, 2);
                }
            }
            let planes_t: Vec<Option<Plane>> = tq.iter().map(|t| plane_of(&k, t)).collect();
            let got = classify_all(&face(&k, &q), &planes_t);
            // With the order reversed, even Coplanar and CoplanarOpposite are preserved.
            prop_assert_eq!(&got, &base);
            if mirror {
                // Without reversing, the polygon faces the other way.
                let unreversed: Vec<[i64; 3]> = pts.iter().map(|&p| m(p)).collect();
                let got = classify_all(&face(&k, &unreversed), &planes_t);
                let want: Vec<Option<PolygonSide>> = base.iter().map(|s| s.map(flip_side)).collect();
                prop_assert_eq!(&got, &want);
            }
            prop_assert_eq!(split_shape(&face(&k, &q), &planes_t), shape.clone());
        }
    }
}

#[test]
fn world_translation_by_whole_steps_keeps_every_decision() {
    use glam::DVec3;
    let k = kernel();
    let s = STEP;
    // Lattice points: translating them by whole steps is exact in f64.
    let tri = [
        DVec3::new(0.125, 0.25, 0.375),
        DVec3::new(0.5, -0.125, 0.25),
        DVec3::new(-0.375, 0.4375, -0.125),
    ];
    let eye = DVec3::new(0.05, 0.06, 0.9);
    let base = k.face_polygons(&tri).unwrap();
    let h0 = k.support(&base[0]);
    let side0 = k.side_of_point(&h0, &k.point(eye).unwrap());
    for t in [
        DVec3::new(3.0 * s, 0.0, 0.0),
        DVec3::new(-1000.0 * s, 77.0 * s, 5.0 * s),
    ] {
        let moved: Vec<DVec3> = tri.iter().map(|&p| p + t).collect();
        let m = k.face_polygons(&moved).unwrap();
        let h = k.support(&m[0]);
        assert_eq!(h.approx()[..3], h0.approx()[..3]);
        assert_eq!(k.side_of_point(&h, &k.point(eye + t).unwrap()), side0);
        let mut a = Vec::new();
        let mut b = Vec::new();
        k.vertices_world(&base[0], &mut a);
        k.vertices_world(&m[0], &mut b);
        for (p, q) in a.iter().zip(&b) {
            assert_eq!(*q - *p, t);
        }
    }
}
