//! 2-D grey images: netpbm's PGM (`P2` text and `P5` binary, 8 or 16 bits) and PNG (grey,
//! 1 to 16 bits), read into an [`Image`] of shape `[rows, cols]` in C order (row by row),
//! the values as stored (no scaling to `maxval`).
//!
//! PGM is read by hand: the magic, then width, height and maxval as decimal tokens
//! separated by white space and `#` comments, then the values (`P2`: decimal tokens; `P5`:
//! one byte each if maxval < 256, else two, big-endian). PNG goes through the `png` crate;
//! a colour or alpha PNG is refused (converting it to grey would pick a weighting for the
//! user). Cost: one pass over the file, one copy of the values.
//!
//! ```
//! use gmap_ops::import::raster::parse_pgm;
//! let img = parse_pgm(b"P2\n# a 2 x 3 image\n3 2\n9\n0 1 2\n3 4 9\n").unwrap();
//! assert_eq!(img.shape(), &[2, 3]);
//! assert_eq!(img.get(&[1, 2]), 9.0);
//! ```

use std::path::Path;

use super::image::{Image, Order};
use super::{FileError, ImportError};

fn format(m: impl Into<String>) -> ImportError {
    ImportError::Format(m.into())
}

/// Reads a PGM or PNG file by its magic number.
pub fn read_raster(path: &Path) -> Result<Image, FileError> {
    let bytes = std::fs::read(path).map_err(|e| FileError::new(path, e.into()))?;
    let r = if bytes.starts_with(b"\x89PNG") {
        parse_png(&bytes)
    } else if bytes.starts_with(b"P2") || bytes.starts_with(b"P5") {
        parse_pgm(&bytes)
    } else {
        Err(format(format!("not a PGM (P2, P5) or PNG file: it starts with {:02x?}", &bytes[..bytes.len().min(8)])))
    };
    r.map_err(|e| FileError::new(path, e))
}

/// A cursor over a PGM header's tokens.
struct Tokens<'a> {
    b: &'a [u8],
    i: usize,
}

impl Tokens<'_> {
    /// The next decimal number, skipping white space and comments; `what` names it in errors.
    fn number(&mut self, what: &str) -> Result<u64, ImportError> {
        loop {
            match self.b.get(self.i) {
                Some(c) if c.is_ascii_whitespace() => self.i += 1,
                Some(b'#') => {
                    while self.b.get(self.i).is_some_and(|&c| c != b'\n') {
                        self.i += 1;
                    }
                }
                _ => break,
            }
        }
        let start = self.i;
        while self.b.get(self.i).is_some_and(u8::is_ascii_digit) {
            self.i += 1;
        }
        let text = &self.b[start..self.i];
        if text.is_empty() {
            let found = self.b.get(start).map_or("the end".to_string(), |c| format!("{:?}", *c as char));
            return Err(format(format!("PGM: expected {what} at byte {start}, found {found}")));
        }
        std::str::from_utf8(text)
            .ok()
            .and_then(|t| t.parse().ok())
            .ok_or_else(|| format(format!("PGM: {what} at byte {start} is too large")))
    }
}

/// Parses a PGM image (`P2` or `P5`).
pub fn parse_pgm(bytes: &[u8]) -> Result<Image, ImportError> {
    let binary = match bytes.get(..2) {
        Some(b"P2") => false,
        Some(b"P5") => true,
        _ => return Err(format("PGM: the file does not start with P2 or P5")),
    };
    let mut t = Tokens { b: bytes, i: 2 };
    let w = t.number("the width")? as usize;
    let h = t.number("the height")? as usize;
    let maxval = t.number("the maximum value")?;
    if w == 0 || h == 0 {
        return Err(format(format!("PGM: an image of {w} x {h} pixels")));
    }
    if maxval == 0 || maxval > 65535 {
        return Err(format(format!("PGM: maximum value {maxval} outside 1..=65535")));
    }
    let n = w.checked_mul(h).ok_or_else(|| format(format!("PGM: {w} x {h} pixels overflow")))?;
    let mut values: Vec<u16> = Vec::with_capacity(n.min(bytes.len()));
    if binary {
        // exactly one white space byte after maxval
        let start = t.i + 1;
        let size = if maxval < 256 { 1 } else { 2 };
        let need = n.checked_mul(size).and_then(|x| x.checked_add(start));
        if need.is_none_or(|need| need > bytes.len()) {
            return Err(format(format!(
                "PGM: {n} pixels of {size} byte(s) need {} bytes after the header, the file has {}",
                n.saturating_mul(size),
                bytes.len().saturating_sub(start)
            )));
        }
        let data = &bytes[start..start + n * size];
        if size == 1 {
            values.extend(data.iter().map(|&x| x as u16));
        } else {
            values.extend(data.chunks_exact(2).map(|c| u16::from_be_bytes([c[0], c[1]])));
        }
    } else {
        for i in 0..n {
            let v = t.number(&format!("pixel {i}"))?;
            if v > maxval {
                return Err(format(format!("PGM: pixel {i} is {v}, above the maximum value {maxval}")));
            }
            values.push(v as u16);
        }
    }
    if let Some(i) = values.iter().position(|&v| v as u64 > maxval) {
        return Err(format(format!("PGM: pixel {i} is {}, above the maximum value {maxval}", values[i])));
    }
    if maxval < 256 {
        Image::from_values(&[h, w], Order::C, values.into_iter().map(|v| v as u8).collect())
    } else {
        Image::from_values(&[h, w], Order::C, values)
    }
}

