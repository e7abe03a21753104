//! Exact painter's ordering for limn: a back-to-front list of fragments such that painting
//! them in order gives the correct picture, for every scene — cyclic overlaps and
//! interpenetrating polygons included. The painters live in `limn-paint`.
//!
//! The pipeline: convert faces to kernel polygons; cull back faces (automatically for
//! closed opaque objects) and faces seen exactly edge-on; clip exactly at the near plane;
//! order ([`SortMode`]); join fragments of one face that end up next to each other.
//! Every decision about planes is made by a [`limn_kernel::Kernel`]: the exact kernel by
//! default, the float kernel for comparison ([`Arith`]).
//!
//! Coplanar overlapping faces have no right answer; limn's rule, in every mode: **the
//! later face in input order is painted last** (it wins).
//!
//! ```
//! use glam::DVec3;
//! use limn_depthsort::{order, OrderOptions};
//! use limn_scene::{Camera, Material, Scene};
//!
//! let mut scene = Scene::default();
//! let m = scene.add_material(Material::unlit("grey", [0.5, 0.5, 0.5]));
//! let o = scene.add_object("quads");
//! for z in [0.0, 1.0] {
//!     let q = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
//!     let c: Vec<DVec3> = q.iter().map(|p| DVec3::new(p[0], p[1], z)).collect();
//!     scene.add_polygon(&c, m, o).unwrap();
//! }
//! let camera = Camera::new(DVec3::new(0.5, 0.5, 5.0), DVec3::new(0.5, 0.5, 0.0), 100, 100);
//! let out = order(&scene, &camera, &OrderOptions::default()).unwrap();
//! // The far quad (face 0) is painted first, the near one (face 1) last.
//! let faces: Vec<u32> = out.fragments.iter().map(|f| f.face).collect();
//! assert_eq!(faces, vec![0, 1]);
//! ```

mod adaptive;
mod broad;
mod bsp;
mod by_vertex;
mod coincident;
mod components;
mod detached;
mod eye;
mod face_runs;
mod feature_edges;
mod geom;
mod hiding;
mod marks;
mod merge;
mod meshed;
mod newell;
mod occlusion;
mod options;
mod partition;
mod pieces;
mod piercing;
mod prepare;
mod probe;
mod rng;
mod separation;
mod simple;
mod split_apart;
mod sweep;
#[cfg(test)]
mod test_scenes;
mod translucent_last;
mod view;

use std::time::Instant;

use glam::DVec3;
use limn_kernel::{ExactKernel, FloatKernel, Kernel};
use limn_scene::{Camera, LightSet, Scene};
use rayon::prelude::*;

pub use crate::feature_edges::{feature_edges, EdgeKind, FeatureEdge};
pub use crate::marks::{
    hide_marks, order_with_marks, MarkStats, VisibleAnchor, VisibleMarks, VisiblePiece,
};
pub use crate::options::{
    default_max_fragments, Arith, CullMode, OrderError, OrderOptions, SortMode, Stats,
};
use crate::pieces::Ctx;

/// One output fragment: a convex piece of one input face.
#[derive(Debug, Clone, PartialEq)]
pub struct Fragment {
    /// The input face (its index in [`Scene::faces`]).
    pub face: u32,
    /// Vertices in pixel coordinates (x right, y down), in order.
    pub points: Vec<[f64; 2]>,
    /// Vertices in world coordinates (rounded from the exact representation once).
    pub world: Vec<DVec3>,
    /// Per edge `i` (vertex `i` to `i + 1`): does it lie on an edge of the input face?
    pub original_edges: Vec<bool>,
    /// The lights (indices into [`Scene::lights`]) this fragment is in the shadow of;
    /// always empty unless some light casts shadows (see [`Scene::shadow_lights`]).
    pub shadowed: LightSet,
}

