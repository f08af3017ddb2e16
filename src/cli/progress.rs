//! Progress on standard error for long work, drawn only when standard error is a terminal.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::time::Duration;

/// Work on inputs with more vertices than this shows a spinner.
pub const LARGE_INPUT: usize = 10_000;

/// Standard error if it is a terminal, else nowhere (so pipes and logs stay clean).
fn target() -> ProgressDrawTarget {
    if std::io::stderr().is_terminal() {
        ProgressDrawTarget::stderr()
    } else {
        ProgressDrawTarget::hidden()
    }
}

/// Run `work`, showing a spinner with `message` if the input has more than [`LARGE_INPUT`]
/// vertices.
pub fn while_working<T>(
    message: impl FnOnce() -> String,
    vertices: usize,
    work: impl FnOnce() -> T,
) -> T {
    if vertices <= LARGE_INPUT {
        return work();
    }
    let spinner = ProgressBar::with_draw_target(None, target()).with_message(message());
    spinner.set_style(
        ProgressStyle::with_template("{spinner} {msg} [{elapsed}]")
            .unwrap_or_else(|_| ProgressStyle::default_spinner()),
    );
    spinner.enable_steady_tick(Duration::from_millis(100));
    let result = work();
    spinner.finish_and_clear();
    result
}

/// A bar counting `len` steps.
pub fn bar(len: u64) -> ProgressBar {
    let bar = ProgressBar::with_draw_target(Some(len), target());
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} {msg} [{elapsed}, eta {eta}]")
            .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    bar
}
