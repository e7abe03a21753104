//! Integer planes `a·x + b·y + c·z + d = 0` over grid coordinates.

use std::fmt;

use crate::grid::GridPoint;
use crate::traits::Side;

/// Exclusive bound on `|a|`, `|b|`, `|c|` of every plane the exact kernel uses.
pub const NORMAL_BOUND: i64 = 1 << 55;

/// Exclusive bound on `|d|` of every plane the exact kernel uses.
pub const OFFSET_BOUND: i128 = 1 << 83;

/// The integer coefficients of a plane, stored compactly in 32 bytes (8-byte aligned):
/// `a`, `b`, `c` need 56 bits each and `d` 84 bits, 252 bits in all. Word 0 holds the low
/// 64 bits of `d`; words 1 to 3 hold `a`, `b`, `c` in their low 56 bits and one byte each
/// of the high 24 bits of `d` (sign-extended from word 3). This is how polygons store
/// their edge and support planes; [`Plane`] adds the f64 roundings the filter uses.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub(crate) struct Coeffs {
    w: [u64; 4],
}

impl fmt::Debug for Coeffs {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.plane().fmt(f)
    }
}

const LOW56: u64 = (1 << 56) - 1;

impl Coeffs {
    #[inline]
    pub(crate) fn new(a: i64, b: i64, c: i64, d: i128) -> Coeffs {
        debug_assert!(a.abs() < NORMAL_BOUND && b.abs() < NORMAL_BOUND && c.abs() < NORMAL_BOUND);
        debug_assert!(d.abs() < OFFSET_BOUND);
        debug_assert!(a != 0 || b != 0 || c != 0);
        let hi = (d >> 64) as i64 as u64;
        Coeffs {
            w: [
                d as u64,
                (a as u64 & LOW56) | ((hi & 0xff) << 56),
                (b as u64 & LOW56) | (((hi >> 8) & 0xff) << 56),
                (c as u64 & LOW56) | (((hi >> 16) & 0xff) << 56),
            ],
        }
    }

    #[inline]
    pub(crate) fn normal(&self) -> [i64; 3] {
        let unpack = |w: u64| ((w << 8) as i64) >> 8;
        [unpack(self.w[1]), unpack(self.w[2]), unpack(self.w[3])]
    }

    /// Bits 64 and up of `d`, sign-extended (magnitude below `2^19`).
    #[inline]
    fn d_hi(&self) -> i64 {
        (((self.w[3] as i64) >> 56) << 16)
            | (((self.w[2] >> 56) << 8) as i64)
            | ((self.w[1] >> 56) as i64)
    }

    #[inline]
    pub(crate) fn d(&self) -> i128 {
        ((self.d_hi() as i128) << 64) | self.w[0] as i128
    }

    /// `d` rounded to f64 without a 128-bit conversion: one rounding when `|d| < 2^63`,
    /// otherwise relative error at most `3·2^-53` (the high half, below `2^19`, converts
    /// exactly; the low half and the sum round once each).
    #[inline]
    pub(crate) fn d_f64(&self) -> f64 {
        let lo = self.w[0] as i64;
        let hi = self.d_hi();
        if (lo >> 63) == hi {
            lo as f64
        } else {
            hi as f64 * 18_446_744_073_709_551_616.0 + self.w[0] as f64
        }
    }

    #[inline]
    pub(crate) fn flipped(&self) -> Coeffs {
        let [a, b, c] = self.normal();
        Coeffs::new(-a, -b, -c, -self.d())
    }

    /// The full plane (with its f64 roundings).
    #[inline]
    pub(crate) fn plane(&self) -> Plane {
        let [a, b, c] = self.normal();
        Plane {
            k: *self,
            f: [a as f64, b as f64, c as f64, self.d_f64()],
        }
    }
}

/// An oriented plane with integer coefficients: the points `x` (in grid coordinates) with
/// `a·x + b·y + c·z + d = 0`. Its front is where the left side is positive.
///
/// Guarantees (checked by every constructor): the normal is not zero,
/// `|a|, |b|, |c| <` [`NORMAL_BOUND`] `= 2^55` and `|d| <` [`OFFSET_BOUND`] `= 2^83`.
/// These bounds make every predicate of the kernel fit 256-bit integers.
///
/// The plane also carries its coefficients rounded to f64 (`a`, `b`, `c` with one
/// rounding, `d` with relative error at most `3·2^-53`) for the floating-point filter, so
/// classifying many polygons against one plane converts nothing. Equality and hashing
/// look at the integer coefficients only.
#[derive(Clone, Copy)]
pub struct Plane {
    k: Coeffs,
    f: [f64; 4],
}

impl PartialEq for Plane {
    fn eq(&self, other: &Plane) -> bool {
        self.k == other.k
    }
}

impl Eq for Plane {}

impl std::hash::Hash for Plane {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        self.k.hash(state);
    }
}

impl fmt::Debug for Plane {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [a, b, c] = self.normal();
        write!(f, "Plane::new({a}, {b}, {c}, {}).unwrap()", self.d())
    }
}

impl Plane {
    /// A plane from its coefficients, or `None` if the normal is zero or a coefficient is
    /// out of bounds.
    pub fn new(a: i64, b: i64, c: i64, d: i128) -> Option<Plane> {
        let ok_n = |v: i64| v > -NORMAL_BOUND && v < NORMAL_BOUND;
        if !(ok_n(a) && ok_n(b) && ok_n(c)) || (a == 0 && b == 0 && c == 0) {
            return None;
        }
        if !(d > -OFFSET_BOUND && d < OFFSET_BOUND) {
            return None;
        }
        Some(Plane::raw(a, b, c, d))
    }

