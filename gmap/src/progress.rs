//! Progress of long work on stderr: an `indicatif` spinner with the elapsed time and the
//! current stage, shown only when stderr is a terminal (so output piped or captured never
//! holds it) and hidden altogether for library callers that do not ask for it.

use std::time::Duration;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// A progress display shared by the stages of one command. Cloning gives another handle on
/// the same display. The default is hidden: nothing is drawn.
#[derive(Clone, Debug)]
pub struct Progress {
    bar: ProgressBar,
}

impl Default for Progress {
    fn default() -> Self {
        Progress::hidden()
    }
}

impl Progress {
    /// A progress display that draws nothing.
    pub fn hidden() -> Self {
        Progress { bar: ProgressBar::hidden() }
    }

    /// A spinner on stderr prefixed by `name` (`gmap homology`), drawn only when stderr is a
    /// terminal; hidden when `quiet`.
    pub fn stderr(name: &str, quiet: bool) -> Self {
        use std::io::IsTerminal;
        if quiet || !std::io::stderr().is_terminal() {
            return Progress::hidden();
        }
        let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
        let style = ProgressStyle::with_template("{prefix}: {spinner} [{elapsed_precise}] {wide_msg}")
            .unwrap_or_else(|_| ProgressStyle::default_spinner());
        bar.set_style(style);
        bar.set_prefix(name.to_string());
        bar.enable_steady_tick(Duration::from_millis(120));
        Progress { bar }
    }

    /// Whether anything is drawn (callers skip work done only for a message).
    pub fn is_visible(&self) -> bool {
        !self.bar.is_hidden()
    }

    /// Starts a stage: its message replaces the previous one.
    pub fn stage(&self, msg: &str) {
        if self.is_visible() {
            self.bar.set_message(format!("{msg}…"));
        }
    }

    /// A message kept above the spinner (a note that stays once the work is done).
    pub fn note(&self, msg: &str) {
        if self.is_visible() {
            self.bar.println(msg);
        }
    }

    /// A bar for `len` steps of one stage (files of a benchmark, bytes of a file); the
    /// spinner comes back with [`Progress::stage`].
    pub fn steps(&self, len: u64, msg: &str) {
        if self.is_visible() {
            self.bar.set_length(len);
            self.bar.set_position(0);
            if let Ok(style) =
                ProgressStyle::with_template("{prefix}: [{elapsed_precise}] {bar:30} {pos}/{len} {wide_msg}")
            {
                self.bar.set_style(style);
            }
            self.bar.set_message(msg.to_string());
        }
    }

    /// One step of the bar made by [`Progress::steps`] done, with the next item's name.
    pub fn step(&self, msg: &str) {
        if self.is_visible() {
            self.bar.inc(1);
            self.bar.set_message(msg.to_string());
        }
    }

    /// Removes the display (at the end of the command).
    pub fn finish(&self) {
        if self.is_visible() {
            self.bar.finish_and_clear();
        }
    }
}
