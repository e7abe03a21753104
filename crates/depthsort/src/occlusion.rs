//! The exact occlusion relations between two pieces: which side of each other's plane
//! they lie on as seen from the eye, the order they must be painted in, and the exact
//! test for pieces that only touch at a shared vertex.

use limn_kernel::{Kernel, Orientation, PolygonSide};

use crate::geom::convex_disjoint;
use crate::pieces::{Ctx, Piece};

/// A projected polygon.
type Ring = Vec<[f64; 2]>;

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

impl<K: Kernel> Ctx<'_, K> {
    /// Where piece `q` lies with respect to the plane of piece `p`.
    pub fn rel(&self, q: u32, p: u32) -> Rel {
        let pp = &self.pieces[p as usize];
        self.rel_of(
            p,
            self.k
                .classify(&self.pieces[q as usize].poly, self.k.support(&pp.poly)),
        )
    }

    /// [`Ctx::rel`] when the kernel can tell it cheaply.
    pub fn rel_if_cheap(&self, q: u32, p: u32) -> Option<Rel> {
        let pp = &self.pieces[p as usize];
        let side = self
            .k
            .classify_if_cheap(&self.pieces[q as usize].poly, self.k.support(&pp.poly))?;
        Some(self.rel_of(p, side))
    }

    /// The relation to `p`'s plane that a classification against it means.
    fn rel_of(&self, p: u32, side: PolygonSide) -> Rel {
        let pp = &self.pieces[p as usize];
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
        if self.apart_by_construction(p, q) {
            return Pair::Free;
        }
        // Neighbours in a mesh share a vertex and usually only touch on screen. When a
        // plane side would need exact evaluation (nearly coplanar neighbours), the sector
        // test at the shared vertex, made of well-conditioned orientations through the
        // eye, is tried first.
        let touching = self.share_projected_corner(p, q);
        let mut sectors_tried = false;
        let costly_rel = |a: u32, b: u32, tried: &mut bool| -> Option<Rel> {
            if let Some(r) = self.rel_if_cheap(a, b) {
                return Some(r);
            }
            if touching && !*tried {
                *tried = true;
                if self.only_touch(p, q) {
                    return None;
                }
            }
            Some(self.rel(a, b))
        };
        let Some(q_rel_p) = costly_rel(q, p, &mut sectors_tried) else {
            return Pair::Free;
        };
        if q_rel_p == Rel::Coplanar {
            return self.coplanar_rule(p, q);
        }
        let Some(p_rel_q) = costly_rel(p, q, &mut sectors_tried) else {
            return Pair::Free;
        };
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
        if pair != Pair::Free && touching && !sectors_tried && self.only_touch(p, q) {
            return Pair::Free;
        }
        pair
    }

    /// Whether `p` and `q` are pieces of the two halves of one quad (triangles sharing a
    /// diagonal) that face the eye alike: each half's projection then lies on its own side
    /// of the projected diagonal (both turn the same way, and they run along the diagonal
    /// in opposite directions), so their projections only touch and neither can hide the
    /// other. Exact: facing is decided exactly, and nothing else is computed.
    pub fn apart_by_construction(&self, p: u32, q: u32) -> bool {
        let (pp, qq) = (&self.pieces[p as usize], &self.pieces[q as usize]);
        pp.face == qq.face && pp.eye_front == qq.eye_front && self.quad_halves[pp.face as usize]
    }

    /// Whether some corner of `p` projects to exactly the same screen point as a corner
    /// of `q`: necessary for them to share a vertex (one input point always projects to
    /// the same f64 values), and cheap enough to screen every pair.
    fn share_projected_corner(&self, p: u32, q: u32) -> bool {
        let (pp, qq) = (&self.pieces[p as usize], &self.pieces[q as usize]);
        pp.pts.iter().any(|a| qq.pts.contains(a))
    }

    /// Whether `p` and `q` share a vertex at which their projections lie in disjoint
    /// angular sectors: then (both being convex) their projections only touch. Decided
    /// exactly; `false` when no shared vertex is exactly known.
    pub fn only_touch(&self, p: u32, q: u32) -> bool {
        let (pp, qq) = (&self.pieces[p as usize], &self.pieces[q as usize]);
        let (np, nq) = (self.k.vertex_count(&pp.poly), self.k.vertex_count(&qq.poly));
        for i in 0..np {
            // A shared vertex projects to the same screen point: only such corners are
            // compared exactly.
            let Some(j) = qq.pts.iter().position(|w| Some(w) == pp.pts.get(i)) else {
                continue;
            };
            let Some(v) = self.k.vertex_exact(&pp.poly, i) else {
                continue;
            };
            if self.k.vertex_exact(&qq.poly, j) != Some(v) {
                continue;
            }
            let (Some(p1), Some(p2)) = (
                self.k.vertex_exact(&pp.poly, (i + np - 1) % np),
                self.k.vertex_exact(&pp.poly, (i + 1) % np),
            ) else {
                continue;
            };
            let (Some(q1), Some(q2)) = (
                self.k.vertex_exact(&qq.poly, (j + nq - 1) % nq),
                self.k.vertex_exact(&qq.poly, (j + 1) % nq),
            ) else {
                continue;
            };
            let o = |a: &K::ExactPoint, b: &K::ExactPoint| self.eye_orientation(&v, a, b);
            // Orient both sectors the same way (as seen from the eye).
            let (p1, p2) = match o(&p1, &p2) {
                Orientation::Positive => (p1, p2),
                Orientation::Negative => (p2, p1),
                Orientation::Coplanar => continue,
            };
            let (q1, q2) = match o(&q1, &q2) {
                Orientation::Positive => (q1, q2),
                Orientation::Negative => (q2, q1),
                Orientation::Coplanar => continue,
            };
            // A boundary ray of one sector whose line leaves the other sector on its
            // outer side separates them.
            let not_pos = |a, b| o(a, b) != Orientation::Positive;
            let not_neg = |a, b| o(a, b) != Orientation::Negative;
            if (not_pos(&p1, &q1) && not_pos(&p1, &q2))
                || (not_neg(&p2, &q1) && not_neg(&p2, &q2))
                || (not_pos(&q1, &p1) && not_pos(&q1, &p2))
                || (not_neg(&q2, &p1) && not_neg(&q2, &p2))
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
    /// split); the order itself follows from exact plane sides. Pieces that clearly pierce
    /// each other by a float estimate are a conflict at once (see [`crate::piercing`]).
    fn resolve_spanning(&self, p: u32, q: u32) -> Pair {
        if self.clearly_pierce(p, q) {
            return Pair::Conflict;
        }
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
        let project = |w: &[glam::DVec3]| -> Option<Ring> {
            (!w.is_empty()).then(|| {
                w.iter()
                    .map(|&v| {
                        let pr = self.camera.project_with(&self.vp, v);
                        [pr.x, pr.y]
                    })
                    .collect()
            })
        };
        let (mut wf, mut wb) = (Vec::new(), Vec::new());
        let (front, back) = if self
            .k
            .split_world(poly, self.k.support(&by.poly), &mut wf, &mut wb)
        {
            (project(&wf), project(&wb))
        } else {
            let (front, back) = self.k.split(poly, self.k.support(&by.poly));
            let world = |h: Option<K::Polygon>| {
                h.and_then(|h| {
                    let n = self.k.vertex_count(&h);
                    let fast: Option<Vec<glam::DVec3>> =
                        (0..n).map(|i| self.k.vertex_world_approx(&h, i)).collect();
                    let w = fast.unwrap_or_else(|| {
                        let mut w = Vec::new();
                        self.k.vertices_world(&h, &mut w);
                        w
                    });
                    project(&w)
                })
            };
            (world(front), world(back))
        };
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
}
