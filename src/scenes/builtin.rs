//! The built-in scenes (the repository's `scenes/*.toml`, compiled in) and loading a
//! scene by name or from a file.

use super::file::{model_name, parse_as, Source};
use super::{AnyScene, DampedOscillator, Harmonic, Pendulum, Scene, MODELS};
use crate::Error;
use std::path::Path;

/// A scene file compiled into the crate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BuiltinScene {
    /// Its name, e.g. `"pendulum"`.
    pub name: &'static str,
    /// The TOML text.
    pub text: &'static str,
}

impl BuiltinScene {
    /// The first comment line of the file, without the `#`: what the scene is.
    pub fn summary(&self) -> &'static str {
        self.text
            .lines()
            .find_map(|l| l.trim().strip_prefix('#'))
            .map_or("", str::trim)
    }
}

/// The built-in scenes, in the order of `SCENES.md`.
pub const BUILTIN: &[BuiltinScene] = &[
    BuiltinScene {
        name: "pendulum",
        text: include_str!("../../scenes/pendulum.toml"),
    },
    BuiltinScene {
        name: "harmonic",
        text: include_str!("../../scenes/harmonic.toml"),
    },
    BuiltinScene {
        name: "damped-oscillator",
        text: include_str!("../../scenes/damped-oscillator.toml"),
    },
];

/// The built-in scene called `name` (`-` and `_` both accepted).
///
/// ```
/// let scene = stormer::scenes::builtin("damped_oscillator").unwrap();
/// assert_eq!(scene.name, "damped-oscillator");
/// assert!(stormer::scenes::builtin("kepler").is_none());
/// ```
pub fn builtin(name: &str) -> Option<&'static BuiltinScene> {
    let key = name.trim().to_lowercase().replace('_', "-");
    BUILTIN.iter().find(|s| s.name == key)
}

/// Loads a scene: a built-in name, or a path to a `.toml` scene file.
///
/// ```
/// let scene = stormer::scenes::load("harmonic").unwrap();
/// assert_eq!(scene.model(), "harmonic");
/// assert_eq!(scene.run().dt, 0.001);
///
/// let err = stormer::scenes::load("pendulm").unwrap_err();
/// assert!(err.to_string().contains("did you mean 'pendulum'"));
/// ```
pub fn load(name_or_path: &str) -> Result<AnyScene, Error> {
    if let Some(scene) = builtin(name_or_path) {
        return parse(scene.text, "built-in", scene.name);
    }
    let path = Path::new(name_or_path);
    let looks_like_path = name_or_path.ends_with(".toml") || name_or_path.contains(['/', '\\']) || path.is_file();
    if !looks_like_path {
        let names: Vec<&str> = BUILTIN.iter().map(|s| s.name).collect();
        let near = names
            .iter()
            .filter(|n| strsim::damerau_levenshtein(&name_or_path.to_lowercase(), n) <= 3)
            .map(|n| format!("; did you mean '{n}'?"))
            .next()
            .unwrap_or_default();
        return Err(Error::Scene {
            file: name_or_path.to_string(),
            reason: format!(
                "not a built-in scene ({}) nor a .toml file{near}",
                names.join(", ")
            ),
        });
    }
    let origin = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| Error::Scene {
        file: origin.clone(),
        reason: format!("cannot read the file: {e}"),
    })?;
    let name = path.file_stem().map_or_else(|| origin.clone(), |s| s.to_string_lossy().into_owned());
    parse(&text, &origin, &name)
}

/// Reads a scene from TOML text; `origin` (a path, or `built-in`) appears in errors and
/// `name` names the scene (in output file names).
///
/// ```
/// let text = "model = \"harmonic\"\n[parameters]\nw0 = 2.0\n[initial]\nx = 1.0\nv = 0.0\n\
///             [run]\nmethod = \"rk4\"\ndt = 0.01\nt_end = 1.0\nQ = 3.0\n";
/// let err = stormer::scenes::parse(text, "mine.toml", "mine").unwrap_err();
/// assert!(err.to_string().contains("line 11"));
/// assert!(err.to_string().contains("unknown field `Q`"));
/// ```
pub fn parse(text: &str, origin: &str, name: &str) -> Result<AnyScene, Error> {
    let src = Source { origin, text };
    let model = model_name(&src)?;
    Ok(match model.get_ref().as_str() {
        Harmonic::MODEL => AnyScene::Harmonic(parse_as(&src, name)?),
        DampedOscillator::MODEL => AnyScene::DampedOscillator(parse_as(&src, name)?),
        Pendulum::MODEL => AnyScene::Pendulum(parse_as(&src, name)?),
        other => {
            return Err(src.error_at(
                model.span(),
                format!("unknown model \"{other}\" (known models: {})", MODELS.join(", ")),
            ))
        }
    })
}
