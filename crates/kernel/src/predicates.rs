//! The side of a plane at an implicit vertex, exactly: the vertex's approximation with a
//! proven error bound (for the filter of [`crate::filter`]), the combinatorial shortcut,
//! and exact evaluation behind them.
//!
//! # Implicit vertices
//!
//! A vertex made by splitting is the intersection `P₁ ∩ P₂ ∩ P₃` of three planes, each
//! defined by input values. Its approximation comes from Cramer's rule in f64 with a
//! priori error bounds on the planes' coefficients; its exact side against `H` is the
//! sign of `(n_H·X + d_H·D)·D` with `D = n₁·(n₂×n₃)`,
//! `X = h₁(n₂×n₃) + h₂(n₃×n₁) + h₃(n₁×n₂)`, `hᵢ = −dᵢ`, evaluated exactly.
//!
//! # Exact evaluation
//!
//! The exact path first scales the inputs of the predicate to integers by a common power
//! of two and, when they span few enough bits that the result fits 1664 bits, evaluates
//! in fixed-capacity integers on the stack (the `fast` module); otherwise in dyadic
//! arithmetic on big integers ([`crate::dyadic`]). Both compute the same exact sign.

use std::cmp::Ordering;

use crate::dyadic::{self, Dyadic};
use crate::plane::Plane;
use crate::side::Side;

mod fast;
mod wide;

#[cfg(test)]
mod tests;

use fast::Fast;

const U: f64 = 1.0 / 9_007_199_254_740_992.0; // 2^-53
const SAFETY: f64 = 1.0 + 1.0 / 1_073_741_824.0; // 1 + 2^-30
/// Absolute slack for subnormal results: 2^-1060.
const ETA: f64 = f64::from_bits(1 << 14);
/// Least relative determinant error assumed in [`approximate`]: 2^-1000.
const T_FLOOR: f64 = 9.332636185032189e-302;

/// A value known to lie within `e` of `v` (midpoint and radius), propagated through
/// Cramer's rule with a priori bounds: cheaper than outward-rounded intervals, which
/// round every bound separately.
///
/// Each operation adds the data error (`|a|·e_b + |b|·e_a + e_a·e_b` for a product,
/// `e_a + e_b` for a sum), the rounding of its own result (`u·|v|`, and `2η` for
/// results and bound terms in the subnormal range), all computed in f64. The bounds are
/// sums and products of non-negative terms, each rounded to nearest, so over the few
/// levels of Cramer's rule they fall short of the true bound by a relative `O(30u)` at
/// most; the result is multiplied by `1 + 2⁻³⁰`, far more than that. An overflow makes a
/// value or a bound infinite or NaN (an infinite bound times a zero value), which
/// [`approximate`] reports as no approximation or as an infinite bound.
#[derive(Debug, Clone, Copy)]
struct Mr {
    v: f64,
    e: f64,
}

impl Mr {
    #[inline(always)]
    fn mul(self, o: Mr) -> Mr {
        let v = self.v * o.v;
        Mr {
            v,
            e: self.v.abs() * o.e + o.v.abs() * self.e + self.e * o.e + U * v.abs() + 2.0 * ETA,
        }
    }

    #[inline(always)]
    fn add(self, o: Mr) -> Mr {
        let v = self.v + o.v;
        Mr {
            v,
            e: self.e + o.e + U * v.abs() + ETA,
        }
    }

    #[inline(always)]
    fn sub(self, o: Mr) -> Mr {
        let v = self.v - o.v;
        Mr {
            v,
            e: self.e + o.e + U * v.abs() + ETA,
        }
    }
}

#[inline(always)]
fn cross_mr(a: [Mr; 3], b: [Mr; 3]) -> [Mr; 3] {
    [
        a[1].mul(b[2]).sub(a[2].mul(b[1])),
        a[2].mul(b[0]).sub(a[0].mul(b[2])),
        a[0].mul(b[1]).sub(a[1].mul(b[0])),
    ]
}

/// A plane's coefficients with their bounds `(n, h)`, `h = −d`, all multiplied by the
/// power of two that brings the largest normal component into `[1, 2)`: the plane and
/// the intersection stay the same, and Cramer's rule neither overflows on huge scenes
/// nor underflows on tiny ones. The scaling is exact except where a result is
/// subnormal, which `η` covers.
#[inline(always)]
fn plane_mr(([a, b, c, d], (en, ed)): Coefficients) -> ([Mr; 3], Mr) {
    let m = a.abs().max(b.abs()).max(c.abs());
    let exp = ((m.to_bits() >> 52) & 0x7ff) as i64 - 1023;
    let scale = if exp >= -1022 {
        // 2^-exp for exp in [-1022, 1023]: normal, or the subnormal 2^-1023.
        if exp == 1023 {
            f64::from_bits(1 << 51)
        } else {
            f64::from_bits(((1023 - exp) as u64) << 52)
        }
    } else {
        // A subnormal largest component: 2^1022 brings it to at least 2^-52.
        f64::from_bits(2045 << 52)
    };
    (
        [a, b, c].map(|v| Mr {
            v: v * scale,
            e: en * scale + ETA,
        }),
        Mr {
            v: -d * scale,
            e: ed * scale + ETA,
        },
    )
}

