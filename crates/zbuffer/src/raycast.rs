//! Ray casting with exact predicates: the arbiter.
//!
//! For pixel `(i, j)` the segment from the pixel centre's point on the near plane, `pn`,
//! to its point on the far plane, `pf`, is computed once in f64 (by unprojecting
//! through the inverse view-projection); everything after that is decided exactly for
//! that segment:
//!
//! * the segment crosses a triangle's plane when `orient3d(a, b, c, pn)` and
//!   `orient3d(a, b, c, pf)` have opposite signs or one is zero (hits on the near and
//!   far planes count, as the z-buffer keeps `near ≤ w ≤ far`);
//! * the line `pn pf` passes through the triangle when `orient3d(pn, pf, a, b)`,
//!   `orient3d(pn, pf, b, c)`, `orient3d(pn, pf, c, a)` share a sign; a zero (the centre
//!   exactly on an edge) is resolved by the top-left rule, with the edge's on-screen
//!   direction taken from its clip-space coordinates, so a centre on a shared edge goes
//!   to exactly one triangle;
//! * of two hits, the nearer is the one with the smaller parameter
//!   `t = αn / (αn − αf)` (`α` the plane's `orient3d` at `pn` and `pf`); the comparison
//!   `αn·βf − βn·αf` is filtered in f64 with an error bound and, when the filter cannot
//!   decide, evaluated exactly with floating-point expansions. Exactly equal depths go
//!   to the later face in input order (the painter's rule for coplanar faces).
//!
//! Accepted input: every finite coordinate up to [`crate::MAX_COORD`] (2¹⁰⁰), as for the
//! other methods. A triangle whose non-zero coordinates all have magnitude in
//! `[MIN_RAYCAST_COORD, MAX_COORD]` = [2⁻¹⁰⁰, 2¹⁰⁰] is tested with `robust::orient3d`
//! (exact for exponents in −142..201) and f64 expansions (exact for products of six
//! such numbers); any other triangle (a coordinate of 5e-36, say) with big integers
//! ([`exact::Big`]), exact for every finite value; so is every test of a ray whose
//! endpoints have such a coordinate. Shadow rays still need every vertex in range (an
//! error names the coordinate otherwise).
//!
//! Depth is reported as f64 window depth of the hit point; the depth format option does
//! not apply.

use glam::{DVec3, DVec4};
use limn_scene::{LightSet, Scene};
use robust::{orient3d, Coord3D};

use crate::bvh::{Bvh, Segment};
use crate::exact;
use crate::image::NO_FACE;
use crate::setup::{face_triangles, Culling, Frame};
use crate::shadow_rays::{Casters, Hit as ShadowHit};
use crate::{ZError, MIN_RAYCAST_COORD};

/// Ids and depths of a ray-cast rendering, with counters.
pub(crate) struct Output {
    pub ids: Vec<u32>,
    pub depths: Vec<f64>,
    /// Exact ray–triangle tests run.
    pub tests: u64,
    /// Depth comparisons the float filter could not decide.
    pub exact_fallbacks: u64,
    pub working_bytes: usize,
    /// World triangles tested.
    pub triangles: usize,
    /// Faces dropped as back faces.
    pub culled_faces: usize,
    /// Per pixel, the lights its point is in the shadow of (only when some light casts
    /// shadows).
    pub shadowed: Option<Vec<LightSet>>,
}

#[derive(Clone, Copy)]
struct Tri {
    p: [DVec3; 3],
    face: u32,
    /// On-screen direction of each edge `k → k+1`: (sign of dx, sign of dy), pixels.
    dir: [(i8, i8); 3],
    /// Every coordinate within the range where `robust` and the expansions are exact;
    /// otherwise every decision about the triangle is made with big integers.
    in_range: bool,
}

#[derive(Clone, Copy)]
struct Hit {
    tri: u32,
    an: f64,
    af: f64,
    ean: f64,
    eaf: f64,
    /// Upper bound of the hit parameter.
    t_hi: f64,
    /// Whether `an` and `af` are `orient3d` negated.
    negated: bool,
}

#[inline]
fn c3(v: DVec3) -> Coord3D<f64> {
    Coord3D {
        x: v.x,
        y: v.y,
        z: v.z,
    }
}

#[inline]
fn sgn(x: f64) -> i8 {
    if x > 0.0 {
        1
    } else if x < 0.0 {
        -1
    } else {
        0
    }
}

