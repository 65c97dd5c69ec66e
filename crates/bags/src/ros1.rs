//! ROS 1 bags, format 2.0: a stream of records, each a header of `name=value` fields and a
//! data block, with messages grouped into chunks (uncompressed, bz2 or lz4 frames) and an
//! index of connections and chunk infos at the end.
//!
//! Why not the `rosbag` crate (0.6): it memory-maps the whole file and slices it by the
//! offsets the file states, so a truncated bag panics (a slice past the end) instead of
//! being an error, and it allocates a chunk's stated uncompressed size before checking
//! it. It also links the C lz4 and bzip2 libraries. The format is small, so this module
//! reads it itself, streaming from a `Read + Seek`: one decompressed chunk in memory at a
//! time, every stated length checked against what the file or chunk has left.

use std::collections::HashMap;
use std::io::{BufReader, Read, Seek, SeekFrom};
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::decode::Encoding;
use crate::{BagError, Codec, Connection, RawMessage, Topic};

const MAGIC: &[u8] = b"#ROSBAG V2.0\n";
const OP_MESSAGE: u8 = 0x02;
const OP_BAG_HEADER: u8 = 0x03;
const OP_INDEX: u8 = 0x04;
const OP_CHUNK: u8 = 0x05;
const OP_CHUNK_INFO: u8 = 0x06;
const OP_CONNECTION: u8 = 0x07;
/// Largest decompressed chunk accepted.
const MAX_CHUNK: u64 = crate::MAX_RECORD;
/// Largest record header accepted (headers hold a few short fields, or a connection's
/// definition).
const MAX_HEADER: u64 = 16 << 20;

/// Whether `start` (the first bytes of a file) is a ROS 1 bag.
pub fn is_ros1(start: &[u8]) -> bool {
    start.starts_with(b"#ROSBAG V")
}

/// The header fields of one record.
struct Fields<'a>(Vec<(&'a str, &'a [u8])>);

impl<'a> Fields<'a> {
    fn parse(bytes: &'a [u8]) -> Result<Fields<'a>, String> {
        let mut out = Vec::new();
        let mut rest = bytes;
        while !rest.is_empty() {
            if rest.len() < 4 {
                return Err("a record header ends inside a field length".into());
            }
            let n = u32::from_le_bytes([rest[0], rest[1], rest[2], rest[3]]) as usize;
            rest = &rest[4..];
            if n > rest.len() {
                return Err(format!(
                    "a header field of {n} bytes, but the header has {} left",
                    rest.len()
                ));
            }
            let (field, tail) = rest.split_at(n);
            rest = tail;
            let Some(eq) = field.iter().position(|&b| b == b'=') else {
                return Err("a header field without `=`".into());
            };
            let name = std::str::from_utf8(&field[..eq])
                .map_err(|_| "a header field name is not UTF-8".to_string())?;
            out.push((name, &field[eq.saturating_add(1)..]));
        }
        Ok(Fields(out))
    }

    fn get(&self, name: &str) -> Option<&'a [u8]> {
        self.0.iter().find(|(n, _)| *n == name).map(|(_, v)| *v)
    }

    fn op(&self) -> Result<u8, String> {
        match self.get("op") {
            Some([op]) => Ok(*op),
            Some(_) => Err("the `op` field is not one byte".into()),
            None => Err("a record without `op`".into()),
        }
    }

    fn u32(&self, name: &str) -> Result<u32, String> {
        match self.get(name) {
            Some(v) if v.len() == 4 => Ok(u32::from_le_bytes([v[0], v[1], v[2], v[3]])),
            Some(v) => Err(format!("`{name}` has {} bytes, not 4", v.len())),
            None => Err(format!("the record has no `{name}` field")),
        }
    }

    fn u64(&self, name: &str) -> Result<u64, String> {
        match self.get(name) {
            Some(v) if v.len() == 8 => {
                let mut b = [0u8; 8];
                b.copy_from_slice(v);
                Ok(u64::from_le_bytes(b))
            }
            Some(v) => Err(format!("`{name}` has {} bytes, not 8", v.len())),
            None => Err(format!("the record has no `{name}` field")),
        }
    }

    fn text(&self, name: &str) -> Result<String, String> {
        match self.get(name) {
            Some(v) => String::from_utf8(v.to_vec()).map_err(|_| format!("`{name}` is not UTF-8")),
            None => Err(format!("the record has no `{name}` field")),
        }
    }

