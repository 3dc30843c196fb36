//! Method files in the catalog's TOML format, shared by every family: one method at top
//! level, or a `[[method]]` array whose entries of the wanted family are read.

use super::MethodInfo;
use crate::text::{one_line, toml_message};
use crate::Error;
use serde::de::DeserializeOwned;

/// The keys of the catalog that describe any method (where it comes from, how it was
/// checked) and are accepted and ignored in a method file.
const DESCRIPTIVE: &[&str] = &[
    "aliases",
    "reference",
    "source_repo",
    "source_path",
    "source_commit",
    "precision",
    "notes",
    "closed_form",
    "checked_ok",
    "checked",
];

/// The entries of `text` that `wanted(family)` keeps (`family` is `None` when an entry
/// does not say), each deserialized as `F` once its descriptive keys ([`DESCRIPTIVE`] and
/// the family's own, `descriptive`) are removed, and converted by `convert`; errors name
/// `origin` and the entry's position.
pub(super) fn read_entries<F, M>(
    text: &str,
    origin: &str,
    wanted: impl Fn(Option<&str>) -> bool,
    descriptive: &[&str],
    convert: impl Fn(F) -> Result<M, Error>,
) -> Result<Vec<M>, Error>
where
    F: DeserializeOwned,
{
    let fail = |reason: String| Error::InvalidMethod {
        name: origin.to_string(),
        reason,
    };
    let value: toml::Table = text.parse().map_err(|e| fail(toml_message(&e, text)))?;
    let (entries, headers): (Vec<toml::Value>, Vec<usize>) = match value.get("method") {
        Some(toml::Value::Array(list)) => {
            // the lines of the `[[method]]` headers, for errors (an inline array has none)
            let mut headers: Vec<usize> = text
                .lines()
                .enumerate()
                .filter(|(_, l)| l.trim_start().starts_with("[[method]]"))
                .map(|(i, _)| i + 1)
                .collect();
            if headers.len() != list.len() {
                headers.clear();
            }
            (list.clone(), headers)
        }
        Some(_) => return Err(fail("`method` must be an array of tables ([[method]])".into())),
        None => {
            // one method at top level: read from the text, so that errors carry their line,
            // unless the error is only a descriptive key, which the cleaned read drops
            match toml::from_str::<F>(text) {
                Ok(file) => return Ok(vec![convert(file)?]),
                Err(e)
                    if !named_key(e.message())
                        .is_some_and(|k| DESCRIPTIVE.iter().chain(descriptive).any(|d| *d == k)) =>
                {
                    return Err(fail(toml_message(&e, text)));
                }
                Err(_) => (vec![toml::Value::Table(value)], Vec::new()),
            }
        }
    };
    let top_level = headers.is_empty();
    entries
        .into_iter()
        .enumerate()
        .filter(|(_, m)| wanted(m.get("family").and_then(|f| f.as_str())))
        .map(|(i, mut entry)| {
            if let toml::Value::Table(keys) = &mut entry {
                keys.retain(|key, _| !DESCRIPTIVE.iter().chain(descriptive).any(|d| *d == key));
            }
            let file: F = entry.try_into().map_err(|e: toml::de::Error| {
                let message = one_line(e.message());
                if top_level {
                    // the key the message names, found in the text: errors carry their line
                    let line = named_key(&message).and_then(|key| line_of_key(text, key));
                    fail(line.map_or(message.clone(), |l| format!("line {l}: {message}")))
                } else {
                    let at = headers.get(i).map_or_else(String::new, |l| format!(" (line {l})"));
                    fail(format!("method {}{at}: {message}", i + 1))
                }
            })?;
            convert(file)
        })
        .collect()
}

/// The key a deserialization message names (`unknown field `x``).
fn named_key(message: &str) -> Option<&str> {
    ["unknown field `"]
        .iter()
        .find_map(|lead| message.split_once(lead))
        .and_then(|(_, rest)| rest.split_once('`'))
        .map(|(key, _)| key)
}

/// The first line (from 1) that assigns `key` at the start of a line.
fn line_of_key(text: &str, key: &str) -> Option<usize> {
    text.lines()
        .position(|l| {
            l.trim_start()
                .strip_prefix(key)
                .is_some_and(|rest| rest.trim_start().starts_with('='))
        })
        .map(|i| i + 1)
}

/// What a file states of a method (its stages and the flags `explicit`, `fsal`,
/// `symplectic`, `symmetric`, when given) must be what the coefficients give (`info`).
pub(super) fn check_declared(stages: Option<usize>, flags: [Option<bool>; 4], info: &MethodInfo) -> Result<(), String> {
    let derived = info.flags;
    let derived = [derived.explicit, derived.fsal, derived.symplectic, derived.symmetric];
    agree("stages", stages, info.stages)?;
    for ((key, said), derived) in ["explicit", "fsal", "symplectic", "symmetric"]
        .iter()
        .zip(flags)
        .zip(derived)
    {
        agree(key, said, derived)?;
    }
    Ok(())
}

/// A count or flag a file states (`declared`) must be what the coefficients give.
fn agree<T: PartialEq + core::fmt::Display>(key: &str, declared: Option<T>, derived: T) -> Result<(), String> {
    match declared {
        Some(said) if said != derived => Err(format!(
            "the file declares {key} = {said} but the coefficients give {derived}"
        )),
        _ => Ok(()),
    }
}

/// The one method of `all`, or an error saying how many `what` the file holds.
pub(super) fn exactly_one<M>(mut all: Vec<M>, origin: &str, what: &str) -> Result<M, Error> {
    match all.len() {
        1 => Ok(all.remove(0)),
        n => Err(Error::InvalidMethod {
            name: origin.to_string(),
            reason: format!("the file holds {n} {what}; give a file with one"),
        }),
    }
}

/// The text of the method file at `path` (read through the bound of [`crate::text`])
/// and its name for messages.
pub(super) fn read_file(path: &std::path::Path) -> Result<(String, String), Error> {
    let origin = path.display().to_string();
    let text = crate::text::read_text(path).map_err(|reason| Error::InvalidMethod {
        name: origin.clone(),
        reason,
    })?;
    Ok((text, origin))
}
