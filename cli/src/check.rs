//! `limn check` and the raster methods of `limn render --method`.

use std::path::Path;
use std::process::ExitCode;

use anyhow::{Context, Result};
use limn_depthsort::{order, CullMode, OrderOptions};
use limn_scene::{Camera, Scene};
use limn_zbuffer::{
    compare, default_band_tolerance, diff_png, edge_band, rasterize_ids, render, scene_edges,
    Method, RenderOptions, NO_FACE,
};
use serde_json::json;

use crate::args::{AgainstArg, CheckArgs, MethodArg, ViewArgs};
use crate::output::write_atomic;
use crate::render::{camera, load, order_options};

/// Exit status when mismatches remain outside the edge band.
const MISMATCH: u8 = 3;

fn method_of(m: MethodArg) -> Option<Method> {
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
) -> Result<ExitCode> {
    let method = method_of(m).context("the painter is not a raster method")?;
    let opts = RenderOptions {
        cull_back_faces: oo.cull == CullMode::On,
        ..RenderOptions::default()
    };
    let r = render(scene, cam, method, &opts)?;
    let png = r.color.encode_png()?;
    write_atomic(output, |w| {
        w.write_all(&png)?;
        Ok(())
    })?;
    if !view.quiet && output.as_os_str() != "-" {
        eprintln!("limn: wrote {} ({})", output.display(), method.name());
    }
    Ok(ExitCode::SUCCESS)
}

/// Orders the scene, resolves which fragment covers each pixel centre, and compares the
/// face ids with a reference.
pub fn check(a: CheckArgs) -> Result<ExitCode> {
    let loaded = load(&a.input, &a.view)?;
    let scene = &loaded.scene;
    let cam = camera(scene, &a.view, loaded.opts.size, &a.input)?;
    let oo = order_options(&a.view, &loaded.opts)?;
    let ordered = order(scene, &cam, &oo).with_context(|| format!("{}", a.input.display()))?;
    let c = &ordered.camera;
    let (w, h) = (c.width, c.height);
    let polys: Vec<(Vec<[f64; 2]>, u32)> = ordered
        .fragments
        .iter()
        .map(|f| (f.points.clone(), f.face))
        .collect();
    let painter = rasterize_ids(&polys, w, h);
    let method = match a.against {
        AgainstArg::Zbuffer => Method::ZBuffer,
        AgainstArg::Raycast => Method::RayCast,
        AgainstArg::Warnock => Method::Warnock,
        AgainstArg::Scanline => Method::ScanLine,
    };
    let ropts = RenderOptions {
        cull_back_faces: oo.cull == CullMode::On,
        near_far: Some((ordered.near, ordered.far)),
        ..RenderOptions::default()
    };
    let reference = render(scene, c, method, &ropts)?;
    // Pixel centres near a projected edge (of a face, a near-plane cut or a fragment:
    // fragments also trace where faces pierce each other) are ambiguous.
    let mut edges = scene_edges(scene, c, &ropts)?;
    for f in &ordered.fragments {
        let n = f.points.len();
        for i in 0..n {
            edges.push((f.points[i], f.points[(i + 1) % n]));
        }
    }
    let tol = default_band_tolerance(w, h);
    let band = edge_band(&edges, w, h, tol);
    let cmp = compare(&painter, &reference.ids, Some(&band));
    if let Some(path) = &a.diff {
        let png = diff_png(&painter, &reference.ids, Some(&band))?;
        write_atomic(path, |out| {
            out.write_all(&png)?;
            Ok(())
        })?;
    }
    let per_face: serde_json::Map<String, serde_json::Value> = cmp
        .per_face
        .iter()
        .filter(|(_, (bad, _))| *bad > 0)
        .map(|(&f, &(bad, total))| {
            let key = if f == NO_FACE {
                "background".to_string()
            } else {
                f.to_string()
            };
            (key, json!({"mismatches": bad, "pixels": total}))
        })
        .collect();
    let v = json!({
        "input": a.input.display().to_string(),
        "against": method.name(),
        "sort": oo.sort.name(),
        "arith": oo.arith.name(),
        "width": w,
        "height": h,
        "pixels": cmp.pixels,
        "mismatches": cmp.mismatches,
        "mismatches_outside_band": cmp.mismatches_outside_band,
        "band_pixels": cmp.band_pixels,
        "band_tolerance_px": tol,
        "fragments": ordered.fragments.len(),
        "splits": ordered.stats.splits,
        "per_face": per_face,
    });
    let text = serde_json::to_string_pretty(&v)? + "\n";
    match &a.view.stats {
        Some(p) => write_atomic(p, |out| {
            out.write_all(text.as_bytes())?;
            Ok(())
        })?,
        None => print!("{text}"),
    }
    if cmp.mismatches_outside_band > 0 {
        if !a.view.quiet {
            eprintln!(
                "limn: {} pixels disagree with {} outside the edge band",
                cmp.mismatches_outside_band,
                method.name()
            );
        }
        return Ok(ExitCode::from(MISMATCH));
    }
    Ok(ExitCode::SUCCESS)
}
