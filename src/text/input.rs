//! Reading a user's text file (a scene, a method file, a study's shard) with a bound: at
//! most [`limit`] bytes are ever held, so that `/dev/zero`, a runaway pipe or a file of
//! gigabytes is refused quickly instead of filling the memory.

use std::io::Read;
use std::path::Path;

/// The default bound on an input file: 64 MiB, far above any scene or method file
/// (an N-body scene of 10^5 bodies is about 12 MiB).
pub const DEFAULT_LIMIT_MIB: u64 = 64;

/// The environment variable that raises (or lowers) the bound, in MiB.
pub const LIMIT_VARIABLE: &str = "STORMER_INPUT_LIMIT_MIB";

/// The bound in bytes: [`LIMIT_VARIABLE`] if it holds a whole number of MiB `>= 1`,
/// otherwise [`DEFAULT_LIMIT_MIB`].
pub fn limit() -> u64 {
    std::env::var(LIMIT_VARIABLE)
        .ok()
        .and_then(|v| v.trim().parse::<u64>().ok())
        .filter(|&mib| mib >= 1)
        .unwrap_or(DEFAULT_LIMIT_MIB)
        .saturating_mul(1 << 20)
}

/// The text of the file at `path` (a regular file, a pipe, `/dev/stdin`...), read up to
/// [`limit`] bytes. The error is the reason alone (the caller names the file): the bound
/// and how to raise it, a NUL byte (not a text file: stops `/dev/zero` at once), bytes
/// that are not UTF-8 (with their line), or the system's reason.
///
/// ```
/// let dir = std::env::temp_dir().join(format!("stormer-input-doc-{}", std::process::id()));
/// std::fs::create_dir_all(&dir).unwrap();
/// let path = dir.join("a.toml");
/// std::fs::write(&path, "x = 1\n").unwrap();
/// assert_eq!(stormer::text::read_text(&path).unwrap(), "x = 1\n");
/// std::fs::write(&path, b"x = 1\n\xff\n").unwrap();
/// assert!(stormer::text::read_text(&path).unwrap_err().contains("line 2"));
/// std::fs::remove_dir_all(&dir).unwrap();
/// ```
pub fn read_text(path: &Path) -> Result<String, String> {
    read_text_within(path, limit())
}

/// [`read_text`] with the bound `limit` in bytes.
pub fn read_text_within(path: &Path, limit: u64) -> Result<String, String> {
    let too_large = || {
        format!(
            "the file is larger than {}, the limit on scene, method and shard files; \
             set {LIMIT_VARIABLE} to a larger number of MiB to read it",
            mib(limit)
        )
    };
    let file = std::fs::File::open(path).map_err(|e| format!("cannot read the file: {e}"))?;
    let meta = file.metadata().map_err(|e| format!("cannot read the file: {e}"))?;
    if meta.is_dir() {
        return Err("cannot read the file: it is a directory".into());
    }
    if meta.is_file() && meta.len() > limit {
        return Err(too_large());
    }
    let mut bytes = Vec::new();
    let mut chunk = vec![0u8; 1 << 16];
    let mut reader = file.take(limit + 1);
    loop {
        let n = match reader.read(&mut chunk) {
            Ok(0) => break,
            Ok(n) => n,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(format!("cannot read the file: {e}")),
        };
        if let Some(k) = chunk[..n].iter().position(|&b| b == 0) {
            let offset = bytes.len() + k;
            bytes.extend_from_slice(&chunk[..k]);
            return Err(format!(
                "line {}: a NUL byte (offset {offset}): this is not a text file",
                line_of(&bytes, offset)
            ));
        }
        bytes.extend_from_slice(&chunk[..n]);
        if bytes.len() as u64 > limit {
            return Err(too_large());
        }
    }
    String::from_utf8(bytes).map_err(|e| {
        let offset = e.utf8_error().valid_up_to();
        format!(
            "line {}: bytes that are not UTF-8 text (offset {offset})",
            line_of(e.as_bytes(), offset)
        )
    })
}

/// The 1-based line of byte `offset`.
fn line_of(bytes: &[u8], offset: usize) -> usize {
    bytes[..offset.min(bytes.len())].iter().filter(|&&b| b == b'\n').count() + 1
}

/// `64 MiB`, or the bytes when they are not a whole number of MiB.
fn mib(bytes: u64) -> String {
    if bytes % (1 << 20) == 0 {
        format!("{} MiB", bytes >> 20)
    } else {
        format!("{bytes} bytes")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str, bytes: &[u8]) -> std::path::PathBuf {
        let dir = std::env::temp_dir().join(format!("stormer-input-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(name);
        std::fs::write(&path, bytes).unwrap();
        path
    }

    #[test]
    fn a_file_over_the_bound_is_refused_with_the_bound_and_how_to_raise_it() {
        let path = scratch("big.toml", &[b'#'; 100]);
        let message = read_text_within(&path, 64).unwrap_err();
        assert!(message.contains("larger than 64 bytes"), "{message}");
        assert!(message.contains(LIMIT_VARIABLE), "{message}");
        assert_eq!(read_text_within(&path, 100).unwrap().len(), 100);
    }

    #[test]
    fn devices_and_pipes_are_read_through_the_bound() {
        // /dev/zero: stopped at its first byte; /dev/urandom holds a NUL within a few KiB
        // or fails UTF-8 at once; neither is read to the bound
        let zero = read_text(Path::new("/dev/zero")).unwrap_err();
        assert!(zero.contains("NUL byte (offset 0)"), "{zero}");
        let random = read_text_within(Path::new("/dev/urandom"), 1 << 20).unwrap_err();
        assert!(random.contains("NUL") || random.contains("not UTF-8"), "{random}");
        // a directory and a missing file
        let dir = read_text(&std::env::temp_dir()).unwrap_err();
        assert!(dir.contains("directory"), "{dir}");
        let missing = read_text(Path::new("/no/such/file.toml")).unwrap_err();
        assert!(missing.starts_with("cannot read the file"), "{missing}");
    }

    /// A pipe that never ends (a writer that loops until the reader leaves) is read up
    /// to the bound and refused.
    #[cfg(unix)]
    #[test]
    fn an_endless_pipe_stops_at_the_bound() {
        use std::io::Write;
        let dir = std::env::temp_dir().join(format!("stormer-input-fifo-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let fifo = dir.join("endless");
        let made = std::process::Command::new("mkfifo").arg(&fifo).status().unwrap();
        assert!(made.success());
        let writer_path = fifo.clone();
        let writer = std::thread::spawn(move || {
            let mut w = std::fs::OpenOptions::new().write(true).open(writer_path).unwrap();
            let line = [b'#'; 4096];
            while w.write_all(&line).is_ok() {}
        });
        let message = read_text_within(&fifo, 1 << 20).unwrap_err();
        assert!(message.contains("larger than 1 MiB"), "{message}");
        writer.join().unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn bytes_that_are_not_text_are_named_with_their_line() {
        let path = scratch("nul.toml", b"a = 1\nb = 2\0\n");
        let message = read_text(&path).unwrap_err();
        assert!(message.starts_with("line 2: a NUL byte (offset 11)"), "{message}");
        let path = scratch("latin1.toml", b"a = 1\n\nname = \"\xe9\"\n");
        let message = read_text(&path).unwrap_err();
        assert!(message.starts_with("line 3: bytes that are not UTF-8"), "{message}");
    }

    #[test]
    fn the_bound_is_stated_in_mib() {
        assert_eq!(mib(64 << 20), "64 MiB");
        assert_eq!(mib(100), "100 bytes");
        assert!(limit() >= 1 << 20);
    }
}
