//! The serde shape of a scene file. Every table refuses unknown keys.

use serde::Deserialize;
use toml::Spanned;

/// Three numbers with their place in the file.
pub(crate) type V3 = Spanned<[f64; 3]>;

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct Doc {
    pub(crate) camera: Option<Spanned<CameraDoc>>,
    pub(crate) output: Option<OutputDoc>,
    #[serde(default)]
    pub(crate) mesh: Vec<Spanned<MeshDoc>>,
    #[serde(default)]
    pub(crate) light: Vec<Spanned<LightDoc>>,
    #[serde(default)]
    pub(crate) line: Vec<Spanned<LineDoc>>,
    #[serde(default)]
    pub(crate) points: Vec<Spanned<PointsDoc>>,
    #[serde(default)]
    pub(crate) label: Vec<Spanned<LabelDoc>>,
    pub(crate) fog: Option<Spanned<FogDoc>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct CameraDoc {
    pub(crate) eye: Option<V3>,
    pub(crate) target: Option<V3>,
    pub(crate) up: Option<V3>,
    pub(crate) fov: Option<f64>,
    /// `"perspective"` (the default) or `"orthographic"`.
    pub(crate) projection: Option<ProjectionDoc>,
    /// The orthographic view height in world units (default: framing the scene).
    pub(crate) height: Option<f64>,
    pub(crate) near: Option<f64>,
    pub(crate) far: Option<f64>,
}

#[derive(Deserialize, Clone, Copy, PartialEq)]
#[serde(rename_all = "lowercase")]
pub(crate) enum ProjectionDoc {
    Perspective,
    Orthographic,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct OutputDoc {
    pub(crate) size: Option<Spanned<SizeDoc>>,
    pub(crate) background: Option<Spanned<ColourDoc>>,
    pub(crate) outline: Option<bool>,
    pub(crate) outline_color: Option<Spanned<ColourDoc>>,
    pub(crate) outline_width: Option<Spanned<f64>>,
    pub(crate) format: Option<FormatDoc>,
    pub(crate) sort: Option<SortDoc>,
    pub(crate) arith: Option<ArithDoc>,
    pub(crate) cull: Option<CullDoc>,
    pub(crate) shading: Option<ShadingDoc>,
    pub(crate) style: Option<StyleDoc>,
    pub(crate) crease: Option<Spanned<f64>>,
    pub(crate) hidden: Option<HiddenDoc>,
    pub(crate) fill: Option<FillDoc>,
    pub(crate) visible: Option<bool>,
}

#[derive(Deserialize, Clone, Copy, Debug)]
#[serde(rename_all = "kebab-case")]
pub(crate) enum StyleDoc {
    Filled,
    HiddenLine,
}

#[derive(Deserialize, Clone, Copy, Debug)]
#[serde(rename_all = "lowercase")]
pub(crate) enum HiddenDoc {
    Omit,
    Dashed,
}

#[derive(Deserialize, Clone, Copy, Debug)]
#[serde(rename_all = "lowercase")]
pub(crate) enum FillDoc {
    Background,
    None,
}

#[derive(Deserialize, Clone, Copy, Debug)]
#[serde(rename_all = "lowercase")]
pub(crate) enum ShadingDoc {
    Flat,
    Gouraud,
    Phong,
}

#[derive(Deserialize, Clone, Copy, Debug, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub(crate) enum FogModeDoc {
    Linear,
    Exponential,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct FogDoc {
    #[serde(alias = "colour")]
    pub(crate) color: Option<Spanned<ColourDoc>>,
    pub(crate) start: Option<f64>,
    pub(crate) end: Option<f64>,
    pub(crate) mode: Option<FogModeDoc>,
    pub(crate) density: Option<f64>,
}

#[derive(Deserialize)]
#[serde(untagged, expecting = "expected a size: [width, height] or \"WxH\"")]
pub(crate) enum SizeDoc {
    Pair([u32; 2]),
    Text(String),
}

#[derive(Deserialize)]
#[serde(
    untagged,
    expecting = "expected a colour: [r, g, b] (each 0 to 1) or \"#rrggbb\""
)]
pub(crate) enum ColourDoc {
    Rgb([f64; 3]),
    Hex(String),
}

