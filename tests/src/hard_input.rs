//! Near-parallel scenes for exactness on the raw f64 input: faces crossing at tiny
//! angles, stacks of nearly parallel quads that pierce their neighbours, needles, and
//! the same scenes far from the origin, very small and very large. Also the exact
//! symmetries (rotations by 90°, mirrors, translations by representable offsets, face
//! permutations, rotated vertex lists) for invariance tests, and the lines where faces
//! meet (in f64, only to mark pixels near them).
//!
//! Every scene comes with its camera. Quads are tilted about one coordinate axis only,
//! so they stay exactly planar after any scaling, translation or symmetry applied here
//! (the two corners on each side of the tilt axis share their tilted coordinate).

use glam::DVec3;
use limn_scene::{Camera, Scene};
use limn_zbuffer::{edge_band, Mask, Segment2};
use num_bigint::{BigInt, Sign};
use num_rational::BigRational;
use num_traits::float::FloatCore;
use num_traits::Zero;

/// A named scene with its camera.
#[derive(Debug, Clone)]
pub struct Scenario {
    /// Name used in test output.
    pub name: String,
    /// The scene.
    pub scene: Scene,
    /// The camera.
    pub camera: Camera,
    /// A translation that was applied to a scene near the origin: subtracting it again
    /// (exactly, see [`recentred`]) gives a congruent scene near the origin.
    pub offset: DVec3,
}

fn start() -> (Scene, Vec<u32>, u32) {
    crate::corpus::palette_scene("near_parallel")
}

fn v(x: f64, y: f64, z: f64) -> DVec3 {
    DVec3::new(x, y, z)
}

/// Picture size of every scenario (square).
pub const SIZE: u32 = 256;

fn camera(eye: DVec3, target: DVec3) -> Camera {
    Camera::new(eye, target, SIZE, SIZE)
}

fn scenario(name: String, scene: Scene, camera: Camera) -> Scenario {
    Scenario {
        name,
        scene,
        camera,
        offset: DVec3::ZERO,
    }
}

/// A deterministic sequence in [0, 1).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64) / ((1u64 << 53) as f64)
    }
}

/// Two large quads crossing at `angle` rad: the square [-1, 1]² in z = 0 and a quad
/// tilted about an axis parallel to y through x = 0.137. The crossing line runs through
/// the middle of the picture, so the wrong order shows about half of the second quad.
pub fn crossing_quads(angle: f64) -> Scenario {
    let (mut s, m, o) = start();
    let t = angle.tan();
    let x0 = 0.137;
    s.add_polygon(
        &[
            v(-1.0, -1.0, 0.0),
            v(1.0, -1.0, 0.0),
            v(1.0, 1.0, 0.0),
            v(-1.0, 1.0, 0.0),
        ],
        m[0],
        o,
    )
    .expect("valid");
    let (xl, xr) = (-0.9, 0.95);
    let (zl, zr) = (t * (xl - x0), t * (xr - x0));
    s.add_polygon(
        &[
            v(xl, -0.8, zl),
            v(xr, -0.8, zr),
            v(xr, 0.85, zr),
            v(xl, 0.85, zl),
        ],
        m[1],
        o,
    )
    .expect("valid");
    scenario(
        format!("quads_{angle:e}"),
        s,
        camera(v(0.1, 0.2, 4.0), v(0.0, 0.0, 0.0)),
    )
}

