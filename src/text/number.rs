//! Numbers in messages and tables, with the digits that matter.

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
mod tests {
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