fn check_small(what: &'static str, p: DVec3) -> Result<(), ZError> {
    for v in p.to_array() {
        if v != 0.0 && v.abs() < MIN_RAYCAST_COORD {
            return Err(ZError::OutOfRange { what, value: v });
        }
    }
    Ok(())
}

/// Screen direction signs of the edge `a → b` from clip coordinates, computed in a
/// canonical order so that `b → a` gets exactly the opposite signs.
fn edge_dir(frame: &Frame, a: DVec3, b: DVec3) -> (i8, i8) {
    let key = |v: DVec3| v.to_array().map(f64::to_bits);
    let (p, q, flip) = if key(a) <= key(b) {
        (a, b, 1)
    } else {
        (b, a, -1)
    };
    let (cp, cq): (DVec4, DVec4) = (frame.clip(p), frame.clip(q));
    // Along the visible part of the edge, ndc moves as these cross terms say (the
    // factor 1/(w_p w_q) is positive once clipped to w > 0).
    let gx = cq.x * cp.w - cp.x * cq.w;
    let gy = cq.y * cp.w - cp.y * cq.w;
    // Pixel y grows downwards.
    (flip * sgn(gx), -flip * sgn(gy))
}

/// Renders by casting one exact ray per pixel centre, and from each hit one exact ray
/// to each light of `casters` (see [`crate::shadow_rays`]).
pub(crate) fn raycast(
    scene: &Scene,
    frame: &Frame,
    cull: Culling<'_>,
    mut casters: Option<&mut Casters>,
) -> Result<Output, ZError> {
    // Shadow rays are exact only in range.
    if casters.is_some() {
        check_small("eye", frame.camera.eye)?;
    }
    let mut tris = Vec::new();
    let mut scratch = Vec::new();
    let mut local = Vec::new();
    let mut culled_faces = 0;
    for f in 0..scene.faces.len() {
        if cull.drops(scene, f, frame.viewpoint) {
            culled_faces += 1;
            continue;
        }
        local.clear();
        face_triangles(scene, f, &mut scratch, &mut local);
        for &(t, _) in &local {
            let p = t.map(|v| scene.vertices[v as usize]);
            if casters.is_some() {
                for &q in &p {
                    check_small("vertex", q)?;
                }
            }
            let dir = [0, 1, 2].map(|k| edge_dir(frame, p[k], p[(k + 1) % 3]));
            tris.push(Tri {
                p,
                face: f as u32,
                dir,
                in_range: p.iter().all(|&q| exact::in_range(q)),
            });
        }
    }
    let boxes: Vec<[DVec3; 3]> = tris.iter().map(|t| t.p).collect();
    let mut bvh = Bvh::build(&boxes);
    drop(boxes);
    // Store the triangles in the hierarchy's leaf order, so a leaf's are contiguous.
    let tris: Vec<Tri> = bvh.order.iter().map(|&k| tris[k as usize]).collect();
    bvh.order = Vec::new();
    let inv = frame.vp.inverse();
    let (w, h) = (frame.width as usize, frame.height as usize);
    let mut out = Output {
        ids: vec![NO_FACE; w * h],
        depths: vec![f64::INFINITY; w * h],
        tests: 0,
        exact_fallbacks: 0,
        working_bytes: tris.len() * std::mem::size_of::<Tri>()
            + bvh.nodes.len() * std::mem::size_of::<crate::bvh::Node>()
            + tris.len() * 4,
        triangles: tris.len(),
        culled_faces,
        shadowed: casters.as_ref().map(|_| vec![LightSet::EMPTY; w * h]),
    };
    let mut shadow_stack = Vec::new();
    if tris.is_empty() {
        return Ok(out);
    }
    let mut stack: Vec<(u32, f64)> = Vec::with_capacity(64);
    for j in 0..h {
        let ny = 1.0 - (j as f64 + 0.5) / h as f64 * 2.0;
        for i in 0..w {
            let nx = (i as f64 + 0.5) / w as f64 * 2.0 - 1.0;
            let un = |z: f64| {
                let q = inv * DVec4::new(nx, ny, z, 1.0);
                q.truncate() / q.w
            };
            let (pn, pf) = (un(-1.0), un(1.0));
            if !(pn.is_finite() && pf.is_finite()) || pn == pf {
                continue;
            }
            let seg = Segment::new(pn, pf);
            let in_range = exact::in_range(pn) && exact::in_range(pf);
            let best = cast(&tris, &bvh, &seg, in_range, &mut stack, &mut out);
            if let Some(hit) = best {
                let t = hit.an / (hit.an - hit.af);
                let t = if t.is_finite() {
                    t.clamp(0.0, 1.0)
                } else {
                    0.0
                };
                let c = frame.clip(pn + (pf - pn) * t);
                let d = ((c.z / c.w + 1.0) * 0.5).clamp(0.0, 1.0);
                out.ids[j * w + i] = tris[hit.tri as usize].face;
                out.depths[j * w + i] = d;
                if let (Some(c), Some(sh)) = (casters.as_deref_mut(), out.shadowed.as_mut()) {
                    let h = ShadowHit {
                        tri: tris[hit.tri as usize].p,
                        pn,
                        pf,
                        an: hit.an,
                        af: hit.af,
                        ean: hit.ean,
                        eaf: hit.eaf,
                        negated: hit.negated,
                    };
                    sh[j * w + i] = c.shadowed(&h, &mut shadow_stack);
                }
            }
        }
    }
    Ok(out)
}

