//! The scene file format: TOML with `model`, `[parameters]`, `[initial]` and `[run]`,
//! parsed with serde (unknown keys rejected) and checked field by field, every error
//! naming the file, the line and the field.

use super::{Scene, Setup};
use serde::Deserialize;
use stormer::text::{line_column, one_line, toml_message};
use stormer::Error;
use toml::de::DeTable;
use toml::Spanned;

/// A number read from a scene file, with where it was written (for error messages).
pub type Number = Spanned<f64>;

/// The text of a scene file and where it came from: the context of every error
/// reported while reading it.
#[derive(Debug, Clone, Copy)]
pub struct Source<'a> {
    /// The scene's name (built-in) or the file's path.
    pub origin: &'a str,
    /// The file's text.
    pub text: &'a str,
    /// The file already read into a table, when it was (an ensemble's members: the
    /// scene's table read once, the varied numbers replaced in it); its spans are `text`'s.
    pub table: Option<&'a Spanned<DeTable<'a>>>,
}

impl Source<'_> {
    /// An [`Error::Scene`] about this file.
    pub fn error(&self, reason: impl Into<String>) -> Error {
        Error::Scene {
            file: self.origin.to_string(),
            reason: one_line(&reason.into()),
        }
    }

    /// An [`Error::Scene`] about the value written at byte range `span`: `line L: reason`.
    pub fn error_at(&self, span: core::ops::Range<usize>, reason: impl core::fmt::Display) -> Error {
        let (line, _) = line_column(self.text, span.start);
        self.error(format!("line {line}: {reason}"))
    }

    /// A TOML or serde error, with its line and column.
    pub fn toml_error(&self, e: &toml::de::Error) -> Error {
        self.error(toml_message(e, self.text))
    }

    /// The value of `field` if it is a finite number.
    pub fn finite(&self, field: &str, x: &Number) -> Result<f64, Error> {
        let v = *x.get_ref();
        if v.is_finite() {
            Ok(v)
        } else {
            Err(self.error_at(x.span(), format!("{field} must be a finite number, got {v}")))
        }
    }

    /// The value of `field` if it is a finite number `> 0`.
    pub fn positive(&self, field: &str, x: &Number) -> Result<f64, Error> {
        let v = self.finite(field, x)?;
        if v > 0.0 {
            Ok(v)
        } else {
            Err(self.error_at(x.span(), format!("{field} must be > 0, got {v}")))
        }
    }

    /// The error for a missing table such as `[parameters]`.
    pub fn missing(&self, table: &str, keys: &str) -> Error {
        self.error(format!("missing table [{table}] (with {keys})"))
    }
}

/// How a scene is run unless the command line says otherwise (the file's `[run]` table).
#[derive(Debug, Clone, PartialEq)]
pub struct RunSettings {
    /// Method name (catalog name, or a path to a method file).
    pub method: String,
    /// Step size (`> 0`; the initial step of an adaptive run).
    pub dt: f64,
    /// Start time (default 0).
    pub t0: f64,
    /// End time.
    pub t_end: f64,
    /// Record every `every` steps (`>= 1`).
    pub every: u64,
    /// The Wisdom-Holman split an n-body scene runs in (`split = "kepler-jacobi"`), if any.
    pub split: Option<stormer::models::KeplerCoordinates>,
    /// An n-body run ends when a body gets this far from the centre of mass (`escape_distance
    /// = 20.0`, REBOUND's `exit_max_distance`), with a sentence saying which body and when.
    pub escape_distance: Option<f64>,
    /// The time transformation the scene runs in (`time_transform = "logh"`), if any: `dt`
    /// is then the step in the fictitious time `s` (docs/close-approaches.md).
    pub time_transform: Option<stormer::time_transform::Transform>,
}

/// The units a scene file names (its optional `[units]` table), for the pictures' axis
/// labels: `t (years)`, `x (AU)`. A unit left out is not printed.
#[derive(Debug, Clone, Default, PartialEq, Eq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Units {
    /// Unit of time (`"years"`, `"s"`, `"sqrt(l/g)"`); a key left out reads as `None`.
    pub time: Option<String>,
    /// Unit of the positions (`"AU"`, `"m"`).
    pub length: Option<String>,
    /// Unit of the angles (`"rad"`).
    pub angle: Option<String>,
}

impl Units {
    /// `name (unit)`, or `name` alone when the unit is not given.
    pub fn label(name: &str, unit: Option<&String>) -> String {
        match unit.map(|u| u.trim()).filter(|u| !u.is_empty()) {
            Some(unit) => format!("{name} ({unit})"),
            None => name.to_string(),
        }
    }

    /// The axis label of time: `t (years)`.
    pub fn t(&self) -> String {
        Self::label("t", self.time.as_ref())
    }

    /// The axis label of a position coordinate: `x (AU)`.
    pub fn position(&self, name: &str) -> String {
        Self::label(name, self.length.as_ref())
    }
}

