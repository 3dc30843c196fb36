//! Mutations of valid input files for the proptest mutation tests: byte flips, deletions,
//! duplications, hostile values (huge numbers, NaN, unicode, TOML syntax) put in place of a
//! number or inserted anywhere, truncation. Shared by the tests of every reader.

#![allow(dead_code)] // each test binary uses its part

use proptest::prelude::*;

/// One edit; positions are taken modulo the text's length.
#[derive(Debug, Clone)]
pub enum Edit {
    /// XOR the byte at a position with a non-zero mask.
    Flip(usize, u8),
    /// Delete up to `n` bytes from a position.
    Delete(usize, usize),
    /// Insert a copy of up to `n` bytes from a position right after them.
    Duplicate(usize, usize),
    /// Insert a hostile string at a position.
    Insert(usize, &'static str),
    /// Replace the k-th number of the text with a hostile string.
    Number(usize, &'static str),
    /// Cut the text at a position.
    Truncate(usize),
}

/// Values no reader should trust: non-finite and out-of-range numbers, integers past
/// 64 bits, unicode (combining, bidi, astral, BOM), NUL, and bits of syntax.
pub const HOSTILE: &[&str] = &[
    "nan",
    "-nan",
    "inf",
    "-inf",
    "NaN",
    "1e309",
    "-1e309",
    "1e-320",
    "0",
    "-0.0",
    "-1",
    "1e300",
    "-1e300",
    "18446744073709551616",
    "-9223372036854775809",
    "9223372036854775807",
    "0.1e",
    "1_000",
    "0x10",
    "\"\"",
    "\"1.0\"",
    "true",
    "[]",
    "[[1, 2], 3]",
    "{}",
    "é",
    "e\u{301}",
    "\u{202e}",
    "\u{1d518}\u{1d52b}",
    "\u{feff}",
    "\0",
    "\t",
    "[",
    "]]",
    "\"",
    "'''",
    "\\u0000",
    "=",
    "\n",
    "#",
    "\n[run]\n",
    "\n[[bodies]]\n",
    "\n[[method]]\n",
    "1979-05-27T07:32:00Z",
];

/// Mutated inputs per reader in `cargo test` (issue 18 asks for at least 2000).
pub const CASES: u32 = 2000;

/// Mutated inputs per reader in the ignored long runs (`-- --ignored`).
pub const LONG_RUN: u32 = 100_000;

/// `cases` cases, no failure file written (a failing case prints its input instead).
pub fn config(cases: u32) -> ProptestConfig {
    ProptestConfig {
        cases,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

/// An edit of any kind.
pub fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        (any::<usize>(), 1..=255u8).prop_map(|(p, x)| Edit::Flip(p, x)),
        (any::<usize>(), 1..40usize).prop_map(|(p, n)| Edit::Delete(p, n)),
        (any::<usize>(), 1..120usize).prop_map(|(p, n)| Edit::Duplicate(p, n)),
        (any::<usize>(), proptest::sample::select(HOSTILE)).prop_map(|(p, s)| Edit::Insert(p, s)),
        (any::<usize>(), proptest::sample::select(HOSTILE)).prop_map(|(k, s)| Edit::Number(k, s)),
        (any::<usize>()).prop_map(Edit::Truncate),
    ]
}

/// One to four edits.
pub fn edits() -> impl Strategy<Value = Vec<Edit>> {
    proptest::collection::vec(edit(), 1..5)
}

/// The byte ranges of the numbers of `text` (runs of digits, signs, dots and exponents
/// that start with a digit or a sign).
fn numbers(text: &[u8]) -> Vec<(usize, usize)> {
    let mut found = Vec::new();
    let mut i = 0;
    while i < text.len() {
        let starts = text[i].is_ascii_digit()
            || (matches!(text[i], b'-' | b'+') && text.get(i + 1).is_some_and(u8::is_ascii_digit));
        let after_word = i > 0 && (text[i - 1].is_ascii_alphanumeric() || text[i - 1] == b'_');
        if starts && !after_word {
            let start = i;
            i += 1;
            while i < text.len() && (text[i].is_ascii_alphanumeric() || matches!(text[i], b'.' | b'-' | b'+' | b'_')) {
                i += 1;
            }
            found.push((start, i));
        } else {
            i += 1;
        }
    }
    found
}

/// `text` after `edits`, as bytes (a flip can leave UTF-8).
pub fn apply(text: &str, edits: &[Edit]) -> Vec<u8> {
    let mut bytes = text.as_bytes().to_vec();
    for e in edits {
        let at = |p: usize, len: usize| if len == 0 { 0 } else { p % len };
        let len = bytes.len();
        match *e {
            Edit::Flip(p, x) if len > 0 => bytes[at(p, len)] ^= x,
            Edit::Delete(p, n) if len > 0 => {
                let start = at(p, len);
                bytes.drain(start..(start + n).min(len));
            }
            Edit::Duplicate(p, n) if len > 0 => {
                let start = at(p, len);
                let copy = bytes[start..(start + n).min(len)].to_vec();
                let end = start + copy.len();
                bytes.splice(end..end, copy);
            }
            Edit::Insert(p, s) => {
                let i = at(p, len + 1);
                bytes.splice(i..i, s.bytes());
            }
            Edit::Number(k, s) => {
                let spans = numbers(&bytes);
                if !spans.is_empty() {
                    let (a, b) = spans[k % spans.len()];
                    bytes.splice(a..b, s.bytes());
                }
            }
            Edit::Truncate(p) => bytes.truncate(at(p, len + 1)),
            _ => {}
        }
    }
    bytes
}

/// The keys and table names of a TOML text (two characters or more), which an error
/// about it may name.
pub fn keys(text: &str) -> Vec<String> {
    let mut keys: Vec<String> = text
        .lines()
        .filter_map(|l| {
            let l = l.trim().trim_start_matches('[').trim_end_matches(']');
            let key = l.split('=').next()?.trim();
            let ok = key.len() >= 2 && key.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
            ok.then(|| key.to_string())
        })
        .collect();
    keys.sort();
    keys.dedup();
    keys
}

/// `word` appears in `message` as a whole word.
pub fn names(message: &str, word: &str) -> bool {
    message.match_indices(word).any(|(i, _)| {
        let before = message[..i].chars().next_back();
        let after = message[i + word.len()..].chars().next();
        let boundary = |c: Option<char>| c.map_or(true, |c| !(c.is_alphanumeric() || c == '_'));
        boundary(before) && boundary(after)
    })
}

/// The error names a line, or a key of the valid file it was made from.
pub fn names_a_line_or_field(message: &str, keys: &[String]) -> bool {
    message.contains("line ") || keys.iter().any(|k| names(message, k))
}
