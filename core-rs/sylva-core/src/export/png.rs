//! A minimal PNG encoder (W3C PNG specification, 3rd edition): 8-bit RGBA, non-interlaced,
//! only the critical chunks `IHDR`, `IDAT`, `IEND` (no colour-space chunks, so glTF validators
//! see a plain sRGB image). Each row takes the filter (None, Sub, Up, Average, Paeth) with the
//! smallest sum of absolute filtered bytes (the libpng heuristic); the filtered stream is
//! zlib-compressed by `miniz_oxide` at a fixed level. Pure Rust, deterministic, builds for
//! wasm32.
//!
//! Row 0 of the input is written first, i.e. it is the **top** row of the image. The baked
//! textures store `v = 0` in row 0, which is exactly glTF's convention (UV `(0, 0)` is the
//! top-left corner of the image), so glTF files use them as they are.

/// Deflate level. The bark maps are noise-like: measured on the 512² bark maps, level 2 encodes
/// both in about a third of level 6's time for files about 20 % larger (≈ 0.6 MB together), small
/// next to the meshes they dress.
const LEVEL: u8 = 2;

/// CRC-32 (ISO 3309, polynomial 0xEDB88320) table, built at compile time.
const CRC_TABLE: [u32; 256] = {
    let mut t = [0u32; 256];
    let mut n = 0;
    while n < 256 {
        let mut c = n as u32;
        let mut k = 0;
        while k < 8 {
            c = if c & 1 != 0 { 0xedb8_8320 ^ (c >> 1) } else { c >> 1 };
            k += 1;
        }
        t[n] = c;
        n += 1;
    }
    t
};

/// CRC-32 (ISO 3309, the one PNG and zip use) of `parts` one after the other.
pub(crate) fn crc32(parts: &[&[u8]]) -> u32 {
    let mut c = 0xffff_ffffu32;
    for p in parts {
        for &b in *p {
            c = CRC_TABLE[((c ^ u32::from(b)) & 0xff) as usize] ^ (c >> 8);
        }
    }
    c ^ 0xffff_ffff
}

fn chunk(out: &mut Vec<u8>, kind: &[u8; 4], data: &[u8]) {
    out.extend_from_slice(&(data.len() as u32).to_be_bytes());
    out.extend_from_slice(kind);
    out.extend_from_slice(data);
    out.extend_from_slice(&crc32(&[kind, data]).to_be_bytes());
}

#[inline]
fn paeth(a: u8, b: u8, c: u8) -> u8 {
    let p = i16::from(a) + i16::from(b) - i16::from(c);
    let (pa, pb, pc) = ((p - i16::from(a)).abs(), (p - i16::from(b)).abs(), (p - i16::from(c)).abs());
    if pa <= pb && pa <= pc {
        a
    } else if pb <= pc {
        b
    } else {
        c
    }
}

/// Filters one row with filter `kind` (0..=4) into `out` (same length as `row`); `prev` is the
/// row above (zeros for the first row); `bpp` bytes per pixel.
fn filter_row(kind: u8, row: &[u8], prev: &[u8], bpp: usize, out: &mut [u8]) {
    for i in 0..row.len() {
        let a = if i >= bpp { row[i - bpp] } else { 0 };
        let b = prev[i];
        let c = if i >= bpp { prev[i - bpp] } else { 0 };
        let pred = match kind {
            0 => 0,
            1 => a,
            2 => b,
            3 => ((u16::from(a) + u16::from(b)) / 2) as u8,
            _ => paeth(a, b, c),
        };
        out[i] = row[i].wrapping_sub(pred);
    }
}

/// Encodes `rgba` (`width * height * 4` bytes, row 0 on top) as a PNG file.
///
/// # Panics
/// If `rgba` does not hold `width * height * 4` bytes or a side is zero (a caller bug).
pub fn encode_rgba(width: u32, height: u32, rgba: &[u8]) -> Vec<u8> {
    encode_rgba_with(width, height, rgba, LEVEL)
}

