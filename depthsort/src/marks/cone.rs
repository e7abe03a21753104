//! The exact cone an occluding polygon casts from the eye, and the exact arithmetic it is
//! evaluated in.
//!
//! A point `P` is hidden by a convex polygon `F` (support plane `π`, edge planes `eᵢ` with
//! the interior on their back sides) when the segment from the eye `E` to `P` meets `F`:
//! `P` lies strictly on the other side of `π` than `E`, and the point `X` where `EP`
//! crosses `π` lies in the closed polygon. Since every plane function is affine,
//! `eᵢ(X) · (π(E) − π(P)) = π(E)·eᵢ(P) − π(P)·eᵢ(E)`, a plane through the eye and the
//! edge's line. So "hidden by `F`" is the conjunction of linear conditions on `P`:
//!
//! - behind: `−s·π(P) > 0`, where `s = sign π(E)`;
//! - one wall per edge: `wᵢ(P) = −s·(π(E)·eᵢ(P) − eᵢ(E)·π(P)) ≥ 0`.
//!
//! A point on `π` itself is never hidden by `F`: a line drawn in a face's plane on top of
//! the face is drawn over it. For an eye at infinity in direction `d` (parallel
//! projections) the same conditions hold with `π(E)` read as `n·d`. The coefficients are polynomials in the f64 values that
//! define the planes and the eye, computed exactly as big rationals (every f64 is one), so
//! each decision is the exact sign on the input as given.

use limn_kernel::{ExactPolygon, Plane, PlaneDef, Side};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};

/// An exact number.
pub(crate) type Q = BigRational;

/// The exact value of a finite f64 (the scene is validated: every value is finite).
pub(crate) fn q(x: f64) -> Q {
    BigRational::from_float(x).unwrap_or_else(|| BigRational::from_integer(BigInt::zero()))
}

/// A point as exact numbers.
pub(crate) fn q3(p: [f64; 3]) -> [Q; 3] {
    p.map(q)
}

/// The eye, exactly: a point, or a direction for an eye at infinity (parallel
/// projections), where a plane's value is that of its normal (the homogeneous point
/// `(d, 0)`).
#[derive(Debug, Clone)]
pub(crate) enum EyeQ {
    /// A finite eye.
    Point([Q; 3]),
    /// An eye at infinity in this direction.
    Toward([Q; 3]),
}

/// An affine function `n·x + d` with exact coefficients.
#[derive(Debug, Clone)]
pub(crate) struct Affine {
    n: [Q; 3],
    d: Q,
}

impl Affine {
    /// The exact coefficients of a kernel plane, from its definition.
    pub(crate) fn of_plane(plane: &Plane) -> Affine {
        let sub =
            |a: [f64; 3], b: [f64; 3]| [q(a[0]) - q(b[0]), q(a[1]) - q(b[1]), q(a[2]) - q(b[2])];
        let (n, p) = match plane.definition() {
            PlaneDef::Through([p, a, b]) => (cross(&sub(a, p), &sub(b, p)), p),
            PlaneDef::Edge { p, q: b, k, flip } => {
                let w = sub(b, p);
                let z = || Q::zero();
                let n = match k {
                    0 => [z(), w[2].clone(), -w[1].clone()],
                    1 => [-w[2].clone(), z(), w[0].clone()],
                    _ => [w[1].clone(), -w[0].clone(), z()],
                };
                (if flip { n.map(|x| -x) } else { n }, p)
            }
            PlaneDef::Along { p, q: b, d } => (cross(&sub(b, p), &q3(d)), p),
            PlaneDef::PointNormal { p, n } => (q3(n), p),
        };
        let pq = q3(p);
        let d = -(&n[0] * &pq[0] + &n[1] * &pq[1] + &n[2] * &pq[2]);
        let a = Affine { n, d };
        if plane.is_flipped() {
            a.scaled(&-Q::from_integer(BigInt::from(1)))
        } else {
            a
        }
    }

    /// The value at an exact point.
    pub(crate) fn at(&self, x: &[Q; 3]) -> Q {
        &self.n[0] * &x[0] + &self.n[1] * &x[1] + &self.n[2] * &x[2] + &self.d
    }

    /// The value at the eye (for an eye at infinity, `n·d`).
    pub(crate) fn at_eye(&self, eye: &EyeQ) -> Q {
        match eye {
            EyeQ::Point(p) => self.at(p),
            EyeQ::Toward(d) => &self.n[0] * &d[0] + &self.n[1] * &d[1] + &self.n[2] * &d[2],
        }
    }

    /// `k · self`.
    fn scaled(&self, k: &Q) -> Affine {
        Affine {
            n: [&self.n[0] * k, &self.n[1] * k, &self.n[2] * k],
            d: &self.d * k,
        }
    }

    /// `a·self + b·other`.
    fn combined(&self, a: &Q, other: &Affine, b: &Q) -> Affine {
        Affine {
            n: [
                &self.n[0] * a + &other.n[0] * b,
                &self.n[1] * a + &other.n[1] * b,
                &self.n[2] * a + &other.n[2] * b,
            ],
            d: &self.d * a + &other.d * b,
        }
    }
}

fn cross(u: &[Q; 3], v: &[Q; 3]) -> [Q; 3] {
    [
        &u[1] * &v[2] - &u[2] * &v[1],
        &u[2] * &v[0] - &u[0] * &v[2],
        &u[0] * &v[1] - &u[1] * &v[0],
    ]
}

/// The hiding conditions of one polygon seen from the eye (see the module docs): `P` is
/// hidden iff `behind(P) > 0` and every `wall(P) ≥ 0`.
#[derive(Debug, Clone)]
pub(crate) struct Cone {
    /// `−s·π`.
    pub(crate) behind: Affine,
    /// `−s·(π(E)·eᵢ − eᵢ(E)·π)`, one per edge.
    pub(crate) walls: Vec<Affine>,
}

impl Cone {
    /// The cone of `poly` from the eye `eye`; `None` when the eye lies in the polygon's
    /// plane (it then hides nothing).
    pub(crate) fn new(poly: &ExactPolygon, eye: &EyeQ) -> Option<Cone> {
        let pi = Affine::of_plane(&poly.support());
        let pe = pi.at_eye(eye);
        if pe.is_zero() {
            return None;
        }
        let minus_s = if pe.is_positive() {
            -Q::from_integer(BigInt::from(1))
        } else {
            Q::from_integer(BigInt::from(1))
        };
        let walls = (0..poly.len())
            .map(|i| {
                let e = Affine::of_plane(&poly.edge_plane(i));
                let ee = e.at_eye(eye);
                // −s·(π(E)·e − e(E)·π)
                e.combined(&(&pe * &minus_s), &pi, &(-(&ee * &minus_s)))
            })
            .collect();
        Some(Cone {
            behind: pi.scaled(&minus_s),
            walls,
        })
    }

    /// Whether `p` is hidden by the polygon.
    pub(crate) fn hides(&self, p: &[Q; 3]) -> bool {
        self.behind.at(p).is_positive() && self.walls.iter().all(|w| !w.at(p).is_negative())
    }
}

/// Whether `x` may lie strictly behind `plane` as seen from a point on side `eye_side`
/// (exact; `false` means it certainly does not).
pub(crate) fn may_be_behind(plane: &Plane, eye_side: Side, x: [f64; 3]) -> bool {
    match (eye_side, plane.side_of(x)) {
        (Side::Front, Side::Back) | (Side::Back, Side::Front) => true,
        (Side::On, _) => false,
        _ => false,
    }
}
