//! The data ranges of a chart's axes: padded, finite, never empty, and equal units per
//! pixel on both axes when asked.

use super::chart::Scale;

/// A value an axis of `scale` can show: finite, and positive on a log axis.
pub(super) fn usable(scale: Scale, v: f64) -> bool {
    v.is_finite() && (scale == Scale::Linear || v > 0.0)
}

/// Linear axes stay within this magnitude, so that a range's width is finite.
const LINEAR_LIMIT: f64 = f64::MAX / 4.0;
/// Log axes stay within these decades, and span at most [`LOG_WIDTH`] of them (the
/// largest values kept): plotters' log axis takes time with the number of decades, and
/// a picture of more is not readable anyway.
const LOG_DECADES: (f64, f64) = (-300.0, 300.0);
const LOG_WIDTH: f64 = 40.0;

/// The data range of one axis, padded, never empty, of finite width, and wide enough for
/// the tick labels to tell apart: data spanning 1e308, a subnormal width, one point or all
/// values equal all give a range a chart can be drawn on in bounded time.
pub(crate) fn range(values: impl Iterator<Item = f64>, scale: Scale) -> (f64, f64) {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if lo > hi {
        return match scale {
            Scale::Linear => (0.0, 1.0),
            Scale::Log => (0.1, 10.0),
        };
    }
    match scale {
        Scale::Linear => {
            let (lo, hi) = (
                lo.clamp(-LINEAR_LIMIT, LINEAR_LIMIT),
                hi.clamp(-LINEAR_LIMIT, LINEAR_LIMIT),
            );
            let magnitude = lo.abs().max(hi.abs());
            // a width below a millionth of the values' magnitude (or subnormal) cannot be
            // labelled: such data are drawn as flat
            let pad = if hi - lo > 1e-6 * magnitude && hi - lo > 1e-300 {
                0.05 * (hi - lo)
            } else {
                0.5 * magnitude.clamp(1.0, LINEAR_LIMIT)
            };
            ((lo - pad).max(-2.0 * LINEAR_LIMIT), (hi + pad).min(2.0 * LINEAR_LIMIT))
        }
        Scale::Log => {
            let (llo, lhi) = (lo.log10(), hi.log10());
            let pad = if lhi - llo > 1e-6 { 0.05 * (lhi - llo) } else { 0.5 };
            let lhi = (lhi + pad).clamp(LOG_DECADES.0 + 1.0, LOG_DECADES.1);
            let llo = (llo - pad).clamp(LOG_DECADES.0.max(lhi - LOG_WIDTH), lhi - 1.0);
            (10f64.powf(llo), 10f64.powf(lhi))
        }
    }
}

/// Widens the shorter range of a linear-linear chart so both axes have the same units per
/// pixel of a plotting area `pw` by `ph` pixels.
pub(super) fn equalize(x: (f64, f64), y: (f64, f64), (pw, ph): (f64, f64)) -> ((f64, f64), (f64, f64)) {
    let (sx, sy) = ((x.1 - x.0) / pw, (y.1 - y.0) / ph);
    if sx > sy {
        let mid = 0.5 * (y.0 + y.1);
        let half = 0.5 * sx * ph;
        (x, (mid - half, mid + half))
    } else {
        let mid = 0.5 * (x.0 + x.1);
        let half = 0.5 * sy * pw;
        ((mid - half, mid + half), y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extreme_ranges_give_finite_resolvable_axes() {
        let cases: [&[f64]; 7] = [
            &[-1.7e308, 1.7e308],
            &[1e308, 1.7e308],
            &[0.0, 5e-324],
            &[1e-320, 2e-320],
            &[3.0],
            &[-0.577, -0.577, -0.577],
            &[1.0, 1.0 + f64::EPSILON],
        ];
        for values in cases {
            let (lo, hi) = range(values.iter().copied(), Scale::Linear);
            assert!(
                lo.is_finite() && hi.is_finite() && (hi - lo).is_finite(),
                "{values:?}: {lo} {hi}"
            );
            assert!(hi - lo > 1e-6 * lo.abs().max(hi.abs()), "{values:?}: {lo} {hi}");
            let positive: Vec<f64> = values.iter().map(|v| v.abs()).filter(|v| *v > 0.0).collect();
            let (lo, hi) = range(positive.iter().copied(), Scale::Log);
            assert!(lo > 0.0 && hi.is_finite() && hi / lo >= 9.99, "{values:?}: {lo} {hi}");
        }
    }
}
