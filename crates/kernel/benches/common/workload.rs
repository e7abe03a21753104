//! Deterministic workloads shared by the divan benchmarks and the `kernel_ratios`
//! example: the same polygons and planes for the naive f64 evaluation, the float kernel
//! and the exact kernel.

#![allow(dead_code)]

use glam::DVec3;
use limn_kernel::{
    ExactKernel, ExactPolygon, FloatKernel, FloatPlane, FloatPolygon, Kernel, Plane,
};

/// A small deterministic generator (SplitMix64).
pub struct Rng(u64);

impl Rng {
    /// A generator from a seed.
    pub fn new(seed: u64) -> Rng {
        Rng(seed)
    }
    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [-1, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
    /// A point uniform in [-1, 1)³.
    pub fn point(&mut self) -> DVec3 {
        DVec3::new(self.unit(), self.unit(), self.unit())
    }
}

/// Pairs (polygon, plane) to classify, in every representation.
pub struct ClassifySet {
    /// Exact polygons.
    pub exact_polys: Vec<ExactPolygon>,
    /// The same polygons in the float kernel.
    pub float_polys: Vec<FloatPolygon>,
    /// Exact planes, one per polygon.
    pub exact_planes: Vec<Plane>,
    /// The same planes in the float kernel.
    pub float_planes: Vec<FloatPlane>,
    /// Vertices (world, f64) of each polygon, for the naive evaluation.
    pub naive_polys: Vec<Vec<[f64; 3]>>,
    /// Plane coefficients `(a, b, c, d)` in world units, for the naive evaluation.
    pub naive_planes: Vec<[f64; 4]>,
    /// Number of vertex classifications in one pass over all pairs.
    pub vertex_count: usize,
}

/// Pairs per workload.
pub const PAIRS: usize = 4096;

/// A triangle, the triangle whose plane it is classified against, and an optional cut
/// (point, normal) applied to the first triangle beforehand.
type Pair = ([DVec3; 3], [DVec3; 3], Option<(DVec3, DVec3)>);

fn triangle(rng: &mut Rng) -> [DVec3; 3] {
    let c = rng.point() * 0.8;
    let r = 0.05 + 0.15 * rng.unit().abs();
    [
        c + rng.point() * r,
        c + rng.point() * r,
        c + rng.point() * r,
    ]
}

fn naive_plane(p: &FloatPlane) -> [f64; 4] {
    [p.normal.x, p.normal.y, p.normal.z, -p.w]
}

impl ClassifySet {
    fn build(pairs: Vec<Pair>) -> ClassifySet {
        let (e, f) = kernels();
        let mut s = ClassifySet {
            exact_polys: Vec::new(),
            float_polys: Vec::new(),
            exact_planes: Vec::new(),
            float_planes: Vec::new(),
            naive_polys: Vec::new(),
            naive_planes: Vec::new(),
            vertex_count: 0,
        };
        for (tri, plane_tri, cut) in pairs {
            let (Ok(ep), Ok(fp), Ok(eh), Ok(fh)) = (
                e.face_polygons(&tri),
                f.face_polygons(&tri),
                e.face_polygons(&plane_tri),
                f.face_polygons(&plane_tri),
            ) else {
                continue;
            };
            let (Some(mut ep), Some(mut fp), Some(eh), Some(fh)) = (
                ep.first().cloned(),
                fp.first().cloned(),
                eh.first(),
                fh.first(),
            ) else {
                continue;
            };
            // Optionally replace the triangle by a piece of it (implicit vertices).
            if let Some((p, n)) = cut {
                let (Ok(ec), Ok(fc)) = (e.plane_through(p, n), f.plane_through(p, n)) else {
                    continue;
                };
                let (Some(ea), Some(fa)) = (e.split(&ep, &ec).0, f.split(&fp, &fc).0) else {
                    continue;
                };
                ep = ea;
                fp = fa;
            }
            let mut world = Vec::new();
            f.vertices_world(&fp, &mut world);
            s.vertex_count += e.vertex_count(&ep);
            s.naive_polys
                .push(world.iter().map(|v| v.to_array()).collect());
            s.naive_planes.push(naive_plane(f.support(fh)));
            s.exact_planes.push(e.support(eh).clone());
            s.float_planes.push(*f.support(fh));
            s.exact_polys.push(ep);
            s.float_polys.push(fp);
        }
        s
    }

    /// Random triangles (half of them cut once, so they have implicit vertices) against
    /// the planes of unrelated random triangles.
    pub fn random() -> ClassifySet {
        let mut rng = Rng::new(1);
        let pairs = (0..PAIRS)
            .map(|i| {
                let t = triangle(&mut rng);
                let h = triangle(&mut rng);
                let c = (t[0] + t[1] + t[2]) / 3.0;
                let cut = (i % 2 == 1).then(|| (c, rng.point()));
                (t, h, cut)
            })
            .collect();
        ClassifySet::build(pairs)
    }

