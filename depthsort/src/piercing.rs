//! Whether two pieces that each span the other's plane visibly pierce each other, by a
//! float estimate: in a dense soup most such pairs do, and the exact answer (each piece's
//! two halves split exactly, projected and tested against the other) costs several exact
//! splits whose results are thrown away. The estimate only shortens the way to a
//! conflict, which is always a safe answer (the pair is split exactly afterwards): when it
//! is wrong, a pair that could have been ordered is split, which costs fragments, never
//! exactness. It answers `true` only when the two cut segments overlap by far more than
//! the float error of their ends.

use glam::DVec3;
use limn_kernel::Kernel;

use crate::pieces::Ctx;

/// Corners of a piece the estimate looks at, at most (pieces of a soup have three to six).
const MAX_CORNERS: usize = 12;

/// How much of the cut segments' length their overlap must exceed for the pieces to be
/// said to pierce each other (the float error of their ends is about 1e-15 of it).
const CLEAR_OVERLAP: f64 = 1e-6;

impl<K: Kernel> Ctx<'_, K> {
    /// Whether pieces `p` and `q`, known exactly to span each other's planes, pierce each
    /// other by a clear margin in float arithmetic (see the module's documentation):
    /// the segment where `p` crosses `q`'s plane and the one where `q` crosses `p`'s
    /// overlap along the line where the planes meet. `false` when the float corners are
    /// not close enough to the exact ones, or the pieces have too many corners.
    pub(crate) fn clearly_pierce(&self, p: u32, q: u32) -> bool {
        let (Some(a), Some(b)) = (self.corners_approx(p), self.corners_approx(q)) else {
            return false;
        };
        let (a, b) = (&a.0[..a.1], &b.0[..b.1]);
        let (na, nb) = (normal(a), normal(b));
        let dir = na.cross(nb);
        let (Some((a0, a1)), Some((b0, b1))) = (cut(a, nb, b[0], dir), cut(b, na, a[0], dir))
        else {
            return false;
        };
        let overlap = a1.min(b1) - a0.max(b0);
        overlap > CLEAR_OVERLAP * ((a1 - a0) + (b1 - b0))
    }

    /// The float corners of piece `p` in world space, when each is known to 1e-9 of its
    /// size and there are at most [`MAX_CORNERS`].
    fn corners_approx(&self, p: u32) -> Option<([DVec3; MAX_CORNERS], usize)> {
        let poly = &self.pieces[p as usize].poly;
        let n = self.k.vertex_count(poly);
        if n > MAX_CORNERS {
            return None;
        }
        let mut out = [DVec3::ZERO; MAX_CORNERS];
        for (i, c) in out.iter_mut().enumerate().take(n) {
            *c = self.k.vertex_world_approx(poly, i)?;
        }
        Some((out, n))
    }
}

/// Newell's normal of a polygon (any length; zero for a degenerate one).
fn normal(v: &[DVec3]) -> DVec3 {
    let mut n = DVec3::ZERO;
    for (i, a) in v.iter().enumerate() {
        let b = v[(i + 1) % v.len()];
        n += DVec3::new(
            (a.y - b.y) * (a.z + b.z),
            (a.z - b.z) * (a.x + b.x),
            (a.x - b.x) * (a.y + b.y),
        );
    }
    n
}

