//! `limn render --method …`: the scene per pixel by an image-space method, as PNG.

use std::path::Path;
use std::process::ExitCode;

use anyhow::{Context, Result};
use limn_depthsort::{CullMode, OrderOptions};
use limn_scene::{Camera, Scene};
use limn_zbuffer::{render_with_shadow_maps, Method, RenderOptions, ShadowMapOptions};

use crate::args::{MethodArg, ViewArgs};
use crate::output::write_atomic;

/// The image-space method of a `--method` value (`None` for the painter).
pub fn method_of(m: MethodArg) -> Option<Method> {
    match m {
        MethodArg::Painter => None,
        MethodArg::Zbuffer => Some(Method::ZBuffer),
        MethodArg::Scanline => Some(Method::ScanLine),
        MethodArg::Abuffer => Some(Method::ABuffer),
        MethodArg::Warnock => Some(Method::Warnock),
        MethodArg::Raycast => Some(Method::RayCast),
    }
}

/// Renders the scene with an image-space method and writes the colour image as PNG.
pub fn raster(
    scene: &Scene,
    cam: &Camera,
    m: MethodArg,
    output: &Path,
    view: &ViewArgs,
    oo: &OrderOptions,
    maps: &ShadowMapOptions,
) -> Result<ExitCode> {
    let method = method_of(m).context("the painter is not a raster method")?;
    let opts = RenderOptions {
        cull_back_faces: oo.cull == CullMode::On,
        ..RenderOptions::default()
    };
    if method == Method::ABuffer && !scene.shadow_lights().is_empty() && !view.quiet {
        eprintln!("limn: warning: the A-buffer draws no shadows (use zbuffer, scanline, warnock or raycast)");
    }
    let r = render_with_shadow_maps(scene, cam, method, &opts, maps)?;
    let png = r.color.encode_png()?;
    write_atomic(output, &scene.files, |w| {
        w.write_all(&png)?;
        Ok(())
    })?;
    if !view.quiet && output.as_os_str() != "-" {
        eprintln!("limn: wrote {} ({})", output.display(), method.name());
    }
    Ok(ExitCode::SUCCESS)
}