/// The result of [`order`]: fragments back to front.
#[derive(Debug, Clone)]
pub struct Ordered {
    /// Fragments in painting order (back to front).
    pub fragments: Vec<Fragment>,
    /// What the ordering did.
    pub stats: Stats,
    /// The camera actually used (the one given: no kernel moves the eye).
    pub camera: Camera,
    /// Near plane distance used for clipping.
    pub near: f64,
    /// Far plane distance (for projections; the painter does not clip there).
    pub far: f64,
    /// Per input face: whether all of it takes part in the order, unclipped, not culled
    /// and with one facing, so that its projected outline is exactly the union of its
    /// fragments (painters may then paint the whole face in place of its first fragment).
    pub whole_faces: Vec<bool>,
    /// Per object: whether its back faces were culled (every object with
    /// [`CullMode::On`], none with [`CullMode::Off`], the closed opaque ones with
    /// [`CullMode::Auto`]), so that a reference can cull the same.
    pub culled_objects: Vec<bool>,
    /// Per input face: whether it was culled when seen from the back (every face with
    /// [`CullMode::On`], none with [`CullMode::Off`], with [`CullMode::Auto`] the faces
    /// of closed opaque shells: the closed opaque objects' and those of the closed
    /// opaque parts of other objects), so that a reference can cull the same.
    pub culled_faces: Vec<bool>,
    /// Whether the fragments are the visible map ([`OrderOptions::visible`]): hidden parts
    /// left out, so that the opaque fragments of different faces never overlap.
    pub visible: bool,
}

/// Orders `scene` as seen by `camera` with the kernel and mode of `opts`.
pub fn order(scene: &Scene, camera: &Camera, opts: &OrderOptions) -> Result<Ordered, OrderError> {
    validate(scene, camera)?;
    let Some((lo, hi)) = scene.bounds() else {
        return Ok(empty(scene, camera));
    };
    match opts.arith {
        Arith::Exact => ordered(&ExactKernel::new(), scene, camera, opts, false).map(|(o, _)| o),
        Arith::Float => {
            ordered(&FloatKernel::new(lo, hi)?, scene, camera, opts, false).map(|(o, _)| o)
        }
    }
}

/// Orders `scene` with an explicit kernel (for the float kernel, the scene's bounds must
/// lie inside its domain).
pub fn order_with<K: Kernel>(
    kernel: &K,
    scene: &Scene,
    camera: &Camera,
    opts: &OrderOptions,
) -> Result<Ordered, OrderError> {
    validate(scene, camera)?;
    ordered(kernel, scene, camera, opts, false).map(|(o, _)| o)
}

/// Like [`order_with`], and also returns the kernel polygon of every fragment (same
/// positions as [`Ordered::fragments`]), for exact checks.
pub fn order_polygons<K: Kernel>(
    kernel: &K,
    scene: &Scene,
    camera: &Camera,
    opts: &OrderOptions,
) -> Result<(Ordered, Vec<K::Polygon>), OrderError> {
    validate(scene, camera)?;
    ordered(kernel, scene, camera, opts, true)
}

/// The input checks every entry point makes once.
fn validate(scene: &Scene, camera: &Camera) -> Result<(), OrderError> {
    scene.validate()?;
    camera.validate()?;
    Ok(())
}

/// The result for a scene without faces.
fn empty(scene: &Scene, camera: &Camera) -> Ordered {
    let (near, far) = camera.near_far(scene);
    Ordered {
        fragments: Vec::new(),
        stats: Stats::default(),
        camera: *camera,
        near,
        far,
        whole_faces: vec![false; scene.faces.len()],
        culled_objects: vec![false; scene.objects.len()],
        culled_faces: vec![false; scene.faces.len()],
        visible: false,
    }
}

