//! The eye at infinity (a parallel projection): plane sides and orientations toward a
//! direction agree with exact integer arithmetic and with a far finite eye.

use glam::DVec3;
use limn_kernel::{ExactKernel, FloatKernel, Kernel, Orientation, Side};

/// A small deterministic source of lattice points.
struct Lcg(u64);

impl Lcg {
    fn coord(&mut self) -> i64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 33) % 9) as i64 - 4
    }
    fn point(&mut self) -> [i64; 3] {
        [self.coord(), self.coord(), self.coord()]
    }
}

fn f(p: [i64; 3]) -> [f64; 3] {
    p.map(|v| v as f64)
}

fn sign(v: i64) -> i64 {
    v.signum()
}

/// `d · ((a − c) × (b − c))` in integers.
fn det(d: [i64; 3], a: [i64; 3], b: [i64; 3], c: [i64; 3]) -> i64 {
    let u = [a[0] - c[0], a[1] - c[1], a[2] - c[2]];
    let v = [b[0] - c[0], b[1] - c[1], b[2] - c[2]];
    let n = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    d[0] * n[0] + d[1] * n[1] + d[2] * n[2]
}

#[test]
fn orientation_toward_a_direction_is_exact_and_matches_a_far_eye() {
    let k = ExactKernel::new();
    let mut r = Lcg(7);
    let (mut zero, mut pos, mut neg) = (0, 0, 0);
    for _ in 0..4000 {
        let (a, b, c, d) = (r.point(), r.point(), r.point(), r.point());
        let want = match sign(det(d, a, b, c)) {
            1 => Orientation::Positive,
            -1 => Orientation::Negative,
            _ => Orientation::Coplanar,
        };
        let got = k.orientation_toward(DVec3::from_array(f(d)), &f(a), &f(b), &f(c));
        assert_eq!(got, want, "{a:?} {b:?} {c:?} toward {d:?}");
        match want {
            Orientation::Positive => pos += 1,
            Orientation::Negative => neg += 1,
            Orientation::Coplanar => zero += 1,
        }
        // A finite eye far out along d orients the same way whenever the sign is not 0.
        if want != Orientation::Coplanar {
            let e = [0, 1, 2].map(|i| (c[i] + 1_000_000 * d[i]) as f64);
            assert_eq!(k.orientation(&e, &f(a), &f(b), &f(c)), want);
        }
    }
    assert!(zero > 50 && pos > 500 && neg > 500, "{zero} {pos} {neg}");
}

#[test]
fn side_of_a_direction_is_the_sign_of_the_normal() {
    let k = ExactKernel::new();
    let mut r = Lcg(11);
    let mut on = 0;
    for _ in 0..4000 {
        let (a, b, c, d) = (r.point(), r.point(), r.point(), r.point());
        let Ok(plane) = limn_kernel::Plane::through(f(c), f(a), f(b)) else {
            continue;
        };
        let want = match sign(det(d, a, b, c)) {
            1 => Side::Front,
            -1 => Side::Back,
            _ => Side::On,
        };
        on += (want == Side::On) as usize;
        assert_eq!(k.side_of_direction(&plane, DVec3::from_array(f(d))), want);
        assert_eq!(
            k.side_of_direction(&plane.flipped(), DVec3::from_array(f(d))),
            want.flip()
        );
    }
    assert!(on > 50);
}

#[test]
fn nearly_parallel_directions_are_decided_exactly() {
    // A plane through points a few ulps off a vertical plane: the f64 dot product of
    // the rounded normal cannot tell, the exact one can.
    let k = ExactKernel::new();
    let e = f64::EPSILON;
    let plane = limn_kernel::Plane::through([0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 0.0, e])
        .expect("a plane");
    // Normal = (0,1,0)×(1,0,e) = (e, 0, −1): toward (1, 0, e) it is exactly 0.
    assert_eq!(
        k.side_of_direction(&plane, DVec3::new(1.0, 0.0, e)),
        Side::On
    );
    assert_eq!(
        k.side_of_direction(&plane, DVec3::new(1.0, 0.0, e * 0.5)),
        Side::Front
    );
    assert_eq!(
        k.side_of_direction(&plane, DVec3::new(1.0, 0.0, e * 2.0)),
        Side::Back
    );
}

#[test]
fn the_float_kernel_agrees_on_clear_cases() {
    let k = FloatKernel::with_epsilon(1e-9).unwrap();
    let p = k.plane_through(DVec3::ZERO, DVec3::Z).unwrap();
    assert_eq!(
        k.side_of_direction(&p, DVec3::new(0.0, 1.0, 2.0)),
        Side::Front
    );
    assert_eq!(
        k.side_of_direction(&p, DVec3::new(0.0, 1.0, -2.0)),
        Side::Back
    );
    assert_eq!(k.side_of_direction(&p, DVec3::X), Side::On);
    let (a, b, c) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0]);
    assert_eq!(
        k.orientation_toward(DVec3::Z, &a, &b, &c),
        Orientation::Positive
    );
}