/// The extent along `dir` of where the convex polygon `v` crosses the plane through `o`
/// with normal `n`: the smallest and largest `dir` coordinate of its boundary's points on
/// that plane (`None` when the float signs say it does not cross).
fn cut(v: &[DVec3], n: DVec3, o: DVec3, dir: DVec3) -> Option<(f64, f64)> {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (i, a) in v.iter().enumerate() {
        let b = v[(i + 1) % v.len()];
        let (da, db) = ((*a - o).dot(n), (b - o).dot(n));
        let at = if da == 0.0 {
            Some(a.dot(dir))
        } else if (da < 0.0) != (db < 0.0) && db != 0.0 {
            let t = da / (da - db);
            Some((*a + (b - *a) * t).dot(dir))
        } else {
            None
        };
        if let Some(s) = at {
            lo = lo.min(s);
            hi = hi.max(s);
        }
    }
    (lo <= hi).then_some((lo, hi))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tri(a: [f64; 3], b: [f64; 3], c: [f64; 3]) -> Vec<DVec3> {
        vec![a.into(), b.into(), c.into()]
    }

    fn pierce(a: &[DVec3], b: &[DVec3]) -> bool {
        let (na, nb) = (normal(a), normal(b));
        let dir = na.cross(nb);
        match (cut(a, nb, b[0], dir), cut(b, na, a[0], dir)) {
            (Some((a0, a1)), Some((b0, b1))) => {
                a1.min(b1) - a0.max(b0) > CLEAR_OVERLAP * ((a1 - a0) + (b1 - b0))
            }
            _ => false,
        }
    }

    #[test]
    fn crossing_triangles_pierce_and_spanning_apart_ones_do_not() {
        // In z = 0, and in y = 0 crossing it through its middle.
        let flat = tri([-1.0, -1.0, 0.0], [1.0, -1.0, 0.0], [0.0, 1.0, 0.0]);
        let upright = tri([-0.5, 0.0, -1.0], [0.5, 0.0, -1.0], [0.0, 0.0, 1.0]);
        assert!(pierce(&flat, &upright));
        assert!(pierce(&upright, &flat));
        // The same upright triangle moved along x beyond the flat one's cut: each still
        // spans the other's plane, but the cut segments are apart.
        let beside = tri([2.0, 0.0, -1.0], [3.0, 0.0, -1.0], [2.5, 0.0, 1.0]);
        assert!(!pierce(&flat, &beside));
        // Cut segments that only touch at one end (x = 0.5) do not count as piercing.
        let touching = tri([0.5, 0.0, -1.0], [2.0, 0.0, -1.0], [0.5, 0.0, 1.0]);
        assert!(!pierce(&flat, &touching));
        assert!(!pierce(&touching, &flat));
    }

    type R = num_rational::BigRational;

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

    /// The exact extent along `dir` of where triangle `v` crosses the plane of `w`.
    fn exact_cut(v: &[[R; 3]; 3], w: &[[R; 3]; 3], dir: &[R; 3]) -> Option<(R, R)> {
        let n = cross(&sub(&w[1], &w[0]), &sub(&w[2], &w[0]));
        let d: Vec<R> = v.iter().map(|p| dot(&sub(p, &w[0]), &n)).collect();
        let zero = R::from_integer(0.into());
        let mut at = Vec::new();
        for i in 0..3 {
            let (a, b) = (&v[i], &v[(i + 1) % 3]);
            let (da, db) = (&d[i], &d[(i + 1) % 3]);
            if *da == zero {
                at.push(dot(a, dir));
            } else if (*da < zero) != (*db < zero) && *db != zero {
                let t = da / (da - db);
                let p = [
                    &a[0] + &t * (&b[0] - &a[0]),
                    &a[1] + &t * (&b[1] - &a[1]),
                    &a[2] + &t * (&b[2] - &a[2]),
                ];
                at.push(dot(&p, dir));
            }
        }
        let lo = at.iter().min()?.clone();
        let hi = at.iter().max()?.clone();
        Some((lo, hi))
    }

    #[test]
    fn a_float_piercing_is_an_exact_one() {
        // Random triangles in a small cube, many nearly touching: whenever the estimate
        // says two pierce each other, the exact cut segments overlap with positive length.
        let mut r = crate::rng::SplitMix::new(11);
        let mut u = || ((r.next_u64() >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 2.0;
        let (mut said, mut checked) = (0, 0);
        for _ in 0..4000 {
            let a = tri([u(), u(), u()], [u(), u(), u()], [u(), u(), u()]);
            let b = tri([u(), u(), u()], [u(), u(), u()], [u(), u(), u()]);
            let ea = [0, 1, 2].map(|i| a[i].to_array().map(exact));
            let eb = [0, 1, 2].map(|i| b[i].to_array().map(exact));
            let dir = cross(
                &cross(&sub(&ea[1], &ea[0]), &sub(&ea[2], &ea[0])),
                &cross(&sub(&eb[1], &eb[0]), &sub(&eb[2], &eb[0])),
            );
            let (Some((a0, a1)), Some((b0, b1))) =
                (exact_cut(&ea, &eb, &dir), exact_cut(&eb, &ea, &dir))
            else {
                continue;
            };
            checked += 1;
            if pierce(&a, &b) {
                said += 1;
                assert!(a1.min(b1) > a0.max(b0), "{a:?} {b:?}");
            }
        }
        assert!(said > 50 && checked > said, "{said} of {checked}");
    }
}
