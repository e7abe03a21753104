//! Exact shadows for the ray caster: from the point a pixel's ray hits, a ray to each
//! light that casts shadows, decided exactly like the rest of ray casting.
//!
//! The hit point `X` is the intersection of the pixel's segment `pn pf` with the plane of
//! the hit triangle `(a, b, c)`: with `αn`, `αf` that plane's `orient3d` at `pn` and `pf`
//! (normalised so that `αn ≥ 0 ≥ αf`), `X = (αn·pf − αf·pn) / (αn − αf)`, a rational
//! point never rounded. Every predicate used below is an affine function `g` of one
//! point, so its sign at `X` is the sign of `αn·g(pf) − αf·g(pn)`: filtered in f64 with
//! a proven error bound, and evaluated with floating-point expansions when the filter
//! cannot decide.
//!
//! `X` is in the shadow of a light when the light does not lie strictly on the side of
//! the hit plane the eye sees, or when the open segment from `X` to the light (a ray
//! along the direction, for a light at infinity) crosses the interior of an opaque
//! triangle: `X` and the light strictly on opposite sides of its plane, and the line
//! through `X` and the light strictly inside its three edges. Touching a triangle's edge
//! or plane casts no shadow (a set of measure zero; the object-space shadows decide the
//! same way).

use glam::DVec3;
use limn_scene::{LightKind, LightSet, Scene};

use crate::bvh::{Bvh, Segment};
use crate::exact;
use crate::setup::face_triangles;
use crate::{ZError, MIN_RAYCAST_COORD};

/// A light as the shadow rays see it.
#[derive(Debug, Clone, Copy)]
enum Toward {
    At(DVec3),
    Direction(DVec3),
}

/// The pixel's hit, as the shadow rays need it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Hit {
    /// The hit triangle.
    pub tri: [DVec3; 3],
    /// The pixel's segment.
    pub pn: DVec3,
    pub pf: DVec3,
    /// The hit plane's `orient3d` at `pn` and `pf`, normalised (`an ≥ 0 ≥ af`, not both
    /// zero), with error bounds.
    pub an: f64,
    pub af: f64,
    pub ean: f64,
    pub eaf: f64,
    /// Whether the normalisation negated `orient3d`.
    pub negated: bool,
}

/// The opaque triangles and the lights that cast shadows.
pub(crate) struct Casters {
    lights: Vec<(usize, Toward)>,
    tris: Vec<[DVec3; 3]>,
    bvh: Bvh,
    /// Length of a ray towards a light at infinity: beyond every triangle.
    reach: f64,
    /// Exact shadow-ray tests run and exact fallbacks.
    pub tests: u64,
    pub fallbacks: u64,
}

impl Casters {
    /// `None` when no light casts shadows.
    pub fn new(scene: &Scene) -> Result<Option<Casters>, ZError> {
        let set = scene.shadow_lights();
        if set.is_empty() {
            return Ok(None);
        }
        let mut lights = Vec::new();
        for i in set.iter() {
            let t = match scene.lights[i].kind {
                LightKind::Point(p) => Toward::At(p),
                LightKind::Directional(d) => Toward::Direction(d),
                LightKind::Ambient | LightKind::Headlight => continue,
            };
            let v = match t {
                Toward::At(p) | Toward::Direction(p) => p,
            };
            for c in v.to_array() {
                if c != 0.0 && !(MIN_RAYCAST_COORD..=crate::MAX_COORD).contains(&c.abs()) {
                    return Err(ZError::OutOfRange {
                        what: "light",
                        value: c,
                    });
                }
            }
            lights.push((i, t));
        }
        let mut tris = Vec::new();
        let (mut scratch, mut local) = (Vec::new(), Vec::new());
        for (f, face) in scene.faces.iter().enumerate() {
            if !scene.materials[face.material as usize].is_opaque() {
                continue;
            }
            local.clear();
            face_triangles(scene, f, &mut scratch, &mut local);
            for &(t, _) in &local {
                tris.push(t.map(|v| scene.vertices[v as usize]));
            }
        }
        let mut bvh = Bvh::build(&tris);
        let tris: Vec<[DVec3; 3]> = bvh.order.iter().map(|&k| tris[k as usize]).collect();
        bvh.order = Vec::new();
        let reach = match scene.bounds() {
            Some((lo, hi)) => 4.0 * (hi - lo).length() + 4.0 * lo.abs().max(hi.abs()).length(),
            None => 1.0,
        };
        Ok(Some(Casters {
            lights,
            tris,
            bvh,
            reach: reach.max(1.0),
            tests: 0,
            fallbacks: 0,
        }))
    }

