//! The reference culls the back faces of exactly the objects and faces the painter culled.

use glam::DVec3;
use limn_check::paint;
use limn_depthsort::{CullMode, OrderOptions};
use limn_scene::{Camera, Material, Scene};
use limn_zbuffer::{DepthFormat, Method};

/// One object that is a closed surface by its edges (a triangle and the same triangle
/// turned over, the second face later in the file), opaque, and beside it an open
/// triangle facing away from the eye.
fn folded() -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::unlit("grey", [0.5; 3]));
    let fold = s.add_object("fold");
    let open = s.add_object("open");
    let p = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]].map(DVec3::from);
    s.add_polygon(&p, m, fold).unwrap();
    s.add_polygon(&[p[0], p[2], p[1]], m, fold).unwrap();
    let q = [[2.0, 0.0, 0.0], [2.0, 1.0, 0.0], [3.0, 0.0, 0.0]].map(DVec3::from);
    s.add_polygon(&q, m, open).unwrap();
    s
}

#[test]
fn with_cull_auto_the_reference_culls_what_the_painter_culled() {
    let scene = folded();
    let camera = Camera::new(DVec3::new(1.5, 0.5, 4.0), DVec3::new(1.5, 0.5, 0.0), 96, 64);
    for cull in CullMode::ALL {
        let opts = OrderOptions {
            cull,
            ..OrderOptions::default()
        };
        let p = paint(&scene, &camera, &opts).unwrap();
        let want = match cull {
            CullMode::Auto => vec![true, false],
            CullMode::On => vec![true, true],
            CullMode::Off => vec![false, false],
        };
        assert_eq!(p.ordered.culled_objects, want, "{cull:?}");
        for method in [Method::RayCast, Method::ZBuffer, Method::Warnock] {
            let r = p.reference(&scene, method, DepthFormat::F64).unwrap();
            let c = p.compare(&r);
            assert_eq!(c.mismatches_outside_band, 0, "{cull:?} {method:?}: {c:?}");
            // The open triangle faces away: drawn unless every back face is culled.
            let shown = r.ids.contains(&2);
            assert_eq!(shown, cull != CullMode::On, "{cull:?} {method:?}");
        }
    }
}

/// The fold and the open triangle in one object: the object is open, its closed part
/// (the fold) is still culled, and the reference culls the same faces.
#[test]
fn with_cull_auto_the_reference_culls_the_closed_parts_the_painter_culled() {
    let mut scene = folded();
    for f in &mut scene.faces {
        f.object = 0;
    }
    let camera = Camera::new(DVec3::new(1.5, 0.5, 4.0), DVec3::new(1.5, 0.5, 0.0), 96, 64);
    let p = paint(&scene, &camera, &OrderOptions::default()).unwrap();
    assert_eq!(p.ordered.culled_objects, vec![false, false]);
    assert_eq!(p.ordered.culled_faces, vec![true, true, false]);
    for method in [Method::RayCast, Method::ZBuffer, Method::Warnock] {
        let r = p.reference(&scene, method, DepthFormat::F64).unwrap();
        let c = p.compare(&r);
        assert_eq!(c.mismatches_outside_band, 0, "{method:?}: {c:?}");
        // The fold's face turned away is culled on both sides; the open triangle, facing
        // away too, is drawn.
        assert!(!r.ids.contains(&1), "{method:?}");
        assert!(r.ids.contains(&2), "{method:?}");
    }
}
