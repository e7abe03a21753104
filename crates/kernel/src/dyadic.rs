//! Exact dyadic numbers `m · 2^e` (big-integer mantissa, machine exponent): the exact
//! fallback of every predicate.
//!
//! Every finite f64 is a dyadic number, and sums, differences and products of dyadic
//! numbers are dyadic, so every predicate of the kernel (a polynomial in input
//! coordinates) is evaluated exactly, for any finite input, with no range limit. This
//! path runs only when the floating-point filters cannot decide, so it favours
//! simplicity over speed (a few microseconds per predicate). It is written here rather
//! than taken from a crate because what it needs (exact ring operations on f64 values
//! and a sign) is about a hundred lines on top of `num-bigint`, while rational crates
//! would normalise by gcd on every operation. The type is exported so that exact
//! evaluations outside the kernel (the hiding of lines and points) use the same numbers,
//! through [`crate::ExactAffine`] and [`crate::Quotient`].

use std::cmp::Ordering;
use std::ops::{Add, Mul, Neg, Sub};

use num_bigint::{BigInt, Sign};
use num_traits::{ToPrimitive, Zero};

/// An exact number `mantissa · 2^exponent`.
#[derive(Debug, Clone)]
pub struct Dyadic {
    m: BigInt,
    e: i64,
}

impl Dyadic {
    /// Zero.
    pub fn zero() -> Dyadic {
        Dyadic {
            m: BigInt::zero(),
            e: 0,
        }
    }

    /// The exact value of a finite f64 (callers check finiteness; NaN and infinities map
    /// to zero).
    pub fn from_f64(x: f64) -> Dyadic {
        if x == 0.0 || !x.is_finite() {
            return Dyadic::zero();
        }
        let bits = x.to_bits();
        let neg = bits >> 63 == 1;
        let exp = ((bits >> 52) & 0x7ff) as i64;
        let frac = bits & ((1u64 << 52) - 1);
        let (mant, e) = if exp == 0 {
            (frac, -1074)
        } else {
            (frac | (1u64 << 52), exp - 1075)
        };
        // Strip trailing zeros so that exponents stay small and alignment cheap.
        let tz = mant.trailing_zeros();
        let m = BigInt::from(mant >> tz);
        Dyadic {
            m: if neg { -m } else { m },
            e: e + tz as i64,
        }
    }

    /// A point's coordinates as exact numbers (each f64 exactly).
    pub fn point3(p: [f64; 3]) -> [Dyadic; 3] {
        point3(p)
    }

    /// `±m · 2^e` for a magnitude `m` given as little-endian 64-bit limbs.
    pub(crate) fn from_limbs(neg: bool, limbs: &[u64], e: i64) -> Dyadic {
        let digits: Vec<u32> = limbs
            .iter()
            .flat_map(|&l| [l as u32, (l >> 32) as u32])
            .collect();
        let sign = if neg { Sign::Minus } else { Sign::Plus };
        Dyadic {
            m: BigInt::from_slice(sign, &digits),
            e,
        }
    }

    /// The sign as an ordering against zero.
    pub fn signum(&self) -> Ordering {
        match self.m.sign() {
            Sign::Minus => Ordering::Less,
            Sign::NoSign => Ordering::Equal,
            Sign::Plus => Ordering::Greater,
        }
    }

    /// The value as `(mantissa, exponent)`: it equals `mantissa · 2^exponent`.
    pub(crate) fn parts(&self) -> (&BigInt, i64) {
        (&self.m, self.e)
    }

    /// Whether the value is exactly zero.
    pub fn is_zero(&self) -> bool {
        self.m.is_zero()
    }

    /// The value rounded to a nearby f64 (within a few ulps; infinite when out of range).
    pub fn to_f64(&self) -> f64 {
        if self.m.is_zero() {
            return 0.0;
        }
        // Keep the top 64 bits of the mantissa, then scale in two steps to avoid
        // intermediate overflow or underflow.
        let bits = self.m.bits() as i64;
        let shift = (bits - 64).max(0);
        let top = (&self.m >> shift as usize).to_f64().unwrap_or(0.0);
        let e = self.e + shift;
        let half = e / 2;
        top * 2f64.powi(half.clamp(-2000, 2000) as i32)
            * 2f64.powi((e - half).clamp(-2000, 2000) as i32)
    }

