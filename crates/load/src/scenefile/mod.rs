//! limn's scene files (TOML): meshes with transforms and material overrides, the
//! camera, lights and output options, so that a figure is reproduced from one file.
//!
//! ```toml
//! [camera]                  # optional; without `eye` the camera frames the scene
//! eye = [3.0, 2.0, 5.0]
//! target = [0.0, 0.0, 0.0]  # default: the centre of the scene's bounds
//! up = [0.0, 1.0, 0.0]      # default +Y
//! fov = 45.0                # vertical, degrees
//! near = 0.1                # default: chosen from the scene's bounds
//! far = 100.0
//!
//! [output]                  # every key optional
//! size = "800x600"          # or [800, 600]
//! background = "#ffffff"    # or [1.0, 1.0, 1.0]
//! outline = true
//! outline_color = [0.0, 0.0, 0.0]
//! outline_width = 0.5
//! format = "svg"            # svg | pdf | eps | png
//! sort = "adaptive"         # adaptive | bsp | newell | simple
//! arith = "exact"           # exact | float
//! cull = "auto"             # auto | on | off
//! style = "hidden-line"     # filled (default) | hidden-line: silhouettes, boundaries,
//! crease = 30.0             #   creases above this angle, exactly where visible
//! hidden = "dashed"         # omit (default) | dashed
//! fill = "none"             # background (default) | none: lines only, joined
//! visible = true            # the visible map: hidden parts left out (default false)
//! shading = "phong"         # flat | gouraud | phong (default: gouraud where there
//!                           # are vertex normals, see limn_scene::Shading)
//!
//! [fog]                     # optional depth cueing (lit materials only)
//! color = [1.0, 1.0, 1.0]   # default white
//! start = 2.0               # distance from the eye where fog begins (default 0)
//! end = 10.0                # linear fog: full fog from here on
//! # mode = "exponential"    # linear (default) | exponential: exp(-density·(d - start))
//! # density = 0.3           # exponential only, instead of end
//!
//! [[mesh]]
//! path = "bunny.obj"        # relative to this file; obj, stl, ply, gltf, glb
//! name = "bunny"            # renames the mesh's object (prefixes several)
//! translate = [0.0, -0.1, 0.0]
//! rotate = [0.0, 90.0, 0.0] # degrees about x, then y, then z
//! # rotate = { axis = [0.0, 1.0, 0.0], angle = 90.0 }
//! scale = 10.0              # or [sx, sy, sz]
//! material = { kd = "#c04030", illum = 1, opacity = 1.0 }
//!
//! [[light]]
//! kind = "directional"      # directional | point | ambient | headlight
//! direction = [1.0, 1.0, 1.0]  # towards the light (point lights: position)
//! color = [1.0, 1.0, 1.0]
//! intensity = 0.8           # multiplies color
//! shadows = true            # cast shadows (directional and point lights; default false)
//!
//! [[line]]                  # a polyline drawn where visible
//! points = [[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]]  # or path = "curve.obj" (only `l`s)
//! color = "#c04030"         # default black; opacity = 1.0
//! width = 1.5               # pixels, default 1
//! dash = [4.0, 2.0]         # pixels: dash, gap, ...; default solid
//! head = true               # an arrow head at the last point
//! name = "trajectory"
//!
//! [[points]]                # markers drawn whole where their point is visible
//! positions = [[0.0, 1.0, 0.0], [1.0, 0.0, 0.0]]
//! marker = "circle"         # dot | circle | square | triangle | cross | plus
//! size = 6.0                # pixels, default 4
//! color = [0.0, 0.0, 1.0]
//!
//! [[label]]                 # text shown when its anchor is visible
//! at = [1.0, 0.0, 0.0]
//! text = "x"
//! size = 10.0               # points (= pixels), default 10
//! anchor = "south west"     # the box point put at the anchor (TikZ names)
//! offset = [2.0, -2.0]      # pixels, y down
//! ```
//!
//! A mesh is placed by `translate · rotate · scale` (scale first). The `material` table
//! overrides the given fields (`name`, `kd` (alias `color`), `ka`, `ks`, `ns`,
//! `opacity`, `illum`) in every material of that mesh. Mesh paths that leave the scene
//! file's folder are refused unless [`LoadOptions::allow_outside`]; a scene file cannot
//! include another one. Unknown keys are errors.

mod doc;
mod effects;
mod marks;
mod settings;

use std::ops::Range;
use std::path::Path;

use glam::{DMat4, DQuat, DVec3};
use toml::Spanned;

use self::doc::{ColourDoc, Doc, MeshDoc, RotateDoc, ScaleDoc, V3};
use super::{refs, transform, Format, LoadError, LoadOptions, Location};
use limn_scene::Scene;