    /// Near-degenerate: each triangle against the plane of a neighbour sharing an edge (two
    /// vertices exactly on the plane), or a piece of a triangle against a plane nearly
    /// through its cut.
    pub fn degenerate() -> ClassifySet {
        let mut rng = Rng::new(2);
        let pairs = (0..PAIRS)
            .map(|i| {
                let t = triangle(&mut rng);
                let d = t[0] + t[1] - t[2] + rng.point() * 0.01;
                let h = [t[1], t[0], d];
                let cut = (i % 2 == 1).then(|| {
                    let c = (t[0] + t[1] + t[2]) / 3.0;
                    (c, (t[1] - t[0]).cross(rng.point()))
                });
                (t, h, cut)
            })
            .collect();
        ClassifySet::build(pairs)
    }

    /// One ulp: each triangle against the plane through two of its corners and its third
    /// corner moved by one ulp on one axis (the third corner, and the new vertices of the
    /// cut half of the triangles, are about 1e-16 from the plane: the filter cannot decide
    /// and the exact path runs).
    pub fn ulp() -> ClassifySet {
        let mut rng = Rng::new(4);
        let pairs = (0..PAIRS)
            .map(|i| {
                let t = triangle(&mut rng);
                let mut c = t[2];
                let axis = (rng.next_u64() % 3) as usize;
                c[axis] = if rng.next_u64() & 1 == 0 {
                    c[axis].next_up()
                } else {
                    c[axis].next_down()
                };
                let h = [t[0], t[1], c];
                let cut = (i % 2 == 1).then(|| {
                    let m = (t[0] + t[1] + t[2]) / 3.0;
                    (m, (t[1] - t[0]).cross(rng.point()))
                });
                (t, h, cut)
            })
            .collect();
        ClassifySet::build(pairs)
    }

    /// The workload of a benchmark argument: `"random"`, `"degenerate"` or `"ulp"`.
    pub fn named(name: &str) -> ClassifySet {
        match name {
            "random" => ClassifySet::random(),
            "degenerate" => ClassifySet::degenerate(),
            _ => ClassifySet::ulp(),
        }
    }
}

/// The kernels of every workload (the float kernel's epsilon for the box [-1, 1]³).
pub fn kernels() -> (ExactKernel, FloatKernel) {
    let (lo, hi) = (DVec3::splat(-1.0), DVec3::splat(1.0));
    (ExactKernel::new(), FloatKernel::new(lo, hi).unwrap())
}

/// Naive f64 classification of every pair (no error bound); returns a checksum.
pub fn classify_naive(s: &ClassifySet) -> usize {
    let mut acc = 0;
    for (poly, h) in s.naive_polys.iter().zip(&s.naive_planes) {
        let (mut front, mut back) = (false, false);
        for v in poly {
            let t = h[0] * v[0] + h[1] * v[1] + h[2] * v[2] + h[3];
            front |= t > 0.0;
            back |= t < 0.0;
        }
        acc += front as usize + 2 * back as usize;
    }
    acc
}

/// Classification of every pair by a kernel; returns a checksum.
pub fn classify_exact(k: &ExactKernel, s: &ClassifySet) -> usize {
    s.exact_polys
        .iter()
        .zip(&s.exact_planes)
        .map(|(p, h)| k.classify(p, h) as usize)
        .sum()
}

/// Classification of every pair by the float kernel; returns a checksum.
pub fn classify_float(k: &FloatKernel, s: &ClassifySet) -> usize {
    s.float_polys
        .iter()
        .zip(&s.float_planes)
        .map(|(p, h)| k.classify(p, h) as usize)
        .sum()
}

/// Triangles with a plane through their interior each (every split is a real split).
pub struct SplitSet {
    /// Exact polygons and planes.
    pub exact: Vec<(ExactPolygon, Plane)>,
    /// The same in the float kernel.
    pub float: Vec<(FloatPolygon, FloatPlane)>,
}

impl Default for SplitSet {
    fn default() -> SplitSet {
        SplitSet::new()
    }
}

impl SplitSet {
    /// The workload.
    pub fn new() -> SplitSet {
        let (e, f) = kernels();
        let mut rng = Rng::new(3);
        let mut s = SplitSet {
            exact: Vec::new(),
            float: Vec::new(),
        };
        while s.exact.len() < PAIRS {
            let t = triangle(&mut rng);
            let c = (t[0] + t[1] + t[2]) / 3.0;
            let n = rng.point();
            let (Ok(ep), Ok(fp), Ok(eh), Ok(fh)) = (
                e.face_polygons(&t),
                f.face_polygons(&t),
                e.plane_through(c, n),
                f.plane_through(c, n),
            ) else {
                continue;
            };
            if let (Some(ep), Some(fp)) = (ep.first(), fp.first()) {
                s.exact.push((ep.clone(), eh));
                s.float.push((fp.clone(), fh));
            }
        }
        s
    }
}

/// Splits every pair with the exact kernel; returns a checksum.
pub fn split_exact(k: &ExactKernel, s: &SplitSet) -> usize {
    s.exact
        .iter()
        .map(|(p, h)| {
            let (a, b) = k.split(p, h);
            a.map_or(0, |a| a.len()) + b.map_or(0, |b| b.len())
        })
        .sum()
}

/// Splits every pair with the float kernel; returns a checksum.
pub fn split_float(k: &FloatKernel, s: &SplitSet) -> usize {
    s.float
        .iter()
        .map(|(p, h)| {
            let (a, b) = k.split(p, h);
            a.map_or(0, |a| k.vertex_count(&a)) + b.map_or(0, |b| k.vertex_count(&b))
        })
        .sum()
}
