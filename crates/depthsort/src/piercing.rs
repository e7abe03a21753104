//! Whether two pieces that each span the other's plane pierce each other, decided in
//! floats with proven error bounds: in a dense soup most such pairs do, and the answer by
//! exact splits (each piece's two halves split exactly, projected and tested against the
//! other) costs several exact splits whose results are thrown away. The kernel gives each
//! corner's position as a box holding the true corner and the other plane's equation
//! there with a bound on its error (its filter's); everything after is computed in the
//! kernel's [`Interval`]s, which hold the exact values. The answer `true` is given only
//! when it holds for the exact pieces, and it is then the exact order's answer (a
//! conflict). Otherwise (`false`: apart, touching, or too close to tell) the exact path
//! decides. No tolerance: bounds that cannot tell say so.

use glam::DVec3;
use limn_kernel::{Interval, Kernel};

use crate::pieces::Ctx;

/// Corners of a piece the test looks at, at most (pieces of a soup have three to six).
const MAX_CORNERS: usize = 12;

/// Largest coordinate (plus its error bound) the test takes: no interval end overflows.
const MAX_COORDINATE: f64 = 1e75;

/// A piece as the test sees it: its corners (each within its bound of the true one in
/// every coordinate), the other piece's plane's equation at each with its error bound,
/// and how many corners there are.
struct Seen {
    corners: [([f64; 3], f64); MAX_CORNERS],
    heights: [(f64, f64); MAX_CORNERS],
    n: usize,
}

impl<K: Kernel> Ctx<'_, K> {
    /// Whether pieces `p` and `q`, known exactly to span each other's planes, pierce each
    /// other: the segment where `p` crosses `q`'s plane and the one where `q` crosses
    /// `p`'s overlap along the line where the planes meet, by a positive length (then
    /// each piece has a part on the eye's side of the other that overlaps it on screen:
    /// a conflict). `true` only when the bounds prove it for the exact pieces; `false`
    /// when they do not (see the module's documentation).
    pub(crate) fn clearly_pierce(&self, p: u32, q: u32) -> bool {
        let Some(a) = self.seen(p, q) else {
            return false;
        };
        let Some(b) = self.seen(q, p) else {
            return false;
        };
        pierce(&a, &b)
    }

    /// Piece `p` as the test sees it against the plane of `other`.
    fn seen(&self, p: u32, other: u32) -> Option<Seen> {
        seen(
            self.k,
            &self.pieces[p as usize].poly,
            self.k.support(&self.pieces[other as usize].poly),
        )
    }
}

/// `poly` as the test sees it against `plane`, when the kernel bounds its corners' errors
/// and it has at most [`MAX_CORNERS`] of them.
fn seen<K: Kernel>(k: &K, poly: &K::Polygon, plane: &K::Plane) -> Option<Seen> {
    let n = k.vertex_count(poly);
    if n > MAX_CORNERS {
        return None;
    }
    let mut s = Seen {
        corners: [([0.0; 3], 0.0); MAX_CORNERS],
        heights: [(0.0, 0.0); MAX_CORNERS],
        n,
    };
    // The sides first: a corner too close to the plane to tell ends the test.
    if !k.vertex_heights(poly, plane, &mut s.heights)
        || !s.heights[..n].iter().all(|&(v, e)| v.abs() > e)
    {
        return None;
    }
    for (i, c) in s.corners.iter_mut().enumerate().take(n) {
        let (v, err) = k.vertex_world_bounded(poly, i)?;
        if !(v.is_finite() && v.abs().max_element() + err <= MAX_COORDINATE) {
            return None;
        }
        *c = (v.to_array(), err);
    }
    Some(s)
}

/// Whether the convex planar polygons `a` and `b`, each spanning the other's plane,
/// provably pierce each other.
fn pierce(a: &Seen, b: &Seen) -> bool {
    // Any direction not across the line where the planes meet orders the points on it;
    // this one (near that line's, from the corners' positions) is a float vector, exact
    // as it stands, scaled to keep the products small.
    let dir = normal(a).cross(normal(b));
    let scale = dir.abs().max_element();
    if !(scale > 0.0 && scale.is_finite()) {
        return false;
    }
    let dir = (dir / scale).to_array();
    let (Some((a0, a1)), Some((b0, b1))) = (cut(a, dir), cut(b, dir)) else {
        return false;
    };
    // Each true cut segment reaches below its `lo` bound and above its `hi` bound: the
    // overlap is positive if the larger of the first is below the smaller of the second.
    a0.max(b0) < a1.min(b1)
}

/// A float normal of a polygon from its corners' positions (Newell's).
fn normal(s: &Seen) -> DVec3 {
    let at = |c: &([f64; 3], f64)| DVec3::from_array(c.0);
    let mut n = DVec3::ZERO;
    for i in 0..s.n {
        let (a, b) = (at(&s.corners[i]), at(&s.corners[(i + 1) % s.n]));
        n += DVec3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        );
    }
    n
}

