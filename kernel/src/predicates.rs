//! The side of a plane at a vertex: an f64 filter with a proven error bound, and exact
//! fixed-width evaluation behind it.
//!
//! # The filter
//!
//! A vertex carries approximate grid coordinates `x̃` and a bound `e` with
//! `|x̃ᵢ - xᵢ| <= e` on every axis. For a plane `h = (a, b, c, d)` the filter computes
//! `v = fl(ã·x̃ + b̃·ỹ + c̃·z̃ + d̃)` (coefficients rounded to f64) and decides `sign(v)`
//! when `|v| > B` with
//!
//! `B = (2^-50 · (|ã·x̃| + |b̃·ỹ| + |c̃·z̃| + |d̃|) + (|ã| + |b̃| + |c̃|) · e) · (1 + 2^-30)`.
//!
//! Proof sketch (u = 2^-53): each product term suffers at most 5 roundings (coefficient,
//! product, three additions), so the evaluation error at `x̃` is at most
//! `γ₅ · Σ|hᵢ x̃ᵢ| <= 6u · Σ|hᵢ x̃ᵢ|`, and the computed magnitude is at least
//! `(1 - u)^5` times the exact one, so `2^-50 = 8u` times it covers this term. Moving from
//! `x̃` to the exact vertex changes the value by at most `(|a| + |b| + |c|) · e`. The final
//! factor absorbs the few roundings made while computing `B` itself. No value is ever
//! subnormal (coefficients are integers, coordinates are ratios of integers below
//! `2^196` or zero), so relative rounding bounds hold.
//!
//! # Exact evaluation
//!
//! A grid point is evaluated in `i128` (|value| < 2^119). An implicit vertex
//! `P₁ ∩ P₂ ∩ P₃` has homogeneous coordinates `X = h₁(n₂×n₃) + h₂(n₃×n₁) + h₃(n₁×n₂)`,
//! `D = n₁·(n₂×n₃)` with `hᵢ = -dᵢ`; the cross products are `i128` (< 2^111), `D < 2^168`,
//! `|X| < 2^196`, and `h(X/D)·D = n·X + d·D < 12·2^249 < 2^253` fits `ethnum::I256`.
//! No heap allocation happens on either path.

use ethnum::I256;

use crate::plane::{side_of_sign, Plane};
use crate::traits::Side;

const U: f64 = 1.0 / 9_007_199_254_740_992.0; // 2^-53
const FILTER_REL: f64 = 8.0 * U; // 2^-50
const SAFETY: f64 = 1.0 + 1.0 / 1_073_741_824.0; // 1 + 2^-30
const DET_REL: f64 = 32.0 * U; // 2^-48
/// Nonzero error bounds are raised to at least this, keeping all bound arithmetic normal.
const ERR_FLOOR: f64 = 1e-200;

/// A plane's coefficients rounded to f64, prepared for the filter.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PlaneF {
    n: [f64; 3],
    d: f64,
    nsum: f64,
}

impl PlaneF {
    #[inline]
    pub(crate) fn new(p: &Plane) -> PlaneF {
        let [a, b, c, d] = p.approx();
        let n = [a, b, c];
        PlaneF {
            n,
            d,
            nsum: n[0].abs() + n[1].abs() + n[2].abs(),
        }
    }

    /// `fl(ã·x + b̃·y + c̃·z + d̃)`.
    #[inline(always)]
    pub(crate) fn eval(&self, x: &[f64; 3]) -> f64 {
        self.n[0] * x[0] + self.n[1] * x[1] + self.n[2] * x[2] + self.d
    }

    /// A bound valid for [`PlaneF::eval`] at every approximate point whose coordinates have
    /// magnitude at most `max_abs` and error bound at most `max_err` (the per-vertex bound
    /// of [`PlaneF::side`] with `|x̃ᵢ|` replaced by `max_abs`: a semi-static filter shared
    /// by all vertices of a polygon).
    #[inline]
    pub(crate) fn bound_for(&self, max_abs: f64, max_err: f64) -> f64 {
        ((self.nsum * max_abs + self.d.abs()) * FILTER_REL + self.nsum * max_err) * SAFETY * SAFETY
    }

    /// The filtered side of an approximate point with error bound `err`, or `None` when
    /// the filter cannot decide.
    #[inline]
    pub(crate) fn side(&self, x: &[f64; 3], err: f64) -> Option<Side> {
        let t0 = self.n[0] * x[0];
        let t1 = self.n[1] * x[1];
        let t2 = self.n[2] * x[2];
        let v = t0 + t1 + t2 + self.d;
        let mag = t0.abs() + t1.abs() + t2.abs() + self.d.abs();
        let bound = (mag * FILTER_REL + self.nsum * err) * SAFETY;
        if v > bound {
            Some(Side::Front)
        } else if v < -bound {
            Some(Side::Back)
        } else {
            None
        }
    }
}

