//! Coefficient expressions: the arithmetic a method's coefficients are written in.
//!
//! `"1/6"`, `"- 3 / 73"`, `"1/2 - sqrt(3)/6"`, `"0.526001519587677318785587544488e-01"`,
//! `"2 ^ -3"`, `"1/(2 - 2^(1/3))"`, `"cbrt(2)"`. The grammar, loosest binding first:
//!
//! ```text
//! expr    = term (("+" | "-") term)*
//! term    = unary (("*" | "/") unary)*
//! unary   = ("+" | "-") unary | power
//! power   = primary (("^" | "**") unary)?        a fractional exponent needs a base > 0
//! primary = number | "(" expr ")" | ("sqrt" | "cbrt") "(" expr ")"
//! ```
//!
//! Whitespace is allowed anywhere between tokens, so the stringified token streams a
//! proc macro sees (`"sqrt (6)"`, `"2 * * 3"`) evaluate like their source.

use std::fmt;

/// Deepest nesting of parentheses, signs and exponents accepted (bounds the recursion).
const MAX_DEPTH: usize = 256;

/// Why a coefficient expression could not be evaluated, and where.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExprError {
    /// What went wrong, e.g. `"division by zero"`.
    pub message: String,
    /// Byte offset in the source string where the problem was found.
    pub offset: usize,
}

impl fmt::Display for ExprError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for ExprError {}

fn error(message: impl Into<String>, offset: usize) -> ExprError {
    ExprError {
        message: message.into(),
        offset,
    }
}

/// Evaluates a coefficient expression to the `f64` it denotes.
///
/// Accepted: integers (`"3"`, `"1_000"`), decimals with optional exponent (`"5.2e-2"`,
/// `"1."`, `".5"`, `"0.526001519587677318785587544488e-01"`), Rust numeric suffixes
/// (`"1.0f64"`, `"2f64"`, `"3u32"`; `f32` literals are still read as `f64`), `+ - * /`,
/// unary minus and plus, parentheses, `sqrt(x)`, `cbrt(x)`, and `x ^ e` or `x ** e`: any
/// integer exponent, or a fractional one of a positive base (`2^(1/3)`, the closed forms of
/// Yoshida's and Suzuki's weights). Whitespace is allowed anywhere between tokens.
///
/// Every decimal literal is converted as a whole by Rust's correctly rounded
/// `str::parse::<f64>`, so a literal yields the `f64` nearest to its exact value.
///
/// # Errors
///
/// Syntax errors, unknown names, `"division by zero"`, `"sqrt of a negative number"`, a
/// fractional power of a base <= 0, and any other non-finite intermediate or final result. The error
/// carries the byte offset in `src` of the offending token.
pub fn eval_coefficient(src: &str) -> Result<f64, ExprError> {
    let mut parser = Parser { src, pos: 0, depth: 0 };
    parser.skip_ws();
    if parser.at_end() {
        return Err(error("empty expression", 0));
    }
    let value = parser.expr()?;
    parser.skip_ws();
    if !parser.at_end() {
        return Err(parser.unexpected("an operator or the end of the expression"));
    }
    Ok(value)
}

/// A recursive-descent evaluator over the source string.
struct Parser<'a> {
    src: &'a str,
    pos: usize,
    depth: usize,
}

