//! Splitting: pieces on the right side (exact reference), no spanning piece, areas add
//! up (rationals), no zero-area piece, numbers never grow.

mod common;

use common::*;
use limn_kernel::{check_polygon, check_split};
use limn_kernel::{ExactKernel, ExactPolygon, Kernel, Plane, PolygonSide, Side};
use num_traits::Zero;
use proptest::prelude::*;

/// A splitting plane chosen relative to `poly`, biased toward degenerate positions.
#[derive(Debug, Clone)]
enum Cut {
    Random([i64; 3], [i64; 3], [i64; 3]),
    ThroughVertex(usize, [i64; 3], [i64; 3]),
    ThroughTwoVertices(usize, usize, [i64; 3]),
    Support(bool),
    AlongEdge(usize, [i64; 3]),
    NearlySupport(usize, i64),
    Api([f64; 3], [f64; 3]),
    ThroughInterior([i64; 3], [i64; 3]),
}

fn cut() -> impl Strategy<Value = Cut> {
    let unit = || [-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0];
    prop_oneof![
        2 => (grid_point(), grid_point(), grid_point()).prop_map(|(a, b, c)| Cut::Random(a, b, c)),
        2 => (0usize..16, grid_point(), grid_point()).prop_map(|(i, a, b)| Cut::ThroughVertex(i, a, b)),
        2 => (0usize..16, 0usize..16, grid_point()).prop_map(|(i, j, a)| Cut::ThroughTwoVertices(i, j, a)),
        1 => any::<bool>().prop_map(Cut::Support),
        2 => (0usize..16, grid_point()).prop_map(|(i, a)| Cut::AlongEdge(i, a)),
        2 => (0usize..16, -2i64..=2).prop_map(|(i, u)| Cut::NearlySupport(i, u)),
        2 => (unit(), unit()).prop_map(|(p, n)| Cut::Api(p, n)),
        4 => ([-99i64..99, -99i64..99, -99i64..99], [-99i64..99, -99i64..99, -99i64..99]).prop_map(|(a, b)| Cut::ThroughInterior(a, b)),
    ]
}

/// Vertex `i` (mod n) of `p`, rounded to f64 (exact for input corners).
fn vert(k: &ExactKernel, p: &ExactPolygon, i: usize) -> [f64; 3] {
    k.vertex_rounded(p, i % p.len())
}

fn make_cut(k: &ExactKernel, poly: &ExactPolygon, c: &Cut) -> Option<Plane> {
    let through = |a: [f64; 3], b: [f64; 3], c: [f64; 3]| Plane::through(a, b, c).ok();
    match c {
        Cut::Random(a, b, c) => plane_g(*a, *b, *c),
        Cut::ThroughVertex(i, a, b) => through(vert(k, poly, *i), gp(*a), gp(*b)),
        Cut::ThroughTwoVertices(i, j, a) => through(vert(k, poly, *i), vert(k, poly, *j), gp(*a)),
        Cut::Support(flip) => {
            let p = poly.support();
            Some(if *flip { p.flipped() } else { p })
        }
        Cut::AlongEdge(i, a) => through(vert(k, poly, *i), vert(k, poly, *i + 1), gp(*a)),
        Cut::NearlySupport(i, ulps) => {
            let mut c = vert(k, poly, *i + 2);
            c[2] = nudge(c[2], *ulps);
            through(vert(k, poly, *i), vert(k, poly, *i + 1), c)
        }
        Cut::ThroughInterior(a, b) => {
            let n = poly.len() as f64;
            let c = (0..poly.len())
                .map(|i| vert(k, poly, i))
                .fold([0.0; 3], |s, v| {
                    [s[0] + v[0] / n, s[1] + v[1] / n, s[2] + v[2] / n]
                });
            let add = |d: &[i64; 3]| {
                let g = gp(*d);
                [c[0] + g[0], c[1] + g[1], c[2] + g[2]]
            };
            through(c, add(a), add(b))
        }
        Cut::Api(p, n) => k
            .plane_through(glam::DVec3::from_array(*p), glam::DVec3::from_array(*n))
            .ok(),
    }
}

