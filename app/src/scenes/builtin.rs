//! The built-in scenes (the repository's `scenes/*.toml`, compiled in) and loading a
//! scene by name or from a file.

use super::file::{model_name, parse_as, Source};
use super::{AnyScene, ChargedScene, DampedOscillator, Harmonic, Pendulum, Scene, MODELS};
use super::{HenonHeiles, RelativisticScene, RestrictedThreeBody, SpinningBall};
use nalgebra::DVector;
use std::path::Path;
use stormer::magnetic::Charged;
use stormer::models::{CentralForce, NBody, PerturbedCentralForce};
use stormer::Error;

/// A scene file compiled into the crate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BuiltinScene {
    /// Its name, e.g. `"pendulum"`.
    pub name: &'static str,
    /// The TOML text.
    pub text: &'static str,
}

/// The built-in scenes, in the order of docs/scenes.md.
pub const BUILTIN: &[BuiltinScene] = &[
    BuiltinScene {
        name: "pendulum",
        text: include_str!("../../../scenes/pendulum.toml"),
    },
    BuiltinScene {
        name: "harmonic",
        text: include_str!("../../../scenes/harmonic.toml"),
    },
    BuiltinScene {
        name: "damped-oscillator",
        text: include_str!("../../../scenes/damped-oscillator.toml"),
    },
    BuiltinScene {
        name: "kepler",
        text: include_str!("../../../scenes/kepler.toml"),
    },
    BuiltinScene {
        name: "kepler-e06",
        text: include_str!("../../../scenes/kepler-e06.toml"),
    },
    BuiltinScene {
        name: "outer-solar-system",
        text: include_str!("../../../scenes/outer-solar-system.toml"),
    },
    BuiltinScene {
        name: "outer-solar-system-6",
        text: include_str!("../../../scenes/outer-solar-system-6.toml"),
    },
    BuiltinScene {
        name: "solar-system-8",
        text: include_str!("../../../scenes/solar-system-8.toml"),
    },
    BuiltinScene {
        name: "coulomb-magnetic",
        text: include_str!("../../../scenes/coulomb-magnetic.toml"),
    },
    BuiltinScene {
        name: "cyclotron",
        text: include_str!("../../../scenes/cyclotron.toml"),
    },
    BuiltinScene {
        name: "exb-drift",
        text: include_str!("../../../scenes/exb-drift.toml"),
    },
    BuiltinScene {
        name: "penning-trap",
        text: include_str!("../../../scenes/penning-trap.toml"),
    },
    BuiltinScene {
        name: "magnetic-bottle",
        text: include_str!("../../../scenes/magnetic-bottle.toml"),
    },
    BuiltinScene {
        name: "arenstorf",
        text: include_str!("../../../scenes/arenstorf.toml"),
    },
    BuiltinScene {
        name: "free-kick",
        text: include_str!("../../../scenes/free-kick.toml"),
    },
    BuiltinScene {
        name: "henon-heiles",
        text: include_str!("../../../scenes/henon-heiles.toml"),
    },
    BuiltinScene {
        name: "two-planets",
        text: include_str!("../../../scenes/two-planets.toml"),
    },
    BuiltinScene {
        name: "kepler-e099",
        text: include_str!("../../../scenes/kepler-e099.toml"),
    },
    BuiltinScene {
        name: "kepler-e099-perturbed",
        text: include_str!("../../../scenes/kepler-e099-perturbed.toml"),
    },
    BuiltinScene {
        name: "pythagorean",
        text: include_str!("../../../scenes/pythagorean.toml"),
    },
];

/// The built-in scene called `name` (`-` and `_` both accepted).
///
/// ```
/// let scene = stormer_app::scenes::builtin("damped_oscillator").unwrap();
/// assert_eq!(scene.name, "damped-oscillator");
/// assert!(stormer_app::scenes::builtin("kepler-e06").is_some());
/// assert!(stormer_app::scenes::builtin("inner-solar-system").is_none());
/// ```
pub fn builtin(name: &str) -> Option<&'static BuiltinScene> {
    let key = name.trim().to_lowercase().replace('_', "-");
    BUILTIN.iter().find(|s| s.name == key)
}

