//! MCAP files (through the `mcap` crate's streaming `LinearReader`) and ROS 2 bag folders,
//! whose `metadata.yaml` lists the files.
//!
//! The reader hands us chunks whole (`emit_chunks`) and we open them here: `mcap` 0.26's
//! own descent into an uncompressed chunk subtracts each inner record's length from the
//! chunk's remaining size unchecked, which overflows (a panic with overflow checks, wrapped
//! garbage without) when a record claims more bytes than its chunk holds; the fuzzer found
//! it (`fuzz/regressions/bag_import/`). Opening the chunk ourselves bounds every inner
//! record by the chunk and reuses the decompressors we already have.

use std::collections::HashMap;
use std::io::{BufReader, Read};
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use mcap::records::Record;
use mcap::sans_io::{LinearReadEvent, LinearReader, LinearReaderOptions};

use crate::decode::Encoding;
use crate::{BagError, Codec, Connection, RawMessage, Topic};

pub const MAGIC: &[u8] = b"\x89MCAP0\r\n";

/// A record's opcode (1 byte) and length (8 bytes, little-endian) before its body.
const RECORD_PREFIX: usize = 9;

pub struct McapReader {
    path: PathBuf,
    file: BufReader<Box<dyn crate::Input>>,
    reader: LinearReader,
    /// Bytes handed to the reader so far: where in the file an error was found.
    consumed: u64,
    schemas: HashMap<u16, (String, String, String)>,
    channels: HashMap<u16, Arc<Connection>>,
    /// The records of the chunk being read, decompressed, and where the next one starts.
    chunk: Vec<u8>,
    chunk_next: usize,
    /// Where in the file the chunk being read ends (for errors inside it).
    chunk_offset: u64,
}

impl McapReader {
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Reads the MCAP file `file`; `path` names it in errors.
    pub fn new(path: &Path, file: Box<dyn crate::Input>) -> McapReader {
        McapReader {
            path: path.to_path_buf(),
            file: BufReader::with_capacity(1 << 16, file),
            // A chunk or record larger than this is taken for corrupt rather than
            // allocated (the reader would otherwise reserve a chunk's stated size). Chunks
            // come whole; `open_chunk` decompresses them and checks their CRCs.
            reader: LinearReader::new_with_options(
                LinearReaderOptions::default()
                    .with_record_length_limit(
                        usize::try_from(crate::MAX_RECORD).unwrap_or(usize::MAX),
                    )
                    .with_emit_chunks(true),
            ),
            consumed: 0,
            schemas: HashMap::new(),
            channels: HashMap::new(),
            chunk: Vec::new(),
            chunk_next: 0,
            chunk_offset: 0,
        }
    }

    fn error(&self, error: mcap::McapError) -> BagError {
        match error {
            mcap::McapError::UnsupportedCompression(compression) => BagError::UnknownCompression {
                path: self.path.clone(),
                offset: self.consumed,
                compression,
                supported: "none, zstd, lz4",
            },
            mcap::McapError::UnexpectedEof | mcap::McapError::UnexpectedEoc => BagError::Corrupt {
                path: self.path.clone(),
                offset: self.consumed,
                what: format!("truncated: {error}"),
            },
            other => BagError::Corrupt {
                path: self.path.clone(),
                offset: self.consumed,
                what: other.to_string(),
            },
        }
    }

    /// The next message in file order, or `None` at the end of the file.
    pub fn next_message(&mut self) -> Result<Option<RawMessage>, BagError> {
        loop {
            if let Some((opcode, range)) = self.next_chunk_record()? {
                let record = match mcap::parse_record(opcode, &self.chunk[range]) {
                    Ok(record) => Owned::from(record),
                    Err(error) => return Err(self.chunk_error(error.to_string())),
                };
                match self.take(record)? {
                    Some(message) => return Ok(Some(message)),
                    None => continue,
                }
            }
            let event = match self.reader.next_event() {
                None => return Ok(None),
                Some(event) => event,
            };
            let record = match event {
                Err(error) => return Err(self.error(error)),
                Ok(LinearReadEvent::ReadRequest(need)) => {
                    let buffer = self.reader.insert(need);
                    let read = match self.file.read(buffer) {
                        Ok(n) => n,
                        Err(source) => {
                            return Err(BagError::Io {
                                path: self.path.clone(),
                                source,
                            })
                        }
                    };
                    self.reader.notify_read(read);
                    self.consumed = self.consumed.saturating_add(read as u64);
                    continue;
                }
                Ok(LinearReadEvent::Record { opcode, data }) => {
                    match mcap::parse_record(opcode, data) {
                        Ok(Record::Chunk { header, data }) => {
                            let data = data.into_owned();
                            self.open_chunk(&header, data)?;
                            continue;
                        }
                        Ok(record) => Owned::from(record),
                        Err(error) => return Err(self.error(error)),
                    }
                }
            };
            if let Some(message) = self.take(record)? {
                return Ok(Some(message));
            }
        }
    }

