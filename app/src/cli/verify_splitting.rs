//! `stormer verify` for a splitting or composition: flags, the word of sub-flows, every
//! order condition of its class up to its declared order with its value, residual and
//! bound, the algebraic orders by class, and the numerical checks.

use super::output::yes_no;
use super::verify::{condition_table, properties, ConditionRow};
use super::verify_checks::{self, JsonChecks};
use std::fmt::Write as _;
use stormer::method::Splitting;
use stormer::verify::conditions::splitting::Flow;
use stormer::verify::conditions::OrderClass;
use stormer::verify::Report as Checks;

/// What `verify` reports about a splitting or composition.
pub struct Report {
    pub method: Splitting,
    pub source: String,
    pub checks: Checks,
}

impl Report {
    fn conditions_ok(&self) -> bool {
        self.method.conditions().iter().all(|c| c.holds())
    }

    /// What the measurements contradict: the numerical checks
    /// ([`verify_checks::contradictions`]), failing order conditions, and a measured
    /// symplecticity defect (a composition of exact flows is symplectic).
    pub fn contradictions(&self) -> Vec<String> {
        let m = &self.method;
        let mut found = verify_checks::contradictions(&self.checks, m.order(), m.flags().symmetric);
        if !self.conditions_ok() {
            found.push("order conditions fail".into());
        }
        if !self.checks.symplectic.holds {
            found.push("the measured symplecticity defect is above its bound".into());
        }
        found
    }

    /// The word as `D(c) K(c) ...`, shortened in the middle when long.
    fn word(&self) -> String {
        let ops: Vec<String> = self
            .method
            .word()
            .iter()
            .map(|op| {
                let f = match op.flow {
                    Flow::Drift => "D",
                    Flow::Kick => "K",
                };
                format!("{f}({:.4})", op.coef)
            })
            .collect();
        if ops.len() <= 12 {
            ops.join(" ")
        } else {
            format!(
                "{} ... {} ({} sub-flows)",
                ops[..5].join(" "),
                ops[ops.len() - 5..].join(" "),
                ops.len()
            )
        }
    }

    pub fn text(&self) -> String {
        let m = &self.method;
        let f = m.flags();
        let mut out = String::new();
        let ok = if self.conditions_ok() { "hold" } else { "FAIL" };
        let orders = m.algebraic_orders();
        let _ = writeln!(
            out,
            "{}: declared order {}, algebraic order {} ({}), order conditions {ok}",
            m.name(),
            m.order(),
            orders.own,
            class_text(m.class()),
        );
        let rows = [
            ("source", self.source.clone()),
            ("family", m.family().to_string()),
            ("stages", format!("{} force evaluations per step", m.stages())),
            ("explicit", yes_no(f.explicit).into()),
            ("FSAL", yes_no(f.fsal).into()),
            ("symplectic", "yes (a composition of exact flows)".into()),
            ("symmetric", yes_no(f.symmetric).into()),
            (
                "kinetic energy",
                if m.requires_quadratic_kinetic() {
                    "must be quadratic (a Runge-Kutta-Nystrom method)".into()
                } else {
                    "any (a general method)".into()
                },
            ),
            ("word", self.word()),
            (
                "algebraic order",
                format!(
                    "{} as a splitting{} of any H = A + B, {} with a quadratic kinetic energy",
                    orders.general,
                    if m.gamma().is_some() { " (over Verlet)" } else { "" },
                    orders.quadratic_kinetic
                ),
            ),
        ];
        properties(&mut out, &rows);
        let conditions: Vec<ConditionRow<'_>> = m.conditions().iter().map(ConditionRow::splitting).collect();
        let title = format!("order conditions, {}", class_text(m.class()));
        condition_table(&mut out, &title, &conditions);
        out += &verify_checks::text(&self.checks, m.order(), f.symmetric);
        out.lines().map(|l| l.trim_end().to_string() + "\n").collect()
    }

    pub fn json(&self) -> JsonReport<'_> {
        let m = &self.method;
        let f = m.flags();
        let orders = m.algebraic_orders();
        JsonReport {
            name: m.name(),
            source: &self.source,
            family: m.family(),
            declared_order: m.order(),
            algebraic_order: orders.own,
            condition_class: m.class().name(),
            algebraic_order_general: orders.general,
            algebraic_order_quadratic_kinetic: orders.quadratic_kinetic,
            conditions_ok: self.conditions_ok(),
            stages: m.stages(),
            explicit: f.explicit,
            fsal: f.fsal,
            symplectic: self.checks.symplectic.holds,
            symmetric: f.symmetric,
            requires_quadratic_kinetic: m.requires_quadratic_kinetic(),
            drift: m.drift(),
            kick: m.kick(),
            gamma: m.gamma(),
            conditions: m.conditions().iter().map(ConditionRow::splitting).collect(),
            checks: JsonChecks::new(&self.checks),
        }
    }
}

/// `verify --format json` for a splitting or composition, keys in this order.
#[derive(serde::Serialize)]
pub struct JsonReport<'a> {
    name: &'a str,
    source: &'a str,
    family: &'a str,
    declared_order: usize,
    /// The highest order whose conditions all hold in the method's class
    /// (`condition_class`), up to 10.
    algebraic_order: usize,
    /// `"general"`, `"quadratic_kinetic"` or `"composition"`.
    condition_class: &'static str,
    /// As a splitting (a composition: over Verlet) of any `H = A + B`.
    algebraic_order_general: usize,
    /// As a splitting with a quadratic kinetic energy.
    algebraic_order_quadratic_kinetic: usize,
    conditions_ok: bool,
    stages: usize,
    explicit: bool,
    fsal: bool,
    /// The numerical verdict (`symplectic_defect` within its bound in every case).
    symplectic: bool,
    symmetric: bool,
    requires_quadratic_kinetic: bool,
    drift: &'a [f64],
    kick: &'a [f64],
    gamma: Option<&'a [f64]>,
    conditions: Vec<ConditionRow<'a>>,
    #[serde(flatten)]
    checks: JsonChecks,
}

/// How the text report names a class of order conditions.
fn class_text(class: OrderClass) -> &'static str {
    match class {
        OrderClass::General => "general class: any H = A + B",
        OrderClass::QuadraticKineticEnergy => "class of a quadratic kinetic energy",
        OrderClass::SymmetricComposition => "composition of a symmetric second-order base",
    }
}
