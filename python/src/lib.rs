//! `stormer._stormer`, the native module of the Python package `stormer` (docs/python.md):
//! the application's commands run in process (`stormer_app::cli::in_process`), methods
//! given as data, a Python callable as the right-hand side. The Python layer
//! (`stormer/__init__.py`) gives them keyword arguments, docstrings and numpy's idiom.

use pyo3::prelude::*;

mod callable;
mod ensemble;
mod errors;
mod method_data;
mod records;

/// The native module.
#[pymodule]
fn _stormer(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(records::methods_json, m)?)?;
    m.add_function(wrap_pyfunction!(records::verify_json, m)?)?;
    m.add_function(wrap_pyfunction!(records::run, m)?)?;
    m.add_function(wrap_pyfunction!(records::scene_info, m)?)?;
    m.add_function(wrap_pyfunction!(records::step_jacobian, m)?)?;
    m.add_function(wrap_pyfunction!(ensemble::ensemble, m)?)?;
    m.add_function(wrap_pyfunction!(callable::integrate, m)?)?;
    m.add_class::<method_data::Method>()?;
    Ok(())
}
