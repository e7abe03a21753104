//! The exact ray-casting referee of the line tests (a module of `lines.rs`,
//! `hidden_line.rs` and `projections.rs`). An eye at infinity (a parallel projection) is
//! the homogeneous point `(d, 0)`: its sight line to `p` is the ray from `p` along `d`,
//! and every orientation involving it is a 4×4 determinant in exact rationals.

use glam::{DVec3, DVec4};
use limn_depthsort::{order_with_marks, OrderOptions, VisibleMarks};
use limn_scene::{Camera, Scene, Viewpoint};
use num_rational::BigRational;
use num_traits::{Signed, Zero};

/// The eye: a point (`w = 1`) or a direction towards an eye at infinity (`w = 0`).
type Eye = DVec4;

/// Sign of the determinant of the rows `(a, 1), (b, 1), (c, 1), e` (homogeneous `e`),
/// exact: orient3d's sign convention for a finite `e`.
fn orient_h(a: DVec3, b: DVec3, c: DVec3, e: Eye) -> i32 {
    if e.w == 1.0 {
        return orient(a, b, c, e.truncate());
    }
    // A float filter with a generous error bound (about 10⁵ times the rounding error of
    // this evaluation), then exact rationals.
    let (uf, vf, d) = (b - a, c - a, e.truncate());
    let df = d.dot(uf.cross(vf));
    let bound = 1e-10 * (uf.abs().element_sum() * vf.abs().element_sum() * d.abs().element_sum());
    if df.abs() > bound {
        return if df > 0.0 { -1 } else { 1 };
    }
    let q = |x: f64| BigRational::from_float(x).expect("finite");
    // det[[a,1],[b,1],[c,1],[d,0]] = −d · ((b − a) × (c − a)) up to orient3d's sign:
    // orient3d(a, b, c, x) = (a − x) · ((b − x) × (c − x)), linear in x with slope
    // −((b − a) × (c − a)) along d.
    let sub = |u: DVec3, v: DVec3| [q(u.x) - q(v.x), q(u.y) - q(v.y), q(u.z) - q(v.z)];
    let (u, v) = (sub(b, a), sub(c, a));
    let n = [
        &u[1] * &v[2] - &u[2] * &v[1],
        &u[2] * &v[0] - &u[0] * &v[2],
        &u[0] * &v[1] - &u[1] * &v[0],
    ];
    let dot = q(e.x) * &n[0] + q(e.y) * &n[1] + q(e.z) * &n[2];
    let s = -dot;
    if s.is_zero() {
        0
    } else if s.is_positive() {
        1
    } else {
        -1
    }
}

/// The eye of `camera` as a homogeneous point.
pub fn eye_of(camera: &Camera) -> Eye {
    match camera.viewpoint().expect("viewpoint") {
        Viewpoint::At(e) => e.extend(1.0),
        Viewpoint::Toward(d) => d.extend(0.0),
    }
}

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

/// Whether the segment from `e` to `p` (the ray from `p` along `d` for `e = (d, 0)`)
/// meets the closed triangle `t` with `p` strictly on the other side of its plane than
/// `e`.
fn hides(e: Eye, p: DVec3, t: [DVec3; 3]) -> bool {
    let se = orient_h(t[0], t[1], t[2], e);
    let sp = orient(t[0], t[1], t[2], p);
    if se == 0 || sp == 0 || se == sp {
        return false;
    }
    // orient(e, p, a, b) = −orient(p, a, b, e) (an odd permutation of the rows).
    let s = [
        -orient_h(p, t[0], t[1], e),
        -orient_h(p, t[1], t[2], e),
        -orient_h(p, t[2], t[0], e),
    ];
    s.iter().all(|&x| x >= 0) || s.iter().all(|&x| x <= 0)
}

/// The referee: `p` is visible iff no triangle of a (fan-triangulated, planar and convex)
/// face hides it. `on`: the segment `p` was sampled from; a triangle whose plane holds it
/// never hides it (the documented rule; the f64 sample itself may be rounded off that
/// plane). Scenes given to it must have planar faces (non-planar ones are triangulated
/// by the kernel along diagonals of its own choosing).
fn visible(scene: &Scene, eye: Eye, p: DVec3, on: Option<(DVec3, DVec3)>) -> bool {
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
    let eye = eye_of(camera);
    let (mut shown, mut hidden) = (0, 0);
    for (i, l) in scene.lines.iter().enumerate() {
        for w in l.points.windows(2) {
            for k in 0..n {
                let t = (k as f64 + 0.5) / n as f64;
                let p = w[0] + (w[1] - w[0]) * t;
                let Some(mine) = in_piece(&marks, i as u32, w[0], w[1], t) else {
                    continue;
                };
                let truth = visible(scene, eye, p, Some((w[0], w[1])));
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
        let truth = visible(scene, eye, p.at, None);
        assert_eq!(
            shown_points.contains(&(i as u32)),
            truth,
            "point {i} at {}",
            p.at
        );
    }
    (shown, hidden)
}
