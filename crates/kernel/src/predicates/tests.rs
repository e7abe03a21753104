//! The fixed-capacity path against the dyadic path: the same sign on random,
//! near-degenerate, exactly degenerate and widely spread inputs, and on both sides of
//! the capacity limits.

use std::cmp::Ordering;

use super::fast::{self, Fast};
use super::*;

/// xorshift64*: reproducible inputs without a dependency.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }

    /// A value in `[-1, 1)` with a full mantissa.
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

/// How coordinates are drawn.
#[derive(Clone, Copy, Debug)]
enum Style {
    /// Full mantissas times `2^s`.
    Scaled(i32),
    /// Small integers times `2^s` (exact degeneracies: coplanar, parallel, on).
    Grid(i32),
    /// Full mantissas with exponents spread over `[s − w, s]`, some zeros.
    Spread(i32, i32),
}

/// `2^k` for `k ≤ 1023` (zero below `−1074`).
fn pow2(k: i32) -> f64 {
    if k < -1074 {
        0.0
    } else if k >= -1022 {
        f64::from_bits(((k + 1023) as u64) << 52)
    } else {
        f64::from_bits(1 << (k + 1074))
    }
}

fn coord(rng: &mut Rng, style: Style) -> f64 {
    match style {
        Style::Scaled(s) => rng.unit() * pow2(s),
        Style::Grid(s) => (rng.below(7) as f64 - 3.0) * pow2(s),
        Style::Spread(s, w) => {
            if rng.below(8) == 0 {
                return 0.0;
            }
            let k = s - rng.below(w as u64 + 1) as i32;
            rng.unit() * pow2(k)
        }
    }
}

fn point(rng: &mut Rng, style: Style) -> [f64; 3] {
    [coord(rng, style), coord(rng, style), coord(rng, style)]
}

/// A random plane of any kind and orientation (`None` for a degenerate draw).
fn plane(rng: &mut Rng, style: Style) -> Option<Plane> {
    let p = match rng.below(4) {
        0 => Plane::through(point(rng, style), point(rng, style), point(rng, style)).ok()?,
        1 => {
            let (a, b) = (point(rng, style), point(rng, style));
            let k = rng.below(3) as usize;
            let (u, v) = crate::plane::plane_axes(k);
            if a[u] == b[u] && a[v] == b[v] {
                return None;
            }
            Plane::edge(a, b, k, rng.below(2) == 0)
        }
        2 => Plane::point_normal(point(rng, style), point(rng, style)).ok()?,
        _ => Plane::along(point(rng, style), point(rng, style), point(rng, style)).ok()?,
    };
    Some(if rng.below(2) == 0 { p.flipped() } else { p })
}

/// The point moved by up to `k` ulps in each coordinate.
fn nudge(rng: &mut Rng, x: [f64; 3], k: u64) -> [f64; 3] {
    x.map(|v| {
        let steps = rng.below(2 * k + 1) as i64 - k as i64;
        let mut v = v;
        for _ in 0..steps.unsigned_abs() {
            v = if steps > 0 {
                v.next_up()
            } else {
                v.next_down()
            };
        }
        v
    })
}

/// Compares both paths; returns whether the fast path decided.
fn agree(p: [&Plane; 4]) -> bool {
    let dy = side_of_intersection_dyadic(p[0], p[1], p[2], p[3]);
    match fast::side_of_intersection(p[0], p[1], p[2], p[3]) {
        Fast::Done(s) => {
            assert_eq!(s, dy, "{p:?}");
            true
        }
        Fast::TooWide => false,
    }
}

/// Compares the homogeneous coordinates: the same point (`X_f·D_d = X_d·D_f`) and the
/// same sign of `D`.
fn same_homogeneous(p: [&Plane; 3]) {
    let (xd, dd) = homogeneous_dyadic(p[0], p[1], p[2]);
    if let Fast::Done((xf, df)) = fast::homogeneous(p[0], p[1], p[2]) {
        assert_eq!(df.signum(), dd.signum(), "{p:?}");
        for j in 0..3 {
            assert_eq!(&xf[j] * &dd, &xd[j] * &df, "{p:?}");
        }
    }
}

fn run(seed: u64, style: Style, cases: usize) -> (usize, usize) {
    let mut rng = Rng(seed);
    let (mut done, mut total) = (0, 0);
    let mut tries = 0;
    while total < cases && tries < 50 * cases {
        tries += 1;
        let (Some(a), Some(b), Some(c)) = (
            plane(&mut rng, style),
            plane(&mut rng, style),
            plane(&mut rng, style),
        ) else {
            continue;
        };
        same_homogeneous([&a, &b, &c]);
        // A random plane, and planes through the rounded vertex (nudged by a few ulps).
        let mut hs: Vec<Plane> = plane(&mut rng, style).into_iter().collect();
        if let Some(x) = rounded_intersection(&a, &b, &c) {
            if x.iter().all(|v| v.is_finite()) {
                for k in [0, 1, 2] {
                    let y = nudge(&mut rng, x, k);
                    if let Ok(h) = Plane::through(y, point(&mut rng, style), point(&mut rng, style))
                    {
                        hs.push(h);
                    }
                    if let Ok(h) = Plane::point_normal(y, point(&mut rng, style)) {
                        hs.push(h.flipped());
                    }
                }
            }
        }
        for h in &hs {
            total += 1;
            done += agree([&a, &b, &c, h]) as usize;
        }
    }
    (done, total)
}

