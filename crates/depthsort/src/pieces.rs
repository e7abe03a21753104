//! The working state shared by the orderings: the piece tree (every polygon and every
//! fragment split from it, with its provenance), projections, counters and the random
//! source. The occlusion predicates between pieces live in [`crate::occlusion`].

use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Arc;

use glam::{DMat4, DVec3};
use limn_kernel::{Kernel, PolygonSide, Side};
use limn_scene::Camera;

use crate::eye::Eye;
use crate::geom::{bbox, Box2};
use crate::options::Stats;
use crate::rng::SplitMix;

/// No piece.
pub(crate) const NONE: u32 = u32::MAX;

/// A convex polygon taking part in the ordering: an input polygon or a piece split from
/// one. Pieces are never removed: a split piece stays as the parent of its two halves,
/// so halves that end up next to each other can be joined again exactly.
pub(crate) struct Piece<K: Kernel> {
    /// The polygon; its supporting plane is the piece's plane ([`Kernel::support`]).
    pub poly: K::Polygon,
    pub face: u32,
    pub parent: u32,
    pub kids: [u32; 2],
    /// The eye lies strictly in front of the supporting plane.
    pub eye_front: bool,
    /// Projected vertices in pixels.
    pub pts: Box<[[f64; 2]]>,
    pub bbox: Box2,
    /// Range of view depth over the vertices (clip w for a perspective camera, device
    /// depth otherwise).
    pub dmin: f64,
    pub dmax: f64,
    pub dmean: f64,
}

impl<K: Kernel> Clone for Piece<K> {
    fn clone(&self) -> Self {
        Piece {
            poly: self.poly.clone(),
            face: self.face,
            parent: self.parent,
            kids: self.kids,
            eye_front: self.eye_front,
            pts: self.pts.clone(),
            bbox: self.bbox,
            dmin: self.dmin,
            dmax: self.dmax,
            dmean: self.dmean,
        }
    }
}

pub(crate) struct Ctx<'a, K: Kernel> {
    pub k: &'a K,
    pub eye: Eye<K::Point>,
    pub vp: DMat4,
    pub camera: Camera,
    pub pieces: Vec<Piece<K>>,
    pub stats: Stats,
    /// Pixel margin of the float prefilters.
    pub margin: f64,
    /// Depth margin of the float prefilters.
    pub dmargin: f64,
    /// Pieces at most (faces' polygons and every piece a split makes); beyond it splits
    /// stop, `exceeded` is set, and the ordering reports an error instead of a result.
    pub limit: usize,
    /// Whether a split was refused because of `limit`.
    pub exceeded: bool,
    /// Per input face: whether it is a quad given as two triangles that share a diagonal
    /// (a quad not exactly planar as given, or not convex).
    pub quad_halves: Arc<[bool]>,
    /// Per input face: the faces it meets at its corners ([`faces_met_at_corners`]);
    /// empty where no scene was prepared (read as none).
    ///
    /// [`faces_met_at_corners`]: crate::meshed::faces_met_at_corners
    pub faces_met: Arc<[u8]>,
    /// For a detached context ([`Ctx::detached`]): the pieces of the whole ordering,
    /// counted across every detached context, against `limit`.
    counted: Option<Arc<AtomicUsize>>,
    /// How many contexts this one is detached from, counting up through their own: a
    /// large set is split apart only a few levels deep ([`Ctx::may_split_apart`]).
    detached_depth: u32,
    /// The pieces of the outermost set split apart that this context orders a part of
    /// (inherited by the contexts detached from it); 0 outside any.
    pub outermost_apart: usize,
    rng: SplitMix,
    scratch: Vec<DVec3>,
}

/// Contexts detached one from another, counting the whole ordering's, in which large
/// sets are split apart (see [`Ctx::may_split_apart`]): a split apart's parts, the large
/// components and parts found inside them, and one level more.
const APART_DEPTH: u32 = 3;

