//! Feeds arbitrary faces and planes through the exact kernel's face conversion and
//! repeated splitting, running the invariant checker after every split.
//!
//! The input's `Debug` form is valid Rust (struct and enum literals), so a crash can be
//! pasted into a regression test as it is.

#![no_main]

use arbitrary::Arbitrary;
use glam::DVec3;
use libfuzzer_sys::fuzz_target;
use limn_kernel::check::{check_polygon, check_split};
use limn_kernel::{ExactKernel, ExactPolygon, GridPoint, Kernel, Plane};

/// A splitting plane, relative to the current polygon where useful.
#[derive(Debug, Arbitrary)]
enum Cut {
    /// Raw coefficients (clamped into the kernel's bounds).
    Coefficients(i64, i64, i64, i64),
    /// Through three grid points.
    Through([i32; 3], [i32; 3], [i32; 3]),
    /// Through a vertex (rounded to the grid) and two grid points.
    ThroughVertex(u8, [i32; 3], [i32; 3]),
    /// The polygon's support plane shifted by a little, maybe flipped.
    Support(i8, bool),
    /// A combination of the support and an edge plane (through that edge's line).
    AlongEdge(u8, i8, i8, i8),
    /// Through the public API from a world point and normal.
    Api([f64; 3], [f64; 3]),
}

/// One fuzz case: a face (grid coordinates), the cuts, and which piece to keep.
#[derive(Debug, Arbitrary)]
struct Case {
    corners: Vec<[i32; 3]>,
    cuts: Vec<(Cut, bool)>,
}

const LIM: i64 = 1 << 25;

fn grid(p: [i32; 3]) -> GridPoint {
    let c = |v: i32| (v as i64).clamp(-LIM, LIM);
    GridPoint::new(c(p[0]), c(p[1]), c(p[2]))
}

fn plane(k: &ExactKernel, poly: &ExactPolygon, cut: &Cut) -> Option<Plane> {
    let n = poly.len();
    match cut {
        Cut::Coefficients(a, b, c, d) => {
            let m = (1i64 << 55) - 1;
            Plane::new(
                (*a).clamp(-m, m),
                (*b).clamp(-m, m),
                (*c).clamp(-m, m),
                *d as i128,
            )
        }
        Cut::Through(a, b, c) => Plane::through(grid(*a), grid(*b), grid(*c)),
        Cut::ThroughVertex(i, a, b) => {
            let v = k
                .vertex_grid(poly, *i as usize % n)
                .map(|x| x.round() as i64);
            Plane::through(GridPoint::from_array(v), grid(*a), grid(*b))
        }
        Cut::Support(d, flip) => {
            let (a, b, c, e) = poly.support().coefficients();
            let p = Plane::new(a, b, c, e + *d as i128)?;
            Some(if *flip { p.flipped() } else { p })
        }
        Cut::AlongEdge(i, s, t, d) => {
            let (a, b, c, e) = poly.support().coefficients();
            let (a2, b2, c2, e2) = poly.edge_plane(*i as usize % n).coefficients();
            let (s, t) = (*s as i64, *t as i64);
            Plane::new(
                a.checked_mul(s)?.checked_add(a2.checked_mul(t)?)?,
                b.checked_mul(s)?.checked_add(b2.checked_mul(t)?)?,
                c.checked_mul(s)?.checked_add(c2.checked_mul(t)?)?,
                e.checked_mul(s as i128)?
                    .checked_add(e2.checked_mul(t as i128)?)?
                    + *d as i128,
            )
        }
        Cut::Api(p, n) => k
            .plane_through(DVec3::from_array(*p), DVec3::from_array(*n))
            .ok(),
    }
}

fuzz_target!(|case: Case| {
    let Ok(k) = ExactKernel::new(DVec3::splat(-1.0), DVec3::splat(1.0)) else {
        return;
    };
    let s = k.step();
    let corners: Vec<DVec3> = case
        .corners
        .iter()
        .take(64)
        .map(|&p| {
            let g = grid(p);
            DVec3::new(g.x as f64, g.y as f64, g.z as f64) * s
        })
        .collect();
    let Ok(polys) = k.face_polygons(&corners) else {
        return;
    };
    for poly in polys {
        if let Err(e) = check_polygon(&poly) {
            panic!("{e}\ncase {case:?}\npolygon {poly:?}");
        }
        let mut p = poly;
        for (cut, keep_front) in case.cuts.iter().take(200) {
            let Some(h) = plane(&k, &p, cut) else {
                continue;
            };
            let (f, b) = k.split(&p, &h);
            if let Err(e) = check_split(&p, &h, f.as_ref(), b.as_ref()) {
                panic!("{e}\npolygon {p:?}\nplane {h:?}");
            }
            p = if *keep_front { f.or(b) } else { b.or(f) }.unwrap();
        }
    }
});