fn cast(
    tris: &[Tri],
    bvh: &Bvh,
    seg: &Segment,
    in_range: bool,
    stack: &mut Vec<(u32, f64)>,
    out: &mut Output,
) -> Option<Hit> {
    let (pn, pf) = (seg.o, seg.o + seg.d);
    let mut best: Option<Hit> = None;
    stack.clear();
    if let Some(t) = seg.enter(&bvh.nodes[0]) {
        stack.push((0, t));
    }
    while let Some((n, tnear)) = stack.pop() {
        if best.is_some_and(|b| tnear > b.t_hi) {
            continue;
        }
        let node = &bvh.nodes[n as usize];
        if node.count > 0 {
            for k in node.first..node.first + node.count {
                out.tests += 1;
                let Some(hit) = test(&tris[k as usize], k, pn, pf, in_range) else {
                    continue;
                };
                best = Some(match best {
                    None => hit,
                    Some(b) => {
                        if nearer(tris, &hit, &b, pn, pf, &mut out.exact_fallbacks) {
                            hit
                        } else {
                            b
                        }
                    }
                });
            }
            continue;
        }
        let (l, r) = (node.first, node.first + 1);
        let tl = seg.enter(&bvh.nodes[l as usize]);
        let tr = seg.enter(&bvh.nodes[r as usize]);
        match (tl, tr) {
            (Some(a), Some(b)) if a <= b => {
                stack.push((r, b));
                stack.push((l, a));
            }
            (Some(a), Some(b)) => {
                stack.push((l, a));
                stack.push((r, b));
            }
            (Some(a), None) => stack.push((l, a)),
            (None, Some(b)) => stack.push((r, b)),
            (None, None) => {}
        }
    }
    best
}

/// The exact segment–triangle test.
#[inline]
fn test(tri: &Tri, k: u32, pn: DVec3, pf: DVec3, ray_in_range: bool) -> Option<Hit> {
    let [a, b, c] = tri.p;
    let (cn, cf) = (c3(pn), c3(pf));
    let corners = [c3(a), c3(b), c3(c)];
    // Out of range, every sign by big integers over the five points' smallest exponent.
    let big = !(tri.in_range && ray_in_range);
    let big = big.then(|| exact::Big::new(&[a, b, c, pn, pf]));
    let orient = |p: DVec3, q: DVec3, r: DVec3, s: DVec3| match &big {
        Some(big) => exact::big_sign(&big.orient3d(p, q, r, s)),
        None => sgn(orient3d(c3(p), c3(q), c3(r), c3(s))),
    };
    // Edge signs, stopping at the first edge with the other sign.
    let mut e = [0i8; 3];
    let mut s = 0i8;
    for i in 0..3 {
        e[i] = match big {
            Some(_) => orient(pn, pf, tri.p[i], tri.p[(i + 1) % 3]),
            None => sgn(orient3d(cn, cf, corners[i], corners[(i + 1) % 3])),
        };
        if e[i] != 0 {
            if s == 0 {
                s = e[i];
            } else if e[i] != s {
                return None;
            }
        }
    }
    if s == 0 {
        return None; // the line lies in the triangle's plane, or the triangle is a point
    }
    // On screen the triangle's orientation is the opposite of `s`.
    let screen_ccw = s < 0;
    for (&ei, &(dx, dy)) in e.iter().zip(&tri.dir) {
        if ei != 0 {
            continue;
        }
        let top_left = if screen_ccw {
            dy < 0 || (dy == 0 && dx > 0)
        } else {
            dy > 0 || (dy == 0 && dx < 0)
        };
        if !top_left {
            return None;
        }
    }
    let sn = orient(a, b, c, pn);
    let sf = orient(a, b, c, pf);
    if sn == sf {
        return None; // same side, or the segment lies in the plane
    }
    let (mut an, ean) = exact::orient3d_bounded(a, b, c, pn);
    let (mut af, eaf) = exact::orient3d_bounded(a, b, c, pf);
    let negated = sn < 0 || (sn == 0 && sf > 0);
    if negated {
        an = -an;
        af = -af;
    }
    let num = (an + ean).max(0.0);
    let den = (-af - eaf).max(0.0);
    // Out of range the floats may have underflowed: no bound, no pruning.
    let t_hi = if big.is_none() && num + den > 0.0 {
        (num / (num + den)) * (1.0 + 1e-12) + 1e-12
    } else {
        1.0
    };
    Some(Hit {
        tri: k,
        an,
        af,
        ean,
        eaf,
        t_hi,
        negated,
    })
}

