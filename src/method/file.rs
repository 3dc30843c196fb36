//! Method files in the catalog's TOML format, shared by every family: one method at top
//! level, or a `[[method]]` array whose entries of the wanted family are read.

use crate::error::{one_line, toml_message};
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
    let value: toml::Table = text.parse().map_err(|e| fail(toml_message(&e, text)))?;
    let list = match value.get("method") {
        Some(toml::Value::Array(list)) => list,
        Some(_) => return Err(fail("`method` must be an array of tables ([[method]])".into())),
        None => {
            // one method at top level: read from the text, so that errors carry their line
            let file: F = toml::from_str(text).map_err(|e| fail(toml_message(&e, text)))?;
            return Ok(vec![convert(file)?]);
        }
    };
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
    list.iter()
        .enumerate()
        .filter(|(_, m)| wanted(m.get("family").and_then(|f| f.as_str())))
        .map(|(i, entry)| {
            let file: F = entry.clone().try_into().map_err(|e: toml::de::Error| {
                let at = headers.get(i).map_or_else(String::new, |l| format!(" (line {l})"));
                fail(format!("method {}{at}: {}", i + 1, one_line(e.message())))
            })?;
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

/// The text of the method file at `path` (read through the bound of [`crate::input`])
/// and its name for messages.
pub(super) fn read_file(path: &std::path::Path) -> Result<(String, String), Error> {
    let origin = path.display().to_string();
    let text = crate::input::read_text(path).map_err(|reason| Error::InvalidMethod {
        name: origin.clone(),
        reason,
    })?;
    Ok((text, origin))
}
