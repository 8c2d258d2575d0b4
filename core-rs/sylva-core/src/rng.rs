//! The one pseudo-random generator of Sylva: PCG32 (O'Neill 2014, XSH-RR output), portable and
//! bit-exact on every target. Each pipeline stage draws from its own *named stream* so that
//! changing one stage never reshuffles another, and child stems get generators split off their
//! parent so that editing a deeper level leaves the levels above it untouched.

/// 64-bit FNV-1a of a string: turns a stream name into a PCG stream selector.
fn fnv1a64(s: &str) -> u64 {
    s.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3))
}

const MULTIPLIER: u64 = 6_364_136_223_846_793_005;

/// PCG32: 64-bit state, 32-bit output, one of 2^63 streams.
#[derive(Clone, Debug)]
pub struct Rng {
    state: u64,
    inc: u64,
}

impl Rng {
    /// A generator for `seed` on the stream called `stream` (e.g. `"skeleton"`).
    pub fn new(seed: u64, stream: &str) -> Self {
        Self::from_parts(seed, fnv1a64(stream))
    }

    fn from_parts(seed: u64, stream: u64) -> Self {
        let mut rng = Rng { state: 0, inc: (stream << 1) | 1 };
        rng.next_u32();
        rng.state = rng.state.wrapping_add(seed);
        rng.next_u32();
        rng
    }

    /// A new independent generator derived from this one (consumes two draws).
    pub fn split(&mut self) -> Rng {
        let seed = u64::from(self.next_u32()) << 32 | u64::from(self.next_u32());
        let stream = self.inc.rotate_left(17) ^ 0x9e37_79b9_7f4a_7c15;
        Rng::from_parts(seed, stream)
    }

    /// Next 32 random bits.
    pub fn next_u32(&mut self) -> u32 {
        let old = self.state;
        self.state = old.wrapping_mul(MULTIPLIER).wrapping_add(self.inc);
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        let rot = (old >> 59) as u32;
        xorshifted.rotate_right(rot)
    }

    /// Uniform in `[0, 1)` with 24 bits of precision (exactly representable in f32).
    pub fn next_f32(&mut self) -> f32 {
        (self.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0)
    }

    /// Uniform in `[lo, hi)`.
    pub fn uniform(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.next_f32()
    }

    /// Weber & Penn's `var(x)`: uniform in `[-x, x]`.
    pub fn var(&mut self, x: f32) -> f32 {
        self.uniform(-x, x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_seed_and_stream_repeat() {
        let a: Vec<u32> = {
            let mut r = Rng::new(7, "skeleton");
            (0..8).map(|_| r.next_u32()).collect()
        };
        let b: Vec<u32> = {
            let mut r = Rng::new(7, "skeleton");
            (0..8).map(|_| r.next_u32()).collect()
        };
        assert_eq!(a, b);
    }

    #[test]
    fn streams_and_seeds_differ() {
        let first = |seed, s: &str| Rng::new(seed, s).next_u32();
        assert_ne!(first(7, "skeleton"), first(7, "leaves"));
        assert_ne!(first(7, "skeleton"), first(8, "skeleton"));
    }

    #[test]
    fn matches_the_pcg32_reference_vector() {
        // pcg32-global demo / pcg_basic: pcg32_srandom_r(&rng, 42, 54) then pcg32_random_r.
        let mut r = Rng::from_parts(42, 54);
        let v: Vec<u32> = (0..6).map(|_| r.next_u32()).collect();
        assert_eq!(v, [0xa15c02b7, 0x7b47f409, 0xba1d3330, 0x83d2f293, 0xbfa4784b, 0xcbed606e]);
    }

    #[test]
    fn named_streams_are_pinned() {
        // Changing these breaks every golden tree hash: do it only on purpose.
        let mut r = Rng::new(42, "test");
        let v: Vec<u32> = (0..3).map(|_| r.next_u32()).collect();
        assert_eq!(v, [2775110972, 898122605, 4018099906]);
    }

    #[test]
    fn floats_in_range() {
        let mut r = Rng::new(1, "f");
        for _ in 0..10_000 {
            let x = r.next_f32();
            assert!((0.0..1.0).contains(&x));
            let v = r.var(2.0);
            assert!((-2.0..=2.0).contains(&v));
        }
    }
}
