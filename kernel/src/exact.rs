//! The exact kernel: integer grid, integer planes, implicit vertices, filtered predicates.

use std::sync::atomic::{AtomicU64, Ordering};

use glam::DVec3;

use crate::grid::{GridPoint, Quantizer, DEFAULT_BITS, FAR_LIMIT};
use crate::plane::Plane;
use crate::polygon::ExactPolygon;
use crate::predicates::{as_grid, rounded_intersection};
use crate::traits::{Kernel, KernelError, PolygonSide, Side};

/// Largest component of a normal given to [`Kernel::plane_through`] after rounding to
/// integers.
const PLANE_NORMAL_SCALE: f64 = 16_777_216.0; // 2^24

/// Largest grid coordinate of the point given to [`Kernel::plane_through`]: with normal
/// components up to `2^24` the offset stays below `3 · 2^80 < 2^83`.
const PLANE_POINT_LIMIT: i64 = 1 << 56;

/// The exact plane-based kernel.
///
/// Every sign it returns is exact; splitting never computes a coordinate and never grows
/// a number (all planes of all polygons are input planes or planes given to
/// [`Kernel::plane_through`]); coordinates are rounded only in
/// [`Kernel::vertices_world`] and [`Kernel::point_world`].
///
/// Input faces ([`Kernel::face_polygons`]): no corners is [`KernelError::Empty`]; a
/// non-finite corner is [`KernelError::NonFinite`]; a corner outside the box is
/// [`KernelError::OutsideGrid`]. Faces that collapse (fewer than three distinct snapped
/// corners, zero area) and outlines that are not simple (self-intersecting) give an
/// empty vector. A face whose snapped corners all lie exactly on one plane and which is
/// strictly convex becomes one polygon with all edges original. Any other face —
/// non-convex, or made non-planar by snapping — is triangulated (constrained Delaunay)
/// on its snapped corners, so faces that share corners in the input share them exactly;
/// diagonals are not original edges.
///
/// World conversion: a vertex's world coordinates are within `4` ulps (relative error
/// `8·2^-53`) of its exact grid position times the step, plus one rounding of adding the
/// grid origin.
#[derive(Debug)]
pub struct ExactKernel {
    quantizer: Quantizer,
    filter: bool,
    fallbacks: AtomicU64,
}

impl ExactKernel {
    /// A kernel for a scene inside the box `[lo, hi]` with the default
    /// [`DEFAULT_BITS`] bits per axis.
    pub fn new(lo: DVec3, hi: DVec3) -> Result<ExactKernel, KernelError> {
        ExactKernel::with_bits(lo, hi, DEFAULT_BITS)
    }

    /// A kernel with `bits` bits per axis (2 to 26).
    pub fn with_bits(lo: DVec3, hi: DVec3, bits: u32) -> Result<ExactKernel, KernelError> {
        Ok(ExactKernel {
            quantizer: Quantizer::new(lo, hi, bits)?,
            filter: true,
            fallbacks: AtomicU64::new(0),
        })
    }

    /// The same kernel with the floating-point filter switched off: every predicate runs
    /// the exact path (for measurements and cross-checks; results are identical).
    pub fn without_filter(mut self) -> ExactKernel {
        self.filter = false;
        self
    }

    /// The quantisation grid.
    pub fn quantizer(&self) -> &Quantizer {
        &self.quantizer
    }

    /// The grid step in scene units.
    pub fn step(&self) -> f64 {
        self.quantizer.step()
    }

    /// The largest snap distance in scene units (half a cell diagonal).
    pub fn max_snap_error(&self) -> f64 {
        self.quantizer.max_snap_error()
    }

    /// The side of `plane` at vertex `i` of `poly` (filter first, counted fallback).
    /// Panics if `i >= poly.len()`.
    pub fn side_of_vertex(&self, poly: &ExactPolygon, i: usize, plane: &Plane) -> Side {
        let mut fb = 0;
        let s = if self.filter {
            poly.side_filtered(i, plane, &crate::predicates::PlaneF::new(plane), &mut fb)
        } else {
            poly.side_exact(i, plane)
        };
        self.count(fb);
        s
    }

    /// Vertex `i` of `poly` in grid coordinates, rounded (relative error at most `8·2^-53`).
    /// Panics if `i >= poly.len()`.
    pub fn vertex_grid(&self, poly: &ExactPolygon, i: usize) -> [f64; 3] {
        let (pos, err) = poly.vertex_approx(i);
        if as_grid(&pos, err).is_some() {
            return pos;
        }
        let [s, a, b] = poly.vertex_planes(i);
        rounded_intersection(&s, &a, &b).unwrap_or(pos)
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
    type Point = GridPoint;

    fn name(&self) -> &'static str {
        "exact"
    }

    fn face_polygons(&self, corners: &[DVec3]) -> Result<Vec<ExactPolygon>, KernelError> {
        crate::face::face_polygons(&self.quantizer, corners)
    }

    fn point(&self, p: DVec3) -> Result<GridPoint, KernelError> {
        self.quantizer.snap_far(p, FAR_LIMIT)
    }

    fn point_world(&self, p: &GridPoint) -> DVec3 {
        self.quantizer.world(*p)
    }

    fn plane_through(&self, point: DVec3, normal: DVec3) -> Result<Plane, KernelError> {
        if !normal.is_finite() {
            return Err(KernelError::NonFinite(normal.x, normal.y, normal.z));
        }
        let m = normal.abs().max_element();
        if m == 0.0 {
            return Err(KernelError::ZeroNormal);
        }
        // Scale in two steps so that tiny or huge normals neither underflow nor overflow.
        let unit = normal / m;
        let n = (unit * PLANE_NORMAL_SCALE).round();
        let n = [n.x as i64, n.y as i64, n.z as i64];
        let g = self.quantizer.snap_far(point, PLANE_POINT_LIMIT)?;
        let d =
            -(n[0] as i128 * g.x as i128 + n[1] as i128 * g.y as i128 + n[2] as i128 * g.z as i128);
        Plane::new(n[0], n[1], n[2], d).ok_or(KernelError::PlaneOutOfRange)
    }

    fn support(&self, poly: &ExactPolygon) -> Plane {
        poly.support()
    }

    fn side_of_point(&self, plane: &Plane, p: &GridPoint) -> Side {
        plane.side_of(p)
    }

    fn classify(&self, poly: &ExactPolygon, plane: &Plane) -> PolygonSide {
        let mut fb = 0;
        let r = poly.classify(plane, self.filter, &mut fb);
        self.count(fb);
        r
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

    fn vertex_count(&self, poly: &ExactPolygon) -> usize {
        poly.len()
    }

    fn vertices_world(&self, poly: &ExactPolygon, out: &mut Vec<DVec3>) {
        out.extend((0..poly.len()).map(|i| self.quantizer.world_f(self.vertex_grid(poly, i))));
    }

    fn edge_is_original(&self, poly: &ExactPolygon, i: usize) -> bool {
        poly.edge_is_original(i)
    }

    fn fallbacks(&self) -> u64 {
        self.fallbacks.load(Ordering::Relaxed)
    }
}
