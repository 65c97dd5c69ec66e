//! The streaming reader: the header when it is made, then one frame at a time.

// A reader of untrusted input (issue 23): no arithmetic that can wrap or panic, no
// cast that can truncate; each such operation is checked, saturating or proved in range.
#![deny(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]

use std::io::{BufRead, Read};

use serde_json::Value;

use crate::check;
use crate::error::{ErrorKind, ReadError};
use crate::model::{Entity, EntityKind, Frame, Header, Pose, Quaternion, Vec3};
use crate::parser::{strip_position, FrameParser, LineError};
use crate::{FORMAT_NAME, FORMAT_VERSION};

/// Longest line of a recording, in bytes, without its line ending: 64 MiB. A frame of
/// all [`crate::MAX_ENTITIES`] entities with every field takes about 10 MB; a longer line
/// is an error ([`ErrorKind::LineTooLong`]) rather than a buffer that grows with the file
/// (a file with no newline at all).
pub const MAX_LINE_BYTES: usize = 64 << 20;

/// Reads a recording line by line. Memory use is bounded by the longest line (at most
/// [`MAX_LINE_BYTES`]), whatever the length of the recording.
///
/// Blank lines are skipped (and counted); lines may end in `\n` or `\r\n`; the last line
/// need not end in a newline. After an error the reader yields nothing more.
#[derive(Debug)]
pub struct Reader<R> {
    input: R,
    header: Header,
    parser: FrameParser,
    buf: Vec<u8>,
    line: u64,
    previous: Option<(f64, u64)>,
    failed: bool,
}

impl<R: BufRead> Reader<R> {
    /// Reads and checks the header.
    pub fn new(mut input: R) -> Result<Reader<R>, ReadError> {
        let mut buf = Vec::with_capacity(4096);
        let mut line = 0u64;
        let header = loop {
            match next_line(&mut input, &mut buf, &mut line)? {
                None => {
                    return Err(ReadError::new(
                        line.max(1),
                        1,
                        0,
                        "format",
                        ErrorKind::Empty,
                    ))
                }
                Some(()) => {
                    // A byte order mark, as some editors write, is not part of the JSON.
                    if line == 1 && buf.starts_with(b"\xEF\xBB\xBF") {
                        buf.drain(..3);
                    }
                    if is_blank(&buf) {
                        continue;
                    }
                    break parse_header(&buf, line)?;
                }
            }
        };
        Ok(Reader {
            input,
            parser: FrameParser::new(&header),
            header,
            buf,
            line,
            previous: None,
            failed: false,
        })
    }

    /// The header.
    pub fn header(&self) -> &Header {
        &self.header
    }

    /// The header, giving up the reader.
    pub fn into_header(self) -> Header {
        self.header
    }

    /// The number of the last line read (1-based; the header's line after [`Reader::new`]).
    pub fn line(&self) -> u64 {
        self.line
    }

    /// Reads the next frame into `frame`, reusing its allocations. Returns `false` at the
    /// end of the recording.
    pub fn read_frame(&mut self, frame: &mut Frame) -> Result<bool, ReadError> {
        if self.failed {
            return Ok(false);
        }
        let result = self.read_frame_inner(frame);
        if result.is_err() {
            self.failed = true;
        }
        result
    }

    fn read_frame_inner(&mut self, frame: &mut Frame) -> Result<bool, ReadError> {
        loop {
            if next_line(&mut self.input, &mut self.buf, &mut self.line)?.is_none() {
                return Ok(false);
            }
            if !is_blank(&self.buf) {
                break;
            }
        }
        let line = self.line;
        let time = self
            .parser
            .parse(&self.buf, frame)
            .map_err(|e| at_line(line, e))?;
        if let Some((previous, previous_line)) = self.previous {
            if frame.time <= previous {
                return Err(ReadError::new(
                    line,
                    time.column.saturating_add(1),
                    time.width,
                    "t",
                    ErrorKind::Time {
                        time: frame.time,
                        previous,
                        previous_line,
                    },
                ));
            }
        }
        self.previous = Some((frame.time, line));
        Ok(true)
    }
}

impl<R: BufRead> Iterator for Reader<R> {
    type Item = Result<Frame, ReadError>;

