//! Exact parameters along a segment: quotients of two exact values, compared by
//! cross-multiplication and never reduced (no gcd), rounded only when a position is
//! output.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;

use super::cone::Q;

/// The exact quotient `num / den`, with `den > 0` (an invariant of the constructors).
#[derive(Debug, Clone)]
pub(crate) struct Param {
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

impl Param {
    /// `0`.
    pub(crate) fn zero() -> Param {
        Param {
            num: Q::zero(),
            den: Q::from_f64(1.0),
        }
    }

    /// `1`.
    pub(crate) fn one() -> Param {
        Param {
            num: Q::from_f64(1.0),
            den: Q::from_f64(1.0),
        }
    }

    /// The root `u` of `fa + u·(fb − fa)` for `fa ≠ fb`, with the sign of the slope
    /// `fb − fa` (`Greater`: the function grows with `u`).
    pub(crate) fn root(fa: &Q, fb: &Q) -> (Param, Ordering) {
        let slope = fb - fa;
        match slope.signum() {
            Ordering::Less => (
                Param {
                    num: fa.clone(),
                    den: -&slope,
                },
                Ordering::Less,
            ),
            s => (
                Param {
                    num: -fa,
                    den: slope,
                },
                s,
            ),
        }
    }

    /// Whether this is exactly `0`.
    pub(crate) fn is_zero(&self) -> bool {
        self.num.is_zero()
    }

    /// Whether this is exactly `1`.
    pub(crate) fn is_one(&self) -> bool {
        self.num == self.den
    }

    /// The exact value as a rational.
    #[cfg(test)]
    pub(crate) fn to_rational(&self) -> BigRational {
        rational(&self.num) / rational(&self.den)
    }

    /// Coordinate `i` of the exact point `A + u(B − A)`, rounded once to the nearest f64
    /// (a zero is `+0`).
    pub(crate) fn lerp(&self, a: f64, b: f64) -> f64 {
        if self.is_zero() {
            return a + 0.0;
        }
        if self.is_one() {
            return b + 0.0;
        }
        let (qa, qb) = (Q::from_f64(a), Q::from_f64(b));
        // (a·den + num·(b − a)) / den
        let n = &(&qa * &self.den) + &(&self.num * &(&qb - &qa));
        (rational(&n) / rational(&self.den))
            .to_f64()
            .unwrap_or(f64::NAN)
    }
}

impl Ord for Param {
    fn cmp(&self, other: &Param) -> Ordering {
        // Both denominators are positive.
        (&(&self.num * &other.den) - &(&other.num * &self.den)).signum()
    }
}

impl PartialOrd for Param {
    fn partial_cmp(&self, other: &Param) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl PartialEq for Param {
    fn eq(&self, other: &Param) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Param {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn roots_compare_and_round_as_rationals() {
        let q = Q::from_f64;
        let (r, s) = Param::root(&q(1.0), &q(-2.0));
        assert_eq!(s, Ordering::Less);
        assert_eq!(r.to_rational(), BigRational::new(1.into(), 3.into()));
        let (t, s) = Param::root(&q(-0.5), &q(1.0));
        assert_eq!(s, Ordering::Greater);
        assert_eq!(t.to_rational(), BigRational::new(1.into(), 3.into()));
        assert_eq!(r, t);
        assert!(Param::zero() < r && r < Param::one());
        assert!(Param::one().is_one() && !r.is_one());
        // One third of the way from 0 to 1, rounded once: the f64 nearest to 1/3.
        assert_eq!(r.lerp(0.0, 1.0), 1.0 / 3.0);
        assert_eq!(Param::zero().lerp(-0.0, 1.0).to_bits(), 0.0f64.to_bits());
        let (tiny, _) = Param::root(&q(1e-300), &q(-1e300));
        assert!(Param::zero() < tiny);
        assert_eq!(
            tiny.to_rational(),
            rational(&q(1e-300)) / (rational(&q(1e-300)) + rational(&q(1e300)))
        );
    }
}
