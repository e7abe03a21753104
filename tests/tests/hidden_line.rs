//! Hidden-line drawings: a cube from a generic view (9 visible edges, 3 hidden), a torus
//! and a sphere (silhouettes), refereed by exact ray casting at sample points, and the
//! same under rotation, translation and permutation.

use glam::{DQuat, DVec3};
use limn::hidden_line_scene;
use limn_depthsort::{feature_edges, order_with_marks, EdgeKind, OrderOptions};
use limn_paint::HiddenLineStyle;
use limn_scene::shapes::{cuboid, torus, uv_sphere};
use limn_scene::{Camera, Material, Scene, Viewpoint};

fn unit_cube() -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::unlit("c", [0.5, 0.5, 0.5]));
    let o = s.add_object("cube");
    cuboid(&mut s, DVec3::ZERO, DVec3::ONE, glam::DMat3::IDENTITY, m, o).unwrap();
    s
}

/// (edges with a visible piece, edges with none) of a hidden-line drawing.
fn visible_edges(scene: &Scene, cam: &Camera) -> (usize, usize, Scene) {
    let (s, first) = hidden_line_scene(scene, cam, &HiddenLineStyle::default(), [1.0; 3]);
    let (_, marks) = order_with_marks(&s, cam, &OrderOptions::default()).unwrap();
    let edges = s.lines.len() - first;
    let shown = (first..s.lines.len())
        .filter(|&l| marks.pieces.iter().any(|p| p.line as usize == l))
        .count();
    (shown, edges - shown, s)
}

#[test]
fn cube_from_a_generic_view_shows_nine_edges_and_hides_three() {
    let s = unit_cube();
    let cam = Camera::new(DVec3::new(3.0, 2.5, 4.0), DVec3::splat(0.5), 200, 150);
    let (shown, hidden, _) = visible_edges(&s, &cam);
    assert_eq!((shown, hidden), (9, 3));
    // Rotated, translated far away and with its faces permuted: the same.
    let r = DQuat::from_axis_angle(DVec3::new(0.3, -1.0, 0.2).normalize(), 1.1);
    let t = DVec3::new(-4e3, 1e3, 7e3);
    let mut moved = s.clone();
    moved.vertices.iter_mut().for_each(|v| *v = r * *v + t);
    moved.faces.reverse();
    let mut c = cam;
    c.eye = r * cam.eye + t;
    c.target = r * cam.target + t;
    c.up = r * cam.up;
    assert_eq!(visible_edges(&moved, &c).0, 9);
    assert_eq!(visible_edges(&moved, &c).1, 3);
}

#[test]
fn a_cube_has_no_creases_below_ninety_degrees_and_twelve_above() {
    let s = unit_cube();
    let eye = DVec3::new(3.0, 2.5, 4.0);
    let kinds = |crease: f64| {
        let mut k: Vec<EdgeKind> = feature_edges(&s, Viewpoint::At(eye), crease)
            .iter()
            .map(|e| e.kind)
            .collect();
        k.sort();
        k
    };
    // Six silhouette edges from a generic view; the other six are creases (90°).
    let k = kinds(30.0);
    assert_eq!(k.len(), 12);
    assert_eq!(k.iter().filter(|&&e| e == EdgeKind::Silhouette).count(), 6);
    assert_eq!(kinds(95.0).len(), 6);
}

#[test]
fn torus_and_sphere_silhouettes_are_visible_where_ray_casting_says() {
    let mut t = Scene::default();
    let m = t.add_material(Material::unlit("t", [0.5, 0.5, 0.5]));
    let o = t.add_object("torus");
    torus(&mut t, DVec3::ZERO, 1.0, 0.35, 36, 18, m, o).unwrap();
    // Its quads are not planar: split them into triangles, so that the referee and the
    // kernel see the same surface.
    let quads = std::mem::take(&mut t.faces);
    for q in quads {
        let v = &q.vertices;
        t.add_face(&[v[0], v[1], v[2]], m, o).unwrap();
        t.add_face(&[v[0], v[2], v[3]], m, o).unwrap();
    }
    let mut sp = Scene::default();
    let m = sp.add_material(Material::unlit("s", [0.5, 0.5, 0.5]));
    let o = sp.add_object("sphere");
    uv_sphere(&mut sp, DVec3::ZERO, 1.0, 16, 24, m, o).unwrap();
    for (s, eye) in [
        (t, DVec3::new(0.5, 2.2, 3.0)),
        (sp, DVec3::new(1.0, 1.5, 4.0)),
    ] {
        let cam = Camera::new(eye, DVec3::ZERO, 200, 160);
        let (shown, hidden, drawn) = visible_edges(&s, &cam);
        let silhouettes = feature_edges(&s, Viewpoint::At(eye), 180.0);
        assert!(silhouettes.iter().all(|e| e.kind == EdgeKind::Silhouette));
        assert!(silhouettes.len() > 20, "{}", silhouettes.len());
        assert!(shown > 20, "{shown} shown, {hidden} hidden");
        common::referee(&drawn, &cam, 6);
    }
}

#[path = "support/line_referee.rs"]
mod common;
