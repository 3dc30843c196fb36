//! What `stormer merge` checks in a partial table before using it: every index in range,
//! every figure finite and non-negative, and which field differs when two parts are not
//! of one study. A part is a file a user can edit or damage, so nothing in it is trusted.

use super::{Control, Part, Row, StudyId};

/// The first thing wrong in `part`, as `field: reason` (`study.jobs[3].method: 7 is out
/// of range, the study has 2 methods`).
pub fn check(part: &Part) -> Result<(), String> {
    let study = &part.study;
    let (i, n) = part.shard;
    if n == 0 || !(1..=n).contains(&i) {
        return Err(format!("shard: [{i}, {n}] is not the I-th of N parts (1 <= I <= N)"));
    }
    finite("study.t0", study.t0)?;
    finite("study.t_end", study.t_end)?;
    if study.methods.is_empty() {
        return Err("study.methods: the study has no methods".into());
    }
    for (k, m) in study.methods.iter().enumerate() {
        if m.label.trim().is_empty() {
            return Err(format!("study.methods[{k}].label: empty"));
        }
        if let Some(t) = &m.transform {
            super::transform::named(t).map_err(|why| format!("study.methods[{k}].transform: {why}"))?;
        }
    }
    for (j, job) in study.jobs.iter().enumerate() {
        if job.method >= study.methods.len() {
            return Err(format!(
                "study.jobs[{j}].method: {} is out of range, the study has {} methods",
                job.method,
                study.methods.len()
            ));
        }
        let field = format!("study.jobs[{j}].control");
        match job.control {
            Control::Dt(h) => positive(&format!("{field}.dt"), h)?,
            Control::Tolerance(tol) => positive(&format!("{field}.tolerance"), tol)?,
            Control::Steps(0) => return Err(format!("{field}.steps: must be >= 1, got 0")),
            Control::Steps(_) => {}
        }
    }
    match (study.truth.as_str(), &part.reference) {
        ("exact", _) => {}
        ("reference", Some(r)) => non_negative("reference.uncertainty", Some(r.uncertainty))?,
        ("reference", None) => {
            return Err("reference: missing, and study.truth says errors are measured against one".into())
        }
        (other, _) => return Err(format!("study.truth: '{other}', expected 'exact' or 'reference'")),
    }
    for (k, row) in part.rows.iter().enumerate() {
        check_row(&format!("rows[{k}]"), row, study)?;
    }
    Ok(())
}

fn check_row(field: &str, row: &Row, study: &StudyId) -> Result<(), String> {
    if row.job >= study.jobs.len() {
        return Err(format!(
            "{field}.job: {} is out of range, the study has {} jobs",
            row.job,
            study.jobs.len()
        ));
    }
    non_negative(&format!("{field}.seconds"), row.seconds)?;
    non_negative(&format!("{field}.error"), row.error)?;
    non_negative(&format!("{field}.energy_error"), row.energy_error)?;
    non_negative(&format!("{field}.floor"), Some(row.floor))?;
    non_negative(&format!("{field}.scale"), row.scale)
}

fn finite(field: &str, x: f64) -> Result<(), String> {
    if x.is_finite() {
        Ok(())
    } else {
        Err(format!("{field}: must be a finite number, got {x}"))
    }
}

fn positive(field: &str, x: f64) -> Result<(), String> {
    if x.is_finite() && x > 0.0 {
        Ok(())
    } else {
        Err(format!("{field}: must be a finite number > 0, got {x}"))
    }
}

fn non_negative(field: &str, x: Option<f64>) -> Result<(), String> {
    match x {
        Some(x) if !(x.is_finite() && x >= 0.0) => Err(format!("{field}: must be a finite number >= 0, got {x}")),
        _ => Ok(()),
    }
}

/// The first field of the study that differs between `a` and `b` (`None`: the same study).
pub fn differing_field(a: &StudyId, b: &StudyId) -> Option<&'static str> {
    let same = [
        ("kind", a.kind == b.kind),
        ("scene", a.scene == b.scene),
        ("scene_hash (the scene file's text)", a.scene_hash == b.scene_hash),
        ("t0", a.t0.to_bits() == b.t0.to_bits()),
        ("t_end", a.t_end.to_bits() == b.t_end.to_bits()),
        ("methods", a.methods == b.methods),
        ("jobs (the step sizes, tolerances or step counts)", a.jobs == b.jobs),
        ("truth", a.truth == b.truth),
        ("energy", a.energy == b.energy),
    ];
    same.into_iter().find(|(_, same)| !same).map(|(field, _)| field)
}