#[derive(Deserialize, Clone, Copy, Debug)]
#[serde(rename_all = "lowercase")]
pub(crate) enum FormatDoc {
    Svg,
    Pdf,
    Eps,
    Png,
}

#[derive(Deserialize, Clone, Copy, Debug)]
#[serde(rename_all = "lowercase")]
pub(crate) enum SortDoc {
    Adaptive,
    Bsp,
    Newell,
    Simple,
}

#[derive(Deserialize, Clone, Copy, Debug)]
#[serde(rename_all = "lowercase")]
pub(crate) enum ArithDoc {
    Exact,
    Float,
}

#[derive(Deserialize, Clone, Copy, Debug)]
#[serde(rename_all = "lowercase")]
pub(crate) enum CullDoc {
    Auto,
    On,
    Off,
}

/// Debug names are the lowercase spellings of the file.
pub(crate) fn lower(v: impl std::fmt::Debug) -> String {
    format!("{v:?}").to_ascii_lowercase()
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct MeshDoc {
    pub(crate) path: Spanned<String>,
    pub(crate) name: Option<String>,
    pub(crate) translate: Option<V3>,
    pub(crate) rotate: Option<Spanned<RotateDoc>>,
    pub(crate) scale: Option<Spanned<ScaleDoc>>,
    pub(crate) material: Option<Spanned<MaterialDoc>>,
}

#[derive(Deserialize)]
#[serde(
    untagged,
    expecting = "expected a rotation: [x, y, z] degrees about the axes, or { axis = [x, y, z], angle = degrees }"
)]
pub(crate) enum RotateDoc {
    Euler([f64; 3]),
    AxisAngle(AxisAngleDoc),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct AxisAngleDoc {
    pub(crate) axis: [f64; 3],
    pub(crate) angle: f64,
}

#[derive(Deserialize)]
#[serde(untagged, expecting = "expected a scale: a number or [x, y, z]")]
pub(crate) enum ScaleDoc {
    Uniform(f64),
    PerAxis([f64; 3]),
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct MaterialDoc {
    pub(crate) name: Option<String>,
    #[serde(alias = "color")]
    pub(crate) kd: Option<Spanned<ColourDoc>>,
    pub(crate) ka: Option<Spanned<ColourDoc>>,
    pub(crate) ks: Option<Spanned<ColourDoc>>,
    pub(crate) ns: Option<f64>,
    pub(crate) opacity: Option<f64>,
    pub(crate) illum: Option<u8>,
}

#[derive(Deserialize, Clone, Copy, PartialEq, Eq, Debug)]
#[serde(rename_all = "lowercase")]
pub(crate) enum LightKindDoc {
    Directional,
    Point,
    Ambient,
    Headlight,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct LightDoc {
    pub(crate) kind: LightKindDoc,
    pub(crate) direction: Option<V3>,
    pub(crate) position: Option<V3>,
    pub(crate) color: Option<Spanned<ColourDoc>>,
    pub(crate) intensity: Option<f64>,
    pub(crate) shadows: Option<Spanned<bool>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct LineDoc {
    pub(crate) points: Option<Spanned<Vec<[f64; 3]>>>,
    pub(crate) path: Option<Spanned<String>>,
    pub(crate) name: Option<String>,
    pub(crate) color: Option<Spanned<ColourDoc>>,
    pub(crate) opacity: Option<Spanned<f64>>,
    pub(crate) width: Option<Spanned<f64>>,
    pub(crate) dash: Option<Spanned<Vec<f64>>>,
    #[serde(default)]
    pub(crate) head: bool,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct PointsDoc {
    pub(crate) positions: Spanned<Vec<[f64; 3]>>,
    pub(crate) name: Option<String>,
    pub(crate) marker: Option<Spanned<String>>,
    pub(crate) size: Option<Spanned<f64>>,
    pub(crate) color: Option<Spanned<ColourDoc>>,
    pub(crate) opacity: Option<Spanned<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct LabelDoc {
    pub(crate) at: V3,
    pub(crate) text: Spanned<String>,
    pub(crate) name: Option<String>,
    pub(crate) size: Option<Spanned<f64>>,
    pub(crate) color: Option<Spanned<ColourDoc>>,
    pub(crate) opacity: Option<Spanned<f64>>,
    pub(crate) anchor: Option<Spanned<String>>,
    pub(crate) offset: Option<Spanned<[f64; 2]>>,
}
