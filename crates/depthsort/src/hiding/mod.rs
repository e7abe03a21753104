//! Exact hiding in object space: each ordered piece split along the boundaries of what
//! opaque faces hide from a source, the shadows each shadow-casting light throws on it
//! and, for the visible map, what the eye cannot see of it; each part knows what it is
//! hidden from.
//!
//! A point of a receiving piece is hidden from a source when the source does not lie
//! strictly on the side of the piece's plane the eye sees (the seen side faces away
//! from it), or when the segment from the point to the source crosses an occluder (the
//! point lies inside that occluder's volume, see [`volume`]). A light's occluders are
//! the scene's opaque faces as given ([`lights`]); the eye's are the opaque polygons the
//! painter draws ([`sight`]). Their corners are input points, so every plane of every
//! volume is defined by input points and the source, and every cut is exact (implicit
//! vertices, no epsilon, no snap, no bias). The cuts of one piece are kept as a tree:
//! where every part of a cut piece ends up hidden from the same sources, the piece is
//! joined again exactly (it is its parent), so a face is split only along the
//! boundaries of what hides it.
//!
//! The parts of a piece tile it and are painted in its place in the order, so the order
//! stays valid; parts hidden from the eye are dropped. Which occluders can touch a
//! receiver is found in a float view from the source ([`broad`]), a prefilter with
//! margins.

mod broad;
mod lights;
mod sight;
mod volume;

use glam::DVec3;
use limn_kernel::{Kernel, Side};
use limn_scene::{LightSet, Scene};
use rayon::prelude::*;

use crate::options::OrderError;
use crate::pieces::Ctx;
use broad::{Extent, Grid, LightView};
use volume::{clip, reach, Clip, Reach, Source, Volume};

pub(crate) use sight::{Occluders, Sight};

/// What a source is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Who {
    /// The light of this index in the scene, casting shadows.
    Light(usize),
    /// The eye: what it cannot see is dropped.
    Eye,
}

/// What a part is hidden from: the eye (then it is not drawn) and the lights it is in
/// the shadow of.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct Hidden {
    /// The eye cannot see it.
    pub from_eye: bool,
    /// The lights it is in the shadow of.
    pub lights: LightSet,
}

impl Hidden {
    fn contains(self, who: Who) -> bool {
        match who {
            Who::Light(i) => self.lights.contains(i),
            Who::Eye => self.from_eye,
        }
    }

    fn insert(&mut self, who: Who) {
        match who {
            Who::Light(i) => self.lights.insert(i),
            Who::Eye => self.from_eye = true,
        }
    }

    fn with(mut self, who: Who) -> Hidden {
        self.insert(who);
        self
    }
}

/// One source with its occluders' volumes and their broad phase.
struct Caster<K: Kernel> {
    who: Who,
    source: Source<K::Point>,
    view: LightView,
    volumes: Vec<Volume<K::Plane>>,
    grid: Grid,
}

impl<K: Kernel> Caster<K> {
    /// A caster of `volumes`, each with its extent seen in `view` (binned).
    fn new(
        who: Who,
        source: Source<K::Point>,
        view: LightView,
        built: Vec<(Volume<K::Plane>, Option<Extent>)>,
    ) -> Caster<K> {
        let grid = Grid::new(built.iter().map(|(_, e)| *e).collect());
        Caster {
            who,
            source,
            view,
            volumes: built.into_iter().map(|(v, _)| v).collect(),
            grid,
        }
    }
}

/// The parts of one receiving piece: polygons that tile it, with what each one is
/// hidden from.
pub(crate) type Parts<P> = Vec<(P, Hidden)>;

/// What [`hidden_parts`] returns.
pub(crate) struct Split<P> {
    /// One list of parts per piece, in order.
    pub parts: Vec<Parts<P>>,
    /// Whether every polygon the painter draws of an opaque face hid from the eye
    /// (`false` when one cut by the near plane in view hid nothing; `true` without the
    /// eye).
    pub complete: bool,
}

/// How a receiver's cuts are kept until they are joined again.
enum Node<P> {
    /// A part, what it is hidden from, and its extent seen from the source being cast
    /// (`None`: not known, or no view).
    Leaf(P, Hidden, Option<Extent>),
    /// A polygon cut into parts that tile it, and its extent seen from the source being
    /// cast (a visit skips the parts when no volume can reach that extent).
    Cut(P, Vec<Node<P>>, Option<Extent>),
    /// Nothing: a node's place while it is rebuilt (never left in a tree).
    Taken,
}

