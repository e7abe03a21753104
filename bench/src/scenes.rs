//! The fixed scenes of the table: soups, closed meshes, plot surfaces and hard cases,
//! each with its camera. Every face gets its own unlit colour, so that a pixel of any
//! program's picture names the face it shows.

use glam::DVec3;
use limn_scene::{shapes, Camera, Material, Scene};
use limn_tests::{corpus, near_parallel};

/// One scene of the table.
pub struct BenchScene {
    /// Short name (a table row).
    pub name: String,
    /// The scene, one unlit colour per face.
    pub scene: Scene,
    /// The camera.
    pub camera: Camera,
}

/// Picture size of every scene.
pub const SIZE: (u32, u32) = (400, 300);

/// The colour that names face `i` (never the white background).
pub fn face_colour(i: usize) -> [u8; 3] {
    let v = i as u32 + 1;
    [(v >> 16) as u8, (v >> 8) as u8, v as u8]
}

/// The face a colour names, if any.
pub fn face_of(c: [u8; 3]) -> Option<u32> {
    let v = (u32::from(c[0]) << 16) | (u32::from(c[1]) << 8) | u32::from(c[2]);
    v.checked_sub(1)
}

/// `scene` with one unlit material per face in the colour [`face_colour`] gives it.
fn identified(scene: &Scene) -> Scene {
    let mut s = scene.clone();
    s.lights.clear();
    s.materials = (0..scene.faces.len())
        .map(|i| Material::unlit("face", face_colour(i).map(|v| f64::from(v) / 255.0)))
        .collect();
    for (i, f) in s.faces.iter_mut().enumerate() {
        f.material = i as u32;
    }
    s
}

fn framed(name: &str, scene: Scene) -> BenchScene {
    let name = format!("{name} ({} faces)", scene.faces.len());
    let camera = Camera::framing(&scene, SIZE.0, SIZE.1).expect("a framable scene");
    BenchScene {
        name,
        scene: identified(&scene),
        camera,
    }
}

fn with_camera(name: &str, scene: &Scene, camera: &Camera) -> BenchScene {
    let mut camera = *camera;
    // The corpus' cameras keep their view; the picture size is the table's.
    camera.width = SIZE.0;
    camera.height = SIZE.1;
    BenchScene {
        name: name.into(),
        scene: identified(scene),
        camera,
    }
}

fn one_object(build: impl FnOnce(&mut Scene, u32, u32)) -> Scene {
    let mut s = Scene::default();
    let m = s.add_material(Material::diffuse("m", [0.7, 0.7, 0.7]));
    let o = s.add_object("o");
    build(&mut s, m, o);
    s
}

fn soup(n: usize, size: f64) -> Scene {
    one_object(|s, m, o| {
        shapes::random_soup(s, n, size, 7, m, o).expect("valid soup");
    })
}

fn sphere(rings: u32, segments: u32) -> Scene {
    one_object(|s, m, o| {
        shapes::uv_sphere(s, DVec3::ZERO, 1.0, rings, segments, m, o).expect("valid sphere");
    })
}

fn torus() -> Scene {
    one_object(|s, m, o| {
        shapes::torus(s, DVec3::ZERO, 1.0, 0.35, 100, 100, m, o).expect("valid torus");
    })
}

/// Two intersecting height fields of `n` × `n` quads: a wave and a tilted plane.
fn surfaces(n: usize) -> Scene {
    one_object(|s, m, o| {
        let at = |i: usize| -1.0 + 2.0 * i as f64 / n as f64;
        type Height = fn(f64, f64) -> f64;
        let fs: [Height; 2] = [
            |x, y| 0.4 * (2.0 * x).sin() * (2.0 * y).cos(),
            |x, y| 0.15 * (x - y),
        ];
        for f in fs {
            for i in 0..n {
                for j in 0..n {
                    let p = |i: usize, j: usize| DVec3::new(at(i), at(j), f(at(i), at(j)));
                    let quad = [p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1)];
                    s.add_polygon(&quad, m, o).expect("valid quad");
                }
            }
        }
    })
}

/// A scene's name and the function that builds it.
pub type LargeScene = (&'static str, fn() -> BenchScene);

/// The large scenes timed against gl2ps alone (`limn-bench large`): two intersecting
/// 300 × 300 height fields and the two soups of 10,000 triangles, each built only when
/// it is measured.
pub fn large() -> Vec<LargeScene> {
    vec![
        ("surfaces 2×300²", || {
            framed("surfaces 2×300²", surfaces(300))
        }),
        ("soup 10k", || framed("soup 10k", soup(10_000, 0.14))),
        ("soup 10k dense", || {
            framed("soup 10k dense", soup(10_000, 0.3))
        }),
    ]
}

/// The scenes: all of them, or (`quick`) those that stay small.
pub fn all(quick: bool) -> Vec<BenchScene> {
    let mut out = vec![
        framed("soup 1k", soup(1_000, 0.3)),
        framed("sphere 10k", sphere(50, 100)),
        framed("torus 10k", torus()),
        framed("surfaces 2×40²", surfaces(40)),
    ];
    if !quick {
        out.push(framed("soup 10k", soup(10_000, 0.14)));
        out.push(framed("soup 10k dense", soup(10_000, 0.3)));
        out.push(framed("sphere 100k", sphere(160, 316)));
        out.push(framed("surfaces 2×100²", surfaces(100)));
    }
    let cyclic = corpus::cyclic_quads();
    out.push(with_camera("cyclic triple", &cyclic.scene, &cyclic.camera));
    let pierce = corpus::interpenetrating_triangles();
    out.push(with_camera(
        "interpenetration",
        &pierce.scene,
        &pierce.camera,
    ));
    let cross = near_parallel::crossing(1e-7);
    out.push(with_camera(
        "crossing 1e-7 rad",
        &cross.scene,
        &cross.camera,
    ));
    let stack = near_parallel::stack(12, 1e-8, 1e-7);
    out.push(with_camera("stack 1e-8 apart", &stack.scene, &stack.camera));
    if let Some(far) = corpus::cyclic_far_and_small().into_iter().next() {
        out.push(with_camera("cyclic triple at 1e7", &far.scene, &far.camera));
    }
    out
}
