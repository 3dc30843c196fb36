//! Signals during `stormer run`: the first SIGINT (Ctrl-C), SIGTERM or SIGHUP stops the run
//! at the driver's next check (within a second whatever a step costs; one after the last
//! step still makes it a stopped run, which never exits 0); the CSV is flushed and kept, a message
//! names the file and the last time written, and the command exits with 128 + the signal's
//! number, the shells' convention. A run that writes checkpoints (`--checkpoint`) stops on
//! the pause flag the signals raise with the stop flag, and writes its checkpoint before it
//! exits. A second signal ends the process at once.

use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
use std::fmt;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, OnceLock};

/// The signals that stop a run and keep its output.
const HANDLED: [i32; 3] = [SIGINT, SIGTERM, SIGHUP];

struct Handlers {
    stop: Arc<AtomicBool>,
    /// Raised with `stop` by the signals, and by a checkpoint falling due: the flag a run
    /// that writes checkpoints stops on (it writes one, then goes on unless `stop` is set).
    pause: Arc<AtomicBool>,
    which: Arc<AtomicUsize>,
}

static HANDLERS: OnceLock<Handlers> = OnceLock::new();

fn handlers() -> &'static Handlers {
    HANDLERS.get_or_init(|| {
        let h = Handlers {
            stop: Arc::new(AtomicBool::new(false)),
            pause: Arc::new(AtomicBool::new(false)),
            which: Arc::new(AtomicUsize::new(0)),
        };
        for signal in HANDLED {
            // In registration order: a signal arriving after the first ends the process;
            // the first records which signal it was, then raises the flag the driver reads.
            // If a handler cannot be installed the signal keeps its default effect (the
            // process ends; the CSV holds the whole rows flushed so far).
            let _ = signal_hook::flag::register_conditional_shutdown(signal, 128 + signal, h.stop.clone());
            let _ = signal_hook::flag::register_usize(signal, h.which.clone(), signal as usize);
            let _ = signal_hook::flag::register(signal, h.pause.clone());
            let _ = signal_hook::flag::register(signal, h.stop.clone());
        }
        h
    })
}

/// The flag the handled signals set, with the handlers installed on first use.
pub fn flag() -> &'static AtomicBool {
    &handlers().stop
}

/// The flag the handled signals set with [`flag`], and that a run writing checkpoints
/// also raises when one falls due; the run lowers it after each checkpoint.
pub fn pause_flag() -> &'static AtomicBool {
    &handlers().pause
}

/// The signal that raised [`flag`]: SIGINT when none was recorded (the flag was set
/// some other way).
pub fn received() -> Signal {
    let which = HANDLERS.get().map_or(0, |h| h.which.load(Ordering::Relaxed));
    Signal(
        i32::try_from(which)
            .ok()
            .filter(|s| HANDLED.contains(s))
            .unwrap_or(SIGINT),
    )
}

/// One of the handled signals.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Signal(i32);

impl Signal {
    /// How the user knows it: Ctrl-C for SIGINT, the signal's name otherwise.
    pub fn name(self) -> &'static str {
        match self.0 {
            SIGTERM => "SIGTERM",
            SIGHUP => "SIGHUP",
            _ => "Ctrl-C",
        }
    }

    /// 128 + the signal's number.
    pub fn exit_code(self) -> u8 {
        u8::try_from(128 + self.0).unwrap_or(130)
    }
}

/// A command stopped by a signal: its message, and the exit code of that signal.
#[derive(Debug)]
pub struct StoppedByUser {
    /// What was kept, and where.
    pub message: String,
    /// The signal.
    pub signal: Signal,
}

impl fmt::Display for StoppedByUser {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl std::error::Error for StoppedByUser {}
