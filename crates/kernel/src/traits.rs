//! The interface every polygon kernel offers to the orderings (exact and float alike).

use glam::DVec3;

use crate::error::KernelError;
use crate::orientation::Orientation;
use crate::side::{PolygonSide, Side};

/// A polygon kernel: planes, convex polygons, classification and splitting.
///
/// Two implementations exist: the exact plane-based kernel (every sign exact, no epsilon)
/// and the float kernel (f64 coordinates with an epsilon, split points interpolated: the
/// measured baseline). The orderings are written once against this trait.
///
/// Conventions: a polygon's vertices are counter-clockwise seen from the front of its
/// supporting plane; edge `i` runs from vertex `i` to vertex `i + 1` (mod n); every edge
/// knows whether it lies on an edge of the input face ("original") or on a cut.
pub trait Kernel: Sync {
    /// An oriented plane.
    type Plane: Clone + Send + Sync + std::fmt::Debug;
    /// A convex polygon with at least three vertices and non-zero area.
    type Polygon: Clone + Send + Sync + std::fmt::Debug;
    /// A point, such as the eye (it may lie outside the scene's box).
    type Point: Copy + Send + Sync + std::fmt::Debug;
    /// A point known exactly (an input point or the eye), for [`Kernel::orientation`].
    type ExactPoint: Copy + PartialEq + Send + Sync + std::fmt::Debug;

    /// Short name for reports: `"exact"` or `"float"`.
    fn name(&self) -> &'static str;

    /// Converts one input face (world coordinates, at least three corners, any shape)
    /// into convex polygons. Convex planar faces give one polygon whose edges are all
    /// original; non-convex or non-planar faces are triangulated, the diagonals being
    /// non-original edges. Faces of zero area (after quantisation) give an empty vector.
    fn face_polygons(&self, corners: &[DVec3]) -> Result<Vec<Self::Polygon>, KernelError>;

    /// Converts a world point (the eye) for use in [`Kernel::side_of_point`].
    fn point(&self, p: DVec3) -> Result<Self::Point, KernelError>;

    /// The world position a converted point stands for (the f64 point itself in both
    /// kernels; projections use this position).
    fn point_world(&self, p: &Self::Point) -> DVec3;

    /// The plane through `point` with normal `normal` (both taken as the given f64
    /// values); its front side is the side `normal` points to. Every later decision of the
    /// exact kernel about this plane is exact.
    fn plane_through(&self, point: DVec3, normal: DVec3) -> Result<Self::Plane, KernelError>;

    /// The plane through three points (taken as the given f64 values), normal
    /// `(q − p) × (r − p)`; exact in the exact kernel. Errors when they are collinear.
    fn plane_through_points(
        &self,
        p: DVec3,
        q: DVec3,
        r: DVec3,
    ) -> Result<Self::Plane, KernelError>;

    /// The plane through `p` and `q` containing the direction `d`, normal `(q − p) × d`
    /// (all taken as the given f64 values); exact in the exact kernel. Errors when
    /// `q − p` is parallel to `d`.
    fn plane_along(&self, p: DVec3, q: DVec3, d: DVec3) -> Result<Self::Plane, KernelError>;

