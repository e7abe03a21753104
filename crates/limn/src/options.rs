//! Every option of a render and a check, by name, with the command's defaults. An option
//! left `None` falls back to the scene file's setting, then to the default.

use std::path::PathBuf;

use limn_depthsort::{Arith, CullMode, SortMode};
use limn_paint::Format;
use limn_scene::Shading;

use crate::error::Error;
use crate::values;

/// The default seam width in pixels (`--seams`): 1 px (a pixel the shared edge crosses
/// reaches up to √2 px beyond it: flaps of 0.5 px left 0.5 % of a shaded sphere's pixels
/// 12 levels or more too light in Chromium, flaps of 1 px 0.2 %, as wider ones).
pub const DEFAULT_SEAMS: f64 = 1.0;
/// The default shading tolerance per colour channel (`--shading-tolerance`): one 8-bit
/// step.
pub const DEFAULT_SHADING_TOLERANCE: f64 = 1.0 / 255.0;

/// Samples per pixel, each way, of the page image textured faces are drawn from in SVG
/// and PDF.
pub const DEFAULT_TEXTURE_SAMPLES: f64 = limn_paint::DEFAULT_TEXTURE_SAMPLES;
/// The default shadow-map size of the image-space methods (`--shadow-map-size`).
pub const DEFAULT_SHADOW_MAP_SIZE: u32 = 2048;
/// The default shadow-map depth bias (`--shadow-bias`).
pub const DEFAULT_SHADOW_BIAS: f64 = 1e-3;
/// The default crease angle of hidden-line drawings in degrees (`--crease`).
pub const DEFAULT_CREASE: f64 = 30.0;
/// The default picture size in pixels (`--size`).
pub const DEFAULT_SIZE: (u32, u32) = (800, 600);

/// How to look at the scene and how to order it: what `render` and `check` share.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ViewOptions {
    /// Picture size in pixels.
    pub size: Option<(u32, u32)>,
    /// Eye position.
    pub eye: Option<[f64; 3]>,
    /// Point looked at.
    pub target: Option<[f64; 3]>,
    /// Up direction.
    pub up: Option<[f64; 3]>,
    /// Vertical field of view in degrees.
    pub fov: Option<f64>,
    /// Orthographic projection: `Some(Some(h))` shows `h` world units vertically,
    /// `Some(None)` frames the scene.
    pub ortho: Option<Option<f64>>,
    /// Visibility ordering.
    pub sort: Option<SortMode>,
    /// Arithmetic of the geometric decisions.
    pub arith: Option<Arith>,
    /// Back-face culling.
    pub cull: Option<CullMode>,
    /// Distance of the near clipping plane from the eye.
    pub near: Option<f64>,
    /// Distance of the far clipping plane from the eye.
    pub far: Option<f64>,
    /// Most fragments the ordering may make before giving up.
    pub max_fragments: Option<usize>,
    /// Follow references (material libraries, buffers, textures, meshes) outside the
    /// input's folder.
    pub allow_outside: bool,
    /// Interpolation across lit faces with vertex normals.
    pub shading: Option<Shading>,
    /// A view-projection matrix (world to OpenGL clip coordinates, column-major) that
    /// replaces the scene's camera, the eye, target, up, field of view and projection.
    pub matrix: Option<[f64; 16]>,
    /// The visible map: every fragment split exactly along what hides it from the eye,
    /// the hidden parts left out of the picture (also when the scene file says
    /// `visible = true`).
    pub visible: bool,
}

/// How to compute the picture.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum Method {
    /// Painter's order of exact fragments: a vector picture (the default).
    #[default]
    Painter,
    /// Z-buffer.
    ZBuffer,
    /// Scan-line z-buffer.
    ScanLine,
    /// A-buffer (transparency).
    ABuffer,
    /// Warnock area subdivision.
    Warnock,
    /// Exact ray casting at pixel centres.
    RayCast,
}

impl Method {
    /// Every method.
    pub const ALL: [Method; 6] = [
        Method::Painter,
        Method::ZBuffer,
        Method::ScanLine,
        Method::ABuffer,
        Method::Warnock,
        Method::RayCast,
    ];

