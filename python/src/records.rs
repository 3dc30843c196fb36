//! The catalog, `verify` and runs of scenes, as the command line gives them, returned to
//! Python: JSON text for the catalog and the reports (the Python layer parses it), numpy
//! arrays for a run's records.

use crate::errors::value_error;
use crate::method_data::Method;
use numpy::{IntoPyArray, PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::collections::BTreeMap;
use stormer_app::cli::in_process::{self, Records, RunRequest, SceneInput};

/// `stormer methods --json`.
#[pyfunction]
pub fn methods_json() -> PyResult<String> {
    in_process::methods_json().map_err(value_error)
}

/// `stormer verify NAME --format json`: the report and the contradictions found.
#[pyfunction]
pub fn verify_json(name: &str) -> PyResult<(String, Vec<String>)> {
    let v = in_process::verify_json(name).map_err(value_error)?;
    Ok((v.json, v.contradictions))
}

/// The scene: a name or path, or a scene file's text made in Python.
fn scene_input(scene: Option<String>, scene_text: Option<String>, name: &str) -> SceneInput {
    match (scene, scene_text) {
        (_, Some(text)) => SceneInput::Text {
            text,
            name: name.to_string(),
        },
        (Some(scene), None) => SceneInput::Named(scene),
        (None, None) => SceneInput::Named(String::new()),
    }
}

/// A method argument: a name (or path), or a `Method`.
pub fn method_arg(method: Option<&Bound<'_, PyAny>>) -> PyResult<(Option<String>, Option<stormer::Method>)> {
    let Some(method) = method else {
        return Ok((None, None));
    };
    if let Ok(m) = method.cast::<Method>() {
        return Ok((None, Some(m.get().method.clone())));
    }
    match method.extract::<String>() {
        Ok(name) => Ok((Some(name), None)),
        Err(_) => Err(pyo3::exceptions::PyTypeError::new_err(format!(
            "method must be a name (str) or a stormer.Method, got {}",
            method.get_type().name()?
        ))),
    }
}

/// Runs a scene as `stormer run` does, its records kept in memory (the interpreter's lock
/// released while it runs).
#[pyfunction]
#[pyo3(signature = (scene=None, scene_text=None, name="scene", method=None, dt=None, t_end=None, every=None,
    save_at=None, split=None, corrector=None, rtol=None, atol=None, compensated=false, max_steps=None, numbers=None))]
pub fn run<'py>(
    py: Python<'py>,
    scene: Option<String>,
    scene_text: Option<String>,
    name: &str,
    method: Option<&Bound<'py, PyAny>>,
    dt: Option<f64>,
    t_end: Option<f64>,
    every: Option<u64>,
    save_at: Option<Vec<f64>>,
    split: Option<String>,
    corrector: Option<usize>,
    rtol: Option<f64>,
    atol: Option<f64>,
    compensated: bool,
    max_steps: Option<u64>,
    numbers: Option<BTreeMap<String, f64>>,
) -> PyResult<Bound<'py, PyDict>> {
    let (method, given) = method_arg(method)?;
    let mut request = RunRequest::new(scene_input(scene, scene_text, name));
    request.method = method;
    request.given = given;
    request.dt = dt;
    request.t_end = t_end;
    request.every = every;
    request.save_at = save_at;
    request.split = split;
    request.corrector = corrector;
    request.rtol = rtol;
    request.atol = atol;
    request.compensated = compensated;
    request.max_steps = max_steps;
    request.numbers = numbers.unwrap_or_default().into_iter().collect();
    let records = py.detach(|| in_process::run(&request, None)).map_err(value_error)?;
    records_dict(py, records)
}

/// The records as a dict of numpy arrays: `t` (n), `y` (n, k), `energy` (n) or None,
/// `components`, `summary` (a dict), `failure` (None or why the run stopped early).
fn records_dict(py: Python<'_>, records: Records) -> PyResult<Bound<'_, PyDict>> {
    let n = records.t.len();
    let k = records.components.len();
    let d = PyDict::new(py);
    d.set_item("t", records.t.into_pyarray(py))?;
    d.set_item("y", PyArray1::from_vec(py, records.y).reshape([n, k])?)?;
    d.set_item("energy", records.energy.map(|e| e.into_pyarray(py)))?;
    d.set_item("components", records.components)?;
    let s = records.summary;
    let summary = PyDict::new(py);
    summary.set_item("text", s.text)?;
    summary.set_item("method", s.method)?;
    summary.set_item("scene", s.scene)?;
    summary.set_item("steps", s.steps)?;
    summary.set_item("rejected", s.rejected)?;
    summary.set_item("evaluations", s.evaluations)?;
    summary.set_item("energy_drift", s.energy_drift)?;
    summary.set_item("max_error", s.max_error)?;
    summary.set_item("stop", s.stop)?;
    summary.set_item("t_end", s.t_end)?;
    d.set_item("summary", summary)?;
    d.set_item("failure", records.failure)?;
    Ok(d)
}

/// A scene's model, initial state (its own coordinates), components, `[run]` settings and
/// bodies, as a dict.
#[pyfunction]
#[pyo3(signature = (scene=None, scene_text=None, name="scene"))]
pub fn scene_info<'py>(
    py: Python<'py>,
    scene: Option<String>,
    scene_text: Option<String>,
    name: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let info = in_process::scene_info(&scene_input(scene, scene_text, name)).map_err(value_error)?;
    let d = PyDict::new(py);
    d.set_item("model", info.model)?;
    d.set_item("components", info.components)?;
    d.set_item("state", info.state)?;
    d.set_item("method", info.method)?;
    d.set_item("dt", info.dt)?;
    d.set_item("t0", info.t0)?;
    d.set_item("split", info.split)?;
    if let Some((names, masses, g)) = info.bodies {
        d.set_item("names", names)?;
        d.set_item("masses", masses)?;
        d.set_item("G", g)?;
    }
    Ok(d)
}

/// The exact Jacobian of one step from an n-body scene's initial state (dual numbers).
#[pyfunction]
#[pyo3(signature = (method, dt, scene=None, scene_text=None, name="scene"))]
pub fn step_jacobian<'py>(
    py: Python<'py>,
    method: &Bound<'py, PyAny>,
    dt: f64,
    scene: Option<String>,
    scene_text: Option<String>,
    name: &str,
) -> PyResult<Bound<'py, numpy::PyArray2<f64>>> {
    let method = match method_arg(Some(method))? {
        (_, Some(m)) => m,
        (name, None) => stormer::Method::resolve(&name.unwrap_or_default()).map_err(crate::errors::library_error)?,
    };
    let (n, j) = in_process::step_jacobian(&scene_input(scene, scene_text, name), &method, dt).map_err(value_error)?;
    PyArray1::from_vec(py, j).reshape([n, n])
}
