//! The numerical part of `stormer verify`: measured order, symplecticity and
//! reversibility from `stormer::verify::report`, as text lines and JSON keys.

use super::output::yes_no;
use std::fmt::Write as _;
use stormer::verify::conditions::stability::{Interval, SCAN_LIMIT};
use stormer::verify::problems::TreeSystem;
use stormer::verify::{Check, OrderError, OrderMeasurement, Report, REVERSIBLE_FACTOR, SYMPLECTIC_FACTOR};
use stormer::Error;

/// The JSON keys the numerical checks add to `verify --format json` (flattened into the
/// report, after its own keys). The verdict `symplectic` is not here: each report keeps
/// it at its place among the flags.
#[derive(serde::Serialize)]
pub struct JsonChecks {
    /// The measured order, `null` if it could not be measured (see `measured_order_error`).
    pub measured_order: Option<f64>,
    /// The problem it was measured on.
    pub measured_order_problem: &'static str,
    /// Why the order could not be measured.
    pub measured_order_error: Option<String>,
    /// `max |J^T S J - S|` of the worst case (exact Jacobian on dual numbers).
    pub symplectic_defect: f64,
    /// That case's bound, `SYMPLECTIC_FACTOR eps max(1, |J|)^2`.
    pub symplectic_defect_bound: f64,
    /// The largest defect with central-difference Jacobians (accurate to `~1e-10`).
    pub symplectic_defect_central_differences: f64,
    /// The numerical verdict of the step-back test.
    pub reversible: bool,
    /// `|Phi_{-h}(Phi_h(y)) - y|` of the worst case.
    pub reversibility_defect: f64,
    /// That case's bound, `REVERSIBLE_FACTOR eps max(1, |y|)`.
    pub reversibility_defect_bound: f64,
    /// The largest `h omega` with no growth on the harmonic oscillator: a number, or
    /// `"unbounded"`.
    pub stability_interval: Stability,
}

/// The stability interval in JSON: its bound, or the string `"unbounded"`.
pub struct Stability(pub Interval);

impl serde::Serialize for Stability {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self.0 {
            Interval::Bounded(x) => s.serialize_f64(x),
            Interval::Unbounded => s.serialize_str("unbounded"),
        }
    }
}

impl JsonChecks {
    pub fn new(r: &Report) -> Self {
        JsonChecks {
            measured_order: r.order.as_ref().ok().map(|m| m.order),
            measured_order_problem: r.order_problem,
            measured_order_error: r.order.as_ref().err().map(|e| e.to_string()),
            symplectic_defect: r.symplectic.defect,
            symplectic_defect_bound: r.symplectic.bound,
            symplectic_defect_central_differences: r.symplectic_defect_central,
            reversible: r.reversible.holds,
            reversibility_defect: r.reversible.defect,
            reversibility_defect_bound: r.reversible.bound,
            stability_interval: Stability(r.stability),
        }
    }
}

fn case(c: &Check) -> String {
    let state: Vec<String> = c.case.state.iter().map(|x| format!("{x}")).collect();
    format!("{}, y = ({}), h = {}", c.case.problem, state.join(", "), c.case.h)
}

fn verdict(c: &Check) -> &'static str {
    if c.holds {
        "<="
    } else {
        ">"
    }
}

/// The text section, with `declared` the declared order and `symmetric` the derived flag
/// (each verdict is compared with what the data say).
pub fn text(r: &Report, declared: usize, symmetric: bool) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "numerical checks (docs/verification.md):");
    out += &order_line("measured order  ", &r.order, r.order_error, r.order_problem, declared);
    if let (Some(m), Some(q)) = (&r.embedded_order, r.info.embedded_order) {
        out += &order_line("  embedded      ", m, OrderError::Global, r.order_problem, q);
    }
    let s = &r.symplectic;
    let _ = writeln!(
        out,
        "  symplectic       {}: max |J^T S J - S| = {:.1e} {} {:.1e} ({SYMPLECTIC_FACTOR} eps max(1,|J|)^2), \
         exact Jacobian (dual numbers), worst case {}",
        yes_no(s.holds),
        s.defect,
        verdict(s),
        s.bound,
        case(s)
    );
    let _ = writeln!(
        out,
        "                   central differences: max |J^T S J - S| = {:.1e} (their own accuracy is ~1e-10)",
        r.symplectic_defect_central
    );
    if let Some(residual) = r.symplectic_condition_residual {
        let _ = writeln!(
            out,
            "                   condition b_i a_ij + b_j a_ji = b_i b_j: residual {residual:.1e}"
        );
    }
    let v = &r.reversible;
    let _ = writeln!(
        out,
        "  reversible       {}: |Phi_-h(Phi_h(y)) - y| = {:.1e} {} {:.1e} ({REVERSIBLE_FACTOR} eps max(1,|y|)), \
         worst case {}{}",
        yes_no(v.holds),
        v.defect,
        verdict(v),
        v.bound,
        case(v),
        if v.holds == symmetric {
            ""
        } else {
            " (DIFFERS from the symmetric flag)"
        }
    );
    out += &stability_line(r.stability, r.info.family == "butcher");
    out
}