#[test]
fn fast_matches_dyadic_on_random_and_near_degenerate_inputs() {
    for (i, style) in [
        Style::Scaled(0),
        Style::Scaled(-1000),
        Style::Scaled(900),
        Style::Grid(0),
        Style::Grid(-1070),
        Style::Grid(1000),
    ]
    .into_iter()
    .enumerate()
    {
        let (done, total) = run(0x9e37_79b9_7f4a_7c15 + i as u64, style, 2000);
        assert!(total >= 2000, "{style:?}: {total}");
        // Declined: only a nudge of a zero coordinate to a subnormal (grid scenes).
        assert!(
            10 * done >= 9 * total,
            "{style:?}: declined {}",
            total - done
        );
    }
}

#[test]
fn fast_matches_dyadic_across_exponents() {
    // Spreads from a few bits to far beyond the capacity: both outcomes occur.
    let mut declined = 0;
    let mut decided = 0;
    for (i, w) in [0, 10, 30, 60, 100, 150, 300, 2000].into_iter().enumerate() {
        let (done, total) = run(12345 + i as u64, Style::Spread(0, w), 800);
        decided += done;
        declined += total - done;
    }
    assert!(decided > 1000 && declined > 100, "{decided} {declined}");
}

/// Four planes through points spanning `bits` bits: coordinates `1` and `2^(1−bits)`
/// times odd integers. Returns the fast outcome and checks it against the dyadic one.
fn spanning(bits: i32, rng: &mut Rng) -> Fast<Option<Ordering>> {
    let lo = pow2(-bits);
    let mut pt = || {
        [0, 1, 2].map(|_| match rng.below(3) {
            0 => (2 * rng.below(1000) + 1) as f64 * lo,
            1 => 0.5 + rng.unit().abs() * 0.25,
            _ => -(rng.unit().abs() * 0.5),
        })
    };
    loop {
        let planes: Vec<Plane> = (0..4)
            .filter_map(|_| Plane::through(pt(), pt(), pt()).ok())
            .collect();
        if planes.len() < 4 {
            continue;
        }
        let p = [&planes[0], &planes[1], &planes[2], &planes[3]];
        let f = fast::side_of_intersection(p[0], p[1], p[2], p[3]);
        if let Fast::Done(s) = f {
            assert_eq!(s, side_of_intersection_dyadic(p[0], p[1], p[2], p[3]));
        }
        return f;
    }
}

#[test]
fn capacity_boundary() {
    let mut rng = Rng(7);
    // The bound is 9b + 21 bits for four planes through points: 1664 bits hold b ≤ 182,
    // and the top bit of the span is reached exactly by the coordinates drawn.
    for bits in [12, 53, 80, 83, 84, 120, 160, 181, 182] {
        for _ in 0..20 {
            assert!(
                matches!(spanning(bits, &mut rng), Fast::Done(_)),
                "{bits} bits declined"
            );
        }
    }
    for bits in [183, 184, 300] {
        for _ in 0..5 {
            assert_eq!(spanning(bits, &mut rng), Fast::TooWide, "{bits} bits");
        }
    }
}