impl<'a, K: Kernel> Ctx<'a, K> {
    pub fn new(
        k: &'a K,
        eye: Eye<K::Point>,
        camera: Camera,
        vp: DMat4,
        far: f64,
        seed: u64,
    ) -> Self {
        let size = (camera.width + camera.height) as f64;
        Ctx {
            k,
            eye,
            vp,
            camera,
            pieces: Vec::new(),
            stats: Stats::default(),
            margin: 1e-7 * size + 1e-9,
            dmargin: 1e-9 * far.abs().max(1e-300),
            limit: usize::MAX,
            exceeded: false,
            quad_halves: Arc::from([]),
            faces_met: Arc::from([]),
            counted: None,
            detached_depth: 0,
            outermost_apart: 0,
            rng: SplitMix::new(seed),
            scratch: Vec::new(),
        }
    }

    /// A context viewing `scene` through a camera framing it at `width` × `height`, with
    /// no pieces yet, and the camera's near distance (for tests that prepare the scene).
    #[cfg(test)]
    pub fn framing(k: &'a K, scene: &limn_scene::Scene, width: u32, height: u32) -> (Self, f64) {
        let camera = Camera::framing(scene, width, height).expect("a framable scene");
        let eye = Eye::of(k, &camera).expect("a camera");
        let (near, far) = camera.near_far(scene);
        let vp = camera.view_projection(near, far);
        (Ctx::new(k, eye, camera, vp, far, 0), near)
    }

    /// A context with the same kernel and view and no pieces: it can make pieces (with
    /// no parent) while this one is being added to.
    pub fn reader(&self) -> Self {
        let mut r = Ctx::new(self.k, self.eye, self.camera, self.vp, 1.0, 0);
        r.margin = self.margin;
        r.dmargin = self.dmargin;
        r
    }

    /// A context with the same kernel, view, margins and limit holding `pieces` (copies
    /// of some of this context's pieces, under ids of their own), its own random source
    /// seeded with `seed`, and no counts: it orders apart from this one while this one is
    /// only read. Its splits count against the limit in `counted`, shared by every
    /// detached context and started at this context's pieces.
    pub fn detached(&self, pieces: Vec<Piece<K>>, seed: u64, counted: Arc<AtomicUsize>) -> Self {
        let mut d = self.reader();
        d.pieces = pieces;
        d.limit = self.limit;
        d.quad_halves = Arc::clone(&self.quad_halves);
        d.faces_met = Arc::clone(&self.faces_met);
        d.counted = Some(counted);
        d.detached_depth = self.detached_depth + 1;
        d.outermost_apart = self.outermost_apart;
        d.rng = SplitMix::new(seed);
        d
    }

    /// The count of pieces that the splits of contexts detached from this one are
    /// counted in against the limit: this context's own when it is detached itself,
    /// otherwise a new one starting at its pieces.
    pub fn split_counter(&self) -> Arc<AtomicUsize> {
        match &self.counted {
            Some(c) => Arc::clone(c),
            None => Arc::new(AtomicUsize::new(self.pieces.len())),
        }
    }

    /// Whether a large set ordered in this context may be split apart
    /// (`split_apart.rs`): in the whole ordering's context and in contexts detached from
    /// it fewer than [`APART_DEPTH`] times. A split apart orders its parts through a
    /// call, not on a stack of tasks, so without this bound a set that splitting does not
    /// shrink (a float kernel far from the origin) would nest calls until the thread's
    /// stack ran out; below the bound sets are split on the task stacks as before.
    pub fn may_split_apart(&self) -> bool {
        self.detached_depth < APART_DEPTH
    }

    /// Makes room, before the `faces` of a scene are added, for every piece the limit
    /// allows: as address space, which is given memory only page by page as pieces are
    /// written, so that the vector never moves. Growing it by doubling copied every piece
    /// into fresh memory at each step (the dense 10k soup's 187,000 pieces of 352 bytes:
    /// a seventh of its ordering time). Where the system refuses that much address space
    /// (a limit on it, strict overcommit, a 32-bit target), room for a piece per face and
    /// as many again (quads as two triangles, splits).
    pub fn make_room(&mut self, faces: usize) {
        let wanted = self.limit.saturating_sub(self.pieces.len());
        if self.pieces.try_reserve_exact(wanted).is_err() {
            self.pieces.reserve(faces.saturating_mul(2));
        }
    }

    /// Whether two more pieces stay within the limit (counted across the detached
    /// contexts for one of them: a refused split of any is over the limit in any order
    /// the contexts run in, since none is refused while all of them together fit).
    fn room_for_two(&self) -> bool {
        match &self.counted {
            None => self.pieces.len() + 2 <= self.limit,
            Some(c) => c.fetch_add(2, Ordering::Relaxed) + 2 <= self.limit,
        }
    }

