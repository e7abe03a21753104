//! Planes defined by input points: exact coefficients on demand, rigorous f64
//! approximations for the filters.
//!
//! A plane is never stored as rounded coefficients. It is *defined* by values the
//! caller gave exactly (f64 input points, a normal, an axis), and its coefficients are
//! polynomials in those values:
//!
//! | definition | normal `n` | offset `d` |
//! |---|---|---|
//! | [`Plane::through`]`(p, q, r)` | `(q − p) × (r − p)` | `−n·p` |
//! | edge plane `(p, q, k)` | `±(q − p) × e_k` | `−n·p` |
//! | [`Plane::point_normal`]`(p, n)` | `n` | `−n·p` |
//!
//! The front of the plane is where `n·x + d > 0`. Each plane carries its coefficients as
//! f64 values with proven error bounds (computed once, in f64 with a-priori bounds), which
//! the filters read; the exact coefficients are recomputed as dyadic numbers only when a
//! filter cannot decide. Planes are shared (`Arc`) between the pieces a split makes, so
//! cloning a polygon copies no coefficients.

use std::cmp::Ordering;
use std::fmt;
use std::sync::Arc;

use crate::dyadic::{self, Dyadic};
use crate::filter::PlaneF;
use crate::interval::Interval;
use crate::side::Side;
use crate::KernelError;

/// How a plane was defined (see the module docs): the exact values its coefficients are
/// polynomials in.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PlaneDef {
    /// Through three points, counter-clockwise seen from the front: normal
    /// `(q − p) × (r − p)`, offset `−n·p`.
    Through([[f64; 3]; 3]),
    /// Through `p` and `q`, containing the direction of axis `k` (0 = x, 1 = y, 2 = z):
    /// normal `(q − p) × e_k`, negated when `flip`; offset `−n·p`.
    Edge {
        /// First point.
        p: [f64; 3],
        /// Second point.
        q: [f64; 3],
        /// The axis whose direction the plane contains.
        k: u8,
        /// Whether the normal is negated.
        flip: bool,
    },
    /// Through `p` and `q`, containing the direction `d`: normal `(q − p) × d`, offset
    /// `−n·p` (a plane through an edge and a point at infinity, such as a directional
    /// light).
    Along {
        /// First point.
        p: [f64; 3],
        /// Second point.
        q: [f64; 3],
        /// The direction the plane contains.
        d: [f64; 3],
    },
    /// Through `p` with normal `n`: offset `−n·p`.
    PointNormal {
        /// The point.
        p: [f64; 3],
        /// The normal.
        n: [f64; 3],
    },
}

/// A plane's definition with its approximate coefficients.
#[derive(Debug)]
pub(crate) struct PlaneData {
    def: PlaneDef,
    /// This plane's identity, never given to another ([`Plane::id`]).
    id: u64,
    /// An input point besides the definition's that is known to lie exactly on the plane
    /// (the fourth corner of a planar quad, checked exactly when the face was converted):
    /// the combinatorial shortcut answers for it as for the definition's points.
    also_on: Option<[f64; 3]>,
    /// Midpoints of `[a, b, c, d]`.
    approx: [f64; 4],
    /// Bound on `|a − ã|`, `|b − b̃|`, `|c − c̃|`.
    err_n: f64,
    /// Bound on `|d − d̃|`.
    err_d: f64,
}

/// An oriented plane defined exactly by input values (see the module docs).
///
/// Equality is identity of definition and orientation: two planes built separately
/// through the same points are different values (use [`Plane::coincides`] for the
/// geometric question).
#[derive(Clone)]
pub struct Plane {
    data: Arc<PlaneData>,
    neg: bool,
}

impl PartialEq for Plane {
    fn eq(&self, other: &Plane) -> bool {
        Arc::ptr_eq(&self.data, &other.data) && self.neg == other.neg
    }
}

impl fmt::Debug for Plane {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [a, b, c, d] = self.approx();
        write!(
            f,
            "Plane {{ {:?}{}, ≈ [{a:e}, {b:e}, {c:e}, {d:e}] }}",
            self.data.def,
            if self.neg { ", flipped" } else { "" }
        )
    }
}

fn cross_axis_exact(w: &[Dyadic; 3], k: u8) -> [Dyadic; 3] {
    match k {
        0 => [Dyadic::zero(), w[2].clone(), -&w[1]],
        1 => [-&w[2], Dyadic::zero(), w[0].clone()],
        _ => [w[1].clone(), -&w[0], Dyadic::zero()],
    }
}

