//! A small PNG encoder (8-bit RGB, no interlace) with its own zlib stream: one deflate
//! block with the fixed Huffman code and LZ77 matches found through hash chains, which
//! shrinks flat-coloured figures well without a dynamic-code encoder. Also a reader for
//! what the encoder writes (stored and fixed-code blocks), used to check the encoder.
//!
//! Everything is deterministic: the same pixels give the same bytes.

/// The eight bytes every PNG file starts with.
pub const SIGNATURE: [u8; 8] = [0x89, b'P', b'N', b'G', 0x0d, 0x0a, 0x1a, 0x0a];

const fn crc_table() -> [u32; 256] {
    let mut table = [0u32; 256];
    let mut n = 0;
    while n < 256 {
        let mut c = n as u32;
        let mut k = 0;
        while k < 8 {
            c = if c & 1 != 0 {
                0xedb8_8320 ^ (c >> 1)
            } else {
                c >> 1
            };
            k += 1;
        }
        table[n] = c;
        n += 1;
    }
    table
}

static CRC_TABLE: [u32; 256] = crc_table();

/// CRC-32 (ISO 3309, as in PNG chunks).
pub fn crc32(parts: &[&[u8]]) -> u32 {
    let mut c = 0xffff_ffffu32;
    for part in parts {
        for &b in *part {
            c = CRC_TABLE[((c ^ u32::from(b)) & 0xff) as usize] ^ (c >> 8);
        }
    }
    c ^ 0xffff_ffff
}

/// Adler-32 (the zlib checksum).
pub fn adler32(data: &[u8]) -> u32 {
    let (mut a, mut b) = (1u32, 0u32);
    for chunk in data.chunks(5552) {
        for &x in chunk {
            a += u32::from(x);
            b += a;
        }
        a %= 65521;
        b %= 65521;
    }
    (b << 16) | a
}

const LENGTH_BASE: [u16; 29] = [
    3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115, 131,
    163, 195, 227, 258,
];
const LENGTH_EXTRA: [u8; 29] = [
    0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0,
];
const DIST_BASE: [u16; 30] = [
    1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769, 1025, 1537,
    2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577,
];
const DIST_EXTRA: [u8; 30] = [
    0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13,
    13,
];

const WINDOW: usize = 32_768;
const MAX_MATCH: usize = 258;
const CHAIN_DEPTH: usize = 32;
const HASH_BITS: u32 = 15;
const NONE: u32 = u32::MAX;

struct BitWriter {
    out: Vec<u8>,
    acc: u64,
    n: u32,
}

impl BitWriter {
    fn bits(&mut self, value: u32, count: u32) {
        self.acc |= u64::from(value) << self.n;
        self.n += count;
        while self.n >= 8 {
            self.out.push((self.acc & 0xff) as u8);
            self.acc >>= 8;
            self.n -= 8;
        }
    }

    /// A Huffman code, most significant bit first.
    fn code(&mut self, code: u32, len: u32) {
        let mut rev = 0;
        for i in 0..len {
            rev |= ((code >> i) & 1) << (len - 1 - i);
        }
        self.bits(rev, len);
    }

    fn finish(mut self) -> Vec<u8> {
        if self.n > 0 {
            self.out.push((self.acc & 0xff) as u8);
        }
        self.out
    }
}

fn literal(w: &mut BitWriter, v: u32) {
    match v {
        0..=143 => w.code(0x30 + v, 8),
        144..=255 => w.code(0x190 + v - 144, 9),
        256..=279 => w.code(v - 256, 7),
        _ => w.code(0xc0 + v - 280, 8),
    }
}

fn length_distance(w: &mut BitWriter, len: usize, dist: usize) {
    let li = LENGTH_BASE
        .iter()
        .rposition(|&b| usize::from(b) <= len)
        .unwrap_or(0);
    literal(w, 257 + li as u32);
    w.bits(
        (len - usize::from(LENGTH_BASE[li])) as u32,
        u32::from(LENGTH_EXTRA[li]),
    );
    let di = DIST_BASE
        .iter()
        .rposition(|&b| usize::from(b) <= dist)
        .unwrap_or(0);
    w.code(di as u32, 5);
    w.bits(
        (dist - usize::from(DIST_BASE[di])) as u32,
        u32::from(DIST_EXTRA[di]),
    );
}

fn hash3(data: &[u8], i: usize) -> usize {
    let v = u32::from(data[i]) | u32::from(data[i + 1]) << 8 | u32::from(data[i + 2]) << 16;
    (v.wrapping_mul(2_654_435_761) >> (32 - HASH_BITS)) as usize
}

