//! Convex polygons as a supporting plane plus one bounding plane per edge, and their
//! classification and splitting by a plane.

use std::borrow::Cow;

use smallvec::SmallVec;

use crate::filter::PlaneF;
use crate::interval::Interval;
use crate::plane::Plane;
use crate::predicates;
use crate::side::{PolygonSide, Side};
use crate::vertex_memo;

/// Vertices stored inline (no heap allocation) up to this count.
pub(crate) const INLINE: usize = 4;

/// The cached data of vertex `i`: what the filter reads, kept apart from the edge planes
/// so that classification touches as little memory as possible.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Corner {
    /// Approximate coordinates of vertex `i`.
    pub(crate) pos: [f64; 3],
    /// Bound on the error of every coordinate of `pos`; 0 means `pos` is the vertex
    /// exactly (an input point, or an intersection that happens to be representable).
    pub(crate) err: f32,
    /// Whether edge `i` (from vertex `i` to `i + 1`) lies on an edge of the input face.
    pub(crate) original: bool,
}

/// Rounds an f64 error bound up to f32; a NaN bound (no bound) becomes infinite, so that
/// the maxima taken over corners cannot drop it.
#[inline]
pub(crate) fn err32(e: f64) -> f32 {
    if e.is_nan() {
        return f32::INFINITY;
    }
    let f = e as f32;
    if (f as f64) < e {
        f.next_up()
    } else {
        f
    }
}

/// Corner and edge lists under construction.
#[derive(Default)]
pub(crate) struct Builder {
    corners: SmallVec<[Corner; INLINE]>,
    edges: SmallVec<[Plane; INLINE]>,
}

impl Builder {
    /// Appends vertex `i` and the plane of edge `i`.
    #[inline]
    pub(crate) fn push(&mut self, corner: Corner, edge: Plane) {
        self.corners.push(corner);
        self.edges.push(edge);
    }

    /// Appends vertex `i` of an input polygon whose edge planes are made when asked for
    /// (see [`ExactPolygon::edge_plane`]): every corner is pushed this way, none by
    /// [`Builder::push`].
    #[inline]
    pub(crate) fn push_input_corner(&mut self, corner: Corner) {
        debug_assert!(self.edges.is_empty());
        self.corners.push(corner);
    }

    /// The polygon, computing the filter's per-polygon bounds.
    pub(crate) fn finish(self, support: Plane) -> ExactPolygon {
        let mut max_abs: f32 = 0.0;
        let mut max_err: f32 = 0.0;
        for c in &self.corners {
            let m = c.pos[0].abs().max(c.pos[1].abs()).max(c.pos[2].abs());
            max_abs = max_abs.max(err32(m));
            max_err = max_err.max(c.err);
        }
        ExactPolygon {
            corners: self.corners,
            max_abs,
            max_err,
            edges: self.edges.into_boxed_slice(),
            support,
        }
    }
}

/// A convex polygon of the exact kernel.
///
/// Representation: the supporting plane `S` and, per edge `i`, a bounding plane `Eᵢ` with
/// the interior on its back side. Vertex `i` is `S ∩ Eᵢ₋₁ ∩ Eᵢ` (an input point for the
/// corners of input faces); it is never stored as rounded coordinates for decisions: the
/// cached f64 position only feeds the filter, together with its proven error bound. Guarantees: at least three vertices, strictly
/// convex (no three consecutive vertices collinear), non-zero area, vertices
/// counter-clockwise seen from the front of `S`.
///
/// Layout: the data the filter reads (cached positions, per-polygon bounds) comes first
/// and is stored apart from the edge planes; up to four vertices need no heap. An input
/// polygon stores no edge planes (`edges` is empty): its edge `i` is the plane through
/// its input corners `i` and `i + 1` along the dominant axis of its supporting plane,
/// made only when asked for (by a split, or [`ExactPolygon::edge_plane`]). Most polygons
/// of a large scene are never split, and three planes per triangle were most of the
/// ordering's memory.
#[derive(Debug, Clone)]
#[repr(C)]
pub struct ExactPolygon {
    pub(crate) corners: SmallVec<[Corner; INLINE]>,
    /// Upper bound on `|coordinate|` over all cached vertex positions (semi-static filter).
    max_abs: f32,
    /// Upper bound on the error bounds of all cached vertex positions.
    max_err: f32,
    /// The edge planes, or none for an input polygon (made when asked for). Boxed, not
    /// inline: most polygons of a large scene are input polygons, and four inline planes
    /// made every one of them 56 bytes larger (a million-face scene's pieces, 27 MB).
    edges: Box<[Plane]>,
    pub(crate) support: Plane,
}

