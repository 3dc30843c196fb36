//! The tick labels of a chart's axes: short, and telling every tick of an axis apart.

use super::chart::Scale;

/// The width of the widest tick label plotters may draw on an axis (about ten ticks at
/// multiples of a round step on a linear axis, the decades on a log axis), in characters.
pub(crate) fn widest_tick(scale: Scale, (lo, hi): (f64, f64)) -> usize {
    let labels = Ticks::new(scale, (lo, hi));
    let values: Vec<f64> = match scale {
        Scale::Linear => {
            let raw = (hi - lo) / 10.0;
            let unit = 10f64.powf(raw.log10().floor());
            let step = [1.0, 2.0, 5.0, 10.0]
                .iter()
                .map(|m| m * unit)
                .find(|s| *s >= raw)
                .unwrap_or(raw);
            let first = (lo / step).ceil();
            (0..12)
                .map(|k| (first + f64::from(k)) * step)
                .take_while(|v| *v <= hi)
                .collect()
        }
        Scale::Log => {
            let (a, b) = (lo.log10().floor() as i32, hi.log10().ceil() as i32);
            (a..=b).take(50).map(|k| 10f64.powi(k)).collect()
        }
    };
    values
        .iter()
        .map(|&v| labels.label(v).chars().count())
        .max()
        .unwrap_or(4)
}

/// How many tick labels plotters may put on an axis: 8, or on a log axis of less than two
/// decades 12, which makes it label 2, 3, ... 9 times the decade too (else it labels the
/// decades alone: one tick, or none).
pub(super) fn label_count(scale: Scale, (lo, hi): (f64, f64)) -> usize {
    if scale == Scale::Log && (hi / lo).log10() < 2.0 {
        12
    } else {
        8
    }
}

/// The tick labels of one axis: on a linear axis, as many digits as tell ticks a tenth of
/// the range apart (`-0.57746`, `-0.57744`, not `-0.577` on every tick), and `0` for a
/// value that is zero to the axis' resolution (not `-2.22e-16`); on a log axis, [`tick`].
pub(crate) struct Ticks {
    /// A tenth of the range of a linear axis; `None` on a log axis or an empty range.
    step: Option<f64>,
    /// A log axis of less than two decades, ticked at every multiple of its decades
    /// ([`label_count`]): only 1, 2 and 5 times a decade are labelled, so that the labels
    /// do not run into each other.
    dense_log: bool,
    /// The last value labelled: plotters gives a short log axis' decade twice (ten times
    /// the decade below, and the decade itself), and a label drawn twice over itself reads
    /// bold.
    last: core::cell::Cell<f64>,
}

impl Ticks {
    pub(crate) fn new(scale: Scale, (lo, hi): (f64, f64)) -> Self {
        let step = (hi - lo).abs() / 10.0;
        Ticks {
            step: (scale == Scale::Linear && step.is_finite() && step > 0.0).then_some(step),
            dense_log: label_count(scale, (lo, hi)) > 8,
            last: core::cell::Cell::new(f64::NAN),
        }
    }

    pub(crate) fn label(&self, v: f64) -> String {
        let Some(step) = self.step else {
            if self.last.replace(v).to_bits() == v.to_bits() {
                return String::new();
            }
            let mantissa = v / 10f64.powf(v.log10().floor());
            let round = [1.0, 2.0, 5.0, 10.0].iter().any(|m| (mantissa - m).abs() < 1e-6 * m);
            return if self.dense_log && !round {
                String::new()
            } else {
                tick(v)
            };
        };
        if v.abs() <= step * 1e-6 {
            return "0".into();
        }
        // the digits that resolve `step` (ticks are multiples of at least `step`)
        let decimals = (-step.log10().floor()).max(0.0) as usize;
        let a = v.abs();
        if (1e-3..1e5).contains(&a) && decimals <= 12 {
            let plain = tick(v);
            let needed = format!("{v:.decimals$}");
            let needed = if needed.contains('.') {
                needed.trim_end_matches('0').trim_end_matches('.').to_string()
            } else {
                needed
            };
            return if needed.len() > plain.len() { needed } else { plain };
        }
        let digits = ((a / step).log10().ceil().max(0.0) as usize + 1).clamp(2, 16);
        let s = format!("{v:.digits$e}");
        let (mantissa, exponent) = s.split_once('e').unwrap_or((&s, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        format!("{mantissa}e{exponent}")
    }
}

/// A tick label with at most three significant digits: `0.001`, `250`, `1e-5`, `2.5e6`
/// (not `9.999999999999999e-5`).
fn tick(v: f64) -> String {
    let a = v.abs();
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    if (1e-3..1e5).contains(&a) {
        let decimals = (2 - a.log10().floor() as i32).max(0) as usize;
        let s = format!("{v:.decimals$}");
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').to_string()
        } else {
            s
        }
    } else {
        let s = format!("{v:.2e}");
        let (mantissa, exponent) = s.split_once('e').unwrap_or((&s, "0"));
        let mantissa = mantissa.trim_end_matches('0').trim_end_matches('.');
        format!("{mantissa}e{exponent}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_ticks_resolve_their_axis_and_print_zero_as_zero() {
        let narrow = Ticks::new(Scale::Linear, (-0.57746, -0.57734));
        let labels: Vec<String> = [-0.57746, -0.57744, -0.57742]
            .iter()
            .map(|&v| narrow.label(v))
            .collect();
        assert_eq!(labels, ["-0.57746", "-0.57744", "-0.57742"]);
        let unit = Ticks::new(Scale::Linear, (-1.0, 1.0));
        assert_eq!(unit.label(-2.220446049250313e-16), "0");
        assert_eq!(unit.label(0.2), "0.2");
        assert_eq!(unit.label(-0.6000000000000001), "-0.6");
        let huge = Ticks::new(Scale::Linear, (1e10, 1e10 + 1e4));
        assert_eq!(huge.label(1e10 + 2e3), "1.0000002e10");
        assert_eq!(Ticks::new(Scale::Log, (1e-3, 1.0)).label(0.01), "0.01");
        // a log axis of less than two decades labels 1, 2 and 5 times its decades only
        let short = Ticks::new(Scale::Log, (300.0, 8000.0));
        let labels: Vec<String> = [1000.0, 2000.0, 3000.0, 5000.0, 6000.000000000001]
            .iter()
            .map(|&v| short.label(v))
            .collect();
        assert_eq!(labels, ["1000", "2000", "", "5000", ""]);
        assert_eq!(Ticks::new(Scale::Log, (1.0, 1e4)).label(3000.0), "3000");
    }

    /// Every text of a picture is at least 2.2% of its width high (15 px of 680: 13 px
    /// when a page shows it 600 px wide; plotters' default was 1.2%), and the equal-aspect

    #[test]
    fn tick_labels_are_short() {
        let cases = [
            (9.999999999999999e-5, "1e-4"),
            (0.009999999999999998, "0.01"),
            (1000.0, "1000"),
            (2.5e6, "2.5e6"),
            (0.25, "0.25"),
            (-3.0, "-3"),
            (0.0, "0"),
        ];
        for (v, s) in cases {
            assert_eq!(tick(v), s);
        }
    }
}
