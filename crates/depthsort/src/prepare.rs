//! Before ordering: convert faces to kernel polygons, cull back faces and faces seen
//! edge-on (exactly), clip at the near plane (exactly), and drop what lies outside the
//! picture (conservatively, in floats).

use std::ops::Range;

use glam::DVec3;
use limn_kernel::Kernel;
use limn_kernel::{PolygonSide, Side};
use limn_scene::Scene;

use crate::by_vertex::ByVertex;
use crate::coincident::{canonical_vertices, hidden_by_later_copies};
use crate::meshed::faces_met_at_corners;
use crate::options::{CullMode, OrderError};
use crate::pieces::{Ctx, Piece, NONE};
use crate::view::{view_planes, ViewPlanes};
use rayon::prelude::*;

/// Which back faces [`CullMode::Auto`] culls: per object, whether it is a closed surface
/// whose materials are all opaque; per face, whether its shell is (the faces of one
/// object connected through shared edges), so that an object made of many parts (an
/// assembly in one file) has the back faces of its closed parts culled even when some
/// other part is open.
///
/// An edge (between vertex positions) is closed when it is used exactly once in each
/// direction within its object. The edges are grouped by their lower end
/// ([`ByVertex`]); within a group, sorted by (upper end, object, direction, face), every
/// run of one edge of one object is then either a closed edge, which joins its two faces
/// into one shell, or open, which opens the shells of all its faces. A shell is closed
/// when none of its edges is open and its faces are all opaque; every face of a closed
/// object is in a closed shell. Back faces of a closed opaque surface are hidden by its
/// front faces wherever the eye is outside it, as for a closed object.
pub(crate) struct ClosedSurfaces {
    /// Per object: closed and opaque.
    pub(crate) objects: Vec<bool>,
    /// Per face: in a closed opaque shell.
    pub(crate) faces: Vec<bool>,
}

/// An open edge's face in the output of [`closed_surfaces`]' edge check.
const OPEN: u32 = u32::MAX;

/// See [`ClosedSurfaces`].
pub(crate) fn closed_surfaces(scene: &Scene, canon: &[u32]) -> ClosedSurfaces {
    let n = scene.objects.len();
    let opaque_face = |f: &limn_scene::Face| scene.materials[f.material as usize].is_opaque();
    let mut ok = vec![true; n];
    let mut has_faces = vec![false; n];
    for f in &scene.faces {
        let o = f.object as usize;
        has_faces[o] = true;
        if !opaque_face(f) {
            ok[o] = false;
        }
    }
    // Every edge at its lower end: (upper end, object, direction, face).
    let mut edges = ByVertex::new(scene.vertices.len(), |put| {
        for (fi, f) in scene.faces.iter().enumerate() {
            let m = f.vertices.len();
            for i in 0..m {
                let a = canon[f.vertices[i] as usize];
                let b = canon[f.vertices[(i + 1) % m] as usize];
                if a != b {
                    put(a.min(b), (a.max(b), f.object, a > b, fi as u32));
                }
            }
        }
    });
    // Closed edges as the pairs of faces they join; open ones as (face, OPEN) for each
    // of their faces.
    let links = edges.flat_map_groups(|group, out: &mut Vec<(u32, u32)>| {
        group.sort_unstable();
        for run in group.chunk_by(|x, y| (x.0, x.1) == (y.0, y.1)) {
            match run {
                [x, y] if x.2 != y.2 => out.push((x.3, y.3)),
                _ => out.extend(run.iter().map(|e| (e.3, OPEN))),
            }
        }
    });
    for &(f, g) in &links {
        if g == OPEN {
            ok[scene.faces[f as usize].object as usize] = false;
        }
    }
    for o in 0..n {
        ok[o] &= has_faces[o];
    }
    let mut faces: Vec<bool> = scene.faces.iter().map(|f| ok[f.object as usize]).collect();
    // Shells only within the objects that are not closed as a whole (and have any
    // closed edge): a closed object's faces are all in closed shells already.
    if ok.iter().all(|&c| c) || links.iter().all(|&(_, g)| g == OPEN) {
        return ClosedSurfaces { objects: ok, faces };
    }
    let mut shells = Shells::new(scene.faces.len());
    for &(f, g) in &links {
        if g != OPEN && !ok[scene.faces[f as usize].object as usize] {
            shells.join(f, g);
        }
    }
    let mut open_shell = vec![false; scene.faces.len()];
    for &(f, g) in &links {
        if g == OPEN {
            let r = shells.root(f);
            open_shell[r as usize] = true;
        }
    }
    for (fi, f) in scene.faces.iter().enumerate() {
        if !opaque_face(f) {
            let r = shells.root(fi as u32);
            open_shell[r as usize] = true;
        }
    }
    for (fi, f) in scene.faces.iter().enumerate() {
        if !ok[f.object as usize] {
            faces[fi] = !open_shell[shells.root(fi as u32) as usize];
        }
    }
    ClosedSurfaces { objects: ok, faces }
}

