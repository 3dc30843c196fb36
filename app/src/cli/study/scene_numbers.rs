//! The numbers written in a scene file, addressed by their keys (`initial.alpha`,
//! `bodies.1.mass`), and the file's text with some of them replaced: how `ensemble` varies
//! any value of any scene without code of its own for the scene. The text is edited where
//! the number is written, so the member's file keeps its lines and comments, and an error
//! in it names the line of the user's file.

use core::ops::Range;
use stormer::Error;
use toml::de::{DeTable, DeValue};
use toml::Spanned;

/// One number of a scene file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Entry {
    /// Its key, the tables' and arrays' names joined by dots (`parameters.spin`,
    /// `bodies.0.mass`, `parameters.E.2`).
    pub key: String,
    /// Where it is written in the text.
    pub span: Range<usize>,
    /// Written as an integer (`every = 1`): it is replaced by integers only.
    pub integer: bool,
}

/// The numbers of a scene file, in the order they are written.
#[derive(Debug, Clone)]
pub struct Numbers {
    entries: Vec<Entry>,
}

impl Numbers {
    /// The numbers of `text` (a scene file already read without error).
    pub fn of(text: &str) -> Result<Self, Error> {
        let table = DeTable::parse(text).map_err(|e| Error::invalid("--vary", format!("the scene file: {e}")))?;
        let mut entries = Vec::new();
        for (key, value) in table.get_ref().iter() {
            collect(key.get_ref(), value, &mut entries);
        }
        entries.sort_by_key(|e| e.span.start);
        Ok(Numbers { entries })
    }

    /// The number `name` addresses: its whole key, or the last parts of it when they name
    /// one number only (`alpha` for `initial.alpha`, `1.mass` for `bodies.1.mass`).
    pub fn find(&self, name: &str) -> Result<&Entry, Error> {
        let matches = |e: &&Entry| e.key == name || e.key.ends_with(&format!(".{name}"));
        let found: Vec<&Entry> = self.entries.iter().filter(matches).collect();
        match found.as_slice() {
            [one] => Ok(one),
            [] => Err(Error::invalid("--vary", self.unknown(name))),
            many => {
                let keys: Vec<&str> = many.iter().take(6).map(|e| e.key.as_str()).collect();
                let more = if many.len() > keys.len() { ", ..." } else { "" };
                Err(Error::invalid(
                    "--vary",
                    format!(
                        "'{name}' names {} numbers of the scene file ({}{more}); give the whole key",
                        many.len(),
                        keys.join(", ")
                    ),
                ))
            }
        }
    }

    /// The error for a name that addresses no number: the nearest key, and the keys.
    fn unknown(&self, name: &str) -> String {
        let last = |key: &str| key.rsplit('.').next().unwrap_or(key).to_string();
        let nearest = self
            .entries
            .iter()
            .map(|e| {
                let distance =
                    strsim::damerau_levenshtein(name, &e.key).min(strsim::damerau_levenshtein(name, &last(&e.key)));
                (distance, e)
            })
            .filter(|(d, _)| *d <= 2)
            .min_by_key(|(d, _)| *d)
            .map_or_else(String::new, |(_, e)| format!("did you mean '{}'? ", e.key));
        let keys: Vec<&str> = self.entries.iter().take(12).map(|e| e.key.as_str()).collect();
        let more = if self.entries.len() > keys.len() { ", ..." } else { "" };
        format!(
            "unknown key '{name}': {nearest}the scene file's numbers are {}{more}",
            keys.join(", ")
        )
    }
}

/// The entries of `value`, written under `key`.
fn collect(key: &str, value: &Spanned<DeValue<'_>>, out: &mut Vec<Entry>) {
    let span = value.span();
    match value.get_ref() {
        DeValue::Integer(_) => out.push(Entry {
            key: key.to_string(),
            span,
            integer: true,
        }),
        DeValue::Float(_) => out.push(Entry {
            key: key.to_string(),
            span,
            integer: false,
        }),
        DeValue::Table(table) => {
            for (k, v) in table.iter() {
                collect(&format!("{key}.{}", k.get_ref()), v, out);
            }
        }
        DeValue::Array(items) => {
            for (i, v) in items.iter().enumerate() {
                collect(&format!("{key}.{i}"), v, out);
            }
        }
        DeValue::String(_) | DeValue::Boolean(_) | DeValue::Datetime(_) => {}
    }
}

/// How `x` is written in place of `entry`'s number: Rust's shortest form that reads back
/// to the same `f64` (a valid TOML float), or an integer for an integer entry.
fn written(entry: &Entry, x: f64) -> Result<String, Error> {
    if !entry.integer {
        return Ok(format!("{x:?}"));
    }
    // the largest f64 below 2^63: every integer-valued f64 up to it converts exactly
    if x.fract() == 0.0 && x.abs() < 9.2e18 {
        Ok(format!("{}", x as i64))
    } else {
        Err(Error::invalid(
            "--vary",
            format!(
                "{} is written as an integer in the scene file; {x:?} is not one",
                entry.key
            ),
        ))
    }
}

/// `text` with the number of each entry replaced by its value.
pub fn substitute(text: &str, values: &[(&Entry, f64)]) -> Result<String, Error> {
    let mut edits: Vec<(Range<usize>, String)> = values
        .iter()
        .map(|(entry, x)| Ok((entry.span.clone(), written(entry, *x)?)))
        .collect::<Result<_, Error>>()?;
    edits.sort_by_key(|(span, _)| span.start);
    let mut out = String::with_capacity(text.len() + 16 * edits.len());
    let mut at = 0;
    for (span, number) in edits {
        out.push_str(&text[at..span.start]);
        out.push_str(&number);
        at = span.end;
    }
    out.push_str(&text[at..]);
    Ok(out)
}

