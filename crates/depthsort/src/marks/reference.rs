//! The reference the fast exact path is tested against: the cone conditions (see
//! `cone.rs`) with coefficients built from the planes' definitions as normalised big
//! rationals, and the hidden parameters clipped as rationals. Slow (a gcd after every
//! operation), simple, and independent of the kernel's dyadic numbers.

use limn_kernel::{ExactPolygon, Plane, PlaneDef};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// An exact number.
type R = BigRational;

/// The exact value of a finite f64.
pub(super) fn r(x: f64) -> R {
    BigRational::from_float(x).unwrap_or_else(|| R::from_integer(BigInt::zero()))
}

/// A point as exact numbers.
pub(super) fn r3(p: [f64; 3]) -> [R; 3] {
    p.map(r)
}

/// An affine function `n·x + d`.
#[derive(Debug, Clone)]
struct Affine {
    n: [R; 3],
    d: R,
}

impl Affine {
    /// The coefficients of a kernel plane, from its definition.
    fn of_plane(plane: &Plane) -> Affine {
        let sub =
            |a: [f64; 3], b: [f64; 3]| [r(a[0]) - r(b[0]), r(a[1]) - r(b[1]), r(a[2]) - r(b[2])];
        let (n, p) = match plane.definition() {
            PlaneDef::Through([p, a, b]) => {
                let (u, v) = (sub(a, p), sub(b, p));
                let n = [
                    &u[1] * &v[2] - &u[2] * &v[1],
                    &u[2] * &v[0] - &u[0] * &v[2],
                    &u[0] * &v[1] - &u[1] * &v[0],
                ];
                (n, p)
            }
            PlaneDef::Edge { p, q, k, flip } => {
                let w = sub(q, p);
                let z = R::zero;
                let n = match k {
                    0 => [z(), w[2].clone(), -w[1].clone()],
                    1 => [-w[2].clone(), z(), w[0].clone()],
                    _ => [w[1].clone(), -w[0].clone(), z()],
                };
                (if flip { n.map(|x| -x) } else { n }, p)
            }
            PlaneDef::Along { p, q, d } => {
                let (u, v) = (sub(q, p), [r(d[0]), r(d[1]), r(d[2])]);
                let n = [
                    &u[1] * &v[2] - &u[2] * &v[1],
                    &u[2] * &v[0] - &u[0] * &v[2],
                    &u[0] * &v[1] - &u[1] * &v[0],
                ];
                (n, p)
            }
            PlaneDef::PointNormal { p, n } => (r3(n), p),
        };
        let pq = r3(p);
        let d = -(&n[0] * &pq[0] + &n[1] * &pq[1] + &n[2] * &pq[2]);
        if plane.is_flipped() {
            Affine {
                n: n.map(|x| -x),
                d: -d,
            }
        } else {
            Affine { n, d }
        }
    }

    fn at(&self, x: &[R; 3]) -> R {
        &self.n[0] * &x[0] + &self.n[1] * &x[1] + &self.n[2] * &x[2] + &self.d
    }

    /// The value at the eye: a point, or `n·d` for an eye at infinity.
    fn at_eye(&self, eye: &Eye) -> R {
        match eye {
            Eye::Point(p) => self.at(p),
            Eye::Toward(d) => &self.n[0] * &d[0] + &self.n[1] * &d[1] + &self.n[2] * &d[2],
        }
    }

    fn combined(&self, a: &R, o: &Affine, b: &R) -> Affine {
        Affine {
            n: [0, 1, 2].map(|i| &self.n[i] * a + &o.n[i] * b),
            d: &self.d * a + &o.d * b,
        }
    }
}

/// The eye: a point, or a direction for an eye at infinity.
pub(super) enum Eye {
    /// A finite eye.
    Point([R; 3]),
    /// An eye at infinity.
    Toward([R; 3]),
}

/// The conditions `behind > 0` and every `wall ≥ 0`; `None` when the eye is in the plane.
fn cone(poly: &ExactPolygon, eye: &Eye) -> Option<(Affine, Vec<Affine>)> {
    let pi = Affine::of_plane(&poly.support());
    let pe = pi.at_eye(eye);
    if pe.is_zero() {
        return None;
    }
    let minus_s = if pe.is_positive() {
        -R::one()
    } else {
        R::one()
    };
    let walls = (0..poly.len())
        .map(|i| {
            let e = Affine::of_plane(&poly.edge_plane(i));
            let ee = e.at_eye(eye);
            e.combined(&(&pe * &minus_s), &pi, &(-(&ee * &minus_s)))
        })
        .collect();
    let behind = pi.combined(&minus_s, &pi, &R::zero());
    Some((behind, walls))
}

/// The parameters in `[lo, hi]` where `fa + u(fb − fa) ≥ 0`.
fn clip(fa: &R, fb: &R, lo: R, hi: R) -> Option<(R, R)> {
    let slope = fb - fa;
    let (mut lo, mut hi) = (lo, hi);
    if slope.is_zero() {
        if fa.is_negative() {
            return None;
        }
    } else {
        let root = -fa / &slope;
        if slope.is_positive() {
            lo = lo.max(root);
        } else {
            hi = hi.min(root);
        }
    }
    (lo <= hi).then_some((lo, hi))
}

