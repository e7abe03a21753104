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
use volume::{clip, volume, Clip, Source, Volume};

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
    Leaf(P, LightSet),
    /// A polygon cut into parts that tile it.
    Cut(P, Vec<Node<P>>),
}

/// Splits every piece of `order` along the shadows of the lights that ask for them
/// (`lit` says, per face, whether its material is lit at all: `illum 0` faces keep their
/// colour and are not split). Returns one list of parts per piece, in order, and the
/// number of exact clips made.
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
                let mut node = Node::Leaf(piece.poly.clone(), LightSet::EMPTY);
                for c in &casters {
                    if c.source.side(ctx.k, &piece.plane) != seen_side {
                        node = node.map_leaves(&mut |p, s| Node::Leaf(p, s.with(c.index)));
                        continue;
                    }
                    corners.clear();
                    ctx.k.vertices_world(&piece.poly, corners);
                    match (&c.grid, c.view.extent(corners)) {
                        (Some(grid), Some(e)) => grid.candidates(&e, seen, cand),
                        _ => {
                            cand.clear();
                            cand.extend(0..c.volumes.len() as u32);
                        }
                    }
                    for &q in cand.iter() {
                        let vol = &c.volumes[q as usize];
                        node = node.map_leaves(&mut |p, s| {
                            if s.contains(c.index) {
                                return Node::Leaf(p, s);
                            }
                            match clip(ctx.k, &p, vol) {
                                Clip::Outside => Node::Leaf(p, s),
                                Clip::Inside => Node::Leaf(p, s.with(c.index)),
                                Clip::Split { inside, outside } => {
                                    let mut kids: Vec<Node<K::Polygon>> =
                                        outside.into_iter().map(|o| Node::Leaf(o, s)).collect();
                                    kids.push(Node::Leaf(inside, s.with(c.index)));
                                    Node::Cut(p, kids)
                                }
                            }
                        });
                    }
                    node = node.joined();
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
        let built: Vec<(Volume<K::Plane>, Option<Extent>)> = polys
            .par_iter()
            .map_init(Vec::new, |corners, poly| {
                Ok(volume(k, poly, &source, corners)?.map(|v| (v, view.extent(corners))))
            })
            .collect::<Result<Vec<_>, OrderError>>()?
            .into_iter()
            .flatten()
            .collect();
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
    /// Replaces every leaf by what `f` makes of it.
    fn map_leaves(self, f: &mut impl FnMut(P, LightSet) -> Node<P>) -> Node<P> {
        match self {
            Node::Leaf(p, s) => f(p, s),
            Node::Cut(p, kids) => Node::Cut(p, kids.into_iter().map(|k| k.map_leaves(f)).collect()),
        }
    }

    /// Joins cut polygons whose parts all ended up with the same lights again.
    fn joined(self) -> Node<P> {
        match self {
            Node::Leaf(..) => self,
            Node::Cut(p, kids) => {
                let kids: Vec<Node<P>> = kids.into_iter().map(Node::joined).collect();
                let first = match &kids[0] {
                    Node::Leaf(_, s) => Some(*s),
                    Node::Cut(..) => None,
                };
                match first {
                    Some(s)
                        if kids
                            .iter()
                            .all(|k| matches!(k, Node::Leaf(_, t) if *t == s)) =>
                    {
                        Node::Leaf(p, s)
                    }
                    _ => Node::Cut(p, kids),
                }
            }
        }
    }

    /// The leaves, in order.
    fn into_parts(self, out: &mut Vec<(P, LightSet)>) {
        match self {
            Node::Leaf(p, s) => out.push((p, s)),
            Node::Cut(_, kids) => kids.into_iter().for_each(|k| k.into_parts(out)),
        }
    }
}
