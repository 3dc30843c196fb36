//! An ensemble's table, whole or one shard of it (the JSON `ensemble --shard` writes and
//! `merge` reads), and what `merge` checks in it before using it: a part is a file a user
//! can edit or damage, so nothing in it is trusted.

use super::vary::{member_count, member_values, Axis};
use super::Sharded;
use serde::{Deserialize, Serialize};

/// The version of the partial-table format of ensembles.
pub const FORMAT: &str = "stormer-ensemble/1";

/// What makes two parts belong to the same ensemble.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EnsembleId {
    /// The scene's name.
    pub scene: String,
    /// FNV-1a hash of the scene file's text (before any number is varied).
    pub scene_hash: String,
    /// The method's name.
    pub method: String,
    /// The fixed step size, when not the scene's.
    pub dt: Option<f64>,
    /// The end time given on the command line (`None`: each member's file's), unless
    /// the scene's stop condition ends a run before.
    pub t_end: Option<f64>,
    /// The varied numbers; the members are their grid, the first axis slowest.
    pub axes: Vec<Axis>,
    /// The names of the state's components.
    pub components: Vec<String>,
    /// The event that ends the scene's runs, if it has one (`landing`).
    pub stop: Option<String>,
    /// Whether the scene has an energy.
    pub energy: bool,
    /// The chaos indicator each member also measures (`megno`: the mean MEGNO at the end,
    /// `lyapunov`, `fli`), if any.
    #[serde(default)]
    pub indicator: Option<String>,
    /// The column drawn against the varied numbers.
    pub show: String,
    /// Its axis label, with the unit the scene file names.
    pub show_label: String,
}

impl EnsembleId {
    /// The stem of the output files: `ensemble-free-kick-alpha+spin`.
    pub fn prefix(&self) -> String {
        let keys: Vec<String> = self
            .axes
            .iter()
            .map(|a| super::file_safe(a.key.rsplit('.').next().unwrap_or(&a.key)))
            .collect();
        format!("ensemble-{}-{}", super::file_safe(&self.scene), keys.join("+"))
    }

    /// The numeric columns a member has, in the table's order after the varied numbers:
    /// `t`, the components, `energy_error` (scenes with an energy), the indicator (with
    /// `--indicator`), `steps`, `evaluations`.
    pub fn columns(&self) -> Vec<String> {
        let mut columns = vec!["t".to_string()];
        columns.extend(self.components.iter().cloned());
        if self.energy {
            columns.push("energy_error".into());
        }
        columns.extend(self.indicator.iter().cloned());
        columns.extend(["steps".into(), "evaluations".into()]);
        columns
    }
}

/// One member's run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Member {
    /// Its index in the grid.
    pub member: usize,
    /// The varied numbers' values, in the order of the axes.
    pub values: Vec<f64>,
    /// Where the run ended: the stop event's time, or the end time.
    pub t: Option<f64>,
    /// The state there (empty when the run failed).
    pub state: Vec<f64>,
    /// Whether the scene's stop condition ended the run (the ball landed).
    pub stopped: bool,
    /// max |E - E0|/|E0| (|E - E0| when E0 = 0) over the records, for scenes with an
    /// energy; `None` also when it is not finite.
    pub energy_error: Option<f64>,
    /// The indicator at the end of the run (with `--indicator`).
    #[serde(default)]
    pub indicator: Option<f64>,
    /// Accepted steps.
    pub steps: u64,
    /// Right-hand-side (force) evaluations.
    pub evaluations: u64,
    /// Why the run stopped early (it diverged, took too many steps).
    pub failure: Option<String>,
}

impl Member {
    /// The value of a column of [`EnsembleId::columns`] (`None`: failed, or no such column).
    pub fn column(&self, id: &EnsembleId, name: &str) -> Option<f64> {
        if self.failure.is_some() {
            return None;
        }
        match name {
            "t" => self.t,
            "energy_error" => self.energy_error,
            _ if id.indicator.as_deref() == Some(name) => self.indicator,
            "steps" => Some(self.steps as f64),
            "evaluations" => Some(self.evaluations as f64),
            _ => {
                let k = id.components.iter().position(|c| c == name)?;
                self.state.get(k).copied()
            }
        }
    }
}

/// An ensemble's table, whole or one shard of it.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EnsemblePart {
    /// [`FORMAT`].
    pub format: String,
    /// The ensemble.
    pub ensemble: EnsembleId,
    /// `(I, N)`: the I-th of N parts.
    pub shard: (usize, usize),
    /// The rows of this part, by member index.
    pub rows: Vec<Member>,
}

