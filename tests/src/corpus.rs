//! The hard-case corpus: small scenes, built in code, on which painter's orderings go
//! wrong. Each comes with a camera.

use glam::DVec3;
use limn_scene::{shapes, Camera, Material, Scene};

/// A named scene with its camera.
#[derive(Debug, Clone)]
pub struct Case {
    /// Short name, used in test output.
    pub name: &'static str,
    /// The scene.
    pub scene: Scene,
    /// The camera.
    pub camera: Camera,
    /// Whether a correct order of whole faces exists (false: some face must be split).
    pub needs_split: bool,
}

const PALETTE: [[f64; 3]; 8] = [
    [0.85, 0.2, 0.2],
    [0.2, 0.65, 0.3],
    [0.2, 0.35, 0.85],
    [0.9, 0.75, 0.2],
    [0.6, 0.3, 0.7],
    [0.2, 0.7, 0.75],
    [0.9, 0.5, 0.2],
    [0.5, 0.5, 0.5],
];

fn scene_with_palette() -> (Scene, Vec<u32>, u32) {
    palette_scene("case")
}

/// An empty scene with the eight unlit palette materials and one object named `object`:
/// (scene, material ids, object id).
pub(crate) fn palette_scene(object: &str) -> (Scene, Vec<u32>, u32) {
    let mut s = Scene::default();
    let mats = PALETTE
        .iter()
        .enumerate()
        .map(|(i, &c)| s.add_material(Material::unlit(&format!("c{i}"), c)))
        .collect();
    let o = s.add_object(object);
    (s, mats, o)
}

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

fn cam(eye: DVec3, target: DVec3) -> Camera {
    Camera::new(eye, target, 160, 120)
}

/// Three strips arranged in a triangle, each passing over the next and under the
/// previous where they cross: no order of whole faces exists.
pub fn cyclic_quads() -> Case {
    let (mut s, m, o) = scene_with_palette();
    let (r, len, h, w) = (1.0, 2.5, 0.5, 0.5);
    for (k, &mat) in m.iter().take(3).enumerate() {
        let th = k as f64 * std::f64::consts::TAU / 3.0;
        let d = v(th.cos(), th.sin(), 0.0);
        let n = v(th.sin(), -th.cos(), 0.0);
        let c = n * r;
        let at = |t: f64, side: f64| c + d * t + n * (side * w / 2.0) + v(0.0, 0.0, -h * t / len);
        let quad = [at(-len, -1.0), at(len, -1.0), at(len, 1.0), at(-len, 1.0)];
        s.add_polygon(&quad, mat, o).expect("valid quad");
    }
    Case {
        name: "cyclic_quads",
        scene: s,
        camera: cam(v(0.3, 0.2, 9.0), v(0.0, 0.0, 0.0)),
        needs_split: true,
    }
}

/// Two triangles that pass through each other.
pub fn interpenetrating_triangles() -> Case {
    let (mut s, m, o) = scene_with_palette();
    s.add_polygon(
        &[v(-1.0, -1.0, -1.0), v(1.0, -1.0, 1.0), v(0.0, 1.0, 0.0)],
        m[0],
        o,
    )
    .expect("valid");
    s.add_polygon(
        &[v(-1.0, -1.0, 1.0), v(1.0, -1.0, -1.0), v(0.0, 0.9, 0.1)],
        m[1],
        o,
    )
    .expect("valid");
    Case {
        name: "interpenetrating_triangles",
        scene: s,
        camera: cam(v(0.2, 0.3, 5.0), v(0.0, 0.0, 0.0)),
        needs_split: true,
    }
}

/// A woven grid: horizontal and vertical strips passing alternately over and under each
/// other, each strip a zig-zag of flat quads with its kinks at the crossings.
pub fn woven_grid() -> Case {
    let (mut s, m, o) = scene_with_palette();
    shapes::woven_strips(&mut s, 3, 0.0, [m[0], m[1]], o).expect("valid");
    Case {
        name: "woven_grid",
        scene: s,
        camera: cam(v(0.7, -1.2, 5.0), v(0.0, 0.0, 0.0)),
        needs_split: false,
    }
}

