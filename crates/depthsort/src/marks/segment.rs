//! One segment at a time: the exact parameter intervals hidden by opaque occluders and
//! covered by translucent ones, the visible pieces between them, joined along the line.

use glam::{DMat4, DVec3};
use limn_kernel::{ExactAffine, Plane, Quotient};
use limn_scene::Camera;
use std::cmp::Ordering;

use super::bins::Bins;
use super::cone::{self, q3, EyeQ, Q};
use super::filter;
use super::{MarkStats, Occluder, VisibleAnchor, VisiblePiece};
use crate::geom::Box2;

/// What every segment and anchor is hidden against (shared by the threads).
pub(super) struct Shared {
    pub(super) occluders: Vec<Occluder>,
    pub(super) bins: Bins,
    pub(super) eye: EyeQ,
    /// The eye as given.
    pub(super) eye_f: filter::EyeF,
    pub(super) near: Plane,
    pub(super) camera: Camera,
    pub(super) vp: DMat4,
    /// The fragments' count: the paint position after every fragment.
    pub(super) end: usize,
    /// Whether the float filter decides what it can (off: everything exactly, the
    /// reference the filter is tested against).
    pub(super) filter: bool,
    /// Whether consecutive visible pieces of a line with different positions are joined
    /// where one position suits both: each occluder is a fragment whose position is its
    /// index, and some are translucent (only they give pieces different positions).
    /// A piece must be painted after every fragment behind it that it is drawn over (the
    /// parts of its cone in front of the fragment's plane, see [`Ctx::over_part`]) and
    /// before every translucent one in front; a run of pieces whose bounds leave room
    /// for one position is one piece at the earliest of their positions.
    pub(super) join_across: bool,
}

impl Shared {
    /// A context for one task (its own scratch space and counts).
    pub(super) fn task(&self) -> Ctx<'_> {
        Ctx {
            sh: self,
            fa: Vec::new(),
            fb: Vec::new(),
            stats: MarkStats::default(),
        }
    }
}

/// What the segment pass works with: the shared data, and one task's scratch space and
/// counts.
pub(super) struct Ctx<'a> {
    pub(super) sh: &'a Shared,
    /// Scratch space of the filter.
    pub(super) fa: Vec<filter::Iv>,
    pub(super) fb: Vec<filter::Iv>,
    pub(super) stats: MarkStats,
}

/// The parameters `u ∈ [lo, hi]` where `f(A) + u·(f(B) − f(A)) ≥ 0`, intersected with
/// `[lo, hi]`; `None` when empty.
fn clip(fa: &Q, fb: &Q, lo: Quotient, hi: Quotient) -> Option<(Quotient, Quotient)> {
    let (mut lo, mut hi) = (lo, hi);
    if fa == fb {
        if fa.signum() == Ordering::Less {
            return None;
        }
    } else {
        let (root, slope) = Quotient::root(fa, fb);
        if slope == Ordering::Greater {
            if root > lo {
                lo = root;
            }
        } else if root < hi {
            hi = root;
        }
    }
    (lo <= hi).then_some((lo, hi))
}

/// A piece being built.
struct Open {
    world: Vec<DVec3>,
    before: usize,
    /// The earliest position its parts allow: after every fragment drawn under them
    /// (0 when not joining across positions).
    after: usize,
    start: f64,
}

