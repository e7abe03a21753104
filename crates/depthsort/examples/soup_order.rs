//! Orders a random triangle soup (`N SIZE [MODE [SEED [WIDTHxHEIGHT]]]`; defaults 10000,
//! 0.3, adaptive, 2, 1920x1080) once and prints the statistics: a profiling target.
//! `limn-bench large` orders the soups of seed 7 at 400x300.

use limn_depthsort::{order, OrderOptions, SortMode};
use limn_scene::{shapes, Camera, Material, Scene};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let n: usize = args.first().and_then(|a| a.parse().ok()).unwrap_or(10_000);
    let size: f64 = args.get(1).and_then(|a| a.parse().ok()).unwrap_or(0.3);
    let sort = args
        .get(2)
        .and_then(|a| SortMode::from_name(a))
        .unwrap_or(SortMode::Adaptive);
    let seed: u64 = args.get(3).and_then(|a| a.parse().ok()).unwrap_or(2);
    let (w, h) = args
        .get(4)
        .and_then(|a| a.split_once('x'))
        .and_then(|(w, h)| Some((w.parse().ok()?, h.parse().ok()?)))
        .unwrap_or((1920, 1080));
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("soup", [0.7, 0.7, 0.7]));
    let o = s.add_object("soup");
    shapes::random_soup(&mut s, n, size, seed, m, o).expect("valid soup");
    let cam = Camera::framing(&s, w, h).expect("camera");
    let t = std::time::Instant::now();
    let r = order(
        &s,
        &cam,
        &OrderOptions {
            sort,
            ..OrderOptions::default()
        },
    )
    .expect("orderable");
    println!(
        "{} faces: {:.1} ms",
        s.faces.len(),
        t.elapsed().as_secs_f64() * 1e3
    );
    println!("{:#?}", r.stats);
}
