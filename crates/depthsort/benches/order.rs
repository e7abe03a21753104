//! Ordering benchmark: prints one table of milliseconds, fragments, splits and peak memory
//! per scene and mode, exact and float, measured in one run, with ratios.
//!
//! `cargo bench -p limn-depthsort --bench order` (add `-- --quick` to skip the largest
//! scenes, `-- --big` to include the 1M-triangle sphere).

use std::time::Instant;

use glam::DVec3;
use limn_depthsort::{order, Arith, OrderOptions, Ordered, SortMode};
use limn_scene::{shapes, Camera, Material, Scene};

fn soup(n: usize, size: f64, seed: u64) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("soup", [0.7, 0.7, 0.7]));
    let o = s.add_object("soup");
    shapes::random_soup(&mut s, n, size, seed, m, o).expect("valid");
    s
}

fn sphere(rings: u32, segments: u32) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("sphere", [0.7, 0.7, 0.7]));
    let o = s.add_object("sphere");
    shapes::uv_sphere(&mut s, DVec3::ZERO, 1.0, rings, segments, m, o).expect("valid");
    s
}

fn woven(n: usize, offset: f64) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("m", [0.7, 0.7, 0.7]));
    let o = s.add_object("o");
    shapes::woven_strips(&mut s, n, offset, [m, m], o).expect("valid strips");
    s
}

fn torus() -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("torus", [0.7, 0.7, 0.7]));
    let o = s.add_object("torus");
    shapes::torus(&mut s, DVec3::ZERO, 1.0, 0.4, 200, 50, m, o).expect("valid");
    s
}

/// Two intersecting plot surfaces of `n × n` quads each over [-1, 1]²: z = 0.4·sin(2x)·
/// cos(2y) and z = 0.3·(x − y)/2 (what 3D plotting libraries hand over: quads, most of
/// them not exactly planar in f64).
fn surfaces(n: usize) -> Scene {
    let mut s = Scene::default();
    let a = s.add_material(Material::diffuse("wave", [0.8, 0.4, 0.2]));
    let b = s.add_material(Material::diffuse("plane", [0.2, 0.5, 0.8]));
    let o = s.add_object("surfaces");
    let at = |i: usize| -1.0 + 2.0 * i as f64 / n as f64;
    type Height = fn(f64, f64) -> f64;
    let fs: [(u32, Height); 2] = [
        (a, |x, y| 0.4 * (2.0 * x).sin() * (2.0 * y).cos()),
        (b, |x, y| 0.15 * (x - y)),
    ];
    for (m, f) in fs {
        for i in 0..n {
            for j in 0..n {
                let p = |i: usize, j: usize| DVec3::new(at(i), at(j), f(at(i), at(j)));
                let quad = [p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)];
                s.add_polygon(&quad, m, o).expect("valid");
            }
        }
    }
    s
}

/// Peak resident memory since the last reset, in MB (Linux; 0 elsewhere).
fn peak_mb() -> f64 {
    let s = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    s.lines()
        .find(|l| l.starts_with("VmHWM:"))
        .and_then(|l| l.split_whitespace().nth(1))
        .and_then(|v| v.parse::<f64>().ok())
        .map_or(0.0, |kb| kb / 1024.0)
}

fn reset_peak() {
    let _ = std::fs::write("/proc/self/clear_refs", "5");
}

struct Row {
    ms: f64,
    frags: usize,
    splits: usize,
    mb: f64,
    fallbacks: u64,
    visible: usize,
}

fn run(scene: &Scene, cam: &Camera, sort: SortMode, arith: Arith) -> Row {
    let opts = OrderOptions {
        sort,
        arith,
        ..OrderOptions::default()
    };
    let before = peak_mb();
    reset_peak();
    let t = Instant::now();
    let o: Ordered = order(scene, cam, &opts).expect("orderable");
    let ms = t.elapsed().as_secs_f64() * 1e3;
    let mb = (peak_mb() - before.min(peak_mb())).max(0.0);
    let visible = o.stats.polygons;
    Row {
        ms,
        frags: o.fragments.len(),
        splits: o.stats.splits,
        mb,
        fallbacks: o.stats.filter_fallbacks,
        visible,
    }
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let quick = args.iter().any(|a| a == "--quick");
    let big = args.iter().any(|a| a == "--big");
    let mut scenes: Vec<(&str, Scene, Vec<SortMode>)> = vec![
        ("soup 1k", soup(1000, 0.3, 1), SortMode::ALL.to_vec()),
        // Triangle size shrinks with n^(1/3) so each triangle meets about as many others.
        (
            "soup 10k",
            soup(10_000, 0.3 * 0.1f64.cbrt(), 2),
            SortMode::ALL.to_vec(),
        ),
        (
            "soup 10k dense",
            soup(10_000, 0.3, 2),
            SortMode::ALL.to_vec(),
        ),
        ("sphere 10k", sphere(50, 100), SortMode::ALL.to_vec()),
        ("torus 10k", torus(), SortMode::ALL.to_vec()),
        (
            "surfaces 2×100²",
            surfaces(100),
            vec![SortMode::Adaptive, SortMode::Bsp, SortMode::Simple],
        ),
        // The same woven strips at the origin and far from it: what exactness costs
        // there (the ratio exact/float) should not depend on the offset.
        ("woven 60² at 0", woven(60, 0.0), vec![SortMode::Adaptive]),
        ("woven 60² at 1e3", woven(60, 1e3), vec![SortMode::Adaptive]),
        ("woven 60² at 1e7", woven(60, 1e7), vec![SortMode::Adaptive]),
        ("woven 60² at 1e9", woven(60, 1e9), vec![SortMode::Adaptive]),
    ];
    if !quick {
        scenes.push((
            "sphere 100k",
            sphere(159, 316),
            vec![SortMode::Adaptive, SortMode::Simple],
        ));
    }
    if big {
        scenes.push((
            "sphere 1M",
            sphere(500, 1000),
            vec![SortMode::Adaptive, SortMode::Simple],
        ));
    }
    println!(
        "| scene | mode | arith | ms | fragments | visible polygons | splits | peak MB | filter fallbacks |"
    );
    println!("|---|---|---|---:|---:|---:|---:|---:|---:|");
    let only: Option<String> = args
        .iter()
        .position(|a| a == "--only")
        .and_then(|i| args.get(i + 1).cloned());
    for (name, scene, modes) in &scenes {
        if only.as_ref().is_some_and(|o| !name.contains(o.as_str())) {
            continue;
        }
        let cam = Camera::framing(scene, 1920, 1080).expect("camera");
        let mut exact_adaptive = None;
        for &mode in modes {
            for arith in [Arith::Exact, Arith::Float] {
                let r = run(scene, &cam, mode, arith);
                println!(
                    "| {name} | {} | {} | {:.1} | {} | {} | {} | {:.0} | {} |",
                    mode.name(),
                    arith.name(),
                    r.ms,
                    r.frags,
                    r.visible,
                    r.splits,
                    r.mb,
                    r.fallbacks
                );
                if mode == SortMode::Adaptive && arith == Arith::Exact {
                    exact_adaptive = Some(r.ms);
                } else if let Some(base) = exact_adaptive {
                    if mode == SortMode::Adaptive {
                        println!(
                            "|  | ratio exact/float |  | {:.2} |  |  |  |  |  |",
                            base / r.ms
                        );
                    }
                }
            }
        }
    }
}
