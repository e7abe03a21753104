//! Shared helpers for the integration tests: an arbitrary-precision reference
//! (num-rational on the planes' definitions, independent of the kernel's arithmetic) and
//! generators biased toward degenerate inputs.
//!
//! Every f64 enters the reference as its exact `BigRational`. Input points are evaluated
//! in rationals; implicit vertices (intersections of three planes) are evaluated
//! homogeneously in integers, each plane's rational coefficients multiplied by a positive
//! power of two (no gcd on numbers of thousands of bits, which is what made a rational
//! Cramer's rule slow at 1e±300).

#![allow(dead_code)]

use limn_kernel::{ExactPolygon, Plane, PlaneDef, PolygonSide, Side};
use num_bigint::{BigInt, Sign};
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use proptest::prelude::*;

/// A rational point.
pub type RPoint = [BigRational; 3];

/// The lattice step used by the integer-lattice generators: lattice point `g` is the
/// world point `g · STEP`, exactly.
pub const STEP: f64 = 1.0 / 33_554_432.0; // 2^-25

/// The exact rational value of an f64.
pub fn q(x: f64) -> BigRational {
    BigRational::from_float(x).expect("finite")
}

/// A rational point from f64 coordinates.
pub fn qp(p: [f64; 3]) -> RPoint {
    p.map(q)
}

