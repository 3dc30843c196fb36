//! The one error type of the library.

use thiserror::Error;

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

/// A TOML error on one line: `line L, column C: message` (toml's own `Display` spans
/// several lines with a source excerpt, which does not fit a one-line error).
pub fn toml_message(e: &toml::de::Error, text: &str) -> String {
    let message = one_line(e.message());
    match e.span() {
        Some(span) => {
            let (line, column) = line_column(text, span.start);
            format!("line {line}, column {column}: {message}")
        }
        None => message,
    }
}

/// The 1-based line and column (in characters) of byte `offset` of `text`.
pub fn line_column(text: &str, offset: usize) -> (usize, usize) {
    let before = text.get(..offset.min(text.len())).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let column = before.rsplit('\n').next().map_or(0, |l| l.chars().count()) + 1;
    (line, column)
}

/// Joins the lines of a message with "; ".
pub fn one_line(message: &str) -> String {
    message
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join("; ")
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

/// A number as messages and tables print it for people: positional from 1e-4 to below 1e7
/// (`0.5`, `19.06688`, `1906688`) and scientific outside (`1e-300`, `2.322e10`), never a
/// 300-digit expansion; by default with the shortest digits that read back to the same
/// number (a time, a value the user typed), or with at most `n` significant digits and
/// trailing zeros dropped ([`Number::significant`], for a measured quantity: `1.137e-12`).
/// [`number`] makes one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Number {
    x: f64,
    significant: Option<usize>,
}

/// `x` for a message: `format!("t = {}", number(t))` ([`Number`]).
pub fn number(x: f64) -> Number {
    Number { x, significant: None }
}

impl Number {
    /// At most `n` (at least 1) significant digits.
    pub fn significant(self, n: usize) -> Number {
        Number {
            significant: Some(n.max(1)),
            ..self
        }
    }
}

impl core::fmt::Display for Number {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let x = self.x;
        if !x.is_finite() || x == 0.0 {
            // `NaN`, `inf`, `-inf`, `0` (and `-0` as `0`)
            return f.pad(&if x == 0.0 { "0".to_string() } else { x.to_string() });
        }
        // the exponent after rounding to the digits asked (9.9999999 rounds to 10)
        let scientific = match self.significant {
            Some(n) => format!("{:.*e}", n - 1, x),
            None => format!("{x:e}"),
        };
        let (mantissa, exponent) = scientific.split_once('e').unwrap_or((&scientific, "0"));
        let exponent: i32 = exponent.parse().unwrap_or(0);
        let text = match self.significant {
            _ if !(-4..7).contains(&exponent) => format!("{}e{exponent}", trim_zeros(mantissa)),
            Some(n) => {
                let decimals = (n as i32 - 1 - exponent).max(0) as usize;
                trim_zeros(&format!("{x:.decimals$}")).to_string()
            }
            None => x.to_string(),
        };
        f.pad(&text)
    }
}

/// `1.2500` to `1.25`, `3.000` to `3`; integers unchanged.
fn trim_zeros(s: &str) -> &str {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        s
    }
}

#[cfg(test)]
mod number_tests {
    use super::number;

    #[test]
    #[allow(clippy::float_cmp)] // the text reads back to exactly the number (-0 as 0)
    fn numbers_for_people_have_a_few_digits_and_no_long_expansions() {
        let cases = [
            (1e-300, "1e-300"),
            (1e-16, "1e-16"),
            (1.1368683772161603e-12, "1.1368683772161603e-12"),
            (0.5, "0.5"),
            (10.0, "10"),
            (19.06688, "19.06688"),
            (1906688.0, "1906688"),
            (2.322e10, "2.322e10"),
            (-3.5e-5, "-3.5e-5"),
            (0.0001, "0.0001"),
            (0.0, "0"),
            (-0.0, "0"),
            (f64::NAN, "NaN"),
            (f64::INFINITY, "inf"),
            (1e300, "1e300"),
        ];
        for (x, text) in cases {
            assert_eq!(number(x).to_string(), text, "{x:e}");
            // the default reads back to the same number
            if x.is_finite() {
                assert_eq!(text.parse::<f64>().unwrap(), x);
            }
        }
        let cases = [
            (1.1368683772161603e-12, 4, "1.137e-12"),
            (1.2390033882430031, 7, "1.239003"),
            (0.021387146, 7, "0.02138715"),
            (9.99999999, 7, "10"),
            (56.5432, 3, "56.5"),
            (1.1e-12, 2, "1.1e-12"),
            (123456789.0, 4, "1.235e8"),
        ];
        for (x, n, text) in cases {
            assert_eq!(number(x).significant(n).to_string(), text, "{x:e} to {n} digits");
        }
        assert_eq!(format!("{:>6}", number(0.5)), "   0.5");
    }
}
