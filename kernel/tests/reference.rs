//! Every predicate sign equals an arbitrary-precision reference.

mod common;

use common::*;
use limn_kernel::predicates::{side_of_intersection, ImplicitPoint};
use limn_kernel::{GridPoint, Kernel, Plane, Side};
use proptest::prelude::*;

/// Adds two planes (the result passes through their common line), if within bounds.
fn combine(p: &Plane, q: &Plane, s: i64, t: i64) -> Option<Plane> {
    let (a, b, c, d) = p.coefficients();
    let (e, f, g, h) = q.coefficients();
    let mix = |x: i64, y: i64| x.checked_mul(s)?.checked_add(y.checked_mul(t)?);
    Plane::new(
        mix(a, e)?,
        mix(b, f)?,
        mix(c, g)?,
        d.checked_mul(s as i128)?
            .checked_add(h.checked_mul(t as i128)?)?,
    )
}

fn check_point(planes: [Plane; 3], h: &Plane) {
    let reference = intersect(&planes).map(|p| side_at(h, &p));
    let exact = side_of_intersection(&planes[0], &planes[1], &planes[2], h);
    assert_eq!(exact, reference, "exact path, planes {planes:?}, h {h:?}");
    if let Some(want) = reference {
        let v = ImplicitPoint::new(planes[0], planes[1], planes[2]).unwrap();
        if let Some(s) = v.side_filtered(h) {
            assert_eq!(s, want, "filter decided wrongly: {planes:?} {h:?}");
        }
        assert_eq!(v.side(h).0, want);
        assert_eq!(v.side_exact(h), want);
    }
}

/// Planes through a common grid point `g` with the given normals.
fn planes_through(g: [i64; 3], normals: &[[i64; 3]]) -> Option<Vec<Plane>> {
    normals
        .iter()
        .map(|n| {
            let d = -(0..3).map(|i| n[i] as i128 * g[i] as i128).sum::<i128>();
            Plane::new(n[0], n[1], n[2], d)
        })
        .collect()
}

