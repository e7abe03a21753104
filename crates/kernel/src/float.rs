//! The float kernel: f64 coordinates, an epsilon, split points by linear interpolation —
//! the way gl2ps and csg.js work. It is kept only as the measured baseline.

use glam::DVec3;

use crate::convex_pieces::convex_pieces;
use crate::error::KernelError;
use crate::face_split::split_face;
use crate::orientation::Orientation;
use crate::side::{PolygonSide, Side};
use crate::traits::Kernel;

/// Default epsilon relative to the scene extent.
pub const DEFAULT_RELATIVE_EPSILON: f64 = 1e-9;

/// A plane `normal · p = w` with a unit normal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FloatPlane {
    /// Unit normal, pointing to the front.
    pub normal: DVec3,
    /// Offset: the plane is `normal · p = w`.
    pub w: f64,
}

impl FloatPlane {
    /// Signed distance of `p` from the plane.
    #[inline]
    pub fn distance(&self, p: DVec3) -> f64 {
        self.normal.dot(p) - self.w
    }
}

/// A corner of a float polygon: the vertex and whether the edge leaving it is original.
#[derive(Debug, Clone, Copy, PartialEq)]
struct FloatCorner {
    p: DVec3,
    original: bool,
}

/// A convex polygon of the float kernel: vertices in world coordinates.
#[derive(Debug, Clone)]
pub struct FloatPolygon {
    plane: FloatPlane,
    corners: Vec<FloatCorner>,
}

impl FloatPolygon {
    /// The vertices in order.
    pub fn vertices(&self) -> impl Iterator<Item = DVec3> + '_ {
        self.corners.iter().map(|c| c.p)
    }
}

/// The float/epsilon kernel.
///
/// A point is on a plane when its distance is at most `epsilon`; by default
/// `epsilon = 1e-9 × extent` ([`DEFAULT_RELATIVE_EPSILON`]), where the extent is the
/// largest side of the scene's box (or 1 for a box of zero extent).
#[derive(Debug, Clone)]
pub struct FloatKernel {
    eps: f64,
}

impl FloatKernel {
    /// A float kernel for the box `[lo, hi]` with the default relative epsilon.
    pub fn new(lo: DVec3, hi: DVec3) -> Result<FloatKernel, KernelError> {
        for p in [lo, hi] {
            if !p.is_finite() {
                return Err(KernelError::NonFinite(p.x, p.y, p.z));
            }
        }
        let ext = (hi - lo).max_element();
        if !ext.is_finite() || ext < 0.0 {
            return Err(KernelError::BadExtent(ext));
        }
        let ext = if ext > 0.0 { ext } else { 1.0 };
        Ok(FloatKernel {
            eps: ext * DEFAULT_RELATIVE_EPSILON,
        })
    }

    /// A float kernel with an absolute epsilon (scene units). Must be finite and `>= 0`.
    pub fn with_epsilon(eps: f64) -> Result<FloatKernel, KernelError> {
        if !eps.is_finite() || eps < 0.0 {
            return Err(KernelError::BadExtent(eps));
        }
        Ok(FloatKernel { eps })
    }

    /// The epsilon in scene units.
    pub fn epsilon(&self) -> f64 {
        self.eps
    }

    #[inline]
    fn side(&self, plane: &FloatPlane, p: DVec3) -> Side {
        let t = plane.distance(p);
        if t > self.eps {
            Side::Front
        } else if t < -self.eps {
            Side::Back
        } else {
            Side::On
        }
    }

    fn polygon(&self, pts: &[DVec3], original: &[bool], normal: DVec3) -> Option<FloatPolygon> {
        let normal = normal.try_normalize()?;
        let corners = pts
            .iter()
            .zip(original)
            .map(|(&p, &original)| FloatCorner { p, original })
            .collect();
        Some(FloatPolygon {
            plane: FloatPlane {
                normal,
                w: normal.dot(pts[0]),
            },
            corners,
        })
    }