/// Overlapping coplanar faces (same and opposite orientation): the later face wins.
pub fn coplanar_overlaps() -> Case {
    let (mut s, m, o) = scene_with_palette();
    s.add_polygon(
        &[
            v(-1.0, -1.0, 0.0),
            v(0.5, -1.0, 0.0),
            v(0.5, 0.5, 0.0),
            v(-1.0, 0.5, 0.0),
        ],
        m[0],
        o,
    )
    .expect("valid");
    s.add_polygon(
        &[
            v(-0.5, -0.5, 0.0),
            v(1.0, -0.5, 0.0),
            v(1.0, 1.0, 0.0),
            v(-0.5, 1.0, 0.0),
        ],
        m[1],
        o,
    )
    .expect("valid");
    // Opposite orientation, overlapping both.
    s.add_polygon(
        &[
            v(-0.2, -0.8, 0.0),
            v(-0.2, 0.8, 0.0),
            v(0.2, 0.8, 0.0),
            v(0.2, -0.8, 0.0),
        ],
        m[2],
        o,
    )
    .expect("valid");
    // A face behind, partly covered.
    s.add_polygon(
        &[v(-1.5, -1.5, -0.5), v(1.5, -1.5, -0.5), v(0.0, 1.5, -0.5)],
        m[3],
        o,
    )
    .expect("valid");
    Case {
        name: "coplanar_overlaps",
        scene: s,
        camera: cam(v(0.3, 0.4, 4.0), v(0.0, 0.0, 0.0)),
        needs_split: false,
    }
}

/// Faces sharing edges, and a T-junction (a vertex of one face in the middle of another
/// face's edge), forming a folded surface seen partly from behind.
pub fn shared_edges_tjunctions() -> Case {
    let (mut s, m, o) = scene_with_palette();
    let a = v(-1.0, -1.0, 0.0);
    let b = v(1.0, -1.0, 0.0);
    let c = v(1.0, 1.0, 0.0);
    let d = v(-1.0, 1.0, 0.0);
    let mid = v(0.0, 1.0, 0.0);
    s.add_polygon(&[a, b, c, d], m[0], o).expect("valid");
    // Two faces hinged on the top edge; their shared vertex `mid` is a T-junction.
    s.add_polygon(&[d, mid, v(0.0, 1.6, 0.8), v(-1.0, 1.6, 0.8)], m[1], o)
        .expect("valid");
    s.add_polygon(&[mid, c, v(1.0, 1.6, 0.8), v(0.0, 1.6, 0.8)], m[2], o)
        .expect("valid");
    // A fold down in front of the lower edge.
    s.add_polygon(&[b, a, v(-1.0, -0.4, 0.9), v(1.0, -0.4, 0.9)], m[3], o)
        .expect("valid");
    Case {
        name: "shared_edges_tjunctions",
        scene: s,
        camera: cam(v(0.4, -2.5, 4.0), v(0.0, 0.2, 0.0)),
        needs_split: false,
    }
}

/// Faces whose planes contain the eye (seen exactly edge-on) among ordinary faces.
pub fn edge_on() -> Case {
    let (mut s, m, o) = scene_with_palette();
    let eye = v(0.0, 0.0, 5.0);
    // The plane x = 0 contains the eye.
    s.add_polygon(
        &[
            v(0.0, -1.0, -1.0),
            v(0.0, -1.0, 1.0),
            v(0.0, 1.0, 1.0),
            v(0.0, 1.0, -1.0),
        ],
        m[0],
        o,
    )
    .expect("valid");
    // The plane y = 0 contains the eye too.
    s.add_polygon(
        &[
            v(-1.0, 0.0, -1.0),
            v(1.0, 0.0, -1.0),
            v(1.0, 0.0, 1.0),
            v(-1.0, 0.0, 1.0),
        ],
        m[1],
        o,
    )
    .expect("valid");
    s.add_polygon(
        &[
            v(-1.5, -1.5, -1.2),
            v(1.5, -1.5, -1.2),
            v(1.5, 1.5, -1.2),
            v(-1.5, 1.5, -1.2),
        ],
        m[2],
        o,
    )
    .expect("valid");
    Case {
        name: "edge_on",
        scene: s,
        camera: cam(eye, v(0.0, 0.0, 0.0)),
        needs_split: false,
    }
}

