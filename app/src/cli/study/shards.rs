//! A work list run in shards: which jobs a shard runs, the parts written and read as
//! JSON, and `merge`'s joining of the parts into the whole table once it has checked
//! that they belong together.

use super::part::{Part, FORMAT};
use super::part_check;
use anyhow::{anyhow, bail, Context};
use serde::Serialize;
use std::path::{Path, PathBuf};

/// The jobs of shard `(i, n)`: every n-th job starting at `i - 1`, so that each method and
/// step size is spread over the shards.
pub fn shard_jobs(count: usize, (i, n): (usize, usize)) -> Vec<usize> {
    (i - 1..count).step_by(n).collect()
}

/// Writes `value` as JSON at `path`, creating its directory.
pub(super) fn write_json<T: Serialize>(path: &Path, value: &T) -> anyhow::Result<()> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).with_context(|| format!("cannot create {}", dir.display()))?;
    }
    let text = serde_json::to_string_pretty(value)?;
    std::fs::write(path, text + "\n").with_context(|| format!("cannot write {}", path.display()))
}

/// The text of the partial table at `path`, read through the input bound; the error names
/// the file.
pub(super) fn read_text(path: &Path) -> anyhow::Result<String> {
    stormer::text::read_text(path).map_err(|reason| anyhow!("{}: {reason}", path.display()))
}

/// A partial table from its JSON text, checked; errors name `file`.
pub(super) fn parse_part(text: &str, file: &str) -> anyhow::Result<Part> {
    let part: Part = serde_json::from_str(text)
        .map_err(|e| anyhow!("{file} is not a partial table of `compare --shard` or `scan --shard`: {e}"))?;
    if part.format != FORMAT {
        bail!("{file}: format '{}', expected '{FORMAT}'", part.format);
    }
    part_check::check(&part).map_err(|reason| anyhow!("{file}: {reason}"))?;
    Ok(part)
}

/// A partial table of a work list run with `--shard`: what `merge` needs to know that a
/// set of parts is one whole (a study's [`Part`], an ensemble's part).
pub(super) trait Sharded {
    /// What the rows are of (`jobs`, `members`).
    const ITEMS: &'static str;
    /// `(I, N)`: the I-th of N parts.
    fn shard(&self) -> (usize, usize);
    /// The size of the whole work list.
    fn size(&self) -> usize;
    /// A row of the table: one job or member's results.
    type Row: Clone;
    /// This part's rows.
    fn rows(&self) -> &[Self::Row];
    /// A row's index in the work list.
    fn index(row: &Self::Row) -> usize;
    /// This part's description with `rows` as its rows: the whole table, shard 1 of 1.
    fn into_whole(self, rows: Vec<Self::Row>) -> Self;
    /// The indices in the work list of this part's rows, in order.
    fn indices(&self) -> Vec<usize> {
        self.rows().iter().map(Self::index).collect()
    }
    /// The first field that makes `self` and `other` parts of different work lists.
    fn differing_field(&self, other: &Self) -> Option<&'static str>;
}

/// Checks that `parts` belong to one work list and hold it whole: none missing or given
/// twice, each with the rows of its shard.
fn check_parts<P: Sharded>(parts: &[(&PathBuf, P)]) -> anyhow::Result<()> {
    let (first_path, first) = parts.first().context("no partial tables given")?;
    let n = first.shard().1;
    let mut seen = std::collections::BTreeMap::<usize, &Path>::new();
    for (path, part) in parts {
        if let Some(field) = first.differing_field(part) {
            bail!(
                "{} and {} are parts of different studies: their {field} differ",
                first_path.display(),
                path.display()
            );
        }
        if part.shard().1 != n {
            bail!(
                "{} is a part of {} shards, {} of {n}",
                path.display(),
                part.shard().1,
                first_path.display()
            );
        }
        let i = part.shard().0;
        if let Some(other) = seen.insert(i, path) {
            bail!(
                "shard {i}/{n} is given twice: {} and {}",
                other.display(),
                path.display()
            );
        }
        let expected = shard_jobs(part.size(), part.shard());
        let got = part.indices();
        if got != expected {
            bail!(
                "{}: rows: their {} {} are not those of shard {i}/{n} of the study ({})",
                path.display(),
                P::ITEMS,
                list_of(&got),
                list_of(&expected)
            );
        }
    }
    // `n` comes from a file: the missing shards are listed without counting to `n`
    if seen.len() < n {
        let missing: Vec<String> = (1..=n)
            .filter(|i| !seen.contains_key(i))
            .take(5)
            .map(|i| format!("{i}/{n}"))
            .collect();
        let more = if n - seen.len() > missing.len() { ", ..." } else { "" };
        bail!(
            "shard {}{more} missing: the study of {} has {n} parts",
            missing.join(", "),
            first_path.display()
        );
    }
    Ok(())
}

/// Joins the parts of one work list (a study's, an ensemble's), checking that they belong
/// together and that none is missing or given twice.
pub(super) fn join<P: Sharded>(parts: Vec<(&PathBuf, P)>) -> anyhow::Result<P> {
    check_parts(&parts)?;
    let mut rows: Vec<P::Row> = parts.iter().flat_map(|(_, p)| p.rows().iter().cloned()).collect();
    rows.sort_by_key(P::index);
    let first = parts
        .into_iter()
        .next()
        .map(|(_, p)| p)
        .context("no partial tables given")?;
    Ok(first.into_whole(rows))
}

/// `[0, 3, 6]`, shortened after 8 entries.
fn list_of(jobs: &[usize]) -> String {
    let shown: Vec<String> = jobs.iter().take(8).map(usize::to_string).collect();
    let more = if jobs.len() > 8 { ", ..." } else { "" };
    format!("[{}{more}]", shown.join(", "))
}

#[cfg(test)]
mod tests {
    use super::super::args::parse_shard;
    use super::*;

    #[test]
    fn shards_partition_the_work_list() {
        for count in [0, 1, 5, 12] {
            for n in 1..5 {
                let mut all: Vec<usize> = (1..=n).flat_map(|i| shard_jobs(count, (i, n))).collect();
                all.sort_unstable();
                assert_eq!(all, (0..count).collect::<Vec<_>>());
            }
        }
        assert_eq!(parse_shard("2/3"), Ok((2, 3)));
        assert!(parse_shard("0/3").is_err() && parse_shard("4/3").is_err() && parse_shard("x").is_err());
    }
}
