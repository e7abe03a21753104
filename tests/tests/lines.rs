//! Lines and markers hidden exactly, refereed by exact ray casting at sample points: a
//! sample is visible iff the segment from the eye to it meets no face (orient3d signs on
//! the f64 sample, exact), and it must lie in a visible piece exactly when it is. Samples
//! within 1e-7 (relative) of a piece's end are skipped: the ends are rounded once.
//! Scenes: a line behind and through the cyclic strips, a helix around a sphere, points
//! around a sphere; each also rotated, translated and with its faces permuted.

use glam::{DQuat, DVec3};
use limn_depthsort::{order_with_marks, OrderOptions, VisibleMarks};
use limn_scene::{Camera, Scene};

#[path = "support/line_referee.rs"]
mod common;
#[path = "support/mark_scenes.rs"]
mod scenes;
use common::referee;
use scenes::{strips_with_lines, surface_with_wireframe};

/// The helix scene at the resolution of these tests.
fn helix_around_sphere() -> (Scene, Camera) {
    scenes::helix_around_sphere(12, 18, 240, 6.0, 5.0)
}

#[test]
fn line_behind_and_through_the_cyclic_strips() {
    let (s, cam) = strips_with_lines();
    let (shown, hidden) = referee(&s, &cam, 200);
    assert!(shown > 50 && hidden > 50, "{shown} shown, {hidden} hidden");
}

#[test]
fn helix_around_a_sphere() {
    let (s, cam) = helix_around_sphere();
    let (shown, hidden) = referee(&s, &cam, 16);
    assert!(
        shown > 500 && hidden > 500,
        "{shown} shown, {hidden} hidden"
    );
}

/// Moves a scene (faces, lines, points) and its camera rigidly.
fn moved(s: &Scene, cam: &Camera, f: impl Fn(DVec3) -> DVec3, r: DQuat) -> (Scene, Camera) {
    let mut s = s.clone();
    s.vertices.iter_mut().for_each(|v| *v = f(*v));
    for l in &mut s.lines {
        l.points.iter_mut().for_each(|v| *v = f(*v));
    }
    s.points.iter_mut().for_each(|p| p.at = f(p.at));
    let mut c = *cam;
    c.eye = f(cam.eye);
    c.target = f(cam.target);
    c.up = r * cam.up;
    (s, c)
}

#[test]
fn the_same_under_rotation_translation_and_permutation() {
    for (s, cam) in [strips_with_lines(), helix_around_sphere()] {
        let base = order_with_marks(&s, &cam, &OrderOptions::default())
            .unwrap()
            .1;
        let r = DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.7);
        let t = DVec3::new(1e3, -2e3, 5e2);
        let (s2, c2) = moved(&s, &cam, |v| r * v + t, r);
        let mut s3 = s.clone();
        s3.faces.reverse();
        for (s, c) in [(s2, c2), (s3, cam)] {
            referee(&s, &c, 8);
            let other = order_with_marks(&s, &c, &OrderOptions::default())
                .unwrap()
                .1;
            assert_eq!(base.stats.pieces_out, other.stats.pieces_out);
            assert_eq!(base.stats.hidden_pieces, other.stats.hidden_pieces);
            let idx = |m: &VisibleMarks| m.points.iter().map(|a| a.index).collect::<Vec<_>>();
            assert_eq!(idx(&base), idx(&other));
        }
    }
}

#[test]
fn wireframe_drawn_on_its_own_surface_shows_where_the_surface_does() {
    let (s, cam) = surface_with_wireframe(12);
    let (shown, hidden) = referee(&s, &cam, 8);
    assert!(
        shown > 1000 && hidden > 200,
        "{shown} shown, {hidden} hidden"
    );
}

/// `limn check`'s line comparison: the painter's pieces against the z-buffer's lines.
#[test]
fn check_compares_line_pixels_with_the_zbuffer() {
    for (s, cam) in [
        helix_around_sphere(),
        surface_with_wireframe(12),
        strips_with_lines(),
    ] {
        let painted = limn_check::paint(&s, &cam, &OrderOptions::default()).unwrap();
        let c = painted.compare_lines(&s).unwrap();
        assert!(c.pixels > 100, "{c:?}");
        // The z-buffer's depth test is itself approximate where a line runs along a fold:
        // the check allows 1 % of the line pixels (`limn check` does the same).
        assert!(!c.fails(), "{c:?}");
        // Drawing every line whole (nothing hidden) must be caught.
        let mut whole = painted.clone();
        for (i, l) in s.lines.iter().enumerate() {
            let vp = cam.view_projection(whole.ordered.near, whole.ordered.far);
            let pts: Vec<[f64; 2]> = l
                .points
                .iter()
                .map(|&p| {
                    let q = cam.project_with(&vp, p);
                    [q.x, q.y]
                })
                .collect();
            for w in pts.windows(2) {
                limn_zbuffer::bresenham(
                    w[0][0].floor() as i64,
                    w[0][1].floor() as i64,
                    w[1][0].floor() as i64,
                    w[1][1].floor() as i64,
                    |x, y| {
                        if x >= 0 && y >= 0 && x < cam.width as i64 && y < cam.height as i64 {
                            whole.line_ids.ids[y as usize * cam.width as usize + x as usize] =
                                i as u32;
                        }
                    },
                );
            }
        }
        let reference = limn_zbuffer::scene_lines(
            &s,
            &cam,
            &whole.ropts,
            limn_zbuffer::LineAlgorithm::Bresenham,
            1e-6,
        )
        .unwrap();
        let c = limn_check::compare_line_images(&whole.line_ids, &reference, &whole.line_band);
        assert!(c.fails(), "{c:?}");
    }
}