    /// Convex, planar and winding once (every corner on the inner side of the line
    /// through the first two), all within epsilon.
    fn is_convex(&self, pts: &[DVec3], normal: DVec3) -> bool {
        let n = pts.len();
        let unit = normal.normalize();
        let w = unit.dot(pts[0]);
        let tol = self.eps * self.eps;
        let turns = (0..n).all(|i| {
            let (a, b, c) = (pts[(i + n - 1) % n], pts[i], pts[(i + 1) % n]);
            (b - a).cross(c - b).dot(unit) > tol && (unit.dot(b) - w).abs() <= self.eps
        });
        let once = (2..n).all(|i| (pts[1] - pts[0]).cross(pts[i] - pts[0]).dot(unit) > tol);
        turns && once
    }
}

/// The orientation of `a, b, c` projected along axis `k`, in f64 (the baseline's
/// counterpart of the exact kernel's test).
fn orient_float(a: [f64; 3], b: [f64; 3], c: [f64; 3], k: usize) -> std::cmp::Ordering {
    let (u, v) = ((k + 1) % 3, (k + 2) % 3);
    let o = (b[u] - a[u]) * (c[v] - a[v]) - (b[v] - a[v]) * (c[u] - a[u]);
    o.partial_cmp(&0.0).unwrap_or(std::cmp::Ordering::Equal)
}

fn newell(pts: &[DVec3]) -> DVec3 {
    let p0 = pts[0];
    (1..pts.len() - 1)
        .map(|i| (pts[i] - p0).cross(pts[i + 1] - p0))
        .sum()
}

impl Kernel for FloatKernel {
    type Plane = FloatPlane;
    type Polygon = FloatPolygon;
    type Point = DVec3;
    type ExactPoint = [f64; 3];

