//! The exact kernel's face conversion and repeated splitting, biased to degenerate
//! inputs: faces on a fine lattice or with any f64 corners, and cutting planes through
//! vertices, along edges, on the support plane or a few ulps off it. The kernel's
//! invariant checker runs after every conversion and split, and the filtered
//! classification must equal the unfiltered one.

use std::fmt;

use arbitrary::{Arbitrary, Unstructured};
use glam::DVec3;
use limn_kernel::{check_polygon, check_split};
use limn_kernel::{ExactKernel, ExactPolygon, Kernel, Plane};

use crate::VecLit;

/// A splitting plane, relative to the current polygon where useful. Raw coordinates are
/// f64 bit patterns ([`f64::from_bits`]).
#[derive(Debug, Clone, Arbitrary)]
pub enum Cut {
    /// Through three raw f64 points (any value).
    Raw([u64; 3], [u64; 3], [u64; 3]),
    /// Through three lattice points.
    Through([i32; 3], [i32; 3], [i32; 3]),
    /// Through a vertex (rounded) and two lattice points.
    ThroughVertex(u8, [i32; 3], [i32; 3]),
    /// The polygon's support plane, maybe flipped.
    Support(bool),
    /// Through an edge's two (rounded) endpoints and a lattice point.
    AlongEdge(u8, [i32; 3]),
    /// Through the public API from a world point and normal (raw f64 bits).
    Api([u64; 3], [u64; 3]),
    /// Through vertices `i` and `i + 1` and vertex `i + 2` moved by a few ulps on one
    /// axis (nearly the support plane).
    Nudged(u8, u8, i8),
}

/// A face corner: a lattice point, or any f64 point given by its bits (non-finite ones
/// are refused by the kernel with an error, which ends the case).
#[derive(Debug, Clone, Arbitrary)]
pub enum Corner {
    /// A point of the lattice of multiples of 2^-25.
    Lattice([i32; 3]),
    /// Any f64 point, as bit patterns.
    Raw([u64; 3]),
}

/// One case: a face, and the cuts with which piece to keep (`true`: the front one).
#[derive(Clone, Arbitrary)]
pub struct Case {
    /// The face's corners (at most 64 are used).
    pub corners: Vec<Corner>,
    /// The planes cutting it in turn (at most 200 are used), and which piece is cut next.
    pub cuts: Vec<(Cut, bool)>,
}

impl fmt::Debug for Case {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Case")
            .field("corners", &VecLit(&self.corners))
            .field("cuts", &VecLit(&self.cuts))
            .finish()
    }
}

/// The world point of a lattice point (exact: multiples of 2^-25).
fn lattice(p: [i32; 3]) -> [f64; 3] {
    p.map(|v| v as f64 / 33_554_432.0)
}

fn bits(p: [u64; 3]) -> [f64; 3] {
    p.map(f64::from_bits)
}

fn plane(k: &ExactKernel, poly: &ExactPolygon, cut: &Cut) -> Option<Plane> {
    let n = poly.len();
    let through = |a, b, c| Plane::through(a, b, c).ok();
    match cut {
        Cut::Raw(a, b, c) => through(bits(*a), bits(*b), bits(*c)),
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
            .plane_through(DVec3::from_array(bits(*p)), DVec3::from_array(bits(*n)))
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

/// Converts the case's face and cuts it in turn, checking the invariants throughout.
pub fn run_case(case: &Case) {
    let k = ExactKernel::new();
    let unfiltered = ExactKernel::new().without_filter();
    let corners: Vec<DVec3> = case
        .corners
        .iter()
        .take(64)
        .map(|c| match c {
            Corner::Lattice(p) => DVec3::from_array(lattice(*p)),
            Corner::Raw(p) => DVec3::from_array(bits(*p)),
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
            let kept = if *keep_front { f.or(b) } else { b.or(f) };
            p = kept.expect("a split keeps at least one piece");
        }
    }
}

/// The [`Case`] that `data` decodes to, as [`run`] decodes it (`None`: skipped).
/// Its `Debug` form is Rust source for a regression test.
pub fn decode(data: &[u8]) -> Option<Case> {
    Case::arbitrary_take_rest(Unstructured::new(data)).ok()
}

/// Decodes a [`Case`] from `data` and runs it; undecodable bytes are skipped.
pub fn run(data: &[u8]) {
    if let Some(case) = decode(data) {
        run_case(&case);
    }
}
