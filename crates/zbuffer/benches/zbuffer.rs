//! Benchmarks of the reference renderers on a height-field terrain:
//! `cargo bench -p limn-zbuffer`. The one-million-triangle runs at 1920×1080 are the
//! headline numbers; `examples/million.rs` prints them as a table with memory.

use std::sync::OnceLock;

use divan::Bencher;
use glam::DVec3;
use limn_scene::{Camera, Material, Scene};
use limn_zbuffer::{render, DepthFormat, Method, RenderOptions};

fn main() {
    divan::main();
}

/// A height field of `n × n` quads, two triangles each (the same as the example's).
fn terrain(n: usize) -> Scene {
    let mut s = Scene::default();
    s.add_material(Material::diffuse("ground", [0.5, 0.7, 0.4]));
    s.add_object("terrain");
    let h = |x: f64, y: f64| {
        0.08 * (7.0 * x).sin() * (5.0 * y).cos() + 0.03 * (23.0 * x + 17.0 * y).sin()
    };
    for i in 0..=n {
        for j in 0..=n {
            let (x, y) = (
                i as f64 / n as f64 * 2.0 - 1.0,
                j as f64 / n as f64 * 2.0 - 1.0,
            );
            s.add_vertex(DVec3::new(x, h(x, y), y));
        }
    }
    let id = |i: usize, j: usize| (i * (n + 1) + j) as u32;
    for i in 0..n {
        for j in 0..n {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            s.add_face(&[a, c, b], 0, 0).expect("face");
            s.add_face(&[a, d, c], 0, 0).expect("face");
        }
    }
    s
}

fn camera(w: u32, h: u32) -> Camera {
    let mut c = Camera::new(
        DVec3::new(0.0, 0.75, 1.2),
        DVec3::new(0.0, -0.2, -0.4),
        w,
        h,
    );
    c.fov_deg = 50.0;
    c
}

/// About one million triangles.
fn million() -> &'static Scene {
    static S: OnceLock<Scene> = OnceLock::new();
    S.get_or_init(|| terrain(707))
}

/// About twenty thousand triangles.
fn small() -> &'static Scene {
    static S: OnceLock<Scene> = OnceLock::new();
    S.get_or_init(|| terrain(100))
}

fn run(b: Bencher, scene: &Scene, method: Method, depth: DepthFormat, w: u32, h: u32) {
    let cam = camera(w, h);
    let opts = RenderOptions {
        depth,
        ..RenderOptions::default()
    };
    b.bench(|| render(scene, &cam, method, &opts).expect("render"));
}

#[divan::bench(sample_count = 5, sample_size = 1, args = [DepthFormat::F64, DepthFormat::F32, DepthFormat::D16])]
fn zbuffer_1m_1080p(b: Bencher, depth: DepthFormat) {
    run(b, million(), Method::ZBuffer, depth, 1920, 1080);
}

#[divan::bench(sample_count = 5, sample_size = 1)]
fn scanline_1m_1080p(b: Bencher) {
    run(b, million(), Method::ScanLine, DepthFormat::F64, 1920, 1080);
}

#[divan::bench(sample_count = 3, sample_size = 1)]
fn raycast_1m_1080p(b: Bencher) {
    run(b, million(), Method::RayCast, DepthFormat::F64, 1920, 1080);
}

#[divan::bench(sample_count = 10, sample_size = 1, args = [Method::ZBuffer, Method::ScanLine, Method::ABuffer, Method::Warnock, Method::RayCast])]
fn every_method_20k_480p(b: Bencher, method: Method) {
    run(b, small(), method, DepthFormat::F64, 854, 480);
}
