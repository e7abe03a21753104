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
//! projections) the same conditions hold with `π(E)` read as `n·d`. The coefficients are
//! polynomials in the f64 values that define the planes and the eye, computed exactly as
//! the kernel's [`Dyadic`] numbers (big-integer mantissa and binary exponent: every f64
//! is one, and sums and products stay exact without the gcd a rational would take after
//! every operation) in its [`ExactAffine`] functions, so each decision is the exact sign
//! on the input as given.

use std::cmp::Ordering;

use limn_kernel::{Dyadic, ExactAffine, ExactPolygon, Plane, Side};

/// An exact number.
pub(crate) type Q = Dyadic;

/// A point as exact numbers.
pub(crate) fn q3(p: [f64; 3]) -> [Q; 3] {
    Dyadic::point3(p)
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

/// The value of `f` at the eye (for an eye at infinity, `n·d`).
fn at_eye(f: &ExactAffine, eye: &EyeQ) -> Q {
    match eye {
        EyeQ::Point(p) => f.at(p),
        EyeQ::Toward(d) => f.toward(d),
    }
}

/// The hiding conditions of one polygon seen from the eye (see the module docs): `P` is
/// hidden iff `behind(P) > 0` and every `wall(P) ≥ 0`.
#[derive(Debug, Clone)]
pub(crate) struct Cone {
    /// `−s·π`.
    pub(crate) behind: ExactAffine,
    /// `−s·(π(E)·eᵢ − eᵢ(E)·π)`, one per edge.
    pub(crate) walls: Vec<ExactAffine>,
}

impl Cone {
    /// The cone of `poly` from the eye `eye`; `None` when the eye lies in the polygon's
    /// plane (it then hides nothing).
    pub(crate) fn new(poly: &ExactPolygon, eye: &EyeQ) -> Option<Cone> {
        let pi = ExactAffine::of_plane(&poly.support());
        let pe = at_eye(&pi, eye);
        // −s·π(E) = −|π(E)|, and −s·π.
        let (minus_s_pe, behind) = match pe.signum() {
            Ordering::Equal => return None,
            Ordering::Greater => (-&pe, pi.negated()),
            Ordering::Less => (pe.clone(), pi.clone()),
        };
        let walls = (0..poly.len())
            .map(|i| {
                let e = ExactAffine::of_plane(&poly.edge_plane(i));
                let ee = at_eye(&e, eye);
                // −s·π(E)·e − eᵢ(E)·(−s·π)
                e.combined(&minus_s_pe, &behind, &-&ee)
            })
            .collect();
        Some(Cone { behind, walls })
    }

    /// Whether `p` is hidden by the polygon.
    pub(crate) fn hides(&self, p: &[Q; 3]) -> bool {
        self.behind.at(p).signum() == Ordering::Greater
            && self
                .walls
                .iter()
                .all(|w| w.at(p).signum() != Ordering::Less)
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
