//! Scenes of the line tests (a module of `lines.rs` and `lines_projections.rs`): lines
//! and points around the cyclic strips, a helix around a sphere, and a surface with its
//! own grid lines.

use glam::DVec3;
use limn_scene::shapes::uv_sphere;
use limn_scene::{Camera, Material, PointMark, Polyline, Scene};
use limn_tests::corpus::cyclic_quads;

/// The cyclic strips with a line behind them, one through them, and points around.
pub fn strips_with_lines() -> (Scene, Camera) {
    let case = cyclic_quads();
    let mut s = case.scene;
    s.lines.push(Polyline::new(vec![
        DVec3::new(-3.0, -0.3, -2.0),
        DVec3::new(3.0, 0.4, -2.0),
    ]));
    s.lines.push(Polyline::new(vec![
        DVec3::new(-3.0, 0.2, -1.0),
        DVec3::new(0.0, 0.1, 0.1),
        DVec3::new(3.0, -0.2, 1.0),
    ]));
    for k in 0..40 {
        let a = k as f64 * 0.7;
        s.points.push(PointMark::new(DVec3::new(
            2.0 * a.cos(),
            1.5 * (a * 1.3).sin(),
            (a * 0.5).sin(),
        )));
    }
    (s, case.camera)
}

/// A sphere of `rings` × `sectors` with a helix of `turns` turns in `steps` segments
/// around it and 60 points inside and outside, seen from `(0.8, 1.1, eye_z)`.
pub fn helix_around_sphere(
    rings: u32,
    sectors: u32,
    steps: u32,
    turns: f64,
    eye_z: f64,
) -> (Scene, Camera) {
    let mut s = Scene::default();
    let m = s.add_material(Material::unlit("grey", [0.7, 0.7, 0.7]));
    let o = s.add_object("sphere");
    uv_sphere(&mut s, DVec3::ZERO, 1.0, rings, sectors, m, o).unwrap();
    let pts = (0..=steps)
        .map(|k| {
            let t = f64::from(k) / f64::from(steps);
            let a = t * turns * std::f64::consts::TAU;
            DVec3::new(1.25 * a.cos(), 3.0 * t - 1.5, 1.25 * a.sin())
        })
        .collect();
    s.lines.push(Polyline::new(pts));
    for k in 0..60 {
        let a = k as f64 * 0.37;
        let r = 0.8 + 0.5 * ((k % 5) as f64 / 4.0);
        s.points.push(PointMark::new(DVec3::new(
            r * a.cos() * (a * 0.3).cos(),
            r * (a * 0.3).sin(),
            r * a.sin() * (a * 0.3).cos(),
        )));
    }
    let cam = Camera::new(DVec3::new(0.8, 1.1, eye_z), DVec3::ZERO, 200, 160);
    (s, cam)
}

/// A wavy height field of `n` × `n` cells in triangles with its own grid lines drawn
/// on it; its folds hide parts of it.
pub fn surface_with_wireframe(n: usize) -> (Scene, Camera) {
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