/// A ground plane running under and behind the camera, and a triangle crossing the near
/// plane: everything behind the eye is clipped, nothing is projected through it.
pub fn behind_eye() -> Case {
    let (mut s, m, o) = scene_with_palette();
    s.add_polygon(
        &[
            v(-20.0, 0.0, 20.0),
            v(20.0, 0.0, 20.0),
            v(20.0, 0.0, -20.0),
            v(-20.0, 0.0, -20.0),
        ],
        m[1],
        o,
    )
    .expect("valid");
    s.add_polygon(
        &[v(-0.5, 0.0, 0.0), v(0.5, 0.0, 0.0), v(0.0, 1.0, 0.0)],
        m[0],
        o,
    )
    .expect("valid");
    // Crosses the eye's plane: part in front, part behind.
    s.add_polygon(
        &[v(0.6, 0.2, 6.0), v(1.2, 0.2, -2.0), v(0.6, 1.0, -2.0)],
        m[2],
        o,
    )
    .expect("valid");
    Case {
        name: "behind_eye",
        scene: s,
        camera: cam(v(0.0, 1.0, 4.0), v(0.0, 0.5, 0.0)),
        needs_split: false,
    }
}

/// Two large faces crossing at an angle of 1e-7 rad.
pub fn tiny_angle() -> Case {
    let (mut s, m, o) = scene_with_palette();
    let t = 1e-7f64.tan();
    s.add_polygon(
        &[
            v(-1.0, -1.0, 0.0),
            v(1.0, -1.0, 0.0),
            v(1.0, 1.0, 0.0),
            v(-1.0, 1.0, 0.0),
        ],
        m[0],
        o,
    )
    .expect("valid");
    s.add_polygon(
        &[
            v(-1.0, -0.8, -t),
            v(1.0, -0.8, t),
            v(1.0, 0.8, t),
            v(-1.0, 0.8, -t),
        ],
        m[1],
        o,
    )
    .expect("valid");
    Case {
        name: "tiny_angle",
        scene: s,
        camera: cam(v(0.1, 0.2, 3.0), v(0.0, 0.0, 0.0)),
        needs_split: true,
    }
}

/// Applies `f` to every vertex, the eye and the target.
pub fn transformed(case: &Case, name: &'static str, f: impl Fn(DVec3) -> DVec3) -> Case {
    let mut c = case.clone();
    c.name = name;
    for p in &mut c.scene.vertices {
        *p = f(*p);
    }
    let up_tip = f(case.camera.eye + case.camera.up);
    c.camera.eye = f(case.camera.eye);
    c.camera.target = f(case.camera.target);
    c.camera.up = up_tip - c.camera.eye;
    c
}

/// The cyclic scene translated by 1e7 and scaled by 1e-9.
pub fn cyclic_far_and_small() -> Vec<Case> {
    let base = cyclic_quads();
    vec![
        transformed(&base, "cyclic_translated_1e7", |p| p + DVec3::splat(1e7)),
        transformed(&base, "cyclic_scaled_1e-9", |p| p * 1e-9),
    ]
}

/// A random soup of `n` triangles in the unit cube (deterministic for a seed).
pub fn soup(n: usize, seed: u64, size: f64) -> Case {
    let (mut s, m, o) = scene_with_palette();
    let mut rng = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    let mut next = move || {
        rng = rng
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((rng >> 11) as f64) / ((1u64 << 53) as f64)
    };
    for i in 0..n {
        let c = v(next() * 2.0 - 1.0, next() * 2.0 - 1.0, next() * 2.0 - 1.0);
        let mut pts = [DVec3::ZERO; 3];
        for p in &mut pts {
            *p = c + v(next() - 0.5, next() - 0.5, next() - 0.5) * size;
        }
        if (pts[1] - pts[0]).cross(pts[2] - pts[0]).length() < 1e-9 {
            continue;
        }
        s.add_polygon(&pts, m[i % m.len()], o).expect("valid");
    }
    Case {
        name: "soup",
        scene: s,
        camera: cam(v(0.8, 1.1, 4.5), v(0.0, 0.0, 0.0)),
        needs_split: true,
    }
}

/// Every hard case.
pub fn all() -> Vec<Case> {
    let mut v = vec![
        cyclic_quads(),
        interpenetrating_triangles(),
        woven_grid(),
        coplanar_overlaps(),
        shared_edges_tjunctions(),
        edge_on(),
        behind_eye(),
        tiny_angle(),
    ];
    v.extend(cyclic_far_and_small());
    let mut s = soup(40, 7, 0.9);
    s.name = "soup_40";
    v.push(s);
    v
}
