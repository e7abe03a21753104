//! The eye as a source: what the opaque polygons the painter draws hide from it, so that
//! the parts of the ordered pieces it cannot see are dropped (the visible map).
//!
//! The eye's occluders are the convex polygons of the opaque faces that the painter
//! draws: not culled (back faces of the objects whose back faces are culled, and
//! polygons seen exactly edge-on, hide nothing in the picture) and not cut by the near
//! plane where the camera would see the cut part. A polygon whose part behind the near
//! plane lies behind the eye or outside the view pyramid hides, within the view, exactly
//! what its drawn part hides (the segment from the eye to a point in view stays in
//! view, in front of the eye); one cut in view (a warning says so) hides nothing here:
//! a volume through the cut's edge is not defined by input points, so its drawn pieces
//! are painted over what they hide, as in painter's output, and the picture stays
//! exact. Translucent faces hide nothing: what lies behind them stays and is painted
//! under them. A polygon lying in an occluder's plane is hidden where the occluder
//! covers it when the occluder's face comes later in the input (the painter's coplanar
//! rule).
//!
//! Seen from a finite eye, every receiver lies beyond the near plane, so the broad phase
//! views them centrally along the camera's axis (an occluder reaching behind the eye has
//! no extent there and is a candidate of every receiver); an eye at infinity views them
//! in parallel.

use limn_kernel::{Kernel, PolygonSide, Side};
use limn_scene::Scene;
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering};

use super::broad::{Extent, LightView};
use super::volume::{volume, SidePlanes, Source, Volume};
use super::{Caster, Who};
use crate::eye::Eye;
use crate::options::OrderError;
use crate::pieces::Ctx;
use crate::prepare::lost_in_view;
use crate::view::view_planes;

/// What the eye's volumes need of the preparation.
#[derive(Debug, Clone)]
pub(crate) struct Sight {
    /// Per object, whether its back faces were culled.
    pub culled_objects: Vec<bool>,
    /// The near plane's distance.
    pub near: f64,
    /// Whether the order is exact (no piece painted over a part of a piece in front of
    /// it), so that a face all of whose pieces come before a receiver in the order is
    /// known to hide none of it.
    pub order_exact: bool,
    /// Which pieces the eye splits, and by which faces.
    pub occluders: Occluders,
}

/// Which pieces the eye splits, and which opaque faces hide parts of them.
#[derive(Debug, Clone)]
pub(crate) enum Occluders {
    /// Every piece, by every opaque face the painter draws (the visible map).
    All,
    /// Only the pieces of translucent faces (the opaque ones stay whole, painted over
    /// what they hide as in painter's output), by the opaque faces marked here, per face
    /// (see [`crate::translucent_last`]).
    OfTranslucent(Vec<bool>),
}

impl Sight {
    /// The eye with the volumes of its occluders, and whether every polygon the painter
    /// draws of an opaque face is one of them (`false` when one cut by the near plane
    /// in view was left out).
    pub(super) fn caster<K: Kernel>(
        &self,
        ctx: &Ctx<'_, K>,
        scene: &Scene,
    ) -> Result<(Caster<K>, bool), OrderError> {
        let planes = view_planes(ctx, self.near)?;
        let (source, view) = match ctx.eye {
            Eye::At(p) => {
                let at = ctx.k.point_world(&p);
                // Clip w: the distance along the view axis, positive beyond the eye.
                let axis = ctx.vp.row(3).truncate();
                (Source::At(at, p), LightView::along(at, axis))
            }
            Eye::Toward(d) => (Source::Toward(d), LightView::parallel(d)),
        };
        let left_out = AtomicBool::new(false);
        let polys: Vec<(K::Polygon, u32)> = scene
            .faces
            .par_iter()
            .enumerate()
            .filter(|(i, f)| {
                scene.materials[f.material as usize].is_opaque()
                    && match &self.occluders {
                        Occluders::All => true,
                        Occluders::OfTranslucent(hides) => hides[*i],
                    }
            })
            .map(|(i, f)| {
                let polys = ctx.k.face_polygons(&scene.face_points(i as u32))?;
                let cull_back = self.culled_objects[f.object as usize];
                Ok(polys
                    .into_iter()
                    .filter(|p| {
                        let drawn = match ctx.eye_side(ctx.k.support(p)) {
                            Side::On => false,
                            Side::Back => !cull_back,
                            Side::Front => true,
                        };
                        drawn
                            && match ctx.k.classify(p, &planes.near) {
                                PolygonSide::Front => true,
                                PolygonSide::Spanning => {
                                    let lost = lost_in_view(
                                        ctx,
                                        p,
                                        &planes.near,
                                        planes.eye.as_ref(),
                                        &planes.sides,
                                    );
                                    if lost {
                                        left_out.store(true, Ordering::Relaxed);
                                    }
                                    !lost
                                }
                                _ => false,
                            }
                    })
                    .map(move |p| (p, i as u32))
                    .collect::<Vec<_>>())
            })
            .collect::<Result<Vec<_>, OrderError>>()?
            .into_iter()
            .flatten()
            .collect();
        let mut shared = SidePlanes::new();
        let mut corners = Vec::new();
        let mut built: Vec<(Volume<K::Plane>, Option<Extent>)> = Vec::with_capacity(polys.len());
        for (poly, face) in &polys {
            if let Some(v) = volume(ctx.k, poly, *face, &source, &mut corners, &mut shared)? {
                built.push((v, view.extent(&corners)));
            }
        }
        // Numbered nearest first (occluders without extent first, ties in input order),
        // so that the candidates of a receiver, listed by number, come nearest first.
        let near = |e: &Option<Extent>| e.map_or(f64::NEG_INFINITY, |e| e.near);
        built.sort_by(|a, b| near(&a.1).total_cmp(&near(&b.1)));
        let complete = !left_out.load(Ordering::Relaxed);
        Ok((Caster::new(Who::Eye, source, view, built), complete))
    }
}
