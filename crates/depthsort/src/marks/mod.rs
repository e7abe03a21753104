//! Lines, point markers and label anchors hidden exactly against the ordered fragments.
//!
//! Each segment of a polyline is split where it passes behind an opaque fragment or
//! through one, exactly: the part of segment `AB` hidden by a convex polygon is the set
//! of parameters `u` where the point `A + u(B − A)` satisfies the linear conditions of
//! the polygon's cone from the eye (see `cone.rs`), an interval whose ends are exact
//! rationals. A point marker or label is shown iff no opaque fragment hides its anchor,
//! decided by the same conditions. Only the positions of visible pieces are rounded, once,
//! for output.
//!
//! Rules:
//! - a point lying in a fragment's plane is never hidden by that fragment, so a line
//!   drawn on a face (a wireframe on its own surface) is drawn over it;
//! - the polygon is closed: a point whose sight line grazes an occluder's edge is hidden;
//!   hidden parts of zero length are ignored (a line is never cut at a single point);
//! - what lies nearer than the near plane is clipped away, as faces are;
//! - with a parallel projection the eye is at infinity: a point is hidden when the ray
//!   from it toward the eye meets a face;
//! - translucent fragments hide nothing, but a visible piece is painted before the first
//!   translucent fragment in front of it (pieces are split where they pass in and out of
//!   a translucent fragment's cone, so that one position holds for the whole piece);
//!   consecutive pieces of a line are one piece again, painted at the earliest of their
//!   positions, where no fragment behind a later one and over it in the picture is
//!   painted between the positions (a line seen through a translucent surface stays
//!   whole instead of passing in and out of each of its triangles).

mod bins;
mod cone;
mod filter;
#[cfg(test)]
mod reference;
mod segment;

use std::sync::OnceLock;

use glam::{DMat4, DVec3};
use limn_kernel::{ExactKernel, ExactPolygon, Kernel, Plane, Side};
use limn_scene::{Camera, Scene, Viewpoint};
use rayon::prelude::*;

use crate::geom::{bbox, Box2};
use crate::{order, order_polygons, Arith, OrderError, OrderOptions, Ordered};
use bins::Bins;
use cone::{q3, Cone, EyeQ};
use filter::{ConePlanes, EyeF};

/// A visible piece of an input polyline.
#[derive(Debug, Clone, PartialEq)]
pub struct VisiblePiece {
    /// The input line (index in [`Scene::lines`]).
    pub line: u32,
    /// At least two points in world coordinates (rounded once from the exact ends).
    pub world: Vec<DVec3>,
    /// The same points in pixel coordinates.
    pub points: Vec<[f64; 2]>,
    /// Paint position: before `fragments[before]` (the fragments' count = after all).
    pub before: usize,
    /// On-screen length of the polyline before this piece, in pixels (for dashes).
    pub start: f64,
}

/// A visible anchor (of a point marker, a label or an arrow head).
#[derive(Debug, Clone, PartialEq)]
pub struct VisibleAnchor {
    /// Index in [`Scene::points`], [`Scene::labels`] or [`Scene::lines`] (heads).
    pub index: u32,
    /// Pixel coordinates.
    pub at: [f64; 2],
    /// For arrow heads: the pixel position of the polyline's point before the tip (the
    /// head points from there to `at`); `at` otherwise.
    pub from: [f64; 2],
    /// Paint position, as for [`VisiblePiece::before`].
    pub before: usize,
}

/// What hiding the marks did.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct MarkStats {
    /// Input polylines.
    pub lines: usize,
    /// Input segments (consecutive point pairs).
    pub segments_in: usize,
    /// Visible pieces out (after joining consecutive pieces of one polyline).
    pub pieces_out: usize,
    /// Hidden (or near-clipped) pieces, joined the same way.
    pub hidden_pieces: usize,
    /// Input point markers.
    pub markers_in: usize,
    /// Markers shown.
    pub markers_shown: usize,
    /// Input labels.
    pub labels_in: usize,
    /// Labels shown.
    pub labels_shown: usize,
    /// Occluder tests that needed exact evaluation (after the exact plane-side prefilter
    /// and the certified float filter).
    pub exact_tests: usize,
    /// Time spent, in milliseconds.
    pub ms: u64,
}

/// The visible parts of a scene's lines, markers and labels.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct VisibleMarks {
    /// Visible line pieces, in line order, each line's pieces from its start.
    pub pieces: Vec<VisiblePiece>,
    /// Visible point markers.
    pub points: Vec<VisibleAnchor>,
    /// Visible labels.
    pub labels: Vec<VisibleAnchor>,
    /// Visible arrow heads.
    pub heads: Vec<VisibleAnchor>,
    /// The hidden (not near-clipped) pieces of the lines, for drawings that show hidden
    /// lines dashed; their `before` is the fragments' count.
    pub hidden: Vec<VisiblePiece>,
    /// Counts.
    pub stats: MarkStats,
}

