//! Lines, markers and labels hidden exactly: known crossings, the in-plane rule,
//! translucent paint positions, and invariance under rigid motions and permutation.

use glam::DVec3;
use limn_depthsort::{order_with_marks, Arith, OrderOptions, VisibleMarks};
use limn_scene::{Camera, Material, PointMark, Polyline, Scene, TextLabel};

fn quad_scene(opacity: f64) -> Scene {
    let mut s = Scene::default();
    let mut m = Material::unlit("q", [0.5, 0.5, 0.5]);
    m.opacity = opacity;
    let m = s.add_material(m);
    let o = s.add_object("quad");
    let c = [[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]];
    let c: Vec<DVec3> = c.iter().map(|p| DVec3::new(p[0], p[1], 0.0)).collect();
    s.add_polygon(&c, m, o).unwrap();
    s
}

fn camera() -> Camera {
    Camera::new(DVec3::new(0.0, 0.0, 5.0), DVec3::ZERO, 200, 200)
}

fn run(scene: &Scene, arith: Arith) -> VisibleMarks {
    let opts = OrderOptions {
        arith,
        ..OrderOptions::default()
    };
    order_with_marks(scene, &camera(), &opts).unwrap().1
}

/// A line piercing the quad at x = 0: the part behind it is hidden from x = −10/9 (where
/// the eye ray grazes the quad's edge x = −1) to the piercing point x = 0.
#[test]
fn line_piercing_a_quad_is_cut_exactly_at_the_crossings() {
    let mut s = quad_scene(1.0);
    s.lines.push(Polyline::new(vec![
        DVec3::new(-2.0, 0.5, -1.0),
        DVec3::new(2.0, 0.5, 1.0),
    ]));
    for arith in [Arith::Exact, Arith::Float] {
        let v = run(&s, arith);
        assert_eq!(v.pieces.len(), 2, "{arith:?}: {v:?}");
        let first = &v.pieces[0].world;
        let second = &v.pieces[1].world;
        assert_eq!(first[0], DVec3::new(-2.0, 0.5, -1.0));
        // u = 2/9: x = −10/9, z = −5/9, each rounded once from the exact value.
        assert_eq!(first[1], DVec3::new(-10.0 / 9.0, 0.5, -5.0 / 9.0));
        assert_eq!(second[0], DVec3::new(0.0, 0.5, 0.0));
        assert_eq!(second[1], DVec3::new(2.0, 0.5, 1.0));
        assert_eq!(v.stats.segments_in, 1);
        assert_eq!(v.stats.pieces_out, 2);
        assert_eq!(v.stats.hidden_pieces, 1);
    }
}

/// A wireframe drawn in the face's own plane is drawn over the face, whole.
#[test]
fn line_in_the_face_plane_is_drawn_over_it() {
    let mut s = quad_scene(1.0);
    s.lines.push(Polyline::new(vec![
        DVec3::new(-1.0, -1.0, 0.0),
        DVec3::new(0.0, 0.0, 0.0),
        DVec3::new(1.0, 1.0, 0.0),
        DVec3::new(1.0, -1.0, 0.0),
    ]));
    let v = run(&s, Arith::Exact);
    assert_eq!(v.pieces.len(), 1, "{v:?}");
    assert_eq!(v.pieces[0].world.len(), 4);
    assert_eq!(v.stats.hidden_pieces, 0);
}

#[test]
fn markers_and_labels_show_iff_their_anchor_is_visible() {
    let mut s = quad_scene(1.0);
    for p in [
        DVec3::new(0.0, 0.0, -1.0), // behind the quad: hidden
        DVec3::new(0.0, 0.0, 1.0),  // in front: shown
        DVec3::new(3.0, 0.0, -1.0), // behind the plane, beside the quad: shown
        DVec3::new(0.5, 0.5, 0.0),  // on the quad: shown
        // Behind the quad's corner exactly (the sight line meets the closed quad).
        DVec3::new(2.0, 2.0, -5.0),
    ] {
        s.points.push(PointMark::new(p));
        s.labels.push(TextLabel::new(p, "p"));
    }
    let v = run(&s, Arith::Exact);
    let shown: Vec<u32> = v.points.iter().map(|a| a.index).collect();
    assert_eq!(shown, vec![1, 2, 3]);
    let shown: Vec<u32> = v.labels.iter().map(|a| a.index).collect();
    assert_eq!(shown, vec![1, 2, 3]);
    assert_eq!((v.stats.markers_in, v.stats.markers_shown), (5, 3));
}