/// Where the convex polygon crosses the other plane, along `dir`: an upper bound on the
/// smallest and a lower bound on the largest `dir` coordinate of its boundary's points on
/// that plane. `None` when some corner's side of the plane is not certain (on it, or too
/// close to tell).
fn cut(s: &Seen, dir: [f64; 3]) -> Option<(f64, f64)> {
    let mut h = [Interval::exactly(0.0); MAX_CORNERS];
    for (hi, &(v, e)) in h.iter_mut().zip(&s.heights[..s.n]) {
        *hi = Interval::around(v, e);
        if !(hi.positive() || hi.negative()) {
            return None;
        }
    }
    let (mut lo_hi, mut hi_lo) = (f64::INFINITY, f64::NEG_INFINITY);
    for i in 0..s.n {
        let j = (i + 1) % s.n;
        if h[i].positive() == h[j].positive() {
            continue;
        }
        // The crossing a + t (b − a), t = |ha| / (|ha| + |hb|), along `dir`.
        let t = h[i].share_of(h[j]);
        let along = |c: &([f64; 3], f64)| Interval::dot_near(c.0, c.1, dir);
        let (sa, sb) = (along(&s.corners[i]), along(&s.corners[j]));
        let at = sa + t * (sb - sa);
        lo_hi = lo_hi.min(at.hi());
        hi_lo = hi_lo.max(at.lo());
    }
    Some((lo_hi, hi_lo))
}

#[cfg(test)]
mod tests {
    use super::*;
    use limn_kernel::{ExactKernel, ExactPolygon};

    use num_traits::ToPrimitive;

    type R = num_rational::BigRational;

    fn poly(k: &ExactKernel, v: &[[f64; 3]]) -> ExactPolygon {
        let corners: Vec<DVec3> = v.iter().map(|&c| c.into()).collect();
        k.face_polygons(&corners).expect("valid").remove(0)
    }

    /// Whether the test proves that `a` and `b` pierce each other.
    fn proven(k: &ExactKernel, a: &ExactPolygon, b: &ExactPolygon) -> bool {
        match (seen(k, a, k.support(b)), seen(k, b, k.support(a))) {
            (Some(sa), Some(sb)) => pierce(&sa, &sb),
            _ => false,
        }
    }

