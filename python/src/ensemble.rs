//! `stormer ensemble` from Python: every member on the cores (rayon), with the
//! interpreter's lock released, one array back.

use crate::errors::value_error;
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use stormer_app::cli::in_process::{self, EnsembleRequest};

/// Runs an ensemble; returns `columns`, `values` (members x columns), `stopped`,
/// `failures`, `threads` and `seconds` in a dict.
#[pyfunction]
#[pyo3(signature = (scene, vary, method=None, dt=None, t_end=None, jobs=None))]
pub fn ensemble<'py>(
    py: Python<'py>,
    scene: String,
    vary: Vec<(String, f64, f64, usize)>,
    method: Option<String>,
    dt: Option<f64>,
    t_end: Option<f64>,
    jobs: Option<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let request = EnsembleRequest {
        scene,
        vary,
        method,
        dt,
        t_end,
        jobs,
    };
    let table = py.detach(|| in_process::ensemble(&request)).map_err(value_error)?;
    let (n, k) = (table.stopped.len(), table.columns.len());
    let d = PyDict::new(py);
    d.set_item("values", PyArray1::from_vec(py, table.values).reshape([n, k])?)?;
    d.set_item("columns", table.columns)?;
    d.set_item("stopped", table.stopped)?;
    d.set_item("failures", table.failures)?;
    d.set_item("threads", table.threads)?;
    d.set_item("seconds", table.seconds)?;
    Ok(d)
}