    /// Takes a record in: schemas and channels are kept, a message is returned.
    fn take(&mut self, record: Owned) -> Result<Option<RawMessage>, BagError> {
        {
            match record {
                Owned::Schema {
                    id,
                    name,
                    encoding,
                    text,
                } => {
                    self.schemas.insert(id, (name, encoding, text));
                }
                Owned::Channel {
                    id,
                    schema_id,
                    topic,
                    message_encoding,
                } => {
                    let connection = self.connection(schema_id, topic, &message_encoding)?;
                    self.channels.insert(id, Arc::new(connection));
                }
                Owned::Message {
                    channel_id,
                    log_time,
                    data,
                } => {
                    let Some(connection) = self.channels.get(&channel_id) else {
                        return Err(BagError::Corrupt {
                            path: self.path.clone(),
                            offset: self.consumed,
                            what: format!(
                                "a message on channel {channel_id}, which the file never declares"
                            ),
                        });
                    };
                    return Ok(Some(RawMessage {
                        connection: connection.clone(),
                        receive_time: i64::try_from(log_time).unwrap_or(i64::MAX),
                        data,
                        offset: self.consumed,
                    }));
                }
                Owned::Other => {}
            }
        }
        Ok(None)
    }

    /// Decompresses a chunk (checking its size and CRC) for `next_chunk_record` to walk.
    fn open_chunk(
        &mut self,
        header: &mcap::records::ChunkHeader,
        data: Vec<u8>,
    ) -> Result<(), BagError> {
        self.chunk_offset = self.consumed;
        let size = header.uncompressed_size;
        if size > crate::MAX_RECORD {
            return Err(self.chunk_error(format!(
                "chunk of {size} bytes uncompressed is larger than the {} accepted",
                crate::MAX_RECORD
            )));
        }
        let compression = header.compression.as_str();
        let mut out = std::mem::take(&mut self.chunk);
        out.clear();
        const CODECS: [(&str, Codec); 3] = [
            ("", Codec::Stored),
            ("zstd", Codec::Zstd),
            ("lz4", Codec::Lz4),
        ];
        let at = (self.path.as_path(), self.consumed);
        let codec = Codec::named(&CODECS, compression, at, "none, zstd, lz4")?;
        let decoded = codec.decompress(data, size, &mut out);
        let shown = if compression.is_empty() {
            "uncompressed"
        } else {
            compression
        };
        if let Err(e) = decoded {
            return Err(self.chunk_error(format!("{shown} chunk does not decompress: {e}")));
        }
        if out.len() as u64 != size {
            return Err(self.chunk_error(format!(
                "{shown} chunk holds {} bytes, but its header says {size}",
                out.len()
            )));
        }
        // A CRC of 0 means none was written (MCAP's specification).
        let crc = crc32fast::hash(&out);
        if header.uncompressed_crc != 0 && crc != header.uncompressed_crc {
            return Err(self.chunk_error(format!(
                "chunk CRC mismatch: the header says {:08x}, the data gives {crc:08x}",
                header.uncompressed_crc
            )));
        }
        self.chunk = out;
        self.chunk_next = 0;
        Ok(())
    }

    /// The opcode and body of the open chunk's next record, bounded by the chunk; `None`
    /// when the chunk is done (or none is open).
    fn next_chunk_record(&mut self) -> Result<Option<(u8, Range<usize>)>, BagError> {
        let rest = self.chunk.len().saturating_sub(self.chunk_next);
        if rest == 0 {
            return Ok(None);
        }
        let start = self.chunk_next;
        let Some(prefix) = self.chunk.get(start..start.saturating_add(RECORD_PREFIX)) else {
            return Err(self.chunk_error(format!(
                "the chunk ends {rest} byte(s) into a record's opcode and length"
            )));
        };
        let mut length = [0u8; 8];
        length.copy_from_slice(&prefix[1..]);
        let length = u64::from_le_bytes(length);
        let opcode = prefix[0];
        // `prefix` is whole, so the chunk has at least RECORD_PREFIX bytes from `start`.
        let body = start.saturating_add(RECORD_PREFIX);
        let room = rest.saturating_sub(RECORD_PREFIX);
        let end = usize::try_from(length)
            .ok()
            .filter(|&length| length <= room)
            .and_then(|length| body.checked_add(length));
        let Some(end) = end else {
            return Err(self.chunk_error(format!(
                "a record (opcode {opcode:#04x}) of {length} bytes, but the chunk has {room} left"
            )));
        };
        self.chunk_next = end;
        Ok(Some((opcode, body..end)))
    }

