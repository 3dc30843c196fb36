//! A Butcher tableau built at run time: from coefficients, or from a TOML file in the
//! catalog's format, validated by the same code the compile-time macro uses.

use super::file::check_declared;
use super::{Flags, MethodInfo, TableauData};
use crate::Error;
use serde::Deserialize;
use stormer_order::{Condition, TableauSpec, ValidTableau};

/// A validated Butcher tableau held in memory (coefficients as `f64`).
///
/// ```
/// use stormer::method::Tableau;
/// let heun = Tableau::from_toml_str(r#"
///     name = "my_heun"
///     order = 2
///     c = ["0", "1"]
///     a = [["0", "0"], ["1", "0"]]
///     b = ["1/2", "1/2"]
/// "#, "inline").unwrap();
/// assert_eq!(heun.stages(), 2);
/// assert!(heun.flags().explicit);
///
/// // A wrong coefficient is an error naming the failing condition, never a panic.
/// let bad = Tableau::from_toml_str(r#"
///     name = "bad"
///     order = 2
///     c = ["0", "1"]
///     a = [["0", "0"], ["1", "0"]]
///     b = ["0.4", "0.6"]
/// "#, "inline");
/// assert!(bad.unwrap_err().to_string().contains("order 2 condition"));
/// ```
#[derive(Debug, Clone)]
pub struct Tableau {
    name: String,
    valid: ValidTableau,
    tolerance: Option<f64>,
}

impl Tableau {
    /// Validates coefficients given as plain data.
    pub fn new(name: impl Into<String>, spec: &TableauSpec) -> Result<Self, Error> {
        let name = name.into();
        match stormer_order::validate(spec) {
            Ok(valid) => Ok(Tableau {
                name,
                valid,
                tolerance: spec.tolerance,
            }),
            Err(e) => Err(Error::InvalidMethod {
                name,
                reason: e.to_string(),
            }),
        }
    }

    /// The run-time copy of a compiled method's data (validated again, which cannot fail
    /// for data that passed the macro).
    pub fn from_data(data: &TableauData) -> Result<Self, Error> {
        let s = data.stages;
        let spec = TableauSpec {
            a: data.a.chunks(s.max(1)).map(<[f64]>::to_vec).collect(),
            b: data.b.to_vec(),
            c: Some(data.c.to_vec()),
            order: data.order,
            b_hat: data.b_hat.map(<[f64]>::to_vec),
            embedded_order: data.embedded_order,
            b_hat3: data.b_hat3.map(<[f64]>::to_vec),
            tolerance: data.tolerance,
            dense: data
                .dense
                .map(|d| d.d.chunks(d.powers.max(1)).map(<[f64]>::to_vec).collect()),
            dense_order: data.dense.map(|d| d.order),
            dense_c: data.dense.map(|d| d.c.to_vec()).filter(|c| !c.is_empty()),
            dense_a: data.dense.filter(|d| !d.c.is_empty()).map(|d| {
                d.a.chunks(s + d.c.len())
                    .enumerate()
                    .map(|(k, row)| row[..s + k].to_vec())
                    .collect()
            }),
        };
        Tableau::new(data.name, &spec)
    }

    /// Reads one method from TOML text in the catalog's format: either the keys of one
    /// method at top level, or a `[[method]]` array holding exactly one Butcher method.
    /// `origin` (a file name) is used in error messages.
    pub fn from_toml_str(text: &str, origin: &str) -> Result<Self, Error> {
        super::file::exactly_one(Tableau::all_from_toml_str(text, origin)?, origin, "Butcher methods")
    }

    /// Reads every Butcher method of TOML text in the catalog's format (a `[[method]]`
    /// array; methods of other families are skipped), or the one method at top level.
    pub fn all_from_toml_str(text: &str, origin: &str) -> Result<Vec<Self>, Error> {
        let butcher = |family: Option<&str>| family.unwrap_or("butcher") == "butcher";
        super::file::read_entries(text, origin, butcher, &[], |file: MethodFile| file.into_tableau(origin))
    }

    /// Reads a method file from disk.
    pub fn from_file(path: &std::path::Path) -> Result<Self, Error> {
        let (text, origin) = super::file::read_file(path)?;
        Tableau::from_toml_str(&text, &origin)
    }

    /// The method's name.
    pub fn name(&self) -> &str {
        &self.name
    }
    /// Number of stages.
    pub fn stages(&self) -> usize {
        self.valid.stages
    }
    /// Verified order.
    pub fn order(&self) -> usize {
        self.valid.order
    }
    /// Verified embedded order.
    pub fn embedded_order(&self) -> Option<usize> {
        self.valid.embedded_order
    }
    /// Derived flags.
    pub fn flags(&self) -> Flags {
        self.valid.flags
    }
    /// Stage matrix, row-major.
    pub fn a(&self) -> &[f64] {
        &self.valid.a
    }
    /// Weights.
    pub fn b(&self) -> &[f64] {
        &self.valid.b
    }
    /// Nodes.
    pub fn c(&self) -> &[f64] {
        &self.valid.c
    }
    /// Embedded weights.
    pub fn b_hat(&self) -> Option<&[f64]> {
        self.valid.b_hat.as_deref()
    }
    /// DOP853's third-order weights.
    pub fn b_hat3(&self) -> Option<&[f64]> {
        self.valid.b_hat3.as_deref()
    }
    /// The method's own dense output: per stage, the coefficients of theta^1 .. theta^m
    /// of `b_i(theta)`, checked to [`Tableau::info`]'s `dense_order`.
    pub fn dense(&self) -> Option<&[Vec<f64>]> {
        self.valid.dense.as_deref()
    }
    /// Nodes of the stages the dense output adds after the step (empty for most).
    pub fn dense_c(&self) -> &[f64] {
        &self.valid.dense_c
    }
    /// Their rows of the stage matrix, `e x (s + e)` row-major.
    pub fn dense_a(&self) -> &[f64] {
        &self.valid.dense_a
    }
    /// Every order condition that was checked, with its residual.
    pub fn conditions(&self) -> &[Condition] {
        &self.valid.conditions
    }
    /// The tolerance factor used by the checks (`None`: the default).
    pub fn tolerance(&self) -> Option<f64> {
        self.tolerance
    }

