//! The writer: the header, then one line per frame, in a fixed layout.

use std::io::Write;

use crate::check;
use crate::error::WriteError;
use crate::model::{Entity, Frame, Header, Pose};
use crate::{FORMAT_NAME, FORMAT_VERSION};

/// Writes a recording in the native format. Numbers are written in the shortest form that
/// reads back to the same value, so reading what was written gives the same frames.
/// Frames the reader would refuse (time not increasing, NaN, unknown ids, a grip on a
/// cube, ...) are refused before anything of them is written.
#[derive(Debug)]
pub struct Writer<W: Write> {
    out: W,
    header: Header,
    previous: Option<f64>,
    frames: u64,
    buf: Vec<u8>,
}

impl<W: Write> Writer<W> {
    /// Checks the header and writes it.
    pub fn new(mut out: W, header: &Header) -> Result<Writer<W>, WriteError> {
        check::check_header(header).map_err(|p| WriteError::Header {
            field: p.field,
            message: p.message,
        })?;
        let mut buf = Vec::with_capacity(4096);
        write_header(&mut buf, header);
        out.write_all(&buf)?;
        Ok(Writer {
            out,
            header: header.clone(),
            previous: None,
            frames: 0,
            buf,
        })
    }

    /// The header written.
    pub fn header(&self) -> &Header {
        &self.header
    }

    /// Checks a frame and writes it as one line.
    pub fn write_frame(&mut self, frame: &Frame) -> Result<(), WriteError> {
        check::check_frame(&self.header, frame, self.previous).map_err(|p| WriteError::Frame {
            frame: self.frames,
            time: frame.time,
            field: p.field,
            message: p.message,
        })?;
        self.buf.clear();
        write_frame(&mut self.buf, &self.header, frame);
        self.out.write_all(&self.buf)?;
        self.previous = Some(frame.time);
        self.frames += 1;
        Ok(())
    }

    /// Flushes and returns the output.
    pub fn finish(mut self) -> Result<W, WriteError> {
        self.out.flush()?;
        Ok(self.out)
    }
}

/// Writes a JSON string literal.
pub(crate) fn json_string(buf: &mut Vec<u8>, s: &str) {
    let simple = s
        .bytes()
        .all(|c| c >= 0x20 && c != b'"' && c != b'\\' && c < 0x7f);
    if simple {
        buf.push(b'"');
        buf.extend_from_slice(s.as_bytes());
        buf.push(b'"');
    } else {
        // serde_json escapes exactly as JSON requires; a String always serialises.
        let text = serde_json::to_string(s).unwrap_or_default();
        buf.extend_from_slice(text.as_bytes());
    }
}

fn number(buf: &mut Vec<u8>, v: f32) {
    // Display for floats prints the shortest decimal that reads back to the same value,
    // without an exponent: always valid JSON for finite values.
    let _ = write!(buf, "{v}");
}

fn numbers(buf: &mut Vec<u8>, values: &[f32]) {
    buf.push(b'[');
    for (i, &v) in values.iter().enumerate() {
        if i > 0 {
            buf.push(b',');
        }
        number(buf, v);
    }
    buf.push(b']');
}

fn pose(buf: &mut Vec<u8>, p: &Pose) {
    buf.extend_from_slice(b"\"pos\":");
    numbers(buf, &p.position.to_array());
    buf.extend_from_slice(b",\"rot\":");
    numbers(buf, &p.orientation.to_array());
}

fn entity(buf: &mut Vec<u8>, e: &Entity) {
    buf.extend_from_slice(b"{\"name\":");
    json_string(buf, &e.name);
    buf.extend_from_slice(b",\"kind\":");
    json_string(buf, e.kind.name());
    buf.extend_from_slice(b",\"size\":");
    numbers(buf, &e.size.to_array());
    if let Some(p) = &e.fixed {
        buf.extend_from_slice(b",\"pose\":{");
        pose(buf, p);
        buf.push(b'}');
    }
    buf.push(b'}');
}

fn write_header(buf: &mut Vec<u8>, h: &Header) {
    buf.extend_from_slice(b"{\"format\":");
    json_string(buf, FORMAT_NAME);
    let _ = write!(buf, ",\"version\":{FORMAT_VERSION},\"id\":");
    json_string(buf, &h.id);
    buf.extend_from_slice(b",\"participant\":");
    json_string(buf, &h.participant);
    buf.extend_from_slice(b",\"task\":");
    json_string(buf, &h.task);
    let _ = write!(buf, ",\"frame_rate\":{},\"entities\":[", h.frame_rate);
    for (i, e) in h.entities.iter().enumerate() {
        if i > 0 {
            buf.push(b',');
        }
        entity(buf, e);
    }
    buf.push(b']');
    if !h.meta.is_empty() {
        buf.extend_from_slice(b",\"meta\":{");
        for (i, (k, v)) in h.meta.iter().enumerate() {
            if i > 0 {
                buf.push(b',');
            }
            json_string(buf, k);
            buf.push(b':');
            json_string(buf, v);
        }
        buf.push(b'}');
    }
    buf.extend_from_slice(b"}\n");
}

fn write_frame(buf: &mut Vec<u8>, h: &Header, f: &Frame) {
    let _ = write!(buf, "{{\"t\":{},\"entities\":{{", f.time);
    let mut first = true;
    for (e, state) in h.entities.iter().zip(&f.states) {
        let Some(s) = state else { continue };
        if !first {
            buf.push(b',');
        }
        first = false;
        json_string(buf, &e.name);
        buf.extend_from_slice(b":{");
        pose(buf, &s.pose);
        if let Some(v) = s.velocity {
            buf.extend_from_slice(b",\"vel\":");
            numbers(buf, &v.to_array());
        }
        if let Some(g) = s.grip {
            buf.extend_from_slice(b",\"grip\":");
            number(buf, g);
        }
        if let Some(held) = s.holding {
            buf.extend_from_slice(b",\"holding\":");
            json_string(buf, &h.entity(held).name);
        }
        buf.push(b'}');
    }
    buf.push(b'}');
    if !f.contacts.is_empty() {
        buf.extend_from_slice(b",\"contacts\":[");
        for (i, c) in f.contacts.iter().enumerate() {
            if i > 0 {
                buf.push(b',');
            }
            buf.push(b'[');
            json_string(buf, &h.entity(c.a).name);
            buf.push(b',');
            json_string(buf, &h.entity(c.b).name);
            buf.push(b']');
        }
        buf.push(b']');
    }
    buf.extend_from_slice(b"}\n");
}
