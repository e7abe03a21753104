//! Closed intervals of reals with float ends, for float computations whose results must
//! hold for the exact values: every operation rounds its ends outward, so the exact
//! result of the same operation on any values inside the operands lies inside the result.
//! The rigorous error bounds of the kernel's plane-level filters, of the ordering's
//! piercing test and of the marks' cone filter are all computed in these.
//!
//! A round-to-nearest result lies within half a step (`ulp`) of the exact one, and a step
//! is at most 2⁻⁵² of the result's size (or the smallest subnormal below 2⁻¹⁰²²): moving
//! it by 2⁻⁵¹ of its size plus two smallest subnormals, rounded to nearest again, lands at
//! least one step past it, whatever its sign. Three float operations and no branch, where
//! `f64::next_up` branches on the sign (which a soup's coordinates change at random).
//! An infinite end stays infinite, and an infinite end times zero gives the whole line;
//! `inf − inf` gives NaN ends, and a NaN end makes every comparison fail, so nothing is
//! ever certified from it.

use std::cmp::Ordering;
use std::ops::{Add, Mul, Neg, Sub};

/// How far a rounded end is moved outward, relative to its size.
const WIDEN_REL: f64 = 1.0 / (1u64 << 51) as f64;
/// How far a rounded end is moved outward at least (two smallest subnormals).
const WIDEN_ABS: f64 = 2.0 * f64::from_bits(1);

/// A float at least the exact value that rounded to `x` (see the module's documentation);
/// an infinite `x` stays as it is (a select, not a branch).
#[inline(always)]
fn up(x: f64) -> f64 {
    let w = x + (x.abs() * WIDEN_REL + WIDEN_ABS);
    if x.is_finite() {
        w
    } else {
        x
    }
}

/// A float at most the exact value that rounded to `x`.
#[inline(always)]
fn down(x: f64) -> f64 {
    let w = x - (x.abs() * WIDEN_REL + WIDEN_ABS);
    if x.is_finite() {
        w
    } else {
        x
    }
}

/// The reals from `lo` to `hi`, known to hold an exact value.
///
/// Every constructor and operation rounds outward, so the interval holds the exact result
/// of the computation it stands for. Its sign is told only when every real in it shares
/// one ([`Interval::sign`]); callers fall back to exact arithmetic otherwise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interval {
    lo: f64,
    hi: f64,
}

