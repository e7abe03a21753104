//! The settings of a run, each resolved the same way: the option given, else the scene
//! file's, else the default. The camera, the ordering, the format and output, the
//! hidden-line style and the picture style.

use std::path::{Path, PathBuf};

use glam::DVec3;
use limn_depthsort::{Arith, CullMode, OrderOptions, SortMode};
use limn_load::SceneOptions;
use limn_paint::{Format, HiddenLineStyle, Outline, Style};
use limn_scene::{Camera, Effects, Projection, Scene};

use crate::error::Error;
use crate::input::Input;
use crate::options::{Background, Look, RenderOptions, ViewOptions, DEFAULT_CREASE, DEFAULT_SIZE};

/// The camera: options first, then the scene's camera, then the view the model file
/// suggests (a glTF camera; not when an eye is given), then framing the scene.
///
/// With an eye and no camera in the scene the camera looks at the target or the centre
/// of the scene's bounds; nothing is framed, so a scene too large to frame can still be
/// drawn from a chosen eye. Without an eye the framed camera keeps its direction when
/// the target moves it. Errors name `input`.
pub fn camera(
    scene: &Scene,
    view: &ViewOptions,
    size: Option<(u32, u32)>,
    input: &str,
) -> Result<Camera, Error> {
    let (w, h) = view.size.or(size).unwrap_or(DEFAULT_SIZE);
    let fail = |what: &'static str| {
        move |source| Error::Camera {
            input: input.to_string(),
            what,
            source: Some(source),
        }
    };
    if let Some(m) = view.matrix {
        let mut cam = Camera::from_matrix(glam::DMat4::from_cols_array(&m), w, h)
            .map_err(fail("invalid view-projection matrix"))?;
        if view.near.is_some() {
            cam.near = view.near;
        }
        if view.far.is_some() {
            cam.far = view.far;
        }
        cam.validate().map_err(fail("invalid camera"))?;
        return Ok(cam);
    }
    // A model file's own view gives way to an eye given by the options.
    let given = scene
        .camera
        .or(scene.default_camera.filter(|_| view.eye.is_none()));
    let mut cam = match (given, view.eye) {
        (Some(c), _) => c,
        (None, Some(eye)) => {
            let (lo, hi) = scene.bounds().ok_or_else(|| Error::Camera {
                input: input.to_string(),
                what: "empty scene",
                source: None,
            })?;
            let target = view.target.map_or(lo * 0.5 + hi * 0.5, DVec3::from);
            Camera::new(DVec3::from(eye), target, w, h)
        }
        (None, None) => {
            let frame = fail("cannot frame the scene (try --eye)");
            let mut c = Camera::framing(scene, w, h).map_err(frame)?;
            if let Some(fov) = view.fov {
                // Re-frame for the new field of view, from the same direction.
                let dir = c.eye - c.target;
                c = Camera::framing_scene(scene, dir, fov, w, h).map_err(frame)?;
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
            .map_err(fail("cannot frame the scene orthographically"))?;
        if view.eye.is_none() && given.is_none() {
            // Framed: the eye stands back far enough that nothing is clipped.
            cam.eye = cam.target + (framed.eye - framed.target);
        }
        let height = height.unwrap_or(match framed.projection {
            Projection::Orthographic { height } => height,
            _ => 1.0,
        });
        cam.projection = Projection::Orthographic { height };
    }
    cam.validate().map_err(fail("invalid camera"))?;
    Ok(cam)
}

/// A name of the scene file's, looked up with `from_name`.
fn named<T>(
    given: Option<T>,
    file: &Option<String>,
    what: &'static str,
    from_name: fn(&str) -> Option<T>,
    default: T,
) -> Result<T, Error> {
    match (given, file) {
        (Some(v), _) => Ok(v),
        (None, Some(s)) => from_name(s).ok_or_else(|| Error::UnknownName {
            what,
            name: s.clone(),
            place: " in the scene file".into(),
        }),
        (None, None) => Ok(default),
    }
}

/// The ordering options.
pub fn order_options(view: &ViewOptions, file: &SceneOptions) -> Result<OrderOptions, Error> {
    Ok(OrderOptions {
        sort: named(
            view.sort,
            &file.sort,
            "sort",
            SortMode::from_name,
            SortMode::Adaptive,
        )?,
        arith: named(
            view.arith,
            &file.arith,
            "arith",
            Arith::from_name,
            Arith::Exact,
        )?,
        cull: named(
            view.cull,
            &file.cull,
            "cull",
            CullMode::from_name,
            CullMode::Auto,
        )?,
        max_fragments: view.max_fragments,
        visible: view.visible || file.visible == Some(true),
        ..OrderOptions::default()
    })
}

/// The format of `output`: the option, else its extension (SVG for `-` or none).
/// `flag` names the option in the message (`--format`, `format=`).
pub fn format_of(
    output: &Path,
    given: Option<Format>,
    flag: &'static str,
) -> Result<Format, Error> {
    if let Some(f) = given {
        return Ok(f);
    }
    if output.as_os_str() == "-" {
        return Ok(Format::Svg);
    }
    match output.extension().and_then(|e| e.to_str()) {
        Some(ext) => Format::from_extension(ext).ok_or_else(|| Error::Extension {
            output: output.to_path_buf(),
            ext: ext.to_string(),
            flag,
        }),
        None => Ok(Format::Svg),
    }
}

/// The output and its format: the output given (its format from the option or its
/// extension), else the input beside itself with the option's, the scene file's or
/// SVG's extension.
pub fn output_and_format(
    input: &Input<'_>,
    output: Option<&Path>,
    given: Option<Format>,
    file: &SceneOptions,
) -> Result<(PathBuf, Format), Error> {
    if let Some(out) = output {
        return Ok((out.to_path_buf(), format_of(out, given, "--format")?));
    }
    let Some(path) = input.path() else {
        return Err(Error::Conflict(format!(
            "{}: a scene built in memory needs an output path",
            input.name()
        )));
    };
    let format = match (given, &file.format) {
        (Some(f), _) => f,
        (None, Some(f)) => Format::from_name(f).ok_or_else(|| Error::UnknownName {
            what: "format",
            name: f.clone(),
            place: " in the scene file".into(),
        })?,
        (None, None) => Format::Svg,
    };
    Ok((path.with_extension(format.name()), format))
}

/// The hidden-line style the options and the scene file ask for, or `None` for filled
/// pictures.
pub fn hidden_line_style(o: &RenderOptions, fo: &SceneOptions) -> Option<HiddenLineStyle> {
    let hidden_line = match o.style {
        Some(s) => s == Look::HiddenLine,
        None => fo.style.as_deref() == Some("hidden-line"),
    };
    if !hidden_line {
        return None;
    }
    let c = fo.outline_color.unwrap_or([0.0; 3]);
    Some(HiddenLineStyle {
        color: [c[0], c[1], c[2], 1.0],
        width: fo.outline_width.unwrap_or(1.0),
        dashed: o
            .dashed
            .unwrap_or_else(|| fo.hidden.as_deref() == Some("dashed")),
        fill: o.fill.unwrap_or_else(|| fo.fill.as_deref() != Some("none")),
        crease: o.crease.or(fo.crease).unwrap_or(DEFAULT_CREASE),
    })
}

/// The background, opaque, or `None`.
pub fn background(o: &RenderOptions, fo: &SceneOptions) -> Option<[f64; 4]> {
    match o.background {
        Some(Background::None) => None,
        Some(Background::Colour(c)) => Some([c[0], c[1], c[2], 1.0]),
        None => fo.background.map(|c| [c[0], c[1], c[2], 1.0]),
    }
}

/// The shading tolerance of one approximation: SVG draws Phong in two (Phong to Gouraud
/// triangles, those to gradients and flat pieces), each getting half of it.
pub fn tolerance(o: &RenderOptions, scene: &Scene, format: Format) -> f64 {
    if format == Format::Svg && Effects::of(scene).phong {
        o.shading_tolerance / 2.0
    } else {
        o.shading_tolerance
    }
}

/// The picture style.
pub fn style(
    o: &RenderOptions,
    fo: &SceneOptions,
    background: Option<[f64; 4]>,
    tolerance: f64,
) -> Style {
    Style {
        seamless: true,
        smooth: true,
        tolerance,
        seams: o.seams,
        background,
        outline: (o.outline || fo.outline == Some(true)).then(|| {
            let c = fo.outline_color.unwrap_or([0.1, 0.1, 0.1]);
            Outline {
                color: [c[0], c[1], c[2], 1.0],
                width: fo.outline_width.unwrap_or(1.0),
            }
        }),
    }
}
