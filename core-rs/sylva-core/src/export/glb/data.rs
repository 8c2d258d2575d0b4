//! The arrays of the GLB's BIN chunk ([`Data`]) and how each is written: one pass per view,
//! appended to the output as little-endian bytes (float and index arrays as one `memcpy`, the
//! rest through a small stack block), and the wind attributes' `u16` encoding ([`WindCodec`]).

use crate::export::quant::{Unorm16, LANES};
use crate::mesh::{Bounds, TreeMesh, WIND_STRIDE};
use serde_json::{json, Value};

/// A borrowed array for the BIN chunk.
#[derive(Clone, Copy)]
pub(super) enum Data<'a> {
    F32(&'a [f32]),
    U32(&'a [u32]),
    /// `u32` values written as `u16` (all known to fit).
    U16(&'a [u32]),
    Bytes(&'a [u8]),
    /// Unit vectors (3 floats each) as normalised `i8` `VEC3` padded to 4 bytes
    /// ([`crate::export::normals_snorm8_append`]).
    Snorm3(&'a [f32]),
    /// Normals and tangents of a mesh interleaved, 8 bytes per vertex: the normal as in
    /// [`Data::Snorm3`], then the tangent (computed into the output,
    /// [`crate::export::frames_snorm8_append`]) as a normalised `i8` `VEC4`.
    Frames(&'a TreeMesh),
    /// [`Data::Frames`] from given normals (3 floats each) and tangents (4 floats, `w` = ±1).
    FramesOf(&'a [f32], &'a [f32]),
    /// The bark's colours (4 bytes per vertex, [`crate::export::BarkTint`], when `Some(bounds)`)
    /// followed by its wind data (16 bytes per vertex, [`WindCodec`], when `Some`): two views
    /// written in one pass over the wind records.
    BarkExtras(&'a TreeMesh, Option<Bounds>, Option<WindCodec>),
    /// Instance matrices (16 floats each) decomposed ([`crate::export::decompose`]) into the output:
    /// translation (`VEC3`), rotation (`VEC4`) or scale (`VEC3`).
    Trs(&'a [f32], Part),
}

/// Which part of a decomposed matrix [`Data::Trs`] writes.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Part {
    Translation,
    Rotation,
    Scale,
}

/// Bytes of the stack block the writers fill before appending it to the output.
const BLOCK: usize = 4096;

/// Appends `f(item)`, `W` bytes per item of `E` values of `src`, to `out` through a stack block:
/// `out` only ever grows by copies of written bytes (no zero fill, one pass over the data).
#[inline(always)]
fn emit<T: Copy, const E: usize, const W: usize>(out: &mut Vec<u8>, src: &[T], f: impl Fn(&[T; E]) -> [u8; W]) {
    let per = BLOCK / W;
    let mut block = [0u8; BLOCK];
    for c in src.chunks(per * E) {
        let k = c.len() / E;
        for (d, x) in block[..k * W].chunks_exact_mut(W).zip(c.chunks_exact(E)) {
            let x: &[T; E] = x.try_into().expect("E values");
            d.copy_from_slice(&f(x));
        }
        out.extend_from_slice(&block[..k * W]);
    }
}

/// Appends 4-byte words as little-endian bytes: one `memcpy` (a `memory.copy` in wasm) of the
/// array's bytes on little-endian targets, a loop over the values elsewhere.
#[inline(always)]
fn copy_words<T: bytemuck::Pod>(out: &mut Vec<u8>, src: &[T], le: impl Fn(T) -> [u8; 4]) {
    if cfg!(target_endian = "little") {
        out.extend_from_slice(bytemuck::cast_slice(src));
    } else {
        for x in src {
            out.extend_from_slice(&le(*x));
        }
    }
}

/// `N` floats as little-endian bytes (`B` = 4 `N`).
#[inline(always)]
fn le<const N: usize, const B: usize>(v: [f32; N]) -> [u8; B] {
    let mut o = [0u8; B];
    for (d, x) in o.chunks_exact_mut(4).zip(v) {
        d.copy_from_slice(&x.to_le_bytes());
    }
    o
}

/// The `u16` encodings of the 8 wind values of a mesh (`TreeMesh::wind`): `pivot_x`, `pivot_y`,
/// `pivot_z`, `distance` and `radius` over the range the mesh's values span; `level` over 0..3
/// (levels 0, 1, 2, 3 are exactly 0, 21845, 43690, 65535), `phase` and `stiffness` over 0..1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct WindCodec(pub [Unorm16; WIND_STRIDE]);

impl WindCodec {
    /// The codec of `wind` (8 floats per vertex): one pass for the ranges. Every value lies in
    /// its component's range, so the encoding never clamps: the fixed ranges are used only when
    /// the data fits them (they always do for the generator's meshes), else the data's range.
    pub(super) fn of(wind: &[f32]) -> WindCodec {
        let (lo, hi) = crate::export::ranges::<WIND_STRIDE>(wind);
        let fixed = |k: usize, max: f32| {
            if lo[k] >= 0.0 && hi[k] <= max {
                Unorm16 { offset: 0.0, scale: max }
            } else {
                Unorm16::over(lo[k], hi[k])
            }
        };
        let data = |k: usize| Unorm16::over(lo[k], hi[k]);
        WindCodec([data(0), data(1), data(2), fixed(3, 3.0), fixed(4, 1.0), fixed(5, 1.0), data(6), data(7)])
    }

    /// `offset` and `scale` of components `k..k + 4` as JSON.
    pub(super) fn json(&self, k: usize) -> Value {
        let c = &self.0[k..k + 4];
        json!({
            "offset": floats(&c.iter().map(|e| e.offset).collect::<Vec<_>>()),
            "scale": floats(&c.iter().map(|e| e.scale).collect::<Vec<_>>()),
        })
    }
}

impl Data<'_> {
    pub(super) fn byte_len(&self) -> usize {
        match self {
            Data::F32(s) => s.len() * 4,
            Data::U32(s) => s.len() * 4,
            Data::U16(s) => s.len() * 2,
            Data::Bytes(s) => s.len(),
            Data::Snorm3(s) => s.len() / 3 * 4,
            Data::Frames(m) => m.vertex_count() * 8,
            Data::FramesOf(n, _) => n.len() / 3 * 8,
            Data::BarkExtras(m, colors, wind) => {
                m.vertex_count() * (if colors.is_some() { 4 } else { 0 } + if wind.is_some() { 16 } else { 0 })
            }
            Data::Trs(m, part) => m.len() / 16 * if *part == Part::Rotation { 16 } else { 12 },
        }
    }

    /// Appends the little-endian bytes to `out`.
    pub(super) fn append(&self, out: &mut Vec<u8>) {
        match *self {
            Data::F32(s) => copy_words(out, s, f32::to_le_bytes),
            Data::U32(s) => copy_words(out, s, u32::to_le_bytes),
            Data::U16(s) => emit::<_, 1, 2>(out, s, |v| (v[0] as u16).to_le_bytes()),
            Data::Bytes(s) => out.extend_from_slice(s),
            Data::Snorm3(s) => crate::export::normals_snorm8_append(s, out),
            Data::Frames(m) => crate::export::frames_snorm8_append(m, out),
            Data::FramesOf(n, t) => crate::export::frames_of_snorm8_append(n, t, out),
            Data::BarkExtras(m, colors, wind) => bark_extras_append(m, colors, wind, out),
            Data::Trs(m, Part::Translation) => emit::<_, 16, 12>(out, m, |m| le([m[12], m[13], m[14]])),
            Data::Trs(m, Part::Rotation) => emit::<_, 16, 16>(out, m, |m| le(crate::export::decompose_rotation(m))),
            Data::Trs(m, Part::Scale) => emit::<_, 16, 12>(out, m, |m| le(crate::export::decompose_scale(m))),
        }
    }
}

/// [`Data::BarkExtras`]: the colours are written into their (zeroed) view block by block while
/// the wind records of the same block are appended after it, so the wind array is read once.
fn bark_extras_append(m: &TreeMesh, colors: Option<Bounds>, wind: Option<WindCodec>, out: &mut Vec<u8>) {
    let n = m.vertex_count();
    let tint = colors.map(|b| crate::export::BarkTint::new(m, &b));
    let at = out.len();
    if tint.is_some() {
        out.resize(at + 4 * n, 0);
    }
    let w = if m.wind.len() == n * WIND_STRIDE { &m.wind[..] } else { &[][..] };
    let codec = wind.map(|c| (c.0.map(|e| e.offset), c.0.map(|e| e.factor())));
    let mut block = [0u8; 16 * LANES];
    let mut base = 0;
    while base < n {
        let k = LANES.min(n - base);
        if let Some(t) = &tint {
            t.write(m, base, &mut out[at + 4 * base..at + 4 * (base + k)]);
        }
        if let Some((offset, factor)) = &codec {
            let rec = w[WIND_STRIDE * base..WIND_STRIDE * (base + k)].chunks_exact(WIND_STRIDE);
            for (d, r) in block.chunks_exact_mut(16).zip(rec) {
                for c in 0..WIND_STRIDE {
                    d[2 * c..2 * c + 2].copy_from_slice(&Unorm16::encode(offset[c], factor[c], r[c]).to_le_bytes());
                }
            }
            out.extend_from_slice(&block[..16 * k]);
        }
        base += k;
    }
}

/// `f32` values as a JSON array, each written from its exact `f64` value.
pub(super) fn floats(v: &[f32]) -> Value {
    Value::Array(v.iter().map(|&x| json!(f64::from(x))).collect())
}
