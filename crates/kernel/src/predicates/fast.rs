//! The fast exact path: the predicates of implicit vertices evaluated in fixed-capacity
//! integers ([`Wide`]) when their inputs span few enough bits, with the same signs as
//! the dyadic evaluation.
//!
//! # Scaling
//!
//! Every point coordinate that defines one of the planes of a predicate is an odd integer
//! times a power of two, `x = m·2^k`. With `e` the smallest such `k` over all of them,
//! every coordinate divided by `2^e` is an integer below `2^b` in magnitude, `b` the
//! bit span. Dividing space by `2^e` changes neither which side of a plane a point lies
//! on nor where planes meet, and in the scaled space a plane's coefficients are integers:
//! `n = (q − p) × (r − p)`, `d = −n·p` for a plane through three points (similarly for an
//! edge plane). The normal of a point-normal plane is divided by its own power of two
//! (any positive factor of a plane's coefficients leaves every sign unchanged, since the
//! predicates are linear in each plane's coefficients).
//!
//! # Capacity
//!
//! From `b` and the kind of each plane, bounds `|nᵢ| < 2^α` and `|d| < 2^β` follow; the
//! predicate's bound is about `9b + 21` bits for four planes through points. The
//! evaluation picks the smallest capacity that holds it (768 or 1664 bits) and returns
//! `None` beyond, where the caller falls back to dyadic arithmetic.

use std::cmp::Ordering;

use super::wide::Wide;
use crate::dyadic::Dyadic;
use crate::plane::{Plane, PlaneDef};

/// Small capacity: 10 limbs (640 bits), inputs spanning up to about 68 bits.
const SMALL: usize = 10;
/// Medium capacity: 16 limbs (1024 bits), inputs spanning up to about 111 bits.
const MEDIUM: usize = 16;
/// Large capacity: 26 limbs (1664 bits), inputs spanning up to about 180 bits.
const LARGE: usize = 26;

/// `x = ±m·2^k` with `m` odd, or `None` for zero (and non-finite values, which callers
/// exclude).
#[inline]
fn decompose(x: f64) -> Option<(u64, i32, bool)> {
    if x == 0.0 || !x.is_finite() {
        return None;
    }
    let bits = x.to_bits();
    let neg = bits >> 63 == 1;
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let frac = bits & ((1u64 << 52) - 1);
    let (mant, k) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1u64 << 52), exp - 1075)
    };
    let tz = mant.trailing_zeros();
    Some((mant >> tz, k + tz as i32, neg))
}

/// The smallest exponent and the largest top bit (exclusive) of a set of values.
#[derive(Clone, Copy)]
struct Span {
    lo: i32,
    hi: i32,
}

impl Span {
    const EMPTY: Span = Span {
        lo: i32::MAX,
        hi: i32::MIN,
    };

    #[inline]
    fn add(&mut self, x: f64) {
        if let Some((m, k, _)) = decompose(x) {
            self.lo = self.lo.min(k);
            self.hi = self.hi.max(k + 64 - m.leading_zeros() as i32);
        }
    }

    #[inline]
    fn add3(&mut self, p: &[f64; 3]) {
        for &x in p {
            self.add(x);
        }
    }

    /// The common exponent (0 when there are no non-zero values).
    #[inline]
    fn exponent(&self) -> i32 {
        if self.lo == i32::MAX {
            0
        } else {
            self.lo
        }
    }

    /// The bit span: every value over `2^exponent` is below `2^bits` in magnitude.
    #[inline]
    fn bits(&self) -> i32 {
        if self.lo == i32::MAX {
            0
        } else {
            self.hi - self.lo
        }
    }
}

/// `x / 2^e` as an integer (`e` at most the exponent of `x`).
#[inline]
fn int<const N: usize>(x: f64, e: i32) -> Wide<N> {
    match decompose(x) {
        None => Wide::ZERO,
        Some((m, k, neg)) => Wide::from_shifted(m, (k - e) as u32, neg),
    }
}

#[inline]
fn int3<const N: usize>(p: &[f64; 3], e: i32) -> [Wide<N>; 3] {
    [int(p[0], e), int(p[1], e), int(p[2], e)]
}

