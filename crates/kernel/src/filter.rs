//! The floating-point filter of a plane's side: a plane's approximate coefficients with
//! their proven error bounds, evaluated at an approximate point with a proven bound on
//! the distance from the exact value.
//!
//! A vertex carries approximate coordinates `x̃` and a bound `e` with `|x̃ᵢ − xᵢ| ≤ e`; a
//! plane carries approximate coefficients `(ã, b̃, c̃, d̃)` with `|nᵢ − ñᵢ| ≤ e_n` and
//! `|d − d̃| ≤ e_d` ([`crate::Plane::error_bounds`]). The filter computes
//! `v = fl(ã·x̃ + b̃·ỹ + c̃·z̃ + d̃)` and decides `sign(v)` when `|v| > B` with
//!
//! `B = (8u·(Σ|ñᵢx̃ᵢ| + |d̃|) + e_n·(Σ|x̃ᵢ| + 3e) + (Σ|ñᵢ|)·e + e_d + η)·(1 + 2⁻³⁰)`,
//!
//! `u = 2⁻⁵³`. The exact value differs from `Σñᵢx̃ᵢ + d̃` by at most
//! `Σ|nᵢ − ñᵢ|·|xᵢ| + Σ|ñᵢ|·|xᵢ − x̃ᵢ| + |d − d̃|`, which the middle terms bound; the four
//! roundings of the evaluation cost at most `γ₄ < 8u` times the magnitudes; `η = 2⁻¹⁰⁶⁰`
//! covers absolute errors of results in the subnormal range; the last factor covers the
//! roundings of `B` itself. An overflow makes `v` or `B` infinite or NaN and the filter
//! undecided.

use crate::side::Side;

const U: f64 = 1.0 / 9_007_199_254_740_992.0; // 2^-53
const FILTER_REL: f64 = 8.0 * U;
const SAFETY: f64 = 1.0 + 1.0 / 1_073_741_824.0; // 1 + 2^-30
/// Absolute slack for subnormal results: 2^-1060.
const ETA: f64 = f64::from_bits(1 << 14);

/// A plane's approximate coefficients prepared for the filter.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PlaneF {
    n: [f64; 3],
    d: f64,
    nsum: f64,
    err_n: f64,
    err_d: f64,
}

impl PlaneF {
    /// The filter of a plane with approximate coefficients `[a, b, c, d]` and error
    /// bounds `(e_n, e_d)` ([`crate::Plane::approx`], [`crate::Plane::error_bounds`]).
    #[inline]
    pub(crate) fn new([a, b, c, d]: [f64; 4], (err_n, err_d): (f64, f64)) -> PlaneF {
        PlaneF {
            n: [a, b, c],
            d,
            nsum: a.abs() + b.abs() + c.abs(),
            err_n,
            err_d,
        }
    }

    /// `fl(ã·x + b̃·y + c̃·z + d̃)`.
    #[inline(always)]
    pub(crate) fn eval(&self, x: &[f64; 3]) -> f64 {
        self.n[0] * x[0] + self.n[1] * x[1] + self.n[2] * x[2] + self.d
    }

    /// A bound valid for [`PlaneF::eval`] at every approximate point whose coordinates
    /// have magnitude at most `max_abs` and error bound at most `max_err` (the bound of
    /// [`PlaneF::side`] maximised over such points: a semi-static filter shared by all
    /// vertices of a polygon).
    #[inline]
    pub(crate) fn bound_for(&self, max_abs: f64, max_err: f64) -> f64 {
        ((self.nsum * max_abs + self.d.abs()) * FILTER_REL
            + self.err_n * 3.0 * (max_abs + max_err)
            + self.nsum * max_err
            + self.err_d
            + ETA)
            * SAFETY
            * SAFETY
    }

    /// The plane's equation at an approximate point with error bound `err`, and a bound
    /// on its distance from the exact equation's value at the exact point.
    #[inline]
    pub(crate) fn height(&self, x: &[f64; 3], err: f64) -> (f64, f64) {
        let t0 = self.n[0] * x[0];
        let t1 = self.n[1] * x[1];
        let t2 = self.n[2] * x[2];
        let v = t0 + t1 + t2 + self.d;
        let mag = t0.abs() + t1.abs() + t2.abs() + self.d.abs();
        let xs = x[0].abs() + x[1].abs() + x[2].abs();
        let bound =
            (mag * FILTER_REL + self.err_n * (xs + 3.0 * err) + self.nsum * err + self.err_d + ETA)
                * SAFETY;
        (v, bound)
    }

    /// The filtered side of an approximate point with error bound `err`, or `None` when
    /// the filter cannot decide.
    #[inline]
    pub(crate) fn side(&self, x: &[f64; 3], err: f64) -> Option<Side> {
        let (v, bound) = self.height(x, err);
        if v > bound {
            Some(Side::Front)
        } else if v < -bound {
            Some(Side::Back)
        } else {
            None
        }
    }

    /// The normal's product `ñ·d` with a direction `d` given exactly, and a bound on its
    /// distance from the exact `n·d` (the coefficient errors, then three roundings).
    #[inline]
    pub(crate) fn direction_height(&self, d: &[f64; 3]) -> (f64, f64) {
        let t0 = self.n[0] * d[0];
        let t1 = self.n[1] * d[1];
        let t2 = self.n[2] * d[2];
        let v = t0 + t1 + t2;
        let mag = t0.abs() + t1.abs() + t2.abs();
        let ds = d[0].abs() + d[1].abs() + d[2].abs();
        let bound = (mag * FILTER_REL + self.err_n * ds + ETA) * SAFETY;
        (v, bound)
    }
}
