//! Orders a random triangle soup (`N SIZE [MODE]`) once and prints the statistics: a
//! profiling target.

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
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("soup", [0.7, 0.7, 0.7]));
    let o = s.add_object("soup");
    shapes::random_soup(&mut s, n, size, 2, m, o).expect("valid soup");
    let cam = Camera::framing(&s, 1920, 1080).expect("camera");
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
