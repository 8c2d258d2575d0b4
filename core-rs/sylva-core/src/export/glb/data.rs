//! The arrays of the GLB's BIN chunk ([`Data`]) and how each is written: as little-endian bytes
//! into its place in the output, any range of its items on its own (so threads can share a
//! view; float and index arrays as one `memcpy`), and the wind attributes' `u16` encoding
//! ([`WindCodec`]).

use crate::export::quant::{Unorm16, LANES};
use crate::mesh::{Bounds, TreeMesh, WIND_STRIDE};
use serde_json::{json, Value};
use std::ops::Range;

/// A borrowed array for the BIN chunk.
#[derive(Clone, Copy)]
pub(super) enum Data<'a> {
    F32(&'a [f32]),
    U32(&'a [u32]),
    /// `u32` values written as `u16` (all known to fit).
    U16(&'a [u32]),
    Bytes(&'a [u8]),
    /// Unit vectors (3 floats each) as normalised `i8` `VEC3` padded to 4 bytes
    /// ([`crate::export::normals_snorm8_write`]).
    Snorm3(&'a [f32]),
    /// Normals and tangents of a mesh interleaved, 8 bytes per vertex: the normal as in
    /// [`Data::Snorm3`], then the tangent (computed into the output,
    /// [`crate::export::frames_snorm8_write`]) as a normalised `i8` `VEC4`.
    Frames(&'a TreeMesh),
    /// [`Data::Frames`] from given normals (3 floats each) and tangents (4 floats, `w` = ±1).
    FramesOf(&'a [f32], &'a [f32]),
    /// The bark's colours (4 bytes per vertex, [`BarkTint`](crate::export::tint::BarkTint), when `Some(bounds)`)
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

/// Writes `f(item)`, `W` bytes per item of `E` values of `src`, into `out`.
#[inline(always)]
fn fill<T: Copy, const E: usize, const W: usize>(out: &mut [u8], src: &[T], f: impl Fn(&[T; E]) -> [u8; W]) {
    for (d, x) in out.chunks_exact_mut(W).zip(src.chunks_exact(E)) {
        d.copy_from_slice(&f(x.try_into().expect("E values")));
    }
}

/// Writes 4-byte words as little-endian bytes: one `memcpy` (a `memory.copy` in wasm) of the
/// array's bytes on little-endian targets, a loop over the values elsewhere.
#[inline(always)]
fn copy_words<T: bytemuck::Pod>(out: &mut [u8], src: &[T], le: impl Fn(T) -> [u8; 4]) {
    if cfg!(target_endian = "little") {
        out.copy_from_slice(bytemuck::cast_slice(src));
    } else {
        fill::<_, 1, 4>(out, src, |x| le(x[0]));
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
    /// The codec of wind data (8 floats per vertex) whose components span `lo..=hi`
    /// ([`crate::mesh::ranges`]). Every value lies in its component's range, so the encoding
    /// never clamps: the fixed ranges are used only when the data fits them (they always do for
    /// the generator's meshes), else the data's range.
    pub(super) fn over(lo: [f32; WIND_STRIDE], hi: [f32; WIND_STRIDE]) -> WindCodec {
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
    /// How many items the data has: the unit a split between threads keeps whole (a value of
    /// the plain arrays, a vertex, a matrix).
    pub(super) fn items(&self) -> usize {
        match self {
            Data::F32(s) => s.len(),
            Data::U32(s) | Data::U16(s) => s.len(),
            Data::Bytes(s) => s.len(),
            Data::Snorm3(s) | Data::FramesOf(s, _) => s.len() / 3,
            Data::Frames(m) | Data::BarkExtras(m, ..) => m.vertex_count(),
            Data::Trs(m, _) => m.len() / 16,
        }
    }

    /// Bytes per item of each of the data's planes: the arrays it writes one after the other,
    /// each `items × width` bytes (only [`Data::BarkExtras`] has a second).
    pub(super) fn widths(&self) -> [usize; 2] {
        match self {
            Data::F32(_) | Data::U32(_) | Data::Snorm3(_) => [4, 0],
            Data::U16(_) => [2, 0],
            Data::Bytes(_) => [1, 0],
            Data::Frames(_) | Data::FramesOf(..) => [8, 0],
            Data::BarkExtras(_, colors, wind) => {
                [if colors.is_some() { 4 } else { 0 }, if wind.is_some() { 16 } else { 0 }]
            }
            Data::Trs(_, part) => [if *part == Part::Rotation { 16 } else { 12 }, 0],
        }
    }

    pub(super) fn byte_len(&self) -> usize {
        let [a, b] = self.widths();
        self.items() * (a + b)
    }

    /// Writes the little-endian bytes of items `r` into `out`, one slice per plane
    /// ([`Data::widths`]: `r.len() × width` bytes each). Any split of the items into ranges
    /// writes the same bytes.
    pub(super) fn write(&self, r: Range<usize>, out: [&mut [u8]; 2]) {
        let [out, second] = out;
        match *self {
            Data::F32(s) => copy_words(out, &s[r], f32::to_le_bytes),
            Data::U32(s) => copy_words(out, &s[r], u32::to_le_bytes),
            Data::U16(s) => fill::<_, 1, 2>(out, &s[r], |v| (v[0] as u16).to_le_bytes()),
            Data::Bytes(s) => out.copy_from_slice(&s[r]),
            Data::Snorm3(s) => crate::export::frames::normals_snorm8_write(&s[3 * r.start..3 * r.end], out),
            Data::Frames(m) => crate::export::frames::frames_snorm8_write(m, r, out),
            Data::FramesOf(n, t) => crate::export::frames::frames_of_snorm8_write(
                &n[3 * r.start..3 * r.end],
                &t[4 * r.start..4 * r.end],
                out,
            ),
            Data::BarkExtras(m, colors, wind) => bark_extras_write(m, colors, wind, r, out, second),
            Data::Trs(m, part) => {
                let m = &m[16 * r.start..16 * r.end];
                match part {
                    Part::Translation => fill::<_, 16, 12>(out, m, |m| le([m[12], m[13], m[14]])),
                    Part::Rotation => fill::<_, 16, 16>(out, m, |m| le(crate::export::bake::decompose_rotation(m))),
                    Part::Scale => fill::<_, 16, 12>(out, m, |m| le(crate::export::bake::decompose_scale(m))),
                }
            }
        }
    }
}

/// [`Data::BarkExtras`] of vertices `vertices`: the colours into `colors_out` and the wind
/// records into `wind_out`, block by block, so the wind array (which the colours read too) is
/// read once.
fn bark_extras_write(
    m: &TreeMesh,
    colors: Option<Bounds>,
    wind: Option<WindCodec>,
    vertices: Range<usize>,
    colors_out: &mut [u8],
    wind_out: &mut [u8],
) {
    let n = m.vertex_count();
    let tint = colors.map(|b| crate::export::tint::BarkTint::new(m, &b));
    let w = if m.wind.len() == n * WIND_STRIDE { &m.wind[..] } else { &[][..] };
    let codec = wind.map(|c| (c.0.map(|e| e.offset), c.0.map(|e| e.factor())));
    for base in vertices.clone().step_by(LANES) {
        let (k, i) = (LANES.min(vertices.end - base), base - vertices.start);
        if let Some(t) = &tint {
            t.write(m, base, &mut colors_out[4 * i..4 * (i + k)]);
        }
        if let Some((offset, factor)) = &codec {
            let rec = w[WIND_STRIDE * base..WIND_STRIDE * (base + k)].chunks_exact(WIND_STRIDE);
            for (d, r) in wind_out[16 * i..16 * (i + k)].chunks_exact_mut(16).zip(rec) {
                for c in 0..WIND_STRIDE {
                    d[2 * c..2 * c + 2].copy_from_slice(&Unorm16::encode(offset[c], factor[c], r[c]).to_le_bytes());
                }
            }
        }
    }
}

/// `f32` values as a JSON array, each written from its exact `f64` value.
pub(super) fn floats(v: &[f32]) -> Value {
    Value::Array(v.iter().map(|&x| json!(f64::from(x))).collect())
}