/// Orders `scene` like [`order`] and hides its lines, markers and labels exactly against
/// the result. With [`Arith::Float`] the faces are still ordered by the float kernel, but
/// the marks are hidden exactly against the input faces (then a mark behind a
/// translucent face is painted before that face's first fragment).
pub fn order_with_marks(
    scene: &Scene,
    camera: &Camera,
    opts: &OrderOptions,
) -> Result<(Ordered, VisibleMarks), OrderError> {
    match opts.arith {
        Arith::Exact => {
            let (ordered, polys) = order_polygons(&ExactKernel::new(), scene, camera, opts)?;
            let marks = hide_marks(scene, &ordered, &polys)?;
            Ok((ordered, marks))
        }
        Arith::Float => {
            let ordered = order(scene, camera, opts)?;
            let marks = hide_marks_by_face(scene, &ordered)?;
            Ok((ordered, marks))
        }
    }
}

/// One polygon that may hide or cover marks.
struct Occluder {
    poly: ExactPolygon,
    /// Paint position of a mark in front of it.
    before: usize,
    opaque: bool,
    support: Plane,
    eye_side: Side,
    cone: OnceLock<Option<Cone>>,
    /// What the float filter reads of it, made on first use.
    cone_planes: OnceLock<ConePlanes>,
}

/// Hides the marks of `scene` against `ordered`, whose fragments' exact polygons are
/// `polys` (as returned by [`order_polygons`] with the exact kernel).
pub fn hide_marks(
    scene: &Scene,
    ordered: &Ordered,
    polys: &[ExactPolygon],
) -> Result<VisibleMarks, OrderError> {
    if !has_marks(scene) {
        return Ok(VisibleMarks::default());
    }
    let occ: Vec<(ExactPolygon, usize, Box2)> = polys
        .iter()
        .zip(&ordered.fragments)
        .enumerate()
        .map(|(i, (p, f))| (p.clone(), i, bbox(&f.points)))
        .collect();
    let opaque = |o: &(ExactPolygon, usize, Box2)| face_opaque(scene, ordered.fragments[o.1].face);
    let flags: Vec<bool> = occ.iter().map(opaque).collect();
    run(scene, ordered, occ, flags, true)
}

/// Hides the marks against exact polygons of the input faces (for orders made by the
/// float kernel, whose fragments have no exact polygons).
fn hide_marks_by_face(scene: &Scene, ordered: &Ordered) -> Result<VisibleMarks, OrderError> {
    if !has_marks(scene) {
        return Ok(VisibleMarks::default());
    }
    let k = ExactKernel::new();
    let n = ordered.fragments.len();
    let mut first = vec![n; scene.faces.len()];
    for (i, f) in ordered.fragments.iter().enumerate().rev() {
        first[f.face as usize] = i;
    }
    let vp = view_projection(ordered);
    let mut occ = Vec::new();
    let mut flags = Vec::new();
    for (fi, _) in scene.faces.iter().enumerate() {
        let corners = scene.face_points(fi as u32);
        let mut b = Box2::EMPTY;
        for &c in &corners {
            let p = ordered.camera.project_with(&vp, c);
            if p.w < ordered.near {
                b = Box2 {
                    min_x: f64::NEG_INFINITY,
                    min_y: f64::NEG_INFINITY,
                    max_x: f64::INFINITY,
                    max_y: f64::INFINITY,
                };
                break;
            }
            b = b.union(&Box2 {
                min_x: p.x,
                min_y: p.y,
                max_x: p.x,
                max_y: p.y,
            });
        }
        for poly in k.face_polygons(&corners)? {
            occ.push((poly, first[fi], b));
            flags.push(face_opaque(scene, fi as u32));
        }
    }
    run(scene, ordered, occ, flags, false)
}

/// Whether the scene has anything to hide: without lines, markers or labels the
/// occluders are not even gathered.
fn has_marks(scene: &Scene) -> bool {
    !(scene.lines.is_empty() && scene.points.is_empty() && scene.labels.is_empty())
}

fn face_opaque(scene: &Scene, face: u32) -> bool {
    let m = scene.faces[face as usize].material;
    scene.materials[m as usize].is_opaque()
}

fn view_projection(ordered: &Ordered) -> DMat4 {
    ordered.camera.view_projection(ordered.near, ordered.far)
}

/// The shared work: bins, then every line, marker, label and head. `fragments`: the
/// occluders are the ordered fragments themselves (each one's position its index), so
/// pieces of a line may be joined where one position suits them all (see
/// `segment::Shared::join_across`).
fn run(
    scene: &Scene,
    ordered: &Ordered,
    occ: Vec<(ExactPolygon, usize, Box2)>,
    opaque: Vec<bool>,
    fragments: bool,
) -> Result<VisibleMarks, OrderError> {
    let t0 = std::time::Instant::now();
    let shared = context(ordered, occ, opaque, fragments)?;
    let mut out = hide_all(scene, &shared);
    out.stats.ms = t0.elapsed().as_millis() as u64;
    Ok(out)
}