/// An approximation of the intersection of three planes with a bound on the error of
/// every coordinate, from Cramer's rule with a priori error bounds ([`Mr`]). `None` when
/// the determinant's bound does not keep it at least half its magnitude away from zero
/// (the planes are, or are nearly, parallel to a common line) or a coordinate or the
/// determinant overflows. A coordinate's bound that overflows, or is NaN because a
/// plane's coefficient bound overflowed (an infinite bound times a zero value), makes the
/// returned bound infinite: the filters then leave the vertex to exact evaluation, and
/// the position is only a hint. The bound is never 0, which would claim the position is
/// the vertex exactly.
///
/// With `X = X̃ ± e_X`, `D = D̃ ± e_D` and `t = e_D / |D̃| ≤ ½`, each coordinate obeys
/// `|X/D − X̃/D̃| ≤ (e_X/|D̃| + |X̃/D̃|·t) / (1 − t)`; the quotient's own rounding adds
/// `u·|x̃| + η`. `t` is raised to at least `2⁻¹⁰⁰⁰` so that its underflow cannot hide
/// error at huge coordinates.
pub(crate) fn approximate(p1: &Plane, p2: &Plane, p3: &Plane) -> Option<([f64; 3], f64)> {
    let c = |p: &Plane| (p.approx(), p.error_bounds());
    approximate_from(c(p1), c(p2), c(p3))
}

/// A plane's approximate coefficients `[a, b, c, d]` and their error bounds `(e_n, e_d)`
/// ([`Plane::approx`], [`Plane::error_bounds`]).
pub(crate) type Coefficients = ([f64; 4], (f64, f64));

/// [`approximate`] from the planes' approximate coefficients and bounds.
pub(crate) fn approximate_from(
    p1: Coefficients,
    p2: Coefficients,
    p3: Coefficients,
) -> Option<([f64; 3], f64)> {
    let (n1, h1) = plane_mr(p1);
    let (n2, h2) = plane_mr(p2);
    let (n3, h3) = plane_mr(p3);
    let c23 = cross_mr(n2, n3);
    let c31 = cross_mr(n3, n1);
    let c12 = cross_mr(n1, n2);
    let det = n1[0]
        .mul(c23[0])
        .add(n1[1].mul(c23[1]))
        .add(n1[2].mul(c23[2]));
    let dabs = det.v.abs();
    let ed = det.e * SAFETY;
    // Finite, and the determinant at least twice its bound (false for NaN too).
    let usable = dabs.is_finite() && ed.is_finite() && ed <= 0.5 * dabs;
    if !usable {
        return None;
    }
    let t = if ed == 0.0 {
        0.0
    } else {
        ((ed / dabs) * SAFETY).max(T_FLOOR)
    };
    let one_minus_t = 1.0 - t;
    let mut pos = [0.0; 3];
    let mut err: f64 = 0.0;
    for j in 0..3 {
        let x = h1.mul(c23[j]).add(h2.mul(c31[j])).add(h3.mul(c12[j]));
        let q = x.v / det.v;
        let data = (x.e * SAFETY / dabs + q.abs() * t + ETA) / one_minus_t;
        let e = (data + U * q.abs() + ETA) * SAFETY;
        pos[j] = q;
        // An infinite coefficient bound times a zero value gives a NaN bound, which means
        // no bound at all; `f64::max` would drop it and keep the other coordinates'.
        err = if e.is_nan() {
            f64::INFINITY
        } else {
            err.max(e)
        };
    }
    if pos.iter().any(|v| !v.is_finite()) {
        return None;
    }
    Some((pos, err))
}

/// Exact homogeneous coordinates `(X, D)` of the intersection of three planes: the
/// point is `X / D`; `D = 0` when they do not meet in one point.
pub(crate) fn homogeneous(p1: &Plane, p2: &Plane, p3: &Plane) -> ([Dyadic; 3], Dyadic) {
    match fast::homogeneous(p1, p2, p3) {
        Fast::Done(r) => r,
        Fast::TooWide => homogeneous_dyadic(p1, p2, p3),
    }
}

