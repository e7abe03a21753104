//! A certified floating-point filter for the cone conditions: every plane value is an
//! interval that provably holds the exact value (the kernel's approximate coefficients
//! with their proven error bounds, then outward-rounded interval arithmetic), so a
//! condition whose interval lies strictly on one side is decided without exact
//! arithmetic; only undecided ones go to the exact rationals.

use std::cmp::Ordering;

use limn_kernel::{ExactPolygon, Plane, Side};

use crate::interval::Interval;

/// A closed interval `[lo, hi]` that holds an exact value, with that value's sign when it
/// is known exactly (from the kernel's exact plane sides); non-finite ends make every
/// test on the bounds undecided.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Iv {
    lo: f64,
    hi: f64,
    sign: Option<Ordering>,
}

impl Iv {
    /// `[lo, hi]`, sign unknown.
    fn new(lo: f64, hi: f64) -> Iv {
        Iv { lo, hi, sign: None }
    }

    /// Exactly zero.
    fn zero() -> Iv {
        Iv {
            lo: 0.0,
            hi: 0.0,
            sign: Some(Ordering::Equal),
        }
    }

    /// The same enclosure with the value's exact sign.
    fn with_sign(self, sign: Ordering) -> Iv {
        Iv {
            sign: Some(sign),
            ..self
        }
    }

    /// The enclosure without the sign.
    fn interval(self) -> Interval {
        Interval {
            lo: self.lo,
            hi: self.hi,
        }
    }

    fn mul(self, o: Iv) -> Iv {
        let r = self.interval() * o.interval();
        Iv::new(r.lo, r.hi)
    }

    fn sub(self, o: Iv) -> Iv {
        let r = self.interval() - o.interval();
        Iv::new(r.lo, r.hi)
    }

    fn neg(self) -> Iv {
        Iv {
            lo: -self.hi,
            hi: -self.lo,
            sign: self.sign.map(Ordering::reverse),
        }
    }

    /// Certainly positive.
    pub(crate) fn pos(self) -> bool {
        self.sign == Some(Ordering::Greater) || self.lo > 0.0
    }

    /// Certainly non-negative.
    pub(crate) fn nonneg(self) -> bool {
        self.sign.is_some_and(|s| s != Ordering::Less) || self.lo >= 0.0
    }

    /// Certainly negative.
    pub(crate) fn neg_strict(self) -> bool {
        self.sign == Some(Ordering::Less) || self.hi < 0.0
    }

    /// Certainly not positive.
    pub(crate) fn nonpos(self) -> bool {
        self.sign.is_some_and(|s| s != Ordering::Greater) || self.hi <= 0.0
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
        return Iv::new(f64::NEG_INFINITY, f64::INFINITY);
    }
    Iv::new((v - e).next_down(), (v + e).next_up())
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
                return Iv::new(f64::NEG_INFINITY, f64::INFINITY);
            }
            Iv::new((v - e).next_down(), (v + e).next_up())
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
    let pe = at_eye(support, eye);
    // A point on the support plane (the usual case at a shared vertex): `behind` is 0 and
    // each wall is `−s·π(E)·eᵢ(x) = −|π(E)|·eᵢ(x)`, enclosed as usual, with the exact sign
    // of `−eᵢ(x)` (the kernel's exact side).
    if support.side_of(x) == Side::On {
        out.push(Iv::zero());
        for i in 0..poly.len() {
            let e = poly.edge_plane(i);
            let v = flip(pe.mul(at(&e, x)));
            out.push(match e.side_of(x) {
                Side::Front => v.with_sign(Ordering::Less),
                Side::Back => v.with_sign(Ordering::Greater),
                Side::On => Iv::zero(),
            });
        }
        return true;
    }
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
/// side by its root `fa/(fa − fb)`, enclosed in an outward-rounded interval (from the
/// enclosures, never from exact signs alone); a condition certainly non-positive at one
/// end and negative at the other holds at most at that end. If the largest lower bound
/// certainly reaches the smallest upper bound, nothing of positive length is left.
pub(crate) fn certainly_empty(fa: &[Iv], fb: &[Iv]) -> bool {
    let (mut low, mut high) = (0.0f64, 1.0f64);
    for (x, y) in fa.iter().zip(fb) {
        if x.pos() && y.neg_strict() {
            // Holds for u ≤ x / (x − y), where x − y ≥ x.lo − y.hi.
            let den = (x.lo - y.hi).next_down();
            if den > 0.0 {
                high = high.min((x.hi / den).next_up());
            }
        } else if x.neg_strict() && y.pos() {
            // Holds for u ≥ −x / (y − x), where −x ≥ −x.hi and y − x ≤ y.hi − x.lo.
            let (num, den) = (-x.hi, (y.hi - x.lo).next_up());
            if num > 0.0 && den > 0.0 {
                low = low.max((num / den).next_down());
            }
        } else if x.nonpos() && y.neg_strict() {
            high = 0.0;
        } else if x.neg_strict() && y.nonpos() {
            low = 1.0;
        }
    }
    low.is_finite() && high.is_finite() && low >= high
}

/// What the filter concluded about a set of parameters or a point.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Verdict {
    /// The conditions certainly hold nowhere (on a segment: at most at a single point).
    Nowhere,
    /// The conditions certainly hold everywhere.
    Everywhere,
    /// The filter cannot tell.
    Unknown,
}

/// The filter's verdict on a segment from the conditions at its start (`fa`) and end
/// (`fb`), each linear along it: a condition certainly failing at both ends fails all
/// along; every condition certainly holding at both ends holds all along.
pub(crate) fn segment_verdict(fa: &[Iv], fb: &[Iv]) -> Verdict {
    let fails = fa[0].nonpos() && fb[0].nonpos()
        || fa[1..]
            .iter()
            .zip(&fb[1..])
            .any(|(x, y)| x.neg_strict() && y.neg_strict());
    if fails {
        return Verdict::Nowhere;
    }
    let holds = fa[0].pos()
        && fb[0].pos()
        && fa[1..]
            .iter()
            .zip(&fb[1..])
            .all(|(x, y)| x.nonneg() && y.nonneg());
    if holds {
        return Verdict::Everywhere;
    }
    if certainly_empty(fa, fb) {
        return Verdict::Nowhere;
    }
    Verdict::Unknown
}

/// The filter's verdict on a point from its conditions.
pub(crate) fn point_verdict(f: &[Iv]) -> Verdict {
    if f[0].nonpos() || f[1..].iter().any(|x| x.neg_strict()) {
        Verdict::Nowhere
    } else if f[0].pos() && f[1..].iter().all(|x| x.nonneg()) {
        Verdict::Everywhere
    } else {
        Verdict::Unknown
    }
}
