//! A non-planar face is triangulated into polygons of different planes that can hide
//! each other; joining its split pieces again must not move a piece across another
//! polygon of the same face (found by the `pipeline` fuzz target).

use glam::DVec3;
use limn_depthsort::{CullMode, OrderOptions, SortMode};
use limn_scene::{Camera, Material, Scene};
use limn_tests::exact::exact_run;

#[test]
fn merging_never_joins_pieces_across_another_plane_of_the_same_face() {
    let mut scene = Scene::default();
    let m = scene.add_material(Material::unlit("m", [0.5, 0.5, 0.5]));
    let o = scene.add_object("folded");
    let corners = [
        DVec3::new(-3.5660651611340723, -5.67970953892497, -5.779137350029521),
        DVec3::new(0.5, -1.0, 1.0),
        DVec3::new(1.5, 1.5000000000000036, 0.0),
        DVec3::new(-0.5, -1.5, -1.0),
        DVec3::new(-4.899572944700379, -5.181471770243453, -5.978022357471916),
    ];
    scene.add_polygon(&corners, m, o).unwrap();
    let camera = Camera::new(
        DVec3::new(-5.0, -6.0, -6.0),
        DVec3::new(-1.5, -0.5, -1.5),
        64,
        48,
    );
    for sort in [SortMode::Adaptive, SortMode::Bsp, SortMode::Newell] {
        for merge in [false, true] {
            let opts = OrderOptions {
                sort,
                cull: CullMode::On,
                merge,
                ..OrderOptions::default()
            };
            let run = exact_run(&scene, &camera, &opts);
            let v = run.checker.violations(&run.fragments);
            assert!(v.is_empty(), "{} merge={merge}: {v:?}", sort.name());
        }
    }
}
