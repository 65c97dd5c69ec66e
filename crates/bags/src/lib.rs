//! ROS bags: ROS 1 bags (format 2.0, chunks uncompressed, bz2 or lz4), bare MCAP files
//! (chunks uncompressed, zstd or lz4) and ROS 2 bag folders (a `metadata.yaml` beside their
//! MCAP files). This crate knows nothing of recordings: it lists a bag's topics and streams
//! its messages, each decoded by the definition the bag itself carries (a ROS 1 connection
//! header's `message_definition`, an MCAP `ros1msg`/`ros2msg` schema) into a dynamic
//! [`Value`] tree that is looked up by field path. No message type is compiled in, so
//! `tf2_msgs/TFMessage` and a lab's own object-list message are read the same way.
//!
//! ```no_run
//! let bag = bags::open(std::path::Path::new("demo.bag"))?;
//! for message in bag.messages(|topic| topic == "/tf")? {
//!     let message = message?;
//!     for x in message.value.lookup("transforms[].transform.translation.x").map_err(|e| e)? {
//!         println!("{} {:?}", message.receive_time, x.as_f64());
//!     }
//! }
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```
//!
//! Messages come in file order, which is the order recorders write them in (receive
//! time); `Message::index` counts the messages of one topic. Memory is bounded by the
//! largest chunk (ROS 1) or record (MCAP), never by the file. Every problem is a
//! [`BagError`] naming the file and a byte offset, or the topic, message and field.

// A reader of untrusted input, every module of it (issue 23): no arithmetic that can wrap
// or panic, no cast that can truncate; each such operation is checked, saturating or
// proved in range.
#![deny(clippy::arithmetic_side_effects, clippy::cast_possible_truncation)]

mod counting;
mod decode;
pub mod definition;
mod mcap_file;
mod ros1;
mod value;

use std::collections::{BTreeMap, HashMap};
use std::io::Read;
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicU64;
use std::sync::Arc;

pub use counting::CountingReader;
pub use decode::{decode, DecodeError, Encoding};
pub use definition::{DefinitionError, Schema};
pub use value::{Message as MessageValue, Value};

/// Largest chunk (decompressed) or record accepted, in bytes. Recorders write chunks of
/// 768 KiB (`rosbag record`), 1 MiB (rosbags) or a few MiB (MCAP writers); a chunk or
/// record claiming more than this is taken for corrupt rather than allocated.
pub const MAX_RECORD: u64 = 256 << 20;

/// Decompresses into `out`, refusing more than `size` bytes (one more is read, so that a
/// chunk longer than its header says shows in `out`'s length).
fn read_bounded(decoder: impl std::io::Read, size: u64, out: &mut Vec<u8>) -> std::io::Result<()> {
    use std::io::Read;
    // `size` is at most `MAX_RECORD` (checked by the callers): a hint that fits usize.
    out.reserve(usize::try_from(size).unwrap_or(0));
    decoder.take(size.saturating_add(1)).read_to_end(out)?;
    Ok(())
}

/// A chunk's compression, under the names of the two chunked formats: MCAP's `""`,
/// `zstd`, `lz4` and ROS 1's `none`, `bz2`, `lz4`.
#[derive(Debug, Clone, Copy)]
enum Codec {
    Stored,
    Zstd,
    Bz2,
    Lz4,
}

impl Codec {
    /// The codec a format names `name` in its `table`; an unknown name is
    /// [`BagError::UnknownCompression`] at `offset`, listing `supported`.
    fn named(
        table: &[(&str, Codec)],
        name: &str,
        (path, offset): (&Path, u64),
        supported: &'static str,
    ) -> Result<Codec, BagError> {
        let found = table.iter().find(|(n, _)| *n == name).map(|&(_, c)| c);
        found.ok_or_else(|| BagError::UnknownCompression {
            path: path.to_path_buf(),
            offset,
            compression: name.to_string(),
            supported,
        })
    }

    /// Decompresses a chunk's `data`, `size` bytes uncompressed, into `out` (stored data
    /// becomes `out` itself), refusing more than `size` bytes ([`read_bounded`]).
    fn decompress(self, data: Vec<u8>, size: u64, out: &mut Vec<u8>) -> std::io::Result<()> {
        match self {
            Codec::Stored => {
                *out = data;
                Ok(())
            }
            Codec::Zstd => zstd::stream::read::Decoder::new(&data[..])
                .and_then(|decoder| read_bounded(decoder, size, out)),
            Codec::Bz2 => read_bounded(bzip2::read::BzDecoder::new(&data[..]), size, out),
            Codec::Lz4 => read_bounded(lz4_flex::frame::FrameDecoder::new(&data[..]), size, out),
        }
    }
}

/// Largest message decoded, in bytes of its serialization: 16 MiB. The topics an import
/// reads (`/tf`, poses, object lists) carry a few kilobytes per message, and a decoded
/// [`Value`] tree takes several times its bytes, so a larger message of a wanted topic is
/// an error ([`BagError::MessageTooLarge`]) naming its topic and index. Messages of other
/// topics (camera images, point clouds) are skipped undecoded, whatever their size.
pub const MAX_MESSAGE: u64 = 16 << 20;

/// Something wrong with a bag: always the file, and where in it.
#[derive(Debug, thiserror::Error)]
pub enum BagError {
    #[error("{}: {source}", path.display())]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    /// Not a bag, or a ROS 2 folder whose metadata this reader cannot use.
    #[error("{}: {what}", path.display())]
    Format { path: PathBuf, what: String },
    /// The container is broken: truncated, a record that does not parse.
    #[error("{}: byte {offset}: {what}", path.display())]
    Corrupt {
        path: PathBuf,
        offset: u64,
        what: String,
    },
    #[error("{}: byte {offset}: chunk compression `{compression}` is not supported (supported: {supported})", path.display())]
    UnknownCompression {
        path: PathBuf,
        offset: u64,
        compression: String,
        supported: &'static str,
    },
    #[error("{}: topic {topic}: the definition of {type_name} does not parse: {source}", path.display())]
    Definition {
        path: PathBuf,
        topic: String,
        type_name: String,
        #[source]
        source: DefinitionError,
    },
    #[error("{}: topic {topic}: message {index} (byte {offset} of the file) has {size} bytes, more than the {MAX_MESSAGE} a decoded message may have", path.display())]
    MessageTooLarge {
        path: PathBuf,
        topic: String,
        /// Position of the message among its topic's messages, from 0.
        index: u64,
        offset: u64,
        size: u64,
    },
    #[error("{}: topic {topic}: message {index} (byte {offset} of the file): {source}", path.display())]
    Decode {
        path: PathBuf,
        topic: String,
        /// Position of the message among its topic's messages, from 0.
        index: u64,
        offset: u64,
        #[source]
        source: DecodeError,
    },
}

impl BagError {
    /// The message without the file's path in front (for callers that show the file
    /// themselves).
    pub fn detail(&self) -> String {
        let full = self.to_string();
        let prefix = format!("{}: ", self.path().display());
        match full.strip_prefix(&prefix) {
            Some(rest) => rest.to_string(),
            None => full,
        }
    }

    /// The file the error is about.
    pub fn path(&self) -> &Path {
        match self {
            BagError::Io { path, .. }
            | BagError::Format { path, .. }
            | BagError::Corrupt { path, .. }
            | BagError::UnknownCompression { path, .. }
            | BagError::Definition { path, .. }
            | BagError::MessageTooLarge { path, .. }
            | BagError::Decode { path, .. } => path,
        }
    }
}

/// A topic as the bag declares it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Topic {
    pub name: String,
    /// The message type, `pkg/Type` or `pkg/msg/Type` as the bag writes it.
    pub type_name: String,
    /// The definition text the bag carries.
    pub definition: String,
    pub encoding: Encoding,
    /// How many messages the topic has, where the bag says (or once counted).
    pub message_count: Option<u64>,
}

/// A ROS 1 connection or MCAP channel: its topic and compiled definition.
#[derive(Debug)]
pub(crate) struct Connection {
    pub topic: Topic,
    pub schema: Result<Arc<Schema>, DefinitionError>,
}

impl Connection {
    fn new(topic: Topic) -> Connection {
        let schema = Schema::parse(&topic.type_name, &topic.definition).map(Arc::new);
        Connection { topic, schema }
    }
}

/// A message before decoding.
#[derive(Debug)]
pub(crate) struct RawMessage {
    pub connection: Arc<Connection>,
    /// Nanoseconds since the epoch (ROS 1 record time, MCAP log time).
    pub receive_time: i64,
    pub data: Vec<u8>,
    /// Byte offset of the record (ROS 1: of the chunk holding it) in the file.
    pub offset: u64,
}

/// One decoded message.
#[derive(Debug, Clone)]
pub struct Message {
    pub topic: Arc<str>,
    pub type_name: Arc<str>,
    /// The compiled definition, for checking field paths.
    pub schema: Arc<Schema>,
    /// Position among the messages of this topic, from 0.
    pub index: u64,
    /// When the recorder received it, in nanoseconds since the epoch.
    pub receive_time: i64,
    pub value: Value,
}

/// What the readers read from: a file, or bytes in memory.
pub(crate) trait Input: std::io::Read + std::io::Seek {}

impl<T: std::io::Read + std::io::Seek> Input for T {}

/// Where a bag's bytes are.
#[derive(Debug, Clone)]
enum Storage {
    /// The files (one, or a ROS 2 folder's), in reading order.
    Files(Vec<PathBuf>),
    /// One bag or MCAP file in memory.
    Memory(Arc<[u8]>),
}

/// The container formats.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    Ros1,
    Mcap,
    /// A ROS 2 bag folder with `metadata.yaml` and MCAP storage.
    Ros2Folder,
}

/// An opened bag: its format and files. Reading starts anew at each [`Bag::messages`].
#[derive(Debug, Clone)]
pub struct Bag {
    path: PathBuf,
    format: Format,
    storage: Storage,
    /// Where every read adds its bytes, if someone watches (see [`Bag::count_bytes_read`]).
    bytes_read: Option<Arc<AtomicU64>>,
}

/// The container format the first bytes of a file announce, if they announce one.
pub fn sniff(start: &[u8]) -> Option<Format> {
    if ros1::is_ros1(start) {
        Some(Format::Ros1)
    } else if start.starts_with(mcap_file::MAGIC) {
        Some(Format::Mcap)
    } else {
        None
    }
}

/// Opens a ROS 1 bag, an MCAP file, or a ROS 2 bag folder (or its `metadata.yaml`).
pub fn open(path: &Path) -> Result<Bag, BagError> {
    let folder = if path.is_dir() {
        Some(path.to_path_buf())
    } else if path.file_name().is_some_and(|n| n == "metadata.yaml") {
        path.parent().map(Path::to_path_buf)
    } else {
        None
    };
    if let Some(folder) = folder {
        let files = mcap_file::folder_files(&folder)?;
        return Ok(Bag {
            path: folder,
            format: Format::Ros2Folder,
            storage: Storage::Files(files),
            bytes_read: None,
        });
    }
    let io = |source| BagError::Io {
        path: path.to_path_buf(),
        source,
    };
    let mut start = Vec::with_capacity(16);
    std::fs::File::open(path)
        .map_err(io)?
        .take(16)
        .read_to_end(&mut start)
        .map_err(io)?;
    let format = if ros1::is_ros1(&start) {
        Format::Ros1
    } else if start.starts_with(mcap_file::MAGIC) {
        Format::Mcap
    } else if start.is_empty() {
        return Err(BagError::Format {
            path: path.to_path_buf(),
            what: "the file is empty".into(),
        });
    } else {
        return Err(BagError::Format {
            path: path.to_path_buf(),
            what: "not a ROS 1 bag (`#ROSBAG V2.0`), an MCAP file or a ROS 2 bag folder".into(),
        });
    };
    Ok(Bag {
        path: path.to_path_buf(),
        format,
        storage: Storage::Files(vec![path.to_path_buf()]),
        bytes_read: None,
    })
}

