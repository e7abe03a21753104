//! The `--stats` JSON object of `render` and `demo`.

use std::path::PathBuf;

use anyhow::Result;
use limn_depthsort::{MarkStats, OrderOptions, Ordered};
use limn_paint::PaintStats;
use limn_scene::{Effects, Scene};
use serde_json::json;

use crate::output::write_atomic;

/// Milliseconds spent per stage.
pub struct Timing {
    /// Loading (or building) the scene.
    pub load: f64,
    /// Ordering.
    pub order: f64,
    /// Writing.
    pub write: f64,
    /// Everything.
    pub total: f64,
}

/// What was drawn: the painter's counts and those of the lines, markers and labels.
pub struct Drawn<'a> {
    /// The painter's counts.
    pub paint: &'a PaintStats,
    /// Lines, markers and labels.
    pub marks: &'a MarkStats,
}

/// Writes the statistics of a run to `path` (nothing when `None`).
pub fn write_stats(
    path: &Option<PathBuf>,
    scene: &Scene,
    ordered: &Ordered,
    oo: &OrderOptions,
    drawn: &Drawn<'_>,
    t: &Timing,
    warnings: &[String],
) -> Result<()> {
    let (ps, marks) = (drawn.paint, drawn.marks);
    let Some(path) = path else { return Ok(()) };
    let s = &ordered.stats;
    let effects = Effects::of(scene);
    let mut effect_names: Vec<&str> = effects.names();
    if s.faces_culled > 0 {
        effect_names.push("backface-culling");
    }
    let v = json!({
        "faces_in": s.faces_in,
        "faces_culled": s.faces_culled,
        "faces_degenerate": s.faces_degenerate,
        "faces_clipped": s.faces_clipped,
        "faces_coincident": s.faces_coincident,
        "faces_near_clipped": s.faces_near_clipped,
        "polygons": s.polygons,
        "candidate_pairs": s.candidate_pairs,
        "constraints": s.constraints,
        "components": s.components,
        "largest_component": s.largest_component,
        "splits": s.splits,
        "parts_apart": s.parts_apart,
        "fragments_before_merge": s.fragments_before_merge,
        "fragments_out": s.fragments_out,
        "fragments_made": s.fragments_made,
        "fragments_in_shadow": s.fragments_in_shadow,
        "fragment_limit": s.fragment_limit,
        "paths_out": ps.paths,
        "bytes_out": ps.bytes,
        "filter_fallbacks": s.filter_fallbacks,
        "sort": oo.sort.name(),
        "arith": oo.arith.name(),
        "effects": effect_names,
        "warnings": warnings,
        "lines": {
            "lines": marks.lines,
            "segments_in": marks.segments_in,
            "pieces_out": marks.pieces_out,
            "hidden_pieces": marks.hidden_pieces,
            "markers": marks.markers_in,
            "markers_shown": marks.markers_shown,
            "labels": marks.labels_in,
            "labels_shown": marks.labels_shown,
            "exact_tests": marks.exact_tests,
            "line_paths_out": ps.lines,
            "ms": marks.ms,
        },
        "ms": {
            "load": t.load,
            "order": t.order,
            "write": t.write,
            "total": t.total,
            "prepare": s.ms_prepare,
            "sort": s.ms_order,
            "merge": s.ms_merge,
            "shadows": s.ms_shadows,
        },
    });
    let text = serde_json::to_string_pretty(&v)? + "\n";
    write_atomic(path, &scene.files, |w| {
        w.write_all(text.as_bytes())?;
        Ok(())
    })
}
