//! A user's right-hand side as a Python callable `f(t, y) -> dy/dt` (numpy arrays in and
//! out), integrated by any Runge-Kutta method of the catalog or given as data. Each
//! evaluation is a call into the interpreter (docs/python.md gives its cost against the
//! built-in models); an exception raised by the callable stops the run at once and is
//! raised again from `integrate`, its records up to there dropped with it.

use crate::errors::library_error;
use crate::records::method_arg;
use nalgebra::DVector;
use numpy::{AllowTypeChange, IntoPyArray, PyArray1, PyArrayLike1, PyArrayMethods};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use std::cell::{Cell, RefCell};
use stormer::driver::Recorder;
use stormer::stepper::{ImplicitOptions, Tolerances};
use stormer::{Driver, Error, Problem};
use stormer_app::cli::in_process::Records;

/// `y' = f(t, y)` with `f` a Python callable.
struct PythonRhs {
    f: Py<PyAny>,
    /// The state's length.
    n: usize,
    /// The first exception the callable raised (or its wrong answer): the run stops.
    error: RefCell<Option<PyErr>>,
    calls: Cell<u64>,
}

impl PythonRhs {
    /// `f(t, y)` as a vector of `n` numbers, or the reason it is not.
    fn call(&self, py: Python<'_>, t: f64, y: &DVector<f64>) -> PyResult<Vec<f64>> {
        let y = PyArray1::from_slice(py, y.as_slice());
        let out = self.f.call1(py, (t, y))?;
        let out = out.bind(py);
        let dy: PyArrayLike1<'_, f64, AllowTypeChange> = out.extract().map_err(|_| {
            PyTypeError::new_err(format!(
                "the right-hand side must return a 1-D array of {} numbers, got {}",
                self.n,
                out.get_type().name().map_or_else(|_| "?".into(), |n| n.to_string())
            ))
        })?;
        let dy = dy.as_slice()?.to_vec();
        if dy.len() != self.n {
            return Err(PyValueError::new_err(format!(
                "the right-hand side returned {} values at t = {t} for a state of {}",
                dy.len(),
                self.n
            )));
        }
        Ok(dy)
    }
}

impl Problem for PythonRhs {
    type Scalar = f64;
    type State = DVector<f64>;

    fn rhs(&self, t: f64, y: &DVector<f64>, dy: &mut DVector<f64>) {
        self.calls.set(self.calls.get() + 1);
        if self.error.borrow().is_some() {
            dy.fill(f64::NAN);
            return;
        }
        match Python::attach(|py| self.call(py, t, y)) {
            Ok(values) => dy.copy_from_slice(&values),
            Err(e) => {
                // a NaN derivative ends the run as a divergence; the exception is raised instead
                *self.error.borrow_mut() = Some(e);
                dy.fill(f64::NAN);
            }
        }
    }
}

/// Integrates `y' = f(t, y)` from `(t0, y0)` to `t_end`.
#[pyfunction]
#[pyo3(signature = (f, y0, t_end, method=None, dt=None, t0=0.0, rtol=None, atol=None, every=1, save_at=None, max_steps=None))]
pub fn integrate<'py>(
    py: Python<'py>,
    f: Py<PyAny>,
    y0: Vec<f64>,
    t_end: f64,
    method: Option<&Bound<'py, PyAny>>,
    dt: Option<f64>,
    t0: f64,
    rtol: Option<f64>,
    atol: Option<f64>,
    every: u64,
    save_at: Option<Vec<f64>>,
    max_steps: Option<u64>,
) -> PyResult<Bound<'py, PyDict>> {
    if !f.bind(py).is_callable() {
        return Err(PyTypeError::new_err("f must be a callable f(t, y) -> dy/dt"));
    }
    if let Some(k) = y0.iter().position(|v| !v.is_finite()) {
        return Err(PyValueError::new_err(format!(
            "the initial state must be finite: y0[{k}] = {}",
            y0[k]
        )));
    }
    let (name, given) = method_arg(method)?;
    let method = match (given, name) {
        (Some(m), _) => m,
        (None, Some(name)) => stormer::Method::resolve(&name).map_err(library_error)?,
        (None, None) => stormer::Method::named("dopri5").map_err(library_error)?,
    };
    let problem = PythonRhs {
        f,
        n: y0.len(),
        error: RefCell::new(None),
        calls: Cell::new(0),
    };
    let y0 = DVector::from_vec(y0);
    let mut stepper = method
        .stepper_for(&problem, &y0, &ImplicitOptions::fixed_point())
        .map_err(library_error)?;
    let mut driver = match (dt, rtol.or(atol)) {
        (_, Some(_)) => Driver::adaptive(Tolerances::new(
            rtol.or(atol).unwrap_or_default(),
            atol.or(rtol).unwrap_or_default(),
        )),
        (Some(h), None) => Driver::fixed(h),
        (None, None) => {
            return Err(PyValueError::new_err(
                "give a step (dt=...) or tolerances (rtol=..., atol=...) for adaptive steps",
            ))
        }
    };
    if every == 0 {
        return Err(PyValueError::new_err("every must be >= 1, got 0"));
    }
    driver = driver.every(every);
    if let Some(times) = save_at {
        driver = driver.save_at(times);
    }
    if let Some(n) = max_steps {
        driver = driver.max_steps(n);
    }
    let mut records = Records {
        components: (0..problem.n).map(|k| format!("y{k}")).collect(),
        ..Records::default()
    };
    let outcome = driver.run_into(
        &problem,
        &mut *stepper,
        t0,
        &y0,
        t_end,
        &mut records as &mut dyn Recorder<f64, DVector<f64>>,
    );
    if let Some(e) = problem.error.borrow_mut().take() {
        return Err(e);
    }
    let (stats, failure): (_, Option<Error>) = match outcome {
        Ok((stats, _)) => (stats, None),
        Err((stats, e)) => (stats, Some(e)),
    };
    let n = records.t.len();
    let d = PyDict::new(py);
    d.set_item("t", records.t.into_pyarray(py))?;
    d.set_item("y", PyArray1::from_vec(py, records.y).reshape([n, problem.n])?)?;
    let summary = PyDict::new(py);
    summary.set_item("method", method.name())?;
    summary.set_item("steps", stats.steps)?;
    summary.set_item("rejected", stats.rejected)?;
    summary.set_item("evaluations", stats.evaluations)?;
    summary.set_item("calls", problem.calls.get())?;
    d.set_item("summary", summary)?;
    d.set_item("failure", failure.map(|e| e.to_string()))?;
    Ok(d)
}