impl ExactPolygon {
    /// The supporting plane (normal towards the front).
    pub fn support(&self) -> Plane {
        self.support.clone()
    }

    /// Number of vertices.
    pub fn len(&self) -> usize {
        self.corners.len()
    }

    /// Always false (a polygon has at least three vertices); present for API symmetry.
    pub fn is_empty(&self) -> bool {
        self.corners.is_empty()
    }

    /// The bounding plane of edge `i` (from vertex `i` to `i + 1`); the interior is on its
    /// back side. Panics if `i` is out of range.
    pub fn edge_plane(&self, i: usize) -> Plane {
        match self.edges.get(i) {
            Some(e) => e.clone(),
            None => self.input_edge(i),
        }
    }

    /// Edge `i` of an input polygon (no stored edge planes): the plane through corners
    /// `i` and `i + 1` (both input points) containing the direction of the supporting
    /// plane's dominant exact axis, as [`crate::face`] defines it. Panics if `i` is out
    /// of range.
    fn input_edge(&self, i: usize) -> Plane {
        self.input_edge_along(i, input_edge_axis(&self.support))
    }

    /// [`ExactPolygon::input_edge`] with the axis and orientation already found.
    fn input_edge_along(&self, i: usize, (k, flip): (usize, bool)) -> Plane {
        let n = self.corners.len();
        Plane::edge(self.corners[i].pos, self.corners[(i + 1) % n].pos, k, flip)
    }