/// A scene file as written, for the model `S`: unknown keys anywhere are errors.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneFile<P, I> {
    #[allow(dead_code)] // read by the first pass (`Header`); kept so that the key is known
    model: String,
    #[serde(default)]
    description: Option<String>,
    #[serde(default = "none")]
    parameters: Option<P>,
    // the N-body model writes its initial state as a list of `[[bodies]]`, the
    // charged-particle model as a list of `[[particles]]`
    #[serde(default = "none", alias = "bodies", alias = "particles")]
    initial: Option<I>,
    run: RunTable,
    #[serde(default)]
    units: Units,
}

fn none<P>() -> Option<P> {
    None
}

/// The `[run]` table.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RunTable {
    method: Spanned<String>,
    dt: Number,
    #[serde(default)]
    t0: Option<Number>,
    t_end: Number,
    #[serde(default)]
    every: Option<Spanned<u64>>,
    #[serde(default)]
    split: Option<Spanned<String>>,
    #[serde(default)]
    escape_distance: Option<Number>,
    time_transform: Option<Spanned<String>>,
}

impl RunTable {
    fn check(self, src: &Source<'_>) -> Result<RunSettings, Error> {
        let method = self.method.get_ref().trim().to_string();
        if method.is_empty() {
            return Err(src.error_at(self.method.span(), "run.method must name a method"));
        }
        let every = match &self.every {
            Some(n) if *n.get_ref() == 0 => return Err(src.error_at(n.span(), "run.every must be >= 1, got 0")),
            Some(n) => *n.get_ref(),
            None => 1,
        };
        Ok(RunSettings {
            method,
            dt: src.positive("run.dt", &self.dt)?,
            t0: self.t0.as_ref().map_or(Ok(0.0), |t| src.finite("run.t0", t))?,
            t_end: src.finite("run.t_end", &self.t_end)?,
            every,
            split: self
                .split
                .as_ref()
                .map(|s| {
                    stormer::models::KeplerCoordinates::named(s.get_ref()).map_err(|e| {
                        let reason = e.to_string();
                        src.error_at(s.span(), format!("run.{}", reason.trim_start_matches("invalid ")))
                    })
                })
                .transpose()?,
            escape_distance: self
                .escape_distance
                .as_ref()
                .map(|d| src.positive("run.escape_distance", d))
                .transpose()?,
            time_transform: self
                .time_transform
                .as_ref()
                .map(|s| {
                    stormer::time_transform::Transform::named(s.get_ref()).map_err(|e| {
                        let reason = e.to_string();
                        src.error_at(s.span(), format!("run.{}", reason.trim_start_matches("invalid ")))
                    })
                })
                .transpose()?,
        })
    }
}

/// First pass: only the model name, to choose the types of the second pass.
#[derive(Debug, Deserialize)]
struct Header {
    model: Spanned<String>,
}

/// The model named by a scene file (syntax errors are reported here, with their line).
///
/// `model` is a top-level key, so it is written before the first table: that part of
/// the file is read alone when it names the model (the whole file, of 10^5 bodies, is
/// read once, by the second pass). Otherwise the whole file is, for its errors.
pub(super) fn model_name(src: &Source<'_>) -> Result<Spanned<String>, Error> {
    let in_table = src.table.and_then(|t| t.get_ref().get("model"));
    if let Some(name) = in_table.and_then(|m| m.get_ref().as_str()) {
        return Ok(Spanned::new(in_table.map_or(0..0, |m| m.span()), name.to_string()));
    }
    let first_table = src
        .text
        .match_indices('\n')
        .map(|(i, _)| i + 1)
        .find(|&i| src.text[i..].trim_start_matches([' ', '\t']).starts_with('['))
        .unwrap_or(src.text.len());
    if let Ok(header) = toml::from_str::<Header>(&src.text[..first_table]) {
        return Ok(header.model);
    }
    toml::from_str::<Header>(src.text)
        .map(|h| h.model)
        .map_err(|e| src.toml_error(&e))
}

/// Second pass: the whole file read as a scene of model `S`.
pub(super) fn parse_as<S: Scene>(src: &Source<'_>, name: &str) -> Result<Setup<S>, Error> {
    let file: SceneFile<S::Parameters, S::Initial> = match src.table {
        Some(table) => SceneFile::deserialize(toml::de::Deserializer::from(table.clone())),
        None => toml::from_str(src.text),
    }
    .map_err(|e| src.toml_error(&e))?;
    let initial = file
        .initial
        .ok_or_else(|| src.error(format!("missing {} (the initial state)", S::INITIAL)))?;
    if let Some(split) = file.run.split.as_ref().filter(|_| S::MODEL != "n-body") {
        return Err(src.error_at(
            split.span(),
            format!(
                "run.split is for n-body scenes with one dominant body, and this scene's model is {}",
                S::MODEL
            ),
        ));
    }
    if let Some(escape) = file.run.escape_distance.as_ref().filter(|_| S::MODEL != "n-body") {
        return Err(src.error_at(
            escape.span(),
            format!(
                "run.escape_distance is for n-body scenes (a body that gets that far from the centre of mass ends \
                 the run), and this scene's model is {}",
                S::MODEL
            ),
        ));
    }
    let (model, y0) = S::build(file.parameters, initial, src)?;
    let run = file.run.check(src)?;
    Ok(Setup {
        name: name.to_string(),
        origin: src.origin.to_string(),
        description: file.description,
        model,
        y0,
        run,
        units: file.units,
    })
}