    fn chunk_error(&self, what: String) -> BagError {
        BagError::Corrupt {
            path: self.path.clone(),
            offset: self.chunk_offset,
            what,
        }
    }

    fn connection(
        &self,
        schema_id: u16,
        topic: String,
        message_encoding: &str,
    ) -> Result<Connection, BagError> {
        let (type_name, schema_encoding, definition) = match self.schemas.get(&schema_id) {
            Some(schema) => schema.clone(),
            None => (String::new(), String::new(), String::new()),
        };
        let encoding = match message_encoding {
            "cdr" => Some(Encoding::Cdr),
            "ros1" => Some(Encoding::Ros1),
            _ => None,
        };
        let topic_info = Topic {
            name: topic,
            type_name: type_name.clone(),
            definition,
            encoding: encoding.unwrap_or(Encoding::Cdr),
            message_count: None,
        };
        let mut connection = Connection::new(topic_info);
        let unsupported = match (encoding, schema_encoding.as_str()) {
            (None, _) => Some(format!(
                "message encoding `{message_encoding}` is not supported (cdr, ros1)"
            )),
            (Some(_), "ros2msg" | "ros1msg") => None,
            (Some(_), "") => Some("the channel has no schema".to_string()),
            (Some(_), other) => Some(format!(
                "schema encoding `{other}` is not supported (ros2msg, ros1msg)"
            )),
        };
        if let Some(what) = unsupported {
            connection.schema = Err(crate::definition::DefinitionError { line: 0, what });
        }
        Ok(connection)
    }
}

/// The records this reader uses, owned so that the reader's buffer is free again.
enum Owned {
    Schema {
        id: u16,
        name: String,
        encoding: String,
        text: String,
    },
    Channel {
        id: u16,
        schema_id: u16,
        topic: String,
        message_encoding: String,
    },
    Message {
        channel_id: u16,
        log_time: u64,
        data: Vec<u8>,
    },
    Other,
}

impl From<Record<'_>> for Owned {
    fn from(record: Record<'_>) -> Owned {
        match record {
            Record::Schema { header, data } => Owned::Schema {
                id: header.id,
                name: header.name,
                encoding: header.encoding,
                text: String::from_utf8_lossy(&data).into_owned(),
            },
            Record::Channel(channel) => Owned::Channel {
                id: channel.id,
                schema_id: channel.schema_id,
                topic: channel.topic,
                message_encoding: channel.message_encoding,
            },
            Record::Message { header, data } => Owned::Message {
                channel_id: header.channel_id,
                log_time: header.log_time,
                data: data.into_owned(),
            },
            _ => Owned::Other,
        }
    }
}

/// `metadata.yaml` of a ROS 2 bag folder, the keys this reader needs.
#[derive(Debug, serde::Deserialize)]
struct Metadata {
    rosbag2_bagfile_information: BagInformation,
}

#[derive(Debug, serde::Deserialize)]
struct BagInformation {
    storage_identifier: String,
    relative_file_paths: Vec<String>,
    #[serde(default)]
    compression_mode: Option<String>,
    #[serde(default)]
    compression_format: Option<String>,
}

/// The MCAP files of a ROS 2 bag folder, in the order `metadata.yaml` lists them.
pub fn folder_files(folder: &Path) -> Result<Vec<PathBuf>, BagError> {
    let metadata_path = folder.join("metadata.yaml");
    let text = std::fs::read_to_string(&metadata_path).map_err(|source| BagError::Io {
        path: metadata_path.clone(),
        source,
    })?;
    let format = |what: String| BagError::Format {
        path: metadata_path.clone(),
        what,
    };
    let metadata: Metadata = serde_yaml_ng::from_str(&text).map_err(|e| format(e.to_string()))?;
    let info = metadata.rosbag2_bagfile_information;
    if info.storage_identifier != "mcap" {
        return Err(format(format!(
            "storage_identifier: `{}` is not supported, only `mcap` (`ros2 bag convert` converts a bag to MCAP storage)",
            info.storage_identifier
        )));
    }
    let mode = info.compression_mode.unwrap_or_default();
    if !(mode.is_empty() || mode.eq_ignore_ascii_case("none")) {
        return Err(format(format!(
            "compression_mode: `{mode}` ({}) is not supported; MCAP's own chunk compression is (`ros2 bag convert` rewrites the bag that way)",
            info.compression_format.unwrap_or_default()
        )));
    }
    if info.relative_file_paths.is_empty() {
        return Err(format("relative_file_paths: the bag lists no files".into()));
    }
    Ok(info
        .relative_file_paths
        .iter()
        .map(|file| folder.join(file))
        .collect())
}
