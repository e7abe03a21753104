//! The same classifications after translating by whole lattice steps and by powers of
//! two (exact in f64), rotating by 90° and mirroring (exact coordinate swaps and
//! negations of any f64), rotating the vertex order, and permuting the faces. Every split
//! made here is checked with `check_split`.

mod common;

use common::*;
use glam::DVec3;
use limn_kernel::check_split;
use limn_kernel::{ExactKernel, ExactPolygon, Kernel, Plane, PolygonSide};
use proptest::prelude::*;

type Map = fn([i64; 3]) -> [i64; 3];

/// Lattice transformations (exact on the f64 input); the bool says whether it reverses orientation.
const MAPS: [(Map, bool); 5] = [
    (|p| [p[0] + 12_345, p[1] - 777, p[2] + 1], false),
    (|p| [-p[1], p[0], p[2]], false),
    (|p| [p[0], -p[2], p[1]], false),
    (|p| [p[2], p[1], -p[0]], false),
    (|p| [-p[0], p[1], p[2]], true),
];

/// A plane through three grid points, as the face of the triangle they form.
fn plane_of(k: &limn_kernel::ExactKernel, t: &[[i64; 3]; 3]) -> Option<Plane> {
    face(k, t).first().map(|p| p.support())
}

fn classify_all(polys: &[ExactPolygon], planes: &[Option<Plane>]) -> Vec<Option<PolygonSide>> {
    let k = kernel();
    polys
        .iter()
        .flat_map(|p| planes.iter().map(|h| h.as_ref().map(|h| k.classify(p, h))))
        .collect()
}

fn split_shape(polys: &[ExactPolygon], planes: &[Option<Plane>]) -> Vec<(usize, usize)> {
    let k = kernel();
    let mut out = Vec::new();
    for p in polys {
        for h in planes.iter().flatten() {
            let (f, b) = k.split(p, h);
            check_split(p, h, f.as_ref(), b.as_ref()).unwrap();
            out.push((f.map_or(0, |f| f.len()), b.map_or(0, |b| b.len())));
        }
    }
    out
}