/// All checks of one split; returns the pieces.
fn checked_split(
    k: &ExactKernel,
    poly: &ExactPolygon,
    h: &Plane,
) -> (Option<ExactPolygon>, Option<ExactPolygon>) {
    // Filtered, unfiltered and reference classifications agree.
    let want = reference_classify(poly, h);
    assert_eq!(
        k.classify(poly, h),
        want,
        "filtered classify: {poly:?} vs {h:?}"
    );
    let unfiltered = kernel().without_filter();
    assert_eq!(unfiltered.classify(poly, h), want);
    for i in 0..poly.len() {
        assert_eq!(k.side_of_vertex(poly, i, h), vertex_side(poly, i, h));
    }
    let (f, b) = k.split(poly, h);
    check_split(poly, h, f.as_ref(), b.as_ref())
        .unwrap_or_else(|e| panic!("{e}: {poly:?} by {h:?}"));
    // The parts' corners without the parts: the same corners, each within the promised
    // relative 1e-9 of the rounded exact one.
    let (mut wf, mut wb) = (Vec::new(), Vec::new());
    if k.split_world(poly, h, &mut wf, &mut wb) {
        for (piece, world) in [(&f, &wf), (&b, &wb)] {
            let n = piece.as_ref().map_or(0, |p| p.len());
            assert_eq!(world.len(), n, "corner count: {poly:?} by {h:?}");
            let Some(p) = piece else { continue };
            for (i, w) in world.iter().enumerate() {
                let r = k.vertex_rounded(p, i);
                let scale = r.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                for j in 0..3 {
                    assert!(
                        (w[j] - r[j]).abs() <= 2e-9 * scale,
                        "corner {i}: {w:?} against {r:?}: {poly:?} by {h:?}"
                    );
                }
            }
        }
    }
    // The reference: every vertex of each piece on the right side, some strictly.
    for (piece, want) in [(&f, Side::Front), (&b, Side::Back)] {
        let Some(p) = piece else { continue };
        let sides: Vec<Side> = (0..p.len()).map(|i| vertex_side(p, i, h)).collect();
        assert!(
            !sides.contains(&want.flip()),
            "piece vertex on the wrong side: {sides:?}"
        );
        let c = k.classify(p, h);
        assert_ne!(c, PolygonSide::Spanning);
    }
    // Areas add up exactly (projected along the support's dominant axis: all pieces share
    // the support plane, so projected areas are proportional to true areas).
    let axis = poly.support().dominant_axis();
    let total = projected_area2(poly, axis);
    let parts = [&f, &b]
        .iter()
        .filter_map(|p| p.as_ref())
        .map(|p| {
            let a = projected_area2(p, axis);
            assert!(!a.is_zero(), "zero-area piece");
            a
        })
        .fold(num_rational::BigRational::zero(), |s, a| s + a);
    assert_eq!(total, parts, "areas do not add up");
    (f, b)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(600))]

    #[test]
    fn one_split(pts in lattice_polygon(), c in cut()) {
        let k = kernel();
        for poly in face(&k, &pts) {
            check_polygon(&poly).unwrap();
            if let Some(h) = make_cut(&k, &poly, &c) {
                checked_split(&k, &poly, &h);
            }
        }
    }

    #[test]
    fn triangles(a in grid_point(), b in grid_point(), c in grid_point(), cuts in prop::collection::vec(cut(), 1..6)) {
        let k = kernel();
        for poly in face(&k, &[a, b, c]) {
            let mut p = poly;
            for c in &cuts {
                let Some(h) = make_cut(&k, &p, c) else { continue };
                let (f, b) = checked_split(&k, &p, &h);
                p = f.or(b).unwrap();
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    /// Raw f64 triangles (any magnitude from 1e-300 to 1e300, values a few ulps from
    /// simple ones) through chains of cuts: every check after every split.
    #[test]
    fn raw_triangles(tri in [world_point(), world_point(), world_point()], cuts in prop::collection::vec(cut(), 1..5)) {
        let k = kernel();
        let corners = tri.map(glam::DVec3::from_array);
        for poly in k.face_polygons(&corners).unwrap() {
            let mut p = poly;
            for c in &cuts {
                let Some(h) = make_cut(&k, &p, c) else { continue };
                let (f, b) = checked_split(&k, &p, &h);
                p = f.or(b).unwrap();
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(30))]

    /// 100 splits in a row: every check after every split, and every plane of the result
    /// is an input plane (so no number ever grows beyond the input bounds; overflow checks
    /// are on in the test profile).
    #[test]
    fn hundred_splits_in_a_row(pts in lattice_polygon(), cuts in prop::collection::vec(cut(), 100), keep in prop::collection::vec(any::<bool>(), 100)) {
        let k = kernel();
        for poly in face(&k, &pts) {
            let mut inputs: Vec<Plane> = vec![poly.support()];
            inputs.extend((0..poly.len()).map(|i| poly.edge_plane(i)));
            let mut p = poly;
            let mut splits = 0;
            let area = projected_area2(&p, p.support().dominant_axis());
            let big = num_traits::Signed::abs(&area) > num_rational::BigRational::from_integer(100_000_000.into());
            for (c, keep_front) in cuts.iter().zip(&keep) {
                let Some(h) = make_cut(&k, &p, c) else { continue };
                inputs.push(h.clone());
                inputs.push(h.flipped());
                let (f, b) = checked_split(&k, &p, &h);
                if f.is_some() && b.is_some() {
                    splits += 1;
                }
                p = if *keep_front { f.or(b) } else { b.or(f) }.unwrap();
                // The same definition (input values) and orientation: an input polygon
                // makes its edge planes when asked for, so they are equal planes, not
                // the same objects.
                let defined = |e: &Plane| (e.definition(), e.is_flipped());
                for i in 0..p.len() {
                    let e = defined(&p.edge_plane(i));
                    prop_assert!(inputs.iter().any(|x| defined(x) == e));
                }
                prop_assert_eq!(p.support(), inputs[0].clone());
            }
            // The generators must actually exercise splitting: a large polygon is cut
            // through its interior by about a quarter of the cuts, so a sequence of 100
            // with no proper split at all means the generator is broken (by chance it
            // happens with probability below 1e-12; fewer than five happens, so that is
            // not asserted).
            if big {
                prop_assert!(splits >= 1, "no proper split in 100 cuts");
            }
        }
    }
}

#[test]
fn split_through_vertices_keeps_both_pieces_proper() {
    let k = kernel();
    let sq = face(&k, &[[0, 0, 0], [10, 0, 0], [10, 10, 0], [0, 10, 0]]);
    assert_eq!(sq.len(), 1);
    // The diagonal plane through (0,0) and (10,10).
    let h = plane_g([0, 0, 0], [10, 10, 0], [0, 0, 1]).unwrap();
    let (f, b) = checked_split(&k, &sq[0], &h);
    let (f, b) = (f.unwrap(), b.unwrap());
    assert_eq!((f.len(), b.len()), (3, 3));
    // The cut edge is not original, the others are.
    let originals = |p: &ExactPolygon| (0..p.len()).filter(|&i| p.edge_is_original(i)).count();
    assert_eq!(originals(&f), 2);
    assert_eq!(originals(&b), 2);
    // A plane touching only a corner does not split.
    let touch = plane_g([0, 0, 0], [-10, 10, 0], [0, 0, 1]).unwrap();
    let (f2, b2) = checked_split(&k, &sq[0], &touch);
    assert!(f2.is_some() && b2.is_none());
    // Coplanar: same facing goes to the front, opposite to the back.
    let s = sq[0].support();
    assert!(matches!(k.split(&sq[0], &s), (Some(_), None)));
    assert!(matches!(k.split(&sq[0], &s.flipped()), (None, Some(_))));
    assert_eq!(k.classify(&sq[0], &s), PolygonSide::Coplanar);
    assert_eq!(
        k.classify(&sq[0], &s.flipped()),
        PolygonSide::CoplanarOpposite
    );
}

/// A raw triangle with one corner near 1e161 and the others at the origin's scale, cut
/// through its interior: the support plane's offset bound overflows, and the cut vertices
/// must still be told apart from input points (they were taken as exact, off the support
/// plane).
#[test]
fn split_of_a_huge_triangle_keeps_its_cut_vertices_implicit() {
    let k = kernel();
    let tri = [
        [-8.960959184079691e161, 0.6858768669052598, 0.0],
        [0.0, 0.0, 0.0],
        [0.0, 0.0, -0.27887452517226574],
    ];
    let polys = k.face_polygons(&tri.map(glam::DVec3::from_array)).unwrap();
    assert_eq!(polys.len(), 1);
    let poly = &polys[0];
    let h = make_cut(&k, poly, &Cut::ThroughInterior([0, 0, 1], [0, 1, 0])).unwrap();
    let (f, b) = checked_split(&k, poly, &h);
    let (f, b) = (f.unwrap(), b.unwrap());
    assert_eq!((f.len(), b.len()), (3, 4));
    for p in [&f, &b] {
        for i in 0..p.len() {
            let (pos, err) = p.vertex_approx(i);
            if !tri.contains(&pos) {
                assert!(err > 0.0, "cut vertex {pos:?} claims to be exact");
            }
        }
    }
}

/// A ground square cut by two planes through the same point along the same direction
/// (the shadow of an occluder's corner under a light at infinity) has a corner where
/// that ray meets it; a third such plane passes exactly through that corner, and the
/// kernel knows it without exact arithmetic: the same sides as with the filter off.
#[test]
fn corners_on_a_shared_shadow_ray_lie_on_every_plane_along_it() {
    let ground = [
        glam::DVec3::new(-2.0, 0.0, -2.0),
        glam::DVec3::new(-2.0, 0.0, 2.0),
        glam::DVec3::new(2.0, 0.0, 2.0),
        glam::DVec3::new(2.0, 0.0, -2.0),
    ];
    let d = glam::DVec3::new(0.3, 1.0, 0.2);
    let v = glam::DVec3::new(0.1, 1.0, 0.0);
    let sides = |k: &ExactKernel| {
        let poly = k.face_polygons(&ground).unwrap().remove(0);
        let a = k
            .plane_along(v, glam::DVec3::new(1.1, 1.0, 0.7), d)
            .unwrap();
        let b = k
            .plane_along(v, glam::DVec3::new(-0.6, 1.0, 0.9), d)
            .unwrap();
        let c = k
            .plane_along(v, glam::DVec3::new(0.4, 1.0, -1.3), d)
            .unwrap();
        let (fa, ba) = k.split(&poly, &a);
        let mut wedges = Vec::new();
        for half in [fa.unwrap(), ba.unwrap()] {
            let (f, g) = k.split(&half, &b);
            wedges.extend(f);
            wedges.extend(g);
        }
        assert_eq!(wedges.len(), 4, "the corner lies inside the square");
        let before = k.fallbacks();
        let sides: Vec<PolygonSide> = wedges.iter().map(|w| k.classify(w, &c)).collect();
        (sides, k.fallbacks() - before)
    };
    let (filtered, fallbacks) = sides(&ExactKernel::new());
    let (exact, _) = sides(&ExactKernel::new().without_filter());
    assert_eq!(filtered, exact);
    assert_eq!(
        filtered
            .iter()
            .filter(|s| **s == PolygonSide::Spanning)
            .count(),
        2,
        "{filtered:?}"
    );
    assert_eq!(
        fallbacks, 0,
        "the shared ray's corner needed exact arithmetic"
    );
}

/// The ground cut by two planes through the eye and an occluder's corner `c` (the corner
/// seen on the ground) has a corner on the line from the eye through `c`. A plane
/// through the eye that misses `c` by an ulp passes that close to the corner: the
/// filter cannot tell its side, the kernel tells it from the side of `c` (the eye lies
/// on the plane) without exact arithmetic, and agrees with the exact evaluation.
#[test]
fn a_corner_on_a_line_through_the_eye_takes_the_side_of_the_line_point_off_the_plane() {
    let ground = [
        glam::DVec3::new(-2.0, 0.0, -2.0),
        glam::DVec3::new(-2.0, 0.0, 2.0),
        glam::DVec3::new(2.0, 0.0, 2.0),
        glam::DVec3::new(2.0, 0.0, -2.0),
    ];
    let eye = glam::DVec3::new(0.1, 4.0, 0.05);
    let c = glam::DVec3::new(0.3, 1.0, 0.2);
    let wedges = |k: &ExactKernel| {
        let poly = k.face_polygons(&ground).unwrap().remove(0);
        let a = k
            .plane_through_points(eye, c, glam::DVec3::new(1.1, 1.0, 0.7))
            .unwrap();
        let b = k
            .plane_through_points(eye, c, glam::DVec3::new(-0.6, 1.0, 0.9))
            .unwrap();
        let (fa, ba) = k.split(&poly, &a);
        let mut wedges = Vec::new();
        for half in [fa.unwrap(), ba.unwrap()] {
            let (f, g) = k.split(&half, &b);
            wedges.extend(f);
            wedges.extend(g);
        }
        assert_eq!(wedges.len(), 4, "the corner lies inside the square");
        wedges
    };
    for nudge in [f64::next_up, f64::next_down] {
        let near = glam::DVec3::new(c.x, c.y, nudge(c.z));
        let sides = |k: &ExactKernel| {
            let h = k
                .plane_through_points(eye, near, glam::DVec3::new(0.4, 1.0, -1.3))
                .unwrap();
            let wedges = wedges(k);
            let undecided = wedges
                .iter()
                .filter(|w| k.classify_if_cheap(w, &h).is_none())
                .count();
            let before = k.fallbacks();
            let sides: Vec<PolygonSide> = wedges.iter().map(|w| k.classify(w, &h)).collect();
            (sides, undecided, k.fallbacks() - before)
        };
        let (filtered, undecided, fallbacks) = sides(&ExactKernel::new());
        let (exact, ..) = sides(&ExactKernel::new().without_filter());
        assert_eq!(filtered, exact);
        assert!(undecided > 0, "the filter alone decided every wedge");
        assert_eq!(fallbacks, 0, "the corner needed exact arithmetic");
    }
}

/// Corners where two planes through the eye and nearly parallel edges far away meet the
/// ground (intersections the cached approximation knows only loosely), classified
/// against planes through the eye passing within a few ulps of them: the same sides
/// with the filters (the cached position's, then the rounded exact corner's) as with
/// exact evaluation alone.
#[test]
fn ill_conditioned_corners_get_their_exact_sides() {
    let ground = [
        glam::DVec3::new(-2.0, 0.0, -2.0),
        glam::DVec3::new(-2.0, 0.0, 2.0),
        glam::DVec3::new(2.0, 0.0, 2.0),
        glam::DVec3::new(2.0, 0.0, -2.0),
    ];
    let eye = glam::DVec3::new(0.1, 40.0, 0.05);
    let mut seed = 0x9e37_79b9_7f4a_7c15u64;
    let mut unit = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
    };
    let mut compared = 0;
    for _ in 0..200 {
        // Two short edges meeting at `c`, nearly parallel seen from the eye.
        let c = glam::DVec3::new(unit() * 0.5, 1.0 + unit() * 0.1, unit() * 0.5);
        let p = c + glam::DVec3::new(1e-3, unit() * 1e-6, 1e-3 * (1.0 + unit() * 1e-4));
        let q = c + glam::DVec3::new(-1e-3, unit() * 1e-6, -1e-3 * (1.0 + unit() * 1e-4));
        // A plane through the eye and two points a few ulps off the line eye–c.
        let off = |v: f64, n: u32| (0..n).fold(v, |v, _| v.next_up());
        let r = glam::DVec3::new(off(c.x, 1), c.y, off(c.z, 3));
        let far = eye + (r - eye) * 1.5;
        let sides = |k: &ExactKernel| -> Option<Vec<PolygonSide>> {
            let poly = k.face_polygons(&ground).unwrap().remove(0);
            let a = k.plane_through_points(eye, c, p).ok()?;
            let b = k.plane_through_points(eye, c, q).ok()?;
            let h = k.plane_through_points(eye, r, far + glam::DVec3::X).ok()?;
            let (fa, ba) = k.split(&poly, &a);
            let mut wedges = Vec::new();
            for half in fa.into_iter().chain(ba) {
                let (f, g) = k.split(&half, &b);
                wedges.extend(f);
                wedges.extend(g);
            }
            Some(wedges.iter().map(|w| k.classify(w, &h)).collect())
        };
        let filtered = sides(&ExactKernel::new());
        let exact = sides(&ExactKernel::new().without_filter());
        assert_eq!(filtered, exact);
        compared += filtered.map_or(0, |s| s.len());
    }
    assert!(compared > 400, "{compared} wedges compared");
}
