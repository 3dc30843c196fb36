//! Splittings and compositions read from TOML text in the catalog's format, validated by
//! the same code as the `splitting!` and `composition!` macros.

use super::file::check_declared;
use super::tableau::{vector, Coefficient};
use super::Splitting;
use crate::Error;
use serde::Deserialize;
use stormer_order::splitting::{CompositionSpec, SplittingSpec};
use stormer_order::OrderClass;

/// The keys of a splitting or composition in the catalog that describe it and are not
/// read, besides those every method may have.
const DESCRIPTIVE: &[&str] = &[
    "order_general",
    "order_rkn",
    "n_kick",
    "n_drift",
    "convention",
    "corrector",
    "corrector_c",
    "corrector_c_closed_form",
    "base",
    "source_convention",
];

/// The keys of one splitting or composition in a file, but for the descriptive ones;
/// declared stages and flags, when given, must agree with the coefficients.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SplittingFile {
    name: String,
    family: Option<String>,
    order: usize,
    drift: Option<Vec<Coefficient>>,
    kick: Option<Vec<Coefficient>>,
    gamma: Option<Vec<Coefficient>>,
    requires_quadratic_kinetic: Option<bool>,
    /// `general`, `rkn`, `near_integrable` or `near_integrable_rkn`: the class of the
    /// generalized order (an `rkn` one assumes a quadratic kinetic energy).
    class: Option<String>,
    /// `(p_1, p_2, ..)` for `H = A + eps B`, checked.
    generalized_order: Option<Vec<usize>>,
    stages: Option<usize>,
    tolerance: Option<f64>,
    explicit: Option<bool>,
    fsal: Option<bool>,
    symmetric: Option<bool>,
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
        let generalized_class = match self.class.as_deref() {
            None | Some("general" | "near_integrable") => OrderClass::General,
            Some("rkn" | "near_integrable_rkn") => OrderClass::QuadraticKineticEnergy,
            Some(other) => {
                return Err(fail(format!(
                    "class = \"{other}\" is not general, rkn, near_integrable or near_integrable_rkn"
                )))
            }
        };
        if family == "composition" && self.generalized_order.is_some() {
            return Err(fail(
                "a generalized order belongs to a splitting (H = A + eps B)".into(),
            ));
        }
        let method = if family == "splitting" {
            let spec = SplittingSpec {
                drift: vector(self.drift.as_deref().unwrap_or_default(), "drift").map_err(fail)?,
                kick: vector(self.kick.as_deref().unwrap_or_default(), "kick").map_err(fail)?,
                order: self.order,
                quadratic_kinetic: self.requires_quadratic_kinetic.unwrap_or(false),
                generalized_order: self.generalized_order.clone().map(|orders| (orders, generalized_class)),
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
        // a splitting is symplectic by construction: the file does not say
        let declared = [self.explicit, self.fsal, None, self.symmetric];
        check_declared(self.stages, declared, &method.info()).map_err(fail)?;
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
        super::file::read_entries(text, origin, not_butcher, DESCRIPTIVE, |file: SplittingFile| {
            file.into_splitting(origin)
        })
    }

    /// Reads a method file from disk.
    pub fn from_file(path: &std::path::Path) -> Result<Self, Error> {
        let (text, origin) = super::file::read_file(path)?;
        Splitting::from_toml_str(&text, &origin)
    }
}
