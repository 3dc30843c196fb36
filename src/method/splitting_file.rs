//! Splittings and compositions read from TOML text in the catalog's format, validated by
//! the same code as the `splitting!` and `composition!` macros.

use super::file::check_declared;
use super::tableau::{coefficient, vector, Coefficient};
use super::Splitting;
use crate::Error;
use serde::Deserialize;
use stormer_order::splitting::{CompositionSpec, Flow, SplittingSpec};
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
    /// The step as any sequence of `"drift(x)"` and `"kick(x)"`, as the macro's `word`.
    word: Option<Vec<String>>,
    gamma: Option<Vec<Coefficient>>,
    /// `quadratic_kinetic` is the macro's name of the catalog's key.
    #[serde(alias = "quadratic_kinetic")]
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
        if self.word.is_some() && (self.drift.is_some() || self.kick.is_some()) {
            return Err(fail("give either word or drift and kick, not both".into()));
        }
        // a word stands for both arrays
        let arrays = (
            self.drift.is_some() || self.word.is_some(),
            self.kick.is_some() || self.word.is_some(),
            self.gamma.is_some(),
        );
        let family = match (self.family.as_deref(), arrays) {
            (Some("splitting") | None, (true, true, false)) => "splitting",
            (Some("composition") | None, (false, false, true)) => "composition",
            (Some(f @ ("splitting" | "composition")), _) => {
                return Err(fail(format!(
                    "family = \"{f}\" needs {} and nothing else of drift, kick, word, gamma",
                    if f == "splitting" {
                        "drift and kick (or word)"
                    } else {
                        "gamma"
                    }
                )))
            }
            (Some(f), _) => return Err(fail(format!("family = \"{f}\" is not a splitting or composition"))),
            (None, _) => {
                return Err(fail(
                    "give drift and kick or a word (a splitting), or gamma (a composition), not a mix".into(),
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
            let (drift, kick) = match &self.word {
                Some(word) => SplittingSpec::arrays_of_word(&word_entries(word).map_err(fail)?),
                None => (
                    vector(self.drift.as_deref().unwrap_or_default(), "drift").map_err(fail)?,
                    vector(self.kick.as_deref().unwrap_or_default(), "kick").map_err(fail)?,
                ),
            };
            let spec = SplittingSpec {
                drift,
                kick,
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

/// The flows of a `word`: each entry `"drift(x)"` or `"kick(x)"`, `x` a coefficient
/// expression; errors name the entry (`word[2]`).
fn word_entries(word: &[String]) -> Result<Vec<(Flow, f64)>, String> {
    word.iter()
        .enumerate()
        .map(|(i, entry)| {
            let field = format!("word[{}]", i + 1);
            let call = entry.trim();
            let flow_and_argument = [Flow::Drift, Flow::Kick].into_iter().find_map(|flow| {
                let argument = call.strip_prefix(flow.name())?.trim_start().strip_prefix('(')?;
                Some((flow, argument.strip_suffix(')')?))
            });
            let Some((flow, argument)) = flow_and_argument else {
                return Err(format!(
                    "{field} = \"{entry}\" is not a flow: write \"drift(fraction)\" or \"kick(fraction)\""
                ));
            };
            Ok((flow, coefficient(&Coefficient::Text(argument.to_string()), &field)?))
        })
        .collect()
}

impl Splitting {
    /// Reads one method from TOML text in the catalog's format: the keys of one method at
    /// top level, or a `[[method]]` array holding exactly one splitting or composition.
    /// `origin` (a file name) is used in error messages.
    ///
    /// ```
    /// use stormer::method::Splitting;
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

#[cfg(test)]
mod tests {
    use super::*;

    /// McLachlan's two-stage method of docs/define-your-own-scheme.md, as a word.
    const WORD: &str = r#"
        name = "my_mclachlan2"
        order = 2
        word = ["kick(0.1931833275037836)", "drift(1/2)", "kick(1 - 2 * 0.1931833275037836)",
                "drift(1/2)", "kick(0.1931833275037836)"]
    "#;

    #[test]
    fn a_word_reads_as_its_drift_first_arrays() {
        let from_word = Splitting::from_toml_str(WORD, "inline").unwrap();
        let arrays = Splitting::from_toml_str(
            r#"
            name = "my_mclachlan2"
            order = 2
            drift = ["0", "1/2", "1/2"]
            kick = ["0.1931833275037836", "1 - 2 * 0.1931833275037836", "0.1931833275037836"]
            "#,
            "inline",
        )
        .unwrap();
        assert_eq!(from_word.word(), arrays.word());
        assert_eq!((from_word.stages(), from_word.flags().fsal), (2, true));
    }

    #[test]
    fn the_macros_quadratic_kinetic_key_is_read() {
        // McLachlan-Atela 4 is of order 4 only with a quadratic kinetic energy
        let mcate4 = |key: &str| {
            format!(
                "name = \"m4\"\norder = 4\n{key} = true\n\
                 drift = [0, 0.5153528374311229364, -0.085782019412973646, 0.4415830236164665242, 0.1288461583653841854]\n\
                 kick = [0.1344961992774310892, -0.2248198030794208058, 0.7563200005156682911, 0.3340036032863214255, 0]\n"
            )
        };
        let m = Splitting::from_toml_str(&mcate4("quadratic_kinetic"), "inline").unwrap();
        assert!(m.requires_quadratic_kinetic());
        assert!(Splitting::from_toml_str(&mcate4("requires_quadratic_kinetic"), "inline").is_ok());
        let general = mcate4("quadratic_kinetic").replace("= true", "= false");
        let e = Splitting::from_toml_str(&general, "inline").unwrap_err().to_string();
        assert!(e.contains("order 4 condition") && e.contains("fails"), "{e}");
    }

    #[test]
    fn bad_words_are_named() {
        for (word, message) in [
            (r#"["kick(1)", "push(1)"]"#, "word[2] = \"push(1)\" is not a flow"),
            (r#"["kick(1/0)"]"#, "word[1] = \"1/0\": division by zero"),
            (r#"["drift(1"]"#, "word[1] = \"drift(1\" is not a flow"),
        ] {
            let text = format!("name = \"w\"\norder = 1\nword = {word}\n");
            let e = Splitting::from_toml_str(&text, "inline").unwrap_err().to_string();
            assert!(e.contains(message), "{word}: {e}");
        }
        let both = "name = \"w\"\norder = 1\nword = [\"drift(1)\", \"kick(1)\"]\ndrift = [\"1\"]\nkick = [\"1\"]\n";
        let e = Splitting::from_toml_str(both, "inline").unwrap_err().to_string();
        assert!(e.contains("give either word or drift and kick, not both"), "{e}");
    }
}
