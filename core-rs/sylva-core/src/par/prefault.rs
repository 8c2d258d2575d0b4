//! Faulting in a buffer's reserved memory on another thread, ahead of the thread that fills it.
//!
//! The first write to each page of fresh memory is a page fault (the kernel maps and zeroes the
//! page): about 1.4 µs per 4 KB page on the project's machine, a third of a fresh generation in
//! wasm (docs/performance.md, "Where the time goes"). Faults of one memory are served on
//! both cores at once, so while the bark is swept on one thread, the thread that placed the
//! leaves can write one byte into each page the bark's buffers have reserved but not yet
//! filled: the sweep then finds them mapped.
//!
//! [`Prefault::new`] takes the buffers' reserved capacity as regions and gives a [`Toucher`] for
//! the other thread ([`Toucher::run`]). The owner calls [`Prefault::claim`] before it writes up to
//! a new end of a buffer. Each region's pages are claimed once, from both ends: the owner from
//! the bottom, as it fills the buffer, the toucher from the top down (so the two meet once, far
//! from where the owner writes, instead of racing for the same pages). Both ends live in one
//! atomic word, changed by compare-and-swap, so no page is given to both threads; the owner
//! that reaches the toucher's pages waits until the toucher has written them (it publishes
//! each with `Release`). Dropping the [`Prefault`] stops the toucher and waits for it, so the
//! owner must drop it before it reallocates or frees a buffer ([`crate::mesh::MeshBuilder`]
//! does).
//! Nothing here changes a byte of the output: the toucher writes zeros into memory the owner
//! has not written yet, which the owner then writes in full.
//!
//! [`offering`] and [`Mailbox`] carry the toucher from the code that reserves the buffers (deep in
//! the bark's sweep) to the other thread of a [`super::join`].

use std::sync::atomic::{AtomicBool, AtomicU64, AtomicU8, AtomicUsize, Ordering};
use std::sync::{Arc, Condvar, Mutex, PoisonError};

/// Bytes in one page of the system's memory.
pub const PAGE: usize = 4096;

/// Reserved buffers smaller than this are not worth another thread's time.
pub const MIN_BYTES: usize = 1 << 20;

/// One buffer's reserved, unwritten memory: whole pages from `start` (page-aligned).
struct Region {
    /// Address of the first whole page.
    start: usize,
    /// Whole pages.
    pages: usize,
    /// The claims, packed by [`pack`]: pages below `lo` are the owner's, pages from `hi` up the
    /// toucher's, the pages between nobody's yet.
    claims: AtomicU64,
    /// The toucher has written every page it claimed from this one up.
    done: AtomicUsize,
}

/// `lo` and `hi` (pages, below 2³²) in one word.
fn pack(lo: usize, hi: usize) -> u64 {
    (hi as u64) << 32 | lo as u64
}

/// The `lo` and `hi` of [`pack`].
fn unpack(c: u64) -> (usize, usize) {
    ((c & 0xffff_ffff) as usize, (c >> 32) as usize)
}

/// Pages the owner claims beyond the one it needs, so that it claims once every few pages.
const AHEAD: usize = 8;

/// The toucher has not started (and will not once stopped)...
const WAITING: u8 = 0;
/// ... is touching pages ...
const RUNNING: u8 = 1;
/// ... or is gone (finished, or stopped before it started).
const GONE: u8 = 2;

struct Shared {
    regions: Vec<Region>,
    stop: AtomicBool,
    state: AtomicU8,
}

/// The owner's side: claims pages before writing them; stops the toucher when dropped.
pub struct Prefault {
    shared: Arc<Shared>,
    /// Per region, the end address below which the owner may write without claiming.
    safe: Vec<usize>,
}

/// The other thread's side ([`Toucher::run`]).
pub struct Toucher {
    shared: Arc<Shared>,
}

