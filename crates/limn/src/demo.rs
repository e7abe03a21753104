//! The built-in demo scene: what limn is for, in one picture.
//!
//! * left: three strips overlapping cyclically (no painter's order of whole faces
//!   exists), drawn with exact unlit colours;
//! * middle: two closed boxes passing through each other, lit;
//! * right: a closed, shaded icosphere with a specular highlight.

use std::borrow::Cow;
use std::path::PathBuf;

use glam::{DMat3, DVec3};
use limn_load::SceneOptions;
use limn_scene::{shapes, Light, LightKind, Material, Scene, SceneError};

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
    // Cyclic strips.
    let colours = [[0.85, 0.25, 0.2], [0.2, 0.6, 0.3], [0.2, 0.4, 0.85]];
    let strips = s.add_object("cyclic strips");
    let (r, len, h, w) = (1.0, 2.4, 0.45, 0.55);
    let centre = DVec3::new(-3.6, 0.0, 0.0);
    for (k, c) in colours.iter().enumerate() {
        let m = s.add_material(Material::unlit(&format!("strip{k}"), *c));
        let th = k as f64 * std::f64::consts::TAU / 3.0 + 0.3;
        let d = DVec3::new(th.cos(), th.sin(), 0.0);
        let n = DVec3::new(th.sin(), -th.cos(), 0.0);
        let at = |t: f64, side: f64| {
            centre + n * r + d * t + n * (side * w / 2.0) + DVec3::new(0.0, 0.0, -h * t / len)
        };
        s.add_polygon(
            &[at(-len, -1.0), at(len, -1.0), at(len, 1.0), at(-len, 1.0)],
            m,
            strips,
        )?;
    }
    // Interpenetrating boxes.
    let red = s.add_material(Material::diffuse("red box", [0.9, 0.3, 0.25]));
    let blue = s.add_material(Material::diffuse("blue box", [0.25, 0.45, 0.9]));
    let a = s.add_object("box A");
    shapes::cuboid(
        &mut s,
        DVec3::new(-1.0, -1.0, -1.0),
        DVec3::new(0.6, 0.6, 0.6),
        DMat3::IDENTITY,
        red,
        a,
    )?;
    let b = s.add_object("box B");
    let rot = DMat3::from_rotation_y(0.6) * DMat3::from_rotation_x(0.45);
    shapes::cuboid(
        &mut s,
        DVec3::new(-0.4, -0.5, -0.4),
        DVec3::new(1.0, 0.9, 1.0),
        rot,
        blue,
        b,
    )?;
    // Shaded sphere.
    let gold = s.add_material(Material::glossy(
        "sphere",
        [0.85, 0.65, 0.25],
        [0.6, 0.6, 0.6],
        40.0,
    ));
    let sphere = s.add_object("sphere");
    shapes::icosphere(&mut s, DVec3::new(3.4, 0.0, 0.0), 1.2, 3, gold, sphere)?;
    s.lights = vec![
        Light {
            kind: LightKind::Directional(DVec3::new(0.6, 1.0, 0.9)),
            color: [0.9, 0.9, 0.9],
            shadows: false,
        },
        Light {
            kind: LightKind::Ambient,
            color: [1.0, 1.0, 1.0],
            shadows: false,
        },
    ];
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
        assert_eq!(s.faces.len(), 3 + 12 + 1280);
    }
}
