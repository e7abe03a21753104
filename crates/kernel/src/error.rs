//! The kernels' errors: all of them input problems.

use thiserror::Error;

/// Errors of the kernels. Everything here is an input problem: the kernels themselves
/// never fail on valid input. The exact kernel accepts every finite f64 coordinate.
#[derive(Debug, Error, Clone, PartialEq)]
#[non_exhaustive]
pub enum KernelError {
    /// A face was given no corners.
    #[error("a face with no corners")]
    Empty,
    /// A coordinate is NaN or infinite.
    #[error("non-finite coordinate ({0}, {1}, {2})")]
    NonFinite(f64, f64, f64),
    /// The scene's extent is not finite, so the float kernel cannot scale its epsilon.
    #[error("scene extent {0} is not finite")]
    BadExtent(f64),
    /// A plane normal is zero.
    #[error("zero plane normal")]
    ZeroNormal,
}
