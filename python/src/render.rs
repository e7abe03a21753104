//! Render and check options from Python keywords to the library's, by the command's
//! names and defaults; the statistics and reports as dicts (the JSON the command writes).

use std::path::PathBuf;

use limn::values::parse_background;
use limn::{
    Against, Arith, Background, CheckOptions, CullMode, Format, Look, Method, RenderOptions,
    SceneOptions, Shading, SortMode, ViewOptions,
};
use pyo3::prelude::*;
use pyo3::types::PyAny;

use crate::errors::value_error;

/// A name the library knows, or a `ValueError` listing the names.
fn named<T: Copy>(what: &str, given: &str, all: &[T], name: fn(T) -> &'static str) -> PyResult<T> {
    all.iter()
        .copied()
        .find(|&v| name(v) == given)
        .ok_or_else(|| {
            let names: Vec<&str> = all.iter().map(|&v| name(v)).collect();
            value_error(format!("unknown {what} `{given}` ({})", names.join(", ")))
        })
}

/// Ordering options by name.
pub(crate) fn order_names(
    view: &mut ViewOptions,
    sort: Option<&str>,
    arith: Option<&str>,
    cull: Option<&str>,
) -> PyResult<()> {
    if let Some(s) = sort {
        view.sort = Some(named("sort", s, &SortMode::ALL, SortMode::name)?);
    }
    if let Some(a) = arith {
        view.arith = Some(named("arith", a, &Arith::ALL, Arith::name)?);
    }
    if let Some(c) = cull {
        view.cull = Some(named("cull", c, &CullMode::ALL, CullMode::name)?);
    }
    Ok(())
}

/// A background: `None`, `"none"`, `"#rrggbb"`, `"r,g,b"` or an `(r, g, b)` sequence.
fn background(b: &Bound<'_, PyAny>) -> PyResult<Background> {
    if let Ok(s) = b.extract::<String>() {
        return parse_background(&s).map_err(value_error);
    }
    let (r, g, bl): (f64, f64, f64) = b
        .extract()
        .map_err(|_| value_error("background must be (r, g, b), \"#rrggbb\" or \"none\""))?;
    Ok(Background::Colour([r, g, bl]))
}

/// Every keyword of `Scene.render`, as the command's flags.
#[derive(Default)]
pub(crate) struct RenderKeywords<'a, 'py> {
    pub format: Option<&'a str>,
    pub sort: Option<&'a str>,
    pub arith: Option<&'a str>,
    pub cull: Option<&'a str>,
    pub outline: bool,
    pub outline_color: Option<(f64, f64, f64)>,
    pub outline_width: Option<f64>,
    pub background: Option<&'a Bound<'py, PyAny>>,
    pub style: Option<&'a str>,
    pub hidden: Option<&'a str>,
    pub fill: Option<&'a str>,
    pub crease: Option<f64>,
    pub seams: f64,
    pub shading: Option<&'a str>,
    pub shading_tolerance: f64,
    pub texture_samples: f64,
    pub method: &'a str,
    pub shadow_map_size: u32,
    pub shadow_bias: f64,
    pub standalone: bool,
    pub max_fragments: Option<usize>,
    pub visible: bool,
    pub near: Option<f64>,
    pub far: Option<f64>,
    pub stats: Option<PathBuf>,
}

impl RenderKeywords<'_, '_> {
    /// The library's options for a scene viewed with `view`, and the scene-file settings
    /// the outline colour and width override.
    pub(crate) fn options(
        &self,
        view: &ViewOptions,
        settings: &SceneOptions,
    ) -> PyResult<(RenderOptions, SceneOptions)> {
        let mut view = view.clone();
        order_names(&mut view, self.sort, self.arith, self.cull)?;
        view.near = self.near.or(view.near);
        view.far = self.far.or(view.far);
        view.max_fragments = self.max_fragments;
        view.visible |= self.visible;
        if let Some(s) = self.shading {
            view.shading = Some(named("shading", s, &Shading::ALL, Shading::name)?);
        }
        let format = self
            .format
            .map(|f| named("format", f, &Format::ALL, Format::name))
            .transpose()?;
        let style = self
            .style
            .map(|s| named("style", s, &Look::ALL, Look::name))
            .transpose()?;
        let dashed = match self.hidden {
            None => None,
            Some("dashed") => Some(true),
            Some("omit") => Some(false),
            Some(h) => return Err(value_error(format!("unknown hidden `{h}` (omit, dashed)"))),
        };
        let fill = match self.fill {
            None => None,
            Some("background") => Some(true),
            Some("none") => Some(false),
            Some(f) => {
                return Err(value_error(format!(
                    "unknown fill `{f}` (background, none)"
                )))
            }
        };
        let method = named("method", self.method, &Method::ALL, Method::name)?;
        let mut settings = settings.clone();
        if let Some((r, g, b)) = self.outline_color {
            settings.outline_color = Some([r, g, b]);
        }
        if let Some(w) = self.outline_width {
            if !(w >= 0.0 && w.is_finite()) {
                return Err(value_error(format!("outline width {w} is not valid")));
            }
            settings.outline_width = Some(w);
        }
        let o = RenderOptions {
            view,
            format,
            outline: self.outline,
            seams: self.seams,
            background: self.background.map(background).transpose()?,
            shading_tolerance: self.shading_tolerance,
            texture_samples: self.texture_samples,
            method,
            shadow_map_size: self.shadow_map_size,
            shadow_bias: self.shadow_bias,
            standalone: self.standalone,
            style,
            crease: self.crease,
            dashed,
            fill,
            stats: self.stats.clone(),
        };
        Ok((o, settings))
    }
}

/// Check options by name (`visible`: check the visible map).
#[allow(clippy::too_many_arguments)]
pub(crate) fn check_options(
    view: &ViewOptions,
    against: &str,
    sort: Option<&str>,
    arith: Option<&str>,
    seams: f64,
    visible: bool,
    diff: Option<PathBuf>,
    stats: Option<PathBuf>,
) -> PyResult<CheckOptions> {
    let mut view = view.clone();
    order_names(&mut view, sort, arith, None)?;
    view.visible |= visible;
    Ok(CheckOptions {
        view,
        against: named("reference", against, &Against::ALL, Against::name)?,
        diff,
        seams,
        stats,
    })
}

/// A JSON value as the Python object `json.loads` makes of it.
pub(crate) fn json_object<'py>(
    py: Python<'py>,
    v: &serde_json::Value,
) -> PyResult<Bound<'py, PyAny>> {
    let text = serde_json::to_string(v).map_err(value_error)?;
    py.import("json")?.call_method1("loads", (text,))
}

/// Runs `f` on a pool of `threads` workers (all cores when `None`).
pub(crate) fn on_threads<T: Send>(
    threads: Option<usize>,
    f: impl FnOnce() -> T + Send,
) -> PyResult<T> {
    match threads {
        None => Ok(f()),
        Some(0) => Err(value_error("threads must be at least 1")),
        Some(n) => {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| value_error(format!("cannot start {n} threads: {e}")))?;
            Ok(pool.install(f))
        }
    }
}
