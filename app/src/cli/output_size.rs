//! A word before a run whose CSV will be huge: how many rows and bytes, and how to write
//! fewer, said before the first row is written rather than found out from a full disk.

/// A run's CSV at or above this size (bytes) gets the note.
const HUGE_BYTES: f64 = 1e9;
/// The size a suggested `--every` aims below.
const COMFORTABLE_BYTES: f64 = 1e8;
/// About this many bytes per column of a row: the shortest digits of an `f64` that read
/// back to it (up to 17 significant digits, a sign, a point, an exponent) and a comma.
const BYTES_PER_COLUMN: f64 = 19.0;

/// The note for a run that will write about `rows` rows of `columns` columns to
/// `destination`, when that is [`HUGE_BYTES`] or more; `save_at` says the rows are output
/// times (where `--every` does not apply).
pub fn note(rows: f64, columns: usize, destination: &str, save_at: bool) -> Option<String> {
    let bytes = rows * (columns as f64 * BYTES_PER_COLUMN + 1.0);
    // NaN rows (an unknown count) write no note either
    if bytes.is_nan() || bytes < HUGE_BYTES {
        return None;
    }
    let fewer = if save_at {
        "a longer --save-at STEP writes fewer".to_string()
    } else {
        // a power of ten that brings the file to a comfortable size
        let every = 10f64.powf((bytes / COMFORTABLE_BYTES).log10().ceil());
        format!(
            "--every N writes one row in N steps (--every {every} about {})",
            size(bytes / every)
        )
    };
    Some(format!(
        "note: this run will write up to {rows} rows (about {}) to {destination}; {fewer}",
        size(bytes)
    ))
}

/// `7.4 GB`, `740 MB`, `74 kB`.
fn size(bytes: f64) -> String {
    let (value, unit) = [(1e12, "TB"), (1e9, "GB"), (1e6, "MB"), (1e3, "kB")]
        .into_iter()
        .find(|(scale, _)| bytes >= *scale)
        .map_or((bytes, "bytes"), |(scale, unit)| (bytes / scale, unit));
    if value >= 10.0 {
        format!("{value:.0} {unit}")
    } else {
        format!("{value:.1} {unit}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_huge_run_is_announced_with_a_way_to_write_less() {
        // `run harmonic --dt 1.0000001e-7`: t, x, v, energy for 99999990 steps
        assert_eq!(
            note(99999992.0, 4, "h.csv", false).unwrap(),
            "note: this run will write up to 99999992 rows (about 7.7 GB) to h.csv; --every N writes one row \
             in N steps (--every 100 about 77 MB)"
        );
        let times = note(1e7, 40, "stdout", true).unwrap();
        assert!(times.ends_with("a longer --save-at STEP writes fewer"), "{times}");
        assert_eq!(note(10001.0, 4, "h.csv", false), None);
    }

    #[test]
    fn sizes_read_as_people_write_them() {
        assert_eq!(size(7.4e9), "7.4 GB");
        assert_eq!(size(7.4e7), "74 MB");
        assert_eq!(size(512.0), "512 bytes");
    }
}
