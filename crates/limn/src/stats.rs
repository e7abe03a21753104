//! The statistics of a render: what `--stats` writes as JSON and Python returns as a
//! dict, assembled once. The keys are documented in the guide (docs/stats.md).

use limn_depthsort::{MarkStats, OrderOptions, Ordered};
use limn_paint::PaintStats;
use limn_scene::Effects;
use serde::Serialize;

/// Milliseconds spent per stage of a render.
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize)]
pub struct Timing {
    /// Loading (or building) the scene.
    pub load: f64,
    /// Ordering (hidden-line preparation included).
    pub order: f64,
    /// Composing and writing the picture.
    pub write: f64,
    /// Everything.
    pub total: f64,
    /// Of ordering: preparing faces (cull, clip, exact planes).
    pub prepare: f64,
    /// Of ordering: sorting.
    pub sort: f64,
    /// Of ordering: merging fragments back.
    pub merge: f64,
    /// Of ordering: splitting fragments at shadow boundaries.
    pub shadows: f64,
    /// Of ordering: splitting fragments along what hides them from the eye (`--visible`;
    /// shadows are split in the same pass and counted here then).
    pub visible: f64,
}

/// Counts of hidden lines, markers and labels.
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct LineStats {
    /// Polylines given.
    pub lines: usize,
    /// Their segments.
    pub segments_in: usize,
    /// Visible pieces drawn.
    pub pieces_out: usize,
    /// Hidden pieces (drawn dashed or left out).
    pub hidden_pieces: usize,
    /// Markers given.
    pub markers: usize,
    /// Markers visible.
    pub markers_shown: usize,
    /// Labels given.
    pub labels: usize,
    /// Labels visible.
    pub labels_shown: usize,
    /// Exact tests made to decide visibility.
    pub exact_tests: usize,
    /// Paths of lines written.
    pub line_paths_out: usize,
    /// Milliseconds spent hiding them.
    pub ms: u64,
}

/// The statistics of one painter's render. Serialised with its keys in alphabetical
/// order (the order `--stats` has always written).
#[derive(Debug, Clone, Default, PartialEq, Serialize)]
pub struct RenderStats {
    /// Faces in the scene.
    pub faces_in: usize,
    /// Back faces culled.
    pub faces_culled: usize,
    /// Faces of zero area as given (not drawn, with a warning).
    pub faces_degenerate: usize,
    /// Faces entirely outside the view.
    pub faces_clipped: usize,
    /// Faces coincident with another (drawn once).
    pub faces_coincident: usize,
    /// Faces cut by the near plane.
    pub faces_near_clipped: usize,
    /// Polygons ordered (faces after splitting into convex planar pieces).
    pub polygons: usize,
    /// Pairs whose screen bounds overlap.
    pub candidate_pairs: usize,
    /// In-front-of constraints found.
    pub constraints: usize,
    /// Strongly connected groups ordered.
    pub components: usize,
    /// Fragments in the largest group.
    pub largest_component: usize,
    /// Splits made to break cycles and interpenetrations.
    pub splits: usize,
    /// Pieces set apart.
    pub parts_apart: usize,
    /// Fragments before merging back.
    pub fragments_before_merge: usize,
    /// Fragments painted.
    pub fragments_out: usize,
    /// Fragments made in all.
    pub fragments_made: usize,
    /// Fragments in the shadow of some light.
    pub fragments_in_shadow: usize,
    /// Parts of fragments left out as hidden (`--visible`).
    pub fragments_hidden: usize,
    /// The limit on fragments in force.
    pub fragment_limit: usize,
    /// Paths written.
    pub paths_out: usize,
    /// Bytes written.
    pub bytes_out: u64,
    /// Decisions the floating-point filter could not make (made exactly).
    pub filter_fallbacks: u64,
    /// The ordering used.
    pub sort: &'static str,
    /// The arithmetic used.
    pub arith: &'static str,
    /// The effects the scene called for.
    pub effects: Vec<&'static str>,
    /// Every warning of the render (loading and drawing).
    pub warnings: Vec<String>,
    /// Lines, markers and labels.
    pub lines: LineStats,
    /// Time per stage.
    pub ms: Timing,
}

impl RenderStats {
    /// The statistics of a render of a scene calling for `effects` (see
    /// [`Effects::of`]) ordered into `ordered` with `oo`, painted with `paint`, its marks
    /// hidden with `marks`.
    pub fn new(
        effects: Effects,
        ordered: &Ordered,
        oo: &OrderOptions,
        (paint, marks): (&PaintStats, &MarkStats),
        [load, order, write, total]: [f64; 4],
        warnings: Vec<String>,
    ) -> RenderStats {
        let s = &ordered.stats;
        let mut effects: Vec<&'static str> = effects.names();
        if s.faces_culled > 0 {
            effects.push("backface-culling");
        }
        RenderStats {
            faces_in: s.faces_in,
            faces_culled: s.faces_culled,
            faces_degenerate: s.faces_degenerate,
            faces_clipped: s.faces_clipped,
            faces_coincident: s.faces_coincident,
            faces_near_clipped: s.faces_near_clipped,
            polygons: s.polygons,
            candidate_pairs: s.candidate_pairs,
            constraints: s.constraints,
            components: s.components,
            largest_component: s.largest_component,
            splits: s.splits,
            parts_apart: s.parts_apart,
            fragments_before_merge: s.fragments_before_merge,
            fragments_out: s.fragments_out,
            fragments_made: s.fragments_made,
            fragments_in_shadow: s.fragments_in_shadow,
            fragments_hidden: s.fragments_hidden,
            fragment_limit: s.fragment_limit,
            paths_out: paint.paths,
            bytes_out: paint.bytes,
            filter_fallbacks: s.filter_fallbacks,
            sort: oo.sort.name(),
            arith: oo.arith.name(),
            effects,
            warnings,
            lines: LineStats {
                lines: marks.lines,
                segments_in: marks.segments_in,
                pieces_out: marks.pieces_out,
                hidden_pieces: marks.hidden_pieces,
                markers: marks.markers_in,
                markers_shown: marks.markers_shown,
                labels: marks.labels_in,
                labels_shown: marks.labels_shown,
                exact_tests: marks.exact_tests,
                line_paths_out: paint.lines,
                ms: marks.ms,
            },
            ms: Timing {
                load,
                order,
                write,
                total,
                prepare: s.ms_prepare,
                sort: s.ms_order,
                merge: s.ms_merge,
                shadows: s.ms_shadows,
                visible: s.ms_visible,
            },
        }
    }

    /// The statistics as a JSON value (objects with sorted keys).
    pub fn to_json(&self) -> serde_json::Value {
        // Serialising plain numbers, strings and vectors cannot fail.
        serde_json::to_value(self).unwrap_or(serde_json::Value::Null)
    }

    /// The statistics as pretty-printed JSON with a final newline, as `--stats` writes.
    pub fn to_json_text(&self) -> String {
        serde_json::to_string_pretty(&self.to_json()).unwrap_or_default() + "\n"
    }
}
