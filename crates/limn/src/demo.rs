//! The built-in demo scene: what limn is for, in one picture, on a floor that catches
//! exact shadows from a directional light.
//!
//! * left: three strips overlapping cyclically (no painter's order of whole faces
//!   exists);
//! * middle: two closed boxes passing through each other;
//! * right: a smooth-shaded icosphere (5,120 triangles) with a specular highlight, and a
//!   rod with an arrow head passing through it (hidden exactly inside).

use std::borrow::Cow;
use std::path::PathBuf;

use glam::{DMat3, DVec3};
use limn_load::SceneOptions;
use limn_scene::{shapes, Camera, Light, LightKind, Material, Polyline, Scene, SceneError};

use crate::error::Error;
use crate::input::Input;
use crate::options::RenderOptions;
use crate::render::Request;

/// The demo's shading tolerance: 4/255 per channel. Its glossy sphere in SVG takes
/// about 1.2 MB at the default 1/255 (gradients and flat pieces, see BENCHMARKS.md),
/// which is too much for a first picture; at 4/255 the highlight still shows no steps.
const DEMO_TOLERANCE: f64 = 4.0 / 255.0;

/// Builds the demo scene.
pub fn scene() -> Result<Scene, SceneError> {
    let mut s = Scene::default();
    // Lit materials whose shadowed side keeps half their colour.
    let lit = |name: &str, kd: [f64; 3]| Material {
        ka: kd.map(|c| c * 0.45),
        ..Material::diffuse(name, kd)
    };
    // A floor to catch the shadows.
    let floor_m = s.add_material(lit("floor", [0.8, 0.79, 0.75]));
    let floor = s.add_object("floor");
    let y0 = -1.25;
    s.add_polygon(
        &[
            DVec3::new(-6.4, y0, -3.2),
            DVec3::new(-6.4, y0, 3.0),
            DVec3::new(5.6, y0, 3.0),
            DVec3::new(5.6, y0, -3.2),
        ],
        floor_m,
        floor,
    )?;
    // Cyclic strips: each lies over the next, so no order of whole faces exists.
    let colours = [[0.85, 0.25, 0.2], [0.2, 0.6, 0.3], [0.2, 0.4, 0.85]];
    let strips = s.add_object("cyclic strips");
    let (r, len, h, w) = (0.75, 1.9, 0.5, 0.75);
    let centre = DVec3::new(-3.6, 0.5, 0.2);
    for (k, c) in colours.iter().enumerate() {
        let m = s.add_material(lit(&format!("strip{k}"), *c));
        let th = k as f64 * std::f64::consts::TAU / 3.0;
        let d = DVec3::new(th.cos(), 0.0, th.sin());
        let n = DVec3::new(th.sin(), 0.0, -th.cos());
        let at = |t: f64, side: f64| {
            centre + n * r + d * t + n * (side * w / 2.0) + DVec3::new(0.0, -h * t / len, 0.0)
        };
        s.add_polygon(
            &[at(-len, -1.0), at(len, -1.0), at(len, 1.0), at(-len, 1.0)],
            m,
            strips,
        )?;
    }
    // Interpenetrating boxes.
    let red = s.add_material(lit("red box", [0.9, 0.3, 0.25]));
    let blue = s.add_material(lit("blue box", [0.25, 0.45, 0.9]));
    let a = s.add_object("box A");
    shapes::cuboid(
        &mut s,
        DVec3::new(-1.2, y0, -0.8),
        DVec3::new(0.3, 0.25, 0.7),
        DMat3::IDENTITY,
        red,
        a,
    )?;
    let b = s.add_object("box B");
    let rot = DMat3::from_rotation_y(0.6) * DMat3::from_rotation_x(0.45);
    shapes::cuboid(
        &mut s,
        DVec3::new(-0.5, -0.6, -0.4),
        DVec3::new(0.9, 0.8, 1.0),
        rot,
        blue,
        b,
    )?;
    // A shaded sphere with a highlight, and a rod through it.
    let gold = s.add_material(Material {
        ka: [0.38, 0.29, 0.11],
        ..Material::glossy("sphere", [0.85, 0.65, 0.25], [0.6, 0.6, 0.6], 40.0)
    });
    let sphere = s.add_object("sphere");
    let c = DVec3::new(3.0, 0.0, 0.0);
    shapes::icosphere(&mut s, c, 1.2, 4, gold, sphere)?;
    let rod = s.add_object("rod");
    s.lines.push(Polyline {
        points: vec![
            c + DVec3::new(-2.2, -0.9, 1.6),
            c + DVec3::new(2.0, 0.9, -1.4),
        ],
        color: [0.1, 0.1, 0.1, 1.0],
        width: 2.0,
        dash: Vec::new(),
        head: true,
        object: rod,
    });
    s.lights = vec![
        Light {
            kind: LightKind::Directional(DVec3::new(0.5, 1.0, 0.6)),
            color: [0.7, 0.7, 0.7],
            shadows: true,
        },
        Light {
            kind: LightKind::Ambient,
            color: [1.0, 1.0, 1.0],
            shadows: false,
        },
    ];
    s.camera = Some(Camera {
        fov_deg: 27.0,
        ..Camera::new(
            DVec3::new(1.2, 7.0, 11.5),
            DVec3::new(-0.4, -0.1, 0.0),
            960,
            540,
        )
    });
    Ok(s)
}

/// The demo's render: the built-in scene, framed at 960×540 on white, written to
/// `output` like any render (its format from the extension).
pub fn request(
    output: PathBuf,
    outline: bool,
    stats: Option<PathBuf>,
) -> Result<Request<'static>, Error> {
    let scene = scene().map_err(|source| Error::Scene {
        input: "demo".into(),
        source,
    })?;
    Ok(Request {
        input: Input::Scene {
            scene: Cow::Owned(scene),
            settings: SceneOptions {
                size: Some((960, 540)),
                background: Some([1.0; 3]),
                ..SceneOptions::default()
            },
            name: "demo".into(),
        },
        output: Some(output),
        options: RenderOptions {
            outline,
            shading_tolerance: DEMO_TOLERANCE,
            stats,
            ..RenderOptions::default()
        },
    })
}

#[cfg(test)]
mod tests {
    #[test]
    fn demo_scene_is_valid() {
        let s = super::scene().unwrap();
        s.validate().unwrap();
        assert_eq!(s.faces.len(), 1 + 3 + 12 + 5120);
    }
}