impl Prefault {
    /// Regions `(address, bytes)` of reserved, unwritten memory (each the spare capacity of a
    /// buffer that will not be reallocated or freed while this [`Prefault`] lives), and the
    /// toucher for another thread. Only the whole pages inside each region are touched.
    pub fn new(regions: &[(usize, usize)]) -> (Prefault, Toucher) {
        let regions: Vec<Region> = regions
            .iter()
            .map(|&(addr, bytes)| {
                let start = addr.next_multiple_of(PAGE);
                let end = (addr + bytes) / PAGE * PAGE;
                let pages = (end.saturating_sub(start) / PAGE).min(u32::MAX as usize);
                Region { start, pages, claims: AtomicU64::new(pack(0, pages)), done: AtomicUsize::new(pages) }
            })
            .collect();
        let safe = regions.iter().map(|r| r.start).collect();
        let shared = Arc::new(Shared { regions, stop: AtomicBool::new(false), state: AtomicU8::new(WAITING) });
        (Prefault { shared: Arc::clone(&shared), safe }, Toucher { shared })
    }

    /// Before the owner writes region `r`'s memory below address `end`: claims the pages it
    /// reaches, waiting for any the toucher is writing.
    #[inline]
    pub fn claim(&mut self, r: usize, end: usize) {
        if end > self.safe[r] {
            self.claim_slow(r, end);
        }
    }

    #[cold]
    fn claim_slow(&mut self, r: usize, end: usize) {
        let region = &self.shared.regions[r];
        let need = (end - region.start).div_ceil(PAGE).min(region.pages);
        let want = (need + AHEAD).min(region.pages);
        let mut c = region.claims.load(Ordering::Acquire);
        let hi = loop {
            let (lo, hi) = unpack(c);
            // Up to `want`, but never into the toucher's pages: those from `hi` up are its.
            let new = pack(lo.max(want.min(hi)), hi);
            if new == c {
                break hi;
            }
            match region.claims.compare_exchange_weak(c, new, Ordering::AcqRel, Ordering::Acquire) {
                Ok(_) => break hi,
                Err(now) => c = now,
            }
        };
        if need <= hi {
            let held = want.min(hi);
            self.safe[r] = if held == region.pages { usize::MAX } else { region.start + held * PAGE };
            return;
        }
        // The owner has reached the toucher's pages, all of them above the ones it now holds
        // (so the toucher claims nothing more here): wait until it has written them.
        while region.done.load(Ordering::Acquire) > hi {
            if self.shared.state.load(Ordering::Acquire) == GONE {
                break;
            }
            std::hint::spin_loop();
        }
        self.safe[r] = usize::MAX;
    }

    /// Stops the toucher and waits until it is gone.
    fn stop(&self) {
        let s = &self.shared;
        s.stop.store(true, Ordering::Release);
        if s.state.compare_exchange(WAITING, GONE, Ordering::AcqRel, Ordering::Acquire).is_ok() {
            return;
        }
        while s.state.load(Ordering::Acquire) != GONE {
            std::hint::spin_loop();
        }
    }
}

impl Drop for Prefault {
    fn drop(&mut self) {
        self.stop();
    }
}

