//! Ctrl-C during `stormer run`: the first one stops the run at the driver's next check
//! (within 1024 steps), the CSV is flushed and kept, and the command exits with code 130;
//! a second Ctrl-C ends the process at once.

use std::fmt;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Once;

/// The exit code of a command stopped by Ctrl-C (128 + SIGINT, the shells' convention).
pub const EXIT_CODE: u8 = 130;

static STOP: AtomicBool = AtomicBool::new(false);
static INSTALL: Once = Once::new();

/// The flag Ctrl-C sets, with the handler installed on first use. If the handler cannot
/// be installed, Ctrl-C keeps its default effect (the process ends; the CSV has the
/// records flushed so far).
pub fn flag() -> &'static AtomicBool {
    INSTALL.call_once(|| {
        let _ = ctrlc::set_handler(|| {
            if STOP.swap(true, Ordering::Relaxed) {
                // the second Ctrl-C: the user does not want to wait for the run to stop
                std::process::exit(i32::from(EXIT_CODE));
            }
        });
    });
    &STOP
}

/// A command stopped by the user: its message, and exit code [`EXIT_CODE`].
#[derive(Debug)]
pub struct StoppedByUser(pub String);

impl fmt::Display for StoppedByUser {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for StoppedByUser {}