/// A ROS 1 bag or MCAP file held in memory; `name` stands for it in errors.
pub fn from_bytes(name: &Path, bytes: Vec<u8>) -> Result<Bag, BagError> {
    let format = match sniff(&bytes) {
        Some(format) => format,
        None if bytes.is_empty() => {
            return Err(BagError::Format {
                path: name.to_path_buf(),
                what: "the file is empty".into(),
            })
        }
        None => {
            return Err(BagError::Format {
                path: name.to_path_buf(),
                what: "not a ROS 1 bag (`#ROSBAG V2.0`) or an MCAP file".into(),
            })
        }
    };
    Ok(Bag {
        path: name.to_path_buf(),
        format,
        storage: Storage::Memory(Arc::from(bytes)),
        bytes_read: None,
    })
}

impl Bag {
    pub fn path(&self) -> &Path {
        &self.path
    }

    pub fn format(&self) -> Format {
        self.format
    }

    /// From now on, every byte read from the bag's storage ([`Bag::topics`],
    /// [`Bag::messages`]) is added to `bytes_read`, for a progress display. Seeks (a ROS 1
    /// bag's index) add nothing.
    pub fn count_bytes_read(&mut self, bytes_read: Arc<AtomicU64>) {
        self.bytes_read = Some(bytes_read);
    }