    /// Builds a plane whose bounds the caller has established (checked in debug builds).
    #[inline]
    pub(crate) fn raw(a: i64, b: i64, c: i64, d: i128) -> Plane {
        Coeffs::new(a, b, c, d).plane()
    }

    /// The compact integer coefficients.
    #[inline]
    pub(crate) fn coeffs(&self) -> Coeffs {
        self.k
    }

    /// The coefficients rounded to f64 `[a, b, c, d]`.
    #[inline]
    pub fn approx(&self) -> [f64; 4] {
        self.f
    }

    /// The plane through three grid points, oriented so that `p`, `q`, `r` run
    /// counter-clockwise seen from its front: normal `(q - p) × (r - p)`.
    ///
    /// `None` if the points are collinear or their coordinates exceed the grid bounds
    /// (magnitude above `2^25 + 1` for the default 26 bits).
    pub fn through(p: GridPoint, q: GridPoint, r: GridPoint) -> Option<Plane> {
        let lim = (1i64 << 25) + 1;
        for g in [p, q, r] {
            if g.to_array().iter().any(|v| v.abs() > lim) {
                return None;
            }
        }
        let u = [q.x - p.x, q.y - p.y, q.z - p.z];
        let v = [r.x - p.x, r.y - p.y, r.z - p.z];
        let n = [
            u[1] * v[2] - u[2] * v[1],
            u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0],
        ];
        if n == [0, 0, 0] {
            return None;
        }
        let d =
            -(n[0] as i128 * p.x as i128 + n[1] as i128 * p.y as i128 + n[2] as i128 * p.z as i128);
        Plane::new(n[0], n[1], n[2], d)
    }

    /// The normal `(a, b, c)`.
    #[inline]
    pub fn normal(&self) -> [i64; 3] {
        self.k.normal()
    }

    /// The offset `d`.
    #[inline]
    pub fn d(&self) -> i128 {
        self.k.d()
    }

    /// All four coefficients.
    pub fn coefficients(&self) -> (i64, i64, i64, i128) {
        let [a, b, c] = self.normal();
        (a, b, c, self.d())
    }

    /// The same plane facing the other way.
    #[inline]
    pub fn flipped(&self) -> Plane {
        Plane {
            k: self.k.flipped(),
            f: self.f.map(|v| -v),
        }
    }

    /// `a·x + b·y + c·z + d` at a grid point, exactly. Valid for coordinates of magnitude
    /// up to [`crate::grid::FAR_LIMIT`] (the value then stays below `2^119`).
    #[inline]
    pub fn eval(&self, p: &GridPoint) -> i128 {
        let [a, b, c] = self.normal();
        a as i128 * p.x as i128 + b as i128 * p.y as i128 + c as i128 * p.z as i128 + self.d()
    }

    /// The exact side of a grid point (coordinates up to [`crate::grid::FAR_LIMIT`]).
    #[inline]
    pub fn side_of(&self, p: &GridPoint) -> Side {
        side_of_sign(self.eval(p).signum() as i32)
    }

    /// The axis (0 = x, 1 = y, 2 = z) of the normal's largest component (lowest index on
    /// ties).
    pub fn dominant_axis(&self) -> usize {
        dominant_axis(self.normal())
    }

    /// Whether the normals of two planes point into the same half-space (their dot product
    /// is positive), exactly.
    pub fn same_facing(&self, other: &Plane) -> bool {
        let n = self.normal();
        let m = other.normal();
        let dot: i128 = (0..3).map(|i| n[i] as i128 * m[i] as i128).sum();
        dot > 0
    }
}

/// The side for the sign of a plane value.
#[inline]
pub(crate) fn side_of_sign(s: i32) -> Side {
    match s {
        1.. => Side::Front,
        0 => Side::On,
        _ => Side::Back,
    }
}

/// The axis of the largest magnitude (lowest index on ties).
pub(crate) fn dominant_axis<T: Into<i128> + Copy>(n: [T; 3]) -> usize {
    let m = n.map(|v| v.into().unsigned_abs());
    if m[0] >= m[1] && m[0] >= m[2] {
        0
    } else if m[1] >= m[2] {
        1
    } else {
        2
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn d_round_trips_through_halves() {
        for d in [
            0i128,
            1,
            -1,
            (1 << 82) - 1,
            -(1 << 82) + 1,
            123_456_789_012_345_678_901,
        ] {
            assert_eq!(Plane::new(1, 0, 0, d).unwrap().d(), d);
        }
    }

    #[test]
    fn bounds_are_enforced() {
        assert!(Plane::new(0, 0, 0, 1).is_none());
        assert!(Plane::new(NORMAL_BOUND, 0, 0, 1).is_none());
        assert!(Plane::new(1, 0, 0, OFFSET_BOUND).is_none());
        assert!(Plane::new(NORMAL_BOUND - 1, 0, 0, OFFSET_BOUND - 1).is_some());
    }

    #[test]
    fn through_orients_counter_clockwise() {
        let p = Plane::through(
            GridPoint::new(0, 0, 0),
            GridPoint::new(1, 0, 0),
            GridPoint::new(0, 1, 0),
        )
        .unwrap();
        assert_eq!(p.side_of(&GridPoint::new(0, 0, 5)), Side::Front);
        assert_eq!(p.side_of(&GridPoint::new(7, -3, 0)), Side::On);
        assert_eq!(p.flipped().side_of(&GridPoint::new(0, 0, 5)), Side::Back);
    }
}
