//! `--section "x = 0, px > 0"`: a Poincare section, the states where a column of the run's
//! CSV crosses a value (optionally only where another column is above or below a value),
//! located on the continuous extension of the steps, written to their own CSV and drawn.

use super::finite_number::finite_number;
use super::output::CsvRecorder;
use super::pictures::Pictures;
use super::plot::{Chart, Series};
use crate::scenes::{Scene, Setup};
use std::path::PathBuf;
use stormer::driver::EventHit;
use stormer::driver::Recorder;
use stormer::Error;

/// A parsed `--section`: the state component `column` crosses `value`, where `side` holds.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    /// The expression as given, for messages.
    pub text: String,
    /// The state component that crosses (0 is the first component, not `t`).
    pub column: usize,
    /// The value it crosses.
    pub value: f64,
    /// Only crossings where component `.0` is above (`.1` true) or below `.2`.
    pub side: Option<(usize, bool, f64)>,
    /// How many components the scene's state has.
    pub components: usize,
}

impl Section {
    /// Parses `NAME = VALUE` or `NAME = VALUE, NAME (>|<) VALUE` against the scene's
    /// `components` (the columns of its CSV between `t` and `energy`).
    pub fn parse(text: &str, components: &[String]) -> Result<Section, Error> {
        let bad = |reason: String| Error::invalid("--section", format!("{reason} (in '{text}')"));
        let find = |name: &str| {
            let name = name.trim();
            components.iter().position(|c| c == name).ok_or_else(|| {
                bad(format!(
                    "unknown column '{name}'; this scene's columns are {}",
                    components.join(", ")
                ))
            })
        };
        let number = |s: &str| finite_number("--section", text, s);
        let (crossing, condition) = match text.split_once(',') {
            Some((a, b)) => (a, Some(b)),
            None => (text, None),
        };
        let Some((name, value)) = crossing.split_once('=') else {
            return Err(bad("expected 'COLUMN = VALUE', e.g. \"x = 0, px > 0\"".into()));
        };
        let (column, value) = (find(name)?, number(value)?);
        let side = match condition {
            None => None,
            Some(c) => {
                let (name, above, value) = if let Some((n, v)) = c.split_once('>') {
                    (n, true, v)
                } else if let Some((n, v)) = c.split_once('<') {
                    (n, false, v)
                } else {
                    return Err(bad(format!(
                        "expected 'COLUMN > VALUE' or 'COLUMN < VALUE' after the comma, got '{}'",
                        c.trim()
                    )));
                };
                Some((find(name)?, above, number(value)?))
            }
        };
        Ok(Section {
            text: text.trim().to_string(),
            column,
            value,
            side,
            components: components.len(),
        })
    }

    /// The event function: the crossing component minus the value.
    pub fn g(&self) -> impl Fn(f64, &[f64]) -> f64 {
        let (column, value) = (self.column, self.value);
        move |_t, y| y[column] - value
    }

    /// True when the state `y` is on the asked side.
    pub fn admits(&self, y: &[f64]) -> bool {
        self.side
            .map_or(true, |(j, above, v)| if above { y[j] > v } else { y[j] < v })
    }

    /// The two columns of the CSV (0 is `t`, `j + 1` component `j`) to draw the section in:
    /// the first two components that are neither the crossing one nor the side's (for a
    /// system of two degrees of freedom, the remaining coordinate and its momentum); with
    /// fewer (one degree of freedom), the other component against the crossing's time.
    pub fn axes(&self) -> [usize; 2] {
        let others = || (0..self.components).filter(|&j| j != self.column);
        let mut free = others().filter(|&j| self.side.map_or(true, |(s, _, _)| s != j));
        match (free.next(), free.next()) {
            (Some(a), Some(b)) => [a + 1, b + 1],
            // the side's component still varies from crossing to crossing
            _ => [0, others().next().unwrap_or(self.column) + 1],
        }
    }
}

