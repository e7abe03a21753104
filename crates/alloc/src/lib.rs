//! The allocator of limn's programs (the `limn` command, `limn-bench` and the loading
//! benchmark): mimalloc, whose per-thread heaps cost less than the system allocator's
//! when ordering and composing make and free millions of small vectors on both cores
//! (BENCHMARKS.md, "Allocator").
//!
//! A program links it with `use limn_alloc as _;` and calls [`return_freed_memory`]
//! first thing in `main`.

/// The global allocator of every program linking this crate.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// mimalloc's `mi_option_purge_delay` (its place in `mi_option_e` of mimalloc 3's
/// `mimalloc.h`; `libmimalloc-sys` names it only for mimalloc 2).
const PURGE_DELAY: libmimalloc_sys::mi_option_t = 15;

/// How long, in milliseconds, freed memory is kept before it goes back to the system.
const PURGE_DELAY_MS: std::ffi::c_long = 10;

/// Makes the allocator give freed memory back to the system after 10 ms instead of
/// mimalloc 3's 1,000 ms.
///
/// A render frees large parts as it goes (the ordering's pieces, the scene's faces once
/// the picture is composed) and then allocates others of different sizes on other
/// threads; memory kept for a second is counted twice. Measured on the idle EPYC
/// (three processes each, alternating): a million smooth triangles
/// (`spheres1m.obj`) peak 692–723 MB → 577–580 MB, the same time; 2CylinderEngine
/// 247–279 MB → 220–225 MB and 1.34–1.75 s → 1.23–1.29 s (fewer fresh pages faulted
/// in); 0 ms instead of 10 cost the engine a sixth to a third more time in page faults
/// (BENCHMARKS.md, "Real models").
pub fn return_freed_memory() {
    // SAFETY: `mi_option_set` only stores an integer in mimalloc's option table; the
    // option exists in the mimalloc this crate links (libmimalloc-sys 0.1.49's
    // mimalloc 3), and any value is valid for it.
    #[allow(unsafe_code)]
    unsafe {
        libmimalloc_sys::mi_option_set(PURGE_DELAY, PURGE_DELAY_MS);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The option set is the purge delay: mimalloc 3's default for it is 1,000 ms (no
    /// other option of the table has that default), and the call sets it.
    #[test]
    fn the_purge_delay_is_the_option_set() {
        if std::env::var_os("MIMALLOC_PURGE_DELAY").is_some() {
            return;
        }
        #[allow(unsafe_code)]
        // SAFETY: reading an option only reads mimalloc's option table.
        let before = unsafe { libmimalloc_sys::mi_option_get(PURGE_DELAY) };
        assert_eq!(before, 1000);
        return_freed_memory();
        #[allow(unsafe_code)]
        // SAFETY: as above.
        let after = unsafe { libmimalloc_sys::mi_option_get(PURGE_DELAY) };
        assert_eq!(after, PURGE_DELAY_MS);
    }
}
