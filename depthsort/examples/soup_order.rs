//! Orders a random triangle soup (`N SIZE [MODE]`) once and prints the statistics: a
//! profiling target.

use glam::DVec3;
use limn_depthsort::{order, OrderOptions, SortMode};
use limn_scene::{Camera, Material, Scene};

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
    let mut rng = 2u64;
    let mut next = move || {
        rng = rng
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((rng >> 11) as f64) / ((1u64 << 53) as f64)
    };
    while s.faces.len() < n {
        let c = DVec3::new(next(), next(), next()) * 2.0 - 1.0;
        let pts: Vec<DVec3> = (0..3)
            .map(|_| c + (DVec3::new(next(), next(), next()) - 0.5) * size)
            .collect();
        if (pts[1] - pts[0]).cross(pts[2] - pts[0]).length() > 1e-9 {
            s.add_polygon(&pts, m, o).expect("valid triangle");
        }
    }
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