/// Loads a scene: a built-in name, or a path to a `.toml` scene file (read through the
/// bound of [`stormer::text`]).
///
/// ```
/// let scene = stormer_app::scenes::load("harmonic").unwrap();
/// assert_eq!(scene.model(), "harmonic");
/// assert_eq!(scene.run().dt, 0.001);
///
/// let err = stormer_app::scenes::load("pendulm").unwrap_err();
/// assert!(err.to_string().contains("did you mean 'pendulum'"));
/// ```
pub fn load(name_or_path: &str) -> Result<AnyScene, Error> {
    let source = source(name_or_path)?;
    parse(&source.text, &source.origin, &source.name)
}

/// A scene's text before it is parsed, read once (a pipe can be read only once).
#[derive(Debug, Clone)]
pub struct SceneSource {
    /// The TOML text.
    pub text: String,
    /// `built-in` or the path, for messages.
    pub origin: String,
    /// The scene's name (the built-in name or the file's stem).
    pub name: String,
}

/// The text of a built-in scene or a scene file (read through the bounded reader), with
/// its origin and name; [`load`] parses it.
pub fn source(name_or_path: &str) -> Result<SceneSource, Error> {
    if let Some(scene) = builtin(name_or_path) {
        return Ok(SceneSource {
            text: scene.text.to_string(),
            origin: "built-in".into(),
            name: scene.name.into(),
        });
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
            reason: format!("not a built-in scene ({}) nor a .toml file{near}", names.join(", ")),
        });
    }
    let origin = path.display().to_string();
    let text = stormer::text::read_text(path).map_err(|reason| Error::Scene {
        file: origin.clone(),
        reason,
    })?;
    let name = path
        .file_stem()
        .map_or_else(|| origin.clone(), |s| s.to_string_lossy().into_owned());
    Ok(SceneSource { text, origin, name })
}

/// Reads a scene from TOML text; `origin` (a path, or `built-in`) appears in errors and
/// `name` names the scene (in output file names).
///
/// ```
/// let text = "model = \"harmonic\"\n[parameters]\nw0 = 2.0\n[initial]\nx = 1.0\nv = 0.0\n\
///             [run]\nmethod = \"rk4\"\ndt = 0.01\nt_end = 1.0\nQ = 3.0\n";
/// let err = stormer_app::scenes::parse(text, "mine.toml", "mine").unwrap_err();
/// assert!(err.to_string().contains("line 11"));
/// assert!(err.to_string().contains("unknown field `Q`"));
/// ```
pub fn parse(text: &str, origin: &str, name: &str) -> Result<AnyScene, Error> {
    parse_source(
        &Source {
            origin,
            text,
            table: None,
        },
        name,
    )
}

/// [`parse`] of a scene file already read into a table (`toml::de::DeTable::parse` of
/// `text`, numbers possibly replaced in it since): the same scene, without reading the
/// text again. Its errors' lines are `text`'s.
pub fn parse_table<'a>(
    table: &'a toml::Spanned<toml::de::DeTable<'a>>,
    text: &'a str,
    origin: &'a str,
    name: &str,
) -> Result<AnyScene, Error> {
    parse_source(
        &Source {
            origin,
            text,
            table: Some(table),
        },
        name,
    )
}

