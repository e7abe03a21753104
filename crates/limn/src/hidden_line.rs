//! The hidden-line stage, before ordering: the scene's feature edges (silhouettes,
//! boundaries, creases) seen from the camera become lines of the scene, hidden by the
//! same exact machinery as any line; the faces become the fill colour.

use limn_depthsort::feature_edges;
use limn_paint::HiddenLineStyle;
use limn_scene::{Camera, Material, Polyline, Scene, Viewpoint};

/// `scene` prepared for a hidden-line drawing seen by `camera`: every material becomes the
/// unlit, opaque `fill` colour, and the feature edges are appended to the lines (in a new
/// object `edges`). Returns the scene and the index of the first edge line.
pub fn hidden_line_scene(
    scene: &Scene,
    camera: &Camera,
    style: &HiddenLineStyle,
    fill: [f64; 3],
) -> (Scene, usize) {
    let mut s = scene.clone();
    for m in &mut s.materials {
        *m = Material::unlit(&m.name, fill);
    }
    let first = s.lines.len();
    let object = s.add_object("edges");
    let view = camera.viewpoint().unwrap_or(Viewpoint::At(camera.eye));
    for e in feature_edges(scene, view, style.crease) {
        s.lines.push(Polyline {
            points: vec![e.a, e.b],
            color: style.color,
            width: style.width,
            dash: Vec::new(),
            head: false,
            object,
        });
    }
    (s, first)
}
