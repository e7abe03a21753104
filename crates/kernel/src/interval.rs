//! Closed intervals of f64 with outward rounding: the rigorous error bounds of the
//! kernel's plane coefficients and of the plane-level filters.
//!
//! Every operation rounds to nearest and then widens its result by one ulp outwards
//! (`next_down` / `next_up`), which encloses the exact result for every finite input,
//! subnormal results included. Overflow gives infinite bounds and `inf - inf` gives NaN;
//! [`Interval::sign`] answers `None` for both, so callers fall back to exact arithmetic.

use std::cmp::Ordering;
use std::ops::{Add, Mul, Neg, Sub};

/// A closed interval `[lo, hi]` known to contain an exact value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Interval {
    pub(crate) lo: f64,
    pub(crate) hi: f64,
}

impl Interval {
    /// The exact value `x` (a point interval).
    #[inline]
    pub(crate) fn point(x: f64) -> Interval {
        Interval { lo: x, hi: x }
    }

    /// The interval `[mid - rad, mid + rad]`, rounded outwards.
    #[inline]
    pub(crate) fn around(mid: f64, rad: f64) -> Interval {
        if rad == 0.0 {
            return Interval::point(mid);
        }
        Interval {
            lo: (mid - rad).next_down(),
            hi: (mid + rad).next_up(),
        }
    }

    /// The sign of every value in the interval, when they all share one (`Equal` only for
    /// the point interval `[0, 0]`); `None` when the interval straddles zero or is not
    /// finite enough to say.
    #[inline]
    pub(crate) fn sign(&self) -> Option<Ordering> {
        if self.lo > 0.0 {
            Some(Ordering::Greater)
        } else if self.hi < 0.0 {
            Some(Ordering::Less)
        } else if self.lo == 0.0 && self.hi == 0.0 {
            Some(Ordering::Equal)
        } else {
            None
        }
    }
}

#[inline]
fn hull(v: [f64; 4]) -> Interval {
    let mut lo = v[0];
    let mut hi = v[0];
    for &x in &v[1..] {
        // NaN propagates through `min`/`max` as the other value; keep it visible.
        if x.is_nan() {
            return Interval {
                lo: f64::NAN,
                hi: f64::NAN,
            };
        }
        lo = lo.min(x);
        hi = hi.max(x);
    }
    if lo.is_nan() {
        return Interval { lo, hi };
    }
    Interval {
        lo: lo.next_down(),
        hi: hi.next_up(),
    }
}

impl Add for Interval {
    type Output = Interval;
    #[inline]
    fn add(self, o: Interval) -> Interval {
        Interval {
            lo: (self.lo + o.lo).next_down(),
            hi: (self.hi + o.hi).next_up(),
        }
    }
}

impl Sub for Interval {
    type Output = Interval;
    #[inline]
    fn sub(self, o: Interval) -> Interval {
        Interval {
            lo: (self.lo - o.hi).next_down(),
            hi: (self.hi - o.lo).next_up(),
        }
    }
}

impl Neg for Interval {
    type Output = Interval;
    #[inline]
    fn neg(self) -> Interval {
        Interval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

impl Mul for Interval {
    type Output = Interval;
    #[inline]
    fn mul(self, o: Interval) -> Interval {
        if self.lo == self.hi && o.lo == o.hi {
            let p = self.lo * o.lo;
            return Interval {
                lo: p.next_down(),
                hi: p.next_up(),
            };
        }
        hull([
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ])
    }
}

/// The dot product of two interval vectors.
pub(crate) fn dot(a: [Interval; 3], b: [Interval; 3]) -> Interval {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn encloses_exact_results() {
        let a = Interval::point(0.1);
        let b = Interval::point(0.2);
        let s = a + b;
        // 0.1 + 0.2 as exact rationals of the two doubles lies strictly inside.
        assert!(s.lo < 0.30000000000000004 && s.hi > 0.3);
        let t = Interval::point(1e-320) * Interval::point(1e-10);
        assert!(t.lo <= 0.0 && t.hi > 0.0);
        let o = Interval::point(f64::MAX) + Interval::point(f64::MAX);
        assert_eq!(o.sign(), Some(Ordering::Greater));
        let n = Interval::point(f64::MAX) * Interval::point(2.0)
            - Interval::point(f64::MAX) * Interval::point(2.0);
        assert_eq!(n.sign(), None);
    }
}
