//! Near-parallel hard cases, where only arithmetic exact on the input as given orders
//! correctly: faces crossing at tiny angles, stacks of nearly coincident tilted quads,
//! needle triangles. Every scene comes with a camera 4 units away, 256 × 256.

use glam::DVec3;
use limn_scene::{Camera, Material, Scene};

use crate::corpus::Case;

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

fn palette_scene(n: usize) -> (Scene, Vec<u32>, u32) {
    let mut s = Scene::default();
    let mats = (0..n)
        .map(|i| {
            let t = i as f64 / n.max(1) as f64;
            s.add_material(Material::unlit(&format!("c{i}"), [t, 1.0 - t, 0.5]))
        })
        .collect();
    let o = s.add_object("near-parallel");
    (s, mats, o)
}

fn camera() -> Camera {
    Camera::new(v(0.3, 0.4, 4.0), v(0.0, 0.0, 0.0), 256, 256)
}

/// Two squares crossing at `angle` radians along the line x = 0.2 (inside the picture):
/// the first lies in z = 0, the second in z = tan(angle)·(x − 0.2).
pub fn crossing(angle: f64) -> Case {
    let (mut s, m, o) = palette_scene(2);
    let t = angle.tan();
    let z = |x: f64| t * (x - 0.2);
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
            v(-1.0, -0.9, z(-1.0)),
            v(1.0, -0.9, z(1.0)),
            v(1.0, 0.9, z(1.0)),
            v(-1.0, 0.9, z(-1.0)),
        ],
        m[1],
        o,
    )
    .expect("valid");
    Case {
        name: "crossing",
        scene: s,
        camera: camera(),
        needs_split: true,
    }
}

/// `n` squares stacked `gap` apart along z, tilted alternately by `±tilt` about the y
/// axis, so that neighbours pass through each other along the lines
/// x = ∓gap / (2·tilt) (inside the picture when gap < tilt).
pub fn stack(n: usize, gap: f64, tilt: f64) -> Case {
    let (mut s, m, o) = palette_scene(n);
    for (k, &mat) in m.iter().enumerate() {
        let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
        let z = |x: f64| k as f64 * gap + sign * tilt * x;
        // Slightly different sizes so that every edge shows.
        let r = 1.0 - 0.004 * k as f64;
        s.add_polygon(
            &[
                v(-r, -r, z(-r)),
                v(r, -r, z(r)),
                v(r, r, z(r)),
                v(-r, r, z(-r)),
            ],
            mat,
            o,
        )
        .expect("valid");
    }
    Case {
        name: "stack",
        scene: s,
        camera: camera(),
        needs_split: true,
    }
}

/// A needle triangle `width` wide and 1.6 long, slanted through a square: its tip lies in
/// front of the square and its base behind.
pub fn needle(width: f64) -> Case {
    let (mut s, m, o) = palette_scene(2);
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
            v(-0.8, -0.3, -0.1),
            v(0.8, 0.5, 0.1),
            v(-0.8, -0.3 + width, -0.1),
        ],
        m[1],
        o,
    )
    .expect("valid");
    Case {
        name: "needle",
        scene: s,
        camera: camera(),
        needs_split: true,
    }
}
