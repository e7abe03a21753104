//! The hard-case corpus seen through an orthographic camera and through cameras given as
//! view-projection matrices: every exact ordering paints what exact ray casting sees.

use glam::DVec3;
use limn_check::paint;
use limn_depthsort::{OrderOptions, SortMode};
use limn_scene::{Camera, Projection, Scene, Viewpoint};
use limn_tests::corpus::{self, Case};
use limn_zbuffer::{DepthFormat, Method};

const EXACT_MODES: [SortMode; 3] = [SortMode::Adaptive, SortMode::Bsp, SortMode::Newell];

fn opts(sort: SortMode) -> OrderOptions {
    OrderOptions {
        sort,
        ..OrderOptions::default()
    }
}

/// Mismatching pixels outside the edge band between the painter's order and ray casting.
fn wrong_pixels(scene: &Scene, camera: &Camera, sort: SortMode) -> usize {
    let p = paint(scene, camera, &opts(sort)).expect("orders");
    let r = p
        .reference(scene, Method::RayCast, DepthFormat::F64)
        .expect("ray casts");
    p.compare(&r).mismatches_outside_band
}

/// An orthographic camera looking along the case's own view direction.
fn ortho(case: &Case) -> Camera {
    let c = &case.camera;
    Camera::framing_orthographic(&case.scene, c.eye - c.target, c.width, c.height).expect("frames")
}

#[test]
fn every_exact_mode_is_exact_through_an_orthographic_camera() {
    let mut painted = 0;
    for case in corpus::all() {
        let cam = ortho(&case);
        assert!(matches!(cam.viewpoint(), Ok(Viewpoint::Toward(_))));
        for mode in EXACT_MODES {
            let wrong = wrong_pixels(&case.scene, &cam, mode);
            assert_eq!(wrong, 0, "{} / {} (orthographic)", case.name, mode.name());
            painted += 1;
        }
    }
    assert!(painted > 20);
}

#[test]
fn one_depth_per_polygon_is_wrong_through_an_orthographic_camera_too() {
    // The check can fail: the baseline paints the cyclic quads wrongly seen from infinity.
    let case = corpus::cyclic_quads();
    let cam = ortho(&case);
    assert!(wrong_pixels(&case.scene, &cam, SortMode::Simple) > 0);
    assert_eq!(wrong_pixels(&case.scene, &cam, SortMode::Adaptive), 0);
}

#[test]
fn matrix_cameras_are_exact_and_match_their_look_at_twins() {
    for case in corpus::all() {
        for look_at in [case.camera, ortho(&case)] {
            let (near, far) = look_at.near_far(&case.scene);
            let m = look_at.view_projection(near, far);
            let cam = Camera::from_matrix(m, look_at.width, look_at.height).expect("matrix");
            assert!(matches!(cam.projection, Projection::Matrix(_)));
            for mode in EXACT_MODES {
                let wrong = wrong_pixels(&case.scene, &cam, mode);
                assert_eq!(wrong, 0, "{} / {} (matrix)", case.name, mode.name());
            }
            // The same picture as the look-at camera, face by face.
            let a = paint(&case.scene, &look_at, &opts(SortMode::Adaptive)).unwrap();
            let b = paint(&case.scene, &cam, &opts(SortMode::Adaptive)).unwrap();
            let cmp = b.compare(&a.ids);
            assert_eq!(cmp.mismatches_outside_band, 0, "{}", case.name);
        }
    }
}

#[test]
fn faces_seen_edge_on_from_infinity_are_dropped_exactly() {
    // A square whose plane contains the viewing direction shows nothing; tilted by one
    // ulp it faces the eye and shows.
    let (mut s, mats, o) = {
        let mut s = Scene::default();
        let m = s.add_material(limn_scene::Material::unlit("a", [1.0, 0.0, 0.0]));
        let o = s.add_object("edge-on");
        (s, m, o)
    };
    let e = f64::EPSILON;
    let quad = |z: f64| {
        [
            DVec3::new(-1.0, -1.0, 0.0),
            DVec3::new(1.0, -1.0, 0.0),
            DVec3::new(1.0, 1.0, z),
            DVec3::new(-1.0, 1.0, z),
        ]
    };
    s.add_polygon(&quad(0.0), mats, o).unwrap();
    // Viewing direction along +y: the square's plane (z = 0) contains it.
    let cam = Camera::orthographic(DVec3::new(0.0, 5.0, 0.0), DVec3::ZERO, 3.0, 40, 40);
    let cam = Camera {
        up: DVec3::Z,
        ..cam
    };
    let ordered = limn_depthsort::order(&s, &cam, &OrderOptions::default()).unwrap();
    assert!(ordered.fragments.is_empty());
    let mut t = Scene::default();
    let m = t.add_material(limn_scene::Material::unlit("a", [1.0, 0.0, 0.0]));
    let o2 = t.add_object("tilted");
    t.add_polygon(&quad(e), m, o2).unwrap();
    let ordered = limn_depthsort::order(&t, &cam, &OrderOptions::default()).unwrap();
    assert_eq!(ordered.fragments.len(), 1);
}