/// Faces joined into shells (union–find with path halving and union by size).
struct Shells {
    parent: Vec<u32>,
    size: Vec<u32>,
}

impl Shells {
    fn new(n: usize) -> Shells {
        Shells {
            parent: (0..n as u32).collect(),
            size: vec![1; n],
        }
    }

    fn root(&mut self, mut x: u32) -> u32 {
        while self.parent[x as usize] != x {
            let up = self.parent[self.parent[x as usize] as usize];
            self.parent[x as usize] = up;
            x = up;
        }
        x
    }

    fn join(&mut self, a: u32, b: u32) {
        let (mut a, mut b) = (self.root(a), self.root(b));
        if a == b {
            return;
        }
        if self.size[a as usize] < self.size[b as usize] {
            std::mem::swap(&mut a, &mut b);
        }
        self.parent[b as usize] = a;
        self.size[a as usize] += self.size[b as usize];
    }
}

/// What [`prepare`] returns.
pub(crate) struct PreparedFaces {
    /// The ids of the pieces to order.
    pub(crate) items: Vec<u32>,
    /// Per face, whether all of it takes part unclipped with one facing (so its
    /// projected outline is exactly the union of its fragments).
    pub(crate) whole: Vec<bool>,
    /// Per object, whether its back faces are culled.
    pub(crate) culled_objects: Vec<bool>,
    /// Per face, whether it is culled when its back is seen.
    pub(crate) culled_faces: Vec<bool>,
}