/// [`encode_rgba`] at deflate `level` (0 = stored .. 10 = smallest).
pub fn encode_rgba_with(width: u32, height: u32, rgba: &[u8], level: u8) -> Vec<u8> {
    let (w, h) = (width as usize, height as usize);
    assert!(w > 0 && h > 0 && rgba.len() == w * h * 4, "PNG: {width}x{height} needs {} bytes", w * h * 4);
    let stride = w * 4;
    let mut filtered = Vec::with_capacity((stride + 1) * h);
    let zeros = vec![0u8; stride];
    let mut cand = vec![0u8; stride];
    let mut best = vec![0u8; stride];
    for y in 0..h {
        let row = &rgba[y * stride..(y + 1) * stride];
        let prev = if y > 0 { &rgba[(y - 1) * stride..y * stride] } else { &zeros[..] };
        let mut best_kind = 0u8;
        let mut best_cost = u64::MAX;
        for kind in 0..=4u8 {
            filter_row(kind, row, prev, 4, &mut cand);
            // Sum of the bytes as signed values (libpng's "minimum sum of absolute differences").
            let cost: u64 = cand.iter().map(|&v| u64::from((v as i8).unsigned_abs())).sum();
            if cost < best_cost {
                best_cost = cost;
                best_kind = kind;
                std::mem::swap(&mut best, &mut cand);
            }
        }
        filtered.push(best_kind);
        filtered.extend_from_slice(&best);
    }
    let idat = miniz_oxide::deflate::compress_to_vec_zlib(&filtered, level);
    let mut out = Vec::with_capacity(idat.len() + 64);
    out.extend_from_slice(&[0x89, b'P', b'N', b'G', b'\r', b'\n', 0x1a, b'\n']);
    let mut ihdr = Vec::with_capacity(13);
    ihdr.extend_from_slice(&width.to_be_bytes());
    ihdr.extend_from_slice(&height.to_be_bytes());
    ihdr.extend_from_slice(&[8, 6, 0, 0, 0]); // 8 bits, RGBA, deflate, adaptive filters, no interlace
    chunk(&mut out, b"IHDR", &ihdr);
    chunk(&mut out, b"IDAT", &idat);
    chunk(&mut out, b"IEND", &[]);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Undoes the filters of a decompressed IDAT stream (test-side decoder).
    fn unfilter(data: &[u8], w: usize, h: usize) -> Vec<u8> {
        let stride = w * 4;
        let mut out = vec![0u8; stride * h];
        for y in 0..h {
            let kind = data[y * (stride + 1)];
            let src = &data[y * (stride + 1) + 1..(y + 1) * (stride + 1)];
            for i in 0..stride {
                let a = if i >= 4 { out[y * stride + i - 4] } else { 0 };
                let b = if y > 0 { out[(y - 1) * stride + i] } else { 0 };
                let c = if i >= 4 && y > 0 { out[(y - 1) * stride + i - 4] } else { 0 };
                let pred = match kind {
                    0 => 0,
                    1 => a,
                    2 => b,
                    3 => ((a as u16 + b as u16) / 2) as u8,
                    4 => paeth(a, b, c),
                    k => panic!("filter {k}"),
                };
                out[y * stride + i] = src[i].wrapping_add(pred);
            }
        }
        out
    }

    #[test]
    fn crc_matches_the_reference_value() {
        // The CRC-32 check value of "123456789".
        assert_eq!(crc32(&[b"123456789"]), 0xcbf4_3926);
        // IEND's CRC as every PNG file ends with it.
        assert_eq!(crc32(&[b"IEND"]), 0xae42_6082);
    }

    #[test]
    fn round_trips_through_a_decoder() {
        let (w, h) = (37usize, 11usize);
        let rgba: Vec<u8> = (0..w * h * 4).map(|i| ((i * 7919) ^ (i >> 3)) as u8).collect();
        let png = encode_rgba(w as u32, h as u32, &rgba);
        assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
        // Walk the chunks and check each CRC.
        let mut at = 8;
        let mut idat = Vec::new();
        let mut kinds = Vec::new();
        while at < png.len() {
            let len = u32::from_be_bytes(png[at..at + 4].try_into().unwrap()) as usize;
            let kind = &png[at + 4..at + 8];
            let data = &png[at + 8..at + 8 + len];
            let crc = u32::from_be_bytes(png[at + 8 + len..at + 12 + len].try_into().unwrap());
            assert_eq!(crc, crc32(&[kind, data]));
            if kind == b"IHDR" {
                assert_eq!(u32::from_be_bytes(data[0..4].try_into().unwrap()), w as u32);
                assert_eq!(u32::from_be_bytes(data[4..8].try_into().unwrap()), h as u32);
                assert_eq!(&data[8..], &[8, 6, 0, 0, 0]);
            }
            if kind == b"IDAT" {
                idat.extend_from_slice(data);
            }
            kinds.push(String::from_utf8(kind.to_vec()).unwrap());
            at += 12 + len;
        }
        assert_eq!(kinds, ["IHDR", "IDAT", "IEND"]);
        let raw = miniz_oxide::inflate::decompress_to_vec_zlib(&idat).unwrap();
        assert_eq!(raw.len(), (w * 4 + 1) * h);
        assert_eq!(unfilter(&raw, w, h), rgba);
        assert_eq!(encode_rgba(w as u32, h as u32, &rgba), png, "deterministic");
    }

    #[test]
    fn smooth_images_compress() {
        let (w, h) = (64usize, 64usize);
        let rgba: Vec<u8> = (0..w * h).flat_map(|i| [(i % w) as u8, (i / w) as u8, 128, 255]).collect();
        let png = encode_rgba(w as u32, h as u32, &rgba);
        assert!(png.len() < rgba.len() / 10, "{} bytes", png.len());
    }
}
