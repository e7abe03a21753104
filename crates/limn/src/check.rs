//! A check: the painter's order against an image-space reference, pixel by pixel
//! (through [`limn_check`], the routine the tests use; the faces compared are those of the
//! picture a render draws, with its whole-face covers and seam flaps), and the visible
//! line pieces against the z-buffer's depth-tested lines. A visible map (`--visible`) is
//! also checked to cover every pixel centre outside the edge band at most once with its
//! opaque regions.

use limn_check::paint;
use limn_paint::{picture, Style};
use limn_zbuffer::{
    default_band_tolerance, diff_png, rasterize_ids, DepthFormat, Method, ShadowMapOptions, NO_FACE,
};
use serde_json::json;

use crate::error::Error;
use crate::events::Events;
use crate::input::{load, Input};
use crate::options::CheckOptions;
use crate::output::{check_writable, write_atomic, OutputError};
use crate::settings::{camera, order_options};

/// What a check found.
#[derive(Debug, Clone)]
pub struct CheckReport {
    /// The report as JSON (what `limn check` prints).
    pub json: serde_json::Value,
    /// Pixels whose face disagrees with the reference outside the edge band.
    pub mismatches_outside_band: usize,
    /// Why the check failed, one sentence each (empty when the pictures agree).
    pub failures: Vec<String>,
}

impl CheckReport {
    /// Whether the pictures agree: no face, shadow or line disagreement outside the band.
    pub fn agrees(&self) -> bool {
        self.failures.is_empty()
    }

    /// The report as pretty-printed JSON with a final newline.
    pub fn to_json_text(&self) -> String {
        serde_json::to_string_pretty(&self.json).unwrap_or_default() + "\n"
    }
}

/// Orders the scene, resolves which fragment covers each pixel centre, and compares the
/// face ids with a reference. Writes the difference image and the report when asked.
pub fn check(
    input: &Input<'_>,
    o: &CheckOptions,
    events: &mut dyn Events,
) -> Result<CheckReport, Error> {
    o.view.validate()?;
    crate::values::seams(o.seams).map_err(Error::Value)?;
    let loaded = load(input, &o.view, events)?;
    let scene = &loaded.scene;
    let name = &loaded.name;
    let cam = camera(scene, &o.view, loaded.settings.size, name)?;
    let oo = order_options(&o.view, &loaded.settings)?;
    for path in o.diff.iter().chain(&o.stats) {
        check_writable(path, &scene.files)?;
    }
    events.phase("ordering");
    let mut painted = paint(scene, &cam, &oo).map_err(|source| Error::Check {
        input: name.clone(),
        source,
    })?;
    // The faces of the picture a render draws: whole-face covers and seam flaps included.
    let pic = picture(
        scene,
        &painted.ordered,
        &Style {
            seams: o.seams,
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
    let method = o.against.method();
    events.phase("rendering the reference");
    let reference = painted.reference(scene, method, DepthFormat::F64)?;
    events.phase("comparing");
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
    if let Some(path) = &o.diff {
        let png = diff_png(&painted.ids, &reference, Some(&painted.band))?;
        write_bytes(path, &scene.files, &png)?;
    }
    // The visible map's opaque regions (the ordered fragments, before seam flaps) cover
    // each pixel centre once.
    let double_covered = oo.visible.then(|| painted.double_covered(scene));
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
        "input": name,
        "against": method.name(),
        "sort": oo.sort.name(),
        "arith": oo.arith.name(),
        "visible": oo.visible,
        "double_covered": double_covered,
        "seams": o.seams,
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
    if ordered.stats.faces_near_clipped > 0 {
        events.warning(&format!(
            "{} faces come closer to the eye than the near plane ({:.6e}); the \
             painter and {} both cut them there, so this comparison does not cover the cut \
             parts (set --near to move it)",
            ordered.stats.faces_near_clipped,
            ordered.near,
            method.name()
        ));
    }
    let mut failures = Vec::new();
    if cmp.mismatches_outside_band > 0 {
        failures.push(format!(
            "{} pixels disagree with {} outside the edge band",
            cmp.mismatches_outside_band,
            method.name()
        ));
    }
    if let Some(n) = double_covered.filter(|&n| n > 0) {
        failures.push(format!(
            "{n} pixel centres outside the edge band are covered by two opaque regions of \
             the visible map"
        ));
    }
    if let Some(c) = shadows.filter(|c| method == Method::RayCast && c.mismatches_outside_band > 0)
    {
        failures.push(format!(
            "{} pixels are shadowed from other lights than by the exact shadow rays \
             outside the edge band",
            c.mismatches_outside_band
        ));
    }
    if lines.fails() {
        failures.push(format!(
            "{} of {} line pixels disagree with the z-buffer's lines outside the band \
             (more than 1 %)",
            lines.mismatches_outside_band, lines.pixels
        ));
    }
    let report = CheckReport {
        json: v,
        mismatches_outside_band: cmp.mismatches_outside_band,
        failures,
    };
    if let Some(p) = &o.stats {
        write_bytes(p, &scene.files, report.to_json_text().as_bytes())?;
    }
    Ok(report)
}

/// Writes `bytes` to `path` safely.
fn write_bytes(
    path: &std::path::Path,
    read: &[std::path::PathBuf],
    bytes: &[u8],
) -> Result<(), Error> {
    write_atomic(path, read, |out| {
        out.write_all(bytes).map_err(|source| OutputError::Write {
            path: path.to_path_buf(),
            source,
        })?;
        Ok(())
    })
}