/// A raw deflate stream of `data`: one final block with the fixed Huffman code.
pub fn deflate(data: &[u8]) -> Vec<u8> {
    let mut w = BitWriter {
        out: Vec::with_capacity(data.len() / 8 + 16),
        acc: 0,
        n: 0,
    };
    w.bits(1, 1); // final block
    w.bits(1, 2); // fixed Huffman code
    let mut head = vec![NONE; 1 << HASH_BITS];
    let mut prev = vec![NONE; data.len()];
    let insert = |head: &mut Vec<u32>, prev: &mut Vec<u32>, i: usize| {
        if i + 3 <= data.len() {
            let h = hash3(data, i);
            prev[i] = head[h];
            head[h] = i as u32;
        }
    };
    let mut i = 0;
    while i < data.len() {
        let mut best_len = 0;
        let mut best_dist = 0;
        if i + 3 <= data.len() {
            let limit = MAX_MATCH.min(data.len() - i);
            let mut cand = head[hash3(data, i)];
            let mut depth = 0;
            while cand != NONE && depth < CHAIN_DEPTH {
                let j = cand as usize;
                if i - j > WINDOW {
                    break;
                }
                let mut len = 0;
                while len < limit && data[j + len] == data[i + len] {
                    len += 1;
                }
                if len > best_len {
                    best_len = len;
                    best_dist = i - j;
                    if len == limit {
                        break;
                    }
                }
                cand = prev[j];
                depth += 1;
            }
        }
        if best_len >= 3 {
            length_distance(&mut w, best_len, best_dist);
            for k in i..i + best_len {
                insert(&mut head, &mut prev, k);
            }
            i += best_len;
        } else {
            literal(&mut w, u32::from(data[i]));
            insert(&mut head, &mut prev, i);
            i += 1;
        }
    }
    literal(&mut w, 256);
    w.finish()
}

/// A zlib stream (RFC 1950) of `data`.
pub fn zlib(data: &[u8]) -> Vec<u8> {
    let mut out = vec![0x78, 0x01];
    out.extend(deflate(data));
    out.extend(adler32(data).to_be_bytes());
    out
}

fn chunk(out: &mut Vec<u8>, kind: &[u8; 4], data: &[u8]) {
    out.extend((data.len() as u32).to_be_bytes());
    out.extend_from_slice(kind);
    out.extend_from_slice(data);
    out.extend(crc32(&[kind, data]).to_be_bytes());
}

/// Encodes row-major RGB pixels (`3 * width * height` bytes; missing bytes are black)
/// as a PNG file.
pub fn encode_rgb(width: u32, height: u32, rgb: &[u8]) -> Vec<u8> {
    let stride = width as usize * 3;
    let mut raw = Vec::with_capacity((stride + 1) * height as usize);
    for y in 0..height as usize {
        raw.push(0); // filter: none
        let start = (y * stride).min(rgb.len());
        let end = (start + stride).min(rgb.len());
        raw.extend_from_slice(&rgb[start..end]);
        raw.resize(raw.len() + stride - (end - start), 0);
    }
    let mut ihdr = Vec::with_capacity(13);
    ihdr.extend(width.to_be_bytes());
    ihdr.extend(height.to_be_bytes());
    ihdr.extend([8, 2, 0, 0, 0]); // 8 bits, RGB, deflate, adaptive filters, no interlace
    let mut out = SIGNATURE.to_vec();
    chunk(&mut out, b"IHDR", &ihdr);
    chunk(&mut out, b"IDAT", &zlib(&raw));
    chunk(&mut out, b"IEND", &[]);
    out
}

/// Why [`decode_rgb`] refused a file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DecodeError(pub String);

impl std::fmt::Display for DecodeError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for DecodeError {}

fn err<T>(msg: &str) -> Result<T, DecodeError> {
    Err(DecodeError(msg.to_string()))
}

struct BitReader<'a> {
    data: &'a [u8],
    pos: usize,
    bit: u32,
}

