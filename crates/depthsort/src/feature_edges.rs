//! The edges a hidden-line drawing shows: silhouettes (between a face seen from the front
//! and one seen from behind or edge-on), boundaries (used by one face), creases (between
//! two faces whose normals differ by more than a given angle) and edges shared by more
//! than two faces.
//!
//! Edges are matched by the positions of their ends (so duplicated vertices still join).
//! Which side of a face the eye is on is decided exactly (the kernel's plane through three
//! of its corners); the crease angle compares float normals (it chooses which edges to
//! draw, not where they are visible).

use std::collections::HashMap;

use glam::DVec3;
use limn_kernel::{Plane, Side};
use limn_scene::{polygon_normal, Scene, Viewpoint};

/// Why an edge is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum EdgeKind {
    /// Between a face seen from the front and one that is not.
    Silhouette,
    /// Used by one face only.
    Boundary,
    /// Between two faces meeting at more than the crease angle.
    Crease,
    /// Used by three faces or more.
    NonManifold,
}

/// One edge of a hidden-line drawing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FeatureEdge {
    /// First end.
    pub a: DVec3,
    /// Second end.
    pub b: DVec3,
    /// Why it is drawn.
    pub kind: EdgeKind,
}

/// Whether the eye sees face `f` from its front (exactly; faces whose first three corners
/// are collinear use the float normal).
fn front_facing(scene: &Scene, f: u32, view: Viewpoint) -> bool {
    let pts = scene.face_points(f);
    if let Ok(plane) = Plane::through(pts[0].to_array(), pts[1].to_array(), pts[2].to_array()) {
        let side = match view {
            Viewpoint::At(e) => plane.side_of(e.to_array()),
            Viewpoint::Toward(d) => plane.side_of_direction(d.to_array()),
        };
        return side == Side::Front;
    }
    let n = polygon_normal(&pts);
    match view {
        Viewpoint::At(e) => n.dot(e - pts[0]) > 0.0,
        Viewpoint::Toward(d) => n.dot(d) > 0.0,
    }
}

/// The feature edges of `scene`'s faces seen from `view` (an eye point, or a direction
/// for parallel projections), with creases above `crease_deg` degrees, in the order their
/// first face lists them.
pub fn feature_edges(scene: &Scene, view: Viewpoint, crease_deg: f64) -> Vec<FeatureEdge> {
    type Key = [u64; 3];
    let key = |p: DVec3| [p.x.to_bits(), p.y.to_bits(), p.z.to_bits()];
    let mut order: Vec<(Key, Key, DVec3, DVec3)> = Vec::new();
    let mut faces: HashMap<(Key, Key), Vec<u32>> = HashMap::new();
    for (fi, f) in scene.faces.iter().enumerate() {
        let n = f.vertices.len();
        for i in 0..n {
            let (a, b) = (
                scene.vertices[f.vertices[i] as usize],
                scene.vertices[f.vertices[(i + 1) % n] as usize],
            );
            let (ka, kb) = (key(a), key(b));
            if ka == kb {
                continue;
            }
            let k = if ka < kb { (ka, kb) } else { (kb, ka) };
            let list = faces.entry(k).or_default();
            if list.is_empty() {
                order.push((k.0, k.1, a, b));
            }
            list.push(fi as u32);
        }
    }
    let cos_crease = crease_deg.to_radians().cos();
    let mut facing: HashMap<u32, bool> = HashMap::new();
    let mut front = |f: u32| {
        *facing
            .entry(f)
            .or_insert_with(|| front_facing(scene, f, view))
    };
    let mut out = Vec::new();
    for (ka, kb, a, b) in order {
        let list = &faces[&(ka, kb)];
        let kind = match list.as_slice() {
            [_] => Some(EdgeKind::Boundary),
            [f, g] => {
                if front(*f) != front(*g) {
                    Some(EdgeKind::Silhouette)
                } else {
                    let nf = polygon_normal(&scene.face_points(*f)).normalize_or_zero();
                    let ng = polygon_normal(&scene.face_points(*g)).normalize_or_zero();
                    (nf.dot(ng) < cos_crease).then_some(EdgeKind::Crease)
                }
            }
            _ => Some(EdgeKind::NonManifold),
        };
        if let Some(kind) = kind {
            out.push(FeatureEdge { a, b, kind });
        }
    }
    out
}
