//! Shared helpers for the integration tests: an arbitrary-precision reference
//! (num-bigint / num-rational, independent of the kernel's fixed-width arithmetic) and
//! generators biased toward degenerate inputs.

#![allow(dead_code)]

use limn_kernel::{ExactPolygon, Plane, Side};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use proptest::prelude::*;

/// A rational point.
pub type RPoint = [BigRational; 3];

fn big(v: i128) -> BigRational {
    BigRational::from_integer(BigInt::from(v))
}

/// The intersection of three planes by Cramer's rule in rationals (`None` if they do not
/// meet in one point).
pub fn intersect(planes: &[Plane; 3]) -> Option<RPoint> {
    let rows: Vec<([BigRational; 3], BigRational)> = planes
        .iter()
        .map(|p| {
            let (a, b, c, d) = p.coefficients();
            ([big(a as i128), big(b as i128), big(c as i128)], -big(d))
        })
        .collect();
    let det3 = |m: [[BigRational; 3]; 3]| -> BigRational {
        &m[0][0] * (&m[1][1] * &m[2][2] - &m[1][2] * &m[2][1])
            - &m[0][1] * (&m[1][0] * &m[2][2] - &m[1][2] * &m[2][0])
            + &m[0][2] * (&m[1][0] * &m[2][1] - &m[1][1] * &m[2][0])
    };
    let m: [[BigRational; 3]; 3] = std::array::from_fn(|r| rows[r].0.clone());
    let d = det3(m.clone());
    if d.is_zero() {
        return None;
    }
    Some(std::array::from_fn(|j| {
        let mut mj = m.clone();
        for r in 0..3 {
            mj[r][j] = rows[r].1.clone();
        }
        det3(mj) / &d
    }))
}

/// The exact side of a plane at a rational point.
pub fn side_at(h: &Plane, p: &RPoint) -> Side {
    let (a, b, c, d) = h.coefficients();
    let v = big(a as i128) * &p[0] + big(b as i128) * &p[1] + big(c as i128) * &p[2] + big(d);
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
    side_at(h, &vertex(poly, i))
}

/// Vertex `i` of `poly` as a rational point.
pub fn vertex(poly: &ExactPolygon, i: usize) -> RPoint {
    intersect(&poly.vertex_planes(i)).expect("vertex planes meet in a point")
}

/// Twice the signed area of `poly` projected along axis `k` (exact).
pub fn projected_area2(poly: &ExactPolygon, k: usize) -> BigRational {
    let (u, v) = ((k + 1) % 3, (k + 2) % 3);
    let pts: Vec<RPoint> = (0..poly.len()).map(|i| vertex(poly, i)).collect();
    let mut s = BigRational::zero();
    for i in 0..pts.len() {
        let (p, q) = (&pts[i], &pts[(i + 1) % pts.len()]);
        s += &p[u] * &q[v] - &q[u] * &p[v];
    }
    s
}

/// Grid coordinates (26-bit grid): within ±2^25, biased toward small values, the box
/// boundary and clustered values.
pub fn coord() -> impl Strategy<Value = i64> {
    let lim = 1i64 << 25;
    prop_oneof![
        3 => -lim..=lim,
        3 => -16i64..=16,
        1 => prop_oneof![Just(lim), Just(-lim), (lim - 4)..=lim, -lim..=(-lim + 4)],
        1 => (-1000i64..1000).prop_map(|v| v * 4096),
    ]
}

/// A grid point.
pub fn grid_point() -> impl Strategy<Value = [i64; 3]> {
    [coord(), coord(), coord()]
}

/// A plane normal component, biased toward the extremes of the allowed range.
pub fn normal_component() -> impl Strategy<Value = i64> {
    let m = (1i64 << 55) - 1;
    prop_oneof![
        2 => -m..=m,
        2 => -3i64..=3,
        1 => prop_oneof![Just(m), Just(-m), (m - 8)..=m],
        1 => -(1i64 << 27)..=(1i64 << 27),
    ]
}

/// A plane offset, biased toward the extremes of the allowed range.
pub fn offset() -> impl Strategy<Value = i128> {
    let m = (1i128 << 83) - 1;
    prop_oneof![
        2 => -m..=m,
        2 => -3i128..=3,
        1 => prop_oneof![Just(m), Just(-m), (m - 8)..=m],
    ]
}

/// Any plane within the kernel's coefficient bounds.
pub fn any_plane() -> impl Strategy<Value = Plane> {
    (
        normal_component(),
        normal_component(),
        normal_component(),
        offset(),
    )
        .prop_filter_map("zero normal", |(a, b, c, d)| Plane::new(a, b, c, d))
}

/// The kernel used by the polygon tests: box [-1, 1]³, 26 bits, so the step is 2^-25 and
/// grid coordinates reach ±2^25.
pub fn kernel() -> limn_kernel::ExactKernel {
    use glam::DVec3;
    limn_kernel::ExactKernel::new(DVec3::splat(-1.0), DVec3::splat(1.0)).unwrap()
}

/// Polygons of the face with the given grid corners.
pub fn face(k: &limn_kernel::ExactKernel, pts: &[[i64; 3]]) -> Vec<ExactPolygon> {
    use limn_kernel::Kernel;
    let s = k.step();
    let corners: Vec<glam::DVec3> = pts
        .iter()
        .map(|p| glam::DVec3::new(p[0] as f64 * s, p[1] as f64 * s, p[2] as f64 * s))
        .collect();
    k.face_polygons(&corners).expect("corners inside the grid")
}

/// A convex planar outline on the lattice `o + i·u + j·v` (exactly planar grid points).
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
