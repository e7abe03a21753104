//! The exact ray-casting referee of the line tests (a module of `lines.rs` and
//! `hidden_line.rs`).

use glam::DVec3;
use limn_depthsort::{order_with_marks, OrderOptions, VisibleMarks};
use limn_scene::{Camera, Scene};

/// Sign of orient3d (robust, exact on f64 input).
fn orient(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> i32 {
    let p = |v: DVec3| robust::Coord3D {
        x: v.x,
        y: v.y,
        z: v.z,
    };
    let o = robust::orient3d(p(a), p(b), p(c), p(d));
    (o > 0.0) as i32 - (o < 0.0) as i32
}

/// Whether the segment from `e` to `p` meets the closed triangle `t` with `p` strictly
/// on the other side of its plane than `e`.
fn hides(e: DVec3, p: DVec3, t: [DVec3; 3]) -> bool {
    let se = orient(t[0], t[1], t[2], e);
    let sp = orient(t[0], t[1], t[2], p);
    if se == 0 || sp == 0 || se == sp {
        return false;
    }
    let s = [
        orient(e, p, t[0], t[1]),
        orient(e, p, t[1], t[2]),
        orient(e, p, t[2], t[0]),
    ];
    s.iter().all(|&x| x >= 0) || s.iter().all(|&x| x <= 0)
}

/// The referee: `p` is visible iff no triangle of a (fan-triangulated, planar and convex)
/// face hides it. `on`: the segment `p` was sampled from; a triangle whose plane holds it
/// never hides it (the documented rule; the f64 sample itself may be rounded off that
/// plane). Scenes given to it must have planar faces (non-planar ones are triangulated
/// by the kernel along diagonals of its own choosing).
fn visible(scene: &Scene, eye: DVec3, p: DVec3, on: Option<(DVec3, DVec3)>) -> bool {
    (0..scene.faces.len() as u32).all(|f| {
        let c = scene.face_points(f);
        (1..c.len() - 1).all(|i| {
            let t = [c[0], c[i], c[i + 1]];
            let in_plane = on.is_some_and(|(a, b)| {
                orient(t[0], t[1], t[2], a) == 0 && orient(t[0], t[1], t[2], b) == 0
            });
            in_plane || !hides(eye, p, t)
        })
    })
}

/// Whether `p` (on segment `a b`) lies inside a visible piece, or `None` when it is too
/// close to a piece's end to tell.
fn in_piece(marks: &VisibleMarks, line: u32, a: DVec3, b: DVec3, t: f64) -> Option<bool> {
    let d = b - a;
    let len2 = d.length_squared();
    let tol = 1e-7;
    for piece in marks.pieces.iter().filter(|p| p.line == line) {
        for w in piece.world.windows(2) {
            let (t0, t1) = ((w[0] - a).dot(d) / len2, (w[1] - a).dot(d) / len2);
            let off = |q: DVec3, tq: f64| (q - (a + d * tq)).length() / d.length();
            if off(w[0], t0) > 1e-9 || off(w[1], t1) > 1e-9 || t1 < t0 {
                continue;
            }
            if (t - t0).abs() < tol || (t - t1).abs() < tol {
                return None;
            }
            if t0 < t && t < t1 {
                return Some(true);
            }
        }
    }
    Some(false)
}

/// Checks every line of `scene` at `n` samples per segment and every point marker;
/// returns (visible samples, hidden samples).
pub fn referee(scene: &Scene, camera: &Camera, n: usize) -> (usize, usize) {
    let (_, marks) = order_with_marks(scene, camera, &OrderOptions::default()).unwrap();
    let (mut shown, mut hidden) = (0, 0);
    for (i, l) in scene.lines.iter().enumerate() {
        for w in l.points.windows(2) {
            for k in 0..n {
                let t = (k as f64 + 0.5) / n as f64;
                let p = w[0] + (w[1] - w[0]) * t;
                let Some(mine) = in_piece(&marks, i as u32, w[0], w[1], t) else {
                    continue;
                };
                let truth = visible(scene, camera.eye, p, Some((w[0], w[1])));
                assert_eq!(mine, truth, "line {i} at {p} (t = {t})");
                if truth {
                    shown += 1;
                } else {
                    hidden += 1;
                }
            }
        }
    }
    let shown_points: Vec<u32> = marks.points.iter().map(|a| a.index).collect();
    for (i, p) in scene.points.iter().enumerate() {
        let truth = visible(scene, camera.eye, p.at, None);
        assert_eq!(
            shown_points.contains(&(i as u32)),
            truth,
            "point {i} at {}",
            p.at
        );
    }
    (shown, hidden)
}