fn dsub(a: &[Dyadic; 3], b: &[Dyadic; 3]) -> [Dyadic; 3] {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

/// `2^-53`, the unit roundoff.
const U: f64 = 1.0 / 9_007_199_254_740_992.0;
/// Relative slack of the a-priori bounds: each covered quantity suffers at most four
/// roundings (`γ₄ < 4.01u`); twice that is used.
const REL: f64 = 8.0 * U;
/// Absolute slack for results in the subnormal range (`2^-1060`).
const ETA: f64 = f64::from_bits(1 << 14);
/// Covers the roundings made while computing a bound.
const SAFETY: f64 = 1.0 + 1.0 / 1_073_741_824.0;

/// A bound that is infinite unless finite (a NaN or an overflow makes every filter
/// undecided, so the exact path decides).
#[inline]
fn finite_or_inf(e: f64) -> f64 {
    if e.is_finite() {
        e
    } else {
        f64::INFINITY
    }
}

/// The cross product `u × v` of rounded differences in f64, and a bound on each
/// component's error against the exact cross product of the exact differences (see
/// [`PlaneDef::approximate`]).
fn cross_with_bound(u: [f64; 3], v: [f64; 3]) -> ([f64; 3], f64) {
    let n = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let m = [
        (u[1] * v[2]).abs() + (u[2] * v[1]).abs(),
        (u[2] * v[0]).abs() + (u[0] * v[2]).abs(),
        (u[0] * v[1]).abs() + (u[1] * v[0]).abs(),
    ];
    (n, (REL * m[0].max(m[1]).max(m[2]) + ETA) * SAFETY)
}

impl PlaneDef {
    /// Approximate coefficients and proven bounds `(ñ, d̃, e_n, e_d)` with
    /// `|nᵢ − ñᵢ| ≤ e_n` and `|d − d̃| ≤ e_d`, in plain f64 with a-priori bounds:
    ///
    /// * a difference `q − p` is rounded once (relative error `u`);
    /// * a cross-product component `a·b − c·d` of rounded differences differs from the
    ///   exact one by at most `γ₄ · (|a·b| + |c·d|)` (two input roundings, the product,
    ///   the difference);
    /// * `d̃ = −fl(ñ·p)` differs from `−n·p` by at most `e_n·Σ|pᵢ| + γ₄·Σ|ñᵢpᵢ|`;
    ///
    /// each with `2γ₄` and an absolute `2^-1060` for subnormal results, times a safety
    /// factor for the bound's own roundings. This is the hot path of face conversion
    /// (interval arithmetic, used for implicit vertices, costs about three times more);
    /// a unit test checks the bounds against the exact dyadic coefficients.
    fn approximate(&self) -> ([f64; 3], f64, f64, f64) {
        let sub = |a: [f64; 3], b: [f64; 3]| [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
        let (n, err_n, p) = match *self {
            PlaneDef::Through([p, q, r]) => {
                let (n, e) = cross_with_bound(sub(q, p), sub(r, p));
                (n, e, p)
            }
            PlaneDef::Edge { p, q, k, flip } => {
                let w = sub(q, p);
                let s = if flip { -1.0 } else { 1.0 };
                let n = match k {
                    0 => [0.0, s * w[2], -s * w[1]],
                    1 => [-s * w[2], 0.0, s * w[0]],
                    _ => [s * w[1], -s * w[0], 0.0],
                };
                let e = (REL * w[0].abs().max(w[1].abs()).max(w[2].abs()) + ETA) * SAFETY;
                (n, e, p)
            }
            PlaneDef::Along { p, q, d: v } => {
                // As `Through` with the second difference exact (`d` is given): the
                // same bound holds with room to spare.
                let (n, e) = cross_with_bound(sub(q, p), v);
                (n, e, p)
            }
            PlaneDef::PointNormal { p, n } => (n, 0.0, p),
        };
        let t = [n[0] * p[0], n[1] * p[1], n[2] * p[2]];
        let d = -(t[0] + t[1] + t[2]);
        let err_d = (err_n * (p[0].abs() + p[1].abs() + p[2].abs())
            + REL * (t[0].abs() + t[1].abs() + t[2].abs())
            + ETA)
            * SAFETY;
        let ok = n.iter().all(|v| v.is_finite()) && d.is_finite();
        if ok {
            (n, d, finite_or_inf(err_n), finite_or_inf(err_d))
        } else {
            (n, d, f64::INFINITY, f64::INFINITY)
        }
    }

    /// The exact normal and offset.
    fn exact(&self) -> ([Dyadic; 3], Dyadic) {
        let (n, p) = match *self {
            PlaneDef::Through([p, q, r]) => {
                let pe = dyadic::point3(p);
                let u = dsub(&dyadic::point3(q), &pe);
                let v = dsub(&dyadic::point3(r), &pe);
                (dyadic::cross3(&u, &v), pe)
            }
            PlaneDef::Edge { p, q, k, flip } => {
                let pe = dyadic::point3(p);
                let n = cross_axis_exact(&dsub(&dyadic::point3(q), &pe), k);
                (if flip { n.map(|x| -&x) } else { n }, pe)
            }
            PlaneDef::Along { p, q, d } => {
                let pe = dyadic::point3(p);
                let u = dsub(&dyadic::point3(q), &pe);
                (dyadic::cross3(&u, &dyadic::point3(d)), pe)
            }
            PlaneDef::PointNormal { p, n } => (dyadic::point3(n), dyadic::point3(p)),
        };
        let d = -&dyadic::dot3(&n, &p);
        (n, d)
    }

    /// The points among the definition (they all lie on the plane).
    fn points(&self) -> ([[f64; 3]; 4], usize) {
        match *self {
            PlaneDef::Through([p, q, r]) => ([p, q, r, r], 3),
            PlaneDef::Edge { p, q, .. } | PlaneDef::Along { p, q, .. } => ([p, q, q, q], 2),
            PlaneDef::PointNormal { p, .. } => ([p, p, p, p], 1),
        }
    }

    /// Whether `x` is one of the points that define the plane (then it lies on it).
    fn defined_by(&self, x: &[f64; 3]) -> bool {
        match self {
            PlaneDef::Through(pts) => pts.iter().any(|p| p == x),
            PlaneDef::Edge { p, q, .. } | PlaneDef::Along { p, q, .. } => p == x || q == x,
            PlaneDef::PointNormal { p, .. } => p == x,
        }
    }
}

/// Exponent range (of non-zero magnitudes) in which Shewchuk's adaptive `orient2d` and
/// `orient3d` (the `robust` crate) are exact: no intermediate overflows or underflows.
const ROBUST_MIN: f64 = 7.888_609_052_210_118e-31; // 2^-100
const ROBUST_MAX: f64 = 1.267_650_600_228_229_4e30; // 2^100

/// Whether every coordinate is zero or of a magnitude where `robust` is exact.
#[inline]
pub(crate) fn robust_safe(pts: &[[f64; 3]]) -> bool {
    pts.iter().flatten().all(|&x| {
        let a = x.abs();
        a == 0.0 || (ROBUST_MIN..=ROBUST_MAX).contains(&a)
    })
}

#[inline]
fn c3(p: [f64; 3]) -> robust::Coord3D<f64> {
    robust::Coord3D {
        x: p[0],
        y: p[1],
        z: p[2],
    }
}

/// Identities of planes: each thread takes blocks of them from one counter, so that
/// making a plane touches no memory shared between threads.
mod plane_identity {
    use std::cell::Cell;
    use std::sync::atomic::{AtomicU64, Ordering};

    /// Identities handed out per block.
    const BLOCK: u64 = 1 << 20;
    /// The first identity of the next block (0 is never an identity).
    static NEXT_BLOCK: AtomicU64 = AtomicU64::new(1);

    thread_local! {
        /// The next identity of this thread's block and the end of the block.
        static RANGE: Cell<(u64, u64)> = const { Cell::new((0, 0)) };
    }

    /// A new identity.
    #[inline]
    pub(super) fn next() -> u64 {
        RANGE
            .try_with(|r| {
                let (mut next, mut end) = r.get();
                if next == end {
                    next = NEXT_BLOCK.fetch_add(BLOCK, Ordering::Relaxed);
                    end = next + BLOCK;
                }
                r.set((next + 1, end));
                next
            })
            // A thread being torn down: a block of one.
            .unwrap_or_else(|_| NEXT_BLOCK.fetch_add(1, Ordering::Relaxed))
    }
}

impl Plane {
    fn from_def(def: PlaneDef) -> Plane {
        let (mid_n, mid_d, err_n, err_d) = def.approximate();
        Plane {
            data: Arc::new(PlaneData {
                def,
                id: plane_identity::next(),
                also_on: None,
                approx: [mid_n[0], mid_n[1], mid_n[2], mid_d],
                err_n,
                err_d,
            }),
            neg: false,
        }
    }

    /// The plane through three points, oriented so that `p`, `q`, `r` run
    /// counter-clockwise seen from its front (normal `(q − p) × (r − p)`).
    ///
    /// Errors: [`KernelError::NonFinite`] for a NaN or infinite coordinate,
    /// [`KernelError::ZeroNormal`] when the points are exactly collinear.
    pub fn through(p: [f64; 3], q: [f64; 3], r: [f64; 3]) -> Result<Plane, KernelError> {
        for x in [p, q, r] {
            check_finite(x)?;
        }
        let plane = Plane::from_def(PlaneDef::Through([p, q, r]));
        if plane.normal_is_zero() {
            return Err(KernelError::ZeroNormal);
        }
        Ok(plane)
    }

    /// The plane through `p` and `q` containing the direction `d`, normal `(q − p) × d`
    /// (front where it points): the plane through an edge and a point at infinity.
    ///
    /// Errors: [`KernelError::NonFinite`], or [`KernelError::ZeroNormal`] when `q − p`
    /// is exactly parallel to `d` (or zero).
    pub fn along(p: [f64; 3], q: [f64; 3], d: [f64; 3]) -> Result<Plane, KernelError> {
        for x in [p, q, d] {
            check_finite(x)?;
        }
        let plane = Plane::from_def(PlaneDef::Along { p, q, d });
        if plane.normal_is_zero() {
            return Err(KernelError::ZeroNormal);
        }
        Ok(plane)
    }

    /// The plane through `p` with normal `n` (front where `n` points).
    ///
    /// Errors: [`KernelError::NonFinite`], or [`KernelError::ZeroNormal`] for `n = 0`.
    pub fn point_normal(p: [f64; 3], n: [f64; 3]) -> Result<Plane, KernelError> {
        check_finite(p)?;
        check_finite(n)?;
        if n == [0.0; 3] {
            return Err(KernelError::ZeroNormal);
        }
        Ok(Plane::from_def(PlaneDef::PointNormal { p, n }))
    }

    /// The edge plane through `p` and `q` containing the direction of axis `k`, normal
    /// `(q − p) × e_k` (negated when `flip`). The caller guarantees that `p` and `q`
    /// differ in projection along `k`.
    pub(crate) fn edge(p: [f64; 3], q: [f64; 3], k: usize, flip: bool) -> Plane {
        Plane::from_def(PlaneDef::Edge {
            p,
            q,
            k: k as u8,
            flip,
        })
    }

    /// The same plane, known also to pass through the input point `x`, which the caller
    /// has proven to lie on it exactly (a planar face's corner outside the definition):
    /// the shortcut then answers `On` for `x` without arithmetic.
    pub(crate) fn also_through(&self, x: [f64; 3]) -> Plane {
        debug_assert!(self.data.also_on.is_none());
        debug_assert_eq!(self.side_exact(x), Side::On);
        Plane {
            data: Arc::new(PlaneData {
                def: self.data.def,
                id: plane_identity::next(),
                also_on: Some(x),
                approx: self.data.approx,
                err_n: self.data.err_n,
                err_d: self.data.err_d,
            }),
            neg: self.neg,
        }
    }

    /// The points the plane is known to pass through: the definition's and
    /// [`Plane::also_through`]'s.
    fn known_points(&self) -> ([[f64; 3]; 4], usize) {
        let (mut pts, mut n) = self.data.def.points();
        if let Some(x) = self.data.also_on {
            pts[n] = x;
            n += 1;
        }
        (pts, n)
    }

    /// The approximate coefficients and error bounds of the edge plane
    /// `Plane::edge(p, q, k, flip)` would have, without making it.
    pub(crate) fn edge_coefficients(
        p: [f64; 3],
        q: [f64; 3],
        k: usize,
        flip: bool,
    ) -> ([f64; 4], (f64, f64)) {
        let def = PlaneDef::Edge {
            p,
            q,
            k: k as u8,
            flip,
        };
        let (n, d, err_n, err_d) = def.approximate();
        ([n[0], n[1], n[2], d], (err_n, err_d))
    }

    /// Whether this plane, defined through three points, is `other` as a set of points:
    /// its three points (not on one line, since its normal is not zero) lie exactly on
    /// `other` (the shortcut first, then the filter, then exact evaluation; a point off
    /// `other` is usually told by the filter at once). Coplanar faces of different
    /// definitions (a face and its reversed twin, faces of two parts in contact) meet
    /// here: a vertex made on one of them lies on the other. `false` for planes of other
    /// definitions.
    pub(crate) fn is_within(&self, other: &Plane) -> bool {
        let PlaneDef::Through(pts) = self.data.def else {
            return false;
        };
        if self.same_definition(other) {
            return true;
        }
        pts.iter()
            .all(|p| other.defined_by(p) || other.side_of(*p) == Side::On)
    }

    /// The definition of the plane before [`Plane::is_flipped`] is applied.
    pub fn definition(&self) -> PlaneDef {
        self.data.def
    }

    /// Whether this plane is its definition flipped (all coefficients negated).
    pub fn is_flipped(&self) -> bool {
        self.neg
    }

    /// Whether the exact normal is zero.
    fn normal_is_zero(&self) -> bool {
        let [a, b, c, _] = self.approx();
        let e = self.data.err_n;
        if a.abs() > e || b.abs() > e || c.abs() > e {
            return false;
        }
        let (n, _) = self.data.def.exact();
        n.iter().all(Dyadic::is_zero)
    }

    /// The same plane facing the other way.
    #[inline]
    pub fn flipped(&self) -> Plane {
        Plane {
            data: Arc::clone(&self.data),
            neg: !self.neg,
        }
    }

    /// The approximate coefficients `[a, b, c, d]` (with proven bounds; see
    /// [`Plane::error_bounds`]).
    #[inline]
    pub fn approx(&self) -> [f64; 4] {
        let a = self.data.approx;
        if self.neg {
            a.map(|v| -v)
        } else {
            a
        }
    }

    /// Bounds on the errors of [`Plane::approx`]: of every normal component, and of the
    /// offset.
    #[inline]
    pub fn error_bounds(&self) -> (f64, f64) {
        (self.data.err_n, self.data.err_d)
    }

    /// The approximate coefficients prepared for the filters.
    #[inline]
    pub(crate) fn filter(&self) -> PlaneF {
        PlaneF::new(self.approx(), self.error_bounds())
    }

    /// An interval holding the exact value `n·x + d` of the plane's equation at the point
    /// `x` (the filter's value and proven bound; the whole line when they overflow).
    #[inline]
    pub fn value_at(&self, x: [f64; 3]) -> Interval {
        let (v, bound) = self.filter().height(&x, 0.0);
        if v.is_finite() && bound.is_finite() {
            Interval::around(v, bound)
        } else {
            Interval::EVERYTHING
        }
    }

    /// An interval holding the exact value `n·d` of the plane's normal against the
    /// direction `d` (the plane's value at the point at infinity in that direction).
    #[inline]
    pub fn value_toward(&self, d: [f64; 3]) -> Interval {
        let (v, bound) = self.filter().direction_height(&d);
        if v.is_finite() && bound.is_finite() {
            Interval::around(v, bound)
        } else {
            Interval::EVERYTHING
        }
    }

    /// The exact coefficients, with this plane's orientation.
    pub fn exact(&self) -> ([Dyadic; 3], Dyadic) {
        let (n, d) = self.data.def.exact();
        if self.neg {
            (n.map(|x| -&x), -&d)
        } else {
            (n, d)
        }
    }

    /// An identity of the plane's definition, shared by its clones and its flipped
    /// copies and by no other plane made in this process (never 0).
    #[inline]
    pub(crate) fn id(&self) -> u64 {
        self.data.id
    }

    /// Whether `self` and `other` share a definition (they are the same plane, possibly
    /// flipped): the combinatorial shortcut of the predicates.
    #[inline]
    pub(crate) fn same_definition(&self, other: &Plane) -> bool {
        Arc::ptr_eq(&self.data, &other.data)
    }

    /// Whether `x` is one of the points defining the plane, or the point it is known to
    /// pass through besides ([`Plane::also_through`]): exactly on it.
    #[inline]
    pub(crate) fn defined_by(&self, x: &[f64; 3]) -> bool {
        self.data.def.defined_by(x) || self.data.also_on.as_ref() == Some(x)
    }

    /// Two distinct points that define both planes, when there are: the line through
    /// them is the planes' intersection (if the planes differ).
    pub(crate) fn common_line(&self, other: &Plane) -> Option<([f64; 3], [f64; 3])> {
        let (a, na) = self.known_points();
        let mut first: Option<[f64; 3]> = None;
        for p in &a[..na] {
            if other.defined_by(p) {
                match first {
                    None => first = Some(*p),
                    Some(f) if f != *p => return Some((f, *p)),
                    Some(_) => {}
                }
            }
        }
        None
    }

    /// A point and a direction that define both planes, when there are (both planes
    /// contain one point and the same direction, as the planes through a light at
    /// infinity and two edges meeting at a corner): the line through the point along the
    /// direction is the planes' intersection (if the planes differ).
    pub(crate) fn common_ray(&self, other: &Plane) -> Option<([f64; 3], [f64; 3])> {
        let (PlaneDef::Along { p, q, d }, PlaneDef::Along { d: e, .. }) =
            (self.data.def, other.data.def)
        else {
            return None;
        };
        if d.map(f64::to_bits) != e.map(f64::to_bits) {
            return None;
        }
        [p, q]
            .into_iter()
            .find(|x| other.defined_by(x))
            .map(|x| (x, d))
    }

    /// Whether the plane contains the direction `d` (is parallel to it), exactly; known
    /// without arithmetic for a plane defined along `d`.
    pub(crate) fn contains_direction(&self, d: [f64; 3]) -> bool {
        match self.data.def {
            PlaneDef::Along { d: e, .. } if e.map(f64::to_bits) == d.map(f64::to_bits) => true,
            _ => self.side_of_direction(d) == Side::On,
        }
    }

    /// The exact side of a point given by its f64 coordinates.
    pub fn side_of(&self, x: [f64; 3]) -> Side {
        self.side_of_counted(x, &mut 0)
    }

    /// [`Plane::side_of`], counting in `fallbacks` when the filter could not decide.
    pub(crate) fn side_of_counted(&self, x: [f64; 3], fallbacks: &mut u64) -> Side {
        if let Some(s) = self.filter().side(&x, 0.0) {
            return s;
        }
        if self.defined_by(&x) {
            return Side::On;
        }
        *fallbacks += 1;
        self.side_exact(x)
    }

    /// The exact side of a point, without filter.
    pub(crate) fn side_exact(&self, x: [f64; 3]) -> Side {
        if self.defined_by(&x) {
            return Side::On;
        }
        let s = match self.data.def {
            PlaneDef::Through([p, q, r]) if robust_safe(&[p, q, r, x]) => {
                // robust's orient3d is positive when x lies on the side the normal of
                // (q − p) × (r − p) points away from.
                let o = robust::orient3d(c3(p), c3(q), c3(r), c3(x));
                0.0f64.partial_cmp(&o).unwrap_or(Ordering::Equal)
            }
            PlaneDef::Edge { p, q, k, flip } if robust_safe(&[p, q, x]) => {
                let (u, v) = plane_axes(k as usize);
                let c2 = |a: [f64; 3]| robust::Coord { x: a[u], y: a[v] };
                // orient2d(p, q, x) = −((q − p) × e_k)·(x − p).
                let o = robust::orient2d(c2(p), c2(q), c2(x));
                let s = 0.0f64.partial_cmp(&o).unwrap_or(Ordering::Equal);
                if flip {
                    s.reverse()
                } else {
                    s
                }
            }
            _ => {
                let (n, d) = self.data.def.exact();
                (&dyadic::dot3(&n, &dyadic::point3(x)) + &d).signum()
            }
        };
        let s = if self.neg { s.reverse() } else { s };
        Side::from_ordering(s)
    }

    /// Whether the normals of two planes point into the same half-space (positive dot
    /// product), exactly.
    pub fn same_facing(&self, other: &Plane) -> bool {
        if self.same_definition(other) {
            return self.neg == other.neg;
        }
        let iv = |p: &Plane| {
            let (e, _) = p.error_bounds();
            let a = p.approx();
            [0, 1, 2].map(|i| Interval::around(a[i], e))
        };
        if let Some(s) = Interval::dot(iv(self), iv(other)).sign() {
            return s == Ordering::Greater;
        }
        let (n, _) = self.exact();
        let (m, _) = other.exact();
        dyadic::dot3(&n, &m).signum() == Ordering::Greater
    }

    /// The exact side of the point at infinity in direction `d` (the eye of a parallel
    /// projection): the sign of `n·d`, `On` when the plane is parallel to `d`.
    pub fn side_of_direction(&self, d: [f64; 3]) -> Side {
        let s = self.normal_dot(d);
        match if self.neg { s.reverse() } else { s } {
            Ordering::Greater => Side::Front,
            Ordering::Less => Side::Back,
            Ordering::Equal => Side::On,
        }
    }

    /// The exact sign of the definition's normal dotted with `d` (orientation ignored).
    fn normal_dot(&self, d: [f64; 3]) -> Ordering {
        let (e, _) = self.error_bounds();
        let a = self.data.approx;
        let n = [0, 1, 2].map(|i| Interval::around(a[i], e));
        if let Some(s) = Interval::dot(n, d.map(Interval::exactly)).sign() {
            return s;
        }
        let (n, _) = self.data.def.exact();
        dyadic::dot3(&n, &dyadic::point3(d)).signum()
    }

    /// The exact sign of normal component `k`.
    pub(crate) fn normal_sign(&self, k: usize) -> Ordering {
        let a = self.approx()[k];
        let e = self.data.err_n;
        if a > e {
            return Ordering::Greater;
        }
        if a < -e {
            return Ordering::Less;
        }
        self.exact().0[k].signum()
    }

    /// The axis of the largest approximate normal component (lowest index on ties). A
    /// choice only: callers check the exact sign of that component.
    pub fn dominant_axis(&self) -> usize {
        let [a, b, c, _] = self.approx().map(f64::abs);
        if a >= b && a >= c {
            0
        } else if b >= c {
            1
        } else {
            2
        }
    }

    /// The dominant axis of the normal ([`Plane::dominant_axis`]) when the normal's
    /// component there is exactly non-zero, else the first axis where it is.
    pub(crate) fn dominant_exact_axis(&self) -> usize {
        let k = self.dominant_axis();
        if self.normal_sign(k) != Ordering::Equal {
            return k;
        }
        // The approximation was too coarse to choose: any exactly non-zero component works.
        (0..3)
            .find(|&j| self.normal_sign(j) != Ordering::Equal)
            .unwrap_or(k)
    }

    /// Whether two planes are the same oriented plane (geometrically), exactly.
    pub fn coincides(&self, other: &Plane) -> bool {
        if self.same_definition(other) {
            return self.neg == other.neg;
        }
        let (n, d) = self.exact();
        let (m, e) = other.exact();
        // Parallel, same direction, and the same offset after scaling.
        let c = dyadic::cross3(&n, &m);
        if !c.iter().all(Dyadic::is_zero) || dyadic::dot3(&n, &m).signum() != Ordering::Greater {
            return false;
        }
        // n = λ m with λ > 0: then d = λ e ⇔ d·m_i = e·n_i for a non-zero component.
        (0..3)
            .find(|&i| !m[i].is_zero())
            .is_some_and(|i| (&(&d * &m[i]) - &(&e * &n[i])).is_zero())
    }
}

/// The two axes spanning the projection along `k`, so that `(u, v, k)` is right-handed.
#[inline]
pub(crate) fn plane_axes(k: usize) -> (usize, usize) {
    ((k + 1) % 3, (k + 2) % 3)
}

pub(crate) fn check_finite(p: [f64; 3]) -> Result<(), KernelError> {
    if p.iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(KernelError::NonFinite(p[0], p[1], p[2]))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn through_orients_counter_clockwise() {
        let p = Plane::through([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
        assert_eq!(p.side_of([0.0, 0.0, 5.0]), Side::Front);
        assert_eq!(p.side_of([7.0, -3.0, 0.0]), Side::On);
        assert_eq!(p.flipped().side_of([0.0, 0.0, 5.0]), Side::Back);
        assert!(Plane::through([0.0; 3], [1.0, 1.0, 1.0], [2.0, 2.0, 2.0]).is_err());
    }

    #[test]
    fn edge_planes_point_outwards() {
        // Edge from (0,0) to (1,0) seen along +z: the interior (y > 0) is behind.
        let e = Plane::edge([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], 2, false);
        assert_eq!(e.side_of([0.5, 1.0, 3.0]), Side::Back);
        assert_eq!(e.side_of([0.5, -1.0, 3.0]), Side::Front);
        assert_eq!(e.side_of([0.5, 0.0, 3.0]), Side::On);
        for k in 0..3 {
            let (u, v) = plane_axes(k);
            let mut p = [0.0; 3];
            let mut q = [0.0; 3];
            q[u] = 1.0;
            let mut inside = [0.0; 3];
            inside[v] = 1.0;
            let e = Plane::edge(p, q, k, false);
            assert_eq!(e.side_of(inside), Side::Back, "axis {k}");
            assert_eq!(e.side_exact(inside), Side::Back, "axis {k}");
            p[k] = 5.0;
            assert_eq!(e.side_of(p), Side::On);
        }
    }

    #[test]
    fn exact_far_from_robust_range() {
        let s = 1e-200;
        let p = Plane::through([0.0, 0.0, 0.0], [s, 0.0, 0.0], [0.0, s, 0.0]).unwrap();
        assert_eq!(p.side_of([0.0, 0.0, s * 1e-100]), Side::Front);
        assert_eq!(p.side_exact([3.0 * s, 5.0 * s, 0.0]), Side::On);
        let big = 1e300;
        let q = Plane::through([0.0, 0.0, big], [big, 0.0, big], [0.0, big, big]).unwrap();
        assert_eq!(q.side_of([1.0, 1.0, big]), Side::On);
        assert_eq!(
            q.side_of([1.0, 1.0, big * (1.0 + f64::EPSILON)]),
            Side::Front
        );
    }

    /// The a-priori bounds enclose the exact coefficients (checked against the exact
    /// dyadic values).
    #[test]
    fn a_priori_bounds_enclose_the_exact_coefficients() {
        let mut x = 0x2545_F491_4F6C_DD1Du64;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let m = (x >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            let e = ((x >> 3) % 40) as i32 - 20;
            m * 2f64.powi(e)
        };
        for round in 0..2000u32 {
            let p = [next(), next(), next()];
            let q = [next(), next(), next()];
            let r = [next(), next(), next()];
            for def in [
                PlaneDef::Through([p, q, r]),
                PlaneDef::Edge {
                    p,
                    q,
                    k: (round % 3) as u8,
                    flip: round % 2 == 0,
                },
                PlaneDef::PointNormal { p, n: q },
                PlaneDef::Along { p, q, d: r },
            ] {
                let (n, d, en, ed) = def.approximate();
                let (ne, de) = def.exact();
                let within = |approx: f64, err: f64, exact: &Dyadic| {
                    let lo = Dyadic::from_f64((approx - err).next_down());
                    let hi = Dyadic::from_f64((approx + err).next_up());
                    (&lo - exact).signum() != Ordering::Greater
                        && (&hi - exact).signum() != Ordering::Less
                };
                for i in 0..3 {
                    assert!(within(n[i], en, &ne[i]), "{def:?} normal {i}");
                }
                assert!(within(d, ed, &de), "{def:?} offset");
            }
        }
    }

    #[test]
    fn a_plane_within_another_is_the_same_set_of_points() {
        let off = 1e7;
        let p = [off, off, off];
        let q = [off + 1.5, off, off + 0.25];
        let r = [off, off + 2.0, off - 0.75];
        let a = Plane::through(p, q, r).unwrap();
        // The reversed twin, and a plane through other points of the same plane.
        let twin = Plane::through(p, r, q).unwrap();
        assert!(twin.is_within(&a) && a.is_within(&twin));
        let s = [off + 1.5, off + 2.0, off - 0.5];
        assert_eq!(a.side_of(s), Side::On);
        let other = Plane::through(q, s, r).unwrap();
        assert!(other.is_within(&a) && a.is_within(&other.flipped()));
        // One point two ulps off: not the same plane.
        let t = [s[0], s[1], s[2] + 2f64.powi(-28)];
        let off_plane = Plane::through(q, t, r).unwrap();
        assert!(!off_plane.is_within(&a) && !a.is_within(&off_plane));
        // Only planes through three points answer.
        let edge = Plane::edge(p, q, 2, false);
        assert!(!edge.is_within(&edge));
    }

    #[test]
    fn coincidence_is_geometric() {
        let a = Plane::through([0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
        let b = Plane::through([2.0, 2.0, 0.0], [3.0, 2.0, 0.0], [2.0, 5.0, 0.0]).unwrap();
        assert!(a.coincides(&b));
        assert!(!a.coincides(&b.flipped()));
        assert!(a.same_facing(&b));
        let n = Plane::point_normal([0.0, 0.0, 0.0], [0.0, 0.0, 3.0]).unwrap();
        assert!(a.coincides(&n));
    }
}