    /// Every edge plane: the stored ones, or made now for an input polygon.
    fn edge_planes(&self) -> Cow<'_, [Plane]> {
        if !self.edges.is_empty() {
            return Cow::Borrowed(&self.edges);
        }
        let axis = input_edge_axis(&self.support);
        Cow::Owned(
            (0..self.corners.len())
                .map(|i| self.input_edge_along(i, axis))
                .collect(),
        )
    }

    /// The stored planes of the edges before and at vertex `i`, a vertex that is not an
    /// input point (only split polygons have such vertices, and they store their edges).
    #[inline]
    fn stored_edges_at(&self, i: usize) -> Option<(&Plane, &Plane)> {
        let n = self.edges.len();
        if n == 0 {
            return None;
        }
        Some((&self.edges[(i + n - 1) % n], &self.edges[i]))
    }

    /// Whether edge `i` lies on an edge of the input face.
    pub fn edge_is_original(&self, i: usize) -> bool {
        self.corners.get(i).is_some_and(|c| c.original)
    }

    /// The three planes whose intersection is vertex `i`: support, edge `i - 1`, edge `i`.
    /// Panics if `i` is out of range.
    pub fn vertex_planes(&self, i: usize) -> [Plane; 3] {
        let n = self.corners.len();
        [
            self.support.clone(),
            self.edge_plane((i + n - 1) % n),
            self.edge_plane(i),
        ]
    }

    /// The cached approximate coordinates of vertex `i` and their error bound (0 when
    /// they are the vertex exactly). Panics if `i` is out of range.
    pub fn vertex_approx(&self, i: usize) -> ([f64; 3], f64) {
        let c = &self.corners[i];
        (c.pos, c.err as f64)
    }

    /// Exact side of `h` at vertex `i`, without the filter. Panics if `i` is out of range.
    pub fn side_exact(&self, i: usize, h: &Plane) -> Side {
        let c = &self.corners[i];
        if c.err == 0.0 {
            return h.side_exact(c.pos);
        }
        match self.stored_edges_at(i) {
            Some((a, b)) => {
                // A vertex lies on its own planes: told at once, not remembered.
                if h.same_definition(&self.support) || h.same_definition(a) || h.same_definition(b)
                {
                    return Side::On;
                }
                vertex_memo::side_at([&self.support, a, b], h, || {
                    predicates::side_of_intersection(&self.support, a, b, h).unwrap_or(Side::On)
                })
            }
            // Not reached: an input polygon's vertices are input points (error 0).
            None => h.side_exact(c.pos),
        }
    }

    /// The semi-static filter's sign at corner `c`: `1` front, `-1` back, `0` undecided.
    /// Branch-free, so that random outcomes cost no mispredictions.
    #[inline(always)]
    fn coarse_sign(c: &Corner, hf: &PlaneF, coarse: f64) -> i8 {
        let v = hf.eval(&c.pos);
        (v > coarse) as i8 - (v < -coarse) as i8
    }

    /// The side of vertex `i` after the coarse filter failed: the per-vertex filter and
    /// the combinatorial shortcuts, then (counted in `fallbacks`) planes known to
    /// coincide, the filter at the vertex's exact intersection rounded to f64, and the
    /// exact evaluation.
    #[inline]
    fn fine_side(&self, i: usize, h: &Plane, hf: &PlaneF, fallbacks: &mut u64) -> Side {
        if let Some(s) = self.filtered_side(i, h, hf) {
            return s;
        }
        let c = &self.corners[i];
        if c.err != 0.0 {
            if let Some((a, b)) = self.stored_edges_at(i) {
                if let Some(s) = side_along_common_line(h, [&self.support, a, b], c) {
                    return s;
                }
            }
        }
        *fallbacks += 1;
        if self.corners[i].err != 0.0 {
            if let Some((a, b)) = self.stored_edges_at(i) {
                if [&self.support, a, b].into_iter().any(|x| h.is_within(x)) {
                    return Side::On;
                }
                if let Some(s) = side_at_rounded([&self.support, a, b], hf) {
                    return s;
                }
            }
        }
        self.side_exact(i, h)
    }

    /// The side of vertex `i` by the per-vertex filter and the combinatorial shortcut,
    /// or `None` when only exact evaluation can tell.
    #[inline]
    fn filtered_side(&self, i: usize, h: &Plane, hf: &PlaneF) -> Option<Side> {
        let c = &self.corners[i];
        if let Some(s) = hf.side(&c.pos, c.err as f64) {
            return Some(s);
        }
        // The combinatorial shortcut: a vertex that defines the plane, or is defined by
        // it, lies on it (neighbouring faces share vertices; split vertices lie on their
        // cut).
        if c.err == 0.0 {
            if h.defined_by(&c.pos) {
                return Some(Side::On);
            }
        } else if let Some((a, b)) = self.stored_edges_at(i) {
            if h.same_definition(&self.support) || h.same_definition(a) || h.same_definition(b) {
                return Some(Side::On);
            }
            if on_common_line(h, [&self.support, a, b]) {
                return Some(Side::On);
            }
        }
        None
    }

    /// [`crate::Kernel::vertex_heights`]: the filter's values and bounds of `h` at the
    /// cached vertex positions.
    pub(crate) fn heights(&self, h: &Plane, out: &mut [(f64, f64)]) -> bool {
        if out.len() < self.corners.len() {
            return false;
        }
        let hf = h.filter();
        for (o, c) in out.iter_mut().zip(&self.corners) {
            *o = hf.height(&c.pos, c.err as f64);
            if !(o.0.is_finite() && o.1.is_finite()) {
                return false;
            }
        }
        true
    }

    /// Classification against `h` when the filters and shortcuts decide it (`None` when
    /// some vertex needs exact evaluation and the answer is still open).
    pub(crate) fn classify_filtered(&self, h: &Plane) -> Option<PolygonSide> {
        let hf = h.filter();
        let coarse = self.coarse_bound(&hf);
        let (mut front, mut back, mut unsure) = (false, false, false);
        for (i, c) in self.corners.iter().enumerate() {
            let side = match Self::coarse_sign(c, &hf, coarse) {
                1 => Some(Side::Front),
                -1 => Some(Side::Back),
                _ => self.filtered_side(i, h, &hf),
            };
            match side {
                Some(Side::Front) => front = true,
                Some(Side::Back) => back = true,
                Some(Side::On) => {}
                None => unsure = true,
            }
            if front && back {
                return Some(PolygonSide::Spanning);
            }
        }
        if unsure {
            return None;
        }
        Some(match (front, back) {
            (true, _) => PolygonSide::Front,
            (_, true) => PolygonSide::Back,
            _ if self.support.same_facing(h) => PolygonSide::Coplanar,
            _ => PolygonSide::CoplanarOpposite,
        })
    }

    #[inline]
    fn coarse_bound(&self, hf: &PlaneF) -> f64 {
        hf.bound_for(self.max_abs as f64, self.max_err as f64)
    }

    /// Side of vertex `i` using the filters first; counts a fallback in `fallbacks`.
    #[inline]
    pub(crate) fn side_filtered(
        &self,
        i: usize,
        h: &Plane,
        hf: &PlaneF,
        fallbacks: &mut u64,
    ) -> Side {
        match Self::coarse_sign(&self.corners[i], hf, self.coarse_bound(hf)) {
            1 => Side::Front,
            -1 => Side::Back,
            _ => self.fine_side(i, h, hf, fallbacks),
        }
    }

    /// Sides of all vertices: the coarse filter on every vertex, then the per-vertex
    /// filter and exact evaluations for the undecided ones (or exact only, without filter).
    #[inline]
    fn sides(
        &self,
        h: &Plane,
        hf: &PlaneF,
        filter: bool,
        fallbacks: &mut u64,
    ) -> SmallVec<[Side; 8]> {
        if !filter {
            return (0..self.corners.len())
                .map(|i| self.side_exact(i, h))
                .collect();
        }
        let coarse = self.coarse_bound(hf);
        let mut signs: SmallVec<[i8; 8]> = SmallVec::with_capacity(self.corners.len());
        let mut unsure = false;
        for c in &self.corners {
            let s = Self::coarse_sign(c, hf, coarse);
            unsure |= s == 0;
            signs.push(s);
        }
        let mut sides: SmallVec<[Side; 8]> = signs
            .iter()
            .map(|&s| match s {
                1 => Side::Front,
                -1 => Side::Back,
                _ => Side::On,
            })
            .collect();
        if unsure {
            for (i, &s) in signs.iter().enumerate() {
                if s == 0 {
                    sides[i] = self.fine_side(i, h, hf, fallbacks);
                }
            }
        }
        sides
    }

    /// Classification against `h`: the coarse filter on every vertex; only if it leaves
    /// vertices undecided and the answer open, the per-vertex filter and then exact
    /// evaluations for those vertices, stopping as soon as the answer is known.
    pub(crate) fn classify(&self, h: &Plane, filter: bool, fallbacks: &mut u64) -> PolygonSide {
        const FRONT: u8 = 1;
        const BACK: u8 = 2;
        let bit = |s: Side| match s {
            Side::Front => FRONT,
            Side::Back => BACK,
            Side::On => 0,
        };
        let hf = h.filter();
        let mut flags = 0u8;
        if filter {
            let coarse = self.coarse_bound(&hf);
            // The extreme filter values decide the common cases at once.
            let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
            for c in &self.corners {
                let v = hf.eval(&c.pos);
                lo = if v < lo { v } else { lo };
                hi = if v > hi { v } else { hi };
            }
            flags = ((hi > coarse) as u8 * FRONT) | ((lo < -coarse) as u8 * BACK);
            // Otherwise some vertex is undecided (all decided means all front, all back,
            // or both present).
            let decided = lo > coarse || hi < -coarse || flags == FRONT | BACK;
            if !decided {
                for (i, c) in self.corners.iter().enumerate() {
                    if Self::coarse_sign(c, &hf, coarse) == 0 {
                        flags |= bit(self.fine_side(i, h, &hf, fallbacks));
                        if flags == FRONT | BACK {
                            break;
                        }
                    }
                }
            }
        } else {
            for i in 0..self.corners.len() {
                flags |= bit(self.side_exact(i, h));
                if flags == FRONT | BACK {
                    break;
                }
            }
        }
        match flags {
            3 => PolygonSide::Spanning,
            FRONT => PolygonSide::Front,
            BACK => PolygonSide::Back,
            _ if self.support.same_facing(h) => PolygonSide::Coplanar,
            _ => PolygonSide::CoplanarOpposite,
        }
    }

    /// Splits by `h` (see [`crate::Kernel::split`]).
    pub(crate) fn split(
        &self,
        h: &Plane,
        filter: bool,
        fallbacks: &mut u64,
    ) -> (Option<ExactPolygon>, Option<ExactPolygon>) {
        let hf = h.filter();
        let sides = self.sides(h, &hf, filter, fallbacks);
        let front = sides.contains(&Side::Front);
        let back = sides.contains(&Side::Back);
        match (front, back) {
            (true, false) => return (Some(self.clone()), None),
            (false, true) => return (None, Some(self.clone())),
            (false, false) => {
                return if self.support.same_facing(h) {
                    (Some(self.clone()), None)
                } else {
                    (None, Some(self.clone()))
                };
            }
            (true, true) => {}
        }
        let n = self.corners.len();
        let neg = h.flipped();
        let edges = self.edge_planes();
        let mut fp = Builder::default();
        let mut bp = Builder::default();
        for i in 0..n {
            let (c, e) = (self.corners[i], &edges[i]);
            let j = if i + 1 == n { 0 } else { i + 1 };
            let (si, sj) = (sides[i], sides[j]);
            // Vertex i itself; its outgoing edge becomes the cut when the polygon leaves
            // the piece's side right after it.
            if si != Side::Back {
                if si == Side::On && sj == Side::Back {
                    fp.push(cut_corner(&c), neg.clone());
                } else {
                    fp.push(c, e.clone());
                }
            }
            if si != Side::Front {
                if si == Side::On && sj == Side::Front {
                    bp.push(cut_corner(&c), h.clone());
                } else {
                    bp.push(c, e.clone());
                }
            }
            // A strict crossing of edge i.
            let crossing = matches!(
                (si, sj),
                (Side::Front, Side::Back) | (Side::Back, Side::Front)
            );
            if crossing {
                let (pos, err) = predicates::approximate(&self.support, e, h)
                    .or_else(|| {
                        let p = predicates::rounded_intersection(&self.support, e, h)?;
                        Some((p, f64::INFINITY))
                    })
                    .unwrap_or(([0.0; 3], f64::INFINITY));
                let on_edge = Corner {
                    pos,
                    err: err32(err),
                    original: c.original,
                };
                if si == Side::Front {
                    fp.push(cut_corner(&on_edge), neg.clone());
                    bp.push(on_edge, e.clone());
                } else {
                    fp.push(on_edge, e.clone());
                    bp.push(cut_corner(&on_edge), h.clone());
                }
            }
        }
        (
            Some(fp.finish(self.support.clone())),
            Some(bp.finish(self.support.clone())),
        )
    }
}