/// The run's records to its CSV and the section's crossings (those on its side, as the
/// run pipeline passes them on) to theirs.
pub struct WithSection<'a, S: Scene> {
    /// The run's CSV.
    pub run: &'a mut CsvRecorder,
    /// The section's CSV (same header).
    pub crossings: CsvRecorder,
    /// The scene (the energy of each crossing).
    pub setup: &'a Setup<S>,
    /// Crossings written.
    pub count: u64,
}

impl<S: Scene> Recorder<f64, S::State> for WithSection<'_, S> {
    fn record(&mut self, t: f64, y: &S::State, energy: Option<f64>) -> Result<(), Error> {
        self.run.record(t, y, energy)
    }

    fn event(&mut self, hit: &EventHit<f64, S::State>) -> Result<(), Error> {
        self.count += 1;
        let energy = self.setup.model.energy(hit.t, &hit.y);
        self.crossings.record(hit.t, &hit.y, energy)
    }
}

/// Draws the crossings kept in `crossings` at `path` (the section's two remaining
/// components as points).
pub fn draw(crossings: &CsvRecorder, section: &Section, path: PathBuf, title: &str, pictures: &mut Pictures) {
    let [a, b] = section.axes();
    let sample = &crossings.sample;
    let header = sample.header();
    // the sample's columns are t, the components, the energy
    let (xs, ys) = (sample.column(a), sample.column(b));
    let chart = Chart::new(title.to_string(), &header[a], &header[b]);
    pictures.draw(
        path,
        &chart,
        &[Series::dots(section.text.clone(), xs.into_iter().zip(ys).collect())],
    );
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // values parsed from text are compared exactly
mod tests {
    use super::*;

    fn columns() -> Vec<String> {
        ["x", "y", "px", "py"].map(String::from).to_vec()
    }

    #[test]
    fn a_section_reads_its_column_value_and_side() {
        let s = Section::parse("x = 0, px > 0", &columns()).unwrap();
        assert_eq!((s.column, s.value, s.side), (0, 0.0, Some((2, true, 0.0))));
        assert_eq!(s.axes(), [2, 4], "y and py");
        assert!(s.admits(&[0.0, 0.1, 0.3, 0.0]) && !s.admits(&[0.0, 0.1, -0.3, 0.0]));
        let s = Section::parse("y=-0.5", &columns()).unwrap();
        assert_eq!((s.column, s.value, s.side), (1, -0.5, None));
        assert_eq!(s.g()(0.0, &[0.0, 1.0, 0.0, 0.0]), 1.5);
    }

    #[test]
    fn a_section_of_one_degree_of_freedom_is_drawn_against_time() {
        let two = ["x", "v"].map(String::from).to_vec();
        // the other component against t, never past the components (the energy column)
        assert_eq!(Section::parse("x = 0", &two).unwrap().axes(), [0, 2]);
        assert_eq!(Section::parse("x = 0, v > 0", &two).unwrap().axes(), [0, 2]);
        assert_eq!(Section::parse("v = 1, x < 0", &two).unwrap().axes(), [0, 1]);
        let one = vec!["z".to_string()];
        assert_eq!(Section::parse("z = 0", &one).unwrap().axes(), [0, 1]);
    }

    #[test]
    fn a_bad_section_says_what_is_wrong() {
        let err = |text: &str| Section::parse(text, &columns()).unwrap_err().to_string();
        assert!(err("q = 0").contains("unknown column 'q'; this scene's columns are x, y, px, py"));
        assert!(err("x = zero").contains("'zero' is not a finite number"));
        assert!(err("x > 0").contains("expected 'COLUMN = VALUE'"));
        assert!(err("x = 0, px = 1").contains("expected 'COLUMN > VALUE' or 'COLUMN < VALUE'"));
        assert!(err("x = 0, p > 0").contains("unknown column 'p'"));
    }
}
