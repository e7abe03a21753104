//! Lines and point markers hidden exactly through orthographic cameras and cameras given
//! as view-projection matrices (with a finite centre of projection or one at infinity),
//! refereed by exact ray casting from the camera's own viewpoint: for an eye at infinity
//! in direction `d`, a sample is hidden iff the ray from it along `d` meets a face.

use limn_depthsort::{order_with_marks, OrderOptions};
use limn_scene::{Camera, Projection, Scene, Viewpoint};

#[path = "support/line_referee.rs"]
mod common;
#[path = "support/mark_scenes.rs"]
mod scenes;
use common::referee;
use scenes::{strips_with_lines, surface_with_wireframe};

/// A sphere with a helix around it and points inside and outside, seen from close by
/// (so that perspective and parallel sight lines disagree about much of the helix).
fn helix_around_sphere() -> (Scene, Camera) {
    scenes::helix_around_sphere(8, 12, 120, 4.0, 3.0)
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
