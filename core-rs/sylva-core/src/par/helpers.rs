//! Helper threads for a wasm module built with atomics (`+atomics,+bulk-memory`, its memory
//! shared): `wasm32-unknown-unknown` cannot start a thread, so its host starts them (a Web
//! Worker each in the browser, a `worker_threads` Worker in Node), instantiates the same module
//! on the same memory there, and calls [`helper_loop`], which never returns. [`join`] then hands
//! its second closure to an idle helper, as `std::thread::scope` hands one to a new thread.
//!
//! Waiting uses std's `Mutex` and `Condvar`, which in such a module are futexes on
//! `memory.atomic.wait32`: allowed in a worker, never on a page's main thread, so the module
//! that generates must itself run in a worker (as `sylva-trees` does).
//!
//! Without a helper (none started yet, or a module without atomics) [`join`] runs both closures
//! in order on the calling thread. Either way the results are the same values: the closures
//! compute nothing across each other.

use std::collections::VecDeque;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};
use std::sync::{Arc, Condvar, Mutex, PoisonError};

/// A closure handed to a helper, with the lifetime of what it borrows erased (see [`join`]).
type Job = Box<dyn FnOnce() + Send + 'static>;

/// Jobs waiting for a helper, each with the number [`join`] gave it.
static QUEUE: Mutex<VecDeque<(u64, Job)>> = Mutex::new(VecDeque::new());
/// Signalled when a job is queued.
static QUEUED: Condvar = Condvar::new();
/// Helpers running [`helper_loop`].
static HELPERS: AtomicUsize = AtomicUsize::new(0);
/// Jobs the helpers ran (not taken back by the thread that handed them out).
static HELPER_JOBS: AtomicU64 = AtomicU64::new(0);
/// Jobs queued and not taken yet (by a helper, or back by the thread that queued them).
static WAITING: AtomicUsize = AtomicUsize::new(0);
/// The next job's number.
static NEXT_JOB: AtomicU64 = AtomicU64::new(0);
/// Held to check or announce a job's end; [`FINISHED`] is signalled on every end and by
/// [`poison`].
static FINISH: Mutex<()> = Mutex::new(());
/// Signalled when a helper finished a job, or when a thread panicked ([`poison`]).
static FINISHED: Condvar = Condvar::new();
/// Set by [`poison`]: a thread panicked (and is aborting), so a job may never finish.
static POISONED: AtomicBool = AtomicBool::new(false);

/// Called by the module's panic hook, on the panicking thread, before it aborts: a helper that
/// panics never finishes its job, so the thread waiting for it must not wait forever. It wakes
/// and panics in turn (a wasm panic aborts the whole instance anyway, and its host starts a new
/// one with new helpers), and the hook keeps the first panic's message.
pub fn poison() {
    POISONED.store(true, Ordering::Release);
    let _finish = FINISH.lock().unwrap_or_else(PoisonError::into_inner);
    FINISHED.notify_all();
}

/// Helper threads started ([`helper_loop`] entered).
pub fn helpers() -> usize {
    HELPERS.load(Ordering::Acquire)
}

/// Runs the jobs [`join`] hands out, forever: the body of a helper thread (its host calls it
/// once, in a worker, on the shared memory).
pub fn helper_loop() -> ! {
    HELPERS.fetch_add(1, Ordering::AcqRel);
    loop {
        let job = {
            let mut q = QUEUE.lock().unwrap_or_else(PoisonError::into_inner);
            loop {
                match q.pop_front() {
                    Some((_, job)) => {
                        WAITING.fetch_sub(1, Ordering::Relaxed);
                        break job;
                    }
                    None => q = QUEUED.wait(q).unwrap_or_else(PoisonError::into_inner),
                }
            }
        };
        job();
        HELPER_JOBS.fetch_add(1, Ordering::Relaxed);
    }
}

/// Whether a job waits for a helper: a helper doing work that may stop early (faulting in the
/// bark's pages ahead of its sweep, [`super::prefault`]) stops, so that it takes the job.
pub fn job_waiting() -> bool {
    WAITING.load(Ordering::Relaxed) > 0
}

/// Jobs the helpers ran since the module started: evidence for the tests that work was shared.
pub fn helper_jobs() -> u64 {
    HELPER_JOBS.load(Ordering::Relaxed)
}

/// What `b` returned, once a helper has run it.
struct Done<B> {
    result: Mutex<Option<B>>,
}

/// `(a(), b())`: `b` on a helper if one takes it before `a` is done, else on this thread after `a`.
pub fn join<A, B: Send>(a: impl FnOnce() -> A, b: impl FnOnce() -> B + Send) -> (A, B) {
    if helpers() == 0 {
        return (a(), b());
    }
    let done = Arc::new(Done { result: Mutex::new(None) });
    let theirs = Arc::clone(&done);
    let job: Box<dyn FnOnce() + Send + '_> = Box::new(move || {
        let r = b();
        *theirs.result.lock().unwrap_or_else(PoisonError::into_inner) = Some(r);
        let _finish = FINISH.lock().unwrap_or_else(PoisonError::into_inner);
        FINISHED.notify_all();
    });
    // SAFETY: `job` borrows what `b` captured, which lives in the caller's frames. The lifetime
    // is erased only to pass it through the static queue; this function returns only once the
    // job has run to its end (taken back below and run here, or its result received from the
    // helper, which sets it as its last use of anything borrowed), so nothing it borrows is
    // used after it is gone: the guarantee `std::thread::scope` gives its threads. A panic
    // aborts the module (wasm has no unwinding), so no path returns early.
    #[allow(
        unsafe_code,
        reason = "a scoped hand-off of a borrowing closure to a helper thread, as std::thread::scope does"
    )]
    let job: Job = unsafe { std::mem::transmute::<Box<dyn FnOnce() + Send + '_>, Job>(job) };
    let id = NEXT_JOB.fetch_add(1, Ordering::Relaxed);
    {
        let mut q = QUEUE.lock().unwrap_or_else(PoisonError::into_inner);
        q.push_back((id, job));
        WAITING.fetch_add(1, Ordering::Relaxed);
    }
    QUEUED.notify_one();
    let a = a();
    // Not started yet (every helper busy): take it back and run it here.
    let mine = {
        let mut q = QUEUE.lock().unwrap_or_else(PoisonError::into_inner);
        let mine = q.iter().position(|(k, _)| *k == id).and_then(|i| q.remove(i));
        if mine.is_some() {
            WAITING.fetch_sub(1, Ordering::Relaxed);
        }
        mine
    };
    if let Some((_, job)) = mine {
        job();
    }
    // The helper sets the result, then signals under `FINISH`: checked under `FINISH`, a
    // result not there yet is signalled after this thread waits.
    let mut finish = FINISH.lock().unwrap_or_else(PoisonError::into_inner);
    loop {
        if let Some(b) = done.result.lock().unwrap_or_else(PoisonError::into_inner).take() {
            return (a, b);
        }
        if POISONED.load(Ordering::Acquire) {
            drop(finish);
            panic!("a helper thread panicked (its message is the first one reported)");
        }
        finish = FINISHED.wait(finish).unwrap_or_else(PoisonError::into_inner);
    }
}
