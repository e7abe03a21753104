//! `limn check`: the painter's order against an image-space reference, pixel by pixel
//! (through [`limn_check`], the routine the tests use; the faces compared are those of the
//! picture `render` draws, with its whole-face covers and seam flaps), and the visible
//! line pieces against the z-buffer's depth-tested lines.

use std::process::ExitCode;

use anyhow::{Context, Result};
use limn_check::paint;
use limn_paint::{picture, Style};
use limn_zbuffer::{
    default_band_tolerance, diff_png, rasterize_ids, DepthFormat, Method, ShadowMapOptions, NO_FACE,
};
use serde_json::json;

use crate::args::{AgainstArg, CheckArgs};
use crate::output::{check_writable, write_atomic};
use crate::progress::Progress;
use crate::setup::{camera, load, order_options};

/// Exit status when mismatches remain outside the edge band.
const MISMATCH: u8 = 3;

/// Orders the scene, resolves which fragment covers each pixel centre, and compares the
/// face ids with a reference.
pub fn check(a: CheckArgs) -> Result<ExitCode> {
    let progress = Progress::start(a.view.quiet);
    let loaded = load(&a.input, &a.view)?;
    let scene = &loaded.scene;
    let cam = camera(scene, &a.view, loaded.opts.size, &a.input)?;
    let oo = order_options(&a.view, &loaded.opts)?;
    for path in a.diff.iter().chain(&a.view.stats) {
        check_writable(path, &scene.files)?;
    }
    progress.phase("ordering");
    let mut painted = paint(scene, &cam, &oo).with_context(|| format!("{}", a.input.display()))?;
    // The faces of the picture `render` draws: whole-face covers and seam flaps included.
    let pic = picture(
        scene,
        &painted.ordered,
        &Style {
            seams: a.seams,
            ..Style::default()
        },
    );
    let polys: Vec<(Vec<[f64; 2]>, u32)> = pic
        .fragments
        .into_iter()
        .map(|f| (f.points, f.face))
        .collect();
    let c = &painted.ordered.camera;
    painted.ids = rasterize_ids(&polys, c.width, c.height);
    let ordered = &painted.ordered;
    let (w, h) = (ordered.camera.width, ordered.camera.height);
    let method = match a.against {
        AgainstArg::Zbuffer => Method::ZBuffer,
        AgainstArg::Raycast => Method::RayCast,
        AgainstArg::Warnock => Method::Warnock,
        AgainstArg::Scanline => Method::ScanLine,
    };
    progress.phase("rendering the reference");
    let reference = painted.reference(scene, method, DepthFormat::F64)?;
    progress.phase("comparing");
    let tol = default_band_tolerance(w, h);
    let cmp = painted.compare(&reference);
    let lines = painted.compare_lines(scene)?;
    // Shadows: the lights each pixel's point is hidden from; exact against ray casting,
    // by shadow maps (reported, never failed on) against the other references.
    let shadows = if scene.shadow_lights().is_empty() {
        None
    } else {
        let r = painted.reference_shadows(scene, method, &ShadowMapOptions::default())?;
        Some(painted.compare_shadows(&r))
    };
    if let Some(path) = &a.diff {
        let png = diff_png(&painted.ids, &reference, Some(&painted.band))?;
        write_atomic(path, &scene.files, |out| {
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
        "seams": a.seams,
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
        "lines": {
            "reference": "zbuffer (depth-tested Bresenham)",
            "pixels": lines.pixels,
            "mismatches": lines.mismatches,
            "mismatches_outside_band": lines.mismatches_outside_band,
            "pieces": painted.marks.stats.pieces_out,
            "markers_shown": painted.marks.stats.markers_shown,
            "labels_shown": painted.marks.stats.labels_shown,
        },
        // Both sides draw through the same near plane: what it cuts away, neither shows,
        // and the comparison cannot see it.
        "near": ordered.near,
        "faces_near_clipped_by_both": ordered.stats.faces_near_clipped,
        "shadows": shadows.as_ref().map(|c| json!({
            "reference": if method == Method::RayCast { "exact shadow rays" } else { "shadow maps" },
            "mismatches": c.mismatches,
            "mismatches_outside_band": c.mismatches_outside_band,
        })),
    });
    if ordered.stats.faces_near_clipped > 0 && !a.view.quiet {
        eprintln!(
            "limn: warning: {} faces come closer to the eye than the near plane ({:.6e}); the \
             painter and {} both cut them there, so this comparison does not cover the cut \
             parts (set --near to move it)",
            ordered.stats.faces_near_clipped,
            ordered.near,
            method.name()
        );
    }
    drop(progress);
    let text = serde_json::to_string_pretty(&v)? + "\n";
    match &a.view.stats {
        Some(p) => write_atomic(p, &scene.files, |out| {
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
    if let Some(c) = shadows.filter(|c| method == Method::RayCast && c.mismatches_outside_band > 0)
    {
        if !a.view.quiet {
            eprintln!(
                "limn: {} pixels are shadowed from other lights than by the exact shadow rays \
                 outside the edge band",
                c.mismatches_outside_band
            );
        }
        return Ok(ExitCode::from(MISMATCH));
    }
    if lines.fails() {
        if !a.view.quiet {
            eprintln!(
                "limn: {} of {} line pixels disagree with the z-buffer's lines outside the band \
                 (more than 1 %)",
                lines.mismatches_outside_band, lines.pixels
            );
        }
        return Ok(ExitCode::from(MISMATCH));
    }
    Ok(ExitCode::SUCCESS)
}