    /// The lights whose shadow `hit`'s point lies in.
    pub fn shadowed(&mut self, hit: &Hit, stack: &mut Vec<u32>) -> LightSet {
        let mut set = LightSet::EMPTY;
        for k in 0..self.lights.len() {
            let (index, light) = self.lights[k];
            if !self.faces_light(hit, light) || self.blocked(hit, light, stack) {
                set.insert(index);
            }
        }
        set
    }

    /// Whether the light lies strictly on the side of the hit plane the eye sees (the
    /// side where the normalised `orient3d` is positive).
    fn faces_light(&mut self, hit: &Hit, light: Toward) -> bool {
        let [a, b, c] = hit.tri;
        let s = match light {
            Toward::At(l) => sign_of(exact::orient3d_bounded(a, b, c, l), || {
                exact::orient3d_exact(a, b, c, l)
            }),
            Toward::Direction(d) => -triple_sign(b - a, c - a, d, || {
                det_exact(
                    diff(b, a),
                    diff(c, a),
                    [[d.x], [d.y], [d.z]].map(|v| v.to_vec()),
                )
            }),
        };
        (if hit.negated { -s } else { s }) > 0
    }

    /// Whether an opaque triangle's interior lies strictly between the hit point and the
    /// light.
    fn blocked(&mut self, hit: &Hit, light: Toward, stack: &mut Vec<u32>) -> bool {
        let x = approx_point(hit);
        let end = match light {
            Toward::At(l) => l,
            Toward::Direction(d) => x + d.normalize() * self.reach,
        };
        let seg = Segment::new(x, end);
        stack.clear();
        if seg.enter(&self.bvh.nodes[0]).is_some() {
            stack.push(0);
        }
        while let Some(n) = stack.pop() {
            let node = self.bvh.nodes[n as usize];
            if node.count == 0 {
                for child in [node.first, node.first + 1] {
                    if seg.enter(&self.bvh.nodes[child as usize]).is_some() {
                        stack.push(child);
                    }
                }
                continue;
            }
            for t in node.first..node.first + node.count {
                self.tests += 1;
                if self.crosses(hit, light, self.tris[t as usize]) {
                    return true;
                }
            }
        }
        false
    }

    /// The exact test of one triangle `(p, q, r)`.
    fn crosses(&mut self, hit: &Hit, light: Toward, [p, q, r]: [DVec3; 3]) -> bool {
        // The light's side of the triangle's plane.
        let sl = match light {
            Toward::At(l) => sign_of(exact::orient3d_bounded(p, q, r, l), || {
                exact::orient3d_exact(p, q, r, l)
            }),
            Toward::Direction(d) => -triple_sign(q - p, r - p, d, || {
                det_exact(
                    diff(q, p),
                    diff(r, p),
                    [[d.x], [d.y], [d.z]].map(|v| v.to_vec()),
                )
            }),
        };
        if sl == 0 {
            return false;
        }
        let sx = self.at_hit(
            hit,
            |y| exact::orient3d_bounded(p, q, r, y),
            |y| exact::orient3d_exact(p, q, r, y),
        );
        if sx == 0 || sx == sl {
            return false;
        }
        // The line through X towards the light, against each edge (u, v).
        let mut first = 0;
        for (u, v) in [(p, q), (q, r), (r, p)] {
            let s = match light {
                Toward::At(l) => self.at_hit(
                    hit,
                    |y| exact::orient3d_bounded(y, l, u, v),
                    |y| exact::orient3d_exact(y, l, u, v),
                ),
                Toward::Direction(d) => self.at_hit(
                    hit,
                    |y| triple_bounded(y - v, d, u - v),
                    |y| {
                        det_exact(
                            diff(y, v),
                            [[d.x], [d.y], [d.z]].map(|c| c.to_vec()),
                            diff(u, v),
                        )
                    },
                ),
            };
            if s == 0 || (first != 0 && s != first) {
                return false;
            }
            first = s;
        }
        true
    }

