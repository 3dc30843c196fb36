//! Splittings and compositions read from TOML text in the catalog's format, validated by
//! the same code as the `splitting!` and `composition!` macros.

use super::tableau::{vector, Coefficient};
use super::Splitting;
use crate::Error;
use serde::Deserialize;
use stormer_order::splitting::{CompositionSpec, SplittingSpec};

/// The keys of one splitting or composition in a file. Descriptive keys of the catalog
/// are accepted and ignored; declared stages and flags, when given, must agree with the
/// coefficients.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
#[allow(dead_code)] // the descriptive keys are read only to be accepted
struct SplittingFile {
    name: String,
    #[serde(default)]
    family: Option<String>,
    order: usize,
    #[serde(default)]
    drift: Option<Vec<Coefficient>>,
    #[serde(default)]
    kick: Option<Vec<Coefficient>>,
    #[serde(default)]
    gamma: Option<Vec<Coefficient>>,
    #[serde(default)]
    requires_quadratic_kinetic: Option<bool>,
    #[serde(default)]
    stages: Option<usize>,
    #[serde(default)]
    tolerance: Option<f64>,
    #[serde(default)]
    explicit: Option<bool>,
    #[serde(default)]
    fsal: Option<bool>,
    #[serde(default)]
    symmetric: Option<bool>,
    // Descriptive keys of the catalog.
    #[serde(default)]
    aliases: Option<toml::Value>,
    #[serde(default)]
    class: Option<toml::Value>,
    #[serde(default)]
    order_general: Option<toml::Value>,
    #[serde(default)]
    order_rkn: Option<toml::Value>,
    #[serde(default)]
    n_kick: Option<toml::Value>,
    #[serde(default)]
    n_drift: Option<toml::Value>,
    #[serde(default)]
    convention: Option<toml::Value>,
    #[serde(default)]
    generalized_order: Option<toml::Value>,
    #[serde(default)]
    corrector: Option<toml::Value>,
    #[serde(default)]
    corrector_c: Option<toml::Value>,
    #[serde(default)]
    corrector_c_closed_form: Option<toml::Value>,
    #[serde(default)]
    base: Option<toml::Value>,
    #[serde(default)]
    reference: Option<toml::Value>,
    #[serde(default)]
    source_repo: Option<toml::Value>,
    #[serde(default)]
    source_path: Option<toml::Value>,
    #[serde(default)]
    source_commit: Option<toml::Value>,
    #[serde(default)]
    source_convention: Option<toml::Value>,
    #[serde(default)]
    precision: Option<toml::Value>,
    #[serde(default)]
    notes: Option<toml::Value>,
    #[serde(default)]
    closed_form: Option<toml::Value>,
    #[serde(default)]
    checked_ok: Option<toml::Value>,
    #[serde(default)]
    checked: Option<toml::Value>,
}

impl SplittingFile {
    fn into_splitting(self, origin: &str) -> Result<Splitting, Error> {
        let fail = |reason: String| Error::InvalidMethod {
            name: format!("{} ({origin})", self.name),
            reason,
        };
        let arrays = (self.drift.as_deref(), self.kick.as_deref(), self.gamma.as_deref());
        let family = match (self.family.as_deref(), arrays) {
            (Some("splitting") | None, (Some(_), Some(_), None)) => "splitting",
            (Some("composition") | None, (None, None, Some(_))) => "composition",
            (Some(f @ ("splitting" | "composition")), _) => {
                return Err(fail(format!(
                    "family = \"{f}\" needs {} and nothing else of drift, kick, gamma",
                    if f == "splitting" { "drift and kick" } else { "gamma" }
                )))
            }
            (Some(f), _) => return Err(fail(format!("family = \"{f}\" is not a splitting or composition"))),
            (None, _) => {
                return Err(fail(
                    "give drift and kick (a splitting) or gamma (a composition), not a mix".into(),
                ))
            }
        };
        let method = if family == "splitting" {
            let spec = SplittingSpec {
                drift: vector(self.drift.as_deref().unwrap_or_default(), "drift").map_err(fail)?,
                kick: vector(self.kick.as_deref().unwrap_or_default(), "kick").map_err(fail)?,
                order: self.order,
                tolerance: self.tolerance,
            };
            Splitting::from_spec(
                self.name.clone(),
                &spec,
                self.requires_quadratic_kinetic.unwrap_or(false),
            )
        } else {
            if self.requires_quadratic_kinetic == Some(true) {
                return Err(fail("a composition cannot require a quadratic kinetic energy".into()));
            }
            let spec = CompositionSpec {
                gamma: vector(self.gamma.as_deref().unwrap_or_default(), "gamma").map_err(fail)?,
                order: self.order,
                tolerance: self.tolerance,
            };
            Splitting::from_composition_spec(self.name.clone(), &spec)
        }
        .map_err(|e| match e {
            Error::InvalidMethod { reason, .. } => fail(reason),
            other => other,
        })?;
        let flags = method.flags();
        let declared = [
            (
                "stages",
                self.stages.map(|s| s.to_string()),
                method.stages().to_string(),
            ),
            (
                "explicit",
                self.explicit.map(|x| x.to_string()),
                flags.explicit.to_string(),
            ),
            ("fsal", self.fsal.map(|x| x.to_string()), flags.fsal.to_string()),
            (
                "symmetric",
                self.symmetric.map(|x| x.to_string()),
                flags.symmetric.to_string(),
            ),
        ];
        for (key, said, derived) in declared {
            if let Some(said) = said.filter(|s| *s != derived) {
                return Err(fail(format!(
                    "the file declares {key} = {said} but the coefficients give {derived}"
                )));
            }
        }
        Ok(method)
    }
}

impl Splitting {
    /// Reads one method from TOML text in the catalog's format: the keys of one method at
    /// top level, or a `[[method]]` array holding exactly one splitting or composition.
    /// `origin` (a file name) is used in error messages.
    ///
    /// ```
    /// use stormer::Splitting;
    /// let m = Splitting::from_toml_str(r#"
    ///     name = "my_leapfrog"
    ///     family = "splitting"
    ///     order = 2
    ///     drift = ["1/2", "1/2"]
    ///     kick = ["1", "0"]
    /// "#, "inline").unwrap();
    /// assert!(m.flags().symmetric);
    /// let bad = Splitting::from_toml_str("name = \"x\"\norder = 2\ngamma = [\"0.9\"]", "inline");
    /// assert!(bad.unwrap_err().to_string().contains("sum gamma_i = 1 fails"));
    /// ```
    pub fn from_toml_str(text: &str, origin: &str) -> Result<Self, Error> {
        let all = Splitting::all_from_toml_str(text, origin)?;
        super::file::exactly_one(all, origin, "splittings or compositions")
    }

    /// Reads every splitting and composition of TOML text in the catalog's format (a
    /// `[[method]]` array; Butcher tableaus are skipped), or the one method at top level.
    pub fn all_from_toml_str(text: &str, origin: &str) -> Result<Vec<Self>, Error> {
        let not_butcher = |family: Option<&str>| family != Some("butcher");
        super::file::read_entries(text, origin, not_butcher, |file: SplittingFile| {
            file.into_splitting(origin)
        })
    }

    /// Reads a method file from disk.
    pub fn from_file(path: &std::path::Path) -> Result<Self, Error> {
        let (text, origin) = super::file::read_file(path)?;
        Splitting::from_toml_str(&text, &origin)
    }
}