impl BitReader<'_> {
    fn bit(&mut self) -> Result<u32, DecodeError> {
        let Some(&byte) = self.data.get(self.pos) else {
            return err("deflate stream ends early");
        };
        let b = (u32::from(byte) >> self.bit) & 1;
        self.bit += 1;
        if self.bit == 8 {
            self.bit = 0;
            self.pos += 1;
        }
        Ok(b)
    }

    fn bits(&mut self, count: u32) -> Result<u32, DecodeError> {
        let mut v = 0;
        for i in 0..count {
            v |= self.bit()? << i;
        }
        Ok(v)
    }

    /// Reads a fixed-code literal/length symbol.
    fn fixed_symbol(&mut self) -> Result<u32, DecodeError> {
        let mut code = 0;
        for len in 1..=9 {
            code = (code << 1) | self.bit()?;
            match len {
                7 if code <= 0x17 => return Ok(code + 256),
                8 if (0x30..=0xbf).contains(&code) => return Ok(code - 0x30),
                8 if (0xc0..=0xc7).contains(&code) => return Ok(code - 0xc0 + 280),
                9 if (0x190..=0x1ff).contains(&code) => return Ok(code - 0x190 + 144),
                _ => {}
            }
        }
        err("bad fixed Huffman code")
    }
}

/// Inflates a raw deflate stream made of stored and fixed-code blocks (dynamic-code
/// blocks are refused: this crate never writes them).
pub fn inflate(data: &[u8]) -> Result<Vec<u8>, DecodeError> {
    let mut r = BitReader {
        data,
        pos: 0,
        bit: 0,
    };
    let mut out = Vec::new();
    loop {
        let last = r.bit()?;
        match r.bits(2)? {
            0 => {
                if r.bit != 0 {
                    r.bit = 0;
                    r.pos += 1;
                }
                let Some(h) = data.get(r.pos..r.pos + 4) else {
                    return err("stored block header ends early");
                };
                let len = usize::from(u16::from_le_bytes([h[0], h[1]]));
                let nlen = u16::from_le_bytes([h[2], h[3]]);
                if nlen != !(len as u16) {
                    return err("stored block length check fails");
                }
                let Some(bytes) = data.get(r.pos + 4..r.pos + 4 + len) else {
                    return err("stored block ends early");
                };
                out.extend_from_slice(bytes);
                r.pos += 4 + len;
            }
            1 => loop {
                let sym = r.fixed_symbol()?;
                if sym < 256 {
                    out.push(sym as u8);
                    continue;
                }
                if sym == 256 {
                    break;
                }
                let li = (sym - 257) as usize;
                if li >= LENGTH_BASE.len() {
                    return err("bad length symbol");
                }
                let len =
                    usize::from(LENGTH_BASE[li]) + r.bits(u32::from(LENGTH_EXTRA[li]))? as usize;
                let mut di = 0;
                for _ in 0..5 {
                    di = (di << 1) | r.bit()? as usize;
                }
                if di >= DIST_BASE.len() {
                    return err("bad distance symbol");
                }
                let dist = usize::from(DIST_BASE[di]) + r.bits(u32::from(DIST_EXTRA[di]))? as usize;
                if dist > out.len() {
                    return err("distance reaches before the start");
                }
                for _ in 0..len {
                    out.push(out[out.len() - dist]);
                }
            },
            2 => return err("dynamic Huffman blocks are not supported"),
            _ => return err("reserved block type"),
        }
        if last == 1 {
            return Ok(out);
        }
    }
}

/// A decoded image: width, height and row-major RGB bytes.
pub type Image = (u32, u32, Vec<u8>);