/// The parameters of `AB` in `[lo, hi]` that `poly`'s cone holds, when of positive
/// length.
pub(super) fn cone_part(
    poly: &ExactPolygon,
    eye: &Eye,
    a: &[R; 3],
    b: &[R; 3],
    lo: R,
    hi: R,
) -> Option<(R, R)> {
    let (behind, walls) = cone(poly, eye)?;
    let (ba, bb) = (behind.at(a), behind.at(b));
    if ba.is_zero() && bb.is_zero() {
        // In the plane: never hidden by it.
        return None;
    }
    let mut iv = clip(&ba, &bb, lo, hi);
    for w in &walls {
        iv = iv.and_then(|(lo, hi)| clip(&w.at(a), &w.at(b), lo, hi));
    }
    iv.filter(|(lo, hi)| lo < hi)
}

/// Whether `poly` hides the point `p`.
pub(super) fn hides(poly: &ExactPolygon, eye: &Eye, p: &[R; 3]) -> bool {
    cone(poly, eye).is_some_and(|(behind, walls)| {
        behind.at(p).is_positive() && walls.iter().all(|w| !w.at(p).is_negative())
    })
}

#[cfg(test)]
mod tests {
    use glam::DVec3;
    use limn_kernel::ExactKernel;
    use limn_kernel::Side;
    use limn_scene::{Camera, Material, PointMark, Polyline, Scene, Viewpoint};

    use super::*;
    use crate::geom::bbox;
    use crate::marks::cone::q3;
    use crate::marks::{context, face_opaque, hide_all};
    use crate::rng::SplitMix;
    use crate::{order_polygons, OrderOptions};
    use limn_kernel::Quotient;

