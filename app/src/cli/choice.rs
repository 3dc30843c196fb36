//! What `--method` names: a catalog method, a method file, or the theta method.

use std::path::{Path, PathBuf};
use stormer::method::SplittingData;
use stormer::registry::{self, normalize, MethodRef};
use stormer::stepper::ParticleMethod;
use stormer::{Error, ImplicitOptions, Splitting, Stepper, Tableau, TableauData};
use stormer_app::scenes::{Scene, SplittingChoice};

/// A method chosen on the command line.
pub enum MethodChoice {
    /// A compiled catalog tableau.
    Catalog(&'static TableauData),
    /// A compiled catalog splitting or composition.
    Splitting(&'static SplittingData),
    /// A tableau read from a TOML method file.
    File {
        /// The validated tableau.
        tableau: Tableau,
        /// Where it was read from.
        path: PathBuf,
    },
    /// A splitting or composition read from a TOML method file.
    SplittingFile {
        /// The validated method.
        method: Splitting,
        /// Where it was read from.
        path: PathBuf,
    },
    /// The theta method with weight `alpha` (`registry::theta`).
    Theta(Tableau),
    /// A charged-particle stepper (Boris, Euler-Cromer): not catalog data, a stepper
    /// for the charged-particle scenes.
    Particle(ParticleMethod),
}

/// A method file holding a splitting or composition: its family says so, or it has
/// `drift`/`kick`/`gamma` keys (a file that does not parse is left to the tableau reader,
/// which reports the TOML error).
fn is_splitting_file(path: &Path) -> bool {
    let Ok(text) = std::fs::read_to_string(path) else {
        return false;
    };
    let Ok(table) = text.parse::<toml::Table>() else {
        return false;
    };
    let entry = match table.get("method") {
        Some(toml::Value::Array(list)) => list.first().and_then(|m| m.as_table()).cloned(),
        _ => Some(table),
    };
    entry.is_some_and(|m| match m.get("family").and_then(|f| f.as_str()) {
        Some(family) => family == "splitting" || family == "composition",
        None => ["drift", "kick", "gamma"].iter().any(|k| m.contains_key(*k)),
    })
}

/// True when `arg` is meant as a file: it ends in `.toml`, has a path separator, or names
/// an existing file.
pub fn looks_like_path(arg: &str) -> bool {
    arg.ends_with(".toml") || arg.contains(['/', '\\']) || Path::new(arg).is_file()
}

impl MethodChoice {
    /// Resolves `name`: `theta` (with `alpha`, default 1/2), a charged-particle stepper
    /// (`boris`, `boris_exact_phase`, `euler_cromer`), a method file, or a catalog name (an unknown name is an error suggesting the nearest ones).
    pub fn resolve(name: &str, alpha: Option<f64>) -> Result<Self, Error> {
        if normalize(name) == "theta" {
            return Ok(MethodChoice::Theta(registry::theta(alpha.unwrap_or(0.5))?));
        }
        if alpha.is_some() {
            return Err(Error::invalid(
                "--alpha",
                format!("it applies to --method theta only, not to {name}"),
            ));
        }
        if let Some(method) = ParticleMethod::find(name) {
            return Ok(MethodChoice::Particle(method));
        }
        if looks_like_path(name) {
            let path = PathBuf::from(name);
            if is_splitting_file(&path) {
                let method = Splitting::from_file(&path)?;
                return Ok(MethodChoice::SplittingFile { method, path });
            }
            let tableau = Tableau::from_file(&path)?;
            return Ok(MethodChoice::File { tableau, path });
        }
        Ok(match registry::lookup(name)? {
            MethodRef::Butcher(d) => MethodChoice::Catalog(d),
            MethodRef::Splitting(d) => MethodChoice::Splitting(d),
        })
    }

    /// The short name used in output file names and summaries.
    pub fn label(&self) -> String {
        match self {
            MethodChoice::Catalog(d) => d.name.to_string(),
            MethodChoice::Splitting(d) => d.name.to_string(),
            MethodChoice::File { tableau, .. } => tableau.name().to_string(),
            MethodChoice::SplittingFile { method, .. } => method.name().to_string(),
            MethodChoice::Theta(t) => t.name().to_string(),
            MethodChoice::Particle(m) => m.name().to_string(),
        }
    }

    /// The run-time tableau (for `verify`).
    pub fn tableau(&self) -> Result<Tableau, Error> {
        match self {
            MethodChoice::Catalog(d) => Tableau::from_data(d),
            MethodChoice::Splitting(_) | MethodChoice::SplittingFile { .. } => Err(Error::Unsupported {
                name: self.label(),
                reason: "it is a splitting or composition, not a Butcher tableau".into(),
            }),
            MethodChoice::Particle(_) => Err(Error::Unsupported {
                name: self.label(),
                reason: "it is a charged-particle stepper, not a Butcher tableau".into(),
            }),
            MethodChoice::File { tableau, .. } | MethodChoice::Theta(tableau) => Ok(tableau.clone()),
        }
    }

    /// A stepper for the scene's model: the compiled stepper of a catalog method, the
    /// run-time one of a file or theta tableau. A splitting goes through the model
    /// ([`Scene::splitting_stepper`]), which refuses it with the reason when the model is
    /// not a Hamiltonian of the kind the method needs; so does a charged-particle stepper
    /// ([`Scene::particle_stepper`]), which needs a charged-particle model.
    pub fn stepper<S: Scene>(
        &self,
        model: &S,
        y0: &S::State,
        implicit: &ImplicitOptions,
    ) -> Result<Box<dyn Stepper<S>>, Error> {
        match self {
            MethodChoice::Catalog(d) => registry::stepper::<S>(d.name, y0, implicit),
            MethodChoice::Splitting(d) => model.splitting_stepper(SplittingChoice::Compiled(d), y0),
            MethodChoice::SplittingFile { method, .. } => model.splitting_stepper(SplittingChoice::Runtime(method), y0),
            MethodChoice::File { tableau, .. } | MethodChoice::Theta(tableau) => {
                registry::tableau_stepper::<S>(tableau, y0, implicit)
            }
            MethodChoice::Particle(m) => model.particle_stepper(*m, y0),
        }
    }
}
