//! Exact shadows in object space: each ordered piece split along the boundaries of the
//! shadows the scene's shadow-casting lights throw on it, each part knowing the lights
//! it is hidden from.
//!
//! A point of a receiving piece is in the shadow of a light when the light does not lie
//! strictly on the side of the piece's plane the eye sees (the seen side faces away
//! from it), or when the segment from the point to the light crosses an opaque face
//! (the point lies inside that face's shadow volume, see [`volume`]). Occluders are the
//! scene's opaque faces as given, culled or clipped from the eye's view or not; their
//! corners are input points, so every plane of every volume is defined by input points
//! and the light, and every cut is exact (implicit vertices, no epsilon, no snap, no
//! bias). The cuts of one piece are kept as a tree: where every part of a cut piece
//! ends up in the shadow of the same lights, the piece is joined again exactly (it is
//! its parent), so a face is split only along the boundaries of its shadows.
//!
//! The parts of a piece tile it and are painted in its place in the order, so the order
//! stays valid. Which occluders can touch a receiver is found in a float view from the
//! light ([`broad`]), a prefilter with margins.

mod broad;
mod volume;

use glam::DVec3;
use limn_kernel::{Kernel, Side};
use limn_scene::{LightKind, LightSet, Scene};
use rayon::prelude::*;

use crate::options::OrderError;
use crate::pieces::Ctx;
use broad::{Extent, Grid, LightView};
use volume::{clip, volume, Clip, SidePlanes, Source, Volume};

/// One shadow-casting light with its occluders' volumes and their broad phase.
struct Caster<K: Kernel> {
    /// The light's index in the scene.
    index: usize,
    source: Source<K::Point>,
    view: LightView,
    volumes: Vec<Volume<K::Plane>>,
    /// `None` when every occluder is a candidate of every receiver.
    grid: Option<Grid>,
}

/// The parts of one receiving piece: polygons that tile it, with the lights each one
/// is in the shadow of.
pub(crate) type Parts<P> = Vec<(P, LightSet)>;

/// How a receiver's cuts are kept until they are joined again.
enum Node<P> {
    /// A part, the lights it is in the shadow of, and its extent seen from the light
    /// being cast (`None`: not known, or no view).
    Leaf(P, LightSet, Option<Extent>),
    /// A polygon cut into parts that tile it, and its extent seen from the light being
    /// cast (a visit skips the parts when no volume can reach that extent).
    Cut(P, Vec<Node<P>>, Option<Extent>),
    /// Nothing: a node's place while it is rebuilt (never left in a tree).
    Taken,
}

/// Splits every piece of `order` along the shadows of the lights that ask for them
/// (faces of `illum 0` materials keep their colour and are not split). Returns one list
/// of parts per piece, in order.
pub(crate) fn shadow_parts<K: Kernel>(
    ctx: &Ctx<'_, K>,
    scene: &Scene,
    order: &[u32],
) -> Result<Vec<Parts<K::Polygon>>, OrderError> {
    let casters = casters(ctx.k, scene)?;
    let lit: Vec<bool> = scene
        .faces
        .iter()
        .map(|f| scene.materials[f.material as usize].illum >= 1)
        .collect();
    order
        .par_iter()
        .map_init(
            || (Vec::new(), Vec::new(), Vec::new()),
            |(seen, cand, corners), &id| {
                let piece = &ctx.pieces[id as usize];
                if !lit[piece.face as usize] {
                    return Ok(vec![(piece.poly.clone(), LightSet::EMPTY)]);
                }
                let seen_side = if piece.eye_front {
                    Side::Front
                } else {
                    Side::Back
                };
                let mut node = Node::Leaf(piece.poly.clone(), LightSet::EMPTY, None);
                for c in &casters {
                    if c.source.side(ctx.k, &piece.plane) != seen_side {
                        node.visit(&|_| false, &mut |_, s, _| {
                            s.insert(c.index);
                            None
                        });
                        continue;
                    }
                    let extent = |p: &K::Polygon, corners: &mut Vec<DVec3>| {
                        corners.clear();
                        ctx.k.vertices_world(p, corners);
                        c.view.extent(corners)
                    };
                    // Every leaf's extent from this light (cuts made for an earlier light
                    // have none from this one).
                    node.forget_cut_extents();
                    node.visit(&|_| false, &mut |p, _, e| {
                        *e = extent(p, corners);
                        None
                    });
                    let whole = extent(&piece.poly, corners);
                    match (&c.grid, whole) {
                        (Some(grid), Some(e)) => grid.candidates(&e, seen, cand),
                        _ => {
                            cand.clear();
                            cand.extend(0..c.volumes.len() as u32);
                        }
                    }
                    for &q in cand.iter() {
                        let vol = &c.volumes[q as usize];
                        let ve = c.grid.as_ref().map(|g| (g, g.extent(q)));
                        let skip = |e: &Extent| ve.is_some_and(|(g, ve)| !g.may_shadow(ve, e));
                        node.visit(&skip, &mut |p, s, e| {
                            if s.contains(c.index) {
                                return None;
                            }
                            if let (Some((g, ve)), Some(e)) = (ve, e.as_ref()) {
                                if !g.may_shadow(ve, e) {
                                    return None;
                                }
                            }
                            match clip(ctx.k, p, vol) {
                                Clip::Outside => None,
                                Clip::Inside => {
                                    s.insert(c.index);
                                    None
                                }
                                Clip::Split { inside, outside } => {
                                    let mut kids: Vec<Node<K::Polygon>> = outside
                                        .into_iter()
                                        .map(|o| {
                                            let e = extent(&o, corners);
                                            Node::Leaf(o, *s, e)
                                        })
                                        .collect();
                                    kids.push(Node::Leaf(inside, s.with(c.index), None));
                                    Some(kids)
                                }
                            }
                        });
                    }
                    node.join();
                }
                let mut parts = Vec::new();
                node.into_parts(&mut parts);
                Ok(parts)
            },
        )
        .collect()
}