#[test]
fn exact_on_and_parallel_cases() {
    let p = |a, b, c| Plane::through(a, b, c).unwrap();
    let z = p([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
    let x = p([0.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    let y = p([0.0, 0.0, 0.0], [0.0, 0.0, 1.0], [1.0, 0.0, 0.0]);
    let diag = p([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    let z2 = p([5.0, 5.0, 3.0], [6.0, 5.0, 3.0], [5.0, 6.0, 3.0]);
    // The origin: on a plane through it, behind the diagonal plane (normal (1,1,1)).
    let through0 = p([-1.0, 1.0, 0.0], [0.0, 0.0, 0.0], [3.0, 0.5, 7.0]);
    for (h, want, o) in [
        (&through0, Side::On, Ordering::Equal),
        (&diag, Side::Back, Ordering::Less),
    ] {
        assert_eq!(side_of_intersection(&z, &x, &y, h), Some(want));
        assert_eq!(
            exact_side_of_intersection(&z, &x, &y, h, ExactPath::Fast),
            Some(Some(o))
        );
    }
    assert_eq!(side_of_intersection(&z, &z2, &x, &diag), None);
    assert_eq!(
        exact_side_of_intersection(&z, &z2, &x, &diag, ExactPath::Fast),
        Some(None)
    );
}

#[test]
fn orient3d_fast_matches_dyadic() {
    let mut rng = Rng(99);
    let mut decided = 0;
    for i in 0..4000 {
        let style = match i % 4 {
            0 => Style::Scaled(-400),
            1 => Style::Grid(700),
            2 => Style::Spread(200, 60),
            _ => Style::Spread(0, 1500),
        };
        let (a, b, c) = (
            point(&mut rng, style),
            point(&mut rng, style),
            point(&mut rng, style),
        );
        // d on or near the plane of a, b, c when possible.
        let d = if i % 2 == 0 {
            let t = rng.unit();
            nudge(&mut rng, [0, 1, 2].map(|j| a[j] + t * (b[j] - a[j])), 1)
        } else {
            point(&mut rng, style)
        };
        let dy = orient3d_dyadic(a, b, c, d);
        if let Fast::Done(s) = fast::orient3d(a, b, c, d) {
            assert_eq!(s, dy, "{a:?} {b:?} {c:?} {d:?}");
            decided += 1;
        }
    }
    assert!(decided > 3000, "{decided}");
}

/// Whether `|X/D − pos| ≤ err` holds exactly.
fn within(x: &Dyadic, d: &Dyadic, pos: f64, err: f64) -> bool {
    let lo = &Dyadic::from_f64(pos) - &Dyadic::from_f64(err);
    let hi = &Dyadic::from_f64(pos) + &Dyadic::from_f64(err);
    let s = d.signum();
    let above_lo = (x - &(&lo * d)).signum();
    let below_hi = (&(&hi * d) - x).signum();
    above_lo != s.reverse() && below_hi != s.reverse()
}

#[test]
fn approximate_encloses_the_exact_intersection() {
    let mut rng = Rng(0x005e_ed0f_a990);
    let mut counts = Vec::new();
    for style in [
        Style::Scaled(0),
        Style::Scaled(-300),
        Style::Scaled(300),
        Style::Grid(0),
        Style::Spread(0, 60),
        Style::Spread(-200, 120),
        Style::Spread(200, 120),
        Style::Scaled(-1000),
        // Magnitudes from 1e-289 to 1e162 mixed with zeros: coefficient bounds overflow
        // while values stay finite (an infinite bound times a zero is NaN).
        Style::Spread(540, 1500),
    ] {
        let mut n = 0;
        let mut tries = 0;
        while n < 1500 && tries < 100_000 {
            tries += 1;
            let (Some(a), Some(b), Some(mut c)) = (
                plane(&mut rng, style),
                plane(&mut rng, style),
                plane(&mut rng, style),
            ) else {
                continue;
            };
            // Every few cases a third plane nearly parallel to the line of the other two.
            if rng.below(3) == 0 {
                let [a0, a1, a2, _] = a.approx();
                let [b0, b1, b2, _] = b.approx();
                let m = [a0 + b0, a1 + b1, a2 + b2].map(|v| v * (1.0 + 1e-9 * rng.unit()));
                if let Ok(p) = Plane::point_normal(point(&mut rng, style), m) {
                    c = p;
                }
            }
            let Some((pos, err)) = approximate(&a, &b, &c) else {
                continue;
            };
            if !err.is_finite() {
                continue;
            }
            let (x, d) = homogeneous_dyadic(&a, &b, &c);
            assert!(!d.is_zero(), "{a:?} {b:?} {c:?}");
            for j in 0..3 {
                assert!(
                    within(&x[j], &d, pos[j], err),
                    "{style:?}: coordinate {j}: {} ± {err} misses the exact point of {a:?} {b:?} {c:?}",
                    pos[j]
                );
            }
            n += 1;
        }
        counts.push(n);
    }
    assert!(counts.iter().all(|&n| n == 1500), "{counts:?}");
}

/// The split of a raw triangle with corners near 1e161 and 0 by a plane through its
/// interior: the support plane's offset bound overflows, and the NaN bound it gives a
/// cut vertex must read as no bound (not as the vertex exactly).
#[test]
fn approximate_reports_overflowed_bounds_as_infinite() {
    let tri = [
        [-8.960959184079691e161, 0.6858768669052598, 0.0],
        [0.0, 0.0, 0.0],
        [0.0, 0.0, -0.27887452517226574],
    ];
    let support = Plane::through(tri[0], tri[1], tri[2]).unwrap();
    assert!(support.error_bounds().1.is_infinite());
    let edge = Plane::edge(tri[0], tri[1], 1, false);
    let c = -2.9869863946932303e161;
    let cut = Plane::through(
        [c, 0.2286256223017533, -0.09295817505742192],
        [c, 0.2286256223017533, -0.09295814525509953],
        [c, 0.22862565210407568, -0.09295817505742192],
    )
    .unwrap();
    let (pos, err) = approximate(&support, &edge, &cut).expect("the planes meet in a point");
    let (x, d) = homogeneous_dyadic(&support, &edge, &cut);
    assert!(!d.is_zero());
    for j in 0..3 {
        assert!(
            err.is_infinite() || within(&x[j], &d, pos[j], err),
            "coordinate {j}: {} ± {err} misses the exact vertex",
            pos[j]
        );
    }
    // The vertex is not representable, so no bound may claim it exactly.
    assert!(err > 0.0);
}
