//! Times every method on a terrain of about one million triangles at 1920×1080 and
//! prints a Markdown table: `cargo run --release -p limn-zbuffer --example million`.
//!
//! Arguments (optional): grid size `n` (2·n² triangles, default 707), width, height,
//! and the methods to run (default `zbuffer scanline raycast`). With
//! `LIMN_MILLION_SCENE=soup` the scene is 2·n² random small triangles in a cube
//! instead (heavy overdraw, many intersections).

use std::time::Instant;

/// CPU time of this thread in seconds (`CLOCK_THREAD_CPUTIME_ID`; `None` where
/// unavailable), so that other load on the machine does not count.
fn cpu_seconds() -> Option<f64> {
    cpu_time::ThreadTime::try_now()
        .ok()
        .map(|t| t.as_duration().as_secs_f64())
}

use glam::DVec3;
use limn_scene::{Camera, Material, Scene};
use limn_zbuffer::{compare, render, DepthFormat, Method, RenderOptions};

/// A height field of `n × n` quads, two triangles each, with smooth hills.
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

/// `count` random small triangles in a cube (edges about `size`), unrelated to each
/// other: much overdraw, many intersections.
fn soup(count: usize, size: f64) -> Scene {
    let mut s = Scene::default();
    s.add_material(Material::diffuse("soup", [0.8, 0.5, 0.3]));
    s.add_object("soup");
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    let mut r = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    };
    for _ in 0..count {
        let c = DVec3::new(r(), r(), r());
        let pts: Vec<DVec3> = (0..3)
            .map(|_| c + DVec3::new(r(), r(), r()) * size)
            .collect();
        s.add_polygon(&pts, 0, 0).expect("face");
    }
    s
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let n: usize = args.first().and_then(|a| a.parse().ok()).unwrap_or(707);
    let w: u32 = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(1920);
    let h: u32 = args.get(2).and_then(|a| a.parse().ok()).unwrap_or(1080);
    let methods: Vec<Method> = if args.len() > 3 {
        args[3..].iter().filter_map(|a| a.parse().ok()).collect()
    } else {
        vec![Method::ZBuffer, Method::ScanLine, Method::RayCast]
    };
    let t = Instant::now();
    let is_soup = std::env::var("LIMN_MILLION_SCENE").is_ok_and(|v| v == "soup");
    let scene = if is_soup {
        soup(2 * n * n, 0.02)
    } else {
        terrain(n)
    };
    eprintln!(
        "built {} triangles in {:.2?}",
        scene.faces.len(),
        t.elapsed()
    );
    let mut camera = Camera::new(
        DVec3::new(0.0, 0.75, 1.2),
        DVec3::new(0.0, -0.2, -0.4),
        w,
        h,
    );
    camera.fov_deg = 50.0;
    println!("| method | depth | CPU time (s) | wall time (s) | covered px | fragments | working memory (MiB) |");
    println!("|---|---|---|---|---|---|---|");
    let mut reference = None;
    for m in methods {
        let formats: &[DepthFormat] = match m {
            Method::ZBuffer => &DepthFormat::ALL,
            _ => &[DepthFormat::F64],
        };
        for &depth in formats {
            let opts = RenderOptions {
                depth,
                ..RenderOptions::default()
            };
            let (t, c0) = (Instant::now(), cpu_seconds());
            let r = render(&scene, &camera, m, &opts).expect("render");
            let secs = t.elapsed().as_secs_f64();
            let cpu = match (c0, cpu_seconds()) {
                (Some(a), Some(b)) => format!("{:.3}", b - a),
                _ => "n/a".to_string(),
            };
            println!(
                "| {m} | {depth:?} | {cpu} | {secs:.3} | {} | {} | {:.1} |",
                r.ids.covered(),
                r.stats.fragments,
                r.stats.working_bytes as f64 / (1 << 20) as f64
            );
            if m == Method::RayCast {
                eprintln!(
                    "raycast: {} exact depth comparisons",
                    r.stats.exact_fallbacks
                );
            }
            if let Ok(path) = std::env::var("LIMN_MILLION_PNG") {
                r.color
                    .save_png(std::path::Path::new(&format!("{path}-{m}.png")))
                    .expect("png");
            }
            if depth == DepthFormat::F64 {
                match &reference {
                    None => reference = Some(r.ids),
                    Some(z) => {
                        let c = compare(z, &r.ids, None);
                        eprintln!(
                            "{m}: {} of {} pixels differ from the first method",
                            c.mismatches, c.pixels
                        );
                    }
                }
            }
        }
    }
}
