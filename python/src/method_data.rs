//! A method given as data from Python: a Butcher tableau or a splitting or composition in
//! the catalog's TOML format (the Python layer writes lists as that TOML), read and checked
//! by the library's own code, so it is refused with the same message as a method file.

use crate::errors::{library_error, value_error};
use pyo3::prelude::*;

/// A method of the catalog, a method file, or a method given as data: pass it as
/// `method=` anywhere a method's name is accepted.
#[pyclass(module = "stormer", frozen)]
#[derive(Clone)]
pub struct Method {
    pub(crate) method: stormer::Method,
    /// Where it came from: "catalog", a file, or "Python".
    source: String,
}

#[pymethods]
impl Method {
    /// A catalog name or alias, or a path to a method file (`stormer verify`'s argument).
    #[staticmethod]
    fn named(name: &str) -> PyResult<Self> {
        let method = stormer::Method::resolve(name).map_err(library_error)?;
        Ok(Method {
            method,
            source: name.to_string(),
        })
    }

    /// A method from TOML text in the catalog's format: a Butcher tableau, or a splitting
    /// or composition (its family, or its `drift`/`kick`/`word`/`gamma` keys, say which).
    #[staticmethod]
    #[pyo3(signature = (text, origin = "Python"))]
    fn from_toml(text: &str, origin: &str) -> PyResult<Self> {
        let method = stormer::Method::from_toml_str(text, origin).map_err(library_error)?;
        Ok(Method {
            method,
            source: origin.to_string(),
        })
    }

    /// The method's name.
    #[getter]
    fn name(&self) -> &str {
        self.method.name()
    }

    /// Name, family, order, stages and flags, as `stormer.methods()` gives them.
    fn info<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, pyo3::types::PyDict>> {
        let info = self.method.info();
        let d = pyo3::types::PyDict::new(py);
        d.set_item("name", &info.name)?;
        d.set_item("family", info.family)?;
        d.set_item("order", info.order)?;
        d.set_item("stages", info.stages)?;
        d.set_item("explicit", info.flags.explicit)?;
        d.set_item("embedded_order", info.embedded_order)?;
        d.set_item("fsal", info.flags.fsal)?;
        d.set_item("symplectic", info.flags.symplectic)?;
        d.set_item("symmetric", info.flags.symmetric)?;
        Ok(d)
    }

    /// `stormer verify`'s JSON report on this method and the contradictions found.
    fn verify_json(&self) -> PyResult<(String, Vec<String>)> {
        let v = stormer_app::cli::in_process::verify_method_json(&self.method, &self.source).map_err(value_error)?;
        Ok((v.json, v.contradictions))
    }

    fn __repr__(&self) -> String {
        format!(
            "stormer.Method({:?}, family={})",
            self.method.name(),
            self.method.info().family
        )
    }
}
