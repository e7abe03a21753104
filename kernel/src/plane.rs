//! Integer planes `a·x + b·y + c·z + d = 0` over grid coordinates.

use std::fmt;

use crate::grid::GridPoint;
use crate::traits::Side;

/// Exclusive bound on `|a|`, `|b|`, `|c|` of every plane the exact kernel uses.
pub const NORMAL_BOUND: i64 = 1 << 55;

/// Exclusive bound on `|d|` of every plane the exact kernel uses.
pub const OFFSET_BOUND: i128 = 1 << 83;

/// An oriented plane with integer coefficients: the points `x` (in grid coordinates) with
/// `a·x + b·y + c·z + d = 0`. Its front is where the left side is positive.
///
/// Guarantees (checked by every constructor): the normal is not zero,
/// `|a|, |b|, |c| <` [`NORMAL_BOUND`] `= 2^55` and `|d| <` [`OFFSET_BOUND`] `= 2^83`.
/// These bounds make every predicate of the kernel fit 256-bit integers.
///
/// `d` is stored as two 64-bit halves so that a plane takes 32 bytes with 8-byte
/// alignment (an `i128` field would force 48).
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Plane {
    a: i64,
    b: i64,
    c: i64,
    d_lo: u64,
    d_hi: i64,
}

impl fmt::Debug for Plane {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "Plane::new({}, {}, {}, {}).unwrap()",
            self.a,
            self.b,
            self.c,
            self.d()
        )
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
    pub(crate) fn raw(a: i64, b: i64, c: i64, d: i128) -> Plane {
        debug_assert!(a.abs() < NORMAL_BOUND && b.abs() < NORMAL_BOUND && c.abs() < NORMAL_BOUND);
        debug_assert!(d.abs() < OFFSET_BOUND);
        debug_assert!(a != 0 || b != 0 || c != 0);
        Plane {
            a,
            b,
            c,
            d_lo: d as u64,
            d_hi: (d >> 64) as i64,
        }
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
        [self.a, self.b, self.c]
    }

    /// The offset `d`.
    #[inline]
    pub fn d(&self) -> i128 {
        ((self.d_hi as i128) << 64) | self.d_lo as i128
    }

    /// All four coefficients.
    pub fn coefficients(&self) -> (i64, i64, i64, i128) {
        (self.a, self.b, self.c, self.d())
    }

    /// The same plane facing the other way.
    #[inline]
    pub fn flipped(&self) -> Plane {
        Plane::raw(-self.a, -self.b, -self.c, -self.d())
    }

    /// `a·x + b·y + c·z + d` at a grid point, exactly. Valid for coordinates of magnitude
    /// up to [`crate::grid::FAR_LIMIT`] (the value then stays below `2^119`).
    #[inline]
    pub fn eval(&self, p: &GridPoint) -> i128 {
        self.a as i128 * p.x as i128
            + self.b as i128 * p.y as i128
            + self.c as i128 * p.z as i128
            + self.d()
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