impl Ctx<'_> {
    fn project(&self, p: DVec3) -> [f64; 2] {
        let s = self.sh.camera.project_with(&self.sh.vp, p);
        [s.x, s.y]
    }

    /// The exact point `A + u(B − A)`, rounded once.
    fn point_at(a: DVec3, b: DVec3, u: &Quotient) -> DVec3 {
        DVec3::new(u.lerp(a.x, b.x), u.lerp(a.y, b.y), u.lerp(a.z, b.z))
    }

    /// Candidate occluders of a screen box that may lie in front of `pts` (exact plane
    /// sides: some point strictly on the far side of the occluder's plane from the eye).
    fn candidates(&mut self, pts: &[DVec3], screen: &Box2) -> Vec<u32> {
        let mut c = self.sh.bins.query(screen);
        c.retain(|&i| {
            let o = &self.sh.occluders[i as usize];
            pts.iter()
                .any(|p| cone::may_be_behind(&o.support, o.eye_side, p.to_array()))
        });
        c
    }

    /// Screen box of the world points, infinite when one lies behind the near plane.
    fn screen_box(&self, pts: &[DVec3], near: &[bool]) -> Box2 {
        if near.iter().any(|&ok| !ok) {
            return Box2 {
                min_x: f64::NEG_INFINITY,
                min_y: f64::NEG_INFINITY,
                max_x: f64::INFINITY,
                max_y: f64::INFINITY,
            };
        }
        let s: Vec<[f64; 2]> = pts.iter().map(|&p| self.project(p)).collect();
        crate::geom::bbox(&s)
    }

    /// Splits polyline `line` into visible pieces (appended to `out`).
    pub(super) fn polyline(
        &mut self,
        line: u32,
        points: &[DVec3],
        out: &mut Vec<VisiblePiece>,
        hidden_out: &mut Vec<VisiblePiece>,
    ) {
        let mut hopen: Option<Open> = None;
        let near = ExactAffine::of_plane(&self.sh.near);
        let mut open: Option<Open> = None;
        let mut hidden_open = false;
        let mut length = 0.0;
        for w in points.windows(2) {
            self.stats.segments_in += 1;
            let (a, b) = (w[0], w[1]);
            let (qa, qb) = (q3(a.to_array()), q3(b.to_array()));
            let seg_start = length;
            let (sa, sb) = (self.project(a), self.project(b));
            let seg_len = (sb[0] - sa[0]).hypot(sb[1] - sa[1]);
            length += if seg_len.is_finite() { seg_len } else { 0.0 };
            if a == b {
                continue;
            }
            // The part in front of the near plane.
            let Some((u_lo, u_hi)) = clip(
                &near.at(&qa),
                &near.at(&qb),
                Quotient::zero(),
                Quotient::one(),
            ) else {
                close(&mut open, line, out, self, &mut hidden_open, true);
                continue;
            };
            let ends = [Self::point_at(a, b, &u_lo), Self::point_at(a, b, &u_hi)];
            let screen = self.screen_box(&ends, &[true, true]);
            let cands = self.candidates(&[a, b], &screen);
            // Exact intervals: hidden (opaque) and covered (translucent, with position).
            let mut hidden: Vec<(Quotient, Quotient)> = Vec::new();
            let mut covered: Vec<(Quotient, Quotient, usize)> = Vec::new();
            for i in cands {
                let (opaque, before) = {
                    let o = &self.sh.occluders[i as usize];
                    (o.opaque, o.before)
                };
                if let Some((lo, hi)) = self.cone_part(i, [a, b], [&qa, &qb], &u_lo, &u_hi) {
                    if opaque {
                        hidden.push((lo, hi));
                    } else {
                        covered.push((lo, hi, before));
                    }
                }
            }
            // Fragments behind the segment that it is drawn over, with the position
            // after them (only to join pieces across positions).
            let mut over: Vec<(Quotient, Quotient, usize)> = Vec::new();
            if self.sh.join_across {
                for i in self.sh.bins.query(&screen) {
                    let pos = self.sh.occluders[i as usize].before + 1;
                    if let Some((lo, hi)) = self.over_part(i, [a, b], [&qa, &qb], &u_lo, &u_hi) {
                        over.push((lo, hi, pos));
                    }
                }
            }
            // Elementary intervals between all break points.
            let mut cuts: Vec<Quotient> = vec![
                Quotient::zero(),
                u_lo.clone(),
                u_hi.clone(),
                Quotient::one(),
            ];
            for (lo, hi) in &hidden {
                cuts.push(lo.clone());
                cuts.push(hi.clone());
            }
            for (lo, hi, _) in &covered {
                cuts.push(lo.clone());
                cuts.push(hi.clone());
            }
            cuts.sort();
            cuts.dedup();
            // Each break point's position, rounded once.
            let at: Vec<DVec3> = cuts.iter().map(|t| Self::point_at(a, b, t)).collect();
            for k in 0..cuts.len() - 1 {
                let (t0, t1) = (&cuts[k], &cuts[k + 1]);
                let inside = |lo: &Quotient, hi: &Quotient| lo <= t0 && t1 <= hi;
                let clipped = t1 <= &u_lo || t0 >= &u_hi;
                if clipped || hidden.iter().any(|(lo, hi)| inside(lo, hi)) {
                    close(&mut open, line, out, self, &mut hidden_open, true);
                    if !clipped {
                        let p0 = at[k];
                        let p1 = at[k + 1];
                        match &mut hopen {
                            Some(o) if o.world.last() == Some(&p0) => o.world.push(p1),
                            _ => {
                                self.flush_hidden(&mut hopen, line, hidden_out);
                                hopen = Some(Open {
                                    world: vec![p0, p1],
                                    before: self.sh.end,
                                    after: 0,
                                    start: seg_start,
                                });
                            }
                        }
                    }
                    continue;
                }
                self.flush_hidden(&mut hopen, line, hidden_out);
                let before = covered
                    .iter()
                    .filter(|(lo, hi, _)| inside(lo, hi))
                    .map(|c| c.2)
                    .min()
                    .unwrap_or(self.sh.end);
                // Conservatively: every fragment drawn under some of the interval.
                let after = over
                    .iter()
                    .filter(|(lo, hi, _)| lo < t1 && t0 < hi)
                    .map(|c| c.2)
                    .max()
                    .unwrap_or(0);
                let p0 = at[k];
                let p1 = at[k + 1];
                match &mut open {
                    Some(o)
                        if o.world.last() == Some(&p0)
                            && (o.before == before
                                || (self.sh.join_across
                                    && o.after.max(after) <= o.before.min(before))) =>
                    {
                        o.world.push(p1);
                        o.before = o.before.min(before);
                        o.after = o.after.max(after);
                    }
                    _ => {
                        close(&mut open, line, out, self, &mut hidden_open, false);
                        let s0 = self.project(p0);
                        let start = seg_start + (s0[0] - sa[0]).hypot(s0[1] - sa[1]);
                        open = Some(Open {
                            world: vec![p0, p1],
                            before,
                            after,
                            start: if start.is_finite() { start } else { 0.0 },
                        });
                    }
                }
            }
        }
        close(&mut open, line, out, self, &mut hidden_open, false);
        self.flush_hidden(&mut hopen, line, hidden_out);
        if hidden_open {
            self.stats.hidden_pieces += 1;
        }
    }

    /// Occluder `i`'s cone conditions at the segment's two ends, as intervals into
    /// `fa` and `fb` (see [`filter::conditions`]): whether both could be computed (not
    /// when the eye lies in the occluder's plane).
    fn end_conditions(&mut self, i: u32, ends: [DVec3; 2]) -> bool {
        let o = &self.sh.occluders[i as usize];
        let [a, b] = ends.map(|p| p.to_array());
        let planes = o.cone_planes(self.sh.eye_f);
        let ok_a = filter::conditions(planes, &o.support, o.eye_side, a, &mut self.fa);
        let ok_b = filter::conditions(planes, &o.support, o.eye_side, b, &mut self.fb);
        ok_a && ok_b
    }

    /// The parameters in `[u_lo, u_hi]` of segment `AB` (`ends`, and exactly `exact`)
    /// where occluder `i`'s cone conditions hold, when they form an interval of positive
    /// length: decided by the float filter where it can, exactly otherwise.
    pub(super) fn cone_part(
        &mut self,
        i: u32,
        ends: [DVec3; 2],
        exact: [&[Q; 3]; 2],
        u_lo: &Quotient,
        u_hi: &Quotient,
    ) -> Option<(Quotient, Quotient)> {
        if self.sh.filter && self.end_conditions(i, ends) {
            match filter::segment_verdict(&self.fa, &self.fb) {
                filter::Verdict::Nowhere => return None,
                filter::Verdict::Everywhere => {
                    return (u_lo < u_hi).then(|| (u_lo.clone(), u_hi.clone()));
                }
                filter::Verdict::Unknown => {}
            }
        }
        self.stats.exact_tests += 1;
        self.exact_part(i, exact, u_lo, u_hi)
    }

    /// [`Ctx::cone_part`] evaluated exactly.
    pub(super) fn exact_part(
        &mut self,
        i: u32,
        [qa, qb]: [&[Q; 3]; 2],
        u_lo: &Quotient,
        u_hi: &Quotient,
    ) -> Option<(Quotient, Quotient)> {
        let c = self.sh.occluders[i as usize].cone(&self.sh.eye)?;
        let (ba, bb) = (c.behind.at(qa), c.behind.at(qb));
        if ba.is_zero() && bb.is_zero() {
            // The segment lies in the occluder's plane: never hidden by it.
            return None;
        }
        let mut iv = clip(&ba, &bb, u_lo.clone(), u_hi.clone());
        for wall in &c.walls {
            iv = iv.and_then(|(lo, hi)| clip(&wall.at(qa), &wall.at(qb), lo, hi));
        }
        iv.filter(|(lo, hi)| lo < hi)
    }

    /// The parameters in `[u_lo, u_hi]` of segment `AB` drawn over occluder `i`: in its
    /// cone from the eye (every wall ≥ 0) and not behind its plane (`behind ≤ 0`), when
    /// they form an interval of positive length. Decided by the float filter where it
    /// can, exactly otherwise.
    pub(super) fn over_part(
        &mut self,
        i: u32,
        ends: [DVec3; 2],
        [qa, qb]: [&[Q; 3]; 2],
        u_lo: &Quotient,
        u_hi: &Quotient,
    ) -> Option<(Quotient, Quotient)> {
        if self.sh.filter {
            if !self.end_conditions(i, ends) {
                // The eye in the occluder's plane: it covers nothing.
                return None;
            }
            filter::negate_first(&mut self.fa);
            filter::negate_first(&mut self.fb);
            match filter::closed_segment_verdict(&self.fa, &self.fb) {
                filter::Verdict::Nowhere => return None,
                filter::Verdict::Everywhere => {
                    return (u_lo < u_hi).then(|| (u_lo.clone(), u_hi.clone()));
                }
                filter::Verdict::Unknown => {}
            }
        }
        self.stats.exact_tests += 1;
        let c = self.sh.occluders[i as usize].cone(&self.sh.eye)?;
        let (ba, bb) = (-&c.behind.at(qa), -&c.behind.at(qb));
        let mut iv = clip(&ba, &bb, u_lo.clone(), u_hi.clone());
        for wall in &c.walls {
            iv = iv.and_then(|(lo, hi)| clip(&wall.at(qa), &wall.at(qb), lo, hi));
        }
        iv.filter(|(lo, hi)| lo < hi)
    }

    /// Whether occluder `i`'s cone holds the point `p` (exactly `qp`): decided by the
    /// float filter where it can, exactly otherwise.
    pub(super) fn cone_holds(&mut self, i: u32, p: DVec3, qp: &[Q; 3]) -> bool {
        if self.sh.filter {
            let o = &self.sh.occluders[i as usize];
            let planes = o.cone_planes(self.sh.eye_f);
            if !filter::conditions(planes, &o.support, o.eye_side, p.to_array(), &mut self.fa) {
                return false;
            }
            match filter::point_verdict(&self.fa) {
                filter::Verdict::Nowhere => return false,
                filter::Verdict::Everywhere => return true,
                filter::Verdict::Unknown => {}
            }
        }
        self.stats.exact_tests += 1;
        self.exact_holds(i, qp)
    }

    /// [`Ctx::cone_holds`] evaluated exactly.
    pub(super) fn exact_holds(&mut self, i: u32, qp: &[Q; 3]) -> bool {
        self.sh.occluders[i as usize]
            .cone(&self.sh.eye)
            .is_some_and(|c| c.hides(qp))
    }

    /// Moves a hidden piece being built to `out`.
    fn flush_hidden(&self, open: &mut Option<Open>, line: u32, out: &mut Vec<VisiblePiece>) {
        if let Some(o) = open.take() {
            let points = o.world.iter().map(|&p| self.project(p)).collect();
            out.push(VisiblePiece {
                line,
                world: o.world,
                points,
                before: o.before,
                start: o.start,
            });
        }
    }

    /// The visible anchor at `p`, or `None` when an opaque occluder hides it or it lies
    /// nearer than the near plane.
    pub(super) fn anchor(&mut self, index: u32, p: DVec3) -> Option<VisibleAnchor> {
        let qp = q3(p.to_array());
        if ExactAffine::of_plane(&self.sh.near).at(&qp).signum() == Ordering::Less {
            return None;
        }
        let at = self.project(p);
        let b = Box2 {
            min_x: at[0],
            min_y: at[1],
            max_x: at[0],
            max_y: at[1],
        };
        let mut before = self.sh.end;
        for i in self.candidates(&[p], &b) {
            let (opaque, pos) = {
                let o = &self.sh.occluders[i as usize];
                (o.opaque, o.before)
            };
            let hides = self.cone_holds(i, p, &qp);
            if hides {
                if opaque {
                    return None;
                }
                before = before.min(pos);
            }
        }
        Some(VisibleAnchor {
            index,
            at,
            from: at,
            before,
        })
    }
}

/// Ends the open piece (if any) and, for `hidden`, starts or continues a hidden stretch.
fn close(
    open: &mut Option<Open>,
    line: u32,
    out: &mut Vec<VisiblePiece>,
    ctx: &mut Ctx,
    hidden_open: &mut bool,
    hidden: bool,
) {
    if let Some(o) = open.take() {
        let points = o.world.iter().map(|&p| ctx.project(p)).collect();
        out.push(VisiblePiece {
            line,
            world: o.world,
            points,
            before: o.before,
            start: o.start,
        });
        ctx.stats.pieces_out += 1;
    }
    if hidden {
        *hidden_open = true;
    } else if *hidden_open {
        ctx.stats.hidden_pieces += 1;
        *hidden_open = false;
    }
}
