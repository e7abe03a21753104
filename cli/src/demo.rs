//! The built-in demo scene: what limn is for, in one picture.
//!
//! * left: three strips overlapping cyclically (no painter's order of whole faces
//!   exists), drawn with exact unlit colours;
//! * middle: two closed boxes passing through each other, lit;
//! * right: a closed, shaded icosphere with a specular highlight.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use anyhow::Result;
use glam::{DMat3, DVec3};
use limn_depthsort::{order, OrderOptions};
use limn_paint::{painter_for, picture, Format, Outline, Painter, Style, SvgOptions, SvgPainter};
use limn_scene::{shapes, Camera, Light, LightKind, Material, Scene, SceneError};

use crate::args::DemoArgs;
use crate::output::write_atomic;
use crate::setup::format_of;
use crate::stats::{write_stats, Drawn, Timing};

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

/// Runs `limn demo`: the built-in scene, framed, written like `render` writes.
pub fn run(a: DemoArgs) -> Result<ExitCode> {
    let t0 = Instant::now();
    let scene = scene()?;
    let output = a
        .output
        .clone()
        .unwrap_or_else(|| PathBuf::from("demo.svg"));
    let format = format_of(&output, None)?;
    let cam = Camera::framing(&scene, 960, 540)?;
    let t1 = Instant::now();
    let oo = OrderOptions::default();
    let ordered = order(&scene, &cam, &oo)?;
    let t2 = Instant::now();
    let style = Style {
        seamless: true,
        smooth: true,
        background: Some([1.0, 1.0, 1.0, 1.0]),
        outline: a.outline.then_some(Outline {
            color: [0.1, 0.1, 0.1, 1.0],
            width: 1.0,
        }),
        tolerance: DEMO_TOLERANCE,
        ..Style::default()
    };
    let pic = picture(&scene, &ordered, &style);
    let painter: Box<dyn Painter> = match format {
        Format::Svg => Box::new(SvgPainter::new(SvgOptions {
            tolerance: DEMO_TOLERANCE,
            ..SvgOptions::default()
        })),
        _ => painter_for(format),
    };
    let ps = write_atomic(&output, &[], |w| Ok(painter.paint(&pic, w)?))?;
    let t3 = Instant::now();
    let timing = Timing {
        load: (t1 - t0).as_secs_f64() * 1e3,
        order: (t2 - t1).as_secs_f64() * 1e3,
        write: (t3 - t2).as_secs_f64() * 1e3,
        total: t0.elapsed().as_secs_f64() * 1e3,
    };
    write_stats(
        &a.stats,
        &scene,
        &ordered,
        &oo,
        &Drawn {
            paint: &ps,
            marks: &Default::default(),
        },
        &timing,
        &[],
    )?;
    if !a.quiet && output.as_os_str() != "-" {
        eprintln!(
            "limn: wrote {} ({} faces, {} fragments, {} splits)",
            output.display(),
            ordered.stats.faces_in,
            ordered.stats.fragments_out,
            ordered.stats.splits
        );
    }
    Ok(ExitCode::SUCCESS)
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