/// Splits every piece of `order` along what hides it: from the eye when `sight` is
/// given (every piece, or only translucent ones when it says so), and the shadows of
/// the lights that ask for them (faces of `illum 0` materials keep their colour and are
/// not split by shadows; parts the eye cannot see are not split further).
pub(crate) fn hidden_parts<K: Kernel>(
    ctx: &Ctx<'_, K>,
    scene: &Scene,
    order: &[u32],
    sight: Option<&Sight>,
) -> Result<Split<K::Polygon>, OrderError> {
    let mut complete = true;
    let mut casters = match sight {
        Some(s) => {
            let (eye, all) = s.caster(ctx, scene)?;
            complete = all;
            vec![eye]
        }
        None => Vec::new(),
    };
    // Per face, whether the eye splits its pieces.
    let seen_by_eye: Vec<bool> = scene
        .faces
        .iter()
        .map(|f| {
            sight.is_some_and(|s| {
                matches!(s.occluders, Occluders::All)
                    || !scene.materials[f.material as usize].is_opaque()
            })
        })
        .collect();
    casters.extend(lights::casters(ctx.k, scene)?);
    // Per face, the position of its last piece in an exact order (`None`: not in the
    // order, or the order not exact): a face can hide from the eye only pieces painted
    // before one of its own.
    let mut last: Vec<Option<u32>> = vec![None; scene.faces.len()];
    if sight.is_some_and(|s| s.order_exact) {
        for (pos, &id) in order.iter().enumerate() {
            last[ctx.pieces[id as usize].face as usize] = Some(pos as u32);
        }
    }
    let lit: Vec<bool> = scene
        .faces
        .iter()
        .map(|f| scene.materials[f.material as usize].illum >= 1)
        .collect();
    order
        .par_iter()
        .enumerate()
        .map_init(
            || (Vec::new(), Vec::new()),
            |(cand, corners), (pos, &id)| {
                let piece = &ctx.pieces[id as usize];
                let seen_side = if piece.eye_front {
                    Side::Front
                } else {
                    Side::Back
                };
                let mut node = Node::Leaf(piece.poly.clone(), Hidden::default(), None);
                for c in &casters {
                    if matches!(&node, Node::Leaf(_, s, _) if s.from_eye) {
                        break; // the eye sees none of it: no shadow to split
                    }
                    if c.who == Who::Eye && !seen_by_eye[piece.face as usize] {
                        continue;
                    }
                    if let Who::Light(_) = c.who {
                        if !lit[piece.face as usize] {
                            continue;
                        }
                        if c.source.side(ctx.k, ctx.k.support(&piece.poly)) != seen_side {
                            node.visit(&|_| false, &mut |_, s, _| {
                                if !s.from_eye {
                                    s.insert(c.who);
                                }
                                None
                            });
                            continue;
                        }
                    }
                    let painted_after = |vol: &Volume<K::Plane>| {
                        c.who != Who::Eye || last[vol.face as usize].is_none_or(|l| l > pos as u32)
                    };
                    cast(
                        ctx,
                        c,
                        (piece.face, &piece.poly, &painted_after),
                        &mut node,
                        (cand, corners),
                    );
                }
                let mut parts = Vec::new();
                node.into_parts(&mut parts);
                Ok(parts)
            },
        )
        .collect::<Result<Vec<_>, _>>()
        .map(|parts| Split { parts, complete })
}

/// The largest half-width, relative to the largest coordinate, of the boxes a part's
/// extent is taken from (the broad phase's margins are a relative 1e-9).
const BOX_REL: f64 = 1e-10;

/// Which occluders' volumes may hide a receiver (the others are not tested).
type MayHide<'a, P> = &'a dyn Fn(&Volume<P>) -> bool;

