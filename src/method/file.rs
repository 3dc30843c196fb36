//! Method files in the catalog's TOML format, shared by every family: one method at top
//! level, or a `[[method]]` array whose entries of the wanted family are read.

use crate::Error;
use serde::de::DeserializeOwned;

/// The entries of `text` that `wanted(family)` keeps (`family` is `None` when an entry
/// does not say), each deserialized as `F` and converted by `convert`; errors name
/// `origin` and the entry's position.
pub(super) fn read_entries<F, M>(
    text: &str,
    origin: &str,
    wanted: impl Fn(Option<&str>) -> bool,
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
        .map(|(i, entry)| {
            let file: F = entry
                .try_into()
                .map_err(|e: toml::de::Error| fail(format!("method {}: {}", i + 1, e.to_string().trim())))?;
            convert(file)
        })
        .collect()
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
