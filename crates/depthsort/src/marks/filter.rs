//! A certified floating-point filter for the cone conditions: every plane value is an
//! interval that provably holds the exact value (the kernel's [`Plane::value_at`], then
//! [`Interval`] arithmetic), so a condition whose interval lies strictly on one side is
//! decided without exact arithmetic; only undecided ones go to the exact numbers.

use std::cmp::Ordering;

use limn_kernel::{ExactPolygon, Interval, Plane, Side};

/// An [`Interval`] that holds an exact value, with that value's sign when it is known
/// exactly (from the kernel's exact plane sides).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Iv {
    iv: Interval,
    sign: Option<Ordering>,
}

impl Iv {
    /// The interval `iv`, sign unknown.
    fn new(iv: Interval) -> Iv {
        Iv { iv, sign: None }
    }

    /// Exactly zero.
    fn zero() -> Iv {
        Iv {
            iv: Interval::exactly(0.0),
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

    fn mul(self, o: Iv) -> Iv {
        Iv::new(self.iv * o.iv)
    }

    fn sub(self, o: Iv) -> Iv {
        Iv::new(self.iv - o.iv)
    }

    fn neg(self) -> Iv {
        Iv {
            iv: -self.iv,
            sign: self.sign.map(Ordering::reverse),
        }
    }

    /// Certainly positive.
    pub(crate) fn pos(self) -> bool {
        self.sign == Some(Ordering::Greater) || self.iv.positive()
    }

    /// Certainly non-negative.
    pub(crate) fn nonneg(self) -> bool {
        self.sign.is_some_and(|s| s != Ordering::Less) || self.iv.non_negative()
    }

    /// Certainly negative.
    pub(crate) fn neg_strict(self) -> bool {
        self.sign == Some(Ordering::Less) || self.iv.negative()
    }

    /// Certainly not positive.
    pub(crate) fn nonpos(self) -> bool {
        self.sign.is_some_and(|s| s != Ordering::Greater) || self.iv.non_positive()
    }
}

/// An interval holding the exact value of `plane` at `x`.
pub(crate) fn at(plane: &Plane, x: [f64; 3]) -> Iv {
    Iv::new(plane.value_at(x))
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
        EyeF::Toward(d) => Iv::new(plane.value_toward(d)),
    }
}

/// What the filter reads of an occluder that does not depend on the point: its edge
/// planes (an input polygon makes them when asked, so they are made once here, not at
/// every point) and the values at the eye of its plane and of each edge plane.
#[derive(Debug)]
pub(crate) struct ConePlanes {
    edges: Box<[Plane]>,
    /// The support plane's value at the eye.
    at_eye: Iv,
    /// Each edge plane's value at the eye.
    edges_at_eye: Box<[Iv]>,
}

impl ConePlanes {
    /// The planes of `poly` (whose support plane is `support`) seen from `eye`.
    pub(crate) fn new(poly: &ExactPolygon, support: &Plane, eye: EyeF) -> ConePlanes {
        let edges: Box<[Plane]> = (0..poly.len()).map(|i| poly.edge_plane(i)).collect();
        let edges_at_eye = edges.iter().map(|e| at_eye(e, eye)).collect();
        ConePlanes {
            at_eye: at_eye(support, eye),
            edges,
            edges_at_eye,
        }
    }
}

/// The cone conditions of an occluder (its plane `support`, its `planes` from the eye)
/// at a point, as intervals into `out`: `behind`, then one wall per edge (see
/// `cone.rs`). False (nothing computed) when the eye's side is `On`.
pub(crate) fn conditions(
    planes: &ConePlanes,
    support: &Plane,
    eye_side: Side,
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
    let pe = planes.at_eye;
    // A point on the support plane (the usual case at a shared vertex): `behind` is 0 and
    // each wall is `−s·π(E)·eᵢ(x) = −|π(E)|·eᵢ(x)`, enclosed as usual, with the exact sign
    // of `−eᵢ(x)` (the kernel's exact side).
    if support.side_of(x) == Side::On {
        out.push(Iv::zero());
        for e in &planes.edges {
            let v = flip(pe.mul(at(e, x)));
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
    for (e, ee) in planes.edges.iter().zip(&planes.edges_at_eye) {
        let g = pe.mul(at(e, x)).sub(ee.mul(px));
        out.push(flip(g));
    }
    true
}

/// Whether the parameters `u ∈ [0, 1]` where every condition holds (`fa`: values at the
/// segment's start, `fb`: at its end; each condition linear in `u`) certainly form an
/// empty set or a single point. Each condition whose enclosures change sign certainly
/// bounds `u` on one side by its root `|fa| / (|fa| + |fb|)`, enclosed by
/// [`Interval::share_of`] (from the enclosures, never from exact signs alone); a condition
/// certainly non-positive at one end and negative at the other holds at most at that end.
/// If the largest lower bound certainly reaches the smallest upper bound, nothing of
/// positive length is left.
pub(crate) fn certainly_empty(fa: &[Iv], fb: &[Iv]) -> bool {
    let (mut low, mut high) = (0.0f64, 1.0f64);
    for (x, y) in fa.iter().zip(fb) {
        if x.iv.positive() && y.iv.negative() {
            // Holds for u ≤ x / (x − y).
            high = high.min(x.iv.share_of(y.iv).hi());
        } else if x.iv.negative() && y.iv.positive() {
            // Holds for u ≥ −x / (y − x).
            low = low.max(x.iv.share_of(y.iv).lo());
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

/// The first condition (`behind`) negated: the conditions of being drawn over the
/// polygon (`behind ≤ 0`, walls ≥ 0) instead of hidden by it.
pub(crate) fn negate_first(f: &mut [Iv]) {
    if let Some(x) = f.first_mut() {
        *x = x.neg();
    }
}

/// [`segment_verdict`] for conditions that all hold where they are zero (`≥ 0`), the
/// first one too.
pub(crate) fn closed_segment_verdict(fa: &[Iv], fb: &[Iv]) -> Verdict {
    if fa
        .iter()
        .zip(fb)
        .any(|(x, y)| x.neg_strict() && y.neg_strict())
    {
        return Verdict::Nowhere;
    }
    if fa.iter().zip(fb).all(|(x, y)| x.nonneg() && y.nonneg()) {
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
