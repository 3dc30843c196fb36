//! `--vary NAME=START:END:COUNT`: the values one number of the scene file takes across an
//! ensemble, and the members of the grid that several of them span.

use serde::{Deserialize, Serialize};
use stormer::Error;

/// One varied number: `COUNT` values evenly spaced from `START` to `END`, both included.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Axis {
    /// The number's whole key in the scene file (`initial.alpha`).
    pub key: String,
    /// First value.
    pub start: f64,
    /// Last value.
    pub end: f64,
    /// How many values.
    pub count: usize,
}

/// `--vary` as written: the name (resolved to a key against the scene file later) and the
/// range.
#[derive(Debug, Clone, PartialEq)]
pub struct Vary {
    /// The name as given (`alpha`).
    pub name: String,
    /// First value.
    pub start: f64,
    /// Last value.
    pub end: f64,
    /// How many values.
    pub count: usize,
}

impl Vary {
    /// Reads `NAME=START:END:COUNT`; every mistake is one sentence naming the value.
    pub fn parse(given: &str) -> Result<Self, Error> {
        let bad = |reason: String| Error::invalid("--vary", format!("{reason} (in '{given}')"));
        let (name, range) = given
            .split_once('=')
            .ok_or_else(|| bad("expected NAME=START:END:COUNT, such as alpha=10:50:41".into()))?;
        let name = name.trim();
        if name.is_empty() {
            return Err(bad("the NAME before '=' is missing".into()));
        }
        let parts: Vec<&str> = range.split(':').map(str::trim).collect();
        let [start, end, count] = parts[..] else {
            return Err(bad(format!(
                "expected START:END:COUNT after '{name}=', such as 10:50:41"
            )));
        };
        let number = |what: &str, s: &str| match s.parse::<f64>() {
            Ok(x) if x.is_finite() => Ok(x),
            _ => Err(bad(format!("{what} '{s}' is not a finite number"))),
        };
        let (start, end) = (number("START", start)?, number("END", end)?);
        let count: usize = count
            .parse()
            .map_err(|_| bad(format!("COUNT '{count}' is not a whole number >= 1")))?;
        if count == 0 {
            return Err(bad("COUNT must be >= 1, got 0".into()));
        }
        if start > end || (start >= end && count > 1) {
            return Err(bad(format!(
                "the range {start:?}:{end:?} is empty: END must be above START (or equal to it, with COUNT 1)"
            )));
        }
        if count == 1 && start < end {
            return Err(bad(format!(
                "COUNT 1 is one value, but {start:?}:{end:?} is a range: give START = END, or COUNT >= 2"
            )));
        }
        Ok(Vary {
            name: name.to_string(),
            start,
            end,
            count,
        })
    }
}

impl Axis {
    /// The `k`-th value: `(START (COUNT-1-k) + END k) / (COUNT-1)`, one rounding from exact,
    /// so that `0:1:11` gives 0.3, not 0.30000000000000004, and both ends are exact.
    pub fn value(&self, k: usize) -> f64 {
        if self.count <= 1 {
            return self.start;
        }
        if k + 1 >= self.count {
            return self.end;
        }
        let n = (self.count - 1) as f64;
        let k = k as f64;
        let x = (self.start * (n - k) + self.end * k) / n;
        // products beyond f64's range: the same point, computed without them
        if x.is_finite() {
            x
        } else {
            let f = k / n;
            self.start * (1.0 - f) + self.end * f
        }
    }

    /// All its values.
    pub fn values(&self) -> Vec<f64> {
        (0..self.count).map(|k| self.value(k)).collect()
    }
}

/// The most members an ensemble runs (its rows are kept in memory).
pub const MAX_MEMBERS: usize = 10_000_000;

