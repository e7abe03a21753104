//! Setting up a run from the command line: loading the input, the camera, the ordering
//! options and the output format. Shared by every subcommand; imports none of them.

use std::path::Path;

use anyhow::{bail, Context, Result};
use glam::DVec3;
use limn_depthsort::{Arith, CullMode, OrderError, OrderOptions, SortMode};
use limn_load::{load_scene_file, LoadError, LoadOptions, SceneOptions};
use limn_paint::Format;
use limn_scene::{Camera, Projection, Scene};

use crate::args::ViewArgs;

/// A loaded scene with the options its file gave (all unset for mesh files).
pub struct Loaded {
    /// The scene.
    pub scene: Scene,
    /// Options of a TOML scene file.
    pub opts: SceneOptions,
}

/// Loads INPUT and reports its warnings.
pub fn load(path: &Path, view: &ViewArgs) -> Result<Loaded> {
    let opts = LoadOptions {
        allow_outside: view.allow_outside,
    };
    let is_toml = path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("toml"));
    let mut loaded = if is_toml {
        let (scene, opts) = load_scene_file(path, &opts).map_err(explain)?;
        Loaded { scene, opts }
    } else {
        let scene = limn_load::load(path, &opts).map_err(explain)?;
        Loaded {
            scene,
            opts: SceneOptions::default(),
        }
    };
    if let Some(s) = view.shading {
        loaded.scene.shading = Some(s);
    }
    if !view.quiet {
        for w in &loaded.scene.warnings {
            eprintln!("limn: warning: {w}");
        }
    }
    let s = &loaded.scene;
    if s.faces.is_empty() && s.lines.is_empty() && s.points.is_empty() && s.labels.is_empty() {
        let what = if s.vertices.is_empty() {
            "no faces, lines, points or labels"
        } else {
            "vertices but no faces, lines, points or labels"
        };
        bail!("{}: the scene has {what}", path.display());
    }
    Ok(loaded)
}

/// A loading error, with the flag that lifts a refusal to follow a reference.
fn explain(e: LoadError) -> anyhow::Error {
    if matches!(e.innermost(), LoadError::OutsideFolder { .. }) {
        let text = format!("{e} (with --allow-outside)");
        anyhow::Error::new(e).context(text)
    } else {
        anyhow::Error::new(e)
    }
}

/// The camera: flags first, then the scene file's camera, then framing the scene.
///
/// With `--eye` and no camera in the scene file the camera looks at `--target` or the
/// centre of the scene's bounds; nothing is framed, so a scene too large to frame can
/// still be drawn from a chosen eye. Without `--eye` the framed camera keeps its
/// direction when `--target` moves it. Errors name `input`.
pub fn camera(
    scene: &Scene,
    view: &ViewArgs,
    size: Option<(u32, u32)>,
    input: &Path,
) -> Result<Camera> {
    let (w, h) = view.size.or(size).unwrap_or((800, 600));
    let at = || format!("{}", input.display());
    let mut cam = match (scene.camera, view.eye) {
        (Some(c), _) => c,
        (None, Some(eye)) => {
            let (lo, hi) = scene
                .bounds()
                .with_context(|| format!("{}: empty scene", at()))?;
            let target = view.target.map_or(lo * 0.5 + hi * 0.5, DVec3::from);
            Camera::new(DVec3::from(eye), target, w, h)
        }
        (None, None) => {
            let frame_error = || format!("{}: cannot frame the scene (try --eye)", at());
            let mut c = Camera::framing(scene, w, h).with_context(frame_error)?;
            if let Some(fov) = view.fov {
                // Re-frame for the new field of view, from the same direction.
                let dir = c.eye - c.target;
                c = Camera::framing_scene(scene, dir, fov, w, h).with_context(frame_error)?;
            }
            if let Some(t) = view.target {
                let t = DVec3::from(t);
                c.eye = t + (c.eye - c.target);
                c.target = t;
            }
            c
        }
    };
    cam.width = w;
    cam.height = h;
    if let Some(fov) = view.fov {
        cam.fov_deg = fov;
    }
    if let Some(e) = view.eye {
        cam.eye = DVec3::from(e);
    }
    if let Some(t) = view.target {
        cam.target = DVec3::from(t);
    }
    if let Some(u) = view.up {
        cam.up = DVec3::from(u);
    }
    if view.near.is_some() {
        cam.near = view.near;
    }
    if view.far.is_some() {
        cam.far = view.far;
    }
    if let Some(height) = view.ortho {
        let framed = Camera::framing_orthographic(scene, cam.eye - cam.target, w, h)
            .with_context(|| format!("{}: cannot frame the scene orthographically", at()))?;
        if view.eye.is_none() && scene.camera.is_none() {
            // Framed: the eye stands back far enough that nothing is clipped.
            cam.eye = cam.target + (framed.eye - framed.target);
        }
        let height = height.unwrap_or(match framed.projection {
            Projection::Orthographic { height } => height,
            _ => 1.0,
        });
        cam.projection = Projection::Orthographic { height };
    }
    cam.validate()
        .with_context(|| format!("{}: invalid camera", at()))?;
    Ok(cam)
}

/// The ordering options: flags first, then the scene file's, then the defaults.
pub fn order_options(view: &ViewArgs, file: &SceneOptions) -> Result<OrderOptions> {
    let sort = match view.sort {
        Some(s) => s,
        None => match &file.sort {
            Some(s) => SortMode::from_name(s)
                .with_context(|| format!("unknown sort `{s}` in the scene file"))?,
            None => SortMode::Adaptive,
        },
    };
    let arith = match view.arith {
        Some(a) => a,
        None => match &file.arith {
            Some(s) => Arith::from_name(s)
                .with_context(|| format!("unknown arith `{s}` in the scene file"))?,
            None => Arith::Exact,
        },
    };
    let cull = match view.cull {
        Some(c) => c,
        None => match &file.cull {
            Some(s) => CullMode::from_name(s)
                .with_context(|| format!("unknown cull `{s}` in the scene file"))?,
            None => CullMode::Auto,
        },
    };
    Ok(OrderOptions {
        sort,
        arith,
        cull,
        max_fragments: view.max_fragments,
        ..OrderOptions::default()
    })
}

/// The output format: the flag, else OUTPUT's extension (SVG for `-` or none).
pub fn format_of(output: &Path, flag: Option<Format>) -> Result<Format> {
    if let Some(f) = flag {
        return Ok(f);
    }
    if output.as_os_str() == "-" {
        return Ok(Format::Svg);
    }
    match output.extension().and_then(|e| e.to_str()) {
        Some(ext) => Format::from_extension(ext).with_context(|| {
            format!(
                "{}: unknown output extension `.{ext}` (use .svg, .pdf, .eps, .png, .tikz or --format)",
                output.display()
            )
        }),
        None => Ok(Format::Svg),
    }
}

/// An ordering error, with the flag that lifts a fragment limit.
pub fn explain_order(e: OrderError, input: &Path) -> anyhow::Error {
    let hint = match e {
        OrderError::TooManyFragments { .. } => " (raise --max-fragments to go on)",
        _ => "",
    };
    let text = format!("{}{hint}", input.display());
    anyhow::Error::new(e).context(text)
}