impl Toucher {
    /// Writes a zero byte into every page of the regions the owner has not claimed, from the
    /// top of each down, the regions side by side (a share of each in turn, as the owner fills
    /// them together), until all are done or the owner stops it. Nothing if the owner stopped
    /// it first. Returns the pages it wrote.
    pub fn run(self) -> usize {
        let s = &self.shared;
        if s.state.compare_exchange(WAITING, RUNNING, Ordering::AcqRel, Ordering::Acquire).is_err() {
            return 0;
        }
        let mut touched = 0;
        const STEPS: usize = 64;
        'steps: for step in 1..=STEPS {
            for region in &s.regions {
                // From the top down, this share of each region by this step.
                let target = region.pages - region.pages * step / STEPS;
                loop {
                    if s.stop.load(Ordering::Acquire) || gives_way() {
                        break 'steps;
                    }
                    let c = region.claims.load(Ordering::Acquire);
                    let (lo, hi) = unpack(c);
                    if hi <= target || hi <= lo {
                        break;
                    }
                    let p = hi - 1;
                    if region.claims.compare_exchange_weak(c, pack(lo, p), Ordering::AcqRel, Ordering::Acquire).is_err()
                    {
                        continue;
                    }
                    // SAFETY: page `p` lies inside memory the owner reserved and keeps
                    // allocated while the toucher runs (its `Prefault` stops and waits for the
                    // toucher before the memory can go), and the owner writes it only after
                    // seeing `done` reach it (Release here, Acquire there): the compare-and-swap
                    // above gave the page to this thread alone.
                    #[allow(
                        unsafe_code,
                        reason = "one byte written into a reserved page no other thread writes until it is released"
                    )]
                    unsafe {
                        ((region.start + p * PAGE) as *mut u8).write_volatile(0);
                    }
                    region.done.store(p, Ordering::Release);
                    touched += 1;
                }
            }
        }
        s.state.store(GONE, Ordering::Release);
        touched
    }
}

/// Whether the toucher gives its thread up: in the threaded wasm module, when a job waits for a
/// helper (the second half of the bark's deepest level, `mesh/tube/halves.rs`), which is worth
/// more than the pages left: the owner faults those in itself.
#[inline]
fn gives_way() -> bool {
    #[cfg(all(target_arch = "wasm32", target_feature = "atomics"))]
    return super::helpers::job_waiting();
    #[cfg(not(all(target_arch = "wasm32", target_feature = "atomics")))]
    false
}

/// Where the code that reserves buffers leaves its [`Toucher`] for the other thread of a join.
#[derive(Default)]
pub struct Mailbox {
    /// The toucher left here, and whether no other will come (the offering code is done).
    slot: Mutex<(Option<Toucher>, bool)>,
    changed: Condvar,
}

impl Mailbox {
    /// Waits until a toucher is left here or the offering code is done ([`offering`] returned,
    /// or [`withdraw`] called), then runs the toucher, if any, on the calling thread. Returns
    /// the pages it wrote.
    pub fn run(&self) -> usize {
        let mut slot = self.slot.lock().unwrap_or_else(PoisonError::into_inner);
        while slot.0.is_none() && !slot.1 {
            slot = self.changed.wait(slot).unwrap_or_else(PoisonError::into_inner);
        }
        let toucher = slot.0.take();
        drop(slot);
        toucher.map_or(0, Toucher::run)
    }

    /// Leaves `toucher` (if any) and says whether more may come.
    fn post(&self, toucher: Option<Toucher>, last: bool) {
        let mut slot = self.slot.lock().unwrap_or_else(PoisonError::into_inner);
        if toucher.is_some() {
            slot.0 = toucher;
        }
        slot.1 |= last;
        self.changed.notify_all();
    }
}

thread_local! {
    /// The mailbox [`offer`] uses on this thread (set by [`offering`]).
    static MAILBOX: std::cell::RefCell<Option<Arc<Mailbox>>> = const { std::cell::RefCell::new(None) };
}

/// Runs `f` with `mailbox` as this thread's: a [`Toucher`] that code inside `f` [`offer`]s goes
/// there. The mailbox is closed when `f` returns (a thread waiting in [`Mailbox::run`] goes on).
pub fn offering<R>(mailbox: &Arc<Mailbox>, f: impl FnOnce() -> R) -> R {
    /// Restores this thread's mailbox and closes the given one, also when `f` panics (the
    /// thread waiting in [`Mailbox::run`] must not wait forever).
    struct Close<'a> {
        mailbox: &'a Mailbox,
        before: Option<Arc<Mailbox>>,
    }
    impl Drop for Close<'_> {
        fn drop(&mut self) {
            let before = self.before.take();
            MAILBOX.with(|m| *m.borrow_mut() = before);
            self.mailbox.post(None, true);
        }
    }
    let before = MAILBOX.with(|m| m.replace(Some(Arc::clone(mailbox))));
    let _close = Close { mailbox, before };
    f()
}