    fn next(&mut self) -> Option<Self::Item> {
        let mut frame = Frame::default();
        match self.read_frame(&mut frame) {
            Ok(true) => Some(Ok(frame)),
            Ok(false) => None,
            Err(e) => Some(Err(e)),
        }
    }
}

fn at_line(line: u64, e: LineError) -> ReadError {
    ReadError::new(line, e.column.saturating_add(1), e.width, e.field, e.kind)
}

fn is_blank(line: &[u8]) -> bool {
    line.iter().all(|c| matches!(c, b' ' | b'\t'))
}

/// Reads one line into `buf` without its line ending; `None` at the end of the input.
fn next_line<R: BufRead>(
    input: &mut R,
    buf: &mut Vec<u8>,
    line: &mut u64,
) -> Result<Option<()>, ReadError> {
    buf.clear();
    // At most the longest line and its `\r\n`: one byte more means the line is too long.
    const READ_AT_MOST: u64 = MAX_LINE_BYTES as u64 + 2;
    let this_line = line.saturating_add(1);
    let n = input
        .by_ref()
        .take(READ_AT_MOST)
        .read_until(b'\n', buf)
        .map_err(|e| ReadError::new(this_line, 1, 0, "", ErrorKind::Io(e)))?;
    if n == 0 {
        return Ok(None);
    }
    *line = this_line;
    let ended = buf.last() == Some(&b'\n');
    if ended {
        buf.pop();
        if buf.last() == Some(&b'\r') {
            buf.pop();
        }
    }
    if buf.len() > MAX_LINE_BYTES || (!ended && n as u64 == READ_AT_MOST) {
        return Err(ReadError::new(
            this_line,
            1,
            0,
            "",
            ErrorKind::LineTooLong {
                max: MAX_LINE_BYTES,
            },
        ));
    }
    Ok(Some(()))
}

/// A header error at the first occurrence of `"key"` in the line (or its start).
fn header_error(text: &[u8], line: u64, field: &str, key: &str, kind: ErrorKind) -> ReadError {
    let needle = format!("\"{key}\"");
    let found = text
        .windows(needle.len())
        .position(|w| w == needle.as_bytes());
    match found {
        Some(p) => ReadError::new(line, p.saturating_add(1), needle.len(), field, kind),
        None => ReadError::new(line, 1, 1, field, kind),
    }
}