    #[test]
    fn crossing_triangles_pierce_and_spanning_apart_ones_do_not() {
        let k = ExactKernel::new();
        // In z = 0, and in y = 0 crossing it through its middle.
        let flat = poly(&k, &[[-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [0.0, 1.0, 0.0]]);
        let upright = poly(&k, &[[-0.5, 0.0, -1.0], [0.5, 0.0, -1.0], [0.0, 0.0, 1.0]]);
        assert!(proven(&k, &flat, &upright));
        assert!(proven(&k, &upright, &flat));
        // The same upright triangle moved along x beyond the flat one's cut: each still
        // spans the other's plane, but the cut segments are apart.
        let beside = poly(&k, &[[2.0, 0.0, -1.0], [3.0, 0.0, -1.0], [2.5, 0.0, 1.0]]);
        assert!(!proven(&k, &flat, &beside));
        // Cut segments that only touch at one end (x = 0.5) do not count as piercing.
        let touching = poly(&k, &[[0.5, 0.0, -1.0], [2.0, 0.0, -1.0], [0.5, 0.0, 1.0]]);
        assert!(!proven(&k, &flat, &touching));
        assert!(!proven(&k, &touching, &flat));
        // A corner on the other's plane: its side is not certain, nothing is proven.
        let on = poly(&k, &[[-0.5, 0.0, 0.0], [0.5, 0.0, -1.0], [0.0, 0.0, 1.0]]);
        assert!(!proven(&k, &flat, &on));
    }

    fn exact(x: f64) -> R {
        R::from_float(x).expect("finite")
    }

    fn sub(a: &[R; 3], b: &[R; 3]) -> [R; 3] {
        [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
    }

    fn dot(a: &[R; 3], b: &[R; 3]) -> R {
        &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
    }

    fn cross(a: &[R; 3], b: &[R; 3]) -> [R; 3] {
        [
            &a[1] * &b[2] - &a[2] * &b[1],
            &a[2] * &b[0] - &a[0] * &b[2],
            &a[0] * &b[1] - &a[1] * &b[0],
        ]
    }

    fn zero() -> R {
        R::from_integer(0.into())
    }

    /// Where the segment `a`–`b` meets the plane through `o` with normal `n`, given the
    /// signed values `da`, `db` there (of opposite signs).
    fn crossing(a: &[R; 3], b: &[R; 3], da: &R, db: &R) -> [R; 3] {
        let t = da / (da - db);
        [
            &a[0] + &t * (&b[0] - &a[0]),
            &a[1] + &t * (&b[1] - &a[1]),
            &a[2] + &t * (&b[2] - &a[2]),
        ]
    }

    /// The part of the convex polygon `v` in front of the plane through `o` with normal
    /// `n` (exactly).
    fn front_part(v: &[[R; 3]], o: &[R; 3], n: &[R; 3]) -> Vec<[R; 3]> {
        let d: Vec<R> = v.iter().map(|p| dot(&sub(p, o), n)).collect();
        let mut out = Vec::new();
        for i in 0..v.len() {
            let j = (i + 1) % v.len();
            if d[i] >= zero() {
                out.push(v[i].clone());
            }
            if (d[i] > zero() && d[j] < zero()) || (d[i] < zero() && d[j] > zero()) {
                out.push(crossing(&v[i], &v[j], &d[i], &d[j]));
            }
        }
        out
    }

    /// The exact extent along `dir` of where polygon `v` crosses the plane of `w`.
    fn exact_cut(v: &[[R; 3]], w: &[[R; 3]], dir: &[R; 3]) -> Option<(R, R)> {
        let n = cross(&sub(&w[1], &w[0]), &sub(&w[2], &w[0]));
        let d: Vec<R> = v.iter().map(|p| dot(&sub(p, &w[0]), &n)).collect();
        let mut at = Vec::new();
        for i in 0..v.len() {
            let j = (i + 1) % v.len();
            if d[i] == zero() {
                at.push(dot(&v[i], dir));
            } else if (d[i] < zero()) != (d[j] < zero()) && d[j] != zero() {
                at.push(dot(&crossing(&v[i], &v[j], &d[i], &d[j]), dir));
            }
        }
        let lo = at.iter().min()?.clone();
        let hi = at.iter().max()?.clone();
        Some((lo, hi))
    }

    #[test]
    fn a_proven_piercing_is_an_exact_one() {
        // Random triangles in a small cube, many nearly touching, as input polygons and as
        // the front parts of them cut by a random plane (corners the kernel knows only to
        // an error bound): whenever the test says two pierce each other, their exact cut
        // segments overlap with positive length, and it says so for nearly all pairs that
        // do.
        let k = ExactKernel::new();
        let mut r = crate::rng::SplitMix::new(11);
        let mut u = || ((r.next_u64() >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 2.0;
        for cut in [false, true] {
            let (mut said, mut overlapping) = (0, 0);
            for _ in 0..3000 {
                let mut pick = || -> Option<(ExactPolygon, Vec<[R; 3]>)> {
                    let t: [[f64; 3]; 3] = std::array::from_fn(|_| [u(), u(), u()]);
                    let whole = k.face_polygons(&t.map(DVec3::from)).ok()?.pop()?;
                    let ex = t.map(|c| c.map(exact)).to_vec();
                    if !cut {
                        return Some((whole, ex));
                    }
                    let (o, n) = ([u(), u(), u()], [u(), u(), u()]);
                    let plane = k.plane_through(o.into(), n.into()).ok()?;
                    let front = k.split(&whole, &plane).0?;
                    let part = front_part(&ex, &o.map(exact), &n.map(exact));
                    // The kernel's front part is this one: its corners are these.
                    assert_eq!(part.len(), k.vertex_count(&front));
                    for (i, c) in part.iter().enumerate() {
                        let (v, _) = k.vertex_world_bounded(&front, i)?;
                        let w = c.clone().map(|x| x.to_f64().expect("small"));
                        assert!(v.distance(DVec3::from(w)) < 1e-9, "{v} {w:?}");
                    }
                    Some((front, part))
                };
                let (Some((a, ea)), Some((b, eb))) = (pick(), pick()) else {
                    continue;
                };
                let dir = cross(
                    &cross(&sub(&ea[1], &ea[0]), &sub(&ea[2], &ea[0])),
                    &cross(&sub(&eb[1], &eb[0]), &sub(&eb[2], &eb[0])),
                );
                let (Some((a0, a1)), Some((b0, b1))) =
                    (exact_cut(&ea, &eb, &dir), exact_cut(&eb, &ea, &dir))
                else {
                    continue;
                };
                let overlaps = a1.min(b1) > a0.max(b0);
                overlapping += usize::from(overlaps);
                if proven(&k, &a, &b) {
                    said += 1;
                    assert!(overlaps, "cut {cut}: {a:?} {b:?}");
                }
            }
            assert!(said > 30, "cut {cut}: {said} of {overlapping}");
            assert!(
                said * 100 >= overlapping * 95,
                "cut {cut}: {said} of {overlapping}"
            );
        }
    }
}