    /// A ROS 1 `time` field: seconds then nanoseconds, as nanoseconds.
    fn time(&self, name: &str) -> Result<i64, String> {
        let t = self.u64(name)?;
        // Both halves are 32-bit: seconds times 10^9 plus nanoseconds fits i64 for any
        // u32 of seconds (below 4.3 * 10^18).
        let half = |x: u64| i64::from(u32::try_from(x & 0xffff_ffff).unwrap_or(u32::MAX));
        let (seconds, nanos) = (half(t), half(t >> 32));
        Ok(seconds.saturating_mul(1_000_000_000).saturating_add(nanos))
    }
}

/// A connection's header block: topic, type and definition.
fn connection(
    path: &Path,
    fields: &Fields<'_>,
    data: &[u8],
    offset: u64,
) -> Result<(u32, Connection), BagError> {
    let corrupt = |what: String| BagError::Corrupt {
        path: path.to_path_buf(),
        offset,
        what: format!("connection record: {what}"),
    };
    let id = fields.u32("conn").map_err(corrupt)?;
    let block = Fields::parse(data).map_err(corrupt)?;
    let topic = fields.text("topic").map_err(corrupt)?;
    let type_name = block.text("type").map_err(corrupt)?;
    let definition = block.text("message_definition").map_err(corrupt)?;
    Ok((
        id,
        Connection::new(Topic {
            name: topic,
            type_name,
            definition,
            encoding: Encoding::Ros1,
            message_count: None,
        }),
    ))
}

pub struct Ros1Reader {
    path: PathBuf,
    file: BufReader<Box<dyn crate::Input>>,
    /// Position of the next record in the file.
    pos: u64,
    /// Where the chunk section ends (the index starts).
    index_pos: u64,
    connections: HashMap<u32, Arc<Connection>>,
    /// The decompressed chunk being read and where in it the next record is.
    chunk: Vec<u8>,
    chunk_pos: usize,
    chunk_offset: u64,
}

impl Ros1Reader {
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Reads the bag `input` of `file_len` bytes; `path` names it in errors.
    pub fn new(
        path: &Path,
        input: Box<dyn crate::Input>,
        file_len: u64,
    ) -> Result<Ros1Reader, BagError> {
        let file = input;
        let mut reader = Ros1Reader {
            path: path.to_path_buf(),
            file: BufReader::with_capacity(1 << 16, file),
            pos: 0,
            index_pos: file_len,
            connections: HashMap::new(),
            chunk: Vec::new(),
            chunk_pos: 0,
            chunk_offset: 0,
        };
        let mut magic = [0u8; MAGIC.len()];
        reader.read_exact(&mut magic, "the version line")?;
        if magic != MAGIC {
            let line = String::from_utf8_lossy(&magic);
            return Err(reader.corrupt(
                0,
                format!("`{}` is not format 2.0 (`#ROSBAG V2.0`)", line.trim_end()),
            ));
        }
        reader.pos = MAGIC.len() as u64;
        let (header, _) = reader.record(file_len)?;
        let fields = Fields::parse(&header).map_err(|w| reader.corrupt(MAGIC.len() as u64, w))?;
        if fields.op() != Ok(OP_BAG_HEADER) {
            return Err(reader.corrupt(
                MAGIC.len() as u64,
                "the first record is not the bag header".into(),
            ));
        }
        let index_pos = fields
            .u64("index_pos")
            .map_err(|w| reader.corrupt(MAGIC.len() as u64, w))?;
        if index_pos == 0 {
            return Err(reader.corrupt(
                MAGIC.len() as u64,
                "the bag has no index: it was not closed (`rosbag reindex` repairs it)".into(),
            ));
        }
        if index_pos > file_len {
            return Err(reader.corrupt(
                file_len,
                format!("truncated: the bag header puts the index at byte {index_pos}, but the file ends at byte {file_len}"),
            ));
        }
        let first_record = reader.pos;
        // The index: every connection, and the message count of each in each chunk.
        reader.index_pos = file_len;
        reader.seek(index_pos)?;
        let mut counts: HashMap<u32, u64> = HashMap::new();
        let mut chunk_infos = 0u64;
        let mut connections = HashMap::new();
        while reader.pos < file_len {
            let offset = reader.pos;
            let (header, data) = reader.record(file_len)?;
            let fields = Fields::parse(&header).map_err(|w| reader.corrupt(offset, w))?;
            match fields.op().map_err(|w| reader.corrupt(offset, w))? {
                OP_CONNECTION => {
                    let (id, connection) = connection(path, &fields, &data, offset)?;
                    connections.insert(id, connection);
                }
                OP_CHUNK_INFO => {
                    chunk_infos = chunk_infos.saturating_add(1);
                    if data.len() % 8 != 0 {
                        return Err(reader.corrupt(
                            offset,
                            "chunk info: its counts are not pairs of u32".into(),
                        ));
                    }
                    for pair in data.chunks_exact(8) {
                        let conn = u32::from_le_bytes([pair[0], pair[1], pair[2], pair[3]]);
                        let count = u32::from_le_bytes([pair[4], pair[5], pair[6], pair[7]]);
                        let total = counts.entry(conn).or_default();
                        *total = total.saturating_add(u64::from(count));
                    }
                }
                _ => {}
            }
        }
        for (id, mut connection) in connections {
            // Without chunk infos (a bag of bare message records) the index gives no counts.
            connection.topic.message_count =
                (chunk_infos > 0).then(|| counts.get(&id).copied().unwrap_or(0));
            reader.connections.insert(id, Arc::new(connection));
        }
        reader.index_pos = index_pos;
        reader.seek(first_record)?;
        Ok(reader)
    }