/// Whether hit `x` is nearer than hit `y`, exactly; equal depths go to the later face.
fn nearer(tris: &[Tri], x: &Hit, y: &Hit, pn: DVec3, pf: DVec3, fallbacks: &mut u64) -> bool {
    // t_x < t_y  ⟺  αn·βf − βn·αf > 0 (with αn ≥ 0 ≥ αf, likewise β).
    let all_in_range = tris[x.tri as usize].in_range
        && tris[y.tri as usize].in_range
        && exact::in_range(pn)
        && exact::in_range(pf);
    if !all_in_range {
        *fallbacks += 1;
        return match big_sign(tris, x, y, pn, pf) {
            1 => true,
            -1 => false,
            _ => tris[x.tri as usize].face > tris[y.tri as usize].face,
        };
    }
    let p1 = x.an * y.af;
    let p2 = y.an * x.af;
    let v = p1 - p2;
    let bound = (x.an.abs() + x.ean) * y.eaf
        + y.af.abs() * x.ean
        + (y.an.abs() + y.ean) * x.eaf
        + x.af.abs() * y.ean
        + 4.0 * f64::EPSILON * (p1.abs() + p2.abs());
    let s = if v > bound {
        1
    } else if v < -bound {
        -1
    } else {
        *fallbacks += 1;
        exact_sign(tris, x, y, pn, pf)
    };
    match s {
        1 => true,
        -1 => false,
        _ => tris[x.tri as usize].face > tris[y.tri as usize].face,
    }
}

/// [`exact_sign`] with big integers, for triangles out of the expansions' range: all
/// four `orient3d` over one common exponent, so each is its value times the same power
/// of two and the comparison keeps its sign.
fn big_sign(tris: &[Tri], x: &Hit, y: &Hit, pn: DVec3, pf: DVec3) -> i8 {
    let [a, b, c] = tris[x.tri as usize].p;
    let [d, e, f] = tris[y.tri as usize].p;
    let big = exact::Big::new(&[a, b, c, d, e, f, pn, pf]);
    let alphas = |[a, b, c]: [DVec3; 3]| {
        let n = big.orient3d(a, b, c, pn);
        let f = big.orient3d(a, b, c, pf);
        let (sn, sf) = (exact::big_sign(&n), exact::big_sign(&f));
        if sn < 0 || (sn == 0 && sf > 0) {
            (-n, -f)
        } else {
            (n, f)
        }
    };
    let (xn, xf) = alphas([a, b, c]);
    let (yn, yf) = alphas([d, e, f]);
    exact::big_sign(&(xn * yf - yn * xf))
}

fn exact_sign(tris: &[Tri], x: &Hit, y: &Hit, pn: DVec3, pf: DVec3) -> i32 {
    let alphas = |h: &Hit| {
        let [a, b, c] = tris[h.tri as usize].p;
        let n = exact::orient3d_exact(a, b, c, pn);
        let f = exact::orient3d_exact(a, b, c, pf);
        let (sn, sf) = (exact::sign(&n), exact::sign(&f));
        if sn < 0 || (sn == 0 && sf > 0) {
            (exact::negate(&n), exact::negate(&f))
        } else {
            (n, f)
        }
    };
    let (xn, xf) = alphas(x);
    let (yn, yf) = alphas(y);
    let d = exact::sum(
        &exact::product(&xn, &yf),
        &exact::negate(&exact::product(&yn, &xf)),
    );
    exact::sign(&d)
}
