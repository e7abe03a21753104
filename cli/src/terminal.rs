//! What a run shows on standard error: warnings as they arise (`limn: warning: …`) and,
//! for work longer than about a second, the stage it is in.

use crate::progress::Progress;

/// The terminal's side of a run.
pub struct Terminal {
    quiet: bool,
    progress: Progress,
}

impl Terminal {
    /// Starts reporting (warnings and progress off with `quiet`).
    pub fn start(quiet: bool) -> Terminal {
        Terminal {
            quiet,
            progress: Progress::start(quiet),
        }
    }

    /// Ends the progress line, so that what follows starts on a clean line.
    pub fn finish(self) {
        drop(self.progress);
    }
}

impl limn::Events for Terminal {
    fn warning(&mut self, text: &str) {
        if !self.quiet {
            eprintln!("limn: warning: {text}");
        }
    }

    fn phase(&mut self, name: &'static str) {
        self.progress.phase(name);
    }
}
