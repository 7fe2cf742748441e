//! Progress on stderr for work that takes a while: a spinner with the time
//! spent for one operation, and a bar of k/N steps with the stage's name
//! where the number of steps is known (the demo's workflows).
//!
//! Both appear only when stderr is a terminal, and only once the work has
//! taken half a second; when stderr is a file or a pipe nothing is drawn, so
//! logs and scripts see only the commands' own messages.

use std::io::IsTerminal;
use std::sync::mpsc;
use std::time::Duration;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// How long work runs before its progress shows.
const DELAY: Duration = Duration::from_millis(500);
/// How often a shown spinner or bar redraws its clock.
const TICK: Duration = Duration::from_millis(100);

/// Runs `work` while `bar`, hidden at first, shows on stderr once the work
/// has taken [`DELAY`] and stderr is a terminal; the bar is cleared when
/// the work ends.
fn shown_after_delay<T>(bar: &ProgressBar, work: impl FnOnce() -> T) -> T {
    if !std::io::stderr().is_terminal() {
        return work();
    }
    let (done, finished) = mpsc::channel::<()>();
    let result = std::thread::scope(|scope| {
        let shown = bar.clone();
        scope.spawn(move || {
            if let Err(mpsc::RecvTimeoutError::Timeout) = finished.recv_timeout(DELAY) {
                shown.set_draw_target(ProgressDrawTarget::stderr());
                shown.enable_steady_tick(TICK);
            }
        });
        let result = work();
        let _ = done.send(());
        result
    });
    bar.finish_and_clear();
    result
}

/// Runs `work`; when it takes longer than half a second and stderr is a
/// terminal, shows `label` and the time spent until it ends.
pub(crate) fn with_spinner<T>(label: &str, work: impl FnOnce() -> T) -> T {
    let spinner = ProgressBar::with_draw_target(None, ProgressDrawTarget::hidden());
    spinner.set_style(
        ProgressStyle::with_template("{spinner} {msg}… {elapsed}")
            .expect("the spinner's template is valid"),
    );
    spinner.set_message(label.to_string());
    shown_after_delay(&spinner, work)
}

/// A bar of numbered steps, for work whose steps are known in advance.
pub(crate) struct Steps {
    bar: ProgressBar,
    title: String,
}

impl Steps {
    /// Starts step `title` (the next of the N), replacing the last one.
    pub(crate) fn start(&mut self, title: &str) {
        if !self.title.is_empty() {
            self.bar.inc(1);
        }
        self.title = title.to_string();
        self.bar.set_message(self.title.clone());
    }

    /// Names the stage the current step has reached.
    pub(crate) fn stage(&self, name: &str) {
        self.bar.set_message(format!("{}: {name}", self.title));
    }

    /// Shows `text` alone, for work after the last step's stages.
    pub(crate) fn note(&self, text: &str) {
        self.bar.set_message(text.to_string());
    }

    /// Prints a line on stdout without tearing the bar.
    pub(crate) fn println(&self, line: &str) {
        self.bar.suspend(|| println!("{line}"));
    }
}

/// Runs `work` with a bar of `total` steps, `[k/N] ████░░░░ 3s step: stage`
/// (k the step under way, the bar filled by the steps done), shown on stderr
/// after half a second when stderr is a terminal.
pub(crate) fn with_steps<T>(total: usize, work: impl FnOnce(&mut Steps) -> T) -> T {
    let bar = ProgressBar::with_draw_target(Some(total as u64), ProgressDrawTarget::hidden());
    bar.set_style(
        ProgressStyle::with_template("[{step}/{len}] {bar:24} {elapsed} {wide_msg}")
            .expect("the bar's template is valid")
            .with_key(
                "step",
                |state: &indicatif::ProgressState, w: &mut dyn std::fmt::Write| {
                    let len = state.len().unwrap_or(0);
                    let _ = write!(w, "{}", (state.pos() + 1).min(len));
                },
            )
            .progress_chars("█▌░"),
    );
    let mut steps = Steps {
        bar: bar.clone(),
        title: String::new(),
    };
    shown_after_delay(&bar, || work(&mut steps))
}