/// The number of members of the grid of `axes`, refused beyond [`MAX_MEMBERS`].
pub fn member_count(axes: &[Axis]) -> Result<usize, Error> {
    let total = axes.iter().try_fold(1usize, |n, a| n.checked_mul(a.count));
    match total {
        Some(n) if n <= MAX_MEMBERS => Ok(n),
        _ => {
            let counts: Vec<String> = axes.iter().map(|a| a.count.to_string()).collect();
            Err(Error::invalid(
                "--vary",
                format!(
                    "the grid of {} values has more than the {MAX_MEMBERS} members an ensemble runs",
                    counts.join(" x ")
                ),
            ))
        }
    }
}

/// The index along each axis of member `m`: the first axis varies slowest (rows in the
/// order of nested loops, the last `--vary` innermost).
pub fn indices(axes: &[Axis], mut m: usize) -> Vec<usize> {
    let mut out = vec![0; axes.len()];
    for (slot, axis) in out.iter_mut().zip(axes).rev() {
        *slot = m % axis.count.max(1);
        m /= axis.count.max(1);
    }
    out
}

/// The varied values of member `m`.
pub fn member_values(axes: &[Axis], m: usize) -> Vec<f64> {
    indices(axes, m).iter().zip(axes).map(|(&k, a)| a.value(k)).collect()
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // the values are exact by construction
mod tests {
    use super::*;

    fn axis(start: f64, end: f64, count: usize) -> Axis {
        Axis {
            key: "a".into(),
            start,
            end,
            count,
        }
    }

    #[test]
    fn values_are_evenly_spaced_and_round_well() {
        assert_eq!(axis(10.0, 50.0, 41).values()[..3], [10.0, 11.0, 12.0]);
        assert_eq!(axis(10.0, 50.0, 41).value(40), 50.0);
        assert_eq!(axis(0.0, 1.0, 11).value(3), 0.3);
        assert_eq!(axis(0.0, 20.0, 41).value(1), 0.5);
        assert_eq!(axis(7.0, 7.0, 1).values(), [7.0]);
        let huge = axis(-1.7e308, 1.7e308, 3).values();
        assert!(huge.iter().all(|x| x.is_finite()) && huge[1] == 0.0, "{huge:?}");
    }

    #[test]
    fn members_run_through_the_grid_first_axis_slowest() {
        let axes = [axis(0.0, 1.0, 2), axis(0.0, 2.0, 3)];
        assert_eq!(member_count(&axes).unwrap(), 6);
        let all: Vec<Vec<usize>> = (0..6).map(|m| indices(&axes, m)).collect();
        assert_eq!(all, [[0, 0], [0, 1], [0, 2], [1, 0], [1, 1], [1, 2]]);
        assert_eq!(member_values(&axes, 5), [1.0, 2.0]);
        let too_many = [axis(0.0, 1.0, usize::MAX), axis(0.0, 1.0, 2)];
        assert!(member_count(&too_many).unwrap_err().to_string().contains("more than"));
    }

    #[test]
    fn bad_ranges_are_one_sentence_each() {
        assert_eq!(
            Vary::parse("alpha=10:50:41").unwrap(),
            Vary {
                name: "alpha".into(),
                start: 10.0,
                end: 50.0,
                count: 41
            }
        );
        assert_eq!(Vary::parse("x = -1 : 1 : 3").unwrap().start, -1.0);
        for (given, must) in [
            ("alpha", "expected NAME=START:END:COUNT"),
            ("=1:2:3", "the NAME before '=' is missing"),
            ("alpha=1:2", "expected START:END:COUNT after 'alpha='"),
            ("alpha=a:2:3", "START 'a' is not a finite number"),
            ("alpha=1:inf:3", "END 'inf' is not a finite number"),
            ("alpha=1:2:-3", "COUNT '-3' is not a whole number"),
            ("alpha=10:50:0", "COUNT must be >= 1, got 0"),
            ("alpha=50:10:41", "the range 50.0:10.0 is empty"),
            ("alpha=10:10:5", "the range 10.0:10.0 is empty"),
            ("alpha=10:20:1", "COUNT 1 is one value"),
        ] {
            let message = Vary::parse(given).unwrap_err().to_string();
            assert!(message.contains(must) && message.contains(given), "{given}: {message}");
            assert!(message.starts_with("invalid --vary: "), "{message}");
        }
    }
}
