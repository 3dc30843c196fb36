//! How numbers are printed in messages: a fixed number of significant digits, trailing
//! zeros trimmed, and as many more digits as needed to tell two different values apart.

/// Formats `x` with at most `digits` significant digits (clamped to `1..=17`), trailing
/// zeros removed: `0.260416…` with 4 digits is `"0.2604"`, `0.25` is `"0.25"`, `3.0` is `"3"`.
///
/// Numbers with a decimal exponent in `-5..=16` are written positionally, others in
/// scientific notation (`"1.5e-7"`). Non-finite values print as `"NaN"`, `"inf"`, `"-inf"`.
pub fn format_significant(x: f64, digits: usize) -> String {
    if x.is_nan() {
        return "NaN".to_string();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf" } else { "-inf" }.to_string();
    }
    if x == 0.0 {
        return "0".to_string();
    }
    let digits = digits.clamp(1, 17);
    let sci = format!("{:.*e}", digits - 1, x.abs());
    let (mantissa, exponent) = match sci.split_once('e') {
        Some(parts) => parts,
        None => return sci,
    };
    let exponent: i64 = match exponent.parse() {
        Ok(e) => e,
        Err(_) => return sci,
    };
    let mut significand: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    while significand.len() > 1 && significand.ends_with('0') {
        significand.pop();
    }
    let sign = if x < 0.0 { "-" } else { "" };
    if (-5..=16).contains(&exponent) {
        // Number of digits before the decimal point.
        let point = exponent + 1;
        let len = significand.len() as i64;
        let body = if point <= 0 {
            format!("0.{}{}", "0".repeat((-point) as usize), significand)
        } else if point >= len {
            format!("{}{}", significand, "0".repeat((point - len) as usize))
        } else {
            let (int, frac) = significand.split_at(point as usize);
            format!("{int}.{frac}")
        };
        format!("{sign}{body}")
    } else {
        let (first, rest) = significand.split_at(1);
        if rest.is_empty() {
            format!("{sign}{first}e{exponent}")
        } else {
            format!("{sign}{first}.{rest}e{exponent}")
        }
    }
}

/// Formats `x` and `y` with the fewest significant digits, at least `min_digits`, that print
/// them differently (up to 17, enough for any two different `f64`). Returns both strings and
/// the number of digits used. Equal values print with `min_digits`.
pub fn format_distinct(x: f64, y: f64, min_digits: usize) -> (String, String, usize) {
    let min_digits = min_digits.clamp(1, 17);
    let mut digits = min_digits;
    loop {
        let (fx, fy) = (format_significant(x, digits), format_significant(y, digits));
        if fx != fy || digits >= 17 || x.to_bits() == y.to_bits() {
            return (fx, fy, digits);
        }
        digits += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn significant_digits() {
        assert_eq!(format_significant(25.0 / 96.0, 4), "0.2604");
        assert_eq!(format_significant(0.25, 4), "0.25");
        assert_eq!(format_significant(3.0, 4), "3");
        assert_eq!(format_significant(-1.0 / 3.0, 4), "-0.3333");
        assert_eq!(format_significant(31.0 / 30.0, 4), "1.033");
        assert_eq!(format_significant(12_345_678.0, 4), "12350000");
        assert_eq!(format_significant(1.5e-7, 4), "1.5e-7");
        assert_eq!(format_significant(0.000_012_34, 4), "0.00001234");
        assert_eq!(format_significant(9.99996, 4), "10");
        assert_eq!(format_significant(0.0, 4), "0");
        assert_eq!(format_significant(f64::NAN, 4), "NaN");
        assert_eq!(format_significant(f64::NEG_INFINITY, 4), "-inf");
        assert_eq!(format_significant(1e300, 0), "1e300");
    }

    #[test]
    fn distinct_values_get_more_digits() {
        let (a, b, d) = format_distinct(0.25 + 1e-11, 0.25, 4);
        assert_ne!(a, b);
        assert_eq!(b, "0.25");
        assert!(d > 4);
        let (a, b, d) = format_distinct(0.5, 0.6, 4);
        assert_eq!((a.as_str(), b.as_str(), d), ("0.5", "0.6", 4));
        let x = 0.1f64;
        let y = f64::from_bits(x.to_bits() + 1);
        let (a, b, _) = format_distinct(x, y, 4);
        assert_ne!(a, b);
    }
}
