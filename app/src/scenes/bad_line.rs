//! For the scene files' tests: the error of a good scene file with one line made bad.

use super::parse;
use stormer::Error;

/// The error message for the scene text `good`, read from `file` (`NAME.toml`), with line
/// `line` (1-based) replaced by `text`: a scene error that names the file, on one line.
pub(super) fn error_with_line(good: &str, file: &str, line: usize, text: &str) -> String {
    let mut lines: Vec<&str> = good.lines().collect();
    lines[line - 1] = text;
    scene_error(&lines.join("\n"), file)
}

/// The error message for the scene text `bad`, read from `file` (`NAME.toml`): a scene
/// error that names the file, on one line.
fn scene_error(bad: &str, file: &str) -> String {
    let name = file.trim_end_matches(".toml");
    let err = parse(bad, file, name).unwrap_err();
    assert!(matches!(err, Error::Scene { .. }), "{err:?}");
    let message = err.to_string();
    assert!(message.starts_with(&format!("scene {file}: ")), "{message}");
    assert!(!message.contains('\n'), "one line: {message}");
    message
}

/// For every `(line, text, expected)` of `cases`: the scene `good` read from `file`, with
/// line `line` replaced by `text`, is refused with a message containing `expected`.
pub(super) fn assert_bad_lines(good: &str, file: &str, cases: &[(usize, &str, &str)]) {
    for &(line, text, expected) in cases {
        let message = error_with_line(good, file, line, text);
        assert!(message.contains(expected), "{text}: {message}");
    }
}

/// For every `(from, to, expected)` of `cases`: `good` holds `from`, and the scene `good`
/// read from `file` with `from` replaced by `to` is refused with a message that names a
/// line and contains `expected`.
pub(super) fn assert_bad_replacements(good: &str, file: &str, cases: &[(&str, &str, &str)]) {
    for &(from, to, expected) in cases {
        assert!(good.contains(from), "{from}");
        let message = scene_error(&good.replace(from, to), file);
        assert!(message.contains(expected), "{to}: {message}");
        assert!(message.contains("line "), "{to}: {message}");
    }
}