/// Parses a grey PNG image (1, 2, 4, 8 or 16 bits per pixel).
pub fn parse_png(bytes: &[u8]) -> Result<Image, ImportError> {
    let mut decoder = png::Decoder::new(bytes);
    decoder.set_transformations(png::Transformations::EXPAND);
    let mut reader = decoder.read_info().map_err(|e| format(format!("PNG: {e}")))?;
    let (color, depth) = reader.output_color_type();
    if color != png::ColorType::Grayscale {
        return Err(format(format!("PNG: a {color:?} image; only grey images (no alpha) are read")));
    }
    // the declared size, checked before the pixels are allocated: deflate packs at most
    // 1032 bytes into one, and expanding 1-bit grey to 8 bits multiplies by 8 (a file of a
    // few bytes declaring millions of pixels cannot hold them); then the memory policy
    let size = reader.output_buffer_size();
    let (w, h) = (reader.info().width, reader.info().height);
    if size as u64 > (bytes.len() as u64).saturating_mul(1032 * 8) {
        return Err(format(format!(
            "PNG: {w} x {h} pixels take {size} bytes, more than the {} bytes of the file can hold compressed",
            bytes.len()
        )));
    }
    gmap_core::resources::check_memory(&format!("the pixels of a {w} x {h} PNG"), Some(size as u64))?;
    let mut buf = vec![0; size];
    let info = reader.next_frame(&mut buf).map_err(|e| format(format!("PNG: {e}")))?;
    let (w, h) = (info.width as usize, info.height as usize);
    let data = &buf[..info.buffer_size()];
    let line = info.line_size;
    match depth {
        png::BitDepth::Sixteen => {
            let values = (0..h)
                .flat_map(|r| {
                    data[r * line..r * line + 2 * w].chunks_exact(2).map(|c| u16::from_be_bytes([c[0], c[1]]))
                })
                .collect();
            Image::from_values(&[h, w], Order::C, values)
        }
        png::BitDepth::Eight => {
            let values = (0..h).flat_map(|r| data[r * line..r * line + w].iter().copied()).collect();
            Image::from_values(&[h, w], Order::C, values)
        }
        d => Err(format(format!("PNG: {d:?} bits per pixel after expansion"))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn p5_eight_and_sixteen_bits() {
        let img = parse_pgm(b"P5 2 1 255\n\x07\xff").unwrap();
        assert_eq!((img.shape(), img.value(0), img.value(1)), (&[1usize, 2][..], 7.0, 255.0));
        let img = parse_pgm(b"P5\n1 2\n# c\n1000\n\x01\x02\x03\xe8").unwrap();
        assert_eq!((img.shape(), img.value(0), img.value(1)), (&[2usize, 1][..], 258.0, 1000.0));
    }

    #[test]
    fn errors_name_what_is_wrong() {
        let e = parse_pgm(b"P2 2 1 9 1 10").unwrap_err().to_string();
        assert!(e.contains("pixel 1 is 10"), "{e}");
        let e = parse_pgm(b"P5 3 3 255\n\x00").unwrap_err().to_string();
        assert!(e.contains("9 pixels"), "{e}");
        let e = parse_pgm(b"P2 x").unwrap_err().to_string();
        assert!(e.contains("the width"), "{e}");
        assert!(parse_pgm(b"P5 1 1 70000\n\x00\x00").is_err());
    }

    #[test]
    fn png_declaring_more_pixels_than_it_can_hold_is_refused() {
        // the fuzzer's input (png_reader), its header's CRC made right (a fuzzing build
        // skips the check): 47 bytes declaring 768 x 50331648 grey 4-bit pixels, whose
        // buffer of 38654705664 bytes was allocated (an abort) before decoding
        let ihdr = b"IHDR\x00\x00\x03\x00\x03\x00\x00\x00\x04\x00\x00\x00\x00";
        let mut bytes = b"\x89PNG\r\n\x1a\n\x00\x00\x00\x0d".to_vec();
        bytes.extend_from_slice(ihdr);
        bytes.extend_from_slice(&crc32(ihdr).to_be_bytes());
        bytes.extend_from_slice(b"\x00\x00\xb0\x11IDAT\x4a\x00\x00\x0a\x00\x1a");
        assert_eq!(bytes.len(), 47);
        assert_eq!(
            parse_png(&bytes).unwrap_err().to_string(),
            "PNG: 768 x 50331648 pixels take 38654705664 bytes, more than the 47 bytes of the file can hold compressed"
        );
    }

    /// The CRC of a PNG chunk's type and data (ISO 3309), bit by bit.
    fn crc32(data: &[u8]) -> u32 {
        let mut c = 0xffff_ffffu32;
        for &b in data {
            c ^= b as u32;
            for _ in 0..8 {
                c = if c & 1 == 1 { 0xedb8_8320 ^ (c >> 1) } else { c >> 1 };
            }
        }
        !c
    }

    #[test]
    fn png_grey_round_trip() {
        for sixteen in [false, true] {
            let mut out = Vec::new();
            {
                let mut enc = png::Encoder::new(&mut out, 3, 2);
                enc.set_color(png::ColorType::Grayscale);
                enc.set_depth(if sixteen { png::BitDepth::Sixteen } else { png::BitDepth::Eight });
                let mut w = enc.write_header().unwrap();
                let data: Vec<u8> = if sixteen {
                    [0u16, 1, 2, 300, 4, 65535].iter().flat_map(|v| v.to_be_bytes()).collect()
                } else {
                    vec![0, 1, 2, 3, 4, 255]
                };
                w.write_image_data(&data).unwrap();
            }
            let img = parse_png(&out).unwrap();
            assert_eq!(img.shape(), &[2, 3]);
            assert_eq!(img.get(&[1, 0]), if sixteen { 300.0 } else { 3.0 });
            assert_eq!(img.get(&[1, 2]), if sixteen { 65535.0 } else { 255.0 });
        }
    }
}
