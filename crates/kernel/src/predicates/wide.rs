//! Fixed-capacity signed integers on the stack: the fast exact path of the predicates.
//!
//! [`Wide<N>`] is a sign and a magnitude of `N` 64-bit limbs (little-endian) with the
//! count of limbs in use, so that additions and schoolbook multiplications cost in
//! proportion to the actual sizes while nothing is allocated. Only the ring operations
//! and the sign are provided: the callers bound the size of every result before they
//! compute (see `predicates::fast`), and an operation whose result does not fit panics
//! (an index out of bounds) rather than wraps, so a wrong bound can never give a wrong
//! sign silently.
//!
//! It is written here rather than taken from a crate: `ethnum` stops at 256 bits, while
//! the degree-9 predicates need up to about 1600; `crypto-bigint`'s fixed-size types are
//! constant-time (every operation costs the full capacity, which is what the limb count
//! avoids here) and bring a large dependency for a hundred lines of arithmetic.

use std::cmp::Ordering;
use std::ops::{Add, Mul, Neg, Sub};

/// A signed integer `±|m|` with `|m| < 2^(64N)`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Wide<const N: usize> {
    /// Magnitude, little-endian; limbs at and above `len` are zero.
    mag: [u64; N],
    /// Number of limbs up to the highest non-zero one (0 for zero).
    len: usize,
    /// Sign (false for zero).
    neg: bool,
}

impl<const N: usize> Wide<N> {
    /// Zero.
    pub(crate) const ZERO: Wide<N> = Wide {
        mag: [0; N],
        len: 0,
        neg: false,
    };

    /// `±m · 2^shift`. Panics if it does not fit.
    #[inline]
    pub(crate) fn from_shifted(m: u64, shift: u32, neg: bool) -> Wide<N> {
        let mut w = Wide::ZERO;
        if m == 0 {
            return w;
        }
        let limb = (shift / 64) as usize;
        let bit = shift % 64;
        w.mag[limb] = m << bit;
        w.len = limb + 1;
        if bit != 0 && m >> (64 - bit) != 0 {
            w.mag[limb + 1] = m >> (64 - bit);
            w.len = limb + 2;
        }
        w.neg = neg;
        w
    }

    /// The sign as an ordering against zero.
    #[inline]
    pub(crate) fn signum(&self) -> Ordering {
        if self.len == 0 {
            Ordering::Equal
        } else if self.neg {
            Ordering::Less
        } else {
            Ordering::Greater
        }
    }

    /// Whether the value is zero.
    #[inline]
    pub(crate) fn is_zero(&self) -> bool {
        self.len == 0
    }

    /// Whether the value is negative.
    #[inline]
    pub(crate) fn is_negative(&self) -> bool {
        self.neg
    }

    /// The limbs of the magnitude in use, little-endian.
    #[inline]
    pub(crate) fn limbs(&self) -> &[u64] {
        &self.mag[..self.len]
    }

    /// Number of significant bits of the magnitude.
    #[cfg(test)]
    pub(crate) fn bits(&self) -> u32 {
        if self.len == 0 {
            0
        } else {
            64 * self.len as u32 - self.mag[self.len - 1].leading_zeros()
        }
    }

    /// `|a|` against `|b|`.
    #[inline]
    fn cmp_mag(a: &Wide<N>, b: &Wide<N>) -> Ordering {
        if a.len != b.len {
            return a.len.cmp(&b.len);
        }
        for i in (0..a.len).rev() {
            match a.mag[i].cmp(&b.mag[i]) {
                Ordering::Equal => {}
                o => return o,
            }
        }
        Ordering::Equal
    }

    /// `|a| + |b|` with the sign `neg`.
    #[inline]
    fn add_mag(a: &Wide<N>, b: &Wide<N>, neg: bool) -> Wide<N> {
        let mut r = Wide::ZERO;
        let n = a.len.max(b.len);
        let mut carry = false;
        for i in 0..n {
            let (s, c1) = a.mag[i].overflowing_add(b.mag[i]);
            let (s, c2) = s.overflowing_add(carry as u64);
            r.mag[i] = s;
            carry = c1 | c2;
        }
        r.len = n;
        if carry {
            r.mag[n] = 1;
            r.len = n + 1;
        }
        r.neg = neg && r.len != 0;
        r
    }

    /// `|a| − |b|` for `|a| ≥ |b|`, with the sign `neg`.
    #[inline]
    fn sub_mag(a: &Wide<N>, b: &Wide<N>, neg: bool) -> Wide<N> {
        let mut r = Wide::ZERO;
        let mut borrow = false;
        for i in 0..a.len {
            let (s, b1) = a.mag[i].overflowing_sub(b.mag[i]);
            let (s, b2) = s.overflowing_sub(borrow as u64);
            r.mag[i] = s;
            borrow = b1 | b2;
        }
        debug_assert!(!borrow);
        let mut n = a.len;
        while n > 0 && r.mag[n - 1] == 0 {
            n -= 1;
        }
        r.len = n;
        r.neg = neg && n != 0;
        r
    }