impl ExactPolygon {
    /// The corners of the two parts [`ExactPolygon::split`] makes, as positions within
    /// `rel` times their largest coordinate of the true corners, appended to `front` and
    /// `back` (see [`crate::Kernel::split_world`]): the same exact sides, the crossing
    /// points approximated from the planes' coefficients (an input polygon's edge plane
    /// only as coefficients, never made), no polygon built. `false`, with `front` and
    /// `back` as they were, when some corner's bound is larger.
    pub(crate) fn split_world(
        &self,
        h: &Plane,
        filter: bool,
        fallbacks: &mut u64,
        rel: f64,
        front: &mut Vec<glam::DVec3>,
        back: &mut Vec<glam::DVec3>,
    ) -> bool {
        let close = |(pos, err): ([f64; 3], f64)| {
            let scale = pos[0].abs().max(pos[1].abs()).max(pos[2].abs());
            (err <= rel * scale).then(|| glam::DVec3::from_array(pos))
        };
        let corner = |c: &Corner| close((c.pos, c.err as f64));
        let hf = h.filter();
        let sides = self.sides(h, &hf, filter, fallbacks);
        let has_front = sides.contains(&Side::Front);
        let has_back = sides.contains(&Side::Back);
        let (f0, b0) = (front.len(), back.len());
        let undo = |front: &mut Vec<glam::DVec3>, back: &mut Vec<glam::DVec3>| {
            front.truncate(f0);
            back.truncate(b0);
            false
        };
        if !(has_front && has_back) {
            let to_front = has_front || (!has_back && self.support.same_facing(h));
            let out = if to_front { &mut *front } else { &mut *back };
            for c in &self.corners {
                match corner(c) {
                    Some(p) => out.push(p),
                    None => return undo(front, back),
                }
            }
            return true;
        }
        let n = self.corners.len();
        let axis = self
            .edges
            .is_empty()
            .then(|| input_edge_axis(&self.support));
        let (sn, sd) = (self.support.approx(), self.support.error_bounds());
        let (hn, hd) = (h.approx(), h.error_bounds());
        for i in 0..n {
            let c = &self.corners[i];
            let j = if i + 1 == n { 0 } else { i + 1 };
            let (si, sj) = (sides[i], sides[j]);
            let Some(p) = corner(c) else {
                return undo(front, back);
            };
            if si != Side::Back {
                front.push(p);
            }
            if si != Side::Front {
                back.push(p);
            }
            if matches!(
                (si, sj),
                (Side::Front, Side::Back) | (Side::Back, Side::Front)
            ) {
                let (en, ed) = match axis {
                    Some((k, flip)) => {
                        Plane::edge_coefficients(c.pos, self.corners[j].pos, k, flip)
                    }
                    None => (self.edges[i].approx(), self.edges[i].error_bounds()),
                };
                let Some(p) =
                    predicates::approximate_from((sn, sd), (en, ed), (hn, hd)).and_then(close)
                else {
                    return undo(front, back);
                };
                front.push(p);
                back.push(p);
            }
        }
        true
    }
}

