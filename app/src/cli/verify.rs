//! `stormer verify METHOD|FILE`: for a Butcher tableau, flags, row sums, every order
//! condition with its residual and the highest order the coefficients reach; for a
//! splitting or composition, its order conditions by class (`verify_splitting`); for both,
//! the numerical checks of `stormer::verify` (`verify_checks`). The exit is non-zero when
//! what it measures contradicts the method's data: its declared order, or the symmetry
//! derived from its coefficients.

use super::output::{print, yes_no};
use super::verify_checks::{self, JsonChecks};
use super::{verify_splitting, TextFormat};
use std::fmt::Write as _;
use stormer::method::{Splitting, Tableau};
use stormer::verify;
use stormer::verify::conditions::{achieved_order, DEFAULT_TOLERANCE, MAX_ORDER};
use stormer::{Error, Method};

/// What `verify` reports about a tableau.
struct Report {
    tableau: Tableau,
    source: String,
    checks: verify::Report,
    row_sum_residual: f64,
    /// Orders checked for exactness: `min(order + 1, MAX_ORDER)`.
    limit: usize,
    achieved: usize,
    achieved_embedded: Option<(usize, usize)>,
}

impl Report {
    fn new(tableau: Tableau, source: String, checks: verify::Report) -> Self {
        let s = tableau.stages();
        let row_sum_residual = tableau
            .c()
            .iter()
            .zip(tableau.a().chunks(s.max(1)))
            .map(|(c, row)| (c - row.iter().sum::<f64>()).abs())
            .fold(0.0f64, f64::max);
        let limit = (tableau.order() + 1).min(MAX_ORDER);
        let achieved = achieved_order(tableau.a(), tableau.b(), limit, DEFAULT_TOLERANCE);
        let achieved_embedded = tableau.b_hat().zip(tableau.embedded_order()).map(|(b_hat, q)| {
            let limit = (q + 1).min(MAX_ORDER);
            (achieved_order(tableau.a(), b_hat, limit, DEFAULT_TOLERANCE), limit)
        });
        Report {
            tableau,
            source,
            checks,
            row_sum_residual,
            limit,
            achieved,
            achieved_embedded,
        }
    }

    fn conditions_ok(&self) -> bool {
        self.tableau.conditions().iter().all(|c| c.holds())
    }

    /// What the measurements contradict: the numerical checks
    /// ([`verify_checks::contradictions`]), failing order conditions, an achieved order
    /// below the declared one, and the symplecticity condition against the measured defect.
    fn contradictions(&self) -> Vec<String> {
        let t = &self.tableau;
        let mut found = verify_checks::contradictions(&self.checks, t.order(), t.flags().symmetric);
        if !self.conditions_ok() {
            found.push("order conditions fail".into());
        }
        if self.achieved < t.order() {
            found.push(format!(
                "the coefficients reach order {}, not the declared {}",
                self.achieved,
                t.order()
            ));
        }
        if t.flags().symplectic != self.checks.symplectic.holds {
            found.push(format!(
                "the symplecticity condition says {}, the measured defect says {}",
                yes_no(t.flags().symplectic),
                yes_no(self.checks.symplectic.holds)
            ));
        }
        found
    }

    /// One sentence on the achieved order against the declared one.
    fn verdict(achieved: usize, declared: usize, limit: usize) -> String {
        if achieved == declared && limit > declared {
            format!("{achieved}: the order {limit} conditions fail, so the order is exactly {declared}")
        } else if achieved == declared {
            format!("{achieved} (order {MAX_ORDER} is the highest checked)")
        } else if achieved > declared {
            format!("{achieved}: the coefficients reach more than the declared order {declared}")
        } else {
            format!("{achieved}: below the declared order {declared} at tolerance {DEFAULT_TOLERANCE:e}")
        }
    }

    fn text(&self) -> String {
        let t = &self.tableau;
        let f = t.flags();
        let mut out = String::new();
        let ok = if self.conditions_ok() { "hold" } else { "FAIL" };
        let _ = writeln!(out, "{}: declared order {}, order conditions {ok}", t.name(), t.order());
        let rows = [
            ("source", self.source.clone()),
            ("family", "butcher".to_string()),
            ("stages", t.stages().to_string()),
            (
                "embedded order",
                t.embedded_order().map_or("none".into(), |q| q.to_string()),
            ),
            ("explicit", yes_no(f.explicit).into()),
            ("FSAL", yes_no(f.fsal).into()),
            ("symplectic", yes_no(f.symplectic).into()),
            ("symmetric", yes_no(f.symmetric).into()),
            (
                "row sums",
                format!(
                    "c_i = sum_j a_ij, max |c_i - sum_j a_ij| = {:.1e}",
                    self.row_sum_residual
                ),
            ),
        ];
        properties(&mut out, &rows);
        let conditions: Vec<ConditionRow<'_>> = t.conditions().iter().map(ConditionRow::tableau).collect();
        condition_table(&mut out, "order conditions", &conditions);
        let _ = writeln!(
            out,
            "achieved order {}",
            Report::verdict(self.achieved, t.order(), self.limit)
        );
        if let (Some((q, limit)), Some(declared)) = (self.achieved_embedded, t.embedded_order()) {
            let _ = writeln!(out, "achieved embedded order {}", Report::verdict(q, declared, limit));
        }
        out += &verify_checks::text(&self.checks, t.order(), f.symmetric);
        out.lines().map(|l| l.trim_end().to_string() + "\n").collect()
    }