    /// `a + b` where `b` has sign `b_neg` (so that subtraction shares the code).
    #[inline]
    fn add_signed(a: &Wide<N>, b: &Wide<N>, b_neg: bool) -> Wide<N> {
        if a.neg == b_neg {
            return Wide::add_mag(a, b, a.neg);
        }
        match Wide::cmp_mag(a, b) {
            Ordering::Less => Wide::sub_mag(b, a, b_neg),
            _ => Wide::sub_mag(a, b, a.neg),
        }
    }
}

impl<const N: usize> Add for &Wide<N> {
    type Output = Wide<N>;
    #[inline]
    fn add(self, o: &Wide<N>) -> Wide<N> {
        Wide::add_signed(self, o, o.neg)
    }
}

impl<const N: usize> Sub for &Wide<N> {
    type Output = Wide<N>;
    #[inline]
    fn sub(self, o: &Wide<N>) -> Wide<N> {
        Wide::add_signed(self, o, !o.neg && o.len != 0)
    }
}

impl<const N: usize> Neg for Wide<N> {
    type Output = Wide<N>;
    #[inline]
    fn neg(mut self) -> Wide<N> {
        self.neg = !self.neg && self.len != 0;
        self
    }
}

impl<const N: usize> Mul for &Wide<N> {
    type Output = Wide<N>;
    /// Schoolbook product. A row or carry beyond the capacity can only be non-zero when
    /// the product itself does not fit, and then indexing panics.
    #[inline]
    fn mul(self, o: &Wide<N>) -> Wide<N> {
        let mut r = Wide::ZERO;
        if self.len == 0 || o.len == 0 {
            return r;
        }
        let (a, b) = if self.len >= o.len {
            (self, o)
        } else {
            (o, self)
        };
        let al = &a.mag[..a.len];
        for (j, &bj) in b.mag[..b.len].iter().enumerate() {
            let row = &mut r.mag[j..j + a.len];
            let mut carry: u64 = 0;
            for (rk, &ai) in row.iter_mut().zip(al) {
                let t = ai as u128 * bj as u128 + *rk as u128 + carry as u128;
                *rk = t as u64;
                carry = (t >> 64) as u64;
            }
            if carry != 0 {
                r.mag[a.len + j] = carry;
            }
        }
        let mut n = (a.len + b.len).min(N);
        while n > 0 && r.mag[n - 1] == 0 {
            n -= 1;
        }
        r.len = n;
        r.neg = self.neg != o.neg;
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    type W = Wide<4>;

    fn w(x: i128) -> W {
        let m = x.unsigned_abs();
        &W::from_shifted(m as u64, 0, x < 0) + &W::from_shifted((m >> 64) as u64, 64, x < 0)
    }

    fn to_i128(v: &W) -> i128 {
        assert!(v.len <= 2);
        let m = v.mag[0] as u128 | (v.mag[1] as u128) << 64;
        assert!(m <= 1 << 127);
        if v.neg {
            (m as i128).wrapping_neg()
        } else {
            m as i128
        }
    }

    #[test]
    fn ring_operations_match_i128() {
        let vals: [i128; 9] = [
            0,
            1,
            -1,
            u64::MAX as i128,
            -(u64::MAX as i128),
            1 << 64,
            (1 << 100) + 12345,
            -(1 << 90) - 7,
            i64::MIN as i128,
        ];
        for &x in &vals {
            for &y in &vals {
                let (a, b) = (w(x), w(y));
                assert_eq!(to_i128(&(&a + &b)), x + y, "{x} + {y}");
                assert_eq!(to_i128(&(&a - &b)), x - y, "{x} - {y}");
                if let Some(p) = x.checked_mul(y) {
                    assert_eq!(to_i128(&(&a * &b)), p, "{x} * {y}");
                }
                assert_eq!((&a - &a).signum(), Ordering::Equal);
                assert_eq!((-a).signum(), x.cmp(&0).reverse());
            }
        }
    }

    #[test]
    fn products_up_to_capacity() {
        // (2^128 − 1)² = 2^256 − 2^129 + 1 fits in four limbs exactly.
        let m = &w(-1) + &W::from_shifted(1, 128, false);
        let p = &m * &m;
        assert_eq!(p.bits(), 256);
        assert_eq!(p.limbs()[0], 1);
        assert_eq!(p.limbs()[1], 0);
        assert_eq!(p.limbs()[2], u64::MAX - 1);
        assert_eq!(p.limbs()[3], u64::MAX);
        assert!(!p.is_negative());
    }

    #[test]
    #[should_panic]
    fn overflow_panics() {
        let m = W::from_shifted(1, 128, false);
        let _ = &m * &m;
    }
}
