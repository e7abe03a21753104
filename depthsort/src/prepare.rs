//! Before ordering: convert faces to kernel polygons, cull back faces and faces seen
//! edge-on (exactly), clip at the near plane (exactly), and drop what lies outside the
//! picture (conservatively, in floats).

use limn_kernel::Kernel;
use limn_kernel::{PolygonSide, Side};
use limn_scene::Scene;

use crate::coincident::{canonical_vertices, hidden_by_later_copies};
use crate::options::{CullMode, OrderError};
use crate::pieces::{Ctx, NONE};
use crate::view::view_planes;

/// For each object: is it a closed surface whose materials are all opaque? Every edge
/// (between vertex positions) must be used exactly once in each direction within the
/// object.
pub(crate) fn closed_opaque_objects(scene: &Scene, canon: &[u32]) -> Vec<bool> {
    let n = scene.objects.len();
    let mut ok = vec![true; n];
    let mut has_faces = vec![false; n];
    // Directed edges (object, from, to).
    let mut edges: Vec<(u32, u32, u32)> = Vec::new();
    for f in &scene.faces {
        let o = f.object as usize;
        has_faces[o] = true;
        if !scene.materials[f.material as usize].is_opaque() {
            ok[o] = false;
        }
        let m = f.vertices.len();
        for i in 0..m {
            let a = canon[f.vertices[i] as usize];
            let b = canon[f.vertices[(i + 1) % m] as usize];
            if a != b {
                edges.push((f.object, a, b));
            }
        }
    }
    edges.sort_unstable();
    for (i, &(o, a, b)) in edges.iter().enumerate() {
        let o = o as usize;
        if !ok[o] {
            continue;
        }
        let dup = (i > 0 && edges[i - 1] == (o as u32, a, b))
            || (i + 1 < edges.len() && edges[i + 1] == (o as u32, a, b));
        if dup || edges.binary_search(&(o as u32, b, a)).is_err() {
            ok[o] = false;
        }
    }
    for o in 0..n {
        ok[o] &= has_faces[o];
    }
    ok
}

/// Converts, culls and clips every face; returns the ids of the pieces to order, and per
/// face whether all of it takes part unclipped with one facing (so its projected outline
/// is exactly the union of its fragments).
pub(crate) fn prepare<K: Kernel>(
    ctx: &mut Ctx<'_, K>,
    scene: &Scene,
    cull: CullMode,
    near: f64,
) -> Result<(Vec<u32>, Vec<bool>), OrderError> {
    let mut whole = vec![false; scene.faces.len()];
    let canon = canonical_vertices(scene);
    let closed = match cull {
        CullMode::Auto => closed_opaque_objects(scene, &canon),
        CullMode::On => vec![true; scene.objects.len()],
        CullMode::Off => vec![false; scene.objects.len()],
    };
    let hidden = hidden_by_later_copies(scene, &canon, &closed);
    // The plane through the eye facing forward: what lies behind it is behind the camera
    // (not in view at all); only what lies between it and the near plane is lost.
    let planes = view_planes(ctx, near)?;
    let (near_plane, eye_plane, frustum) = (&planes.near, planes.eye.as_ref(), &planes.sides);
    let (w, h) = (ctx.camera.width as f64, ctx.camera.height as f64);
    let mut items = Vec::new();
    let mut corners = Vec::new();
    for (fi, face) in scene.faces.iter().enumerate() {
        ctx.stats.faces_in += 1;
        if hidden[fi] {
            ctx.stats.faces_coincident += 1;
            continue;
        }
        corners.clear();
        corners.extend(face.vertices.iter().map(|&v| scene.vertices[v as usize]));
        let polys = ctx.k.face_polygons(&corners)?;
        if polys.is_empty() {
            ctx.stats.faces_degenerate += 1;
            continue;
        }
        let cull_back = closed[face.object as usize];
        let mut kept_any = false;
        let mut culled_all = true;
        let mut intact = true;
        let mut facing = None;
        let mut lost_to_near = false;
        for poly in polys {
            let plane = ctx.k.support(&poly);
            let side = ctx.eye_side(&plane);
            if *facing.get_or_insert(side) != side {
                intact = false;
            }
            match side {
                Side::On => {
                    intact = false;
                    continue;
                }
                Side::Back if cull_back => {
                    intact = false;
                    continue;
                }
                _ => {}
            }
            culled_all = false;
            let poly = match ctx.k.classify(&poly, near_plane) {
                PolygonSide::Front => poly,
                PolygonSide::Spanning => {
                    intact = false;
                    lost_to_near |= lost_in_view(ctx, &poly, near_plane, eye_plane, frustum);
                    ctx.stats.splits += 1;
                    match ctx.k.split(&poly, near_plane).0 {
                        Some(p) => p,
                        None => continue,
                    }
                }
                _ => {
                    intact = false;
                    lost_to_near |= lost_in_view(ctx, &poly, near_plane, eye_plane, frustum);
                    continue;
                }
            };
            let id = ctx.add(poly, fi as u32, NONE, Some(side == Side::Front));
            let b = ctx.pieces[id as usize].bbox;
            // Entirely outside the picture (with a one-pixel margin): never painted.
            if b.max_x < -1.0
                || b.min_x > w + 1.0
                || b.max_y < -1.0
                || b.min_y > h + 1.0
                || !b.min_x.is_finite()
            {
                continue;
            }
            kept_any = true;
            items.push(id);
        }
        whole[fi] = intact && kept_any;
        ctx.stats.faces_near_clipped += lost_to_near as usize;
        if culled_all {
            ctx.stats.faces_culled += 1;
        } else if !kept_any {
            ctx.stats.faces_clipped += 1;
        }
    }
    ctx.stats.polygons = items.len();
    Ok((items, whole))
}

/// Whether the near plane cuts away a part of `poly` that the camera would see: some of
/// what lies behind `near` is in front of the eye's plane and inside the view pyramid
/// (clipped exactly, one plane after another). A warning depends on it, no picture does.
fn lost_in_view<K: Kernel>(
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