    /// Every connection the index lists.
    pub fn connections(&self) -> impl Iterator<Item = &Arc<Connection>> {
        self.connections.values()
    }

    fn corrupt(&self, offset: u64, what: String) -> BagError {
        BagError::Corrupt {
            path: self.path.clone(),
            offset,
            what,
        }
    }

    fn seek(&mut self, pos: u64) -> Result<(), BagError> {
        self.file
            .seek(SeekFrom::Start(pos))
            .map_err(|source| BagError::Io {
                path: self.path.clone(),
                source,
            })?;
        self.pos = pos;
        Ok(())
    }

    fn read_exact(&mut self, buf: &mut [u8], what: &str) -> Result<(), BagError> {
        match self.file.read_exact(buf) {
            Ok(()) => {
                self.pos = self.pos.saturating_add(buf.len() as u64);
                Ok(())
            }
            Err(e) if e.kind() == std::io::ErrorKind::UnexpectedEof => {
                Err(self.corrupt(self.pos, format!("truncated: the file ends inside {what}")))
            }
            Err(source) => Err(BagError::Io {
                path: self.path.clone(),
                source,
            }),
        }
    }

    fn length(&mut self, end: u64, max: u64, what: &str) -> Result<usize, BagError> {
        let at = self.pos;
        let mut b = [0u8; 4];
        self.read_exact(&mut b, what)?;
        let n = u32::from_le_bytes(b) as u64;
        if n > end.saturating_sub(self.pos) {
            return Err(self.corrupt(
                at,
                format!(
                    "truncated: {what} of {n} bytes, but only {} are left",
                    end.saturating_sub(self.pos)
                ),
            ));
        }
        if n > max {
            return Err(self.corrupt(
                at,
                format!("{what} of {n} bytes is larger than the {max} accepted"),
            ));
        }
        // At most `max`, itself at most `MAX_RECORD` (256 MiB): fits usize.
        usize::try_from(n)
            .map_err(|_| self.corrupt(at, format!("{what} of {n} bytes does not fit in memory")))
    }

    /// The record at `self.pos`: its header and data, both read.
    fn record(&mut self, end: u64) -> Result<(Vec<u8>, Vec<u8>), BagError> {
        let n = self.length(end, MAX_HEADER, "a record header")?;
        let mut header = vec![0u8; n];
        self.read_exact(&mut header, "a record header")?;
        let n = self.length(end, MAX_CHUNK, "a record's data")?;
        let mut data = vec![0u8; n];
        self.read_exact(&mut data, "a record's data")?;
        Ok((header, data))
    }

    /// The next message in file order, or `None` at the end of the chunk section.
    pub fn next_message(&mut self) -> Result<Option<RawMessage>, BagError> {
        loop {
            if self.chunk_pos < self.chunk.len() {
                if let Some(message) = self.next_in_chunk()? {
                    return Ok(Some(message));
                }
                continue;
            }
            if self.pos >= self.index_pos {
                return Ok(None);
            }
            let offset = self.pos;
            let (header, data) = self.record(self.index_pos)?;
            let fields = Fields::parse(&header).map_err(|w| self.corrupt(offset, w))?;
            match fields.op().map_err(|w| self.corrupt(offset, w))? {
                OP_CHUNK => self.open_chunk(&fields, data, offset)?,
                OP_CONNECTION => {
                    let (id, connection) = connection(&self.path, &fields, &data, offset)?;
                    self.connections
                        .entry(id)
                        .or_insert_with(|| Arc::new(connection));
                }
                OP_MESSAGE => return self.message(&fields, data, offset).map(Some),
                OP_INDEX => {}
                op => {
                    return Err(self.corrupt(
                        offset,
                        format!("record op {op:#04x} does not belong in the chunk section"),
                    ))
                }
            }
        }
    }

