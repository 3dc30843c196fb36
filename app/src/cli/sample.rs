//! A bounded copy of a run's records, for its pictures: every record while they fit,
//! then every second, fourth, ... (the stride doubles each time the copy fills), and
//! always the last one. Memory stays bounded whatever the run's length, and the pictures
//! never re-read the output (which may be a pipe, a device, or gone).

/// At most this many rows are kept: more than a picture's width in pixels, many times.
const MAX_ROWS: usize = 20_000;
/// At most this many numbers are kept (8 MB), for scenes with many bodies.
const MAX_CELLS: usize = 1 << 20;

/// The sampled records: `t`, the state's components, the energy when there is one.
#[derive(Debug, Clone)]
pub struct Sample {
    header: Vec<String>,
    capacity: usize,
    stride: u64,
    seen: u64,
    cells: Vec<f64>,
    last: Vec<f64>,
}

impl Sample {
    /// An empty sample of records with these columns.
    pub fn new(header: Vec<String>) -> Self {
        let width = header.len().max(1);
        Sample {
            capacity: (MAX_CELLS / width).clamp(2, MAX_ROWS),
            header,
            stride: 1,
            seen: 0,
            cells: Vec::new(),
            last: Vec::new(),
        }
    }

    /// The column names.
    pub fn header(&self) -> &[String] {
        &self.header
    }

    fn width(&self) -> usize {
        self.header.len().max(1)
    }

    /// Offers one record; missing columns (an energy the record lacks) are NaN.
    pub fn push(&mut self, t: f64, y: &[f64], energy: Option<f64>) {
        let width = self.width();
        self.last.clear();
        self.last.push(t);
        self.last.extend_from_slice(y);
        self.last.push(energy.unwrap_or(f64::NAN));
        self.last.resize(width, f64::NAN);
        if self.seen % self.stride == 0 {
            if self.cells.len() / width == self.capacity {
                self.halve();
            }
            if self.seen % self.stride == 0 {
                self.cells.extend_from_slice(&self.last);
            }
        }
        self.seen += 1;
    }

    /// Keeps every second row and doubles the stride.
    fn halve(&mut self) {
        let width = self.width();
        let rows = self.cells.len() / width;
        for (to, from) in (0..rows).step_by(2).enumerate() {
            self.cells.copy_within(from * width..(from + 1) * width, to * width);
        }
        self.cells.truncate(rows.div_ceil(2) * width);
        self.stride *= 2;
    }

    /// The kept rows in order, the last record included.
    pub fn rows(&self) -> Vec<&[f64]> {
        let mut rows: Vec<&[f64]> = self.cells.chunks(self.width()).collect();
        if self.seen > 0 && (self.seen - 1) % self.stride != 0 {
            rows.push(&self.last);
        }
        rows
    }

    /// Column `j` of the kept rows.
    pub fn column(&self, j: usize) -> Vec<f64> {
        self.rows()
            .iter()
            .map(|r| r.get(j).copied().unwrap_or(f64::NAN))
            .collect()
    }
}

#[cfg(test)]
#[allow(clippy::float_cmp)] // the sampled values are small integers, kept exactly
mod tests {
    use super::*;

    #[test]
    fn a_long_run_is_thinned_evenly_and_keeps_its_last_record() {
        let mut s = Sample::new(vec!["t".into(), "x".into()]);
        let n = 3 * MAX_ROWS as u64 + 7;
        for i in 0..n {
            s.push(i as f64, &[2.0 * i as f64], None);
        }
        let t = s.column(0);
        assert!(t.len() <= MAX_ROWS + 1, "{}", t.len());
        assert!(t.len() > MAX_ROWS / 2);
        let step = t[1] - t[0];
        assert!(
            t.windows(2).take(t.len() - 2).all(|w| w[1] - w[0] == step),
            "even spacing"
        );
        assert_eq!(*t.last().unwrap(), (n - 1) as f64);
        assert_eq!(s.column(1)[5], 2.0 * t[5]);
    }

    #[test]
    fn a_short_run_is_kept_whole() {
        let mut s = Sample::new(vec!["t".into(), "x".into(), "energy".into()]);
        for i in 0..10 {
            s.push(i as f64, &[0.5], Some(-1.0));
        }
        assert_eq!(s.rows().len(), 10);
        assert_eq!(s.rows()[9], &[9.0, 0.5, -1.0]);
    }

    #[test]
    fn many_columns_keep_memory_bounded() {
        let width = 600_001;
        let mut s = Sample::new((0..width).map(|i| i.to_string()).collect());
        let y = vec![1.0; width - 2];
        for i in 0..100 {
            s.push(i as f64, &y, Some(0.0));
        }
        assert!(s.cells.len() <= 2 * width.max(MAX_CELLS));
        assert_eq!(s.rows().last().unwrap()[0], 99.0);
    }
}
