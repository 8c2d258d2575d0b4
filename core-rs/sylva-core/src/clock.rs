//! Stage timing without tying the core to a platform: `std::time::Instant` does not exist on
//! `wasm32-unknown-unknown`, so the binding passes a clock backed by `performance.now()`.

/// A monotonic millisecond clock.
pub trait Clock {
    /// Milliseconds since an arbitrary origin.
    fn now_ms(&self) -> f64;

    /// This clock, if it may be read from other threads too (stages that run side by side time
    /// themselves with it); `None`: the stages run one after the other.
    fn shared(&self) -> Option<&(dyn Clock + Sync)> {
        None
    }
}

/// No clock: every stage takes 0 ms. The default on wasm when no clock is passed.
pub struct NoClock;
impl Clock for NoClock {
    fn now_ms(&self) -> f64 {
        0.0
    }
    fn shared(&self) -> Option<&(dyn Clock + Sync)> {
        Some(self)
    }
}

/// `std::time::Instant` (native only).
#[cfg(not(target_arch = "wasm32"))]
pub struct StdClock(std::time::Instant);

#[cfg(not(target_arch = "wasm32"))]
impl Default for StdClock {
    fn default() -> Self {
        StdClock(std::time::Instant::now())
    }
}

#[cfg(not(target_arch = "wasm32"))]
impl Clock for StdClock {
    fn now_ms(&self) -> f64 {
        self.0.elapsed().as_secs_f64() * 1000.0
    }
    fn shared(&self) -> Option<&(dyn Clock + Sync)> {
        Some(self)
    }
}

/// The best clock of the current target.
pub fn default_clock() -> Box<dyn Clock> {
    #[cfg(not(target_arch = "wasm32"))]
    {
        Box::new(StdClock::default())
    }
    #[cfg(target_arch = "wasm32")]
    {
        Box::new(NoClock)
    }
}
