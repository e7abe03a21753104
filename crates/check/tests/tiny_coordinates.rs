//! Ray casting agrees with the painter on coordinates of any finite size: a vertex
//! coordinate of 5.2e-36 beside coordinates near 1 (as a glTF file had), and a whole
//! scene scaled by 2⁻¹³⁰ (below the range of f64 expansions; the camera refuses much smaller scenes).

use glam::DVec3;
use limn_check::paint;
use limn_depthsort::OrderOptions;
use limn_scene::{Camera, Material, Scene};
use limn_zbuffer::{DepthFormat, Method};

/// Two triangles passing through each other and a quad behind them, every coordinate
/// times `s`; `nudge` is added to one coordinate of the first triangle.
fn crossing(s: f64, nudge: f64) -> Scene {
    let mut scene = Scene::default();
    let m = scene.add_material(Material::unlit("grey", [0.5; 3]));
    let o = scene.add_object("parts");
    let faces: [&[[f64; 3]]; 3] = [
        &[[-1.0, -1.0, -0.5], [1.0, -1.0, 0.5], [0.0, 1.0, 0.0]],
        &[[-1.0, 0.0, 0.5], [1.0, 0.2, -0.5], [0.0, -1.0, 0.0]],
        &[
            [-2.0, -2.0, -1.0],
            [2.0, -2.0, -1.0],
            [2.0, 2.0, -1.0],
            [-2.0, 2.0, -1.0],
        ],
    ];
    for (k, f) in faces.iter().enumerate() {
        let mut pts: Vec<DVec3> = f.iter().map(|&p| DVec3::from(p) * s).collect();
        if k == 0 {
            pts[2].x += nudge;
        }
        scene.add_polygon(&pts, m, o).unwrap();
    }
    scene
}

fn agrees(scene: &Scene, camera: &Camera) {
    let painted = paint(scene, camera, &OrderOptions::default()).unwrap();
    assert!(!painted.ordered.fragments.is_empty());
    let r = painted
        .reference(scene, Method::RayCast, DepthFormat::F64)
        .expect("ray casting accepts every finite coordinate");
    let c = painted.compare(&r);
    assert_eq!(c.mismatches_outside_band, 0, "{c:?}");
    // Something of every face is seen.
    for f in 0..3 {
        assert!(r.ids.contains(&f), "face {f}");
    }
}

#[test]
fn a_tiny_coordinate_beside_ordinary_ones() {
    let scene = crossing(1.0, 5.2e-36);
    let camera = Camera::new(DVec3::new(0.3, 0.4, 5.0), DVec3::ZERO, 96, 72);
    agrees(&scene, &camera);
}

#[test]
fn a_whole_scene_at_two_to_the_minus_130() {
    let s = 2f64.powi(-130);
    let scene = crossing(s, 0.0);
    let camera = Camera::new(DVec3::new(0.3, 0.4, 5.0) * s, DVec3::ZERO, 96, 72);
    agrees(&scene, &camera);
}
