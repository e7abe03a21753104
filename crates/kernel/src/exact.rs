//! The exact kernel: planes defined by input values, implicit vertices, filtered exact
//! predicates.

use std::sync::atomic::{AtomicU64, Ordering};

use glam::DVec3;

use crate::error::KernelError;
use crate::orientation::Orientation;
use crate::plane::Plane;
use crate::polygon::ExactPolygon;
use crate::predicates::rounded_intersection;
use crate::side::{PolygonSide, Side};
use crate::traits::Kernel;
use crate::vertex_memo;

/// Largest relative error bound (against the largest coordinate) at which the cached
/// approximation of a vertex is returned as its world position; beyond it the exact
/// intersection is rounded instead.
const WORLD_REL: f64 = 1e-12;

/// Largest relative error bound of the positions [`Kernel::vertex_world_approx`] and
/// [`Kernel::split_world`] give.
const WORLD_APPROX_REL: f64 = 1e-9;

/// The exact plane-based kernel.
///
/// Every sign it returns equals the sign computed with exact rational arithmetic on the
/// f64 values it was given (face corners, the eye, plane points and normals), for every
/// finite value: there is no grid, no snap and no epsilon. Splitting never computes a
/// coordinate and never grows a number (all planes of all polygons are input planes or
/// planes given to [`Kernel::plane_through`]); coordinates are rounded only in
/// [`Kernel::vertices_world`].
///
/// Input faces ([`Kernel::face_polygons`]): no corners is [`KernelError::Empty`]; a
/// non-finite corner is [`KernelError::NonFinite`]. Faces of zero area and outlines that
/// are not simple (self-intersecting) give an empty vector. A face whose corners all lie
/// exactly on one plane and which is strictly convex becomes one polygon with all edges
/// original; any other face is triangulated (constrained Delaunay) on its own corners;
/// diagonals are not original edges.
///
/// World conversion: input corners are returned exactly; a vertex made by splitting is
/// returned within a relative error of about `1e-12` of its largest coordinate (its
/// cached approximation when that is proven so close, the rounded exact intersection
/// otherwise).
#[derive(Debug)]
pub struct ExactKernel {
    filter: bool,
    fallbacks: AtomicU64,
}

impl Default for ExactKernel {
    fn default() -> Self {
        ExactKernel::new()
    }
}

impl ExactKernel {
    /// The exact kernel (no set-up: it works on the input's own coordinates).
    pub fn new() -> ExactKernel {
        ExactKernel {
            filter: true,
            fallbacks: AtomicU64::new(0),
        }
    }

    /// The same kernel with the floating-point filter switched off: every predicate runs
    /// the exact path (for measurements and cross-checks; results are identical).
    pub fn without_filter(mut self) -> ExactKernel {
        self.filter = false;
        self
    }

    /// The side of `plane` at vertex `i` of `poly` (filter first, counted fallback).
    /// Panics if `i >= poly.len()`.
    pub fn side_of_vertex(&self, poly: &ExactPolygon, i: usize, plane: &Plane) -> Side {
        let mut fb = 0;
        let s = if self.filter {
            poly.side_filtered(i, plane, &plane.filter(), &mut fb)
        } else {
            poly.side_exact(i, plane)
        };
        self.count(fb);
        s
    }

    /// Vertex `i` of `poly` rounded to f64 (see the type's docs for the accuracy). Panics
    /// if `i >= poly.len()`.
    pub fn vertex_rounded(&self, poly: &ExactPolygon, i: usize) -> [f64; 3] {
        let (pos, err) = poly.vertex_approx(i);
        let scale = pos[0].abs().max(pos[1].abs()).max(pos[2].abs());
        if err == 0.0 || err <= WORLD_REL * scale {
            return pos;
        }
        let [s, a, b] = poly.vertex_planes(i);
        vertex_memo::rounded([&s, &a, &b], || rounded_intersection(&s, &a, &b)).unwrap_or(pos)
    }

    #[inline]
    fn count(&self, n: u64) {
        if n > 0 {
            self.fallbacks.fetch_add(n, Ordering::Relaxed);
        }
    }
}

impl Kernel for ExactKernel {
    type Plane = Plane;
    type Polygon = ExactPolygon;
    type Point = DVec3;
    type ExactPoint = [f64; 3];