/// Converts, culls and clips every face.
pub(crate) fn prepare<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    scene: &Scene,
    cull: CullMode,
    near: f64,
) -> Result<PreparedFaces, OrderError> {
    let mut whole = vec![false; scene.faces.len()];
    let canon = canonical_vertices(scene);
    let ClosedSurfaces {
        objects: closed,
        faces: cull_face,
    } = match cull {
        CullMode::Auto => {
            // Single-sided objects are culled whole, closed or not.
            let mut c = closed_surfaces(scene, &canon);
            for (f, face) in c.faces.iter_mut().zip(&scene.faces) {
                *f |= scene.objects[face.object as usize].single_sided;
            }
            for (o, object) in c.objects.iter_mut().zip(&scene.objects) {
                *o |= object.single_sided;
            }
            c
        }
        CullMode::On => ClosedSurfaces {
            objects: vec![true; scene.objects.len()],
            faces: vec![true; scene.faces.len()],
        },
        CullMode::Off => ClosedSurfaces {
            objects: vec![false; scene.objects.len()],
            faces: vec![false; scene.faces.len()],
        },
    };
    let hidden = hidden_by_later_copies(scene, &canon, &closed);
    ctx.faces_met = faces_met_at_corners(scene, &canon).into();
    // The plane through the eye facing forward: what lies behind it is behind the camera
    // (not in view at all); only what lies between it and the near plane is lost.
    let planes = view_planes(ctx, near)?;
    // Faces are converted, culled, clipped and projected independently, in parallel, a
    // block at a time (so that the pieces waiting to be added stay few); their pieces are
    // then added in face order, so ids do not depend on the threads.
    let mut items = Vec::with_capacity(scene.faces.len());
    ctx.make_room(scene.faces.len());
    let mut quad_halves = vec![false; scene.faces.len()];
    // Block k + 1 is prepared on the pool while block k's pieces are added (by a reader
    // with the same view and no pieces of its own).
    let reader = ctx.reader();
    let prepare_block = |r: Range<usize>| -> Vec<Result<Option<FaceOut<K>>, OrderError>> {
        r.into_par_iter()
            .with_min_len(FACES_PER_TASK)
            .map_init(Vec::new, |scratch, fi| {
                if hidden[fi] {
                    return Ok(None);
                }
                let cull_back = cull_face[fi];
                prepare_face(&reader, scene, fi, cull_back, &planes, scratch).map(Some)
            })
            .collect()
    };
    let blocks: Vec<Range<usize>> = (0..scene.faces.len())
        .step_by(FACES_PER_BLOCK)
        .map(|b| b..(b + FACES_PER_BLOCK).min(scene.faces.len()))
        .collect();
    let mut next = blocks.first().map(|r| prepare_block(r.clone()));
    for (k, block) in blocks.iter().enumerate() {
        let outs = next.take().unwrap_or_default();
        let (added, prepared) = rayon::join(
            || {
                let done = Done {
                    items: &mut items,
                    whole: &mut whole,
                    quad_halves: &mut quad_halves,
                };
                add_block(ctx, block.clone(), outs, done)
            },
            || blocks.get(k + 1).map(|r| prepare_block(r.clone())),
        );
        added?;
        next = prepared;
    }
    ctx.stats.polygons = items.len();
    ctx.quad_halves = quad_halves.into();
    Ok(PreparedFaces {
        items,
        whole,
        culled_objects: closed,
        culled_faces: cull_face,
    })
}

/// What [`add_block`] records besides the pieces: the ids to order, and per face whether
/// it is whole and whether it is a quad as two triangles.
struct Done<'a> {
    items: &'a mut Vec<u32>,
    whole: &'a mut [bool],
    quad_halves: &'a mut [bool],
}

/// Adds the pieces of the faces of `block` (`outs`, prepared in parallel) in face order:
/// their ids, the ids to order, whether each face is whole, and the counts. The first
/// error in face order is returned.
fn add_block<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    block: Range<usize>,
    outs: Vec<Result<Option<FaceOut<K>>, OrderError>>,
    done: Done<'_>,
) -> Result<(), OrderError> {
    let Done {
        items,
        whole,
        quad_halves,
    } = done;
    for (fi, out) in block.zip(outs) {
        ctx.stats.faces_in += 1;
        let Some(out) = out? else {
            ctx.stats.faces_coincident += 1;
            continue;
        };
        if out.degenerate {
            ctx.stats.faces_degenerate += 1;
            continue;
        }
        ctx.stats.splits += out.splits;
        quad_halves[fi] = out.quad_halves;
        let mut kept_any = false;
        for (piece, in_picture) in out.pieces {
            let id = ctx.push(piece);
            if in_picture {
                kept_any = true;
                items.push(id);
            }
        }
        whole[fi] = out.intact && kept_any;
        ctx.stats.faces_near_clipped += out.lost_to_near as usize;
        if out.culled_all {
            ctx.stats.faces_culled += 1;
        } else if !kept_any {
            ctx.stats.faces_clipped += 1;
        }
    }
    Ok(())
}

/// Faces prepared in parallel before their pieces are added, in [`prepare`].
const FACES_PER_BLOCK: usize = 8192;

/// Faces per parallel task in [`prepare`].
const FACES_PER_TASK: usize = 64;

