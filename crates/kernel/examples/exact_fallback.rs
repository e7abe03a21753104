//! Times the exact evaluation of the side of a plane at an implicit vertex (the
//! intersection of three planes), in dyadic big-integer arithmetic and in fixed-capacity
//! integers, on torus-like inputs: vertices where three face planes of a torus mesh meet,
//! tested against a fourth face plane and against planes through the rounded vertex
//! (within an ulp or so of it). Prints nanoseconds per call. Run with `cargo run
//! --release -p limn-kernel --example exact_fallback`.

use std::hint::black_box;
use std::time::Instant;

use limn_kernel::Plane;
use limn_kernel::{exact_side_of_intersection, ExactPath};

fn torus(u: usize, v: usize, nu: usize, nv: usize) -> [f64; 3] {
    let (a, b) = (
        std::f64::consts::TAU * u as f64 / nu as f64,
        std::f64::consts::TAU * v as f64 / nv as f64,
    );
    let (big, small) = (1.0, 0.35);
    [
        (big + small * b.cos()) * a.cos(),
        (big + small * b.cos()) * a.sin(),
        small * b.sin(),
    ]
}

/// The intersection of three planes in f64 (Cramer's rule on the approximations).
fn solve(p: [&Plane; 3]) -> Option<[f64; 3]> {
    let r = p.map(|p| p.approx());
    let n = r.map(|c| [c[0], c[1], c[2]]);
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let (c23, c31, c12) = (cross(n[1], n[2]), cross(n[2], n[0]), cross(n[0], n[1]));
    let det = dot(n[0], c23);
    if det == 0.0 {
        return None;
    }
    let h = r.map(|c| -c[3]);
    Some([0, 1, 2].map(|j| (h[0] * c23[j] + h[1] * c31[j] + h[2] * c12[j]) / det))
}

fn main() {
    let (nu, nv) = (100, 50);
    let face = |u: usize, v: usize| {
        let (u1, v1) = ((u + 1) % nu, (v + 1) % nv);
        Plane::through(
            torus(u, v, nu, nv),
            torus(u1, v, nu, nv),
            torus(u1, v1, nu, nv),
        )
        .ok()
    };
    let mut cases = Vec::new();
    for u in 0..nu {
        for v in 0..nv {
            let (up, vp) = ((u + nu - 1) % nu, (v + nv - 1) % nv);
            let (Some(a), Some(b), Some(c), Some(d)) =
                (face(u, v), face(up, v), face(u, vp), face(up, vp))
            else {
                continue;
            };
            cases.push([a.clone(), b.clone(), c.clone(), d]);
            if let Some(x) = solve([&a, &b, &c]) {
                let far = torus((u + nu / 3) % nu, (v + 7) % nv, nu, nv);
                let other = torus((u + 2 * nu / 3) % nu, (v + 19) % nv, nu, nv);
                if let Ok(h) = Plane::through(x, far, other) {
                    cases.push([a, b, c, h]);
                }
            }
        }
    }
    let mut fast_declined = 0;
    for c in &cases {
        let f = exact_side_of_intersection(&c[0], &c[1], &c[2], &c[3], ExactPath::Fast);
        let d = exact_side_of_intersection(&c[0], &c[1], &c[2], &c[3], ExactPath::Dyadic);
        match f {
            Some(s) => assert_eq!(Some(s), d),
            None => fast_declined += 1,
        }
    }
    let time = |path: ExactPath| {
        let mut best = f64::INFINITY;
        for _ in 0..7 {
            let t = Instant::now();
            for c in &cases {
                black_box(exact_side_of_intersection(
                    black_box(&c[0]),
                    &c[1],
                    &c[2],
                    &c[3],
                    path,
                ));
            }
            best = best.min(t.elapsed().as_secs_f64() * 1e9 / cases.len() as f64);
        }
        best
    };
    let dy = time(ExactPath::Dyadic);
    let fa = time(ExactPath::Fast);
    println!(
        "{} exact side_of_intersection calls (torus {nu}×{nv}), fast path declined {fast_declined}",
        cases.len()
    );
    println!("dyadic: {dy:.0} ns/call");
    println!("fast:   {fa:.0} ns/call ({:.1}× faster)", dy / fa);
}
