//! Exact plane-based polygon kernel for limn.
//!
//! Two implementations of one [`Kernel`] trait:
//!
//! - [`ExactKernel`]: input positions are snapped to a uniform integer grid
//!   ([`Quantizer`], 26 bits per axis by default); a convex polygon is its supporting
//!   [`Plane`] plus one bounding plane per edge, with integer coefficients; vertices are
//!   intersections of three planes, never rounded coordinates. The side of a plane at a
//!   vertex is decided by an f64 filter with a proven error bound and, when the filter
//!   cannot decide, by exact 256-bit integer arithmetic. Splitting adds the splitting plane
//!   as a bounding plane, so numbers never grow.
//! - [`FloatKernel`]: f64 coordinates with an epsilon and interpolated split points, the
//!   measured baseline.
//!
//! ```
//! use glam::DVec3;
//! use limn_kernel::{ExactKernel, Kernel, PolygonSide};
//!
//! let k = ExactKernel::new(DVec3::splat(-1.0), DVec3::splat(1.0)).unwrap();
//! let square = [
//!     DVec3::new(-1.0, -1.0, 0.0),
//!     DVec3::new(1.0, -1.0, 0.0),
//!     DVec3::new(1.0, 1.0, 0.0),
//!     DVec3::new(-1.0, 1.0, 0.0),
//! ];
//! let polys = k.face_polygons(&square).unwrap();
//! assert_eq!(polys.len(), 1);
//! // Cut by the plane x = 0.25: two pieces, each entirely on its side.
//! let cut = k.plane_through(DVec3::new(0.25, 0.0, 0.0), DVec3::X).unwrap();
//! assert_eq!(k.classify(&polys[0], &cut), PolygonSide::Spanning);
//! let (front, back) = k.split(&polys[0], &cut);
//! assert_eq!(k.classify(&front.unwrap(), &cut), PolygonSide::Front);
//! assert_eq!(k.classify(&back.unwrap(), &cut), PolygonSide::Back);
//! ```

#[cfg(any(test, feature = "check-invariants"))]
pub mod check;
mod exact;
mod face;
mod float;
pub mod grid;
pub mod plane;
mod polygon;
pub mod predicates;
mod traits;
mod triangulate;

pub use exact::ExactKernel;
pub use float::{FloatKernel, FloatPlane, FloatPolygon, DEFAULT_RELATIVE_EPSILON};
pub use grid::{GridPoint, Quantizer};
pub use plane::Plane;
pub use polygon::ExactPolygon;
pub use predicates::ImplicitPoint;
pub use traits::{Kernel, KernelError, PolygonSide, Side};
