//! Scenes the unit tests order: one grey material and one object each.

use glam::DVec3;
use limn_scene::{shapes, Material, Scene};

/// `n` random triangles of size `size` (`shapes::random_soup`, seeded by `seed`).
pub(crate) fn soup(n: usize, size: f64, seed: u64) -> Scene {
    one_object("soup", |s, m, o| {
        shapes::random_soup(s, n, size, seed, m, o).expect("a valid soup");
    })
}

/// A torus of `rings` × `sides` quads about the origin (radii 1 and 0.35).
pub(crate) fn torus(rings: u32, sides: u32) -> Scene {
    one_object("torus", |s, m, o| {
        shapes::torus(s, DVec3::ZERO, 1.0, 0.35, rings, sides, m, o).expect("a valid torus");
    })
}

/// A scene of one material and one object `name`, its faces added by `add(scene,
/// material, object)`.
fn one_object(name: &str, add: impl FnOnce(&mut Scene, u32, u32)) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("m", [0.5; 3]));
    let o = s.add_object(name);
    add(&mut s, m, o);
    s
}
