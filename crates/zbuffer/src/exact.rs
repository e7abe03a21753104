//! Exact arithmetic for the ray caster's depth comparisons: floating-point expansions
//! (Shewchuk 1997), used only when a float filter with a proven error bound cannot
//! decide, and big integers for points with coordinates outside the expansions' range.
//!
//! An expansion is a sum of f64 components, non-overlapping and increasing in magnitude;
//! its sign is the sign of its last component. All operations are exact as long as no
//! intermediate product overflows or underflows, which holds for coordinates of
//! magnitude in `[MIN_RAYCAST_COORD, MAX_COORD]` (or zero): products of six such
//! numbers stay within 2^±600.
//!
//! Outside that range (a coordinate of 5e-36 beside coordinates near 1, say) products
//! would underflow, so the predicates are evaluated on big integers instead: every f64
//! is an integer times a power of two, and all the coordinates of one predicate are
//! written as integers over the smallest of those powers, which multiplies the
//! predicate's value by a positive power of two and keeps its sign ([`orient3d_sign`],
//! [`Big`]).

use glam::DVec3;
use num_bigint::BigInt;
use num_traits::Signed;

use crate::{MAX_COORD, MIN_RAYCAST_COORD};

/// Whether every coordinate of `p` is zero or of magnitude in
/// `[MIN_RAYCAST_COORD, MAX_COORD]`, where expansions and `robust` are exact.
#[inline]
pub(crate) fn in_range(p: DVec3) -> bool {
    p.to_array()
        .iter()
        .all(|&v| v == 0.0 || (MIN_RAYCAST_COORD..=MAX_COORD).contains(&v.abs()))
}

/// `v` (finite) as `m · 2^e` with an integer `m`; zero as `(0, i32::MAX)` (it does not
/// lower the common exponent).
fn split(v: f64) -> (i64, i32) {
    if v == 0.0 {
        return (0, i32::MAX);
    }
    let bits = v.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i32;
    let frac = (bits & ((1u64 << 52) - 1)) as i64;
    let (m, e) = if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1i64 << 52), exp - 1075)
    };
    (if v < 0.0 { -m } else { m }, e)
}

/// Exact arithmetic on the coordinates of a few points: each coordinate as a big
/// integer over one common power of two (the smallest exponent among them), so that a
/// polynomial of degree `d` in them is its exact value times `2^(−d·e)`, of the same
/// sign.
pub(crate) struct Big {
    /// The common exponent.
    base: i32,
}

impl Big {
    /// The arithmetic for `points` (all finite).
    pub(crate) fn new(points: &[DVec3]) -> Big {
        let base = points
            .iter()
            .flat_map(|p| p.to_array())
            .map(|v| split(v).1)
            .min()
            .unwrap_or(0);
        Big {
            base: if base == i32::MAX { 0 } else { base },
        }
    }

    /// `v` as an integer over `2^base`.
    fn int(&self, v: f64) -> BigInt {
        let (m, e) = split(v);
        if m == 0 {
            return BigInt::from(0);
        }
        BigInt::from(m) << ((e - self.base) as usize)
    }