/// What preparing one face gives.
struct FaceOut<K: Kernel> {
    /// The face has zero area (or is not simple).
    degenerate: bool,
    /// Every polygon of the face was culled (back-facing or seen edge-on).
    culled_all: bool,
    /// No polygon was culled, clipped or seen from the other side.
    intact: bool,
    /// The near plane cut away a part the camera would see.
    lost_to_near: bool,
    /// Near-plane splits made.
    splits: usize,
    /// The face is a quad converted into two polygons (sharing a diagonal).
    quad_halves: bool,
    /// The pieces, each with whether it can be painted inside the picture.
    pieces: Vec<(Piece<K>, bool)>,
}

/// Converts, culls, clips and projects face `fi` (reading the context only).
fn prepare_face<K: Kernel>(
    ctx: &Ctx<'_, K>,
    scene: &Scene,
    fi: usize,
    cull_back: bool,
    planes: &ViewPlanes<K::Plane>,
    scratch: &mut Vec<DVec3>,
) -> Result<FaceOut<K>, OrderError> {
    let face = &scene.faces[fi];
    scratch.clear();
    scratch.extend(face.vertices.iter().map(|&v| scene.vertices[v as usize]));
    let polys = ctx.k.face_polygons(scratch)?;
    let mut out = FaceOut {
        degenerate: polys.is_empty(),
        quad_halves: face.vertices.len() == 4 && polys.len() == 2,
        culled_all: true,
        intact: true,
        lost_to_near: false,
        splits: 0,
        pieces: Vec::with_capacity(polys.len()),
    };
    let (w, h) = (ctx.camera.width as f64, ctx.camera.height as f64);
    let mut facing = None;
    for poly in polys {
        let plane = ctx.k.support(&poly);
        let side = ctx.eye_side(plane);
        if *facing.get_or_insert(side) != side {
            out.intact = false;
        }
        match side {
            Side::On => {
                out.intact = false;
                continue;
            }
            Side::Back if cull_back => {
                out.intact = false;
                continue;
            }
            _ => {}
        }
        out.culled_all = false;
        let lost = |poly: &K::Polygon| {
            lost_in_view(ctx, poly, &planes.near, planes.eye.as_ref(), &planes.sides)
        };
        let poly = match ctx.k.classify(&poly, &planes.near) {
            PolygonSide::Front => poly,
            PolygonSide::Spanning => {
                out.intact = false;
                out.lost_to_near |= lost(&poly);
                out.splits += 1;
                match ctx.k.split(&poly, &planes.near).0 {
                    Some(p) => p,
                    None => continue,
                }
            }
            _ => {
                out.intact = false;
                out.lost_to_near |= lost(&poly);
                continue;
            }
        };
        let piece = ctx.piece(poly, fi as u32, NONE, Some(side == Side::Front), scratch);
        let b = piece.bbox;
        // Entirely outside the picture (with a one-pixel margin): never painted.
        let outside = b.max_x < -1.0
            || b.min_x > w + 1.0
            || b.max_y < -1.0
            || b.min_y > h + 1.0
            || !b.min_x.is_finite();
        out.pieces.push((piece, !outside));
    }
    Ok(out)
}