    fn name(&self) -> &'static str {
        "exact"
    }

    fn face_polygons(&self, corners: &[DVec3]) -> Result<Vec<ExactPolygon>, KernelError> {
        crate::face::face_polygons(corners)
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

    fn plane_through(&self, point: DVec3, normal: DVec3) -> Result<Plane, KernelError> {
        Plane::point_normal(point.to_array(), normal.to_array())
    }

    fn plane_through_points(&self, p: DVec3, q: DVec3, r: DVec3) -> Result<Plane, KernelError> {
        Plane::through(p.to_array(), q.to_array(), r.to_array())
    }

    fn plane_along(&self, p: DVec3, q: DVec3, d: DVec3) -> Result<Plane, KernelError> {
        Plane::along(p.to_array(), q.to_array(), d.to_array())
    }

    fn support<'a>(&self, poly: &'a ExactPolygon) -> &'a Plane {
        &poly.support
    }

    fn side_of_point(&self, plane: &Plane, p: &DVec3) -> Side {
        let mut fb = 0;
        let s = if self.filter {
            plane.side_of_counted(p.to_array(), &mut fb)
        } else {
            plane.side_exact(p.to_array())
        };
        self.count(fb);
        s
    }

    fn side_of_direction(&self, plane: &Plane, d: DVec3) -> Side {
        plane.side_of_direction(d.to_array())
    }

    fn classify(&self, poly: &ExactPolygon, plane: &Plane) -> PolygonSide {
        let mut fb = 0;
        let r = poly.classify(plane, self.filter, &mut fb);
        self.count(fb);
        r
    }

    fn classify_if_cheap(&self, poly: &ExactPolygon, plane: &Plane) -> Option<PolygonSide> {
        if !self.filter {
            return Some(self.classify(poly, plane));
        }
        poly.classify_filtered(plane)
    }

    fn split(
        &self,
        poly: &ExactPolygon,
        plane: &Plane,
    ) -> (Option<ExactPolygon>, Option<ExactPolygon>) {
        let mut fb = 0;
        let r = poly.split(plane, self.filter, &mut fb);
        self.count(fb);
        r
    }

    fn split_world(
        &self,
        poly: &ExactPolygon,
        plane: &Plane,
        front: &mut Vec<DVec3>,
        back: &mut Vec<DVec3>,
    ) -> bool {
        let mut fb = 0;
        let r = poly.split_world(plane, self.filter, &mut fb, WORLD_APPROX_REL, front, back);
        self.count(fb);
        r
    }

    fn vertex_count(&self, poly: &ExactPolygon) -> usize {
        poly.len()
    }

    fn vertices_world(&self, poly: &ExactPolygon, out: &mut Vec<DVec3>) {
        out.extend((0..poly.len()).map(|i| DVec3::from_array(self.vertex_rounded(poly, i))));
    }

    fn edge_is_original(&self, poly: &ExactPolygon, i: usize) -> bool {
        poly.edge_is_original(i)
    }

    fn fallbacks(&self) -> u64 {
        self.fallbacks.load(Ordering::Relaxed)
    }

    fn vertex_exact(&self, poly: &ExactPolygon, i: usize) -> Option<[f64; 3]> {
        let (c, err) = poly.vertex_approx(i);
        (err == 0.0).then_some(c)
    }

    fn point_exact(&self, p: &DVec3) -> [f64; 3] {
        p.to_array()
    }

    fn orientation(&self, e: &[f64; 3], a: &[f64; 3], b: &[f64; 3], c: &[f64; 3]) -> Orientation {
        Orientation::from_ordering(crate::predicates::orient3d(*e, *a, *b, *c))
    }

    fn orientation_toward(
        &self,
        d: DVec3,
        a: &[f64; 3],
        b: &[f64; 3],
        c: &[f64; 3],
    ) -> Orientation {
        // The plane through c, a, b has normal (a − c) × (b − c); collinear points (no
        // plane) are coplanar with any direction.
        match Plane::through(*c, *a, *b) {
            Ok(plane) => match plane.side_of_direction(d.to_array()) {
                Side::Front => Orientation::Positive,
                Side::Back => Orientation::Negative,
                Side::On => Orientation::Coplanar,
            },
            Err(_) => Orientation::Coplanar,
        }
    }

    fn vertex_world_approx(&self, poly: &ExactPolygon, i: usize) -> Option<DVec3> {
        let (c, err) = poly.vertex_approx(i);
        let scale = c[0].abs().max(c[1].abs()).max(c[2].abs());
        (err <= WORLD_APPROX_REL * scale).then(|| DVec3::from_array(c))
    }

    fn vertex_world_bounded(&self, poly: &ExactPolygon, i: usize) -> Option<(DVec3, f64)> {
        let (c, err) = poly.vertex_approx(i);
        err.is_finite().then(|| (DVec3::from_array(c), err))
    }

    fn vertex_heights(&self, poly: &ExactPolygon, plane: &Plane, out: &mut [(f64, f64)]) -> bool {
        poly.heights(plane, out)
    }
}