/// The pipeline on validated input: prepare, order, merge, build the fragments (and,
/// when `with_polygons`, copies of their kernel polygons; otherwise the vector is empty).
fn ordered<K: Kernel>(
    kernel: &K,
    scene: &Scene,
    camera: &Camera,
    opts: &OrderOptions,
    with_polygons: bool,
) -> Result<(Ordered, Vec<K::Polygon>), OrderError> {
    let t0 = Instant::now();
    let fallbacks0 = kernel.fallbacks();
    let eye = eye::Eye::of(kernel, camera)?;
    let (near, far) = camera.near_far(scene);
    let vp = camera.view_projection(near, far);
    // The depth margin's scale: the far distance, or device depth's range.
    let depth_scale = if camera.is_perspective() { far } else { 1.0 };
    let mut ctx = Ctx::new(kernel, eye, *camera, vp, depth_scale, opts.seed);
    let limit = opts
        .max_fragments
        .unwrap_or_else(|| default_max_fragments(scene.faces.len()));
    ctx.limit = limit;
    let prepare::PreparedFaces {
        items,
        whole: mut whole_faces,
        culled_objects,
        culled_faces,
    } = prepare::prepare(&mut ctx, scene, opts.cull, near)?;
    let t1 = Instant::now();
    let order = sort(&mut ctx, items, opts);
    if ctx.exceeded {
        return Err(OrderError::TooManyFragments {
            limit,
            faces: scene.faces.len(),
        });
    }
    ctx.stats.fragments_made = ctx.pieces.len();
    ctx.stats.fragment_limit = limit;
    let t2 = Instant::now();
    ctx.stats.fragments_before_merge = order.len();
    let order = if opts.merge {
        merge::merge(&ctx, &order)
    } else {
        order
    };
    let hides_translucent =
        translucent_last::occluders(scene, opts, |id| ctx.pieces[id as usize].face, &order);
    let translucent_last = hides_translucent.is_some();
    let sight = (opts.visible || translucent_last).then(|| hiding::Sight {
        culled_objects: culled_objects.clone(),
        near,
        order_exact: opts.sort != SortMode::Simple && opts.arith == Arith::Exact,
        occluders: if opts.visible {
            hiding::Occluders::All
        } else {
            hiding::Occluders::OfTranslucent(hides_translucent.unwrap_or_default())
        },
    });
    let parts = if scene.shadow_lights().is_empty() && sight.is_none() {
        None
    } else {
        let t = Instant::now();
        let parts = hiding::hidden_parts(&ctx, scene, &order, sight.as_ref())?;
        let ms = t.elapsed().as_secs_f64() * 1e3;
        if sight.is_some() {
            ctx.stats.ms_visible = ms;
        } else {
            ctx.stats.ms_shadows = ms;
        }
        Some(parts)
    };
    let (fragments, polys) = match parts {
        None => {
            // The pieces' projected points are not read again (a fragment's are computed
            // again from its corners): released first.
            ctx.pieces
                .par_iter_mut()
                .with_min_len(FRAGMENTS_PER_TASK)
                .for_each(|p| p.pts = Box::default());
            fragments(&mut ctx, &order, with_polygons)
        }
        Some(hiding::Split { parts, complete }) => {
            let mut items: Vec<PieceParts<K::Polygon>> = order
                .iter()
                .zip(parts)
                .map(|(&id, parts)| (ctx.pieces[id as usize].face, (id, parts)))
                .collect();
            if translucent_last && complete {
                translucent_last::opaque_first(scene, &mut items);
            }
            part_fragments(&mut ctx, items, &mut whole_faces)
        }
    };
    let t3 = Instant::now();
    let mut stats = ctx.stats;
    stats.fragments_out = fragments.len();
    stats.filter_fallbacks = kernel.fallbacks() - fallbacks0;
    stats.ms_prepare = (t1 - t0).as_secs_f64() * 1e3;
    stats.ms_order = (t2 - t1).as_secs_f64() * 1e3;
    stats.ms_merge = (t3 - t2).as_secs_f64() * 1e3 - stats.ms_shadows - stats.ms_visible;
    let ordered = Ordered {
        fragments,
        stats,
        camera: *camera,
        near,
        far,
        whole_faces,
        culled_objects,
        culled_faces,
        visible: opts.visible,
    };
    Ok((ordered, polys))
}

/// Runs the ordering `opts.sort` asks for on the prepared pieces.
fn sort<K: Kernel>(ctx: &mut Ctx<'_, K>, items: Vec<u32>, opts: &OrderOptions) -> Vec<u32> {
    let candidates = opts.candidates.max(1);
    match opts.sort {
        SortMode::Simple => simple::simple(ctx, items),
        SortMode::Bsp => bsp::bsp(ctx, items, candidates),
        SortMode::Newell => newell::newell(ctx, items, candidates),
        SortMode::Adaptive => adaptive::adaptive(ctx, items, candidates),
    }
}

