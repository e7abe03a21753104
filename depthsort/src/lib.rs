//! Exact painter's ordering for limn: a back-to-front list of fragments such that painting
//! them in order gives the correct picture, for every scene — cyclic overlaps and
//! interpenetrating polygons included — plus the painter backends.
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
mod ctx;
mod geom;
mod merge;
mod newell;
mod options;
pub mod paint;
mod partition;
mod picture;
mod prepare;
mod shared;

use std::time::Instant;

use glam::DVec3;
use limn_kernel::{ExactKernel, FloatKernel};
use limn_scene::{Camera, Scene};

use crate::ctx::Ctx;
pub use crate::options::{Arith, CullMode, OrderError, OrderOptions, SortMode, Stats};
pub use crate::picture::{picture, seam_flaps, Style};
pub use crate::shared::ExactVertices;

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
    /// The eye sees the front of the face (its vertices run counter-clockwise).
    pub front_facing: bool,
    /// Set on the first fragment painted of an input polygon that was split: the whole
    /// polygon. Painting it instead of the fragment gives the same picture for an opaque
    /// face (every later piece is painted again, on top, at its own place in the order,
    /// and whatever comes in between and overlaps a later piece lies behind it), but the
    /// cut edges of the later pieces then fall on the face's own colour: no seam.
    pub cover: Option<Cover>,
}

/// A whole input polygon to paint in place of its first fragment (see
/// [`Fragment::cover`]).
#[derive(Debug, Clone, PartialEq)]
pub struct Cover {
    /// Vertices in pixel coordinates.
    pub points: Vec<[f64; 2]>,
    /// Per edge: does it lie on an edge of the input face?
    pub original_edges: Vec<bool>,
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
}

/// Orders `scene` as seen by `camera` with the kernel and mode of `opts`.
pub fn order(scene: &Scene, camera: &Camera, opts: &OrderOptions) -> Result<Ordered, OrderError> {
    scene.validate()?;
    camera.validate()?;
    let Some((lo, hi)) = scene.bounds() else {
        let (near, far) = camera.near_far(scene);
        return Ok(Ordered {
            fragments: Vec::new(),
            stats: Stats::default(),
            camera: *camera,
            near,
            far,
        });
    };
    match opts.arith {
        Arith::Exact => order_with(&ExactKernel::new(), scene, camera, opts),
        Arith::Float => order_with(&FloatKernel::new(lo, hi)?, scene, camera, opts),
    }
}

/// Orders `scene` with an explicit kernel (the scene's bounds must lie inside the
/// kernel's domain).
pub fn order_with<K: ExactVertices>(
    kernel: &K,
    scene: &Scene,
    camera: &Camera,
    opts: &OrderOptions,
) -> Result<Ordered, OrderError> {
    order_polygons(kernel, scene, camera, opts).map(|(o, _)| o)
}

/// Like [`order_with`], and also returns the kernel polygon of every fragment (same
/// positions as [`Ordered::fragments`]), for exact checks.
pub fn order_polygons<K: ExactVertices>(
    kernel: &K,
    scene: &Scene,
    camera: &Camera,
    opts: &OrderOptions,
) -> Result<(Ordered, Vec<K::Polygon>), OrderError> {
    scene.validate()?;
    camera.validate()?;
    let t0 = Instant::now();
    let fallbacks0 = kernel.fallbacks();
    let eye = kernel.point(camera.eye)?;
    let mut cam = *camera;
    cam.eye = kernel.point_world(&eye);
    cam.validate()?;
    let (near, far) = cam.near_far(scene);
    let vp = cam.view_projection(near, far);
    let mut ctx = Ctx::new(kernel, eye, cam, vp, far, opts.seed);
    let (items, whole) = prepare::prepare(&mut ctx, scene, opts.cull, near)?;
    let t1 = Instant::now();
    let cands = opts.candidates.max(1);
    let order = match opts.sort {
        SortMode::Simple => {
            let mut v = items;
            v.sort_by(|&a, &b| {
                let (pa, pb) = (&ctx.pieces[a as usize], &ctx.pieces[b as usize]);
                pb.dmean.total_cmp(&pa.dmean).then(pa.face.cmp(&pb.face))
            });
            v
        }
        SortMode::Bsp => partition::bsp(&mut ctx, items, cands),
        SortMode::Newell => newell::newell(&mut ctx, items, cands),
        SortMode::Adaptive => adaptive::adaptive(&mut ctx, items, cands),
    };
    let t2 = Instant::now();
    ctx.stats.fragments_before_merge = order.len();
    let order = if opts.merge {
        merge::merge(&ctx, &order)
    } else {
        order
    };
    let mut fragments = Vec::with_capacity(order.len());
    let mut polys = Vec::with_capacity(order.len());
    let mut per_face = vec![0u32; scene.faces.len()];
    for &id in &order {
        per_face[ctx.pieces[id as usize].face as usize] += 1;
    }
    let mut covered = vec![false; scene.faces.len()];
    for id in order {
        let p = &ctx.pieces[id as usize];
        let f = p.face as usize;
        let cover = (whole[f] && per_face[f] > 1 && !std::mem::replace(&mut covered[f], true))
            .then(|| {
                let pts: Vec<[f64; 2]> = scene.faces[f]
                    .vertices
                    .iter()
                    .map(|&v| {
                        let pr = ctx.camera.project_with(&ctx.vp, scene.vertices[v as usize]);
                        [pr.x, pr.y]
                    })
                    .collect();
                Cover {
                    original_edges: vec![true; pts.len()],
                    points: pts,
                }
            });
        let mut world = Vec::with_capacity(p.pts.len());
        kernel.vertices_world(&p.poly, &mut world);
        let original_edges = (0..world.len())
            .map(|i| kernel.edge_is_original(&p.poly, i))
            .collect();
        fragments.push(Fragment {
            face: p.face,
            points: p.pts.clone(),
            world,
            original_edges,
            front_facing: p.eye_front,
            cover,
        });
        polys.push(p.poly.clone());
    }
    let t3 = Instant::now();
    let mut stats = ctx.stats;
    stats.fragments_out = fragments.len();
    stats.filter_fallbacks = kernel.fallbacks() - fallbacks0;
    stats.ms_prepare = (t1 - t0).as_secs_f64() * 1e3;
    stats.ms_order = (t2 - t1).as_secs_f64() * 1e3;
    stats.ms_merge = (t3 - t2).as_secs_f64() * 1e3;
    Ok((
        Ordered {
            fragments,
            stats,
            camera: cam,
            near,
            far,
        },
        polys,
    ))
}
