//! Feeds arbitrary faces (lattice or any f64 corners) and planes through the exact
//! kernel's face conversion and repeated splitting, running the invariant checker after
//! every split and comparing filtered with unfiltered classification.
//!
//! The input's `Debug` form is valid Rust (struct and enum literals), so a crash can be
//! pasted into a regression test as it is.

#![no_main]

use arbitrary::Arbitrary;
use glam::DVec3;
use libfuzzer_sys::fuzz_target;
use limn_kernel::check::{check_polygon, check_split};
use limn_kernel::{ExactKernel, ExactPolygon, Kernel, Plane};

/// A splitting plane, relative to the current polygon where useful.
#[derive(Debug, Arbitrary)]
enum Cut {
    /// Through three raw f64 points (any finite value).
    Raw([f64; 3], [f64; 3], [f64; 3]),
    /// Through three lattice points.
    Through([i32; 3], [i32; 3], [i32; 3]),
    /// Through a vertex (rounded) and two lattice points.
    ThroughVertex(u8, [i32; 3], [i32; 3]),
    /// The polygon's support plane, maybe flipped.
    Support(bool),
    /// Through an edge's two (rounded) endpoints and a lattice point.
    AlongEdge(u8, [i32; 3]),
    /// Through the public API from a world point and normal.
    Api([f64; 3], [f64; 3]),
    /// Through vertices `i` and `i + 1` and vertex `i + 2` moved by a few ulps on one
    /// axis (nearly the support plane).
    Nudged(u8, u8, i8),
}

/// A face corner: a lattice point, or any f64 point (non-finite ones are refused by the
/// kernel with an error, which ends the case).
#[derive(Debug, Arbitrary)]
enum Corner {
    Lattice([i32; 3]),
    Raw([f64; 3]),
}

/// One fuzz case: a face, the cuts, and which piece to keep.
#[derive(Debug, Arbitrary)]
struct Case {
    corners: Vec<Corner>,
    cuts: Vec<(Cut, bool)>,
}

/// The world point of a lattice point (exact: multiples of 2^-25).
fn lattice(p: [i32; 3]) -> [f64; 3] {
    p.map(|v| v as f64 / 33_554_432.0)
}

fn plane(k: &ExactKernel, poly: &ExactPolygon, cut: &Cut) -> Option<Plane> {
    let n = poly.len();
    let through = |a, b, c| Plane::through(a, b, c).ok();
    match cut {
        Cut::Raw(a, b, c) => through(*a, *b, *c),
        Cut::Through(a, b, c) => through(lattice(*a), lattice(*b), lattice(*c)),
        Cut::ThroughVertex(i, a, b) => through(
            k.vertex_rounded(poly, *i as usize % n),
            lattice(*a),
            lattice(*b),
        ),
        Cut::Support(flip) => {
            let p = poly.support();
            Some(if *flip { p.flipped() } else { p })
        }
        Cut::AlongEdge(i, a) => {
            let i = *i as usize % n;
            through(
                k.vertex_rounded(poly, i),
                k.vertex_rounded(poly, (i + 1) % n),
                lattice(*a),
            )
        }
        Cut::Api(p, n) => k
            .plane_through(DVec3::from_array(*p), DVec3::from_array(*n))
            .ok(),
        Cut::Nudged(i, axis, ulps) => {
            let i = *i as usize % n;
            let mut c = k.vertex_rounded(poly, (i + 2) % n);
            let a = *axis as usize % 3;
            for _ in 0..ulps.unsigned_abs().min(8) {
                c[a] = if *ulps > 0 {
                    c[a].next_up()
                } else {
                    c[a].next_down()
                };
            }
            through(
                k.vertex_rounded(poly, i),
                k.vertex_rounded(poly, (i + 1) % n),
                c,
            )
        }
    }
}

fuzz_target!(|case: Case| {
    let k = ExactKernel::new();
    let unfiltered = ExactKernel::new().without_filter();
    let corners: Vec<DVec3> = case
        .corners
        .iter()
        .take(64)
        .map(|c| match c {
            Corner::Lattice(p) => DVec3::from_array(lattice(*p)),
            Corner::Raw(p) => DVec3::from_array(*p),
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
            // The filter never changes an answer.
            assert_eq!(
                k.classify(&p, &h),
                unfiltered.classify(&p, &h),
                "{p:?} {h:?}"
            );
            let (f, b) = k.split(&p, &h);
            if let Err(e) = check_split(&p, &h, f.as_ref(), b.as_ref()) {
                panic!("{e}\npolygon {p:?}\nplane {h:?}");
            }
            p = if *keep_front { f.or(b) } else { b.or(f) }.unwrap();
        }
    }
});