/// The axis an input polygon's edge planes contain, and whether their normals are
/// negated: the dominant exact axis of the supporting plane's normal, negated when the
/// normal's component there is negative (so the interior lies behind every edge).
pub(crate) fn input_edge_axis(support: &Plane) -> (usize, bool) {
    let k = support.dominant_exact_axis();
    (k, support.normal_sign(k) == std::cmp::Ordering::Less)
}

/// Whether two of a vertex's planes meet in a line through two input points that both lie
/// on `h` (or through an input point along a direction that both lie in `h`): then the
/// vertex lies on `h` (the usual case of a vertex made on an edge that neighbouring faces
/// share, or on the shadow of a corner that neighbouring occluders share).
fn on_common_line(h: &Plane, planes: [&Plane; 3]) -> bool {
    for (x, y) in [(0, 1), (0, 2), (1, 2)] {
        if let Some((p, q)) = planes[x].common_line(planes[y]) {
            if h.side_of(p) == Side::On && h.side_of(q) == Side::On {
                return true;
            }
        }
        if let Some((p, d)) = planes[x].common_ray(planes[y]) {
            if h.contains_direction(d) && h.side_of(p) == Side::On {
                return true;
            }
        }
    }
    false
}

/// The side of `h` at the vertex of corner `c` (the intersection of `planes`) when two of
/// the planes meet in a line through two input points `p`, `q` of which exactly one lies
/// on `h`, and the cached position tells on which side of that point along the line the
/// vertex lies: `None` otherwise.
///
/// The vertex is `v = p + t·(q − p)` and `h`'s equation is affine along the line, so
/// with `h(p) = 0` its value at `v` is `t·h(q)`: the side of `q`, kept when `t > 0` and
/// reversed when `t < 0`. The sign of `t` is that of `(v − p)·(q − p)`, told by interval
/// arithmetic on the cached position and its error bound (undecided near `t = 0`, where
/// only exact evaluation can tell). So the side at an implicit vertex costs one exact
/// side of an input point instead of a degree-nine polynomial in the input: the usual
/// case, seen from the eye, of a corner's shadow on a receiver (the line from the eye
/// through an occluder's corner) tested against a side plane of a neighbouring occluder
/// through the eye and an edge away from that corner.
fn side_along_common_line(h: &Plane, planes: [&Plane; 3], c: &Corner) -> Option<Side> {
    for (x, y) in [(0, 1), (0, 2), (1, 2)] {
        let Some((p, q)) = planes[x].common_line(planes[y]) else {
            continue;
        };
        let (on, other, toward) = match (h.side_of(p), h.side_of(q)) {
            (Side::On, Side::On) => return Some(Side::On),
            (Side::On, s) => (p, s, q),
            (s, Side::On) => (q, s, p),
            _ => continue,
        };
        let err = c.err as f64;
        let w = [0, 1, 2].map(|k| Interval::around(c.pos[k], err) - Interval::exactly(on[k]));
        let d = [0, 1, 2].map(|k| Interval::exactly(toward[k]) - Interval::exactly(on[k]));
        match Interval::dot(w, d).sign() {
            Some(std::cmp::Ordering::Greater) => return Some(other),
            Some(std::cmp::Ordering::Less) => return Some(other.flip()),
            _ => {}
        }
    }
    None
}