    /// `robust::orient3d(a, b, c, d)` (the determinant of the rows `a − d`, `b − d`,
    /// `c − d`) times `2^(−3·base)`; the points must be among those given to
    /// [`Big::new`].
    pub(crate) fn orient3d(&self, a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> BigInt {
        let row = |p: DVec3| {
            [
                self.int(p.x) - self.int(d.x),
                self.int(p.y) - self.int(d.y),
                self.int(p.z) - self.int(d.z),
            ]
        };
        let (ad, bd, cd) = (row(a), row(b), row(c));
        let bc = &bd[1] * &cd[2] - &bd[2] * &cd[1];
        let ca = &cd[1] * &ad[2] - &cd[2] * &ad[1];
        let ab = &ad[1] * &bd[2] - &ad[2] * &bd[1];
        &ad[0] * bc + &bd[0] * ca + &cd[0] * ab
    }
}

/// The sign of a big integer: −1, 0 or 1.
pub(crate) fn big_sign(v: &BigInt) -> i8 {
    if v.is_positive() {
        1
    } else if v.is_negative() {
        -1
    } else {
        0
    }
}

/// The exact sign of `robust::orient3d(a, b, c, d)` for any finite coordinates:
/// `robust` where it is exact, big integers elsewhere.
pub(crate) fn orient3d_sign(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> i8 {
    if in_range(a) && in_range(b) && in_range(c) && in_range(d) {
        let c3 = |v: DVec3| robust::Coord3D {
            x: v.x,
            y: v.y,
            z: v.z,
        };
        let v = robust::orient3d(c3(a), c3(b), c3(c), c3(d));
        return if v > 0.0 {
            1
        } else if v < 0.0 {
            -1
        } else {
            0
        };
    }
    big_sign(&Big::new(&[a, b, c, d]).orient3d(a, b, c, d))
}

/// `a + b` as a rounded sum and its exact error.
#[inline]
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bv = s - a;
    let av = s - bv;
    (s, (a - av) + (b - bv))
}

/// `a · b` as a rounded product and its exact error (fused multiply-add).
#[inline]
fn two_product(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// `e + b` (Grow-Expansion with zero elimination).
fn grow(e: &[f64], b: f64, out: &mut Vec<f64>) {
    out.clear();
    let mut q = b;
    for &x in e {
        let (s, h) = two_sum(q, x);
        if h != 0.0 {
            out.push(h);
        }
        q = s;
    }
    if q != 0.0 || out.is_empty() {
        out.push(q);
    }
}

/// `e + f`.
pub(crate) fn sum(e: &[f64], f: &[f64]) -> Vec<f64> {
    let mut acc = e.to_vec();
    let mut tmp = Vec::with_capacity(e.len() + f.len());
    for &x in f {
        grow(&acc, x, &mut tmp);
        std::mem::swap(&mut acc, &mut tmp);
    }
    acc
}

/// `e · b` (Scale-Expansion with zero elimination).
fn scale(e: &[f64], b: f64) -> Vec<f64> {
    let mut h = Vec::with_capacity(2 * e.len());
    let Some((&first, rest)) = e.split_first() else {
        return h;
    };
    let (mut q, lo) = two_product(first, b);
    if lo != 0.0 {
        h.push(lo);
    }
    for &x in rest {
        let (p1, p0) = two_product(x, b);
        let (s, lo) = two_sum(q, p0);
        if lo != 0.0 {
            h.push(lo);
        }
        let (s2, lo2) = two_sum(p1, s);
        if lo2 != 0.0 {
            h.push(lo2);
        }
        q = s2;
    }
    if q != 0.0 || h.is_empty() {
        h.push(q);
    }
    h
}

/// `e · f`.
pub(crate) fn product(e: &[f64], f: &[f64]) -> Vec<f64> {
    let mut acc = vec![0.0];
    for &x in f {
        acc = sum(&acc, &scale(e, x));
    }
    acc
}

/// `-e`.
pub(crate) fn negate(e: &[f64]) -> Vec<f64> {
    e.iter().map(|x| -x).collect()
}

/// The sign of an expansion: −1, 0 or 1.
pub(crate) fn sign(e: &[f64]) -> i32 {
    match e.iter().rev().find(|&&x| x != 0.0) {
        Some(&x) if x > 0.0 => 1,
        Some(_) => -1,
        None => 0,
    }
}

/// The exact value of `robust::orient3d(a, b, c, d)` (the determinant of the rows
/// `a − d`, `b − d`, `c − d`), as an expansion: the 4×4 determinant of the rows
/// `(p, 1)`, expanded into its 24 products of three coordinates.
pub(crate) fn orient3d_exact(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> Vec<f64> {
    let rows = [a.to_array(), b.to_array(), c.to_array(), d.to_array()];
    let mut acc = vec![0.0];
    let mut perm = [0usize, 1, 2, 3];
    // Heap's algorithm over the permutations of the columns, tracking the parity.
    let mut term = |p: &[usize; 4], odd: bool| {
        let mut factors = [0.0; 3];
        let mut n = 0;
        for (row, &col) in p.iter().enumerate() {
            if col < 3 {
                factors[n] = rows[row][col];
                n += 1;
            }
        }
        let (hi, lo) = two_product(factors[0], factors[1]);
        let mut t = scale(&[lo, hi], factors[2]);
        if odd {
            t = negate(&t);
        }
        acc = sum(&acc, &t);
    };
    let mut c_state = [0usize; 4];
    let mut odd = false;
    term(&perm, odd);
    let mut i = 1;
    while i < 4 {
        if c_state[i] < i {
            if i % 2 == 0 {
                perm.swap(0, i);
            } else {
                perm.swap(c_state[i], i);
            }
            odd = !odd;
            term(&perm, odd);
            c_state[i] += 1;
            i = 1;
        } else {
            c_state[i] = 0;
            i += 1;
        }
    }
    acc
}

/// `robust::orient3d(a, b, c, d)` evaluated in f64 with Shewchuk's formula, and a bound
/// on its absolute error.
#[inline]
pub(crate) fn orient3d_bounded(a: DVec3, b: DVec3, c: DVec3, d: DVec3) -> (f64, f64) {
    let (ad, bd, cd) = (a - d, b - d, c - d);
    let bc = bd.y * cd.z - bd.z * cd.y;
    let ca = cd.y * ad.z - cd.z * ad.y;
    let ab = ad.y * bd.z - ad.z * bd.y;
    let det = ad.x * bc + bd.x * ca + cd.x * ab;
    let perm = ad.x.abs() * ((bd.y * cd.z).abs() + (bd.z * cd.y).abs())
        + bd.x.abs() * ((cd.y * ad.z).abs() + (cd.z * ad.y).abs())
        + cd.x.abs() * ((ad.y * bd.z).abs() + (ad.z * bd.y).abs());
    // Shewchuk's O3DERRBOUND_A, rounded up generously.
    (det, 8.0e-16 * perm)
}

#[cfg(test)]
mod tests {
    use super::*;
    use robust::{orient3d, Coord3D};

    fn c(v: DVec3) -> Coord3D<f64> {
        Coord3D {
            x: v.x,
            y: v.y,
            z: v.z,
        }
    }

    #[test]
    fn exact_orient3d_has_robusts_sign() {
        let mut seed = 12345u64;
        let mut rnd = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        };
        for k in 0..2000 {
            let a = DVec3::new(rnd(), rnd(), rnd());
            let b = DVec3::new(rnd(), rnd(), rnd());
            let cc = DVec3::new(rnd(), rnd(), rnd());
            // Every other case: d on the plane up to rounding.
            let d = if k % 2 == 0 {
                DVec3::new(rnd(), rnd(), rnd())
            } else {
                a + (b - a) * 0.3 + (cc - a) * 0.45
            };
            let r = orient3d(c(a), c(b), c(cc), c(d));
            let e = orient3d_exact(a, b, cc, d);
            assert_eq!(sign(&e), r.partial_cmp(&0.0).unwrap() as i32, "case {k}");
            let (v, err) = orient3d_bounded(a, b, cc, d);
            if v.abs() > err {
                assert_eq!(v > 0.0, r > 0.0);
            }
        }
    }

    #[test]
    fn big_integers_agree_with_robust_where_it_is_exact_and_stay_exact_below() {
        let mut seed = 99u64;
        let mut rnd = || {
            seed = seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((seed >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        };
        for k in 0..500 {
            let p = [0; 4].map(|_| DVec3::new(rnd(), rnd(), rnd()));
            let d = if k % 2 == 0 {
                p[3]
            } else {
                p[0] + (p[1] - p[0]) * 0.3 + (p[2] - p[0]) * 0.45
            };
            let r = orient3d(c(p[0]), c(p[1]), c(p[2]), c(d));
            let big = Big::new(&[p[0], p[1], p[2], d]).orient3d(p[0], p[1], p[2], d);
            assert_eq!(big_sign(&big) as i32, r.partial_cmp(&0.0).unwrap() as i32);
            // Scaled by 2^-1000 every sign stays (robust underflows there).
            let s = 2f64.powi(-1000);
            let q = [p[0] * s, p[1] * s, p[2] * s, d * s];
            assert!(q.iter().all(|v| v.is_finite()));
            assert_eq!(
                orient3d_sign(q[0], q[1], q[2], q[3]) as i32,
                r.partial_cmp(&0.0).unwrap() as i32,
                "case {k}"
            );
        }
        // A point 2^-1074 off a plane through the origin, and one on it.
        let (a, b, cc) = (DVec3::X, DVec3::Y, DVec3::ZERO);
        let tiny = f64::from_bits(1);
        assert_eq!(orient3d_sign(a, b, cc, DVec3::new(0.5, 0.25, tiny)), -1);
        assert_eq!(orient3d_sign(a, b, cc, DVec3::new(0.5, 0.25, -tiny)), 1);
        assert_eq!(orient3d_sign(a, b, cc, DVec3::new(tiny, tiny, 0.0)), 0);
        assert_eq!(split(-tiny), (-1, -1074));
        assert_eq!(split(1.5), (3 << 51, -52));
    }

    #[test]
    fn products_and_sums_are_exact() {
        let a = [1e-30, 1.0];
        let b = [3.0];
        let p = product(&a, &b);
        assert_eq!(p.iter().sum::<f64>(), 3.0);
        assert_eq!(sign(&sum(&p, &negate(&p))), 0);
        let x = 1.0 + f64::EPSILON;
        let sq = product(&[x], &[x]);
        let target = sum(&[1.0, 2.0 * f64::EPSILON], &[f64::EPSILON * f64::EPSILON]);
        assert_eq!(sign(&sum(&sq, &negate(&target))), 0);
    }
}