/// Two large triangles in a general plane crossing at about `angle` rad along a line
/// that is oblique on screen; the first lies in z = 0.3x − 0.2y + 0.1, the second in
/// that plane plus `tan(angle)·(0.6(x − 0.11) + 0.8(y + 0.07))`.
pub fn crossing_triangles(angle: f64) -> Scenario {
    let (mut s, m, o) = start();
    let t = angle.tan();
    let za = |x: f64, y: f64| 0.3 * x - 0.2 * y + 0.1;
    let zb = |x: f64, y: f64| za(x, y) + t * (0.6 * (x - 0.11) + 0.8 * (y + 0.07));
    let a = [(-1.2, -1.0), (1.1, -0.9), (0.1, 1.2)];
    let b = [(-1.0, 0.9), (-0.7, -1.1), (1.2, 0.3)];
    s.add_polygon(&a.map(|(x, y)| v(x, y, za(x, y))), m[0], o)
        .expect("valid");
    s.add_polygon(&b.map(|(x, y)| v(x, y, zb(x, y))), m[1], o)
        .expect("valid");
    scenario(
        format!("triangles_{angle:e}"),
        s,
        camera(v(-0.15, 0.25, 4.0), v(0.0, 0.0, 0.1)),
    )
}

/// `n` quads stacked `gap` apart along z, each tilted about the x or the y axis
/// (alternately) by ±`tilt`·[0.7, 1.3) rad around a centre line within ±0.4 of the
/// middle, so that neighbours (and the layers two apart, whose slopes have opposite
/// signs) pierce each other along lines inside the picture; the extents vary a little,
/// so many layers show edges.
pub fn stack(n: usize, gap: f64, tilt: f64, seed: u64) -> Scenario {
    let (mut s, m, o) = start();
    let mut r = Rng(seed);
    for k in 0..n {
        let slope = tilt * (0.7 + 0.6 * r.next()) * if (k / 2) % 2 == 0 { 1.0 } else { -1.0 };
        let c = 0.8 * r.next() - 0.4;
        let (x0, x1) = (-1.0 + 0.2 * r.next(), 1.0 - 0.2 * r.next());
        let (y0, y1) = (-1.0 + 0.2 * r.next(), 1.0 - 0.2 * r.next());
        let base = k as f64 * gap;
        let z = |u: f64| base + slope * (u - c);
        let corners = if k % 2 == 0 {
            [
                v(x0, y0, z(x0)),
                v(x1, y0, z(x1)),
                v(x1, y1, z(x1)),
                v(x0, y1, z(x0)),
            ]
        } else {
            [
                v(x0, y0, z(y0)),
                v(x1, y0, z(y0)),
                v(x1, y1, z(y1)),
                v(x0, y1, z(y1)),
            ]
        };
        s.add_polygon(&corners, m[k % m.len()], o).expect("valid");
    }
    scenario(
        format!("stack{n}_{gap:e}_{tilt:e}"),
        s,
        camera(v(0.15, -0.1, 4.0), v(0.0, 0.0, 0.0)),
    )
}

/// Which view of [`needles`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NeedleView {
    /// The whole scene: the needles cover no pixel centre and only take part in the
    /// ordering (as splitters).
    Whole,
    /// A field of view about 4e-7 units across, centred where the first needle
    /// pierces the square at a moderate angle.
    Steep,
    /// The same, centred where the last needle, at about 1e-7 rad to the square, crosses
    /// it.
    Flat,
}