    fn name(&self) -> &'static str {
        "float"
    }

    fn face_polygons(&self, corners: &[DVec3]) -> Result<Vec<FloatPolygon>, KernelError> {
        if corners.is_empty() {
            return Err(KernelError::Empty);
        }
        let mut pts: Vec<DVec3> = Vec::with_capacity(corners.len());
        for &c in corners {
            if !c.is_finite() {
                return Err(KernelError::NonFinite(c.x, c.y, c.z));
            }
            if pts.last().is_none_or(|l| l.distance(c) > self.eps) {
                pts.push(c);
            }
        }
        while pts.len() > 1 && pts[0].distance(pts[pts.len() - 1]) <= self.eps {
            pts.pop();
        }
        if pts.len() < 3 {
            return Ok(Vec::new());
        }
        let normal = newell(&pts);
        if !normal.is_finite() {
            return Ok(Vec::new());
        }
        // A face whose lobes cancel (a balanced bow tie) has no Newell normal but has
        // area: only the convex path needs the normal.
        if normal.length() > self.eps * self.eps && self.is_convex(&pts, normal) {
            let original = vec![true; pts.len()];
            return Ok(self.polygon(&pts, &original, normal).into_iter().collect());
        }
        let g: Vec<[f64; 3]> = pts.iter().map(|p| p.to_array()).collect();
        let mut out = Vec::new();
        if let Some(unit) = normal.try_normalize() {
            let w = unit.dot(pts[0]);
            if pts.iter().all(|&p| (unit.dot(p) - w).abs() <= self.eps) {
                // Planar within epsilon: its triangles merged into convex pieces, as the
                // exact kernel merges an exactly planar face's.
                let k = normal.abs().max_position();
                let tris = split_face(&g, normal.to_array(), orient_float);
                let turn = |a: usize, b: usize, c: usize| orient_float(g[a], g[b], g[c], k);
                for piece in convex_pieces(&tris, turn) {
                    let corners: Vec<DVec3> = piece.idx.iter().map(|&i| pts[i]).collect();
                    out.extend(self.polygon(&corners, &piece.original, normal));
                }
                return Ok(out);
            }
        }
        for t in split_face(&g, normal.to_array(), orient_float) {
            let tp = t.idx.map(|i| pts[i]);
            let n = (tp[1] - tp[0]).cross(tp[2] - tp[0]);
            if n.length() > self.eps * self.eps {
                out.extend(self.polygon(&tp, &t.original, n));
            }
        }
        Ok(out)
    }

    fn point(&self, p: DVec3) -> Result<DVec3, KernelError> {
        if !p.is_finite() {
            return Err(KernelError::NonFinite(p.x, p.y, p.z));
        }
        Ok(p)
    }

    fn point_world(&self, p: &DVec3) -> DVec3 {
        *p
    }

    fn plane_through_points(
        &self,
        p: DVec3,
        q: DVec3,
        r: DVec3,
    ) -> Result<FloatPlane, KernelError> {
        self.plane_through(p, (q - p).cross(r - p))
    }

    fn plane_along(&self, p: DVec3, q: DVec3, d: DVec3) -> Result<FloatPlane, KernelError> {
        self.plane_through(p, (q - p).cross(d))
    }

    fn plane_through(&self, point: DVec3, normal: DVec3) -> Result<FloatPlane, KernelError> {
        for p in [point, normal] {
            if !p.is_finite() {
                return Err(KernelError::NonFinite(p.x, p.y, p.z));
            }
        }
        let m = normal.abs().max_element();
        if m == 0.0 {
            return Err(KernelError::ZeroNormal);
        }
        let normal = (normal / m).normalize();
        Ok(FloatPlane {
            normal,
            w: normal.dot(point),
        })
    }

    fn support<'a>(&self, poly: &'a FloatPolygon) -> &'a FloatPlane {
        &poly.plane
    }

    fn side_of_point(&self, plane: &FloatPlane, p: &DVec3) -> Side {
        self.side(plane, *p)
    }

    fn side_of_direction(&self, plane: &FloatPlane, d: DVec3) -> Side {
        // The plane's normal is a unit vector: compare the cosine with the epsilon.
        let t = plane.normal.dot(d.normalize_or_zero());
        if t > self.eps {
            Side::Front
        } else if t < -self.eps {
            Side::Back
        } else {
            Side::On
        }
    }

    fn classify(&self, poly: &FloatPolygon, plane: &FloatPlane) -> PolygonSide {
        let (mut front, mut back) = (false, false);
        for c in &poly.corners {
            match self.side(plane, c.p) {
                Side::Front => front = true,
                Side::Back => back = true,
                Side::On => {}
            }
        }
        match (front, back) {
            (true, true) => PolygonSide::Spanning,
            (true, false) => PolygonSide::Front,
            (false, true) => PolygonSide::Back,
            (false, false) if poly.plane.normal.dot(plane.normal) > 0.0 => PolygonSide::Coplanar,
            (false, false) => PolygonSide::CoplanarOpposite,
        }
    }

    fn split(
        &self,
        poly: &FloatPolygon,
        plane: &FloatPlane,
    ) -> (Option<FloatPolygon>, Option<FloatPolygon>) {
        match self.classify(poly, plane) {
            PolygonSide::Front | PolygonSide::Coplanar => return (Some(poly.clone()), None),
            PolygonSide::Back | PolygonSide::CoplanarOpposite => return (None, Some(poly.clone())),
            PolygonSide::Spanning => {}
        }
        let cs = &poly.corners;
        let n = cs.len();
        let sides: Vec<Side> = cs.iter().map(|c| self.side(plane, c.p)).collect();
        let mut f = Vec::with_capacity(n + 1);
        let mut b = Vec::with_capacity(n + 1);
        for i in 0..n {
            let j = (i + 1) % n;
            let (si, sj) = (sides[i], sides[j]);
            let c = cs[i];
            if si != Side::Back {
                let cut = si == Side::On && sj == Side::Back;
                f.push(FloatCorner {
                    p: c.p,
                    original: c.original && !cut,
                });
            }
            if si != Side::Front {
                let cut = si == Side::On && sj == Side::Front;
                b.push(FloatCorner {
                    p: c.p,
                    original: c.original && !cut,
                });
            }
            if matches!(
                (si, sj),
                (Side::Front, Side::Back) | (Side::Back, Side::Front)
            ) {
                let (pi, pj) = (c.p, cs[j].p);
                let t = (plane.w - plane.normal.dot(pi)) / plane.normal.dot(pj - pi);
                let x = pi.lerp(pj, t);
                let on_edge = FloatCorner {
                    p: x,
                    original: c.original,
                };
                let cut = FloatCorner {
                    p: x,
                    original: false,
                };
                if si == Side::Front {
                    f.push(cut);
                    b.push(on_edge);
                } else {
                    f.push(on_edge);
                    b.push(cut);
                }
            }
        }
        let mk = |corners: Vec<FloatCorner>| {
            (corners.len() >= 3).then_some(FloatPolygon {
                plane: poly.plane,
                corners,
            })
        };
        (mk(f), mk(b))
    }

    fn vertex_count(&self, poly: &FloatPolygon) -> usize {
        poly.corners.len()
    }

    fn vertices_world(&self, poly: &FloatPolygon, out: &mut Vec<DVec3>) {
        out.extend(poly.corners.iter().map(|c| c.p));
    }

    fn edge_is_original(&self, poly: &FloatPolygon, i: usize) -> bool {
        poly.corners.get(i).is_some_and(|c| c.original)
    }

    fn fallbacks(&self) -> u64 {
        0
    }

    fn vertex_exact(&self, poly: &FloatPolygon, i: usize) -> Option<[f64; 3]> {
        poly.vertices().nth(i).map(|v| v.to_array())
    }

    fn point_exact(&self, p: &DVec3) -> [f64; 3] {
        p.to_array()
    }

    /// Shewchuk's adaptive `orient3d` on the float kernel's (interpolated) vertices.
    fn orientation(&self, e: &[f64; 3], a: &[f64; 3], b: &[f64; 3], c: &[f64; 3]) -> Orientation {
        let pt = |p: &[f64; 3]| robust::Coord3D {
            x: p[0],
            y: p[1],
            z: p[2],
        };
        let o = robust::orient3d(pt(e), pt(a), pt(b), pt(c));
        Orientation::from_ordering(o.partial_cmp(&0.0).unwrap_or(std::cmp::Ordering::Equal))
    }

    /// The sign of `d · ((a − c) × (b − c))` in f64, with the epsilon on the unit vectors.
    fn orientation_toward(
        &self,
        d: DVec3,
        a: &[f64; 3],
        b: &[f64; 3],
        c: &[f64; 3],
    ) -> Orientation {
        let c = DVec3::from_array(*c);
        let n = (DVec3::from_array(*a) - c).cross(DVec3::from_array(*b) - c);
        let t = n.normalize_or_zero().dot(d.normalize_or_zero());
        Orientation::from_ordering(if t > self.eps {
            std::cmp::Ordering::Greater
        } else if t < -self.eps {
            std::cmp::Ordering::Less
        } else {
            std::cmp::Ordering::Equal
        })
    }

    fn vertex_world_approx(&self, poly: &FloatPolygon, i: usize) -> Option<DVec3> {
        poly.vertices().nth(i)
    }

    /// Signed distances, with the kernel's epsilon as their bound (its own sides).
    fn vertex_heights(
        &self,
        poly: &FloatPolygon,
        plane: &FloatPlane,
        out: &mut [(f64, f64)],
    ) -> bool {
        if out.len() < poly.corners.len() {
            return false;
        }
        for (o, c) in out.iter_mut().zip(&poly.corners) {
            *o = (plane.distance(c.p), self.eps);
        }
        true
    }

    /// The float kernel's vertices are its polygons: each is exactly itself.
    fn vertex_world_bounded(&self, poly: &FloatPolygon, i: usize) -> Option<(DVec3, f64)> {
        poly.vertices().nth(i).map(|v| (v, 0.0))
    }
}
