//! Polygons sharing an input edge in opposite directions and facing the eye alike are
//! never tested as a pair (their projections only touch); every other pair still is, and
//! folded meshes, where neighbours face the eye differently and do hide each other, are
//! still ordered correctly (checked exactly) by the orderings that test pairs (BSP never
//! does).

use glam::DVec3;
use limn_depthsort::{order, OrderOptions, SortMode};
use limn_scene::{Camera, Material, Scene};
use limn_tests::exact::exact_run;

/// Two triangles sharing the edge (0,0,0)–(1,0,0); the second one's corners in the given
/// order.
fn two_triangles(second: [DVec3; 3]) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::unlit("grey", [0.5; 3]));
    let o = s.add_object("pair");
    let (a, b) = (DVec3::ZERO, DVec3::X);
    s.add_polygon(&[a, b, DVec3::new(0.5, 1.0, 0.2)], m, o)
        .unwrap();
    s.add_polygon(&second, m, o).unwrap();
    s
}

fn pairs_tested(scene: &Scene) -> usize {
    let camera = Camera::new(
        DVec3::new(0.5, -0.3, 4.0),
        DVec3::new(0.5, 0.0, 0.0),
        200,
        200,
    );
    let o = order(scene, &camera, &OrderOptions::default()).unwrap();
    assert_eq!(o.fragments.len(), 2);
    o.stats.candidate_pairs
}

#[test]
fn neighbours_along_an_edge_are_not_tested_unless_they_face_the_eye_differently() {
    let c = DVec3::new(0.5, -1.0, -0.3);
    let (a, b) = (DVec3::ZERO, DVec3::X);
    // b → a: the edge in the opposite direction, both facing the eye.
    assert_eq!(pairs_tested(&two_triangles([b, a, c])), 0);
    // a → b: the same direction, the second triangle seen from behind (an open mesh is
    // not culled): tested.
    assert_eq!(pairs_tested(&two_triangles([a, b, c])), 1);
    // The same corners, the edge split by an extra corner: no shared input edge.
    let mid = DVec3::new(0.5, 0.0, 0.0);
    let mut s = two_triangles([b, a, c]);
    let m = s.faces[1].material;
    let o = s.faces[1].object;
    s.faces.pop();
    s.add_polygon(&[b, mid, c], m, o).unwrap();
    assert_eq!(pairs_tested(&s), 1);
}

/// A strip folded like an accordion, seen at a grazing angle so that folds hide the
/// strips behind them: every pair of neighbours shares an edge in opposite directions,
/// and half of them face the eye differently.
fn accordion(folds: usize) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::unlit("grey", [0.5; 3]));
    let o = s.add_object("accordion");
    let x = |i: usize| i as f64 * 0.25;
    let z = |i: usize| if i.is_multiple_of(2) { 0.0 } else { 1.0 };
    for i in 0..folds {
        let p = |k: usize, y: f64| DVec3::new(x(k), y, z(k));
        s.add_polygon(&[p(i, 0.0), p(i + 1, 0.0), p(i + 1, 2.0), p(i, 2.0)], m, o)
            .unwrap();
    }
    s
}

/// A height field of non-planar quads with pleats and a saddle.
fn pleated(n: usize) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::unlit("grey", [0.5; 3]));
    let o = s.add_object("pleats");
    let h = |i: usize, j: usize| {
        let (x, y) = (i as f64 / n as f64 - 0.5, j as f64 / n as f64 - 0.5);
        x * x - y * y + if i.is_multiple_of(3) { 0.3 } else { 0.0 }
    };
    let v = |i: usize, j: usize| DVec3::new(i as f64 / n as f64, j as f64 / n as f64, h(i, j));
    for i in 0..n {
        for j in 0..n {
            s.add_polygon(&[v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)], m, o)
                .unwrap();
        }
    }
    s
}

#[test]
fn folded_meshes_pass_the_exact_checker_in_the_pair_testing_modes() {
    let cameras = [
        Camera::new(
            DVec3::new(3.0, 1.0, 0.6),
            DVec3::new(1.0, 1.0, 0.5),
            300,
            200,
        ),
        Camera::new(
            DVec3::new(-1.5, -1.0, 0.9),
            DVec3::new(1.0, 1.0, 0.5),
            300,
            200,
        ),
        Camera::orthographic(
            DVec3::new(4.0, 0.5, 0.2),
            DVec3::new(1.0, 1.0, 0.5),
            3.0,
            300,
            200,
        ),
        Camera::new(
            DVec3::new(0.5, -1.2, 0.8),
            DVec3::new(0.5, 0.5, 0.0),
            300,
            200,
        ),
    ];
    for (name, scene) in [("accordion", accordion(9)), ("pleated", pleated(6))] {
        for camera in &cameras {
            for sort in [SortMode::Adaptive, SortMode::Newell] {
                let opts = OrderOptions {
                    sort,
                    ..OrderOptions::default()
                };
                let run = exact_run(&scene, camera, &opts);
                let v = run.checker.violations(&run.fragments);
                assert!(v.is_empty(), "{name} / {}: {v:?}", sort.name());
            }
        }
    }
}