impl Interval {
    /// Every real (what an overflowed computation knows).
    pub const EVERYTHING: Interval = Interval {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    /// The one real `x` (a float is a real exactly).
    #[inline]
    pub fn exactly(x: f64) -> Interval {
        Interval { lo: x, hi: x }
    }

    /// The reals within `err` of `x`, rounded outwards.
    #[inline]
    pub fn around(x: f64, err: f64) -> Interval {
        Interval {
            lo: down(x - err),
            hi: up(x + err),
        }
    }

    /// The lower end.
    #[inline]
    pub fn lo(self) -> f64 {
        self.lo
    }

    /// The upper end.
    #[inline]
    pub fn hi(self) -> f64 {
        self.hi
    }

    /// Whether every real in it is above zero.
    #[inline]
    pub fn positive(self) -> bool {
        self.lo > 0.0
    }

    /// Whether every real in it is below zero.
    #[inline]
    pub fn negative(self) -> bool {
        self.hi < 0.0
    }

    /// Whether every real in it is at least zero.
    #[inline]
    pub fn non_negative(self) -> bool {
        self.lo >= 0.0
    }

    /// Whether every real in it is at most zero.
    #[inline]
    pub fn non_positive(self) -> bool {
        self.hi <= 0.0
    }

    /// The sign of every value in the interval, when they all share one (`Equal` only for
    /// the point interval `[0, 0]`); `None` when the interval straddles zero or is not
    /// finite enough to say.
    #[inline]
    pub fn sign(self) -> Option<Ordering> {
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

    /// The absolute values of the reals of an interval that lies on one side of zero.
    fn abs_one_sided(self) -> Interval {
        if self.hi < 0.0 {
            -self
        } else {
            self
        }
    }

    /// `a / (a + b)` for every `a` in `self` and `b` in `other`, both positive (or both
    /// taken by absolute value from intervals on one side of zero): where along a segment
    /// its ends' distances `a` and `b` from a plane put the crossing. Increasing in `a`,
    /// decreasing in `b`, and within [0, 1].
    pub fn share_of(self, other: Interval) -> Interval {
        let (a, b) = (self.abs_one_sided(), other.abs_one_sided());
        let lo = down(a.lo / up(a.lo + b.hi));
        // The sum rounded down stays positive unless both are next to the smallest
        // subnormal; then 1 bounds the share.
        let den = down(a.hi + b.lo);
        let hi = if den > 0.0 { up(a.hi / den) } else { 1.0 };
        Interval {
            lo: lo.max(0.0),
            hi: hi.min(1.0),
        }
    }

    /// The dot product of two interval vectors.
    #[inline]
    pub fn dot(a: [Interval; 3], b: [Interval; 3]) -> Interval {
        a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
    }

    /// `x · d` for every point `x` within `err` of `c` in each coordinate, `d` a float
    /// vector (exact as it stands): the float dot product and a bound on its distance
    /// from every such value (`err·Σ|dᵢ|` for the point, at most `3u·Σ|cᵢdᵢ|` for three
    /// roundings, `4u` taken, and subnormal products' absolute errors), itself rounded up
    /// by a margin far above its own few roundings.
    pub fn dot_near(c: [f64; 3], err: f64, d: [f64; 3]) -> Interval {
        let (p0, p1, p2) = (c[0] * d[0], c[1] * d[1], c[2] * d[2]);
        let v = p0 + p1 + p2;
        let mag = p0.abs() + p1.abs() + p2.abs();
        let spread = d[0].abs() + d[1].abs() + d[2].abs();
        const U4: f64 = 4.0 / (1u64 << 53) as f64;
        let bound = (err * spread + U4 * mag) * (1.0 + U4) + 8.0 * f64::from_bits(1);
        Interval {
            lo: down(v - bound),
            hi: up(v + bound),
        }
    }
}

impl Add for Interval {
    type Output = Interval;
    #[inline]
    fn add(self, o: Interval) -> Interval {
        Interval {
            lo: down(self.lo + o.lo),
            hi: up(self.hi + o.hi),
        }
    }
}

impl Sub for Interval {
    type Output = Interval;
    #[inline]
    fn sub(self, o: Interval) -> Interval {
        Interval {
            lo: down(self.lo - o.hi),
            hi: up(self.hi - o.lo),
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
        let p = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        // An infinite end times zero: nothing is known.
        if p.iter().any(|x| x.is_nan()) {
            return Interval::EVERYTHING;
        }
        Interval {
            lo: down(p[0].min(p[1]).min(p[2]).min(p[3])),
            hi: up(p[0].max(p[1]).max(p[2]).max(p[3])),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational as R;

    fn exact(x: f64) -> R {
        R::from_float(x).expect("finite")
    }

    fn holds(i: Interval, x: &R) -> bool {
        exact(i.lo) <= *x && *x <= exact(i.hi)
    }

    /// SplitMix64, seeded as the ordering's generator is.
    struct SplitMix(u64);

    impl SplitMix {
        fn new(seed: u64) -> SplitMix {
            SplitMix(seed ^ 0x9e37_79b9_7f4a_7c15)
        }

        fn next_u64(&mut self) -> u64 {
            self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = self.0;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            z ^ (z >> 31)
        }
    }

    #[test]
    fn encloses_exact_results() {
        let a = Interval::exactly(0.1);
        let b = Interval::exactly(0.2);
        let s = a + b;
        // 0.1 + 0.2 as exact rationals of the two doubles lies strictly inside.
        assert!(s.lo < 0.30000000000000004 && s.hi > 0.3);
        let t = Interval::exactly(1e-320) * Interval::exactly(1e-10);
        assert!(t.lo <= 0.0 && t.hi > 0.0);
        let o = Interval::exactly(f64::MAX) + Interval::exactly(f64::MAX);
        assert_eq!(o.sign(), Some(Ordering::Greater));
        let n = Interval::exactly(f64::MAX) * Interval::exactly(2.0)
            - Interval::exactly(f64::MAX) * Interval::exactly(2.0);
        assert_eq!(n.sign(), None);
    }

    #[test]
    fn results_hold_the_exact_results_of_their_operands_ends() {
        let mut r = SplitMix::new(3);
        let mut u = || {
            let m = (r.next_u64() >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            m * [1e-9, 1.0, 3.0, 1e12][(r.next_u64() % 4) as usize]
        };
        for _ in 0..2000 {
            let (x, y, e) = (u(), u(), u().abs() * 1e-3);
            let (a, b) = (Interval::around(x, e), Interval::exactly(y));
            // The interval's ends and the middle stand for the reals inside.
            for xa in [a.lo, x, a.hi] {
                let (ea, eb) = (exact(xa), exact(y));
                assert!(holds(a + b, &(&ea + &eb)));
                assert!(holds(a - b, &(&ea - &eb)));
                assert!(holds(b - a, &(&eb - &ea)));
                assert!(holds(a * b, &(&ea * &eb)));
                assert!(holds(a * a, &(&ea * &ea)));
            }
            // Distances on either side of a plane: intervals clear of zero.
            let (dp, dq) = (x.abs().max(1e-6), y.abs().max(1e-6));
            let (p, q) = (
                Interval::around(dp, dp * 1e-3),
                Interval::around(-dq, dq * 0.5),
            );
            assert!(p.positive() && q.negative());
            for (xp, xq) in [(p.lo, q.hi), (p.hi, q.lo), (p.lo, q.lo), (p.hi, q.hi)] {
                let (ep, eq) = (exact(xp), -exact(xq));
                let t = &ep / (&ep + &eq);
                assert!(holds(p.share_of(q), &t), "{p:?} {q:?}");
            }
        }
    }

    #[test]
    fn a_dot_product_near_a_point_holds_the_exact_ones() {
        let mut r = SplitMix::new(9);
        let mut u = || {
            let m = (r.next_u64() >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            m * [1e-300, 1e-9, 1.0, 1e12][(r.next_u64() % 4) as usize]
        };
        for _ in 0..3000 {
            let (c, d, e) = ([u(), u(), u()], [u(), u(), u()], u().abs() * 1e-6);
            let got = Interval::dot_near(c, e, d);
            // The corners of the box stand for the points in it.
            for k in 0..8 {
                let x: [R; 3] = std::array::from_fn(|i| {
                    let s = if k >> i & 1 == 1 { e } else { -e };
                    exact(c[i]) + exact(s)
                });
                let v = &x[0] * exact(d[0]) + &x[1] * exact(d[1]) + &x[2] * exact(d[2]);
                assert!(holds(got, &v), "{c:?} {d:?} {e}");
            }
        }
    }

    #[test]
    fn infinite_ends_stay_infinite_and_unknown_products_are_the_whole_line() {
        let half_line = Interval {
            lo: f64::NEG_INFINITY,
            hi: 1.0,
        };
        let sum = half_line + Interval::exactly(2.0);
        assert_eq!(sum.lo, f64::NEG_INFINITY);
        assert!(sum.hi >= 3.0 && sum.hi.is_finite());
        let product = half_line * Interval::exactly(0.0);
        assert_eq!(product, Interval::EVERYTHING);
        assert!(!product.positive() && !product.negative());
    }

    #[test]
    fn signs_are_told_only_when_the_interval_is_clear_of_zero() {
        assert!(Interval::around(1.0, 0.5).positive());
        assert!(!Interval::around(1.0, 1.0).positive());
        assert!(Interval::around(-1.0, 0.5).negative());
        assert!(!Interval::exactly(0.0).positive() && !Interval::exactly(0.0).negative());
        assert!(!Interval::exactly(f64::NAN).positive());
        assert_eq!(Interval::exactly(0.0).sign(), Some(Ordering::Equal));
        assert_eq!(Interval::around(0.0, 1.0).sign(), None);
    }
}