    /// A deterministic pseudo-random number.
    pub fn next_random(&mut self) -> u64 {
        self.rng.next_u64()
    }

    /// Adds a piece and projects it. `eye_front` is computed when `None`.
    pub fn add(
        &mut self,
        poly: K::Polygon,
        face: u32,
        parent: u32,
        eye_front: Option<bool>,
    ) -> u32 {
        let mut scratch = std::mem::take(&mut self.scratch);
        let piece = self.piece(poly, face, parent, eye_front, &mut scratch);
        self.scratch = scratch;
        self.push(piece)
    }

    /// Adds a piece made by [`Ctx::piece`]; returns its id.
    pub fn push(&mut self, piece: Piece<K>) -> u32 {
        self.pieces.push(piece);
        (self.pieces.len() - 1) as u32
    }

    /// A piece with its projection, not yet added (`scratch` is working space).
    /// `eye_front` is computed when `None`.
    pub fn piece(
        &self,
        poly: K::Polygon,
        face: u32,
        parent: u32,
        eye_front: Option<bool>,
        scratch: &mut Vec<DVec3>,
    ) -> Piece<K> {
        let eye_front =
            eye_front.unwrap_or_else(|| self.eye_side(self.k.support(&poly)) == Side::Front);
        // Depth: clip w (the distance along the view axis) for a perspective camera,
        // normalised device depth for any other.
        let by_w = self.camera.is_perspective();
        scratch.clear();
        self.k.vertices_world(&poly, scratch);
        let mut pts = Vec::with_capacity(scratch.len());
        let (mut dmin, mut dmax, mut dsum) = (f64::INFINITY, f64::NEG_INFINITY, 0.0);
        for &p in scratch.iter() {
            let pr = self.camera.project_with(&self.vp, p);
            pts.push([pr.x, pr.y]);
            let d = if by_w { pr.w } else { pr.z };
            dmin = dmin.min(d);
            dmax = dmax.max(d);
            dsum += d;
        }
        let dmean = dsum / pts.len().max(1) as f64;
        let bbox = bbox(&pts);
        Piece {
            poly,
            face,
            parent,
            kids: [NONE, NONE],
            eye_front,
            pts: pts.into_boxed_slice(),
            bbox,
            dmin,
            dmax,
            dmean,
        }
    }

    /// Splits piece `id` by the plane of piece `by`. Returns the ids of the part on the
    /// eye's side of that plane and the part on the far side (either may be absent when
    /// the piece does not span the plane).
    pub fn split_by(&mut self, id: u32, by: u32) -> (Option<u32>, Option<u32>) {
        let plane = self.k.support(&self.pieces[by as usize].poly).clone();
        let by_eye_front = self.pieces[by as usize].eye_front;
        let (front, back) = self.split_plane(id, &plane);
        if by_eye_front {
            (front, back)
        } else {
            (back, front)
        }
    }

    /// Splits piece `id` by `plane` into (front, back) piece ids. A piece that lies on one
    /// side is returned unchanged on that side.
    pub fn split_plane(&mut self, id: u32, plane: &K::Plane) -> (Option<u32>, Option<u32>) {
        let piece = &self.pieces[id as usize];
        match self.k.classify(&piece.poly, plane) {
            PolygonSide::Front | PolygonSide::Coplanar => (Some(id), None),
            PolygonSide::Back | PolygonSide::CoplanarOpposite => (None, Some(id)),
            PolygonSide::Spanning if !self.room_for_two() => {
                // Over the limit: the result is discarded, so any side will do; the
                // orderings still terminate (no piece is ever split again).
                self.exceeded = true;
                (Some(id), None)
            }
            PolygonSide::Spanning => {
                let (f, b) = self.k.split(&piece.poly, plane);
                let face = piece.face;
                let ef = Some(piece.eye_front);
                self.stats.splits += 1;
                let f = f.map(|poly| self.add(poly, face, id, ef));
                let b = b.map(|poly| self.add(poly, face, id, ef));
                self.pieces[id as usize].kids = [f.unwrap_or(NONE), b.unwrap_or(NONE)];
                (f, b)
            }
        }
    }
}
