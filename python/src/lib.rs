//! limn from Python: the `limn._limn` extension module (PyO3, numpy arrays in).
//!
//! The Python package `limn` (in `python/limn/`) wraps this module: it turns array-likes
//! into contiguous numpy arrays (copying only when their type or layout requires it) and
//! documents the API; this module checks shapes, values and indices, builds a
//! [`limn_scene::Scene`] (or loads a file) and renders or checks it through the `limn`
//! library, the command's own front door: the same options, defaults, file safety and
//! statistics. Every error becomes a Python exception (`ValueError` for bad geometry,
//! cameras and options, `OSError` for files) and no output file is left behind on error.

mod errors;
mod marks;
mod mesh;
mod render;
mod scene;

use pyo3::prelude::*;

/// The native module.
#[pymodule]
fn _limn(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<scene::PyScene>()?;
    m.add_function(wrap_pyfunction!(scene::load, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
