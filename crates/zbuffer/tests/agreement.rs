//! The methods against each other on random scenes.

mod common;

use common::{cam, grid, layered_triangles, poly, scene_with, Lcg};
use glam::DVec3;
use limn_scene::{Camera, Scene};
use limn_zbuffer::{
    compare, default_band_tolerance, edge_band, render, scene_edges, DepthFormat, Method,
    RenderOptions,
};
use proptest::prelude::*;

const CAMERAS: [[f64; 3]; 4] = [
    [0.0, 0.0, 5.0],
    [2.5, 1.5, 3.5],
    [-3.0, 2.0, 1.0],
    // Inside the scene's extent: triangles cross the near plane and the eye.
    [0.3, 0.2, 0.4],
];

/// Random triangles anywhere (intersecting, any orientation), a height field and a
/// non-convex face.
fn wild_scene(rng: &mut Lcg, n: usize) -> Scene {
    let mut s = scene_with(&[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
    for k in 0..n {
        let pts: Vec<DVec3> = (0..3)
            .map(|_| {
                DVec3::new(
                    rng.range(-1.5, 1.5),
                    rng.range(-1.5, 1.5),
                    rng.range(-1.5, 1.5),
                )
            })
            .collect();
        poly(&mut s, &pts, (k % 3) as u32);
    }
    grid(&mut s, 4, 0.3, -0.5, rng, 1);
    let l = [
        (0.0, 0.0),
        (1.0, 0.0),
        (1.0, 0.4),
        (0.4, 0.4),
        (0.4, 1.0),
        (0.0, 1.0),
    ]
    .map(|(x, y)| DVec3::new(x - 0.5, y - 0.5, 0.7));
    poly(&mut s, &l, 2);
    s
}

fn camera(k: usize) -> Camera {
    cam(DVec3::from(CAMERAS[k]), 64, 48)
}

fn band_for(scene: &Scene, camera: &Camera, opts: &RenderOptions) -> limn_zbuffer::Mask {
    let edges = scene_edges(scene, camera, opts).unwrap();
    let (w, h) = (camera.width, camera.height);
    edge_band(&edges, w, h, default_band_tolerance(w, h))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    #[test]
    fn scanline_gives_the_zbuffers_ids_and_depths(
        seed in any::<u64>(),
        n in 1usize..30,
        fmt in 0usize..4,
        cam_k in 0usize..4,
        cull in any::<bool>(),
    ) {
        let scene = wild_scene(&mut Lcg(seed), n);
        let camera = camera(cam_k);
        let opts = RenderOptions {
            depth: DepthFormat::ALL[fmt],
            cull_back_faces: cull,
            ..RenderOptions::default()
        };
        let z = render(&scene, &camera, Method::ZBuffer, &opts).unwrap();
        let s = render(&scene, &camera, Method::ScanLine, &opts).unwrap();
        prop_assert_eq!(&z.ids, &s.ids);
        prop_assert_eq!(&z.depth, &s.depth);
        prop_assert_eq!(&z.color, &s.color);
        prop_assert!(s.stats.working_bytes < z.stats.working_bytes || z.stats.triangles > 200);
    }

    #[test]
    fn warnock_matches_the_zbuffer_outside_the_band(
        seed in any::<u64>(),
        n in 1usize..25,
        cam_k in 0usize..3,
        fmt in 0usize..2,
    ) {
        let mut rng = Lcg(seed);
        let mut scene = layered_triangles(&mut rng, n, 0.05);
        grid(&mut scene, 3, 0.2, -2.0, &mut rng, 0);
        let camera = camera(cam_k);
        let opts = RenderOptions { depth: DepthFormat::ALL[fmt], ..RenderOptions::default() };
        let z = render(&scene, &camera, Method::ZBuffer, &opts).unwrap();
        let w = render(&scene, &camera, Method::Warnock, &opts).unwrap();
        let band = band_for(&scene, &camera, &opts);
        let c = compare(&z.ids, &w.ids, Some(&band));
        prop_assert_eq!(c.mismatches_outside_band, 0, "{:?}", c);
    }

    #[test]
    fn ray_casting_matches_the_f64_zbuffer_outside_the_band(
        seed in any::<u64>(),
        n in 1usize..25,
        cam_k in 0usize..3,
        cull in any::<bool>(),
    ) {
        let mut rng = Lcg(seed);
        let mut scene = layered_triangles(&mut rng, n, 0.05);
        grid(&mut scene, 3, 0.2, -2.0, &mut rng, 0);
        let camera = camera(cam_k);
        let opts = RenderOptions { cull_back_faces: cull, ..RenderOptions::default() };
        let z = render(&scene, &camera, Method::ZBuffer, &opts).unwrap();
        let r = render(&scene, &camera, Method::RayCast, &opts).unwrap();
        let band = band_for(&scene, &camera, &opts);
        let c = compare(&z.ids, &r.ids, Some(&band));
        prop_assert_eq!(c.mismatches_outside_band, 0, "{:?}", c);
        // Depths agree too where ids agree.
        for i in 0..z.ids.ids.len() {
            if z.ids.ids[i] == r.ids.ids[i] && z.ids.ids[i] != u32::MAX {
                prop_assert!((z.depth.depths[i] - r.depth.depths[i]).abs() < 1e-9);
            }
        }
    }
}

/// A scene where every method must agree everywhere: a closed cube seen from outside,
/// with and without culling (the A-buffer's ids are the nearest fragment's).
#[test]
fn all_methods_agree_on_a_cube() {
    let mut s = scene_with(&[[0.9, 0.1, 0.1]]);
    let v: Vec<u32> = (0..8)
        .map(|i| {
            s.add_vertex(DVec3::new(
                if i & 1 == 0 { -1.0 } else { 1.0 },
                if i & 2 == 0 { -1.0 } else { 1.0 },
                if i & 4 == 0 { -1.0 } else { 1.0 },
            ))
        })
        .collect();
    for q in [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ] {
        s.add_face(&q.map(|k| v[k]), 0, 0).unwrap();
    }
    assert!(s.is_closed());
    let camera = cam(DVec3::new(3.0, 2.2, 4.1), 80, 60);
    for cull in [false, true] {
        let opts = RenderOptions {
            cull_back_faces: cull,
            ..RenderOptions::default()
        };
        let band = band_for(&s, &camera, &opts);
        let reference = render(&s, &camera, Method::RayCast, &opts).unwrap();
        assert!(reference.ids.covered() > 1000);
        for m in Method::ALL {
            let r = render(&s, &camera, m, &opts).unwrap();
            let c = compare(&reference.ids, &r.ids, Some(&band));
            assert_eq!(c.mismatches_outside_band, 0, "{m} cull={cull}: {c:?}");
            if cull {
                assert_eq!(r.stats.culled_faces, 3, "{m}");
            }
        }
    }
}
