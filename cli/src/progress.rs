//! A progress line on standard error for work longer than about a second, only when
//! standard error is a terminal and `--quiet` was not given.

use std::io::{IsTerminal, Write};
use std::sync::mpsc::{channel, RecvTimeoutError, Sender};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// Shows the current phase and elapsed time after a one-second delay.
pub struct Progress {
    tx: Option<Sender<Option<&'static str>>>,
    handle: Option<JoinHandle<()>>,
}

impl Progress {
    /// Starts a progress line (inactive when `quiet` or standard error is no terminal).
    pub fn start(quiet: bool) -> Progress {
        if quiet || !std::io::stderr().is_terminal() {
            return Progress {
                tx: None,
                handle: None,
            };
        }
        let (tx, rx) = channel::<Option<&'static str>>();
        let handle = std::thread::spawn(move || {
            let t0 = Instant::now();
            let mut phase = "loading";
            let mut shown = false;
            loop {
                match rx.recv_timeout(Duration::from_millis(200)) {
                    Ok(Some(p)) => phase = p,
                    Ok(None) | Err(RecvTimeoutError::Disconnected) => break,
                    Err(RecvTimeoutError::Timeout) => {}
                }
                let t = t0.elapsed();
                if t >= Duration::from_secs(1) {
                    shown = true;
                    let mut e = std::io::stderr();
                    let _ = write!(e, "\r\x1b[2Klimn: {phase}… {:.1} s", t.as_secs_f64());
                    let _ = e.flush();
                }
            }
            if shown {
                let _ = write!(std::io::stderr(), "\r\x1b[2K");
            }
        });
        Progress {
            tx: Some(tx),
            handle: Some(handle),
        }
    }

    /// Names the phase now running.
    pub fn phase(&self, name: &'static str) {
        if let Some(tx) = &self.tx {
            let _ = tx.send(Some(name));
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        if let Some(tx) = self.tx.take() {
            let _ = tx.send(None);
        }
        if let Some(h) = self.handle.take() {
            let _ = h.join();
        }
    }
}
