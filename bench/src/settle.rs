//! Before a timed run: the file data written so far goes to disk first. A program that
//! writes a large file leaves the system writing it back for a while after it exits;
//! the next program measured then shares the machine with that (a 300 MB file written
//! just before doubled the 10k soup's 31 ms). Every timed run, limn's and the peers',
//! starts after this, outside its clock.

/// Flushes every file system's cached writes (`sync(2)`), returning when they are on
/// disk.
pub fn settle() {
    rustix::fs::sync();
}