    /// The bytes of the bag's storage: the file's size, or the sum of a ROS 2 folder's
    /// MCAP files. A full pass reads this many.
    pub fn size(&self) -> Result<u64, BagError> {
        match &self.storage {
            Storage::Memory(bytes) => Ok(bytes.len() as u64),
            Storage::Files(files) => files.iter().try_fold(0u64, |sum, path| {
                let meta = std::fs::metadata(path).map_err(|source| BagError::Io {
                    path: path.clone(),
                    source,
                })?;
                Ok(sum.saturating_add(meta.len()))
            }),
        }
    }

    /// `input`, counted if someone watches.
    fn counted(&self, input: Box<dyn Input>) -> Box<dyn Input> {
        match &self.bytes_read {
            Some(counter) => Box::new(CountingReader::new(input, counter.clone())),
            None => input,
        }
    }

    /// The topics, by name. A ROS 1 bag's index lists them; MCAP files are read through
    /// once (without decoding) to find them and count their messages.
    pub fn topics(&self) -> Result<Vec<Topic>, BagError> {
        let mut topics: BTreeMap<String, Topic> = BTreeMap::new();
        let mut add = |topic: &Topic, count: u64| {
            let entry = topics.entry(topic.name.clone()).or_insert_with(|| Topic {
                message_count: Some(0),
                ..topic.clone()
            });
            entry.message_count = Some(entry.message_count.unwrap_or(0).saturating_add(count));
        };
        let mut counted = false;
        if self.format == Format::Ros1 {
            let reader = self.ros1_reader()?;
            counted = reader
                .connections()
                .all(|c| c.topic.message_count.is_some());
            for connection in reader.connections() {
                add(
                    &connection.topic,
                    connection.topic.message_count.unwrap_or(0),
                );
            }
        }
        if !counted {
            // Count by reading through: MCAP, or a ROS 1 bag whose index has no counts.
            for topic in topics.values_mut() {
                topic.message_count = Some(0);
            }
            let mut source = self.source()?;
            while let Some(raw) = source.next_raw()? {
                let topic = &raw.connection.topic;
                let entry = topics.entry(topic.name.clone()).or_insert_with(|| Topic {
                    message_count: Some(0),
                    ..topic.clone()
                });
                entry.message_count = Some(entry.message_count.unwrap_or(0).saturating_add(1));
            }
        }
        Ok(topics.into_values().collect())
    }