/// Needle triangles 1e-7 wide at their base and about 1.5 long piercing the square
/// [-1, 1]² in z = 0: three at moderate angles, one at about 1e-7 rad to the square.
pub fn needles(view: NeedleView) -> Scenario {
    let (mut s, m, o) = start();
    s.add_polygon(
        &[
            v(-1.0, -1.0, 0.0),
            v(1.0, -1.0, 0.0),
            v(1.0, 1.0, 0.0),
            v(-1.0, 1.0, 0.0),
        ],
        m[0],
        o,
    )
    .expect("valid");
    let w = 1e-7;
    // (apex, middle of the base, direction of the base).
    let needles = [
        (v(-0.5, 0.2, -0.4), v(0.6, 0.225, 0.5), v(0.3, -1.0, 0.7)),
        (v(0.7, -0.6, 0.45), v(-0.4, 0.1, -0.6), v(1.0, 1.0, 0.2)),
        (v(0.2, 0.9, 0.8), v(-0.1, -0.8, -0.7), v(1.0, 0.1, -0.3)),
        (
            v(-0.7, -0.5, -0.7e-7),
            v(0.8, -0.4, 0.8e-7),
            v(0.05, 1.0, 0.0),
        ),
    ];
    for (k, &(apex, base, side)) in needles.iter().enumerate() {
        let h = side.normalize() * (w / 2.0);
        s.add_polygon(&[apex, base - h, base + h], m[k + 1], o)
            .expect("valid");
    }
    // Where the axis of needle `k` meets z = 0.
    let pierce = |k: usize| {
        let (a, b, _) = needles[k];
        let t = a.z / (a.z - b.z);
        let p = a + (b - a) * t;
        v(p.x, p.y, 0.0)
    };
    let zoom = |target: DVec3| {
        let mut c = camera(target + v(0.1, 0.2, 4.0), target);
        let dist = (c.eye - c.target).length();
        c.fov_deg = (2.0 * (2e-7 / dist).atan()).to_degrees();
        c
    };
    let (name, cam) = match view {
        NeedleView::Whole => ("needles", camera(v(0.1, 0.2, 4.0), v(0.0, 0.0, 0.0))),
        NeedleView::Steep => ("needles_zoom_steep", zoom(pierce(0))),
        NeedleView::Flat => ("needles_zoom_flat", zoom(pierce(3))),
    };
    scenario(name.to_string(), s, cam)
}

/// Applies the affine map `f` to every vertex and to the camera's eye and target, and
/// its linear part `f(p) − f(0)` to the camera's up vector.
pub fn mapped(s: &Scenario, suffix: &str, f: impl Fn(DVec3) -> DVec3) -> Scenario {
    let mut out = s.clone();
    out.name = format!("{}{suffix}", s.name);
    for p in &mut out.scene.vertices {
        *p = f(*p);
    }
    out.camera.eye = f(s.camera.eye);
    out.camera.target = f(s.camera.target);
    out.camera.up = f(s.camera.up) - f(DVec3::ZERO);
    out.offset = f(s.offset) - f(DVec3::ZERO);
    out
}

/// `s` translated by `offset` (rounded as f64 addition rounds).
pub fn translated(s: &Scenario, suffix: &str, offset: DVec3) -> Scenario {
    let mut out = mapped(s, suffix, |p| p + offset);
    out.offset = s.offset + offset;
    out
}

/// `s` far from the origin (translated by 1e7 on every axis), scaled by 1e-9 and by
/// 1e9 (the camera moves with the scene).
pub fn far_and_scaled(s: &Scenario) -> Vec<Scenario> {
    vec![
        translated(s, "+1e7", DVec3::splat(1e7)),
        mapped(s, "*1e-9", |p| p * 1e-9),
        mapped(s, "*1e9", |p| p * 1e9),
    ]
}

/// The scene translated back by its [`Scenario::offset`]. For a scene translated by
/// 1e7 this is exact (each coordinate is within a factor of two of the offset), so the
/// result is congruent to the translated scene, with coordinates near the origin.
pub fn recentred(s: &Scenario) -> Scenario {
    if s.offset == DVec3::ZERO {
        return s.clone();
    }
    let off = s.offset;
    let mut out = mapped(s, "", |p| p - off);
    out.name = format!("{} (recentred)", s.name);
    out.offset = DVec3::ZERO;
    out
}

/// The crossings: quads at 1e-7, 1e-9 and 1e-12 rad, oblique triangles at the same
/// angles, each also far, small and large.
pub fn crossings() -> Vec<Scenario> {
    let mut out = Vec::new();
    for angle in [1e-7, 1e-9, 1e-12] {
        for base in [crossing_quads(angle), crossing_triangles(angle)] {
            out.push(base.clone());
            out.extend(far_and_scaled(&base));
        }
    }
    out
}

