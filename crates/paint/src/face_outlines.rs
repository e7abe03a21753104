//! The projected outlines of the translucent input faces: what the writers prove two
//! translucent runs disjoint from when their own corners cannot (see `layers.rs`).
//!
//! Every fragment of a face lies inside its face, and a face that lies wholly in front
//! of the eye projects into the convex hull of its projected corners (a perspective
//! projection keeps straight lines straight where nothing crosses the eye's plane). So
//! when the hulls of two faces' projected corners have disjoint interiors, so have any
//! fragments of theirs, whatever corners cutting gave them. Two neighbouring triangles
//! of a translucent mesh, each cut along what hides it, have parts whose rounded
//! corners meet a few units in the last place apart (a corner of one part on the
//! other's edge, rounded off it): their own corners show an overlap that is not in
//! the picture, while the faces' input corners are shared exactly.

use std::collections::BTreeMap;

use limn_depthsort::Ordered;
use limn_scene::Scene;

/// Per translucent face of `scene` painted in `ordered` whose corners all lie in front of
/// the eye, its corners projected onto the page.
pub(crate) fn translucent_outlines(
    scene: &Scene,
    ordered: &Ordered,
) -> BTreeMap<u32, Vec<[f64; 2]>> {
    let cam = &ordered.camera;
    let vp = cam.view_projection(ordered.near, ordered.far);
    let mut out = BTreeMap::new();
    for frag in &ordered.fragments {
        let face = &scene.faces[frag.face as usize];
        if scene.materials[face.material as usize].is_opaque() || out.contains_key(&frag.face) {
            continue;
        }
        let projected: Vec<_> = face
            .vertices
            .iter()
            .map(|&v| cam.project_with(&vp, scene.vertices[v as usize]))
            .collect();
        if projected
            .iter()
            .all(|p| p.w > 0.0 && p.x.is_finite() && p.y.is_finite())
        {
            out.insert(frag.face, projected.iter().map(|p| [p.x, p.y]).collect());
        }
    }
    out
}