/// The shadow-casting lights of `scene` with their occluders (every polygon of every
/// opaque face).
fn casters<K: Kernel>(k: &K, scene: &Scene) -> Result<Vec<Caster<K>>, OrderError> {
    let shadow_lights = scene.shadow_lights();
    if shadow_lights.is_empty() {
        return Ok(Vec::new());
    }
    // The occluders: opaque faces' convex polygons (their corners are input points).
    let polys: Vec<K::Polygon> = scene
        .faces
        .par_iter()
        .enumerate()
        .filter(|(_, f)| scene.materials[f.material as usize].is_opaque())
        .map(|(i, _)| k.face_polygons(&scene.face_points(i as u32)))
        .collect::<Result<Vec<_>, _>>()?
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
        for poly in &polys {
            if let Some(v) = volume(k, poly, &source, &mut corners, &mut shared)? {
                built.push((v, view.extent(&corners)));
            }
        }
        let grid = if built.iter().all(|(_, e)| e.is_some()) {
            Some(Grid::new(built.iter().filter_map(|(_, e)| *e).collect()))
        } else {
            None
        };
        out.push(Caster {
            index,
            source,
            view,
            volumes: built.into_iter().map(|(v, _)| v).collect(),
            grid,
        });
    }
    Ok(out)
}

impl<P> Node<P> {
    /// Calls `f` on every leaf (its polygon, lights and extent, which `f` may change);
    /// a leaf for which `f` returns parts becomes a cut into them.
    /// Cuts whose extent `skip` rejects are not entered.
    fn visit(
        &mut self,
        skip: &impl Fn(&Extent) -> bool,
        f: &mut impl FnMut(&P, &mut LightSet, &mut Option<Extent>) -> Option<Vec<Node<P>>>,
    ) {
        match self {
            Node::Cut(_, _, Some(e)) if skip(e) => {}
            Node::Cut(_, kids, _) => {
                kids.iter_mut().for_each(|k| k.visit(skip, f));
                // Parts that now agree are joined at once, so the tree stays as small as
                // the shadows' boundaries make it.
                self.join_here();
            }
            Node::Taken => {}
            Node::Leaf(p, s, e) => {
                if let Some(kids) = f(p, s, e) {
                    if let Node::Leaf(p, _, e) = std::mem::replace(self, Node::Taken) {
                        *self = Node::Cut(p, kids, e);
                    }
                }
            }
        }
    }

    /// Drops the extents of every cut (they were seen from another light).
    fn forget_cut_extents(&mut self) {
        if let Node::Cut(_, kids, e) = self {
            *e = None;
            kids.iter_mut().for_each(Node::forget_cut_extents);
        }
    }

    /// Joins cut polygons whose parts all ended up with the same lights again.
    fn join(&mut self) {
        if let Node::Cut(_, kids, _) = self {
            kids.iter_mut().for_each(Node::join);
        }
        self.join_here();
    }

    /// Joins this cut when its parts are leaves with the same lights.
    fn join_here(&mut self) {
        let Node::Cut(_, kids, _) = self else {
            return;
        };
        let first = match &kids[0] {
            Node::Leaf(_, s, _) => *s,
            _ => return,
        };
        if kids
            .iter()
            .all(|k| matches!(k, Node::Leaf(_, t, _) if *t == first))
        {
            if let Node::Cut(p, ..) = std::mem::replace(self, Node::Taken) {
                *self = Node::Leaf(p, first, None);
            }
        }
    }

    /// The leaves, in order.
    fn into_parts(self, out: &mut Vec<(P, LightSet)>) {
        match self {
            Node::Leaf(p, s, _) => out.push((p, s)),
            Node::Cut(_, kids, _) => kids.into_iter().for_each(|k| k.into_parts(out)),
            Node::Taken => {}
        }
    }
}