/// What hiding works with: the occluders with their planes' sides of the eye, the bins,
/// the eye and the near plane.
fn context(
    ordered: &Ordered,
    occ: Vec<(ExactPolygon, usize, Box2)>,
    opaque: Vec<bool>,
    fragments: bool,
) -> Result<segment::Shared, OrderError> {
    let join_across = fragments && opaque.iter().any(|&o| !o);
    let cam = &ordered.camera;
    let fwd = cam.forward();
    let eye = cam.eye;
    let near = Plane::point_normal((eye + fwd * ordered.near).to_array(), fwd.to_array())?;
    let (eye_q, eye_f) = match cam.viewpoint()? {
        Viewpoint::At(p) => (EyeQ::Point(q3(p.to_array())), EyeF::Point(p.to_array())),
        Viewpoint::Toward(d) => (EyeQ::Toward(q3(d.to_array())), EyeF::Toward(d.to_array())),
    };
    let boxes: Vec<Box2> = occ.iter().map(|o| o.2).collect();
    let occluders: Vec<Occluder> = occ
        .into_iter()
        .zip(opaque)
        .map(|((poly, before, _), opaque)| {
            let support = poly.support();
            let eye_side = match eye_f {
                EyeF::Point(p) => support.side_of(p),
                EyeF::Toward(d) => support.side_of_direction(d),
            };
            Occluder {
                poly,
                before,
                opaque,
                support,
                eye_side,
                cone: OnceLock::new(),
                cone_planes: OnceLock::new(),
            }
        })
        .collect();
    Ok(segment::Shared {
        occluders,
        bins: Bins::new(boxes),
        eye: eye_q,
        eye_f,
        near,
        camera: *cam,
        vp: view_projection(ordered),
        end: ordered.fragments.len(),
        filter: true,
        join_across,
    })
}

/// What hiding one polyline gives.
#[derive(Default)]
struct LineOut {
    pieces: Vec<VisiblePiece>,
    hidden: Vec<VisiblePiece>,
    head: Option<VisibleAnchor>,
    stats: MarkStats,
}

/// Every line, marker, label and head, hidden: the lines, points and labels each in
/// parallel tasks whose results are joined in input order (the same on any number of
/// threads).
fn hide_all(scene: &Scene, sh: &segment::Shared) -> VisibleMarks {
    let cam = sh.camera;
    let lines: Vec<LineOut> = scene
        .lines
        .par_iter()
        .enumerate()
        .map(|(i, line)| {
            let mut ctx = sh.task();
            let mut o = LineOut::default();
            ctx.stats.lines += 1;
            ctx.polyline(i as u32, &line.points, &mut o.pieces, &mut o.hidden);
            if line.head {
                let n = line.points.len();
                o.head = ctx.anchor(i as u32, line.points[n - 1]).map(|mut a| {
                    let prev = cam.project_with(&sh.vp, line.points[n - 2]);
                    a.from = [prev.x, prev.y];
                    a
                });
            }
            o.stats = ctx.stats;
            o
        })
        .collect();
    let mut out = VisibleMarks::default();
    for l in lines {
        out.pieces.extend(l.pieces);
        out.hidden.extend(l.hidden);
        out.heads.extend(l.head);
        out.stats.add(&l.stats);
    }
    let anchors = |at: Vec<DVec3>| -> Vec<(Option<VisibleAnchor>, MarkStats)> {
        at.par_iter()
            .enumerate()
            .map(|(i, &p)| {
                let mut ctx = sh.task();
                (ctx.anchor(i as u32, p), ctx.stats)
            })
            .collect()
    };
    for (a, st) in anchors(scene.points.iter().map(|p| p.at).collect()) {
        out.stats.add(&st);
        out.stats.markers_in += 1;
        out.stats.markers_shown += usize::from(a.is_some());
        out.points.extend(a);
    }
    for (a, st) in anchors(scene.labels.iter().map(|l| l.at).collect()) {
        out.stats.add(&st);
        out.stats.labels_in += 1;
        out.stats.labels_shown += usize::from(a.is_some());
        out.labels.extend(a);
    }
    out
}

impl MarkStats {
    /// Adds the counts of `o` (the time is left alone).
    fn add(&mut self, o: &MarkStats) {
        self.lines += o.lines;
        self.segments_in += o.segments_in;
        self.pieces_out += o.pieces_out;
        self.hidden_pieces += o.hidden_pieces;
        self.markers_in += o.markers_in;
        self.markers_shown += o.markers_shown;
        self.labels_in += o.labels_in;
        self.labels_shown += o.labels_shown;
        self.exact_tests += o.exact_tests;
    }
}

impl Occluder {
    /// The exact cone, computed on first use (by whichever task needs it first).
    fn cone(&self, eye: &EyeQ) -> Option<&Cone> {
        self.cone
            .get_or_init(|| Cone::new(&self.poly, eye))
            .as_ref()
    }

    /// What the float filter reads of it, from `eye` (the same eye at every call), made
    /// on first use.
    fn cone_planes(&self, eye: EyeF) -> &ConePlanes {
        self.cone_planes
            .get_or_init(|| ConePlanes::new(&self.poly, &self.support, eye))
    }
}
