//! A small deterministic zip writer (PKWARE APPNOTE 6.3.x, §4.3): entries deflated with
//! `miniz_oxide` at a fixed level (stored when that is not smaller), every entry dated
//! 1980-01-01 00:00, no extra fields, no zip64 (the whole archive under 4 GiB). The same files
//! give the same bytes on every target.

/// Deflate level of the entries (1: fast; GLB floats and PNGs gain little from more).
const LEVEL: u8 = 1;
/// MS-DOS date of 1980-01-01 (the earliest a zip can hold) and time 00:00.
const DOS_DATE: u16 = (1 << 5) | 1;
const DOS_TIME: u16 = 0;

/// The zip of `files` (name, bytes), in the given order, or an error message when it would
/// pass 4 GiB (this writer has no zip64).
pub fn zip(files: &[(String, Vec<u8>)]) -> Result<Vec<u8>, String> {
    let mut out = Vec::new();
    let mut central = Vec::new();
    for (name, data) in files {
        let crc = super::png::crc32(&[data]);
        let deflated = miniz_oxide::deflate::compress_to_vec(data, LEVEL);
        let (method, body): (u16, &[u8]) = if deflated.len() < data.len() { (8, &deflated) } else { (0, data) };
        let offset = out.len();
        let too_big = |n: usize| u32::try_from(n).map_err(|_| format!("the zip would pass 4 GiB at {name}"));
        let (size, packed, at) = (too_big(data.len())?, too_big(body.len())?, too_big(offset)?);
        let head = |sig: u32, central: bool| {
            let mut h = Vec::with_capacity(46 + name.len());
            h.extend_from_slice(&sig.to_le_bytes());
            if central {
                h.extend_from_slice(&20u16.to_le_bytes()); // made by: MS-DOS, version 2.0
            }
            for w in [20u16, 0x0800, method, DOS_TIME, DOS_DATE] {
                h.extend_from_slice(&w.to_le_bytes()); // version needed, flags (UTF-8 names), ...
            }
            for d in [crc, packed, size] {
                h.extend_from_slice(&d.to_le_bytes());
            }
            h.extend_from_slice(&(name.len() as u16).to_le_bytes());
            h.extend_from_slice(&0u16.to_le_bytes()); // extra field length
            if central {
                h.extend_from_slice(&[0; 6]); // comment length, disk, internal attributes
                h.extend_from_slice(&0u32.to_le_bytes()); // external attributes
                h.extend_from_slice(&at.to_le_bytes());
            }
            h.extend_from_slice(name.as_bytes());
            h
        };
        out.extend_from_slice(&head(0x0403_4b50, false));
        out.extend_from_slice(body);
        central.extend_from_slice(&head(0x0201_4b50, true));
    }
    let dir_at = u32::try_from(out.len()).map_err(|_| "the zip would pass 4 GiB".to_string())?;
    out.extend_from_slice(&central);
    let n = u16::try_from(files.len()).map_err(|_| "more than 65,535 files".to_string())?;
    out.extend_from_slice(&0x0605_4b50u32.to_le_bytes());
    out.extend_from_slice(&[0; 4]); // this disk, the directory's disk
    out.extend_from_slice(&n.to_le_bytes());
    out.extend_from_slice(&n.to_le_bytes());
    out.extend_from_slice(&(central.len() as u32).to_le_bytes());
    out.extend_from_slice(&dir_at.to_le_bytes());
    out.extend_from_slice(&0u16.to_le_bytes()); // comment length
    u32::try_from(out.len()).map_err(|_| "the zip would pass 4 GiB".to_string())?;
    Ok(out)
}