/// Splits the parts of a receiver (`node`, a piece `whole` of face `face`) along the
/// volumes of caster `c` that `may_hide` lets through; parts already hidden from the
/// eye are left as they are.
fn cast<K: Kernel>(
    ctx: &Ctx<'_, K>,
    c: &Caster<K>,
    (face, whole, may_hide): (u32, &K::Polygon, MayHide<'_, K::Plane>),
    node: &mut Node<K::Polygon>,
    (cand, corners): (&mut Vec<u32>, &mut Vec<(DVec3, f64)>),
) {
    // The extent of a part from its corners' proven boxes where the kernel's cached
    // positions are that close (a prefilter needs no rounded corners); the corners
    // known less closely are rounded (their boxes then points), since wide boxes would
    // let fewer occluders be pruned.
    let extent = |p: &K::Polygon, corners: &mut Vec<(DVec3, f64)>| {
        corners.clear();
        let n = ctx.k.vertex_count(p);
        corners.extend((0..n).map_while(|i| {
            ctx.k
                .vertex_world_bounded(p, i)
                .filter(|(v, r)| *r <= BOX_REL * v.abs().max_element())
        }));
        if corners.len() < n {
            let mut rounded = Vec::with_capacity(n);
            ctx.k.vertices_world(p, &mut rounded);
            corners.clear();
            corners.extend(rounded.into_iter().map(|v| (v, 0.0)));
        }
        c.view.extent_of_boxes(corners)
    };
    // Every leaf's extent from this source (cuts made for an earlier source have none
    // from this one).
    node.forget_cut_extents();
    node.visit(&|_| false, &mut |p, _, e| {
        *e = extent(p, corners);
        None
    });
    let all = extent(whole, corners);
    match all {
        Some(e) => c.grid.candidates(&e, cand),
        None => {
            cand.clear();
            cand.extend(0..c.volumes.len() as u32);
        }
    }
    // In index order: seen from the eye, that is nearest first (see [`Sight`]), so what
    // the nearest occluders hide needs no cut by the occluders behind them. A light's
    // occluders stay in input order: sorted, the demo's shadow parts took 68 % more
    // bytes.
    cand.retain(|&q| may_hide(&c.volumes[q as usize]));
    // The painter's coplanar rule, seen from the eye: the later face wins.
    let coplanar_hidden = |vol: &Volume<K::Plane>| c.who == Who::Eye && face < vol.face;
    // A receiver not yet cut that one occluder hides whole is hidden without a cut (most
    // of what the eye cannot see, in a scene of many layers; one cut by an occluder that
    // hides only a part of it would leave parts to clip by every later candidate). Only
    // an occluder whose extent holds the receiver's can hide all of it; those of them
    // found to lie apart from it touch none of its parts and are dropped.
    if let Node::Leaf(p, s, e) = node {
        if !s.contains(c.who) && !s.from_eye {
            let may_cover = |q: u32| match (c.grid.extent(q), e.as_ref()) {
                (Some(o), Some(r)) => c.grid.may_cover(o, r),
                _ => true,
            };
            let mut covered = false;
            cand.retain(|&q| {
                if covered || !may_cover(q) {
                    return true;
                }
                let v = &c.volumes[q as usize];
                match reach(ctx.k, p, v, coplanar_hidden(v)) {
                    Reach::Covered => covered = true,
                    Reach::Apart => return false,
                    Reach::Across => {}
                }
                true
            });
            if covered {
                s.insert(c.who);
                return;
            }
        }
    }
    for &q in cand.iter() {
        let vol = &c.volumes[q as usize];
        let coplanar_hidden = coplanar_hidden(vol);
        let g = &c.grid;
        let ve = g.extent(q);
        let skip = |e: &Extent| ve.is_some_and(|ve| !g.may_hide(ve, e));
        node.visit(&skip, &mut |p, s, e| {
            if s.contains(c.who) || s.from_eye {
                return None;
            }
            if let (Some(ve), Some(e)) = (ve, e.as_ref()) {
                if !g.may_hide(ve, e) {
                    return None;
                }
            }
            match clip(ctx.k, p, vol, coplanar_hidden) {
                Clip::Outside => None,
                Clip::Inside => {
                    s.insert(c.who);
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
                    kids.push(Node::Leaf(inside, s.with(c.who), None));
                    Some(kids)
                }
            }
        });
    }
    node.join();
}

impl<P> Node<P> {
    /// Calls `f` on every leaf (its polygon, what hides it and its extent, which `f` may
    /// change);
    /// a leaf for which `f` returns parts becomes a cut into them.
    /// Cuts whose extent `skip` rejects are not entered.
    fn visit(
        &mut self,
        skip: &impl Fn(&Extent) -> bool,
        f: &mut impl FnMut(&P, &mut Hidden, &mut Option<Extent>) -> Option<Vec<Node<P>>>,
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

    /// Joins cut polygons whose parts all ended up hidden from the same sources again.
    fn join(&mut self) {
        if let Node::Cut(_, kids, _) = self {
            kids.iter_mut().for_each(Node::join);
        }
        self.join_here();
    }

    /// Joins this cut when its parts are leaves hidden from the same sources.
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
    fn into_parts(self, out: &mut Vec<(P, Hidden)>) {
        match self {
            Node::Leaf(p, s, _) => out.push((p, s)),
            Node::Cut(_, kids, _) => kids.into_iter().for_each(|k| k.into_parts(out)),
            Node::Taken => {}
        }
    }
}