fn parse_header(text: &[u8], line: u64) -> Result<Header, ReadError> {
    let value: Value = serde_json::from_slice(text).map_err(|e| {
        let kind = if e.is_eof() {
            ErrorKind::Truncated
        } else {
            ErrorKind::Syntax(strip_position(&e))
        };
        ReadError::new(line, e.column().max(1), 1, "", kind)
    })?;
    let Value::Object(obj) = value else {
        return Err(ReadError::new(
            line,
            1,
            1,
            "format",
            ErrorKind::MissingHeader,
        ));
    };
    let err = |field: &str, key: &str, kind: ErrorKind| header_error(text, line, field, key, kind);
    let invalid =
        |field: &str, key: &str, message: String| err(field, key, ErrorKind::Invalid(message));
    // A field of the wrong type is pointed at by its key; a missing one, at `format`.
    let wrong_type =
        |key: &str, expected: &str| invalid(key, key, format!("`{key}` must be {expected}"));
    let missing =
        |key: &str, what: &str| invalid(key, "format", format!("missing field `{key}`{what}"));
    match obj.get("format") {
        None => {
            return Err(ReadError::new(
                line,
                1,
                1,
                "format",
                ErrorKind::MissingHeader,
            ))
        }
        Some(Value::String(s)) if s == FORMAT_NAME => {}
        Some(other) => {
            let found = match other {
                Value::String(s) => s.clone(),
                v => v.to_string(),
            };
            return Err(err("format", "format", ErrorKind::NotARecording(found)));
        }
    }
    match obj.get("version") {
        Some(Value::Number(n)) if n.as_u64() == Some(u64::from(FORMAT_VERSION)) => {}
        Some(v) => return Err(err("version", "version", ErrorKind::Version(v.to_string()))),
        None => return Err(missing("version", " (the format version, 1)")),
    }
    for key in obj.keys() {
        if !matches!(
            key.as_str(),
            "format"
                | "version"
                | "id"
                | "participant"
                | "task"
                | "frame_rate"
                | "entities"
                | "meta"
        ) {
            return Err(invalid(
                key,
                key,
                format!(
                    "unknown field `{key}` (a header has format, version, id, participant, task, \
                     frame_rate, entities and meta)"
                ),
            ));
        }
    }
    let string = |key: &str| -> Result<String, ReadError> {
        match obj.get(key) {
            Some(Value::String(s)) => Ok(s.clone()),
            Some(_) => Err(wrong_type(key, "a string")),
            None => Err(missing(key, "")),
        }
    };
    let id = string("id")?;
    let participant = string("participant")?;
    let task = string("task")?;
    let frame_rate = match obj.get("frame_rate") {
        Some(Value::Number(n)) => n.as_f64().unwrap_or(f64::NAN),
        Some(_) => return Err(wrong_type("frame_rate", "a number")),
        None => return Err(missing("frame_rate", " (nominal frames per second)")),
    };
    let entities = match obj.get("entities") {
        // Before looking at each of them: a count over the limit is the whole story.
        Some(Value::Array(list)) if list.len() > check::MAX_ENTITIES => {
            return Err(invalid(
                "entities",
                "entities",
                check::too_many_entities_message(list.len()),
            ))
        }
        Some(Value::Array(list)) => list
            .iter()
            .enumerate()
            .map(|(i, v)| parse_entity(i, v, &err))
            .collect::<Result<Vec<_>, _>>()?,
        Some(_) => return Err(wrong_type("entities", "a list")),
        None => return Err(missing("entities", "")),
    };
    let meta = match obj.get("meta") {
        None => Default::default(),
        Some(Value::Object(m)) => m
            .iter()
            .map(|(k, v)| match v {
                Value::String(s) => Ok((k.clone(), s.clone())),
                _ => Err(invalid(
                    &format!("meta.{k}"),
                    k,
                    "meta values must be strings".into(),
                )),
            })
            .collect::<Result<_, _>>()?,
        Some(_) => return Err(wrong_type("meta", "an object of strings")),
    };
    let header = Header {
        id,
        participant,
        task,
        frame_rate,
        entities,
        meta,
    };
    check::check_header(&header).map_err(|p| {
        let key = p
            .field
            .rsplit(['.', '['])
            .next()
            .unwrap_or("")
            .trim_end_matches(']');
        // For a named entity, point at its name rather than the first `"name"`.
        let key = match p.field.strip_prefix("entities[") {
            Some(rest) => rest
                .split(']')
                .next()
                .and_then(|i| i.parse::<usize>().ok())
                .and_then(|i| header.entities.get(i))
                .map_or(key.to_string(), |e| e.name.clone()),
            None => key.to_string(),
        };
        invalid(&p.field, &key, p.message)
    })?;
    Ok(header)
}

