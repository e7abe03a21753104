//! Affine functions `n·x + d` with exact (dyadic) coefficients: a plane's equation taken
//! exactly, and the exact combinations of such equations that conditions on points are
//! made of (the walls of the cone a polygon casts from the eye, for example).

use crate::dyadic::{self, Dyadic};
use crate::plane::Plane;

/// An affine function `n·x + d` of a point `x`, with exact coefficients.
#[derive(Debug, Clone)]
pub struct ExactAffine {
    n: [Dyadic; 3],
    d: Dyadic,
}

impl ExactAffine {
    /// The equation of a plane (its exact coefficients, with its orientation): positive
    /// in front of it, zero on it.
    pub fn of_plane(plane: &Plane) -> ExactAffine {
        let (n, d) = plane.exact();
        ExactAffine { n, d }
    }

    /// The value at an exact point.
    pub fn at(&self, x: &[Dyadic; 3]) -> Dyadic {
        &dyadic::dot3(&self.n, x) + &self.d
    }

    /// The value at the point at infinity in direction `v`: `n·v`, the sign the function
    /// tends to far along `v`.
    pub fn toward(&self, v: &[Dyadic; 3]) -> Dyadic {
        dyadic::dot3(&self.n, v)
    }

    /// `−self`.
    pub fn negated(&self) -> ExactAffine {
        ExactAffine {
            n: [-&self.n[0], -&self.n[1], -&self.n[2]],
            d: -&self.d,
        }
    }

    /// `a·self + b·other`.
    pub fn combined(&self, a: &Dyadic, other: &ExactAffine, b: &Dyadic) -> ExactAffine {
        let c = |x: &Dyadic, y: &Dyadic| &(x * a) + &(y * b);
        ExactAffine {
            n: [
                c(&self.n[0], &other.n[0]),
                c(&self.n[1], &other.n[1]),
                c(&self.n[2], &other.n[2]),
            ],
            d: c(&self.d, &other.d),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cmp::Ordering;

    #[test]
    fn a_plane_equation_is_exact_and_combines_exactly() {
        let p = Plane::through([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]).unwrap();
        let f = ExactAffine::of_plane(&p);
        let above = Dyadic::point3([0.1, 0.2, 1e-300]);
        assert_eq!(f.at(&above).signum(), Ordering::Greater);
        assert_eq!(f.negated().at(&above).signum(), Ordering::Less);
        assert_eq!(
            f.toward(&Dyadic::point3([0.0, 0.0, -1.0])).signum(),
            Ordering::Less
        );
        // f − f is zero everywhere.
        let one = Dyadic::from_f64(1.0);
        let zero = f.combined(&one, &f, &-&one);
        assert!(zero.at(&above).is_zero());
    }
}
