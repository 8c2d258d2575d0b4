//! Data parallelism for the big writers (the GLB export): a list of independent jobs run on
//! up to [`threads()`] threads, the calling thread one of them.
//!
//! Jobs must write disjoint outputs and compute nothing across jobs, so what they produce does
//! not depend on how many threads run them or in which order: the bytes are the same with one
//! thread as with eight, and the same as in wasm, which runs every job in order on the calling
//! thread (a plain `wasm32-unknown-unknown` module has no threads). A wasm module built with
//! atomics uses the helper threads its host started (`par/helpers.rs`); the bytes stay the same.

#[cfg(all(target_arch = "wasm32", target_feature = "atomics"))]
pub mod helpers;
pub mod prefault;

/// Whether this build runs jobs on threads it starts itself (`std::thread`): native builds.
const SPAWNS: bool = !cfg!(target_arch = "wasm32");

/// The most threads [`threads()`] offers.
pub const MAX_THREADS: usize = 8;

/// Threads worth using on this machine: its available parallelism (at most [`MAX_THREADS`]);
/// in wasm, 1 plus the helper threads the host started (none without atomics); 1 inside
/// [`serial`].
pub fn threads() -> usize {
    if SERIAL.with(std::cell::Cell::get) {
        return 1;
    }
    #[cfg(all(target_arch = "wasm32", target_feature = "atomics"))]
    return (1 + helpers::helpers()).min(MAX_THREADS);
    #[cfg(all(target_arch = "wasm32", not(target_feature = "atomics")))]
    return 1;
    #[cfg(not(target_arch = "wasm32"))]
    {
        // Asked once: on Linux the standard library reads the cgroup's CPU quota from files at
        // every call (1% of a small tree's generation when every stage asked).
        static MACHINE: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
        *MACHINE.get_or_init(|| std::thread::available_parallelism().map_or(1, |n| n.get()).min(MAX_THREADS))
    }
}

thread_local! {
    /// Set on this thread by [`serial`].
    static SERIAL: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Runs `f` with [`threads()`] at 1 on this thread: for callers that already keep every core
/// busy with work of their own (`sylva batch` generates one tree per core), so the writers
/// inside do not start threads of their own on top.
pub fn serial<R>(f: impl FnOnce() -> R) -> R {
    let before = SERIAL.with(|s| s.replace(true));
    let r = f();
    SERIAL.with(|s| s.set(before));
    r
}

/// Runs `work` on every job, on up to `threads` threads: each thread takes the next job of the
/// list until none is left, so jobs given largest first balance best. One thread (or wasm
/// without helper threads) runs them in order on the calling thread. A panicking job panics
/// the caller once all threads have stopped.
pub fn run<J: Send>(jobs: Vec<J>, threads: usize, work: impl Fn(J) + Sync) {
    let threads = threads.min(jobs.len());
    if threads <= 1 {
        jobs.into_iter().for_each(work);
        return;
    }
    let queue = std::sync::Mutex::new(jobs.into_iter());
    // A poisoned queue (a job panicked while another thread took one) ends the loop.
    let next = || queue.lock().ok().and_then(|mut q| q.next());
    let drain = || {
        while let Some(job) = next() {
            work(job);
        }
    };
    if !SPAWNS {
        spread(threads, &drain);
        return;
    }
    std::thread::scope(|s| {
        let helpers: Vec<_> = (1..threads).map(|_| s.spawn(drain)).collect();
        drain();
        for h in helpers {
            // Re-raise a helper's panic with its own message.
            h.join().unwrap_or_else(|e| std::panic::resume_unwind(e));
        }
    });
}

/// `f` of every item, in the items' order, computed on up to `threads` threads ([`run`]).
pub fn map<T: Send, R: Send>(items: Vec<T>, threads: usize, f: impl Fn(T) -> R + Sync) -> Vec<R> {
    let mut out: Vec<Option<R>> = items.iter().map(|_| None).collect();
    run(items.into_iter().zip(out.iter_mut()).collect(), threads, |(t, slot)| *slot = Some(f(t)));
    out.into_iter().map(|r| r.expect("every job ran")).collect()
}

/// `0..n` in `parts` ranges of about equal length (fewer when `n` is smaller; none when 0).
pub fn ranges(n: usize, parts: usize) -> Vec<std::ops::Range<usize>> {
    let parts = parts.clamp(1, n.max(1));
    (0..parts).map(|p| n * p / parts..n * (p + 1) / parts).filter(|r| !r.is_empty()).collect()
}

/// `drain` on `threads` threads at once, through [`join`] (the helpers of a wasm module).
fn spread(threads: usize, drain: &(impl Fn() + Sync)) {
    if threads <= 1 {
        drain();
    } else {
        join(2, drain, || spread(threads - 1, drain));
    }
}

/// `(a(), b())`, run side by side when `threads` > 1 (in wasm, on a helper thread if one was
/// started; in order without).
pub fn join<A: Send, B: Send>(threads: usize, a: impl FnOnce() -> A + Send, b: impl FnOnce() -> B + Send) -> (A, B) {
    if threads <= 1 {
        return (a(), b());
    }
    #[cfg(all(target_arch = "wasm32", target_feature = "atomics"))]
    return helpers::join(a, b);
    #[cfg(all(target_arch = "wasm32", not(target_feature = "atomics")))]
    return (a(), b());
    #[cfg(not(target_arch = "wasm32"))]
    std::thread::scope(|s| {
        let b = s.spawn(b);
        let a = a();
        (a, b.join().unwrap_or_else(|e| std::panic::resume_unwind(e)))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    #[test]
    fn every_job_runs_once_on_any_thread_count() {
        for threads in [0, 1, 2, 3, 8] {
            let mut out = vec![0u32; 100];
            let jobs: Vec<(usize, &mut [u32])> = out.chunks_mut(7).enumerate().collect();
            let calls = AtomicUsize::new(0);
            run(jobs, threads, |(k, part)| {
                calls.fetch_add(1, Ordering::Relaxed);
                for (i, x) in part.iter_mut().enumerate() {
                    *x += (7 * k + i) as u32;
                }
            });
            assert_eq!(calls.load(Ordering::Relaxed), 100usize.div_ceil(7), "{threads} threads");
            assert!(out.iter().enumerate().all(|(i, &x)| x == i as u32), "{threads} threads");
        }
    }

    #[test]
    fn map_keeps_the_order_and_ranges_cover_everything_once() {
        for threads in [1, 2, 5] {
            assert_eq!(map((0..50).collect(), threads, |x: u64| x * x), (0..50).map(|x| x * x).collect::<Vec<_>>());
        }
        for (n, parts) in [(0, 3), (1, 3), (10, 3), (10, 1), (7, 0), (1000, 8)] {
            let r = ranges(n, parts);
            assert!(r.len() <= parts.max(1) && r.iter().all(|r| !r.is_empty()), "{n} in {parts}");
            assert_eq!(r.iter().flat_map(|r| r.clone()).collect::<Vec<_>>(), (0..n).collect::<Vec<_>>());
        }
    }

    #[test]
    fn join_returns_both_in_order() {
        for threads in [1, 2] {
            assert_eq!(join(threads, || 1, || "two"), (1, "two"));
        }
    }

    #[test]
    #[should_panic(expected = "job 3")]
    fn a_panicking_job_panics_the_caller() {
        run((0..6).collect(), 2, |k: i32| assert!(k != 3, "job {k}"));
    }
}
