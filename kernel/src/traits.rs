//! The interface every polygon kernel offers to the orderings (exact and float alike).

use glam::DVec3;
use thiserror::Error;

/// The side of a plane a point lies on. `Front` is the side the plane's normal points to
/// (where `a·x + b·y + c·z + d > 0`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Side {
    /// Strictly on the side the normal points to.
    Front,
    /// Strictly on the other side.
    Back,
    /// Exactly on the plane.
    On,
}

impl Side {
    /// The opposite side (`On` stays `On`).
    pub fn flip(self) -> Side {
        match self {
            Side::Front => Side::Back,
            Side::Back => Side::Front,
            Side::On => Side::On,
        }
    }
}

/// Where a convex polygon lies with respect to a plane.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum PolygonSide {
    /// Every vertex is in front or on the plane, at least one strictly in front.
    Front,
    /// Every vertex is behind or on the plane, at least one strictly behind.
    Back,
    /// In the plane, facing the same way as the plane.
    Coplanar,
    /// In the plane, facing the opposite way.
    CoplanarOpposite,
    /// Vertices strictly on both sides.
    Spanning,
}

/// Errors of the kernels. Everything here is an input problem: the kernels themselves
/// never fail on valid input.
#[derive(Debug, Error, Clone, PartialEq)]
#[non_exhaustive]
pub enum KernelError {
    /// No points were given to build a quantisation grid from.
    #[error("no geometry: cannot build a quantisation grid from an empty scene")]
    Empty,
    /// A coordinate is NaN or infinite.
    #[error("non-finite coordinate ({0}, {1}, {2})")]
    NonFinite(f64, f64, f64),
    /// A point lies outside the quantisation grid's box.
    #[error("point ({0}, {1}, {2}) lies outside the quantisation grid")]
    OutsideGrid(f64, f64, f64),
    /// A point (such as the eye) is too far from the scene to be represented exactly.
    #[error("point ({0}, {1}, {2}) is too far from the scene for exact predicates")]
    TooFar(f64, f64, f64),
    /// The scene's extent is too large or too small to quantise in f64.
    #[error("scene extent {0} cannot be quantised (must be finite, and positive after snapping)")]
    BadExtent(f64),
    /// A plane normal is zero.
    #[error("zero plane normal")]
    ZeroNormal,
    /// The number of grid bits asked for is outside the supported range.
    #[error("unsupported number of grid bits {0} (supported: 2 to 26)")]
    BadBits(u32),
    /// Integer plane coefficients exceed the bounds the exact predicates are proven for.
    #[error("plane coefficients out of range")]
    PlaneOutOfRange,
}

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

    /// Short name for reports: `"exact"` or `"float"`.
    fn name(&self) -> &'static str;

    /// Converts one input face (world coordinates, at least three corners, any shape)
    /// into convex polygons. Convex planar faces give one polygon whose edges are all
    /// original; non-convex or non-planar faces are triangulated, the diagonals being
    /// non-original edges. Faces of zero area (after quantisation) give an empty vector.
    fn face_polygons(&self, corners: &[DVec3]) -> Result<Vec<Self::Polygon>, KernelError>;

    /// Converts a world point (the eye) for use in [`Kernel::side_of_point`].
    fn point(&self, p: DVec3) -> Result<Self::Point, KernelError>;

    /// The world position a converted point stands for (the exact kernel snaps points to
    /// its grid; projections should use this position so they agree with the decisions).
    fn point_world(&self, p: &Self::Point) -> DVec3;

    /// A plane through (approximately) `point` with (approximately) `normal`; its front
    /// side is the side `normal` points to. The exact kernel rounds to an integer plane;
    /// every later decision about this plane is exact.
    fn plane_through(&self, point: DVec3, normal: DVec3) -> Result<Self::Plane, KernelError>;

    /// The supporting plane of a polygon; its normal points to the polygon's front.
    fn support(&self, poly: &Self::Polygon) -> Self::Plane;

    /// The side of `plane` that `p` lies on.
    fn side_of_point(&self, plane: &Self::Plane, p: &Self::Point) -> Side;

    /// Where `poly` lies with respect to `plane`.
    fn classify(&self, poly: &Self::Polygon, plane: &Self::Plane) -> PolygonSide;

    /// Splits `poly` by `plane` into its part in front and its part behind. A polygon on
    /// one side is returned whole on that side; a coplanar polygon goes to the front when
    /// it faces the same way as the plane, to the back otherwise. No piece has zero area.
    /// New edges along `plane` are not original.
    fn split(
        &self,
        poly: &Self::Polygon,
        plane: &Self::Plane,
    ) -> (Option<Self::Polygon>, Option<Self::Polygon>);

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
}
