//! Quantisation kernels of the GLB writer: plain IEEE `+ − × ÷ √`, integer arithmetic and
//! comparisons, so the bytes are the same on every target; no branch in the common case.
//!
//! * [`snorm8_unit_word`]: a unit vector as three normalised `i8` (glTF: `x = max(c / 127,
//!   −1)`) that stay unit within the glTF validator's tolerance for quantised vectors
//!   (|length − 1| ≤ 0.00674).
//! * [`Unorm16`]: floats as normalised `u16` over a stated range (`value = offset + scale ·
//!   q / 65535`).

/// Vertices per block of the writers' loops.
pub(super) const LANES: usize = 64;

/// 1.5 · 2²³: adding it to a float in ±2²² leaves the value rounded to an integer (ties to even)
/// in the low mantissa bits.
const MAGIC: f32 = 12_582_912.0;

/// `x` in −1..1 as a normalised `i8`, rounded to nearest (ties to even), clamped: the reference
/// for the tests.
#[cfg(test)]
fn snorm8(x: f32) -> i8 {
    ((x.clamp(-1.0, 1.0) * 127.0 + MAGIC).to_bits() as i32 - MAGIC.to_bits() as i32) as i8
}

/// 127², the squared length of a unit vector in normalised `i8`.
const UNIT2: i32 = 127 * 127;

/// Squared lengths (in units of 1/127²) a quantised unit vector may have: length 126.2..127.8,
/// inside the validator's 126.14..127.86.
const UNIT2_MIN: f32 = 15_926.0;
const UNIT2_MAX: f32 = 16_333.0;

/// A unit vector as three normalised `i8` in a little-endian word `x | y << 8 | z << 16` (top
/// byte 0), each component rounded to nearest (ties to even) by the float addition of
/// [`MAGIC`], which leaves the integer in the low mantissa bits (exact IEEE arithmetic, the same
/// on every target, cheaper than a conversion), and whether that word is unit within the
/// validator's tolerance (when not, use [`snorm8_unit_closest`]). No clamp: a component past
/// ±1 rounds past ±127 and fails the length check.
#[inline(always)]
fn snorm8_word(v: [f32; 3]) -> (u32, bool) {
    let r = v.map(|c| c * 127.0 + MAGIC);
    // The rounded components as floats (exact small integers): the length check without
    // integer multiplications.
    let [a, b, c] = r.map(|r| r - MAGIC);
    let l2 = a * a + b * b + c * c;
    let ok = (UNIT2_MIN..=UNIT2_MAX).contains(&l2);
    let [a, b, c] = r.map(|r| r.to_bits().wrapping_sub(MAGIC.to_bits()) & 0xff);
    (a | b << 8 | c << 16, ok)
}

/// [`snorm8_word`] of a unit vector, unit within the validator's tolerance: the rounded word,
/// or where that misses (rare: rounding can be off by up to 0.0068), the floor/ceiling
/// combination closest to unit length.
#[inline(always)]
pub(super) fn snorm8_unit_word(v: [f32; 3]) -> u32 {
    match snorm8_word(v) {
        (w, true) => w,
        _ => closest_word(v),
    }
}

/// [`snorm8_unit_word`] of [`LANES`] unit vectors given as one array per component, into
/// `out`: the rounding and the length check of every lane in a loop without branches (vector
/// code where there is vector code), then the closest-length search for the rare lanes whose
/// rounding misses. The same words as [`snorm8_unit_word`] lane by lane.
#[inline(always)]
pub(super) fn snorm8_unit_words(v: &[[f32; LANES]; 3], out: &mut [u32; LANES]) {
    let mut ok = [true; LANES];
    for i in 0..LANES {
        (out[i], ok[i]) = snorm8_word([v[0][i], v[1][i], v[2][i]]);
    }
    for i in 0..LANES {
        if !ok[i] {
            out[i] = closest_word([v[0][i], v[1][i], v[2][i]]);
        }
    }
}

/// [`snorm8_unit_closest`] as a word.
#[cold]
#[inline(never)]
fn closest_word(v: [f32; 3]) -> u32 {
    let [a, b, c] = snorm8_unit_closest(v).map(|c| u32::from(c as u8));
    a | b << 8 | c << 16
}

/// One unit vector as [`snorm8_unit_word`] quantises it.
#[cfg(test)]
pub(super) fn snorm8_unit(v: [f32; 3]) -> [i8; 3] {
    let q = snorm8_unit_word(v);
    [q as u8 as i8, (q >> 8) as u8 as i8, (q >> 16) as u8 as i8]
}

/// The floor/ceiling combination of `127 v` whose length is closest to 127 (first in
/// `x`-fastest order on ties). Within 0.5 of 127 for any unit `v`.
#[cold]
#[inline(never)]
fn snorm8_unit_closest(v: [f32; 3]) -> [i8; 3] {
    let len2 = |q: [i32; 3]| q[0] * q[0] + q[1] * q[1] + q[2] * q[2];
    let lo = v.map(|x| {
        let x = x.clamp(-1.0, 1.0) * 127.0;
        let t = x as i32; // toward zero
        if (t as f32) > x {
            t - 1
        } else {
            t
        }
    });
    let mut best = lo;
    let mut err = i32::MAX;
    for k in 0..8 {
        let c = [lo[0] + (k & 1), lo[1] + ((k >> 1) & 1), lo[2] + ((k >> 2) & 1)].map(|x| x.clamp(-127, 127));
        let e = (len2(c) - UNIT2).abs();
        if e < err {
            (best, err) = (c, e);
        }
    }
    best.map(|x| x as i8)
}