    fn json(&self) -> JsonReport<'_> {
        let t = &self.tableau;
        let f = t.flags();
        JsonReport {
            name: t.name(),
            source: &self.source,
            family: "butcher",
            declared_order: t.order(),
            order_conditions_ok: self.conditions_ok(),
            embedded_order: t.embedded_order(),
            stages: t.stages(),
            explicit: f.explicit,
            fsal: f.fsal,
            symplectic: self.checks.symplectic.holds,
            symmetric: f.symmetric,
            row_sum_residual: self.row_sum_residual,
            conditions: t.conditions().iter().map(ConditionRow::tableau).collect(),
            achieved_order: self.achieved,
            achieved_order_checked_up_to: self.limit,
            achieved_embedded_order: self.achieved_embedded.map(|(q, _)| q),
            measured_embedded_order: self
                .checks
                .embedded_order
                .as_ref()
                .and_then(|m| m.as_ref().ok())
                .map(|m| m.order),
            measured_embedded_order_error: self
                .checks
                .embedded_order
                .as_ref()
                .and_then(|m| m.as_ref().err())
                .map(|e| e.to_string()),
            symplectic_condition: f.symplectic,
            symplectic_condition_residual: self.checks.symplectic_condition_residual,
            checks: JsonChecks::new(&self.checks),
        }
    }
}

/// `verify --format json`, keys in this order.
#[derive(serde::Serialize)]
struct JsonReport<'a> {
    name: &'a str,
    source: &'a str,
    family: &'a str,
    declared_order: usize,
    order_conditions_ok: bool,
    embedded_order: Option<usize>,
    stages: usize,
    explicit: bool,
    fsal: bool,
    /// The numerical verdict (`symplectic_defect` within its bound in every case); the
    /// algebraic one is `symplectic_condition`.
    symplectic: bool,
    symmetric: bool,
    row_sum_residual: f64,
    conditions: Vec<ConditionRow<'a>>,
    achieved_order: usize,
    achieved_order_checked_up_to: usize,
    achieved_embedded_order: Option<usize>,
    /// The embedded solution's order measured like `measured_order` (`null` without one).
    measured_embedded_order: Option<f64>,
    /// Why the embedded order could not be measured.
    measured_embedded_order_error: Option<String>,
    /// `b_i a_ij + b_j a_ji = b_i b_j` holds (the derived flag).
    symplectic_condition: bool,
    symplectic_condition_residual: Option<f64>,
    #[serde(flatten)]
    checks: JsonChecks,
}

/// One order (or consistency) condition, in the text table and in `verify --format
/// json`: a tableau's has a residual and its tolerance, a splitting's a bound.
#[derive(serde::Serialize)]
pub(super) struct ConditionRow<'a> {
    order: usize,
    condition: &'a str,
    expected: f64,
    got: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    residual: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    tolerance: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    bound: Option<f64>,
    ok: bool,
}

impl<'a> ConditionRow<'a> {
    fn tableau(c: &'a stormer::verify::conditions::Condition) -> Self {
        ConditionRow {
            order: c.order,
            condition: &c.text,
            expected: c.expected,
            got: c.got,
            residual: Some(c.residual),
            tolerance: Some(c.tolerance),
            bound: None,
            ok: c.holds(),
        }
    }

    pub(super) fn splitting(c: &'a stormer::verify::conditions::SplitCondition) -> Self {
        ConditionRow {
            order: c.order,
            condition: &c.text,
            expected: c.expected,
            got: c.value,
            residual: Some(c.residual()),
            tolerance: None,
            bound: Some(c.bound),
            ok: c.holds(),
        }
    }
}

/// The `  key             value` lines under a report's first line.
pub(super) fn properties(out: &mut String, rows: &[(&str, String)]) {
    for (key, value) in rows {
        let _ = writeln!(out, "  {key:<15} {value}");
    }
}