fn sub(a: &RPoint, b: &RPoint) -> RPoint {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

fn cross(a: &RPoint, b: &RPoint) -> RPoint {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

/// The exact coefficients `(n, d)` of a plane, from its definition.
pub fn coefficients(pl: &Plane) -> (RPoint, BigRational) {
    let (n, p) = match pl.definition() {
        PlaneDef::Through([p, qq, r]) => {
            let p = qp(p);
            (cross(&sub(&qp(qq), &p), &sub(&qp(r), &p)), p)
        }
        PlaneDef::Edge { p, q: qq, k, flip } => {
            let p = qp(p);
            let w = sub(&qp(qq), &p);
            let z = BigRational::zero();
            let n = match k {
                0 => [z, w[2].clone(), -&w[1]],
                1 => [-&w[2], z, w[0].clone()],
                _ => [w[1].clone(), -&w[0], z],
            };
            (if flip { n.map(|x| -x) } else { n }, p)
        }
        PlaneDef::Along { p, q: qq, d } => {
            let p = qp(p);
            (cross(&sub(&qp(qq), &p), &qp(d)), p)
        }
        PlaneDef::PointNormal { p, n } => (qp(n), qp(p)),
    };
    let d = -(&n[0] * &p[0] + &n[1] * &p[1] + &n[2] * &p[2]);
    if pl.is_flipped() {
        (n.map(|x| -x), -d)
    } else {
        (n, d)
    }
}

/// Whether a positive integer is a power of two.
fn is_pow2(x: &BigInt) -> bool {
    x.sign() == Sign::Plus && x.bits() == x.trailing_zeros().unwrap_or(0) + 1
}

/// The values defining a plane (points, normal) as integers: each f64 as an exact
/// rational, all multiplied by their largest denominator (a power of two).
/// Returns them with the exponent `l` of that denominator `2^l`.
fn integer_values<const N: usize>(v: [[f64; 3]; N]) -> ([[BigInt; 3]; N], u64) {
    let r = v.map(qp);
    let tz = |x: &BigRational| x.denom().trailing_zeros().unwrap_or(0);
    assert!(r.iter().flatten().all(|x| is_pow2(x.denom())), "dyadic");
    let l = r.iter().flatten().map(tz).max().unwrap_or(0);
    (r.map(|p| p.map(|x| x.numer() << (l - tz(&x)) as usize)), l)
}

fn isub(a: &[BigInt; 3], b: &[BigInt; 3]) -> [BigInt; 3] {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

fn icross(a: &[BigInt; 3], b: &[BigInt; 3]) -> [BigInt; 3] {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

/// A plane's coefficients `[a, b, c, d]` in integers: a positive multiple of the exact
/// rational coefficients ([`coefficients`]), computed from the definition with every
/// defining value scaled by the same power of two `2^l`, so no gcd is ever taken. The
/// normal computed so is `2^l` times too large relative to the offset (whose extra
/// factor `p` carries), hence `n·2^l` in the row.
pub fn integer_row(pl: &Plane) -> [BigInt; 4] {
    let (n, p, l) = match pl.definition() {
        PlaneDef::Through(pts) => {
            let ([p, qq, r], l) = integer_values(pts);
            (icross(&isub(&qq, &p), &isub(&r, &p)), p, l)
        }
        PlaneDef::Edge { p, q: qq, k, flip } => {
            let ([p, qq], l) = integer_values([p, qq]);
            let w = isub(&qq, &p);
            let z = BigInt::zero();
            let n = match k {
                0 => [z, w[2].clone(), -&w[1]],
                1 => [-&w[2], z, w[0].clone()],
                _ => [w[1].clone(), -&w[0], z],
            };
            (if flip { n.map(|x| -x) } else { n }, p, l)
        }
        PlaneDef::Along { p, q: qq, d } => {
            // Like `Through`: a cross product of two scaled vectors.
            let ([p, qq, d], l) = integer_values([p, qq, d]);
            (icross(&isub(&qq, &p), &d), p, l)
        }
        PlaneDef::PointNormal { p, n } => {
            let ([p, n], l) = integer_values([p, n]);
            (n, p, l)
        }
    };
    let d = -(&n[0] * &p[0] + &n[1] * &p[1] + &n[2] * &p[2]);
    let row = [
        &n[0] << l as usize,
        &n[1] << l as usize,
        &n[2] << l as usize,
        d,
    ];
    if pl.is_flipped() {
        row.map(|x| -x)
    } else {
        row
    }
}

fn det3(m: &[[BigInt; 3]; 3]) -> BigInt {
    &m[0][0] * (&m[1][1] * &m[2][2] - &m[1][2] * &m[2][1])
        - &m[0][1] * (&m[1][0] * &m[2][2] - &m[1][2] * &m[2][0])
        + &m[0][2] * (&m[1][0] * &m[2][1] - &m[1][1] * &m[2][0])
}

/// The intersection of three planes as exact homogeneous integer coordinates `(X, D)`
/// (the point is `X / D`), by Cramer's rule; `None` if they do not meet in one point.
pub fn intersect_homogeneous(planes: &[Plane; 3]) -> Option<([BigInt; 3], BigInt)> {
    let rows = planes.each_ref().map(integer_row);
    let m: [[BigInt; 3]; 3] = std::array::from_fn(|r| std::array::from_fn(|c| rows[r][c].clone()));
    let d = det3(&m);
    if d.is_zero() {
        return None;
    }
    let x = std::array::from_fn(|j| {
        let mut mj = m.clone();
        for r in 0..3 {
            mj[r][j] = -&rows[r][3];
        }
        det3(&mj)
    });
    Some((x, d))
}

/// The intersection of three planes in rationals (`None` if they do not meet in one
/// point).
pub fn intersect(planes: &[Plane; 3]) -> Option<RPoint> {
    let (x, d) = intersect_homogeneous(planes)?;
    Some(x.map(|v| BigRational::new(v, d.clone())))
}

/// The exact side of `h` at the intersection of three planes (`None` if they do not meet
/// in one point): the sign of `(n_h·X + d_h·D)·D`, in integers.
pub fn implicit_side(planes: &[Plane; 3], h: &Plane) -> Option<Side> {
    let (x, d) = intersect_homogeneous(planes)?;
    let r = integer_row(h);
    let v = &r[0] * &x[0] + &r[1] * &x[1] + &r[2] * &x[2] + &r[3] * &d;
    let s = if d.is_negative() { -v } else { v };
    Some(if s.is_positive() {
        Side::Front
    } else if s.is_negative() {
        Side::Back
    } else {
        Side::On
    })
}

/// The exact side of a plane at a rational point.
pub fn side_at(h: &Plane, p: &RPoint) -> Side {
    let (n, d) = coefficients(h);
    let v = &n[0] * &p[0] + &n[1] * &p[1] + &n[2] * &p[2] + d;
    if v.is_positive() {
        Side::Front
    } else if v.is_negative() {
        Side::Back
    } else {
        Side::On
    }
}

/// The reference side of `h` at vertex `i` of `poly`.
pub fn vertex_side(poly: &ExactPolygon, i: usize, h: &Plane) -> Side {
    implicit_side(&poly.vertex_planes(i), h).expect("vertex planes meet in a point")
}

/// Vertex `i` of `poly` as a rational point.
pub fn vertex(poly: &ExactPolygon, i: usize) -> RPoint {
    intersect(&poly.vertex_planes(i)).expect("vertex planes meet in a point")
}

/// The reference classification of `poly` against `h`.
pub fn reference_classify(poly: &ExactPolygon, h: &Plane) -> PolygonSide {
    let sides: Vec<Side> = (0..poly.len()).map(|i| vertex_side(poly, i, h)).collect();
    match (sides.contains(&Side::Front), sides.contains(&Side::Back)) {
        (true, true) => PolygonSide::Spanning,
        (true, false) => PolygonSide::Front,
        (false, true) => PolygonSide::Back,
        _ if same_facing(&poly.support(), h) => PolygonSide::Coplanar,
        _ => PolygonSide::CoplanarOpposite,
    }
}

/// Whether the normals of two planes have a positive dot product (rationals).
pub fn same_facing(a: &Plane, b: &Plane) -> bool {
    let (n, _) = coefficients(a);
    let (m, _) = coefficients(b);
    (&n[0] * &m[0] + &n[1] * &m[1] + &n[2] * &m[2]).is_positive()
}

/// Twice the signed area of `poly` projected along axis `k` (exact).
pub fn projected_area2(poly: &ExactPolygon, k: usize) -> BigRational {
    let (u, v) = ((k + 1) % 3, (k + 2) % 3);
    let pts: Vec<RPoint> = (0..poly.len()).map(|i| vertex(poly, i)).collect();
    let mut s = BigRational::zero();
    for i in 0..pts.len() {
        let (p, qq) = (&pts[i], &pts[(i + 1) % pts.len()]);
        s += &p[u] * &qq[v] - &qq[u] * &p[v];
    }
    s
}

/// Lattice coordinates: within ±2^25, biased toward small values, the box boundary and
/// clustered values.
pub fn coord() -> impl Strategy<Value = i64> {
    let lim = 1i64 << 25;
    prop_oneof![
        3 => -lim..=lim,
        3 => -16i64..=16,
        1 => prop_oneof![Just(lim), Just(-lim), (lim - 4)..=lim, -lim..=(-lim + 4)],
        1 => (-1000i64..1000).prop_map(|v| v * 4096),
    ]
}

/// A lattice point.
pub fn grid_point() -> impl Strategy<Value = [i64; 3]> {
    [coord(), coord(), coord()]
}

/// The world point of a lattice point (exact).
pub fn gp(a: [i64; 3]) -> [f64; 3] {
    a.map(|v| v as f64 * STEP)
}

/// The plane through three lattice points, if they are not collinear.
pub fn plane_g(a: [i64; 3], b: [i64; 3], c: [i64; 3]) -> Option<Plane> {
    Plane::through(gp(a), gp(b), gp(c)).ok()
}

/// `x` moved by `ulps` representable values (through zero and subnormals as needed).
pub fn nudge(mut x: f64, ulps: i64) -> f64 {
    for _ in 0..ulps.abs() {
        x = if ulps > 0 { x.next_up() } else { x.next_down() };
    }
    x
}

/// An f64 coordinate biased toward hard cases: uniform, small integers, values a few ulps
/// from simple ones, and every magnitude from 1e-300 to 1e300.
pub fn world_coord() -> impl Strategy<Value = f64> {
    prop_oneof![
        3 => -1.0f64..1.0,
        2 => (-8i64..=8, -3i64..=3).prop_map(|(k, u)| nudge(k as f64 * 0.125, u)),
        1 => (-1.0f64..1.0, -300i32..=300).prop_map(|(m, e)| m * 10f64.powi(e)),
    ]
}

/// A world point.
pub fn world_point() -> impl Strategy<Value = [f64; 3]> {
    [world_coord(), world_coord(), world_coord()]
}

/// Any plane: through three world points, or a point and a normal.
pub fn any_plane() -> impl Strategy<Value = Plane> {
    prop_oneof![
        (world_point(), world_point(), world_point())
            .prop_filter_map("collinear", |(a, b, c)| Plane::through(a, b, c).ok()),
        (world_point(), world_point())
            .prop_filter_map("zero normal", |(p, n)| Plane::point_normal(p, n).ok()),
    ]
}

/// The kernel used by the polygon tests.
pub fn kernel() -> limn_kernel::ExactKernel {
    limn_kernel::ExactKernel::new()
}

/// Polygons of the face with the given lattice corners.
pub fn face(k: &limn_kernel::ExactKernel, pts: &[[i64; 3]]) -> Vec<ExactPolygon> {
    use limn_kernel::Kernel;
    let corners: Vec<glam::DVec3> = pts
        .iter()
        .map(|p| glam::DVec3::from_array(gp(*p)))
        .collect();
    k.face_polygons(&corners).expect("finite corners")
}

/// A convex planar outline on the lattice `o + i·u + j·v` (exactly planar points).
pub fn lattice_polygon() -> impl Strategy<Value = Vec<[i64; 3]>> {
    let small = || -300i64..=300;
    let vec3 = move || [small(), small(), small()];
    let shapes = prop_oneof![
        Just(vec![(0i64, 0i64), (1, 0), (0, 1)]),
        Just(vec![(0, 0), (1, 0), (1, 1), (0, 1)]),
        Just(vec![(0, 0), (2, 0), (3, 1), (2, 2), (0, 2), (-1, 1)]),
        Just(vec![(0, 0), (4, 1), (5, 3), (1, 4)]),
    ];
    (
        [
            -(1i64 << 20)..(1 << 20),
            -(1i64 << 20)..(1 << 20),
            -(1i64 << 20)..(1 << 20),
        ],
        vec3(),
        vec3(),
        1i64..2000,
        shapes,
    )
        .prop_map(|(o, u, v, scale, shape)| {
            shape
                .iter()
                .map(|&(i, j)| std::array::from_fn(|a| o[a] + scale * (i * u[a] + j * v[a])))
                .collect()
        })
}