/// A normalised `u16` encoding of the floats in `offset..offset + scale`: `q = round((x −
/// offset) · 65535 / scale)`, read back as `offset + scale · q / 65535` (error at most `scale /
/// 131070`, plus float rounding). A zero scale (no range, or none a float can divide by)
/// encodes everything as 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Unorm16 {
    /// The value of `q = 0`.
    pub offset: f32,
    /// The value of `q = 65535` minus `offset`.
    pub scale: f32,
}

impl Unorm16 {
    /// The encoding of `min..max`.
    pub fn over(min: f32, max: f32) -> Unorm16 {
        let scale = max - min;
        if min.is_finite() && scale > 0.0 && scale.is_finite() && (65_535.0 / scale).is_finite() {
            Unorm16 { offset: min, scale }
        } else {
            Unorm16 { offset: if min.is_finite() { min } else { 0.0 }, scale: 0.0 }
        }
    }

    /// `65535 / scale` (0 for a zero scale).
    #[inline(always)]
    pub fn factor(&self) -> f32 {
        if self.scale > 0.0 {
            65_535.0 / self.scale
        } else {
            0.0
        }
    }

    /// `x` encoded with `factor` = [`Unorm16::factor`], for `x` in the encoded range as
    /// [`Unorm16::over`] makes it (no clamp: then `x − offset ≥ 0` exactly and `(x − offset) ·
    /// factor` is at most 65535 plus a rounding error), rounded to nearest (ties to even) by the
    /// addition of [`MAGIC`], as [`snorm8_word`] does.
    #[inline(always)]
    pub fn encode(offset: f32, factor: f32, x: f32) -> u16 {
        ((x - offset) * factor + MAGIC).to_bits().wrapping_sub(MAGIC.to_bits()) as u16
    }

    /// The value `q` stands for.
    #[cfg(test)]
    pub fn decode(&self, q: u16) -> f32 {
        self.offset + self.scale * (f32::from(q) / 65_535.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn snorm8_rounds_to_nearest_and_saturates() {
        assert_eq!([1.0, -1.0, 0.0, 0.5, -0.5, 2.0, -2.0].map(snorm8), [127, -127, 0, 64, -64, 127, -127]);
        // 0.5 · 127 = 63.5: ties to even.
        assert_eq!(snorm8(63.5 / 127.0), 64);
        assert_eq!(snorm8(62.5 / 127.0), 62);
    }

    #[test]
    fn quantised_unit_vectors_stay_unit_within_the_validator_tolerance() {
        // A dense spiral over the sphere, plus the axes and diagonals.
        let n = 200_000;
        let mut dirs: Vec<[f32; 3]> = (0..n)
            .map(|i| {
                let z = 1.0 - 2.0 * (i as f32 + 0.5) / n as f32;
                let r = (1.0 - z * z).max(0.0).sqrt();
                let a = i as f32 * 2.399_963;
                let v = glam::Vec3::new(r * crate::math::cos(a), r * crate::math::sin(a), z).normalize();
                v.to_array()
            })
            .collect();
        dirs.extend([[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0], [0.577_350_3; 3]]);
        let mut fixed = 0;
        for v in dirs {
            let q = snorm8_unit(v);
            let d = q.map(|c| f32::from(c) / 127.0);
            let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            assert!((len - 1.0).abs() <= 0.00674, "{v:?} -> {q:?} ({len})");
            assert!((0..3).all(|k| (d[k] - v[k]).abs() <= 1.0 / 127.0), "{v:?} -> {q:?}");
            fixed += usize::from(q != v.map(snorm8));
        }
        assert!(fixed > 0 && fixed < n / 100, "{fixed} vectors needed the closest-length search");
    }

    #[test]
    fn unorm16_round_trips_within_half_a_step() {
        let e = Unorm16::over(-3.0, 27.0);
        let f = e.factor();
        for i in 0..=3000 {
            let x = -3.0 + i as f32 * 0.01;
            let back = e.decode(Unorm16::encode(e.offset, f, x));
            assert!((back - x).abs() <= 30.0 / 131_070.0 + 4e-6, "{x} -> {back}");
        }
        assert_eq!((Unorm16::encode(e.offset, f, -3.0), Unorm16::encode(e.offset, f, 27.0)), (0, 65_535));
        // The top of any range encodes as 65535 (the scaled value rounds down to it).
        let mut rng = crate::rng::Rng::new(3, "unorm16");
        for _ in 0..100_000 {
            let (a, b) = (rng.uniform(-50.0, 50.0), rng.uniform(-50.0, 50.0));
            let e = Unorm16::over(a.min(b), a.max(b));
            assert_eq!(Unorm16::encode(e.offset, e.factor(), a.max(b)), if a == b { 0 } else { 65_535 }, "{a} {b}");
        }
        let flat = Unorm16::over(2.0, 2.0);
        assert_eq!((flat.scale, Unorm16::encode(flat.offset, flat.factor(), 2.0)), (0.0, 0));
        assert_eq!(flat.decode(0), 2.0);
        // No range (infinite values): everything encodes as 0.
        let none = Unorm16::over(f32::NEG_INFINITY, 1.0);
        assert_eq!((none.scale, Unorm16::encode(none.offset, none.factor(), 0.5)), (0.0, 0));
    }
}
