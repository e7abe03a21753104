//! The working state shared by the orderings: the piece arena (every polygon and every
//! fragment split from it, with its provenance), projections, and the exact pair
//! relations.

use crate::shared::ExactVertices;
use glam::{DMat4, DVec3};
use limn_kernel::{PolygonSide, Side};
use limn_scene::Camera;

use crate::geom::{bbox, convex_disjoint, Box2};
use crate::options::Stats;

/// A projected polygon.
type Ring = Vec<[f64; 2]>;

/// No piece.
pub(crate) const NONE: u32 = u32::MAX;

/// A convex polygon taking part in the ordering: an input polygon or a piece split from
/// one. Pieces are never removed: a split piece stays as the parent of its two halves,
/// so halves that end up next to each other can be joined again exactly.
pub(crate) struct Piece<K: ExactVertices> {
    pub poly: K::Polygon,
    pub plane: K::Plane,
    pub face: u32,
    pub parent: u32,
    pub kids: [u32; 2],
    /// The eye lies strictly in front of the supporting plane.
    pub eye_front: bool,
    /// Projected vertices in pixels.
    pub pts: Vec<[f64; 2]>,
    pub bbox: Box2,
    /// Range of view depth (clip w) over the vertices.
    pub dmin: f64,
    pub dmax: f64,
    pub dmean: f64,
}

/// Where a polygon lies with respect to another polygon's plane, seen from the eye.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Rel {
    /// On the eye's side (touching allowed).
    Eye,
    /// On the far side (touching allowed).
    Far,
    /// In the plane.
    Coplanar,
    /// Strictly on both sides.
    Span,
}

/// The order two polygons must be painted in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Pair {
    /// Neither can hide the other.
    Free,
    /// The first must be painted before the second.
    FirstBefore,
    /// The second must be painted before the first.
    SecondBefore,
    /// Each could hide the other (interpenetration): only splitting helps.
    Conflict,
}

pub(crate) struct Ctx<'a, K: ExactVertices> {
    pub k: &'a K,
    pub eye: K::Point,
    pub vp: DMat4,
    pub camera: Camera,
    pub pieces: Vec<Piece<K>>,
    pub stats: Stats,
    /// Pixel margin of the float prefilters.
    pub margin: f64,
    /// Depth margin of the float prefilters.
    pub dmargin: f64,
    rng: u64,
    scratch: Vec<DVec3>,
}

