//! Exact quotients of two dyadic numbers (parameters along a segment), compared by
//! cross-multiplication and never reduced (no gcd), rounded only when a position is
//! output.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;

use crate::dyadic::{quotient_f64, Dyadic};

/// The exact numbers of a quotient.
type Q = Dyadic;

/// The exact quotient `num / den` of two [`Dyadic`] numbers, with `den > 0` (an
/// invariant of the constructors): a parameter `u` along a segment, such as the root of
/// an affine function between the segment's ends. Ordered exactly; rounded once, to the
/// nearest f64, only by [`Quotient::lerp`].
#[derive(Debug, Clone)]
pub struct Quotient {
    num: Q,
    den: Q,
}

/// The exact value `mantissa · 2^exponent` as a rational.
fn rational(x: &Q) -> BigRational {
    let (m, e) = x.parts();
    let two = BigInt::from(2);
    if e >= 0 {
        BigRational::from_integer(m * two.pow(e as u32))
    } else {
        BigRational::new(m.clone(), two.pow(e.unsigned_abs() as u32))
    }
}

/// `n / d` (`d > 0`) rounded to the nearest f64, ties to even, as the rational's own
/// conversion rounds (`+0` for zero, `−0` for a negative value that rounds to zero).
/// From an approximation within a few ulps, the result is certified by exact
/// comparisons with the midpoints between it and its neighbours (dyadic numbers, so no
/// division and no gcd), moving one step while the quotient lies beyond one.
fn nearest(n: &Q, d: &Q) -> f64 {
    if n.is_zero() {
        return 0.0;
    }
    let mut c = quotient_f64(n, d);
    if !c.is_finite() {
        return (rational(n) / rational(d)).to_f64().unwrap_or(f64::NAN);
    }
    let half = Q::from_f64(0.5);
    // The sign of n/d − (x + y)/2, for finite x and y.
    let beyond = |x: f64, y: f64| {
        let m = &(&Q::from_f64(x) + &Q::from_f64(y)) * &half;
        (n - &(&m * d)).signum()
    };
    let even = |x: f64, y: f64| if x.to_bits() & 1 == 0 { x } else { y };
    let r = loop {
        let (down, up) = (c.next_down(), c.next_up());
        if up.is_finite() {
            match beyond(c, up) {
                Ordering::Greater => {
                    c = up;
                    continue;
                }
                Ordering::Equal => break even(c, up),
                Ordering::Less => {}
            }
        }
        if down.is_finite() {
            match beyond(down, c) {
                Ordering::Less => {
                    c = down;
                    continue;
                }
                Ordering::Equal => break even(down, c),
                Ordering::Greater => {}
            }
        }
        break c;
    };
    match (r == 0.0, n.signum()) {
        (true, Ordering::Less) => -0.0,
        (true, _) => 0.0,
        _ => r,
    }
}

impl Quotient {
    /// `0`.
    pub fn zero() -> Quotient {
        Quotient {
            num: Q::zero(),
            den: Q::from_f64(1.0),
        }
    }

    /// `1`.
    pub fn one() -> Quotient {
        Quotient {
            num: Q::from_f64(1.0),
            den: Q::from_f64(1.0),
        }
    }

    /// The root `u` of `fa + u·(fb − fa)` for `fa ≠ fb`, with the sign of the slope
    /// `fb − fa` (`Greater`: the function grows with `u`).
    pub fn root(fa: &Q, fb: &Q) -> (Quotient, Ordering) {
        let slope = fb - fa;
        match slope.signum() {
            Ordering::Less => (
                Quotient {
                    num: fa.clone(),
                    den: -&slope,
                },
                Ordering::Less,
            ),
            s => (
                Quotient {
                    num: -fa,
                    den: slope,
                },
                s,
            ),
        }
    }

    /// Whether this is exactly `0`.
    pub fn is_zero(&self) -> bool {
        self.num.is_zero()
    }

    /// Whether this is exactly `1`.
    pub fn is_one(&self) -> bool {
        self.num == self.den
    }

    /// The exact value as a rational (for references and tests).
    pub fn to_rational(&self) -> BigRational {
        rational(&self.num) / rational(&self.den)
    }