/// The output fragments of the pieces in `order` (built in parallel, in order), and
/// copies of their kernel polygons when `with_polygons` (else an empty vector). The
/// pieces are released on the way: what a fragment keeps of its piece (its corners,
/// rounded once, and which edges are original) is taken first, in flat blocks, then the
/// pieces go, then the fragments are made. Made beside the pieces, a million-face
/// ordering's fragments (about 110 MB) met its pieces (about 270 MB) at the highest
/// point of its memory.
fn fragments<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    order: &[u32],
    with_polygons: bool,
) -> (Vec<Fragment>, Vec<K::Polygon>) {
    let blocks: Vec<Corners> = order
        .par_chunks(FRAGMENTS_PER_TASK)
        .map(|ids| Corners::of(ctx, ids))
        .collect();
    let polys = if with_polygons {
        order
            .iter()
            .map(|&id| ctx.pieces[id as usize].poly.clone())
            .collect()
    } else {
        Vec::new()
    };
    ctx.pieces = Vec::new();
    let ctx = &*ctx;
    let fragments = (0..order.len())
        .into_par_iter()
        .with_min_len(FRAGMENTS_PER_TASK)
        .map(|i| {
            let block = &blocks[i / FRAGMENTS_PER_TASK];
            let k = i % FRAGMENTS_PER_TASK;
            let corners = block.ends[k] as usize..block.ends[k + 1] as usize;
            let world = block.world[corners.clone()].to_vec();
            // The piece's projected points, computed again as `Ctx::piece` computed
            // them (the same bits) instead of copied.
            let points = world
                .iter()
                .map(|&w| {
                    let pr = ctx.camera.project_with(&ctx.vp, w);
                    [pr.x, pr.y]
                })
                .collect();
            Fragment {
                face: block.faces[k],
                points,
                world,
                original_edges: block.original[corners].to_vec(),
                shadowed: LightSet::EMPTY,
            }
        })
        .collect();
    (fragments, polys)
}

/// What the fragments of a block of pieces keep of them: each piece's face, its corners
/// in world coordinates (rounded from the exact representation once) and whether each
/// edge lies on an edge of the input face, one after another.
struct Corners {
    faces: Vec<u32>,
    world: Vec<DVec3>,
    original: Vec<bool>,
    /// Where each piece's corners start in `world` and `original`, and the end.
    ends: Vec<u32>,
}

impl Corners {
    /// The corners of the pieces `ids`.
    fn of<K: Kernel>(ctx: &Ctx<'_, K>, ids: &[u32]) -> Corners {
        let mut c = Corners {
            faces: Vec::with_capacity(ids.len()),
            world: Vec::with_capacity(3 * ids.len()),
            original: Vec::with_capacity(3 * ids.len()),
            ends: Vec::with_capacity(ids.len() + 1),
        };
        c.ends.push(0);
        for &id in ids {
            let p = &ctx.pieces[id as usize];
            let start = c.world.len();
            ctx.k.vertices_world(&p.poly, &mut c.world);
            c.original
                .extend((0..c.world.len() - start).map(|i| ctx.k.edge_is_original(&p.poly, i)));
            c.faces.push(p.face);
            c.ends.push(c.world.len() as u32);
        }
        c
    }
}

/// A piece's face, and the piece's id with its parts.
type PieceParts<P> = (u32, (u32, hiding::Parts<P>));

/// Fragments built by one parallel task at least (smaller tasks cost more to hand out
/// than they save).
const FRAGMENTS_PER_TASK: usize = 1024;

/// [`fragments`] of the pieces of `items` (each piece's face, its id and its parts, in
/// paint order), each piece replaced by its parts: the parts the eye cannot see left out (their faces are then not whole), the others with
/// the lights they are in the shadow of.
fn part_fragments<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    items: Vec<PieceParts<K::Polygon>>,
    whole_faces: &mut [bool],
) -> (Vec<Fragment>, Vec<K::Polygon>) {
    let mut fragments = Vec::with_capacity(items.len());
    let mut polys = Vec::with_capacity(items.len());
    let mut scratch = Vec::new();
    for (_, (id, parts)) in items {
        let (face, eye_front) = {
            let p = &ctx.pieces[id as usize];
            (p.face, p.eye_front)
        };
        for (poly, hidden) in parts {
            if hidden.from_eye {
                ctx.stats.fragments_hidden += 1;
                whole_faces[face as usize] = false;
                continue;
            }
            let piece = ctx.piece(poly, face, id, Some(eye_front), &mut scratch);
            let original_edges = (0..scratch.len())
                .map(|i| ctx.k.edge_is_original(&piece.poly, i))
                .collect();
            if !hidden.lights.is_empty() {
                ctx.stats.fragments_in_shadow += 1;
            }
            fragments.push(Fragment {
                face,
                points: piece.pts.into_vec(),
                world: std::mem::take(&mut scratch),
                original_edges,
                shadowed: hidden.lights,
            });
            polys.push(piece.poly);
        }
    }
    (fragments, polys)
}