/// The stacks: 60 quads 1e-6 apart with tilts about 1e-5, and 24 quads 1e-7, 1e-8 and
/// 1e-9 apart with tilts about 1e-6, 1e-7 and 1e-9; each also far, small and large.
pub fn stacks() -> Vec<Scenario> {
    let mut out = Vec::new();
    for (n, gap, tilt) in [
        (60, 1e-6, 1e-5),
        (24, 1e-7, 1e-6),
        (24, 1e-8, 1e-7),
        (24, 1e-9, 1e-9),
    ] {
        let base = stack(n, gap, tilt, 7);
        out.push(base.clone());
        out.extend(far_and_scaled(&base));
    }
    out
}

/// The needles, seen whole and through both narrow views, these also small and large.
/// Not far: at 1e7 the spacing of f64 values (1.9e-9) is about a pixel of the narrow
/// views, so neither the ray caster's f64 rays nor any f64 picture could resolve them.
pub fn needle_scenes() -> Vec<Scenario> {
    let mut out = vec![needles(NeedleView::Whole)];
    for view in [NeedleView::Steep, NeedleView::Flat] {
        let z = needles(view);
        out.push(mapped(&z, "*1e-9", |p| p * 1e-9));
        out.push(mapped(&z, "*1e9", |p| p * 1e9));
        out.insert(out.len() - 2, z);
    }
    out
}

/// Every scenario of this module.
pub fn all() -> Vec<Scenario> {
    let mut v = crossings();
    v.extend(stacks());
    v.extend(needle_scenes());
    v
}

// ---------------------------------------------------------------------------------
// Exact symmetries.

/// Rounds every coordinate (vertices, eye, target) to a multiple of 2^-`bits`, so that
/// translations by small integers stay exact.
pub fn dyadic(s: &Scenario, bits: i32) -> Scenario {
    let q = 2f64.powi(bits);
    let mut out = mapped(s, "", |p| (p * q).round() / q);
    out.camera.up = s.camera.up;
    out.name = s.name.clone();
    out
}

/// A map of space that f64 arithmetic performs exactly on the scenes it is used on: a
/// signed permutation of the axes followed by a translation.
#[derive(Debug, Clone, Copy)]
pub struct Symmetry {
    /// Name in test output.
    pub name: &'static str,
    /// The linear part: swaps and negations of coordinates only (always exact).
    pub linear: fn(DVec3) -> DVec3,
    /// The translation (exact on coordinates on a coarse enough dyadic grid).
    pub offset: DVec3,
    /// Whether it reverses orientation (the picture is then mirrored left to right).
    pub mirrors: bool,
}

impl Symmetry {
    /// The image of `p`.
    pub fn apply(&self, p: DVec3) -> DVec3 {
        (self.linear)(p) + self.offset
    }

    /// Whether the translation is exact on `p` (it round-trips).
    pub fn exact_at(&self, p: DVec3) -> bool {
        let l = (self.linear)(p);
        (l + self.offset) - self.offset == l
    }

    /// Whether the map is exact on every vertex of `s` and on its eye and target.
    pub fn exact_on(&self, s: &Scenario) -> bool {
        s.scene
            .vertices
            .iter()
            .chain([&s.camera.eye, &s.camera.target])
            .all(|&p| self.exact_at(p))
    }

    /// `s` mapped (vertices, eye, target; up by the linear part).
    pub fn image(&self, s: &Scenario) -> Scenario {
        let mut out = mapped(s, &format!(" {}", self.name), |p| self.apply(p));
        out.camera.up = (self.linear)(s.camera.up);
        out
    }
}

