use glam::DVec3;
use limn_scene::{Camera, Material, Scene};
use limn_zbuffer::*;

fn main() {
    let mut s = Scene::default();
    for (k, c) in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]].iter().enumerate() {
        s.add_material(Material::diffuse(&format!("m{k}"), *c));
    }
    s.add_object("o");
    let mut seed = 7u64;
    let mut f = || {
        seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        (seed >> 11) as f64 / (1u64 << 53) as f64 * 3.0 - 1.5
    };
    for k in 0..20 {
        let pts: Vec<DVec3> = (0..3).map(|_| DVec3::new(f(), f(), f())).collect();
        s.add_polygon(&pts, k % 3, 0).unwrap();
    }
    let eye: Vec<f64> = std::env::args().skip(1).map(|a| a.parse().unwrap()).collect();
    let eye = if eye.len() == 3 { DVec3::new(eye[0], eye[1], eye[2]) } else { DVec3::new(2.5, 1.5, 3.5) };
    let cam = Camera::new(eye, DVec3::ZERO, 320, 240);
    let opts = RenderOptions::default();
    let edges = scene_edges(&s, &cam, &opts).unwrap();
    let band = edge_band(&edges, 320, 240, default_band_tolerance(320, 240));
    let r = render(&s, &cam, Method::RayCast, &opts).unwrap();
    println!("band {} raycast covered {} stats {:?}", band.count(), r.ids.covered(), r.stats);
    for m in Method::ALL {
        let x = render(&s, &cam, m, &opts).unwrap();
        let c = compare(&r.ids, &x.ids, Some(&band));
        println!("{m}: covered {} mism {} outside {} stats {:?}", x.ids.covered(), c.mismatches, c.mismatches_outside_band, x.stats);
        x.color.save_png(std::path::Path::new(&format!("/tmp/zb_{m}.png"))).unwrap();
        save_diff_png(&r.ids, &x.ids, Some(&band), std::path::Path::new(&format!("/tmp/zb_diff_{m}.png"))).unwrap();
    }
    r.depth.save_png(std::path::Path::new("/tmp/zb_depth.png")).unwrap();
    r.ids.save_png(std::path::Path::new("/tmp/zb_ids.png")).unwrap();
}
