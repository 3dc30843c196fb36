//! The library's and the application's errors as Python exceptions: every refusal of an
//! input (an unknown method, a bad scene, a value out of its domain) is a `ValueError`
//! with the message the command line prints.

use pyo3::exceptions::PyValueError;
use pyo3::PyErr;

/// An error of the commands as a `ValueError` carrying its whole message (its causes
/// joined as the command line joins them).
pub fn value_error(e: anyhow::Error) -> PyErr {
    PyValueError::new_err(format!("{e:#}"))
}

/// A library error as a `ValueError`.
pub fn library_error(e: stormer::Error) -> PyErr {
    PyValueError::new_err(e.to_string())
}