    /// Both mantissas aligned to the smaller exponent.
    fn aligned(a: &Dyadic, b: &Dyadic) -> (BigInt, BigInt, i64) {
        match a.e.cmp(&b.e) {
            Ordering::Equal => (a.m.clone(), b.m.clone(), a.e),
            Ordering::Greater => ((&a.m) << ((a.e - b.e) as usize), b.m.clone(), b.e),
            Ordering::Less => (a.m.clone(), (&b.m) << ((b.e - a.e) as usize), a.e),
        }
    }
}

/// Equality of values (representations may differ by trailing zeros).
impl PartialEq for Dyadic {
    fn eq(&self, other: &Dyadic) -> bool {
        (self - other).is_zero()
    }
}

impl Add for &Dyadic {
    type Output = Dyadic;
    fn add(self, o: &Dyadic) -> Dyadic {
        if self.m.is_zero() {
            return o.clone();
        }
        if o.m.is_zero() {
            return self.clone();
        }
        let (a, b, e) = Dyadic::aligned(self, o);
        Dyadic { m: a + b, e }
    }
}

impl Sub for &Dyadic {
    type Output = Dyadic;
    fn sub(self, o: &Dyadic) -> Dyadic {
        if o.m.is_zero() {
            return self.clone();
        }
        if self.m.is_zero() {
            return -o;
        }
        let (a, b, e) = Dyadic::aligned(self, o);
        Dyadic { m: a - b, e }
    }
}

impl Mul for &Dyadic {
    type Output = Dyadic;
    fn mul(self, o: &Dyadic) -> Dyadic {
        if self.m.is_zero() || o.m.is_zero() {
            return Dyadic::zero();
        }
        Dyadic {
            m: &self.m * &o.m,
            e: self.e + o.e,
        }
    }
}

impl Neg for &Dyadic {
    type Output = Dyadic;
    fn neg(self) -> Dyadic {
        Dyadic {
            m: -&self.m,
            e: self.e,
        }
    }
}

/// `a·b + c·d + e·f`, exactly.
pub(crate) fn dot3(a: &[Dyadic; 3], b: &[Dyadic; 3]) -> Dyadic {
    let s = &(&a[0] * &b[0]) + &(&a[1] * &b[1]);
    &s + &(&a[2] * &b[2])
}

/// The cross product `a × b`, exactly.
pub(crate) fn cross3(a: &[Dyadic; 3], b: &[Dyadic; 3]) -> [Dyadic; 3] {
    [
        &(&a[1] * &b[2]) - &(&a[2] * &b[1]),
        &(&a[2] * &b[0]) - &(&a[0] * &b[2]),
        &(&a[0] * &b[1]) - &(&a[1] * &b[0]),
    ]
}

/// A point's coordinates as exact dyadic numbers.
pub(crate) fn point3(p: [f64; 3]) -> [Dyadic; 3] {
    p.map(Dyadic::from_f64)
}

/// `a / b` rounded to a nearby f64 (within a few ulps) for `b ≠ 0`.
pub(crate) fn quotient_f64(a: &Dyadic, b: &Dyadic) -> f64 {
    if a.is_zero() {
        return 0.0;
    }
    // Scale the numerator so that the integer quotient keeps at least 64 bits.
    let shift = (b.m.bits() as i64 - a.m.bits() as i64 + 66).max(0);
    let q = (&a.m << shift as usize) / &b.m;
    Dyadic {
        m: q,
        e: a.e - b.e - shift,
    }
    .to_f64()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trips_and_signs() {
        for x in [
            0.0,
            1.0,
            -1.5,
            1e-310,
            -1e300,
            0.1,
            f64::MAX,
            -f64::MIN_POSITIVE,
        ] {
            let d = Dyadic::from_f64(x);
            assert_eq!(d.to_f64(), x, "{x}");
            assert_eq!(d.signum(), x.partial_cmp(&0.0).unwrap());
        }
    }

    #[test]
    fn arithmetic_is_exact_where_f64_is_not() {
        let a = Dyadic::from_f64(1e300);
        let b = Dyadic::from_f64(1e-300);
        let s = &(&a + &b) - &a;
        assert_eq!(s, b);
        let p = &Dyadic::from_f64(0.1) * &Dyadic::from_f64(0.1);
        // 0.1·0.1 is not 0.01 in f64, and the exact product is neither.
        assert_ne!(&p - &Dyadic::from_f64(0.1 * 0.1), Dyadic::zero());
        assert_eq!(&p - &p, Dyadic::zero());
    }
}