/// Reads an 8-bit RGB, non-interlaced PNG as written by [`encode_rgb`]: checks the
/// signature, every chunk's CRC, the zlib checksum, and undoes the row filters.
pub fn decode_rgb(png: &[u8]) -> Result<Image, DecodeError> {
    if png.get(..8) != Some(&SIGNATURE[..]) {
        return err("not a PNG signature");
    }
    let mut pos = 8;
    let mut size = None;
    let mut idat = Vec::new();
    let mut ended = false;
    while pos + 12 <= png.len() {
        let len = u32::from_be_bytes([png[pos], png[pos + 1], png[pos + 2], png[pos + 3]]) as usize;
        let Some(kind) = png.get(pos + 4..pos + 8) else {
            return err("chunk ends early");
        };
        let Some(body) = png.get(pos + 8..pos + 8 + len) else {
            return err("chunk ends early");
        };
        let Some(crc) = png.get(pos + 8 + len..pos + 12 + len) else {
            return err("chunk ends early");
        };
        if crc32(&[kind, body]).to_be_bytes() != crc {
            return err("chunk CRC mismatch");
        }
        match kind {
            b"IHDR" => {
                if body.len() != 13 || body[8..13] != [8, 2, 0, 0, 0] {
                    return err("only 8-bit RGB without interlace is read");
                }
                let w = u32::from_be_bytes([body[0], body[1], body[2], body[3]]);
                let h = u32::from_be_bytes([body[4], body[5], body[6], body[7]]);
                size = Some((w, h));
            }
            b"IDAT" => idat.extend_from_slice(body),
            b"IEND" => {
                ended = true;
                break;
            }
            _ => {}
        }
        pos += 12 + len;
    }
    let Some((w, h)) = size else {
        return err("no IHDR chunk");
    };
    if !ended {
        return err("no IEND chunk");
    }
    if idat.len() < 6 || (u32::from(idat[0]) * 256 + u32::from(idat[1])) % 31 != 0 {
        return err("bad zlib header");
    }
    let raw = inflate(&idat[2..idat.len() - 4])?;
    let tail = &idat[idat.len() - 4..];
    if adler32(&raw).to_be_bytes() != tail {
        return err("zlib checksum mismatch");
    }
    let stride = w as usize * 3;
    if raw.len() != (stride + 1) * h as usize {
        return err("image data has the wrong size");
    }
    let mut rgb = vec![0u8; stride * h as usize];
    for y in 0..h as usize {
        let filter = raw[y * (stride + 1)];
        let line = &raw[y * (stride + 1) + 1..(y + 1) * (stride + 1)];
        for x in 0..stride {
            let a = if x >= 3 { rgb[y * stride + x - 3] } else { 0 };
            let b = if y > 0 { rgb[(y - 1) * stride + x] } else { 0 };
            let c = if x >= 3 && y > 0 {
                rgb[(y - 1) * stride + x - 3]
            } else {
                0
            };
            let pred = match filter {
                0 => 0,
                1 => a,
                2 => b,
                3 => ((u16::from(a) + u16::from(b)) / 2) as u8,
                4 => paeth(a, b, c),
                _ => return err("bad filter type"),
            };
            rgb[y * stride + x] = line[x].wrapping_add(pred);
        }
    }
    Ok((w, h, rgb))
}

fn paeth(a: u8, b: u8, c: u8) -> u8 {
    let p = i16::from(a) + i16::from(b) - i16::from(c);
    let (pa, pb, pc) = (
        (p - i16::from(a)).abs(),
        (p - i16::from(b)).abs(),
        (p - i16::from(c)).abs(),
    );
    if pa <= pb && pa <= pc {
        a
    } else if pb <= pc {
        b
    } else {
        c
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn checksums_match_known_values() {
        assert_eq!(crc32(&[b"123456789"]), 0xcbf4_3926);
        assert_eq!(crc32(&[b"IEND"]), 0xae42_6082);
        assert_eq!(adler32(b"Wikipedia"), 0x11e6_0398);
    }

    #[test]
    fn deflate_round_trips() {
        let mut data: Vec<u8> = Vec::new();
        for i in 0..70_000u32 {
            data.push((i % 7 + i / 1000) as u8);
            if i % 5000 < 300 {
                data.push(255);
            }
        }
        for sample in [&b""[..], b"a", b"abcabcabcabcabc", &data] {
            let packed = deflate(sample);
            assert_eq!(inflate(&packed), Ok(sample.to_vec()));
        }
        assert!(deflate(&vec![7u8; 100_000]).len() < 1000);
    }

    #[test]
    fn stored_blocks_are_read() {
        // final stored block "hi"
        let stream = [0x01, 0x02, 0x00, 0xfd, 0xff, b'h', b'i'];
        assert_eq!(inflate(&stream), Ok(b"hi".to_vec()));
    }

    #[test]
    fn png_round_trips_and_has_the_ihdr_size() {
        let (w, h) = (7u32, 5u32);
        let rgb: Vec<u8> = (0..w * h * 3).map(|i| (i * 37 % 251) as u8).collect();
        let png = encode_rgb(w, h, &rgb);
        assert_eq!(&png[..8], &SIGNATURE);
        assert_eq!(&png[12..16], b"IHDR");
        assert_eq!(&png[16..20], &w.to_be_bytes());
        assert_eq!(&png[20..24], &h.to_be_bytes());
        assert_eq!(decode_rgb(&png), Ok((w, h, rgb)));
    }

    #[test]
    fn corrupt_files_are_refused() {
        let png = encode_rgb(2, 2, &[9; 12]);
        let mut bad = png.clone();
        bad[30] ^= 1;
        assert!(decode_rgb(&bad).is_err());
        assert!(decode_rgb(&png[..20]).is_err());
        assert!(decode_rgb(b"GIF89a").is_err());
    }
}