/// Behind a translucent quad nothing is hidden, but the piece behind it is painted before
/// it and the piece in front after it. The part outside the quad's cone may go either
/// way: it joins the piece behind (one piece, painted before the quad).
#[test]
fn translucent_faces_hide_nothing_and_order_the_pieces() {
    let mut s = quad_scene(0.5);
    s.lines.push(Polyline::new(vec![
        DVec3::new(-2.0, 0.5, -1.0),
        DVec3::new(2.0, 0.5, 1.0),
    ]));
    let v = run(&s, Arith::Exact);
    let before: Vec<usize> = v.pieces.iter().map(|p| p.before).collect();
    // Outside the quad's cone and behind it (0), in front of it (1: over the quad).
    assert_eq!(before, vec![0, 1], "{v:?}");
    assert_eq!(
        v.pieces[0].world,
        vec![
            DVec3::new(-2.0, 0.5, -1.0),
            DVec3::new(-10.0 / 9.0, 0.5, -5.0 / 9.0),
            DVec3::new(0.0, 0.5, 0.0)
        ]
    );
    assert_eq!(v.pieces[1].world[0], DVec3::new(0.0, 0.5, 0.0));
}

/// A line seen through a translucent surface of many faces is one piece, painted before
/// the surface; a line over the surface's faces is painted after them, however many
/// translucent faces lie in front of its parts.
#[test]
fn a_line_behind_a_translucent_surface_stays_one_piece() {
    let mut s = Scene::default();
    let mut glass = Material::unlit("glass", [0.2, 0.4, 0.8]);
    glass.opacity = 0.5;
    let m = s.add_material(glass);
    let o = s.add_object("strips");
    // Ten strips side by side in the plane z = 0.
    for k in 0..10 {
        let x = -1.0 + 0.2 * f64::from(k);
        s.add_polygon(
            &[
                DVec3::new(x, -1.0, 0.0),
                DVec3::new(x + 0.2, -1.0, 0.0),
                DVec3::new(x + 0.2, 1.0, 0.0),
                DVec3::new(x, 1.0, 0.0),
            ],
            m,
            o,
        )
        .unwrap();
    }
    // Behind the strips, across all of them; then in front of them, across all.
    s.lines.push(Polyline::new(vec![
        DVec3::new(-0.95, 0.0, -0.5),
        DVec3::new(0.95, 0.1, -0.5),
    ]));
    s.lines.push(Polyline::new(vec![
        DVec3::new(-0.95, 0.0, 0.5),
        DVec3::new(0.95, 0.1, 0.5),
    ]));
    let v = run(&s, Arith::Exact);
    let behind: Vec<usize> = v
        .pieces
        .iter()
        .filter(|p| p.line == 0)
        .map(|p| p.before)
        .collect();
    let front: Vec<usize> = v
        .pieces
        .iter()
        .filter(|p| p.line == 1)
        .map(|p| p.before)
        .collect();
    assert_eq!(behind.len(), 1, "{v:?}");
    assert_eq!(front, vec![10], "{v:?}");
    // Painted before every strip it lies behind: the first.
    assert_eq!(behind[0], 0);
}

/// Geometry nearer than the near plane is clipped, as faces are.
#[test]
fn lines_behind_the_eye_are_clipped() {
    let mut s = quad_scene(1.0);
    s.lines.push(Polyline::new(vec![
        DVec3::new(1.5, 0.0, 0.0),
        DVec3::new(1.5, 0.0, 10.0),
    ]));
    s.points.push(PointMark::new(DVec3::new(0.0, 0.0, 6.0)));
    let v = run(&s, Arith::Exact);
    assert_eq!(v.pieces.len(), 1);
    let end = v.pieces[0].world[1];
    assert!(end.z < 5.0, "{end}");
    assert!(v.points.is_empty());
}

/// With a parallel projection the eye is at infinity: the line is hidden exactly where it
/// passes behind the quad along the view direction, from x = −1 to the piercing point.
#[test]
fn parallel_projection_hides_along_the_view_direction() {
    let mut s = quad_scene(1.0);
    s.lines.push(Polyline::new(vec![
        DVec3::new(-2.0, 0.5, -1.0),
        DVec3::new(2.0, 0.5, 1.0),
    ]));
    s.points.push(PointMark::new(DVec3::new(0.9, 0.9, -3.0)));
    s.points.push(PointMark::new(DVec3::new(1.1, 0.9, -3.0)));
    let mut cam = camera();
    cam.projection = limn_scene::Projection::Orthographic { height: 6.0 };
    let (_, v) = order_with_marks(&s, &cam, &OrderOptions::default()).unwrap();
    assert_eq!(v.pieces.len(), 2, "{v:?}");
    assert_eq!(v.pieces[0].world[1], DVec3::new(-1.0, 0.5, -0.5));
    assert_eq!(v.pieces[1].world[0], DVec3::new(0.0, 0.5, 0.0));
    let shown: Vec<u32> = v.points.iter().map(|a| a.index).collect();
    assert_eq!(shown, vec![1]);
}
