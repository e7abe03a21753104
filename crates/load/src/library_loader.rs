//! An OBJ's material library, parsed on another thread while the OBJ is read.
//!
//! `mtllib` hands a large library file (from [`PARALLEL_FROM`] bytes) to a thread of its
//! own and the OBJ reads on (its vertices, typically); the library is waited for where
//! it is first needed: a `usemtl` resolved, a texture map looked up, the next `mtllib`,
//! the end of the file. The outcome is the sequential one: libraries are parsed one after
//! the other into the same [`Library`], each library's warnings follow the warnings
//! before its `mtllib`, and a library's error wins over any error the OBJ meets after
//! the `mtllib` (as if the library had been read at its line). Smaller libraries are
//! parsed at once: a thread costs more than they do.

use std::path::PathBuf;
use std::sync::mpsc;
use std::thread::JoinHandle;

use super::mtl::{self, Library};
use super::LoadError;

/// Libraries from this size (bytes) are parsed on a thread of their own. Starting and
/// joining a thread took 10–18 µs on a shared 2-core machine, about the time of parsing
/// 3–5 KB of MTL (about 280 KB per ms); from 32 KB it is a small part of what the
/// overlap can save.
pub(crate) const PARALLEL_FROM: usize = 32 * 1024;

/// A library file to parse into a library.
struct Job {
    bytes: Vec<u8>,
    path: PathBuf,
    library: Library,
}

/// What a parse on another thread gives back: the library, its warnings, its outcome.
type Parsed = (Library, Vec<String>, Result<(), LoadError>);

impl Job {
    fn run(mut self) -> Parsed {
        let mut warnings = Vec::new();
        let result = mtl::parse(&self.bytes, &self.path, &mut self.library, &mut warnings);
        (self.library, warnings, result)
    }
}

/// The libraries an OBJ names, merged into one [`Library`] in the order named, the last
/// one possibly still being parsed on another thread.
#[derive(Debug)]
pub(crate) struct LibraryLoader {
    /// Every library parsed so far (empty while `pending` holds it).
    library: Library,
    /// The parse under way, which owns the library meanwhile.
    pending: Option<JoinHandle<Parsed>>,
    /// Libraries from this many bytes go to another thread.
    parallel_from: usize,
}

impl LibraryLoader {
    /// No library yet; libraries of `parallel_from` bytes or more will be parsed on
    /// another thread ([`PARALLEL_FROM`] normally; `usize::MAX` never, 0 always).
    pub(crate) fn new(parallel_from: usize) -> Self {
        LibraryLoader {
            library: Library::default(),
            pending: None,
            parallel_from,
        }
    }

    /// Parses library file `path` (its `bytes`) into the library, after the libraries
    /// named before it: now, or on another thread when it is large. Warnings of earlier
    /// libraries still being parsed are appended to `warnings` first.
    pub(crate) fn add(
        &mut self,
        bytes: Vec<u8>,
        path: PathBuf,
        warnings: &mut Vec<String>,
    ) -> Result<(), LoadError> {
        self.wait(warnings)?;
        // Here, not on the other thread: memory a short-lived thread allocates and this
        // one frees costs more (the other thread's allocator arena gives it back and
        // asks for it anew at the next library).
        self.library.reserve(&bytes);
        if bytes.len() < self.parallel_from {
            return mtl::parse(&bytes, &path, &mut self.library, warnings);
        }
        let job = Job {
            bytes,
            path,
            library: std::mem::take(&mut self.library),
        };
        // The job is sent once the thread exists, so that it is still here (and is
        // parsed at once) when no thread can be started.
        let (send, receive) = mpsc::channel::<Job>();
        let started = std::thread::Builder::new()
            .name("limn-mtl".into())
            .spawn(move || match receive.recv() {
                Ok(job) => job.run(),
                // No job sent: nothing to parse (and nobody waits for this).
                Err(mpsc::RecvError) => (Library::default(), Vec::new(), Ok(())),
            });
        match started {
            Ok(handle) => match send.send(job) {
                Ok(()) => {
                    self.pending = Some(handle);
                    Ok(())
                }
                Err(mpsc::SendError(job)) => self.run_here(job, warnings),
            },
            Err(_) => self.run_here(job, warnings),
        }
    }

    /// The library, once the parse under way (if any) has ended; its warnings are
    /// appended to `warnings`, its error returned.
    pub(crate) fn wait(&mut self, warnings: &mut Vec<String>) -> Result<&mut Library, LoadError> {
        if let Some(handle) = self.pending.take() {
            // A panic on the other thread goes on here, as it would have here.
            let (library, more, result) = handle
                .join()
                .unwrap_or_else(|panic| std::panic::resume_unwind(panic));
            self.library = library;
            warnings.extend(more);
            result?;
        }
        Ok(&mut self.library)
    }

    fn run_here(&mut self, job: Job, warnings: &mut Vec<String>) -> Result<(), LoadError> {
        let (library, more, result) = job.run();
        self.library = library;
        warnings.extend(more);
        result
    }
}
