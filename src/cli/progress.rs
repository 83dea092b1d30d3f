//! The progress bar of a long run: an `indicatif` bar on stderr, drawn only when
//! stderr is a terminal and only once the run has lasted [`SHOW_AFTER`] (a short run never
//! flickers a bar), cleared before the summary line or the error is printed. When stderr is
//! not a terminal (a pipe, a file, CI) nothing is drawn at all.
//!
//! The delay can be set with the environment variable `GEN_RAPID_PROGRESS_AFTER_MS` (the
//! tests set 0 to see the bar on a short run).

use crate::progress::Progress;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::sync::{Arc, Condvar, Mutex};
use std::thread::JoinHandle;
use std::time::Duration;

/// How long a run goes on before its bar appears.
pub const SHOW_AFTER: Duration = Duration::from_secs(1);

/// The environment variable that overrides [`SHOW_AFTER`] (milliseconds).
pub const SHOW_AFTER_ENV: &str = "GEN_RAPID_PROGRESS_AFTER_MS";

/// A bar that appears after the delay if the run is still going; dropping it clears it.
pub struct TerminalProgress {
    bar: ProgressBar,
    /// Set (and signalled) when the run is over, so the watcher does not show the bar late.
    over: Arc<(Mutex<bool>, Condvar)>,
    watcher: Option<JoinHandle<()>>,
}

impl TerminalProgress {
    /// A bar for this run: `None` when stderr is not a terminal.
    pub fn for_stderr() -> Option<TerminalProgress> {
        if !std::io::stderr().is_terminal() {
            return None;
        }
        let after = std::env::var(SHOW_AFTER_ENV)
            .ok()
            .and_then(|v| v.trim().parse::<u64>().ok())
            .map(Duration::from_millis)
            .unwrap_or(SHOW_AFTER);
        let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::hidden());
        bar.set_style(spinner_style());
        let over = Arc::new((Mutex::new(false), Condvar::new()));
        let watcher = {
            let (bar, over) = (bar.clone(), Arc::clone(&over));
            std::thread::spawn(move || {
                let (lock, signal) = &*over;
                let Ok(done) = lock.lock() else { return };
                let Ok((done, _)) = signal.wait_timeout_while(done, after, |done| !*done) else {
                    return;
                };
                if !*done {
                    bar.set_draw_target(ProgressDrawTarget::stderr());
                    bar.enable_steady_tick(Duration::from_millis(120));
                }
            })
        };
        Some(TerminalProgress {
            bar,
            over,
            watcher: Some(watcher),
        })
    }
}

impl Progress for TerminalProgress {
    fn stage(&self, name: &str, units: u64) {
        if units > 0 {
            self.bar.set_style(bar_style());
            self.bar.set_length(units);
        } else {
            self.bar.set_style(spinner_style());
            self.bar.unset_length();
        }
        self.bar.set_position(0);
        self.bar.set_message(name.to_string());
    }

    fn advance(&self, n: u64) {
        self.bar.inc(n);
    }
}

impl Drop for TerminalProgress {
    fn drop(&mut self) {
        let (lock, signal) = &*self.over;
        if let Ok(mut done) = lock.lock() {
            *done = true;
        }
        signal.notify_all();
        if let Some(watcher) = self.watcher.take() {
            let _ = watcher.join();
        }
        if std::thread::panicking() {
            // Leave the bar and the panic's message as they are on the screen.
            self.bar.abandon();
        } else {
            self.bar.finish_and_clear();
        }
    }
}

fn bar_style() -> ProgressStyle {
    ProgressStyle::with_template("gen-rapid: {msg} [{bar:30}] {percent:>3}% {elapsed}")
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .progress_chars("=> ")
}

fn spinner_style() -> ProgressStyle {
    ProgressStyle::with_template("gen-rapid: {msg} {spinner} {elapsed}")
        .unwrap_or_else(|_| ProgressStyle::default_spinner())
}
