//! Errors as Python exceptions: `OSError` for files (outputs refused or not written,
//! inputs not read), `ValueError` for what the caller passed; the message is the one
//! the command prints. Warnings as `limn.LimnWarning`.

use pyo3::exceptions::{PyOSError, PyUserWarning, PyValueError};
use pyo3::prelude::*;
use pyo3::PyErr;

/// A `ValueError` with the message of `e`.
pub(crate) fn value_error(e: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(e.to_string())
}

/// The exception of a library error.
pub(crate) fn raise(e: limn::Error) -> PyErr {
    if e.is_file_error() {
        PyOSError::new_err(e.message())
    } else {
        PyValueError::new_err(e.message())
    }
}

/// Issues each warning as a Python `UserWarning` (the package's `LimnWarning` filters
/// them by message prefix `limn: `).
pub(crate) fn warn(py: Python<'_>, warnings: &[String]) -> PyResult<()> {
    let category = py.get_type::<PyUserWarning>();
    for w in warnings {
        let text = std::ffi::CString::new(format!("limn: {w}"))
            .map_err(|_| value_error("a warning contains a NUL character"))?;
        PyErr::warn(py, &category, &text, 1)?;
    }
    Ok(())
}