/// The output part of a scene file, for the command that renders it. `None` means the
/// file does not say (the renderer's default applies). The enumerated settings are
/// checked against their allowed spellings and kept as those strings.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SceneOptions {
    /// Picture size in pixels (width, height), each 1 to 65536.
    pub size: Option<(u32, u32)>,
    /// Background colour, each channel in [0, 1].
    pub background: Option<[f64; 3]>,
    /// Draw outlines along the model's edges.
    pub outline: Option<bool>,
    /// Outline colour.
    pub outline_color: Option<[f64; 3]>,
    /// Outline width in pixels (> 0).
    pub outline_width: Option<f64>,
    /// Output format: `svg`, `pdf`, `eps` or `png`.
    pub format: Option<String>,
    /// Visibility ordering: `adaptive`, `bsp`, `newell` or `simple`.
    pub sort: Option<String>,
    /// Arithmetic: `exact` or `float`.
    pub arith: Option<String>,
    /// Back-face culling: `auto`, `on` or `off`.
    pub cull: Option<String>,
    /// Picture style: `filled` or `hidden-line`.
    pub style: Option<String>,
    /// Crease angle in degrees (0 to 180) of hidden-line drawings.
    pub crease: Option<f64>,
    /// Hidden edges of hidden-line drawings: `omit` or `dashed`.
    pub hidden: Option<String>,
    /// Faces of hidden-line drawings: `background` or `none`.
    pub fill: Option<String>,
    /// Draw only the visible map: each fragment's hidden parts left out.
    pub visible: Option<bool>,
}

/// Loads a scene file: its meshes (placed and with their material overrides), lights,
/// camera (`scene.camera`, when the file has a `[camera]` table) and output options.
pub fn load_scene_file(
    path: &Path,
    opts: &LoadOptions,
) -> Result<(Scene, SceneOptions), LoadError> {
    let bytes = refs::read(path)?;
    if bytes.is_empty() {
        return Err(LoadError::Empty {
            at: Location::file(path),
        });
    }
    let (mut scene, options) = parse(&bytes, path, opts)?;
    scene.files.insert(0, path.to_path_buf());
    let scene = super::checked(scene, path)?;
    Ok((scene, options))
}

/// The scene file being read: its path and text, for locating values.
struct Ctx<'a> {
    path: &'a Path,
    src: &'a str,
}

impl Ctx<'_> {
    fn line(&self, span: Range<usize>) -> Location {
        let end = span.start.min(self.src.len());
        let line = self.src.as_bytes()[..end]
            .iter()
            .filter(|&&b| b == b'\n')
            .count();
        Location::line(self.path, line as u64 + 1)
    }

    fn invalid(&self, span: Range<usize>, message: impl Into<String>) -> LoadError {
        LoadError::Invalid {
            at: self.line(span),
            message: message.into(),
        }
    }

    fn finite3(&self, v: &V3, what: &str) -> Result<DVec3, LoadError> {
        let p = DVec3::from(*v.get_ref());
        if !p.is_finite() {
            return Err(LoadError::NonFinite {
                at: self.line(v.span()),
                what: what.into(),
            });
        }
        Ok(p)
    }

    fn colour(&self, c: &Spanned<ColourDoc>, max: f64) -> Result<[f64; 3], LoadError> {
        let rgb = match c.get_ref() {
            ColourDoc::Rgb(rgb) => *rgb,
            ColourDoc::Hex(s) => parse_hex(s)
                .ok_or_else(|| self.invalid(c.span(), format!("{s:?} is not a #rrggbb colour")))?,
        };
        if rgb.iter().any(|v| !(0.0..=max).contains(v)) {
            return Err(self.invalid(
                c.span(),
                format!("colour channels must be between 0 and {max}"),
            ));
        }
        Ok(rgb)
    }
}

fn parse_hex(s: &str) -> Option<[f64; 3]> {
    let h = s.strip_prefix('#')?;
    if h.len() != 6 || !h.is_ascii() {
        return None;
    }
    let ch = |i: usize| {
        u8::from_str_radix(&h[i..i + 2], 16)
            .ok()
            .map(|v| v as f64 / 255.0)
    };
    Some([ch(0)?, ch(2)?, ch(4)?])
}

/// Parses scene-file bytes; meshes are looked up beside `path`.
pub(crate) fn parse(
    bytes: &[u8],
    path: &Path,
    opts: &LoadOptions,
) -> Result<(Scene, SceneOptions), LoadError> {
    let src = std::str::from_utf8(bytes).map_err(|e| {
        let line = bytes[..e.valid_up_to()]
            .iter()
            .filter(|&&b| b == b'\n')
            .count() as u64
            + 1;
        LoadError::syntax(path, line, "not UTF-8 text")
    })?;
    let cx = Ctx { path, src };
    let doc: Doc = toml::from_str(src).map_err(|e| LoadError::Syntax {
        at: match e.span() {
            Some(s) => cx.line(s),
            None => Location::file(path),
        },
        message: e.message().trim_end().to_string(),
    })?;
    let mut scene = Scene::default();
    for mesh in &doc.mesh {
        let sub = load_mesh(&cx, mesh.get_ref(), opts)?;
        scene.append(&sub);
    }
    if doc.mesh.is_empty() && doc.line.is_empty() && doc.points.is_empty() {
        scene
            .warnings
            .push(format!("{}: no [[mesh]]", path.display()));
    }
    for l in &doc.light {
        scene.lights.push(settings::light(&cx, l)?);
    }
    marks::add(&cx, &doc.line, &doc.points, &doc.label, &mut scene, opts)?;
    let options = settings::options(&cx, &doc)?;
    scene.shading = doc
        .output
        .as_ref()
        .and_then(|o| o.shading)
        .map(effects::shading);
    if let Some(f) = &doc.fog {
        scene.fog = Some(effects::fog(&cx, f)?);
    }
    if let Some(cam) = &doc.camera {
        let size = options.size.unwrap_or((800, 600));
        scene.camera = Some(settings::camera(&cx, cam, &scene, size)?);
    }
    Ok((scene, options))
}