#[inline]
fn cross_i(n: [i64; 3], m: [i64; 3]) -> [i128; 3] {
    let w = |a: i64, b: i64| a as i128 * b as i128;
    [
        w(n[1], m[2]) - w(n[2], m[1]),
        w(n[2], m[0]) - w(n[0], m[2]),
        w(n[0], m[1]) - w(n[1], m[0]),
    ]
}

#[inline]
fn mul(a: i128, b: i128) -> I256 {
    I256::from(a) * I256::from(b)
}

/// Exact homogeneous coordinates `(X, D)` of the intersection of three planes: the point
/// is `X / D`. `D == 0` when the planes do not meet in one point.
pub fn homogeneous(p1: &Plane, p2: &Plane, p3: &Plane) -> ([I256; 3], I256) {
    let (n1, n2, n3) = (p1.normal(), p2.normal(), p3.normal());
    let (h1, h2, h3) = (-p1.d(), -p2.d(), -p3.d());
    let c23 = cross_i(n2, n3);
    let c31 = cross_i(n3, n1);
    let c12 = cross_i(n1, n2);
    let d = mul(n1[0] as i128, c23[0]) + mul(n1[1] as i128, c23[1]) + mul(n1[2] as i128, c23[2]);
    let x = [0, 1, 2].map(|j| mul(h1, c23[j]) + mul(h2, c31[j]) + mul(h3, c12[j]));
    (x, d)
}

/// The exact side of `h` at the intersection of three planes, or `None` if they do not
/// meet in a single point.
pub fn side_of_intersection(p1: &Plane, p2: &Plane, p3: &Plane, h: &Plane) -> Option<Side> {
    let (x, d) = homogeneous(p1, p2, p3);
    if d == I256::ZERO {
        return None;
    }
    let n = h.normal();
    let v = I256::from(n[0]) * x[0]
        + I256::from(n[1]) * x[1]
        + I256::from(n[2]) * x[2]
        + I256::from(h.d()) * d;
    Some(side_of_sign(v.signum128() as i32 * d.signum128() as i32))
}

/// An approximation of the intersection of three planes in grid coordinates, with a bound
/// `err` on the error of every coordinate. `None` if the planes do not meet in one point.
///
/// First Cramer's rule in f64 with a bound on every rounding (each entry of a determinant
/// suffers at most 10 roundings, bounded by `2^-48` times the same determinant on absolute
/// values);
/// when the denominator is too uncertain, the exact `I256` determinants are rounded
/// instead (relative error at most `8u`).
pub fn approximate(p1: &Plane, p2: &Plane, p3: &Plane) -> Option<([f64; 3], f64)> {
    approximate_f(&PlaneF::new(p1), &PlaneF::new(p2), &PlaneF::new(p3))
        .or_else(|| approximate_exact(p1, p2, p3))
}

/// Cramer's rule in f64 on rounded coefficients, with a proven bound; `None` when the
/// denominator is not clearly away from zero.
///
/// Each entry of a determinant or numerator suffers at most 10 roundings relative to the
/// exact product of integer coefficients (3 for `d`'s conversion, 1 per other coefficient,
/// products, 2 additions per 2×2 minor and per 3-term sum), so its error is at most
/// `γ₁₀ · M` where `M` is the same expression on absolute values; `2^-48 = 32u` times the
/// computed `M` covers this. Then with `|D̃ - D| <= e_D < |D̃|`:
/// `|X/D - X̃/D̃| <= (|X̃|·e_D + |D̃|·e_X) / (|D̃|·(|D̃| - e_D))`, plus the two roundings of
/// `x̃ = X̃ · fl(1/D̃)`; the safety factor covers the roundings of the bound itself.
#[inline]
pub(crate) fn approximate_f(p1: &PlaneF, p2: &PlaneF, p3: &PlaneF) -> Option<([f64; 3], f64)> {
    let (n1, h1) = (p1.n, -p1.d);
    let (n2, h2) = (p2.n, -p2.d);
    let (n3, h3) = (p3.n, -p3.d);
    let cr = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let cra = |a: [f64; 3], b: [f64; 3]| {
        let a = a.map(f64::abs);
        let b = b.map(f64::abs);
        [
            a[1] * b[2] + a[2] * b[1],
            a[2] * b[0] + a[0] * b[2],
            a[0] * b[1] + a[1] * b[0],
        ]
    };
    let (c23, c31, c12) = (cr(n2, n3), cr(n3, n1), cr(n1, n2));
    let (a23, a31, a12) = (cra(n2, n3), cra(n3, n1), cra(n1, n2));
    let det = n1[0] * c23[0] + n1[1] * c23[1] + n1[2] * c23[2];
    let det_mag = n1[0].abs() * a23[0] + n1[1].abs() * a23[1] + n1[2].abs() * a23[2];
    let e_det = det_mag * DET_REL;
    let ad = det.abs();
    if ad.is_nan() || ad <= 2.0 * e_det {
        return None;
    }
    let inv = 1.0 / det;
    let inv_denom = 1.0 / (ad * (ad - e_det));
    let mut pos = [0.0; 3];
    let mut err: f64 = 0.0;
    for j in 0..3 {
        let x = h1 * c23[j] + h2 * c31[j] + h3 * c12[j];
        let x_mag = h1.abs() * a23[j] + h2.abs() * a31[j] + h3.abs() * a12[j];
        let e_x = x_mag * DET_REL;
        pos[j] = x * inv;
        let e = (x.abs() * e_det + ad * e_x) * inv_denom + pos[j].abs() * (3.0 * U);
        err = err.max(e);
    }
    Some((pos, finish_err(err)))
}