impl Parser<'_> {
    fn at_end(&self) -> bool {
        self.pos >= self.src.len()
    }

    fn peek(&self) -> Option<u8> {
        self.src.as_bytes().get(self.pos).copied()
    }

    fn peek_at(&self, pos: usize) -> Option<u8> {
        self.src.as_bytes().get(pos).copied()
    }

    fn current_char(&self) -> Option<char> {
        self.src.get(self.pos..).and_then(|rest| rest.chars().next())
    }

    fn skip_ws(&mut self) {
        while let Some(c) = self.current_char() {
            if !c.is_whitespace() {
                break;
            }
            self.pos += c.len_utf8();
        }
    }

    /// The position of the next non-whitespace character at or after `pos`.
    fn skip_ws_from(&self, mut pos: usize) -> usize {
        while let Some(c) = self.src.get(pos..).and_then(|rest| rest.chars().next()) {
            if !c.is_whitespace() {
                break;
            }
            pos += c.len_utf8();
        }
        pos
    }

    fn unexpected(&self, expected: &str) -> ExprError {
        match self.current_char() {
            None => error(format!("expected {expected} but the expression ends here"), self.pos),
            Some(c) => error(format!("expected {expected} but found '{c}'"), self.pos),
        }
    }

    fn enter(&mut self) -> Result<(), ExprError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            Err(error("expression nested too deeply", self.pos))
        } else {
            Ok(())
        }
    }

    fn leave(&mut self) {
        self.depth = self.depth.saturating_sub(1);
    }

    fn expr(&mut self) -> Result<f64, ExprError> {
        self.chain(b"+-", Self::term)
    }

    fn term(&mut self) -> Result<f64, ExprError> {
        self.chain(b"*/", Self::unary)
    }

    /// `operand (op operand)*` for the operators `ops` of one binding strength, evaluated
    /// from the left.
    fn chain(&mut self, ops: &[u8], operand: fn(&mut Self) -> Result<f64, ExprError>) -> Result<f64, ExprError> {
        let mut value = operand(self)?;
        loop {
            self.skip_ws();
            let op = self.pos;
            match self.peek() {
                Some(c) if ops.contains(&c) => {
                    self.pos += 1;
                    let rhs = operand(self)?;
                    value = apply(c, value, rhs, op)?;
                }
                _ => return Ok(value),
            }
        }
    }

    fn unary(&mut self) -> Result<f64, ExprError> {
        self.enter()?;
        self.skip_ws();
        let result = match self.peek() {
            Some(b'-') => {
                self.pos += 1;
                self.unary().map(|v| -v)
            }
            Some(b'+') => {
                self.pos += 1;
                self.unary()
            }
            _ => self.power(),
        };
        self.leave();
        result
    }

    fn power(&mut self) -> Result<f64, ExprError> {
        let base = self.primary()?;
        self.skip_ws();
        let op = self.pos;
        match self.peek() {
            Some(b'^') => self.pos += 1,
            Some(b'*') => {
                let next = self.skip_ws_from(self.pos + 1);
                if self.peek_at(next) != Some(b'*') {
                    return Ok(base);
                }
                self.pos = next + 1;
            }
            _ => return Ok(base),
        }
        self.skip_ws();
        let exponent_at = self.pos;
        let exponent = self.unary()?;
        if exponent.fract() == 0.0 && exponent.abs() <= f64::from(i32::MAX) {
            // Checked: an integer within the range of i32.
            let n = exponent as i32;
            if base == 0.0 && n < 0 {
                return Err(error("division by zero", op));
            }
            return finite(base.powi(n), op);
        }
        if base <= 0.0 {
            return Err(error(
                format!("a fractional power needs a base > 0, got {base} ^ {exponent}"),
                exponent_at,
            ));
        }
        // thirds and halves through the correctly rounded roots: 2^(1/3) is cbrt(2) to the bit
        let root = |k: f64, r: fn(f64) -> f64| {
            let m = exponent * k;
            (m.fract() == 0.0 && m.abs() <= 64.0).then(|| r(base).powi(m as i32))
        };
        let value = root(2.0, f64::sqrt)
            .or_else(|| root(3.0, f64::cbrt))
            .unwrap_or_else(|| base.powf(exponent));
        finite(value, op)
    }

    fn primary(&mut self) -> Result<f64, ExprError> {
        self.skip_ws();
        let start = self.pos;
        match self.peek() {
            Some(b'0'..=b'9') => self.number(),
            Some(b'.') if matches!(self.peek_at(self.pos + 1), Some(b'0'..=b'9')) => self.number(),
            Some(b'(') => self.parenthesized(start),
            Some(c) if c.is_ascii_alphabetic() || c == b'_' => {
                let name = self.identifier();
                let cube = match name {
                    "sqrt" => false,
                    "cbrt" => true,
                    _ => {
                        return Err(error(
                            format!(
                                "unknown name `{name}` (only numbers, + - * / ^, parentheses, sqrt(...) and \
                                 cbrt(...) are allowed)"
                            ),
                            start,
                        ))
                    }
                };
                self.skip_ws();
                if self.peek() != Some(b'(') {
                    return Err(self.unexpected(if cube { "'(' after cbrt" } else { "'(' after sqrt" }));
                }
                let value = self.parenthesized(self.pos)?;
                if cube {
                    return Ok(value.cbrt());
                }
                if value < 0.0 {
                    return Err(error("sqrt of a negative number", start));
                }
                Ok(value.sqrt())
            }
            _ => Err(self.unexpected("a number, '(' or sqrt(...)")),
        }
    }

    /// The expression between the `(` at byte `open`, the current one, and its `)`.
    fn parenthesized(&mut self, open: usize) -> Result<f64, ExprError> {
        self.enter()?;
        self.pos += 1;
        let value = self.expr()?;
        self.close(open)?;
        self.leave();
        Ok(value)
    }

    /// Consumes the `)` matching the `(` at byte `open`.
    fn close(&mut self, open: usize) -> Result<(), ExprError> {
        self.skip_ws();
        if self.peek() == Some(b')') {
            self.pos += 1;
            Ok(())
        } else {
            Err(self.unexpected(&format!("')' to close the '(' at offset {open}")))
        }
    }

    fn identifier(&mut self) -> &str {
        let start = self.pos;
        while matches!(self.peek(), Some(c) if c.is_ascii_alphanumeric() || c == b'_') {
            self.pos += 1;
        }
        self.src.get(start..self.pos).unwrap_or("")
    }

    fn skip_digits(&mut self) {
        while matches!(self.peek(), Some(b'0'..=b'9' | b'_')) {
            self.pos += 1;
        }
    }

    /// A numeric literal: digits, optional fraction, optional exponent, optional suffix.
    fn number(&mut self) -> Result<f64, ExprError> {
        let start = self.pos;
        self.skip_digits();
        let mut integer = true;
        if self.peek() == Some(b'.') {
            integer = false;
            self.pos += 1;
            self.skip_digits();
        }
        if matches!(self.peek(), Some(b'e' | b'E')) {
            let mut p = self.pos + 1;
            if matches!(self.peek_at(p), Some(b'+' | b'-')) {
                p += 1;
            }
            if matches!(self.peek_at(p), Some(b'0'..=b'9')) {
                integer = false;
                self.pos = p;
                self.skip_digits();
            }
        }
        let literal_end = self.pos;
        let suffix = self.identifier().to_string();
        let float_suffix = matches!(suffix.as_str(), "" | "f64" | "f32");
        let int_suffix = matches!(
            suffix.as_str(),
            "i8" | "i16" | "i32" | "i64" | "i128" | "isize" | "u8" | "u16" | "u32" | "u64" | "u128" | "usize"
        );
        if !(float_suffix || int_suffix && integer) {
            return Err(error(format!("invalid suffix `{suffix}` on a number"), literal_end));
        }
        let literal: String = self
            .src
            .get(start..literal_end)
            .unwrap_or("")
            .chars()
            .filter(|&c| c != '_')
            .collect();
        match literal.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(v),
            Ok(_) => Err(error("number too large for f64", start)),
            Err(_) => Err(error(format!("invalid number `{literal}`"), start)),
        }
    }
}

