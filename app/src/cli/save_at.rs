//! `--save-at`: the output times of a run, as `START:STEP:END` or a comma list.

use super::finite_number::finite_number;
use stormer::Error;

/// At most this many output times: they are held in memory (8 bytes each, in the few
/// copies a run keeps), and each is a CSV row (about 20 bytes a column) on disk. A range
/// is counted before any time is made, so a finer STEP is refused at once.
const MAX_TIMES: f64 = 1e7;

/// The times of `--save-at`: `START:STEP:END` (from START by STEP while not past END,
/// END itself included when STEP divides the span to rounding) or `T1,T2,...`.
pub fn parse(text: &str) -> Result<Vec<f64>, Error> {
    let bad = |reason: String| Error::invalid("--save-at", reason);
    let number = |s: &str| finite_number("--save-at", text, s);
    let parts: Vec<&str> = text.split(':').collect();
    match parts[..] {
        [start, step, end] => {
            let (start, step, end) = (number(start)?, number(step)?, number(end)?);
            if step == 0.0 || (end - start) * step < 0.0 {
                return Err(bad(format!(
                    "the step {step} does not lead from {start} to {end}; give START:STEP:END with a step of the \
                     span's sign"
                )));
            }
            let ratio = (end - start) / step;
            // END counts when it is a whole number of steps away, to rounding (the nearest
            // whole number then, not the floor of the ratio plus the allowance, which
            // counted a thousand times too many for 1e12 steps)
            let nearest = ratio.round();
            let whole = (ratio - nearest).abs() <= 1e-9 * ratio.abs().max(1.0);
            let last = if whole { nearest } else { ratio.floor() };
            if last + 1.0 > MAX_TIMES {
                return Err(bad(format!(
                    "'{text}' gives {} output times, more than the {} a run writes (a CSV row \
                     each); take a longer STEP",
                    last + 1.0,
                    MAX_TIMES as u64
                )));
            }
            let n = last as usize;
            Ok((0..=n)
                .map(|i| if i == n && whole { end } else { start + step * i as f64 })
                .collect())
        }
        [list] => list.split(',').map(number).collect(),
        _ => Err(bad(format!(
            "expected START:STEP:END or a comma list of times, got '{text}'"
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_range_includes_its_end_when_the_step_divides_the_span() {
        let times = parse("0:0.01:3.5").unwrap();
        assert_eq!(times.len(), 351);
        assert_eq!((times[0], times[350]), (0.0, 3.5));
        assert_eq!(parse("0:0.3:1").unwrap(), [0.0, 0.3, 0.6, 0.8999999999999999]);
        assert_eq!(parse("1:-0.5:0").unwrap(), [1.0, 0.5, 0.0]);
        assert_eq!(parse("0.5, 1,2").unwrap(), [0.5, 1.0, 2.0]);
    }

    #[test]
    fn bad_ranges_and_numbers_are_named() {
        for (text, message) in [
            ("5:-1:10", "the step -1 does not lead from 5 to 10"),
            ("0:0:1", "the step 0 does not lead"),
            ("0:1", "expected START:STEP:END or a comma list"),
            ("0:x:1", "'x' is not a finite number"),
            ("1,,2", "'' is not a finite number"),
            (
                "0:1e-12:1",
                "output times, more than the 10000000 a run writes",
            ),
            (
                "0:1.0000001e-7:10",
                "'0:1.0000001e-7:10' gives 99999991 output times, more than the 10000000 a run writes (a CSV row each); take a \
                 longer STEP",
            ),
            ("inf", "'inf' is not a finite number"),
        ] {
            let e = parse(text).unwrap_err().to_string();
            assert!(e.contains(message), "{text}: {e}");
        }
    }
}