    /// The same tableau propagating its embedded solution (`b := b_hat`), e.g. to measure
    /// the embedded order. `None` without `b_hat`.
    pub fn embedded_as_main(&self) -> Option<Result<Tableau, Error>> {
        let b_hat = self.valid.b_hat.clone()?;
        let s = self.stages();
        let spec = TableauSpec {
            a: self.valid.a.chunks(s).map(<[f64]>::to_vec).collect(),
            b: b_hat,
            c: Some(self.valid.c.clone()),
            order: self.valid.embedded_order?,
            b_hat: None,
            embedded_order: None,
            b_hat3: None,
            tolerance: self.tolerance,
            ..Default::default()
        };
        Some(Tableau::new(format!("{} (embedded)", self.name), &spec))
    }
    /// The table row of this method.
    pub fn info(&self) -> MethodInfo {
        MethodInfo {
            name: self.name.clone(),
            family: "butcher",
            order: self.order(),
            stages: self.stages(),
            embedded_order: self.embedded_order(),
            dense_order: self.valid.dense_order,
            flags: self.flags(),
        }
    }
}

/// A coefficient as written in a file: an expression string, or a TOML number.
#[derive(Debug, Deserialize)]
#[serde(untagged)]
pub(super) enum Coefficient {
    Text(String),
    Integer(i64),
    Float(f64),
}

/// The keys of one Butcher method in a file (catalog format), but for the descriptive ones
/// every method may have; the flags, when given, must agree with the data.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct MethodFile {
    name: String,
    family: Option<String>,
    order: usize,
    embedded_order: Option<usize>,
    stages: Option<usize>,
    c: Option<Vec<Coefficient>>,
    a: Vec<Vec<Coefficient>>,
    b: Vec<Coefficient>,
    b_hat: Option<Vec<Coefficient>>,
    b_hat3: Option<Vec<Coefficient>>,
    dense: Option<Vec<Vec<Coefficient>>>,
    dense_order: Option<usize>,
    dense_c: Option<Vec<Coefficient>>,
    dense_a: Option<Vec<Vec<Coefficient>>>,
    tolerance: Option<f64>,
    explicit: Option<bool>,
    fsal: Option<bool>,
    symplectic: Option<bool>,
    symmetric: Option<bool>,
}

pub(super) fn coefficient(c: &Coefficient, field: &str) -> Result<f64, String> {
    match c {
        Coefficient::Text(s) => stormer_order::eval_coefficient(s).map_err(|e| format!("{field} = \"{s}\": {e}")),
        Coefficient::Integer(i) => Ok(*i as f64),
        Coefficient::Float(x) if x.is_finite() => Ok(*x),
        Coefficient::Float(x) => Err(format!("{field} = {x}: not a finite number")),
    }
}

/// Rows of coefficients, each named `field[i]` in errors.
fn matrix(rows: &[Vec<Coefficient>], field: &str) -> Result<Vec<Vec<f64>>, String> {
    rows.iter()
        .enumerate()
        .map(|(i, row)| vector(row, &format!("{field}[{}]", i + 1)))
        .collect()
}

pub(super) fn vector(v: &[Coefficient], field: &str) -> Result<Vec<f64>, String> {
    v.iter()
        .enumerate()
        .map(|(i, c)| coefficient(c, &format!("{field}[{}]", i + 1)))
        .collect()
}

impl MethodFile {
    fn into_tableau(self, origin: &str) -> Result<Tableau, Error> {
        let fail = |reason: String| Error::InvalidMethod {
            name: format!("{} ({origin})", self.name),
            reason,
        };
        if let Some(f) = self.family.as_deref().filter(|f| *f != "butcher") {
            return Err(fail(format!("family = \"{f}\" is not a Butcher tableau")));
        }
        let spec = TableauSpec {
            a: matrix(&self.a, "a").map_err(fail)?,
            b: vector(&self.b, "b").map_err(fail)?,
            c: self.c.as_deref().map(|c| vector(c, "c")).transpose().map_err(fail)?,
            order: self.order,
            b_hat: self
                .b_hat
                .as_deref()
                .map(|v| vector(v, "b_hat"))
                .transpose()
                .map_err(fail)?,
            embedded_order: self.embedded_order,
            b_hat3: self
                .b_hat3
                .as_deref()
                .map(|v| vector(v, "b_hat3"))
                .transpose()
                .map_err(fail)?,
            tolerance: self.tolerance,
            dense: self
                .dense
                .as_deref()
                .map(|d| matrix(d, "dense"))
                .transpose()
                .map_err(fail)?,
            dense_order: self.dense_order,
            dense_c: self
                .dense_c
                .as_deref()
                .map(|c| vector(c, "dense_c"))
                .transpose()
                .map_err(fail)?,
            dense_a: self
                .dense_a
                .as_deref()
                .map(|d| matrix(d, "dense_a"))
                .transpose()
                .map_err(fail)?,
        };
        let tableau = Tableau::new(self.name.clone(), &spec).map_err(|e| match e {
            Error::InvalidMethod { reason, .. } => fail(reason),
            other => other,
        })?;
        let declared = [self.explicit, self.fsal, self.symplectic, self.symmetric];
        check_declared(self.stages, declared, &tableau.info()).map_err(fail)?;
        Ok(tableau)
    }
}