fn parse_entity(
    i: usize,
    v: &Value,
    err: &dyn Fn(&str, &str, ErrorKind) -> ReadError,
) -> Result<Entity, ReadError> {
    let at = format!("entities[{i}]");
    let invalid = |field: &str, key: &str, m: String| err(field, key, ErrorKind::Invalid(m));
    let Value::Object(obj) = v else {
        return Err(invalid(
            &at,
            "entities",
            "an entity is an object with name, kind and size".into(),
        ));
    };
    let name = match obj.get("name") {
        Some(Value::String(s)) => s.clone(),
        _ => {
            return Err(invalid(
                &format!("{at}.name"),
                "entities",
                "an entity needs a `name` string".into(),
            ))
        }
    };
    for key in obj.keys() {
        if !matches!(key.as_str(), "name" | "kind" | "size" | "pose") {
            return Err(invalid(
                &format!("{at}.{key}"),
                key,
                format!("unknown field `{key}` (an entity has name, kind, size and pose)"),
            ));
        }
    }
    let kind = match obj.get("kind") {
        Some(Value::String(s)) => EntityKind::from_name(s).ok_or_else(|| {
            invalid(
                &format!("{at}.kind"),
                s,
                format!("unknown kind `{s}` (hand, cube, table or other)"),
            )
        })?,
        _ => {
            return Err(invalid(
                &format!("{at}.kind"),
                &name,
                "an entity needs a `kind`: hand, cube, table or other".into(),
            ))
        }
    };
    let size = numbers::<3>(obj.get("size"), &format!("{at}.size"), &name, &invalid)?;
    let fixed = match obj.get("pose") {
        None => None,
        Some(Value::Object(p)) => {
            let pos = numbers::<3>(p.get("pos"), &format!("{at}.pose.pos"), &name, &invalid)?;
            let rot = numbers::<4>(p.get("rot"), &format!("{at}.pose.rot"), &name, &invalid)?;
            if let Some(k) = p.keys().find(|k| !matches!(k.as_str(), "pos" | "rot")) {
                return Err(invalid(
                    &format!("{at}.pose.{k}"),
                    k,
                    format!("unknown field `{k}` (a pose has pos and rot)"),
                ));
            }
            Some(Pose {
                position: Vec3::from_array(pos),
                orientation: Quaternion::from_array(rot),
            })
        }
        Some(_) => {
            return Err(invalid(
                &format!("{at}.pose"),
                "pose",
                "`pose` is an object with pos and rot".into(),
            ))
        }
    };
    Ok(Entity {
        name,
        kind,
        size: Vec3::from_array(size),
        fixed,
    })
}

fn numbers<const N: usize>(
    v: Option<&Value>,
    field: &str,
    near: &str,
    invalid: &dyn Fn(&str, &str, String) -> ReadError,
) -> Result<[f32; N], ReadError> {
    let bad = || {
        invalid(
            field,
            near,
            format!("`{field}` must be a list of {N} numbers"),
        )
    };
    let Some(Value::Array(list)) = v else {
        return Err(bad());
    };
    if list.len() != N {
        return Err(bad());
    }
    let mut out = [0.0f32; N];
    for (slot, v) in out.iter_mut().zip(list) {
        // The format's numbers are f32: rounding is the point, and one too large for
        // f32 becomes an infinity, refused below.
        #[allow(clippy::cast_possible_truncation)]
        let narrowed = v.as_f64().ok_or_else(bad)? as f32;
        *slot = narrowed;
        if !slot.is_finite() {
            return Err(invalid(field, near, format!("`{field}` is not finite")));
        }
    }
    Ok(out)
}

#[cfg(test)]
#[allow(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)] // tests, not readers
mod tests {
    use super::*;

    const HEADER: &str = r#"{"format":"demoplan-recording","version":1,"id":"r","participant":"p","task":"t","frame_rate":90,"entities":[{"name":"h","kind":"hand","size":[0.1,0.1,0.1]},{"name":"c","kind":"cube","size":[0.05,0.05,0.05]},{"name":"table","kind":"table","size":[1,1,0.7],"pose":{"pos":[0,0,0.35],"rot":[0,0,0,1]}}]}"#;

    fn read(frames: &str) -> Result<Vec<Frame>, ReadError> {
        let text = format!("{HEADER}\n{frames}");
        Reader::new(text.as_bytes())?.collect()
    }

    fn error_of(frames: &str) -> ReadError {
        read(frames).unwrap_err()
    }

    const H: &str = r#""h":{"pos":[0,0,1],"rot":[0,0,0,1],"grip":0.5}"#;

    #[test]
    fn reads_frames_with_every_field() {
        let f = read(&format!(
            "{{\"t\":0,\"entities\":{{{H},\"c\":{{\"pos\":[1,2,3],\"rot\":[0,0,0.7071068,0.7071068],\"vel\":[0.1,0,0]}}}},\"contacts\":[[\"c\",\"table\"]]}}\n\r\n\
             {{\"t\":0.5,\"entities\":{{\"c\":{{\"pos\":[1,2,3],\"rot\":[0,0,0,1]}},\"h\":{{\"pos\":[0,0,1],\"rot\":[0,0,0,1],\"grip\":1,\"holding\":\"c\"}}}}}}"
        ))
        .unwrap();
        assert_eq!(f.len(), 2);
        assert_eq!(f[0].contacts.len(), 1);
        assert_eq!(
            f[0].states[1].unwrap().velocity,
            Some(Vec3::new(0.1, 0.0, 0.0))
        );
        assert_eq!(f[1].states[0].unwrap().holding, Some(crate::EntityId(1)));
        assert!(f[1].states[2].is_none());
    }