/// The intersection rounded from the exact determinants.
fn approximate_exact(p1: &Plane, p2: &Plane, p3: &Plane) -> Option<([f64; 3], f64)> {
    let (x, d) = homogeneous(p1, p2, p3);
    if d == I256::ZERO {
        return None;
    }
    let df = d.as_f64();
    let mut pos = [0.0; 3];
    let mut err: f64 = 0.0;
    for j in 0..3 {
        pos[j] = x[j].as_f64() / df;
        err = err.max(pos[j].abs() * FILTER_REL);
    }
    Some((pos, finish_err(err)))
}

/// Applies the safety factor and the floor to an error bound (zero stays zero: it means
/// the coordinates are exact).
#[inline]
pub(crate) fn finish_err(err: f64) -> f64 {
    if err == 0.0 {
        0.0
    } else {
        (err * SAFETY).max(ERR_FLOOR)
    }
}

/// Whether approximate coordinates with bound `err` are an exact grid point, and which.
#[inline]
pub(crate) fn as_grid(pos: &[f64; 3], err: f64) -> Option<crate::grid::GridPoint> {
    const LIM: f64 = (1u64 << 62) as f64;
    if err != 0.0 {
        return None;
    }
    let g = pos.map(|v| v as i64);
    let exact = (0..3).all(|i| v_ok(pos[i], LIM) && g[i] as f64 == pos[i]);
    exact.then(|| crate::grid::GridPoint::from_array(g))
}

#[inline]
fn v_ok(v: f64, lim: f64) -> bool {
    v.abs() < lim
}

/// Rounds the exact intersection of three planes to f64 grid coordinates (each
/// coordinate within `8u` relative error, about 4 ulps). `None` if the planes do not
/// meet in one point.
pub fn rounded_intersection(p1: &Plane, p2: &Plane, p3: &Plane) -> Option<[f64; 3]> {
    let (x, d) = homogeneous(p1, p2, p3);
    if d == I256::ZERO {
        return None;
    }
    let df = d.as_f64();
    Some(x.map(|v| v.as_f64() / df))
}

/// A vertex given implicitly as the intersection of three planes, with its cached f64
/// approximation for the filter.
#[derive(Debug, Clone, Copy)]
pub struct ImplicitPoint {
    planes: [Plane; 3],
    pos: [f64; 3],
    err: f64,
}

impl ImplicitPoint {
    /// The intersection of three planes, or `None` if they do not meet in one point.
    pub fn new(p1: Plane, p2: Plane, p3: Plane) -> Option<ImplicitPoint> {
        let (pos, err) = approximate(&p1, &p2, &p3)?;
        Some(ImplicitPoint {
            planes: [p1, p2, p3],
            pos,
            err,
        })
    }

    /// The approximate grid coordinates.
    pub fn approx(&self) -> [f64; 3] {
        self.pos
    }

    /// The proven bound on the error of every approximate coordinate (grid units).
    pub fn error_bound(&self) -> f64 {
        self.err
    }

    /// The three planes.
    pub fn planes(&self) -> &[Plane; 3] {
        &self.planes
    }

    /// The side of `h`, by the filter alone (`None` if it cannot decide).
    pub fn side_filtered(&self, h: &Plane) -> Option<Side> {
        PlaneF::new(h).side(&self.pos, self.err)
    }

    /// The side of `h`, exactly, without the filter.
    pub fn side_exact(&self, h: &Plane) -> Side {
        let [p1, p2, p3] = &self.planes;
        side_of_intersection(p1, p2, p3, h).unwrap_or(Side::On)
    }

    /// The side of `h`: the filter, then the exact evaluation if needed. The flag says
    /// whether the exact evaluation ran.
    pub fn side(&self, h: &Plane) -> (Side, bool) {
        match self.side_filtered(h) {
            Some(s) => (s, false),
            None => (self.side_exact(h), true),
        }
    }
}