    /// The sign at the hit point of an affine function given at points by `bounded`
    /// (value and error bound) and `exact` (an expansion): the sign of
    /// `an·g(pf) − af·g(pn)`.
    fn at_hit(
        &mut self,
        hit: &Hit,
        bounded: impl Fn(DVec3) -> (f64, f64),
        exact_at: impl Fn(DVec3) -> Vec<f64>,
    ) -> i32 {
        let (gf, egf) = bounded(hit.pf);
        let (gn, egn) = bounded(hit.pn);
        let p1 = hit.an * gf;
        let p2 = hit.af * gn;
        let v = p1 - p2;
        let bound = hit.an.abs() * egf
            + hit.ean * (gf.abs() + egf)
            + hit.af.abs() * egn
            + hit.eaf * (gn.abs() + egn)
            + 4.0 * f64::EPSILON * (p1.abs() + p2.abs());
        if v > bound {
            return 1;
        }
        if v < -bound {
            return -1;
        }
        self.fallbacks += 1;
        let [a, b, c] = hit.tri;
        let mut an = exact::orient3d_exact(a, b, c, hit.pn);
        let mut af = exact::orient3d_exact(a, b, c, hit.pf);
        if hit.negated {
            an = exact::negate(&an);
            af = exact::negate(&af);
        }
        let d = exact::sum(
            &exact::product(&an, &exact_at(hit.pf)),
            &exact::negate(&exact::product(&af, &exact_at(hit.pn))),
        );
        exact::sign(&d)
    }
}

/// The hit point in f64 (for the broad phase only).
fn approx_point(hit: &Hit) -> DVec3 {
    let w = hit.an - hit.af;
    let x = (hit.pf * hit.an - hit.pn * hit.af) / w;
    if x.is_finite() {
        x
    } else {
        hit.pn
    }
}

/// The sign of a bounded value, or of its exact expansion when the bound cannot tell.
fn sign_of((v, e): (f64, f64), exact_value: impl Fn() -> Vec<f64>) -> i32 {
    if v > e {
        1
    } else if v < -e {
        -1
    } else {
        exact::sign(&exact_value())
    }
}

/// `det[u, v, w]` (rows) in f64 with an error bound, for rows that are rounded
/// differences or exact values (the bound of `orient3d_bounded`, which covers three
/// rounded rows).
fn triple_bounded(u: DVec3, v: DVec3, w: DVec3) -> (f64, f64) {
    let det = u.x * (v.y * w.z - v.z * w.y)
        + u.y * (v.z * w.x - v.x * w.z)
        + u.z * (v.x * w.y - v.y * w.x);
    let perm = u.x.abs() * ((v.y * w.z).abs() + (v.z * w.y).abs())
        + u.y.abs() * ((v.z * w.x).abs() + (v.x * w.z).abs())
        + u.z.abs() * ((v.x * w.y).abs() + (v.y * w.x).abs());
    (det, 8.0e-16 * perm)
}

/// The sign of `det[u, v, w]` with `u`, `v` rounded differences: filtered, else exact.
fn triple_sign(u: DVec3, v: DVec3, w: DVec3, exact_value: impl Fn() -> Vec<f64>) -> i32 {
    sign_of(triple_bounded(u, v, w), exact_value)
}

/// `a − b` per coordinate, exactly (two-term expansions).
fn diff(a: DVec3, b: DVec3) -> [Vec<f64>; 3] {
    [0, 1, 2].map(|i| exact::sum(&[a[i]], &[-b[i]]))
}

/// `det[u, v, w]` of exact rows.
fn det_exact(u: [Vec<f64>; 3], v: [Vec<f64>; 3], w: [Vec<f64>; 3]) -> Vec<f64> {
    let minor = |i: usize, j: usize| {
        exact::sum(
            &exact::product(&v[i], &w[j]),
            &exact::negate(&exact::product(&v[j], &w[i])),
        )
    };
    let t0 = exact::product(&u[0], &minor(1, 2));
    let t1 = exact::product(&u[1], &minor(2, 0));
    let t2 = exact::product(&u[2], &minor(0, 1));
    exact::sum(&exact::sum(&t0, &t1), &t2)
}
