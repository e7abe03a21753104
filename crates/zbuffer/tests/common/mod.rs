//! Scene builders shared by the integration tests.
#![allow(dead_code)]

use glam::DVec3;
use limn_scene::{Camera, Material, Scene};

/// A scene with one unlit material per colour given, and one object.
pub fn scene_with(colors: &[[f64; 3]]) -> Scene {
    let mut s = Scene::default();
    for (k, &c) in colors.iter().enumerate() {
        s.add_material(Material::unlit(&format!("m{k}"), c));
    }
    s.add_object("o");
    s
}

/// Adds a polygon with material `m`.
pub fn poly(s: &mut Scene, pts: &[DVec3], m: u32) -> u32 {
    s.add_polygon(pts, m, 0).expect("valid polygon")
}

/// A camera at `eye` looking at the origin.
pub fn cam(eye: DVec3, w: u32, h: u32) -> Camera {
    Camera::new(eye, DVec3::ZERO, w, h)
}

/// A small deterministic generator (tests must not depend on the system's randomness).
pub struct Lcg(pub u64);

impl Lcg {
    /// Uniform in [0, 1).
    pub fn f(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.f()
    }
}

/// A height-field mesh of `n × n` quads (two triangles each) over [−1, 1]², shared
/// edges everywhere, heights from `rng` scaled by `amp`, at z offset `z0`.
pub fn grid(s: &mut Scene, n: usize, amp: f64, z0: f64, rng: &mut Lcg, m: u32) {
    let mut idx = vec![vec![0u32; n + 1]; n + 1];
    for (i, row) in idx.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            let x = -1.0 + 2.0 * i as f64 / n as f64;
            let y = -1.0 + 2.0 * j as f64 / n as f64;
            *v = s.add_vertex(DVec3::new(x, y, z0 + amp * rng.f()));
        }
    }
    for i in 0..n {
        for j in 0..n {
            let (a, b, c, d) = (idx[i][j], idx[i + 1][j], idx[i + 1][j + 1], idx[i][j + 1]);
            s.add_face(&[a, b, c], m, 0).expect("face");
            s.add_face(&[a, c, d], m, 0).expect("face");
        }
    }
}

/// Random triangles roughly facing +z, each on its own depth layer (layer `k` at
/// `z = −gap·k`, tilted by less than the gap allows), so no two of them come closer
/// than about `gap / 2` in depth: they never intersect, not even at pixel scale.
pub fn layered_triangles(rng: &mut Lcg, count: usize, gap: f64) -> Scene {
    let mut s = scene_with(&[[0.8, 0.2, 0.2], [0.2, 0.8, 0.2], [0.2, 0.2, 0.8]]);
    let mut order: Vec<usize> = (0..count).collect();
    // Shuffle depths so that input order is unrelated to depth order.
    for i in (1..count).rev() {
        let j = (rng.f() * (i + 1) as f64) as usize;
        order.swap(i, j.min(i));
    }
    for (k, &layer) in order.iter().enumerate() {
        let z = -gap * layer as f64;
        let c = DVec3::new(rng.range(-1.0, 1.0), rng.range(-1.0, 1.0), z);
        let r = rng.range(0.2, 0.9);
        let pts: Vec<DVec3> = (0..3)
            .map(|i| {
                let ang = rng.range(0.0, 1.0) * 0.6 + i as f64 * 2.1;
                let p = c + DVec3::new(ang.cos(), ang.sin(), 0.0) * r;
                // Tilt by at most gap / 4 over the triangle's extent.
                p + DVec3::Z * rng.range(-0.2, 0.2) * gap
            })
            .collect();
        poly(&mut s, &pts, (k % 3) as u32);
    }
    s
}
