//! Orders a closed UV sphere (`RINGS SEGMENTS` arguments) once and prints the statistics:
//! a profiling target.

use glam::DVec3;
use limn_depthsort::{order, OrderOptions};
use limn_scene::{shapes, Camera, Material, Scene};

fn main() {
    let args: Vec<u32> = std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect();
    let (rings, segments) = (
        args.first().copied().unwrap_or(159),
        args.get(1).copied().unwrap_or(316),
    );
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("sphere", [0.7, 0.7, 0.7]));
    let o = s.add_object("sphere");
    shapes::uv_sphere(&mut s, DVec3::ZERO, 1.0, rings, segments, m, o).expect("valid sphere");
    let cam = Camera::framing(&s, 1920, 1080).expect("camera");
    let t = std::time::Instant::now();
    let r = order(&s, &cam, &OrderOptions::default()).expect("orderable");
    println!(
        "{} faces: {:.1} ms",
        s.faces.len(),
        t.elapsed().as_secs_f64() * 1e3
    );
    println!("{:#?}", r.stats);
}