/// The identity, rotations by 90° about x, y and z, a mirror, a translation by
/// (3, −5, 1024), and a composition of a rotation, the mirror and a translation.
pub fn symmetries() -> Vec<Symmetry> {
    let sym = |name, linear, offset, mirrors| Symmetry {
        name,
        linear,
        offset,
        mirrors,
    };
    vec![
        sym("identity", |p| p, DVec3::ZERO, false),
        sym("rot90x", |p| v(p.x, -p.z, p.y), DVec3::ZERO, false),
        sym("rot90y", |p| v(p.z, p.y, -p.x), DVec3::ZERO, false),
        sym("rot90z", |p| v(-p.y, p.x, p.z), DVec3::ZERO, false),
        sym("mirror_x", |p| v(-p.x, p.y, p.z), DVec3::ZERO, true),
        sym("translate", |p| p, v(3.0, -5.0, 1024.0), false),
        sym("all", |p| v(p.z, p.x, -p.y), v(-7.0, 2.0, 16.0), true),
    ]
}

/// `s` with its faces in the order `perm` (new face `i` is old face `perm[i]`) and each
/// face's vertex list rotated by its new index (mod its length). Returns the scenario and
/// the map from new face ids to old ones (`perm` itself).
pub fn permuted(s: &Scenario, perm: &[u32]) -> Scenario {
    let mut out = s.clone();
    out.name = format!("{} (permuted)", s.name);
    out.scene.faces = perm
        .iter()
        .enumerate()
        .map(|(i, &old)| {
            let mut f = s.scene.faces[old as usize].clone();
            let n = f.vertices.len();
            f.vertices.rotate_left(i % n);
            if let Some(ns) = &mut f.normals {
                ns.rotate_left(i % n);
            }
            f
        })
        .collect();
    out
}

/// A fixed permutation of `n` faces: reversed, then adjacent pairs swapped.
pub fn shuffle(n: usize) -> Vec<u32> {
    let mut p: Vec<u32> = (0..n as u32).rev().collect();
    for pair in p.chunks_mut(2) {
        pair.reverse();
    }
    p
}

// ---------------------------------------------------------------------------------
// Where faces meet.

/// The segments where two faces of `scene` meet (in f64; for marking pixels near them,
/// not for decisions). Exactly coplanar pairs are skipped.
pub fn crossing_segments(scene: &Scene) -> Vec<(DVec3, DVec3)> {
    let polys: Vec<Vec<DVec3>> = (0..scene.faces.len() as u32)
        .map(|f| scene.face_points(f))
        .collect();
    let planes: Vec<(DVec3, f64)> = polys
        .iter()
        .map(|p| {
            let n = limn_scene::polygon_normal(p);
            (n, n.dot(p[0]))
        })
        .collect();
    // Where polygon `a` meets the plane `pl`: the segment of its boundary's crossings.
    let cut = |a: &[DVec3], (n, d): (DVec3, f64)| -> Option<(DVec3, DVec3)> {
        let s: Vec<f64> = a.iter().map(|&p| n.dot(p) - d).collect();
        let mut pts = Vec::new();
        for i in 0..a.len() {
            let j = (i + 1) % a.len();
            if s[i] == 0.0 {
                pts.push(a[i]);
            }
            if (s[i] < 0.0 && s[j] > 0.0) || (s[i] > 0.0 && s[j] < 0.0) {
                let t = s[i] / (s[i] - s[j]);
                pts.push(a[i] + (a[j] - a[i]) * t);
            }
        }
        (pts.len() >= 2).then(|| (pts[0], pts[pts.len() - 1]))
    };
    let mut out = Vec::new();
    for i in 0..polys.len() {
        for j in i + 1..polys.len() {
            let dir = planes[i].0.cross(planes[j].0);
            if dir == DVec3::ZERO {
                continue;
            }
            let (Some(si), Some(sj)) = (cut(&polys[i], planes[j]), cut(&polys[j], planes[i]))
            else {
                continue;
            };
            // Both segments lie on the line of the two planes: keep their overlap.
            let t = |p: DVec3| p.dot(dir);
            let (a0, a1) = (t(si.0).min(t(si.1)), t(si.0).max(t(si.1)));
            let (b0, b1) = (t(sj.0).min(t(sj.1)), t(sj.0).max(t(sj.1)));
            let (lo, hi) = (a0.max(b0), a1.min(b1));
            if lo > hi {
                continue;
            }
            let (p, q) = (si.0, si.1);
            let (tp, tq) = (t(p), t(q));
            let at = |x: f64| {
                if tq == tp {
                    p
                } else {
                    p + (q - p) * ((x - tp) / (tq - tp))
                }
            };
            out.push((at(lo), at(hi)));
        }
    }
    out
}