/// [`homogeneous`] in dyadic arithmetic.
fn homogeneous_dyadic(p1: &Plane, p2: &Plane, p3: &Plane) -> ([Dyadic; 3], Dyadic) {
    let (n1, d1) = p1.exact();
    let (n2, d2) = p2.exact();
    let (n3, d3) = p3.exact();
    let (h1, h2, h3) = (-&d1, -&d2, -&d3);
    let c23 = dyadic::cross3(&n2, &n3);
    let c31 = dyadic::cross3(&n3, &n1);
    let c12 = dyadic::cross3(&n1, &n2);
    let d = dyadic::dot3(&n1, &c23);
    let x = [0, 1, 2].map(|j| &(&(&h1 * &c23[j]) + &(&h2 * &c31[j])) + &(&h3 * &c12[j]));
    (x, d)
}

/// The exact side of `h` at the intersection of three planes, or `None` if they do not
/// meet in a single point.
pub(crate) fn side_of_intersection(p1: &Plane, p2: &Plane, p3: &Plane, h: &Plane) -> Option<Side> {
    if h.same_definition(p1) || h.same_definition(p2) || h.same_definition(p3) {
        return Some(Side::On);
    }
    let s = match fast::side_of_intersection(p1, p2, p3, h) {
        Fast::Done(s) => s,
        Fast::TooWide => side_of_intersection_dyadic(p1, p2, p3, h),
    };
    s.map(Side::from_ordering)
}

/// The sign of `(n_H·X + d_H·D)·D` in dyadic arithmetic, `None` when `D = 0`.
fn side_of_intersection_dyadic(p1: &Plane, p2: &Plane, p3: &Plane, h: &Plane) -> Option<Ordering> {
    let (x, d) = homogeneous_dyadic(p1, p2, p3);
    if d.is_zero() {
        return None;
    }
    let (n, e) = h.exact();
    let v = &dyadic::dot3(&n, &x) + &(&e * &d);
    Some(match d.signum() {
        Ordering::Less => v.signum().reverse(),
        _ => v.signum(),
    })
}

/// Which exact evaluation [`exact_side_of_intersection`] uses (for measurements).
#[doc(hidden)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExactPath {
    /// Fixed-capacity integers, `None` when the inputs span too many bits.
    Fast,
    /// Dyadic big-integer arithmetic.
    Dyadic,
}

/// The exact sign of `h` at the intersection of three planes, without filter or
/// shortcut, through the given path: `Some(None)` when the planes do not meet in one
/// point, `None` when the fast path cannot hold the inputs. For measurements and tests.
#[doc(hidden)]
pub fn exact_side_of_intersection(
    p1: &Plane,
    p2: &Plane,
    p3: &Plane,
    h: &Plane,
    path: ExactPath,
) -> Option<Option<Ordering>> {
    match path {
        ExactPath::Fast => match fast::side_of_intersection(p1, p2, p3, h) {
            Fast::Done(s) => Some(s),
            Fast::TooWide => None,
        },
        ExactPath::Dyadic => Some(side_of_intersection_dyadic(p1, p2, p3, h)),
    }
}

/// The intersection of three planes rounded to f64 (each coordinate within a few ulps),
/// or `None` if they do not meet in one point.
pub(crate) fn rounded_intersection(p1: &Plane, p2: &Plane, p3: &Plane) -> Option<[f64; 3]> {
    let (x, d) = homogeneous(p1, p2, p3);
    if d.is_zero() {
        return None;
    }
    // Divide with 64 bits of quotient precision: scale X by 2^k first.
    Some(x.map(|v| dyadic::quotient_f64(&v, &d)))
}

/// The exact sign of `robust::orient3d(a, b, c, d)`: `Greater` when `d` lies below the
/// plane through `a`, `b`, `c` (counter-clockwise seen from above), for every finite
/// input (Shewchuk's adaptive predicate where it is exact, exact integer arithmetic
/// otherwise).
pub fn orient3d(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> Ordering {
    if crate::plane::robust_safe(&[a, b, c, d]) {
        let p = |v: [f64; 3]| robust::Coord3D {
            x: v[0],
            y: v[1],
            z: v[2],
        };
        let o = robust::orient3d(p(a), p(b), p(c), p(d));
        return o.partial_cmp(&0.0).unwrap_or(Ordering::Equal);
    }
    match fast::orient3d(a, b, c, d) {
        Fast::Done(s) => s,
        Fast::TooWide => orient3d_dyadic(a, b, c, d),
    }
}

/// [`orient3d`] in dyadic arithmetic.
fn orient3d_dyadic(a: [f64; 3], b: [f64; 3], c: [f64; 3], d: [f64; 3]) -> Ordering {
    let dd = dyadic::point3(d);
    let row = |v: [f64; 3]| {
        let e = dyadic::point3(v);
        [&e[0] - &dd[0], &e[1] - &dd[1], &e[2] - &dd[2]]
    };
    let (ra, rb, rc) = (row(a), row(b), row(c));
    dyadic::dot3(&ra, &dyadic::cross3(&rb, &rc)).signum()
}