impl<'a, K: ExactVertices> Ctx<'a, K> {
    pub fn new(k: &'a K, eye: K::Point, camera: Camera, vp: DMat4, far: f64, seed: u64) -> Self {
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
            rng: seed ^ 0x9E37_79B9_7F4A_7C15,
            scratch: Vec::new(),
        }
    }

    /// A deterministic pseudo-random number (splitmix64).
    pub fn next_random(&mut self) -> u64 {
        self.rng = self.rng.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.rng;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Adds a piece and projects it. `eye_front` is computed when `None`.
    pub fn add(
        &mut self,
        poly: K::Polygon,
        face: u32,
        parent: u32,
        eye_front: Option<bool>,
    ) -> u32 {
        let plane = self.k.support(&poly);
        let eye_front =
            eye_front.unwrap_or_else(|| self.k.side_of_point(&plane, &self.eye) == Side::Front);
        self.scratch.clear();
        self.k.vertices_world(&poly, &mut self.scratch);
        let mut pts = Vec::with_capacity(self.scratch.len());
        let (mut dmin, mut dmax, mut dsum) = (f64::INFINITY, f64::NEG_INFINITY, 0.0);
        for &p in &self.scratch {
            let pr = self.camera.project_with(&self.vp, p);
            pts.push([pr.x, pr.y]);
            dmin = dmin.min(pr.w);
            dmax = dmax.max(pr.w);
            dsum += pr.w;
        }
        let dmean = dsum / pts.len().max(1) as f64;
        let bbox = bbox(&pts);
        self.pieces.push(Piece {
            poly,
            plane,
            face,
            parent,
            kids: [NONE, NONE],
            eye_front,
            pts,
            bbox,
            dmin,
            dmax,
            dmean,
        });
        (self.pieces.len() - 1) as u32
    }

    /// Where piece `q` lies with respect to the plane of piece `p`.
    pub fn rel(&self, q: u32, p: u32) -> Rel {
        let pp = &self.pieces[p as usize];
        let side = self.k.classify(&self.pieces[q as usize].poly, &pp.plane);
        match side {
            PolygonSide::Front => {
                if pp.eye_front {
                    Rel::Eye
                } else {
                    Rel::Far
                }
            }
            PolygonSide::Back => {
                if pp.eye_front {
                    Rel::Far
                } else {
                    Rel::Eye
                }
            }
            PolygonSide::Coplanar | PolygonSide::CoplanarOpposite => Rel::Coplanar,
            PolygonSide::Spanning => Rel::Span,
        }
    }

    /// The exact order constraint between pieces `p` and `q`, assuming their projections
    /// may overlap. Coplanar pieces of different faces: the later face in input order is
    /// painted last (it wins); pieces of one face never constrain each other.
    pub fn pair(&self, p: u32, q: u32) -> Pair {
        let q_rel_p = self.rel(q, p);
        if q_rel_p == Rel::Coplanar {
            return self.coplanar_rule(p, q);
        }
        let p_rel_q = self.rel(p, q);
        if p_rel_q == Rel::Coplanar {
            return self.coplanar_rule(p, q);
        }
        let q_cannot_hide_p = q_rel_p == Rel::Far || p_rel_q == Rel::Eye;
        let p_cannot_hide_q = p_rel_q == Rel::Far || q_rel_p == Rel::Eye;
        let pair = match (q_cannot_hide_p, p_cannot_hide_q) {
            (true, true) => return Pair::Free,
            (true, false) => Pair::SecondBefore,
            (false, true) => Pair::FirstBefore,
            (false, false) => self.resolve_spanning(p, q),
        };
        if pair != Pair::Free && self.only_touch(p, q) {
            return Pair::Free;
        }
        pair
    }

    /// Whether `p` and `q` share a vertex at which their projections lie in disjoint
    /// angular sectors: then (both being convex) their projections only touch. Decided
    /// exactly; `false` when no shared vertex is exactly known.
    pub fn only_touch(&self, p: u32, q: u32) -> bool {
        let (pp, qq) = (&self.pieces[p as usize], &self.pieces[q as usize]);
        let (np, nq) = (self.k.vertex_count(&pp.poly), self.k.vertex_count(&qq.poly));
        let qv: Vec<Option<K::Exact>> = (0..nq).map(|j| self.k.vertex_exact(&qq.poly, j)).collect();
        let e = self.k.point_exact(&self.eye);
        for i in 0..np {
            let Some(v) = self.k.vertex_exact(&pp.poly, i) else {
                continue;
            };
            let Some(j) = qv.iter().position(|w| *w == Some(v)) else {
                continue;
            };
            let (Some(p1), Some(p2)) = (
                self.k.vertex_exact(&pp.poly, (i + np - 1) % np),
                self.k.vertex_exact(&pp.poly, (i + 1) % np),
            ) else {
                continue;
            };
            let (Some(q1), Some(q2)) = (qv[(j + nq - 1) % nq], qv[(j + 1) % nq]) else {
                continue;
            };
            let o = |a: &K::Exact, b: &K::Exact| self.k.orient(&e, &v, a, b);
            // Orient both sectors counter-clockwise (as seen from the eye).
            let (p1, p2) = match o(&p1, &p2) {
                1 => (p1, p2),
                -1 => (p2, p1),
                _ => continue,
            };
            let (q1, q2) = match o(&q1, &q2) {
                1 => (q1, q2),
                -1 => (q2, q1),
                _ => continue,
            };
            // A boundary ray of one sector whose line leaves the other sector on its
            // outer side separates them.
            if (o(&p1, &q1) <= 0 && o(&p1, &q2) <= 0)
                || (o(&p2, &q1) >= 0 && o(&p2, &q2) >= 0)
                || (o(&q1, &p1) <= 0 && o(&q1, &p2) <= 0)
                || (o(&q2, &p1) >= 0 && o(&q2, &p2) >= 0)
            {
                return true;
            }
        }
        false
    }

    /// `p` and `q` each span the other's plane. If they do not pierce each other, only
    /// one half of `p` (cut by `q`'s plane) can overlap `q` on screen, and that half
    /// decides the order. A half is ruled out only when the float separating-axis test
    /// shows a gap wider than the margin, so a doubtful case stays a conflict (and gets
    /// split); the order itself follows from exact plane sides.
    fn resolve_spanning(&self, p: u32, q: u32) -> Pair {
        let (pp, qq) = (&self.pieces[p as usize], &self.pieces[q as usize]);
        // Halves of p: the one on the eye's side of q's plane cannot be hidden by q; the
        // far one cannot hide q.
        let (p_eye, p_far) = self.halves(&pp.poly, qq);
        let p_eye_clear = p_eye
            .as_ref()
            .is_none_or(|h| convex_disjoint(h, &qq.pts, self.margin));
        let p_far_clear = p_far
            .as_ref()
            .is_none_or(|h| convex_disjoint(h, &qq.pts, self.margin));
        match (p_eye_clear, p_far_clear) {
            (true, true) => return Pair::Free,
            (false, true) => return Pair::SecondBefore,
            (true, false) => return Pair::FirstBefore,
            (false, false) => {}
        }
        let (q_eye, q_far) = self.halves(&qq.poly, pp);
        let q_eye_clear = q_eye
            .as_ref()
            .is_none_or(|h| convex_disjoint(h, &pp.pts, self.margin));
        let q_far_clear = q_far
            .as_ref()
            .is_none_or(|h| convex_disjoint(h, &pp.pts, self.margin));
        match (q_eye_clear, q_far_clear) {
            (true, true) => Pair::Free,
            (false, true) => Pair::FirstBefore,
            (true, false) => Pair::SecondBefore,
            (false, false) => Pair::Conflict,
        }
    }

    /// The projected halves of `poly` on the eye's side and on the far side of `by`'s
    /// plane.
    fn halves(&self, poly: &K::Polygon, by: &Piece<K>) -> (Option<Ring>, Option<Ring>) {
        let (front, back) = self.k.split(poly, &by.plane);
        let project = |h: Option<K::Polygon>| {
            h.map(|h| {
                let n = self.k.vertex_count(&h);
                let fast: Option<Vec<glam::DVec3>> =
                    (0..n).map(|i| self.k.vertex_world_fast(&h, i)).collect();
                let w = fast.unwrap_or_else(|| {
                    let mut w = Vec::new();
                    self.k.vertices_world(&h, &mut w);
                    w
                });
                w.iter()
                    .map(|&v| {
                        let pr = self.camera.project_with(&self.vp, v);
                        [pr.x, pr.y]
                    })
                    .collect::<Vec<_>>()
            })
        };
        let (front, back) = (project(front), project(back));
        if by.eye_front {
            (front, back)
        } else {
            (back, front)
        }
    }

    fn coplanar_rule(&self, p: u32, q: u32) -> Pair {
        let (fp, fq) = (self.pieces[p as usize].face, self.pieces[q as usize].face);
        match fp.cmp(&fq) {
            std::cmp::Ordering::Less => Pair::FirstBefore,
            std::cmp::Ordering::Greater => Pair::SecondBefore,
            std::cmp::Ordering::Equal => Pair::Free,
        }
    }

    /// Splits piece `id` by the plane of piece `by`. Returns the ids of the part on the
    /// eye's side of that plane and the part on the far side (either may be absent when
    /// the piece does not span the plane).
    pub fn split_by(&mut self, id: u32, by: u32) -> (Option<u32>, Option<u32>) {
        let plane = self.pieces[by as usize].plane.clone();
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