/// Pixels within `tolerance_px` of where two faces meet, as seen by `camera` with
/// `near_far`. Segments reaching behind the near plane are left out (the scenes here
/// lie wholly in front of the eye).
pub fn crossing_band(
    scene: &Scene,
    camera: &Camera,
    near_far: (f64, f64),
    tolerance_px: f64,
) -> Mask {
    let vp = camera.view_projection(near_far.0, near_far.1);
    let segs: Vec<Segment2> = crossing_segments(scene)
        .into_iter()
        .filter_map(|(a, b)| {
            let (pa, pb) = (camera.project_with(&vp, a), camera.project_with(&vp, b));
            (pa.w > 0.0 && pb.w > 0.0).then_some(([pa.x, pa.y], [pb.x, pb.y]))
        })
        .collect();
    edge_band(&segs, camera.width, camera.height, tolerance_px)
}

// ---------------------------------------------------------------------------------
// Exact coplanarity.

fn rational(x: f64) -> BigRational {
    BigRational::from_float(x).expect("finite")
}

/// Whether faces `a` and `b` lie exactly in one plane (rational arithmetic on the f64
/// coordinates; the plane of `a` is taken through three of its corners that are not
/// collinear).
pub fn exactly_coplanar(scene: &Scene, a: u32, b: u32) -> bool {
    let r = |p: DVec3| [rational(p.x), rational(p.y), rational(p.z)];
    let pa: Vec<[BigRational; 3]> = scene.face_points(a).into_iter().map(r).collect();
    let pb: Vec<[BigRational; 3]> = scene.face_points(b).into_iter().map(r).collect();
    let sub =
        |u: &[BigRational; 3], w: &[BigRational; 3]| [&u[0] - &w[0], &u[1] - &w[1], &u[2] - &w[2]];
    let cross = |u: &[BigRational; 3], w: &[BigRational; 3]| {
        [
            &u[1] * &w[2] - &u[2] * &w[1],
            &u[2] * &w[0] - &u[0] * &w[2],
            &u[0] * &w[1] - &u[1] * &w[0],
        ]
    };
    let dot =
        |u: &[BigRational; 3], w: &[BigRational; 3]| &u[0] * &w[0] + &u[1] * &w[1] + &u[2] * &w[2];
    let mut normal = None;
    'outer: for i in 1..pa.len() {
        for j in i + 1..pa.len() {
            let n = cross(&sub(&pa[i], &pa[0]), &sub(&pa[j], &pa[0]));
            if n.iter().any(|c| !c.is_zero()) {
                normal = Some(n);
                break 'outer;
            }
        }
    }
    let Some(n) = normal else {
        return false;
    };
    pb.iter().all(|q| dot(&n, &sub(q, &pa[0])).is_zero())
}

// ---------------------------------------------------------------------------------
// An independent exact ray cast at single pixel centres.

/// Points as integer vectors in units of a common power of two (exact for f64 input).
type Z3 = [BigInt; 3];

/// The smallest exponent `e` such that every coordinate is an integer multiple of 2^e.
fn min_exponent(pts: &[DVec3]) -> i32 {
    pts.iter()
        .flat_map(|p| p.to_array())
        .filter(|&x| x != 0.0)
        .map(|x| {
            let (m, e, _) = x.integer_decode();
            e as i32 + m.trailing_zeros() as i32
        })
        .min()
        .unwrap_or(0)
}

fn zint(x: f64, e0: i32) -> BigInt {
    if x == 0.0 {
        return BigInt::zero();
    }
    let (m, e, sign) = x.integer_decode();
    let tz = m.trailing_zeros();
    let v = BigInt::from(m >> tz) << (e as i32 + tz as i32 - e0) as usize;
    if sign < 0 {
        -v
    } else {
        v
    }
}

