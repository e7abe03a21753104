//! Line drawing: Bresenham and DDA, and hidden-line wireframes.

mod common;

use common::{cam, scene_with, Lcg};
use glam::DVec3;
use limn_zbuffer::{bresenham, dda, wireframe, LineAlgorithm, LineOptions, RenderOptions, NO_FACE};

fn bres(a: (i64, i64), b: (i64, i64)) -> Vec<(i64, i64)> {
    let mut v = Vec::new();
    bresenham(a.0, a.1, b.0, b.1, |x, y| v.push((x, y)));
    v
}

fn dda_centres(a: (i64, i64), b: (i64, i64)) -> Vec<(i64, i64)> {
    let mut v = Vec::new();
    let c = |p: i64| p as f64 + 0.5;
    dda(c(a.0), c(a.1), c(b.0), c(b.1), u64::MAX, |x, y| {
        v.push((x, y))
    });
    v
}

#[test]
fn bresenham_hits_both_endpoints_and_is_connected() {
    let mut rng = Lcg(99);
    for _ in 0..2000 {
        let mut p = || (rng.range(-50.0, 50.0) as i64, rng.range(-50.0, 50.0) as i64);
        let (a, b) = (p(), p());
        let line = bres(a, b);
        assert_eq!(line.first(), Some(&a));
        assert_eq!(line.last(), Some(&b));
        let n = (b.0 - a.0).abs().max((b.1 - a.1).abs());
        assert_eq!(line.len() as i64, n + 1, "one pixel per major step");
        for w in line.windows(2) {
            let (dx, dy) = (w[1].0 - w[0].0, w[1].1 - w[0].1);
            assert!(
                dx.abs() <= 1 && dy.abs() <= 1 && (dx, dy) != (0, 0),
                "8-connected"
            );
        }
        // The same pixels drawn in the other direction.
        let mut back = bres(b, a);
        back.reverse();
        assert_eq!(line, back);
        // Every pixel is within half a pixel of the exact line along the minor axis.
        for &(x, y) in &line {
            let (dx, dy) = ((b.0 - a.0) as f64, (b.1 - a.1) as f64);
            if dx.abs() >= dy.abs() && dx != 0.0 {
                let yl = a.1 as f64 + (x - a.0) as f64 * dy / dx;
                assert!((y as f64 - yl).abs() <= 0.5);
            } else if dy != 0.0 {
                let xl = a.0 as f64 + (y - a.1) as f64 * dx / dy;
                assert!((x as f64 - xl).abs() <= 0.5);
            }
        }
    }
    assert_eq!(
        bres((3, 7), (9, 11)),
        vec![(3, 7), (4, 8), (5, 8), (6, 9), (7, 10), (8, 10), (9, 11)]
    );
}

#[test]
fn dda_and_bresenham_agree() {
    let mut rng = Lcg(7);
    let mut with_ties = 0;
    for _ in 0..3000 {
        let mut p = || (rng.range(-40.0, 40.0) as i64, rng.range(-40.0, 40.0) as i64);
        let (a, b) = (p(), p());
        let (br, dd) = (bres(a, b), dda_centres(a, b));
        assert_eq!(br.len(), dd.len());
        // A tie: the exact line passes half-way between two pixel centres.
        let (da, db) = if (b.0 - a.0).abs() >= (b.1 - a.1).abs() {
            (b.0 - a.0, b.1 - a.1)
        } else {
            (b.1 - a.1, b.0 - a.0)
        };
        let ties =
            da != 0 && (0..=da.abs()).any(|k| (2 * k * db).rem_euclid(2 * da.abs()) == da.abs());
        if ties {
            with_ties += 1;
            for (p, q) in br.iter().zip(&dd) {
                assert!((p.0 - q.0).abs() + (p.1 - q.1).abs() <= 1);
            }
        } else {
            assert_eq!(br, dd, "{a:?} → {b:?}");
        }
    }
    assert!(with_ties > 0);
}

#[test]
fn hidden_lines_of_a_cube_are_removed() {
    let mut s = scene_with(&[[0.5, 0.5, 0.5]]);
    let v: Vec<u32> = (0..8)
        .map(|i| {
            s.add_vertex(DVec3::new(
                if i & 1 == 0 { -1.0 } else { 1.0 },
                if i & 2 == 0 { -1.0 } else { 1.0 },
                if i & 4 == 0 { -1.0 } else { 1.0 },
            ))
        })
        .collect();
    for q in [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ] {
        s.add_face(&q.map(|k| v[k]), 0, 0).unwrap();
    }
    let camera = cam(DVec3::new(3.0, 2.5, 4.0), 120, 100);
    let opts = RenderOptions::default();
    let vp = camera.view_projection(1.0, 20.0);
    let px = |p: DVec3| {
        let q = camera.project_with(&vp, p);
        (q.x as u32, q.y as u32)
    };
    // The edge hidden behind the cube: from (−1,−1,−1) to (1,−1,−1), seen from +x+y+z.
    let hidden_mid = px(DVec3::new(0.0, -1.0, -1.0));
    let visible_mid = px(DVec3::new(0.0, 1.0, 1.0));
    for algorithm in [LineAlgorithm::Bresenham, LineAlgorithm::Dda] {
        let all = wireframe(
            &s,
            &camera,
            &opts,
            &LineOptions {
                algorithm,
                hidden_line: false,
                ..LineOptions::default()
            },
        )
        .unwrap();
        let vis = wireframe(
            &s,
            &camera,
            &opts,
            &LineOptions {
                algorithm,
                ..LineOptions::default()
            },
        )
        .unwrap();
        assert!(vis.covered() < all.covered());
        assert_ne!(
            all.get(hidden_mid.0, hidden_mid.1),
            Some(NO_FACE),
            "{algorithm:?}"
        );
        assert_eq!(
            vis.get(hidden_mid.0, hidden_mid.1),
            Some(NO_FACE),
            "{algorithm:?}"
        );
        assert_ne!(
            vis.get(visible_mid.0, visible_mid.1),
            Some(NO_FACE),
            "{algorithm:?}"
        );
        // Nine visible edges of a cube seen from a corner direction: long lines.
        assert!(vis.covered() > 9 * 20);
    }
}