    fn open_chunk(
        &mut self,
        fields: &Fields<'_>,
        data: Vec<u8>,
        offset: u64,
    ) -> Result<(), BagError> {
        let compression = fields
            .text("compression")
            .map_err(|w| self.corrupt(offset, format!("chunk: {w}")))?;
        let size = fields
            .u32("size")
            .map_err(|w| self.corrupt(offset, format!("chunk: {w}")))? as u64;
        if size > MAX_CHUNK {
            return Err(self.corrupt(
                offset,
                format!(
                    "chunk of {size} bytes uncompressed is larger than the {MAX_CHUNK} accepted"
                ),
            ));
        }
        let mut out = std::mem::take(&mut self.chunk);
        out.clear();
        const CODECS: [(&str, Codec); 3] = [
            ("none", Codec::Stored),
            ("bz2", Codec::Bz2),
            ("lz4", Codec::Lz4),
        ];
        let at = (self.path.as_path(), offset);
        let codec = Codec::named(&CODECS, &compression, at, "none, bz2, lz4")?;
        let decoded = codec.decompress(data, size, &mut out);
        decoded.map_err(|e| {
            self.corrupt(
                offset,
                format!("{compression} chunk does not decompress: {e}"),
            )
        })?;
        if out.len() as u64 != size {
            return Err(self.corrupt(
                offset,
                format!(
                    "{compression} chunk decompresses to {} bytes, but its header says {size}",
                    out.len()
                ),
            ));
        }
        self.chunk = out;
        self.chunk_pos = 0;
        self.chunk_offset = offset;
        Ok(())
    }

    /// The next record inside the current chunk: a message, or `None` after a connection.
    fn next_in_chunk(&mut self) -> Result<Option<RawMessage>, BagError> {
        let at = self.chunk_pos;
        let chunk_offset = self.chunk_offset;
        let corrupt = |what: String| BagError::Corrupt {
            path: self.path.clone(),
            offset: chunk_offset,
            what: format!("chunk, byte {at} of its data: {what}"),
        };
        let (header, data, next) = split_record(&self.chunk, at).map_err(corrupt)?;
        let fields = Fields::parse(header).map_err(corrupt)?;
        let op = fields.op().map_err(corrupt)?;
        let result = match op {
            OP_CONNECTION => {
                let (id, connection) = connection(&self.path, &fields, data, chunk_offset)?;
                self.connections
                    .entry(id)
                    .or_insert_with(|| Arc::new(connection));
                None
            }
            OP_MESSAGE => Some(self.message(&fields, data.to_vec(), chunk_offset)?),
            op => {
                return Err(corrupt(format!(
                    "record op {op:#04x} does not belong in a chunk"
                )))
            }
        };
        self.chunk_pos = next;
        Ok(result)
    }

    fn message(
        &self,
        fields: &Fields<'_>,
        data: Vec<u8>,
        offset: u64,
    ) -> Result<RawMessage, BagError> {
        let conn = fields
            .u32("conn")
            .map_err(|w| self.corrupt(offset, format!("message: {w}")))?;
        let time = fields
            .time("time")
            .map_err(|w| self.corrupt(offset, format!("message: {w}")))?;
        let Some(connection) = self.connections.get(&conn) else {
            return Err(self.corrupt(
                offset,
                format!("a message on connection {conn}, which the bag never declares"),
            ));
        };
        Ok(RawMessage {
            connection: connection.clone(),
            receive_time: time,
            data,
            offset,
        })
    }
}

/// Splits the record at `at` of a chunk into header, data and where the next one starts.
fn split_record(chunk: &[u8], at: usize) -> Result<(&[u8], &[u8], usize), String> {
    // Every position below is at most the chunk's length: checked before it is made.
    let take_len = |pos: usize| -> Result<(usize, usize), String> {
        let start = pos.saturating_add(4);
        let Some(b) = chunk.get(pos..start) else {
            return Err("truncated: the chunk ends inside a length".into());
        };
        let n = u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as usize;
        let left = chunk.len().saturating_sub(start);
        if n > left {
            return Err(format!(
                "truncated: a length of {n} bytes, but the chunk has {left} left"
            ));
        }
        Ok((n, start))
    };
    let (header_len, header_at) = take_len(at)?;
    let header_end = header_at.saturating_add(header_len);
    let (data_len, data_at) = take_len(header_end)?;
    let data_end = data_at.saturating_add(data_len);
    Ok((
        &chunk[header_at..header_end],
        &chunk[data_at..data_end],
        data_end,
    ))
}