/// [`parse`] of a [`Source`].
fn parse_source(src: &Source<'_>, name: &str) -> Result<AnyScene, Error> {
    let src = *src;
    let model = model_name(&src)?;
    let scene = match model.get_ref().as_str() {
        Harmonic::MODEL => AnyScene::Harmonic(parse_as(&src, name)?),
        DampedOscillator::MODEL => AnyScene::DampedOscillator(parse_as(&src, name)?),
        Pendulum::MODEL => AnyScene::Pendulum(parse_as(&src, name)?),
        CentralForce::<f64, DVector<f64>>::MODEL => AnyScene::CentralForce(parse_as(&src, name)?),
        NBody::<f64, DVector<f64>>::MODEL => {
            let setup = parse_as::<NBody<f64, DVector<f64>>>(&src, name)?;
            match setup.run.split {
                Some(split) => AnyScene::NBody(setup).with_split(split)?,
                None => AnyScene::NBody(setup),
            }
        }
        ChargedScene::MODEL => AnyScene::ChargedParticles(parse_as(&src, name)?),
        RelativisticScene::MODEL => AnyScene::RelativisticParticles(parse_as(&src, name)?),
        Charged::<RestrictedThreeBody>::MODEL => AnyScene::RestrictedThreeBody(parse_as(&src, name)?),
        SpinningBall::MODEL => AnyScene::SpinningBall(parse_as(&src, name)?),
        HenonHeiles::MODEL => AnyScene::HenonHeiles(parse_as(&src, name)?),
        PerturbedCentralForce::<f64, DVector<f64>>::MODEL => AnyScene::PerturbedCentralForce(parse_as(&src, name)?),
        other => {
            return Err(src.error_at(
                model.span(),
                format!("unknown model \"{other}\" (known models: {})", MODELS.join(", ")),
            ))
        }
    };
    match scene.run().time_transform {
        Some(transform) => scene
            .with_time_transform(transform)
            .map_err(|e| src.error(e.to_string())),
        None => Ok(scene),
    }
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // values read from a file or computed exactly are compared exactly
mod tests {
    use super::*;
    use crate::scenes::bad_line;

    #[test]
    fn every_builtin_scene_loads_with_the_users_values() {
        let models = [
            ("pendulum", "pendulum"),
            ("harmonic", "harmonic"),
            ("damped-oscillator", "damped-oscillator"),
            ("kepler", "n-body"),
            ("kepler-e06", "central-force"),
            ("outer-solar-system", "n-body"),
            ("outer-solar-system-6", "n-body"),
            ("solar-system-8", "n-body"),
            ("coulomb-magnetic", "charged-particles"),
            ("cyclotron", "charged-particles"),
            ("exb-drift", "charged-particles"),
            ("penning-trap", "charged-particles"),
            ("magnetic-bottle", "charged-particles"),
            ("arenstorf", "restricted-3-body"),
            ("free-kick", "spinning-ball"),
            ("henon-heiles", "henon-heiles"),
            ("two-planets", "n-body"),
            ("kepler-e099", "central-force"),
            ("kepler-e099-perturbed", "perturbed-central-force"),
            ("pythagorean", "n-body"),
        ];
        assert_eq!(BUILTIN.len(), models.len());
        for (s, (name, model)) in BUILTIN.iter().zip(models) {
            let scene = load(s.name).unwrap();
            assert_eq!((scene.name(), scene.model()), (name, model));
        }
        let AnyScene::DampedOscillator(d) = load("damped-oscillator").unwrap() else {
            panic!("model")
        };
        assert_eq!(d.model.w0, (100.0f64 / 5.0).sqrt());
        assert_eq!(d.model.q, d.model.w0);
        assert_eq!(d.y0, [10.0, 0.0]);
        assert_eq!((d.run.dt, d.run.t0, d.run.t_end, d.run.every), (0.001, 0.0, 10.0, 1));
        assert!(d.initial_energy().is_none(), "the damped oscillator has no energy");
        let AnyScene::Pendulum(p) = load("pendulum").unwrap() else {
            panic!("model")
        };
        assert_eq!(p.y0, [core::f64::consts::FRAC_PI_4, 0.0]);
        assert_eq!(p.run.t_end, 60.0);
        assert!(p.exact(1.0).is_none());
        let AnyScene::Harmonic(h) = load("harmonic").unwrap() else {
            panic!("model")
        };
        assert_eq!(h.model.w0, 20f64.sqrt());
        let e0 = h.initial_energy().unwrap();
        assert!((e0 - 1000.0).abs() < 1e-12, "w0^2 x0^2 / 2 = 1000, got {e0}");
    }

    const GOOD: &str = "model = \"damped-oscillator\"\n\
                        [parameters]\n\
                        w0 = 2.0\n\
                        Q = 1.0\n\
                        [initial]\n\
                        x = 1.0\n\
                        v = 0.0\n\
                        [run]\n\
                        method = \"rk4\"\n\
                        dt = 0.01\n\
                        t_end = 1.0\n\
                        every = 1\n";

    #[test]
    fn the_good_file_parses() {
        assert_eq!(parse(GOOD, "t.toml", "t").unwrap().model(), "damped-oscillator");
    }

    #[test]
    fn every_mistake_is_an_error_naming_its_line() {
        let cases = [
            (4, "Q = -1.0", "line 4: parameters.Q must be > 0, got -1"),
            (4, "Q = 0", "line 4: parameters.Q must be > 0, got 0"),
            (3, "w0 = nan", "line 3: parameters.w0 must be a finite number, got NaN"),
            (6, "x = inf", "line 6: initial.x must be a finite number, got inf"),
            (6, "x = \"ten\"", "line 6, column 5: invalid type: string \"ten\""),
            (6, "y = 1.0", "line 6, column 1: unknown field `y`"),
            (10, "dt = 0.0", "line 10: run.dt must be > 0, got 0"),
            (10, "dt = -1", "line 10: run.dt must be > 0, got -1"),
            (
                11,
                "t_end = -inf",
                "line 11: run.t_end must be a finite number, got -inf",
            ),
            (12, "every = 0", "line 12: run.every must be >= 1, got 0"),
            (
                12,
                "every = 1.5",
                "line 12, column 9: invalid type: floating point `1.5`, expected u64",
            ),
            (9, "method = \"\"", "line 9: run.method must name a method"),
            (5, "[initial", "line 5, column 9: unclosed table, expected `]`"),
            (1, "model = \"kepler\"", "line 1: unknown model \"kepler\""),
            (1, "mdl = \"harmonic\"", "missing field `model`"),
        ];
        bad_line::assert_bad_lines(GOOD, "t.toml", &cases);
        assert!(bad_line::error_with_line(GOOD, "t.toml", 11, "").contains("missing field `t_end`"));
        // a key outside its table: w0 and Q are both unknown at top level
        let message = bad_line::error_with_line(GOOD, "t.toml", 2, "");
        assert!(
            message.contains("unknown field `w0`") || message.contains("unknown field `Q`"),
            "{message}"
        );
    }

    #[test]
    fn units_are_read_for_the_axes_and_checked() {
        let text = format!("{GOOD}[units]\ntime = \"s\"\nlength = \"m\"\n");
        let AnyScene::DampedOscillator(s) = parse(&text, "t.toml", "t").unwrap() else {
            panic!("model")
        };
        assert_eq!((s.units.t(), s.units.position("x")), ("t (s)".into(), "x (m)".into()));
        let AnyScene::DampedOscillator(s) = parse(GOOD, "t.toml", "t").unwrap() else {
            panic!("model")
        };
        assert_eq!(s.units.t(), "t", "no unit, no parentheses");
        let message = parse(&format!("{GOOD}[units]\nmass = \"kg\"\n"), "t.toml", "t")
            .unwrap_err()
            .to_string();
        assert!(
            message.contains("line 14") && message.contains("unknown field `mass`"),
            "{message}"
        );
        let AnyScene::NBody(kepler) = load("kepler").unwrap() else {
            panic!("model")
        };
        assert_eq!(kepler.units.position("y"), "y (AU)");
    }

    #[test]
    fn missing_parameters_are_named() {
        let text = GOOD.replace("[parameters]\nw0 = 2.0\nQ = 1.0\n", "");
        let message = parse(&text, "t.toml", "t").unwrap_err().to_string();
        assert!(message.contains("missing table [parameters]"), "{message}");
    }

    #[test]
    fn names_and_paths() {
        assert!(builtin("Damped_Oscillator").is_some());
        let message = load("harmonik").unwrap_err().to_string();
        assert!(message.contains("did you mean 'harmonic'"), "{message}");
        let message = load("no/such/file.toml").unwrap_err().to_string();
        assert!(message.contains("cannot read the file"), "{message}");
        let dir = std::env::temp_dir().join(format!("stormer-scene-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("my-scene.toml");
        std::fs::write(&path, GOOD).unwrap();
        let scene = load(path.to_str().unwrap()).unwrap();
        assert_eq!(scene.name(), "my-scene");
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
