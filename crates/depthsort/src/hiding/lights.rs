//! The shadow-casting lights as sources: each light with the volumes every opaque face
//! of the scene hides from it (culled or clipped from the eye's view or not: a face
//! the eye does not see still casts its shadow).

use glam::DVec3;
use limn_kernel::Kernel;
use limn_scene::{LightKind, Scene};
use rayon::prelude::*;

use super::broad::{Extent, LightView};
use super::volume::{volume, SidePlanes, Source, Volume};
use super::{Caster, Who};
use crate::options::OrderError;

/// The shadow-casting lights of `scene` with their occluders (every polygon of every
/// opaque face).
pub(super) fn casters<K: Kernel>(k: &K, scene: &Scene) -> Result<Vec<Caster<K>>, OrderError> {
    let shadow_lights = scene.shadow_lights();
    if shadow_lights.is_empty() {
        return Ok(Vec::new());
    }
    // The occluders: opaque faces' convex polygons (their corners are input points).
    let polys: Vec<(K::Polygon, u32)> = scene
        .faces
        .par_iter()
        .enumerate()
        .filter(|(_, f)| scene.materials[f.material as usize].is_opaque())
        .map(|(i, _)| {
            let polys = k.face_polygons(&scene.face_points(i as u32))?;
            Ok(polys.into_iter().map(move |p| (p, i as u32)))
        })
        .collect::<Result<Vec<_>, OrderError>>()?
        .into_iter()
        .flatten()
        .collect();
    let (lo, hi) = scene.bounds().unwrap_or((DVec3::ZERO, DVec3::ZERO));
    let mut out = Vec::new();
    for index in shadow_lights.iter() {
        let (source, view) = match scene.lights[index].kind {
            LightKind::Point(p) => (Source::At(p, k.point(p)?), LightView::central(p, lo, hi)),
            LightKind::Directional(d) => (Source::Toward(d), LightView::parallel(d)),
            LightKind::Ambient | LightKind::Headlight => continue,
        };
        let mut shared = SidePlanes::new();
        let mut corners = Vec::new();
        let mut built: Vec<(Volume<K::Plane>, Option<Extent>)> = Vec::with_capacity(polys.len());
        for (poly, face) in &polys {
            if let Some(v) = volume(k, poly, *face, &source, &mut corners, &mut shared)? {
                built.push((v, view.extent(&corners)));
            }
        }
        out.push(Caster::new(Who::Light(index), source, view, built));
    }
    Ok(out)
}