    /// The method's name.
    pub fn name(self) -> &'static str {
        match self {
            Method::Painter => "painter",
            Method::ZBuffer => "zbuffer",
            Method::ScanLine => "scanline",
            Method::ABuffer => "abuffer",
            Method::Warnock => "warnock",
            Method::RayCast => "raycast",
        }
    }

    /// The method of a name.
    pub fn from_name(s: &str) -> Option<Method> {
        Method::ALL.into_iter().find(|m| m.name() == s)
    }

    /// The image-space method, or `None` for the painter.
    pub fn raster(self) -> Option<limn_zbuffer::Method> {
        match self {
            Method::Painter => None,
            Method::ZBuffer => Some(limn_zbuffer::Method::ZBuffer),
            Method::ScanLine => Some(limn_zbuffer::Method::ScanLine),
            Method::ABuffer => Some(limn_zbuffer::Method::ABuffer),
            Method::Warnock => Some(limn_zbuffer::Method::Warnock),
            Method::RayCast => Some(limn_zbuffer::Method::RayCast),
        }
    }
}

/// What the picture shows of the faces.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum Look {
    /// Filled faces (the default).
    #[default]
    Filled,
    /// Silhouettes, creases and boundaries of the faces as lines, hidden exactly.
    HiddenLine,
}

impl Look {
    /// Every look.
    pub const ALL: [Look; 2] = [Look::Filled, Look::HiddenLine];

    /// The look's name (`--style`).
    pub fn name(self) -> &'static str {
        match self {
            Look::Filled => "filled",
            Look::HiddenLine => "hidden-line",
        }
    }

    /// The look of a name.
    pub fn from_name(s: &str) -> Option<Look> {
        Look::ALL.into_iter().find(|l| l.name() == s)
    }
}

/// A background: none (transparent), or an RGB colour with channels in 0..1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Background {
    /// No background.
    None,
    /// A colour.
    Colour([f64; 3]),
}

/// Every option of `limn render`.
#[derive(Debug, Clone, PartialEq)]
pub struct RenderOptions {
    /// Camera and ordering.
    pub view: ViewOptions,
    /// Output format [default: the output's extension, else the scene file's, else SVG].
    pub format: Option<Format>,
    /// Stroke every model edge.
    pub outline: bool,
    /// Width in pixels of the seam flaps that close hairline gaps between adjacent
    /// fragments (0 to 10; 0 draws none).
    pub seams: f64,
    /// Background.
    pub background: Option<Background>,
    /// Largest difference per colour channel between the painted picture and per-point
    /// shading where the format cannot interpolate exactly.
    pub shading_tolerance: f64,
    /// SVG and PDF: samples per pixel, each way, of the one image of the page that
    /// opaque textured faces are drawn from (0 to 16; 0 draws each face's texture under
    /// its own maps instead; see `limn_paint::draw_from_page_image`).
    pub texture_samples: f64,
    /// How to compute the picture.
    pub method: Method,
    /// Shadow-map size of the image-space methods.
    pub shadow_map_size: u32,
    /// Shadow-map depth bias of the image-space methods.
    pub shadow_bias: f64,
    /// A TikZ file that compiles on its own.
    pub standalone: bool,
    /// Filled or hidden-line.
    pub style: Option<Look>,
    /// Hidden-line drawings: the angle between faces above which their shared edge is
    /// drawn, in degrees.
    pub crease: Option<f64>,
    /// Hidden-line drawings: draw hidden lines dashed (else leave them out).
    pub dashed: Option<bool>,
    /// Hidden-line drawings: fill faces with the background (else draw lines only).
    pub fill: Option<bool>,
    /// Where to write the statistics as JSON (`-` for standard output).
    pub stats: Option<PathBuf>,
}

impl Default for RenderOptions {
    fn default() -> Self {
        RenderOptions {
            view: ViewOptions::default(),
            format: None,
            outline: false,
            seams: DEFAULT_SEAMS,
            background: None,
            shading_tolerance: DEFAULT_SHADING_TOLERANCE,
            texture_samples: DEFAULT_TEXTURE_SAMPLES,
            method: Method::Painter,
            shadow_map_size: DEFAULT_SHADOW_MAP_SIZE,
            shadow_bias: DEFAULT_SHADOW_BIAS,
            standalone: false,
            style: None,
            crease: None,
            dashed: None,
            fill: None,
            stats: None,
        }
    }
}