fn load_mesh(cx: &Ctx, m: &MeshDoc, opts: &LoadOptions) -> Result<Scene, LoadError> {
    let at = cx.line(m.path.span());
    let reference = m.path.get_ref();
    if Format::from_path(Path::new(reference)) == Some(Format::Toml) {
        return Err(LoadError::Unsupported {
            at,
            what: "a scene file naming another scene file".into(),
        });
    }
    let file = refs::resolve(reference, &at, opts)?;
    let mut sub = super::load(&file, opts).map_err(|e| LoadError::InMesh {
        at: at.clone(),
        source: Box::new(e),
    })?;
    let mut matrix = DMat4::IDENTITY;
    if let Some(t) = &m.translate {
        matrix = DMat4::from_translation(cx.finite3(t, "translation")?);
    }
    if let Some(r) = &m.rotate {
        matrix *= DMat4::from_quat(rotation(cx, r)?);
    }
    if let Some(s) = &m.scale {
        let v = match s.get_ref() {
            ScaleDoc::Uniform(k) => DVec3::splat(*k),
            ScaleDoc::PerAxis(a) => DVec3::from(*a),
        };
        if !v.is_finite() || v.x * v.y * v.z == 0.0 {
            return Err(cx.invalid(s.span(), "scale factors must be finite and non-zero"));
        }
        matrix *= DMat4::from_scale(v);
    }
    transform::apply(&mut sub, &matrix, 0, 0, 0);
    transform::apply_to_marks(&mut sub, &matrix);
    if !transform::vertices_finite(&sub, 0) || !transform::marks_finite(&sub) {
        return Err(LoadError::NonFinite {
            at,
            what: "vertex after the mesh's transform".into(),
        });
    }
    if let Some(mat) = &m.material {
        override_materials(cx, mat, &mut sub)?;
    }
    if let Some(name) = &m.name {
        let single = sub.objects.len() == 1;
        for o in &mut sub.objects {
            o.name = if single {
                name.clone()
            } else {
                format!("{name}/{}", o.name)
            };
        }
    }
    Ok(sub)
}

fn rotation(cx: &Ctx, r: &Spanned<RotateDoc>) -> Result<DQuat, LoadError> {
    let q = match r.get_ref() {
        RotateDoc::Euler([x, y, z]) => {
            DQuat::from_rotation_z(z.to_radians())
                * DQuat::from_rotation_y(y.to_radians())
                * DQuat::from_rotation_x(x.to_radians())
        }
        RotateDoc::AxisAngle(a) => {
            let axis = DVec3::from(a.axis);
            if axis.length_squared() == 0.0 || !axis.is_finite() {
                return Err(cx.invalid(r.span(), "the rotation axis must be finite and non-zero"));
            }
            DQuat::from_axis_angle(axis.normalize(), a.angle.to_radians())
        }
    };
    if !q.is_finite() {
        return Err(LoadError::NonFinite {
            at: cx.line(r.span()),
            what: "rotation".into(),
        });
    }
    Ok(q)
}

fn override_materials(
    cx: &Ctx,
    mat: &Spanned<doc::MaterialDoc>,
    sub: &mut Scene,
) -> Result<(), LoadError> {
    let d = mat.get_ref();
    let kd = d.kd.as_ref().map(|c| cx.colour(c, 1.0)).transpose()?;
    let ka = d.ka.as_ref().map(|c| cx.colour(c, 1.0)).transpose()?;
    let ks = d.ks.as_ref().map(|c| cx.colour(c, 1.0)).transpose()?;
    if d.ns.is_some_and(|v| !(v.is_finite() && v >= 0.0)) {
        return Err(cx.invalid(mat.span(), "ns must be a finite number >= 0"));
    }
    if d.opacity.is_some_and(|v| !(0.0..=1.0).contains(&v)) {
        return Err(cx.invalid(mat.span(), "opacity must be between 0 and 1"));
    }
    if d.illum.is_some_and(|v| v > 10) {
        return Err(cx.invalid(mat.span(), "illum must be a model number 0..10"));
    }
    for m in &mut sub.materials {
        if let Some(n) = &d.name {
            m.name = n.clone();
        }
        if let Some(c) = kd {
            m.kd = c;
        }
        if let Some(c) = ka {
            m.ka = c;
        }
        if let Some(c) = ks {
            m.ks = c;
        }
        if let Some(v) = d.ns {
            m.ns = v;
        }
        if let Some(v) = d.opacity {
            m.opacity = v;
        }
        if let Some(v) = d.illum {
            m.illum = v;
        }
    }
    Ok(())
}
