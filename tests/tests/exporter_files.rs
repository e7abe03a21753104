//! Files as other programs wrote them (`data/exporters/`, see its README) drawn as their
//! writers meant them, and agreeing with ray casting.

use std::path::{Path, PathBuf};

use limn_check::paint;
use limn_depthsort::OrderOptions;
use limn_load::{load, LoadOptions};
use limn_scene::Camera;
use limn_zbuffer::{DepthFormat, Method};

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/exporters")
        .join(name)
}

#[test]
fn meshlab_tr_one_draws_an_opaque_tetrahedron() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(data("fuze.obj.mtl"), dir.path().join("fuze.obj.mtl")).unwrap();
    let obj = dir.path().join("t.obj");
    std::fs::write(
        &obj,
        "mtllib ./fuze.obj.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n\
         usemtl a-super-duper-material\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n",
    )
    .unwrap();
    let scene = load(&obj, &LoadOptions::default()).unwrap();
    assert_eq!(scene.materials[0].opacity, 1.0);
    assert_eq!(scene.warnings.len(), 1, "{:?}", scene.warnings);
    assert!(
        scene.warnings[0].contains("fuze.obj.mtl:10: material")
            && scene.warnings[0].ends_with("drawn opaque"),
        "{:?}",
        scene.warnings
    );
    let camera = Camera::framing(&scene, 80, 60).unwrap();
    let painted = paint(&scene, &camera, &OrderOptions::default()).unwrap();
    assert!(!painted.ordered.fragments.is_empty());
    let r = painted
        .reference(&scene, Method::RayCast, DepthFormat::F64)
        .unwrap();
    assert_eq!(painted.compare(&r).mismatches_outside_band, 0);
}

#[test]
fn a_ply_point_cloud_is_its_points() {
    let scene = load(&data("points_ascii.ply"), &LoadOptions::default()).unwrap();
    assert!(scene.faces.is_empty());
    assert_eq!(scene.points.len(), 5);
    assert!(
        scene.warnings[0].ends_with("its 5 vertices are drawn as points"),
        "{:?}",
        scene.warnings
    );
    let camera = Camera::framing(&scene, 80, 60).unwrap();
    let painted = paint(&scene, &camera, &OrderOptions::default()).unwrap();
    assert_eq!(painted.marks.points.len(), 5);
}