/// A range check's verdict as an option error.
fn v<T>(r: Result<T, String>) -> Result<(), Error> {
    r.map(|_| ()).map_err(Error::Value)
}

impl ViewOptions {
    /// Checks every value's range (the command's parser checks them as it reads them).
    pub fn validate(&self) -> Result<(), Error> {
        if let Some((w, h)) = self.size {
            v(values::size(w, h))?;
        }
        for p in [self.eye, self.target, self.up].into_iter().flatten() {
            v(values::vec3(p))?;
        }
        if let Some(f) = self.fov {
            v(values::fov(f))?;
        }
        for d in [self.ortho.flatten(), self.near, self.far]
            .into_iter()
            .flatten()
        {
            v(values::distance(d))?;
        }
        if let Some(m) = self.matrix {
            if m.iter().any(|x| !x.is_finite()) {
                return Err(Error::Value(
                    "the view-projection matrix is not finite".into(),
                ));
            }
        }
        Ok(())
    }
}

impl RenderOptions {
    /// Checks every value's range (the command's parser checks them as it reads them).
    pub fn validate(&self) -> Result<(), Error> {
        self.view.validate()?;
        v(values::seams(self.seams))?;
        v(values::tolerance(self.shading_tolerance))?;
        v(values::texture_samples(self.texture_samples))?;
        v(values::shadow_map_size(self.shadow_map_size))?;
        v(values::bias(self.shadow_bias))?;
        if let Some(Background::Colour(c)) = self.background {
            v(values::colour(c))?;
        }
        if let Some(c) = self.crease {
            v(values::crease(c))?;
        }
        if self.method != Method::Painter && (self.stats.is_some() || self.outline) {
            return Err(Error::Conflict(
                "--stats and --outline apply to the painter only, not to --method".into(),
            ));
        }
        Ok(())
    }
}

/// The image-space references `limn check` compares with.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum Against {
    /// Exact ray casting at pixel centres (the default).
    #[default]
    RayCast,
    /// Z-buffer.
    ZBuffer,
    /// Warnock area subdivision.
    Warnock,
    /// Scan-line z-buffer.
    ScanLine,
}

impl Against {
    /// Every reference.
    pub const ALL: [Against; 4] = [
        Against::ZBuffer,
        Against::RayCast,
        Against::Warnock,
        Against::ScanLine,
    ];

    /// The image-space method.
    pub fn method(self) -> limn_zbuffer::Method {
        match self {
            Against::RayCast => limn_zbuffer::Method::RayCast,
            Against::ZBuffer => limn_zbuffer::Method::ZBuffer,
            Against::Warnock => limn_zbuffer::Method::Warnock,
            Against::ScanLine => limn_zbuffer::Method::ScanLine,
        }
    }

    /// The reference's name.
    pub fn name(self) -> &'static str {
        self.method().name()
    }

    /// The reference of a name.
    pub fn from_name(s: &str) -> Option<Against> {
        Against::ALL.into_iter().find(|a| a.name() == s)
    }
}

/// Every option of `limn check`.
#[derive(Debug, Clone, PartialEq)]
pub struct CheckOptions {
    /// Camera and ordering.
    pub view: ViewOptions,
    /// The reference.
    pub against: Against,
    /// Where to write a PNG of the disagreeing pixels.
    pub diff: Option<PathBuf>,
    /// Seam width of the picture compared, as in [`RenderOptions::seams`].
    pub seams: f64,
    /// Where to write the report as JSON (`-` for standard output).
    pub stats: Option<PathBuf>,
}

impl Default for CheckOptions {
    fn default() -> Self {
        CheckOptions {
            view: ViewOptions::default(),
            against: Against::RayCast,
            diff: None,
            seams: DEFAULT_SEAMS,
            stats: None,
        }
    }
}
