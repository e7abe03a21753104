//! debug
use glam::DVec3;
use limn_scene::{Camera, Material, Scene};
use limn_zbuffer::*;

fn main() {
    let mut s = Scene::default();
    s.add_material(Material::unlit("a", [1.0, 0.0, 0.0]));
    s.add_object("o");
    let corners = [(1.0, -1.0), (1.0, 1.0), (-1.0, 1.0), (-1.0, -1.0)].map(|(x, y)| DVec3::new(x, y, 0.0));
    for k in 0..4 {
        s.add_polygon(&[DVec3::ZERO, corners[k], corners[(k + 1) % 4]], 0, 0).unwrap();
    }
    let camera = Camera::new(DVec3::new(0.0, 0.0, 4.0), DVec3::ZERO, 65, 65);
    let opts = RenderOptions::default();
    let z = render(&s, &camera, Method::ZBuffer, &opts).unwrap();
    let r = render(&s, &camera, Method::RayCast, &opts).unwrap();
    for y in 0..65 {
        for x in 0..65 {
            let (a, b) = (z.ids.get(x, y).unwrap(), r.ids.get(x, y).unwrap());
            if a != b {
                println!("{x},{y}: z {a} r {b}");
            }
        }
    }
}