    #[test]
    fn errors_name_line_and_field() {
        // A case a line: the error's code, its field (`-`: none) and the frames, `\n`
        // between two.
        let cases = r#"
not-finite      entities.h.pos[1]   {"t":0,"entities":{"h":{"pos":[0,NaN,1],"rot":[0,0,0,1],"grip":0.5}}}
unknown-entity  entities.x          {"t":0,"entities":{"x":{}}}
invalid         entities.h.grip     {"t":0,"entities":{"h":{"pos":[0,0,1],"rot":[0,0,0,1],"grip":1.5}}}
invalid         entities.h          {"t":0,"entities":{"h":{"pos":[0,0,1],"rot":[0,0,0,1]}}}
invalid         entities.h.rot      {"t":0,"entities":{"h":{"pos":[0,0,1],"rot":[0,0,0,2],"grip":0}}}
invalid         entities.table      {"t":0,"entities":{"table":{}}}
invalid         entities.c.pos      {"t":0,"entities":{"c":{"pos":[0,0],"rot":[0,0,0,1]}}}
invalid         entities.c.grip     {"t":0,"entities":{"c":{"pos":[0,0,1],"rot":[0,0,0,1],"grip":0}}}
invalid         entities.h.holding  {"t":0,"entities":{"h":{"pos":[0,0,1],"rot":[0,0,0,1],"grip":0,"holding":"h"}}}
unknown-entity  entities.h.holding  {"t":0,"entities":{"h":{"pos":[0,0,1],"rot":[0,0,0,1],"grip":0,"holding":"q"}}}
invalid         contacts[0]         {"t":0,"contacts":[["c","c"]]}
unknown-entity  contacts[0][1]      {"t":0,"contacts":[["c","z"]]}
truncated       entities            {"t":0,"entities":{"c":{"pos":[0,0,1],"rot":[0,0,0,1]}
truncated       entities.c.pos      {"t":0,"entities":{"c":{"pos":[0,0,1
invalid         velocity            {"t":0,"velocity":1}
invalid         t                   {"entities":{}}
syntax          -                   {"t":0} x
time            t                   {"t":1}\n{"t":1}
not-finite      t                   {"t":1}\n{"t":Infinity}
"#;
        for case in cases.lines().filter(|l| !l.is_empty()) {
            let (code, rest) = case.split_once(' ').unwrap();
            let (field, frames) = rest.trim_start().split_once(' ').unwrap();
            let field = if field == "-" { "" } else { field };
            let frames = frames.trim_start().replace("\\n", "\n");
            let e = error_of(&frames);
            assert_eq!(
                (e.field.as_str(), e.kind.code()),
                (field, code),
                "{frames}: {e}"
            );
            assert!(e.line >= 2, "{frames}: {e}");
        }
        let e = error_of("{\"t\":2}\n\n{\"t\":1.5}");
        assert_eq!(e.line, 4);
        assert_eq!(e.column, 6);
        assert_eq!(
            e.to_string(),
            "line 4, field `t`: time 1.5 s is not after the previous frame's 2 s (line 2)"
        );
    }

    #[test]
    fn a_byte_order_mark_is_skipped() {
        let text = format!("\u{feff}{HEADER}\n{{\"t\":0}}\n");
        let frames: Vec<Frame> = Reader::new(text.as_bytes())
            .unwrap()
            .map(|f| f.unwrap())
            .collect();
        assert_eq!(frames.len(), 1);
    }

    #[test]
    fn header_errors() {
        let cases: &[(&str, &str, &str)] = &[
            ("", "format", "empty"),
            ("\n\n", "format", "empty"),
            (r#"{"t":0}"#, "format", "missing-header"),
            (r#"{"format":"other","version":1}"#, "format", "format"),
            (
                r#"{"format":"demoplan-recording","version":2}"#,
                "version",
                "version",
            ),
            (
                r#"{"format":"demoplan-recording","version":1,"id":"r""#,
                "",
                "truncated",
            ),
            (
                r#"{"format":"demoplan-recording","version":1,"id":"r","participant":"p","task":"t","frame_rate":0,"entities":[]}"#,
                "frame_rate",
                "invalid",
            ),
            (
                r#"{"format":"demoplan-recording","version":1,"id":"r","participant":"p","task":"t","frame_rate":9,"entities":[{"name":"a","kind":"robot","size":[1,1,1]}]}"#,
                "entities[0].kind",
                "invalid",
            ),
            (
                r#"{"format":"demoplan-recording","version":1,"id":"r","participant":"p","task":"t","frame_rate":9,"entities":[{"name":"a","kind":"cube","size":[1,1,1]},{"name":"A","kind":"cube","size":[1,1,1]}]}"#,
                "entities[1].name",
                "invalid",
            ),
        ];
        for (text, field, code) in cases {
            let e = Reader::new(text.as_bytes()).unwrap_err();
            assert_eq!(
                (e.field.as_str(), e.kind.code()),
                (*field, *code),
                "{text}: {e}"
            );
        }
    }

    /// A header declaring `n` cubes.
    fn header_with_cubes(n: usize) -> String {
        let cubes: Vec<String> = (0..n)
            .map(|i| format!(r#"{{"name":"c{i}","kind":"cube","size":[0.05,0.05,0.05]}}"#))
            .collect();
        format!(
            r#"{{"format":"demoplan-recording","version":1,"id":"r","participant":"p","task":"t","frame_rate":90,"entities":[{}]}}"#,
            cubes.join(",")
        )
    }

    #[test]
    fn a_header_of_65535_entities_or_more_is_refused_naming_its_field() {
        let most = header_with_cubes(crate::MAX_ENTITIES);
        assert_eq!(
            Reader::new(most.as_bytes())
                .unwrap()
                .header()
                .entities
                .len(),
            65_534
        );
        for n in [crate::MAX_ENTITIES + 1, 70_000] {
            let text = format!("{}\n{{\"t\":0}}\n", header_with_cubes(n));
            let e = Reader::new(text.as_bytes()).unwrap_err();
            assert_eq!(
                (e.line, e.field.as_str(), e.kind.code()),
                (1, "entities", "invalid")
            );
            assert!(e.to_string().contains(&format!("{n} entities")), "{e}");
            assert!(e.to_string().contains("at most 65534"), "{e}");
            // The column points at the `"entities"` key.
            assert_eq!(&text[e.column as usize - 1..][..10], "\"entities\"");
        }
    }

    #[test]
    fn a_line_longer_than_the_maximum_is_an_error_naming_it() {
        // A frame line padded with spaces (valid JSON) to exactly the longest line, then
        // one byte longer; and a file that never ends its line.
        let frame = |len: usize| {
            let mut line = String::from("{\"t\":0");
            line.push_str(&" ".repeat(len - line.len() - 1));
            line.push('}');
            line
        };
        let longest = format!("{HEADER}\n{}\r\n{{\"t\":1}}\n", frame(MAX_LINE_BYTES));
        let frames: Vec<Frame> = Reader::new(longest.as_bytes())
            .unwrap()
            .map(|f| f.unwrap())
            .collect();
        assert_eq!(frames.len(), 2);
        for (text, line) in [
            (
                format!("{HEADER}\n{}\n{{\"t\":1}}\n", frame(MAX_LINE_BYTES + 1)),
                2,
            ),
            (
                format!("{HEADER}\n{{\"t\":0}}\n{}", "x".repeat(MAX_LINE_BYTES * 2)),
                3,
            ),
        ] {
            let e = Reader::new(text.as_bytes())
                .unwrap()
                .collect::<Result<Vec<Frame>, _>>()
                .unwrap_err();
            assert_eq!((e.line, e.kind.code()), (line, "line-too-long"), "{e}");
            assert!(e.to_string().contains("longer than 67108864 bytes"), "{e}");
        }
        let e =
            Reader::new(format!("{}\n", " ".repeat(MAX_LINE_BYTES + 1)).as_bytes()).unwrap_err();
        assert_eq!((e.line, e.kind.code()), (1, "line-too-long"));
    }
}