    /// Coordinate `i` of the exact point `A + u(B − A)`, rounded once to the nearest f64
    /// (a zero is `+0`).
    pub fn lerp(&self, a: f64, b: f64) -> f64 {
        if self.is_zero() {
            return a + 0.0;
        }
        if self.is_one() {
            return b + 0.0;
        }
        let (qa, qb) = (Q::from_f64(a), Q::from_f64(b));
        // (a·den + num·(b − a)) / den
        let n = &(&qa * &self.den) + &(&self.num * &(&qb - &qa));
        nearest(&n, &self.den)
    }
}

impl Ord for Quotient {
    fn cmp(&self, other: &Quotient) -> Ordering {
        // Both denominators are positive.
        (&(&self.num * &other.den) - &(&other.num * &self.den)).signum()
    }
}

impl PartialOrd for Quotient {
    fn partial_cmp(&self, other: &Quotient) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl PartialEq for Quotient {
    fn eq(&self, other: &Quotient) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Quotient {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_compare_and_round_as_rationals() {
        let q = Q::from_f64;
        let (r, s) = Quotient::root(&q(1.0), &q(-2.0));
        assert_eq!(s, Ordering::Less);
        assert_eq!(r.to_rational(), BigRational::new(1.into(), 3.into()));
        let (t, s) = Quotient::root(&q(-0.5), &q(1.0));
        assert_eq!(s, Ordering::Greater);
        assert_eq!(t.to_rational(), BigRational::new(1.into(), 3.into()));
        assert_eq!(r, t);
        assert!(Quotient::zero() < r && r < Quotient::one());
        assert!(Quotient::one().is_one() && !r.is_one());
        // One third of the way from 0 to 1, rounded once: the f64 nearest to 1/3.
        assert_eq!(r.lerp(0.0, 1.0), 1.0 / 3.0);
        assert_eq!(Quotient::zero().lerp(-0.0, 1.0).to_bits(), 0.0f64.to_bits());
        let (tiny, _) = Quotient::root(&q(1e-300), &q(-1e300));
        assert!(Quotient::zero() < tiny);
        assert_eq!(
            tiny.to_rational(),
            rational(&q(1e-300)) / (rational(&q(1e-300)) + rational(&q(1e300)))
        );
    }

    /// The certified rounding equals the rational's own conversion, bit for bit, on
    /// random quotients of every size, ties and values rounding to zero included.
    #[test]
    fn nearest_rounds_as_the_rational_conversion() {
        let q = Q::from_f64;
        let mut x: u64 = 0x2545_f491_4f6c_dd1d;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            x
        };
        let draw = |next: &mut dyn FnMut() -> u64| {
            let bits = next();
            let v = f64::from_bits(bits);
            match bits % 4 {
                0 if v.is_finite() => v,
                1 => (bits >> 11) as f64,
                2 => ((bits >> 40) as f64 + 0.5) * if bits & 1 == 0 { 1.0 } else { -1.0 },
                _ => f64::from_bits(bits >> 12) * if bits & 2 == 0 { 1.0 } else { -1.0 },
            }
        };
        let mut checked = 0;
        for _ in 0..20_000 {
            let (a, b, c) = (draw(&mut next), draw(&mut next), draw(&mut next));
            // n = a·b + c, d = |b| (or 1): exact dyadic values of every size.
            let n = &(&q(a) * &q(b)) + &q(c);
            let d = if b == 0.0 { q(1.0) } else { q(b.abs()) };
            let want = (rational(&n) / rational(&d)).to_f64().unwrap();
            if !want.is_finite() {
                continue;
            }
            let got = nearest(&n, &d);
            assert_eq!(
                got.to_bits(),
                want.to_bits(),
                "{a:e} {b:e} {c:e}: {got:e} {want:e}"
            );
            checked += 1;
        }
        assert!(checked > 10_000, "{checked}");
        // Exact ties: 1/2 ulp above 1 rounds to 1 (even), 3/2 ulp above to 1 + 2 ulp.
        let ulp = f64::EPSILON;
        for (k, want) in [(1.0, 1.0), (3.0, 1.0 + 2.0 * ulp)] {
            let n = &q(1.0) + &(&q(k) * &q(ulp / 2.0));
            assert_eq!(nearest(&n, &q(1.0)), want);
        }
        assert_eq!(
            nearest(&q(-1e-300), &q(1e300)).to_bits(),
            (-0.0f64).to_bits()
        );
    }
}
