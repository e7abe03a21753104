//! A certified floating-point filter for the cone conditions: every plane value is an
//! interval that provably holds the exact value (the kernel's approximate coefficients
//! with their proven error bounds, then outward-rounded interval arithmetic), so a
//! condition whose interval lies strictly on one side is decided without exact
//! arithmetic; only undecided ones go to the exact rationals.

use limn_kernel::{ExactPolygon, Plane, Side};

/// A closed interval `[lo, hi]`; non-finite ends make every test undecided.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Iv(f64, f64);

impl Iv {
    fn mul(self, o: Iv) -> Iv {
        let p = [self.0 * o.0, self.0 * o.1, self.1 * o.0, self.1 * o.1];
        let lo = p.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Iv(lo.next_down(), hi.next_up())
    }

    fn sub(self, o: Iv) -> Iv {
        Iv((self.0 - o.1).next_down(), (self.1 - o.0).next_up())
    }

    fn neg(self) -> Iv {
        Iv(-self.1, -self.0)
    }

    /// Certainly positive.
    pub(crate) fn pos(self) -> bool {
        self.0 > 0.0
    }

    /// Certainly non-negative.
    pub(crate) fn nonneg(self) -> bool {
        self.0 >= 0.0
    }

    /// Certainly negative.
    pub(crate) fn neg_strict(self) -> bool {
        self.1 < 0.0
    }

    /// Certainly not positive.
    pub(crate) fn nonpos(self) -> bool {
        self.1 <= 0.0
    }
}

/// `2^-53`.
const U: f64 = 1.0 / 9_007_199_254_740_992.0;

/// An interval holding the exact value of `plane` at `x`.
pub(crate) fn at(plane: &Plane, x: [f64; 3]) -> Iv {
    let [a, b, c, d] = plane.approx();
    let (en, ed) = plane.error_bounds();
    let v = a * x[0] + b * x[1] + c * x[2] + d;
    let mag = (a * x[0]).abs() + (b * x[1]).abs() + (c * x[2]).abs() + d.abs();
    let sx = x[0].abs() + x[1].abs() + x[2].abs();
    // Coefficient errors, then the evaluation's roundings (at most four, 8u is ample),
    // then slack for the roundings of this bound itself.
    let e = (en * sx + ed + 8.0 * U * mag) * (1.0 + 16.0 * U) + f64::MIN_POSITIVE;
    if !(v.is_finite() && e.is_finite()) {
        return Iv(f64::NEG_INFINITY, f64::INFINITY);
    }
    Iv((v - e).next_down(), (v + e).next_up())
}

/// The eye as given: a point, or a direction for an eye at infinity.
#[derive(Debug, Clone, Copy)]
pub(crate) enum EyeF {
    /// A finite eye.
    Point([f64; 3]),
    /// An eye at infinity in this direction.
    Toward([f64; 3]),
}

/// An interval holding the exact value of `plane` at the eye (`n·d` for a direction).
fn at_eye(plane: &Plane, eye: EyeF) -> Iv {
    match eye {
        EyeF::Point(p) => at(plane, p),
        EyeF::Toward(d) => {
            let [a, b, c, _] = plane.approx();
            let (en, _) = plane.error_bounds();
            let v = a * d[0] + b * d[1] + c * d[2];
            let mag = (a * d[0]).abs() + (b * d[1]).abs() + (c * d[2]).abs();
            let sd = d[0].abs() + d[1].abs() + d[2].abs();
            let e = (en * sd + 8.0 * U * mag) * (1.0 + 16.0 * U) + f64::MIN_POSITIVE;
            if !(v.is_finite() && e.is_finite()) {
                return Iv(f64::NEG_INFINITY, f64::INFINITY);
            }
            Iv((v - e).next_down(), (v + e).next_up())
        }
    }
}

/// The cone conditions of `poly` seen from `eye` at a point, as intervals: `behind`,
/// then one wall per edge (see `cone.rs`). `None` when the eye's side is `On`.
pub(crate) fn conditions(
    poly: &ExactPolygon,
    support: &Plane,
    eye_side: Side,
    eye: EyeF,
    x: [f64; 3],
    out: &mut Vec<Iv>,
) -> bool {
    out.clear();
    let s_neg = match eye_side {
        Side::Front => true,
        Side::Back => false,
        Side::On => return false,
    };
    let flip = |v: Iv| if s_neg { v.neg() } else { v };
    // A point on the support plane (the usual case at a shared vertex): `behind` is 0 and
    // each wall has the sign of `−eᵢ(x)`, all exactly (the kernel's exact sides).
    if support.side_of(x) == Side::On {
        out.push(Iv(0.0, 0.0));
        for i in 0..poly.len() {
            out.push(match poly.edge_plane(i).side_of(x) {
                Side::Front => Iv(-1.0, -1.0),
                Side::Back => Iv(1.0, 1.0),
                Side::On => Iv(0.0, 0.0),
            });
        }
        return true;
    }
    let pe = at_eye(support, eye);
    let px = at(support, x);
    out.push(flip(px));
    for i in 0..poly.len() {
        let e = poly.edge_plane(i);
        let g = pe.mul(at(&e, x)).sub(at_eye(&e, eye).mul(px));
        out.push(flip(g));
    }
    true
}

/// Whether the parameters `u ∈ [0, 1]` where every condition holds (`fa`: values at the
/// segment's start, `fb`: at its end; each condition linear in `u`) certainly form an
/// empty set or a single point. Each condition changing sign certainly bounds `u` on one
/// side by its root `fa/(fa − fb)`, enclosed in an outward-rounded interval; if the
/// largest lower bound certainly reaches the smallest upper bound, nothing of positive
/// length is left.
pub(crate) fn certainly_empty(fa: &[Iv], fb: &[Iv]) -> bool {
    let (mut low, mut high) = (0.0f64, 1.0f64);
    for (x, y) in fa.iter().zip(fb) {
        if x.pos() && y.neg_strict() {
            // Holds for u ≤ x / (x − y).
            let r = (x.1 / (x.0 - y.1).next_down()).next_up();
            high = high.min(r);
        } else if x.neg_strict() && y.pos() {
            // Holds for u ≥ −x / (y − x).
            let r = ((-x.1) / (y.1 - x.0).next_up()).next_down();
            low = low.max(r);
        }
    }
    low.is_finite() && high.is_finite() && low >= high
}