/// A measured order agrees with the declared one within 0.2 (the slope of a fit over a
/// range of steps; docs/verification.md).
fn agrees(measured: f64, declared: usize) -> bool {
    (measured - declared as f64).abs() <= 0.2
}

/// What the measurements contradict among the method's declarations, with `declared` its
/// declared order and `symmetric` its symmetric flag: a measured order (main or embedded)
/// that differs from the declared one, a step-back test that differs from the flag.
/// An order that could not be measured contradicts nothing.
pub fn contradictions(r: &Report, declared: usize, symmetric: bool) -> Vec<String> {
    let mut found = Vec::new();
    let mut order = |what: &str, measured: &Result<OrderMeasurement, Error>, declared: usize| {
        if let Some(m) = measured.as_ref().ok().filter(|m| !agrees(m.order, declared)) {
            found.push(format!(
                "the {what} measured is {:.2}, not the declared {declared}",
                m.order
            ));
        }
    };
    order("order", &r.order, declared);
    if let (Some(m), Some(q)) = (&r.embedded_order, r.info.embedded_order) {
        order("embedded order", m, q);
    }
    if r.reversible.holds != symmetric {
        // the flag is derived, never declared (a file's `symmetric` must agree with the
        // coefficients to be read at all): say so, and what the step did
        found.push(format!(
            "the step-back test finds the step {}reversible, but the symmetric flag stormer derives from the \
             coefficients is {}",
            if r.reversible.holds { "" } else { "not " },
            yes_no(symmetric)
        ));
    }
    found
}

/// The line of a measured order (`label` 16 characters wide).
fn order_line(
    label: &str,
    order: &Result<OrderMeasurement, Error>,
    error: OrderError,
    problem: &str,
    declared: usize,
) -> String {
    let m = match order {
        Ok(m) => m,
        Err(e) => return format!("  {label} not measured on {problem}: {e}\n"),
    };
    let fitted = &m.samples[m.fitted.clone()];
    let (first, last) = (fitted[0], fitted[fitted.len() - 1]);
    let agrees = if agrees(m.order, declared) {
        "agrees with"
    } else {
        "DIFFERS from"
    };
    let how = match error {
        OrderError::CentredLocal => {
            format!(
                "slope of the centred local error on {problem}, h = {:.3} .. {:.3}",
                first.h, last.h
            )
        }
        OrderError::Global => format!(
            "slope of the global error at t = 1 from t = -1 on {problem} (trees of orders 2 to {}), \
             {} .. {} steps",
            TreeSystem::<f64>::max_order_for(declared),
            (2.0 / first.h).round(),
            (2.0 / last.h).round(),
        ),
    };
    format!(
        "  {label} {:.2} ({agrees} the declared {declared}): {how}, errors {:.1e} .. {:.1e}\n",
        m.order, first.error, last.error
    )
}

/// The stability interval and what it means.
fn stability_line(interval: Interval, butcher: bool) -> String {
    let how = if butcher {
        "|R(i h omega)| <= 1"
    } else {
        "|trace| <= 2 of the transfer matrix"
    };
    let oscillator = "on the harmonic oscillator q'' = -omega^2 q";
    match interval {
        Interval::Bounded(x) if x <= 0.0 => format!(
            "  stability        0: a step grows {oscillator} at every h*omega > 0 (from the coefficients: {how} fails)\n"
        ),
        Interval::Bounded(x) => format!(
            "  stability        h*omega <= {x:.4}: the largest h*omega with no growth {oscillator} \
             (from the coefficients: {how})\n"
        ),
        Interval::Unbounded => format!(
            "  stability        unbounded: no growth {oscillator} at any h*omega (up to {SCAN_LIMIT}; \
             from the coefficients: {how})\n"
        ),
    }
}
