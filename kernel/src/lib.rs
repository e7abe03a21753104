//! Exact plane-based polygon kernel for limn.
//!
//! (Crate documentation is completed with the implementation.)

mod traits;

pub use traits::{Kernel, KernelError, PolygonSide, Side};