/// The values written as [`substitute`] writes them into the text (`None` if one cannot
/// be), for [`replaced`].
pub fn written_values(values: &[(&Entry, f64)]) -> Option<Vec<String>> {
    values.iter().map(|(entry, x)| written(entry, *x).ok()).collect()
}

/// `table` (a scene file read by `toml::de::DeTable::parse`) with each entry's number
/// replaced by its value as `written` ([`written_values`]): the table [`substitute`]'s text
/// would read into. `None` where an entry's key does not lead to a number in it (the
/// caller then reads the substituted text, for its errors).
pub fn replaced<'i>(
    table: &toml::Spanned<toml::de::DeTable<'i>>,
    values: &[(&Entry, f64)],
    written: &'i [String],
) -> Option<toml::Spanned<toml::de::DeTable<'i>>> {
    use toml::de::DeValue;
    let mut table = table.clone();
    for ((entry, _), number) in values.iter().zip(written) {
        let number = DeValue::parse(number).ok()?.into_inner();
        let mut keys = entry.key.split('.');
        let mut at = table.get_mut().get_mut(keys.next()?)?.get_mut();
        for key in keys {
            at = match at {
                DeValue::Table(t) => t.get_mut(key)?.get_mut(),
                DeValue::Array(a) => a.get_mut(key.parse::<usize>().ok()?)?.get_mut(),
                _ => return None,
            };
        }
        if !matches!(at, DeValue::Float(_) | DeValue::Integer(_)) {
            return None;
        }
        if !matches!(number, DeValue::Float(_) | DeValue::Integer(_)) {
            return None;
        }
        *at = number;
    }
    Some(table)
}

#[cfg(test)]
mod tests {
    use super::*;

    const SCENE: &str = "model = \"m\" # x = 1\n[parameters]\nspin = 12.5   # rad/s\nE = [0.0, 1, 2e3]\n\
                         [initial]\nalpha = 30.0\n[[bodies]]\nmass = 1.0\n[[bodies]]\nmass = 2.0\n[run]\nevery = 1\n";

    #[test]
    fn a_table_with_numbers_replaced_reads_as_the_substituted_text() {
        use serde::Deserialize;
        let numbers = Numbers::of(SCENE).unwrap();
        let value =
            |table: toml::Spanned<DeTable<'_>>| toml::Value::deserialize(toml::de::Deserializer::from(table)).unwrap();
        let table = DeTable::parse(SCENE).unwrap();
        // every entry, floats and the integer, arrays and arrays of tables
        let values: Vec<(&Entry, f64)> = numbers
            .entries
            .iter()
            .zip([0.25, -3.0, 7.0, 1e-9, 2.0, 5.0, 6.0, 4.0])
            .collect();
        let written = written_values(&values).unwrap();
        let in_table = replaced(&table, &values, &written).unwrap();
        let text = substitute(SCENE, &values).unwrap();
        assert_eq!(value(in_table), value(DeTable::parse(&text).unwrap()));
        // a key that leads to no number: left to the text
        let missing = Entry {
            key: "parameters.nothing".into(),
            span: 0..0,
            integer: false,
        };
        assert!(replaced(&table, &[(&missing, 1.0)], &["1.0".to_string()]).is_none());
    }

    #[test]
    fn keys_address_every_number_in_file_order() {
        let numbers = Numbers::of(SCENE).unwrap();
        let keys: Vec<&str> = numbers.entries.iter().map(|e| e.key.as_str()).collect();
        assert_eq!(
            keys,
            [
                "parameters.spin",
                "parameters.E.0",
                "parameters.E.1",
                "parameters.E.2",
                "initial.alpha",
                "bodies.0.mass",
                "bodies.1.mass",
                "run.every"
            ]
        );
        assert_eq!(numbers.find("alpha").unwrap().key, "initial.alpha");
        assert_eq!(numbers.find("initial.alpha").unwrap().key, "initial.alpha");
        assert_eq!(numbers.find("1.mass").unwrap().key, "bodies.1.mass");
        assert!(numbers.find("E.1").unwrap().integer);
        let ambiguous = numbers.find("mass").unwrap_err().to_string();
        assert!(
            ambiguous.contains("'mass' names 2 numbers") && ambiguous.contains("bodies.0.mass"),
            "{ambiguous}"
        );
        let unknown = numbers.find("alpah").unwrap_err().to_string();
        assert!(
            unknown.contains("unknown key 'alpah': did you mean 'initial.alpha'?"),
            "{unknown}"
        );
        // a key that is not a number is not a number to vary
        assert!(numbers.find("model").is_err() && numbers.find("lpha").is_err());
    }

    #[test]
    fn substitution_keeps_lines_and_comments() {
        let numbers = Numbers::of(SCENE).unwrap();
        let spin = numbers.find("spin").unwrap();
        let alpha = numbers.find("alpha").unwrap();
        let every = numbers.find("every").unwrap();
        let text = substitute(SCENE, &[(alpha, 11.0), (spin, -0.1), (every, 3.0)]).unwrap();
        assert_eq!(
            text,
            SCENE
                .replace("12.5", "-0.1")
                .replace("30.0", "11.0")
                .replace("every = 1", "every = 3")
        );
        assert_eq!(text.lines().count(), SCENE.lines().count());
        let refused = substitute(SCENE, &[(every, 2.5)]).unwrap_err().to_string();
        assert!(refused.contains("run.every is written as an integer"), "{refused}");
        // the shortest form that reads back to the same number
        let tiny = substitute(SCENE, &[(spin, 1e-300)]).unwrap();
        assert!(tiny.contains("spin = 1e-300   # rad/s"), "{tiny}");
    }
}