    /// Every message of the topics `wanted` accepts, decoded, in file order. Messages of
    /// other topics are skipped without decoding.
    pub fn messages(&self, wanted: impl Fn(&str) -> bool + 'static) -> Result<Messages, BagError> {
        Ok(Messages {
            source: self.source()?,
            wanted: Box::new(wanted),
            counts: HashMap::new(),
            done: false,
        })
    }

    fn ros1_reader(&self) -> Result<ros1::Ros1Reader, BagError> {
        let (input, len) = match &self.storage {
            Storage::Memory(bytes) => (self.counted(open_memory(bytes)), bytes.len() as u64),
            Storage::Files(files) => {
                let path = files.first().unwrap_or(&self.path);
                let io = |source| BagError::Io {
                    path: path.clone(),
                    source,
                };
                let file = std::fs::File::open(path).map_err(io)?;
                let len = file.metadata().map_err(io)?.len();
                (self.counted(Box::new(file)), len)
            }
        };
        ros1::Ros1Reader::new(&self.path, input, len)
    }

    fn source(&self) -> Result<Source, BagError> {
        if self.format == Format::Ros1 {
            return Ok(Source::Ros1(Box::new(self.ros1_reader()?)));
        }
        Ok(match &self.storage {
            Storage::Files(files) => Source::Mcap {
                files: files.iter().rev().cloned().collect(),
                current: None,
                bytes_read: self.bytes_read.clone(),
            },
            Storage::Memory(bytes) => Source::Mcap {
                files: Vec::new(),
                current: Some(Box::new(mcap_file::McapReader::new(
                    &self.path,
                    self.counted(open_memory(bytes)),
                ))),
                bytes_read: None,
            },
        })
    }
}

