//! A study's table, whole or one shard of it ([`Part`]): what identifies the study, its
//! work list of jobs and the measured row of each job, as `--shard` writes them (JSON) and
//! `merge` reads them.

use super::file_safe;
use super::part_check;
use super::shards::Sharded;
use serde::{Deserialize, Serialize};

/// The version of the partial-table format written by `--shard` and read by `merge`.
pub(super) const FORMAT: &str = "stormer-study/1";

/// The kind of study.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Kind {
    /// Work-precision comparison.
    Compare,
    /// Convergence scan.
    Scan,
}

/// How one job chooses its steps.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Control {
    /// Fixed step size.
    Dt(f64),
    /// Adaptive steps, rtol = atol = this.
    Tolerance(f64),
    /// This many fixed steps over the span.
    Steps(u64),
}

/// A method of the study, as resolved on the scene.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct MethodEntry {
    /// As given on the command line.
    pub given: String,
    /// Its name.
    pub label: String,
    /// Declared order.
    pub order: usize,
    /// Has an embedded error estimate (adaptive steps).
    pub embedded: bool,
    /// The time transformation it runs in (`logh`, `ttl`, `none`), when a method of the
    /// study runs in one: its fixed steps are then steps of the fictitious time `s`.
    /// Absent: the scene untransformed, as its file says (and the parts of older versions).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub transform: Option<String>,
}

impl MethodEntry {
    /// Steps in a fictitious time `s` (a time transformation other than `none`).
    pub fn transformed(&self) -> bool {
        self.transform.as_deref().is_some_and(|t| t != super::transform::NONE)
    }
}

/// One job: a method (index into [`StudyId::methods`]) and its step control.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Job {
    /// Index of the method.
    pub method: usize,
    /// Step control.
    pub control: Control,
}

/// What makes two parts belong to the same study.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StudyId {
    /// compare or scan.
    pub kind: Kind,
    /// The scene's name.
    pub scene: String,
    /// FNV-1a hash of the scene file's text.
    pub scene_hash: String,
    /// Start time.
    pub t0: f64,
    /// End time.
    pub t_end: f64,
    /// The methods.
    pub methods: Vec<MethodEntry>,
    /// The work list.
    pub jobs: Vec<Job>,
    /// What errors are measured against: `exact` or `reference`.
    pub truth: String,
    /// Whether the scene has an energy.
    pub energy: bool,
    /// The event that ends the scene's runs before the end time, if it has one
    /// (`landing`): errors are measured where it happens.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stop: Option<String>,
}

impl StudyId {
    /// The stem of the output files.
    pub fn prefix(&self) -> String {
        let scene = file_safe(&self.scene);
        match self.kind {
            Kind::Compare => format!("compare-{scene}"),
            Kind::Scan => {
                let methods: Vec<String> = self.methods.iter().map(|m| file_safe(&m.label)).collect();
                format!("scan-{scene}-{}", methods.join("+"))
            }
        }
    }
}

/// The measured outcome of one job.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Row {
    /// Index of the job in the work list.
    pub job: usize,
    /// Accepted steps.
    pub steps: u64,
    /// Rejected steps (adaptive).
    pub rejected: u64,
    /// Right-hand-side (force) evaluations, all included.
    pub evaluations: u64,
    /// Best wall time of the timing runs, seconds.
    pub seconds: Option<f64>,
    /// Timing runs made.
    pub timing_runs: u32,
    /// max |y_i - y_true_i| at the end.
    pub error: Option<f64>,
    /// max |E - E0|/|E0| (|E - E0| when E0 = 0) over the sampled records.
    pub energy_error: Option<f64>,
    /// Errors below this are the reference's or the rounding's, not the method's:
    /// `max(10 eps steps max|y|, 10 x the reference's uncertainty)`.
    pub floor: f64,
    /// The size of the solution the error measures, `max |y_true_i|` (absent from the
    /// parts of older versions): an error as large is not in the asymptotic regime.
    #[serde(default)]
    pub scale: Option<f64>,
    /// Why the run stopped early (it diverged, or took too many steps).
    pub failure: Option<String>,
}

/// The reference solution's description, as kept in a study's parts.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ReferenceInfo {
    /// How it was computed.
    pub recipe: String,
    /// An upper bound on its error (max norm).
    pub uncertainty: f64,
    /// The cache file.
    pub file: String,
}

/// A study's table, whole or one shard of it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Part {
    /// [`FORMAT`].
    pub format: String,
    /// The study.
    pub study: StudyId,
    /// `(I, N)`: the I-th of N parts.
    pub shard: (usize, usize),
    /// The reference, when errors are measured against one.
    pub reference: Option<ReferenceInfo>,
    /// The rows of this part, by job index.
    pub rows: Vec<Row>,
}

/// FNV-1a, 64 bits: a hash that stays the same across Rust versions and machines.
pub fn fnv1a(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325u64, |h, &b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    })
}

impl Sharded for Part {
    const ITEMS: &'static str = "jobs";
    fn shard(&self) -> (usize, usize) {
        self.shard
    }
    fn size(&self) -> usize {
        self.study.jobs.len()
    }
    type Row = Row;
    fn rows(&self) -> &[Row] {
        &self.rows
    }
    fn index(row: &Row) -> usize {
        row.job
    }
    fn into_whole(self, rows: Vec<Row>) -> Self {
        Part {
            rows,
            shard: (1, 1),
            ..self
        }
    }
    fn differing_field(&self, other: &Self) -> Option<&'static str> {
        part_check::differing_field(&self.study, &other.study)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a_is_the_published_function() {
        assert_eq!(fnv1a(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a(b"a"), 0xaf63_dc4c_8601_ec8c);
    }
}
