//! Lines and point markers hidden exactly through orthographic cameras and cameras given
//! as view-projection matrices (with a finite centre of projection or one at infinity),
//! refereed by exact ray casting from the camera's own viewpoint: for an eye at infinity
//! in direction `d`, a sample is hidden iff the ray from it along `d` meets a face.

use glam::DVec3;
use limn_depthsort::{order_with_marks, OrderOptions};
use limn_scene::{Camera, Material, Polyline, Projection, Scene, Viewpoint};

#[path = "support/line_referee.rs"]
mod common;
#[path = "support/mark_scenes.rs"]
mod scenes;
use common::referee;
use scenes::strips_with_lines;

/// A sphere with a helix around it and points inside and outside, seen from close by
/// (so that perspective and parallel sight lines disagree about much of the helix).
fn helix_around_sphere() -> (Scene, Camera) {
    scenes::helix_around_sphere(8, 12, 120, 4.0, 3.0)
}

/// A height field in triangles with its own grid lines on it.
fn surface_with_wireframe(n: usize) -> (Scene, Camera) {
    let mut s = Scene::default();
    let m = s.add_material(Material::unlit("surface", [0.8, 0.8, 0.7]));
    let o = s.add_object("surface");
    let z = |i: usize, j: usize| {
        let (x, y) = (
            i as f64 / n as f64 * 4.0 - 2.0,
            j as f64 / n as f64 * 4.0 - 2.0,
        );
        DVec3::new(x, y, 0.6 * (1.3 * x).sin() * (0.9 * y).cos())
    };
    for i in 0..n {
        for j in 0..n {
            let (a, b, c, d) = (z(i, j), z(i + 1, j), z(i + 1, j + 1), z(i, j + 1));
            s.add_polygon(&[a, b, c], m, o).unwrap();
            s.add_polygon(&[a, c, d], m, o).unwrap();
        }
    }
    for i in 0..=n {
        s.lines
            .push(Polyline::new((0..=n).map(|j| z(i, j)).collect()));
        s.lines
            .push(Polyline::new((0..=n).map(|j| z(j, i)).collect()));
    }
    let cam = Camera::new(DVec3::new(1.0, -5.5, 1.1), DVec3::ZERO, 240, 180);
    (s, cam)
}

fn scenes() -> Vec<(Scene, Camera, usize)> {
    vec![
        (strips_with_lines().0, strips_with_lines().1, 64),
        (helix_around_sphere().0, helix_around_sphere().1, 6),
        (surface_with_wireframe(8).0, surface_with_wireframe(8).1, 4),
    ]
}

/// An orthographic camera looking along the perspective camera's direction.
fn ortho(s: &Scene, c: &Camera) -> Camera {
    Camera::framing_orthographic(s, c.eye - c.target, c.width, c.height).expect("frames")
}

/// The matrix camera with the same view and projection as `c`.
fn matrix(s: &Scene, c: &Camera) -> Camera {
    let (near, far) = c.near_far(s);
    let cam = Camera::from_matrix(c.view_projection(near, far), c.width, c.height).unwrap();
    assert!(matches!(cam.projection, Projection::Matrix(_)));
    cam
}

#[test]
fn lines_and_points_are_hidden_exactly_through_an_orthographic_camera() {
    for (s, cam, n) in scenes() {
        let cam = ortho(&s, &cam);
        assert!(matches!(cam.viewpoint(), Ok(Viewpoint::Toward(_))));
        let (shown, hidden) = referee(&s, &cam, n);
        assert!(shown > 20 && hidden > 20, "{shown} shown, {hidden} hidden");
    }
}

#[test]
fn lines_and_points_are_hidden_exactly_through_matrix_cameras() {
    for (s, cam, n) in scenes() {
        for look_at in [cam, ortho(&s, &cam)] {
            let m = matrix(&s, &look_at);
            assert_eq!(
                matches!(m.viewpoint(), Ok(Viewpoint::Toward(_))),
                !look_at.is_perspective()
            );
            let (shown, hidden) = referee(&s, &m, n);
            assert!(shown > 20 && hidden > 20, "{shown} shown, {hidden} hidden");
            // The same marks as the look-at twin.
            let a = order_with_marks(&s, &look_at, &OrderOptions::default()).unwrap();
            let b = order_with_marks(&s, &m, &OrderOptions::default()).unwrap();
            let idx =
                |v: &[limn_depthsort::VisibleAnchor]| v.iter().map(|a| a.index).collect::<Vec<_>>();
            assert_eq!(idx(&a.1.points), idx(&b.1.points));
            assert_eq!(a.1.stats.pieces_out, b.1.stats.pieces_out);
        }
    }
}
