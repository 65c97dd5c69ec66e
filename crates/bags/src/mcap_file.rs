//! MCAP files (through the `mcap` crate's streaming `LinearReader`, which decompresses zstd
//! and lz4 chunks itself) and ROS 2 bag folders, whose `metadata.yaml` lists the files.

use std::collections::HashMap;
use std::io::{BufReader, Read};
use std::path::{Path, PathBuf};
use std::sync::Arc;

use mcap::records::Record;
use mcap::sans_io::{LinearReadEvent, LinearReader, LinearReaderOptions};

use crate::decode::Encoding;
use crate::{BagError, Connection, RawMessage, Topic};

pub const MAGIC: &[u8] = b"\x89MCAP0\r\n";

pub struct McapReader {
    path: PathBuf,
    file: BufReader<Box<dyn crate::Input>>,
    reader: LinearReader,
    /// Bytes handed to the reader so far: where in the file an error was found.
    consumed: u64,
    schemas: HashMap<u16, (String, String, String)>,
    channels: HashMap<u16, Arc<Connection>>,
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
            // allocated (the reader would otherwise reserve a chunk's stated size), and chunk
            // CRCs are checked so that a damaged uncompressed chunk is an error.
            reader: LinearReader::new_with_options(
                LinearReaderOptions::default()
                    .with_record_length_limit(
                        usize::try_from(crate::MAX_RECORD).unwrap_or(usize::MAX),
                    )
                    .with_validate_chunk_crcs(true),
            ),
            consumed: 0,
            schemas: HashMap::new(),
            channels: HashMap::new(),
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
                        Ok(record) => Owned::from(record),
                        Err(error) => return Err(self.error(error)),
                    }
                }
            };
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