/// The table of conditions: their residuals, and their bounds when they have them (a
/// splitting's or composition's).
pub(super) fn condition_table(out: &mut String, title: &str, conditions: &[ConditionRow<'_>]) {
    let _ = writeln!(out, "{title} ({}):", conditions.len());
    let width = conditions.iter().map(|c| c.condition.len()).max().unwrap_or(0).max(9);
    let bounds = conditions.iter().any(|c| c.bound.is_some());
    let _ = writeln!(
        out,
        "  {:<5}  {:<width$}  {:<22}  {:<24}  {:<9}{}",
        "order",
        "condition",
        "expected",
        "got",
        "residual",
        if bounds { "  bound    " } else { "" }
    );
    for c in conditions {
        let bound = c.bound.map(|b| format!("  {b:<9.1e}")).unwrap_or_default();
        let _ = writeln!(
            out,
            "  {:<5}  {:<width$}  {:<22}  {:<24}  {:<9.1e}{bound}  {}",
            c.order,
            c.condition,
            format!("{:?}", c.expected),
            format!("{:?}", c.got),
            c.residual.unwrap_or(f64::NAN),
            if c.ok { "ok" } else { "FAILS" }
        );
    }
}

/// A report, and what its measurements contradict among the method's declarations.
type Outcome = (String, Vec<String>);

/// The report of a splitting or composition: its order conditions and the checks.
fn splitting_report(method: Splitting, source: String, scheme: &Method, format: TextFormat) -> anyhow::Result<Outcome> {
    let report = verify_splitting::Report {
        checks: verify::report(scheme)?,
        method,
        source,
    };
    let text = match format {
        TextFormat::Text => report.text(),
        TextFormat::Json => serde_json::to_string_pretty(&report.json())? + "\n",
    };
    Ok((text, report.contradictions()))
}

/// The report of a tableau: its order conditions and the checks.
fn tableau_report(tableau: Tableau, source: String, scheme: &Method, format: TextFormat) -> anyhow::Result<Outcome> {
    let report = Report::new(tableau, source, verify::report(scheme)?);
    let text = match format {
        TextFormat::Text => report.text(),
        TextFormat::Json => serde_json::to_string_pretty(&report.json())? + "\n",
    };
    Ok((text, report.contradictions()))
}

/// Verifies a catalog method or a method file and prints the report.
pub fn run(method: &str, format: TextFormat) -> anyhow::Result<()> {
    let verified = report(method, format)?;
    print(&verified.text)?;
    verified.verdict()
}

/// What `verify` found: the report, and what its measurements contradict among the
/// method's declarations.
pub struct Verified {
    /// The report as text or JSON.
    pub text: String,
    /// The contradictions (none for a sound method).
    pub contradictions: Vec<String>,
    /// The method as the verdict names it.
    name: String,
}

impl Verified {
    /// `Err` naming the contradictions, when there are any.
    pub fn verdict(&self) -> anyhow::Result<()> {
        if self.contradictions.is_empty() {
            return Ok(());
        }
        Err(anyhow::anyhow!(
            "{}: the checks disagree with the method's data: {}",
            self.name,
            self.contradictions.join("; ")
        ))
    }
}

/// The report on a catalog method or a method file (`method` as `--method` names it).
pub fn report(method: &str, format: TextFormat) -> anyhow::Result<Verified> {
    let choice = super::choice::resolve(method, None)?;
    // what was read from a file (a path, or a bare name the catalog does not know)
    let from_file = matches!(choice, Method::RuntimeTableau(_) | Method::RuntimeSplitting(_))
        && stormer::catalog::normalize(method) != "theta";
    let source = if from_file {
        method.to_string()
    } else if stormer::catalog::normalize(method) == "theta" {
        "the theta method (alpha = 1/2)".to_string()
    } else {
        "catalog".to_string()
    };
    let mut verified = report_on(&choice, source, format)?;
    if from_file {
        verified.name = format!("{} ({method})", choice.name());
    }
    Ok(verified)
}

/// The report on a method already built, read from `source` (a file, "catalog", or where
/// a method built in Python came from).
pub fn report_on(choice: &Method, source: String, format: TextFormat) -> anyhow::Result<Verified> {
    let (text, contradictions) = match choice {
        Method::Splitting(d) => splitting_report(Splitting::from_data(d)?, source, choice, format)?,
        Method::RuntimeSplitting(s) => splitting_report(s.clone(), source, choice, format)?,
        Method::Tableau(d) => tableau_report(Tableau::from_data(d)?, source, choice, format)?,
        Method::RuntimeTableau(t) => tableau_report(t.clone(), source, choice, format)?,
        Method::Particle(_) | Method::Relativistic(_) => {
            return Err(Error::Unsupported {
                name: choice.name().into(),
                reason: "it is a charged-particle stepper, not catalog data: `stormer verify` checks tableaus, \
                         splittings and compositions (run it on a charged-particle scene with `stormer run`; \
                         docs/charged-particles.md gives its properties)"
                    .into(),
            }
            .into())
        }
    };
    Ok(Verified {
        text,
        contradictions,
        name: choice.name().to_string(),
    })
}
