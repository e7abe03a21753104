//! Exact plane-based polygon kernel for limn.
//!
//! Two implementations of one [`Kernel`] trait:
//!
//! - [`ExactKernel`]: exact on the input as given. A convex polygon is its supporting
//!   [`Plane`] plus one bounding plane per edge; every plane is *defined* by input values
//!   (three corners of an input face, an edge and a coordinate axis, or a point and a
//!   normal), never by rounded coefficients. A vertex is an input point or the
//!   intersection of three such planes, kept symbolically. The side of a plane at a
//!   vertex is decided by an f64 filter with a proven error bound, a combinatorial
//!   shortcut (a point that defines the plane lies on it), Shewchuk's adaptive
//!   predicates for input points, and exact dyadic (big-integer) arithmetic otherwise,
//!   so every sign equals the sign computed with exact rationals on the f64 input, for
//!   every finite coordinate. Splitting adds the splitting plane as a bounding plane:
//!   numbers never grow and no coordinate is computed for a decision.
//! - [`FloatKernel`]: f64 coordinates with an epsilon and interpolated split points, the
//!   measured baseline.
//!
//! The certified arithmetic the rest of limn builds on lives here too, behind three
//! number types: [`Interval`] (float intervals rounded outward, for filters whose answers
//! must hold for the exact values), [`Dyadic`] (exact `m · 2^e` numbers, every f64 being
//! one) and [`Quotient`] (exact quotients of two of them, rounded once for output), with
//! [`ExactAffine`] for a plane's equation taken exactly and [`Plane::value_at`] for its
//! certified float value.
//!
//! ```
//! use glam::DVec3;
//! use limn_kernel::{ExactKernel, Kernel, PolygonSide};
//!
//! let k = ExactKernel::new();
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

mod affine;
#[cfg(any(test, feature = "check-invariants"))]
mod check;
mod convex_pieces;
mod dyadic;
mod error;
mod exact;
mod face;
mod face_split;
mod filter;
mod float;
mod interval;
mod orientation;
mod plane;
mod polygon;
mod predicates;
mod quotient;
mod side;
mod traits;
mod triangulate;
mod vertex_memo;

pub use affine::ExactAffine;
#[cfg(any(test, feature = "check-invariants"))]
pub use check::{check_polygon, check_split};
pub use dyadic::Dyadic;
pub use error::KernelError;
pub use exact::ExactKernel;
pub use face::{face_triangles, FaceTriangle};
pub use float::{FloatKernel, FloatPlane, FloatPolygon, DEFAULT_RELATIVE_EPSILON};
pub use interval::Interval;
pub use orientation::Orientation;
pub use plane::{Plane, PlaneDef};
pub use polygon::ExactPolygon;
pub use predicates::orient3d;
#[doc(hidden)]
pub use predicates::{exact_side_of_intersection, ExactPath};
pub use quotient::Quotient;
pub use side::{PolygonSide, Side};
pub use traits::Kernel;
