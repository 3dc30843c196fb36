//! Method files in the catalog's TOML format, shared by every family: one method at top
//! level, or a `[[method]]` array whose entries of the wanted family are read.

use super::MethodInfo;
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
    let value: toml::Table = text.parse().map_err(|e: toml::de::Error| fail(e.to_string()))?;
    let entries = match value.get("method") {
        Some(toml::Value::Array(list)) => list
            .iter()
            .filter(|m| wanted(m.get("family").and_then(|f| f.as_str())))
            .cloned()
            .collect(),
        Some(_) => return Err(fail("`method` must be an array of tables ([[method]])".into())),
        None => vec![toml::Value::Table(value)],
    };
    entries
        .into_iter()
        .enumerate()
        .map(|(i, mut entry)| {
            if let toml::Value::Table(keys) = &mut entry {
                keys.retain(|key, _| !DESCRIPTIVE.iter().chain(descriptive).any(|d| *d == key));
            }
            let file: F = entry
                .try_into()
                .map_err(|e: toml::de::Error| fail(format!("method {}: {}", i + 1, e.to_string().trim())))?;
            convert(file)
        })
        .collect()
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

/// The text of the method file at `path` and its name for messages.
pub(super) fn read_file(path: &std::path::Path) -> Result<(String, String), Error> {
    let origin = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| Error::InvalidMethod {
        name: origin.clone(),
        reason: format!("cannot read the file: {e}"),
    })?;
    Ok((text, origin))
}