    /// The supporting plane of a polygon; its normal points to the polygon's front.
    fn support<'a>(&self, poly: &'a Self::Polygon) -> &'a Self::Plane;

    /// The side of `plane` that `p` lies on.
    fn side_of_point(&self, plane: &Self::Plane, p: &Self::Point) -> Side;

    /// The side of `plane` on which the point at infinity in direction `d` lies (the eye
    /// of a parallel projection, `d` pointing from the scene towards it): the sign of the
    /// plane's normal dotted with `d`, [`Side::On`] when the plane is parallel to `d`.
    fn side_of_direction(&self, plane: &Self::Plane, d: DVec3) -> Side;

    /// Where `poly` lies with respect to `plane`.
    fn classify(&self, poly: &Self::Polygon, plane: &Self::Plane) -> PolygonSide;

    /// [`Kernel::classify`] when it comes cheap (the exact kernel: without exact
    /// evaluation); `None` when only a costly evaluation can tell, so that a caller with a
    /// cheaper way to the answer it needs can try that first.
    fn classify_if_cheap(&self, poly: &Self::Polygon, plane: &Self::Plane) -> Option<PolygonSide> {
        Some(self.classify(poly, plane))
    }

    /// Splits `poly` by `plane` into its part in front and its part behind. A polygon on
    /// one side is returned whole on that side; a coplanar polygon goes to the front when
    /// it faces the same way as the plane, to the back otherwise. No piece has zero area.
    /// New edges along `plane` are not original.
    fn split(
        &self,
        poly: &Self::Polygon,
        plane: &Self::Plane,
    ) -> (Option<Self::Polygon>, Option<Self::Polygon>);

    /// The corners of the two parts [`Kernel::split`] makes of `poly` by `plane`, as world
    /// positions each within a relative 1e-9 of the true corner (as
    /// [`Kernel::vertex_world_approx`]), appended to `front` and `back` (a part that is
    /// empty adds nothing); for float prefilters only, never for decisions. `false`, with
    /// both left as they were, when the kernel has no such positions at hand (the
    /// caller then splits). The exact kernel finds the parts' corners without making the
    /// parts.
    fn split_world(
        &self,
        poly: &Self::Polygon,
        plane: &Self::Plane,
        front: &mut Vec<DVec3>,
        back: &mut Vec<DVec3>,
    ) -> bool {
        let _ = (poly, plane, front, back);
        false
    }

    /// Number of vertices of `poly`.
    fn vertex_count(&self, poly: &Self::Polygon) -> usize;

    /// Appends the vertices of `poly`, in order, in world coordinates, to `out`.
    fn vertices_world(&self, poly: &Self::Polygon, out: &mut Vec<DVec3>);

    /// Whether edge `i` of `poly` (from vertex `i` to `i + 1`) lies on an edge of the
    /// input face.
    fn edge_is_original(&self, poly: &Self::Polygon, i: usize) -> bool;

    /// How often an exact predicate had to fall back from its floating-point filter since
    /// this kernel was created (always 0 for the float kernel).
    fn fallbacks(&self) -> u64;

    /// Vertex `i` of `poly` when it is known exactly (an input point, or an intersection
    /// whose coordinates happen to be representable, for the exact kernel; every vertex
    /// for the float kernel).
    fn vertex_exact(&self, poly: &Self::Polygon, i: usize) -> Option<Self::ExactPoint>;

    /// A point, exactly.
    fn point_exact(&self, p: &Self::Point) -> Self::ExactPoint;

    /// The orientation of `e, a, b, c` (see [`Orientation`]); exact in the exact kernel.
    fn orientation(
        &self,
        e: &Self::ExactPoint,
        a: &Self::ExactPoint,
        b: &Self::ExactPoint,
        c: &Self::ExactPoint,
    ) -> Orientation;

    /// [`Kernel::orientation`] with `e` the point at infinity in direction `d`: the sign
    /// of `d · ((a − c) × (b − c))`, which `orientation(e, a, b, c)` takes for `e = c + t·d`
    /// and every large enough `t`. Exact in the exact kernel.
    fn orientation_toward(
        &self,
        d: DVec3,
        a: &Self::ExactPoint,
        b: &Self::ExactPoint,
        c: &Self::ExactPoint,
    ) -> Orientation;

    /// A cheap world position of vertex `i`, within a relative 1e-9 of the true one,
    /// when the kernel has it at hand (for float prefilters only; never for decisions).
    fn vertex_world_approx(&self, poly: &Self::Polygon, i: usize) -> Option<DVec3>;

    /// A world position of vertex `i` and a proven bound on the error of each of its
    /// coordinates (0 when it is the vertex exactly), when the kernel has them at hand:
    /// the true vertex lies in the box of that half-width around the position. For float
    /// computations that must hold for the true vertex (interval filters).
    fn vertex_world_bounded(&self, poly: &Self::Polygon, i: usize) -> Option<(DVec3, f64)>;

    /// For every vertex of `poly`, in `out` (which must hold them all), the value `v` of
    /// `plane`'s equation there and a bound `e` with the exact value within `e` of `v`:
    /// one equation for all vertices (values on one scale, positive in front), so `v > e`
    /// proves a vertex in front and ratios of values are ratios of distances. `false`
    /// when `out` is too short or some bound is not finite. For float filters that must
    /// hold exactly (in the float kernel, the bound is its epsilon).
    fn vertex_heights(
        &self,
        poly: &Self::Polygon,
        plane: &Self::Plane,
        out: &mut [(f64, f64)],
    ) -> bool;
}