fn small_normal() -> impl Strategy<Value = [i64; 3]> {
    let m = (1i64 << 54) - 1;
    [
        prop_oneof![-m..=m, -2i64..=2],
        prop_oneof![-m..=m, -2i64..=2],
        prop_oneof![-m..=m, -2i64..=2],
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    #[test]
    fn random_planes(p1 in any_plane(), p2 in any_plane(), p3 in any_plane(), h in any_plane()) {
        check_point([p1, p2, p3], &h);
    }

    /// `h` is a combination of two of the planes: it passes exactly through the vertex,
    /// or (with `delta`) misses it by one unit of offset.
    #[test]
    fn coplanar_combinations(
        p1 in any_plane(), p2 in any_plane(), p3 in any_plane(),
        s in -3i64..=3, t in -3i64..=3, delta in -2i128..=2,
    ) {
        let Some(h) = combine(&p1, &p2, s, t) else { return Ok(()) };
        let (a, b, c, d) = h.coefficients();
        let Some(h) = Plane::new(a, b, c, d + delta) else { return Ok(()) };
        check_point([p1, p2, p3], &h);
    }

    /// Vertices that are grid points (possibly far off-centre), planes through them, and
    /// planes through them shifted by one unit.
    #[test]
    fn through_grid_points(
        g in grid_point(),
        n1 in small_normal(), n2 in small_normal(), n3 in small_normal(), nh in small_normal(),
        delta in -1i128..=1,
    ) {
        // Normals below 2^54 and coordinates up to 2^25 keep offsets below 2^83.
        let Some(ps) = planes_through(g, &[n1, n2, n3, nh]) else { return Ok(()) };
        let (a, b, c, d) = ps[3].coefficients();
        let Some(h) = Plane::new(a, b, c, d + delta) else { return Ok(()) };
        check_point([ps[0], ps[1], ps[2]], &h);
        let want = match delta { 0 => Side::On, 1.. => Side::Front, _ => Side::Back };
        if intersect(&[ps[0], ps[1], ps[2]]).is_some() {
            prop_assert_eq!(side_of_intersection(&ps[0], &ps[1], &ps[2], &h), Some(want));
        }
        prop_assert_eq!(h.side_of(&GridPoint::new(g[0], g[1], g[2])), want);
    }

    /// Nearly parallel planes: the vertex is ill-conditioned and far away.
    #[test]
    fn nearly_parallel(p in any_plane(), e1 in -2i64..=2, e2 in -2i64..=2, q in any_plane(), h in any_plane()) {
        let (a, b, c, d) = p.coefficients();
        let Some(p2) = Plane::new(a.saturating_add(e1).clamp(-(1 << 55) + 1, (1 << 55) - 1), b.saturating_add(e2).clamp(-(1 << 55) + 1, (1 << 55) - 1), c, d) else { return Ok(()) };
        check_point([p, p2, q], &h);
        let Some(h2) = combine(&p, &q, 1, 1) else { return Ok(()) };
        check_point([p, p2, q], &h2);
    }
}

#[test]
fn extreme_coefficients_do_not_overflow() {
    let m = (1i64 << 55) - 1;
    let d = (1i128 << 83) - 1;
    let signs = [1i64, -1];
    for &s1 in &signs {
        for &s2 in &signs {
            for &s3 in &signs {
                let p1 = Plane::new(m, s1 * m, s2 * m, d).unwrap();
                let p2 = Plane::new(s3 * m, m, -m, -d).unwrap();
                let p3 = Plane::new(-m, s1 * m, m, d).unwrap();
                let h = Plane::new(m * s2, -m, m * s3, -d * s1 as i128).unwrap();
                check_point([p1, p2, p3], &h);
            }
        }
    }
}

/// A world coordinate in [-1, 1], biased toward grid cell boundaries (half steps, where
/// snapping rounds ties) and nudged by a few ulps.
fn world_coord() -> impl Strategy<Value = f64> {
    let half_step = |(k, ulps): (i64, i64)| nudge((k as f64 + 0.5) * 2f64.powi(-25), ulps);
    let coarse = |(k, ulps): (i64, i64)| nudge(k as f64 * 2f64.powi(-15), ulps).clamp(-1.0, 1.0);
    prop_oneof![
        -1.0f64..1.0,
        (-1000i64..1000, -3i64..=3).prop_map(half_step),
        (-1000i64..1000, -3i64..=3).prop_map(coarse),
    ]
}

/// `x` moved by `ulps` representable values (through zero and subnormals as needed).
fn nudge(mut x: f64, ulps: i64) -> f64 {
    for _ in 0..ulps.abs() {
        x = if ulps > 0 { x.next_up() } else { x.next_down() };
    }
    x
}

fn big(v: i64) -> num_bigint::BigInt {
    num_bigint::BigInt::from(v)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// The side of an eye point (possibly far away) with respect to the plane of a
    /// triangle given in world coordinates, against a bigint evaluation on the snapped
    /// points.
    #[test]
    fn eye_against_world_triangle(
        tri in [[world_coord(), world_coord(), world_coord()], [world_coord(), world_coord(), world_coord()], [world_coord(), world_coord(), world_coord()]],
        dir in [-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0],
        scale in prop_oneof![Just(0.0), 0.0f64..2.0, 1.0f64..1e7],
        on_plane in any::<bool>(),
    ) {
        use glam::DVec3;
        let k = kernel();
        let corners: Vec<DVec3> = tri.iter().map(|p| DVec3::from_array(*p)).collect();
        let polys = k.face_polygons(&corners).unwrap();
        let q = k.quantizer();
        let g: Vec<[i64; 3]> = corners.iter().map(|c| q.snap(*c).unwrap().to_array()).collect();
        let u: Vec<_> = (0..3).map(|i| big(g[1][i] - g[0][i])).collect();
        let v: Vec<_> = (0..3).map(|i| big(g[2][i] - g[0][i])).collect();
        let n = [
            &u[1] * &v[2] - &u[2] * &v[1],
            &u[2] * &v[0] - &u[0] * &v[2],
            &u[0] * &v[1] - &u[1] * &v[0],
        ];
        let zero = num_bigint::BigInt::from(0);
        if n.iter().all(|c| *c == zero) {
            prop_assert!(polys.is_empty());
            return Ok(());
        }
        prop_assert_eq!(polys.len(), 1);
        // An eye on the triangle's plane (a snapped corner) or off it, possibly far away.
        let eye_w = if on_plane { corners[1] } else { corners[0] + DVec3::from_array(dir) * scale };
        let eye = k.point(eye_w).unwrap();
        let e = eye.to_array();
        let val: num_bigint::BigInt = (0..3).map(|i| &n[i] * big(e[i] - g[0][i])).sum();
        let want = match val.sign() {
            num_bigint::Sign::Plus => Side::Front,
            num_bigint::Sign::Minus => Side::Back,
            num_bigint::Sign::NoSign => Side::On,
        };
        let h = k.support(&polys[0]);
        prop_assert_eq!(k.side_of_point(&h, &eye), want);
        if on_plane {
            prop_assert_eq!(want, Side::On);
        }
    }

    /// Three planes through one line never meet in a single point: both the kernel and
    /// the reference say so.
    #[test]
    fn collinear_planes(p1 in any_plane(), p2 in any_plane(), s in -2i64..=2, t in -2i64..=2, h in any_plane()) {
        let Some(p3) = combine(&p1, &p2, s, t) else { return Ok(()) };
        prop_assert!(intersect(&[p1, p2, p3]).is_none());
        prop_assert_eq!(side_of_intersection(&p1, &p2, &p3, &h), None);
        prop_assert!(ImplicitPoint::new(p1, p2, p3).is_none());
    }
}