    /// A random scene biased to the hard cases: a height field whose heights come from a
    /// few values (so neighbouring triangles are often coplanar), its grid lines and
    /// diagonals (lying in its faces), lines between its vertices and edge midpoints,
    /// random lines and triangles, points at vertices, on edges and anywhere, one face in
    /// three translucent.
    fn scene(rng: &mut SplitMix) -> (Scene, Camera) {
        let mut f = || (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        let mut s = Scene::default();
        let opaque = s.add_material(Material::unlit("o", [0.5, 0.5, 0.5]));
        let mut m = Material::unlit("t", [0.5, 0.5, 0.5]);
        m.opacity = 0.5;
        let translucent = s.add_material(m);
        let o = s.add_object("o");
        let n = 3 + (f() * 3.0) as usize;
        let levels = [0.0, 0.5, 1.0, 0.25];
        let heights: Vec<f64> = (0..(n + 1) * (n + 1))
            .map(|_| levels[(f() * 4.0) as usize])
            .collect();
        let at = |i: usize, j: usize| DVec3::new(i as f64, heights[i * (n + 1) + j], j as f64);
        for i in 0..n {
            for j in 0..n {
                let [a, b, c, d] = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
                for t in [[a, d, c], [a, c, b]] {
                    let mat = if f() < 0.3 { translucent } else { opaque };
                    // Degenerate draws are skipped: the scene rejects them.
                    let _ = s.add_polygon(&t, mat, o);
                }
            }
        }
        let random_point = |f: &mut dyn FnMut() -> f64| {
            DVec3::new(f() * n as f64, f() * 2.0 - 0.5, f() * n as f64)
        };
        for _ in 0..3 {
            let t = [0; 3].map(|_| random_point(&mut f));
            let _ = s.add_polygon(&t, opaque, o);
        }
        let pick = |f: &mut dyn FnMut() -> f64| {
            let (i, j) = ((f() * n as f64) as usize, (f() * n as f64) as usize);
            match (f() * 4.0) as usize {
                0 => at(i, j),
                1 => (at(i, j) + at(i + 1, j)) * 0.5,
                2 => (at(i, j) + at(i + 1, j + 1)) * 0.5,
                _ => at(i + 1, j + 1),
            }
        };
        for k in 0..=n {
            s.lines
                .push(Polyline::new((0..=n).map(|j| at(k, j)).collect()));
            s.lines
                .push(Polyline::new((0..=n).map(|i| at(i, k)).collect()));
        }
        s.lines
            .push(Polyline::new((0..=n).map(|i| at(i, i)).collect()));
        for _ in 0..8 {
            let pts = vec![pick(&mut f), pick(&mut f), random_point(&mut f)];
            if pts.windows(2).all(|w| w[0] != w[1]) {
                s.lines.push(Polyline::new(pts));
            }
        }
        for _ in 0..30 {
            let p = if f() < 0.5 {
                pick(&mut f)
            } else {
                random_point(&mut f)
            };
            s.points.push(PointMark::new(p));
        }
        let c = n as f64 / 2.0;
        let eye = DVec3::new(c + 6.0 * (f() - 0.5), 3.0 + 4.0 * f(), c + 6.0 + 4.0 * f());
        let target = DVec3::new(c, 0.3, c);
        let cam = if f() < 0.3 {
            Camera::orthographic(eye, target, 2.0 * n as f64, 300, 200)
        } else {
            Camera::new(eye, target, 300, 200)
        };
        (s, cam)
    }

    fn rational(p: &Quotient) -> R {
        p.to_rational()
    }

    /// On random scenes: for every segment and point against every fragment, the dyadic
    /// cone and the filtered decision equal the rational reference; and the whole output
    /// is the same with the filter as without.
    #[test]
    fn fast_paths_equal_the_rational_reference() {
        let mut rng = SplitMix::new(7);
        let mut checked = [0usize; 4];
        for round in 0..12 {
            let (s, cam) = scene(&mut rng);
            let (ordered, polys) =
                order_polygons(&ExactKernel::new(), &s, &cam, &OrderOptions::default()).unwrap();
            let occ = || -> Vec<(ExactPolygon, usize, crate::geom::Box2)> {
                polys
                    .iter()
                    .zip(&ordered.fragments)
                    .enumerate()
                    .map(|(i, (p, f))| (p.clone(), i, bbox(&f.points)))
                    .collect()
            };
            let flags: Vec<bool> = ordered
                .fragments
                .iter()
                .map(|f| face_opaque(&s, f.face))
                .collect();
            let eye = match cam.viewpoint().unwrap() {
                Viewpoint::At(p) => Eye::Point(r3(p.to_array())),
                Viewpoint::Toward(d) => Eye::Toward(r3(d.to_array())),
            };
            let shared = context(&ordered, occ(), flags.clone(), true).unwrap();
            let mut ctx = shared.task();
            for line in &s.lines {
                for w in line.points.windows(2) {
                    let (a, b) = (w[0], w[1]);
                    let (qa, qb) = (q3(a.to_array()), q3(b.to_array()));
                    let (ra, rb) = (r3(a.to_array()), r3(b.to_array()));
                    for (i, poly) in polys.iter().enumerate() {
                        // As in the segment pass: only occluders some end lies behind;
                        // a segment in the occluder's plane is never hidden by it.
                        let o = &shared.occluders[i];
                        let sides = [a, b].map(|p| o.support.side_of(p.to_array()));
                        if sides == [Side::On; 2] {
                            let (lo, hi) = (Quotient::zero(), Quotient::one());
                            assert!(ctx.exact_part(i as u32, [&qa, &qb], &lo, &hi).is_none());
                            checked[3] += 1;
                        }
                        if ![a, b].iter().any(|p| {
                            crate::marks::cone::may_be_behind(&o.support, o.eye_side, p.to_array())
                        }) {
                            continue;
                        }
                        let want = cone_part(poly, &eye, &ra, &rb, R::zero(), R::one());
                        let (lo, hi) = (Quotient::zero(), Quotient::one());
                        let exact = ctx.exact_part(i as u32, [&qa, &qb], &lo, &hi);
                        let got = exact.as_ref().map(|(x, y)| (rational(x), rational(y)));
                        assert_eq!(got, want, "round {round}: segment {a} {b}, fragment {i}");
                        let filtered = ctx.cone_part(i as u32, [a, b], [&qa, &qb], &lo, &hi);
                        assert_eq!(
                            filtered, exact,
                            "round {round}: segment {a} {b}, fragment {i}"
                        );
                        checked[0] += 1;
                        checked[1] += usize::from(want.is_some());
                    }
                }
            }
            for p in &s.points {
                let qp = q3(p.at.to_array());
                let rp = r3(p.at.to_array());
                for (i, poly) in polys.iter().enumerate() {
                    let want = hides(poly, &eye, &rp);
                    assert_eq!(
                        ctx.exact_holds(i as u32, &qp),
                        want,
                        "round {round}: point {}",
                        p.at
                    );
                    assert_eq!(
                        ctx.cone_holds(i as u32, p.at, &qp),
                        want,
                        "round {round}: point {}",
                        p.at
                    );
                    checked[2] += usize::from(want);
                }
            }
            let fast = hide_all(&s, &context(&ordered, occ(), flags.clone(), true).unwrap());
            let mut slow_shared = context(&ordered, occ(), flags, true).unwrap();
            slow_shared.filter = false;
            let mut slow = hide_all(&s, &slow_shared);
            assert!(slow.stats.exact_tests >= fast.stats.exact_tests);
            slow.stats.exact_tests = fast.stats.exact_tests;
            assert_eq!(fast, slow, "round {round}");
        }
        // The draws reach every case: many pairs, some hidden parts, some hidden points,
        // segments in a fragment's plane.
        assert!(
            checked[0] > 10_000 && checked[1] > 100 && checked[2] > 50 && checked[3] > 100,
            "{checked:?}"
        );
    }
}