/// Bytes in memory as an input (shared, not copied).
fn open_memory(bytes: &Arc<[u8]>) -> Box<dyn Input> {
    Box::new(std::io::Cursor::new(SharedBytes(bytes.clone())))
}

struct SharedBytes(Arc<[u8]>);

impl AsRef<[u8]> for SharedBytes {
    fn as_ref(&self) -> &[u8] {
        &self.0
    }
}

enum Source {
    Ros1(Box<ros1::Ros1Reader>),
    /// The files still to read (last first) and the one being read.
    Mcap {
        files: Vec<PathBuf>,
        current: Option<Box<mcap_file::McapReader>>,
        /// The bag's counter, for the files opened later.
        bytes_read: Option<Arc<AtomicU64>>,
    },
}

impl Source {
    fn next_raw(&mut self) -> Result<Option<RawMessage>, BagError> {
        match self {
            Source::Ros1(reader) => reader.next_message(),
            Source::Mcap {
                files,
                current,
                bytes_read,
            } => loop {
                if let Some(reader) = current {
                    if let Some(message) = reader.next_message()? {
                        return Ok(Some(message));
                    }
                }
                match files.pop() {
                    Some(path) => {
                        let file = std::fs::File::open(&path).map_err(|source| BagError::Io {
                            path: path.clone(),
                            source,
                        })?;
                        let input: Box<dyn Input> = match bytes_read {
                            Some(counter) => Box::new(CountingReader::new(file, counter.clone())),
                            None => Box::new(file),
                        };
                        *current = Some(Box::new(mcap_file::McapReader::new(&path, input)));
                    }
                    None => {
                        *current = None;
                        return Ok(None);
                    }
                }
            },
        }
    }

    /// The file being read.
    fn path(&self) -> PathBuf {
        match self {
            Source::Ros1(reader) => reader.path().to_path_buf(),
            Source::Mcap {
                current: Some(reader),
                ..
            } => reader.path().to_path_buf(),
            Source::Mcap { current: None, .. } => PathBuf::new(),
        }
    }
}

/// The messages of a bag, decoded; see [`Bag::messages`]. Stops after the first error.
pub struct Messages {
    source: Source,
    wanted: Box<dyn Fn(&str) -> bool>,
    /// Messages seen so far per topic, and the topic's shared name and type.
    counts: HashMap<String, (u64, Arc<str>, Arc<str>)>,
    done: bool,
}

impl std::fmt::Debug for Messages {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Messages")
            .field("done", &self.done)
            .finish_non_exhaustive()
    }
}

impl Messages {
    fn next_message(&mut self) -> Result<Option<Message>, BagError> {
        loop {
            let Some(raw) = self.source.next_raw()? else {
                return Ok(None);
            };
            let topic = &raw.connection.topic;
            if !(self.wanted)(&topic.name) {
                continue;
            }
            let entry = self.counts.entry(topic.name.clone()).or_insert_with(|| {
                (
                    0,
                    Arc::from(topic.name.as_str()),
                    Arc::from(topic.type_name.as_str()),
                )
            });
            let index = entry.0;
            entry.0 = entry.0.saturating_add(1);
            let (topic_name, type_name) = (entry.1.clone(), entry.2.clone());
            let path = || self.source.path();
            let schema = match &raw.connection.schema {
                Ok(schema) => schema.clone(),
                Err(source) => {
                    return Err(BagError::Definition {
                        path: path(),
                        topic: topic.name.clone(),
                        type_name: topic.type_name.clone(),
                        source: source.clone(),
                    })
                }
            };
            let size = raw.data.len() as u64;
            if size > MAX_MESSAGE {
                return Err(BagError::MessageTooLarge {
                    path: path(),
                    topic: topic.name.clone(),
                    index,
                    offset: raw.offset,
                    size,
                });
            }
            let value =
                decode(&schema, topic.encoding, &raw.data).map_err(|source| BagError::Decode {
                    path: path(),
                    topic: topic.name.clone(),
                    index,
                    offset: raw.offset,
                    source,
                })?;
            return Ok(Some(Message {
                topic: topic_name,
                type_name,
                schema,
                index,
                receive_time: raw.receive_time,
                value,
            }));
        }
    }
}

impl Iterator for Messages {
    type Item = Result<Message, BagError>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.done {
            return None;
        }
        match self.next_message() {
            Ok(Some(message)) => Some(Ok(message)),
            Ok(None) => {
                self.done = true;
                None
            }
            Err(error) => {
                self.done = true;
                Some(Err(error))
            }
        }
    }
}