/// Rejects overflow to infinity (and NaN) produced by the operator at `offset`.
/// `left op right` for a binary operator `+ - * /` at byte `at`: a division by zero or a
/// result too large is an error there.
fn apply(op: u8, left: f64, right: f64, at: usize) -> Result<f64, ExprError> {
    let value = match op {
        b'+' => left + right,
        b'-' => left - right,
        b'*' => left * right,
        _ if right == 0.0 => return Err(error("division by zero", at)),
        _ => left / right,
    };
    finite(value, at)
}

fn finite(value: f64, offset: usize) -> Result<f64, ExprError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(error("result too large for f64", offset))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ok(src: &str) -> f64 {
        match eval_coefficient(src) {
            Ok(v) => v,
            Err(e) => panic!("{src:?}: {e} at {}", e.offset),
        }
    }

    fn err(src: &str) -> ExprError {
        match eval_coefficient(src) {
            Ok(v) => panic!("{src:?} evaluated to {v}, expected an error"),
            Err(e) => e,
        }
    }

    fn same(x: f64, y: f64) -> bool {
        x.to_bits() == y.to_bits()
    }

    /// Every `(src, value)` of `cases` evaluates to `value`, to the bit.
    fn assert_exact(cases: &[(&str, f64)]) {
        for &(src, value) in cases {
            let got = ok(src);
            assert!(same(got, value), "{src:?} evaluated to {got:e}, expected {value:e}");
        }
    }

    #[test]
    fn literals_are_correctly_rounded() {
        let src = "0.526001519587677318785587544488e-01";
        let expected: f64 = src.parse().unwrap_or(f64::NAN);
        assert_exact(&[
            (src, expected),
            ("5.2e-2", 0.052),
            ("5.2E-2", 0.052),
            ("1.", 1.0),
            (".5", 0.5),
            ("3", 3.0),
            ("1e3", 1000.0),
            ("1.5e+2", 150.0),
            // A literal digit by digit would be 0.1 * 3 style; the whole literal is exact.
            ("0.3", 0.3),
            ("2.2250738585072014e-308", f64::MIN_POSITIVE),
        ]);
    }

    #[test]
    fn rust_suffixes_and_underscores() {
        assert_exact(&[
            ("1.0f64", 1.0),
            ("2f64", 2.0),
            ("1_000", 1000.0),
            ("1_000.5_0f64", 1000.5),
            ("3u32", 3.0),
            ("0.5f32", 0.5),
        ]);
        assert_eq!(err("1.5u32").message, "invalid suffix `u32` on a number");
        assert_eq!(err("2x").offset, 1);
    }

    #[test]
    fn arithmetic() {
        assert_exact(&[
            ("-3/73", -3.0 / 73.0),
            ("- 3 / 73", -3.0 / 73.0),
            ("1 / 6", 1.0 / 6.0),
            ("1/2 - sqrt(3)/6", 0.5 - 3f64.sqrt() / 6.0),
            ("sqrt (6)", 6f64.sqrt()),
            ("( 1 + 2 ) * 3", 9.0),
            ("1 + 2 * 3", 7.0),
            ("8 / 4 / 2", 1.0),
            ("1 - 2 - 3", -4.0),
            ("+4 - -2", 6.0),
            ("(16 - sqrt(6)) / 36", (16.0 - 6f64.sqrt()) / 36.0),
            ("\t1\n/\u{a0}4 ", 0.25),
        ]);
    }

    #[test]
    fn powers() {
        assert_exact(&[
            ("2^3", 8.0),
            ("2 ** 3", 8.0),
            ("2 * * 3", 8.0),
            ("2^-2", 0.25),
            ("-2^2", -4.0),
            ("2^3^2", 512.0),
            ("(1/2)^2 * 4", 1.0),
            ("2^(1/3)", 2f64.cbrt()),
            ("cbrt(2)", 2f64.cbrt()),
            ("2^0.5", 2f64.sqrt()),
            ("4^(2/3)", 4f64.cbrt().powi(2)),
            ("cbrt(-8)", -2.0),
            ("2^0.3", 2f64.powf(0.3)),
            ("1/(2 - 2^(1/3))", 1.0 / (2.0 - 2f64.cbrt())),
        ]);
        let e = err("(-2)^(1/3)");
        assert_eq!(
            e.message,
            "a fractional power needs a base > 0, got -2 ^ 0.3333333333333333"
        );
        assert_eq!(e.offset, 5);
        assert_eq!(err("0^0.5").message, "a fractional power needs a base > 0, got 0 ^ 0.5");
        assert_eq!(err("0^-1").message, "division by zero");
        assert_eq!(err("2^99999").message, "result too large for f64");
    }

    #[test]
    fn errors() {
        let e = err("1/0");
        assert_eq!((e.message.as_str(), e.offset), ("division by zero", 1));
        assert_eq!(e.to_string(), "division by zero");
        let e = err("abc");
        assert_eq!(e.offset, 0);
        assert!(e.message.contains("unknown name `abc`"), "{e}");
        let e = err("sqrt(-1)");
        assert_eq!((e.message.as_str(), e.offset), ("sqrt of a negative number", 0));
        assert_eq!(err("").message, "empty expression");
        assert_eq!(err("   ").message, "empty expression");
        let e = err("1 +");
        assert_eq!(e.offset, 3);
        assert!(e.message.contains("ends here"), "{e}");
        let e = err("(1 + 2");
        assert_eq!(e.offset, 6);
        assert!(e.message.contains("')'"), "{e}");
        assert_eq!(err("1 2").offset, 2);
        assert_eq!(err("1 / (2 - 2)").offset, 2);
        assert_eq!(err("1e999").message, "number too large for f64");
        assert_eq!(err("1e308 * 10").message, "result too large for f64");
        assert_eq!(err("sqrt 4").offset, 5);
        assert_eq!(err("é").offset, 0);
        assert_eq!(err("1 + é").offset, 4);
        assert_eq!(err("1e").offset, 1);
        assert_eq!(err(".").offset, 0);
        assert_eq!(err("*2").offset, 0);
    }

    #[test]
    fn deep_nesting_is_an_error_not_a_crash() {
        let deep = format!("{}1{}", "(".repeat(100_000), ")".repeat(100_000));
        assert_eq!(err(&deep).message, "expression nested too deeply");
        let signs = format!("{}1", "-".repeat(100_000));
        assert_eq!(err(&signs).message, "expression nested too deeply");
        let powers = format!("2{}", "^2".repeat(100_000));
        assert_eq!(err(&powers).message, "expression nested too deeply");
        assert!(same(ok(&format!("{}1{}", "(".repeat(50), ")".repeat(50))), 1.0));
    }
}
