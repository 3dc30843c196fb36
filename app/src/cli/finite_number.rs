//! A finite number read from a part of a command-line argument.

use stormer::Error;

/// `part` of the value `whole` of `flag` as a finite number, or the error that names it
/// (`invalid --save-at: 'x' is not a finite number (in '0:x:1')`).
pub fn finite_number(flag: &str, whole: &str, part: &str) -> Result<f64, Error> {
    let part = part.trim();
    part.parse::<f64>()
        .ok()
        .filter(|x| x.is_finite())
        .ok_or_else(|| Error::invalid(flag, format!("'{part}' is not a finite number (in '{whole}')")))
}