impl Sharded for EnsemblePart {
    const ITEMS: &'static str = "members";
    fn shard(&self) -> (usize, usize) {
        self.shard
    }
    fn size(&self) -> usize {
        member_count(&self.ensemble.axes).unwrap_or(0)
    }
    type Row = Member;
    fn rows(&self) -> &[Member] {
        &self.rows
    }
    fn index(row: &Member) -> usize {
        row.member
    }
    fn into_whole(self, rows: Vec<Member>) -> Self {
        EnsemblePart {
            rows,
            shard: (1, 1),
            ..self
        }
    }
    fn differing_field(&self, other: &Self) -> Option<&'static str> {
        let (a, b) = (&self.ensemble, &other.ensemble);
        let same = [
            ("scene", a.scene == b.scene),
            ("scene_hash (the scene file's text)", a.scene_hash == b.scene_hash),
            ("method", a.method == b.method),
            ("dt", a.dt.map(f64::to_bits) == b.dt.map(f64::to_bits)),
            ("t_end", a.t_end.map(f64::to_bits) == b.t_end.map(f64::to_bits)),
            ("axes (the varied numbers and their ranges)", a.axes == b.axes),
            ("components", a.components == b.components),
            ("stop", a.stop == b.stop),
            ("energy", a.energy == b.energy),
            (
                "show (the column drawn)",
                a.show == b.show && a.show_label == b.show_label,
            ),
        ];
        same.into_iter().find(|(_, same)| !same).map(|(field, _)| field)
    }
}

/// The first thing wrong in `part`, as `field: reason`.
pub fn check(part: &EnsemblePart) -> Result<(), String> {
    let id = &part.ensemble;
    let (i, n) = part.shard;
    if n == 0 || !(1..=n).contains(&i) {
        return Err(format!("shard: [{i}, {n}] is not the I-th of N parts (1 <= I <= N)"));
    }
    if let Some(t) = id.t_end.filter(|t| !t.is_finite()) {
        return Err(format!("ensemble.t_end: must be a finite number, got {t}"));
    }
    if let Some(h) = id.dt.filter(|h| !(h.is_finite() && *h > 0.0)) {
        return Err(format!("ensemble.dt: must be a finite number > 0, got {h}"));
    }
    if id.axes.is_empty() {
        return Err("ensemble.axes: the ensemble varies no number".into());
    }
    for (k, a) in id.axes.iter().enumerate() {
        let field = format!("ensemble.axes[{k}]");
        if a.key.trim().is_empty() {
            return Err(format!("{field}.key: empty"));
        }
        if !(a.start.is_finite() && a.end.is_finite() && a.count >= 1) {
            return Err(format!(
                "{field}: {:?}:{:?}:{} is not a range of finite numbers with COUNT >= 1",
                a.start, a.end, a.count
            ));
        }
    }
    let size = member_count(&id.axes).map_err(|e| format!("ensemble.axes: {e}"))?;
    if !id.columns().contains(&id.show) {
        return Err(format!("ensemble.show: '{}' is not a column of the table", id.show));
    }
    for (k, row) in part.rows.iter().enumerate() {
        let field = format!("rows[{k}]");
        if row.member >= size {
            return Err(format!(
                "{field}.member: {} is out of range, the ensemble has {size} members",
                row.member
            ));
        }
        let values = member_values(&id.axes, row.member);
        if values.iter().zip(&row.values).any(|(a, b)| a.to_bits() != b.to_bits()) || values.len() != row.values.len() {
            return Err(format!(
                "{field}.values: {:?} are not those of member {} ({values:?})",
                row.values, row.member
            ));
        }
        let finished = row.failure.is_none();
        if finished && row.state.len() != id.components.len() {
            return Err(format!(
                "{field}.state: {} numbers, the scene's state has {}",
                row.state.len(),
                id.components.len()
            ));
        }
        if let Some(x) = row.t.iter().chain(&row.state).find(|x| !x.is_finite()) {
            return Err(format!("{field}: {x} is not a finite number"));
        }
        if let Some(e) = row.energy_error.filter(|e| !(e.is_finite() && *e >= 0.0)) {
            return Err(format!("{field}.energy_error: must be a finite number >= 0, got {e}"));
        }
        if let Some(x) = row.indicator.filter(|x| !x.is_finite()) {
            return Err(format!("{field}.indicator: must be a finite number, got {x}"));
        }
    }
    Ok(())
}