/// Bounds of the magnitudes at which [`predicates::rounded_intersection`] is within
/// `2⁻⁵⁰` of each coordinate relative to the largest (its quotient keeps 64 bits and is
/// scaled by powers of two that neither overflow nor underflow there): `2⁻⁹⁰⁰..2⁹⁰⁰`.
const ROUNDED_MIN: f64 = 1.2e-271;
const ROUNDED_MAX: f64 = 8.4e270;

/// The filter at the exact intersection of `planes` rounded to f64 (remembered per
/// vertex): a second, tighter filter than the cached Cramer approximation, whose bound
/// grows with how nearly the planes meet in a line (as side planes through the eye and
/// two short edges far from it do). The rounded coordinates are within `2⁻⁵⁰` of the
/// largest one's magnitude of the exact ones (see [`ROUNDED_MIN`]); `None` when the
/// filter cannot decide there, or the coordinates lie outside that range.
fn side_at_rounded(planes: [&Plane; 3], hf: &PlaneF) -> Option<Side> {
    let [s, a, b] = planes;
    let pos = vertex_memo::rounded(planes, || predicates::rounded_intersection(s, a, b))?;
    let scale = pos[0].abs().max(pos[1].abs()).max(pos[2].abs());
    let usable = pos
        .iter()
        .all(|x| *x == 0.0 || (ROUNDED_MIN..=ROUNDED_MAX).contains(&x.abs()));
    if !usable || scale == 0.0 {
        return None;
    }
    hf.side(&pos, scale * f64::powi(2.0, -50))
}

/// The corner at the same vertex whose outgoing edge is a cut (not original).
#[inline]
fn cut_corner(c: &Corner) -> Corner {
    Corner {
        pos: c.pos,
        err: c.err,
        original: false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The depth orderings keep about a million polygons: guard the layout.
    #[test]
    fn layout_stays_compact() {
        assert_eq!(std::mem::size_of::<Corner>(), 32);
        assert_eq!(std::mem::size_of::<Plane>(), 16);
        assert!(std::mem::size_of::<ExactPolygon>() <= 176);
    }

    #[test]
    fn err32_rounds_up() {
        for e in [1e-300, 0.1, 1.0 / 3.0, 1e30, 123456.789] {
            assert!(err32(e) as f64 >= e);
        }
        assert_eq!(err32(0.0), 0.0);
        assert_eq!(err32(f64::NAN), f32::INFINITY);
        assert_eq!(err32(1e300), f32::INFINITY);
    }
}