fn z3(p: DVec3, e0: i32) -> Z3 {
    [zint(p.x, e0), zint(p.y, e0), zint(p.z, e0)]
}

fn zsub(a: &Z3, b: &Z3) -> Z3 {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

fn zcross(a: &Z3, b: &Z3) -> Z3 {
    [
        &a[1] * &b[2] - &a[2] * &b[1],
        &a[2] * &b[0] - &a[0] * &b[2],
        &a[0] * &b[1] - &a[1] * &b[0],
    ]
}

fn zdot(a: &Z3, b: &Z3) -> BigInt {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}

/// A point on the ray from the eye through the centre of pixel (`i`, `j`), computed in
/// f64 from the camera's frame (independently of limn-zbuffer's unprojection).
pub fn pixel_ray_point(camera: &Camera, i: u32, j: u32) -> DVec3 {
    let f = camera.forward();
    let s = f.cross(camera.up).normalize();
    let u = s.cross(f);
    let th = (camera.fov_deg.to_radians() * 0.5).tan();
    let x = 2.0 * (i as f64 + 0.5) / camera.width as f64 - 1.0;
    let y = 1.0 - 2.0 * (j as f64 + 0.5) / camera.height as f64;
    let d = (camera.target - camera.eye).length();
    camera.eye + (f + s * (x * th * camera.aspect()) + u * (y * th)) * d
}

/// What [`exact_first_hit`] found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ExactHit {
    /// The first face met in front of the eye, if any.
    First(Option<u32>),
    /// The line passes exactly through some face's boundary (callers skip the sample).
    OnBoundary,
}

/// The face that the line from the eye through `through` meets first in front of the
/// eye, decided with exact integer arithmetic on the f64 input (scaled by a common
/// power of two) (faces must be convex; ties of
/// depth go to the later face).
pub fn exact_first_hit(scene: &Scene, eye: DVec3, through: DVec3) -> ExactHit {
    let mut all = scene.vertices.clone();
    all.extend([eye, through]);
    let e0 = min_exponent(&all);
    let e = z3(eye, e0);
    let d = zsub(&z3(through, e0), &e);
    // The best hit so far as t = num / den with den > 0.
    let mut best: Option<(BigInt, BigInt, u32)> = None;
    for f in 0..scene.faces.len() as u32 {
        let pts: Vec<Z3> = scene
            .face_points(f)
            .into_iter()
            .map(|p| z3(p, e0))
            .collect();
        let rel: Vec<Z3> = pts.iter().map(|p| zsub(p, &e)).collect();
        // The line meets the polygon when d is on one side of every edge's plane
        // through the eye.
        let mut sign = Sign::NoSign;
        let mut inside = true;
        for k in 0..rel.len() {
            let g = zdot(&zcross(&rel[k], &rel[(k + 1) % rel.len()]), &d).sign();
            if g == Sign::NoSign {
                return ExactHit::OnBoundary;
            }
            if sign == Sign::NoSign {
                sign = g;
            } else if g != sign {
                inside = false;
                break;
            }
        }
        if !inside {
            continue;
        }
        let n = zcross(&zsub(&pts[1], &pts[0]), &zsub(&pts[2], &pts[0]));
        let (mut num, mut den) = (zdot(&n, &rel[0]), zdot(&n, &d));
        if den.is_zero() {
            continue;
        }
        if den.sign() == Sign::Minus {
            num = -num;
            den = -den;
        }
        if num.sign() != Sign::Plus {
            continue;
        }
        let nearer = best
            .as_ref()
            .is_none_or(|(bn, bd, _)| &num * bd <= bn * &den);
        if nearer {
            best = Some((num, den, f));
        }
    }
    ExactHit::First(best.map(|(_, _, f)| f))
}
