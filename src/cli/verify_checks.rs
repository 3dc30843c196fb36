//! The numerical part of `stormer verify`: measured order, symplecticity and
//! reversibility from `stormer::verify::report`, as text lines and JSON keys.

use super::output::yes_no;
use std::fmt::Write as _;
use stormer::verify::{Check, Report, REVERSIBLE_FACTOR, SYMPLECTIC_FACTOR};

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
    match &r.order {
        Ok(m) => {
            let fitted = &m.samples[m.fitted.clone()];
            let agrees = if (m.order - declared as f64).abs() <= 0.2 {
                "agrees with"
            } else {
                "DIFFERS from"
            };
            let _ = writeln!(
                out,
                "  measured order   {:.2} ({agrees} the declared {declared}): slope of the centred local error on {}, \
                 h = {:.3} .. {:.3}, errors {:.1e} .. {:.1e}",
                m.order,
                r.order_problem,
                fitted[0].h,
                fitted[fitted.len() - 1].h,
                fitted[0].error,
                fitted[fitted.len() - 1].error,
            );
        }
        Err(e) => {
            let _ = writeln!(out, "  measured order   not measured on {}: {e}", r.order_problem);
        }
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
    out
}