/// Whether the near plane cuts away a part of `poly` that the camera would see: some of
/// what lies behind `near` is in front of the eye's plane and inside the view pyramid
/// (clipped exactly, one plane after another). A warning depends on it, and whether the
/// polygon hides anything in the visible map (`hiding/sight.rs`).
pub(crate) fn lost_in_view<K: Kernel>(
    ctx: &Ctx<'_, K>,
    poly: &K::Polygon,
    near: &K::Plane,
    eye_plane: Option<&K::Plane>,
    sides: &[K::Plane; 4],
) -> bool {
    let behind_near = match ctx.k.classify(poly, near) {
        PolygonSide::Front => return false,
        PolygonSide::Spanning => match ctx.k.split(poly, near).1 {
            Some(p) => p,
            None => return false,
        },
        _ => poly.clone(),
    };
    let mut part = behind_near;
    for plane in eye_plane.into_iter().chain(sides) {
        part = match ctx.k.classify(&part, plane) {
            PolygonSide::Front => part,
            PolygonSide::Spanning => match ctx.k.split(&part, plane).0 {
                Some(p) => p,
                None => return false,
            },
            _ => return false,
        };
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::coincident::canonical_vertices;
    use glam::{DMat3, DVec3};
    use limn_scene::{shapes, Material, Scene};

    fn cube(opacity: f64) -> Scene {
        let mut s = Scene::default();
        let mut mat = Material::diffuse("m", [0.5, 0.5, 0.5]);
        mat.opacity = opacity;
        let m = s.add_material(mat);
        let o = s.add_object("cube");
        shapes::cuboid(&mut s, -DVec3::ONE, DVec3::ONE, DMat3::IDENTITY, m, o).unwrap();
        s
    }

    fn closed(s: &Scene) -> bool {
        closed_surfaces(s, &canonical_vertices(s)).objects[0]
    }

    #[test]
    fn a_cube_is_closed_and_a_changed_one_is_not() {
        let s = cube(1.0);
        assert!(closed(&s));
        assert!(!closed(&cube(0.5)), "translucent");
        let mut open = s.clone();
        open.faces.pop();
        assert!(!closed(&open), "a face missing");
        let mut twice = s.clone();
        let f = twice.faces[0].clone();
        twice.faces.push(f);
        assert!(!closed(&twice), "a face used twice");
        let mut flipped = s.clone();
        flipped.faces[0].vertices.reverse();
        assert!(!closed(&flipped), "a face turned over");
        let mut separate = s.clone();
        let o = separate.add_object("other");
        separate.faces[5].object = o;
        let both = closed_surfaces(&separate, &canonical_vertices(&separate)).objects;
        assert_eq!(both, vec![false, false], "a face in another object");
    }

    /// An object of two parts, a closed cube and an open one: the closed part's faces
    /// are culled, the open part's are not, and the object is not closed as a whole;
    /// turning one face of the first part over opens that part too.
    #[test]
    fn a_closed_part_of_an_open_object_is_culled() {
        let mut s = cube(1.0);
        let m = 0;
        let o = 0;
        let shift = DVec3::new(3.0, 0.0, 0.0);
        shapes::cuboid(
            &mut s,
            shift - DVec3::ONE,
            shift + DVec3::ONE,
            DMat3::IDENTITY,
            m,
            o,
        )
        .unwrap();
        s.faces.pop();
        let c = closed_surfaces(&s, &canonical_vertices(&s));
        assert_eq!(c.objects, vec![false]);
        let first = 6;
        assert_eq!(c.faces.len(), first + 5);
        assert!(c.faces[..first].iter().all(|&f| f), "{:?}", c.faces);
        assert!(c.faces[first..].iter().all(|&f| !f), "{:?}", c.faces);
        let mut turned = s.clone();
        turned.faces[0].vertices.reverse();
        let t = closed_surfaces(&turned, &canonical_vertices(&turned));
        assert!(t.faces.iter().all(|&f| !f), "{:?}", t.faces);
        // A translucent face opens only its own part.
        let mut two = s.clone();
        let g = two.add_material({
            let mut mat = Material::diffuse("g", [0.5, 0.5, 0.5]);
            mat.opacity = 0.5;
            mat
        });
        shapes::cuboid(
            &mut two,
            -shift - DVec3::ONE,
            -shift + DVec3::ONE,
            DMat3::IDENTITY,
            m,
            o,
        )
        .unwrap();
        two.faces[first + 5].material = g;
        let w = closed_surfaces(&two, &canonical_vertices(&two));
        assert!(w.faces[..first].iter().all(|&f| f), "{:?}", w.faces);
        assert!(w.faces[first..].iter().all(|&f| !f), "{:?}", w.faces);
    }
}