#[inline]
fn sub3<const N: usize>(a: &[Wide<N>; 3], b: &[Wide<N>; 3]) -> [Wide<N>; 3] {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

#[inline]
fn cross<const N: usize>(a: &[Wide<N>; 3], b: &[Wide<N>; 3]) -> [Wide<N>; 3] {
    [
        &(&a[1] * &b[2]) - &(&a[2] * &b[1]),
        &(&a[2] * &b[0]) - &(&a[0] * &b[2]),
        &(&a[0] * &b[1]) - &(&a[1] * &b[0]),
    ]
}

#[inline]
fn dot<const N: usize>(a: &[Wide<N>; 3], b: &[Wide<N>; 3]) -> Wide<N> {
    &(&(&a[0] * &b[0]) + &(&a[1] * &b[1])) + &(&a[2] * &b[2])
}

/// The points of a plane's definition and, for a point-normal plane, its normal.
#[inline]
fn span_of(def: &PlaneDef, points: &mut Span) {
    match def {
        PlaneDef::Through(pts) => pts.iter().for_each(|p| points.add3(p)),
        PlaneDef::Edge { p, q, .. } | PlaneDef::Along { p, q, .. } => {
            points.add3(p);
            points.add3(q);
        }
        PlaneDef::PointNormal { p, .. } => points.add3(p),
    }
}

/// Bit bounds `(α, β)` with `|nᵢ| < 2^α`, `|d| < 2^β` for the scaled plane, given the bit
/// span `b` of the point coordinates.
#[inline]
fn coefficient_bits(def: &PlaneDef, b: i32) -> (i32, i32) {
    match def {
        // Differences < 2^(b+1); two products of them < 2^(2b+3); d: three products.
        PlaneDef::Through(_) => (2 * b + 3, 3 * b + 5),
        // n is ± a difference (one component zero); d: two products.
        PlaneDef::Edge { .. } => (b + 1, 2 * b + 2),
        PlaneDef::PointNormal { n, .. } => {
            let mut s = Span::EMPTY;
            s.add3(n);
            let bn = s.bits();
            (bn, bn + b + 2)
        }
        // The direction is scaled on its own (< 2^bd); n: two products of a difference
        // (< 2^(b+1)) and a direction component; d: three products of n and a point.
        PlaneDef::Along { d, .. } => {
            let mut s = Span::EMPTY;
            s.add3(d);
            let bd = s.bits();
            (b + bd + 2, 2 * b + bd + 4)
        }
    }
}

/// A plane's scaled integer coefficients `(n, d)` with its orientation.
#[inline]
fn coefficients<const N: usize>(plane: &Plane, e: i32) -> ([Wide<N>; 3], Wide<N>) {
    let (n, p) = match plane.definition() {
        PlaneDef::Through([p, q, r]) => {
            let pi = int3(&p, e);
            let u = sub3(&int3(&q, e), &pi);
            let v = sub3(&int3(&r, e), &pi);
            (cross(&u, &v), pi)
        }
        PlaneDef::Edge { p, q, k, flip } => {
            let pi = int3(&p, e);
            let w = sub3(&int3(&q, e), &pi);
            let z = Wide::ZERO;
            let n = match k {
                0 => [z, w[2], -w[1]],
                1 => [-w[2], z, w[0]],
                _ => [w[1], -w[0], z],
            };
            (if flip { n.map(|x| -x) } else { n }, pi)
        }
        PlaneDef::Along { p, q, d } => {
            let pi = int3(&p, e);
            let w = sub3(&int3(&q, e), &pi);
            let mut s = Span::EMPTY;
            s.add3(&d);
            (cross(&w, &int3(&d, s.exponent())), pi)
        }
        PlaneDef::PointNormal { p, n } => {
            let mut s = Span::EMPTY;
            s.add3(&n);
            (int3(&n, s.exponent()), int3(&p, e))
        }
    };
    let d = -dot(&n, &p);
    if plane.is_flipped() {
        (n.map(|x| -x), -d)
    } else {
        (n, d)
    }
}

/// Scaling exponent, and bit bounds `(α, β)` of the planes' coefficients.
#[inline]
fn scale<const K: usize>(planes: [&Plane; K]) -> (i32, [(i32, i32); K]) {
    let defs = planes.map(Plane::definition);
    let mut s = Span::EMPTY;
    defs.iter().for_each(|d| span_of(d, &mut s));
    let b = s.bits();
    (s.exponent(), defs.map(|d| coefficient_bits(&d, b)))
}

/// Bit bounds of `X` (every component) and `D` for three planes.
#[inline]
fn homogeneous_bits(ab: &[(i32, i32)]) -> (i32, i32) {
    let (a1, b1) = ab[0];
    let (a2, b2) = ab[1];
    let (a3, b3) = ab[2];
    // Each cross-product component < 2^(αj+αk+1); D and X are sums of three products.
    let d = a1 + a2 + a3 + 3;
    let x = (b1 + a2 + a3).max(b2 + a3 + a1).max(b3 + a1 + a2) + 3;
    (x, d)
}

/// `(X, D)` of three scaled planes: the intersection is `X / D` in the scaled space.
#[inline]
fn homogeneous_in<const N: usize>(
    p1: &Plane,
    p2: &Plane,
    p3: &Plane,
    e: i32,
) -> ([Wide<N>; 3], Wide<N>) {
    let (n1, d1) = coefficients::<N>(p1, e);
    let (n2, d2) = coefficients::<N>(p2, e);
    let (n3, d3) = coefficients::<N>(p3, e);
    let c23 = cross(&n2, &n3);
    let c31 = cross(&n3, &n1);
    let c12 = cross(&n1, &n2);
    let d = dot(&n1, &c23);
    // h = −d, so X = −(d₁c₂₃ + d₂c₃₁ + d₃c₁₂).
    let x = [0, 1, 2].map(|j| -(&(&(&d1 * &c23[j]) + &(&d2 * &c31[j])) + &(&d3 * &c12[j])));
    (x, d)
}

/// Sign of `(n_H·X + d_H·D)·D`, or `None` when `D = 0`.
#[inline]
fn side_in<const N: usize>(p: [&Plane; 4], e: i32) -> Option<Ordering> {
    let (x, d) = homogeneous_in::<N>(p[0], p[1], p[2], e);
    if d.is_zero() {
        return None;
    }
    let (n, o) = coefficients::<N>(p[3], e);
    let v = &dot(&n, &x) + &(&o * &d);
    Some(if d.is_negative() {
        v.signum().reverse()
    } else {
        v.signum()
    })
}

/// Outcome of the fast path.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Fast<T> {
    /// Decided.
    Done(T),
    /// The inputs span too many bits: use the dyadic path.
    TooWide,
}

