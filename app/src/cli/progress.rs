//! A progress bar for long runs (indicatif): shown only when stderr is a terminal and only
//! once a run has lasted a second, so quick runs and scripts see nothing.

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::time::{Duration, Instant};

/// Progress of a run from `t0` to `t_end`, updated at each record.
pub struct Progress {
    start: Instant,
    t0: f64,
    t_end: f64,
    bar: Option<ProgressBar>,
    enabled: bool,
}

/// Positions on the bar.
const TICKS: u64 = 1000;

impl Progress {
    /// A bar for a run over `[t0, t_end]` (silent when stderr is not a terminal).
    pub fn new(t0: f64, t_end: f64) -> Self {
        Progress {
            start: Instant::now(),
            t0,
            t_end,
            bar: None,
            enabled: std::io::stderr().is_terminal(),
        }
    }

    /// The run has reached `t`.
    pub fn update(&mut self, t: f64) {
        if !self.enabled {
            return;
        }
        if self.bar.is_none() && self.start.elapsed() > Duration::from_secs(1) {
            let bar = ProgressBar::new(TICKS);
            if let Ok(style) = ProgressStyle::with_template("{bar:40} {percent:>3}% t = {msg} ({elapsed}, eta {eta})") {
                bar.set_style(style);
            }
            self.bar = Some(bar);
        }
        if let Some(bar) = &self.bar {
            let span = self.t_end - self.t0;
            let fraction = if span == 0.0 {
                1.0
            } else {
                ((t - self.t0) / span).clamp(0.0, 1.0)
            };
            bar.set_position((fraction * TICKS as f64) as u64);
            bar.set_message(format!("{t:.6}"));
        }
    }

    /// Removes the bar (before the summary is printed).
    pub fn finish(&mut self) {
        if let Some(bar) = self.bar.take() {
            bar.finish_and_clear();
        }
    }
}