/// Whether a toucher offered now would reach another thread ([`offering`] is active here).
pub fn wanted() -> bool {
    MAILBOX.with(|m| m.borrow().is_some())
}

/// Leaves `toucher` in this thread's mailbox (dropped, never run, without one). Only one is
/// offered: the mailbox is closed.
pub fn offer(toucher: Toucher) {
    MAILBOX.with(|m| {
        if let Some(mb) = m.borrow().as_ref() {
            mb.post(Some(toucher), true);
        }
    });
}

/// Says that no toucher will be offered here: the thread waiting in [`Mailbox::run`] goes on.
pub fn withdraw() {
    MAILBOX.with(|m| {
        if let Some(mb) = m.borrow().as_ref() {
            mb.post(None, true);
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The spare capacity of `v` as a region.
    fn spare(v: &mut Vec<u8>) -> (usize, usize) {
        (v.as_mut_ptr() as usize + v.len(), v.capacity() - v.len())
    }

    #[test]
    fn owner_and_toucher_share_the_pages_and_the_bytes_are_the_owners() {
        // A page the toucher wrote after the owner would show as a zero at the page's start.
        let mut touched = 0;
        for round in 0..20 {
            let n = 3 << 20;
            let mut a: Vec<u8> = Vec::with_capacity(n);
            let mut b: Vec<u8> = Vec::with_capacity(n / 2);
            a.push(7);
            let (mut pf, toucher) = Prefault::new(&[spare(&mut a), spare(&mut b)]);
            touched += std::thread::scope(|s| {
                // Start the toucher at different moments of the owner's filling.
                let t = s.spawn(move || {
                    std::thread::sleep(std::time::Duration::from_micros(50 * round));
                    toucher.run()
                });
                let (pa, pb) = (a.as_ptr() as usize, b.as_ptr() as usize);
                for k in 1..n {
                    // Claimed before the next 512 bytes of `a` (256 of `b`) are written.
                    if k % 512 == 1 {
                        pf.claim(0, pa + k + 512);
                        pf.claim(1, pb + k / 2 + 256);
                    }
                    a.push((k % 251 + 1) as u8);
                    if k % 2 == 0 {
                        b.push((k % 13 + 1) as u8);
                    }
                }
                drop(pf);
                t.join().unwrap()
            });
            assert_eq!(a.len(), n);
            assert!(a.iter().enumerate().all(|(k, &x)| x == if k == 0 { 7 } else { (k % 251 + 1) as u8 }));
            assert!(b.iter().enumerate().all(|(k, &x)| x == ((2 * k + 2) % 13 + 1) as u8));
        }
        assert!(touched > 0, "the toucher wrote no page in any round");
    }

    /// A bark swept while another thread faults in its buffers is the bark swept alone, and the
    /// other thread did fault in pages (Weeping Willow: thousands of stems, 61 MB of buffers).
    /// Up to eight rounds each: on a loaded machine (the other tests running on every core) the
    /// other thread may not be scheduled before the sweep stops it (session 19: once in a run).
    #[test]
    fn a_bark_swept_beside_a_toucher_is_the_same_bark() {
        for name in ["default", "weeping_willow"] {
            let params = crate::presets::find(name).expect("preset").params().expect("params");
            let sk = crate::skeleton::build(&params.skeleton).expect("skeleton");
            let alone = crate::mesh::tube::build_with_stats(&sk, &params.mesh).expect("bark").mesh;
            let mut touched = 0;
            for _ in 0..8 {
                let mb = Arc::new(Mailbox::default());
                let (beside, pages) = std::thread::scope(|s| {
                    let runner = s.spawn(|| mb.run());
                    let built = offering(&mb, || crate::mesh::tube::build_with_stats(&sk, &params.mesh));
                    (built.expect("bark").mesh, runner.join().expect("runner"))
                });
                assert_eq!(beside.content_hash(), alone.content_hash(), "{name}");
                assert!(beside.positions == alone.positions && beside.indices == alone.indices, "{name}");
                touched += pages;
                if touched > 0 {
                    break;
                }
            }
            assert!(touched > 0, "{name}: no page touched in any round");
        }
    }

    #[test]
    fn a_panic_while_offering_still_releases_the_runner() {
        let mb = Arc::new(Mailbox::default());
        let ran = std::thread::scope(|s| {
            let runner = s.spawn(|| mb.run());
            let panicked = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                offering(&mb, || panic!("the bark failed"));
            }));
            assert!(panicked.is_err());
            runner.join().expect("runner")
        });
        assert_eq!(ran, 0);
        assert!(!wanted());
    }

    #[test]
    fn a_toucher_run_after_the_owner_stopped_touches_nothing() {
        let mut a: Vec<u8> = Vec::with_capacity(2 << 20);
        let (pf, toucher) = Prefault::new(&[spare(&mut a)]);
        drop(pf);
        assert_eq!(toucher.run(), 0);
        assert_eq!(a.len(), 0);
    }

    #[test]
    fn a_toucher_alone_touches_every_whole_page_once() {
        let mut a: Vec<u8> = Vec::with_capacity(1 << 20);
        let region = spare(&mut a);
        let (pf, toucher) = Prefault::new(&[region]);
        toucher.run();
        let r = &pf.shared.regions[0];
        assert_eq!(r.pages, ((region.0 + region.1) / PAGE * PAGE - region.0.next_multiple_of(PAGE)) / PAGE);
        assert_eq!(r.done.load(Ordering::Relaxed), 0);
        assert_eq!(unpack(r.claims.load(Ordering::Relaxed)), (0, 0));
        assert_eq!(pf.shared.state.load(Ordering::Relaxed), GONE);
    }

    #[test]
    fn only_an_offering_thread_receives_a_toucher() {
        let mut a: Vec<u8> = Vec::with_capacity(1 << 16);
        let (_pf, toucher) = Prefault::new(&[spare(&mut a)]);
        assert!(!wanted());
        offer(toucher);
        let mb = Arc::new(Mailbox::default());
        let (_pf2, toucher2) = Prefault::new(&[spare(&mut a)]);
        offering(&mb, || {
            assert!(wanted());
            offer(toucher2);
        });
        assert!(!wanted());
        assert!(mb.slot.lock().unwrap().0.is_some());
        mb.run();
        assert!(mb.slot.lock().unwrap().0.is_none());
    }

    #[test]
    fn the_runner_waits_for_the_offer_or_for_the_offering_to_end() {
        for offered in [true, false] {
            let mb = Arc::new(Mailbox::default());
            let mut a: Vec<u8> = Vec::with_capacity(1 << 21);
            let region = spare(&mut a);
            let ran = std::thread::scope(|s| {
                // The runner starts first and must wait.
                let runner = s.spawn(|| mb.run());
                std::thread::sleep(std::time::Duration::from_millis(20));
                offering(&mb, || {
                    if offered {
                        let (pf, toucher) = Prefault::new(&[region]);
                        offer(toucher);
                        // The runner touches every page, then the owner stops it.
                        while pf.shared.regions[0].done.load(Ordering::Acquire) > 0 {
                            std::hint::spin_loop();
                        }
                        drop(pf);
                    }
                });
                runner.join().unwrap()
            });
            let pages = ((region.0 + region.1) / PAGE * PAGE - region.0.next_multiple_of(PAGE)) / PAGE;
            assert_eq!(ran, if offered { pages } else { 0 });
        }
    }
}
