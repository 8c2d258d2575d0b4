//! The process's allocator settings: freed memory is kept for the next tree.
//!
//! glibc's `malloc` serves blocks above its *mmap threshold* with a fresh mapping and unmaps
//! them when freed, and hands the heap's free top back to the system above its *trim
//! threshold*. A tree's buffers are such blocks (the default tree's bark is about 11 MB), so
//! every tree of `sylva batch` (and every run of `sylva bench`) wrote its buffers into new
//! pages, each a page fault in which the kernel zeroes the page first: 102–118 trees/s for a
//! batch of 100 default trees on this project's 2-core machine, against 141–160 with freed
//! memory kept (docs/performance.md, the cold path). Blocks up to 32 MB (glibc's ceiling for
//! the threshold on 64-bit systems) now come from the heap, which keeps what is freed; larger
//! ones are still mapped and unmapped. The trees are the same bytes either way.

/// glibc's `mallopt` parameters (`<malloc.h>`).
#[cfg(all(target_os = "linux", target_env = "gnu"))]
mod glibc {
    pub const M_TRIM_THRESHOLD: i32 = -1;
    pub const M_MMAP_THRESHOLD: i32 = -3;
    /// The largest mmap threshold glibc accepts on 64-bit systems (half its 64 MB heaps).
    pub const MMAP_THRESHOLD_MAX: i32 = 32 << 20;

    extern "C" {
        pub fn mallopt(param: i32, value: i32) -> i32;
    }
}

/// Keeps freed memory in the process (see the module docs). Returns whether the allocator
/// took both settings (always false where the allocator is not glibc's).
pub fn keep_freed_memory() -> bool {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    #[allow(unsafe_code, reason = "glibc's mallopt, called before any thread starts, with documented parameters")]
    // SAFETY: `mallopt` only changes the allocator's thresholds; it is called at start-up on the
    // main thread, with parameters and values glibc documents (it returns 0 for others).
    unsafe {
        let mmap = glibc::mallopt(glibc::M_MMAP_THRESHOLD, glibc::MMAP_THRESHOLD_MAX);
        let trim = glibc::mallopt(glibc::M_TRIM_THRESHOLD, i32::MAX);
        mmap == 1 && trim == 1
    }
    #[cfg(not(all(target_os = "linux", target_env = "gnu")))]
    false
}

#[cfg(test)]
mod tests {
    #[test]
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    fn glibc_takes_both_settings() {
        assert!(super::keep_freed_memory());
    }

    #[test]
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    fn a_freed_tree_sized_block_stays_in_the_process() {
        // 12 MB, the default tree's bark: above glibc's default threshold (128 kB, growing to
        // at most 32 MB only after such blocks were freed), so without the settings it would be
        // a mapping of its own, unmapped when freed, and the next one would be new pages again.
        assert!(super::keep_freed_memory());
        let first = vec![1u8; 12 << 20];
        let at = first.as_ptr() as usize;
        drop(first);
        let second = vec![2u8; 12 << 20];
        assert_eq!(second.as_ptr() as usize, at, "the freed block was reused");
    }
}