fn flip_side(s: PolygonSide) -> PolygonSide {
    match s {
        PolygonSide::Coplanar => PolygonSide::CoplanarOpposite,
        PolygonSide::CoplanarOpposite => PolygonSide::Coplanar,
        s => s,
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    #[test]
    fn transforms_preserve_classification(
        pts in lattice_polygon(),
        tri in prop::collection::vec([-2000i64..2000, -2000i64..2000, -2000i64..2000], 3..12),
        rot in 0usize..6,
    ) {
        let k = kernel();
        // Planes: some through corners of the polygon (degenerate), some arbitrary, and
        // the polygon's own plane.
        let mut tris: Vec<[[i64; 3]; 3]> = tri.chunks(3).filter(|c| c.len() == 3).map(|c| [c[0], c[1], c[2]]).collect();
        tris.push([pts[0], pts[1], tri[0]]);
        tris.push([pts[0], pts[1], pts[2]]);
        tris.push([pts[1], pts[2], pts[0]]);
        let planes: Vec<Option<Plane>> = tris.iter().map(|t| plane_of(&k, t)).collect();
        let base = classify_all(&face(&k, &pts), &planes);
        let shape = split_shape(&face(&k, &pts), &planes);

        // Rotating the vertex order.
        let mut rotated = pts.clone();
        let r = rot % pts.len();
        rotated.rotate_left(r);
        prop_assert_eq!(&classify_all(&face(&k, &rotated), &planes), &base);

        for (m, mirror) in MAPS {
            let mut q: Vec<[i64; 3]> = pts.iter().map(|&p| m(p)).collect();
            let mut tq: Vec<[[i64; 3]; 3]> = tris.iter().map(|t| t.map(m)).collect();
            if mirror {
                // Mirroring reverses orientation; reversing the order restores it.
                q.reverse();
                for t in &mut tq {
                    t.swap(1, 2);
                }
            }
            let planes_t: Vec<Option<Plane>> = tq.iter().map(|t| plane_of(&k, t)).collect();
            let got = classify_all(&face(&k, &q), &planes_t);
            // With the order reversed, even Coplanar and CoplanarOpposite are preserved.
            prop_assert_eq!(&got, &base);
            if mirror {
                // Without reversing, the polygon faces the other way.
                let unreversed: Vec<[i64; 3]> = pts.iter().map(|&p| m(p)).collect();
                let got = classify_all(&face(&k, &unreversed), &planes_t);
                let want: Vec<Option<PolygonSide>> = base.iter().map(|s| s.map(flip_side)).collect();
                prop_assert_eq!(&got, &want);
            }
            prop_assert_eq!(split_shape(&face(&k, &q), &planes_t), shape.clone());
        }
    }
}

#[test]
fn world_translation_by_whole_steps_keeps_every_decision() {
    let k = kernel();
    let s = STEP;
    // Lattice points: translating them by whole steps is exact in f64.
    let tri = [
        DVec3::new(0.125, 0.25, 0.375),
        DVec3::new(0.5, -0.125, 0.25),
        DVec3::new(-0.375, 0.4375, -0.125),
    ];
    let eye = DVec3::new(0.05, 0.06, 0.9);
    let base = k.face_polygons(&tri).unwrap();
    let h0 = k.support(&base[0]);
    let side0 = k.side_of_point(h0, &k.point(eye).unwrap());
    for t in [
        DVec3::new(3.0 * s, 0.0, 0.0),
        DVec3::new(-1000.0 * s, 77.0 * s, 5.0 * s),
    ] {
        let moved: Vec<DVec3> = tri.iter().map(|&p| p + t).collect();
        let m = k.face_polygons(&moved).unwrap();
        let h = k.support(&m[0]);
        assert_eq!(h.approx()[..3], h0.approx()[..3]);
        assert_eq!(k.side_of_point(h, &k.point(eye + t).unwrap()), side0);
        let mut a = Vec::new();
        let mut b = Vec::new();
        k.vertices_world(&base[0], &mut a);
        k.vertices_world(&m[0], &mut b);
        for (p, q) in a.iter().zip(&b) {
            assert_eq!(*q - *p, t);
        }
    }
}

/// A signed permutation of the axes: `out[i] = sign[i] · p[perm[i]]`, exact for every f64.
#[derive(Debug, Clone, Copy)]
struct Signed3 {
    perm: [usize; 3],
    sign: [f64; 3],
}

impl Signed3 {
    fn apply(&self, p: [f64; 3]) -> [f64; 3] {
        std::array::from_fn(|i| self.sign[i] * p[self.perm[i]])
    }

    /// Whether the map reverses orientation (determinant −1).
    fn mirrors(&self) -> bool {
        let parity_odd = matches!(self.perm, [0, 2, 1] | [2, 1, 0] | [1, 0, 2]);
        let negs = self.sign.iter().filter(|&&s| s < 0.0).count();
        parity_odd != (negs % 2 == 1)
    }
}

/// The 90° rotations about each axis, a half turn, a rotation about the diagonal, and
/// mirrors in each coordinate plane and through a diagonal plane.
const SIGNED: [Signed3; 9] = [
    Signed3 {
        perm: [1, 0, 2],
        sign: [-1.0, 1.0, 1.0],
    },
    Signed3 {
        perm: [0, 2, 1],
        sign: [1.0, -1.0, 1.0],
    },
    Signed3 {
        perm: [2, 1, 0],
        sign: [1.0, 1.0, -1.0],
    },
    Signed3 {
        perm: [0, 1, 2],
        sign: [-1.0, -1.0, 1.0],
    },
    Signed3 {
        perm: [1, 2, 0],
        sign: [1.0, 1.0, 1.0],
    },
    Signed3 {
        perm: [0, 1, 2],
        sign: [-1.0, 1.0, 1.0],
    },
    Signed3 {
        perm: [0, 1, 2],
        sign: [1.0, -1.0, 1.0],
    },
    Signed3 {
        perm: [0, 1, 2],
        sign: [1.0, 1.0, -1.0],
    },
    Signed3 {
        perm: [1, 0, 2],
        sign: [1.0, 1.0, 1.0],
    },
];

/// Polygons of a face given by f64 corners.
fn face_f(k: &ExactKernel, pts: &[[f64; 3]]) -> Vec<ExactPolygon> {
    let c: Vec<DVec3> = pts.iter().map(|p| DVec3::from_array(*p)).collect();
    k.face_polygons(&c).unwrap()
}

/// A raw f64 triangle biased toward degenerate planes: random corners, and planes through
/// its corners with a point a few ulps off its plane.
fn raw_case() -> impl Strategy<Value = (Vec<[f64; 3]>, Vec<[[f64; 3]; 3]>)> {
    (
        [world_point(), world_point(), world_point(), world_point()],
        prop::collection::vec([world_point(), world_point(), world_point()], 1..4),
        0usize..3,
        -2i64..=2,
    )
        .prop_map(|(q, mut planes, axis, ulps)| {
            let face = vec![q[0], q[1], q[2]];
            // Through two corners and the third moved by a few ulps (nearly the face's
            // own plane), through a corner and two random points, and the face itself.
            let mut c = q[2];
            c[axis] = nudge(c[axis], ulps);
            planes.push([q[0], q[1], c]);
            planes.push([q[1], q[3], q[0]]);
            planes.push([q[0], q[1], q[2]]);
            (face, planes)
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(100))]

    /// Any f64 input, rotated by 90° or mirrored by exact swaps and negations: the same
    /// classifications and the same split shapes (reversing the order restores the facing
    /// after a mirror; without it, Coplanar and CoplanarOpposite swap).
    #[test]
    fn raw_signed_permutations_preserve_classification((face, tris) in raw_case(), rot in 0usize..3) {
        let k = kernel();
        let planes: Vec<Option<Plane>> = tris
            .iter()
            .map(|t| Plane::through(t[0], t[1], t[2]).ok())
            .collect();
        let polys = face_f(&k, &face);
        let base = classify_all(&polys, &planes);
        let shape = split_shape(&polys, &planes);
        let mut rotated = face.clone();
        rotated.rotate_left(rot);
        prop_assert_eq!(&classify_all(&face_f(&k, &rotated), &planes), &base);
        for m in SIGNED {
            let mut q: Vec<[f64; 3]> = face.iter().map(|&p| m.apply(p)).collect();
            let mut tq: Vec<[[f64; 3]; 3]> = tris.iter().map(|t| t.map(|p| m.apply(p))).collect();
            if m.mirrors() {
                q.reverse();
                for t in &mut tq {
                    t.swap(1, 2);
                }
            }
            let planes_t: Vec<Option<Plane>> = tq
                .iter()
                .map(|t| Plane::through(t[0], t[1], t[2]).ok())
                .collect();
            let polys_t = face_f(&k, &q);
            prop_assert_eq!(&classify_all(&polys_t, &planes_t), &base, "{:?}", m);
            prop_assert_eq!(&split_shape(&polys_t, &planes_t), &shape, "{:?}", m);
            if m.mirrors() {
                let unreversed: Vec<[f64; 3]> = face.iter().map(|&p| m.apply(p)).collect();
                let got = classify_all(&face_f(&k, &unreversed), &planes_t);
                let want: Vec<Option<PolygonSide>> = base.iter().map(|s| s.map(flip_side)).collect();
                prop_assert_eq!(&got, &want);
            }
        }
    }

    /// Lattice polygons (multiples of 2^-25 below 2^-2 in magnitude) translated by powers
    /// of two up to 2^27 (exact: 53 bits suffice) keep every classification and split
    /// shape; so do point-normal planes translated with them.
    #[test]
    fn power_of_two_translations_preserve_classification(
        pts in lattice_polygon(),
        tri in prop::collection::vec(grid_point(), 3..9),
        normals in prop::collection::vec([-4i64..=4, -4i64..=4, -4i64..=4], 1..3),
        e in prop::sample::select(vec![-20i32, -3, 0, 1, 7, 20, 27]),
        signs in [any::<bool>(), any::<bool>(), any::<bool>()],
    ) {
        let k = kernel();
        let t: [f64; 3] = std::array::from_fn(|i| if signs[i] { 1.0 } else { -1.0 } * 2f64.powi(e));
        let mv = |p: [f64; 3]| [p[0] + t[0], p[1] + t[1], p[2] + t[2]];
        let face0: Vec<[f64; 3]> = pts.iter().map(|&g| gp(g)).collect();
        let face1: Vec<[f64; 3]> = face0.iter().map(|&p| mv(p)).collect();
        // The translation is exact.
        for (a, b) in face0.iter().zip(&face1) {
            for i in 0..3 {
                prop_assert_eq!(b[i] - t[i], a[i]);
            }
        }
        let tri_w: Vec<[f64; 3]> = tri.iter().map(|&g| gp(g)).collect();
        let planes = |shift: &dyn Fn([f64; 3]) -> [f64; 3]| -> Vec<Option<Plane>> {
            let mut out: Vec<Option<Plane>> = tri_w
                .chunks(3)
                .filter(|c| c.len() == 3)
                .map(|c| Plane::through(shift(c[0]), shift(c[1]), shift(c[2])).ok())
                .collect();
            out.push(Plane::through(shift(face0[0]), shift(face0[1]), shift(tri_w[0])).ok());
            out.push(Plane::through(shift(face0[1]), shift(face0[2]), shift(face0[0])).ok());
            for n in &normals {
                let n = n.map(|v| v as f64);
                out.push(Plane::point_normal(shift(face0[0]), n).ok());
                out.push(Plane::point_normal(shift(tri_w[1]), n).ok());
            }
            out
        };
        let p0 = planes(&|p| p);
        let p1 = planes(&mv);
        prop_assert_eq!(p0.iter().map(Option::is_some).collect::<Vec<_>>(), p1.iter().map(Option::is_some).collect::<Vec<_>>());
        let (f0, f1) = (face_f(&k, &face0), face_f(&k, &face1));
        prop_assert_eq!(classify_all(&f1, &p1), classify_all(&f0, &p0));
        prop_assert_eq!(split_shape(&f1, &p1), split_shape(&f0, &p0));
    }

    /// Permuting the faces of a scene permutes the classification matrix (faces against
    /// the supports of all faces and a few other planes) and nothing else: no decision
    /// depends on which faces were converted before.
    #[test]
    fn face_permutation_permutes_the_results(
        faces in prop::collection::vec(lattice_polygon(), 2..6),
        perm_seed in any::<u64>(),
    ) {
        let k = kernel();
        let convert = |fs: &[Vec<[i64; 3]>]| -> Vec<Vec<ExactPolygon>> { fs.iter().map(|f| face(&k, f)).collect() };
        let matrix = |polys: &[Vec<ExactPolygon>], planes: &[Vec<Option<Plane>>]| -> Vec<Vec<Vec<Option<PolygonSide>>>> {
            polys
                .iter()
                .map(|ps| planes.iter().map(|hs| classify_all(ps, hs)).collect())
                .collect()
        };
        let planes_of = |polys: &[Vec<ExactPolygon>], fs: &[Vec<[i64; 3]>]| -> Vec<Vec<Option<Plane>>> {
            polys
                .iter()
                .zip(fs)
                .map(|(ps, f)| {
                    let mut v: Vec<Option<Plane>> = ps.iter().map(|p| Some(p.support())).collect();
                    v.push(plane_g(f[0], f[1], [f[2][0], f[2][1], f[2][2] + 1]));
                    v
                })
                .collect()
        };
        let polys = convert(&faces);
        let planes = planes_of(&polys, &faces);
        let base = matrix(&polys, &planes);
        // A permutation from the seed (Fisher–Yates on a SplitMix sequence).
        let mut order: Vec<usize> = (0..faces.len()).collect();
        let mut s = perm_seed;
        for i in (1..order.len()).rev() {
            s = s.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let z = (s ^ (s >> 31)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            order.swap(i, (z % (i as u64 + 1)) as usize);
        }
        let permuted: Vec<Vec<[i64; 3]>> = order.iter().map(|&i| faces[i].clone()).collect();
        let polys_p = convert(&permuted);
        let planes_p = planes_of(&polys_p, &permuted);
        let got = matrix(&polys_p, &planes_p);
        for (a, &i) in order.iter().enumerate() {
            for (b, &j) in order.iter().enumerate() {
                prop_assert_eq!(&got[a][b], &base[i][j]);
            }
        }
    }
}
