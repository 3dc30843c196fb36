//! The one error type of the library.

use thiserror::Error;

use crate::text::number;

/// Everything that can go wrong while building a method or integrating.
///
/// Numbers are reported as `f64` whatever the scalar type, so the error is not generic.
#[derive(Debug, Clone, Error, PartialEq)]
#[non_exhaustive]
pub enum Error {
    /// The state became NaN or infinite.
    #[error("the state became non-finite at t = {} (step {step})", number(*t))]
    NonFinite {
        /// Time at the start of the failing step.
        t: f64,
        /// Index of the failing step (0-based).
        step: u64,
    },
    /// The run was cancelled from outside ([`Driver::cancel_when`](crate::Driver::cancel_when),
    /// Ctrl-C in `stormer run`); everything recorded before is kept.
    #[error("cancelled at t = {} (step {step})", number(*t))]
    Cancelled {
        /// Time reached: the start of the first step not taken.
        t: f64,
        /// Steps taken before the cancellation was seen.
        step: u64,
    },
    /// The reversible step control ([`Driver::reversible`](crate::Driver::reversible)) cannot
    /// choose the next step: its density returned a value that is not finite and > 0, or a
    /// rate that is not finite, or its control variable fell to 0 or below (`eps` too large
    /// for how fast the density changes). Everything recorded before is kept.
    #[error("the reversible step control failed at t = {} (step {step}): {what}", number(*t))]
    StepDensity {
        /// Time of the state where it happened.
        t: f64,
        /// Steps taken before.
        step: u64,
        /// What was wrong, with the value.
        what: String,
    },
    /// An implicit stage equation was not solved.
    #[error("the implicit solver did not converge at t = {}: residual {residual:.3e} after {iterations} iterations", number(*t))]
    SolverDiverged {
        /// Time at the start of the step.
        t: f64,
        /// Last residual (max norm of the stage update).
        residual: f64,
        /// Iterations performed.
        iterations: usize,
    },
    /// The adaptive controller needed a step below the smallest representable increment.
    #[error("step size underflow at t = {}: h = {}", number(*t), number(*h))]
    StepSizeTooSmall {
        /// Time where it happened.
        t: f64,
        /// The rejected step size.
        h: f64,
    },
    /// The run would need, or has taken, more steps than its limit (`Driver::max_steps`).
    #[error("{}", too_many_steps(*t, *steps, *needed))]
    TooManySteps {
        /// Time reached (the start time for a run refused before its first step).
        t: f64,
        /// The limit.
        steps: u64,
        /// The steps a fixed-step run would need; `None` for an adaptive run that reached
        /// the limit on its way.
        needed: Option<f64>,
    },
    /// A method's data are not a valid method.
    #[error("invalid method {name}: {reason}")]
    InvalidMethod {
        /// The method's name (or file).
        name: String,
        /// What is wrong.
        reason: String,
    },
    /// A method name that is not in the catalog.
    #[error("unknown method '{name}'{}", suggest(.suggestions))]
    UnknownMethod {
        /// What the user typed.
        name: String,
        /// The nearest catalog names.
        suggestions: Vec<String>,
    },
    /// A method that cannot run the requested way (e.g. adaptive steps without an embedded pair).
    #[error("method {name} cannot be used here: {reason}")]
    Unsupported {
        /// The method.
        name: String,
        /// Why.
        reason: String,
    },
    /// A scene file that cannot be read or does not describe a valid scene.
    #[error("scene {file}: {reason}")]
    Scene {
        /// The scene's name or file path.
        file: String,
        /// What is wrong, with the line and the field where the file says it.
        reason: String,
    },
    /// Writing the output of a run failed.
    #[error("cannot write {path}: {reason}")]
    Io {
        /// The file being written.
        path: String,
        /// The operating system's reason.
        reason: String,
    },
    /// A library type used against its contract, e.g. `Stepper::step_in_place` on a
    /// stepper whose `steps_in_place` is false. A static message: building it calls nothing,
    /// so that the hot paths which can return it stay free of calls.
    #[error("{0}")]
    Misuse(&'static str),
    /// An argument out of its domain.
    #[error("invalid {what}: {reason}")]
    InvalidArgument {
        /// Which argument.
        what: String,
        /// Why.
        reason: String,
    },
}

fn too_many_steps(t: f64, limit: u64, needed: Option<f64>) -> String {
    match needed {
        Some(n) => {
            // a count in full where it is one, else three digits: never 9.999999999999999e299
            let n = match n {
                n if n <= 1e15 => format!("{n:.0}"),
                n if n.is_finite() => format!("{n:.3e}"),
                _ => "over 1e308".into(),
            };
            format!(
                "the run needs {n} steps, more than the limit of {limit} steps (max_steps); \
                 raise the limit or take longer steps"
            )
        }
        None => format!(
            "gave up at t = {} after {limit} steps, the limit (max_steps); raise the limit, \
             loosen the tolerances or shorten the span",
            number(t)
        ),
    }
}

fn suggest(names: &[String]) -> String {
    match names {
        [] => String::new(),
        [one] => format!("; did you mean '{one}'?"),
        more => format!("; did you mean one of: {}?", more.join(", ")),
    }
}

impl Error {
    /// Shorthand for [`Error::InvalidArgument`].
    pub fn invalid(what: impl Into<String>, reason: impl Into<String>) -> Self {
        Error::InvalidArgument {
            what: what.into(),
            reason: reason.into(),
        }
    }
}
