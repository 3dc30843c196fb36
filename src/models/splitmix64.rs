//! A seeded sequence of numbers that is the same on every platform: many particles drawn
//! reproducibly (the scene files' `count`, the tests and benchmarks of many particles).

/// SplitMix64 (Steele, Lea and Flood 2014): a 64-bit state, numbers in `[-1, 1)` with 53
/// bits, the same sequence on every platform.
///
/// ```
/// use stormer::models::SplitMix64;
/// let xs: Vec<f64> = SplitMix64::new(7).take(1000).collect();
/// assert!(xs.iter().all(|x| (-1.0..1.0).contains(x)));
/// assert_eq!(xs, SplitMix64::new(7).take(1000).collect::<Vec<_>>());
/// ```
#[derive(Debug, Clone)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// The sequence from `seed`.
    pub fn new(seed: u64) -> Self {
        SplitMix64(seed)
    }

    /// The next number.
    pub fn draw(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

/// The numbers one after the other, without end.
impl Iterator for SplitMix64 {
    type Item = f64;

    fn next(&mut self) -> Option<f64> {
        Some(self.draw())
    }
}

#[cfg(test)]
mod tests {
    use super::SplitMix64;

    /// The first outputs of SplitMix64 from seed 0 (the reference C code's `next()` with
    /// `x = 0`: 0xE220A8397B1DCDAF, 0x6E789E6AA1B965F4), in `[-1, 1)`.
    #[test]
    fn the_generator_is_splitmix64() {
        let mut s = SplitMix64::new(0);
        let expect = |bits: u64| (bits >> 11) as f64 / (1u64 << 52) as f64 - 1.0;
        assert_eq!(s.draw().to_bits(), expect(0xE220_A839_7B1D_CDAF).to_bits());
        assert_eq!(s.draw().to_bits(), expect(0x6E78_9E6A_A1B9_65F4).to_bits());
    }
}