/// The sign of `h` at the intersection of `p1`, `p2`, `p3` (the sign of
/// `(n_H·X + d_H·D)·D`), `Done(None)` when `D = 0`.
pub(crate) fn side_of_intersection(
    p1: &Plane,
    p2: &Plane,
    p3: &Plane,
    h: &Plane,
) -> Fast<Option<Ordering>> {
    let planes = [p1, p2, p3, h];
    let (e, ab) = scale(planes);
    let (xb, db) = homogeneous_bits(&ab);
    let (ah, bh) = ab[3];
    // n_H·X < 3·2^(α_H + x), d_H·D < 2^(β_H + d), and the sum of both.
    let bits = (ah + xb + 2).max(bh + db) + 1;
    if bits <= 64 * SMALL as i32 {
        Fast::Done(side_in::<SMALL>(planes, e))
    } else if bits <= 64 * MEDIUM as i32 {
        Fast::Done(side_in::<MEDIUM>(planes, e))
    } else if bits <= 64 * LARGE as i32 {
        Fast::Done(side_in::<LARGE>(planes, e))
    } else {
        Fast::TooWide
    }
}

/// The intersection of three planes as exact homogeneous coordinates `(X, D)`, the
/// point `X / D` (scaled by positive factors against the dyadic path's), `D = 0` when
/// they do not meet in one point.
pub(crate) fn homogeneous(p1: &Plane, p2: &Plane, p3: &Plane) -> Fast<([Dyadic; 3], Dyadic)> {
    let (e, ab) = scale([p1, p2, p3]);
    let (xb, db) = homogeneous_bits(&ab);
    if xb.max(db) > 64 * LARGE as i32 {
        return Fast::TooWide;
    }
    let (x, d) = homogeneous_in::<LARGE>(p1, p2, p3, e);
    // The point is 2^e·X/D in unscaled space.
    let dy = |v: &Wide<LARGE>, e: i32| Dyadic::from_limbs(v.is_negative(), v.limbs(), e as i64);
    Fast::Done((x.map(|v| dy(&v, e)), dy(&d, 0)))
}

/// The sign of `orient3d(a, b, c, d)`: `det[a − d; b − d; c − d]`.
pub(crate) fn orient3d(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> Fast<Ordering> {
    let mut s = Span::EMPTY;
    for p in [&a, &b, &c, &d] {
        s.add3(p);
    }
    let e = s.exponent();
    // Rows < 2^(b+1), the cross product < 2^(2b+3), the determinant < 2^(3b+6).
    let bits = 3 * s.bits() + 6;
    if bits > 64 * LARGE as i32 {
        return Fast::TooWide;
    }
    fn det<const N: usize>(
        a: &[f64; 3],
        b: &[f64; 3],
        c: &[f64; 3],
        d: &[f64; 3],
        e: i32,
    ) -> Ordering {
        let di = int3::<N>(d, e);
        let ra = sub3(&int3(a, e), &di);
        let rb = sub3(&int3(b, e), &di);
        let rc = sub3(&int3(c, e), &di);
        dot(&ra, &cross(&rb, &rc)).signum()
    }
    Fast::Done(if bits <= 64 * SMALL as i32 {
        det::<SMALL>(&a, &b, &c, &d, e)
    } else {
        det::<LARGE>(&a, &b, &c, &d, e)
    })
}
